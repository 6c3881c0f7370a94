//! How each method's cost grows with the work: two series, each method at its default
//! settings at every point of one run.
//!
//! - `glyph-count`: the page's text at the page's size, cut after 100 → 30 000 glyphs,
//!   framed to its ink, so the frame's pixels grow with the glyphs;
//! - `px-per-em`: one word at 4 → 4 096 px/em, framed to its ink but at most
//!   [`MAX_FRAME_SIDE`] a side, so the glyphs and their curves stay fixed while the
//!   pixels grow.
//!
//! Per point and method: GPU and CPU time per frame and GPU memory (the atlas's glyph
//! cache apart too); per series, a fitted log–log slope per method and where the atlas
//! stops being the cheapest, by time and by memory.

use std::fmt::Write;

use glam::DVec2;
use indicatif::ProgressBar;

use super::method_settings;
use super::numbers::{kb_or_mb, sig};
use super::result::{MethodCost, ScalingPoint, Series};
use super::scenes::{PAGE_PX_PER_EM, PAGE_TEXT};
use crate::Error;
use crate::effort::Effort;
use crate::gpu::GpuContext;
use crate::measure::{self, FrameTiming};
use crate::methods::info::MethodInfo;
use crate::methods::registry;
use crate::metrics;
use crate::view_args::ViewArgs;

/// The word the `px-per-em` series enlarges: capitals, ascenders and descenders, so
/// its frame is a full line's height.
pub const WORD: &str = "Glyphs";

/// The `px-per-em` series frames the word to its ink, but at most this many pixels a
/// side (a window centred on the ink beyond): the largest sizes then draw only part of
/// the word, and their pixels grow more slowly than the size squared.
pub const MAX_FRAME_SIDE: u32 = 4096;

/// The most points a series takes: more only repeats sizes that round alike.
pub const MAX_POINTS: usize = 64;

/// Untimed frames per point and method before the timed ones (shaders compile on the
/// first frames), in a full run and with `--quick` alike; how many are timed is the
/// run's [`Effort::bench_scaling_frames`].
pub const WARMUP_FRAMES: usize = 1;

/// A method whose slope against the covered pixels' is at least this fraction of it
/// grows with the pixels…
const FOLLOWS_PIXELS: f64 = 2.0 / 3.0;
/// …and at most this fraction, with the curves (which stay fixed as the size grows).
const FOLLOWS_CURVES: f64 = 1.0 / 3.0;
/// A series separates pixels from curves only where the covered pixels grow at least
/// this much faster than the glyphs do.
const SEPARATES: f64 = 0.5;

/// What each series measures (its names: [`Series`] in `result`).
impl Series {
    /// First and last point of the work: the last is the run's `effort`'s.
    fn range(self, effort: &Effort) -> (f64, f64) {
        match self {
            Series::GlyphCount => (100.0, effort.bench_glyph_count_up_to),
            Series::PxPerEm => (4.0, effort.bench_px_per_em_up_to),
        }
    }

    /// The points of work the series is measured at: `count` of them, evenly spaced on
    /// a log scale over its range (glyph counts rounded to whole glyphs).
    pub fn points(self, count: usize, effort: &Effort) -> Vec<f64> {
        let (first, last) = self.range(effort);
        let points = log_spaced(first, last, count);
        match self {
            Series::GlyphCount => points.into_iter().map(f64::round).collect(),
            Series::PxPerEm => points,
        }
    }

    /// The view that draws `work` of this series.
    pub fn view(self, work: f64) -> Result<ViewArgs, Error> {
        match self {
            Series::GlyphCount => Ok(ViewArgs::text(&page_text_of(work as usize), PAGE_PX_PER_EM)),
            Series::PxPerEm => capped(ViewArgs::text(WORD, work)),
        }
    }

    /// How the series builds its frames, for the report.
    fn about(self) -> String {
        match self {
            Series::GlyphCount => format!(
                "The page's text (its lines repeated in order) at {PAGE_PX_PER_EM} px/em, cut \
                 after the given number of glyphs; the frame is the ink's box plus 4 px, so \
                 its pixels grow with the glyphs."
            ),
            Series::PxPerEm => format!(
                "The word \"{WORD}\" (DejaVu Sans) at each size; the frame is the ink's box \
                 plus 4 px, capped at {MAX_FRAME_SIDE} px a side (a window centred on the \
                 ink), so from about 1 200 px/em only part of the word is drawn and the \
                 pixels grow more slowly than the size squared. The atlas caches at the \
                 frame's size up to {} px/em and magnifies beyond.",
                method_settings::BASELINE_CACHE_MAX_PX_PER_EM
            ),
        }
    }
}

/// `count` values from `first` to `last`, evenly spaced in their logarithm (exact at
/// both ends; powers of two stay exact where the spacing falls on them).
pub fn log_spaced(first: f64, last: f64, count: usize) -> Vec<f64> {
    if count < 2 {
        return vec![first; count];
    }
    let (lo, span) = (first.log2(), (last / first).log2());
    (0..count)
        .map(|i| (lo + span * i as f64 / (count - 1) as f64).exp2())
        .collect()
}

/// The page's text, its lines repeated in order, cut after `glyphs` characters that
/// are not spaces (shaping may join a few, so the scene's count is the one reported).
pub fn page_text_of(glyphs: usize) -> String {
    let mut text = String::new();
    let mut drawn = 0;
    let mut lines = PAGE_TEXT.lines().filter(|l| !l.trim().is_empty()).cycle();
    while drawn < glyphs {
        let Some(line) = lines.next() else { break };
        if !text.is_empty() {
            text.push('\n');
        }
        for c in line.chars() {
            if drawn == glyphs {
                break;
            }
            text.push(c);
            if !c.is_whitespace() {
                drawn += 1;
            }
        }
    }
    text
}

/// `args` framed to their ink, each side cut to [`MAX_FRAME_SIDE`] about the ink's
/// centre.
fn capped(args: ViewArgs) -> Result<ViewArgs, Error> {
    let (_, camera) = args.build()?;
    let (width, height) = (
        camera.width.min(MAX_FRAME_SIDE),
        camera.height.min(MAX_FRAME_SIDE),
    );
    if (width, height) == (camera.width, camera.height) {
        return Ok(args);
    }
    let cut = DVec2::new(
        f64::from(camera.width - width),
        f64::from(camera.height - height),
    );
    Ok(ViewArgs {
        width: Some(width),
        height: Some(height),
        origin: Some(camera.origin - cut / 2.0),
        ..args
    })
}

/// Measures `methods` (the GPU ones; the reference has no GPU cost) at their defaults
/// at each point of `series`, one progress step per point and method.
pub fn measure_series(
    gpu: &GpuContext,
    series: Series,
    methods: &[&MethodInfo],
    works: &[f64],
    timing: FrameTiming,
    progress: &ProgressBar,
) -> Result<Vec<ScalingPoint>, Error> {
    let mut points = Vec::with_capacity(works.len());
    for &work in works {
        let (scene, camera) = series.view(work)?.build()?;
        let mut costs = Vec::with_capacity(methods.len());
        let mut covered = Vec::with_capacity(methods.len());
        for method in methods {
            progress.set_message(format!(
                "{} {} {}: {}",
                series.name(),
                work,
                series.work_label(),
                method.name
            ));
            let stats = measure::measure(Some(gpu), &scene, &camera, method, &[], timing)?.stats;
            covered.push(stats.covered_area_px);
            costs.push(MethodCost {
                method: method.name.to_owned(),
                gpu_clock: stats.gpu_clock,
                gpu_ms: stats.gpu_ms,
                cpu_frame_ms: stats.cpu_frame_ms,
                frame_ms: stats.frame_ms,
                gpu_bytes: stats.gpu_bytes,
                cache_bytes: stats.cache_bytes,
            });
            progress.inc(1);
        }
        points.push(ScalingPoint {
            series,
            work: match series {
                Series::GlyphCount => scene.instances.len() as f64,
                Series::PxPerEm => work,
            },
            size_px_per_em: camera.size_px_per_em,
            glyphs: scene.instances.len(),
            width: camera.width,
            height: camera.height,
            covered_px: metrics::median(covered).unwrap_or(0.0),
            atlas_cache_px_per_em: method_settings::baseline_cache_size(camera.size_px_per_em),
            costs,
        });
    }
    Ok(points)
}

/// The least-squares slope k of log y against log x (y ∝ x^k), or None with fewer
/// than two distinct x or any value not finite and positive (a missing or broken
/// measurement is not fitted around).
pub fn log_log_slope(points: &[(f64, f64)]) -> Option<f64> {
    let valid = |v: f64| v.is_finite() && v > 0.0;
    if points.len() < 2 || !points.iter().all(|&(x, y)| valid(x) && valid(y)) {
        return None;
    }
    let logs: Vec<(f64, f64)> = points.iter().map(|&(x, y)| (x.ln(), y.ln())).collect();
    let n = logs.len() as f64;
    let (mean_x, mean_y) = logs
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x / n, b + y / n));
    let (sxy, sxx) = logs.iter().fold((0.0, 0.0), |(sxy, sxx), &(x, y)| {
        let dx = x - mean_x;
        (sxy + dx * (y - mean_y), sxx + dx * dx)
    });
    (sxx > 0.0).then(|| sxy / sxx)
}

/// The first point from which `other` costs less than `atlas` at every later point, or
/// None when it does not at the last point. A missing or non-finite cost is never
/// "less".
pub fn cheaper_from(atlas: &[Option<f64>], other: &[Option<f64>]) -> Option<usize> {
    let less = |(a, o): (&Option<f64>, &Option<f64>)| match (a, o) {
        (Some(a), Some(o)) => a.is_finite() && o.is_finite() && o < a,
        _ => false,
    };
    let trailing = atlas
        .iter()
        .zip(other)
        .rev()
        .take_while(|&pair| less(pair))
        .count();
    (trailing > 0).then(|| atlas.len().min(other.len()) - trailing)
}

/// What a cost is compared by.
#[derive(Clone, Copy)]
enum Measure {
    Time,
    Memory,
}

impl Measure {
    fn of(self, cost: &MethodCost) -> Option<f64> {
        match self {
            Measure::Time => cost.frame_ms,
            Measure::Memory => Some(cost.gpu_bytes as f64),
        }
    }

    fn label(self) -> &'static str {
        match self {
            Measure::Time => "time (GPU + CPU per frame)",
            Measure::Memory => "memory (GPU bytes held)",
        }
    }
}

/// The methods measured in `points`, in the order they were.
fn methods_of(points: &[&ScalingPoint]) -> Vec<String> {
    points.first().map_or(Vec::new(), |p| {
        p.costs.iter().map(|c| c.method.clone()).collect()
    })
}

/// `method`'s figure by `measure` at each point.
fn column(points: &[&ScalingPoint], method: &str, measure: Measure) -> Vec<Option<f64>> {
    points
        .iter()
        .map(|p| p.cost(method).and_then(|c| measure.of(c)))
        .collect()
}

/// `method`'s fitted slope of time against the series' work.
fn time_slope(points: &[&ScalingPoint], method: &str) -> Option<f64> {
    let pairs: Option<Vec<(f64, f64)>> = points
        .iter()
        .map(|p| Some((p.work, p.cost(method)?.frame_ms?)))
        .collect();
    log_log_slope(&pairs?)
}

/// The points of `series` in `all`, in order of work.
pub fn series_points(all: &[ScalingPoint], series: Series) -> Vec<&ScalingPoint> {
    all.iter().filter(|p| p.series == series).collect()
}

/// The report's "Scaling" section.
pub fn markdown(all: &[ScalingPoint], timing: FrameTiming, md: &mut String) {
    if all.is_empty() {
        return;
    }
    let _ = writeln!(
        md,
        "## Scaling\n\nHow each method's cost grows with the work: every method at its \
         default settings, prepared anew at each point, {} frame{} timed after {} warm-up \
         (median). *ms*: GPU + CPU time per frame; *mem*: the GPU memory it holds once it \
         has drawn (for the atlas, its glyph texture in brackets). The slope k is fitted \
         by least squares on log–log axes over the series' points: time ∝ work^k. \
         Plots: `scaling-glyph-count.svg`, `scaling-px-per-em.svg`; every figure in \
         `scaling.csv`.\n",
        timing.frames,
        if timing.frames == 1 { "" } else { "s" },
        timing.warmup,
    );
    for series in Series::ALL {
        let points = series_points(all, series);
        if points.is_empty() {
            continue;
        }
        let _ = writeln!(
            md,
            "### Against {}\n\n{}\n",
            series.work_label(),
            series.about()
        );
        table(&points, md);
        slopes(series, &points, md);
        for measure in [Measure::Time, Measure::Memory] {
            crossing(series, &points, measure, md);
        }
    }
}

/// A point's work: whole glyphs and whole sizes as they are, other sizes to three
/// digits.
fn shown_work(work: f64) -> String {
    if work.fract() == 0.0 {
        format!("{work:.0}")
    } else {
        sig(work)
    }
}

/// One row per point, one column per method (time and memory).
fn table(points: &[&ScalingPoint], md: &mut String) {
    let methods = methods_of(points);
    let series = points[0].series;
    let _ = write!(md, "| {} | frame px | covered px |", series.work_label());
    for m in &methods {
        let _ = write!(md, " {m} ms | {m} mem |");
    }
    md.push_str("\n|---:|---:|---:|");
    md.push_str(&"---:|---:|".repeat(methods.len()));
    md.push('\n');
    for p in points {
        let _ = write!(
            md,
            "| {} | {}×{} | {} |",
            shown_work(p.work),
            p.width,
            p.height,
            sig(p.covered_px)
        );
        for m in &methods {
            let cost = p.cost(m);
            let ms = cost.and_then(|c| c.frame_ms).map_or("—".into(), sig);
            let mem = cost.map_or("—".into(), |c| {
                let held = kb_or_mb(c.gpu_bytes);
                match c.cache_bytes {
                    Some(cache) => format!("{held} ({})", kb_or_mb(cache)),
                    None => held,
                }
            });
            let _ = write!(md, " {ms} | {mem} |");
        }
        md.push('\n');
    }
    md.push('\n');
}

/// The fitted slopes, and what they say: grows with the pixels or with the curves.
fn slopes(series: Series, points: &[&ScalingPoint], md: &mut String) {
    let work = series.work_label();
    let fit = |pairs: Vec<(f64, f64)>| log_log_slope(&pairs);
    let pixels = fit(points.iter().map(|p| (p.work, p.covered_px)).collect());
    let glyphs = fit(points.iter().map(|p| (p.work, p.glyphs as f64)).collect());
    let shown = |k: Option<f64>| k.map_or("—".into(), |k| format!("{k:.2}"));
    let methods = methods_of(points);
    let per_method: Vec<(String, Option<f64>)> = methods
        .iter()
        .map(|m| (m.clone(), time_slope(points, m)))
        .collect();
    let list: Vec<String> = per_method
        .iter()
        .map(|(m, k)| format!("{m} {}", shown(*k)))
        .collect();
    // Against glyphs, the glyphs' own slope is 1 by definition.
    let glyphs_grow = match series {
        Series::GlyphCount => String::new(),
        Series::PxPerEm => format!(" and the glyphs as {work}^{}", shown(glyphs)),
    };
    let _ = writeln!(
        md,
        "Slopes (time ∝ {work}^k): {}. Over the same points the covered pixels grow as \
         {work}^{}{glyphs_grow}.\n",
        list.join(", "),
        shown(pixels),
    );
    let (Some(pixels), Some(glyphs)) = (pixels, glyphs) else {
        return;
    };
    if pixels - glyphs < SEPARATES {
        let _ = writeln!(
            md,
            "Here pixels and curves grow together, so a slope near 1 is a constant cost per \
             glyph; above 1, a cost per glyph that grows with the text.\n"
        );
        return;
    }
    let grouped = |keep: &dyn Fn(f64) -> bool| -> Vec<String> {
        per_method
            .iter()
            .filter_map(|(m, k)| k.filter(|k| keep(k / pixels)).map(|_| m.clone()))
            .collect()
    };
    let with_pixels = grouped(&|r| r >= FOLLOWS_PIXELS);
    let with_curves = grouped(&|r| r <= FOLLOWS_CURVES);
    let between = grouped(&|r| r > FOLLOWS_CURVES && r < FOLLOWS_PIXELS);
    let named = |v: &[String]| {
        if v.is_empty() {
            "none".to_owned()
        } else {
            v.join(", ")
        }
    };
    let _ = writeln!(
        md,
        "The glyphs and their curves stay fixed here while the pixels grow, so a slope near \
         the covered pixels' ({pixels:.2}) is a cost per pixel and one near 0 a cost per \
         curve. Growing with the pixels (k ≥ {FOLLOWS_PIXELS:.2} of theirs): {}. Growing \
         with the curves (k ≤ {FOLLOWS_CURVES:.2} of theirs): {}. Between: {}.\n",
        named(&with_pixels),
        named(&with_curves),
        named(&between),
    );
}

/// Where the atlas stops being the cheapest by `measure`, as sentences.
fn crossing(series: Series, points: &[&ScalingPoint], measure: Measure, md: &mut String) {
    let baseline = registry::baseline().name;
    let methods = methods_of(points);
    if !methods.iter().any(|m| m == baseline) || methods.len() < 2 {
        return;
    }
    let at = |i: usize| format!("{} {}", shown_work(points[i].work), series.work_label());
    let atlas = column(points, baseline, measure);
    let others: Vec<(&String, Vec<Option<f64>>)> = methods
        .iter()
        .filter(|m| *m != baseline)
        .map(|m| (m, column(points, m, measure)))
        .collect();
    let cheapest = (0..points.len())
        .filter(|&i| {
            let Some(a) = atlas[i].filter(|a| a.is_finite()) else {
                return false;
            };
            others
                .iter()
                .all(|(_, o)| o[i].is_some_and(|o| o.is_finite() && a <= o))
        })
        .count();
    let overtakes: Vec<(&String, Option<usize>)> = others
        .iter()
        .map(|(m, o)| (*m, cheaper_from(&atlas, o)))
        .collect();
    // The earliest point from which some method stays below the atlas, and every method
    // that does from there.
    let earliest = overtakes.iter().filter_map(|(_, i)| *i).min();
    let first = earliest.map(|from| {
        let those: Vec<&str> = overtakes
            .iter()
            .filter(|(_, i)| *i == Some(from))
            .map(|(m, _)| m.as_str())
            .collect();
        (those.join(" and "), from)
    });
    let _ = write!(
        md,
        "By {}, the atlas is the cheapest at {cheapest} of {} points. ",
        measure.label(),
        points.len()
    );
    match first {
        None => {
            let _ = write!(
                md,
                "No method costs less than it at the last point ({}).",
                at(points.len() - 1)
            );
        }
        Some((methods, 0)) => {
            let _ = write!(md, "At every point {methods} cost less than it.");
        }
        Some((methods, i)) => {
            let _ = write!(
                md,
                "It stops being the cheapest for good after {}: from {} on, {methods} cost \
                 less at every point.",
                at(i - 1),
                at(i)
            );
        }
    }
    let each: Vec<String> = overtakes
        .iter()
        .map(|(m, i)| match i {
            Some(0) => format!("{m} at every point"),
            Some(i) => format!("{m} from {}", at(*i)),
            None => format!("{m} not at the last point"),
        })
        .collect();
    let _ = writeln!(md, " Less than the atlas: {}.\n", each.join("; "));
}

/// One line per point and method.
pub fn csv(all: &[ScalingPoint]) -> String {
    let mut out = String::from(
        "series,work,size_px_per_em,glyphs,width,height,covered_px,atlas_cache_px_per_em,\
         method,gpu_ms,cpu_frame_ms,frame_ms,gpu_bytes,cache_bytes\n",
    );
    let opt = |v: Option<f64>| v.map_or(String::new(), |v| v.to_string());
    for p in all {
        for c in &p.costs {
            let _ = writeln!(
                out,
                "{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
                p.series.name(),
                p.work,
                p.size_px_per_em,
                p.glyphs,
                p.width,
                p.height,
                p.covered_px,
                p.atlas_cache_px_per_em,
                c.method,
                opt(c.gpu_ms),
                opt(c.cpu_frame_ms),
                opt(c.frame_ms),
                c.gpu_bytes,
                c.cache_bytes.map_or(String::new(), |b| b.to_string()),
            );
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An exact power law gives its exponent back, whatever its factor.
    #[test]
    fn slope_of_a_power_law_is_its_exponent() {
        for k in [0.0, 0.5, 1.0, 1.7, 2.0] {
            let points: Vec<(f64, f64)> = [1.0, 3.0, 10.0, 100.0, 4096.0]
                .iter()
                .map(|&x| (x, 3.5 * f64::powf(x, k)))
                .collect();
            let fitted = log_log_slope(&points).unwrap();
            assert!((fitted - k).abs() < 1e-12, "k = {k}: fitted {fitted}");
        }
    }

    /// Scattered points against a slope worked out by hand: y = x² times 2 and ½ in
    /// turn at x = 1, 2, 4, 8 (the scatter is not symmetric in x, so k is not 2).
    #[test]
    fn slope_by_hand_on_scattered_points() {
        // log₂x = 0, 1, 2, 3; log₂y = 2·log₂x + (1, −1, 1, −1) = 1, 1, 5, 5 (the ratio of
        // the fit is the same in any base).
        // Least squares: mean x 1.5, mean y 3; Σdx·dy = (−1.5)(−2) + (−0.5)(−2) + (0.5)(2)
        // + (1.5)(2) = 8; Σdx² = 5; k = 8/5.
        let points = [(1.0, 2.0), (2.0, 2.0), (4.0, 32.0), (8.0, 32.0)];
        let fitted = log_log_slope(&points).unwrap();
        assert!((fitted - 1.6).abs() < 1e-12, "{fitted}");
    }

    #[test]
    fn slope_refuses_what_it_cannot_fit() {
        assert_eq!(log_log_slope(&[(1.0, 1.0)]), None, "one point");
        assert_eq!(log_log_slope(&[(2.0, 1.0), (2.0, 5.0)]), None, "one x");
        for bad in [f64::NAN, f64::INFINITY, 0.0, -1.0] {
            assert_eq!(
                log_log_slope(&[(1.0, 1.0), (2.0, bad), (4.0, 3.0)]),
                None,
                "{bad}"
            );
        }
    }

    #[test]
    fn cheaper_from_finds_the_last_crossing() {
        let atlas = [Some(1.0), Some(2.0), Some(4.0), Some(8.0)];
        let s = |v: [f64; 4]| v.map(Some);
        // Never less, at the end.
        assert_eq!(cheaper_from(&atlas, &s([2.0, 3.0, 5.0, 9.0])), None);
        assert_eq!(cheaper_from(&atlas, &s([2.0, 3.0, 3.0, 9.0])), None);
        // Less from the third point on.
        assert_eq!(cheaper_from(&atlas, &s([2.0, 3.0, 3.0, 7.0])), Some(2));
        // Less, then not, then less again: from the last crossing.
        assert_eq!(cheaper_from(&atlas, &s([0.5, 3.0, 3.0, 7.0])), Some(2));
        // Less everywhere.
        assert_eq!(cheaper_from(&atlas, &s([0.5, 1.0, 3.0, 7.0])), Some(0));
        // A tie is not less.
        assert_eq!(cheaper_from(&atlas, &s([0.5, 1.0, 3.0, 8.0])), None);
        // A missing or broken figure is never less.
        let broken = [Some(0.5), None, Some(3.0), Some(7.0)];
        assert_eq!(cheaper_from(&atlas, &broken), Some(2));
        let nan = [Some(0.5), Some(1.0), Some(f64::NAN), Some(7.0)];
        assert_eq!(cheaper_from(&atlas, &nan), Some(3));
    }

    #[test]
    fn points_are_log_spaced_over_the_range() {
        let full = Effort::FULL;
        let sizes = Series::PxPerEm.points(full.bench_scaling_points, &full);
        let powers: Vec<f64> = (2..=12).map(|e| f64::from(1u32 << e)).collect();
        assert_eq!(
            sizes, powers,
            "4 → 4096 px/em in 11 points: the powers of two"
        );
        let glyphs = Series::GlyphCount.points(3, &full);
        // √(100 · 30 000) = 1 732.05…
        assert_eq!(glyphs, vec![100.0, 1732.0, 30_000.0]);
        let quick = Effort::QUICK;
        assert_eq!(
            Series::GlyphCount.points(quick.bench_scaling_points, &quick)[2],
            3_000.0
        );
    }

    #[test]
    fn page_text_is_cut_after_the_glyphs_asked_for() {
        for glyphs in [1, 100, 2947, 30_000] {
            let text = page_text_of(glyphs);
            let drawn = text.chars().filter(|c| !c.is_whitespace()).count();
            assert_eq!(drawn, glyphs);
            assert!(!text.ends_with(char::is_whitespace), "{glyphs}");
        }
        // The page has 2 947 such characters: 3 000 starts it again.
        assert!(page_text_of(3_000).starts_with(page_text_of(60).as_str()));
        assert_eq!(page_text_of(3_000).lines().count(), 31);
    }

    #[test]
    fn the_word_is_framed_to_its_ink_and_capped() {
        for size in [4.0, 512.0, 4096.0] {
            let (_, camera) = Series::PxPerEm.view(size).unwrap().build().unwrap();
            assert!(camera.width <= MAX_FRAME_SIDE && camera.height <= MAX_FRAME_SIDE);
            if size == 4096.0 {
                assert_eq!(camera.width, MAX_FRAME_SIDE, "'{WORD}' is 3 em wide");
            }
        }
    }
}
