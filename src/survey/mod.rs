//! `glyphscope survey`: every glyph of the fonts given, by glyph id, at each size and
//! transform, through each method, against the reference; each claim the registry
//! states held on every glyph. The fonts' files form one sorted list ([`fonts`]); each
//! file's rows and worst tiles are written into `DIR/fonts/` atomically as it finishes,
//! so a run stopped part way resumes where it stopped, a shard (`--shard I/N`) takes a
//! share of the list, and [`merge`] joins shards' folders into the outputs one run
//! would write ([`report`]).

pub mod fonts;
pub mod grid;
pub mod measure;
pub mod plan;
pub mod report;
pub mod row;
pub mod traits;

use std::path::{Path, PathBuf};

use indicatif::{ProgressBar, ProgressStyle};

use crate::Error;
use crate::gpu::GpuContext;
use plan::{Plan, PlanFile};
use report::FontRows;
use row::{Verdict, file_safe};

/// What `glyphscope survey` runs.
#[derive(Clone, Debug)]
pub struct SurveyOptions {
    pub fonts: Vec<PathBuf>,
    pub plan: Plan,
    /// This shard's index and the number of shards.
    pub shard: Option<(usize, usize)>,
    pub out: PathBuf,
    pub adapter: Option<String>,
}

/// The plan a folder's results were measured by.
const PLAN_FILE: &str = "survey-plan.json";
/// The font files a folder is to hold, and its shard: what a merge checks is there.
const FONTS_FILE: &str = "survey-fonts.json";
/// The folder of finished fonts, one folder each.
const FONTS_DIR: &str = "fonts";
/// In a finished font's folder: the font's label, its rows and its worst tiles.
const LABEL_FILE: &str = "font.txt";
const ROWS_FILE: &str = "rows.csv";
const TILES_DIR: &str = "tiles";
/// A font being written: renamed to its folder's name only once complete.
const PARTIAL: &str = ".partial";

fn output(path: &Path, e: &dyn std::fmt::Display) -> Error {
    Error::Output(format!("cannot write '{}': {e}", path.display()))
}

/// The folder a font file's results go in: its path made safe, and a hash of the path
/// so that two files whose safe names agree stay apart.
pub fn font_folder(label: &str) -> String {
    let safe = file_safe(label);
    // FNV-1a, 64-bit: stable across runs and machines, unlike std's hasher.
    let hash = label.bytes().fold(0xcbf2_9ce4_8422_2325_u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    });
    let tail: String = safe
        .chars()
        .rev()
        .take(60)
        .collect::<Vec<_>>()
        .into_iter()
        .rev()
        .collect();
    format!("{tail}-{hash:016x}")
}

/// Writes the plan into `out`, or checks it against the one there: a folder holds the
/// results of one plan.
fn claim_folder(out: &Path, plan: &PlanFile) -> Result<(), Error> {
    std::fs::create_dir_all(out.join(FONTS_DIR)).map_err(|e| output(out, &e))?;
    let path = out.join(PLAN_FILE);
    match std::fs::read_to_string(&path) {
        Ok(text) => {
            let found = read_plan(&path, &text)?;
            if &found != plan {
                return Err(Error::Input(format!(
                    "'{}' holds a survey of another plan ({}); give the same sizes, \
                     transforms, methods, instances and glyphs to resume it, or another --out",
                    out.display(),
                    to_json(&found)
                )));
            }
            Ok(())
        }
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            write_atomically(&path, &(to_json(plan) + "\n"))
        }
        Err(e) => Err(Error::Input(format!(
            "cannot read '{}': {e}",
            path.display()
        ))),
    }
}

/// A plan file's text read, or why it is not one.
fn read_plan(path: &Path, text: &str) -> Result<PlanFile, Error> {
    serde_json::from_str(text)
        .map_err(|e| Error::Input(format!("'{}' is not a survey's plan: {e}", path.display())))
}

/// Which fonts a folder is to hold (`FONTS_FILE`): a shard's, or a merge's.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
struct FontsFile {
    /// (index, count) of a shard; None for a whole run or a merge.
    shard: Option<(usize, usize)>,
    /// The fonts' labels, as found under `--fonts`.
    fonts: Vec<String>,
}

/// One line of JSON.
fn to_json(value: &impl serde::Serialize) -> String {
    serde_json::to_string(value).expect("plain data serializes")
}

/// Writes `text` to `path` through a temporary file renamed over it.
fn write_atomically(path: &Path, text: &str) -> Result<(), Error> {
    let partial = PathBuf::from(format!("{}{PARTIAL}", path.display()));
    std::fs::write(&partial, text).map_err(|e| output(&partial, &e))?;
    std::fs::rename(&partial, path).map_err(|e| output(path, &e))
}

/// Runs the survey and writes its outputs. Returns whether every claim held.
pub fn run(options: &SurveyOptions) -> Result<bool, Error> {
    let mut files = fonts::files(&options.fonts)?;
    if let Some((index, count)) = options.shard {
        files = fonts::shard(files, index, count);
    }
    let description = options.plan.describe();
    claim_folder(&options.out, &description)?;
    let fonts_dir = options.out.join(FONTS_DIR);
    // A font whose writing was cut short is measured again.
    for entry in std::fs::read_dir(&fonts_dir).map_err(|e| output(&fonts_dir, &e))? {
        let path = entry.map_err(|e| output(&fonts_dir, &e))?.path();
        if path.to_string_lossy().ends_with(PARTIAL) {
            std::fs::remove_dir_all(&path).map_err(|e| output(&path, &e))?;
        }
    }
    let labels: Vec<String> = files.iter().map(|f| f.display().to_string()).collect();
    let expected = FontsFile {
        shard: options.shard,
        fonts: labels.clone(),
    };
    let path = options.out.join(FONTS_FILE);
    write_atomically(&path, &(to_json(&expected) + "\n"))?;
    let to_do: Vec<(&PathBuf, &String)> = files
        .iter()
        .zip(&labels)
        .filter(|(_, label)| !fonts_dir.join(font_folder(label)).is_dir())
        .collect();
    if to_do.len() < files.len() {
        eprintln!(
            "resuming: {} of {} fonts already finished in '{}'",
            files.len() - to_do.len(),
            files.len(),
            options.out.display()
        );
    }
    if !to_do.is_empty() {
        let gpu = GpuContext::open(options.adapter.as_deref())?;
        let plan = &options.plan;
        let views: u64 = to_do.iter().map(|(file, _)| views_in(file, plan)).sum();
        eprintln!(
            "{} fonts: {views} glyph views ({} sizes × {} transforms) through {} methods on {}",
            to_do.len(),
            plan.sizes.len(),
            plan.transforms.len(),
            plan.methods.len(),
            gpu.adapter_name()
        );
        let bar = ProgressBar::new(views);
        bar.set_style(
            ProgressStyle::with_template(
                "{elapsed_precise} {wide_bar} {pos}/{len} glyph views, {per_sec}, {eta} left {msg}",
            )
            .expect("a valid template"),
        );
        let start = web_time::Instant::now();
        for (file, label) in &to_do {
            bar.set_message(label.to_string());
            let result = measure::font_file(&gpu, file, label, plan, |n| bar.inc(n));
            save_font(&fonts_dir, label, &result)?;
        }
        bar.finish_and_clear();
        let seconds = start.elapsed().as_secs_f64();
        eprintln!(
            "surveyed {views} glyph views in {seconds:.1} s: {:.0} glyph views/s",
            views as f64 / seconds.max(1e-9)
        );
    }
    write_outputs(&options.out, &description, &options.plan, &labels)
}

/// Glyph views a file will give under `plan`, for the progress bar: its faces' glyphs
/// in range × sizes × transforms (blank glyphs count too; they pass at once).
fn views_in(file: &Path, plan: &Plan) -> u64 {
    let glyphs: u64 = fonts::faces(file, &plan.instances)
        .0
        .iter()
        .filter_map(|f| f.font.as_ref().ok())
        .map(|font| plan.glyph_ids(font.glyph_count()).count() as u64)
        .sum();
    glyphs * (plan.sizes.len() * plan.transforms.len()) as u64
}

/// Writes a finished font into `fonts_dir` atomically: into a partial folder, renamed
/// once its every file is written.
fn save_font(fonts_dir: &Path, label: &str, result: &measure::FontResult) -> Result<(), Error> {
    let name = font_folder(label);
    let partial = fonts_dir.join(format!("{name}{PARTIAL}"));
    let tiles = partial.join(TILES_DIR);
    std::fs::create_dir_all(&tiles).map_err(|e| output(&tiles, &e))?;
    for (file, tile) in &result.tiles {
        let path = tiles.join(file);
        tile.save(&path).map_err(|e| output(&path, &e))?;
    }
    let path = partial.join(ROWS_FILE);
    std::fs::write(&path, row::to_csv(&result.rows)).map_err(|e| output(&path, &e))?;
    let path = partial.join(LABEL_FILE);
    std::fs::write(&path, label).map_err(|e| output(&path, &e))?;
    let done = fonts_dir.join(name);
    std::fs::rename(&partial, &done).map_err(|e| output(&done, &e))
}

/// Reads the finished font in `folder`.
fn read_font(folder: &Path) -> Result<FontRows, Error> {
    let read = |name: &str| {
        let path = folder.join(name);
        std::fs::read_to_string(&path)
            .map_err(|e| Error::Input(format!("cannot read '{}': {e}", path.display())))
    };
    let label = read(LABEL_FILE)?;
    let rows = row::from_csv(&read(ROWS_FILE)?)
        .map_err(|e| Error::Input(format!("'{}': {e}", folder.join(ROWS_FILE).display())))?;
    Ok(FontRows {
        label,
        rows,
        tiles: folder.join(TILES_DIR),
    })
}

/// The finished fonts in `out`, sorted by label (`only`: just these labels).
fn finished_fonts(out: &Path, only: Option<&[String]>) -> Result<Vec<FontRows>, Error> {
    let dir = out.join(FONTS_DIR);
    let mut fonts = Vec::new();
    for entry in std::fs::read_dir(&dir)
        .map_err(|e| Error::Input(format!("cannot list '{}': {e}", dir.display())))?
    {
        let path = entry.map_err(|e| output(&dir, &e))?.path();
        if path.is_dir() && !path.to_string_lossy().ends_with(PARTIAL) {
            let font = read_font(&path)?;
            if only.is_none_or(|labels| labels.contains(&font.label)) {
                fonts.push(font);
            }
        }
    }
    fonts.sort_by(|a, b| a.label.cmp(&b.label));
    Ok(fonts)
}

/// Writes the outputs from the fonts finished in `out` (those of `labels` only), and
/// says whether every claim held.
fn write_outputs(
    out: &Path,
    description: &PlanFile,
    plan: &Plan,
    labels: &[String],
) -> Result<bool, Error> {
    let fonts = finished_fonts(out, Some(labels))?;
    let methods: Vec<String> = plan.methods.iter().map(|m| m.label.clone()).collect();
    let transforms: Vec<(String, (f64, f64))> = plan
        .transforms
        .iter()
        .map(|t| (t.name.clone(), (t.rotation_deg, t.skew)))
        .collect();
    report::write(out, description, &methods, &transforms, &fonts)?;
    conclude(out, &fonts)
}

/// Prints where the report is and each broken claim; whether every claim held.
fn conclude(out: &Path, fonts: &[FontRows]) -> Result<bool, Error> {
    let broken: Vec<&row::Row> = fonts
        .iter()
        .flat_map(|f| &f.rows)
        .filter(|r| r.verdict == Verdict::Broken)
        .collect();
    for r in broken.iter().take(20) {
        eprintln!(
            "broken: {} {} glyph {} at {} px/em, {}: {} max {:.3}, MAE {:.2}/255, edge MAE {:.2}/255 (claims {})",
            r.font,
            r.face,
            r.glyph.unwrap_or_default(),
            r.size,
            r.transform,
            r.method,
            r.max,
            r.mae_255,
            r.edge_mae_255,
            r.bound
        );
    }
    if broken.len() > 20 {
        eprintln!("broken: … {} more in survey.csv", broken.len() - 20);
    }
    println!("{}", out.join("survey.md").display());
    Ok(broken.is_empty())
}

/// `glyphscope survey merge`: the finished fonts of every folder in `dirs` (shards of
/// one plan) copied into `out`, and the outputs written from them as one run would.
pub fn merge(dirs: &[PathBuf], out: &Path) -> Result<bool, Error> {
    let mut description: Option<PlanFile> = None;
    for dir in dirs {
        let path = dir.join(PLAN_FILE);
        let text = std::fs::read_to_string(&path).map_err(|e| {
            Error::Input(format!("'{}' is not a survey's folder: {e}", dir.display()))
        })?;
        let plan = read_plan(&path, &text)?;
        match &description {
            Some(first) if *first != plan => {
                return Err(Error::Input(format!(
                    "'{}' was surveyed by another plan than '{}': shards merge only under one plan",
                    dir.display(),
                    dirs[0].display()
                )));
            }
            _ => description = Some(plan),
        }
    }
    let description = description
        .ok_or_else(|| Error::Input("survey merge: give the folders to merge".into()))?;
    check_shards_complete(dirs)?;
    let plan = Plan::from_file(&description)?;
    claim_folder(out, &description)?;
    let mut labels: Vec<String> = Vec::new();
    for dir in dirs {
        for font in finished_fonts(dir, None)? {
            if labels.contains(&font.label) {
                return Err(Error::Input(format!(
                    "survey merge: font '{}' is in more than one of the folders",
                    font.label
                )));
            }
            let name = font_folder(&font.label);
            let target = out.join(FONTS_DIR).join(&name);
            let source = dir.join(FONTS_DIR).join(&name);
            if source != target {
                copy_folder(&source, &target)?;
            }
            labels.push(font.label);
        }
    }
    labels.sort();
    let merged = FontsFile {
        shard: None,
        fonts: labels.clone(),
    };
    write_atomically(&out.join(FONTS_FILE), &(to_json(&merged) + "\n"))?;
    write_outputs(out, &description, &plan, &labels)
}

/// Refuses shards that do not make a whole: each folder must hold every font it was
/// to survey (a shard that died part way is rerun, and resumes, before merging), and
/// sharded folders must be the N shards of one split, each once.
fn check_shards_complete(dirs: &[PathBuf]) -> Result<(), Error> {
    let mut shards: Vec<(usize, usize)> = Vec::new();
    for dir in dirs {
        let path = dir.join(FONTS_FILE);
        let expected: FontsFile = std::fs::read_to_string(&path)
            .ok()
            .and_then(|t| serde_json::from_str(&t).ok())
            .ok_or_else(|| Error::Input(format!("'{}' is not a survey's folder", dir.display())))?;
        let finished: Vec<String> = finished_fonts(dir, None)?
            .into_iter()
            .map(|f| f.label)
            .collect();
        let missing: Vec<&str> = expected
            .fonts
            .iter()
            .map(String::as_str)
            .filter(|label| !finished.iter().any(|f| f == label))
            .collect();
        if !missing.is_empty() {
            return Err(Error::Input(format!(
                "survey merge: '{}' has not finished {} of its fonts ({}…); rerun its command \
                 to resume it",
                dir.display(),
                missing.len(),
                missing[0]
            )));
        }
        if let Some(shard) = expected.shard {
            shards.push(shard);
        }
    }
    if let Some(&(_, count)) = shards.first() {
        let mut indices: Vec<usize> = shards.iter().map(|&(i, _)| i).collect();
        indices.sort_unstable();
        if shards.iter().any(|&(_, n)| n != count) || indices != (0..count).collect::<Vec<_>>() {
            return Err(Error::Input(format!(
                "survey merge: the folders are shards {shards:?} (index, count): give each of \
                 the {count} shards once"
            )));
        }
    }
    Ok(())
}

fn copy_folder(from: &Path, to: &Path) -> Result<(), Error> {
    let partial = PathBuf::from(format!("{}{PARTIAL}", to.display()));
    let copy = |from: &Path, to: &Path| -> std::io::Result<()> {
        std::fs::create_dir_all(to.join(TILES_DIR))?;
        for name in [LABEL_FILE, ROWS_FILE] {
            std::fs::copy(from.join(name), to.join(name))?;
        }
        for entry in std::fs::read_dir(from.join(TILES_DIR))? {
            let entry = entry?;
            std::fs::copy(entry.path(), to.join(TILES_DIR).join(entry.file_name()))?;
        }
        Ok(())
    };
    copy(from, &partial).map_err(|e| output(&partial, &e))?;
    if to.exists() {
        std::fs::remove_dir_all(to).map_err(|e| output(to, &e))?;
    }
    std::fs::rename(&partial, to).map_err(|e| output(to, &e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn font_folders_are_safe_and_apart() {
        let a = font_folder("fonts/My Font.ttf");
        let b = font_folder("fonts/My_Font.ttf");
        assert_ne!(a, b);
        assert!(a.starts_with("fonts_My_Font.ttf-"), "{a}");
        assert!(
            a.chars()
                .all(|c| c.is_ascii_alphanumeric() || "-._".contains(c))
        );
        assert_eq!(a, font_folder("fonts/My Font.ttf"), "stable");
    }
}
