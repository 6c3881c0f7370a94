//! The outline's segments: lines, quadratics and cubics, with their control points, and
//! how they meet lyon_geom, which evaluates, splits and flattens them.

use glam::DVec2;

use super::quadratic::{Quad, line_as_quad};

/// One outline segment in font units (or any 2D space), y up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Segment {
    Line(DVec2, DVec2),
    Quad(DVec2, DVec2, DVec2),
    Cubic(DVec2, DVec2, DVec2, DVec2),
}

impl Segment {
    /// Where the segment starts.
    pub fn start(&self) -> DVec2 {
        match *self {
            Segment::Line(p, _) | Segment::Quad(p, _, _) | Segment::Cubic(p, _, _, _) => p,
        }
    }

    /// Where the segment ends.
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

    /// The segment as a quadratic Bézier: a line as the quadratic running along it
    /// ([`line_as_quad`]), a quadratic as it is; `None` for a cubic, which needs a
    /// conversion (`cubic_to_quadratics`).
    pub fn as_quad(&self) -> Option<Quad> {
        match *self {
            Segment::Line(a, b) => Some(line_as_quad(a, b)),
            Segment::Quad(a, b, c) => Some([a, b, c]),
            Segment::Cubic(..) => None,
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

/// The control points of a segment, by value.
pub fn segment_points(s: &Segment) -> impl Iterator<Item = DVec2> {
    let (pts, n): ([DVec2; 4], usize) = match *s {
        Segment::Line(a, b) => ([a, b, b, b], 2),
        Segment::Quad(a, b, c) => ([a, b, c, c], 3),
        Segment::Cubic(a, b, c, d) => ([a, b, c, d], 4),
    };
    pts.into_iter().take(n)
}

/// The point as lyon_geom's.
pub fn to_lyon(p: DVec2) -> lyon_geom::Point<f64> {
    lyon_geom::point(p.x, p.y)
}

/// The cubic with these control points, as lyon_geom's segment.
pub fn lyon_cubic(
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

/// The quadratic as lyon_geom's segment.
pub fn lyon_quad(q: Quad) -> lyon_geom::QuadraticBezierSegment<f64> {
    lyon_geom::QuadraticBezierSegment {
        from: to_lyon(q[0]),
        ctrl: to_lyon(q[1]),
        to: to_lyon(q[2]),
    }
}

/// lyon_geom's point as ours.
pub fn from_lyon(p: lyon_geom::Point<f64>) -> DVec2 {
    DVec2::new(p.x, p.y)
}
