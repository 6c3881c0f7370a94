//! A glyph's outline as the shader reads it: quadratic Béziers only, filled on their
//! right, in the seed's point layout.
//!
//! Layout, per contour of n curves (font units, y up):
//!
//! ```text
//!   prev.p0 prev.p1 | c0.p0 c0.p1 | c1.p0 c1.p1 | … | c(n-1).p0 c(n-1).p1 | end pad
//! ```
//!
//! Curve k starts at an even point index (its *slot* is that index / 2), its control
//! point follows, and its end is the next curve's start. The two leading points repeat
//! the contour's last curve, so `points[i - 2]` is the previous curve's start for every
//! curve — the estimate's tie-break reads it — and the trailing pad keeps the next
//! contour on an even index.

use glam::DVec2;

use crate::camera::Camera;
use crate::geometry::{Outline, Segment};
use crate::reference;
use crate::scene::Scene;

/// A quadratic Bézier: start, control, end.
pub type Quad = [DVec2; 3];

#[derive(Clone, Debug, Default, PartialEq)]
pub struct CurveLayout {
    /// The points, two per slot (see the module comment).
    pub points: Vec<DVec2>,
    /// The slot of every curve, in outline order.
    pub curve_slots: Vec<u32>,
    /// For every slot, the contour it holds a curve of (`None` for the prefix and end
    /// slots, which hold no curve): runs of the packed encoding stay within a contour.
    pub slot_contour: Vec<Option<u32>>,
}

impl CurveLayout {
    /// Lays out `outline` (cubics must already be quadratics). Lines become quadratics
    /// with the control point at their midpoint; segments of zero length are dropped
    /// (they bound nothing); contours are turned so that the fill lies on the right of
    /// every curve, as the seed's signed distance assumes.
    pub fn new(outline: &Outline) -> CurveLayout {
        let mut contours: Vec<Vec<Quad>> = outline
            .contours
            .iter()
            .map(|c| c.segments.iter().filter_map(as_quad).collect::<Vec<_>>())
            .filter(|c: &Vec<Quad>| !c.is_empty())
            .collect();
        // Nonzero fill puts the inside on the left of counter-clockwise (positive area)
        // outer contours, as CFF fonts draw them; TrueType draws them clockwise. One
        // orientation per glyph, from its total signed area.
        if contours.iter().map(|c| signed_area(c)).sum::<f64>() > 0.0 {
            for contour in &mut contours {
                contour.reverse();
                for q in contour.iter_mut() {
                    q.reverse();
                }
            }
        }
        let mut layout = CurveLayout::default();
        for (index, contour) in contours.iter().enumerate() {
            let last = contour[contour.len() - 1];
            layout.push_slot([last[0], last[1]], None);
            for q in contour {
                layout.curve_slots.push((layout.points.len() / 2) as u32);
                layout.push_slot([q[0], q[1]], Some(index as u32));
            }
            layout.push_slot([last[2], last[2]], None);
        }
        layout
    }

    fn push_slot(&mut self, points: [DVec2; 2], contour: Option<u32>) {
        self.points.extend(points);
        self.slot_contour.push(contour);
    }

    /// The curve starting at `slot`.
    pub fn curve(&self, slot: u32) -> Quad {
        let i = 2 * slot as usize;
        [self.points[i], self.points[i + 1], self.points[i + 2]]
    }

    /// Every curve with its slot.
    pub fn curves(&self) -> impl Iterator<Item = (u32, Quad)> + '_ {
        self.curve_slots.iter().map(|&s| (s, self.curve(s)))
    }

    pub fn slots(&self) -> u32 {
        self.slot_contour.len() as u32
    }
}

/// A segment as a quadratic; `None` for one of zero length (in f32). Cubics are not expected
/// here (the caller converts them) but are reduced to their endpoints' line rather than
/// dropped if one slips through.
fn as_quad(segment: &Segment) -> Option<Quad> {
    let q = match *segment {
        Segment::Line(a, b) => [a, (a + b) * 0.5, b],
        Segment::Quad(a, b, c) => [a, b, c],
        Segment::Cubic(a, _, _, d) => {
            debug_assert!(false, "cubics are converted before layout");
            [a, (a + d) * 0.5, d]
        }
    };
    // Zero length as the GPU sees it, in f32: a curve whose points differ only in f64
    // would reach the shader as a point, whose tangent direction is NaN.
    let seen = q.map(|p| p.as_vec2());
    (seen[0] != seen[1] || seen[1] != seen[2]).then_some(q)
}

/// Whether contours of `outline` (cubics converted already) overlap, or one crosses
/// itself: then the nonzero rule fills less than the contours' signed areas add up to,
/// and the distance to the nearest curve is wrong near the curves inside the fill (a
/// known weakness of distance fields). Measured with the exact reference at 512 px
/// across the glyph, whose area is good to about 1e-6: a difference of 1e-4 of the area
/// counts, so that the small folds variable fonts leave at joins (Inter's 'G' has one
/// of 0.04%) count too.
pub fn overlapping_contours(outline: &Outline) -> bool {
    let Some(bounds) = outline.control_bounds() else {
        return false;
    };
    let contours: Vec<Vec<Quad>> = outline
        .contours
        .iter()
        .map(|c| c.segments.iter().filter_map(as_quad).collect())
        .collect();
    let signed: f64 = contours.iter().map(|c| signed_area(c)).sum();
    // An em as large as the glyph, drawn 512 pixels across.
    let extent = bounds.size().max_element().max(1e-9);
    let scene = Scene::from_outlines(extent, vec![(outline.clone(), DVec2::ZERO)]);
    let scale = 512.0 / extent;
    let camera = Camera::new(
        (bounds.size().x * scale).ceil() as u32 + 4,
        (bounds.size().y * scale).ceil() as u32 + 4,
        512.0,
        DVec2::new(2.0 - bounds.min.x * scale, 2.0 + bounds.max.y * scale),
    );
    let filled = reference::rasterize(&scene, &camera).map_or(0.0, |image| image.sum());
    let filled = filled / (scale * scale);
    (filled - signed.abs()).abs() > 1e-4 * filled.max(signed.abs())
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Contour;

    fn square(clockwise: bool) -> Outline {
        let mut p = [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]
            .map(|(x, y)| DVec2::new(x, y))
            .to_vec();
        if clockwise {
            p.reverse();
        }
        Outline {
            contours: vec![Contour {
                segments: (0..4)
                    .map(|k| Segment::Line(p[k], p[(k + 1) % 4]))
                    .collect(),
            }],
        }
    }

    /// Zero length is judged in f32, the precision the shader sees: a segment 1e-7 units
    /// long at 14 units is one point there (its tangent would be NaN) and is dropped,
    /// while one that is distinct in f32 is kept.
    #[test]
    fn curves_that_are_points_in_f32_are_dropped() {
        let start = DVec2::new(14.0, 14.0);
        let collapsed = Segment::Line(start, start + DVec2::new(1e-7, 0.0));
        assert_ne!(start, start + DVec2::new(1e-7, 0.0), "distinct in f64");
        assert!(as_quad(&collapsed).is_none());
        let short = Segment::Line(start, start + DVec2::new(1e-3, 0.0));
        assert!(as_quad(&short).is_some());
        let point = Segment::Quad(start, start, start);
        assert!(as_quad(&point).is_none());
    }

    #[test]
    fn layout_puts_curves_on_even_points_after_their_predecessor() {
        let layout = CurveLayout::new(&square(true));
        // One contour of 4 curves: prefix slot, 4 curve slots, end slot.
        assert_eq!(layout.slots(), 6);
        assert_eq!(layout.curve_slots, vec![1, 2, 3, 4]);
        for (k, &slot) in layout.curve_slots.iter().enumerate() {
            let i = 2 * slot as usize;
            let previous = layout.curve_slots[(k + 3) % 4];
            assert_eq!(layout.points[i - 2], layout.curve(previous)[0]);
            let next = layout.curve_slots[(k + 1) % 4];
            assert_eq!(layout.curve(slot)[2], layout.curve(next)[0], "closed");
        }
    }

    #[test]
    fn fill_ends_up_on_the_right_whatever_the_font_drew() {
        for clockwise in [false, true] {
            let layout = CurveLayout::new(&square(clockwise));
            let curves: Vec<Quad> = layout.curves().map(|(_, q)| q).collect();
            assert!(signed_area(&curves) < 0.0, "clockwise={clockwise}");
            assert!((signed_area(&curves) + 100.0).abs() < 1e-12);
        }
    }

    #[test]
    fn parabola_area_is_two_thirds_of_its_triangle() {
        // y = x(2 - x)·… : the chord (0,0)-(2,0) and control (1,2) enclose 4/3.
        let q = [DVec2::ZERO, DVec2::new(1.0, 2.0), DVec2::new(2.0, 0.0)];
        let back = [DVec2::new(2.0, 0.0), DVec2::new(1.0, 0.0), DVec2::ZERO];
        assert!((signed_area(&[q, back]) + 4.0 / 3.0).abs() < 1e-12);
    }

    #[test]
    fn overlaps_are_told_from_holes() {
        let square = |x: f64, y: f64, clockwise: bool| {
            let mut p = [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]
                .map(|(a, b)| DVec2::new(a + x, b + y))
                .to_vec();
            if clockwise {
                p.reverse();
            }
            Contour {
                segments: (0..4)
                    .map(|k| Segment::Line(p[k], p[(k + 1) % 4]))
                    .collect(),
            }
        };
        let outline = |contours| Outline { contours };
        let ring = {
            // A hole: a smaller square inside, the other way round.
            let mut hole = square(0.0, 0.0, true);
            for s in &mut hole.segments {
                *s = s.map(|p| p * 0.5 + DVec2::splat(2.5));
            }
            outline(vec![square(0.0, 0.0, false), hole])
        };
        assert!(!overlapping_contours(&ring));
        assert!(!overlapping_contours(&outline(vec![
            square(0.0, 0.0, false),
            square(20.0, 0.0, false)
        ])));
        assert!(overlapping_contours(&outline(vec![
            square(0.0, 0.0, false),
            square(5.0, 5.0, false)
        ])));
    }

    #[test]
    fn zero_length_segments_are_dropped() {
        let mut outline = square(false);
        let p = DVec2::new(10.0, 0.0);
        outline.contours[0].segments.insert(1, Segment::Line(p, p));
        assert_eq!(CurveLayout::new(&outline).curve_slots.len(), 4);
    }
}
