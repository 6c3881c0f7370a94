//! Cubics as quadratic Béziers: the conversion with a guaranteed maximum distance.
//!
//! Each cubic is split into n equal parameter ranges, each replaced by the quadratic
//! whose control point averages the two tangent-preserving ones (lyon_geom). For that
//! approximation |C(t) − Q(t)| ≤ √3/36 · |p0 − 3p1 + 3p2 − p3| / n³ at every t, so n
//! follows from the tolerance in closed form: a bound, not a sampled estimate, and no
//! recursion that a degenerate cubic could drive to its maximum depth (harfbuzz 76eb0ae).
//! Endpoints are kept exactly and consecutive pieces share their joins exactly.
//!
//! A cubic whose inner control points lie within the tolerance of its chord is a line
//! for all purposes (the curve stays in their convex hull, hence within the tolerance of
//! the chord, and sweeps the whole chord): it becomes that line.

use glam::DVec2;

use super::distance::distance_to_segment;
use super::segment::{Segment, from_lyon, lyon_cubic};

/// Default conversion tolerance in em: 1/16 px at 4096 px/em, where an edge pixel's
/// coverage moves by at most 16/255 (and 0.006 px at 400 px/em). What it costs per font
/// in quadratics and time: `cargo run --release --example prepare_outlines`.
pub const DEFAULT_QUAD_TOLERANCE_EM: f64 = 1.0 / (4096.0 * 16.0);

/// Replaces a cubic by lines and quadratics within `tolerance` of it; any other segment
/// is passed through unchanged.
pub fn cubic_to_quadratics(segment: &Segment, tolerance: f64, out: &mut impl FnMut(Segment)) {
    let Segment::Cubic(p0, p1, p2, p3) = *segment else {
        out(*segment);
        return;
    };
    if distance_to_segment(p1, p0, p3) <= tolerance && distance_to_segment(p2, p0, p3) <= tolerance
    {
        out(Segment::Line(p0, p3));
        return;
    }
    lyon_cubic(p0, p1, p2, p3).for_each_quadratic_bezier(tolerance, &mut |q| {
        out(Segment::Quad(
            from_lyon(q.from),
            from_lyon(q.ctrl),
            from_lyon(q.to),
        ))
    });
}

/// The largest distance from points of `cubic` to the `pieces` and back (Hausdorff),
/// measured on polylines within `resolution` of the true curves: an estimate, for tests
/// and reports, of the error that the bound above guarantees.
pub fn max_distance_to_cubic(pieces: &[Segment], cubic: &Segment, resolution: f64) -> f64 {
    let fine = resolution;
    let polyline = |segments: &[Segment]| -> Vec<DVec2> {
        let mut points = vec![segments[0].start()];
        for s in segments {
            s.flatten(fine, &mut |p| points.push(p));
        }
        points
    };
    let along_cubic = polyline(std::slice::from_ref(cubic));
    let along_pieces = polyline(pieces);
    let one_way = |from: &[DVec2], to: &[DVec2]| {
        from.iter()
            .map(|p| polyline_distance(*p, to))
            .fold(0.0, f64::max)
    };
    one_way(&along_cubic, &along_pieces).max(one_way(&along_pieces, &along_cubic))
}

fn polyline_distance(p: DVec2, polyline: &[DVec2]) -> f64 {
    polyline
        .windows(2)
        .map(|w| distance_to_segment(p, w[0], w[1]))
        .fold(f64::INFINITY, f64::min)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cubic(pts: [(f64, f64); 4]) -> Segment {
        let p = pts.map(|(x, y)| DVec2::new(x, y));
        Segment::Cubic(p[0], p[1], p[2], p[3])
    }

    fn convert(c: &Segment, tol: f64) -> Vec<Segment> {
        let mut out = Vec::new();
        cubic_to_quadratics(c, tol, &mut |s| out.push(s));
        out
    }

    /// Pieces are contiguous, start and end exactly at the cubic's endpoints, and stay
    /// within the tolerance.
    fn check(c: &Segment, tol: f64) -> Vec<Segment> {
        let pieces = convert(c, tol);
        assert_eq!(pieces.first().unwrap().start(), c.start(), "start moved");
        assert_eq!(pieces.last().unwrap().end(), c.end(), "end moved");
        for w in pieces.windows(2) {
            assert_eq!(w[0].end(), w[1].start(), "gap between pieces");
        }
        // Measured on polylines within tol/100 of the curves.
        let err = max_distance_to_cubic(&pieces, c, tol / 100.0);
        assert!(
            err <= tol * 1.02,
            "error {err} over tolerance {tol} with {} pieces",
            pieces.len()
        );
        pieces
    }

    #[test]
    fn hard_cubics_stay_within_tolerance() {
        let cases = [
            (
                "cusp",
                cubic([(0.0, 0.0), (1000.0, 1000.0), (0.0, 1000.0), (1000.0, 0.0)]),
            ),
            (
                "loop",
                cubic([
                    (0.0, 0.0),
                    (1500.0, 1000.0),
                    (-500.0, 1000.0),
                    (1000.0, 0.0),
                ]),
            ),
            (
                "inflection",
                cubic([(0.0, 0.0), (400.0, 800.0), (600.0, -800.0), (1000.0, 0.0)]),
            ),
            (
                "arc",
                cubic([(0.0, 0.0), (0.0, 552.0), (448.0, 1000.0), (1000.0, 1000.0)]),
            ),
            (
                "tiny",
                cubic([(0.0, 0.0), (0.1, 0.2), (0.2, -0.1), (0.3, 0.0)]),
            ),
        ];
        for tol in [1.0, 0.1, 0.01] {
            for (name, c) in &cases {
                let n = check(c, tol).len();
                assert!(n < 200, "{name}: {n} pieces at tolerance {tol}");
            }
        }
    }

    #[test]
    fn collinear_cubics_become_lines_not_deep_recursion() {
        // Inner points on the chord, unevenly spaced (nonzero third difference).
        let c = cubic([(0.0, 0.0), (100.0, 100.0), (150.0, 150.0), (1000.0, 1000.0)]);
        assert_eq!(check(&c, 0.01), vec![Segment::Line(c.start(), c.end())]);
        // Degenerate: control points on the endpoints.
        let c = cubic([(0.0, 0.0), (0.0, 0.0), (500.0, 0.0), (500.0, 0.0)]);
        assert_eq!(check(&c, 0.01).len(), 1);
        // All four points equal.
        let c = cubic([(7.0, 7.0); 4]);
        assert_eq!(convert(&c, 0.01), vec![Segment::Line(c.start(), c.end())]);
    }

    #[test]
    fn collinear_cubic_that_doubles_back_keeps_its_overshoot() {
        // Collinear, but the curve runs past its end and returns: a line would cut the
        // overshoot off, so it must go through the bounded split instead.
        let c = cubic([(0.0, 0.0), (2000.0, 0.0), (2000.0, 0.0), (1000.0, 0.0)]);
        let pieces = check(&c, 0.01);
        assert!(pieces.len() > 1 && pieces.len() < 200);
    }

    #[test]
    fn latin_modern_cubics_at_the_default_tolerance() {
        let font = crate::font::Font::shipped(1);
        let tol = DEFAULT_QUAD_TOLERANCE_EM * font.units_per_em();
        let mut checked = 0;
        for c in "&Qag§".chars() {
            let outline = font.outline(font.glyph_for_char(c).unwrap());
            for s in outline
                .segments()
                .filter(|s| matches!(s, Segment::Cubic(..)))
            {
                let pieces = convert(s, tol);
                let err = max_distance_to_cubic(&pieces, s, tol / 20.0);
                assert!(err <= tol * 1.1, "{c:?}: {err} over {tol}");
                checked += 1;
            }
        }
        assert!(checked > 50, "only {checked} cubics");
    }

    #[test]
    fn piece_count_follows_the_closed_form_bound() {
        let c = cubic([(0.0, 0.0), (400.0, 800.0), (600.0, -800.0), (1000.0, 0.0)]);
        let coarse = convert(&c, 1.0).len();
        let fine = convert(&c, 1.0 / 8.0).len();
        // n ∝ tolerance^(-1/3): 8x tighter needs about twice the pieces.
        assert!(
            (fine as f64 / coarse as f64 - 2.0).abs() < 0.5,
            "{coarse} -> {fine}"
        );
    }
}
