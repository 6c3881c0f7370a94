//! Text in motion: the temporal error of a straight edge drifting 1/8 px a frame,
//! worked by hand, under the reference, a copy of it snapped to 4 sub-pixel phases,
//! and the atlas; and `glyphscope motion` as a user runs it.

mod common;

use common::binary::{self, scratch};
use common::{gpu, polygons, rect, single};
use glam::DVec2;
use glyphscope::camera::Camera;
use glyphscope::metrics::{self, TemporalError};
use glyphscope::motion::MotionPath;
use glyphscope::motion::run::{self, MethodSpec};
use glyphscope::reference;

/// A 6×2 image, 2 font units a pixel (the atlas caches at most 512 px/em), of a
/// rectangle whose left edge is the only one in view, at x = 2.3 + n/8 in frame n; it
/// covers both rows wholly.
fn drifting_edge() -> (glyphscope::scene::Scene, Camera, MotionPath) {
    let scene = single(polygons(&[rect(0.0, -100.0, 100.0, 100.0).as_slice()]));
    let camera = Camera::new(6, 2, 500.0, DVec2::new(2.3, 1.0));
    (scene, camera, MotionPath::parse("drift:0.125,0").unwrap())
}

/// The hand-worked change of each frame pair: the edge sweeps 1/8 of a pixel, the copy
/// snapped to the nearest 1/4 px jumps a quarter every other frame (2.25, 2.5, 2.5,
/// 2.75, 2.75, 3, 3, 3.25, 3.25), so in each row the pixel under the edge is off by
/// 1/8 — except from frame 5 to 6, where the edge crosses x = 3 between pixels 2
/// (−0.075) and 3 (−0.05) and the copy stays at 3: the same 1/8 in two pixels.
const PAIRS: usize = 8;
const HAND_MAE_255: f64 = 0.125 / 6.0 * 255.0;

fn hand_max(pair: usize) -> f64 {
    if pair == 5 { 0.075 } else { 0.125 }
}

fn check_against_hand(pairs: &[TemporalError], tolerance: f64, what: &str) {
    assert_eq!(pairs.len(), PAIRS, "{what}");
    for (k, t) in pairs.iter().enumerate() {
        assert!(
            (t.mae_255 - HAND_MAE_255).abs() <= tolerance * 255.0 / 6.0,
            "{what}, pair {k}: MAE {}",
            t.mae_255
        );
        assert!(
            (t.max - hand_max(k)).abs() <= tolerance,
            "{what}, pair {k}: max {}",
            t.max
        );
        // One pixel a row over 0.1, none in pair 5.
        let over = if k == 5 { 0 } else { 2 };
        assert_eq!(t.pixels_over, over, "{what}, pair {k}");
    }
}

#[test]
fn a_drifting_edge_has_the_hand_worked_temporal_error() {
    let (scene, base, path) = drifting_edge();
    let frames: Vec<_> = (0..=PAIRS as i64)
        .map(|n| reference::rasterize(&scene, &path.camera_at(&base, n)).unwrap())
        .collect();
    let snapped: Vec<_> = (0..=PAIRS as i64)
        .map(|n| {
            let mut camera = path.camera_at(&base, n);
            camera.origin.x = (camera.origin.x * 4.0).round() / 4.0;
            reference::rasterize(&scene, &camera).unwrap()
        })
        .collect();
    let mut snapping = Vec::new();
    for k in 0..PAIRS {
        let reference = [&frames[k], &frames[k + 1]];
        // Δr − Δr: a metric that forgot to subtract the reference's change (|Δm|) would
        // count the edge's 1/8 here.
        let own = metrics::temporal(reference, reference).unwrap();
        assert_eq!(
            (own.mae_255, own.max),
            (0.0, 0.0),
            "the reference against itself, pair {k}"
        );
        snapping.push(metrics::temporal([&snapped[k], &snapped[k + 1]], reference).unwrap());
    }
    check_against_hand(&snapping, 1e-6, "snapped to 4 phases");
    // Edge pixels, by hand: the pixel under the edge in each row (partial in the
    // reference), and in pair 5 both pixels 2 and 3 (the reference partial in one frame
    // each, where the copy is whole).
    for (k, t) in snapping.iter().enumerate() {
        assert_eq!(t.edge.pixels, if k == 5 { 4 } else { 2 }, "pair {k}");
    }
}

/// The atlas (4×4 sub-pixel phases) is that snapped copy, within its texture's 8 bits.
#[test]
fn the_atlas_snaps_as_worked_by_hand_and_the_reference_does_not() {
    let (scene, base, path) = drifting_edge();
    let methods = [
        MethodSpec::parse("reference").unwrap(),
        MethodSpec::parse("atlas").unwrap(),
    ];
    let result = run::run(
        Some(gpu()),
        &scene,
        &base,
        &path,
        PAIRS + 1,
        &methods,
        |_| {},
    )
    .unwrap();
    let pairs = |k: usize| -> Vec<TemporalError> {
        result.methods[k]
            .frames
            .iter()
            .filter_map(|f| f.temporal)
            .collect()
    };
    // The reference as a method: each frame paired with the reference's same two frames
    // (a run that paired it with the wrong ones would see the edge move).
    assert!(pairs(0).iter().all(|t| t.mae_255 == 0.0 && t.max == 0.0));
    assert_eq!(result.methods[0].temporal.pairs, PAIRS);
    check_against_hand(&pairs(1), 2.0 / 255.0, "atlas");
}

#[test]
fn the_motion_command_writes_its_report_and_animation() {
    let out = scratch("run");
    let result = binary::run(&[
        "motion",
        "--text",
        "Wave",
        "--size",
        "11",
        "--path",
        "drift:0.0625,0.03+rotate:0.5",
        "--frames",
        "6",
        "--method",
        "winding,atlas,reference",
        "--magnify",
        "8",
        "--out",
        out.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(result.status.success(), "{stderr}");
    let csv = std::fs::read_to_string(out.join("motion.csv")).unwrap();
    // A header and 6 frames of 3 methods; the first frame of each has no temporal error.
    assert_eq!(csv.lines().count(), 1 + 18);
    assert!(
        csv.lines()
            .nth(1)
            .unwrap()
            .starts_with("0,winding,\"default\"")
    );
    let md = std::fs::read_to_string(out.join("motion.md")).unwrap();
    assert!(md.contains("| reference | 0.00 (0.000) | 0.000 |"), "{md}");
    let svg = std::fs::read_to_string(out.join("temporal.svg")).unwrap();
    assert!(svg.contains("atlas") && svg.contains("<polyline"));
    // An APNG: its acTL chunk says 6 frames.
    let png = std::fs::read(out.join("motion.png")).unwrap();
    let actl = png
        .windows(4)
        .position(|w| w == b"acTL")
        .expect("an animation chunk");
    assert_eq!(
        u32::from_be_bytes(png[actl + 4..actl + 8].try_into().unwrap()),
        6
    );
    assert!(String::from_utf8_lossy(&result.stdout).contains("| winding |"));
}

#[test]
fn the_motion_command_refuses_bad_input_in_one_line() {
    let out = scratch("bad");
    for (args, expect) in [
        (vec!["--path", "spin:3"], "unknown motion 'spin'"),
        (vec!["--path", "zoom:0"], "must be positive"),
        (vec!["--frames", "1"], "frames"),
        (vec!["--method", "nonesuch"], "nonesuch"),
        (vec!["--method", "winding:aa"], "KEY=VALUE"),
        (vec!["--method", "winding:aa=nope"], "aa"),
        (vec!["--path", "sway:80,4", "--tilt", "30"], "frame 1"),
        (vec!["--animate", "3"], "--animate 3"),
        (vec!["--focus", "900,9"], "outside"),
    ] {
        let mut all = vec![
            "motion",
            "--text",
            "a",
            "--size",
            "12",
            "--method",
            "atlas,winding",
        ];
        all.extend(&args);
        if !args.contains(&"--frames") {
            all.extend(["--frames", "3"]);
        }
        all.extend(["--out", out.to_str().unwrap()]);
        let result = binary::run(&all);
        let stderr = String::from_utf8_lossy(&result.stderr);
        assert_eq!(result.status.code(), Some(2), "{args:?}: {stderr}");
        // The first line says it (clap adds a usage hint under its own).
        let first = stderr.lines().next().unwrap_or_default();
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert!(first.contains(expect), "{args:?}: {first} lacks {expect:?}");
    }
}
