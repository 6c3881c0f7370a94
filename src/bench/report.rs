//! The bench's outputs as text: a Markdown report (a table per scene and view, and the
//! fastest method at each error level), CSV, and JSON.

use std::fmt::Write;

use super::method_settings::{CONTRAST, SHIPPED, setting_name};
use super::numbers::{kb_or_mb, sig};
use super::result::{BenchResult, Measurement, Refusal, SceneCamera, SceneInfo};
use super::{motion, scaling, scenes, winding_cost};
use crate::intervals::Interval;
use crate::methods::registry;

/// Mean-error levels (1/255) at which the report names the fastest method.
pub const ERROR_LEVELS: &[f64] = &[0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0];

/// A case's time per frame (GPU + CPU) over the atlas baseline's in the same scene and
/// view: the median of the rounds' ratios where the rounds gave one (`settle`), else
/// the ratio of the medians (1 for the baseline itself).
pub fn ratio_to_baseline(result: &BenchResult, case: &Measurement) -> Option<f64> {
    if case.is_reference() {
        return None;
    }
    if let Some(r) = case.ratio_atlas {
        return Some(r.value);
    }
    let baseline = result.baseline_in(&case.scene, case.scene_camera)?;
    Some(case.frame_ms? / baseline.frame_ms?)
}

/// A case's time per frame (GPU + CPU) over [`SHIPPED`]'s default (glyphon) in the same
/// scene and view, where glyphon drew it; as [`ratio_to_baseline`].
pub fn ratio_to_shipped(result: &BenchResult, case: &Measurement) -> Option<f64> {
    if case.is_reference() {
        return None;
    }
    if let Some(r) = case.ratio_glyphon {
        return Some(r.value);
    }
    let shipped = result.default_case_in(SHIPPED, &case.scene, case.scene_camera)?;
    Some(case.frame_ms? / shipped.frame_ms?)
}

/// A ratio as a cell: `2.67 (2.60–2.75)` with its 95 % interval, `*` after it where
/// the interval is wider than ±5 % (`intervals::TARGET`); the bare ratio where the rounds
/// gave no interval (the divisor itself); `suffix` after each figure.
fn ratio_cell(interval: Option<Interval>, value: Option<f64>, suffix: &str) -> Option<String> {
    match interval {
        Some(i) => Some(format!(
            "{:.2}{suffix} ({:.2}–{:.2}){}",
            i.value,
            i.low,
            i.high,
            if i.settled { "" } else { "*" }
        )),
        None => value.map(|v| format!("{v:.2}{suffix}")),
    }
}

/// [`ratio_to_baseline`] as a cell, with its interval; `—` for the reference.
pub fn atlas_cell(result: &BenchResult, case: &Measurement, suffix: &str) -> String {
    ratio_cell(case.ratio_atlas, ratio_to_baseline(result, case), suffix).unwrap_or("—".into())
}

/// [`ratio_to_shipped`] as a cell, with its interval: `n/a` where glyphon cannot draw
/// the view (the peers' table says why), `—` where it was not run.
pub fn shipped_cell(result: &BenchResult, case: &Measurement, suffix: &str) -> String {
    let refused = result
        .refusal_in(SHIPPED, &case.scene, case.scene_camera)
        .is_some();
    match ratio_cell(case.ratio_glyphon, ratio_to_shipped(result, case), suffix) {
        Some(cell) => cell,
        None if refused => "n/a".into(),
        None => "—".into(),
    }
}

/// The fastest GPU case of `cases` (by GPU + CPU time per frame) whose mean error is at
/// most `level` (1/255) and which has no pixel off by more than 0.5: a method with
/// rare full-pixel artifacts is not "accurate on average".
pub fn fastest_within<'a>(cases: &[&'a Measurement], level: f64) -> Option<&'a Measurement> {
    cases
        .iter()
        .copied()
        .filter(|c| !c.is_reference() && c.error.mae_255 <= level && c.error.pixels_over_05 == 0)
        .filter_map(|c| Some((c, c.frame_ms?)))
        .min_by(|(_, a), (_, b)| a.total_cmp(b))
        .map(|(c, _)| c)
}

fn refusals_of<'a>(result: &'a BenchResult, info: &SceneInfo) -> Vec<&'a Refusal> {
    result
        .refusals
        .iter()
        .filter(|r| r.scene == info.name && r.scene_camera == info.scene_camera)
        .collect()
}

fn cases_of<'a>(result: &'a BenchResult, info: &SceneInfo) -> Vec<&'a Measurement> {
    result
        .measurements
        .iter()
        .filter(|c| c.scene == info.name && c.scene_camera == info.scene_camera)
        .collect()
}

pub fn markdown(result: &BenchResult) -> String {
    let mut md = String::new();
    let clock = result.gpu_clock.as_deref().unwrap_or("not measured");
    let _ = writeln!(md, "# glyphscope bench\n");
    if result.measurements.is_empty() {
        let _ = writeln!(
            md,
            "Device: **{}**. GPU time per frame by {clock}.\n",
            result.adapter
        );
    } else {
        scene_sections(result, clock, &mut md);
    }
    motion::markdown(result, &mut md);
    winding_cost::markdown(result, &mut md);
    scaling::markdown(&result.scaling, result.scaling_timing, &mut md);
    md
}

/// The standard scenes' part of the report: how they were timed, the summary, and a
/// table per scene and view.
fn scene_sections(result: &BenchResult, clock: &str, md: &mut String) {
    let timed: Vec<&Measurement> = result
        .measurements
        .iter()
        .filter(|c| !c.is_reference())
        .collect();
    let most_rounds = timed.iter().map(|c| c.rounds).max().unwrap_or(0);
    let most_warmup = timed
        .iter()
        .filter_map(|c| c.warmup_frames)
        .max()
        .unwrap_or(0);
    let batched: Vec<String> = timed
        .iter()
        .filter(|c| c.frames_per_submission.is_some_and(|k| k > 1))
        .map(|c| {
            format!(
                "{} {} on {} {} ({})",
                c.method,
                c.settings(),
                c.scene,
                c.scene_camera.name(),
                c.frames_per_submission.unwrap_or(1)
            )
        })
        .collect();
    let unsettled = timed
        .iter()
        .filter(|c| {
            [c.ratio_atlas, c.ratio_glyphon]
                .iter()
                .flatten()
                .any(|r| !r.settled)
        })
        .count();
    let _ = writeln!(
        md,
        "Device: **{}**. {} GPU time per frame by {clock}. The cases of a view are timed \
         in interleaved rounds, each preparing every method anew and timing {} frames \
         after at least {} warm-up frames (more while a frame was still faster than all \
         before it by 5 %: up to {most_warmup} here); a frame under {} ms is timed several \
         to a submission and a pair of timestamps, each its share ({}). After {} rounds, the cases whose ratio to the atlas or to glyphon has a 95 % \
         interval (a bootstrap over the rounds of the median of the rounds' ratios) wider \
         than ±{} % are timed on, with the atlas and glyphon, for up to {} s each{}: up \
         to {most_rounds} rounds here, and {unsettled} case{} left unsettled, marked `*`. \
         **× atlas** is GPU + CPU time per frame over the atlas baseline's (`atlas` at its \
         default, 4×4 sub-pixel phases, cached at the scene's own size) in the same scene, \
         view and round, the median over the rounds with its interval in brackets: \
         compare methods by these ratios, not by absolute times, which belong to this \
         device alone. *GPU ms*: the median of the rounds' medians, fastest–slowest frame \
         of all in brackets; *CPU/frame*: the CPU's work of recording each frame (the \
         method's culling, sorting, meshing and instance writes).\n",
        result.adapter,
        crate::info::adapter_class_sentence(&result.adapter_class),
        result.timing.per_round.frames,
        result.timing.per_round.warmup,
        crate::methods::frame::SHORT_FRAME_MS,
        if batched.is_empty() {
            "none was here".to_owned()
        } else {
            format!("frames per submission: {}", batched.join(", "))
        },
        result.timing.rounds,
        crate::intervals::TARGET * 100.0,
        result.settle_cap_s,
        if result.quick { " (`--quick`)" } else { "" },
        if unsettled == 1 { "" } else { "s" },
    );
    let _ = writeln!(
        md,
        "Columns: *CPU prep*: the method's `prepare` (the reference: its rasterization); \
         *GPU mem*: memory the method holds once it has drawn; *curves/px*: curves \
         evaluated per covered pixel, mean (max), for methods with that notion; *points*: \
         outline points tessellated; errors against the exact reference: *MAE* and *p99* \
         of the absolute error in 1/255 over all pixels, *edge MAE* over the edge pixels \
         alone (partial in the reference or the method, or differing), *max* as coverage, \
         *> 0.5*: pixels off by more than half. *Fastest at each error level* ranks by GPU \
         + CPU time per frame, among the cases with no pixel off by more than 0.5.\n"
    );
    summary(result, md);
    peers_summary(result, md);
    for info in &result.scenes {
        let cases = cases_of(result, info);
        if cases.is_empty() {
            continue;
        }
        let view = match info.scene_camera {
            SceneCamera::Own => String::new(),
            SceneCamera::Moved => format!(
                ", after caching: zoomed {}×, turned {}°",
                scenes::MOVED_ZOOM,
                scenes::MOVED_ROTATION_DEG
            ),
        };
        let _ = writeln!(md, "## {}{view}\n", info.name);
        let _ = writeln!(
            md,
            "{}. {}×{} px, {} px/em, {} glyphs ({} distinct); the atlas caches at {} px/em.\n",
            capitalized(&info.about),
            info.width,
            info.height,
            info.size_px_per_em,
            info.instances,
            info.distinct_glyphs,
            info.atlas_cache_px_per_em
        );
        md.push_str(
            "| method | settings | GPU ms | CPU/frame ms | × atlas | × glyphon | CPU prep ms | \
             GPU mem | curves/px | points | MAE /255 | edge MAE /255 | p99 /255 | max | > 0.5 |\n\
             |---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
        );
        for case in &cases {
            let time = match (case.gpu_ms, case.gpu_ms_range) {
                (Some(ms), Some((lo, hi))) => format!("{} ({}–{})", sig(ms), sig(lo), sig(hi)),
                (Some(ms), None) => format!("{} (CPU)", sig(ms)),
                _ => "—".into(),
            };
            let _ = writeln!(
                md,
                "| {} | {} | {time} | {} | {} | {} | {} | {} | {} | {} | {:.2} | {:.2} | {:.1} \
                 | {:.3} | {} |",
                case.method,
                case.settings(),
                case.cpu_frame_ms.map_or("—".into(), sig),
                atlas_cell(result, case, ""),
                shipped_cell(result, case, ""),
                case.cpu_render_ms
                    .map_or_else(|| sig(case.cpu_prepare_ms), sig),
                kb_or_mb(case.gpu_bytes),
                case.curves_per_pixel.map_or("—".into(), |c| format!(
                    "{:.1} ({})",
                    c.mean,
                    c.max_text()
                )),
                case.mesh_points.map_or("—".into(), |p| p.to_string()),
                case.error.mae_255,
                case.error.edge.mae_255,
                case.error.p99_255,
                case.error.max,
                case.error.pixels_over_05,
            );
        }
        for refusal in refusals_of(result, info) {
            let _ = writeln!(
                md,
                "| {} | {} | n/a — {} | | | | | | | | | | | | |",
                refusal.method,
                setting_name(&refusal.params),
                refusal.reason
            );
        }
        for case in cases.iter().filter(|c| c.layout_offset.is_some()) {
            let o = case.layout_offset.expect("filtered");
            let _ = writeln!(
                md,
                "\n{}'s own layout against glyphscope's shaping, over {} glyphs ({} with \
                 another glyph id): pens {:.3} px apart on average (max {:.3}) as laid out, \
                 {:.3} px (max {:.3}) where it draws them after snapping to its pixel grid; \
                 its errors above include that placement.",
                case.method,
                o.glyphs,
                o.mismatched,
                o.laid_out_mean_px,
                o.laid_out_max_px,
                o.placed_mean_px,
                o.placed_max_px
            );
        }
        md.push_str(
            "\nFastest at each error level (no pixel off by more than 0.5):\n\n\
             | MAE ≤ /255 | fastest | settings | GPU + CPU ms | × atlas | × glyphon |\n\
             |---:|---|---|---:|---:|---:|\n",
        );
        for &level in ERROR_LEVELS {
            match fastest_within(&cases, level) {
                Some(c) => {
                    let _ = writeln!(
                        md,
                        "| {level} | {} | {} | {} | {} | {} |",
                        c.method,
                        c.settings(),
                        c.frame_ms.map_or("—".into(), sig),
                        atlas_cell(result, c, ""),
                        shipped_cell(result, c, ""),
                    );
                }
                None => {
                    let _ = writeln!(md, "| {level} | none | | | | |");
                }
            }
        }
        md.push('\n');
    }
}

/// One line per scene and view: the baseline's error, the most accurate method, and
/// the fastest within two error levels.
fn summary(result: &BenchResult, md: &mut String) {
    const LEVELS: [f64; 2] = [0.5, 1.0];
    md.push_str(
        "## Summary\n\nPer scene and view (*moved*: after caching, zoomed and turned): the \
         atlas baseline's error, the most accurate GPU case, and the fastest case within a \
         mean error of 0.5/255 and 1/255 with no pixel off by more than 0.5, with its GPU + \
         CPU time per frame over the atlas's and over glyphon's (`n/a` where glyphon cannot \
         draw the view).\n\n\
         | scene | view | atlas MAE /255 (max) | most accurate | fastest, MAE ≤ 0.5 | fastest, MAE ≤ 1 |\n\
         |---|---|---:|---|---|---|\n",
    );
    let named = |c: &Measurement| format!("{} {}", c.method, c.settings()).replace(" default", "");
    for info in &result.scenes {
        let cases = cases_of(result, info);
        let gpu: Vec<&Measurement> = cases
            .iter()
            .copied()
            .filter(|c| !c.is_reference())
            .collect();
        if gpu.is_empty() {
            continue;
        }
        let baseline = cases
            .iter()
            .find(|c| c.is_baseline())
            .map_or("—".into(), |c| {
                format!("{:.2} ({:.2})", c.error.mae_255, c.error.max)
            });
        let best = gpu
            .iter()
            .min_by(|a, b| a.error.mae_255.total_cmp(&b.error.mae_255))
            .map_or("—".into(), |c| {
                format!("{} ({:.2})", named(c), c.error.mae_255)
            });
        let fastest = LEVELS.map(|level| {
            fastest_within(&cases, level).map_or("none".into(), |c| {
                format!(
                    "{} ({} × atlas, {} × glyphon)",
                    named(c),
                    atlas_cell(result, c, ""),
                    shipped_cell(result, c, "")
                )
            })
        });
        let view = info.scene_camera.name();
        let _ = writeln!(
            md,
            "| {} | {view} | {baseline} | {best} | {} | {} |",
            info.name, fastest[0], fastest[1]
        );
    }
    md.push('\n');
}

/// Winding's default beside each peer's default, per scene and view: GPU + CPU time per
/// frame over the atlas's, and the error, or the peer's refusal.
fn peers_summary(result: &BenchResult, md: &mut String) {
    let peers: Vec<&str> = registry::METHODS
        .iter()
        .filter(|m| m.is_peer())
        .map(|m| m.name)
        .collect();
    let ours = CONTRAST.name;
    if !result
        .measurements
        .iter()
        .any(|c| peers.contains(&c.method.as_str()))
        && result.refusals.is_empty()
    {
        return;
    }
    let _ = write!(
        md,
        "## {} against the peers\n\nEach at its default: × atlas (GPU + CPU per frame \
         over the atlas's, this run) · × glyphon (over glyphon's) · MAE /255 · edge MAE /255 · max · pixels > 0.5, or \
         why the peer cannot draw the view. The peers draw into 8-bit textures: up to \
         1/510 per edge pixel is their floor.\n\n| scene | view | {ours} |",
        capitalized(ours)
    );
    for peer in &peers {
        let _ = write!(md, " {peer} |");
    }
    let _ = writeln!(md, "\n|---|---|---|{}", "---|".repeat(peers.len()));
    for info in &result.scenes {
        let cases = cases_of(result, info);
        let refusals = refusals_of(result, info);
        let cell = |method: &str| -> String {
            if let Some(c) = cases
                .iter()
                .find(|c| c.method == method && c.settings() == "default")
            {
                format!(
                    "{} · {} · {:.2} · {:.2} · {:.3} · {}",
                    atlas_cell(result, c, "×"),
                    shipped_cell(result, c, "×"),
                    c.error.mae_255,
                    c.error.edge.mae_255,
                    c.error.max,
                    c.error.pixels_over_05
                )
            } else if let Some(r) = refusals
                .iter()
                .find(|r| r.method == method && setting_name(&r.params) == "default")
            {
                format!("n/a — {}", r.reason)
            } else {
                "not run".into()
            }
        };
        let view = info.scene_camera.name();
        let _ = write!(md, "| {} | {view} | {} |", info.name, cell(ours));
        for peer in &peers {
            let _ = write!(md, " {} |", cell(peer));
        }
        md.push('\n');
    }
    md.push('\n');
}

/// One line per measurement, and one per view a peer refused (its reason in the last
/// column); `settings` quoted, since it holds commas.
pub fn csv(result: &BenchResult) -> String {
    let mut out = String::from(
        "scene,view,method,settings,gpu_ms,gpu_ms_min,gpu_ms_max,cpu_frame_ms,frame_ms,\
         ratio_to_atlas,ratio_to_atlas_low,ratio_to_atlas_high,ratio_to_atlas_settled,\
         ratio_to_glyphon,ratio_to_glyphon_low,ratio_to_glyphon_high,ratio_to_glyphon_settled,\
         rounds,cpu_prepare_ms,cpu_render_ms,mesh_build_ms,gpu_bytes,\
         curves_per_pixel_mean,curves_per_pixel_max,mesh_points,mae_255,p99_255,rmse_255,max,\
         pixels_over_025,pixels_over_05,pixels,invalid_pixels,edge_pixels,edge_mae_255,\
         edge_max,edge_pixels_over_025,edge_pixels_over_05,refused\n",
    );
    let opt = |v: Option<f64>| v.map_or(String::new(), |v| v.to_string());
    for c in &result.measurements {
        let e = &c.error;
        let _ = writeln!(
            out,
            "{},{},{},\"{}\",{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},\
             {},{},{},{},{},{},{},{},{},{},{},{},",
            c.scene,
            serde_json::to_value(c.scene_camera)
                .expect("a view serializes")
                .as_str()
                .unwrap_or(""),
            c.method,
            c.settings(),
            opt(c.gpu_ms),
            opt(c.gpu_ms_range.map(|r| r.0)),
            opt(c.gpu_ms_range.map(|r| r.1)),
            opt(c.cpu_frame_ms),
            opt(c.frame_ms),
            opt(ratio_to_baseline(result, c)),
            opt(c.ratio_atlas.map(|r| r.low)),
            opt(c.ratio_atlas.map(|r| r.high)),
            c.ratio_atlas
                .map_or(String::new(), |r| r.settled.to_string()),
            opt(ratio_to_shipped(result, c)),
            opt(c.ratio_glyphon.map(|r| r.low)),
            opt(c.ratio_glyphon.map(|r| r.high)),
            c.ratio_glyphon
                .map_or(String::new(), |r| r.settled.to_string()),
            c.rounds,
            c.cpu_prepare_ms,
            opt(c.cpu_render_ms),
            opt(c.mesh_build_ms),
            c.gpu_bytes,
            opt(c.curves_per_pixel.map(|p| p.mean)),
            c.curves_per_pixel
                .map_or(String::new(), |p| p.max.to_string()),
            c.mesh_points.map_or(String::new(), |p| p.to_string()),
            e.mae_255,
            e.p99_255,
            e.rmse_255,
            e.max,
            e.pixels_over_025,
            e.pixels_over_05,
            e.pixels,
            e.invalid_pixels,
            e.edge.pixels,
            e.edge.mae_255,
            e.edge.max,
            e.edge.pixels_over_025,
            e.edge.pixels_over_05,
        );
    }
    // What a peer could not draw: a row with its reason, never left out.
    for r in &result.refusals {
        let _ = writeln!(
            out,
            "{},{},{},\"{}\",{}\"n/a: {}\"",
            r.scene,
            serde_json::to_value(r.scene_camera)
                .expect("a view serializes")
                .as_str()
                .unwrap_or(""),
            r.method,
            setting_name(&r.params),
            ",".repeat(34),
            r.reason.replace('"', "'")
        );
    }
    out
}

pub fn json(result: &BenchResult) -> String {
    serde_json::to_string_pretty(result).expect("bench results serialize") + "\n"
}

fn capitalized(s: &str) -> String {
    let mut chars = s.chars();
    chars
        .next()
        .map_or(String::new(), |c| c.to_uppercase().chain(chars).collect())
}
