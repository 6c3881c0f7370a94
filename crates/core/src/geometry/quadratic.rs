//! The quadratic Bézier ([`Quad`]) and its math, in f64: evaluation and pieces by
//! blossoming, where x or y turns, the parameter at a value, the integrals a closed
//! chain of them encloses, and the winding number they make around a point.
//!
//! `crates/text/shaders/winding_area.wgsl` has the f32 twins of [`blossom_value`], [`point_at`],
//! [`subcurve`], [`monomial`], [`t_at`] and [`integral_x_dy`], under the same names:
//! `winding`'s CPU mirror of that shader (`methods/winding/area.rs`) calls these.

use glam::DVec2;

/// A quadratic Bézier: start, control, end.
pub type Quad = [DVec2; 3];

/// The quadratic that runs along the segment from `a` to `b` at constant speed: its
/// control point is the midpoint, exact in f64 (a sum and a halving).
pub fn line_as_quad(a: DVec2, b: DVec2) -> Quad {
    [a, (a + b) * 0.5, b]
}

/// A quadratic's blossom at (a, b), for one coordinate (control values `c`): its value
/// at t when a = b = t, the middle control value of its piece between a and b.
pub fn blossom_value(c: [f64; 3], a: f64, b: f64) -> f64 {
    c[0] * ((1.0 - a) * (1.0 - b)) + c[1] * ((1.0 - a) * b + a * (1.0 - b)) + c[2] * (a * b)
}

/// The curve's blossom at (a, b), both coordinates.
fn blossom(c: Quad, a: f64, b: f64) -> DVec2 {
    DVec2::new(
        blossom_value(c.map(|p| p.x), a, b),
        blossom_value(c.map(|p| p.y), a, b),
    )
}

/// The curve at t.
pub fn point_at(c: Quad, t: f64) -> DVec2 {
    blossom(c, t, t)
}

/// The piece of `c` between parameters `a` and `b`, as a quadratic Bézier of its own.
pub fn subcurve(c: Quad, a: f64, b: f64) -> Quad {
    [blossom(c, a, a), blossom(c, a, b), blossom(c, b, b)]
}

/// How far a quadratic strays from its chord: the largest distance from a point of
/// the curve to the segment between its ends, at most |p0 − 2·p1 + p2| / 4 (reached at
/// t = ½ for the distance to the chord's line; the bound also covers the segment).
pub fn chord_deviation(c: Quad) -> f64 {
    (c[0] - 2.0 * c[1] + c[2]).length() / 4.0
}

/// `c` halved (at t = ½, by blossoming) until every piece keeps within `tolerance` of
/// its chord ([`chord_deviation`]), the pieces handed to `out` in order. Each halving
/// quarters the deviation, so a curve takes 2^⌈log₄(deviation / tolerance)⌉ pieces.
pub fn halved_until_flat(c: Quad, tolerance: f64, out: &mut impl FnMut(Quad)) {
    // A tolerance of 0, or one below what f64 resolves at the curve's size, would halve
    // forever: 2^16 pieces at most.
    fn halve(c: Quad, tolerance: f64, depth: u32, out: &mut impl FnMut(Quad)) {
        let deviation = chord_deviation(c);
        if depth >= 16 || deviation <= tolerance || deviation.is_nan() {
            out(c);
            return;
        }
        halve(subcurve(c, 0.0, 0.5), tolerance, depth + 1, out);
        halve(subcurve(c, 0.5, 1.0), tolerance, depth + 1, out);
    }
    halve(c, tolerance, 0, out);
}

/// Monomial coefficients (t², t, 1) of a quadratic given by its control values.
pub fn monomial(c: [f64; 3]) -> [f64; 3] {
    [c[0] - 2.0 * c[1] + c[2], 2.0 * (c[1] - c[0]), c[0]]
}

/// Where a quadratic (control values) turns, or 1 when it does not inside (0, 1).
fn turn_at(c: [f64; 3]) -> f64 {
    let denominator = c[0] - 2.0 * c[1] + c[2];
    if denominator == 0.0 {
        return 1.0;
    }
    let t = (c[0] - c[1]) / denominator;
    if t > 0.0 && t < 1.0 { t } else { 1.0 }
}

/// The curve split where x or y turns: up to three pieces, each monotone in both.
/// `winding`'s preparation splits every curve so (`aa=area`'s shader takes them
/// monotone).
pub fn monotone_pieces(c: Quad) -> [Option<Quad>; 3] {
    let (tx, ty) = (turn_at(c.map(|p| p.x)), turn_at(c.map(|p| p.y)));
    let (t1, t2) = (tx.min(ty), tx.max(ty));
    let piece = |a: f64, b: f64| (b > a).then(|| subcurve(c, a, b));
    [piece(0.0, t1), piece(t1, t2), piece(t2, 1.0)]
}

/// The parameter in [0, 1] where a quadratic monotone on [0, 1] (control values `c`)
/// takes `value`: 0 or 1 when it stays on one side. The stable form of the
/// quadratic formula, which stays finite as the quadratic degenerates to a line.
pub fn t_at(c: [f64; 3], value: f64) -> f64 {
    let increasing = c[2] >= c[0];
    let (low, high) = if increasing {
        (c[0], c[2])
    } else {
        (c[2], c[0])
    };
    if value <= low {
        return if increasing { 0.0 } else { 1.0 };
    }
    if value >= high {
        return if increasing { 1.0 } else { 0.0 };
    }
    let a = c[0] - 2.0 * c[1] + c[2];
    let b = 2.0 * (c[1] - c[0]);
    let k = c[0] - value;
    let root = (b * b - 4.0 * a * k).max(0.0).sqrt();
    let denominator = b + if increasing { root } else { -root };
    if denominator == 0.0 {
        // Only when rounding has flattened the piece: its chord's answer.
        return ((value - c[0]) / (c[2] - c[0])).clamp(0.0, 1.0);
    }
    (-2.0 * k / denominator).clamp(0.0, 1.0)
}

/// ∫₀¹ x(t) y′(t) dt for a quadratic Bézier given by its control values: exact (the
/// integrand is a cubic in t).
pub fn integral_x_dy(x: [f64; 3], y: [f64; 3]) -> f64 {
    let d0 = y[1] - y[0];
    let d1 = y[2] - y[1];
    (x[0] * (3.0 * d0 + d1) + 2.0 * x[1] * (d0 + d1) + x[2] * (d0 + 3.0 * d1)) / 6.0
}

/// Signed area enclosed by a closed chain of quadratics (positive counter-clockwise,
/// y up): the polygon of their endpoints plus, for each, the parabolic segment between
/// the curve and its chord, 2/3 of its control triangle.
pub fn signed_area(contour: &[Quad]) -> f64 {
    contour
        .iter()
        .map(|[a, b, c]| 0.5 * a.perp_dot(*c) + (b - a).perp_dot(c - a) / 3.0)
        .sum()
}

/// The winding number of closed chains of quadratics around `point`: the signed
/// crossings of the ray from it towards +x, +1 where a curve crosses upwards (the inside
/// of a counter-clockwise contour is on its left), −1 downwards. Half-open in y (a point
/// counts as above the ray when y > point.y), so a crossing at a join of two curves
/// counts once. A point on a curve gets the number of one of its sides.
pub fn winding_number<'a>(point: DVec2, curves: impl IntoIterator<Item = &'a Quad>) -> i32 {
    curves.into_iter().map(|q| ray_crossings(q, point)).sum()
}

/// One curve's signed crossings of the ray from `p` towards +x (see [`winding_number`]),
/// in f64: the curve is split at its y extremum into monotonic pieces, each crossing
/// found by bisection.
fn ray_crossings(q: &Quad, p: DVec2) -> i32 {
    let [a, b, c] = q.map(|v| v - p);
    if a.x.max(b.x).max(c.x) <= 0.0 {
        return 0;
    }
    let at = |t: f64| a * (1.0 - t) * (1.0 - t) + b * 2.0 * t * (1.0 - t) + c * t * t;
    let split = turn_at([a.y, b.y, c.y]);
    let mut w = 0;
    for (t0, t1) in [(0.0, split), (split, 1.0)] {
        let (above0, above1) = (at(t0).y > 0.0, at(t1).y > 0.0);
        if t0 == t1 || above0 == above1 {
            continue;
        }
        let (mut low, mut high) = (t0, t1);
        for _ in 0..60 {
            let mid = 0.5 * (low + high);
            if (at(mid).y > 0.0) == above0 {
                low = mid;
            } else {
                high = mid;
            }
        }
        if at(0.5 * (low + high)).x > 0.0 {
            w += if above1 { 1 } else { -1 };
        }
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> Quad {
        [DVec2::from(a), DVec2::from(b), DVec2::from(c)]
    }

    /// The arch (0,0)–(1,2)–(2,0): x(t) = 2t, y(t) = 4t(1 − t).
    fn arch() -> Quad {
        q((0.0, 0.0), (1.0, 2.0), (2.0, 0.0))
    }

    #[test]
    fn a_curve_is_halved_until_each_piece_keeps_to_its_chord() {
        // The arch strays |p0 − 2p1 + p2| / 4 = |(0, −4)| / 4 = 1 from its chord, at
        // t = ½ (its top, (1, 1), over the chord's midpoint (1, 0)).
        assert_eq!(chord_deviation(arch()), 1.0);
        // Each halving quarters it: 1/4 after one, 1/16 after two. Within 0.3: two
        // pieces; within 0.1: four, ending at t = ¼, ½, ¾: (0.5, 0.75), (1, 1), (1.5, 0.75).
        let pieces = |tolerance: f64| {
            let mut out = Vec::new();
            halved_until_flat(arch(), tolerance, &mut |p| out.push(p));
            out
        };
        assert_eq!(pieces(0.3).len(), 2);
        let four = pieces(0.1);
        let ends: Vec<DVec2> = four.iter().map(|p| p[2]).collect();
        assert_eq!(
            ends,
            [(0.5, 0.75), (1.0, 1.0), (1.5, 0.75), (2.0, 0.0)].map(DVec2::from)
        );
        assert_eq!(four[0][0], DVec2::ZERO);
        for pair in four.windows(2) {
            assert_eq!(pair[0][2], pair[1][0], "the pieces chain");
        }
        assert!(four.iter().all(|p| chord_deviation(*p) == 1.0 / 16.0));
        // Flat already: kept whole; a curve that no tolerance reaches stops at 2^16.
        assert_eq!(pieces(1.0).len(), 1);
        assert_eq!(pieces(0.0).len(), 1 << 16);
    }

    #[test]
    fn points_and_pieces_by_blossoming() {
        assert_eq!(point_at(arch(), 0.25), DVec2::new(0.5, 0.75));
        assert_eq!(point_at(arch(), 0.5), DVec2::new(1.0, 1.0));
        // The blossom at (0, 1) is the control point; at (t, t) the point at t.
        assert_eq!(blossom_value([0.0, 2.0, 0.0], 0.0, 1.0), 2.0);
        assert_eq!(blossom_value([0.0, 2.0, 0.0], 0.5, 0.5), 1.0);
        // The left half: from the start, through the midpoint of the first leg, to the
        // apex (de Casteljau by hand).
        assert_eq!(
            subcurve(arch(), 0.0, 0.5),
            q((0.0, 0.0), (0.5, 1.0), (1.0, 1.0))
        );
        // A piece runs along the curve: at s it is the curve at a + s (b − a).
        let piece = subcurve(arch(), 0.2, 0.6);
        for s in [0.0, 0.25, 0.5, 1.0] {
            let t = 0.2 + s * 0.4;
            let want = DVec2::new(2.0 * t, 4.0 * t * (1.0 - t));
            assert!((point_at(piece, s) - want).length() < 1e-15, "s {s}");
        }
    }

    #[test]
    fn monomials_expand_the_bernstein_form() {
        // (1 − t)² + 2·2t(1 − t) + 4t² = 1 + 2t + t².
        assert_eq!(monomial([1.0, 2.0, 4.0]), [1.0, 2.0, 1.0]);
    }

    #[test]
    fn a_line_as_a_quadratic() {
        let line = line_as_quad(DVec2::new(1.0, 2.0), DVec2::new(3.0, -4.0));
        assert_eq!(line, q((1.0, 2.0), (2.0, -1.0), (3.0, -4.0)));
    }

    /// (0,0)–(2,−1)–(1,2): x(t) = 4t − 3t² turns at t = 2/3 (x = 4/3, y = 4/9), y(t) =
    /// 4t² − 2t at t = 1/4 (x = 13/16, y = −1/4).
    #[test]
    fn monotone_pieces_split_where_x_and_y_turn() {
        let c = q((0.0, 0.0), (2.0, -1.0), (1.0, 2.0));
        let pieces: Vec<Quad> = monotone_pieces(c).into_iter().flatten().collect();
        let ends = [
            DVec2::ZERO,
            DVec2::new(13.0 / 16.0, -0.25),
            DVec2::new(4.0 / 3.0, 4.0 / 9.0),
            DVec2::new(1.0, 2.0),
        ];
        assert_eq!(pieces.len(), 3);
        for (k, piece) in pieces.iter().enumerate() {
            assert!((piece[0] - ends[k]).length() < 1e-15, "piece {k} starts");
            assert!((piece[2] - ends[k + 1]).length() < 1e-15, "piece {k} ends");
            // Within rounding: at a turn the middle control value meets the end's.
            let slack = 1e-15;
            for values in [piece.map(|p| p.x), piece.map(|p| p.y)] {
                let rising = values[0] <= values[1] + slack && values[1] <= values[2] + slack;
                let falling = values[0] + slack >= values[1] && values[1] + slack >= values[2];
                assert!(rising || falling, "piece {k}: {values:?}");
            }
        }
        // Monotone already: one piece, the curve itself.
        let monotone = q((0.0, 0.0), (1.0, 0.5), (2.0, 3.0));
        assert_eq!(monotone_pieces(monotone), [Some(monotone), None, None]);
    }

    #[test]
    fn roots_of_monotone_pieces() {
        // A line from 1 to 3: 2 at the middle.
        assert_eq!(t_at([1.0, 2.0, 3.0], 2.0), 0.5);
        // x(t) = t² (0, 0, 1): √0.25 = 0.5; decreasing (1, 1, 0): 1 − t²… at 0.75 → 0.5.
        assert!((t_at([0.0, 0.0, 1.0], 0.25) - 0.5).abs() < 1e-15);
        assert!((t_at([1.0, 1.0, 0.0], 0.75) - 0.5).abs() < 1e-15);
        // Outside the range: the end on that side.
        assert_eq!(t_at([0.0, 0.5, 1.0], -1.0), 0.0);
        assert_eq!(t_at([1.0, 0.5, 0.0], -1.0), 1.0);
    }

    #[test]
    fn integral_of_x_along_y() {
        // x = t, y = t²: ∫ t · 2t dt = 2/3.
        assert!((integral_x_dy([0.0, 0.5, 1.0], [0.0, 0.0, 1.0]) - 2.0 / 3.0).abs() < 1e-15);
        // x constant: the rise times x.
        assert_eq!(integral_x_dy([3.0, 3.0, 3.0], [1.0, 5.0, 2.0]), 3.0);
    }

    #[test]
    fn parabola_area_is_two_thirds_of_its_triangle() {
        // y = x(2 - x)·… : the chord (0,0)-(2,0) and control (1,2) enclose 4/3.
        let back = q((2.0, 0.0), (1.0, 0.0), (0.0, 0.0));
        assert!((signed_area(&[arch(), back]) + 4.0 / 3.0).abs() < 1e-12);
    }

    /// The square (x, y)–(x + size, y + size), its sides as quadratics, counter-clockwise
    /// unless `clockwise`.
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

    #[test]
    fn winding_counts_each_crossing_once() {
        let contour = square(0.0, 0.0, 10.0, false);
        assert_eq!(winding_number(DVec2::new(5.0, 5.0), &contour), 1);
        assert_eq!(
            winding_number(DVec2::new(5.0, 5.0), &square(0.0, 0.0, 10.0, true)),
            -1
        );
        // Level with the bottom side's ends: the vertex at (10, 0) counts once.
        assert_eq!(winding_number(DVec2::new(5.0, 0.0), &contour), 1);
        assert_eq!(winding_number(DVec2::new(15.0, 5.0), &contour), 0);
        // Inside two squares, one in the other, wound the same way; inside a ring.
        let stacked = [contour.clone(), square(2.0, 2.0, 6.0, false)].concat();
        assert_eq!(winding_number(DVec2::new(5.0, 5.0), &stacked), 2);
        let ring = [contour.clone(), square(2.0, 2.0, 6.0, true)].concat();
        assert_eq!(winding_number(DVec2::new(5.0, 5.0), &ring), 0);
        assert_eq!(winding_number(DVec2::new(1.0, 5.0), &ring), 1);
        // A curved side: the parabola (0,0)–(5,10)–(10,0) peaks at y = 5.
        let arch = [
            q((0.0, 0.0), (5.0, 10.0), (10.0, 0.0)),
            q((10.0, 0.0), (5.0, 0.0), (0.0, 0.0)),
        ];
        assert_eq!(winding_number(DVec2::new(5.0, 4.9), &arch), -1);
        assert_eq!(winding_number(DVec2::new(5.0, 5.1), &arch), 0);
    }

    #[test]
    fn ray_crossings_count_each_way_once_at_joins() {
        let p = DVec2::ZERO;
        // Upwards right of p: +1; downwards: −1; left of p: nothing.
        assert_eq!(ray_crossings(&q((1.0, -1.0), (2.0, 0.0), (1.0, 1.0)), p), 1);
        assert_eq!(
            ray_crossings(&q((1.0, 1.0), (2.0, 0.0), (1.0, -1.0)), p),
            -1
        );
        assert_eq!(
            ray_crossings(&q((-1.0, -1.0), (-2.0, 0.0), (-1.0, 1.0)), p),
            0
        );
        // A parabola dipping through the ray twice, and one only touching it.
        assert_eq!(ray_crossings(&q((1.0, 1.0), (2.0, -2.0), (3.0, 1.0)), p), 0);
        assert_eq!(ray_crossings(&q((1.0, 1.0), (2.0, -1.0), (3.0, 1.0)), p), 0);
        // Two lines joined on the ray, going up: one crossing between them.
        let below = q((1.0, -1.0), (1.0, -0.5), (1.0, 0.0));
        let above = q((1.0, 0.0), (1.0, 0.5), (1.0, 1.0));
        assert_eq!(ray_crossings(&below, p) + ray_crossings(&above, p), 1);
        // A crossing left of p on a curve that reaches right of it does not count.
        assert_eq!(
            ray_crossings(&q((-1.0, -1.0), (3.0, 0.0), (-1.0, 1.0)), p),
            1
        );
        assert_eq!(
            ray_crossings(&q((-1.0, -1.0), (0.0, 0.0), (-1.0, 1.0)), p),
            0
        );
    }
}
