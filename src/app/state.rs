//! What the explorer keeps between frames for its canvas, blink, Cases menu, artifact
//! search and playback: the state [`Explorer`](super::explorer::Explorer) holds and
//! each of those files works on in its `impl Explorer`. It lives apart from them so that
//! the explorer holds it without importing them: the imports point one way, from each
//! feature to the explorer to this file.

use std::collections::BTreeMap;

use eframe::egui;

use super::analysis::MotionKey;
use super::settings::{CameraSettings, Layout, PANES, PaneSettings, PaneSource, SceneSettings};
use crate::camera::Camera;
use crate::gpu::PendingReadback;
use crate::magnify::Window;
use crate::metrics::{PixelError, TemporalError};
use crate::motion::MotionPath;
use crate::named_views::NamedView;

/// When the view fits the text to the panes by itself: when the layout or the text
/// changes — the text once its field is left, not at each key — and on a first start,
/// which opens on small text magnified on an artifact instead (see [`OPENING`](super::canvas::OPENING)).
#[derive(Default)]
pub struct AutoFit {
    pub pending: bool,
    /// The first start's opening view is still to be placed.
    pub opening: bool,
    pub(super) layout: Option<Layout>,
    pub(super) text: Option<String>,
}

/// What the view shows; when it stops changing, the view is at rest.
#[derive(Clone, Debug, PartialEq)]
pub struct CanvasKey {
    pub(super) camera: Camera,
    pub(super) scene: u64,
    pub(super) panes: Vec<(u64, bool)>,
}

/// The read-backs of a view at rest, one per pane drawing a method.
pub(super) struct Reading {
    pub(super) key: CanvasKey,
    pub(super) pending: Vec<(usize, PendingReadback)>,
}

/// The pane layout and hover of the last frame.
#[derive(Default)]
pub struct CanvasState {
    /// The camera every pane shares this frame (its size: one pane, in pixels, or the
    /// magnifier's window of it).
    pub camera: Option<Camera>,
    /// The pixels of the ×1 pane that camera draws, and their magnification.
    pub window: Option<Window>,
    /// One pane's size in pixels, unmagnified.
    pub pane_size: Option<(u32, u32)>,
    /// The wheel's scroll action began with Alt: what egui still smooths out of it is
    /// the magnifier's, not a zoom.
    pub(super) magnifying_scroll: bool,
    pub key: Option<CanvasKey>,
    pub(super) changed_at: f64,
    pub analysed: Option<CanvasKey>,
    /// The panes' read-backs under way for a view at rest.
    pub(super) reading: Option<Reading>,
    /// Pane index and pixel under the pointer.
    pub hovered: Option<(usize, u32, u32)>,
    /// Notes to show, per pane.
    pub(super) notes: Vec<String>,
    /// Where the visible panes are, in points.
    pub rects: Vec<egui::Rect>,
}

/// Whether pane A shows the other rendering now, and whether it flips on its own.
#[derive(Default)]
pub struct Blink {
    pub(super) flipped: bool,
    pub(super) auto: bool,
}

/// The menu's list, and what a loaded case is waiting for.
#[derive(Default)]
pub struct CasesMenu {
    /// Listed on the menu's first opening (building every case's scene takes a moment).
    pub(super) views: Option<Vec<NamedView>>,
    /// The scene settings a case was loaded over: changing the font, text or glyph
    /// leaves the case.
    pub(super) loaded_over: Option<SceneSettings>,
    /// Each pane's outline switch before a case turned them on, restored on leaving.
    pub(super) outlines_before: Option<[bool; PANES]>,
}

/// The view a worst-pixel request was made for.
pub struct WorstPixelRequest {
    pub(super) camera: CameraSettings,
    pub(super) scene: SceneSettings,
}

/// The pixel the view opened on (a worst pixel, a link's focus), marked in every pane
/// while the view it was found for is shown: the camera and scene settings and the
/// motion frame of that moment. Any change to them (a pan, a zoom, a new focus, scene
/// or case) leaves it; a pane's method or overlay does not, the pixel being the same.
#[derive(Clone, Debug, PartialEq)]
pub struct Mark {
    /// The pixel, in ×1 pane pixels.
    pub(super) pixel: (u32, u32),
    pub(super) camera: CameraSettings,
    pub(super) scene: SceneSettings,
    pub(super) frame: i64,
}

/// A search for a pane's artifacts under way: its method drawn into a frame of its own,
/// read back without waiting (`PendingReadback`), then compared with the reference on
/// a later frame; and what to do with the answer.
pub struct ArtifactSearch {
    pub(super) pane: usize,
    pub(super) camera: Camera,
    pub(super) then: Then,
    /// What it was started for: an answer for a view changed since is dropped.
    pub(super) source: PaneSource,
    pub(super) scene_generation: u64,
    pub(super) settings_camera: CameraSettings,
    pub(super) readback: PendingReadback,
}

/// What a search is for.
#[derive(Clone, Copy)]
pub(super) enum Then {
    /// A case's frame larger than the pane: move the pane's window onto the frame's
    /// worst pixel, then go to the worst pixel as `Step(None)` does.
    BringCaseWorst,
    /// Go to the worst pixel (None) or step on from the one `shown` (Some(forward)).
    Step(Option<bool>, Option<(u32, u32)>),
}

/// One pane's pixels over the threshold, and the one shown.
pub struct Artifacts {
    pub(super) pane: usize,
    /// What they were worked out for: the pane's source, the scene, the ×1 camera.
    pub(super) source: PaneSource,
    pub(super) scene_generation: u64,
    pub(super) camera: Camera,
    pub(super) pixels: Vec<PixelError>,
    /// The worst pixel, over the threshold or not.
    pub(super) worst: PixelError,
    pub(super) current: usize,
    /// Worked out anew with the pixel shown before still among them, at `current`.
    pub(super) found_again: bool,
}

/// A pane's figures in one frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FramePoint {
    /// Against the reference's frame, 1/255.
    pub mae_255: f64,
    /// Against the frame before (none for the first frame analysed, or after a jump).
    pub temporal: Option<TemporalError>,
}

/// The inspected pixel in one frame: each visible pane's coverage (none for a pane
/// without a capture) and the reference's.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelSample {
    pub panes: Vec<Option<f32>>,
    pub reference: f32,
}

/// The inspected pixel (in the panes' drawn pixels) and its samples by frame.
pub type PixelHistory = ((u32, u32), Vec<(i64, PixelSample)>);

/// What the charts are of: a change of any of it starts them afresh.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct ChartKey {
    pub(super) scene: u64,
    pub(super) motion: Option<MotionKey>,
    pub(super) panes: Vec<PaneSettings>,
}

/// Where text in motion stands: the frame shown, the transport, and the charts' points.
#[derive(Default)]
pub struct Playback {
    /// The frame shown; 0 is the camera the controls set.
    pub frame: i64,
    pub playing: bool,
    /// The frame was changed by the transport: analyse it at once, not after the view
    /// has rested.
    pub stepped: bool,
    /// The charts' window is open.
    pub charts_open: bool,
    pub(super) history: Vec<BTreeMap<i64, FramePoint>>,
    /// The inspected pixel (in the panes' drawn pixels) and its samples.
    pub(super) pixel: Option<((u32, u32), BTreeMap<i64, PixelSample>)>,
    pub(super) chart_key: Option<ChartKey>,
    /// Why playback stopped by itself.
    pub stopped: Option<String>,
}

impl Playback {
    /// The path of `text` and the frame, when the text is a path that moves.
    pub fn motion(&self, text: &str) -> Option<(MotionPath, i64)> {
        MotionPath::parse(text)
            .ok()
            .filter(|p| !p.is_still())
            .map(|p| (p, self.frame))
    }

    /// Pane `index`'s points, by frame.
    pub fn history(&self, index: usize) -> Vec<(i64, FramePoint)> {
        self.history
            .get(index)
            .map(|h| h.iter().map(|(&n, &p)| (n, p)).collect())
            .unwrap_or_default()
    }

    /// The inspected pixel and its samples, by frame.
    pub fn pixel_history(&self) -> Option<PixelHistory> {
        let (pixel, samples) = self.pixel.as_ref()?;
        Some((
            *pixel,
            samples.iter().map(|(&n, s)| (n, s.clone())).collect(),
        ))
    }

    pub(super) fn step(&mut self, by: i64) {
        self.frame += by;
        self.stepped = true;
        self.stopped = None;
    }

    pub(super) fn clear(&mut self) {
        self.history.clear();
        self.pixel = None;
    }
}
