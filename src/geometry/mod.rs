//! Bézier geometry, written once and shared by the reference, the methods' CPU
//! preparation and the tests. Curve evaluation, splitting, flattening and bounds come
//! from lyon_geom; what is ours is the outline model and the error-bounded conversion
//! policy around it.

mod overlaps;
mod quadratic;

pub use overlaps::merge_overlaps;

pub use quadratic::{
    DEFAULT_QUAD_TOLERANCE_EM, Quad, cubic_to_quadratics, distance_to_segment,
    max_distance_to_cubic, signed_area,
};

use glam::{DMat3, DVec2, DVec3};

/// One outline segment in font units (or any 2D space), y up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Segment {
    Line(DVec2, DVec2),
    Quad(DVec2, DVec2, DVec2),
    Cubic(DVec2, DVec2, DVec2, DVec2),
}

impl Segment {
    pub fn start(&self) -> DVec2 {
        match *self {
            Segment::Line(p, _) | Segment::Quad(p, _, _) | Segment::Cubic(p, _, _, _) => p,
        }
    }

    pub fn end(&self) -> DVec2 {
        match *self {
            Segment::Line(_, p) | Segment::Quad(_, _, p) | Segment::Cubic(_, _, _, p) => p,
        }
    }

    /// The segment with every control point mapped by `f`.
    pub fn map(&self, f: impl Fn(DVec2) -> DVec2) -> Segment {
        match *self {
            Segment::Line(a, b) => Segment::Line(f(a), f(b)),
            Segment::Quad(a, b, c) => Segment::Quad(f(a), f(b), f(c)),
            Segment::Cubic(a, b, c, d) => Segment::Cubic(f(a), f(b), f(c), f(d)),
        }
    }

    /// Calls `f` on points along the segment, after its start and ending exactly at its
    /// end, such that the polyline is within `tolerance` of the curve (Wang's bound,
    /// guaranteed, not estimated).
    pub fn flatten(&self, tolerance: f64, f: &mut impl FnMut(DVec2)) {
        match *self {
            Segment::Line(_, b) => f(b),
            // Degree elevation is exact, so one bounded flattener serves both degrees.
            Segment::Quad(a, b, c) => {
                Segment::Cubic(a, a + (b - a) * (2.0 / 3.0), c + (b - c) * (2.0 / 3.0), c)
                    .flatten(tolerance, f)
            }
            Segment::Cubic(a, b, c, d) => {
                lyon_cubic(a, b, c, d)
                    .for_each_flattened(tolerance, &mut |line| f(from_lyon(line.to)));
            }
        }
    }
}

pub(crate) fn to_lyon(p: DVec2) -> lyon_geom::Point<f64> {
    lyon_geom::point(p.x, p.y)
}

/// The cubic with these control points, as lyon_geom's segment.
pub(crate) fn lyon_cubic(
    p0: DVec2,
    p1: DVec2,
    p2: DVec2,
    p3: DVec2,
) -> lyon_geom::CubicBezierSegment<f64> {
    lyon_geom::CubicBezierSegment {
        from: to_lyon(p0),
        ctrl1: to_lyon(p1),
        ctrl2: to_lyon(p2),
        to: to_lyon(p3),
    }
}

pub(crate) fn from_lyon(p: lyon_geom::Point<f64>) -> DVec2 {
    DVec2::new(p.x, p.y)
}

/// A closed contour: each segment starts where the previous one ends, and the last ends
/// where the first starts.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Contour {
    pub segments: Vec<Segment>,
}

/// A glyph outline: closed contours, filled by the nonzero rule.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Outline {
    pub contours: Vec<Contour>,
}

impl Outline {
    pub fn is_empty(&self) -> bool {
        self.contours.is_empty()
    }

    pub fn segments(&self) -> impl Iterator<Item = &Segment> {
        self.contours.iter().flat_map(|c| c.segments.iter())
    }

    /// Bounds of the control points, which contain the curves (convex hull property).
    pub fn control_bounds(&self) -> Option<Rect> {
        Rect::enclosing(self.segments().flat_map(segment_points))
    }

    /// The same outline with every cubic replaced by quadratics within `tolerance`
    /// (same units as the outline). Lines and quadratics are kept as they are.
    pub fn to_quadratics(&self, tolerance: f64) -> Outline {
        Outline {
            contours: self
                .contours
                .iter()
                .map(|c| {
                    let mut segments = Vec::with_capacity(c.segments.len());
                    for s in &c.segments {
                        match *s {
                            Segment::Cubic(..) => {
                                cubic_to_quadratics(s, tolerance, &mut |q| segments.push(q))
                            }
                            other => segments.push(other),
                        }
                    }
                    Contour { segments }
                })
                .collect(),
        }
    }
}

/// Contours as one kurbo path in the same units, each closed: how the geometry meets
/// kurbo's users (the union in `merge_overlaps`, the linebender peers).
pub fn kurbo_path(contours: &[Contour]) -> kurbo::BezPath {
    let point = |p: DVec2| kurbo::Point::new(p.x, p.y);
    let mut path = kurbo::BezPath::new();
    for contour in contours {
        let Some(first) = contour.segments.first() else {
            continue;
        };
        path.move_to(point(first.start()));
        for segment in &contour.segments {
            match *segment {
                Segment::Line(_, b) => path.line_to(point(b)),
                Segment::Quad(_, c, b) => path.quad_to(point(c), point(b)),
                Segment::Cubic(_, c1, c2, b) => path.curve_to(point(c1), point(c2), point(b)),
            }
        }
        path.close_path();
    }
    path
}

/// The control points of a segment, by value.
pub fn segment_points(s: &Segment) -> impl Iterator<Item = DVec2> {
    let (pts, n): ([DVec2; 4], usize) = match *s {
        Segment::Line(a, b) => ([a, b, b, b], 2),
        Segment::Quad(a, b, c) => ([a, b, c, c], 3),
        Segment::Cubic(a, b, c, d) => ([a, b, c, d], 4),
    };
    pts.into_iter().take(n)
}

/// An axis-aligned rectangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    pub min: DVec2,
    pub max: DVec2,
}

impl Rect {
    pub fn enclosing(points: impl IntoIterator<Item = DVec2>) -> Option<Rect> {
        let mut it = points.into_iter();
        let first = it.next()?;
        Some(it.fold(
            Rect {
                min: first,
                max: first,
            },
            |r, p| Rect {
                min: r.min.min(p),
                max: r.max.max(p),
            },
        ))
    }

    pub fn union(self, other: Rect) -> Rect {
        Rect {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    pub fn size(&self) -> DVec2 {
        self.max - self.min
    }

    pub fn corners(&self) -> [DVec2; 4] {
        [
            self.min,
            DVec2::new(self.max.x, self.min.y),
            self.max,
            DVec2::new(self.min.x, self.max.y),
        ]
    }

    pub fn overlaps(&self, other: &Rect) -> bool {
        self.min.x < other.max.x
            && other.min.x < self.max.x
            && self.min.y < other.max.y
            && other.min.y < self.max.y
    }
}

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
/// square frame (`SQUARE` in shaders/winding_area.wgsl). Rotations, mirrors and scales
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
