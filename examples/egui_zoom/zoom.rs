//! The app of `examples/egui_zoom`, shared with its test (`tests/egui_zoom.rs`): an
//! egui `Scene` whose labels are drawn twice, side by side in one font — on the left by
//! egui, which rasterizes each glyph once and magnifies the bitmap as you zoom, on the
//! right by `glyphscope::text`, whose coverage stays exact at every zoom. Below them, a
//! panel of [`PANEL`] small labels drawn by the library alone, as a UI's are, which
//! "animate" scrolls every frame: the frame time in the corner says what they cost.

use std::sync::Arc;

use eframe::{egui, egui_wgpu};
use glam::{Mat3, vec2};
use glyphscope::font::DEFAULT_FONT_BYTES;
use glyphscope::text::{Content, FontId, TextRenderer, TextRun};

/// The labels, one a line.
pub const LABELS: [&str; 3] = [
    "Hamburgefonstiv",
    "Zoom in: egui magnifies",
    "its bitmaps; this stays sharp",
];
/// Their size and line pitch, scene points.
pub const SIZE: f32 = 14.0;
pub const PITCH: f32 = 22.0;
/// Where the library's column starts, scene points (egui's starts at 0).
pub const LIBRARY_X: f32 = 240.0;
/// The text colour (sRGB) on a light background.
pub const INK: [u8; 3] = [20, 20, 30];
/// The panel's labels, in columns below the lines, and its top, scene points.
pub const PANEL: usize = 300;
const PANEL_COLUMNS: usize = 10;
const PANEL_TOP: f32 = 90.0;
const PANEL_WORDS: [&str; 8] = [
    "Layer", "Opacity", "Node", "Mix", "Width", "Street", "Item", "Value",
];

pub struct ZoomApp {
    /// What the scene shows, in scene points: egui's Scene keeps it as you pan and zoom.
    pub scene_rect: egui::Rect,
    /// Scene points to screen points, as the last frame drew them.
    pub scene_to_screen: Mat3,
    /// The target's format, as eframe chose it (its test reads coverage back by it).
    #[allow(dead_code)]
    pub format: wgpu::TextureFormat,
    /// Whether the panel's switch and the frame time are shown over the scene (the
    /// example shows them; its test measures the scene alone).
    pub controls: bool,
    /// Whether the panel scrolls every frame, and by how much it has.
    animate: bool,
    scroll: f32,
}

/// The library, kept with egui's renderer so that paint callbacks reach it.
struct Library {
    text: TextRenderer,
    font: FontId,
    /// The panel's labels: text, size and baseline start (scene points).
    panel: Vec<(String, f32, egui::Pos2)>,
}

/// The library's column and panel, placed by the scene's transform (scene points to
/// screen points), the panel scrolled by `scroll` points.
struct LibraryLabels {
    scene_to_screen: Mat3,
    scroll: f32,
}

/// The panel's labels: a word and a number, 6 to 9 points, in columns.
fn panel() -> Vec<(String, f32, egui::Pos2)> {
    (0..PANEL)
        .map(|k| {
            let (column, row) = (k % PANEL_COLUMNS, k / PANEL_COLUMNS);
            let text = format!("{} {}", PANEL_WORDS[k % PANEL_WORDS.len()], k);
            let size = 6.0 + (k % 4) as f32;
            let pen = egui::pos2(47.0 * column as f32, PANEL_TOP + 9.0 * row as f32);
            (text, size, pen)
        })
        .collect()
}

impl ZoomApp {
    pub fn new(cc: &eframe::CreationContext<'_>) -> Result<ZoomApp, String> {
        // egui draws DejaVu Sans too, so the columns differ only in how they rasterize.
        let mut fonts = egui::FontDefinitions::default();
        fonts.font_data.insert(
            "dejavu".into(),
            Arc::new(egui::FontData::from_static(DEFAULT_FONT_BYTES)),
        );
        if let Some(family) = fonts.families.get_mut(&egui::FontFamily::Proportional) {
            family.insert(0, "dejavu".into());
        }
        cc.egui_ctx.set_fonts(fonts);
        let state = cc
            .wgpu_render_state
            .as_ref()
            .ok_or("eframe runs without wgpu")?;
        let mut text = TextRenderer::new(&state.device, &state.queue, state.target_format);
        let font = text
            .add_font(DEFAULT_FONT_BYTES.to_vec())
            .map_err(|e| e.to_string())?;
        state.renderer.write().callback_resources.insert(Library {
            text,
            font,
            panel: panel(),
        });
        let panel_bottom = PANEL_TOP + 9.0 * PANEL.div_ceil(PANEL_COLUMNS) as f32;
        Ok(ZoomApp {
            // Room above the lines for the controls.
            scene_rect: egui::Rect::from_min_max(
                egui::pos2(-10.0, -34.0),
                egui::pos2(470.0, panel_bottom),
            ),
            scene_to_screen: Mat3::IDENTITY,
            format: state.target_format,
            controls: false,
            animate: false,
            scroll: 0.0,
        })
    }

    /// The baseline's start of label `k` in the library's column, scene points.
    pub fn library_pen(k: usize) -> egui::Pos2 {
        egui::pos2(LIBRARY_X, SIZE + PITCH * k as f32)
    }
}

impl eframe::App for ZoomApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let ink = egui::Color32::from_rgb(INK[0], INK[1], INK[2]);
        egui::Frame::new()
            .fill(egui::Color32::from_gray(235))
            .show(ui, |ui| {
                // Where the Scene puts itself: all the room left.
                let outer =
                    egui::Rect::from_min_size(ui.cursor().min, ui.available_size_before_wrap());
                let scene = egui::Scene::new().zoom_range(0.1..=64.0);
                scene.show(ui, &mut self.scene_rect, |ui| {
                    for (k, label) in LABELS.iter().enumerate() {
                        let top = egui::pos2(0.0, PITCH * k as f32);
                        let text = egui::RichText::new(*label).size(SIZE).color(ink);
                        // Left-aligned at its line, as the library's column is.
                        let line =
                            egui::Rect::from_min_size(top, egui::vec2(LIBRARY_X - 10.0, PITCH));
                        ui.scope_builder(egui::UiBuilder::new().max_rect(line), |ui| {
                            ui.label(text)
                        });
                    }
                });
                // The transform egui's Scene uses: the scene rect fitted into the outer rect.
                let scale = (outer.size() / self.scene_rect.size()).min_elem();
                let shift = outer.center().to_vec2() - self.scene_rect.center().to_vec2() * scale;
                let scene_to_screen = Mat3::from_scale_angle_translation(
                    vec2(scale, scale),
                    0.0,
                    vec2(shift.x, shift.y),
                );
                self.scene_to_screen = scene_to_screen;
                if self.animate {
                    // A tenth of a point a frame, back to the top past two rows.
                    self.scroll = (self.scroll + 0.1) % 18.0;
                    ui.ctx().request_repaint();
                }
                let callback = LibraryLabels {
                    scene_to_screen,
                    scroll: self.scroll,
                };
                // Covering the screen, the callback's viewport is the whole target; the clip
                // keeps it inside the scene.
                let screen = ui.ctx().content_rect();
                ui.painter()
                    .with_clip_rect(outer)
                    .add(egui_wgpu::Callback::new_paint_callback(screen, callback));
                if !self.controls {
                    return;
                }
                // Over the scene's top left: the panel's switch and the frame time.
                let corner = egui::Rect::from_min_size(
                    outer.min + egui::vec2(8.0, 4.0),
                    egui::vec2(420.0, 24.0),
                );
                ui.scope_builder(egui::UiBuilder::new().max_rect(corner), |ui| {
                    ui.visuals_mut().override_text_color = Some(egui::Color32::from_gray(40));
                    ui.horizontal(|ui| {
                        ui.checkbox(&mut self.animate, "animate");
                        let ms = ui.ctx().input(|i| i.stable_dt) * 1e3;
                        ui.label(format!(
                            "{} labels by glyphscope::text · {ms:.1} ms a frame",
                            PANEL + LABELS.len()
                        ));
                    });
                });
            });
    }
}

impl egui_wgpu::CallbackTrait for LibraryLabels {
    fn prepare(
        &self,
        _device: &wgpu::Device,
        _queue: &wgpu::Queue,
        screen: &egui_wgpu::ScreenDescriptor,
        encoder: &mut wgpu::CommandEncoder,
        resources: &mut egui_wgpu::CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Some(library) = resources.get_mut::<Library>() else {
            return Vec::new();
        };
        let to_pixels = Mat3::from_scale(vec2(screen.pixels_per_point, screen.pixels_per_point))
            * self.scene_to_screen;
        let color = INK.map(|c| f32::from(c) / 255.0);
        let color = [color[0], color[1], color[2], 1.0];
        let lines = LABELS.iter().enumerate().map(|(k, label)| {
            let pen = ZoomApp::library_pen(k);
            TextRun {
                font: library.font,
                content: Content::Text(label),
                size_px: SIZE,
                transform: to_pixels * Mat3::from_translation(vec2(pen.x, pen.y)),
                color,
            }
        });
        let panel = library.panel.iter().map(|(text, size, pen)| TextRun {
            font: library.font,
            content: Content::Text(text),
            size_px: *size,
            transform: to_pixels * Mat3::from_translation(vec2(pen.x, pen.y + self.scroll)),
            color,
        });
        let runs: Vec<TextRun<'_>> = lines.chain(panel).collect();
        if let Err(e) = library.text.prepare(encoder, screen.size_in_pixels, &runs) {
            eprintln!("egui_zoom: {e}");
        }
        // What no frame draws any more (text that changed) is forgotten.
        library.text.trim();
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &egui_wgpu::CallbackResources,
    ) {
        if let Some(library) = resources.get::<Library>() {
            library.text.render(pass);
        }
    }
}
