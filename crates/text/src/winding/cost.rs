//! Where `aa=area`'s time goes: the counts behind a frame's cost and the shader cut
//! short after each of its stages, for the bench's breakdown
//! (`crate::bench::winding_cost`).
//!
//! Two counting passes draw the frame as usual but write, summed per pixel over the
//! quads that reach it: the curves visited, those wholly right of the pixel and those
//! across it (`OVERLAY` 4), and the fragments, those whose coverage came out exactly 0
//! or 1, and those that integrated the sub-pixel grid (`OVERLAY` 5). A [`Stage`] cuts
//! the shader short so that each stage's time is the difference from the one before.

use super::{Output, Settings, Stage, Winding};
use crate::Error;
use crate::camera::Camera;
use crate::gpu::{GpuContext, kit};

/// One frame's counts, summed over its pixels.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct CostCounts {
    /// Glyph quads drawn.
    pub quads: u64,
    pub fragments: u64,
    /// Pixels with coverage above 0.
    pub covered_pixels: u64,
    /// Fragments whose coverage came out exactly 0, exactly 1.
    pub coverage_zero: u64,
    pub coverage_one: u64,
    /// Fragments that integrated the sub-pixel grid (three winding levels may meet).
    pub grid: u64,
    /// Band entries visited (each sub-pixel's walk counted where the grid ran): the
    /// curves as the shader holds them, monotone pieces of the font's.
    pub visited: u64,
    /// Visited curves wholly right of the pixel (their term: the pixel's area between
    /// their end heights), and across it (the full integral); the rest add nothing.
    pub right: u64,
    pub across: u64,
    /// Pixels whose counts the half-float target did not hold exactly (past
    /// [`kit::EXACT_COUNT_LIMIT`], or not integers): the sums are then approximate.
    pub inexact: u64,
}

impl CostCounts {
    /// `count` per fragment.
    pub fn per_fragment(&self, count: u64) -> f64 {
        count as f64 / self.fragments.max(1) as f64
    }

    /// Visited curves that added no term: below, above or left of the pixel.
    pub fn no_term(&self) -> u64 {
        self.visited.saturating_sub(self.right + self.across)
    }
}

impl Winding {
    /// `winding` at `settings`, its shader stopping after `stage`.
    pub fn staged(settings: Settings, stage: Stage) -> Winding {
        Winding {
            settings,
            user: None,
            stage,
            layout: None,
            pipelines: Vec::new(),
            prepared: None,
        }
    }

    /// The counts of a frame through `camera` (prepared, `aa=area`).
    pub fn cost_counts(&mut self, gpu: &GpuContext, camera: &Camera) -> Result<CostCounts, Error> {
        let size = (camera.width, camera.height);
        let mut quads = 0;
        let curves = kit::counting_pass(gpu, size, |encoder, target| {
            quads = self.draw(gpu, encoder, target, camera, Output::CurveTally)?;
            Ok(())
        })?;
        let fragments = kit::counting_pass(gpu, size, |encoder, target| {
            self.draw(gpu, encoder, target, camera, Output::FragmentTally)
                .map(drop)
        })?;
        // Each texel's sums are integers, exact below kit::EXACT_COUNT_LIMIT; a pixel whose
        // count is past it, or is no integer at all (NaN included), is said in `inexact`.
        let sum = |texels: &[[f32; 4]], channel: usize| -> u64 {
            texels.iter().map(|t| f64::from(t[channel]) as u64).sum()
        };
        let exact = |count: f32| count < kit::EXACT_COUNT_LIMIT && count.fract() == 0.0;
        let inexact = curves
            .iter()
            .zip(&fragments)
            .filter(|(c, f)| !(c[..3].iter().chain(f.iter()).all(|&n| exact(n))))
            .count() as u64;
        Ok(CostCounts {
            quads: u64::from(quads),
            fragments: sum(&fragments, 0),
            covered_pixels: curves.iter().filter(|t| t[3] > 0.0).count() as u64,
            coverage_zero: sum(&fragments, 1),
            coverage_one: sum(&fragments, 2),
            grid: sum(&fragments, 3),
            visited: sum(&curves, 0),
            right: sum(&curves, 1),
            across: sum(&curves, 2),
            inexact,
        })
    }
}
