//! The outline model: a glyph is closed contours of segments, filled by the nonzero
//! rule; and the outline as a kurbo path, for kurbo's users.

use glam::DVec2;

use super::cubic::cubic_to_quadratics;
use super::quadratic::halved_until_flat;
use super::rect::Rect;
use super::segment::{Segment, segment_points};

/// A closed contour: each segment starts where the previous one ends, and the last ends
/// where the first starts.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Contour {
    pub segments: Vec<Segment>,
}

impl Contour {
    /// The contour traversed the other way: the same curves, each reversed, in reverse
    /// order (under the nonzero rule, a hole instead of a fill).
    pub fn reversed(&self) -> Contour {
        Contour {
            segments: self
                .segments
                .iter()
                .rev()
                .map(|s| match *s {
                    Segment::Line(a, b) => Segment::Line(b, a),
                    Segment::Quad(a, b, c) => Segment::Quad(c, b, a),
                    Segment::Cubic(a, b, c, d) => Segment::Cubic(d, c, b, a),
                })
                .collect(),
        }
    }
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
        self.map_segments(|s, out| match *s {
            Segment::Cubic(..) => cubic_to_quadratics(s, tolerance, &mut |q| out.push(q)),
            other => out.push(other),
        })
    }

    /// The same outline (cubics must already be quadratics) with every quadratic halved
    /// until each piece keeps within `tolerance` of its chord
    /// ([`halved_until_flat`]); lines are kept.
    pub fn halved_until_flat(&self, tolerance: f64) -> Outline {
        self.map_segments(|s, out| match *s {
            Segment::Quad(a, b, c) => halved_until_flat([a, b, c], tolerance, &mut |[p, q, r]| {
                out.push(Segment::Quad(p, q, r))
            }),
            other => out.push(other),
        })
    }

    /// Each contour with each segment replaced by what `f` pushes for it.
    fn map_segments(&self, mut f: impl FnMut(&Segment, &mut Vec<Segment>)) -> Outline {
        Outline {
            contours: self
                .contours
                .iter()
                .map(|c| {
                    let mut segments = Vec::with_capacity(c.segments.len());
                    for s in &c.segments {
                        f(s, &mut segments);
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
