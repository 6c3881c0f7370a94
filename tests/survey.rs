//! `glyphscope survey` as a user runs it: the four outputs, a broken font as a row with
//! its reason, shards run as separate processes merging into the single run row for
//! row, a killed run resuming to the same rows, and bad arguments as one line and
//! exit 2.

mod common;

use std::path::{Path, PathBuf};
use std::process::Output;
use std::sync::OnceLock;
use std::time::{Duration, Instant};

use common::binary::{bin, run, scratch};

const SHIPPED: [&str; 4] = [
    "DejaVuSans.ttf",
    "Inter-roman.var.ttf",
    "Lohit-Bengali.ttf",
    "lmroman10-regular.otf",
];

/// A folder holding the four shipped fonts (and, if given, more files by name and
/// bytes).
fn font_folder(name: &str, more: &[(&str, &[u8])]) -> PathBuf {
    let dir = scratch(name);
    std::fs::create_dir_all(&dir).unwrap();
    for font in SHIPPED {
        let from = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("fonts")
            .join(font);
        std::fs::copy(from, dir.join(font)).unwrap();
    }
    for (file, bytes) in more {
        std::fs::write(dir.join(file), bytes).unwrap();
    }
    dir
}

fn text(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// The plan the shard and resume tests share: two transforms, two methods, a few
/// glyphs of each font.
const PLAN: [&str; 8] = [
    "--sizes",
    "12",
    "--transforms",
    "still,rotate:30",
    "--methods",
    "winding,atlas",
    "--glyphs",
    "30-90",
];

/// `survey` over `fonts` into `out` by [`PLAN`], as owned arguments.
fn plan_args(fonts: &Path, out: &Path) -> Vec<String> {
    let mut args = vec![
        "survey".to_owned(),
        "--fonts".into(),
        fonts.display().to_string(),
    ];
    args.extend(["--out".into(), out.display().to_string()]);
    args.extend(PLAN.map(str::to_owned));
    args
}

fn survey(fonts: &Path, out: &Path, more: &[&str]) -> Output {
    let (fonts, out) = (fonts.to_str().unwrap(), out.to_str().unwrap());
    let mut args = vec!["survey", "--fonts", fonts, "--out", out];
    args.extend(PLAN);
    args.extend(more);
    run(&args)
}

/// The single run of [`PLAN`] over the shipped fonts, once for every test here.
fn single_run() -> &'static (PathBuf, PathBuf) {
    static RUN: OnceLock<(PathBuf, PathBuf)> = OnceLock::new();
    RUN.get_or_init(|| {
        let fonts = font_folder("plan-fonts", &[]);
        let out = scratch("single");
        let output = survey(&fonts, &out, &[]);
        assert!(output.status.success(), "{}", stderr(&output));
        (fonts, out)
    })
}

/// The command (on a glyph range, to keep it short): the four outputs are
/// written; survey.md names each method's worst glyphs with explorer links that place
/// the glyph as measured; the exit code is 1 exactly when survey.md lists a broken
/// claim.
#[test]
fn a_survey_writes_its_four_outputs_and_names_each_methods_worst_glyphs() {
    let out = scratch("four-outputs");
    let output = run(&[
        "survey",
        "--fonts",
        "fonts/",
        "--sizes",
        "12,24",
        "--methods",
        "winding,sdf-cells,atlas",
        "--glyphs",
        "30-70",
        "--out",
        out.to_str().unwrap(),
    ]);
    let md = text(&out.join("survey.md"));
    let broken = md
        .split("## Broken claims (")
        .nth(1)
        .and_then(|rest| rest.split(')').next())
        .and_then(|n| n.parse::<usize>().ok())
        .expect("survey.md counts the broken claims");
    assert_eq!(
        output.status.code(),
        Some(i32::from(broken > 0)),
        "{}",
        stderr(&output)
    );
    let csv = text(&out.join("survey.csv"));
    let json: serde_json::Value = serde_json::from_str(&text(&out.join("survey.json"))).unwrap();
    let rows = json["rows"].as_array().unwrap();
    assert_eq!(csv.lines().count(), rows.len() + 1, "one CSV line per row");
    // 41 ids of 4 fonts, 2 sizes, 2 transforms, 3 methods, less blank glyphs.
    assert!(rows.len() > 41 * 4 * 12 / 2, "{} rows", rows.len());
    for method in ["winding", "sdf-cells", "atlas"] {
        assert!(
            md.contains(&format!("## {method}: its 20 worst glyphs")),
            "{method}"
        );
        let sheet = image::open(out.join(format!("worst-{method}.png"))).unwrap();
        assert!(sheet.width() > 100 && sheet.height() > 100);
    }
    // Every measured row in a table links to its glyph at its size and transform.
    let table_rows: Vec<&str> = md.lines().filter(|l| l.starts_with("| 1 | ")).collect();
    assert_eq!(table_rows.len(), 3);
    for line in table_rows {
        let cells: Vec<&str> = line.split(" | ").collect();
        let id = cells[2].trim_start_matches('#').split(' ').next().unwrap();
        let link = line
            .split("--view '")
            .nth(1)
            .unwrap()
            .split('\'')
            .next()
            .unwrap();
        assert!(link.contains(&format!("glyph=%23{id}&")), "{link}");
        assert!(link.contains(&format!("size={}&", cells[3])), "{link}");
        assert!(link.contains("&magnify=16&focus="), "{link}");
    }
}

/// A file that is not a font, and one cut short, are rows with their reasons; the
/// survey goes on through the real fonts and exits by the claims alone (winding's
/// hold on these glyphs).
#[test]
fn a_broken_font_is_a_row_with_its_reason_and_the_survey_goes_on() {
    let dejavu = std::fs::read("fonts/DejaVuSans.ttf").unwrap();
    let fonts = font_folder(
        "broken-fonts",
        &[
            ("broken.ttf", b"not a font at all"),
            ("cut-short.ttf", &dejavu[..2000]),
        ],
    );
    let out = scratch("broken-out");
    let output = run(&[
        "survey",
        "--fonts",
        fonts.to_str().unwrap(),
        "--sizes",
        "12",
        "--transforms",
        "still",
        "--methods",
        "winding",
        "--glyphs",
        "36-40",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let csv = text(&out.join("survey.csv"));
    for name in ["broken.ttf", "cut-short.ttf"] {
        let row = csv
            .lines()
            .find(|l| l.contains(name))
            .unwrap_or_else(|| panic!("no row for {name}:\n{csv}"));
        assert!(row.contains(",unreadable,"), "{row}");
        assert!(
            row.contains(name) && row.len() > name.len() + 40,
            "a reason: {row}"
        );
    }
    let md = text(&out.join("survey.md"));
    assert!(md.contains("## Unreadable (2)"), "{md}");
    assert!(
        csv.lines()
            .filter(|l| l.contains("DejaVuSans.ttf,,3"))
            .count()
            >= 4
    );
}

/// Shards 0/3, 1/3 and 2/3 run as separate processes at once and merged give the
/// single run's outputs, row for row.
#[test]
fn three_shards_merged_equal_the_single_run() {
    let (fonts, single) = single_run();
    let shards: Vec<PathBuf> = (0..3).map(|i| scratch(&format!("shard-{i}"))).collect();
    let children: Vec<_> = shards
        .iter()
        .enumerate()
        .map(|(i, out)| {
            let mut args = plan_args(fonts, out);
            args.extend(["--shard".into(), format!("{i}/3")]);
            bin().args(&args).output()
        })
        .collect();
    for child in children {
        let output = child.unwrap();
        assert!(output.status.success(), "{}", stderr(&output));
    }
    let merged = scratch("merged");
    let mut args = vec!["survey".to_owned(), "merge".into()];
    args.extend(shards.iter().map(|s| s.display().to_string()));
    args.extend(["--out".into(), merged.display().to_string()]);
    let output = bin().args(&args).output().unwrap();
    assert!(output.status.success(), "{}", stderr(&output));
    let (one, joined) = (
        text(&single.join("survey.csv")),
        text(&merged.join("survey.csv")),
    );
    assert!(one.lines().count() > 100, "{one}");
    for (k, (a, b)) in one.lines().zip(joined.lines()).enumerate() {
        assert_eq!(a, b, "row {k}");
    }
    assert_eq!(one.lines().count(), joined.lines().count());
    assert_eq!(
        text(&single.join("survey.md")),
        text(&merged.join("survey.md"))
    );
    // A shard missing a font it was to survey (one that died) is refused, and so is a
    // set of shards without one of them.
    let dead = shards[1].join("fonts");
    let first = std::fs::read_dir(&dead)
        .unwrap()
        .next()
        .unwrap()
        .unwrap()
        .path();
    std::fs::rename(&first, dead.join("gone.partial")).unwrap();
    let refused = bin().args(&args).output().unwrap();
    assert_eq!(refused.status.code(), Some(2), "{}", stderr(&refused));
    assert!(
        stderr(&refused).contains("has not finished 1 of its fonts"),
        "{}",
        stderr(&refused)
    );
    std::fs::rename(dead.join("gone.partial"), &first).unwrap();
    let two = [
        "survey".to_owned(),
        "merge".into(),
        shards[0].display().to_string(),
        shards[2].display().to_string(),
        "--out".into(),
        scratch("two-of-three").display().to_string(),
    ];
    let refused = bin().args(two).output().unwrap();
    assert_eq!(refused.status.code(), Some(2), "{}", stderr(&refused));
    assert!(
        stderr(&refused).contains("each of the 3 shards once"),
        "{}",
        stderr(&refused)
    );
    // Each shard holds only its own fonts.
    let rows_of = |dir: &Path| text(&dir.join("survey.csv")).lines().count() - 1;
    assert_eq!(
        shards.iter().map(|s| rows_of(s)).sum::<usize>(),
        one.lines().count() - 1
    );
}

/// A run killed after its first font, with a font's half-written folder left behind,
/// finishes on the second try with the rows of a run never stopped.
#[test]
fn a_killed_survey_resumes_to_the_same_rows() {
    let (fonts, single) = single_run();
    let out = scratch("killed");
    let args = plan_args(fonts, &out);
    let mut child = bin()
        .args(&args)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let finished = |dir: &Path| {
        std::fs::read_dir(dir.join("fonts")).map_or(0, |entries| {
            entries
                .filter_map(Result::ok)
                .filter(|e| !e.file_name().to_string_lossy().ends_with(".partial"))
                .count()
        })
    };
    let started = Instant::now();
    while finished(&out) == 0 {
        assert!(
            started.elapsed() < Duration::from_secs(120),
            "no font finished"
        );
        assert!(
            child.try_wait().unwrap().is_none(),
            "it ended before it could be killed"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    let done = finished(&out);
    assert!(
        (1..SHIPPED.len()).contains(&done),
        "{done} fonts finished when killed"
    );
    assert!(
        !out.join("survey.csv").exists(),
        "killed before its outputs"
    );
    // What a kill during a font's writing leaves: a partial folder, never trusted.
    // The last font's own folder name, so a resume that trusted it would skip that font.
    let last = format!("{}/{}", fonts.display(), SHIPPED[3]);
    let partial = out.join("fonts").join(format!(
        "{}.partial",
        glyphscope::survey::font_folder(&last)
    ));
    std::fs::create_dir_all(&partial).unwrap();
    std::fs::write(partial.join("rows.csv"), "font,face\nhalf").unwrap();
    let output = bin().args(&args).output().unwrap();
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(
        stderr(&output).contains(&format!("resuming: {done} of 4 fonts")),
        "{}",
        stderr(&output)
    );
    assert!(!partial.exists());
    let finished_last = out
        .join("fonts")
        .join(glyphscope::survey::font_folder(&last));
    assert!(
        finished_last.join("rows.csv").exists(),
        "the half-written font measured again"
    );
    assert_eq!(
        text(&single.join("survey.csv")),
        text(&out.join("survey.csv"))
    );
    // Resumed under another plan, the folder is refused.
    let mut other = args.clone();
    let sizes = other.iter().position(|a| a == "--sizes").unwrap();
    other[sizes + 1] = "13".into();
    let output = bin().args(&other).output().unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("another plan"),
        "{}",
        stderr(&output)
    );
}

/// Bad arguments: one line, exit 2, no panic.
#[test]
fn bad_survey_arguments_are_one_line_and_exit_2() {
    let out = scratch("bad");
    let out = out.to_str().unwrap();
    for (args, says) in [
        (vec!["--fonts", "no/such.ttf"], "no/such.ttf"),
        (vec!["--fonts", "fonts", "--sizes", "-3"], "--sizes"),
        (
            vec!["--fonts", "fonts", "--transforms", "tilt:10"],
            "tilt:10",
        ),
        (
            vec!["--fonts", "fonts", "--methods", "reference"],
            "reference",
        ),
        (
            vec!["--fonts", "fonts", "--methods", "winding:aa=nope"],
            "aa",
        ),
        (vec!["--fonts", "fonts", "--shard", "3/3"], "shard"),
        (vec!["--fonts", "fonts", "--glyphs", "9-2"], "9-2"),
        (
            vec!["--fonts", "Cargo.toml", "--sizes", "12", "--glyphs", "1"],
            "",
        ),
    ] {
        let mut all = vec!["survey", "--out", out];
        all.extend(&args);
        let output = run(&all);
        let err = stderr(&output);
        if says.is_empty() {
            // A lone file that is not a font is a row, not an argument error.
            assert_eq!(output.status.code(), Some(0), "{args:?}: {err}");
            continue;
        }
        assert_eq!(output.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
    let output = run(&["survey", "merge", "no/such/dir", "--out", out]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("no/such/dir"),
        "{}",
        stderr(&output)
    );
}
