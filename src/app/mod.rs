//! The interactive explorer. It is UI only: every pixel it shows comes from the render
//! core — the methods through [`crate::methods::Method`], the reference, the metrics —
//! and it prepares data only when the scene or a method's parameters change.
//!
//! - `settings`: what is remembered between runs.
//! - `scene_state`: the font and scene built from the settings.
//! - `camera_control`: the shared camera and how input steers it.
//! - `shortcuts`: the keyboard and mouse, one table for the keys, the help and the docs.
//! - `panes`: the method catalog, each pane's prepared method, the pane controls.
//! - `canvas`: the panes laid out, steered by the pointer, and settling when at rest.
//! - `gpu_view`: egui_wgpu paint callbacks drawing each pane's offscreen target.
//! - `display`: what a pane shows of a coverage value (blending, stem darkening).
//! - `analysis`: the reference and the error figures, on a background thread.
//! - `cases_menu`: the Cases menu, loading each named hard case and bench scene.
//! - `artifacts`: a pane's pixels off from the reference, worst first, to step through.
//! - `blink`: pane A flipped in place to pane B's method or the reference.
//! - `playback`: text in motion: the camera along a path frame by frame, with strip
//!   charts of each pane's error and temporal error.
//! - `pareto`: speed against error over every parameter combination, plotted with its
//!   Pareto front.
//! - `controls`: the side panel, the status bar and the windows.
//! - `web`: the explorer as a web page (wasm32 and WebGPU only).
//! - `link`: a view as a URL fragment, copied from the explorer and opened by
//!   `glyphscope --view`.
//! - `outline_painter`, `font_dialog`, `headless` (offscreen frames for `glyphscope screenshots`).

mod analysis;
mod artifacts;
mod blink;
mod camera_control;
mod canvas;
mod cases_menu;
mod controls;
pub mod display;
mod font_dialog;
mod gpu_view;
pub mod headless;
mod link;
mod outline_painter;
mod panes;
mod pareto;
mod playback;
mod scene_state;
pub mod screenshots;
pub mod settings;
mod shortcuts;
#[cfg(target_arch = "wasm32")]
pub mod web;

use std::collections::VecDeque;
use std::sync::{Arc, Mutex};

use eframe::egui;
use glam::DVec2;

use self::analysis::{Analysis, ReferenceState};
use self::canvas::CanvasState;
use self::font_dialog::FontDialog;
use self::gpu_view::{Compositor, lock};
use self::panes::{Catalog, Pane};
use self::pareto::ParetoSweep;
use self::scene_state::SceneState;
use self::settings::{PANES, Settings, sanitize};
use crate::camera::Camera;
use crate::coverage::CoverageImage;
use crate::gpu::GpuContext;
use crate::scene::Scene;

/// Opens the explorer window, on the view a link describes when `view` is given (a
/// malformed one opens the default view and says what was wrong). The web page starts
/// the explorer its own way (`web`).
#[cfg(not(target_arch = "wasm32"))]
pub fn run(view: Option<&str>) -> Result<(), crate::Error> {
    let view = view.map(str::to_owned);
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
        Box::new(move |cc| {
            let mut app = Explorer::new(cc);
            if let Some(link) = &view {
                app.open_link(link);
            }
            Ok(Box::new(app))
        }),
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

/// eframe's setup on a device already open: the app draws on `gpu`'s device (the
/// tests' one device per test binary).
pub fn wgpu_setup_on(gpu: &GpuContext) -> egui_wgpu::WgpuSetup {
    let (instance, adapter) = gpu.instance_and_adapter();
    egui_wgpu::WgpuSetup::Existing(egui_wgpu::WgpuSetupExisting {
        instance: instance.clone(),
        adapter: adapter.clone(),
        device: gpu.device.clone(),
        queue: gpu.queue.clone(),
    })
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
    canvas: CanvasState,
    sweep: ParetoSweep,
    font_dialog: FontDialog,
    help_open: bool,
    /// The pixels the magnifier was last centred on by "worst pixel", to step on from.
    artifacts: Option<artifacts::Artifacts>,
    /// A search for a pane's artifacts waiting for the GPU's answer.
    artifact_search: Option<artifacts::ArtifactSearch>,
    blink: blink::Blink,
    cases: cases_menu::CasesMenu,
    /// Go to the worst pixel once a pane is ready (see `go_to_worst_pixel_when_ready`).
    worst_pixel_pending: Option<artifacts::WorstPixelRequest>,
    /// Each pane's heat-scale legend's own uniform and bind group.
    legends: Vec<gpu_view::SharedSurface>,
    /// Messages from screenshots and file drops; shared with the screenshot callback.
    status: Arc<Mutex<String>>,
    frame_intervals: VecDeque<f64>,
    auto_fit: canvas::AutoFit,
    playback: playback::Playback,
}

impl Explorer {
    /// The app inside eframe: settings from the last run, eframe's wgpu device.
    pub fn new(cc: &eframe::CreationContext<'_>) -> Explorer {
        let saved = cc
            .storage
            .and_then(|s| eframe::get_value::<Settings>(s, eframe::APP_KEY));
        // A first start (somewhere to keep settings, none kept yet) opens on an artifact.
        let first_start = cc.storage.is_some() && saved.is_none();
        let mut app = Explorer::with_render_state(
            &cc.egui_ctx,
            cc.wgpu_render_state.as_ref(),
            saved.unwrap_or_default(),
        );
        if first_start {
            app.open_as_on_a_first_start();
        }
        app
    }

    /// Shows the view `link` describes (a URL fragment: see `link`), or the default view
    /// and one line saying what is wrong with it.
    pub fn open_link(&mut self, link: &str) {
        self.auto_fit = canvas::AutoFit::default();
        // A link carries the view, not the display preferences (colours, display mode,
        // darkening): those stay as they are.
        let mut show = |settings: Settings| {
            self.settings.scene = settings.scene;
            self.settings.camera = settings.camera;
            self.settings.layout = settings.layout;
            self.settings.panes = settings.panes;
            self.settings.motion_path = settings.motion_path;
        };
        match link::open(link) {
            Ok(view) => {
                show(view.settings);
                self.remember_the_scene_under_the_case();
                self.playback.frame = view.frame;
                self.set_status(String::new());
                if let (Some(case), false) = (self.settings.scene.case.clone(), view.camera_given) {
                    self.load_case(&case);
                }
            }
            Err(e) => {
                show(Settings::default());
                self.playback.frame = 0;
                self.set_status(e);
            }
        }
        sanitize(&mut self.settings);
    }

    /// The link (a URL fragment, with its `#`) that opens the view shown, or why this
    /// view cannot travel in one.
    pub fn link(&self) -> Result<String, String> {
        link::fragment(&self.settings, self.playback.frame).map(|f| format!("#{f}"))
    }

    /// What a first start shows: the default side-by-side (a method beside the
    /// reference) with the text small, magnified on pane A's worst pixel
    /// ([`canvas::OPENING`]).
    pub fn open_as_on_a_first_start(&mut self) {
        self.auto_fit.opening = true;
    }

    /// The app on any egui context and wgpu render state (eframe's, a test harness's, or
    /// the headless renderer's).
    pub fn with_render_state(
        ctx: &egui::Context,
        render_state: Option<&egui_wgpu::RenderState>,
        settings: Settings,
    ) -> Explorer {
        let gpu = render_state.map(|rs| {
            let gpu = GpuContext::from_device(
                rs.instance.clone(),
                rs.adapter.clone(),
                rs.device.clone(),
                rs.queue.clone(),
            );
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
            canvas: CanvasState::default(),
            sweep: ParetoSweep::default(),
            font_dialog: FontDialog::default(),
            help_open: false,
            artifacts: None,
            artifact_search: None,
            blink: blink::Blink::default(),
            cases: cases_menu::CasesMenu::default(),
            worst_pixel_pending: None,
            legends: (0..PANES).map(|_| gpu_view::PaneSurface::new()).collect(),
            status: Arc::new(Mutex::new(String::new())),
            frame_intervals: VecDeque::new(),
            auto_fit: canvas::AutoFit::default(),
            playback: playback::Playback::default(),
        }
    }

    /// The camera the panes share this frame, if the view has been laid out.
    pub fn camera(&self) -> Option<Camera> {
        self.canvas.camera
    }

    /// The pixels of a ×1 pane the panes draw this frame, and their magnification.
    pub fn magnified_window(&self) -> Option<crate::magnify::Window> {
        self.canvas.window
    }

    /// A pane's size in pixels at ×1, once laid out.
    pub fn pane_pixels(&self) -> Option<(u32, u32)> {
        self.canvas.pane_size
    }

    /// Where the visible panes are on the screen, in points.
    pub fn pane_rects(&self) -> &[egui::Rect] {
        &self.canvas.rects
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
        let camera = self.canvas.camera?;
        let (c, image) = self.panes[index].capture.as_ref()?;
        (*c == camera).then(|| image.clone())
    }

    pub fn pane_error(&self, index: usize) -> Option<crate::metrics::ErrorStats> {
        let camera = self.canvas.camera?;
        let (c, stats) = self.panes[index].error.as_ref()?;
        (*c == camera).then_some(*stats)
    }

    /// Curves evaluated per pixel in pane `index` for the resting view, for methods that
    /// count them.
    pub fn pane_curves(&self, index: usize) -> Option<crate::methods::CurveCost> {
        let camera = self.canvas.camera?;
        let (c, cost) = self.panes[index].curves.as_ref()?;
        (*c == camera).then_some(*cost)
    }

    /// The reference for the current view, once worked out.
    pub fn reference_image(&self) -> Option<Arc<CoverageImage>> {
        self.reference_is_current()
            .then(|| self.reference.image.clone())
            .flatten()
    }

    /// Whether the view is at rest: the reference and every pane's numbers worked out
    /// for it, and nothing it is still to do by itself (framing the text, placing a
    /// case, going to the worst pixel).
    pub fn settled(&self) -> bool {
        let placing = self.auto_fit.pending || self.auto_fit.opening;
        self.view_settled()
            && !(placing && self.scene.scene().is_some())
            && self.worst_pixel_pending.is_none()
            && self.artifact_search.is_none()
    }

    /// Whether the reference and every pane's numbers are worked out for this view, and
    /// the view is what the settings say (nothing changed since it was laid out).
    fn view_settled(&self) -> bool {
        let up_to_date = self.scene.is_built_for(&self.settings.scene)
            && self.canvas.camera.is_some_and(|c| {
                self.canvas
                    .pane_size
                    .is_some_and(|(w, h)| c == self.pane_camera_now(w, h).0)
            })
            && (0..self.settings.layout.panes()).all(|i| {
                self.panes[i].is_built_for(&self.settings.panes[i], self.scene.generation())
            });
        up_to_date
            && self.canvas.key.is_some()
            && self.canvas.analysed == self.canvas.key
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

    fn reference_is_current(&self) -> bool {
        match (self.reference.made_for, self.canvas.camera) {
            (Some((generation, camera)), Some(current)) => {
                generation == self.scene.generation() && camera == current
            }
            _ => false,
        }
    }

    /// The centre of what a pane shows, in its ×1 pixels (the magnified window's
    /// centre when magnified): what keys and sliders zoom and rotate about.
    fn view_centre(&self) -> DVec2 {
        self.canvas.window.map_or(DVec2::ZERO, |w| {
            DVec2::new(f64::from(w.x0), f64::from(w.y0))
                + DVec2::new(f64::from(w.cols), f64::from(w.rows)) / 2.0
        })
    }

    /// A pane's size in pixels, unmagnified.
    fn pane_size(&self) -> DVec2 {
        self.canvas
            .pane_size
            .map_or(DVec2::ZERO, |(w, h)| DVec2::new(f64::from(w), f64::from(h)))
    }

    /// The status line's message (a link's error, the worst pixel, a case).
    pub fn status_text(&self) -> String {
        self.status
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .clone()
    }

    fn set_status(&self, message: String) {
        *self.status.lock().unwrap_or_else(|p| p.into_inner()) = message;
    }
}

impl eframe::App for Explorer {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.show(ui);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, eframe::APP_KEY, &self.settings);
    }

    /// What lets the page reach the explorer between frames (`web::WebHandle`: a font
    /// the page read, a fragment typed into the address).
    #[cfg(target_arch = "wasm32")]
    fn as_any_mut(&mut self) -> Option<&mut dyn std::any::Any> {
        Some(&mut *self)
    }
}

impl Explorer {
    /// One frame of the whole app.
    pub fn show(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        self.take_background_results();
        self.take_dropped_files(&ctx);
        self.shortcuts(&ctx);
        self.tick_blink(&ctx);
        self.leave_case_on_scene_change();
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
            .show(ui, |ui| self.show_canvas(ui));
        self.windows(&ctx);
        self.settle(&ctx);
        self.tick_playback(&ctx);
        self.answer_worst_pixel_request(&ctx);
        self.poll_artifact_search(&ctx);
        if self.settings.continuous {
            ctx.request_repaint();
        }
        #[cfg(target_arch = "wasm32")]
        web::after_frame(self);
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
        if let Some(outcome) = self.analysis.receive() {
            self.take_analysis(outcome);
        }
    }
}
