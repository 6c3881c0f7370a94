//! Text in motion: the shared camera moved along a path ([`crate::motion`]) frame by
//! frame — play, pause, a step either way, back to frame 0 — in every pane at once,
//! magnified or not. Each frame is analysed before the next is shown (the reference of
//! what the panes show, magnified: only the window's pixels), so the strip charts hold
//! one point per frame: each pane's error against the reference and its temporal
//! error ([`crate::metrics::temporal`]); and the inspected pixel's coverage in every
//! pane beside the reference's, frame by frame.

use std::collections::BTreeMap;

use eframe::egui;
use egui_plot::{Legend, Line, Plot, PlotPoints};

use super::analysis::MotionKey;
use super::explorer::Explorer;
use super::panes::pane_letter;
use super::settings::PaneSource;
use super::shortcuts::{Action, key_name};
use super::state::{ChartKey, FramePoint, PixelHistory, PixelSample};
use crate::camera::Camera;
use crate::magnify::Window;
use crate::metrics::{ErrorStats, TemporalError};
use crate::motion::{self, MotionPath, PATH_GRAMMAR};

/// Frames the charts keep (those nearest the frame shown).
const KEPT_FRAMES: usize = 600;

/// Paths the Motion controls offer ready-made, as the bench measures them.
const PRESETS: &[(&str, &str)] = &[
    ("drift along x, 1/16 px a frame", motion::DRIFT_X),
    ("drift along 30°, 1/16 px a frame", motion::DRIFT_30),
    ("rotate 0.25° a frame", motion::TURN),
    ("zoom in and out, 1× to 2×", "pulse:1,2,64"),
    ("sway the tilt ±20°", "sway:20,64"),
    ("drift and turn", "drift:0.0625,0+rotate:0.1"),
];

/// "A atlas": a pane's letter and its method; none for a difference pane, which has no
/// coverage of its own to chart.
fn pane_label(source: &PaneSource, index: usize) -> Option<String> {
    match source {
        PaneSource::Method { name, .. } => Some(format!("{} {name}", pane_letter(index))),
        PaneSource::Difference { .. } => None,
    }
}

/// Keeps the [`KEPT_FRAMES`] of a chart nearest the frame shown (stepping back drops
/// the far end ahead, playing on the far end behind).
fn trim<T>(map: &mut BTreeMap<i64, T>, frame: i64) {
    while map.len() > KEPT_FRAMES {
        let (Some((&first, _)), Some((&last, _))) = (map.first_key_value(), map.last_key_value())
        else {
            return;
        };
        if frame - first >= last - frame {
            map.pop_first();
        } else {
            map.pop_last();
        }
    }
}

impl Explorer {
    /// The camera the panes share at the frame shown, and the magnifier's window.
    pub fn pane_camera_now(&self, width: u32, height: u32) -> (Camera, Window) {
        let motion = self.playback.motion(&self.settings.motion_path);
        self.settings
            .camera
            .pane_camera_moved(width, height, motion.as_ref().map(|(p, n)| (p, *n)))
    }

    /// What makes the frames one motion, when the path moves and the panes are laid
    /// out.
    pub(super) fn motion_key(&self) -> Option<MotionKey> {
        self.playback.motion(&self.settings.motion_path)?;
        Some(MotionKey {
            path: self.settings.motion_path.clone(),
            camera: self.settings.camera,
            pane: self.canvas.pane_size?,
        })
    }

    /// Why frame `frame` cannot be drawn, if it cannot (a sway past the eye, a zoom
    /// past the size range).
    fn undrawable(&self, frame: i64) -> Option<String> {
        let (path, _) = self.playback.motion(&self.settings.motion_path)?;
        let (w, h) = self.canvas.pane_size?;
        let camera = path.camera_at(&self.settings.camera.camera(w, h), frame);
        camera
            .validate()
            .err()
            .map(|e| format!("frame {frame} cannot be drawn: {e}"))
    }

    /// The frame shown.
    pub fn motion_frame(&self) -> i64 {
        self.playback.frame
    }

    pub fn is_playing(&self) -> bool {
        self.playback.playing
    }

    /// Plays or pauses the motion, as Space does; with the charts' window open.
    pub fn play_motion(&mut self, playing: bool) {
        self.playback.playing = playing;
        self.playback.stopped = None;
        self.playback.charts_open = true;
    }

    /// Pane `index`'s strip chart: error and temporal error by frame.
    pub fn motion_history(&self, index: usize) -> Vec<(i64, FramePoint)> {
        self.playback.history(index)
    }

    /// The inspected pixel's coverage by frame, in every pane and the reference.
    pub fn motion_pixel_history(&self) -> Option<PixelHistory> {
        self.playback.pixel_history()
    }

    pub(super) fn transport(&mut self, action: Action) {
        let next = self.playback.frame
            + if action == Action::StepFrame(false) {
                -1
            } else {
                1
            };
        let undrawable = self.undrawable(next);
        let playback = &mut self.playback;
        match action {
            Action::PlayPause => {
                playback.playing ^= true;
                playback.stopped = None;
                // Playing shows what it measures.
                playback.charts_open |= playback.playing;
            }
            Action::StepFrame(_) if undrawable.is_some() => {
                playback.playing = false;
                playback.stopped = undrawable;
            }
            Action::StepFrame(forward) => {
                playback.playing = false;
                playback.step(if forward { 1 } else { -1 });
            }
            Action::Rewind => {
                playback.playing = false;
                playback.step(-playback.frame);
                playback.clear();
            }
            _ => {}
        }
    }

    /// Once a frame: starts the charts afresh when what they are of changed, and while
    /// playing, shows the next frame once this one has been analysed.
    pub(super) fn tick_playback(&mut self, ctx: &egui::Context) {
        let visible = self.settings.layout.panes();
        let key = ChartKey {
            scene: self.scene.generation(),
            motion: self.motion_key(),
            panes: self.settings.panes[..visible].to_vec(),
        };
        if self.playback.chart_key.as_ref() != Some(&key) {
            self.playback.clear();
            self.playback.chart_key = Some(key);
        }
        if !self.playback.playing {
            return;
        }
        if self.playback.motion(&self.settings.motion_path).is_none() {
            self.playback.playing = false;
            self.playback.stopped = Some("the path does not move: set one to play".into());
            return;
        }
        // A frame whose reference cannot be made would never settle: stop and say why.
        if let Some(problem) = &self.reference.problem {
            self.playback.playing = false;
            self.playback.stopped = Some(format!(
                "stopped at frame {}: {problem}",
                self.playback.frame
            ));
            return;
        }
        if !self.view_settled() {
            ctx.request_repaint();
            return;
        }
        if let Some(why) = self.undrawable(self.playback.frame + 1) {
            self.playback.playing = false;
            self.playback.stopped = Some(why);
            return;
        }
        self.playback.step(1);
        ctx.request_repaint();
    }

    /// Takes in the analysis of a frame of the motion: each pane's point, and the
    /// inspected pixel.
    pub(super) fn record_motion_frame(
        &mut self,
        frame: i64,
        errors: &[(usize, ErrorStats)],
        temporal: &[(usize, TemporalError)],
    ) {
        let visible = self.settings.layout.panes();
        let playback = &mut self.playback;
        playback.history.resize_with(visible, BTreeMap::new);
        for &(pane, stats) in errors {
            let Some(history) = playback.history.get_mut(pane) else {
                continue;
            };
            let own = temporal.iter().find(|(p, _)| *p == pane).map(|(_, t)| *t);
            // Stepping back onto a frame keeps the temporal error worked out on the way
            // forward.
            let kept = history.get(&frame).and_then(|p| p.temporal);
            history.insert(
                frame,
                FramePoint {
                    mae_255: stats.mae_255,
                    temporal: own.or(kept),
                },
            );
            trim(history, frame);
        }
        let Some(reference) = self.reference_image() else {
            return;
        };
        let pixel = match self.canvas.hovered {
            Some((_, x, y)) => (x, y),
            None => {
                let Some(window) = self.canvas.window else {
                    return;
                };
                let focus = if window.factor > 1 {
                    (window.focus.0 - window.x0, window.focus.1 - window.y0)
                } else {
                    window.focus
                };
                (
                    focus.0.min(reference.width - 1),
                    focus.1.min(reference.height - 1),
                )
            }
        };
        if pixel.0 >= reference.width || pixel.1 >= reference.height {
            return;
        }
        let panes = (0..visible)
            .map(|i| {
                self.pane_capture(i)
                    .map(|image| image.get(pixel.0, pixel.1))
            })
            .collect();
        let sample = PixelSample {
            panes,
            reference: reference.get(pixel.0, pixel.1),
        };
        let playback = &mut self.playback;
        if playback.pixel.as_ref().is_none_or(|(p, _)| *p != pixel) {
            playback.pixel = Some((pixel, BTreeMap::new()));
        }
        if let Some((_, samples)) = &mut playback.pixel {
            samples.insert(frame, sample);
            trim(samples, frame);
        }
    }

    /// The side panel's Motion section: the path, the transport and the charts' button.
    pub(super) fn motion_controls(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.label("Path");
            ui.add(
                egui::TextEdit::singleline(&mut self.settings.motion_path)
                    .desired_width(170.0)
                    .font(egui::TextStyle::Monospace),
            )
            .on_hover_text(format!("Per frame: {PATH_GRAMMAR}"));
            ui.menu_button("Presets", |ui| {
                for (label, path) in PRESETS {
                    if ui
                        .selectable_label(self.settings.motion_path == *path, *label)
                        .clicked()
                    {
                        self.settings.motion_path = (*path).into();
                        ui.close();
                    }
                }
            });
        });
        if let Err(e) = MotionPath::parse(&self.settings.motion_path) {
            ui.colored_label(ui.visuals().error_fg_color, e.to_string());
        }
        ui.horizontal(|ui| {
            let hint = |action| key_name(action);
            if ui
                .button("To 0")
                .on_hover_text(format!("back to frame 0 ({})", hint(Action::Rewind)))
                .clicked()
            {
                self.transport(Action::Rewind);
            }
            if ui
                .button("Back")
                .on_hover_text(format!(
                    "one frame back ({})",
                    hint(Action::StepFrame(false))
                ))
                .clicked()
            {
                self.transport(Action::StepFrame(false));
            }
            let play = if self.playback.playing {
                "Pause"
            } else {
                "Play"
            };
            if ui
                .button(play)
                .on_hover_text(hint(Action::PlayPause))
                .clicked()
            {
                self.transport(Action::PlayPause);
            }
            if ui
                .button("Step")
                .on_hover_text(format!("one frame on ({})", hint(Action::StepFrame(true))))
                .clicked()
            {
                self.transport(Action::StepFrame(true));
            }
            ui.label(format!("frame {}", self.playback.frame));
            if ui.button("Charts…").clicked() {
                self.playback.charts_open = true;
            }
        });
        if let Some(why) = &self.playback.stopped {
            ui.colored_label(ui.visuals().warn_fg_color, why);
        } else if self.playback.playing {
            let note = match self.reference.cpu_ms {
                Some(ms) => format!(
                    "each frame waits for its reference ({ms:.0} ms on the CPU){}",
                    if self.settings.camera.magnify > 1 {
                        ""
                    } else {
                        ": magnify (M) to draw only the window's"
                    }
                ),
                None => "each frame waits for its reference".into(),
            };
            ui.weak(note);
        }
    }

    /// The Motion window: a strip chart per pane, and the inspected pixel by frame.
    pub(super) fn motion_window(&mut self, ctx: &egui::Context) {
        let mut open = self.playback.charts_open;
        egui::Window::new("Motion")
            .open(&mut open)
            // Low on the screen: the panes' text is usually in their upper half.
            .default_pos([410.0, 420.0])
            .default_size([560.0, 420.0])
            .show(ctx, |ui| {
                ui.weak(
                    "Per frame: each pane's mean error against the reference, and its temporal \
                     error, |Δm − Δr| — what it changes between frames that the reference does \
                     not (shimmer), mean over the pane, in 1/255.",
                );
                let visible = self.settings.layout.panes();
                for index in 0..visible {
                    let Some(label) = pane_label(&self.settings.panes[index].source, index) else {
                        continue;
                    };
                    ui.label(label);
                    let history = self.playback.history(index);
                    let error: PlotPoints = history
                        .iter()
                        .map(|(n, p)| [*n as f64, p.mae_255])
                        .collect();
                    let temporal: PlotPoints = history
                        .iter()
                        .filter_map(|(n, p)| p.temporal.map(|t| [*n as f64, t.mae_255]))
                        .collect();
                    Plot::new(("motion", index))
                        .height(100.0)
                        .legend(Legend::default())
                        .x_axis_label("frame")
                        .show(ui, |plot| {
                            plot.line(Line::new("error", error));
                            plot.line(Line::new("temporal", temporal));
                        });
                }
                if let Some(((x, y), samples)) = self.playback.pixel_history() {
                    // Samples are of the drawn pixels: a magnified window's own; named
                    // here by the pane's ×1 pixel.
                    let (x, y) = self
                        .canvas
                        .window
                        .filter(|w| w.factor > 1)
                        .map_or((x, y), |w| (x + w.x0, y + w.y0));
                    ui.label(format!(
                        "pixel ({x}, {y}): coverage by frame ({})",
                        if self.canvas.hovered.is_some() {
                            "under the pointer"
                        } else {
                            "the magnifier's focus; point at a pane for another"
                        }
                    ));
                    Plot::new("motion pixel")
                        .height(120.0)
                        .legend(Legend::default())
                        .x_axis_label("frame")
                        .show(ui, |plot| {
                            for index in 0..visible {
                                let Some(label) =
                                    pane_label(&self.settings.panes[index].source, index)
                                else {
                                    continue;
                                };
                                let points: PlotPoints = samples
                                    .iter()
                                    .filter_map(|(n, s)| {
                                        s.panes
                                            .get(index)
                                            .copied()
                                            .flatten()
                                            .map(|v| [*n as f64, f64::from(v)])
                                    })
                                    .collect();
                                plot.line(Line::new(label, points));
                            }
                            let reference: PlotPoints = samples
                                .iter()
                                .map(|(n, s)| [*n as f64, f64::from(s.reference)])
                                .collect();
                            plot.line(
                                Line::new("reference", reference)
                                    .style(egui_plot::LineStyle::dashed_dense()),
                            );
                        });
                }
            });
        self.playback.charts_open = open;
    }
}
