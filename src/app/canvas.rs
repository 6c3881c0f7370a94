//! The canvas, the central panel: the panes laid out on whole pixels, the shared camera steered by
//! the pointer, each pane's paint callback, and what is drawn over the panes (labels
//! and numbers, legends, outlines). When the view rests, each pane's coverage is read
//! back once and the reference and errors are asked for in the background.

use std::sync::Arc;

use eframe::egui;
use glam::DVec2;

use super::analysis::Request;
use super::blink::BLINKING_PANE;
use super::display::{CoverageAdjust, DisplayMode};
use super::explorer::Explorer;
use super::gpu_view::{CompositeMode, PanePaint, Source, lock};
use super::outline_painter::{self, Style};
use super::panes::{REFERENCE, pane_letter, subtrahend_label};
use super::settings::{PaneOverlay, PaneSource};
use super::state::{CanvasKey, Reading};
use crate::camera::Camera;
use crate::gpu::shaders::COST_SCALE_CURVES;
use crate::magnify::{VALUES_FROM, block_labels};
use crate::methods::params::assignments;
use crate::methods::{Overlay, registry};

/// Space between panes, points.
const GAP: f32 = 2.0;
/// Wheel zoom: factor per point scrolled.
const WHEEL_ZOOM_PER_POINT: f64 = 0.004;
/// Seconds the view must stay still before the reference and the errors are worked out.
const REST_SECONDS: f64 = 0.25;

/// The first start's view: the text at a size where methods differ visibly
/// (px/em), its top-left at the margin, magnified (×N) on pane A's worst pixel.
pub const OPENING: (f64, u32) = (12.0, 8);

impl Explorer {
    pub(super) fn show_canvas(&mut self, ui: &mut egui::Ui) {
        let area = ui.available_rect_before_wrap();
        let ppp = ui.ctx().pixels_per_point();
        let ((width, height), rects) = pane_rects(area, ppp, self.settings.layout.grid());

        self.frame_text(ui, (width, height));
        self.steer(ui, area, &rects, ppp, (width, height));
        self.canvas.rects = rects.clone();
        let (camera, window) = self.pane_camera_now(width, height);
        self.canvas.camera = Some(camera);
        self.canvas.window = Some(window);
        self.canvas.pane_size = Some((width, height));

        let Some((gpu, _)) = self.gpu.clone() else {
            return;
        };
        let scene = self.scene.scene().cloned();
        let generation = self.scene.generation();
        for (index, pane) in self.panes.iter_mut().enumerate().take(rects.len()) {
            pane.sync(
                &gpu,
                &self.catalog,
                &self.settings.panes[index],
                scene.as_deref().map(|s| (s, generation)),
            );
        }
        // A pane drawing a user's file looks for a save twice a second, input or not.
        if self.settings.panes[..rects.len()]
            .iter()
            .any(|p| super::panes::user_file(p).is_some())
        {
            ui.ctx()
                .request_repaint_after(std::time::Duration::from_millis(500));
        }

        // Methods draw first, so that a difference pane, and a blinking pane showing
        // another's target, read this frame's targets.
        let blinking = self.blink_source().is_some();
        let mut order: Vec<usize> = (0..rects.len()).collect();
        order.sort_by_key(|&i| {
            matches!(self.settings.panes[i].source, PaneSource::Difference { .. })
                || (blinking && i == BLINKING_PANE)
        });
        let painter = ui.painter();
        painter.rect_filled(area, 0.0, ui.visuals().extreme_bg_color);
        self.canvas.notes = vec![String::new(); rects.len()];
        let now = ui.ctx().input(|i| i.time);
        let moving = self.canvas.key.as_ref().is_none_or(|k| k.camera != camera)
            || now - self.canvas.changed_at < REST_SECONDS;
        for index in order {
            let rect = rects[index];
            painter.rect_filled(rect, 0.0, color(self.settings.background));
            let (paint, note) = self.pane_paint(index, &camera, rect, moving);
            self.canvas.notes[index] = note;
            if let Some(paint) = paint {
                painter.add(egui_wgpu::Callback::new_paint_callback(rect, paint));
            }
        }
        for (index, rect) in rects.iter().enumerate() {
            self.decorate(ui, index, *rect, &camera, ppp);
        }
    }

    /// Fits the text (or places a loaded case) in a `pane` of pixels when [`AutoFit`]
    /// says so.
    fn frame_text(&mut self, ui: &egui::Ui, pane: (u32, u32)) {
        let auto_fit = &mut self.auto_fit;
        let layout = self.settings.layout;
        if auto_fit.layout.replace(layout).is_some_and(|l| l != layout) {
            auto_fit.pending = true;
        }
        let text = &self.settings.scene.text;
        if !ui.ctx().egui_wants_keyboard_input()
            && auto_fit.text.as_ref() != Some(text)
            && auto_fit.text.replace(text.clone()).is_some()
        {
            auto_fit.pending = true;
        }
        if (auto_fit.pending || auto_fit.opening)
            && self.scene.is_built_for(&self.settings.scene)
            && let Some(scene) = self.scene.scene().cloned()
        {
            if std::mem::take(&mut self.auto_fit.opening) {
                let camera = &mut self.settings.camera;
                camera.size_px_per_em = OPENING.0;
                camera.reset(&scene);
                camera.magnify = OPENING.1;
                self.go_to_worst_pixel_when_ready();
            } else if !self.place_case(pane) {
                let size = DVec2::new(f64::from(pane.0), f64::from(pane.1));
                self.settings.camera.fit(&scene, size);
            }
            self.auto_fit.pending = false;
        }
    }

    /// Pan by dragging, zoom with the wheel about the cursor, and find the pixel under it.
    fn steer(
        &mut self,
        ui: &mut egui::Ui,
        area: egui::Rect,
        rects: &[egui::Rect],
        ppp: f32,
        pane_pixels: (u32, u32),
    ) {
        let response = ui.interact(
            area,
            ui.scope_id().with("view"),
            egui::Sense::click_and_drag(),
        );
        let upem = self.scene.units_per_em();
        if response.dragged() {
            let block = f64::from(self.settings.camera.magnify.max(1));
            // Magnified, the text follows the pointer block for block.
            let d = response.drag_delta() * ppp;
            self.settings
                .camera
                .pan(DVec2::new(f64::from(d.x), f64::from(d.y)) / block);
        }
        self.canvas.hovered = None;
        let Some(pointer) = response.hover_pos() else {
            return;
        };
        let Some((index, rect)) = rects.iter().enumerate().find(|(_, r)| r.contains(pointer))
        else {
            return;
        };
        let local = (pointer - rect.min) * ppp;
        let cursor = DVec2::new(f64::from(local.x), f64::from(local.y));
        let (width, height) = pane_pixels;
        let window = self.settings.camera.pane_camera(width, height).1;
        let block = f64::from(window.factor);
        // The ×1 pane pixel under the cursor.
        let under = DVec2::new(f64::from(window.x0), f64::from(window.y0)) + cursor / block;
        let (scroll, pinch, alt, scrolling) = ui.input(|i| {
            (
                i.smooth_scroll_delta.y,
                i.zoom_delta(),
                i.modifiers.alt,
                i.is_scrolling(),
            )
        });
        self.canvas.magnifying_scroll &= scrolling;
        // Alt + wheel, from the wheel's own events (unsmoothed, each with its modifiers):
        // the magnifier, one notch a doubling, about the cursor.
        let magnify_scroll: f32 = ui.input(|i| {
            i.raw
                .events
                .iter()
                .map(|e| match e {
                    egui::Event::MouseWheel {
                        delta, modifiers, ..
                    } if modifiers.alt => delta.y,
                    _ => 0.0,
                })
                .sum()
        });
        if magnify_scroll != 0.0 {
            self.canvas.magnifying_scroll = true;
            let factor = if magnify_scroll > 0.0 {
                window.factor * 2
            } else {
                window.factor / 2
            };
            self.settings
                .camera
                .magnify_about(factor, cursor, width, height);
        } else if !alt && !self.canvas.magnifying_scroll {
            let factor = f64::from(pinch) * (f64::from(scroll) * WHEEL_ZOOM_PER_POINT).exp();
            if factor != 1.0 {
                let anchor = self.settings.camera.untilted(under, width, height);
                self.settings.camera.zoom(factor, anchor, upem);
            }
        }
        // The pixel of the drawn image (the window's, when magnified) under the cursor.
        self.canvas.hovered = pixel_under(
            pointer,
            *rect,
            ppp,
            window.factor,
            (window.cols, window.rows),
        )
        .map(|(x, y)| (index, x, y));
    }

    /// A pane that shows a method's coverage, or the reference, as a source for others.
    fn source_of(&self, index: usize) -> Option<Source> {
        match &self.settings.panes[index].source {
            PaneSource::Method { name, .. } if name == REFERENCE => self
                .reference_is_current()
                .then(|| Source::Reference(self.reference.texture.clone())),
            PaneSource::Method { .. } => self.panes[index]
                .has_method()
                .then(|| Source::Pane(self.panes[index].surface.clone())),
            PaneSource::Difference { .. } => None,
        }
    }

    /// What pane `index` draws this frame (the GPU handles are filled in by the caller),
    /// and a note to show on it.
    fn pane_paint(
        &self,
        index: usize,
        camera: &Camera,
        rect: egui::Rect,
        moving: bool,
    ) -> (Option<PanePaint>, String) {
        let settings = &self.settings.panes[index];
        let pane = &self.panes[index];
        let text_srgb = self.settings.text_color.map(|c| f32::from(c) / 255.0);
        let darkening = self
            .settings
            .darkening
            .adjust(camera.size_px_per_em as f32, text_srgb);
        let paint = |camera: Option<Camera>, first, second, mode| PanePaint {
            gpu: self.gpu.as_ref().expect("checked by the caller").0.clone(),
            compositor: self.gpu.as_ref().expect("checked by the caller").1.clone(),
            surface: pane.surface.clone(),
            camera,
            always: self.settings.continuous,
            first,
            second,
            mode,
            text: color(self.settings.text_color).into(),
            background: color(self.settings.background).into(),
            difference_scale: self.settings.difference_scale,
            display: self.settings.display,
            darkening,
            block: self.canvas.window.map_or(1, |w| w.factor),
            moving,
            rect,
        };
        let waiting = "error: shown once the view rests and the reference is ready".to_string();
        // The title says what it shows: a note would sit over the pixels compared.
        if index == BLINKING_PANE
            && let Some((source, _)) = self.blink_source()
        {
            return (
                Some(paint(None, Some(source), None, CompositeMode::Coverage)),
                String::new(),
            );
        }
        match &settings.source {
            PaneSource::Method { name, .. } if name == REFERENCE => {
                if self.reference.image.is_none() {
                    let note = self
                        .reference
                        .problem
                        .clone()
                        .unwrap_or("reference: working…".into());
                    return (None, note);
                }
                let note = if self.reference_is_current() {
                    String::new()
                } else {
                    "reference: working…".into()
                };
                let source = Source::Reference(self.reference.texture.clone());
                (
                    Some(paint(None, Some(source), None, CompositeMode::Coverage)),
                    note,
                )
            }
            PaneSource::Method { name, .. } => {
                if !pane.has_method() {
                    return (None, String::new());
                }
                let surface = lock(&pane.surface);
                if moving && surface.waits_for_rest() {
                    let ms = surface.last_encode_ms.unwrap_or_default();
                    let note = format!(
                        "{name}: a frame takes {ms:.0} ms on this device, so it is redrawn \
                         when the view rests"
                    );
                    drop(surface);
                    return (
                        Some(paint(Some(*camera), None, None, CompositeMode::Coverage)),
                        note,
                    );
                }
                drop(surface);
                match &settings.overlay {
                    PaneOverlay::Method(_) => (
                        Some(paint(
                            Some(*camera),
                            None,
                            None,
                            CompositeMode::OverlayPicture,
                        )),
                        String::new(),
                    ),
                    PaneOverlay::Error if self.reference_is_current() => (
                        Some(paint(
                            Some(*camera),
                            None,
                            Some(Source::Reference(self.reference.texture.clone())),
                            CompositeMode::Difference,
                        )),
                        String::new(),
                    ),
                    PaneOverlay::Error => (
                        Some(paint(Some(*camera), None, None, CompositeMode::Coverage)),
                        waiting,
                    ),
                    PaneOverlay::None => (
                        Some(paint(Some(*camera), None, None, CompositeMode::Coverage)),
                        String::new(),
                    ),
                }
            }
            PaneSource::Difference { first, second } => {
                let first = self.source_of(*first);
                let second = match second {
                    Some(i) => self.source_of(*i),
                    None => self
                        .reference_is_current()
                        .then(|| Source::Reference(self.reference.texture.clone())),
                };
                match (first, second) {
                    (Some(a), Some(b)) => (
                        Some(paint(None, Some(a), Some(b), CompositeMode::Difference)),
                        String::new(),
                    ),
                    _ => (None, "difference: waiting for both sides (a method pane, or the reference once the view rests)".into()),
                }
            }
        }
    }

    /// Labels, numbers, legends, outline and notes over pane `index`.
    fn decorate(
        &self,
        ui: &mut egui::Ui,
        index: usize,
        rect: egui::Rect,
        camera: &Camera,
        ppp: f32,
    ) {
        let settings = &self.settings.panes[index];
        let painter = ui.painter_at(rect);
        let mut notes: Vec<String> = Vec::new();
        let block = self.canvas.window.map_or(1, |w| w.factor);
        if block >= VALUES_FROM
            && let Some((captured, image)) = &self.panes[index].capture
            && Some(*captured) == self.canvas.camera
        {
            // The error overlay writes each pixel's error under its coverage.
            let reference = (settings.overlay == PaneOverlay::Error)
                .then(|| self.reference_image())
                .flatten()
                .filter(|r| (r.width, r.height) == (image.width, image.height));
            paint_values(&painter, rect, block, ppp, image, reference.as_deref());
        }
        // The merged scene is made only when a pane shows it (a union per glyph).
        let outlines = [
            (
                settings.merged.then(|| self.scene.merged_scene()).flatten(),
                Style::Merged,
            ),
            (
                settings.outline.then(|| self.scene.scene()).flatten(),
                Style::Font,
            ),
        ];
        for (scene, style) in outlines {
            if let Some(scene) = scene
                && let Err(e) = outline_painter::paint(&painter, scene, camera, ppp, block, style)
            {
                notes.push(e);
            }
        }
        self.paint_mark(&painter, rect, ppp);
        let mut lines = vec![self.pane_title(index)];
        lines.extend(self.pane_numbers(index));
        let text = lines.join("\n");
        let font = egui::FontId::monospace(11.0);
        let galley = painter.layout_no_wrap(text, font, egui::Color32::from_gray(230));
        let label = egui::Rect::from_min_size(
            rect.min + egui::vec2(4.0, 4.0),
            galley.size() + egui::vec2(8.0, 6.0),
        );
        painter.rect_filled(label, 3.0, egui::Color32::from_black_alpha(170));
        painter.galley(
            label.min + egui::vec2(4.0, 3.0),
            galley,
            egui::Color32::WHITE,
        );

        if let Some(problem) = self.pane_problem(index) {
            notes.push(problem);
        }
        if !self.canvas.notes[index].is_empty() {
            notes.push(self.canvas.notes[index].clone());
        }
        if let Some(scene_problem) = self.scene.problem() {
            notes.push(scene_problem);
        }
        if !notes.is_empty() {
            painter.text(
                rect.center(),
                egui::Align2::CENTER_CENTER,
                notes.join("\n"),
                egui::FontId::proportional(14.0),
                egui::Color32::from_gray(150),
            );
        }
        self.legend(ui, index, rect);
    }

    fn pane_title(&self, index: usize) -> String {
        let settings = &self.settings.panes[index];
        let mut title = match &settings.source {
            PaneSource::Method { name, params } => {
                let params: Vec<String> = assignments(params).collect();
                format!("{} {name} {}", pane_letter(index), params.join(" "))
                    .trim_end()
                    .to_string()
            }
            PaneSource::Difference { first, second } => format!(
                "{} difference {} − {}",
                pane_letter(index),
                pane_letter(*first),
                subtrahend_label(*second)
            ),
        };
        match &settings.overlay {
            PaneOverlay::Method(name) => title += &format!(" · overlay {name}"),
            PaneOverlay::Error => title += " · error vs reference",
            PaneOverlay::None => {}
        }
        if index == BLINKING_PANE
            && let Some((_, shown)) = self.blink_source()
        {
            title += &format!(" · blink: showing {shown}");
        }
        title
    }

    /// The live numbers of a pane, one line each.
    fn pane_numbers(&self, index: usize) -> Vec<String> {
        let pane = &self.panes[index];
        let mut lines = Vec::new();
        if matches!(&self.settings.panes[index].source, PaneSource::Method { name, .. } if name == REFERENCE)
        {
            if let Some(ms) = self.reference.cpu_ms {
                lines.push(format!(
                    "CPU {ms:.0} ms (exact, {})",
                    super::analysis::WHERE
                ));
            }
            return lines;
        }
        if !pane.has_method() {
            return lines;
        }
        let surface = lock(&pane.surface);
        let gpu_time = match surface.timer.median_ms() {
            Some((ms, n)) => format!("GPU {ms:.3} ms (median of {n})"),
            None if self.gpu.as_ref().is_some_and(|(g, _)| !g.has_timestamps()) => {
                "GPU time: no timestamp queries".into()
            }
            None => "GPU time: …".into(),
        };
        // The CPU's share of every frame: the method's culling, meshing and uploads.
        let time = match surface.timer.median_cpu_ms() {
            Some(ms) => format!("{gpu_time} + CPU {ms:.3} ms/frame"),
            None => gpu_time,
        };
        drop(surface);
        // A peer's live figures are the pane's frame as recorded here (the copy of its
        // picture in, vello's own submissions under CPU): `render --stats` separates
        // them.
        let is_peer = match &self.settings.panes[index].source {
            PaneSource::Method { name, .. } => registry::find(name).is_ok_and(|m| m.is_peer()),
            PaneSource::Difference { .. } => false,
        };
        let time = if is_peer {
            format!("{time} (as drawn here; render --stats times the peer alone)")
        } else {
            time
        };
        lines.push(format!(
            "{time} · {} · prepare {:.0} ms",
            kib_or_mib(pane.gpu_bytes),
            pane.prepare_ms
        ));
        match self.pane_error(index) {
            Some(e) => lines.push(format!(
                "MAE {:.3}/255 (edges {:.2}) · max {:.3} · >0.5: {} px",
                e.mae_255, e.edge.mae_255, e.max, e.pixels_over_05
            )),
            None => lines.push("error vs reference: …".into()),
        }
        if let Some((c, cost)) = &pane.curves
            && Some(*c) == self.canvas.camera
        {
            lines.push(format!(
                "curves/px {:.2} mean, {} max",
                cost.mean,
                cost.max_text()
            ));
        }
        lines
    }

    /// The colour scale of the picture a pane shows, if it has one.
    fn legend(&self, ui: &mut egui::Ui, index: usize, rect: egui::Rect) {
        let settings = &self.settings.panes[index];
        let bar = egui::Rect::from_min_size(
            egui::pos2(rect.min.x + 12.0, rect.max.y - 30.0),
            egui::vec2((rect.width() * 0.4).min(240.0), 10.0),
        );
        let painter = ui.painter_at(rect);
        let label = |x: f32, align: egui::Align2, text: String| {
            painter.text(
                egui::pos2(x, bar.max.y + 2.0),
                align,
                text,
                egui::FontId::monospace(10.0),
                egui::Color32::from_gray(220),
            );
        };
        let cost = settings.overlay == PaneOverlay::Method(Overlay::CostHeatMap.name().into());
        let signed = settings.overlay == PaneOverlay::Error
            || matches!(settings.source, PaneSource::Difference { .. });
        if cost && let Some((gpu, compositor)) = &self.gpu {
            let paint = PanePaint {
                gpu: gpu.clone(),
                compositor: compositor.clone(),
                surface: self.legend_surface(index),
                camera: None,
                always: false,
                first: None,
                second: None,
                mode: CompositeMode::HeatScale,
                text: egui::Rgba::WHITE,
                background: egui::Rgba::BLACK,
                difference_scale: 1.0,
                display: DisplayMode::Linear,
                darkening: CoverageAdjust::NONE,
                block: 1,
                moving: false,
                rect: bar,
            };
            painter.add(egui_wgpu::Callback::new_paint_callback(bar, paint));
            label(bar.min.x, egui::Align2::LEFT_TOP, "0".into());
            label(
                bar.max.x,
                egui::Align2::RIGHT_TOP,
                format!("{COST_SCALE_CURVES}+ curves/px"),
            );
        } else if signed {
            // Linear in value, like `metrics::error_image`: blue, black, red.
            let mut mesh = egui::Mesh::default();
            let stops = [
                (0.0, egui::Color32::from_rgb(0, 0, 255)),
                (0.5, egui::Color32::BLACK),
                (1.0, egui::Color32::from_rgb(255, 0, 0)),
            ];
            for pair in stops.windows(2) {
                let (t0, c0) = pair[0];
                let (t1, c1) = pair[1];
                let x0 = bar.min.x + bar.width() * t0;
                let x1 = bar.min.x + bar.width() * t1;
                let base = mesh.vertices.len() as u32;
                mesh.colored_vertex(egui::pos2(x0, bar.min.y), c0);
                mesh.colored_vertex(egui::pos2(x1, bar.min.y), c1);
                mesh.colored_vertex(egui::pos2(x1, bar.max.y), c1);
                mesh.colored_vertex(egui::pos2(x0, bar.max.y), c0);
                mesh.add_triangle(base, base + 1, base + 2);
                mesh.add_triangle(base, base + 2, base + 3);
            }
            painter.add(mesh);
            let s = self.settings.difference_scale;
            label(
                bar.min.x,
                egui::Align2::LEFT_TOP,
                format!("−{s:.2} too little"),
            );
            label(bar.center().x, egui::Align2::CENTER_TOP, "0".into());
            label(
                bar.max.x,
                egui::Align2::RIGHT_TOP,
                format!("+{s:.2} too much"),
            );
        }
    }
}

/// A human size: B, KiB or MiB.
fn kib_or_mib(n: u64) -> String {
    match n {
        0..1024 => format!("{n} B"),
        1024..1_048_576 => format!("{:.1} KiB", n as f64 / 1024.0),
        _ => format!("{:.1} MiB", n as f64 / 1_048_576.0),
    }
}

impl Explorer {
    /// The surface a pane's heat-scale legend draws with (its own uniform and bind group).
    fn legend_surface(&self, index: usize) -> super::gpu_view::SharedSurface {
        self.legends[index].clone()
    }

    /// Whether every visible pane that draws a method has drawn the view shown.
    pub fn panes_drawn(&self) -> bool {
        let Some(camera) = self.canvas.camera else {
            return false;
        };
        let visible = self.settings.layout.panes();
        self.panes[..visible].iter().zip(&self.settings.panes).all(|(pane, settings)| {
            let draws = matches!(&settings.source, PaneSource::Method { name, .. } if name != REFERENCE);
            !draws || lock(&pane.surface).shows(&camera)
        })
    }

    /// Once the view has rested: reads each pane's coverage back once and asks the
    /// background worker for the reference, the errors and the curves per pixel.
    pub(super) fn settle(&mut self, ctx: &egui::Context) {
        let (Some(camera), Some(scene)) = (self.canvas.camera, self.scene.scene().cloned()) else {
            return;
        };
        let Some((gpu, _)) = self.gpu.clone() else {
            return;
        };
        let visible = self.settings.layout.panes();
        let key = CanvasKey {
            camera,
            scene: self.scene.generation(),
            panes: self.panes[..visible]
                .iter()
                .map(|p| {
                    let surface = lock(&p.surface);
                    (surface.generation, surface.method.is_some())
                })
                .collect(),
        };
        let now = ctx.input(|i| i.time);
        if self.canvas.key.as_ref() != Some(&key) {
            self.canvas.key = Some(key.clone());
            self.canvas.changed_at = now;
        }
        if self.canvas.analysed.as_ref() == Some(&key) {
            // A step that changed nothing (Home at frame 0) has nothing to analyse.
            self.playback.stepped = false;
            return;
        }
        let waited = now - self.canvas.changed_at;
        // A frame of motion is analysed at once: it is not the pointer still moving.
        if waited < REST_SECONDS && !self.playback.stepped {
            ctx.request_repaint_after(std::time::Duration::from_secs_f64(REST_SECONDS - waited));
            return;
        }
        // Read each drawn pane back without waiting: started once the view has rested
        // and every pane has drawn it, taken on the frames after, then sent.
        if self.canvas.reading.as_ref().is_none_or(|r| r.key != key) {
            // Every pane drawn for this view first, so that no read-back is started and
            // then dropped.
            let all_drawn = self.panes[..visible].iter().all(|pane| {
                let surface = lock(&pane.surface);
                surface.method.is_none() || surface.draw_error.is_some() || surface.shows(&camera)
            });
            if !all_drawn {
                self.canvas.reading = None;
                ctx.request_repaint();
                return;
            }
            let mut pending = Vec::new();
            for (index, pane) in self.panes[..visible].iter_mut().enumerate() {
                let surface = lock(&pane.surface);
                if surface.method.is_none() || surface.draw_error.is_some() {
                    continue;
                }
                let target = surface.target.as_ref().expect("drawn, so it has a target");
                match target.start_readback(&gpu) {
                    Ok(readback) => pending.push((index, readback)),
                    Err(e) => {
                        drop(surface);
                        pane.problem = Some(e.to_string());
                    }
                }
            }
            self.canvas.reading = Some(Reading { key, pending });
            ctx.request_repaint();
            return;
        }
        let answered = self
            .canvas
            .reading
            .as_ref()
            .is_some_and(|r| r.pending.iter().all(|(_, p)| p.is_answered(&gpu)));
        if !answered {
            // The GPU has not answered every read-back yet: look again next frame.
            ctx.request_repaint();
            return;
        }
        let Some(reading) = self.canvas.reading.take() else {
            return;
        };
        let mut captures = Vec::new();
        let mut counts = Vec::new();
        for (index, readback) in reading.pending {
            match readback.take() {
                Ok(image) => {
                    let image = Arc::new(image);
                    self.panes[index].capture = Some((camera, image.clone()));
                    captures.push((index, image));
                }
                Err(e) => self.panes[index].problem = Some(e.to_string()),
            }
            if let PaneSource::Method { name, params } = &self.settings.panes[index].source {
                counts.push((index, name.clone(), params.clone()));
            }
        }
        let pane_generations = self
            .panes
            .iter()
            .map(|pane| lock(&pane.surface).generation)
            .collect();
        self.analysis.send(Request {
            id: 0,
            scene,
            scene_generation: self.scene.generation(),
            camera,
            captures,
            counts,
            pane_generations,
            motion_frame: self.motion_key().map(|key| (self.playback.frame, key)),
        });
        self.playback.stepped = false;
        self.canvas.analysed = Some(reading.key);
    }
}

/// Each block's coverage, as read back, written in it (`magnify::block_labels`, as
/// `render --magnify` writes them), and its error against `reference` under it.
fn paint_values(
    painter: &egui::Painter,
    rect: egui::Rect,
    block: u32,
    ppp: f32,
    image: &crate::coverage::CoverageImage,
    reference: Option<&crate::coverage::CoverageImage>,
) {
    let step = block as f32 / ppp;
    let size = (step / 4.0).clamp(6.0, 14.0);
    let font = egui::FontId::monospace(size);
    for y in 0..image.height {
        for x in 0..image.width {
            let min = rect.min + egui::vec2(x as f32, y as f32) * step;
            if min.x >= rect.max.x || min.y >= rect.max.y {
                continue;
            }
            let labels = block_labels(image.get(x, y), reference.map(|r| r.get(x, y)));
            for (line, label) in labels.into_iter().enumerate() {
                let at = min + egui::vec2(0.0, line as f32 * size * 1.2);
                // White on a black shadow: legible over any text and background colour.
                for (offset, ink) in [(3.0, egui::Color32::BLACK), (2.0, egui::Color32::WHITE)] {
                    painter.text(
                        at + egui::vec2(offset, offset),
                        egui::Align2::LEFT_TOP,
                        label.clone(),
                        font.clone(),
                        ink,
                    );
                }
            }
        }
    }
}

fn color(rgb: [u8; 3]) -> egui::Color32 {
    egui::Color32::from_rgb(rgb[0], rgb[1], rgb[2])
}

/// The panes of a `(columns, rows)` grid in `area` at `ppp` pixels per point: each
/// pane's size in whole pixels (so a target texel is a framebuffer pixel) and where each
/// is drawn, in points, its corner snapped to a pixel.
fn pane_rects(
    area: egui::Rect,
    ppp: f32,
    (columns, rows): (usize, usize),
) -> ((u32, u32), Vec<egui::Rect>) {
    let cell = egui::vec2(
        (area.width() - GAP * (columns - 1) as f32) / columns as f32,
        (area.height() - GAP * (rows - 1) as f32) / rows as f32,
    );
    let width = (cell.x * ppp).floor().max(1.0) as u32;
    let height = (cell.y * ppp).floor().max(1.0) as u32;
    let size = egui::vec2(width as f32, height as f32) / ppp;
    let snap = |p: egui::Pos2| (p.to_vec2() * ppp).round().to_pos2() / ppp;
    let rects = (0..columns * rows)
        .map(|k| {
            let (c, r) = (k % columns, k / columns);
            let min = area.min + egui::vec2(c as f32 * (size.x + GAP), r as f32 * (size.y + GAP));
            egui::Rect::from_min_size(snap(min), size)
        })
        .collect();
    ((width, height), rects)
}

/// The pixel under `pointer` in a pane drawn at `rect` (points) whose target is
/// `width` × `height` pixels at `ppp` pixels per point, each drawn `block` pixels a
/// side (the magnifier). Bounded in whole pixels after
/// flooring: the pane's rect holds its far edge, and in points at a fractional scale
/// its width times `ppp` may round past the last pixel, so a bound in floats let the
/// pointer there read one column or row beyond the target.
fn pixel_under(
    pointer: egui::Pos2,
    rect: egui::Rect,
    ppp: f32,
    block: u32,
    (width, height): (u32, u32),
) -> Option<(u32, u32)> {
    let local = ((pointer - rect.min) * ppp / block as f32).floor();
    if !(local.x >= 0.0 && local.y >= 0.0) {
        return None;
    }
    // Non-negative and floored: the casts only saturate, and the bound then refuses.
    let (x, y) = (local.x as u32, local.y as u32);
    (x < width && y < height).then_some((x, y))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At fractional scale factors, a pointer anywhere in a pane's rect (its far edges
    /// included, as `Rect::contains` has them) names a pixel of the pane's target or,
    /// on the far edges, none; never one past the last column or row.
    #[test]
    fn the_hovered_pixel_stays_inside_the_pane_at_fractional_scales() {
        let mut checked = 0;
        for ppp in [1.1, 1.25, 4.0 / 3.0, 1.5, 1.75, 2.25, 2.5, 0.9] {
            for grid in [(1, 1), (2, 1), (2, 2), (3, 2)] {
                for extent in (300..=1400).step_by(7) {
                    let area = egui::Rect::from_min_size(
                        egui::pos2(13.37, 41.3),
                        egui::vec2(extent as f32, extent as f32 * 0.61),
                    );
                    let ((width, height), rects) = pane_rects(area, ppp, grid);
                    for rect in rects {
                        for block in [1, 3, 8] {
                            let (cols, rows) = (width.div_ceil(block), height.div_ceil(block));
                            let under = |p| pixel_under(p, rect, ppp, block, (cols, rows));
                            assert!(under(rect.center()).is_some());
                            for pointer in
                                [rect.min, rect.max, rect.right_top(), rect.left_bottom()]
                            {
                                assert!(rect.contains(pointer));
                                if let Some((x, y)) = under(pointer) {
                                    assert!(
                                        x < cols && y < rows,
                                        "ppp {ppp} ×{block}: ({x}, {y}) outside {cols}x{rows} \
                                         for {pointer:?} in {rect:?}"
                                    );
                                }
                                checked += 1;
                            }
                        }
                    }
                }
            }
        }
        assert!(checked > 10_000);
    }
}
