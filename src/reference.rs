//! The exact CPU reference: box-filter coverage of every pixel under the nonzero rule,
//! in f64. Every error figure in the project is measured against it.
//!
//! How it is exact:
//! 1. Curves are flattened with a guaranteed chord error (Wang's bound) of
//!    `tolerance_px`; the area this moves in a pixel is at most the tolerance times the
//!    length of outline inside it — under 1/4096 for any real glyph at the default.
//! 2. Each pixel row is cut into horizontal strips at every edge endpoint and every
//!    crossing of two edges inside the row. Within a strip no edges cross, so sorting
//!    them by x and summing their directions gives the winding number of every region
//!    between neighbours; regions with nonzero winding are trapezoids.
//! 3. A trapezoid's area in each pixel column is integrated in closed form.
//!
//! Nothing is sampled, so overlapping and self-intersecting contours are as exact as
//! simple ones — where signed-area accumulation (FreeType, font-rs) double-counts.
//!
//! Instances whose image-space bounds do not overlap are rasterized separately (their
//! areas add exactly), which keeps each strip's edge list short on a page of text.

use glam::{DMat3, DVec2};

use crate::Error;
use crate::camera::Camera;
use crate::coverage::CoverageImage;
use crate::geometry::{
    DEFAULT_QUAD_TOLERANCE_EM, Outline, Rect, Segment, jacobian_bound, overlapping_groups, project,
    segment_points, signed_area,
};
use crate::scene::Scene;

/// Default flattening tolerance, pixels.
pub const DEFAULT_TOLERANCE_PX: f64 = 1.0 / 16384.0;

/// Rasterizes `scene` as seen by `camera` with the default tolerance.
pub fn rasterize(scene: &Scene, camera: &Camera) -> Result<CoverageImage, Error> {
    rasterize_with_tolerance(scene, camera, DEFAULT_TOLERANCE_PX)
}

pub fn rasterize_with_tolerance(
    scene: &Scene,
    camera: &Camera,
    tolerance_px: f64,
) -> Result<CoverageImage, Error> {
    camera.validate()?;
    let view = Rect {
        min: DVec2::ZERO,
        max: DVec2::new(f64::from(camera.width), f64::from(camera.height)),
    };
    let mut placed = Vec::new();
    for instance in &scene.instances {
        let glyph = &scene.glyphs[instance.glyph as usize];
        let to_image = camera.glyph_to_image(scene.units_per_em, instance.position);
        let bounds = Camera::project_bounds(&to_image, &glyph.bounds)?;
        // A closed outline wholly outside the view has winding 0 everywhere inside it.
        if bounds.overlaps(&view) {
            placed.push(Placed {
                glyph: instance.glyph as usize,
                to_image,
                bounds,
            });
        }
    }
    let mut image = CoverageImage::new(camera.width, camera.height);
    let mut rows = RowBuffers::default();
    let bounds: Vec<Rect> = placed.iter().map(|p| p.bounds).collect();
    for cluster in overlapping_groups(&bounds) {
        let mut edges = Vec::new();
        let mut bounds: Option<Rect> = None;
        for &i in &cluster {
            let p = &placed[i];
            let outline = &scene.glyphs[p.glyph].outline;
            let local_tolerance =
                tolerance_px / jacobian_bound(&p.to_image, &scene.glyphs[p.glyph].bounds);
            for segment in outline.segments() {
                add_edges(segment, &p.to_image, local_tolerance, &view, &mut edges);
            }
            bounds = Some(bounds.map_or(p.bounds, |b| b.union(p.bounds)));
        }
        if let Some(bounds) = bounds {
            sweep(&mut edges, &bounds, &mut image, &mut rows);
        }
    }
    check_coverage(&mut image)?;
    Ok(image)
}

/// How far f64 rounding of the strip areas may carry a pixel's coverage past 0 or 1.
const ROUNDING: f32 = 1e-6;

/// Snaps rounding past 0 and 1 back, and refuses anything further off: a value no
/// exact area can take is a bug to report, not to clamp away.
fn check_coverage(image: &mut CoverageImage) -> Result<(), Error> {
    for (i, v) in image.data.iter_mut().enumerate() {
        if !(-ROUNDING..=1.0 + ROUNDING).contains(v) {
            let (x, y) = (i % image.width as usize, i / image.width as usize);
            return Err(Error::Internal(format!(
                "the reference computed coverage {v} at pixel ({x}, {y}), outside [0, 1]"
            )));
        }
        *v = v.clamp(0.0, 1.0);
    }
    Ok(())
}

struct Placed {
    glyph: usize,
    to_image: DMat3,
    bounds: Rect,
}

/// A straight edge in image space with y0 < y1 and the winding direction it carries.
#[derive(Clone, Copy, Debug)]
struct Edge {
    x0: f64,
    y0: f64,
    x1: f64,
    y1: f64,
    dir: i32,
}

impl Edge {
    fn new(a: DVec2, b: DVec2) -> Option<Edge> {
        // A horizontal edge bounds no area in a horizontal sweep.
        match a.y.partial_cmp(&b.y)? {
            std::cmp::Ordering::Less => Some(Edge {
                x0: a.x,
                y0: a.y,
                x1: b.x,
                y1: b.y,
                dir: 1,
            }),
            std::cmp::Ordering::Greater => Some(Edge {
                x0: b.x,
                y0: b.y,
                x1: a.x,
                y1: a.y,
                dir: -1,
            }),
            std::cmp::Ordering::Equal => None,
        }
    }

    fn x_at(&self, y: f64) -> f64 {
        if y <= self.y0 {
            self.x0
        } else if y >= self.y1 {
            self.x1
        } else {
            self.x0 + (y - self.y0) * (self.x1 - self.x0) / (self.y1 - self.y0)
        }
    }
}

/// Flattens one segment into image-space edges, skipping what cannot affect the view.
fn add_edges(
    segment: &Segment,
    to_image: &DMat3,
    local_tolerance: f64,
    view: &Rect,
    edges: &mut Vec<Edge>,
) {
    let hull =
        Rect::enclosing(segment_points(segment).map(|p| project(to_image, p))).expect("points");
    // Above, below or right of the view: no pixel's winding (counted from the left)
    // depends on it.
    if hull.max.y <= view.min.y || hull.min.y >= view.max.y || hull.min.x >= view.max.x {
        return;
    }
    let start = project(to_image, segment.start());
    let end = project(to_image, segment.end());
    // Wholly left of the view, a curve and its chord differ by a closed loop that winds
    // zero times around every pixel: the chord is exact.
    if hull.max.x <= view.min.x {
        edges.extend(Edge::new(start, end));
        return;
    }
    let mut previous = start;
    segment.flatten(local_tolerance, &mut |p| {
        let p = project(to_image, p);
        edges.extend(Edge::new(previous, p));
        previous = p;
    });
}

/// Scratch space reused across rows and clusters.
#[derive(Default)]
struct RowBuffers {
    pieces: Vec<Piece>,
    events: Vec<f64>,
    strip: Vec<(f64, f64, f64, i32)>,
    area: Vec<f64>,
    /// Difference array: full-height coverage of the columns left of an edge.
    full: Vec<f64>,
}

/// An edge clipped to one pixel row.
#[derive(Clone, Copy, Debug)]
struct Piece {
    ya: f64,
    xa: f64,
    yb: f64,
    xb: f64,
    dir: i32,
}

impl Piece {
    fn x_at(&self, y: f64) -> f64 {
        if y <= self.ya {
            self.xa
        } else if y >= self.yb {
            self.xb
        } else {
            self.xa + (y - self.ya) * (self.xb - self.xa) / (self.yb - self.ya)
        }
    }

    fn x_range(&self) -> (f64, f64) {
        (self.xa.min(self.xb), self.xa.max(self.xb))
    }
}

/// Accumulates the nonzero coverage of `edges` into `image`, over the rows and columns
/// of `bounds` (the edges' cluster).
fn sweep(edges: &mut [Edge], bounds: &Rect, image: &mut CoverageImage, buf: &mut RowBuffers) {
    let width = image.width as i64;
    let row_start = bounds.min.y.floor().max(0.0) as i64;
    let row_end = (bounds.max.y.ceil() as i64).min(i64::from(image.height));
    let col_start = bounds.min.x.floor().max(0.0) as i64;
    let col_end = (bounds.max.x.ceil() as i64 + 1).min(width);
    if row_start >= row_end || col_start >= col_end {
        return;
    }
    let columns = (col_end - col_start) as usize;
    edges.sort_by(|a, b| a.y0.total_cmp(&b.y0));
    let mut next_edge = 0;
    let mut active: Vec<Edge> = Vec::new();
    for row in row_start..row_end {
        let (top, bottom) = (row as f64, row as f64 + 1.0);
        while next_edge < edges.len() && edges[next_edge].y0 < bottom {
            active.push(edges[next_edge]);
            next_edge += 1;
        }
        active.retain(|e| e.y1 > top);
        buf.pieces.clear();
        for e in &active {
            let (ya, yb) = (e.y0.max(top), e.y1.min(bottom));
            if yb > ya {
                buf.pieces.push(Piece {
                    ya,
                    xa: e.x_at(ya),
                    yb,
                    xb: e.x_at(yb),
                    dir: e.dir,
                });
            }
        }
        if buf.pieces.is_empty() {
            continue;
        }
        buf.area.clear();
        buf.area.resize(columns, 0.0);
        buf.full.clear();
        buf.full.resize(columns + 1, 0.0);
        row_coverage(top, bottom, col_start, buf);
        let mut full = 0.0;
        let out = &mut image.data[row as usize * image.width as usize..][..image.width as usize];
        for k in 0..columns {
            full += buf.full[k];
            out[col_start as usize + k] += (buf.area[k] + full) as f32;
        }
    }
}

/// Coverage of one row from its clipped edges, into `buf.area` / `buf.full`.
fn row_coverage(top: f64, bottom: f64, col_start: i64, buf: &mut RowBuffers) {
    let RowBuffers {
        pieces,
        events,
        strip,
        area,
        full,
    } = buf;
    events.clear();
    events.extend([top, bottom]);
    for p in pieces.iter() {
        events.extend([p.ya, p.yb]);
    }
    // Crossings: only pairs whose x ranges overlap can cross.
    pieces.sort_by(|a, b| a.x_range().0.total_cmp(&b.x_range().0));
    for (i, a) in pieces.iter().enumerate() {
        let a_max = a.x_range().1;
        for b in &pieces[i + 1..] {
            if b.x_range().0 > a_max {
                break;
            }
            let (y0, y1) = (a.ya.max(b.ya), a.yb.min(b.yb));
            if y1 <= y0 {
                continue;
            }
            let d0 = a.x_at(y0) - b.x_at(y0);
            let d1 = a.x_at(y1) - b.x_at(y1);
            if (d0 < 0.0 && d1 > 0.0) || (d0 > 0.0 && d1 < 0.0) {
                let y = y0 + (y1 - y0) * (d0 / (d0 - d1));
                if y > y0 && y < y1 {
                    events.push(y);
                }
            }
        }
    }
    events.sort_by(f64::total_cmp);
    events.dedup();
    pieces.sort_by(|a, b| a.ya.total_cmp(&b.ya));
    let mut next = 0;
    let mut active: Vec<Piece> = Vec::new();
    for w in events.windows(2) {
        let (y0, y1) = (w[0], w[1]);
        if y1 <= y0 {
            continue;
        }
        while next < pieces.len() && pieces[next].ya <= y0 {
            active.push(pieces[next]);
            next += 1;
        }
        active.retain(|p| p.yb > y0);
        // Every piece that spans part of this strip spans all of it: its ends are events.
        strip.clear();
        strip.extend(active.iter().map(|p| {
            let (xt, xb) = (p.x_at(y0), p.x_at(y1));
            ((xt + xb) * 0.5, xt, xb, p.dir)
        }));
        strip.sort_by(|a, b| a.0.total_cmp(&b.0));
        let dy = y1 - y0;
        let mut winding = 0;
        let mut left = None;
        for &(_, xt, xb, dir) in strip.iter() {
            let was_inside = winding != 0;
            winding += dir;
            match (was_inside, winding != 0) {
                (false, true) => left = Some((xt, xb)),
                (true, false) => {
                    let (lt, lb) = left.take().expect("entered before leaving");
                    add_edge_area(-1.0, lt, lb, dy, col_start, area, full);
                    add_edge_area(1.0, xt, xb, dy, col_start, area, full);
                }
                _ => {}
            }
        }
        // Edges right of the view were culled, so a span may still be open: it closes
        // beyond the last column.
        if let Some((lt, lb)) = left {
            add_edge_area(-1.0, lt, lb, dy, col_start, area, full);
            add_edge_area(1.0, f64::INFINITY, f64::INFINITY, dy, col_start, area, full);
        }
    }
}

/// Adds `sign` × ∫ clamp(x(y) − column, 0, 1) dy for every column, where x(y) runs
/// linearly from `xt` to `xb` over a strip of height `dy`: the area left of the edge in
/// each column. A span's coverage is this for its right edge minus its left edge.
fn add_edge_area(
    sign: f64,
    xt: f64,
    xb: f64,
    dy: f64,
    col_start: i64,
    area: &mut [f64],
    full: &mut [f64],
) {
    let columns = area.len() as i64;
    let (lo, hi) = (xt.min(xb), xt.max(xb));
    let first = lo.floor() as i64 - col_start;
    let last = hi.floor() as i64 - col_start;
    // Columns entirely left of the edge get the full strip height.
    let full_end = first.clamp(0, columns) as usize;
    if full_end > 0 {
        full[0] += sign * dy;
        full[full_end] -= sign * dy;
    }
    for k in first.max(0)..=last.min(columns - 1) {
        let column = (k + col_start) as f64;
        area[k as usize] += sign * dy * mean_clamp01(xt - column, xb - column);
    }
}

/// The mean of clamp(u, 0, 1) for u running linearly over [a, b], integrated piecewise
/// so that it stays exact as b − a shrinks to zero.
fn mean_clamp01(a: f64, b: f64) -> f64 {
    let (lo, hi) = (a.min(b), a.max(b));
    let length = hi - lo;
    if length == 0.0 {
        return lo.clamp(0.0, 1.0);
    }
    let mut integral = 0.0;
    let (m0, m1) = (lo.max(0.0), hi.min(1.0));
    if m1 > m0 {
        integral += (m1 - m0) * (m0 + m1) * 0.5;
    }
    let above = lo.max(1.0);
    if hi > above {
        integral += hi - above;
    }
    integral / length
}

/// Whether contours of `outline` overlap, or one crosses itself: then the nonzero rule
/// fills less than the contours' signed areas add up to (and a distance field is wrong
/// near the curves inside the fill; `aa=area`'s coverage from the winding number near
/// the curves where three levels meet). Measured with this reference at 512 px across
/// the glyph, whose area is good to about 1e-6: a difference of 1e-4 of the area
/// counts, so that the small folds variable fonts leave at joins (Inter's 'G' has one)
/// count too. The signed areas are the quadratics' (cubics converted at the project's
/// tolerance, taking the glyph's extent for an em).
pub fn overlapping_contours(outline: &Outline) -> bool {
    let Some(bounds) = outline.control_bounds() else {
        return false;
    };
    // An em as large as the glyph, drawn 512 pixels across.
    let extent = bounds.size().max_element().max(1e-9);
    let quadratic = outline.to_quadratics(DEFAULT_QUAD_TOLERANCE_EM * extent);
    let signed: f64 = quadratic
        .contours
        .iter()
        .map(|c| {
            signed_area(
                &c.segments
                    .iter()
                    .filter_map(Segment::as_quad)
                    .collect::<Vec<_>>(),
            )
        })
        .sum();
    let scene = Scene::from_outlines(extent, vec![(outline.clone(), DVec2::ZERO)]);
    let scale = 512.0 / extent;
    let camera = Camera::new(
        (bounds.size().x * scale).ceil() as u32 + 4,
        (bounds.size().y * scale).ceil() as u32 + 4,
        512.0,
        DVec2::new(2.0 - bounds.min.x * scale, 2.0 + bounds.max.y * scale),
    );
    let filled = rasterize(&scene, &camera).map_or(0.0, |image| image.sum());
    let filled = filled / (scale * scale);
    (filled - signed.abs()).abs() > 1e-4 * filled.max(signed.abs())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Contour;

    /// A square of side 10 at (x, y), its sides as lines, counter-clockwise unless
    /// `clockwise`.
    fn square(x: f64, y: f64, clockwise: bool) -> Contour {
        let mut p = [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]
            .map(|(a, b)| DVec2::new(x + a, y + b))
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

    #[test]
    fn overlaps_are_told_from_holes() {
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
        // A bow tie crosses itself: its signed areas cancel, its fill does not.
        let p = [(0.0, 0.0), (10.0, 10.0), (10.0, 0.0), (0.0, 10.0)].map(|(x, y)| DVec2::new(x, y));
        let bow_tie = Contour {
            segments: (0..4)
                .map(|k| Segment::Line(p[k], p[(k + 1) % 4]))
                .collect(),
        };
        assert!(overlapping_contours(&outline(vec![bow_tie])));
    }

    #[test]
    fn mean_clamp_pieces() {
        assert_eq!(mean_clamp01(0.25, 0.25), 0.25);
        assert_eq!(mean_clamp01(-1.0, -0.5), 0.0);
        assert_eq!(mean_clamp01(2.0, 3.0), 1.0);
        assert!((mean_clamp01(0.0, 1.0) - 0.5).abs() < 1e-15);
        assert!((mean_clamp01(-1.0, 1.0) - 0.25).abs() < 1e-15);
        assert!((mean_clamp01(0.5, 1.5) - (0.375 + 0.5) / 1.0).abs() < 1e-15);
        // Tiny intervals stay exact.
        assert!((mean_clamp01(0.3, 0.3 + 1e-15) - 0.3).abs() < 1e-14);
    }
}
