//! One cell of the stability table: a method variant on a hard case, over the cameras
//! it was seen through — the figures the sweep adds frame by frame, where it was worst,
//! and whether that breaks the variant's claim.

use glam::DVec2;
use serde::Serialize;

use super::claims::Variant;
use super::hard_cases::HardCase;
use crate::coverage::CoverageImage;
use crate::methods::info::Bound;
use crate::metrics::ErrorStats;

/// Where a (case, variant) was worst.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Worst {
    pub rotation_deg: f64,
    pub subpixel: (f64, f64),
    /// Pixel (x, y) in that frame.
    pub pixel: (u32, u32),
}

/// One cell of the table: a variant on a case, over every camera of the sweep.
#[derive(Clone, Debug, Serialize)]
pub struct Outcome {
    pub case: &'static str,
    pub variant: &'static str,
    /// Mean over the frames of each frame's MAE, in 1/255.
    pub mae_255: f64,
    /// Mean over the frames of each frame's MAE over its edge pixels (see
    /// [`ErrorStats::edge`]), in 1/255.
    pub edge_mae_255: f64,
    /// Largest pixel error over all frames (infinite for NaN coverage).
    pub max: f64,
    /// Pixels off by more than 0.25, summed over the frames (all of them edge pixels).
    pub pixels_over_025: usize,
    /// Artifacts: pixels off by more than 0.5 (nearer the wrong level), summed over
    /// the frames.
    pub artifact_pixels: usize,
    pub frames: usize,
    pub worst: Worst,
    /// Whether the case is a documented limitation of the method.
    pub limitation: bool,
    /// The claimed bound (on a limitation, the looser one that still holds), if any.
    pub bound: Option<Bound>,
    /// A failure to prepare or draw, which breaks any claim.
    pub failure: Option<String>,
    /// Why a peer could not draw some of the cameras (its documented limit): the
    /// figures are over the others (none, when `frames` is 0). Never a failure.
    pub refused: Option<String>,
    /// A row with no claim at all (a peer's): measured and shown, never judged.
    pub observed: bool,
    /// The worst frame and its reference (not serialized).
    #[serde(skip)]
    pub worst_images: Option<(CoverageImage, CoverageImage)>,
}

impl Outcome {
    /// `variant`'s cell on `case`, before any frame.
    pub fn new(case: &HardCase, variant: &Variant) -> Outcome {
        Outcome {
            case: case.name,
            variant: variant.label,
            mae_255: 0.0,
            edge_mae_255: 0.0,
            max: 0.0,
            pixels_over_025: 0,
            artifact_pixels: 0,
            frames: 0,
            worst: Worst::default(),
            limitation: variant.claim.is_limitation(case.traits),
            bound: variant.claim.bound(case.traits),
            failure: None,
            refused: None,
            observed: variant.claim.bound.is_none() && variant.claim.limitation.is_none(),
            worst_images: None,
        }
    }

    /// Adds one frame: `stats` compare `image` with `reference`, seen through `camera`
    /// (rotation, offset). The means are sums until [`Outcome::finish`].
    pub fn add_frame(
        &mut self,
        stats: &ErrorStats,
        camera: (f64, DVec2),
        image: CoverageImage,
        reference: &CoverageImage,
    ) {
        self.frames += 1;
        self.mae_255 += stats.mae_255;
        self.edge_mae_255 += stats.edge.mae_255;
        self.pixels_over_025 += stats.pixels_over_025;
        self.artifact_pixels += stats.pixels_over_05;
        // `compare` gives an invalid pixel an infinite error, so NaN never hides here.
        if stats.max > self.max || self.worst_images.is_none() {
            self.max = stats.max;
            self.worst = Worst {
                rotation_deg: camera.0,
                subpixel: camera.1.into(),
                pixel: stats.worst_pixel,
            };
            self.worst_images = Some((image, reference.clone()));
        }
    }

    /// The cell with its means taken over its frames.
    pub fn finish(mut self) -> Outcome {
        let frames = self.frames.max(1) as f64;
        self.mae_255 /= frames;
        self.edge_mae_255 /= frames;
        self
    }

    /// Whether the measurement breaks the claim (a failure always does). An observed
    /// row (a peer's) has no claim to break: its failures are shown, never judged.
    pub fn breaks_claim(&self) -> bool {
        !self.observed
            && (self.failure.is_some()
                || self
                    .bound
                    .is_some_and(|b| !b.holds(self.max, self.mae_255, self.edge_mae_255)))
    }
}
