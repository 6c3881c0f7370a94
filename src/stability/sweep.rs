//! The sweep: every case × every method variant × sub-pixel offsets × rotations,
//! compared with the reference (rendered once per camera), artifacts counted and the
//! worst pixel located.

use glam::DVec2;
use serde::Serialize;

use super::claims::Variant;
use super::hard_cases::HardCase;
use super::worst_cameras;
use crate::Error;
use crate::coverage::CoverageImage;
use crate::gpu::GpuContext;
use crate::methods::info::Bound;
use crate::methods::{Method, frame, registry};
use crate::metrics::{self, ErrorStats};
use crate::reference;

/// The cameras each case is seen through.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepSize {
    pub offsets: Vec<DVec2>,
    pub rotations_deg: Vec<f64>,
    /// Rotations added for the cases seen through a full turn (`HardCase::full_turn`).
    pub full_turn_deg: Vec<f64>,
    /// Cameras added for named cases (case, rotation, offset): where the full sweep
    /// found a method worst, so that a grid too coarse to contain them still runs them.
    pub also: Vec<(&'static str, f64, DVec2)>,
}

impl SweepSize {
    /// 16 sub-pixel offsets (a 4×4 grid of 1/4 px) × rotations of 0°, 1°, 45°, 89.9°;
    /// for a full turn, every 30° besides.
    pub fn full() -> SweepSize {
        SweepSize {
            offsets: (0..16)
                .map(|k| DVec2::new(f64::from(k % 4), f64::from(k / 4)) / 4.0)
                .collect(),
            rotations_deg: vec![0.0, 1.0, 45.0, 89.9],
            full_turn_deg: every(30.0),
            // Its grid is where every worst camera was found.
            also: Vec::new(),
        }
    }

    /// The CI size: 4 offsets (one per row and column of the grid) × 0° and 45°; for a
    /// full turn, every 90° besides; and the camera where the full sweep found each
    /// method worst on each case ([`worst_cameras`]).
    pub fn quick() -> SweepSize {
        SweepSize {
            offsets: [(0.0, 0.0), (0.25, 0.5), (0.5, 0.75), (0.75, 0.25)]
                .map(DVec2::from)
                .to_vec(),
            rotations_deg: vec![0.0, 45.0],
            full_turn_deg: every(90.0),
            also: worst_cameras::all()
                .iter()
                .map(|w| (w.case, w.rotation_deg, DVec2::from(w.subpixel)))
                .collect(),
        }
    }

    /// The grid's cameras for a case not seen through a full turn.
    pub fn grid_cameras(&self) -> usize {
        self.offsets.len() * self.rotations_deg.len()
    }

    /// The rotations `case` is seen at: the sweep's, and for a full turn its full
    /// turn's too, each once, in increasing order.
    pub fn rotations_for(&self, case: &HardCase) -> Vec<f64> {
        let mut rotations = self.rotations_deg.clone();
        if case.full_turn {
            rotations.extend(&self.full_turn_deg);
            rotations.sort_by(f64::total_cmp);
            rotations.dedup();
        }
        rotations
    }

    /// Every camera `case` is seen through, (rotation, offset): the grid, then the
    /// cameras added for it that the grid lacks.
    pub fn cameras_for(&self, case: &HardCase) -> Vec<(f64, DVec2)> {
        let mut cameras: Vec<(f64, DVec2)> = self
            .rotations_for(case)
            .into_iter()
            .flat_map(|r| self.offsets.iter().map(move |&o| (r, o)))
            .collect();
        for &(name, rotation, offset) in &self.also {
            if name == case.name && !cameras.contains(&(rotation, offset)) {
                cameras.push((rotation, offset));
            }
        }
        cameras
    }
}

/// Rotations from 0° up to a full turn (not included) in steps of `step_deg`.
fn every(step_deg: f64) -> Vec<f64> {
    let steps = (360.0 / step_deg).round() as u32;
    (0..steps).map(|k| f64::from(k) * step_deg).collect()
}

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
    /// [`metrics::ErrorStats::edge`]), in 1/255.
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
                || self.bound.is_some_and(|b| !b.holds(self.max, self.mae_255)))
    }
}

/// Runs `variants` on `cases` through the cameras of `size`. `progress` hears one line
/// per case.
pub fn run(
    gpu: &GpuContext,
    cases: &[HardCase],
    variants: &[Variant],
    size: &SweepSize,
    mut progress: impl FnMut(&str),
) -> Result<Vec<Outcome>, Error> {
    let mut outcomes = Vec::new();
    for case in cases {
        progress(case.name);
        let mut cells: Vec<(Option<Box<dyn Method>>, Outcome)> = variants
            .iter()
            .map(|variant| {
                let mut outcome = Outcome::new(case, variant);
                let method = registry::create(variant.method, &variant.params())
                    .and_then(|mut m| m.prepare(gpu, &case.scene).map(|()| m))
                    .map_err(|e| match e {
                        Error::Refused(reason) => outcome.refused = Some(reason),
                        e => outcome.failure = Some(format!("prepare: {e}")),
                    })
                    .ok();
                (method, outcome)
            })
            .collect();
        for (rotation_deg, subpixel) in size.cameras_for(case) {
            let camera = case.camera(rotation_deg, subpixel)?;
            let reference = reference::rasterize(&case.scene, &camera)?;
            for (method, outcome) in &mut cells {
                let Some(m) = method else { continue };
                let image = match frame::render_image(gpu, m.as_mut(), &camera) {
                    Ok(image) => image,
                    // A peer's limit at this camera (glyphon: a turn): said, and the
                    // other cameras still drawn.
                    Err(Error::Refused(reason)) => {
                        outcome.refused = Some(reason);
                        continue;
                    }
                    Err(e) => {
                        outcome.failure = Some(format!(
                            "drawing at {rotation_deg}°, offset {subpixel}: {e}"
                        ));
                        *method = None;
                        continue;
                    }
                };
                let stats = metrics::compare(&image, &reference)?;
                outcome.add_frame(&stats, (rotation_deg, subpixel), image, &reference);
            }
        }
        outcomes.extend(cells.into_iter().map(|(_, outcome)| outcome.finish()));
    }
    Ok(outcomes)
}
