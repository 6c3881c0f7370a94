//! Where `winding`'s default (`aa=area`) spends a frame, per scene and view: the counts
//! behind its cost (`winding::CostCounts`) and the time of the shader cut short after each
//! stage ([`Stage`]), so that each stage's time is the difference from the one before.
//! Measured in every bench run that includes `winding`; the report's "Where winding's
//! time goes" section.

use std::fmt::Write as _;

use super::result::{BenchResult, Rounds, SceneCamera, WindingCost};
use crate::Error;
use crate::camera::Camera;
use crate::gpu::{Channels, CoverageTarget, GpuContext};
use crate::methods::frame;
use crate::methods::info::MethodInfo;
use crate::methods::winding::{self, Settings, Stage, Winding};
use crate::metrics;
use crate::scene::Scene;

/// The method this section breaks down: its stages are its shader's (`STAGE` in
/// crates/text/shaders/winding.wgsl) and its counts its own counting passes, which no registry row
/// describes, so this section names it; the run measures it wherever the method is
/// measured.
pub const METHOD: &MethodInfo = &winding::INFO;

/// Counts and stage times of `winding` at its default on `scene` through `camera`,
/// timed in `timing`'s rounds, each stage prepared anew in each round.
pub fn measure(
    gpu: &GpuContext,
    (scene_name, scene_camera): (&str, SceneCamera),
    scene: &Scene,
    camera: &Camera,
    timing: Rounds,
) -> Result<WindingCost, Error> {
    let mut whole = Winding::staged(Settings::default(), Stage::Full);
    whole.prepare(gpu, scene)?;
    let counts = whole.cost_counts(gpu, camera)?;
    let target = CoverageTarget::new(gpu, camera.width, camera.height, Channels::Coverage)?;
    let mut medians: [Vec<f64>; 5] = Default::default();
    for _ in 0..timing.rounds {
        for (stage, medians) in Stage::ALL.into_iter().zip(&mut medians) {
            let mut method = Winding::staged(Settings::default(), stage);
            method.prepare(gpu, scene)?;
            let per_round = timing.per_round;
            let times = frame::time_frames(
                gpu,
                &mut method,
                &target,
                camera,
                per_round.warmup,
                per_round.frames,
            )?;
            let Some(times) = times else {
                return Ok(WindingCost {
                    scene: scene_name.into(),
                    scene_camera,
                    counts,
                    stage_gpu_ms: None,
                });
            };
            medians.extend(metrics::median(times.iter().map(|t| t.gpu_ms)));
        }
    }
    let stage_gpu_ms = medians
        .iter()
        .map(|m| metrics::median(m.iter().copied()))
        .collect::<Option<Vec<f64>>>()
        .and_then(|m| <[f64; 5]>::try_from(m).ok());
    Ok(WindingCost {
        scene: scene_name.into(),
        scene_camera,
        counts,
        stage_gpu_ms,
    })
}

/// The report's section: the counts, then the stage times against the atlas's frame.
pub fn markdown(result: &BenchResult, md: &mut String) {
    if result.winding_costs.is_empty() {
        return;
    }
    let _ = writeln!(
        md,
        "## Where winding's time goes\n\n\
         `winding` at its default (`aa=area`), per scene and view. Counts, summed over \
         each frame: *quads* drawn; *fragments* shaded, per quad and per covered pixel \
         (quads overlap where glyphs are close); the share of fragments whose coverage \
         came out exactly 0 and exactly 1, and of those that integrated the 4×4 sub-pixel \
         grid; per fragment, the band entries *visited* and of those the curves wholly \
         *right* of the pixel (a term from their end heights), *across* it (the full \
         integral) and those adding *no term* (below, above or left).\n\n\
         | scene | view | quads | fragments / quad | fragments / covered px | coverage 0 | coverage 1 | grid | visited / fragment | right | across | no term |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    );
    for cost in &result.winding_costs {
        let c = &cost.counts;
        let share = |n: u64| format!("{:.0} %", 100.0 * c.per_fragment(n));
        let _ = writeln!(
            md,
            "| {} | {} | {} | {:.1} | {:.2} | {} | {} | {} | {:.2} | {:.2} | {:.2} | {:.2} |",
            cost.scene,
            cost.scene_camera.name(),
            c.quads,
            c.fragments as f64 / c.quads.max(1) as f64,
            c.fragments as f64 / c.covered_pixels.max(1) as f64,
            share(c.coverage_zero),
            share(c.coverage_one),
            share(c.grid),
            c.per_fragment(c.visited),
            c.per_fragment(c.right),
            c.per_fragment(c.across),
            c.per_fragment(c.no_term()),
        );
    }
    for cost in result.winding_costs.iter().filter(|c| c.counts.inexact > 0) {
        let _ = writeln!(
            md,
            "\n{} ({}): {} pixels' counts were past what the half-float target holds \
             exactly: their sums are approximate.",
            cost.scene,
            cost.scene_camera.name(),
            cost.counts.inexact
        );
    }
    let _ = writeln!(
        md,
        "\nGPU time of a frame with the shader cut short after each stage (`STAGE` in \
         crates/text/shaders/winding.wgsl), each the difference from the stage before: *quads* \
         (rasterizing and blending: fragments that write 1 at once), *setup* \
         (derivatives, the pixel's frame, its band), *walk* (each visited entry's curve \
         ends loaded, mapped into the pixel's frame and sorted into its zone), *right* \
         (the terms of the curves wholly right of the pixel), *across* (the curves across \
         it loaded whole and integrated, the fill rule, the grid where needed); *whole* is their sum, with its ratio to \
         the atlas's GPU + CPU frame in the same view of this run.\n\n\
         | scene | view | quads ms | setup ms | walk ms | right ms | across ms | whole ms | × atlas |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|"
    );
    for cost in &result.winding_costs {
        let Some(ms) = cost.stage_gpu_ms else {
            let _ = writeln!(
                md,
                "| {} | {} | not timed: no timestamp queries ||||||",
                cost.scene,
                cost.scene_camera.name()
            );
            continue;
        };
        let part = |k: usize| {
            let time = if k == 0 { ms[0] } else { ms[k] - ms[k - 1] };
            format!("{time:.2} ({:.0} %)", 100.0 * time / ms[4])
        };
        let atlas = result
            .baseline_in(&cost.scene, cost.scene_camera)
            .and_then(|m| m.frame_ms);
        let ratio = atlas.map_or("—".into(), |a| format!("{:.2}", ms[4] / a));
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {} | {:.2} | {ratio} |",
            cost.scene,
            cost.scene_camera.name(),
            part(0),
            part(1),
            part(2),
            part(3),
            part(4),
            ms[4],
        );
    }
    md.push('\n');
}
