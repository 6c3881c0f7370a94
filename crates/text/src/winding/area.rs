//! `aa=area`: the exact box-filter coverage of one pixel, in f64 — the CPU mirror of
//! `crates/text/shaders/winding_area.wgsl`, function for function, so that the shader's
//! formulation is checked here against closed forms. [`pixel_winding`] is the shader's
//! `area_winding` over every curve (no bands), and [`curve_term`] the zone test in its
//! loop; [`PixelFrame`] is `pixel_frame` and `frame_map`, [`zone`] `area_zone`; the
//! rest keep their names. [`fill`] is `fill` in `crates/text/shaders/winding.wgsl`. The shader's
//! `area_pixel` (fill(F), or the mean over a grid of sub-pixels where contours overlap)
//! has no mirror here, nor its `AXIS` draws' rounding of the pixel's steps to the axes;
//! `stretch` and `right_of` here are steps the shader writes inline, and the frame's
//! constants for `area_below` (`width`, `rise`, `growth`) it computes once a pixel.
//! The quadratic's own helpers the shader has (`blossom_value`, `point_at`, `subcurve`,
//! `monomial`, `t_at`, `integral_x_dy`) are [`crate::geometry`]'s, under the same names.
//!
//! # The integral
//!
//! The pixel-averaged winding number over a region P is, by Green's theorem,
//!
//! ```text
//! F = (1/|P|) ∬_P w dA = (1/|P|) Σ_curves ∫ G(x(t), y(t)) y′(t) dt,
//! G(x, y) = length of the horizontal chord of P at height y left of x,
//! ```
//!
//! since ∂G/∂x is P's indicator. Each curve contributes on its own; a curve below or
//! above P contributes nothing (G = 0), one wholly left of P nothing either, one wholly
//! right of P the area of P between its end heights. That is what lets bands with an
//! early exit pick the curves: a glyph's bands are horizontal in its local coordinates.
//!
//! P is the pixel square taken back into local coordinates by the Jacobian at the
//! pixel: a parallelogram. The frame the integral runs in keeps the local axes (x
//! mirrored when the walk goes towards −x) and scales them so that |P| = 1: horizontal
//! lines stay horizontal, for the bands, and a curve monotone in x stays monotone in u.
//! P's corners are ±b (the lowest and the highest) and ±m; its boundary runs from the
//! bottom corner b to the top one −b through one of ±m on the left and the other on the
//! right, so the chord at height v is [lo(v), hi(v)] with lo and hi each two segments,
//! and
//!
//! ```text
//! G(u, v) = ramp(u − lo(v)) − ramp(u − hi(v)),   ramp(x) = max(x, 0),
//! ```
//!
//! for v between the bottom and top corners. Under a rotation, skew or mirror this is
//! exact; under a perspective tilt the Jacobian is the homography's linearisation at
//! the pixel. Every curve is split where x or y turns when the glyph is prepared
//! ([`monotone_pieces`]), so u and v are monotone along it and it meets P's bounding box
//! in one stretch. In the frame:
//!
//! - right of P's columns (u ≥ `reach`) G is the whole chord, so that part of the curve
//!   adds `area_below(v_end) − area_below(v_start)`;
//! - left of them G = 0;
//! - the stretch within P's bounding box, cut out of the curve (blossoming) so that
//!   every value in it is within a pixel or so of P, adds four ramp integrals, one per
//!   segment of lo and hi, each over that segment's heights (`edge_ramp`): ℓ = u −
//!   edge(v) is a quadratic in t whose roots cut the heights' stretch into parts of one
//!   sign, and ∫ ℓ v′ dt over each is a cubic's antiderivative (`ramp_over`).
//!
//! Where P's axes are the image's (no rotation, skew or tilt), P is a rectangle and the
//! stretch within it is integrated at once ([`across_axis`], the shader's `AXIS`
//! variant): the same integral, fewer terms. Where P's steps lean apart (the shader's
//! `SQUARE` variant), a curve across P is integrated in P's own square frame and
//! corrected back to this frame's form at its ends ([`across_square`]).
//!
//! Coverage is `fill(F)`: min(|F|, 1) for nonzero, a triangle wave for even-odd — exact
//! wherever the winding inside the pixel takes two adjacent values, which every pixel
//! of a glyph without overlapping contours does.

use glam::DVec2;

use crate::geometry::{
    Quad, blossom_value, integral_x_dy, monomial, monotone_pieces, point_at, subcurve, t_at,
};

/// The frame one pixel is integrated in: local offsets from the pixel's centre,
/// mirrored to the band direction and scaled so that the pixel P has area 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelFrame {
    /// ±1: local x is mirrored when the bands are walked towards −x.
    direction: f64,
    /// u = direction · x · scale, v = y · scale.
    scale: f64,
    /// P's lowest corner (the highest is its opposite).
    pub bottom: DVec2,
    /// The corner the left side of P passes through from the bottom corner to the top
    /// one (the right side passes through its opposite).
    pub left: DVec2,
    /// P spans u in [−reach, reach].
    pub reach: f64,
    /// P's own coordinates α = alpha_of·q, β = beta_of·q of a point q of this frame, in
    /// which P is the square |α|, |β| ≤ ½: α along P's shallower step (pointing right),
    /// β along its steeper one (pointing up), so that α grows along every row.
    alpha_of: DVec2,
    beta_of: DVec2,
    /// Whether P's steps lean apart ([`steps_lean_apart`](crate::geometry::steps_lean_apart)):
    /// the shader's `SQUARE` draws, which integrate a curve across P in the square frame.
    pub square: bool,
}

impl PixelFrame {
    /// The frame of the pixel whose one-pixel steps along image x and y are the local
    /// offsets `jx` and `jy`, walked towards `direction` (±1) along local x. None for a
    /// pixel that covers no area.
    pub fn new(jx: DVec2, jy: DVec2, direction: f64) -> Option<PixelFrame> {
        let mirror = |v: DVec2| DVec2::new(direction * v.x, v.y);
        let (jx, jy) = (mirror(jx), mirror(jy));
        let det = jx.perp_dot(jy).abs();
        if det.is_nan() || det == 0.0 {
            return None;
        }
        let scale = 1.0 / det.sqrt();
        let (a, b) = (0.5 * scale * jx, 0.5 * scale * jy);
        // Both half-steps taken downwards reach the lowest corner; one of them upwards,
        // a middle one. Of that one and its opposite, the one left of the diagonal from
        // the bottom corner to the top one (through the centre) is on the left side.
        let down = |v: DVec2| if v.y > 0.0 { -v } else { v };
        let bottom = down(a) + down(b);
        let middle = down(a) - down(b);
        let left = if middle.x * bottom.y > middle.y * bottom.x {
            middle
        } else {
            -middle
        };
        // The steeper step pointing up and the other pointing right span P with a
        // positive determinant, 1 (the scale): the square frame's axes, whose inverse is
        // their adjugate.
        let (up, right) = if (b.y * a.x).abs() >= (a.y * b.x).abs() {
            (2.0 * b, 2.0 * a)
        } else {
            (2.0 * a, 2.0 * b)
        };
        let up = if up.y < 0.0 { -up } else { up };
        let right = if right.x < 0.0 { -right } else { right };
        Some(PixelFrame {
            direction,
            scale,
            bottom,
            left,
            reach: bottom.x.abs().max(middle.x.abs()),
            alpha_of: DVec2::new(up.y, -up.x),
            beta_of: DVec2::new(-right.y, right.x),
            square: jx.x * jx.y * jy.x * jy.y <= 0.0,
        })
    }

    /// A local offset from the pixel's centre in this frame.
    pub fn map(&self, offset: DVec2) -> DVec2 {
        DVec2::new(self.direction * offset.x, offset.y) * self.scale
    }

    /// Whether P is a rectangle (its axes the frame's): the shader's `AXIS` variant.
    pub fn is_rectangle(&self) -> bool {
        self.left.y == self.bottom.y || self.left.y == -self.bottom.y
    }
}

/// Area of P below height `v`: its chord grows from 0 at the bottom corner to its full
/// width at the lower middle corner, stays there up to the higher one, and shrinks to 0
/// at the top.
pub fn area_below(v: f64, f: &PixelFrame) -> f64 {
    let low = f.bottom.y;
    let middle = f.left.y.abs();
    let width = 1.0 / (middle - low);
    // The height over which the chord grows (and shrinks).
    let rise = -(middle + low);
    if v <= low {
        0.0
    } else if v >= -low {
        1.0
    } else if v < -middle {
        // Only reached when rise > 0.
        0.5 * width * (v - low) * (v - low) / rise
    } else if v > middle {
        1.0 - 0.5 * width * (v + low) * (v + low) / rise
    } else {
        width * (v + middle + 0.5 * rise)
    }
}

/// The pixel-averaged winding number F of the pixel centred on local point `centre`
/// (steps `jx`, `jy`), over every curve of a glyph: every curve is visited, no bands;
/// each is first split where x or y turns, as the glyph's preparation does.
pub fn pixel_winding(curves: &[Quad], centre: DVec2, jx: DVec2, jy: DVec2) -> f64 {
    let Some(frame) = PixelFrame::new(jx, jy, 1.0) else {
        return 0.0;
    };
    curves
        .iter()
        .flat_map(|&c| monotone_pieces(c).into_iter().flatten())
        .map(|c| curve_term(c.map(|p| frame.map(p - centre)), &frame))
        .sum()
}

/// Coverage of a pixel-averaged winding number under the fill rule.
pub fn fill(winding: f64, even_odd: bool) -> f64 {
    let w = winding.abs();
    if even_odd {
        // Distance to the nearest even number: 0 → 0, 1 → 1, 2 → 0.
        (w - 2.0 * (0.5 * w).round()).abs()
    } else {
        w.min(1.0)
    }
}

/// Where one curve (in a pixel frame) lies against P: what decides its term.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Zone {
    /// Wholly below or above P's heights, or wholly left of P: no term.
    Outside,
    /// Wholly right of P: P's area between its end heights.
    Right,
    /// Its bounds meet P's bounding box: the full integral.
    Across,
}

/// The zone of a curve's control points (a curve lies within their hull).
pub fn zone(c: &Quad, f: &PixelFrame) -> Zone {
    let min = c[0].min(c[1]).min(c[2]);
    let max = c[0].max(c[1]).max(c[2]);
    if max.y <= f.bottom.y || min.y >= -f.bottom.y || max.x <= -f.reach {
        Zone::Outside
    } else if min.x >= f.reach {
        Zone::Right
    } else {
        Zone::Across
    }
}

/// ∫ G dv along one curve monotone in u and v, in a pixel frame.
pub fn curve_term(c: Quad, f: &PixelFrame) -> f64 {
    match zone(&c, f) {
        Zone::Outside => 0.0,
        Zone::Right => area_below(c[2].y, f) - area_below(c[0].y, f),
        Zone::Across if f.square && !f.is_rectangle() => across_square(c, f),
        Zone::Across => across_term(c, f),
    }
}

/// The stretch where a monotone quadratic (control values) runs from `low` to `high`:
/// its parameters there, in order along the curve.
fn stretch(c: [f64; 3], low: f64, high: f64) -> (f64, f64) {
    let (a, b) = (t_at(c, low), t_at(c, high));
    (a.min(b), a.max(b))
}

/// Where u runs past P's right side, along a curve monotone in u: the parameters.
fn right_of(u: [f64; 3], reach: f64) -> (f64, f64) {
    let t = t_at(u, reach);
    if u[2] >= u[0] { (t, 1.0) } else { (0.0, t) }
}

/// ∫ G dv along a curve across P when P is a rectangle ([`PixelFrame::is_rectangle`]):
/// G is u − left inside its columns, their width right of them, 0 left. A curve
/// monotone in u and v meets the rectangle in one stretch, [the later entry, the
/// earlier exit]; right of it, it adds the width times the height it climbs within the
/// rows.
pub fn across_axis(c: Quad, f: &PixelFrame) -> f64 {
    let (u, v) = (c.map(|p| p.x), c.map(|p| p.y));
    let (left, low) = (-f.reach, f.bottom.y);
    let rows = stretch(v, low, -low);
    let columns = stretch(u, left, -left);
    let enter = rows.0.max(columns.0);
    let inside = subcurve(c, enter, enter.max(rows.1.min(columns.1)));
    let (from, to) = right_of(u, f.reach);
    let climbed = point_at(c, to).y.clamp(low, -low) - point_at(c, from).y.clamp(low, -low);
    integral_x_dy(inside.map(|p| p.x - left), inside.map(|p| p.y)) - 2.0 * left * climbed
}

/// ∫ G dv along a curve across P: right of P's columns P's area between heights, and
/// the stretch within P's bounding box, cut out first so that u and v stay within a
/// pixel, as four ramps, one per segment of P's left and right sides.
pub fn across_term(c: Quad, f: &PixelFrame) -> f64 {
    let (u, v) = (c.map(|p| p.x), c.map(|p| p.y));
    let low = f.bottom.y;
    let columns = stretch(u, -f.reach, f.reach);
    let rows = stretch(v, low, -low);
    let (from, to) = right_of(u, f.reach);
    let right = area_below(point_at(c, to).y, f) - area_below(point_at(c, from).y, f);
    let enter = columns.0.max(rows.0);
    let piece = subcurve(c, enter, enter.max(columns.1.min(rows.1)));
    let pv = piece.map(|p| p.y);
    // The parameters on the piece where v is at the corners' heights (the piece lies
    // between the bottom and top heights).
    let rising = pv[2] >= pv[0];
    let t = [
        if rising { 0.0 } else { 1.0 },
        t_at(pv, f.left.y),
        t_at(pv, -f.left.y),
        if rising { 1.0 } else { 0.0 },
    ];
    let (pu, pv) = (monomial(piece.map(|p| p.x)), monomial(pv));
    let (bottom, top, left, right_corner) = (f.bottom, -f.bottom, f.left, -f.left);
    right + edge_ramp(pu, pv, bottom, left, t[0], t[1]) + edge_ramp(pu, pv, left, top, t[1], t[3])
        - edge_ramp(pu, pv, bottom, right_corner, t[0], t[2])
        - edge_ramp(pu, pv, right_corner, top, t[2], t[3])
}

/// ∫ ramp(u − edge(v)) v′ dt over the heights of P's side from corner `p` up to corner
/// `q`, along the piece (monomials `u`, `v`) whose parameters at those heights are `tp`
/// and `tq`. ℓ is taken scaled by a = rise / max(|run|, rise) (ramp(a·ℓ) = a·ramp(ℓ)),
/// so that no coordinate is multiplied by more than 1 however near level the side is.
fn edge_ramp(u: [f64; 3], v: [f64; 3], p: DVec2, q: DVec2, tp: f64, tq: f64) -> f64 {
    let (run, rise) = (q.x - p.x, q.y - p.y);
    if rise.is_nan() || rise <= 0.0 {
        // A level side spans no height.
        return 0.0;
    }
    let a = rise / run.abs().max(rise);
    let b = run / run.abs().max(rise);
    ramp_over(
        u.map(|c| a * c),
        v,
        b,
        a * p.x - b * p.y,
        tp.min(tq),
        tp.max(tq),
    ) / a
}

/// ∫ ramp(ℓ) v′ dt over t in [t0, t1], ℓ = u − k·v − offset, for a piece given by the
/// monomial coefficients (t², t, 1) of u and v; taken about t0, so that nothing
/// outside [t0, t1] enters the sums. ℓ's roots cut the stretch in three parts, each of
/// one sign; each positive part adds its cubic's antiderivative.
fn ramp_over(u: [f64; 3], v: [f64; 3], k: f64, offset: f64, t0: f64, t1: f64) -> f64 {
    let m = [0, 1, 2].map(|i| u[i] - k * v[i]);
    // ℓ(t0 + τ) and v′(t0 + τ) as polynomials in τ.
    let l = [
        m[0],
        2.0 * m[0] * t0 + m[1],
        (m[0] * t0 + m[1]) * t0 + m[2] - offset,
    ];
    let (d, e) = (2.0 * v[0], 2.0 * v[0] * t0 + v[1]);
    let span = t1 - t0;
    // Past the stretch for a root that does not exist.
    let [r0, r1] = quadratic_roots(l).map(|r| r.unwrap_or(span));
    let cuts = [
        0.0,
        r0.min(r1).clamp(0.0, span),
        r0.max(r1).clamp(0.0, span),
        span,
    ];
    let antiderivative = product_antiderivative(l, d, e);
    cuts.windows(2)
        .map(|w| {
            let mid = 0.5 * (w[0] + w[1]);
            let value = (l[0] * mid + l[1]) * mid + l[2];
            if value > 0.0 {
                antiderivative(w[1]) - antiderivative(w[0])
            } else {
                0.0
            }
        })
        .sum()
}

/// ∫ G dv along a curve across P, in P's square frame, where P's steps lean apart.
/// Two 1-forms have P's indicator as their derivative: ω_rows = G dv, the one the bands
/// need (it vanishes off P's rows and left of P), and ω_square = c(α) c′(β) dβ with c(x)
/// = clamp(x + ½, 0, 1), P's own. Their difference is closed, so exact: dψ
/// (`rows_correction`), and a curve adds ∫ ω_square + ψ(end) − ψ(start). Where the
/// curve turns in β it adds instead ∫ ω_swapped + φ(end) − φ(start), ω_swapped =
/// −c(β) c′(α) dα and φ = c(α) c(β), since ω_square − ω_swapped = dφ. A curve monotone
/// in x and y turns in α or in β, not both, when P's steps lean apart (its tangent
/// stays in one quadrant, and only one step's line runs through it), so the form it is
/// integrated by keeps its edge coordinate monotone (`clamp_term`).
pub fn across_square(c: Quad, f: &PixelFrame) -> f64 {
    let square = c.map(|p| DVec2::new(f.alpha_of.dot(p), f.beta_of.dot(p)));
    let (alpha, beta) = (square.map(|p| p.x), square.map(|p| p.y));
    // A coordinate's derivative is linear in t: it changes sign where its ends' signs
    // differ. The form taken is the one whose edge coordinate turns less (where a step
    // lies within rounding of an axis, the shader's derivatives may tilt it across).
    let beta_turn = (beta[1] - beta[0]) * (beta[2] - beta[1]);
    let swap = beta_turn < 0.0 && beta_turn < (alpha[1] - alpha[0]) * (alpha[2] - alpha[1]);
    let term = if swap {
        let corner = |p: DVec2| (p.x + 0.5).clamp(0.0, 1.0) * (p.y + 0.5).clamp(0.0, 1.0);
        corner(square[2]) - corner(square[0]) - clamp_term(beta, alpha)
    } else {
        clamp_term(alpha, beta)
    };
    term + rows_correction(c[2], f) - rows_correction(c[0], f)
}

/// ∫ c(A) dclamp(B, −½, ½) along a curve whose control values are `a` and `b`, B
/// monotone: its stretch within the strip |B| ≤ ½ is cut out (blossoming), its ends put
/// on the strip's edges exactly (or left at the curve's), so that in f32 the integral
/// spans the strip's height however long the curve and however coarse its parameter
/// there; A's roots at ±½ cut the stretch into parts on which c(A) is 0, A + ½ or 1.
fn clamp_term(a: [f64; 3], b: [f64; 3]) -> f64 {
    let (t0, t1) = stretch(b, -0.5, 0.5);
    let l = monomial([
        blossom_value(a, t0, t0),
        blossom_value(a, t0, t1),
        blossom_value(a, t1, t1),
    ]);
    let pb = monomial([
        b[0].clamp(-0.5, 0.5),
        blossom_value(b, t0, t1),
        b[2].clamp(-0.5, 0.5),
    ]);
    // B′ = e + d·t.
    let (d, e) = (2.0 * pb[0], pb[1]);
    let mut cuts = vec![0.0, 1.0];
    cuts.extend(level_roots(l));
    cuts.sort_by(f64::total_cmp);
    let with_a = product_antiderivative([l[0], l[1], l[2] + 0.5], d, e);
    let rise = |t: f64| (0.5 * d * t + e) * t;
    cuts.windows(2)
        .map(|w| {
            let mid = 0.5 * (w[0] + w[1]);
            let at = (l[0] * mid + l[1]) * mid + l[2];
            if at < -0.5 {
                0.0
            } else if at > 0.5 {
                rise(w[1]) - rise(w[0])
            } else {
                with_a(w[1]) - with_a(w[0])
            }
        })
        .sum()
}

/// The roots in [0, 1] where the quadratic with monomials `l` takes −½ or ½.
fn level_roots(l: [f64; 3]) -> Vec<f64> {
    [-0.5, 0.5]
        .into_iter()
        .flat_map(|level| quadratic_roots([l[0], l[1], l[2] - level]))
        .flatten()
        .map(|r| r.clamp(0.0, 1.0))
        .collect()
}

/// The roots of the quadratic with monomials `l` (t², t, 1) by the stable form of the
/// quadratic formula, which stays finite as it degenerates to a line: None for a root
/// that does not exist.
fn quadratic_roots(l: [f64; 3]) -> [Option<f64>; 2] {
    let discriminant = l[1] * l[1] - 4.0 * l[0] * l[2];
    if discriminant.is_nan() || discriminant < 0.0 {
        return [None, None];
    }
    let root = discriminant.sqrt();
    let q = -0.5 * (l[1] + if l[1] >= 0.0 { root } else { -root });
    [
        (q != 0.0).then(|| l[2] / q),
        (l[0] != 0.0).then(|| q / l[0]),
    ]
}

/// The antiderivative from 0 of l(t)·(e + d·t), l a quadratic given by its monomials:
/// a quartic, for the integral of a coordinate along a curve against another's slope.
fn product_antiderivative(l: [f64; 3], d: f64, e: f64) -> impl Fn(f64) -> f64 {
    let cubic = [
        l[0] * d / 4.0,
        (l[0] * e + l[1] * d) / 3.0,
        (l[1] * e + l[2] * d) / 2.0,
        l[2] * e,
    ];
    move |t: f64| (((cubic[0] * t + cubic[1]) * t + cubic[2]) * t + cubic[3]) * t
}

/// ψ at a point q of the frame, dψ = ω_rows − ω_square, 0 far left. Along q's row ω_rows
/// vanishes (dv = 0), so ψ = −∫ c(α) c′(β) dβ along the row from far left to q: β runs
/// linearly there (β_u = beta_of.x), so the strip |β| ≤ ½ is a stretch [lo, hi] of u,
/// on which α grows by α_u = alpha_of.x > 0 a unit of u; the integral is (β_u / α_u)
/// times ∫ c(α) dα from the stretch's start to q clamped into it. A row along the strip
/// (β_u = 0) adds nothing to ω_square: ψ = 0.
fn rows_correction(q: DVec2, f: &PixelFrame) -> f64 {
    let beta_u = f.beta_of.x;
    if beta_u == 0.0 {
        return 0.0;
    }
    let ends = [-0.5, 0.5].map(|level| (level - f.beta_of.y * q.y) / beta_u);
    let (lo, hi) = (ends[0].min(ends[1]), ends[0].max(ends[1]));
    let alpha_at = |u: f64| f.alpha_of.x * u + f.alpha_of.y * q.y;
    // ∫ c(x) dx from far below.
    let antiderivative = |x: f64| {
        if x < -0.5 {
            0.0
        } else if x > 0.5 {
            x
        } else {
            0.5 * (x + 0.5) * (x + 0.5)
        }
    };
    let start = alpha_at(lo);
    if start > 0.5 {
        // The row meets the strip past α = ½, where c = 1: the strip's height crossed,
        // from β's values (α far from the square would cancel).
        let edge = if beta_u > 0.0 { -0.5 } else { 0.5 };
        return -(f.beta_of.dot(q).clamp(-0.5, 0.5) - edge);
    }
    -beta_u / f.alpha_of.x * (antiderivative(alpha_at(q.x.clamp(lo, hi))) - antiderivative(start))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::line_as_quad;

    /// Local → image as a 2×2 matrix (columns: the images of local x and y), the same
    /// in every test: a pixel's steps are its inverse's columns.
    struct Camera {
        to_image: glam::DMat2,
        origin: DVec2,
    }

    impl Camera {
        fn new(to_image: glam::DMat2, origin: DVec2) -> Camera {
            Camera { to_image, origin }
        }

        fn image(&self, local: DVec2) -> DVec2 {
            self.to_image * local + self.origin
        }

        /// F at the pixel whose top-left corner is (i, j), from the curves in local.
        fn winding(&self, curves: &[Quad], i: i32, j: i32) -> f64 {
            let to_local = self.to_image.inverse();
            let centre =
                to_local * (DVec2::new(f64::from(i) + 0.5, f64::from(j) + 0.5) - self.origin);
            pixel_winding(curves, centre, to_local.x_axis, to_local.y_axis)
        }
    }

    fn rotation(degrees: f64) -> glam::DMat2 {
        glam::DMat2::from_angle(degrees.to_radians())
    }

    /// The cameras every shape is seen through: identity, rotations (the pixel's sides
    /// slant in the band frame), a skew, a mirror, an anisotropic scale, and y flipped
    /// as images are.
    fn cameras() -> Vec<(&'static str, glam::DMat2)> {
        let flip = glam::DMat2::from_cols(DVec2::X, DVec2::NEG_Y);
        vec![
            ("identity", glam::DMat2::IDENTITY),
            ("y down", flip),
            ("rotated 30°", rotation(30.0) * flip),
            ("rotated 45°", rotation(45.0)),
            ("rotated 0.01°", rotation(0.01)),
            ("rotated 100°", rotation(100.0) * flip),
            (
                "skewed",
                glam::DMat2::from_cols(DVec2::new(1.0, 0.0), DVec2::new(0.4, -1.0)),
            ),
            (
                "mirrored",
                glam::DMat2::from_cols(DVec2::new(-1.0, 0.0), DVec2::new(0.0, -1.0)),
            ),
            (
                "stretched and turned",
                rotation(-20.0)
                    * glam::DMat2::from_cols(DVec2::new(2.5, 0.0), DVec2::new(0.0, 0.7)),
            ),
        ]
    }

    fn polygon_curves(points: &[DVec2]) -> Vec<Quad> {
        (0..points.len())
            .map(|k| line_as_quad(points[k], points[(k + 1) % points.len()]))
            .collect()
    }

    /// Area of a convex polygon (image space) inside the pixel at (i, j), by clipping
    /// it to the pixel's four sides (Sutherland–Hodgman) and the shoelace formula: an
    /// independent reckoning, no Green's theorem over curves.
    fn clipped_area(polygon: &[DVec2], i: i32, j: i32) -> f64 {
        let (x0, y0) = (f64::from(i), f64::from(j));
        let mut poly = polygon.to_vec();
        let sides: [(DVec2, f64); 4] = [
            (DVec2::X, x0),
            (DVec2::NEG_X, -(x0 + 1.0)),
            (DVec2::Y, y0),
            (DVec2::NEG_Y, -(y0 + 1.0)),
        ];
        for (normal, offset) in sides {
            let inside = |p: DVec2| normal.dot(p) >= offset;
            let mut out = Vec::new();
            for k in 0..poly.len() {
                let (p, q) = (poly[k], poly[(k + 1) % poly.len()]);
                if inside(p) {
                    out.push(p);
                }
                if inside(p) != inside(q) {
                    let t = (offset - normal.dot(p)) / normal.dot(q - p);
                    out.push(p + (q - p) * t);
                }
            }
            poly = out;
            if poly.is_empty() {
                return 0.0;
            }
        }
        let twice: f64 = (0..poly.len())
            .map(|k| poly[k].perp_dot(poly[(k + 1) % poly.len()]))
            .sum();
        0.5 * twice.abs()
    }

    /// Every pixel near a convex polygon (local points), through every camera: |F| is
    /// the clipped area.
    fn check_convex(name: &str, local: &[DVec2], origin: DVec2) {
        let curves = polygon_curves(local);
        for (camera_name, m) in cameras() {
            let cam = Camera::new(m, origin);
            let image: Vec<DVec2> = local.iter().map(|&p| cam.image(p)).collect();
            let min = image.iter().fold(DVec2::INFINITY, |a, &b| a.min(b)).floor();
            let max = image
                .iter()
                .fold(DVec2::NEG_INFINITY, |a, &b| a.max(b))
                .ceil();
            for j in (min.y as i32 - 1)..=(max.y as i32) {
                for i in (min.x as i32 - 1)..=(max.x as i32) {
                    let got = cam.winding(&curves, i, j).abs();
                    let want = clipped_area(&image, i, j);
                    assert!(
                        (got - want).abs() < 1e-9,
                        "{name}, {camera_name}, pixel ({i}, {j}): {got} vs {want}"
                    );
                }
            }
        }
    }

    #[test]
    fn a_square_at_sub_pixel_offsets_and_rotations() {
        for k in 0..16 {
            let offset = DVec2::new(
                f64::from(k % 4) * 0.25 + 0.03,
                f64::from(k / 4) * 0.25 + 0.11,
            );
            for turn in [0.0, 7.0, 30.0, 45.0, 61.0] {
                let r = rotation(turn);
                let square: Vec<DVec2> = [(0.0, 0.0), (2.3, 0.0), (2.3, 2.3), (0.0, 2.3)]
                    .map(|(x, y)| r * DVec2::new(x, y))
                    .to_vec();
                check_convex(&format!("square turned {turn}°"), &square, offset + 4.0);
            }
        }
    }

    #[test]
    fn a_triangle_and_a_sliver() {
        let triangle = [
            DVec2::new(0.2, 0.1),
            DVec2::new(5.3, 1.7),
            DVec2::new(1.9, 4.4),
        ];
        check_convex("triangle", &triangle, DVec2::new(3.4, 3.7));
        // Thinner than a pixel and longer than several: every pixel meets both edges.
        let sliver = [
            DVec2::new(0.0, 0.0),
            DVec2::new(6.0, 0.9),
            DVec2::new(6.0, 1.2),
        ];
        check_convex("sliver", &sliver, DVec2::new(2.2, 5.1));
    }

    /// Clockwise or counter-clockwise, the magnitude is the same: the sign follows the
    /// orientation only.
    #[test]
    fn orientation_flips_the_sign_only() {
        let square =
            [(0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (0.0, 3.0)].map(|(x, y)| DVec2::new(x, y) + 0.4);
        let mut reversed = square;
        reversed.reverse();
        for (name, m) in cameras() {
            let cam = Camera::new(m, DVec2::new(5.0, 5.0));
            for (i, j) in [(5, 5), (6, 6), (7, 8), (4, 4)] {
                let a = cam.winding(&polygon_curves(&square), i, j);
                let b = cam.winding(&polygon_curves(&reversed), i, j);
                assert!((a + b).abs() < 1e-12, "{name} ({i}, {j}): {a} {b}");
            }
        }
    }

    /// A straight edge at any angle and phase: a huge square whose one side crosses the
    /// pixel, against the pixel's share on its inner side.
    #[test]
    fn a_straight_edge_at_any_angle_and_phase() {
        for step in 0..72 {
            let angle = f64::from(step) * 5.0 + 0.7;
            let (sin, cos) = angle.to_radians().sin_cos();
            let normal = DVec2::new(cos, sin);
            let along = normal.perp();
            for phase in [-0.9, -0.5, -0.31, 0.0, 0.12, 0.5, 0.77] {
                // The edge passes `phase` px from the centre of pixel (0, 0); the square
                // lies on its −normal side, 1000 px deep.
                let centre = DVec2::splat(0.5);
                let on_edge = centre + normal * phase;
                let square = [
                    on_edge - along * 1000.0,
                    on_edge + along * 1000.0,
                    on_edge + along * 1000.0 - normal * 2000.0,
                    on_edge - along * 1000.0 - normal * 2000.0,
                ];
                let curves = polygon_curves(&square);
                for (name, m) in cameras() {
                    // The square is given in image space: take it back to local.
                    let to_local = m.inverse();
                    let local: Vec<Quad> = curves.iter().map(|c| c.map(|p| to_local * p)).collect();
                    let got = Camera::new(m, DVec2::ZERO).winding(&local, 0, 0).abs();
                    let want = clipped_area(&square, 0, 0);
                    assert!(
                        (got - want).abs() < 1e-9,
                        "{angle}° phase {phase}, {name}: {got} vs {want}"
                    );
                }
            }
        }
    }

    /// A parabolic segment (a quadratic and its chord) wholly inside one pixel covers
    /// 2/3 of its control triangle (Archimedes).
    #[test]
    fn a_parabolic_segment_covers_two_thirds_of_its_triangle() {
        let (a, b, c) = (
            DVec2::new(0.1, 0.2),
            DVec2::new(0.5, 0.95),
            DVec2::new(0.85, 0.3),
        );
        let triangle = 0.5 * (b - a).perp_dot(c - a).abs();
        let segment = [[a, b, c], line_as_quad(c, a)];
        for (name, m) in cameras() {
            // Given in image space inside pixel (3, 2); taken back to local.
            let to_local = m.inverse();
            let local: Vec<Quad> = segment
                .iter()
                .map(|q| q.map(|p| to_local * (p + DVec2::new(3.0, 2.0))))
                .collect();
            let cam = Camera::new(m, DVec2::ZERO);
            let got = cam.winding(&local, 3, 2).abs();
            assert!((got - 2.0 / 3.0 * triangle).abs() < 1e-12, "{name}: {got}");
            assert!(
                cam.winding(&local, 4, 2).abs() < 1e-12,
                "{name}: the next pixel"
            );
        }
    }

    /// The region under the parabola y = x² (a quadratic Bézier from (−2, 4) through
    /// (0, −4) to (2, 4), closed by its chord), cut by pixels: each pixel's share is
    /// ∫ (clamp(x², y0, y1) − y0) dx over its columns subtracted from its full area,
    /// integrated by hand.
    #[test]
    fn a_parabola_cut_by_pixels_matches_its_integral() {
        let arc = [
            DVec2::new(-2.0, 4.0),
            DVec2::new(0.0, -4.0),
            DVec2::new(2.0, 4.0),
        ];
        let closed = [arc, line_as_quad(arc[2], arc[0])];
        // ∫ from a to b of clamp(x², lo, hi) dx, split where x² crosses lo and hi.
        let clamped_integral = |a: f64, b: f64, lo: f64, hi: f64| {
            let mut cuts = vec![a, b];
            for level in [lo, hi] {
                if level > 0.0 {
                    cuts.extend(
                        [-level.sqrt(), level.sqrt()]
                            .into_iter()
                            .filter(|r| *r > a && *r < b),
                    );
                }
            }
            cuts.sort_by(f64::total_cmp);
            cuts.windows(2)
                .map(|w| {
                    let mid = 0.5 * (w[0] + w[1]);
                    if mid * mid <= lo {
                        lo * (w[1] - w[0])
                    } else if mid * mid >= hi {
                        hi * (w[1] - w[0])
                    } else {
                        (w[1].powi(3) - w[0].powi(3)) / 3.0
                    }
                })
                .sum::<f64>()
        };
        // The area of {x² ≤ y ≤ 4} in [x0, x0+1] × [y0, y0+1]: over the columns inside
        // |x| ≤ 2, the height between max(x², y0) and top = min(4, y0 + 1).
        let exact = |x0: f64, y0: f64| {
            let (a, b) = (x0.max(-2.0), (x0 + 1.0).min(2.0));
            let top = (y0 + 1.0).min(4.0);
            if b <= a || top <= y0 {
                return 0.0;
            }
            (b - a) * top - clamped_integral(a, b, y0, top)
        };
        for (name, m) in cameras() {
            let to_local = m.inverse();
            let local: Vec<Quad> = closed.iter().map(|q| q.map(|p| to_local * p)).collect();
            let cam = Camera::new(m, DVec2::ZERO);
            for j in -1..5 {
                for i in -3..3 {
                    let got = cam.winding(&local, i, j).abs();
                    let want = exact(f64::from(i), f64::from(j));
                    assert!(
                        (got - want).abs() < 1e-9,
                        "{name} ({i}, {j}): {got} vs {want}"
                    );
                }
            }
        }
    }

    #[test]
    fn area_below_is_the_parallelogram_area() {
        let frame = |jx: DVec2, jy: DVec2| PixelFrame::new(jx, jy, 1.0).unwrap();
        let cases = [
            frame(DVec2::X, DVec2::NEG_Y),
            frame(DVec2::new(2.0, 0.0), DVec2::new(0.0, 0.5)),
            frame(rotation(45.0).x_axis, rotation(45.0).y_axis),
            frame(DVec2::new(1.0, 0.3), DVec2::new(0.4, -1.0)),
        ];
        for f in cases {
            assert_eq!(area_below(f.bottom.y - 1e-9, &f), 0.0);
            assert_eq!(area_below(-f.bottom.y, &f), 1.0);
            assert!(
                (area_below(0.0, &f) - 0.5).abs() < 1e-15,
                "symmetric about 0"
            );
        }
        // The unit square: the height below.
        assert!((area_below(0.2, &cases[0]) - 0.7).abs() < 1e-15);
        // A square of area 1 turned 45°: its bottom corner at −√½, and d above it the
        // chord is 2d wide, so the area below is d².
        let d = 0.3;
        let turned = &cases[2];
        assert!((turned.bottom.y + 0.5f64.sqrt()).abs() < 1e-15);
        assert!((area_below(turned.bottom.y + d, turned) - d * d).abs() < 1e-12);
    }

    /// Where P is a rectangle, the shader's `AXIS` stretch is the general term.
    #[test]
    fn the_rectangle_stretch_is_the_general_term() {
        let frames = [
            PixelFrame::new(DVec2::X, DVec2::NEG_Y, 1.0).unwrap(),
            PixelFrame::new(DVec2::new(0.0, 0.7), DVec2::new(1.9, 0.0), -1.0).unwrap(),
        ];
        let curves = [
            [
                DVec2::new(-0.9, -1.2),
                DVec2::new(0.1, -0.6),
                DVec2::new(0.3, 0.9),
            ],
            [
                DVec2::new(2.0, 0.2),
                DVec2::new(0.0, 0.25),
                DVec2::new(-0.1, 0.3),
            ],
            [
                DVec2::new(0.2, 3.0),
                DVec2::new(0.2, 0.0),
                DVec2::new(0.2, -3.0),
            ],
        ];
        for f in &frames {
            assert!(f.is_rectangle());
            for c in curves {
                let c = c.map(|p| p * f.reach * 2.0);
                let (a, b) = (across_axis(c, f), across_term(c, f));
                assert!((a - b).abs() < 1e-12, "{f:?} {c:?}: {a} vs {b}");
            }
        }
    }

    /// Where P's steps lean apart, the square frame's term is the four ramps' term, on
    /// curves of every direction, size and position about P: long ones running far
    /// past it, short ones inside it, ones touching its corners' heights.
    #[test]
    fn the_square_frame_term_is_the_general_term() {
        // A small linear congruential generator: the same curves every run.
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut compared = 0;
        let mut swapped = 0;
        for step in 0..64 {
            let angle = f64::from(step) * 5.7 + 0.3;
            let stretch = 0.6 + 1.4 * next();
            let m = rotation(angle)
                * glam::DMat2::from_cols(
                    DVec2::new(stretch, 0.0),
                    DVec2::new(0.3 * (next() - 0.5), 1.0 / stretch),
                );
            let to_local = m.inverse();
            let direction = if step % 2 == 0 { 1.0 } else { -1.0 };
            let Some(f) = PixelFrame::new(to_local.x_axis, to_local.y_axis, direction) else {
                continue;
            };
            if !f.square || f.is_rectangle() {
                continue;
            }
            for _ in 0..200 {
                let size = [0.3, 2.0, 40.0][(next() * 3.0) as usize];
                let start = DVec2::new(next() - 0.5, next() - 0.5) * 3.0;
                let curve = [
                    start,
                    start + DVec2::new(next() - 0.5, next() - 0.5) * size,
                    start + DVec2::new(next() - 0.5, next() - 0.5) * size,
                ];
                for piece in monotone_pieces(curve).into_iter().flatten() {
                    if zone(&piece, &f) != Zone::Across {
                        continue;
                    }
                    let beta = piece.map(|p| f.beta_of.dot(p));
                    swapped += usize::from((beta[1] - beta[0]) * (beta[2] - beta[1]) < 0.0);
                    let (a, b) = (across_square(piece, &f), across_term(piece, &f));
                    assert!(
                        (a - b).abs() < 1e-9 * (1.0 + size),
                        "{f:?} {piece:?}: {a} vs {b}"
                    );
                    compared += 1;
                }
            }
        }
        assert!(
            compared > 5000 && swapped > 500,
            "{compared} compared, {swapped} swapped"
        );
    }

    /// Steps that lean the same way by a rounding's worth (a near-level step tilted
    /// across the axis, as a shader's derivatives can): a piece leaving along the axis
    /// turns in β by a hair while it turns in α for real, and the square's term takes
    /// the form whose edge coordinate turns less, staying with the four ramps' term.
    #[test]
    fn the_square_frame_term_survives_a_step_rounded_across_an_axis() {
        let jx = DVec2::new(1.0, 1e-7);
        let jy = DVec2::new(0.5, 1.0);
        let f = PixelFrame::new(jx, jy, 1.0).unwrap();
        assert!(!f.square, "the steps lean the same way");
        for offset in [-0.6, -0.2, 0.0, 0.3, 0.7] {
            // Level at its start (a split point), steeper than jy at its end: α rises
            // past ½ and comes back.
            let start = DVec2::new(-1.5, offset - 0.4);
            let piece = [
                start,
                start + DVec2::new(4.0, 0.0),
                start + DVec2::new(4.5, 8.0),
            ];
            let beta = piece.map(|p| f.beta_of.dot(p));
            let alpha = piece.map(|p| f.alpha_of.dot(p));
            assert!(
                (beta[1] - beta[0]) * (beta[2] - beta[1]) < 0.0,
                "β turns by a hair"
            );
            assert!(
                (alpha[1] - alpha[0]) * (alpha[2] - alpha[1]) < 0.0,
                "α turns"
            );
            let (a, b) = (across_square(piece, &f), across_term(piece, &f));
            assert!((a - b).abs() < 1e-5, "offset {offset}: {a} vs {b}");
        }
    }

    #[test]
    fn fill_rules() {
        assert_eq!(fill(-0.3, false), 0.3);
        assert_eq!(fill(1.7, false), 1.0);
        assert!((fill(1.7, true) - 0.3).abs() < 1e-15);
        assert!((fill(2.25, true) - 0.25).abs() < 1e-15);
    }
}
