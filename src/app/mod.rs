//! The interactive explorer. It is UI only: every pixel it shows comes from the render
//! core — the methods through [`crate::methods::Method`], the reference, the metrics —
//! and it prepares data only when the scene or a method's parameters change.
//!
//! - `settings`: what is remembered between runs.
//! - `camera_control`: the shared camera and how input steers it.
//! - `panes`: the method catalog, each pane's prepared method, the pane controls.
//! - `gpu_view`: egui_wgpu paint callbacks drawing each pane's offscreen target.
//! - `analysis`: the reference and the error figures, on a background thread.
//! - `sweep`: speed against error over every parameter combination, plotted.
//! - `outline`, `font_dialog`, `headless` (offscreen frames for `glyphscope screenshots`).

mod analysis;
mod camera_control;
mod controls;
mod font_dialog;
mod gpu_view;
pub mod headless;
mod outline;
mod panes;
pub mod screenshots;
pub mod settings;
mod sweep;
mod view;

use std::collections::VecDeque;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use eframe::egui;
use glam::DVec2;

use self::analysis::Analysis;
use self::camera_control::{MAX_SIZE_PX_PER_EM, MAX_TILT_DEG, MIN_SIZE_PX_PER_EM};
use self::font_dialog::FontDialog;
use self::gpu_view::{Compositor, lock};
use self::panes::{Catalog, Pane, REFERENCE};
use self::settings::{FontChoice, Layout, PANES, PaneOverlay, PaneSource, SceneSettings, Settings};
use self::sweep::Sweep;
use crate::camera::Camera;
use crate::coverage::CoverageImage;
use crate::font::{Font, SHIPPED_FONTS, axis_tag};
use crate::gpu::GpuContext;
use crate::scene::Scene;

/// Seconds the view must stay still before the reference and the errors are worked out.
const REST_SECONDS: f64 = 0.25;
/// Pixels an arrow key pans by.
const ARROW_PAN_PX: f64 = 40.0;

/// The keyboard and mouse, as the help window and the README list them.
pub const SHORTCUTS: &[(&str, &str)] = &[
    ("drag", "pan"),
    ("wheel / pinch", "zoom about the cursor"),
    ("arrows", "pan"),
    ("+ / −", "zoom in / out ×2 about the centre"),
    ("[ / ]", "rotate −15° / +15°"),
    ("R", "reset the camera"),
    ("F", "fit the text to the pane"),
    ("1 / 2 / 4", "one pane / side by side / 2×2"),
    ("G", "glyph mode on / off"),
    ("O", "outline overlay on / off"),
    ("E", "error overlay on / off"),
    ("C", "draw continuously (live GPU time)"),
    ("P", "speed-vs-error plot"),
    ("Ctrl+O", "open a font file"),
    ("S", "screenshot (PNG in the current folder)"),
    ("H / F1", "this help"),
];

/// Opens the explorer window.
pub fn run() -> Result<(), crate::Error> {
    let options = eframe::NativeOptions {
        renderer: eframe::Renderer::Wgpu,
        viewport: egui::ViewportBuilder::default()
            .with_inner_size([1400.0, 860.0])
            .with_title("glyphscope")
            .with_drag_and_drop(true),
        wgpu_options: egui_wgpu::WgpuConfiguration {
            wgpu_setup: wgpu_setup(),
            ..Default::default()
        },
        ..Default::default()
    };
    eframe::run_native(
        "glyphscope",
        options,
        Box::new(|cc| Ok(Box::new(Explorer::new(cc)))),
    )
    .map_err(|e| crate::Error::Gpu(format!("cannot open the window: {e}")))
}

/// The device the explorer asks for (in eframe, headless and in tests): what the methods
/// get from [`GpuContext::new`], timestamp queries included.
pub fn wgpu_setup() -> egui_wgpu::WgpuSetup {
    let mut setup = egui_wgpu::WgpuSetupCreateNew::without_display_handle();
    setup.device_descriptor = Arc::new(GpuContext::device_descriptor);
    egui_wgpu::WgpuSetup::CreateNew(setup)
}

/// The scene built from [`SceneSettings`], rebuilt only when they change.
#[derive(Default)]
struct SceneState {
    built_for: Option<SceneSettings>,
    font: Option<(FontChoice, Result<Font, String>)>,
    scene: Option<Result<Arc<Scene>, String>>,
    generation: u64,
}

impl SceneState {
    fn sync(&mut self, wanted: &SceneSettings) {
        if self.built_for.as_ref() == Some(wanted) {
            return;
        }
        self.built_for = Some(wanted.clone());
        self.generation += 1;
        if self.font.as_ref().map(|(c, _)| c) != Some(&wanted.font) {
            let font = match &wanted.font {
                FontChoice::Shipped(i) if *i < SHIPPED_FONTS.len() => Ok(Font::shipped(*i)),
                FontChoice::Shipped(i) => Err(format!("there is no shipped font {i}")),
                FontChoice::File(path) => Font::from_path(path).map_err(|e| e.to_string()),
            };
            self.font = Some((wanted.font.clone(), font));
        }
        let font = self.font.as_ref().expect("set above").1.clone();
        self.scene = Some(font.and_then(|font| build_scene(&font, wanted)));
    }

    fn font(&self) -> Option<&Font> {
        self.font.as_ref().and_then(|(_, f)| f.as_ref().ok())
    }

    fn scene(&self) -> Option<&Arc<Scene>> {
        self.scene.as_ref().and_then(|s| s.as_ref().ok())
    }

    fn problem(&self) -> Option<String> {
        match (&self.font, &self.scene) {
            (Some((_, Err(e))), _) | (_, Some(Err(e))) => Some(e.clone()),
            _ => None,
        }
    }

    fn units_per_em(&self) -> f64 {
        self.scene().map_or(1000.0, |s| s.units_per_em)
    }
}

fn build_scene(font: &Font, wanted: &SceneSettings) -> Result<Arc<Scene>, String> {
    // Axes the font lacks (left from another font) are ignored, not an error.
    let axes = font.axes();
    let variations: Vec<(String, f32)> = wanted
        .variations
        .iter()
        .filter(|(tag, _)| axis_tag(tag).is_ok_and(|tag| axes.iter().any(|a| a.tag == tag)))
        .cloned()
        .collect();
    let font = font
        .with_variations(&variations)
        .map_err(|e| e.to_string())?;
    let scene = if wanted.glyph_mode {
        let spec = wanted.glyph.trim();
        let id = match spec.strip_prefix('#') {
            Some(n) => n
                .trim()
                .parse::<u32>()
                .map_err(|_| format!("'{spec}': give a character, or # and a glyph id"))?,
            None => {
                let c = spec
                    .chars()
                    .next()
                    .ok_or("glyph mode: give a character or #id")?;
                u32::from(font.glyph_for_char(c).map_err(|e| e.to_string())?)
            }
        };
        Scene::from_glyph_id(&font, id)
    } else {
        Scene::from_text(&font, &wanted.text)
    };
    scene.map(Arc::new).map_err(|e| e.to_string())
}

/// The reference for the resting view, on the GPU for the panes that show it.
#[derive(Default)]
struct ReferenceState {
    texture: gpu_view::ReferenceTexture,
    image: Option<Arc<CoverageImage>>,
    /// (scene generation, camera) the image is for.
    made_for: Option<(u64, Camera)>,
    cpu_ms: Option<f64>,
    problem: Option<String>,
}

/// What the view shows; when it stops changing, the view is at rest.
#[derive(Clone, Debug, PartialEq)]
struct ViewKey {
    camera: Camera,
    scene: u64,
    panes: Vec<(u64, bool)>,
}

/// The pane layout and hover of the last frame.
#[derive(Default)]
struct ViewState {
    /// The camera every pane shares this frame (its size: one pane, in pixels).
    camera: Option<Camera>,
    key: Option<ViewKey>,
    changed_at: f64,
    analysed: Option<ViewKey>,
    /// Pane index and pixel under the pointer.
    hovered: Option<(usize, u32, u32)>,
    /// Notes to show, per pane.
    notes: Vec<String>,
    /// Where the visible panes are, in points.
    rects: Vec<egui::Rect>,
}

/// The explorer app.
pub struct Explorer {
    pub settings: Settings,
    gpu: Option<(GpuContext, Arc<Compositor>)>,
    catalog: Catalog,
    scene: SceneState,
    panes: Vec<Pane>,
    reference: ReferenceState,
    analysis: Analysis,
    view: ViewState,
    sweep: Sweep,
    font_dialog: FontDialog,
    help_open: bool,
    /// Each pane's heat-scale legend's own uniform and bind group.
    legends: Vec<gpu_view::SharedSurface>,
    /// Messages from screenshots and file drops; shared with the screenshot callback.
    status: Arc<Mutex<String>>,
    frame_intervals: VecDeque<f64>,
}

impl Explorer {
    /// The app inside eframe: settings from the last run, eframe's wgpu device.
    pub fn new(cc: &eframe::CreationContext<'_>) -> Explorer {
        let settings = cc
            .storage
            .and_then(|s| eframe::get_value::<Settings>(s, eframe::APP_KEY))
            .unwrap_or_default();
        Explorer::with_render_state(&cc.egui_ctx, cc.wgpu_render_state.as_ref(), settings)
    }

    /// The app on any egui context and wgpu render state (eframe's, a test harness's, or
    /// the headless renderer's).
    pub fn with_render_state(
        ctx: &egui::Context,
        render_state: Option<&egui_wgpu::RenderState>,
        settings: Settings,
    ) -> Explorer {
        let gpu = render_state.map(|rs| {
            let gpu =
                GpuContext::from_device(rs.adapter.clone(), rs.device.clone(), rs.queue.clone());
            let compositor = Arc::new(Compositor::new(&gpu, rs.target_format));
            (gpu, compositor)
        });
        let mut settings = settings;
        sanitize(&mut settings);
        let analysis = Analysis::start(ctx.clone(), gpu.as_ref().map(|(g, _)| g.clone()));
        Explorer {
            settings,
            gpu,
            catalog: Catalog::discover(),
            scene: SceneState::default(),
            panes: (0..PANES).map(|_| Pane::new()).collect(),
            reference: ReferenceState::default(),
            analysis,
            view: ViewState::default(),
            sweep: Sweep::default(),
            font_dialog: FontDialog::default(),
            help_open: false,
            legends: (0..PANES).map(|_| gpu_view::PaneSurface::new()).collect(),
            status: Arc::new(Mutex::new(String::new())),
            frame_intervals: VecDeque::new(),
        }
    }

    /// The camera the panes share this frame, if the view has been laid out.
    pub fn camera(&self) -> Option<Camera> {
        self.view.camera
    }

    /// Where the visible panes are on the screen, in points.
    pub fn pane_rects(&self) -> &[egui::Rect] {
        &self.view.rects
    }

    /// The scene shown, if it could be built.
    pub fn scene(&self) -> Option<&Arc<Scene>> {
        self.scene.scene()
    }

    /// Why pane `index` shows nothing, if it does not.
    pub fn pane_problem(&self, index: usize) -> Option<String> {
        let pane = &self.panes[index];
        pane.problem
            .clone()
            .or_else(|| lock(&pane.surface).draw_error.clone())
    }

    /// Pane `index`'s coverage and error for the resting view, once worked out.
    pub fn pane_capture(&self, index: usize) -> Option<Arc<CoverageImage>> {
        let camera = self.view.camera?;
        let (c, image) = self.panes[index].capture.as_ref()?;
        (*c == camera).then(|| image.clone())
    }

    pub fn pane_error(&self, index: usize) -> Option<crate::metrics::ErrorStats> {
        let camera = self.view.camera?;
        let (c, stats) = self.panes[index].error.as_ref()?;
        (*c == camera).then_some(*stats)
    }

    /// Curves evaluated per pixel in pane `index` for the resting view, for methods that
    /// count them.
    pub fn pane_curves(&self, index: usize) -> Option<crate::methods::CurveCost> {
        let camera = self.view.camera?;
        let (c, cost) = self.panes[index].curves.as_ref()?;
        (*c == camera).then_some(*cost)
    }

    /// The reference for the current view, once worked out.
    pub fn reference_image(&self) -> Option<Arc<CoverageImage>> {
        self.reference_is_current()
            .then(|| self.reference.image.clone())
            .flatten()
    }

    /// Whether the reference and every pane's numbers are worked out for this view, and
    /// the view is what the settings say (nothing changed since it was laid out).
    pub fn settled(&self) -> bool {
        let up_to_date = self.scene.built_for.as_ref() == Some(&self.settings.scene)
            && self
                .view
                .camera
                .is_some_and(|c| c == self.settings.camera.camera(c.width, c.height))
            && (0..self.settings.layout.panes()).all(|i| {
                self.panes[i].is_built_for(&self.settings.panes[i], self.scene.generation)
            });
        up_to_date
            && self.view.key.is_some()
            && self.view.analysed == self.view.key
            && !self.analysis.busy()
            && self.reference_is_current()
    }

    /// Median GPU time of pane `index`'s recent frames, ms.
    pub fn pane_gpu_ms(&self, index: usize) -> Option<f64> {
        lock(&self.panes[index].surface)
            .timer
            .median_ms()
            .map(|(m, _)| m)
    }

    pub fn sweep_points(&self) -> &[sweep::SweepPoint] {
        &self.sweep.points
    }

    pub fn sweep_running(&self) -> bool {
        self.sweep.running()
    }

    /// Starts the speed-vs-error sweep on the current scene and view and opens its window.
    pub fn start_sweep(&mut self, ctx: &egui::Context) {
        self.sweep.open = true;
        if let (Some((gpu, _)), Some(scene), Some(camera)) =
            (&self.gpu, self.scene.scene(), self.view.camera)
        {
            self.sweep
                .start(ctx, gpu, &self.catalog, scene.clone(), camera);
        }
    }

    /// Opens a font file, as the font dialog and a file drop do.
    pub fn open_font(&mut self, path: PathBuf) {
        self.settings.scene.font = FontChoice::File(path);
        self.settings.scene.variations.clear();
    }

    fn reference_is_current(&self) -> bool {
        match (self.reference.made_for, self.view.camera) {
            (Some((generation, camera)), Some(current)) => {
                generation == self.scene.generation && camera == current
            }
            _ => false,
        }
    }

    fn set_status(&self, message: String) {
        *self.status.lock().unwrap_or_else(|p| p.into_inner()) = message;
    }
}

/// Keeps remembered settings usable with this build (fonts, pane references).
fn sanitize(settings: &mut Settings) {
    if let FontChoice::Shipped(i) = settings.scene.font
        && i >= SHIPPED_FONTS.len()
    {
        settings.scene.font = FontChoice::Shipped(0);
    }
    for (index, pane) in settings.panes.iter_mut().enumerate() {
        if let PaneSource::Difference { first, second } = &mut pane.source {
            if *first >= PANES || *first == index {
                *first = usize::from(index == 0);
            }
            if second.is_some_and(|s| s >= PANES || s == index) {
                *second = None;
            }
        }
    }
    let c = &mut settings.camera;
    if !(c.size_px_per_em.is_finite() && c.size_px_per_em > 0.0) {
        *c = Default::default();
    }
    c.size_px_per_em = c
        .size_px_per_em
        .clamp(MIN_SIZE_PX_PER_EM, MAX_SIZE_PX_PER_EM);
    c.tilt_deg = c.tilt_deg.clamp(-MAX_TILT_DEG, MAX_TILT_DEG);
}

fn pane_letter(index: usize) -> char {
    (b'A' + index as u8) as char
}

fn color(rgb: [u8; 3]) -> egui::Color32 {
    egui::Color32::from_rgb(rgb[0], rgb[1], rgb[2])
}

impl eframe::App for Explorer {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.show(ui);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, eframe::APP_KEY, &self.settings);
    }
}

impl Explorer {
    /// One frame of the whole app.
    pub fn show(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        self.take_background_results();
        self.take_dropped_files(&ctx);
        self.shortcuts(&ctx);
        self.scene.sync(&self.settings.scene);
        egui::Panel::left("controls")
            .resizable(true)
            .default_size(330.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| self.controls(ui));
            });
        egui::Panel::bottom("status").show(ui, |ui| self.status_bar(ui));
        egui::CentralPanel::default()
            .frame(egui::Frame::NONE.fill(ui.visuals().extreme_bg_color))
            .show(ui, |ui| self.view(ui));
        self.windows(&ctx);
        self.settle(&ctx);
        if self.settings.continuous {
            ctx.request_repaint();
        }
        let dt = f64::from(ctx.input(|i| i.unstable_dt)) * 1e3;
        if self.frame_intervals.len() == 60 {
            self.frame_intervals.pop_front();
        }
        self.frame_intervals.push_back(dt);
    }

    fn take_background_results(&mut self) {
        if let Some((gpu, _)) = &self.gpu {
            for pane in &self.panes {
                lock(&pane.surface).timer.collect(gpu);
            }
        }
        self.sweep.poll();
        let Some(outcome) = self.analysis.receive() else {
            return;
        };
        // Results for a pane whose method was remade meanwhile belong to the old one.
        let current = |pane: usize| {
            lock(&self.panes[pane].surface).generation == outcome.pane_generations[pane]
        };
        let errors: Vec<_> = outcome
            .errors
            .into_iter()
            .filter(|(p, _)| current(*p))
            .collect();
        let curves: Vec<_> = outcome
            .curves
            .into_iter()
            .filter(|(p, _)| current(*p))
            .collect();
        for (pane, result) in errors {
            match result {
                Ok(stats) => self.panes[pane].error = Some((outcome.camera, stats)),
                Err(e) => self.panes[pane].problem = Some(e),
            }
        }
        for (pane, result) in curves {
            match result {
                Ok(cost) => self.panes[pane].curves = cost.map(|c| (outcome.camera, c)),
                Err(e) => self.panes[pane].problem = Some(e),
            }
        }
        if let Some(ms) = outcome.reference_ms {
            self.reference.cpu_ms = Some(ms);
        }
        match outcome.reference {
            Ok(image) => {
                self.reference.problem = None;
                if let Some((gpu, _)) = &self.gpu {
                    gpu_view::upload_reference(gpu, &self.reference.texture, &image);
                }
                self.reference.image = Some(image);
                self.reference.made_for = Some((outcome.scene_generation, outcome.camera));
            }
            Err(e) => self.reference.problem = Some(e),
        }
    }

    fn take_dropped_files(&mut self, ctx: &egui::Context) {
        let dropped: Vec<PathBuf> = ctx.input(|i| {
            i.raw
                .dropped_files
                .iter()
                .map(|f| f.path().to_path_buf())
                .collect()
        });
        if let Some(path) = dropped.into_iter().next() {
            if font_dialog::is_font_file(&path) {
                self.open_font(path);
            } else {
                self.set_status(format!("'{}' is not a .ttf/.otf font", path.display()));
            }
        }
    }

    fn shortcuts(&mut self, ctx: &egui::Context) {
        if ctx.egui_wants_keyboard_input() {
            return;
        }
        let centre = self.view.camera.map_or(DVec2::ZERO, |c| {
            DVec2::new(f64::from(c.width), f64::from(c.height)) / 2.0
        });
        let upem = self.scene.units_per_em();
        let pressed = |key| ctx.input_mut(|i| i.consume_key(egui::Modifiers::NONE, key));
        if ctx.input_mut(|i| i.consume_key(egui::Modifiers::COMMAND, egui::Key::O)) {
            self.font_dialog.open = true;
        }
        let camera = &mut self.settings.camera;
        for (key, delta) in [
            (egui::Key::ArrowLeft, DVec2::new(ARROW_PAN_PX, 0.0)),
            (egui::Key::ArrowRight, DVec2::new(-ARROW_PAN_PX, 0.0)),
            (egui::Key::ArrowUp, DVec2::new(0.0, ARROW_PAN_PX)),
            (egui::Key::ArrowDown, DVec2::new(0.0, -ARROW_PAN_PX)),
        ] {
            if pressed(key) {
                camera.pan(delta);
            }
        }
        if pressed(egui::Key::Plus) || pressed(egui::Key::Equals) {
            camera.zoom(2.0, centre, upem);
        }
        if pressed(egui::Key::Minus) {
            camera.zoom(0.5, centre, upem);
        }
        if pressed(egui::Key::OpenBracket) {
            camera.rotate(-15.0, centre, upem);
        }
        if pressed(egui::Key::CloseBracket) {
            camera.rotate(15.0, centre, upem);
        }
        if let Some(scene) = self.scene.scene().cloned() {
            if pressed(egui::Key::R) {
                self.settings.camera.reset(&scene);
            }
            if pressed(egui::Key::F) {
                self.settings.camera.fit(&scene, centre * 2.0);
            }
        }
        for (key, layout) in [
            (egui::Key::Num1, Layout::Single),
            (egui::Key::Num2, Layout::SideBySide),
            (egui::Key::Num4, Layout::Grid),
        ] {
            if pressed(key) {
                self.settings.layout = layout;
            }
        }
        if pressed(egui::Key::G) {
            self.settings.scene.glyph_mode ^= true;
        }
        let visible = self.settings.layout.panes();
        if pressed(egui::Key::O) {
            let on = !self.settings.panes[..visible].iter().all(|p| p.outline);
            for pane in &mut self.settings.panes[..visible] {
                pane.outline = on;
            }
        }
        if pressed(egui::Key::E) {
            let on = !self.settings.panes[..visible]
                .iter()
                .any(|p| p.overlay == PaneOverlay::Error);
            for pane in &mut self.settings.panes[..visible] {
                let is_gpu_method =
                    matches!(&pane.source, PaneSource::Method { name, .. } if name != REFERENCE);
                if on && is_gpu_method {
                    pane.overlay = PaneOverlay::Error;
                } else if pane.overlay == PaneOverlay::Error {
                    pane.overlay = PaneOverlay::None;
                }
            }
        }
        if pressed(egui::Key::C) {
            self.settings.continuous ^= true;
        }
        if pressed(egui::Key::P) {
            self.sweep.open ^= true;
        }
        if pressed(egui::Key::S) {
            self.screenshot(ctx);
        }
        if pressed(egui::Key::H) || pressed(egui::Key::F1) {
            self.help_open ^= true;
        }
    }

    fn screenshot(&self, ctx: &egui::Context) {
        let status = self.status.clone();
        ctx.request_screenshot(move |image| {
            let stamp = std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map_or(0, |d| d.as_secs());
            let path = PathBuf::from(format!("glyphscope-{stamp}.png"));
            let [w, h] = image.size;
            let bytes: Vec<u8> = image.pixels.iter().flat_map(|p| p.to_array()).collect();
            let message = match image::RgbaImage::from_raw(w as u32, h as u32, bytes)
                .map(|img| img.save(&path))
            {
                Some(Ok(())) => format!("screenshot saved to {}", path.display()),
                Some(Err(e)) => format!("cannot write {}: {e}", path.display()),
                None => "the screenshot had no pixels".into(),
            };
            *status.lock().unwrap_or_else(|p| p.into_inner()) = message;
        });
        ctx.request_repaint();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_compositor_shader_is_valid_wgsl() {
        let module = naga::front::wgsl::parse_str(&gpu_view::composite_wgsl()).unwrap();
        naga::valid::Validator::new(Default::default(), naga::valid::Capabilities::all())
            .validate(&module)
            .unwrap();
    }

    #[test]
    fn glyph_mode_takes_a_character_or_an_id() {
        let font = Font::default_font();
        let mut s = SceneSettings {
            glyph_mode: true,
            glyph: "g".into(),
            ..Default::default()
        };
        let by_char = build_scene(&font, &s).unwrap();
        s.glyph = format!("#{}", by_char.glyphs[0].id);
        let by_id = build_scene(&font, &s).unwrap();
        assert_eq!(by_char.glyphs[0].id, by_id.glyphs[0].id);
        s.glyph = "#99999".into();
        assert!(build_scene(&font, &s).unwrap_err().contains("out of range"));
    }

    #[test]
    fn remembered_settings_survive_a_round_trip_and_bad_values_are_mended() {
        let mut s = Settings::default();
        s.panes[2].source = PaneSource::Difference {
            first: 9,
            second: Some(2),
        };
        s.scene.font = FontChoice::Shipped(42);
        let mut back: Settings = serde_json::from_str(&serde_json::to_string(&s).unwrap()).unwrap();
        assert_eq!(back, s);
        sanitize(&mut back);
        assert_eq!(back.scene.font, FontChoice::Shipped(0));
        assert_eq!(
            back.panes[2].source,
            PaneSource::Difference {
                first: 0,
                second: None
            }
        );
    }
}
