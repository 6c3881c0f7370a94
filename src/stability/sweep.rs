//! The sweep: every case × every method variant × sub-pixel offsets × rotations,
//! compared with the reference (rendered once per camera), artifacts counted and the
//! worst pixel located.

use glam::DVec2;
use serde::Serialize;

use super::cases::Case;
use super::claims::Variant;
use crate::Error;
use crate::coverage::CoverageImage;
use crate::gpu::GpuContext;
use crate::methods::{self, Method, frame};
use crate::metrics;
use crate::reference;

/// The cameras each case is seen through.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepSize {
    pub offsets: Vec<DVec2>,
    pub rotations_deg: Vec<f64>,
    /// Rotations added for the cases seen through a full turn (`Case::full_turn`).
    pub full_turn_deg: Vec<f64>,
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
        }
    }

    /// The CI size: 4 offsets (one per row and column of the grid) × 0° and 45°; for a
    /// full turn, every 90° besides.
    pub fn quick() -> SweepSize {
        SweepSize {
            offsets: [(0.0, 0.0), (0.25, 0.5), (0.5, 0.75), (0.75, 0.25)]
                .map(DVec2::from)
                .to_vec(),
            rotations_deg: vec![0.0, 45.0],
            full_turn_deg: every(90.0),
        }
    }

    /// The cameras of a case not seen through a full turn.
    pub fn cameras(&self) -> usize {
        self.offsets.len() * self.rotations_deg.len()
    }

    /// The rotations `case` is seen at: the sweep's, and for a full turn its full
    /// turn's too, each once, in increasing order.
    pub fn rotations_for(&self, case: &Case) -> Vec<f64> {
        let mut rotations = self.rotations_deg.clone();
        if case.full_turn {
            rotations.extend(&self.full_turn_deg);
            rotations.sort_by(f64::total_cmp);
            rotations.dedup();
        }
        rotations
    }

    pub fn cameras_for(&self, case: &Case) -> usize {
        self.offsets.len() * self.rotations_for(case).len()
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
    /// Largest pixel error over all frames (infinite for NaN coverage).
    pub max: f64,
    /// Artifacts: pixels off by more than 0.5 (nearer the wrong level), summed over
    /// the frames.
    pub artifact_pixels: usize,
    pub frames: usize,
    pub worst: Worst,
    /// Whether the case is a documented limitation of the method.
    pub limitation: bool,
    /// The claimed bound on the largest error (on a limitation, the looser one that
    /// still holds), if any.
    pub bound: Option<f64>,
    /// A failure to prepare or draw, which breaks any claim.
    pub failure: Option<String>,
    /// The worst frame and its reference (not serialized).
    #[serde(skip)]
    pub worst_images: Option<(CoverageImage, CoverageImage)>,
}

impl Outcome {
    /// Whether the measurement breaks the claim (a failure always does).
    pub fn breaks_claim(&self) -> bool {
        // A NaN max compares false with everything: it breaks the claim too.
        let within = |bound: f64| self.max <= bound;
        self.failure.is_some() || self.bound.is_some_and(|b| !within(b))
    }
}

/// Runs `variants` on `cases` through the cameras of `size`. `progress` hears one line
/// per case.
pub fn run(
    gpu: &GpuContext,
    cases: &[Case],
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
                let mut outcome = Outcome {
                    case: case.name,
                    variant: variant.label,
                    mae_255: 0.0,
                    max: 0.0,
                    artifact_pixels: 0,
                    frames: 0,
                    worst: Worst::default(),
                    limitation: variant.claim.is_limitation(case.traits),
                    bound: variant.claim.bound(case.traits),
                    failure: None,
                    worst_images: None,
                };
                let method = methods::create(variant.method, &variant.params())
                    .and_then(|mut m| m.prepare(gpu, &case.scene).map(|()| m))
                    .map_err(|e| outcome.failure = Some(format!("prepare: {e}")))
                    .ok();
                (method, outcome)
            })
            .collect();
        for rotation_deg in size.rotations_for(case) {
            for &subpixel in &size.offsets {
                let camera = case.camera(rotation_deg, subpixel)?;
                let reference = reference::rasterize(&case.scene, &camera)?;
                for (method, outcome) in &mut cells {
                    let Some(m) = method else { continue };
                    let image = match frame::render_image(gpu, m.as_mut(), &camera) {
                        Ok(image) => image,
                        Err(e) => {
                            outcome.failure = Some(format!(
                                "drawing at {rotation_deg}°, offset {subpixel}: {e}"
                            ));
                            *method = None;
                            continue;
                        }
                    };
                    let stats = metrics::compare(&image, &reference)?;
                    outcome.frames += 1;
                    outcome.mae_255 += stats.mae_255;
                    outcome.artifact_pixels += stats.pixels_over_05;
                    if stats.max > outcome.max || outcome.worst_images.is_none() {
                        outcome.max = stats.max;
                        outcome.worst = Worst {
                            rotation_deg,
                            subpixel: subpixel.into(),
                            pixel: stats.worst_pixel,
                        };
                        outcome.worst_images = Some((image, reference.clone()));
                    }
                }
            }
        }
        for (_, mut outcome) in cells {
            outcome.mae_255 /= outcome.frames.max(1) as f64;
            outcomes.push(outcome);
        }
    }
    Ok(outcomes)
}
