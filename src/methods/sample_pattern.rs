//! What a pattern of point samples can get wrong on a pixel crossed by one straight
//! edge: the derivation behind the claims of the sampling methods (`xor-stencil`,
//! `tessellation`), which bound their error per edge pixel.
//!
//! A pixel whose samples count the inside of a straight edge reads the share of its
//! samples inside; the exact coverage is the area inside. Over every line through the
//! pixel, the largest difference is the pattern's worst error on an edge pixel, and
//! its mean over lines is what an edge pixel is off by on average. Both come from the
//! pattern alone, in closed form per line, never from a render.

use glam::DVec2;

/// The standard sample positions of 4× MSAA in a unit pixel (Vulkan's
/// `standardSampleLocations`, Direct3D's the same): a rotated grid, one sample in each
/// quarter-pixel row and column, at 1/8, 3/8, 5/8 and 7/8 along each axis.
pub const STANDARD_4X: [DVec2; 4] = [
    DVec2::new(0.375, 0.125),
    DVec2::new(0.875, 0.375),
    DVec2::new(0.125, 0.625),
    DVec2::new(0.625, 0.875),
];

/// The mean error, 1/255, of one sample at the pixel's centre (aliasing: coverage
/// rounded to 0 or 1) on a pixel crossed by one straight edge, 0.194, rounded down
/// (`mean_straight_edge_error`; checked in the tests). A sampled method's claim on the
/// mean over edge pixels: under it, on every glyph, its samples do better on average
/// than no anti-aliasing would on plain edges — a claim coverage rounded to 0 or 1
/// breaks.
pub const ALIASED_EDGE_MAE_255: f64 = 49.0;

/// Area of the part of the unit pixel [0, 1]² where n·p ≤ c, for a unit normal n: the
/// exact coverage of a straight edge; the pixel clipped by the half-plane, by the
/// shoelace formula.
pub fn area_below(n: DVec2, c: f64) -> f64 {
    let corners = [
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 0.0),
        DVec2::new(1.0, 1.0),
        DVec2::new(0.0, 1.0),
    ];
    let mut clipped = Vec::with_capacity(5);
    for (i, &a) in corners.iter().enumerate() {
        let b = corners[(i + 1) % 4];
        let (da, db) = (n.dot(a) - c, n.dot(b) - c);
        if da <= 0.0 {
            clipped.push(a);
        }
        if (da < 0.0) != (db < 0.0) && da != db {
            clipped.push(a + (b - a) * (da / (da - db)));
        }
    }
    let twice: f64 = (0..clipped.len())
        .map(|i| clipped[i].perp_dot(clipped[(i + 1) % clipped.len()]))
        .sum();
    twice.abs() / 2.0
}

/// The error of `samples` (inside the unit pixel) on the half-plane n·p ≤ c: the share
/// of samples inside less the area inside, as a magnitude.
fn error_at(samples: &[DVec2], n: DVec2, c: f64) -> f64 {
    let inside = samples.iter().filter(|s| n.dot(**s) <= c).count();
    (inside as f64 / samples.len() as f64 - area_below(n, c)).abs()
}

/// Directions the sweep tries: `steps` even ones, and those along the line through
/// each two samples (where a line can take two samples in or out at once), each
/// nudged either way.
fn directions(samples: &[DVec2], steps: usize) -> Vec<DVec2> {
    let mut angles: Vec<f64> = (0..steps)
        .map(|k| std::f64::consts::TAU * (k as f64 + 0.5) / steps as f64)
        .collect();
    for (i, a) in samples.iter().enumerate() {
        for b in &samples[i + 1..] {
            let along = (*b - *a).to_angle() + std::f64::consts::FRAC_PI_2;
            for turn in [0.0, std::f64::consts::PI] {
                for nudge in [-1e-9, 0.0, 1e-9] {
                    angles.push(along + turn + nudge);
                }
            }
        }
    }
    angles.into_iter().map(DVec2::from_angle).collect()
}

/// The largest error of `samples` on a pixel crossed by one straight edge, over every
/// line. Between two samples' projections the count is constant and the area moves one
/// way, so per direction the extremes lie just before and just after each sample.
pub fn worst_straight_edge_error(samples: &[DVec2]) -> f64 {
    let mut worst = 0.0f64;
    for n in directions(samples, 3600) {
        for s in samples {
            let c = n.dot(*s);
            for side in [-1e-12, 1e-12] {
                worst = worst.max(error_at(samples, n, c + side));
            }
        }
    }
    worst
}

/// The mean error of `samples` on a pixel crossed by one straight edge: over lines of
/// uniform direction and uniform offset among those that cross the pixel.
pub fn mean_straight_edge_error(samples: &[DVec2]) -> f64 {
    let (steps, offsets) = (720, 800);
    let mut sum = 0.0;
    for k in 0..steps {
        let n = DVec2::from_angle(std::f64::consts::TAU * (k as f64 + 0.5) / steps as f64);
        let ends = [0.0, n.x, n.y, n.x + n.y];
        let low = ends.iter().copied().fold(f64::INFINITY, f64::min);
        let high = ends.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        for j in 0..offsets {
            let c = low + (high - low) * (j as f64 + 0.5) / offsets as f64;
            sum += error_at(samples, n, c);
        }
    }
    sum / (steps * offsets) as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn areas_are_the_hand_worked_ones() {
        let diagonal = DVec2::new(1.0, 1.0).normalize();
        // x + y ≤ 1: half the pixel; x + y ≤ 1/2: a corner triangle of legs 1/2.
        assert!((area_below(diagonal, 1.0 / 2f64.sqrt()) - 0.5).abs() < 1e-12);
        assert!((area_below(diagonal, 0.5 / 2f64.sqrt()) - 0.125).abs() < 1e-12);
        assert!((area_below(DVec2::X, 0.3) - 0.3).abs() < 1e-12);
        assert_eq!(area_below(DVec2::X, -0.1), 0.0);
        assert_eq!(area_below(DVec2::X, 1.1), 1.0);
    }

    #[test]
    fn one_sample_at_the_centre_is_off_by_half_at_worst() {
        // A line just past the centre: the sample counts all or nothing of half a
        // pixel. Hand-worked: 1/2 at worst.
        let centre = [DVec2::splat(0.5)];
        assert!((worst_straight_edge_error(&centre) - 0.5).abs() < 1e-6);
        // A vertical edge at x: error |[x ≥ 1/2] − x|, mean 1/4 over x; over every
        // direction the mean is below that of the worst direction.
        let mean = mean_straight_edge_error(&centre);
        assert!(mean > 0.15 && mean < 0.25, "{mean}");
        assert_eq!(ALIASED_EDGE_MAE_255, (mean * 255.0).floor(), "{mean}");
    }

    #[test]
    fn four_rooks_resolve_an_axis_aligned_edge_to_an_eighth() {
        // Along x the rotated grid's samples sit at 1/8, 3/8, 5/8, 7/8: a vertical edge
        // is off by at most 1/8 (hand-worked); a slanted one can do worse.
        let vertical = (0..1000)
            .map(|j| error_at(&STANDARD_4X, DVec2::X, j as f64 / 1000.0))
            .fold(0.0f64, f64::max);
        assert!((vertical - 0.125).abs() < 1e-3, "{vertical}");
        assert!(worst_straight_edge_error(&STANDARD_4X) > 0.125);
    }
}
