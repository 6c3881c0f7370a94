//! The interactive explorer (UI only: every pixel it shows comes from the render core).
//!
//! For now it shows the exact reference rasterization of shaped text in any shipped
//! font; the GPU methods, overlays and comparison panes join it as they land.

use eframe::egui;

use crate::camera::Camera;
use crate::cli::FRAME_MARGIN_PX;
use crate::coverage::CoverageImage;
use crate::font::{Font, SHIPPED_FONTS};
use crate::reference;
use crate::scene::Scene;

const DEFAULT_TEXT: &str = "Hamburgefonstiv\nThe quick brown fox jumps over the lazy dog.";

pub fn run() -> Result<(), crate::Error> {
    let options = eframe::NativeOptions {
        renderer: eframe::Renderer::Wgpu,
        viewport: egui::ViewportBuilder::default().with_inner_size([1200.0, 800.0]),
        ..Default::default()
    };
    eframe::run_native(
        "glyphscope",
        options,
        Box::new(|_cc| Ok(Box::new(Explorer::default()))),
    )
    .map_err(|e| crate::Error::Gpu(format!("cannot open the window: {e}")))
}

/// What the view shows; a change re-rasterizes, nothing else does.
#[derive(Clone, PartialEq)]
struct Settings {
    text: String,
    font: usize,
    size_px_per_em: f64,
}

struct Explorer {
    settings: Settings,
    shown: Option<Settings>,
    texture: Option<egui::TextureHandle>,
    status: String,
}

impl Default for Explorer {
    fn default() -> Self {
        Explorer {
            settings: Settings {
                text: DEFAULT_TEXT.into(),
                font: 0,
                size_px_per_em: 48.0,
            },
            shown: None,
            texture: None,
            status: String::new(),
        }
    }
}

impl Explorer {
    fn rasterize(&self) -> Result<CoverageImage, crate::Error> {
        let s = &self.settings;
        let scene = Scene::from_text(&Font::shipped(s.font), &s.text)?;
        let ink = scene.ink_bounds().expect("a text scene has ink");
        let scale = s.size_px_per_em / scene.units_per_em;
        let size = ink.size() * scale + 2.0 * FRAME_MARGIN_PX;
        let origin = glam::DVec2::new(-ink.min.x, ink.max.y) * scale + FRAME_MARGIN_PX;
        let camera = Camera::new(
            size.x.ceil() as u32,
            size.y.ceil() as u32,
            s.size_px_per_em,
            origin,
        );
        reference::rasterize(&scene, &camera)
    }

    fn refresh(&mut self, ctx: &egui::Context) {
        if self.shown.as_ref() == Some(&self.settings) {
            return;
        }
        self.shown = Some(self.settings.clone());
        match self.rasterize() {
            Ok(image) => {
                let pixels = image
                    .data
                    .iter()
                    .map(|&c| egui::Color32::from_white_alpha((c * 255.0).round() as u8));
                let color = egui::ColorImage::new(
                    [image.width as usize, image.height as usize],
                    pixels.collect(),
                );
                self.texture =
                    Some(ctx.load_texture("reference", color, egui::TextureOptions::NEAREST));
                self.status = format!("{}×{} px, reference rasterizer", image.width, image.height);
            }
            Err(e) => {
                self.texture = None;
                self.status = e.to_string();
            }
        }
    }
}

impl eframe::App for Explorer {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        egui::Panel::left("settings").show(ui, |ui| {
            ui.heading("Scene");
            egui::ComboBox::from_label("font")
                .selected_text(SHIPPED_FONTS[self.settings.font].0)
                .show_ui(ui, |ui| {
                    for (i, (name, _, _)) in SHIPPED_FONTS.iter().enumerate() {
                        ui.selectable_value(&mut self.settings.font, i, *name);
                    }
                });
            ui.add(
                egui::Slider::new(&mut self.settings.size_px_per_em, 4.0..=400.0)
                    .logarithmic(true)
                    .text("px/em"),
            );
            ui.text_edit_multiline(&mut self.settings.text);
            ui.separator();
            ui.label(&self.status);
        });
        self.refresh(ui.ctx());
        egui::CentralPanel::default().show(ui, |ui| {
            if let Some(texture) = &self.texture {
                // Coverage is white alpha, tinted to whatever the theme draws text in.
                let ink = ui.visuals().strong_text_color();
                egui::ScrollArea::both().show(ui, |ui| {
                    ui.add(egui::Image::new((texture.id(), texture.size_vec2())).tint(ink));
                });
            }
        });
    }
}
