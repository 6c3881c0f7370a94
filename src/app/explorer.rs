//! The explorer: [`Explorer`], what it holds, and its frame. Each of the app's other
//! files adds the methods of its own part (`impl Explorer` in `canvas`, `controls`,
//! `playback`, …); this file holds the state they share and calls them once a frame.
//! It imports the state types (`state`, and the workers of `analysis` and `pareto`),
//! never the files that work on them.

use std::collections::VecDeque;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use eframe::egui;
use glam::DVec2;

use super::analysis::{Analysis, Outcome, ReferenceState};
use super::file_dialog::{FileDialog, FileKind, is_font_file};
use super::gpu_view::{self, Compositor, PaneSurface, SharedSurface, lock};
use super::link;
use super::panes::{Catalog, Pane};
use super::pareto::{ParetoPoint, ParetoSweep};
use super::scene_state::SceneState;
use super::settings::{FontBytes, FontChoice, PANES, Settings, sanitize};
use super::state::{
    ArtifactSearch, Artifacts, AutoFit, Blink, CanvasState, CasesMenu, Mark, Playback,
    WorstPixelRequest,
};
use crate::camera::Camera;
use crate::coverage::CoverageImage;
use crate::gpu::GpuContext;
use crate::scene::Scene;

/// The explorer app.
pub struct Explorer {
    pub settings: Settings,
    pub(super) gpu: Option<(GpuContext, Arc<Compositor>)>,
    pub(super) catalog: Catalog,
    pub(super) scene: SceneState,
    pub(super) panes: Vec<Pane>,
    pub(super) reference: ReferenceState,
    pub(super) analysis: Analysis,
    pub(super) canvas: CanvasState,
    pub(super) sweep: ParetoSweep,
    pub(super) font_dialog: FileDialog,
    pub(super) help_open: bool,
    /// The pixels the magnifier was last centred on by "worst pixel", to step on from.
    pub(super) artifacts: Option<Artifacts>,
    /// A search for a pane's artifacts waiting for the GPU's answer.
    pub(super) artifact_search: Option<ArtifactSearch>,
    pub(super) blink: Blink,
    pub(super) cases: CasesMenu,
    /// Go to the worst pixel once a pane is ready (see `go_to_worst_pixel_when_ready`).
    pub(super) worst_pixel_pending: Option<WorstPixelRequest>,
    /// The pixel the view opened on, framed in every pane until the view moves (`mark`).
    pub(super) mark: Option<Mark>,
    /// Each pane's heat-scale legend's own uniform and bind group.
    pub(super) legends: Vec<SharedSurface>,
    /// Messages from screenshots and file drops; shared with the screenshot callback.
    pub(super) status: Arc<Mutex<String>>,
    pub(super) frame_intervals: VecDeque<f64>,
    pub(super) auto_fit: AutoFit,
    pub(super) playback: Playback,
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
        self.auto_fit = AutoFit::default();
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
                // Only under a case: remembered with none, leaving it would frame the
                // text anew over the link's camera (and set the link's outlines back).
                if self.settings.scene.case.is_some() {
                    self.remember_the_scene_under_the_case();
                } else {
                    self.cases.loaded_over = None;
                    self.cases.outlines_before = None;
                }
                self.playback.frame = view.frame;
                self.set_status(String::new());
                if let (Some(case), false) = (self.settings.scene.case.clone(), view.camera_given) {
                    self.load_case(&case);
                }
                sanitize(&mut self.settings);
                // The pixel a magnified link is centred on is the one it points at.
                let [x, y] = self.settings.camera.focus;
                if view.focus_given && self.settings.camera.magnify > 1 && x >= 0.0 && y >= 0.0 {
                    self.mark_pixel((x.floor() as u32, y.floor() as u32));
                }
            }
            Err(e) => {
                show(Settings::default());
                self.playback.frame = 0;
                self.set_status(e);
                sanitize(&mut self.settings);
            }
        }
    }

    /// The link (a URL fragment, with its `#`) that opens the view shown, or why this
    /// view cannot travel in one.
    pub fn link(&self) -> Result<String, String> {
        link::fragment(&self.settings, self.playback.frame).map(|f| format!("#{f}"))
    }

    /// What a first start shows: the default side-by-side (a method beside the
    /// reference) with the text small, magnified on pane A's worst pixel
    /// (`OPENING`).
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
            font_dialog: FileDialog::new(FileKind::Font),
            help_open: false,
            artifacts: None,
            artifact_search: None,
            blink: Blink::default(),
            cases: CasesMenu::default(),
            worst_pixel_pending: None,
            mark: None,
            legends: (0..PANES).map(|_| PaneSurface::new()).collect(),
            status: Arc::new(Mutex::new(String::new())),
            frame_intervals: VecDeque::new(),
            auto_fit: AutoFit::default(),
            playback: Playback::default(),
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
    pub(super) fn view_settled(&self) -> bool {
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

    pub(super) fn reference_is_current(&self) -> bool {
        match (self.reference.made_for, self.canvas.camera) {
            (Some((generation, camera)), Some(current)) => {
                generation == self.scene.generation() && camera == current
            }
            _ => false,
        }
    }

    /// The centre of what a pane shows, in its ×1 pixels (the magnified window's
    /// centre when magnified): what keys and sliders zoom and rotate about.
    pub(super) fn view_centre(&self) -> DVec2 {
        self.canvas.window.map_or(DVec2::ZERO, |w| {
            DVec2::new(f64::from(w.x0), f64::from(w.y0))
                + DVec2::new(f64::from(w.cols), f64::from(w.rows)) / 2.0
        })
    }

    /// A pane's size in pixels, unmagnified.
    pub(super) fn pane_size(&self) -> DVec2 {
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

    pub(super) fn set_status(&self, message: String) {
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
        self.forget_the_mark_once_the_view_moves();
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
        self.after_frame_on_the_page();
        let dt = f64::from(ctx.input(|i| i.unstable_dt)) * 1e3;
        if self.frame_intervals.len() == 60 {
            self.frame_intervals.pop_front();
        }
        self.frame_intervals.push_back(dt);
    }

    pub(super) fn take_background_results(&mut self) {
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

impl Explorer {
    /// Takes in an answer of the worker: the reference, and each pane's numbers.
    pub(super) fn take_analysis(&mut self, outcome: Outcome) {
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
        let temporal: Vec<_> = outcome
            .temporal
            .iter()
            .copied()
            .filter(|(p, _)| current(*p))
            .collect();
        let mut frame_errors = Vec::new();
        for (pane, result) in errors {
            match result {
                Ok(stats) => {
                    self.panes[pane].error = Some((outcome.camera, stats));
                    frame_errors.push((pane, stats));
                }
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
                if let Some(frame) = outcome.motion_frame {
                    self.record_motion_frame(frame, &frame_errors, &temporal);
                }
            }
            Err(e) => self.reference.problem = Some(e),
        }
    }
}

impl Explorer {
    /// Opens a font file, as the font dialog and a file drop do.
    pub fn open_font(&mut self, path: PathBuf) {
        self.settings.scene.font = FontChoice::File(path);
        self.settings.scene.variations.clear();
    }

    /// Opens a font given as bytes (the web page's file picker, a file dropped on the
    /// page), named `name`.
    pub fn open_font_bytes(&mut self, name: String, bytes: std::sync::Arc<[u8]>) {
        if !is_font_file(Path::new(&name)) {
            self.set_status(format!("'{name}' is not a .ttf/.otf font"));
            return;
        }
        self.settings.scene.font = FontChoice::Opened {
            name,
            bytes: FontBytes(bytes),
        };
        self.settings.scene.variations.clear();
    }

    /// A file dropped on the desktop window. (On the web page the page itself reads a
    /// dropped file, which egui would hand over only as a future, and passes its bytes
    /// to `open_font_bytes`.)
    pub(super) fn take_dropped_files(&mut self, ctx: &egui::Context) {
        if cfg!(target_arch = "wasm32") {
            return;
        }
        let dropped = ctx.input(|i| i.raw.dropped_files.first().map(|f| f.path().to_path_buf()));
        if let Some(path) = dropped {
            if is_font_file(&path) {
                self.open_font(path);
            } else {
                self.set_status(format!("'{}' is not a .ttf/.otf font", path.display()));
            }
        }
    }
}

impl Explorer {
    pub fn sweep_points(&self) -> &[ParetoPoint] {
        &self.sweep.points
    }

    pub fn sweep_running(&self) -> bool {
        self.sweep.running()
    }

    /// The combinations the last sweep could not measure, each with its reason.
    pub fn sweep_problems(&self) -> &[String] {
        &self.sweep.problems
    }

    /// Starts the speed-vs-error sweep on the current scene and view and opens its window.
    pub fn start_sweep(&mut self, ctx: &egui::Context) {
        self.sweep.open = true;
        if let (Some((gpu, _)), Some(scene), Some(camera)) =
            (&self.gpu, self.scene.scene(), self.canvas.camera)
        {
            self.sweep
                .start(ctx, gpu, &self.catalog, scene.clone(), camera);
        }
    }
}
