//! The sweep: every case × every method variant × sub-pixel offsets × rotations,
//! compared with the reference (rendered once per camera), artifacts counted and the
//! worst pixel located.

use glam::DVec2;

use super::claims::Variant;
use super::hard_cases::HardCase;
use super::outcome::Outcome;
use super::worst_cameras;
use crate::Error;
use crate::gpu::GpuContext;
use crate::methods::{self, Method, frame};
use crate::metrics;
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
                let method = methods::create(variant.method, &variant.params())
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
