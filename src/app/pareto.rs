//! Speed against error: every parameter combination of every method, timed with
//! timestamp queries and compared with the reference on the current scene and view, on a
//! background thread, plotted with the Pareto front (no other point is both faster and
//! more accurate than a point on it).

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::{Receiver, channel};

use eframe::egui;
use egui_plot::{Legend, Line, MarkerShape, Plot, PlotPoints, Points};

use super::panes::Catalog;
use crate::camera::Camera;
use crate::coverage::CoverageImage;
use crate::gpu::GpuContext;
use crate::measure::{self, FrameTiming};
use crate::methods::params::{ParamSpec, assignments};
use crate::methods::registry;
use crate::metrics;
use crate::reference;
use crate::scene::Scene;

/// Frames timed per combination, after untimed warm-up frames (shaders compile lazily).
const WARMUP_FRAMES: usize = 3;
const TIMED_FRAMES: usize = 9;

/// One measured combination.
#[derive(Clone, Debug)]
pub struct ParetoPoint {
    pub method: &'static str,
    pub params: Vec<(String, String)>,
    /// Median GPU time of a frame, ms, and its 95 % interval over the timed frames.
    pub gpu_ms: f64,
    pub gpu_ms_interval: Option<(f64, f64)>,
    pub mae_255: f64,
    pub max: f64,
}

impl ParetoPoint {
    pub fn label(&self) -> String {
        let params: Vec<String> = assignments(&self.params).collect();
        format!("{} {}", self.method, params.join(" "))
    }
}

enum Message {
    Point(ParetoPoint),
    Problem(String),
    Finished,
}

struct Running {
    done: Arc<AtomicUsize>,
    total: usize,
    cancel: Arc<AtomicBool>,
    messages: Receiver<Message>,
}

/// The sweep window's state.
#[derive(Default)]
pub struct ParetoSweep {
    pub open: bool,
    running: Option<Running>,
    pub points: Vec<ParetoPoint>,
    pub problems: Vec<String>,
    /// The view the points were measured on.
    pub measured_on: String,
}

/// The parameter sets a sweep measures for a method: its defaults, then each other
/// listed value of each parameter alone (overlays aside).
pub fn combinations(specs: &[ParamSpec]) -> Vec<Vec<(String, String)>> {
    // The defaults, then each other choice of each parameter on its own: a full
    // factorial of every method's parameters runs to hundreds of renders (effects
    // included) and says no more about each setting's trade.
    let mut all = vec![Vec::new()];
    for spec in specs.iter().filter(|s| s.key != "overlay") {
        for choice in spec.choices.iter().skip(1) {
            all.push(vec![(spec.key.to_string(), choice.to_string())]);
        }
    }
    all
}

/// Indices of the points no other point beats on both time and error, fastest first.
pub fn pareto_front(points: &[ParetoPoint]) -> Vec<usize> {
    let time_and_error: Vec<(f64, f64)> = points.iter().map(|p| (p.gpu_ms, p.mae_255)).collect();
    metrics::pareto_front(&time_and_error)
}

impl ParetoSweep {
    pub fn running(&self) -> bool {
        self.running.is_some()
    }

    /// (done, total) while running.
    pub fn progress(&self) -> Option<(usize, usize)> {
        self.running
            .as_ref()
            .map(|r| (r.done.load(Ordering::Relaxed), r.total))
    }

    /// Starts measuring every combination of every GPU method on `scene` seen by `camera`.
    pub fn start(
        &mut self,
        ctx: &egui::Context,
        gpu: &GpuContext,
        catalog: &Catalog,
        scene: Arc<Scene>,
        camera: Camera,
    ) {
        self.cancel();
        let jobs: Vec<(&'static str, Vec<(String, String)>)> = catalog
            .gpu_methods()
            .flat_map(|m| {
                combinations(registry::param_specs(m.name))
                    .into_iter()
                    .map(move |p| (m.name, p))
            })
            .collect();
        let done = Arc::new(AtomicUsize::new(0));
        let cancel = Arc::new(AtomicBool::new(false));
        let (sender, messages) = channel();
        self.points.clear();
        self.problems.clear();
        self.measured_on = format!(
            "{}×{} px at {:.4} px/em, {} glyphs",
            camera.width,
            camera.height,
            camera.size_px_per_em,
            scene.instances.len()
        );
        self.running = Some(Running {
            done: done.clone(),
            total: jobs.len(),
            cancel: cancel.clone(),
            messages,
        });
        let gpu = gpu.clone();
        let ctx = ctx.clone();
        // A page (wasm32) has no threads yet: said in the window, not a panic.
        let started = std::thread::Builder::new()
            .name("sweep".into())
            .spawn(move || {
                let send = |m| {
                    // The window may be gone; then nobody wants the numbers.
                    let _ = sender.send(m);
                    ctx.request_repaint();
                };
                match reference::rasterize(&scene, &camera) {
                    Err(e) => send(Message::Problem(format!("reference: {e}"))),
                    Ok(reference) => {
                        for (method, params) in jobs {
                            if cancel.load(Ordering::Relaxed) {
                                break;
                            }
                            let measured =
                                measure(&gpu, &scene, &camera, &reference, method, params);
                            send(match measured {
                                Ok(point) => Message::Point(point),
                                Err(e) => Message::Problem(format!("{method}: {e}")),
                            });
                            done.fetch_add(1, Ordering::Relaxed);
                        }
                    }
                }
                send(Message::Finished);
            })
            .map_err(|e| format!("the sweep needs a thread: {e}"));
        if let Err(why) = started {
            self.running = None;
            self.problems.push(why);
        }
    }

    pub fn cancel(&mut self) {
        if let Some(running) = self.running.take() {
            running.cancel.store(true, Ordering::Relaxed);
        }
    }

    /// Takes what the thread sent; ends the run when everything is measured.
    pub fn poll(&mut self) {
        let Some(running) = &self.running else {
            return;
        };
        let mut finished = false;
        for message in running.messages.try_iter() {
            match message {
                Message::Point(p) => self.points.push(p),
                Message::Problem(p) => self.problems.push(p),
                Message::Finished => finished = true,
            }
        }
        if finished {
            self.running = None;
        }
    }

    /// The plot; returns a point the user clicked, to apply to the first pane.
    pub fn plot(&self, ui: &mut egui::Ui) -> Option<ParetoPoint> {
        let front = pareto_front(&self.points);
        let points = &self.points;
        let labels = move |position: &egui_plot::HoverPosition<'_>| -> Option<String> {
            let egui_plot::HoverPosition::NearDataPoint { position, .. } = position else {
                return None;
            };
            let nearest = nearest(points, position.x, position.y)?;
            let p = &points[nearest];
            let interval = p
                .gpu_ms_interval
                .map_or(String::new(), |(lo, hi)| format!(" ({lo:.3}–{hi:.3})"));
            Some(format!(
                "{}\n{:.3} ms{interval}, MAE {:.3}/255, max {:.3}",
                p.label(),
                p.gpu_ms,
                p.mae_255,
                p.max
            ))
        };
        // Both axes are logarithmic: times and errors span decades.
        let power_of_ten = |mark: egui_plot::GridMark, _: &std::ops::RangeInclusive<f64>| {
            format!("{}", 10f64.powf(mark.value))
        };
        let response = Plot::new("speed vs error")
            .legend(Legend::default())
            .x_axis_label("GPU time per frame, ms (median and its 95 % interval, log scale)")
            .y_axis_label("mean error vs reference, 1/255 (log scale)")
            .x_axis_formatter(power_of_ten)
            .y_axis_formatter(power_of_ten)
            .x_grid_spacer(egui_plot::log_grid_spacer(10))
            .y_grid_spacer(egui_plot::log_grid_spacer(10))
            .label_formatter(labels)
            .show(ui, |plot| {
                for (k, method) in unique_methods(points).into_iter().enumerate() {
                    let series: PlotPoints = points
                        .iter()
                        .filter(|p| p.method == method)
                        .map(plotted)
                        .collect();
                    plot.points(
                        Points::new(method, series)
                            .radius(4.0)
                            .shape(MarkerShape::Circle)
                            .color(method_color(k)),
                    );
                    // Each point's 95 % interval of its frame time, as a bar along x.
                    for p in points.iter().filter(|p| p.method == method) {
                        let Some((lo, hi)) = p.gpu_ms_interval else {
                            continue;
                        };
                        let [_, y] = plotted(p);
                        let bar: PlotPoints =
                            vec![[lo.max(1e-6).log10(), y], [hi.max(1e-6).log10(), y]].into();
                        plot.line(Line::new("", bar).color(method_color(k)).width(1.0));
                    }
                }
                let line: PlotPoints = front.iter().map(|&i| plotted(&points[i])).collect();
                plot.line(
                    Line::new("Pareto front", line)
                        .color(egui::Color32::from_gray(200))
                        .width(1.5),
                );
                plot.response()
                    .clicked()
                    .then(|| plot.pointer_coordinate())
                    .flatten()
            });
        let clicked = response.inner?;
        nearest(points, clicked.x, clicked.y).map(|i| points[i].clone())
    }
}

fn unique_methods(points: &[ParetoPoint]) -> Vec<&'static str> {
    let mut names: Vec<&'static str> = Vec::new();
    for p in points {
        if !names.contains(&p.method) {
            names.push(p.method);
        }
    }
    names
}

fn method_color(k: usize) -> egui::Color32 {
    // No grey: the Pareto front is drawn in grey.
    const COLORS: [egui::Color32; 7] = [
        egui::Color32::from_rgb(80, 170, 255),
        egui::Color32::from_rgb(255, 140, 60),
        egui::Color32::from_rgb(120, 220, 120),
        egui::Color32::from_rgb(230, 90, 200),
        egui::Color32::from_rgb(240, 220, 80),
        egui::Color32::from_rgb(90, 220, 220),
        egui::Color32::from_rgb(255, 90, 90),
    ];
    COLORS[k % COLORS.len()]
}

/// Where a point is drawn: log10 of its time and error (a perfect score sits at 1e-3/255).
fn plotted(p: &ParetoPoint) -> [f64; 2] {
    [p.gpu_ms.max(1e-6).log10(), p.mae_255.max(1e-3).log10()]
}

/// The point drawn nearest to plot position (x, y).
fn nearest(points: &[ParetoPoint], x: f64, y: f64) -> Option<usize> {
    (0..points.len()).min_by(|&a, &b| {
        let d = |p: &ParetoPoint| {
            let [px, py] = plotted(p);
            (px - x).powi(2) + (py - y).powi(2)
        };
        d(&points[a]).total_cmp(&d(&points[b]))
    })
}

/// One point: the method drawn and timed exactly as `render --stats` and the bench do.
fn measure(
    gpu: &GpuContext,
    scene: &Scene,
    camera: &Camera,
    reference: &CoverageImage,
    method: &'static str,
    params: Vec<(String, String)>,
) -> Result<ParetoPoint, crate::Error> {
    let timing = FrameTiming {
        warmup: WARMUP_FRAMES,
        frames: TIMED_FRAMES,
    };
    let measured = measure::measure(
        Some(gpu),
        scene,
        camera,
        registry::find(method)?,
        &params,
        timing,
    )?;
    let error = metrics::compare(&measured.image, reference)?;
    let gpu_ms = measured
        .stats
        .gpu_ms
        .ok_or_else(|| crate::Error::Gpu(format!("'{method}' drew no timed frame")))?;
    Ok(ParetoPoint {
        method,
        params,
        gpu_ms,
        gpu_ms_interval: measured.stats.gpu_ms_interval.map(|i| (i.low, i.high)),
        mae_255: error.mae_255,
        max: error.max,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn combinations_cover_every_choice_but_overlays() {
        let winding = registry::param_specs(crate::methods::winding::INFO.name);
        let all = combinations(winding);
        let one_at_a_time: usize = 1 + winding
            .iter()
            .filter(|s| s.key != "overlay")
            .map(|s| s.choices.len() - 1)
            .sum::<usize>();
        assert_eq!(all.len(), one_at_a_time);
        assert!(all.iter().all(|p| p.iter().all(|(k, _)| k != "overlay")));
        assert_eq!(combinations(&[]), vec![Vec::new()]);
    }
}
