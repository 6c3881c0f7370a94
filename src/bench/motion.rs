//! Text in motion, in the bench: on the page and tiny scenes, every method at its
//! default drawn through three camera paths — drifting 1/16 px a frame along x and
//! along 30°, and turning 0.25° a frame — each frame against the reference's, with its
//! temporal error (see [`crate::metrics::temporal`]). The report's "In motion" section;
//! `glyphscope motion` reruns any one of them with its per-frame figures and pictures.

use std::fmt::Write as _;

use super::method_settings;
use super::result::{BenchResult, MotionCase};
use crate::Error;
use crate::camera::Camera;
use crate::gpu::GpuContext;
use crate::motion::MotionPath;
use crate::motion::run::{self, MethodSpec};
use crate::scene::Scene;

/// The scenes measured in motion.
pub const SCENES: [&str; 2] = ["page", "tiny"];

/// The paths: a name for the table, and the path in `--path`'s grammar. 1/16 px a frame
/// falls between every atlas phase (4 a pixel); along 30° it crosses pixel rows too.
pub const PATHS: [(&str, &str); 3] = [
    ("drift x", crate::motion::DRIFT_X),
    ("drift 30°", crate::motion::DRIFT_30),
    ("rotate", crate::motion::TURN),
];

/// Draws `methods` through every path of [`PATHS`] from `camera`, `frames` frames each
/// (the run's `Effort::bench_motion_frames`).
pub fn measure(
    gpu: &GpuContext,
    scene_name: &str,
    scene: &Scene,
    camera: &Camera,
    methods: &[MethodSpec],
    frames: usize,
) -> Result<Vec<MotionCase>, Error> {
    let mut cases = Vec::new();
    for (name, path) in PATHS {
        let path = MotionPath::parse(path)?;
        let result = run::run(Some(gpu), scene, camera, &path, frames, methods, |_| {})?;
        cases.extend(result.methods.into_iter().map(|m| MotionCase {
            scene: scene_name.into(),
            path_name: name.into(),
            path: path.to_string(),
            frames,
            still_mae_255: m.still_mae_255(),
            still_max: m.still_max(),
            temporal: m.temporal,
            refused: m.refused,
            method: m.method,
        }));
    }
    Ok(cases)
}

/// The report's section: per scene, a row per method, a column per path.
pub fn markdown(result: &BenchResult, md: &mut String) {
    if result.motion.is_empty() {
        return;
    }
    let frames = result.motion[0].frames;
    let _ = writeln!(
        md,
        "## In motion\n\nEach method at its default drawn through {frames} frames of three \
         camera paths, each frame against the reference's: *still* is the mean of the \
         MAE of the first path's frames (the largest pixel error of any of them in brackets); the others are the \
         temporal error, per pixel the method's change from one frame to the next less the \
         reference's, |Δm − Δr|: its mean over frame pairs in 1/255 and, in brackets, the \
         largest. A method exact in every frame has none; one that snaps or flips as text \
         moves has much, though its still error may be small. Paths (`--path`): {}. \
         `glyphscope motion --case SCENE --path PATH --method …` reruns one with its \
         per-frame figures, plot and animated picture.\n",
        PATHS
            .iter()
            .map(|(name, path)| format!("{name} `{path}`"))
            .collect::<Vec<_>>()
            .join(", ")
    );
    for scene in SCENES {
        let cases: Vec<&MotionCase> = result.motion.iter().filter(|c| c.scene == scene).collect();
        if cases.is_empty() {
            continue;
        }
        let _ = writeln!(
            md,
            "### {scene}\n\n| method | settings | still MAE /255 (max) | {} |\n|---|---|---:|{}",
            PATHS.map(|p| p.0).join(" | "),
            "---:|".repeat(PATHS.len())
        );
        let mut seen: Vec<&MethodSpec> = Vec::new();
        for case in &cases {
            if seen.contains(&&case.method) {
                continue;
            }
            seen.push(&case.method);
            let of_method: Vec<&&MotionCase> =
                cases.iter().filter(|c| c.method == case.method).collect();
            // Over the first path's frames.
            let still = match of_method.first() {
                Some(c) if c.refused.is_none() => {
                    format!("{:.2} ({:.3})", c.still_mae_255, c.still_max)
                }
                _ => "n/a".into(),
            };
            let columns: Vec<String> = PATHS
                .iter()
                .map(
                    |(name, _)| match of_method.iter().find(|c| c.path_name == *name) {
                        Some(c) if c.refused.is_some() => "n/a".into(),
                        Some(c) => format!("{:.3} ({:.3})", c.temporal.mae_255, c.temporal.max),
                        None => "—".into(),
                    },
                )
                .collect();
            let _ = writeln!(
                md,
                "| {} | {} | {still} | {} |",
                case.method.name,
                method_settings::setting_name(&case.method.params),
                columns.join(" | ")
            );
        }
        let refused: Vec<String> = cases
            .iter()
            .filter_map(|c| {
                c.refused
                    .as_ref()
                    .map(|r| format!("{} on `{}`: {r}", c.method.name, c.path))
            })
            .collect();
        if !refused.is_empty() {
            let _ = writeln!(md, "\nn/a: {}.", refused.join("; "));
        }
        md.push('\n');
    }
}
