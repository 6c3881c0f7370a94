//! The jittered passes' N-rooks pattern of sub-pixel offsets.

use glam::DVec2;

/// The sub-pixel offsets of `passes` jittered passes over `samples` MSAA samples,
/// centred on the pixel centre in a cell of side 1/samples.
///
/// The pattern is N-rooks (one point in each row and each column of an N×N grid, so an
/// axis-aligned edge is resolved to 1/N) with samples spread as far apart as a local
/// search finds: from the best affine permutation i ↦ (k·i + c) mod N, swaps of two
/// rows while they increase the smallest distance between two points (or keep it and
/// make it rarer). For N = 4 that is the rotated grid of 4× MSAA; for 6, the best of
/// all 720 patterns.
///
/// With 4 samples, whose standard positions lie at 1/8, 3/8, 5/8 and 7/8 in both axes,
/// offsets within ±1/8 keep every sample inside its pixel, as the box filter needs;
/// the frame's samples then form a 4N-rooks pattern, but one gathered in four
/// quarter-pixel squares (docs/methods/xor-stencil.md says what that costs).
pub fn jitter_offsets(passes: u32, samples: u32) -> Vec<DVec2> {
    let n = passes.max(1) as usize;
    let point = |i: usize, row: usize| {
        DVec2::new((i as f64 + 0.5) / n as f64, (row as f64 + 0.5) / n as f64)
    };
    // (smallest squared distance between two points, minus how many pairs have it).
    let spread = |rows: &[usize]| -> (f64, i64) {
        let (mut closest, mut count) = (f64::INFINITY, 0);
        for i in 0..n {
            for j in i + 1..n {
                let d = point(i, rows[i]).distance_squared(point(j, rows[j]));
                if d < closest {
                    (closest, count) = (d, 0);
                }
                count -= i64::from(d == closest);
            }
        }
        (closest, count)
    };
    let better = |a: (f64, i64), b: (f64, i64)| a.0 > b.0 || (a.0 == b.0 && a.1 > b.1);
    let gcd = |mut a: usize, mut b: usize| {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    let mut rows: Vec<usize> = (0..n).collect();
    let mut score = spread(&rows);
    for step in (1..n).filter(|&k| gcd(k, n) == 1) {
        for shift in 0..n {
            let candidate: Vec<usize> = (0..n).map(|i| (i * step + shift) % n).collect();
            let s = spread(&candidate);
            if better(s, score) {
                (rows, score) = (candidate, s);
            }
        }
    }
    let mut improved = true;
    while improved {
        improved = false;
        for a in 0..n {
            for b in a + 1..n {
                rows.swap(a, b);
                let s = spread(&rows);
                if better(s, score) {
                    score = s;
                    improved = true;
                } else {
                    rows.swap(a, b);
                }
            }
        }
    }
    let cell = 1.0 / f64::from(samples);
    (0..n).map(|i| (point(i, rows[i]) - 0.5) * cell).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Smallest distance between two of `points`.
    fn closest(points: &[DVec2]) -> f64 {
        let mut d = f64::INFINITY;
        for (i, a) in points.iter().enumerate() {
            for b in &points[i + 1..] {
                d = d.min(a.distance(*b));
            }
        }
        d
    }

    #[test]
    fn the_patterns_straight_edge_errors() {
        use crate::methods::sample_pattern::{
            STANDARD_4X, mean_straight_edge_error, worst_straight_edge_error,
        };
        let settings = super::super::Settings::default();
        assert_eq!((settings.samples, settings.passes), (4, 4));
        // Each pass moves the geometry by an offset, so the frame's samples are the 4x
        // standard ones moved back by each offset: 16 samples in four clusters.
        let samples: Vec<DVec2> = jitter_offsets(settings.passes, settings.samples)
            .iter()
            .flat_map(|o| STANDARD_4X.map(|s| s - *o))
            .collect();
        assert!(
            samples
                .iter()
                .all(|s| s.min_element() > 0.0 && s.max_element() < 1.0)
        );
        let worst = worst_straight_edge_error(&samples);
        let mean = mean_straight_edge_error(&samples);
        assert!((worst - 0.234).abs() < 0.0005, "{worst}");
        assert!((mean - 0.040).abs() < 0.0005, "{mean}");
        // A quarter of one centre sample's mean error, the claim's bound.
        let aliased = crate::methods::sample_pattern::ALIASED_EDGE_MAE_255 / 255.0;
        assert!(mean < aliased / 4.0, "{mean} against {aliased}");
    }

    #[test]
    fn jitter_finds_the_rotated_grid_and_the_best_six() {
        // Four passes: the rotated grid of 4x MSAA (rows 2, 0, 3, 1 or its mirror).
        let four = jitter_offsets(4, 1);
        let d = closest(&four);
        assert!(
            (d - (1.0f64 / 16.0 + 1.0 / 4.0).sqrt()).abs() < 1e-12,
            "{four:?}"
        );
        // Six: as far apart as the best of all 720 rooks patterns (among the 6^6 row
        // choices, those that use every row).
        let mut best = 0.0f64;
        for code in 0..6usize.pow(6) {
            let rows: Vec<usize> = (0..6).map(|i| code / 6usize.pow(i) % 6).collect();
            if (0..6).all(|r| rows.contains(&r)) {
                let p: Vec<DVec2> = (0..6)
                    .map(|i| DVec2::new(i as f64 + 0.5, rows[i] as f64 + 0.5) / 6.0)
                    .collect();
                best = best.max(closest(&p));
            }
        }
        assert!((closest(&jitter_offsets(6, 1)) - best).abs() < 1e-12);
    }

    #[test]
    fn jitter_is_a_rooks_pattern_inside_the_pixel() {
        for samples in [1, 4] {
            for passes in 1..=20 {
                let offsets = jitter_offsets(passes, samples);
                assert_eq!(offsets.len(), passes as usize);
                let cell = 1.0 / f64::from(samples);
                // Every offset keeps a sample inside its pixel: the 4x standard
                // positions are 1/8 from the borders.
                for o in &offsets {
                    assert!(o.x.abs() < cell / 2.0 && o.y.abs() < cell / 2.0, "{o}");
                }
                // One per row and one per column of the passes × passes grid.
                for axis in [0, 1] {
                    let mut rows: Vec<i64> = offsets
                        .iter()
                        .map(|o| ((o[axis] / cell + 0.5) * f64::from(passes)).floor() as i64)
                        .collect();
                    rows.sort();
                    assert_eq!(rows, (0..i64::from(passes)).collect::<Vec<_>>());
                }
            }
        }
        assert_eq!(jitter_offsets(1, 1), vec![DVec2::ZERO]);
    }
}
