//! Going to the artifacts: a pane's pixels off from the reference, worst first, worked
//! out over the whole ×1 pane (not only the magnified window) with the method's own
//! frame and the CPU reference, the way `glyphscope render` measures them; the magnifier
//! is centred on one after another.

use eframe::egui;

use super::explorer::Explorer;
use super::gpu_view::lock;
use super::panes::{REFERENCE, pane_letter};
use super::settings::PaneSource;
use super::state::{ArtifactSearch, Artifacts, Then, WorstPixelRequest};
use crate::camera::Camera;
use crate::gpu::{Channels, CoverageTarget, PendingReadback};
use crate::methods::frame;
use crate::metrics::{self, PixelError};
use crate::reference;

/// The pixels stepped through are those off by more than this (coverage): the figure
/// the error tables count as "> 0.25".
pub const ARTIFACT_THRESHOLD: f64 = 0.25;

/// The magnification the worst pixel is shown at when the view is not magnified yet.
const ARTIFACT_MAGNIFY: u32 = 16;

impl Explorer {
    /// Centres the magnifier on the worst pixel of the hovered pane (else pane A).
    pub(super) fn go_to_worst_pixel(&mut self) {
        self.step_through_artifacts(None, self.hovered_pane());
    }

    /// Asks for the magnifier on the worst pixel of the view the settings show now, as
    /// soon as a pane's method is ready (a case loaded, the first start); any change to
    /// the camera or the scene before then cancels it.
    pub(super) fn go_to_worst_pixel_when_ready(&mut self) {
        self.worst_pixel_pending = Some(WorstPixelRequest {
            camera: self.settings.camera,
            scene: self.settings.scene.clone(),
        });
    }

    /// Carries out a pending request once the first visible pane that shows a GPU method
    /// has it prepared for the view; once a frame.
    pub(super) fn answer_worst_pixel_request(&mut self, ctx: &egui::Context) {
        let Some(request) = &self.worst_pixel_pending else {
            return;
        };
        if request.camera != self.settings.camera || request.scene != self.settings.scene {
            self.worst_pixel_pending = None;
            return;
        }
        let shown = self.settings.layout.panes();
        let Some(pane) = (0..shown).find(|&i| self.pane_is_gpu_method(i)) else {
            self.worst_pixel_pending = None;
            self.set_status("no pane shows a GPU method to find the worst pixel of".into());
            return;
        };
        let ready = self.canvas.pane_size.is_some()
            && self.scene.is_built_for(&self.settings.scene)
            && self.panes[pane].is_built_for(&self.settings.panes[pane], self.scene.generation())
            && self.panes[pane].has_method();
        if ready {
            self.worst_pixel_pending = None;
            self.bring_case_worst_into_pane(pane);
            ctx.request_repaint();
        }
    }

    /// For a case whose frame is larger than the pane: finds pane `pane`'s worst pixel
    /// over the whole frame and moves the pane's window of the frame (by whole pixels,
    /// inside the frame) so it is in view; the pane then holds no pixel outside the
    /// frame along that side, so its worst is the frame's.
    fn bring_case_worst_into_pane(&mut self, pane: usize) {
        let (Some(frame), Some((width, height))) =
            (self.scene.case_camera().copied(), self.canvas.pane_size)
        else {
            return self.step_through_artifacts(None, pane);
        };
        if frame.width <= width && frame.height <= height {
            return self.step_through_artifacts(None, pane);
        }
        self.start_search(pane, frame, Then::BringCaseWorst);
    }

    /// Whether pane `index` shows a GPU method (not the reference or a difference).
    fn pane_is_gpu_method(&self, index: usize) -> bool {
        matches!(&self.settings.panes[index].source,
            PaneSource::Method { name, .. } if name != REFERENCE)
    }

    /// Centres the magnifier on the next (`forward`) or previous pixel over the
    /// threshold, in descending error, wrapping round; from the worst when the list is
    /// not for this view.
    pub(super) fn step_artifact(&mut self, forward: bool) {
        self.step_through_artifacts(Some(forward), self.hovered_pane());
    }

    fn hovered_pane(&self) -> usize {
        self.canvas.hovered.map_or(0, |(index, _, _)| index)
    }

    fn step_through_artifacts(&mut self, step: Option<bool>, pane: usize) {
        let Some((width, height)) = self.canvas.pane_size else {
            return;
        };
        let camera = self.settings.camera.camera(width, height);
        let source = self.settings.panes[pane].source.clone();
        let generation = self.scene.generation();
        let current = self.artifacts.as_ref().is_some_and(|a| {
            a.pane == pane
                && a.source == source
                && a.scene_generation == generation
                && a.camera == camera
        });
        // Stepping goes on from the pixel shown, found again in a list worked out anew
        // (the pane may have changed size as the status line wrapped).
        let shown = step
            .and(self.artifacts.as_ref())
            .filter(|a| a.pane == pane)
            .and_then(|a| a.pixels.get(a.current))
            .map(|p| p.0);
        if !current {
            self.start_search(pane, camera, Then::Step(step, shown));
            return;
        }
        self.show_artifact(step, pane, true);
    }

    /// Centres the magnifier on the artifact `step` asks for among those found, and says
    /// which in the status bar; `current`: the list was already this view's.
    fn show_artifact(&mut self, step: Option<bool>, pane: usize, current: bool) {
        let Some(artifacts) = self.artifacts.as_mut() else {
            return;
        };
        let n = artifacts.pixels.len();
        if n == 0 {
            // Nothing to step through; going to the worst still shows the worst there is.
            let ((x, y), error) = artifacts.worst;
            if step.is_some() || error == 0.0 {
                self.set_status(format!(
                    "pane {}: no pixel is off by more than {ARTIFACT_THRESHOLD}",
                    pane_letter(pane)
                ));
            } else {
                self.magnify_on((x, y));
                self.mark_pixel((x, y));
                self.set_status(format!(
                    "worst pixel ({x}, {y}) error {error:.3}; none is off by more than \
                     {ARTIFACT_THRESHOLD}"
                ));
            }
            return;
        }
        let continuing = current || artifacts.found_again;
        artifacts.current = match (step, continuing) {
            (Some(true), true) => (artifacts.current + 1) % n,
            (Some(false), true) => (artifacts.current + n - 1) % n,
            _ => 0,
        };
        let ((x, y), error) = artifacts.pixels[artifacts.current];
        let message = format!(
            "worst pixel {} of {n}: ({x}, {y}) error {error:.3}",
            artifacts.current + 1
        );
        self.magnify_on((x, y));
        self.mark_pixel((x, y));
        self.set_status(message);
    }

    /// Centres the magnifier on pixel (`x`, `y`), magnifying if it is not yet.
    fn magnify_on(&mut self, (x, y): (u32, u32)) {
        let camera = &mut self.settings.camera;
        if camera.magnify == 1 {
            camera.magnify = ARTIFACT_MAGNIFY;
        }
        camera.focus = [f64::from(x) + 0.5, f64::from(y) + 0.5];
    }

    /// Starts working out pane `pane`'s pixels over the threshold at the ×1 `camera`:
    /// its prepared method drawn into a frame of its own and read back as `render` does
    /// (coverage over 1 taken down to the union's 1), compared with the CPU reference
    /// once the GPU has answered ([`Explorer::poll_artifact_search`]).
    fn start_search(&mut self, pane: usize, camera: Camera, then: Then) {
        match self.draw_for_search(pane, &camera) {
            Ok(readback) => {
                self.artifact_search = Some(ArtifactSearch {
                    pane,
                    camera,
                    then,
                    source: self.settings.panes[pane].source.clone(),
                    scene_generation: self.scene.generation(),
                    settings_camera: self.settings.camera,
                    readback,
                });
            }
            Err(message) => {
                self.artifacts = None;
                self.set_status(format!("pane {}: {message}", pane_letter(pane)));
            }
        }
    }

    fn draw_for_search(&self, pane: usize, camera: &Camera) -> Result<PendingReadback, String> {
        let Some((gpu, _)) = &self.gpu else {
            return Err("no wgpu device".into());
        };
        if !self.pane_is_gpu_method(pane) {
            return Err("worst pixels are a GPU method's; this pane shows none".into());
        }
        let mut surface = lock(&self.panes[pane].surface);
        let method = surface
            .method
            .as_mut()
            .ok_or("the pane's method is not ready")?;
        let target = CoverageTarget::new(gpu, camera.width, camera.height, Channels::Coverage)
            .map_err(|e| e.to_string())?;
        frame::submit_frame(gpu, method.as_mut(), &target, camera).map_err(|e| e.to_string())?;
        // The target may go: wgpu keeps what submitted work reads until it is done.
        target.start_readback(gpu).map_err(|e| e.to_string())
    }

    /// Once a frame: finishes the search under way when the GPU has answered.
    pub(super) fn poll_artifact_search(&mut self, ctx: &egui::Context) {
        let Some((gpu, _)) = self.gpu.clone() else {
            return;
        };
        if !self
            .artifact_search
            .as_ref()
            .is_some_and(|s| s.readback.is_answered(&gpu))
        {
            if self.artifact_search.is_some() {
                ctx.request_repaint();
            }
            return;
        }
        let Some(search) = self.artifact_search.take() else {
            return;
        };
        let pane = search.pane;
        // The method, the scene or the camera changed while the GPU worked: the answer
        // is for a view no longer shown.
        if search.source != self.settings.panes[pane].source
            || search.scene_generation != self.scene.generation()
            || search.settings_camera != self.settings.camera
        {
            return;
        }
        let found = search
            .readback
            .take()
            .map_err(|e| e.to_string())
            .and_then(|image| self.compare_with_reference(&image.clamp_to_union(), &search.camera));
        let (pixels, worst) = match found {
            Ok(found) => found,
            Err(message) => {
                self.artifacts = None;
                self.set_status(format!("pane {}: {message}", pane_letter(pane)));
                return;
            }
        };
        match search.then {
            Then::BringCaseWorst => {
                if let Some(size) = self.canvas.pane_size {
                    self.settings.camera.show_frame_pixel(worst.0, size);
                }
                self.step_through_artifacts(None, pane);
            }
            Then::Step(step, shown) => {
                let found = shown.and_then(|s| pixels.iter().position(|p| p.0 == s));
                self.artifacts = Some(Artifacts {
                    pane,
                    source: self.settings.panes[pane].source.clone(),
                    scene_generation: self.scene.generation(),
                    camera: search.camera,
                    worst,
                    current: found.unwrap_or(0),
                    found_again: found.is_some(),
                    pixels,
                });
                self.show_artifact(step, pane, false);
            }
        }
        // The magnifier moved after this frame's panes were laid out.
        ctx.request_repaint();
    }

    /// The pixels of `image` over the threshold against the reference at `camera`,
    /// worst first, and its worst pixel.
    fn compare_with_reference(
        &self,
        image: &crate::coverage::CoverageImage,
        camera: &Camera,
    ) -> Result<(Vec<PixelError>, PixelError), String> {
        let scene = self.scene.scene().ok_or("no scene")?;
        let reference = reference::rasterize(scene, camera).map_err(|e| e.to_string())?;
        let over = metrics::pixels_over(image, &reference, ARTIFACT_THRESHOLD)
            .map_err(|e| e.to_string())?;
        let stats = metrics::compare(image, &reference).map_err(|e| e.to_string())?;
        Ok((over, (stats.worst_pixel, stats.max)))
    }
}
