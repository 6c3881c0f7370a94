//! The bench's plots, as SVG (text is left to the viewer's fonts, so no font is
//! embedded): GPU time against mean error per scene and view, with each method's
//! Pareto front; the tessellation's outline points against its error; and each scaling
//! series' time and memory against its work.

use std::path::Path;

use plotters::coord::ranged1d::ValueFormatter;
use plotters::prelude::*;

use super::result::{BenchResult, Measurement, ScalingPoint, SceneCamera, Series};
use super::{scaling, scenes};
use crate::Error;
use crate::methods::registry;
use crate::metrics::pareto_front;

/// Mean errors are drawn no lower than this (1/255): a log axis has no zero.
const MAE_FLOOR: f64 = 0.01;

/// Labels per axis: log axes offer one per grid line, which crowd into each other.
const LABELS: usize = 6;

/// A method's colour, from its registry row.
fn colour(method: &str) -> RGBColor {
    registry::find(method).map_or(BLACK, |m| {
        let [r, g, b] = m.colour;
        RGBColor(r, g, b)
    })
}

fn plot_error(e: impl std::fmt::Debug) -> Error {
    Error::Output(format!("cannot draw the plot: {e:?}"))
}

/// Axes with their descriptions, mean error up the side, and only the major grid.
fn draw_axes<'a, DB, X, Y>(
    chart: &mut ChartContext<'a, DB, Cartesian2d<X, Y>>,
    x_desc: &str,
) -> Result<(), Error>
where
    DB: DrawingBackend + 'a,
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    draw_described_axes(chart, x_desc, "mean error, 1/255")
}

/// Axes with both descriptions, and only the major grid.
fn draw_described_axes<'a, DB, X, Y>(
    chart: &mut ChartContext<'a, DB, Cartesian2d<X, Y>>,
    x_desc: &str,
    y_desc: &str,
) -> Result<(), Error>
where
    DB: DrawingBackend + 'a,
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_labels(LABELS)
        .y_labels(LABELS)
        .light_line_style(WHITE)
        .draw()
        .map_err(plot_error)
}

/// The series' labels, in a box at the lower left: fast and exact at once, the corner
/// no method reaches.
fn draw_legend<'a, DB: DrawingBackend + 'a, CT: CoordTranslate>(
    chart: &mut ChartContext<'a, DB, CT>,
) -> Result<(), Error> {
    draw_legend_at(chart, SeriesLabelPosition::LowerLeft)
}

fn draw_legend_at<'a, DB: DrawingBackend + 'a, CT: CoordTranslate>(
    chart: &mut ChartContext<'a, DB, CT>,
    position: SeriesLabelPosition,
) -> Result<(), Error> {
    chart
        .configure_series_labels()
        .position(position)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(plot_error)
}

/// (GPU + CPU ms per frame, MAE) of a case, if it was timed on the GPU.
fn time_and_error(case: &Measurement) -> Option<(f64, f64)> {
    if case.is_reference() {
        return None;
    }
    Some((case.frame_ms?, case.error.mae_255.max(MAE_FLOOR)))
}

/// Range of `values` widened by a margin on a log scale.
fn log_range(values: impl Iterator<Item = f64>) -> std::ops::Range<f64> {
    let (lo, hi) = values.fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if lo.is_finite() && hi > 0.0 {
        lo / 1.5..hi * 1.5
    } else {
        0.1..10.0
    }
}

/// Time against mean error, one panel per scene and view.
pub fn time_against_error(result: &BenchResult, path: &Path) -> Result<(), Error> {
    let panels: Vec<_> = result
        .scenes
        .iter()
        .filter(|s| {
            result.measurements.iter().any(|c| {
                c.scene == s.name && c.scene_camera == s.scene_camera && time_and_error(c).is_some()
            })
        })
        .collect();
    let columns = 2;
    let rows = panels.len().div_ceil(columns).max(1);
    let root = SVGBackend::new(path, (1200, 420 * rows as u32)).into_drawing_area();
    root.fill(&WHITE).map_err(plot_error)?;
    for (area, info) in root.split_evenly((rows, columns)).iter().zip(&panels) {
        let cases: Vec<&Measurement> = result
            .measurements
            .iter()
            .filter(|c| c.scene == info.name && c.scene_camera == info.scene_camera)
            .collect();
        let all: Vec<(f64, f64)> = cases.iter().filter_map(|c| time_and_error(c)).collect();
        let caption = match info.scene_camera {
            SceneCamera::Own => info.name.clone(),
            SceneCamera::Moved => format!("{}, after caching (zoom 2.5×, 30°)", info.name),
        };
        let mut chart = ChartBuilder::on(area)
            .caption(caption, ("sans-serif", 18))
            .margin(12)
            .x_label_area_size(36)
            .y_label_area_size(52)
            .build_cartesian_2d(
                log_range(all.iter().map(|p| p.0)).log_scale(),
                log_range(all.iter().map(|p| p.1)).log_scale(),
            )
            .map_err(plot_error)?;
        draw_axes(
            &mut chart,
            &format!("GPU + CPU ms per frame ({})", result.adapter),
        )?;
        for method in registry::benched().map(|m| m.name) {
            let points: Vec<(f64, f64)> = cases
                .iter()
                .filter(|c| c.method == method)
                .filter_map(|c| time_and_error(c))
                .collect();
            if points.is_empty() {
                continue;
            }
            let c = colour(method);
            chart
                .draw_series(LineSeries::new(
                    pareto_front(&points).into_iter().map(|i| points[i]),
                    c.stroke_width(2),
                ))
                .map_err(plot_error)?;
            // Each case's 95 % interval of its frame time over the rounds, as a bar.
            let bars: Vec<[(f64, f64); 2]> = cases
                .iter()
                .filter(|c| c.method == method)
                .filter_map(|c| {
                    let (_, mae) = time_and_error(c)?;
                    let i = c.frame_ms_interval?;
                    Some([(i.low, mae), (i.high, mae)])
                })
                .collect();
            chart
                .draw_series(
                    bars.into_iter()
                        .map(|b| PathElement::new(b, c.stroke_width(1))),
                )
                .map_err(plot_error)?;
            // The peers as triangles, glyphscope's own methods as discs.
            if registry::find(method).is_ok_and(|m| m.is_peer()) {
                chart
                    .draw_series(
                        points
                            .iter()
                            .map(|&p| TriangleMarker::new(p, 6, c.filled())),
                    )
                    .map_err(plot_error)?
                    .label(format!("{method} (peer)"))
                    .legend(move |(x, y)| TriangleMarker::new((x + 8, y), 6, c.filled()));
            } else {
                chart
                    .draw_series(points.iter().map(|&p| Circle::new(p, 4, c.filled())))
                    .map_err(plot_error)?
                    .label(method)
                    .legend(move |(x, y)| Circle::new((x + 8, y), 4, c.filled()));
            }
        }
        draw_legend(&mut chart)?;
    }
    root.present().map_err(plot_error)
}

/// The tessellation's outline points against its mean error, per scene and view.
pub fn points_against_error(result: &BenchResult, path: &Path) -> Result<(), Error> {
    let series: Vec<(String, Vec<(f64, f64)>)> = result
        .scenes
        .iter()
        .map(|info| {
            let points = result
                .measurements
                .iter()
                .filter(|c| c.scene == info.name && c.scene_camera == info.scene_camera)
                .filter_map(|c| Some((c.mesh_points? as f64, c.error.mae_255.max(MAE_FLOOR))))
                .collect();
            let label = match info.scene_camera {
                SceneCamera::Own => info.name.clone(),
                SceneCamera::Moved => format!("{} (moved)", info.name),
            };
            (label, points)
        })
        .filter(|(_, p): &(String, Vec<(f64, f64)>)| !p.is_empty())
        .collect();
    let root = SVGBackend::new(path, (900, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(plot_error)?;
    let all = || series.iter().flat_map(|(_, p)| p.iter().copied());
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "tessellation: outline points against error",
            ("sans-serif", 18),
        )
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(52)
        .build_cartesian_2d(
            // Points from zero, linear: a few hundred to a few thousand.
            0.0..all().map(|p| p.0).fold(1.0, f64::max) * 1.1,
            log_range(all().map(|p| p.1)).log_scale(),
        )
        .map_err(plot_error)?;
    draw_axes(&mut chart, "outline points tessellated")?;
    for (i, (label, points)) in series.iter().enumerate() {
        let c = Palette99::pick(i).to_rgba();
        chart
            .draw_series(points.iter().map(|&p| Cross::new(p, 5, c.stroke_width(2))))
            .map_err(plot_error)?
            .label(label.clone())
            .legend(move |(x, y)| Cross::new((x + 8, y), 5, c.stroke_width(2)));
    }
    draw_legend(&mut chart)?;
    root.present().map_err(plot_error)
}

/// A method's figure at a scaling point (method named), if it was measured.
type PointFigure = dyn Fn(&ScalingPoint, &str) -> Option<f64>;

/// One scaling series: time per frame (left) and GPU memory (right) against its work,
/// log–log, a line per method; the legends sit at the upper left, where little work
/// costs little.
pub fn scaling(points: &[&ScalingPoint], adapter: &str, path: &Path) -> Result<(), Error> {
    let Some(first) = points.first() else {
        return Ok(());
    };
    let series = first.series;
    let methods: Vec<&str> = first.costs.iter().map(|c| c.method.as_str()).collect();
    let root = SVGBackend::new(path, (1200, 480)).into_drawing_area();
    root.fill(&WHITE).map_err(plot_error)?;
    let panels = root.split_evenly((1, 2));
    let x_desc: String = match series {
        Series::GlyphCount => format!(
            "glyphs drawn (the page's text, {} px/em)",
            scenes::PAGE_PX_PER_EM
        ),
        Series::PxPerEm => format!("px/em (\"{}\")", scaling::WORD),
    };
    let time = |p: &ScalingPoint, m: &str| p.cost(m).and_then(|c| c.frame_ms);
    let memory = |p: &ScalingPoint, m: &str| p.cost(m).map(|c| c.gpu_bytes as f64 / 1024.0);
    let panels_of: [(&str, String, &PointFigure); 2] = [
        (
            "time per frame",
            format!("GPU + CPU ms per frame ({adapter})"),
            &time,
        ),
        ("GPU memory", "GPU memory held, kB".into(), &memory),
    ];
    for (area, (caption, y_desc, figure)) in panels.iter().zip(panels_of) {
        let line = |m: &str| -> Vec<(f64, f64)> {
            points
                .iter()
                .filter_map(|p| Some((p.work, figure(p, m)?)))
                .filter(|&(_, v)| v.is_finite() && v > 0.0)
                .collect()
        };
        let all: Vec<(f64, f64)> = methods.iter().flat_map(|m| line(m)).collect();
        let mut chart = ChartBuilder::on(area)
            .caption(
                format!("{caption} against {}", series.work_label()),
                ("sans-serif", 18),
            )
            .margin(12)
            .x_label_area_size(36)
            .y_label_area_size(60)
            .build_cartesian_2d(
                log_range(all.iter().map(|p| p.0)).log_scale(),
                log_range(all.iter().map(|p| p.1)).log_scale(),
            )
            .map_err(plot_error)?;
        draw_described_axes(&mut chart, &x_desc, &y_desc)?;
        for &method in &methods {
            let c = colour(method);
            let points = line(method);
            chart
                .draw_series(LineSeries::new(points.iter().copied(), c.stroke_width(2)))
                .map_err(plot_error)?;
            chart
                .draw_series(points.iter().map(|&p| Circle::new(p, 3, c.filled())))
                .map_err(plot_error)?
                .label(method)
                .legend(move |(x, y)| Circle::new((x + 8, y), 4, c.filled()));
        }
        draw_legend_at(&mut chart, SeriesLabelPosition::UpperLeft)?;
    }
    root.present().map_err(plot_error)
}
