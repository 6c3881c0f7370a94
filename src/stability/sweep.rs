//! The sweep: every case × every method variant × sub-pixel offsets × rotations,
//! compared with the reference (rendered once per camera), artifacts counted and the
//! worst pixel located.

use glam::DVec2;

use super::claims::Variant;
use super::hard_cases::HardCase;
use super::outcome::Outcome;
use super::worst_cameras;
use crate::Error;
use crate::effort::Effort;
use crate::gpu::GpuContext;
use crate::methods::{Method, frame, registry};
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
    /// The cameras `effort` sweeps: its offsets at each of its rotations, its full
    /// turn's rotations for the cases seen through one, and, where it reruns them, the
    /// camera where the full sweep found each method worst on each case
    /// ([`worst_cameras`]).
    pub fn of(effort: &Effort) -> SweepSize {
        let also = if effort.sweep_reruns_worst_cameras {
            worst_cameras::all()
                .iter()
                .map(|w| (w.case, w.rotation_deg, DVec2::from(w.subpixel)))
                .collect()
        } else {
            Vec::new()
        };
        SweepSize {
            offsets: effort
                .sweep_offsets
                .iter()
                .map(|&o| DVec2::from(o))
                .collect(),
            rotations_deg: effort.sweep_rotations_deg.to_vec(),
            full_turn_deg: every(effort.sweep_full_turn_step_deg),
            also,
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
                    // As every measurement takes it (`measure`, `motion`): instances
                    // added past 1 are their union.
                    Ok(image) => image.clamp_to_union(),
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
