//! Projective maps of the plane (3×3 matrices, column vectors): applying one, and what
//! a method asks of one over a region (does it keep the axes, do a pixel's steps lean
//! apart, how far may it stretch).

use glam::{DMat3, DVec2, DVec3};

use super::rect::Rect;

/// Applies a projective 3×3 matrix to a 2D point (column vectors, w = last row).
pub fn project(m: &DMat3, p: DVec2) -> DVec2 {
    let v = *m * DVec3::new(p.x, p.y, 1.0);
    DVec2::new(v.x / v.z, v.y / v.z)
}

/// Whether a homography maps local axes onto image axes: a scale (mirrors and quarter
/// turns included) and a translation, no rotation between, no skew, no perspective.
/// Then a pixel, taken back to local coordinates, is an axis-aligned rectangle. Terms
/// under 1e-12 of the scale count as 0: a quarter turn made from sin and cos leaves
/// 6e-17 where there is nothing, far below what f32 coordinates resolve.
pub fn keeps_axes(to_image: &DMat3) -> bool {
    let (x, y) = (to_image.x_axis, to_image.y_axis);
    let scale = x.truncate().length().max(y.truncate().length());
    let nothing = |v: f64| v.abs() <= 1e-12 * scale;
    let affine = nothing(x.z) && nothing(y.z);
    affine && ((nothing(x.y) && nothing(y.x)) || (nothing(x.x) && nothing(y.y)))
}

/// Whether, at every point of the image region `view`, a pixel's two steps taken back
/// into local coordinates (the columns of the image → local Jacobian) lean apart: one
/// rises to the right and the other to the left, or one runs along an axis (the
/// products of their components have no common sign). A curve monotone in x and y then
/// turns along at most one of the pixel's own axes — the condition of `winding`'s
/// square frame (`SQUARE` in crates/text/shaders/winding_area.wgsl). Rotations, mirrors and scales
/// always lean apart; a skew or a perspective tilt may not. Each component of a step,
/// times w² (w the homogeneous coordinate), is affine in the image point, so the corners
/// of `view` bound it; a product of those bounds that may be positive anywhere, or a
/// corner where they are not finite, answers false.
pub fn steps_lean_apart(to_image: &DMat3, view: &Rect) -> bool {
    let to_local = to_image.inverse();
    let extent = |values: [f64; 4]| {
        values
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
                (lo.min(v), hi.max(v))
            })
    };
    let range = |component: &dyn Fn(DVec2) -> f64| extent(view.corners().map(component));
    let times = |(a, b): (f64, f64), (c, d): (f64, f64)| extent([a * c, a * d, b * c, b * d]);
    // w² times the step along image axis `axis`: column·w − (local·w)·column.z.
    let step = |axis: usize, coordinate: usize| {
        let column = to_local.col(axis);
        move |s: DVec2| {
            let h = to_local * DVec3::new(s.x, s.y, 1.0);
            column[coordinate] * h.z - h[coordinate] * column.z
        }
    };
    let finite = view.corners().iter().all(|&s| {
        (0..2).all(|axis| (0..2).all(|coordinate| step(axis, coordinate)(s).is_finite()))
    });
    let lean = |axis: usize| times(range(&step(axis, 0)), range(&step(axis, 1)));
    let (lo, hi) = times(lean(0), lean(1));
    finite && lo.is_finite() && hi <= 0.0
}

/// An upper bound of the local→image scale over `local` (Frobenius norm of the
/// Jacobian of the homography, maximised over the rectangle's corners: w is affine, so
/// its minimum is at a corner, and so is the largest image-space distance).
pub fn jacobian_bound(to_image: &DMat3, local: &Rect) -> f64 {
    let linear = glam::DMat2::from_cols(to_image.x_axis.truncate(), to_image.y_axis.truncate());
    let w_row = to_image.row(2);
    let mut min_w = f64::INFINITY;
    let mut max_image = 0.0f64;
    for c in local.corners() {
        min_w = min_w.min(w_row.dot(c.extend(1.0)));
        max_image = max_image.max(project(to_image, c).length());
    }
    let frobenius = |m: glam::DMat2| m.to_cols_array().iter().map(|v| v * v).sum::<f64>().sqrt();
    let perspective = DVec2::new(w_row.x, w_row.y).length();
    (frobenius(linear) + max_image * perspective) / min_w
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_lean_apart_under_rotations_not_under_a_strong_skew() {
        let view = Rect {
            min: DVec2::splat(-1.0),
            max: DVec2::new(801.0, 601.0),
        };
        let at = |linear: glam::DMat2| {
            DMat3::from_cols(
                linear.x_axis.extend(0.0),
                linear.y_axis.extend(0.0),
                DVec3::new(400.0, 300.0, 1.0),
            )
        };
        for degrees in [0.0, 0.01, 30.0, 45.0, 89.0, 135.0, 200.0] {
            let turn = glam::DMat2::from_angle(f64::to_radians(degrees)) * 0.02;
            assert!(steps_lean_apart(&at(turn), &view), "{degrees}°");
            let flipped = turn * glam::DMat2::from_cols(DVec2::X, DVec2::NEG_Y);
            assert!(
                steps_lean_apart(&at(flipped), &view),
                "{degrees}°, mirrored"
            );
        }
        // Image x takes local (1, 0.2)·s and image y local (1, 3)·s back: both rise to
        // the right.
        let skew = glam::DMat2::from_cols(DVec2::new(1.0, 0.2), DVec2::new(1.0, 3.0)).inverse();
        assert!(!steps_lean_apart(&at(skew), &view));
        // The same steps mirrored in y lean apart.
        let apart = glam::DMat2::from_cols(DVec2::new(1.0, 0.2), DVec2::new(-1.0, 3.0)).inverse();
        assert!(steps_lean_apart(&at(apart), &view));
    }

    /// The Jacobian that `steps_lean_apart` bounds, by finite differences of the
    /// homography at points of the view: where it answers true, no sampled pixel's
    /// steps lean the same way.
    #[test]
    fn steps_lean_apart_holds_at_every_sampled_pixel_of_a_tilted_view() {
        let view = Rect {
            min: DVec2::splat(-1.0),
            max: DVec2::new(641.0, 481.0),
        };
        let linear = glam::DMat2::from_angle(0.5) * 0.03;
        // w runs over 1 ± tilt · 8 000 across the view (local units are 1/0.03 px).
        for tilt in [0.0, 1e-6, 1e-5, 5e-5, 1e-4] {
            let to_image = DMat3::from_cols(
                linear.x_axis.extend(tilt * 0.3),
                linear.y_axis.extend(tilt),
                DVec3::new(320.0, 240.0, 1.0),
            );
            let answer = steps_lean_apart(&to_image, &view);
            let to_local = to_image.inverse();
            let mut all_apart = true;
            for j in 0..=12 {
                for i in 0..=16 {
                    let s = view.min
                        + (view.max - view.min)
                            * DVec2::new(f64::from(i) / 16.0, f64::from(j) / 12.0);
                    let h = 1e-3;
                    let jx = (project(&to_local, s + DVec2::new(h, 0.0))
                        - project(&to_local, s - DVec2::new(h, 0.0)))
                        / (2.0 * h);
                    let jy = (project(&to_local, s + DVec2::new(0.0, h))
                        - project(&to_local, s - DVec2::new(0.0, h)))
                        / (2.0 * h);
                    all_apart &= jx.x * jx.y * jy.x * jy.y <= 1e-18;
                }
            }
            assert!(
                !answer || all_apart,
                "tilt {tilt}: answered true, but a pixel leans"
            );
            if tilt <= 1e-5 {
                assert!(answer, "tilt {tilt}: a turn with little tilt leans apart");
            }
        }
    }

    #[test]
    fn axes_are_kept_by_scales_mirrors_and_quarter_turns_only() {
        // Columns: the images of local x and y, then the translation.
        let m = |a: f64, b: f64, c: f64, d: f64| {
            DMat3::from_cols_array(&[a, c, 0.0, b, d, 0.0, 5.0, 7.0, 1.0])
        };
        let (s, c) = std::f64::consts::FRAC_PI_2.sin_cos();
        assert!(keeps_axes(&m(2.0, 0.0, 0.0, -0.5)));
        assert!(keeps_axes(&m(0.0, -3.0, 1.0, 0.0)));
        assert!(
            keeps_axes(&m(c, -s, s, c)),
            "a quarter turn from sin and cos"
        );
        assert!(!keeps_axes(&m(1.0, 1e-9, 0.0, 1.0)), "a skew f32 resolves");
        let (s, c) = 0.3f64.sin_cos();
        assert!(!keeps_axes(&m(c, -s, s, c)));
        let mut tilted = m(1.0, 0.0, 0.0, 1.0);
        tilted.y_axis.z = 1e-3;
        assert!(!keeps_axes(&tilted), "perspective");
    }
}
