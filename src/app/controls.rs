//! The side panel (scene, camera, view, panes), the status bar with the pixel inspector,
//! and the windows (help, open font, speed vs error).

use eframe::egui;

use super::display::{Darkening, DisplayMode};
use super::explorer::Explorer;
use super::panes::{REFERENCE, pane_controls, pane_letter};
use super::settings::{FontChoice, Layout, MAX_TILT_DEG, MIN_SIZE_PX_PER_EM, PaneSource};
use super::shortcuts::{Action, SHORTCUTS, key_name};
use crate::camera::MAX_SIZE_PX_PER_EM;
use crate::font::SHIPPED_FONTS;
use crate::magnify::MAX_FACTOR;

impl Explorer {
    /// "Open font…": the dialog on the desktop, the browser's file picker on the page.
    pub(super) fn ask_for_font(&mut self) {
        #[cfg(not(target_arch = "wasm32"))]
        {
            self.font_dialog.open = true;
        }
        #[cfg(target_arch = "wasm32")]
        if let Err(e) = super::web::pick_font() {
            self.set_status(e);
        }
    }

    pub(super) fn controls(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.heading("Scene");
            self.cases_menu(ui);
        });
        self.scene_controls(ui);
        ui.separator();
        ui.heading("Camera");
        self.camera_controls(ui);
        ui.separator();
        ui.heading("View");
        self.view_controls(ui);
        ui.separator();
        let visible = self.settings.layout.panes();
        for index in 0..visible {
            egui::CollapsingHeader::new(format!("Pane {}", pane_letter(index)))
                .default_open(true)
                .show(ui, |ui| {
                    pane_controls(
                        ui,
                        index,
                        &mut self.settings.panes[index],
                        &self.catalog,
                        visible,
                    );
                });
        }
        ui.separator();
        // Closed until asked for, below the panes' controls.
        egui::CollapsingHeader::new("Motion")
            .default_open(false)
            .show(ui, |ui| self.motion_controls(ui));
        ui.separator();
        ui.horizontal(|ui| {
            if ui
                .button("Speed vs error…")
                .on_hover_text(key_name(Action::ToggleSweep))
                .clicked()
            {
                self.sweep.open = true;
            }
            if ui
                .button("Screenshot")
                .on_hover_text(format!(
                    "{}: PNG in the current folder",
                    key_name(Action::Screenshot)
                ))
                .clicked()
            {
                self.screenshot(ui.ctx());
            }
            let link = self.link();
            let hover = match &link {
                Ok(link) => format!("copy the link that opens this view: {link}"),
                Err(why) => why.clone(),
            };
            if ui
                .add_enabled(link.is_ok(), egui::Button::new("Copy link"))
                .on_hover_text(hover)
                .on_disabled_hover_text(link.as_ref().err().cloned().unwrap_or_default())
                .clicked()
                && let Ok(link) = link
            {
                ui.ctx().copy_text(link.clone());
                self.set_status(format!("link copied (glyphscope --view '{link}' opens it)"));
            }
            if ui
                .button("Help")
                .on_hover_text(key_name(Action::ToggleHelp))
                .clicked()
            {
                self.help_open = true;
            }
        });
    }

    fn scene_controls(&mut self, ui: &mut egui::Ui) {
        self.case_controls(ui);
        let mut ask_for_font = false;
        let scene = &mut self.settings.scene;
        ui.horizontal(|ui| {
            let label = ui.label("font");
            egui::ComboBox::from_id_salt("font")
                .selected_text(scene.font.label())
                .width(170.0)
                .show_ui(ui, |ui| {
                    for (i, (name, _, _)) in SHIPPED_FONTS.iter().enumerate() {
                        if ui
                            .selectable_label(scene.font == FontChoice::Shipped(i), *name)
                            .clicked()
                        {
                            scene.font = FontChoice::Shipped(i);
                            scene.variations.clear();
                        }
                    }
                })
                .response
                .labelled_by(label.id);
            if ui
                .button("Open…")
                .on_hover_text(format!(
                    "{}, or drop a font file",
                    key_name(Action::OpenFont)
                ))
                .clicked()
            {
                ask_for_font = true;
            }
        });
        if ask_for_font {
            self.ask_for_font();
        }
        let scene = &mut self.settings.scene;
        if let Some(font) = self.scene.font() {
            for axis in font.axes() {
                let mut value = scene
                    .variations
                    .iter()
                    .find(|(t, _)| *t == axis.tag)
                    .map_or(axis.default, |(_, v)| *v);
                // Shown without its padding; stored padded, as the font names it.
                let slider =
                    egui::Slider::new(&mut value, axis.min..=axis.max).text(axis.tag.trim_end());
                if ui.add(slider).changed() {
                    scene.variations.retain(|(t, _)| *t != axis.tag);
                    scene.variations.push((axis.tag.clone(), value));
                }
            }
        }
        ui.horizontal(|ui| {
            let toggle = ui
                .checkbox(&mut scene.glyph_mode, "one glyph")
                .on_hover_text(format!(
                    "{}: a single glyph, big; a character, or # and a glyph id",
                    key_name(Action::ToggleGlyphMode)
                ));
            ui.add_enabled(
                scene.glyph_mode,
                egui::TextEdit::singleline(&mut scene.glyph)
                    .desired_width(80.0)
                    .id_salt("glyph"),
            )
            .labelled_by(toggle.id);
        });
        let label = ui.label("text");
        // Four lines tall (a TextEdit's rows and its 2 + 2 px margin) whatever the text's
        // length, so the controls below stay put.
        let rows = 4;
        let height = ui.text_style_height(&egui::TextStyle::Body) * rows as f32 + 4.0;
        egui::ScrollArea::vertical()
            .id_salt("text scroll")
            .max_height(height)
            .show(ui, |ui| {
                ui.add_enabled(
                    !scene.glyph_mode,
                    egui::TextEdit::multiline(&mut scene.text)
                        .desired_rows(rows)
                        .desired_width(f32::INFINITY)
                        .id_salt("text"),
                )
                .labelled_by(label.id);
            });
        if let Some(problem) = self.scene.problem() {
            ui.colored_label(ui.visuals().error_fg_color, problem);
        } else if let Some(scene) = self.scene.scene() {
            ui.weak(format!(
                "{} glyphs, {} distinct",
                scene.instances.len(),
                scene.glyphs.len()
            ));
        }
    }

    fn camera_controls(&mut self, ui: &mut egui::Ui) {
        let upem = self.scene.units_per_em();
        let centre = self.view_centre();
        let pane_size = self.pane_size();
        let camera = &mut self.settings.camera;
        let mut size = camera.size_px_per_em;
        ui.horizontal(|ui| {
            ui.label("size");
            let speed = size * 0.01;
            let drag = egui::DragValue::new(&mut size)
                .range(MIN_SIZE_PX_PER_EM..=MAX_SIZE_PX_PER_EM)
                .speed(speed)
                .max_decimals(3)
                .suffix(" px/em");
            if ui
                .add(drag)
                .on_hover_text("wheel over the view zooms about the cursor")
                .changed()
            {
                camera.set_size(size, centre, upem);
            }
        });
        let mut rotation = camera.rotation_deg;
        if ui
            .add(egui::Slider::new(&mut rotation, -180.0..=180.0).text("rotate °"))
            .changed()
        {
            camera.rotate(rotation - camera.rotation_deg, centre, upem);
        }
        let mut skew = camera.skew;
        if ui
            .add(egui::Slider::new(&mut skew, -1.0..=1.0).text("skew"))
            .changed()
        {
            camera.set_skew(skew, centre, upem);
        }
        ui.add(
            egui::Slider::new(&mut camera.tilt_deg, -MAX_TILT_DEG..=MAX_TILT_DEG).text("tilt °"),
        )
        .on_hover_text("perspective: the image plane turns about its horizontal centre line");
        ui.horizontal(|ui| {
            let scene = self.scene.scene().cloned();
            if ui
                .add_enabled(scene.is_some(), egui::Button::new("Reset"))
                .on_hover_text(key_name(Action::ResetCamera))
                .clicked()
                && let Some(scene) = &scene
            {
                self.settings.camera.reset(scene);
            }
            if ui
                .add_enabled(scene.is_some(), egui::Button::new("Fit"))
                .on_hover_text(key_name(Action::FitText))
                .clicked()
                && let Some(scene) = &scene
            {
                self.settings.camera.fit(scene, pane_size);
            }
            // The magnifier beside them, on this row so the panel keeps its height.
            let camera = &mut self.settings.camera;
            let mut factor = camera.magnify;
            let (w, h) = (pane_size.x as u32, pane_size.y as u32);
            ui.label("magnify");
            if ui
                .add(
                    egui::DragValue::new(&mut factor)
                        .range(1..=MAX_FACTOR)
                        .speed(0.2)
                        .prefix("×"),
                )
                .on_hover_text(
                    "each pixel drawn as an N×N block, its true size kept (Alt + wheel, \
                     M / N); a grid from ×8, values from ×32",
                )
                .changed()
                && w > 0
                && h > 0
            {
                let window = camera.pane_camera(w, h).1;
                let drawn_centre = (centre - window.origin()) * f64::from(window.factor);
                camera.magnify_about(factor, drawn_centre, w, h);
            }
        });
    }

    fn view_controls(&mut self, ui: &mut egui::Ui) {
        let settings = &mut self.settings;
        ui.horizontal(|ui| {
            for layout in Layout::ALL {
                ui.selectable_value(&mut settings.layout, layout, layout.label())
                    .on_hover_text(key_name(Action::SetLayout(layout)));
            }
        });
        ui.horizontal(|ui| {
            ui.label("text");
            ui.color_edit_button_srgb(&mut settings.text_color);
            ui.label("background");
            ui.color_edit_button_srgb(&mut settings.background);
            fixed_width_choice(
                ui,
                ("display mode", 80.0),
                &mut settings.display,
                &DisplayMode::ALL,
                |m| (m.label(), m.label()),
            )
            .on_hover_text("how coverage is shown; error figures stay linear coverage");
            fixed_width_choice(
                ui,
                ("darkening", 84.0),
                &mut settings.darkening,
                &Darkening::ALL,
                |d| (d.short_label(), d.label()),
            )
            .on_hover_text(
                "stem darkening at display time: FreeType's CFF curve (approximated), or \
                 HarfBuzz's GPU formula (heavier dark text, lighter light text); error \
                 figures stay linear coverage",
            );
        });
        ui.add(
            egui::Slider::new(&mut settings.difference_scale, 0.01..=1.0)
                .logarithmic(true)
                .text("difference scale"),
        )
        .on_hover_text("coverage error drawn at full red or blue");
        ui.checkbox(&mut settings.continuous, "draw continuously")
            .on_hover_text(format!(
                "{}: redraw every frame, for live GPU time; otherwise panes are drawn only when something changes",
                key_name(Action::ToggleContinuous)
            ));
    }

    pub(super) fn status_bar(&mut self, ui: &mut egui::Ui) {
        // One line, clipped at the right: a message that wrapped would resize the panes,
        // and with them the camera the numbers and the worst pixels were worked out for.
        ui.horizontal(|ui| {
            // The message first (the worst pixel, a case, a screenshot): what was just
            // asked for is what the clipping must not hide.
            let status = self.status_text();
            if !status.is_empty() {
                ui.label(status);
                ui.separator();
            }
            #[cfg(target_arch = "wasm32")]
            ui.colored_label(ui.visuals().warn_fg_color, super::web::LIMITS);
            ui.label(self.inspector_text());
            ui.separator();
            let mut intervals: Vec<f64> = self.frame_intervals.iter().copied().collect();
            intervals.sort_by(f64::total_cmp);
            if let Some(median) = intervals.get(intervals.len() / 2) {
                ui.weak(format!("frame interval {median:.1} ms"))
                    .on_hover_text(
                        "median of the last 60 frames; in continuous mode, the frame time",
                    );
            }
            if let Some(ms) = self.reference.cpu_ms {
                ui.weak(format!(
                    "reference {ms:.0} ms (CPU, {})",
                    super::analysis::WHERE
                ));
            }
            if self.analysis.busy() {
                ui.spinner();
            }
            if let Some((gpu, _)) = &self.gpu {
                ui.separator();
                ui.weak(gpu.adapter_name());
            } else {
                ui.colored_label(
                    ui.visuals().error_fg_color,
                    "no wgpu device: the explorer needs eframe's wgpu renderer",
                );
            }
        });
    }

    /// The pixel inspector: coverage under the cursor in every pane and the reference.
    fn inspector_text(&self) -> String {
        let Some((pane, x, y)) = self.canvas.hovered else {
            return "pixel inspector: point at a pane".into();
        };
        let mut parts = vec![format!("pixel ({x}, {y}) in {}", pane_letter(pane))];
        for index in 0..self.settings.layout.panes() {
            let name = match &self.settings.panes[index].source {
                PaneSource::Method { name, .. } => name.clone(),
                PaneSource::Difference { .. } => continue,
            };
            let value = self
                .pane_capture(index)
                .or_else(|| {
                    (name == REFERENCE)
                        .then(|| self.reference_image())
                        .flatten()
                })
                .map_or("…".into(), |img| format!("{:.4}", img.get(x, y)));
            parts.push(format!("{} {name} {value}", pane_letter(index)));
        }
        let reference = self
            .reference_image()
            .map_or("…".into(), |img| format!("{:.4}", img.get(x, y)));
        parts.push(format!("reference {reference}"));
        parts.join(" · ")
    }

    pub(super) fn windows(&mut self, ctx: &egui::Context) {
        egui::Window::new("Keyboard and mouse")
            .open(&mut self.help_open)
            .resizable(false)
            .show(ctx, |ui| {
                egui::Grid::new("shortcuts").striped(true).show(ui, |ui| {
                    for shortcut in SHORTCUTS {
                        ui.strong(shortcut.keys);
                        ui.label(shortcut.what);
                        ui.end_row();
                    }
                });
            });
        self.motion_window(ctx);
        if let Some(path) = self.font_dialog.show(ctx, "font") {
            self.open_font(path);
        }
        let mut open = self.sweep.open;
        let mut start = false;
        let mut apply = None;
        egui::Window::new("Speed vs error")
            .open(&mut open)
            .default_pos([360.0, 120.0])
            .default_size([720.0, 480.0])
            .show(ctx, |ui| {
                ui.horizontal(|ui| {
                    if self.sweep.running() {
                        if ui.button("Cancel").clicked() {
                            self.sweep.cancel();
                        }
                    } else if ui
                        .button("Run sweep")
                        .on_hover_text(
                            "every parameter combination of every method, on this scene and view",
                        )
                        .clicked()
                    {
                        start = true;
                    }
                    if let Some((done, total)) = self.sweep.progress() {
                        ui.add(
                            egui::ProgressBar::new(done as f32 / total.max(1) as f32)
                                .text(format!("{done} / {total}"))
                                .desired_width(200.0),
                        );
                    } else if !self.sweep.points.is_empty() {
                        ui.weak(format!("measured on {}", self.sweep.measured_on));
                    }
                });
                for problem in &self.sweep.problems {
                    ui.colored_label(ui.visuals().warn_fg_color, problem);
                }
                ui.weak("Click a point to give its parameters to pane A.");
                apply = self.sweep.plot(ui);
            });
        self.sweep.open = open;
        if start {
            self.start_sweep(ctx);
        }
        if let Some(point) = apply {
            self.settings.panes[0].source = PaneSource::Method {
                name: point.method.into(),
                params: point.params,
            };
        }
    }
}

/// A combo box choosing `value` among `all`, `labels` giving each its (shown when
/// chosen, listed) names. A fixed width: a label-sized box would resize the panel and so
/// the panes.
fn fixed_width_choice<T: Copy + PartialEq>(
    ui: &mut egui::Ui,
    (id, width): (&str, f32),
    value: &mut T,
    all: &[T],
    labels: impl Fn(T) -> (&'static str, &'static str),
) -> egui::Response {
    egui::ComboBox::from_id_salt(id)
        .width(width)
        .selected_text(labels(*value).0)
        .show_ui(ui, |ui| {
            for &choice in all {
                ui.selectable_value(value, choice, labels(choice).1);
            }
        })
        .response
}
