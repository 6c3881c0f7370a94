//! Overlap removal: a glyph's outline replaced by the nonzero union of its contours,
//! as curves. The union fills exactly the region the nonzero rule fills, so no pixel of
//! the exact answer changes; what changes is that every point of the result winds 0 or
//! 1 and no two contours cross or nest the same way. A method that reads an outline
//! locally, as a distance estimate does, needs that (kocsis1david's font-demo asks for
//! overlapping contours to be merged first).
//!
//! The union comes from `linesweeper` (Joe Neeman's robust sweep-line, on kurbo paths):
//! it keeps lines, quadratics and cubics as they are, splitting them only where
//! contours meet, and it is built to survive touching and tangent contours and
//! near-degenerate curves, the way variable fonts' overlaps come. (`i_overlay` works on
//! polygons, so curves would be flattened and refitted; `flo_curves` has Bézier booleans
//! but no robustness argument for coincident edges.)

use glam::DVec2;
use kurbo::{BezPath, PathEl, Shape};
use linesweeper::{BinaryOp, FillRule};

use super::outline::{Contour, Outline, kurbo_path};
use super::segment::Segment;

/// How much the union's area may differ from the sum of the contours' areas, in em²,
/// before the glyph counts as overlapping when its contours are as many as the union's
/// (a fold of one contour over itself): above the union's own rounding (its curves are
/// the input's, split in f64, good to about 1e-15 of the area), and at 10⁶ px/em, the
/// largest size, still 1e-6 of a pixel.
const SAME_AREA_EM2: f64 = 1e-12;

/// The nonzero union of `outline`'s contours, when it differs from the outline: when
/// contours overlap, cross or fold over themselves, nest the same way, share an edge or
/// have no area (the union has fewer or more contours, or less area). `None` when the
/// outline is already its own union (the usual glyph: outer contours and their holes,
/// nothing crossing), and then it is kept exactly as it is. (Orientation alone is not a
/// difference: the union turns every contour its own way, which a method that needs one
/// way sets itself.)
pub fn merge_overlaps(outline: &Outline, units_per_em: f64) -> Result<Option<Outline>, String> {
    if outline.is_empty() {
        return Ok(None);
    }
    let path = kurbo_path(&outline.contours);
    let union = linesweeper::binary_op(&path, &BezPath::new(), FillRule::NonZero, BinaryOp::Union)
        .map_err(|e| format!("the outline's union failed: {e}"))?;
    let contours: Vec<BezPath> = union.into_contours().map(|c| c.path).collect();
    let area = |paths: &mut dyn Iterator<Item = f64>| paths.map(f64::abs).sum::<f64>();
    let before = area(&mut outline.contours.iter().map(|c| contour_path(c).area()));
    let after = area(&mut contours.iter().map(|c| c.area()));
    let same_area = (before - after).abs() <= SAME_AREA_EM2 * units_per_em * units_per_em;
    if same_area && contours.len() == outline.contours.len() {
        return Ok(None);
    }
    // The union's outer contours turn the way the original's largest contour does, so a
    // method that reads the fill side from the direction sees the font's convention.
    let turn = |c: &BezPath| c.area().signum();
    let largest = outline
        .contours
        .iter()
        .map(contour_path)
        .max_by(|a, b| a.area().abs().total_cmp(&b.area().abs()))
        .map_or(1.0, |c| turn(&c));
    let outer = contours
        .iter()
        .max_by(|a, b| a.area().abs().total_cmp(&b.area().abs()))
        .map_or(1.0, turn);
    let flip = largest != outer;
    Ok(Some(Outline {
        contours: contours
            .iter()
            .map(|c| {
                from_bez_path(if flip {
                    c.reverse_subpaths()
                } else {
                    c.clone()
                })
            })
            .filter(|c| !c.segments.is_empty())
            .collect(),
    }))
}

/// Whether the areas the nonzero rule fills in `a` and in `b` share more than rounding
/// (the same tolerance as [`merge_overlaps`], 1e-12 em²): two glyphs whose ink overlaps,
/// whose coverages therefore do not add. Touching along an edge or at a point shares no
/// area and is not an overlap (box-filter coverage of the two adds exactly there).
pub fn inks_overlap(a: &Outline, b: &Outline, units_per_em: f64) -> Result<bool, String> {
    if a.is_empty() || b.is_empty() {
        return Ok(false);
    }
    let both = linesweeper::binary_op(
        &kurbo_path(&a.contours),
        &kurbo_path(&b.contours),
        FillRule::NonZero,
        BinaryOp::Intersection,
    )
    .map_err(|e| format!("the outlines' intersection failed: {e}"))?;
    // Each contour of the result bounds area or, nested in one, a hole.
    let area: f64 = both
        .into_contours()
        .map(|c| c.path.area().abs() * if c.outer { 1.0 } else { -1.0 })
        .sum();
    Ok(area > SAME_AREA_EM2 * units_per_em * units_per_em)
}

fn vec(p: kurbo::Point) -> DVec2 {
    DVec2::new(p.x, p.y)
}

fn contour_path(contour: &Contour) -> BezPath {
    kurbo_path(std::slice::from_ref(contour))
}

/// One closed kurbo subpath as a contour (its closing line made explicit).
fn from_bez_path(path: BezPath) -> Contour {
    let mut segments = Vec::new();
    let (mut start, mut at) = (DVec2::ZERO, DVec2::ZERO);
    for element in path.elements() {
        match *element {
            PathEl::MoveTo(p) => {
                start = vec(p);
                at = start;
            }
            PathEl::LineTo(p) => {
                segments.push(Segment::Line(at, vec(p)));
                at = vec(p);
            }
            PathEl::QuadTo(c, p) => {
                segments.push(Segment::Quad(at, vec(c), vec(p)));
                at = vec(p);
            }
            PathEl::CurveTo(c1, c2, p) => {
                segments.push(Segment::Cubic(at, vec(c1), vec(c2), vec(p)));
                at = vec(p);
            }
            PathEl::ClosePath => {
                if at != start {
                    segments.push(Segment::Line(at, start));
                }
                at = start;
            }
        }
    }
    Contour { segments }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A square, counter-clockwise (y up).
    fn square(x0: f64, y0: f64, side: f64) -> Contour {
        let p = [
            (x0, y0),
            (x0 + side, y0),
            (x0 + side, y0 + side),
            (x0, y0 + side),
        ]
        .map(|(x, y)| DVec2::new(x, y));
        Contour {
            segments: (0..4)
                .map(|i| Segment::Line(p[i], p[(i + 1) % 4]))
                .collect(),
        }
    }

    /// Two unit-100 squares overlapping by a 50×50 corner: one contour of area
    /// 2·100² − 50² = 17 500, hand-worked.
    #[test]
    fn overlapping_squares_become_one_contour_of_their_union_area() {
        let outline = Outline {
            contours: vec![square(0.0, 0.0, 100.0), square(50.0, 50.0, 100.0)],
        };
        let merged = merge_overlaps(&outline, 1000.0)
            .unwrap()
            .expect("they overlap");
        assert_eq!(merged.contours.len(), 1);
        let area = contour_path(&merged.contours[0]).area();
        assert!((area - 17_500.0).abs() < 1e-6, "{area}");
        // Turned as the input's largest contour was.
        assert_eq!(
            area.signum(),
            contour_path(&square(0.0, 0.0, 100.0)).area().signum()
        );
    }

    /// A glyph with a hole (an outer square and an inner one wound the other way) is
    /// its own union: kept as it is.
    #[test]
    fn a_glyph_with_a_hole_is_kept_as_it_is() {
        let hole = square(25.0, 25.0, 50.0).reversed();
        let outline = Outline {
            contours: vec![square(0.0, 0.0, 100.0), hole],
        };
        assert_eq!(merge_overlaps(&outline, 1000.0).unwrap(), None);
    }

    /// Two glyphs' ink overlaps where their fills share area: a corner overlap does;
    /// squares side by side sharing an edge, squares apart, and a square inside
    /// another's hole (wound the other way) do not.
    #[test]
    fn inks_overlap_where_fills_share_area() {
        let one = |c: Contour| Outline { contours: vec![c] };
        let a = one(square(0.0, 0.0, 100.0));
        let overlaps = |b: &Outline| inks_overlap(&a, b, 1000.0).unwrap();
        assert!(overlaps(&one(square(50.0, 50.0, 100.0))));
        assert!(!overlaps(&one(square(100.0, 0.0, 100.0))));
        assert!(!overlaps(&one(square(300.0, 0.0, 100.0))));
        let hole = square(25.0, 25.0, 100.0).reversed();
        // The ring: the square -100..300 with the hole 25..125 on both axes.
        let ring = Outline {
            contours: vec![square(-100.0, -100.0, 400.0), hole],
        };
        let inside = one(square(50.0, 50.0, 50.0));
        assert!(!inks_overlap(&ring, &inside, 1000.0).unwrap());
        assert!(inks_overlap(&ring, &a, 1000.0).unwrap());
    }

    /// Curves survive the union as curves: a square with a quadratic bump, overlapped by
    /// a square, keeps its quadratic.
    #[test]
    fn curves_stay_curves() {
        let bump = Contour {
            segments: vec![
                Segment::Line(DVec2::new(0.0, 0.0), DVec2::new(100.0, 0.0)),
                Segment::Quad(
                    DVec2::new(100.0, 0.0),
                    DVec2::new(150.0, 50.0),
                    DVec2::new(100.0, 100.0),
                ),
                Segment::Line(DVec2::new(100.0, 100.0), DVec2::new(0.0, 100.0)),
                Segment::Line(DVec2::new(0.0, 100.0), DVec2::new(0.0, 0.0)),
            ],
        };
        let outline = Outline {
            contours: vec![bump, square(-25.0, 25.0, 50.0)],
        };
        let merged = merge_overlaps(&outline, 1000.0)
            .unwrap()
            .expect("they overlap");
        let quads = merged
            .segments()
            .filter(|s| matches!(s, Segment::Quad(..)))
            .count();
        assert_eq!(quads, 1);
        // 100² + the bump (a parabolic segment: 2/3 of its chord, 100, times its height,
        // 25: half the control point's 50) + the square's 25×50 outside.
        let area: f64 = merged
            .contours
            .iter()
            .map(|c| contour_path(c).area().abs())
            .sum();
        let expected = 10_000.0 + 2.0 / 3.0 * 100.0 * 25.0 + 1_250.0;
        assert!((area - expected).abs() < 1e-6, "{area} vs {expected}");
    }
}
