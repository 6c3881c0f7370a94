//! The subdivision of Jeff Boody's Glyph: each contour walked as TrueType points and
//! tags, each curve cut into straight steps.
//!
//! - **Fixed (FSA)**: N equal parameter steps per curve.
//! - **Adaptive (ASA)**: 1, 2, 4, 8 or 16 steps, the fewest whose average area error (below)
//!   is under the threshold; 16 when none is.
//! - **Tolerance** (not in Glyph): the fewest equal steps that keep the polyline within
//!   a distance of the curve — Wang's bound, through [`Segment::flatten`]. The caller sets
//!   the distance from pixels, which is what makes it a screen-space tolerance.
//!
//! Glyph's area error of an n-step polyline: for each step from B(ta) to B(tb), the
//! triangles fanned from B(ta) through the 16-step points inside it to B(tb) (Heron's
//! formula), summed, then divided by the length of the 16-step polyline. For n = 1, 2, 4, 8
//! this is exactly Glyph's Eabs/Length; any other n reads the same formula with its own
//! step ends. Errors are quoted as Glyph's table quotes them: with the glyph's height
//! normalised to 1000.
//!
//! Cubics (which Glyph does not support) are stepped directly, with the same rules.

use glam::DVec2;

use crate::geometry::{Contour, Outline, Segment, from_lyon, lyon_cubic};

/// Steps of Glyph's "best" subdivision, the one errors are measured against.
pub const BEST_STEPS: u32 = 16;

/// The height Glyph's errors and thresholds are normalised to (its table's glyphs were
/// 1000 units tall).
pub const GLYPH_TABLE_HEIGHT: f64 = 1000.0;

/// Ems per normalised height: Glyph's converter (font2outline) sets the em to 90% of
/// the glyph cell it normalises.
pub const GLYPH_TABLE_EM_PER_HEIGHT: f64 = 0.9;

/// A point's tag in the TrueType outline model (Glyph's `t`: 1, 0 and 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tag {
    On,
    /// A quadratic's control point.
    Conic,
    /// One of a cubic's two control points.
    Cubic,
}

/// A closed contour as the font stores it: points and their tags.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TaggedContour {
    pub points: Vec<DVec2>,
    pub tags: Vec<Tag>,
}

/// What a polyline point is, for the subdivision-points overlay.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u32)]
pub enum PointKind {
    /// An on-curve point of the outline.
    On = 0,
    /// A virtual point: the midpoint of two consecutive conic control points.
    Virtual = 1,
    /// A point inside a curve, where it was cut.
    Step = 2,
}

/// One curve of a decomposed contour, from the previous curve's end to its own.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Curve {
    pub segment: Segment,
    /// Where the curve ends: on an outline point or a virtual one.
    pub end: PointKind,
}

impl TaggedContour {
    /// The points and tags a font stores for `contour`: an on-curve point exactly halfway
    /// between two conic control points is implied, and left out as TrueType leaves it.
    pub fn from_contour(contour: &Contour) -> TaggedContour {
        let mut tagged = TaggedContour::default();
        let segments = &contour.segments;
        for (i, segment) in segments.iter().enumerate() {
            let previous = &segments[(i + segments.len() - 1) % segments.len()];
            let implied = matches!(
                (previous, segment),
                (Segment::Quad(_, a, _), Segment::Quad(_, b, _)) if (*a + *b) * 0.5 == segment.start()
            );
            if !implied {
                tagged.push(segment.start(), Tag::On);
            }
            match *segment {
                Segment::Line(..) => {}
                Segment::Quad(_, c, _) => tagged.push(c, Tag::Conic),
                Segment::Cubic(_, c1, c2, _) => {
                    tagged.push(c1, Tag::Cubic);
                    tagged.push(c2, Tag::Cubic);
                }
            }
        }
        tagged
    }

    /// Every contour of `outline`, as [`from_contour`](Self::from_contour) stores it.
    pub fn from_outline(outline: &Outline) -> Vec<TaggedContour> {
        outline.contours.iter().map(Self::from_contour).collect()
    }

    pub fn push(&mut self, point: DVec2, tag: Tag) {
        self.points.push(point);
        self.tags.push(tag);
    }

    /// Glyph's state machine: for each point p1 and its neighbours p0, p2 (wrapping
    /// around the contour), by tags (t0, t1, t2), 1 = on, 0 = conic:
    ///
    /// ```text
    /// 000  quadratic (pi, pj]     pi, pj: virtual midpoints of p0p1 and p1p2
    /// 001  quadratic (pi, p2]
    /// 01X  skip                   the curve before ended here
    /// 100  quadratic (p0, pj]
    /// 101  quadratic (p0, p2]
    /// 11X  line (p0, p1]
    /// ```
    ///
    /// Glyph's text gives 11X as "\[p2\]", but its code (and every count in its table)
    /// adds p1: p2 may be a control point. Cubics, which Glyph lacks, follow the same
    /// idea: the first of two cubic controls after an on point starts the curve
    /// (p0, p3], and every other point next to a cubic control is skipped.
    pub fn curves(&self) -> Vec<Curve> {
        let n = self.points.len();
        let mut curves = Vec::with_capacity(n);
        for i in 0..n {
            let at = |k: usize| (self.points[(i + k) % n], self.tags[(i + k) % n]);
            let ((p0, t0), (p1, t1), (p2, t2)) = (at(n - 1), at(0), at(1));
            let midpoint = |a: DVec2, b: DVec2| (a + b) * 0.5;
            match (t0, t1) {
                (Tag::On, Tag::On) => curves.push(Curve {
                    segment: Segment::Line(p0, p1),
                    end: PointKind::On,
                }),
                (_, Tag::On) => {}
                (_, Tag::Conic) => {
                    let start = if t0 == Tag::Conic {
                        midpoint(p0, p1)
                    } else {
                        p0
                    };
                    let (end, kind) = if t2 == Tag::Conic {
                        (midpoint(p1, p2), PointKind::Virtual)
                    } else {
                        (p2, PointKind::On)
                    };
                    curves.push(Curve {
                        segment: Segment::Quad(start, p1, end),
                        end: kind,
                    });
                }
                (Tag::On, Tag::Cubic) => curves.push(Curve {
                    segment: Segment::Cubic(p0, p1, p2, at(2).0),
                    end: PointKind::On,
                }),
                (_, Tag::Cubic) => {}
            }
        }
        curves
    }
}

/// How curves are cut into steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Subdivision {
    /// FSA: this many equal parameter steps per curve.
    Fixed(u32),
    /// ASA with Glyph's threshold: an average area error under threshold/10 with the
    /// height normalised to 1000 (the `thresh` of Glyph's table, 1 to 20).
    Adaptive(f64),
    /// At most this distance from the curve, in the outline's units.
    Tolerance(f64),
}

/// A glyph's contours as closed polylines: the points the subdivision emits, each
/// contour's last point closing it onto its first.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Polylines {
    pub contours: Vec<Vec<(DVec2, PointKind)>>,
    /// Glyph's area error summed over the curves (height normalised to 1000); None
    /// for the tolerance mode, whose measure is its distance.
    pub area_error: Option<f64>,
}

impl Polylines {
    /// Points emitted, as Glyph counts them.
    pub fn points(&self) -> usize {
        self.contours.iter().map(Vec::len).sum()
    }
}

/// Cuts every curve of `contours` by `mode`. `height` is the glyph height in outline
/// units that errors and thresholds are normalised against.
pub fn subdivide(contours: &[TaggedContour], mode: Subdivision, height: f64) -> Polylines {
    let to_glyph_table_units = GLYPH_TABLE_HEIGHT / height;
    let mut area_error = 0.0;
    let contours = contours
        .iter()
        .map(|contour| {
            let mut points = Vec::new();
            for curve in contour.curves() {
                let mut emit = |p: DVec2| points.push((p, PointKind::Step));
                match (curve.segment, mode) {
                    (Segment::Line(_, end), _) => emit(end),
                    (segment, Subdivision::Tolerance(distance)) => {
                        segment.flatten(distance, &mut emit)
                    }
                    (segment, Subdivision::Fixed(steps)) => {
                        area_error += average_area_error(&segment, steps) * to_glyph_table_units;
                        emit_steps(&segment, steps, &mut emit);
                    }
                    (segment, Subdivision::Adaptive(threshold)) => {
                        let (steps, error) =
                            adaptive_steps(&segment, threshold / to_glyph_table_units / 10.0);
                        area_error += error * to_glyph_table_units;
                        emit_steps(&segment, steps, &mut emit);
                    }
                }
                // Every path above ends exactly on the curve's end point.
                points.last_mut().expect("a curve emits its end").1 = curve.end;
            }
            points
        })
        .collect();
    Polylines {
        contours,
        area_error: (!matches!(mode, Subdivision::Tolerance(_))).then_some(area_error),
    }
}

/// Glyph's ASA choice for one curve: the fewest of 1, 2, 4, 8 steps whose average
/// area error is under `threshold` (outline units), with that error; else 16 and 0.
fn adaptive_steps(curve: &Segment, threshold: f64) -> (u32, f64) {
    [1, 2, 4, 8]
        .into_iter()
        .map(|steps| (steps, average_area_error(curve, steps)))
        .find(|&(_, error)| error < threshold)
        .unwrap_or((BEST_STEPS, 0.0))
}

/// B(i/steps) for i = 1..=steps, ending exactly on the curve's end point.
fn emit_steps(curve: &Segment, steps: u32, emit: &mut impl FnMut(DVec2)) {
    for i in 1..steps {
        emit(evaluate(curve, f64::from(i) / f64::from(steps)));
    }
    emit(curve.end());
}

/// Glyph's average area error of cutting `curve` into `steps` equal parameter steps
/// (see the module docs), in outline units.
pub fn average_area_error(curve: &Segment, steps: u32) -> f64 {
    let best: Vec<DVec2> = (0..=BEST_STEPS)
        .map(|j| evaluate(curve, f64::from(j) / f64::from(BEST_STEPS)))
        .collect();
    let length: f64 = best.windows(2).map(|w| w[0].distance(w[1])).sum();
    if length == 0.0 {
        return 0.0;
    }
    let mut area = 0.0;
    for k in 0..steps {
        let from = evaluate(curve, f64::from(k) / f64::from(steps));
        let to = evaluate(curve, f64::from(k + 1) / f64::from(steps));
        // 16-step points strictly inside this step: k/steps < j/16 < (k+1)/steps.
        let inside = (1..BEST_STEPS)
            .filter(|j| j * steps > k * BEST_STEPS && j * steps < (k + 1) * BEST_STEPS)
            .map(|j| best[j as usize]);
        let fan: Vec<DVec2> = inside.chain([to]).collect();
        area += fan.windows(2).map(|w| heron(from, w[0], w[1])).sum::<f64>();
    }
    area / length
}

/// The curve's point at parameter t. Quadratics as Glyph writes them:
/// B(t) = P1 + (1−t)²(P0 − P1) + t²(P2 − P1).
fn evaluate(curve: &Segment, t: f64) -> DVec2 {
    match *curve {
        Segment::Line(a, b) => a.lerp(b, t),
        Segment::Quad(p0, p1, p2) => p1 + (1.0 - t) * (1.0 - t) * (p0 - p1) + t * t * (p2 - p1),
        Segment::Cubic(p0, p1, p2, p3) => from_lyon(lyon_cubic(p0, p1, p2, p3).sample(t)),
    }
}

/// A triangle's area from its sides (Heron's formula), as Glyph computes it.
fn heron(a: DVec2, b: DVec2, c: DVec2) -> f64 {
    let (x, y, z) = (a.distance(b), b.distance(c), c.distance(a));
    let s = (x + y + z) / 2.0;
    // Rounding can make a degenerate triangle's product slightly negative.
    (s * (s - x) * (s - y) * (s - z)).max(0.0).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> DVec2 {
        DVec2::new(x, y)
    }

    #[test]
    fn tags_round_trip_through_the_state_machine() {
        // Two quadratics meeting at an implied midpoint, a line, a cubic.
        let (a, c1, m, c2, b, e) = (
            v(0.0, 0.0),
            v(10.0, 20.0),
            v(20.0, 20.0),
            v(30.0, 20.0),
            v(40.0, 0.0),
            v(20.0, -10.0),
        );
        let contour = Contour {
            segments: vec![
                Segment::Quad(a, c1, m),
                Segment::Quad(m, c2, b),
                Segment::Line(b, e),
                Segment::Cubic(e, v(15.0, -10.0), v(5.0, -5.0), a),
            ],
        };
        let tagged = TaggedContour::from_contour(&contour);
        use Tag::*;
        assert_eq!(tagged.tags, [On, Conic, Conic, On, On, Cubic, Cubic]);
        let curves = tagged.curves();
        let segments: Vec<Segment> = curves.iter().map(|c| c.segment).collect();
        assert_eq!(segments, contour.segments);
        assert_eq!(
            curves
                .iter()
                .filter(|c| c.end == PointKind::Virtual)
                .count(),
            1
        );
    }

    #[test]
    fn a_contour_of_only_control_points_is_all_virtual_midpoints() {
        // TrueType allows a circle stored as four conic points and no on point.
        let mut tagged = TaggedContour::default();
        for p in [v(1.0, 0.0), v(0.0, 1.0), v(-1.0, 0.0), v(0.0, -1.0)] {
            tagged.push(p, Tag::Conic);
        }
        let curves = tagged.curves();
        assert_eq!(curves.len(), 4);
        assert!(curves.iter().all(|c| c.end == PointKind::Virtual));
        for w in curves.windows(2) {
            assert_eq!(w[0].segment.end(), w[1].segment.start());
        }
    }

    #[test]
    fn area_error_is_the_area_between_the_polylines() {
        // A parabola: the one-step error is the area between the chord and the 16-step
        // polyline over its length; that area is close to the exact segment area, 2/3 of
        // the control triangle's 200.
        let q = Segment::Quad(v(0.0, 0.0), v(10.0, 20.0), v(20.0, 0.0));
        let best: Vec<DVec2> = (0..=16)
            .map(|j| evaluate(&q, f64::from(j) / 16.0))
            .collect();
        let length: f64 = best.windows(2).map(|w| w[0].distance(w[1])).sum();
        let shoelace = best
            .iter()
            .zip(best.iter().cycle().skip(1))
            .map(|(a, b)| a.perp_dot(*b))
            .sum::<f64>()
            .abs()
            / 2.0;
        assert!((average_area_error(&q, 1) * length - shoelace).abs() < 1e-9);
        // 16 steps leave 1/256 of it out.
        assert!((shoelace - 400.0 / 3.0 * (1.0 - 1.0 / 256.0)).abs() < 1e-9);
        // Finer steps, smaller error; the best has none.
        let errors: Vec<f64> = [1, 2, 3, 4, 8, 16]
            .map(|n| average_area_error(&q, n))
            .to_vec();
        assert!(errors.windows(2).all(|w| w[1] < w[0]), "{errors:?}");
        assert_eq!(average_area_error(&q, 16), 0.0);
        assert_eq!(average_area_error(&q, 32), 0.0);
    }

    #[test]
    fn tolerance_mode_stays_within_its_distance() {
        let cubic = Segment::Cubic(
            v(0.0, 0.0),
            v(400.0, 800.0),
            v(600.0, -800.0),
            v(1000.0, 0.0),
        );
        let mut tagged = TaggedContour::default();
        for (p, t) in [
            (v(0.0, 0.0), Tag::On),
            (v(400.0, 800.0), Tag::Cubic),
            (v(600.0, -800.0), Tag::Cubic),
            (v(1000.0, 0.0), Tag::On),
        ] {
            tagged.push(p, t);
        }
        for distance in [10.0, 1.0, 0.1] {
            let polylines = subdivide(&[tagged.clone()], Subdivision::Tolerance(distance), 1000.0);
            // The closing line ends on the cubic's start; the cubic's steps follow.
            let points = &polylines.contours[0];
            let pieces: Vec<Segment> = points
                .windows(2)
                .map(|w| Segment::Line(w[0].0, w[1].0))
                .collect();
            let error = crate::geometry::max_distance_to_cubic(&pieces, &cubic, distance / 100.0);
            assert!(error <= distance, "{error} over {distance}");
            assert!(error > distance / 8.0, "{error}: far finer than asked");
            assert_eq!(polylines.area_error, None);
        }
    }
}
