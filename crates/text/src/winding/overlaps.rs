//! Which curves of a glyph can put three winding levels in one pixel: the curves
//! `aa=area` marks so that a pixel one of them crosses is integrated again in
//! sub-pixels.
//!
//! One pixel's coverage from its averaged winding number F is exact where the winding
//! inside the pixel takes two values, 0 and the glyph's fill sign. A curve whose two
//! sides are always those two values cannot break that; every other curve can: one
//! that crosses or touches another contour, or its own contour elsewhere (the levels
//! change along it where the other curve crosses), and one whose sides are 1 and 2 (a
//! contour inside another wound the same way) or −1 and 0. A pixel whose curves are all
//! plain holds only the two levels of their sides, so F is exact there.
//!
//! Decided once per glyph on the CPU, in f64, from the curves themselves: each pair of
//! curves that are not neighbours in a contour is tested for coming within a small
//! distance by subdividing both, and each remaining curve's side levels are read from
//! the winding of the other contours at its midpoint (constant along a curve nothing
//! crosses) and its own contour's orientation.

use glam::DVec2;

use crate::geometry::{
    Quad, distance_between_segments, point_at, signed_area, subcurve, winding_number,
};

/// How near two curves may come before they count as touching, in em. Only the cost
/// depends on it (a curve marked needlessly costs sub-pixels where it meets another
/// one); what makes the rest exact is that an unmarked curve's midpoint is this far
/// from every other contour, so its winding there is never in doubt.
const TOUCHING_EM: f64 = 1.0 / 4096.0;

/// For each curve of `contours` (in order), whether it may separate winding levels
/// other than 0 and the glyph's fill sign.
pub fn overlap_flags(contours: &[Vec<Quad>], units_per_em: f64) -> Vec<Vec<bool>> {
    let touching = TOUCHING_EM * units_per_em;
    let mut flags: Vec<Vec<bool>> = contours.iter().map(|c| vec![false; c.len()]).collect();
    let curves: Vec<(usize, usize)> = contours
        .iter()
        .enumerate()
        .flat_map(|(k, c)| (0..c.len()).map(move |i| (k, i)))
        .collect();
    let mut crosses_itself = vec![false; contours.len()];
    for a in 0..curves.len() {
        for b in a + 1..curves.len() {
            let ((ka, ia), (kb, ib)) = (curves[a], curves[b]);
            if ka == kb && neighbours(ia, ib, contours[ka].len()) {
                continue;
            }
            if within(contours[ka][ia], contours[kb][ib], touching, MAX_SPLITS) {
                flags[ka][ia] = true;
                flags[kb][ib] = true;
                crosses_itself[ka] |= ka == kb;
            }
        }
    }

    let bounds: Vec<(DVec2, DVec2)> = contours
        .iter()
        .map(|c| {
            c.iter()
                .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), q| {
                    (
                        lo.min(q[0].min(q[1]).min(q[2])),
                        hi.max(q[0].max(q[1]).max(q[2])),
                    )
                })
        })
        .collect();
    let areas: Vec<f64> = contours.iter().map(|c| signed_area(c)).collect();
    let fill_sign = if areas.iter().sum::<f64>() < 0.0 {
        -1
    } else {
        1
    };
    for (k, contour) in contours.iter().enumerate() {
        // A contour that crosses itself has no one orientation: all of it is marked.
        if crosses_itself[k] {
            flags[k].fill(true);
            continue;
        }
        let own = areas[k].signum() as i32;
        for (i, q) in contour.iter().enumerate() {
            if flags[k][i] {
                continue;
            }
            let midpoint = point_at(*q, 0.5);
            let others: i32 = (0..contours.len())
                .filter(|&other| other != k)
                .filter(|&other| {
                    let (lo, hi) = bounds[other];
                    midpoint.cmpge(lo).all() && midpoint.cmple(hi).all()
                })
                .map(|other| winding_number(midpoint, &contours[other]))
                .sum();
            // Its sides wind `others` and `others + own`: plain only as {0, fill sign}.
            let plain =
                (others == 0 && own == fill_sign) || (others == fill_sign && own == -fill_sign);
            flags[k][i] = !plain;
        }
    }
    flags
}

/// Halvings after which two curves still within reach of each other count as touching:
/// 2⁻⁴⁰ of a glyph is below f64's resolution of it.
const MAX_SPLITS: u32 = 40;

/// Whether curves `k` and `l` follow each other in a closed contour of `len` curves.
fn neighbours(k: usize, l: usize, len: usize) -> bool {
    (k + 1) % len == l || (l + 1) % len == k
}

/// Whether curves `a` and `b` come within about `distance` of each other: their
/// control hulls' bounds are apart by more (no), or both are flat to a quarter of it
/// and their chords are within it, or the more bent one is halved and each half asked.
fn within(a: Quad, b: Quad, distance: f64, splits_left: u32) -> bool {
    let bounds = |q: &Quad| (q[0].min(q[1]).min(q[2]), q[0].max(q[1]).max(q[2]));
    let ((lo_a, hi_a), (lo_b, hi_b)) = (bounds(&a), bounds(&b));
    if lo_a.cmpgt(hi_b + distance).any() || lo_b.cmpgt(hi_a + distance).any() {
        return false;
    }
    let bend = |q: &Quad| (q[0] - 2.0 * q[1] + q[2]).length();
    let (bend_a, bend_b) = (bend(&a), bend(&b));
    if splits_left == 0 {
        return true;
    }
    if bend_a.max(bend_b) <= 0.25 * distance {
        // A chord strays from its curve by at most a quarter of the bend.
        return distance_between_segments(a[0], a[2], b[0], b[2]) <= distance;
    }
    let (bent, other) = if bend_a >= bend_b { (a, b) } else { (b, a) };
    [subcurve(bent, 0.0, 0.5), subcurve(bent, 0.5, 1.0)]
        .into_iter()
        .any(|half| within(half, other, distance, splits_left - 1))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::line_as_quad;

    fn square(x: f64, y: f64, size: f64, clockwise: bool) -> Vec<Quad> {
        let mut p: Vec<DVec2> = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
            .iter()
            .map(|&(a, b)| DVec2::new(x + a * size, y + b * size))
            .collect();
        if clockwise {
            p.reverse();
        }
        (0..4).map(|k| line_as_quad(p[k], p[(k + 1) % 4])).collect()
    }

    fn flags(contours: &[Vec<Quad>]) -> Vec<Vec<bool>> {
        overlap_flags(contours, 1000.0)
    }

    #[test]
    fn a_ring_is_plain_either_way_round() {
        for clockwise in [false, true] {
            let ring = [
                square(0.0, 0.0, 10.0, clockwise),
                square(3.0, 3.0, 4.0, !clockwise),
            ];
            assert_eq!(
                flags(&ring),
                vec![vec![false; 4]; 2],
                "clockwise outer: {clockwise}"
            );
        }
    }

    /// Squares over (0, 0)–(10, 10) and (5, 5)–(15, 15), wound the same way: the first
    /// one's right and top sides run through the second one (sides 1|2 there), and the
    /// second one's bottom and left sides through the first; the other four have 0 and
    /// 1 on their sides.
    #[test]
    fn overlapping_squares_mark_the_sides_that_cross() {
        let squares = [square(0.0, 0.0, 10.0, false), square(5.0, 5.0, 10.0, false)];
        // Sides in order: bottom, right, top, left.
        assert_eq!(
            flags(&squares),
            vec![
                vec![false, true, true, false],
                vec![true, false, false, true]
            ]
        );
    }

    /// A contour inside another wound the same way has 1 and 2 on its sides; the outer
    /// one stays plain. Wound against it, it is a hole.
    #[test]
    fn a_stacked_contour_is_marked_and_a_hole_is_not() {
        let stacked = [square(0.0, 0.0, 10.0, false), square(3.0, 3.0, 4.0, false)];
        assert_eq!(flags(&stacked), vec![vec![false; 4], vec![true; 4]]);
    }

    /// Two contours side by side, a gap wider than the touching distance (1/4096 em of
    /// 1000 units) apart, are plain; touching along a side, they are not.
    #[test]
    fn touching_counts_and_a_gap_does_not() {
        let apart = [
            square(0.0, 0.0, 10.0, false),
            square(10.3, 0.0, 10.0, false),
        ];
        assert_eq!(flags(&apart), vec![vec![false; 4]; 2]);
        let touching = [
            square(0.0, 0.0, 10.0, false),
            square(10.0, 0.0, 10.0, false),
        ];
        let marked = flags(&touching);
        assert!(marked[0][1] && marked[1][3], "the shared side: {marked:?}");
    }

    /// A bow tie, (0,0) → (10,10) → (10,0) → (0,10) → back: its diagonals cross, and a
    /// contour crossing itself has no one orientation, so all of it is marked.
    #[test]
    fn a_contour_crossing_itself_is_marked() {
        let p = [(0.0, 0.0), (10.0, 10.0), (10.0, 0.0), (0.0, 10.0)].map(|(x, y)| DVec2::new(x, y));
        let bow_tie: Vec<Quad> = (0..4).map(|k| line_as_quad(p[k], p[(k + 1) % 4])).collect();
        assert_eq!(flags(&[bow_tie]), vec![vec![true; 4]]);
    }

    #[test]
    fn distance_of_curves_by_subdivision() {
        // An arch peaking at y = 5 and a line at y = 5 + d: within d, not within d/2.
        let arch = [
            DVec2::new(0.0, 0.0),
            DVec2::new(5.0, 10.0),
            DVec2::new(10.0, 0.0),
        ];
        let d = 0.01;
        let line = [
            DVec2::new(0.0, 5.0 + d),
            DVec2::new(5.0, 5.0 + d),
            DVec2::new(10.0, 5.0 + d),
        ];
        assert!(within(arch, line, 1.1 * d, MAX_SPLITS));
        assert!(!within(arch, line, 0.5 * d, MAX_SPLITS));
    }
}
