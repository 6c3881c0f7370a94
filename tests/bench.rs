//! `glyphscope bench` as a user runs it: `--quick` on one scene writes every output,
//! with every method and the atlas baseline in both views and finite numbers; a case's
//! error is the one `render --error-image --stats` gives for the same command line; the
//! scaling series grow their work and report every method at every point; bad input
//! fails with exit code 2 before anything is measured.

mod common;

use std::path::Path;
use std::process::Output;

use common::binary::{run, scratch};
use glyphscope::methods::registry;
use serde_json::Value;

fn succeeds(args: &[&str]) -> Output {
    let out = run(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

fn read_json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn number(v: &Value, what: &str) -> f64 {
    let n = v
        .as_f64()
        .unwrap_or_else(|| panic!("{what} is not a number: {v}"));
    assert!(n.is_finite(), "{what} = {n}");
    n
}

/// What the bench measures: the reference and every benched method of the registry.
fn measured() -> Vec<&'static str> {
    std::iter::once(registry::REFERENCE.name)
        .chain(registry::benched().map(|m| m.name))
        .collect()
}

/// The quick bench on the headlines (the whole `--quick` run takes about two minutes on
/// a loaded two-core machine; every method and both views are still here).
#[test]
fn quick_bench_outputs_agree_with_render() {
    let out = scratch("quick");
    // A short cap: the settling rounds run, the run stays short.
    succeeds(&[
        "bench",
        "--quick",
        "--scenes",
        "headlines",
        "--settle-cap",
        "2",
        "--out",
        out.to_str().unwrap(),
    ]);
    let bench = glyphscope::bench::REPORTS.iter();
    for file in bench.chain(glyphscope::bench::SCENE_OUTPUTS) {
        let len = std::fs::metadata(out.join(file)).unwrap().len();
        assert!(len > 500, "{file}: {len} bytes");
    }
    for file in glyphscope::bench::SCALING_OUTPUTS {
        assert!(!out.join(file).exists(), "{file}: no series was asked for");
    }
    let json = read_json(&out.join("bench.json"));
    assert!(json["adapter"].as_str().unwrap().len() > 3);
    let cases = json["cases"].as_array().unwrap();
    for view in ["own", "moved"] {
        // After caching, --quick measures the atlas and winding, the contrast.
        let expected: Vec<&str> = if view == "own" {
            measured()
        } else {
            vec![
                registry::REFERENCE.name,
                "winding",
                registry::baseline().name,
            ]
        };
        for method in expected {
            let of: Vec<&Value> = cases
                .iter()
                .filter(|c| c["view"] == view && c["method"] == method)
                .collect();
            assert!(!of.is_empty(), "{method} missing in the {view} view");
        }
        let baseline = cases
            .iter()
            .find(|c| c["view"] == view && c["method"] == "atlas")
            .unwrap();
        assert_eq!(
            baseline["params"][0][0], "cache_px_per_em",
            "the default first"
        );
        assert_eq!(
            baseline["params"][0][1], "120",
            "cached at the scene's size"
        );
    }
    for case in cases {
        let what = format!("{} {} {}", case["view"], case["method"], case["params"]);
        assert!(number(&case["gpu_ms"], &what) > 0.0, "{what}");
        for key in ["mae_255", "p99_255", "max", "rmse_255"] {
            assert!(number(&case["error"][key], &what) >= 0.0, "{what}");
        }
        if case["method"] != "reference" {
            let (lo, hi) = (&case["gpu_ms_range"][0], &case["gpu_ms_range"][1]);
            assert!(number(lo, &what) <= number(hi, &what), "{what}");
            assert!(case["gpu_bytes"].as_u64().unwrap() > 0, "{what}");
            // Timed in the least rounds at least; every ratio but the baseline's own
            // with its interval around it.
            assert!(case["rounds"].as_u64().unwrap() >= 3, "{what}");
            let is_baseline =
                case["method"] == "atlas" && case["params"].as_array().unwrap().len() == 1;
            let ratios: &[&str] = if is_baseline { &[] } else { &["ratio_atlas"] };
            for key in ratios.iter().chain(&["frame_ms_interval"]) {
                let r = &case[*key];
                let (low, value, high) = (
                    number(&r["low"], &what),
                    number(&r["value"], &what),
                    number(&r["high"], &what),
                );
                assert!(
                    0.0 < low && low <= value && value <= high,
                    "{what} {key}: {r}"
                );
                assert!(r["settled"].is_boolean(), "{what} {key}: {r}");
            }
        }
    }
    // Where winding's time goes: a breakdown per view, its stages timed.
    let costs = json["winding_costs"].as_array().unwrap();
    assert_eq!(costs.len(), 2, "{costs:?}");
    for cost in costs {
        let counts = &cost["counts"];
        let count = |key: &str| counts[key].as_u64().unwrap();
        assert!(count("fragments") >= count("covered_pixels"), "{cost}");
        assert!(count("covered_pixels") > 0 && count("quads") > 0, "{cost}");
        assert!(
            count("visited") >= count("right") + count("across"),
            "{cost}"
        );
        assert_eq!(count("inexact"), 0, "{cost}");
        let stages = cost["stage_gpu_ms"].as_array().unwrap();
        assert_eq!(stages.len(), 5);
        assert!(stages.iter().all(|ms| number(ms, "stage") > 0.0), "{cost}");
    }
    // The Markdown holds a row per case plus the fastest-per-level tables.
    let md = std::fs::read_to_string(out.join("bench.md")).unwrap();
    assert!(md.contains("× atlas") && md.contains("Fastest at each error level"));
    assert!(md.contains("## Where winding's time goes") && md.contains("| headlines | moved |"));
    // A row per case, and one per view a peer refused, with its reason: none left out.
    let refusals = json["refusals"].as_array().unwrap();
    assert!(!refusals.is_empty(), "glyphon cannot draw the moved view");
    let csv = std::fs::read_to_string(out.join("bench.csv")).unwrap();
    assert_eq!(csv.lines().count(), cases.len() + refusals.len() + 1);
    let refused_rows = csv.lines().filter(|l| l.contains("\"n/a: ")).count();
    assert_eq!(refused_rows, refusals.len());

    // One case rerun by `render` from the command line the bench reports: the same
    // error. The atlas after caching takes its cache size as a parameter like any other.
    for (view, method) in [("own", "winding"), ("moved", "atlas")] {
        let case = cases
            .iter()
            .find(|c| c["view"] == view && c["method"] == method)
            .unwrap();
        let scene = json["scenes"]
            .as_array()
            .unwrap()
            .iter()
            .find(|s| s["view"] == view)
            .unwrap();
        let (png, err, stats) = (scratch("r.png"), scratch("r-err.png"), scratch("r.json"));
        let mut args: Vec<String> = vec!["render".into(), "--method".into(), method.into()];
        args.extend(
            scene["render_args"]
                .as_array()
                .unwrap()
                .iter()
                .map(|a| a.as_str().unwrap().to_owned()),
        );
        for param in case["params"].as_array().unwrap() {
            args.push("--param".into());
            args.push(format!(
                "{}={}",
                param[0].as_str().unwrap(),
                param[1].as_str().unwrap()
            ));
        }
        for (flag, path) in [
            ("--out", &png),
            ("--error-image", &err),
            ("--stats", &stats),
        ] {
            args.extend([flag.into(), path.to_str().unwrap().to_owned()]);
        }
        succeeds(&args.iter().map(String::as_str).collect::<Vec<_>>());
        let rendered = read_json(&stats)["error"].clone();
        for key in ["mae_255", "p99_255", "max"] {
            let (a, b) = (
                number(&case["error"][key], key),
                number(&rendered[key], key),
            );
            assert!(
                (a - b).abs() <= 1e-6 * a.abs().max(1.0),
                "{view} {method} {key}: bench {a}, render {b}"
            );
        }
        assert_eq!(case["error"]["pixels_over_05"], rendered["pixels_over_05"]);
    }
}

/// The two scaling series at their quick size, three points each: the work rises from
/// point to point, the frame's pixels with it, every method is measured at every point
/// with finite times and memory, and the report, CSV and both plots are written.
#[test]
fn scaling_series_grow_and_are_reported() {
    let out = scratch("scaling");
    succeeds(&[
        "bench",
        "--quick",
        "--scenes",
        "glyph-count,px-per-em",
        "--scaling-points",
        "3",
        "--out",
        out.to_str().unwrap(),
    ]);
    let bench = glyphscope::bench::REPORTS.iter();
    for file in bench.chain(glyphscope::bench::SCALING_OUTPUTS) {
        let len = std::fs::metadata(out.join(file)).unwrap().len();
        assert!(len > 500, "{file}: {len} bytes");
    }
    for file in glyphscope::bench::SCENE_OUTPUTS {
        assert!(!out.join(file).exists(), "{file}: no scene was asked for");
    }
    let json = read_json(&out.join("bench.json"));
    assert!(json["cases"].as_array().unwrap().is_empty());
    let points = json["scaling"].as_array().unwrap();
    let gpu_methods: Vec<&str> = registry::benched().map(|m| m.name).collect();
    for series in ["glyph-count", "px-per-em"] {
        let of: Vec<&Value> = points.iter().filter(|p| p["series"] == series).collect();
        assert_eq!(of.len(), 3, "{series}");
        let figure = |p: &Value, key: &str| number(&p[key], &format!("{series} {key}"));
        for pair in of.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            assert!(
                figure(b, "work") > figure(a, "work"),
                "{series}: work rises"
            );
            let pixels = |p: &Value| figure(p, "width") * figure(p, "height");
            assert!(pixels(b) > pixels(a), "{series}: the frame grows");
            assert!(
                figure(b, "covered_px") > figure(a, "covered_px"),
                "{series}: more is covered"
            );
        }
        for p in &of {
            let what = format!("{series} at {}", p["work"]);
            let methods: Vec<&str> = p["costs"]
                .as_array()
                .unwrap()
                .iter()
                .map(|c| c["method"].as_str().unwrap())
                .collect();
            assert_eq!(methods, gpu_methods, "{what}: every GPU method, in order");
            for cost in p["costs"].as_array().unwrap() {
                let what = format!("{what} {}", cost["method"]);
                for key in ["cpu_frame_ms", "frame_ms"] {
                    assert!(number(&cost[key], &what) > 0.0, "{what} {key}");
                }
                // vello-cpu draws on the CPU: its GPU time, the harness's copy taken out,
                // can be nothing at all (0 at 256 px/em in one lavapipe run).
                let gpu_ms = number(&cost["gpu_ms"], &what);
                if cost["method"] == "vello-cpu" {
                    assert!(gpu_ms >= 0.0, "{what} gpu_ms");
                } else {
                    assert!(gpu_ms > 0.0, "{what} gpu_ms");
                }
                let held = cost["gpu_bytes"].as_u64().unwrap();
                assert!(held > 0, "{what}");
                // The two that cache glyphs in a texture: the atlas's coverage bitmaps,
                // msdf's distance fields.
                let textured = [registry::baseline().name, "msdf"];
                if textured.contains(&cost["method"].as_str().unwrap()) {
                    let cache = cost["cache_bytes"].as_u64().unwrap();
                    assert!(cache > 0 && cache < held, "{what}: its texture, within");
                } else {
                    assert!(cost["cache_bytes"].is_null(), "{what}: no glyph cache");
                }
            }
        }
    }
    // The glyph-count series draws the glyphs it was asked for, give or take the few
    // that shaping joins.
    let first = points
        .iter()
        .find(|p| p["series"] == "glyph-count")
        .unwrap();
    let drawn = number(&first["glyphs"], "glyphs");
    assert!((95.0..=100.0).contains(&drawn), "{drawn} glyphs for 100");

    let md = std::fs::read_to_string(out.join("bench.md")).unwrap();
    for expected in [
        "## Scaling",
        "### Against glyphs",
        "### Against px/em",
        "Slopes (time ∝ glyphs^k)",
        "Slopes (time ∝ px/em^k)",
        "By time (GPU + CPU per frame), the atlas is the cheapest at",
        "By memory (GPU bytes held), the atlas is the cheapest at",
    ] {
        assert!(md.contains(expected), "bench.md lacks '{expected}':\n{md}");
    }
    assert!(!md.contains("## Summary"), "no scene, no summary");
    let csv = std::fs::read_to_string(out.join("scaling.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 6 * gpu_methods.len());
}

#[test]
fn bad_input_fails_cleanly_before_measuring() {
    let file = scratch("a-file");
    std::fs::write(&file, "not a folder").unwrap();
    let out_dir = scratch("unused");
    let out_dir = out_dir.to_str().unwrap();
    for (args, expect) in [
        (
            vec!["--scenes", "nope", "--out", out_dir],
            "unknown scene 'nope'",
        ),
        (
            vec!["--methods", "bounds", "--out", out_dir],
            "no method 'bounds'",
        ),
        (vec!["--frames", "0", "--out", out_dir], "at least 1"),
        (
            vec!["--settle-cap=-1", "--out", out_dir],
            "--settle-cap must be a number of seconds",
        ),
        (
            vec!["--scaling-points", "1", "--out", out_dir],
            "--scaling-points must be from 2",
        ),
        (
            vec![
                "--scenes",
                "px-per-em",
                "--methods",
                "reference",
                "--out",
                out_dir,
            ],
            "measure GPU methods",
        ),
        (vec!["--out", file.to_str().unwrap()], "cannot write into"),
    ] {
        let mut all = vec!["bench", "--quick"];
        all.extend(&args);
        let result = run(&all);
        let stderr = String::from_utf8_lossy(&result.stderr);
        assert_eq!(result.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert!(stderr.contains(expect), "{args:?}: {stderr}");
    }
}

/// The "In motion" section on tiny: each method through the three paths, the exact mode
/// within what its still bound allows between two frames (|Δe| ≤ 2·max|e|, the page's
/// max 0.02: 0.04), the atlas's phase snapping far above it.
#[test]
fn the_bench_measures_methods_in_motion() {
    let out = scratch("motion");
    succeeds(&[
        "bench",
        "--quick",
        "--scenes",
        "tiny",
        "--methods",
        "winding,atlas",
        "--frames",
        "1",
        "--settle-cap",
        "0",
        "--out",
        out.to_str().unwrap(),
    ]);
    let json = read_json(&out.join("bench.json"));
    let motion = json["motion"].as_array().unwrap();
    assert_eq!(motion.len(), 2 * glyphscope::bench::motion::PATHS.len());
    let temporal = |method: &str, path: &str| -> (f64, f64) {
        let case = motion
            .iter()
            .find(|c| c["method"]["name"] == method && c["path"] == path)
            .unwrap_or_else(|| panic!("{method} on {path} missing"));
        let what = format!("{method} {path}");
        assert_eq!(
            case["temporal"]["pairs"],
            glyphscope::effort::Effort::QUICK.bench_motion_frames - 1
        );
        (
            number(&case["temporal"]["mae_255"], &what),
            number(&case["temporal"]["max"], &what),
        )
    };
    for (_, path) in glyphscope::bench::motion::PATHS {
        let path = glyphscope::motion::MotionPath::parse(path)
            .unwrap()
            .to_string();
        let (winding_mae, winding_max) = temporal("winding", &path);
        assert!(winding_max <= 0.04, "winding on {path}: {winding_max}");
        let (atlas_mae, _) = temporal("atlas", &path);
        assert!(
            atlas_mae > 10.0 * winding_mae,
            "{path}: atlas {atlas_mae}, winding {winding_mae}"
        );
    }
    let md = std::fs::read_to_string(out.join("bench.md")).unwrap();
    assert!(
        md.contains("## In motion") && md.contains("| winding | default |"),
        "{md}"
    );
}
