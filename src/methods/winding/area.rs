//! `aa=area`: the exact box-filter coverage of one pixel, in f64 — the CPU mirror of
//! `shaders/winding_area.wgsl`, function for function, so that the shader's
//! formulation is checked here against closed forms. [`pixel_winding`] is the shader's
//! `area_winding` over every curve (no bands), and [`curve_term`] the zone test in its
//! loop; [`PixelFrame`] is `pixel_frame` and `frame_map`, [`levels`] `frame_levels`,
//! [`zone`] `area_zone`, `monotone_pieces` the splits in `across_term`; the rest keep
//! their names. [`fill`] is `fill` in `shaders/winding.wgsl`. The shader's `area_pixel`
//! (fill(F), or the mean over a grid of sub-pixels where contours overlap) has no
//! mirror here.
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
//! pixel: a parallelogram. Horizontal lines must stay horizontal for the bands, so the
//! frame the integral runs in is the local one sheared and scaled (never rotated): one
//! pair of P's sides becomes vertical at u = ±½ and the area 1, and the other pair
//! slants with slope `s` in [0, 1] (0 when the camera neither rotates nor skews the
//! glyph):
//!
//! ```text
//! P = {(σ, s·σ + τ) : |σ|, |τ| ≤ ½},   heights v0 < v1 ≤ v2 < v3 = ∓½ ∓ s/2.
//! ```
//!
//! Under a rotation, skew or mirror this is exact; under a perspective tilt the
//! Jacobian is the homography's linearisation at the pixel. In this frame:
//!
//! - right of P (u ≥ ½) G is the chord, so the curve adds `area_below(v_end) −
//!   area_below(v_start)`;
//! - inside P's columns (|u| ≤ ½), with α = u + ½, G = α between v0 and v2, less
//!   ramp(α − (v − v0)/s) below v1 (the bottom side), plus ramp(α − (v − v2)/s) above
//!   v2 (the top side, where G would otherwise be 0);
//! - left of P, G = 0.
//!
//! Each curve is split where u or v turns, so every piece crosses each of those lines
//! at most once; a piece is cut at u = ±½ and at the heights v0…v3 by one root each,
//! and ∫ ℓ dv over a quadratic piece (ℓ linear in the coordinates) is closed form
//! ([`integral_x_dy`]). Pieces are cut out of their curve first (blossoming), so every
//! integral runs over points within a pixel or so of P: nothing far away is subtracted
//! from anything.
//!
//! Coverage is `fill(F)`: min(|F|, 1) for nonzero, a triangle wave for even-odd — exact
//! wherever the winding inside the pixel takes two adjacent values, which every pixel
//! of a glyph without overlapping contours does.

use glam::DVec2;

/// A quadratic Bézier: its three control points.
pub type Bezier = [DVec2; 3];

/// The frame one pixel is integrated in: local offsets from the pixel's centre,
/// mirrored to the band direction, sheared and scaled so the pixel is the canonical P.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelFrame {
    /// ±1: local x is mirrored when the bands are walked towards −x.
    direction: f64,
    /// u = (x_f − shear·y) · u_scale, v = y · v_scale, with x_f = direction · x.
    shear: f64,
    u_scale: f64,
    v_scale: f64,
    /// The slope of P's slanted sides, in [0, 1].
    pub slope: f64,
}

impl PixelFrame {
    /// The frame of the pixel whose one-pixel steps along image x and y are the local
    /// offsets `jx` and `jy`, walked towards `direction` (±1) along local x. None for a
    /// pixel that covers no area.
    pub fn new(jx: DVec2, jy: DVec2, direction: f64) -> Option<PixelFrame> {
        let mirror = |v: DVec2| DVec2::new(direction * v.x, v.y);
        let (jx, jy) = (mirror(jx), mirror(jy));
        // `b` becomes the vertical sides: the step with more height, so the other
        // one's slope is at most 1.
        let (a, b) = if jx.y.abs() > jy.y.abs() {
            (jy, jx)
        } else {
            (jx, jy)
        };
        let det = a.perp_dot(b);
        if det == 0.0 || b.y == 0.0 {
            return None;
        }
        let shear = b.x / b.y;
        let u_scale = b.y.abs() / det.abs();
        // `a` maps to (±1, a.y / |b.y|); flip v so that P's sides slope upwards.
        let a_u = (a.x - shear * a.y) * u_scale;
        let a_v = a.y / b.y.abs();
        let flip = if a_u * a_v < 0.0 { -1.0 } else { 1.0 };
        Some(PixelFrame {
            direction,
            shear,
            u_scale,
            v_scale: flip / b.y.abs(),
            slope: (a_u * a_v).abs(),
        })
    }

    /// A local offset from the pixel's centre in this frame.
    pub fn map(&self, offset: DVec2) -> DVec2 {
        let x = self.direction * offset.x;
        DVec2::new(
            (x - self.shear * offset.y) * self.u_scale,
            offset.y * self.v_scale,
        )
    }
}

/// The heights of the four corners of P with sides sloping by `slope`, lowest first.
pub fn levels(slope: f64) -> [f64; 4] {
    let h = 0.5 * slope;
    [-0.5 - h, -0.5 + h, 0.5 - h, 0.5 + h]
}

/// Area of P below height `v`: 0 under P, 1 over it, quadratic across each slanted side.
pub fn area_below(v: f64, slope: f64) -> f64 {
    let [v0, v1, v2, v3] = levels(slope);
    if v <= v0 {
        0.0
    } else if v >= v3 {
        1.0
    } else if v < v1 {
        // Only reached when slope > 0: v0 < v < v1.
        (v - v0) * (v - v0) / (2.0 * slope)
    } else if v > v2 {
        1.0 - (v3 - v) * (v3 - v) / (2.0 * slope)
    } else {
        v - v1 + 0.5 * slope
    }
}

/// The pixel-averaged winding number F of the pixel centred on local point `centre`
/// (steps `jx`, `jy`), over every curve of a glyph: every curve is visited, no bands.
pub fn pixel_winding(curves: &[Bezier], centre: DVec2, jx: DVec2, jy: DVec2) -> f64 {
    let Some(frame) = PixelFrame::new(jx, jy, 1.0) else {
        return 0.0;
    };
    curves
        .iter()
        .map(|c| curve_term(c.map(|p| frame.map(p - centre)), frame.slope))
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
    /// Its bounds meet P's: the full integral.
    Across,
}

/// The zone of a curve's control points (a curve lies within their hull).
pub fn zone(c: &Bezier, slope: f64) -> Zone {
    let [v0, _, _, v3] = levels(slope);
    let min = c[0].min(c[1]).min(c[2]);
    let max = c[0].max(c[1]).max(c[2]);
    if max.y <= v0 || min.y >= v3 || max.x <= -0.5 {
        Zone::Outside
    } else if min.x >= 0.5 {
        Zone::Right
    } else {
        Zone::Across
    }
}

/// ∫ G dv along one curve, in a pixel frame of slope `slope`.
pub fn curve_term(c: Bezier, slope: f64) -> f64 {
    match zone(&c, slope) {
        Zone::Outside => 0.0,
        Zone::Right => area_below(c[2].y, slope) - area_below(c[0].y, slope),
        Zone::Across => across_term(c, slope),
    }
}

/// ∫ G dv along a curve across P, split where u or v turns.
fn across_term(c: Bezier, slope: f64) -> f64 {
    monotone_pieces(c)
        .into_iter()
        .flatten()
        .map(|piece| piece_term(piece, slope))
        .sum()
}

/// Where a quadratic (control values) turns, or 1 when it does not inside (0, 1).
fn turn(c: [f64; 3]) -> f64 {
    let denominator = c[0] - 2.0 * c[1] + c[2];
    if denominator == 0.0 {
        return 1.0;
    }
    let t = (c[0] - c[1]) / denominator;
    if t > 0.0 && t < 1.0 { t } else { 1.0 }
}

/// The curve split where x or y turns: up to three pieces, each monotone in both.
pub(super) fn monotone_pieces(c: Bezier) -> [Option<Bezier>; 3] {
    let (tx, ty) = (turn(c.map(|p| p.x)), turn(c.map(|p| p.y)));
    let (t1, t2) = (tx.min(ty), tx.max(ty));
    let piece = |a: f64, b: f64| (b > a).then(|| subcurve(c, a, b));
    [piece(0.0, t1), piece(t1, t2), piece(t2, 1.0)]
}

/// ∫ G dv along a piece monotone in u and v: the part right of P by its area, the part
/// inside P's columns by [`inside_term`], the part left of P nothing.
fn piece_term(c: Bezier, slope: f64) -> f64 {
    let u = c.map(|p| p.x);
    let t_left = t_at(u, -0.5);
    let t_right = t_at(u, 0.5);
    let increasing = u[2] >= u[0];
    let (right_from, right_to) = if increasing {
        (t_right, 1.0)
    } else {
        (0.0, t_right)
    };
    let mut term = 0.0;
    if right_to > right_from {
        let v_at = |t: f64| blossom(c, t, t).y;
        term += area_below(v_at(right_to), slope) - area_below(v_at(right_from), slope);
    }
    let (from, to) = (t_left.min(t_right), t_left.max(t_right));
    if to > from {
        term += inside_term(subcurve(c, from, to), slope);
    }
    term
}

/// ∫ G dv along a piece monotone in u and v lying within P's columns (|u| ≤ ½): with
/// α = u + ½, α between heights v0 and v2, plus ramp(α − (v − v2)/slope) across the top
/// side, less ramp(α − (v − v0)/slope) across the bottom one (the chord's end there
/// moves a pixel's width over `slope` of height).
fn inside_term(c: Bezier, slope: f64) -> f64 {
    let [v0, v1, v2, v3] = levels(slope);
    // (heights, whether the side slants, sign)
    let slabs = [
        (v0, v2, false, 1.0),
        (v2, v3, true, 1.0),
        (v0, v1, true, -1.0),
    ];
    let v = c.map(|p| p.y);
    let mut term = 0.0;
    for (low, high, slanted, sign) in slabs {
        if slanted && slope == 0.0 {
            continue;
        }
        let (a, b) = (t_at(v, low), t_at(v, high));
        if a.max(b) <= a.min(b) {
            continue;
        }
        let part = subcurve(c, a.min(b), a.max(b));
        let ramp = part.map(|p| {
            let alpha = p.x + 0.5;
            let l = if slanted {
                alpha - (p.y - low) / slope
            } else {
                alpha
            };
            DVec2::new(l, p.y)
        });
        term += sign * ramp_integral(ramp);
    }
    term
}

/// ∫ ramp(ℓ(t)) y′(t) dt over a quadratic piece (ℓ its x, y its y), split where ℓ
/// turns so that each part crosses ℓ = 0 once at most.
fn ramp_integral(c: Bezier) -> f64 {
    let t = turn(c.map(|p| p.x));
    [(0.0, t), (t, 1.0)]
        .into_iter()
        .filter(|(a, b)| b > a)
        .map(|(a, b)| {
            let part = subcurve(c, a, b);
            let l = part.map(|p| p.x);
            let (mut low, mut high) = (0.0, 1.0);
            if l[0] < 0.0 || l[2] < 0.0 {
                if l[2] > l[0] {
                    low = t_at(l, 0.0);
                } else {
                    high = t_at(l, 0.0);
                }
            }
            if high <= low || (l[0] <= 0.0 && l[2] <= 0.0) {
                return 0.0;
            }
            let positive = subcurve(part, low, high);
            integral_x_dy(positive.map(|p| p.x), positive.map(|p| p.y))
        })
        .sum()
}

/// ∫₀¹ x(t) y′(t) dt for a quadratic Bézier given by its control values: exact (the
/// integrand is a cubic in t).
pub fn integral_x_dy(x: [f64; 3], y: [f64; 3]) -> f64 {
    let d0 = y[1] - y[0];
    let d1 = y[2] - y[1];
    (x[0] * (3.0 * d0 + d1) + 2.0 * x[1] * (d0 + d1) + x[2] * (d0 + 3.0 * d1)) / 6.0
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

/// The curve's blossom at (a, b): the point at t when a = b = t; the middle control
/// point of the piece between a and b.
fn blossom(c: Bezier, a: f64, b: f64) -> DVec2 {
    c[0] * ((1.0 - a) * (1.0 - b)) + c[1] * ((1.0 - a) * b + a * (1.0 - b)) + c[2] * (a * b)
}

/// The piece of `c` between parameters `a` and `b`, as a quadratic Bézier of its own.
fn subcurve(c: Bezier, a: f64, b: f64) -> Bezier {
    [blossom(c, a, a), blossom(c, a, b), blossom(c, b, b)]
}

#[cfg(test)]
mod tests {
    use super::*;

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
        fn winding(&self, curves: &[Bezier], i: i32, j: i32) -> f64 {
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

    fn line(a: DVec2, b: DVec2) -> Bezier {
        [a, (a + b) * 0.5, b]
    }

    fn polygon_curves(points: &[DVec2]) -> Vec<Bezier> {
        (0..points.len())
            .map(|k| line(points[k], points[(k + 1) % points.len()]))
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
                    let local: Vec<Bezier> =
                        curves.iter().map(|c| c.map(|p| to_local * p)).collect();
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
        let segment = [[a, b, c], line(c, a)];
        for (name, m) in cameras() {
            // Given in image space inside pixel (3, 2); taken back to local.
            let to_local = m.inverse();
            let local: Vec<Bezier> = segment
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
        let closed = [arc, line(arc[2], arc[0])];
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
            let local: Vec<Bezier> = closed.iter().map(|q| q.map(|p| to_local * p)).collect();
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
        for slope in [0.0, 0.25, 1.0] {
            assert_eq!(area_below(-2.0, slope), 0.0);
            assert_eq!(area_below(2.0, slope), 1.0);
            assert!(
                (area_below(0.0, slope) - 0.5).abs() < 1e-15,
                "symmetric about 0"
            );
        }
        // Slope 1: v0 = −1, and up to v = −½ the corner triangle's legs are ½ high and
        // ½ wide (the chord grows a pixel per unit of height): 1/8.
        assert!((area_below(-0.5, 1.0) - 0.125).abs() < 1e-15);
        // Slope 0: a unit square.
        assert!((area_below(0.2, 0.0) - 0.7).abs() < 1e-15);
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
    fn fill_rules() {
        assert_eq!(fill(-0.3, false), 0.3);
        assert_eq!(fill(1.7, false), 1.0);
        assert!((fill(1.7, true) - 0.3).abs() < 1e-15);
        assert!((fill(2.25, true) - 0.25).abs() < 1e-15);
    }
}
