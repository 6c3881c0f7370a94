//! A glyph's outline as the shader reads it: quadratic Béziers only, filled on their
//! right, in the point layout of kocsis1david's font-demo.
//!
//! Layout, per contour of n curves (font units, y up):
//!
//! ```text
//!   prev.p0 prev.p1 | c0.p0 c0.p1 | c1.p0 c1.p1 | … | c(n-1).p0 c(n-1).p1 | c0.p0 c0.p1 | c0.p2 c0.p2
//! ```
//!
//! Curve k starts at an even point index (its *slot* is that index / 2), its control
//! point follows, and its end is the next curve's start. The two leading points repeat
//! the contour's last curve and the trailing ones its first curve, so `points[i - 2 ..=
//! i]` is the previous curve and `points[i + 2 ..= i + 4]` the next one for every curve:
//! the estimate reads the corner at either end of a curve from them. The trailing slots
//! also keep the next contour on an even index.

use glam::DVec2;

use crate::geometry::{
    Contour, Outline, Quad, Segment, line_as_quad, point_at, signed_area, winding_number,
};

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
    /// with the control point at their midpoint; segments too short in f32 to have a
    /// direction are merged into the next one (`contour_quads`); each contour is
    /// turned so that the fill lies on its right, as font-demo's signed distance assumes
    /// (`turn_fill_to_the_right`).
    pub fn new(outline: &Outline) -> CurveLayout {
        let mut contours: Vec<Vec<Quad>> = outline
            .contours
            .iter()
            .map(contour_quads)
            .filter(|c| !c.is_empty())
            .collect();
        turn_fill_to_the_right(&mut contours);
        let mut layout = CurveLayout::default();
        for (index, contour) in contours.iter().enumerate() {
            let (first, last) = (contour[0], contour[contour.len() - 1]);
            debug_assert_eq!(last[2], first[0], "contours are closed");
            layout.push_slot([last[0], last[1]], None);
            for q in contour {
                layout.curve_slots.push((layout.points.len() / 2) as u32);
                layout.push_slot([q[0], q[1]], Some(index as u32));
            }
            layout.push_slot([first[0], first[1]], None);
            layout.push_slot([first[2], first[2]], None);
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

/// Curves shorter than this many f32 steps (ulps at the magnitude of their coordinates)
/// are merged into the next curve. Each coordinate reaches the GPU rounded by up to half
/// a step, so the difference of two points is off by up to a step on each axis, and a
/// chord n steps long has its direction off by up to about √2/n rad: anything at 1 or 2
/// steps, 20° at 4, 8° at 10, 5° at 16. The estimate takes the side of a pixel from that
/// direction (the chord's tangent line), so a short slanted segment at a corner whose
/// direction rounds past either neighbour's puts a wedge of pixels beyond the corner on
/// the wrong side. Below 10 steps the direction is not worth keeping, and merging moves
/// the outline by less than 10 steps: 1/1600 px for a 1000-unit em at 1000 px/em (steps
/// of 2⁻¹⁴ units between 512 and 1024), and at the largest size accepted (10⁶ px/em),
/// where f32 coordinates resolve only about 1/32 px anyway, ten times that.
const MERGED_BELOW_STEPS: f64 = 10.0;

/// A segment as a quadratic. Cubics are not expected here (the caller converts them) but
/// are reduced to their endpoints' line rather than dropped if one slips through.
fn as_quad(segment: &Segment) -> Quad {
    segment.as_quad().unwrap_or_else(|| {
        debug_assert!(false, "cubics are converted before layout");
        line_as_quad(segment.start(), segment.end())
    })
}

/// Whether the curve is too short, as the GPU sees it in f32, for its direction to mean
/// anything: its control point and end lie within [`MERGED_BELOW_STEPS`] f32 steps of its
/// start (a point in f32, whose direction is NaN, included).
fn too_short_in_f32(q: &Quad) -> bool {
    let magnitude = q
        .iter()
        .map(|p| p.as_vec2().abs().max_element())
        .fold(0.0, f32::max);
    let step = f64::from(magnitude.next_up() - magnitude);
    let reach = q[1..].iter().map(|p| p.distance(q[0])).fold(0.0, f64::max);
    reach < MERGED_BELOW_STEPS * step
}

/// A contour's segments as quadratics, with runs of curves too short in f32 to have a
/// direction merged into the curve after them: that curve starts where the run started,
/// so the chain stays closed and its winding unchanged, and the outline moves by no more
/// than the run's length. The contour is read from its first curve long enough on its
/// own, so that a run never wraps around past the end; a contour with no such curve
/// merges from its first.
fn contour_quads(contour: &Contour) -> Vec<Quad> {
    let quads: Vec<Quad> = contour.segments.iter().map(as_quad).collect();
    let first = quads.iter().position(|q| !too_short_in_f32(q)).unwrap_or(0);
    let mut kept: Vec<Quad> = Vec::with_capacity(quads.len());
    let mut run_start: Option<DVec2> = None;
    for q in quads[first..].iter().chain(&quads[..first]) {
        let merged = [run_start.unwrap_or(q[0]), q[1], q[2]];
        if too_short_in_f32(&merged) {
            run_start = Some(merged[0]);
        } else {
            kept.push(merged);
            run_start = None;
        }
    }
    if let (Some(start), Some(q)) = (run_start, kept.first_mut()) {
        q[0] = start;
    }
    kept
}

/// Turns every contour so that the filled side is on its right, as font-demo's signed
/// distance assumes, judging each contour on its own: nonzero fill lets one glyph hold
/// contours wound either way (two side by side, wound opposite ways, both fill), so the
/// glyph's total orientation cannot stand for each of them. A contour's inside is the
/// filled side when it winds the same way as the other contours around it or none do
/// (then the winding's magnitude grows across it, inward); otherwise it is a hole, filled
/// outside. Where contours overlap, the side whose winding has the larger magnitude is
/// taken as the filled one.
fn turn_fill_to_the_right(contours: &mut [Vec<Quad>]) {
    let turn: Vec<bool> = (0..contours.len())
        .map(|k| {
            let area = signed_area(&contours[k]);
            let around = winding_of_others_around(contours, k);
            let inside_filled = f64::from(around) * area >= 0.0;
            // Counter-clockwise (positive area, y up) has its inside on the left.
            inside_filled == (area > 0.0)
        })
        .collect();
    for (contour, turn) in contours.iter_mut().zip(turn) {
        if turn {
            contour.reverse();
            for q in contour.iter_mut() {
                q.reverse();
            }
        }
    }
}

/// Points of a contour sampled to find the winding of the others around it.
const WINDING_SAMPLES: usize = 7;

/// The nonzero winding number of the contours other than `k` along contour `k`: the most
/// common value at the midpoints of up to [`WINDING_SAMPLES`] of its curves, so that a
/// few points lying on another contour (shared edges, touching corners) do not decide.
fn winding_of_others_around(contours: &[Vec<Quad>], k: usize) -> i32 {
    if contours.len() < 2 {
        return 0;
    }
    let own = &contours[k];
    let stride = own.len().div_ceil(WINDING_SAMPLES);
    let mut seen: Vec<(i32, usize)> = Vec::new();
    for q in own.iter().step_by(stride) {
        let others = contours
            .iter()
            .enumerate()
            .filter(|&(j, _)| j != k)
            .flat_map(|(_, other)| other.iter());
        let w = winding_number(point_at(*q, 0.5), others);
        match seen.iter_mut().find(|(value, _)| *value == w) {
            Some((_, count)) => *count += 1,
            None => seen.push((w, 1)),
        }
    }
    seen.iter()
        .max_by_key(|&&(_, count)| count)
        .map_or(0, |&(w, _)| w)
}

#[cfg(test)]
mod tests {
    use super::*;

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

    /// A 15-unit square, counter-clockwise, whose corner (15, 15) is cut by a segment
    /// `steps` f32 steps long (2⁻²⁰ units each between 8 and 16: 23 fraction bits),
    /// slanted 3:4 off the square's sides, between points off the f32 grid.
    fn square_cut_by(steps: f64) -> Outline {
        let step = 2f64.powi(-20);
        let cut = DVec2::new(-0.6, 0.8) * steps * step;
        let from = DVec2::new(15.0, 15.0 - cut.y - 0.3 * step);
        let to = from + cut;
        Outline {
            contours: vec![Contour {
                segments: vec![
                    Segment::Line(DVec2::ZERO, DVec2::new(15.0, 0.0)),
                    Segment::Line(DVec2::new(15.0, 0.0), from),
                    Segment::Line(from, to),
                    Segment::Line(to, DVec2::new(0.0, to.y)),
                    Segment::Line(DVec2::new(0.0, to.y), DVec2::ZERO),
                ],
            }],
        }
    }

    /// Segments under 10 f32 steps are merged into the next one, longer ones kept; the
    /// chain stays closed and its area is the square's less the cut corner's (at most
    /// 16² steps²), whatever is merged.
    #[test]
    fn segments_under_ten_f32_steps_are_merged_into_the_next() {
        let step = 2f64.powi(-20);
        assert_eq!(f64::from(15f32.next_up() - 15.0), step);
        for (steps, curves) in [(1.0, 4), (2.0, 4), (4.0, 4), (8.0, 4), (16.0, 5)] {
            let layout = CurveLayout::new(&square_cut_by(steps));
            assert_eq!(layout.curve_slots.len(), curves, "{steps} steps");
            let quads: Vec<Quad> = layout.curves().map(|(_, q)| q).collect();
            for (k, q) in quads.iter().enumerate() {
                let next = quads[(k + 1) % quads.len()];
                assert_eq!(q[2], next[0], "{steps} steps: closed at curve {k}");
                assert!(q.iter().all(|p| p.is_finite()));
            }
            // Clockwise after layout (fill on the right).
            let area = -signed_area(&quads);
            assert!(
                (area - 225.0).abs() < 16.0 * 15.0 * step,
                "{steps} steps: {area}"
            );
        }
    }

    /// A segment 1e-7 units long at 14 units (0.1 f32 step) is one point in f32, where
    /// its direction would be NaN: merged, as is a quadratic that is one point in f64.
    #[test]
    fn curves_that_are_points_in_f32_are_merged() {
        let start = DVec2::new(14.0, 14.0);
        let collapsed = [
            start,
            start + DVec2::new(5e-8, 0.0),
            start + DVec2::new(1e-7, 0.0),
        ];
        assert_eq!(collapsed[0].as_vec2(), collapsed[2].as_vec2());
        assert!(too_short_in_f32(&collapsed));
        assert!(too_short_in_f32(&[start; 3]));
        let short = [
            start,
            start + DVec2::new(5e-4, 0.0),
            start + DVec2::new(1e-3, 0.0),
        ];
        assert!(!too_short_in_f32(&short), "1000 steps");
        let closed_loop = [start, start + DVec2::new(0.0, 1.0), start];
        assert!(
            !too_short_in_f32(&closed_loop),
            "a loop back to its start has extent"
        );
    }

    /// A side drawn as a chain of short segments keeps its shape: runs merge only until
    /// the merged curve is 10 steps long. A square 1024 f32 steps across (at 15 units)
    /// whose top runs right to left in 3-step segments: every 4 segments (12 steps) make
    /// one curve, 85 of them, and the last 4 steps go to the left side.
    #[test]
    fn merging_stops_once_the_run_is_long_enough() {
        let step = 2f64.powi(-20);
        let (low, high) = (15.0 - 1024.0 * step, 15.0);
        let mut segments = vec![
            Segment::Line(DVec2::splat(low), DVec2::new(high, low)),
            Segment::Line(DVec2::new(high, low), DVec2::splat(high)),
        ];
        let mut x = high;
        while x > low {
            let next = (x - 3.0 * step).max(low);
            segments.push(Segment::Line(DVec2::new(x, high), DVec2::new(next, high)));
            x = next;
        }
        segments.push(Segment::Line(DVec2::new(low, high), DVec2::splat(low)));
        let layout = CurveLayout::new(&Outline {
            contours: vec![Contour { segments }],
        });
        let quads: Vec<Quad> = layout.curves().map(|(_, q)| q).collect();
        let top = quads.iter().filter(|q| q[0].y == high && q[2].y == high);
        assert_eq!(top.count(), 85);
        assert_eq!(quads.len(), 85 + 3);
        let area = -signed_area(&quads);
        let side = 1024.0 * step;
        assert!((area - side * side).abs() <= 4.0 * step * side, "{area}");
    }

    #[test]
    fn layout_puts_curves_on_even_points_after_their_predecessor() {
        let layout = CurveLayout::new(&square(true));
        // One contour of 4 curves: prefix slot, 4 curve slots, two end slots.
        assert_eq!(layout.slots(), 7);
        assert_eq!(layout.curve_slots, vec![1, 2, 3, 4]);
        for (k, &slot) in layout.curve_slots.iter().enumerate() {
            let previous = layout.curve_slots[(k + 3) % 4];
            assert_eq!(
                layout.curve(slot - 1),
                layout.curve(previous),
                "the previous curve leads"
            );
            let next = layout.curve_slots[(k + 1) % 4];
            assert_eq!(layout.curve(slot)[2], layout.curve(next)[0], "closed");
            assert_eq!(
                layout.curve(slot + 1),
                layout.curve(next),
                "the next curve follows"
            );
        }
    }

    /// A curve's neighbours sit beside it (`points[i - 2 ..= i + 4]`) in contours of two,
    /// three and four curves, one after another.
    #[test]
    fn every_curve_has_its_neighbours_beside_it() {
        let line = |a: (f64, f64), b: (f64, f64)| Segment::Line(DVec2::from(a), DVec2::from(b));
        let quad = |a: (f64, f64), c: (f64, f64), b: (f64, f64)| {
            Segment::Quad(DVec2::from(a), DVec2::from(c), DVec2::from(b))
        };
        let outline = Outline {
            contours: vec![
                Contour {
                    segments: vec![
                        line((0.0, 0.0), (60.0, 0.0)),
                        line((60.0, 0.0), (30.0, 50.0)),
                        line((30.0, 50.0), (0.0, 0.0)),
                    ],
                },
                Contour {
                    segments: vec![
                        quad((100.0, 0.0), (150.0, 60.0), (200.0, 0.0)),
                        line((200.0, 0.0), (100.0, 0.0)),
                    ],
                },
                square_at(300.0, 0.0, 50.0, false),
            ],
        };
        let layout = CurveLayout::new(&outline);
        let mut start = 0;
        for contour in [3, 2, 4] {
            let slots = &layout.curve_slots[start..start + contour];
            for (k, &slot) in slots.iter().enumerate() {
                let previous = slots[(k + contour - 1) % contour];
                let next = slots[(k + 1) % contour];
                assert_eq!(
                    layout.curve(slot - 1),
                    layout.curve(previous),
                    "{contour}: {k}"
                );
                assert_eq!(layout.curve(slot + 1), layout.curve(next), "{contour}: {k}");
            }
            start += contour;
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

    /// A square `size` units across with its corner at (x, y), either way round.
    fn square_at(x: f64, y: f64, size: f64, clockwise: bool) -> Contour {
        let mut p = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
            .map(|(a, b)| DVec2::new(x + a * size, y + b * size))
            .to_vec();
        if clockwise {
            p.reverse();
        }
        Contour {
            segments: (0..4)
                .map(|k| Segment::Line(p[k], p[(k + 1) % 4]))
                .collect(),
        }
    }

    /// Each contour is turned on its own: of two separate squares wound opposite ways
    /// (both filled under nonzero), and a ring whose outer contour and hole are wound
    /// either way, every filled contour ends up clockwise and every hole
    /// counter-clockwise, whichever way the glyph's total area points.
    #[test]
    fn each_contour_gets_the_fill_on_its_right() {
        for (big_clockwise, ring_clockwise) in [(false, false), (false, true), (true, false)] {
            let outline = Outline {
                contours: vec![
                    square_at(0.0, 0.0, 10.0, big_clockwise),
                    square_at(20.0, 0.0, 6.0, !big_clockwise),
                    square_at(40.0, 0.0, 10.0, ring_clockwise),
                    square_at(43.0, 3.0, 4.0, !ring_clockwise),
                ],
            };
            let layout = CurveLayout::new(&outline);
            let mut areas = vec![0.0; 4];
            for (slot, q) in layout.curves() {
                let contour = layout.slot_contour[slot as usize].unwrap() as usize;
                areas[contour] += signed_area(&[q]);
            }
            let expected = [-100.0, -36.0, -100.0, 16.0];
            for (area, expected) in areas.iter().zip(expected) {
                assert!(
                    (area - expected).abs() < 1e-9,
                    "big clockwise {big_clockwise}, ring clockwise {ring_clockwise}: {areas:?}"
                );
            }
        }
    }

    #[test]
    fn zero_length_segments_are_dropped() {
        let mut outline = square(false);
        let p = DVec2::new(10.0, 0.0);
        outline.contours[0].segments.insert(1, Segment::Line(p, p));
        assert_eq!(CurveLayout::new(&outline).curve_slots.len(), 4);
    }
}
