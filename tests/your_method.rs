//! A WGSL file is a method (`--method wgsl:PATH`, docs/your-method.md), run as a user
//! runs it: the example drawn and measured against the reference within its own claim,
//! a function that draws nothing measured as the error it is, a broken file refused in
//! one line that names its place, and the survey holding a file to the claim it makes.

mod common;

use std::path::Path;

use common::binary::{bin, output_within, run, scratch};

const EXAMPLE: &str = "wgsl:examples/methods/supersampled.wgsl";
/// "GPU Font Rendering"'s two rays with a one-pixel window, as a user's file.
const TWO_RAYS: &str = "wgsl:examples/methods/two_rays.wgsl";
/// The naive one: a pixel wholly covered where its centre is inside.
const ONE_RAY: &str = "wgsl:examples/methods/one_ray.wgsl";

/// `render --stats` of `method` on a line of text at 24 px/em, as JSON.
fn measured(method: &str, name: &str) -> serde_json::Value {
    let error = scratch(&format!("{name}-error.png"));
    let view = ["--text", "Hamburgefonstiv", "--size", "24"];
    stats_of(
        &view,
        method,
        &["--error-image", error.to_str().unwrap()],
        name,
    )
}

/// `render VIEW --method METHOD EXTRA --stats`, run to success, its statistics as JSON.
fn stats_of(view: &[&str], method: &str, extra: &[&str], name: &str) -> serde_json::Value {
    let out = scratch(&format!("{name}.png"));
    let stats = scratch(&format!("{name}.json"));
    let mut args = vec!["render"];
    args.extend(view);
    args.extend(["--method", method]);
    args.extend(extra);
    args.extend([
        "--out",
        out.to_str().unwrap(),
        "--stats",
        stats.to_str().unwrap(),
    ]);
    let result = run(&args);
    assert!(
        result.status.success(),
        "{}",
        String::from_utf8_lossy(&result.stderr)
    );
    serde_json::from_str(&std::fs::read_to_string(stats).unwrap()).unwrap()
}

/// A file of `text` in the scratch folder, as a method name.
fn user_file(name: &str, text: &str) -> (String, std::path::PathBuf) {
    let path = scratch(name);
    std::fs::write(&path, text).unwrap();
    (format!("wgsl:{}", path.display()), path)
}

#[test]
fn the_examples_are_measured_within_their_claims_and_a_blank_function_is_not() {
    // Each with its header's claim, set before measuring: 4×4 samples resolve an edge
    // to about a quarter; two windowed rays are off by at most half of what the ray
    // along an edge misses.
    for (example, name, claim_max, claim_mae) in [
        (EXAMPLE, "example", 0.3, 8.0),
        (TWO_RAYS, "two-rays", 0.6, 6.0),
    ] {
        let json = measured(example, name);
        assert_eq!(json["method"], example);
        let error = &json["error"];
        let max = error["max"].as_f64().unwrap();
        let mae = error["mae_255"].as_f64().unwrap();
        println!("{example} on Hamburgefonstiv at 24 px/em: max {max:.4}, MAE {mae:.3}/255");
        assert!(max <= claim_max && mae <= claim_mae, "{error}");
        assert_eq!(json["claim"]["held"], true, "{json}");
        // Sampled or windowed, not integrated: some edge pixel is off by more than an
        // exact method's 0.02.
        assert!(max > 0.02, "{error}");
        assert!(error["edge"]["pixels"].as_u64().unwrap() > 0, "{error}");
    }
    // The same pipeline with a function that covers nothing: the glyphs' insides are
    // off by all of their coverage, so the measurement sees the user's function.
    let (blank, _) = user_file(
        "blank.wgsl",
        "fn user_coverage(g: Glyph, p: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> f32 {\n    return 0.0;\n}\n",
    );
    let json = measured(&blank, "blank");
    assert!(
        json["error"]["max"].as_f64().unwrap() > 0.99,
        "{}",
        json["error"]
    );
}

#[test]
fn a_broken_file_is_one_line_naming_its_place() {
    let (syntax, path) = user_file(
        "syntax.wgsl",
        "// a comment\nfn user_coverage(g: Glyph, p: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> f32 {\n    let x = 1.0\n    return x;\n}\n",
    );
    let (types, types_path) = user_file(
        "types.wgsl",
        "fn user_coverage(g: Glyph, p: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> f32 {\n    return 1u;\n}\n",
    );
    let missing = "wgsl:no/such/file.wgsl".to_owned();
    // No function, or one of another signature: the error the prelude meets names
    // what the file must define.
    let (empty, empty_path) = user_file("empty.wgsl", "");
    let (arity, arity_path) = user_file(
        "arity.wgsl",
        "fn user_coverage(g: Glyph, p: vec2<f32>) -> f32 {\n    return 0.0;\n}\n",
    );
    // The path ends at `.wgsl`: what follows is a parameter, which a file takes none of.
    let with_param = format!("{EXAMPLE}:samples=4");
    for (method, place) in [
        (
            empty,
            format!("{}: it must define fn user_coverage", empty_path.display()),
        ),
        (
            arity,
            format!("{}: it must define fn user_coverage", arity_path.display()),
        ),
        (with_param, "samples".to_owned()),
        // The missing `;` is found at the next token: line 4, column 5.
        (syntax, format!("{}:4:5:", path.display())),
        // A value of the wrong type is found at the statement that returns it.
        (types, format!("{}:2:", types_path.display())),
        (missing, "no/such/file.wgsl:".into()),
    ] {
        let out = scratch("broken.png");
        let result = run(&[
            "render",
            "--text",
            "a",
            "--size",
            "12",
            "--method",
            &method,
            "--out",
            out.to_str().unwrap(),
        ]);
        let stderr = String::from_utf8_lossy(&result.stderr);
        assert_eq!(result.status.code(), Some(2), "{method}: {stderr}");
        assert_eq!(stderr.trim().lines().count(), 1, "{method}: {stderr}");
        assert!(stderr.contains(&place), "{method}: {stderr} lacks {place}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}

#[test]
fn the_survey_holds_a_file_to_the_claim_it_makes() {
    let survey = |method: &str, name: &str| {
        let out = scratch(name);
        let result = run(&[
            "survey",
            "--fonts",
            "fonts/DejaVuSans.ttf",
            "--sizes",
            "24",
            "--transforms",
            "still",
            "--glyphs",
            "36-45",
            "--methods",
            method,
            "--out",
            out.to_str().unwrap(),
        ]);
        let rows = std::fs::read_to_string(Path::new(&out).join("survey.csv")).unwrap_or_default();
        (result, rows)
    };
    let (result, rows) = survey(EXAMPLE, "survey-example");
    assert!(
        result.status.success(),
        "{}",
        String::from_utf8_lossy(&result.stderr)
    );
    assert!(
        rows.contains(",max ≤ 0.3 and MAE ≤ 8/255,"),
        "the claim's bound in the rows:\n{rows}"
    );
    assert!(rows.lines().skip(1).all(|l| l.contains(",ok,")), "{rows}");
    // The same function claiming what it cannot keep: the survey says so and exits 1.
    let text = std::fs::read_to_string("examples/methods/supersampled.wgsl")
        .unwrap()
        .replace("// claim: max=0.3 mae=8", "// claim: max=0.01 mae=0.1");
    // A survey that finds claims broken: exit 1 and broken rows, which it returns.
    let breaks = |method: &str, name: &str| {
        let (result, rows) = survey(method, name);
        let stderr = String::from_utf8_lossy(&result.stderr);
        assert_eq!(result.status.code(), Some(1), "{method}: {stderr}");
        assert!(rows.contains(",broken,"), "{method}: {rows}");
        rows
    };
    let (strict, _) = user_file("strict.wgsl", &text);
    breaks(&strict, "survey-strict");
    // The claim given with the method overrides the header's, in the survey ...
    let rows = breaks(&format!("{EXAMPLE}:claim=0.01/0.1"), "survey-given");
    assert!(rows.contains(",max ≤ 0.01 and MAE ≤ 0.1/255,"), "{rows}");
    // ... and in render's statistics, as --param claim= too.
    for (claim, held) in [("0.01/0.1", false), ("0.9/50", true)] {
        let param = format!("claim={claim}");
        let json = stats_of(&["--case", "tiny"], EXAMPLE, &["--param", &param], "given");
        assert_eq!(json["claim"]["held"], held, "{claim}: {}", json["claim"]);
    }
    for bad in ["2/1", "0.1", "x/1", "NaN/1"] {
        let out = scratch("bad-claim.png");
        let result = run(&[
            "render",
            "--case",
            "tiny",
            "--method",
            &format!("{EXAMPLE}:claim={bad}"),
            "--out",
            out.to_str().unwrap(),
        ]);
        let stderr = String::from_utf8_lossy(&result.stderr);
        assert_eq!(result.status.code(), Some(2), "{bad}: {stderr}");
        assert!(
            stderr.contains("claim=MAX/MAE") && stderr.trim().lines().count() == 1,
            "{stderr}"
        );
    }
    // The naive example believes that no pixel is off by more than a half; the survey
    // shows where it is (thin strokes, inner corners) and exits 1.
    breaks(ONE_RAY, "survey-one-ray");
}

#[test]
fn the_stability_sweep_and_motion_run_a_file_too() {
    let out = scratch("stability");
    let result = run(&[
        "stability",
        "--quick",
        "--cases",
        "collinear-quadratic",
        "--methods",
        EXAMPLE,
        "--out",
        out.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&result.stdout);
    // 0: its claim held; 1: broken (said on stderr). Either way it ran, and its column
    // is the file's.
    assert!(
        matches!(result.status.code(), Some(0 | 1)),
        "{}",
        String::from_utf8_lossy(&result.stderr)
    );
    assert!(stdout.contains(EXAMPLE), "{stdout}");
    // A copy claiming what 16 samples cannot keep breaks its claim: exit 1; and so
    // does the file itself held to that claim with the method.
    let text = std::fs::read_to_string("examples/methods/supersampled.wgsl")
        .unwrap()
        .replace("// claim: max=0.3 mae=8", "// claim: max=0.001 mae=0.01");
    let (strict, _) = user_file("strict-stability.wgsl", &text);
    for method in [strict, format!("{EXAMPLE}:claim=0.001/0.01")] {
        let result = run(&[
            "stability",
            "--quick",
            "--cases",
            "collinear-quadratic",
            "--methods",
            &method,
        ]);
        assert_eq!(
            result.status.code(),
            Some(1),
            "{method}: {}",
            String::from_utf8_lossy(&result.stderr)
        );
    }
    let out = scratch("motion");
    let result = run(&[
        "motion",
        "--text",
        "Ob",
        "--size",
        "20",
        "--frames",
        "3",
        "--method",
        &format!("winding,{EXAMPLE}"),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        result.status.success(),
        "{}",
        String::from_utf8_lossy(&result.stderr)
    );
    let summary = std::fs::read_to_string(out.join("motion.md")).unwrap();
    assert!(summary.contains(EXAMPLE), "{summary}");
}

#[test]
fn a_shader_that_never_returns_is_reported_not_hung_on() {
    // A loop whose end depends on data that never says so (a band's count compared
    // with a number no band has): the compiler cannot drop it, and lavapipe has no GPU
    // timeout.
    let (forever, path) = user_file(
        "forever.wgsl",
        "fn user_coverage(g: Glyph, p: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> f32 {\n    var i = 0u;\n    loop {\n        if band_at(g.first_band + (i & 1u)).count == 0xdeadbeefu {\n            break;\n        }\n        i++;\n    }\n    return f32(i);\n}\n",
    );
    let out = scratch("forever.png");
    let mut command = bin();
    command
        .args(["render", "--case", "tiny", "--method", &forever, "--out"])
        .arg(&out)
        .env("GLYPHSCOPE_FRAME_LIMIT_S", "3");
    let started = std::time::Instant::now();
    let result = output_within(command, std::time::Duration::from_secs(90))
        .expect("the command ends on its own, past its frame limit");
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.trim().lines().count(), 1, "{stderr}");
    assert!(
        stderr.starts_with(&format!(
            "error: {}: your shader has not finished a frame in",
            path.display()
        )),
        "{stderr}"
    );
    println!(
        "a shader that never returns: exit 2 after {:.1} s",
        started.elapsed().as_secs_f64()
    );
}
