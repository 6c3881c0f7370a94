//! The interactive explorer (UI only: every pixel it shows comes from the render core).
//!
//! It shows shaped text in any shipped font, drawn by the exact reference or by any GPU
//! method with its parameters (an overlay's picture in colour), and the method's error
//! against the reference. GPU methods render offscreen on a device of their own and
//! are read back, exactly as the command line renders them.

use eframe::egui;

use crate::camera::Camera;
use crate::cli::FRAME_MARGIN_PX;
use crate::coverage::CoverageImage;
use crate::font::{Font, SHIPPED_FONTS};
use crate::gpu::{self, CoverageTarget, GpuContext};
use crate::methods::{self, METHOD_NAMES};
use crate::metrics;
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
    method: &'static str,
    /// `KEY=VALUE` pairs separated by spaces, as `--param` takes them.
    params: String,
}

struct Explorer {
    settings: Settings,
    shown: Option<Settings>,
    /// The picture, and whether it is coverage (tinted like text) or an overlay's
    /// colours.
    texture: Option<(egui::TextureHandle, bool)>,
    status: String,
    /// Opened on the first GPU method.
    gpu: Option<GpuContext>,
}

/// What a method drew: coverage, and the overlay's picture if one was asked for.
struct Drawn {
    coverage: CoverageImage,
    overlay: Option<image::RgbImage>,
    reference: CoverageImage,
}

impl Default for Explorer {
    fn default() -> Self {
        Explorer {
            settings: Settings {
                text: DEFAULT_TEXT.into(),
                font: 0,
                size_px_per_em: 48.0,
                method: "reference",
                params: String::new(),
            },
            shown: None,
            texture: None,
            status: String::new(),
            gpu: None,
        }
    }
}

impl Explorer {
    fn draw(&mut self) -> Result<Drawn, crate::Error> {
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
        let reference = reference::rasterize(&scene, &camera)?;
        if s.method == "reference" {
            return Ok(Drawn {
                coverage: reference.clone(),
                overlay: None,
                reference,
            });
        }
        let params: Vec<(String, String)> = s
            .params
            .split_whitespace()
            .map(|pair| match pair.split_once('=') {
                Some((k, v)) => Ok((k.to_string(), v.to_string())),
                None => Err(crate::Error::Input(format!(
                    "parameters are KEY=VALUE, got '{pair}'"
                ))),
            })
            .collect::<Result<_, _>>()?;
        let mut method = methods::create(s.method, &params)?;
        if self.gpu.is_none() {
            self.gpu = Some(GpuContext::new()?);
        }
        let gpu = self.gpu.as_ref().expect("opened above");
        let target = CoverageTarget::new(gpu, camera.width, camera.height)?;
        method.prepare(gpu, &scene)?;
        gpu::render_frame(gpu, method.as_mut(), &target, &camera)?;
        let overlay = methods::param(&params, "overlay")
            .is_some_and(|v| v != "none")
            .then(|| target.readback_color(gpu))
            .transpose()?;
        Ok(Drawn {
            coverage: target.readback(gpu)?,
            overlay,
            reference,
        })
    }

    fn refresh(&mut self, ctx: &egui::Context) {
        if self.shown.as_ref() == Some(&self.settings) {
            return;
        }
        self.shown = Some(self.settings.clone());
        match self.draw() {
            Ok(drawn) => {
                let image = &drawn.coverage;
                let size = [image.width as usize, image.height as usize];
                let color = match &drawn.overlay {
                    Some(picture) => egui::ColorImage::from_rgb(size, picture.as_raw()),
                    None => egui::ColorImage::new(
                        size,
                        image
                            .data
                            .iter()
                            .map(|&c| egui::Color32::from_white_alpha((c * 255.0).round() as u8))
                            .collect(),
                    ),
                };
                let texture = ctx.load_texture("glyphs", color, egui::TextureOptions::NEAREST);
                self.texture = Some((texture, drawn.overlay.is_none()));
                self.status = format!(
                    "{}×{} px, {}",
                    image.width, image.height, self.settings.method
                );
                if self.settings.method != "reference"
                    && let Ok(e) = metrics::compare(image, &drawn.reference)
                {
                    self.status += &format!(
                        "\nvs reference: mean {:.2}/255, max {:.3}",
                        e.mae_255, e.max
                    );
                }
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
            ui.heading("Method");
            egui::ComboBox::from_label("method")
                .selected_text(self.settings.method)
                .show_ui(ui, |ui| {
                    for name in METHOD_NAMES {
                        ui.selectable_value(&mut self.settings.method, *name, *name);
                    }
                });
            ui.label("parameters (KEY=VALUE …)");
            ui.text_edit_singleline(&mut self.settings.params);
            ui.separator();
            ui.label(&self.status);
        });
        self.refresh(ui.ctx());
        egui::CentralPanel::default().show(ui, |ui| {
            if let Some((texture, is_coverage)) = &self.texture {
                // Coverage is white alpha, tinted to whatever the theme draws text in;
                // an overlay's picture shows as it is.
                let ink = if *is_coverage {
                    ui.visuals().strong_text_color()
                } else {
                    egui::Color32::WHITE
                };
                egui::ScrollArea::both().show(ui, |ui| {
                    ui.add(egui::Image::new((texture.id(), texture.size_vec2())).tint(ink));
                });
            }
        });
    }
}
