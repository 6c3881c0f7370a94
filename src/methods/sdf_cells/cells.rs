//! The grid of cells over a glyph and the curves each cell lists.
//!
//! A cell lists every curve that can be the nearest one — or lie within the tie bias
//! of the nearest — for some point of the cell. With the distance the mode uses (to the
//! chord for the estimate, to the curve for exact distances):
//!
//! - `reach` = min over curves of an *upper* bound of that curve's distance from any
//!   point of the cell: for a point q on the curve, no point of the cell is farther from
//!   it than the farthest corner, so max over corners |corner − q| bounds the distance;
//! - a curve is listed when a *lower* bound of its distance to the cell is at most
//!   `reach + bias`.
//!
//! Every point of the cell then finds its nearest curve (and every curve it ties with)
//! in the list, whatever the zoom: the list does not depend on the pixel size, unlike
//! the lists of curves crossing the cell in kocsis1david's font-demo. The bound is loose
//! by about the cell's diagonal, so a long list is tightened once to the union of its
//! quarters' lists (fewer curves per pixel). Cells are grown by a small pad first, since
//! the shader picks a point's cell in f32.
//!
//! Exact mode also needs the winding number, from a ray to +x (and the estimate, where a
//! rule rather than a tangent line gives a pixel's side): each grid row gets a band
//! of the curves whose y-range meets it, sorted by decreasing right end so the shader
//! can stop at the first curve wholly left of the pixel.

use std::ops::Range;

use glam::DVec2;
use lyon_geom::LineSegment;

use super::curves::CurveLayout;
use crate::geometry::{Quad, Rect, from_lyon, lyon_quad, to_lyon};

/// Which distance decides the nearest curve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// font-demo's estimate: nearest by distance to the chord p0–p2, signed by the
    /// tangent line there.
    Estimate,
    /// True distance to each quadratic, signed by the winding number.
    Exact,
}

/// Cells are grown by this fraction of their size before listing, to cover points that
/// f32 rounding puts in the neighbouring cell.
const CELL_PAD: f64 = 1.0 / 256.0;

/// An axis-aligned grid of `cols` × `rows` equal cells, in font units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    pub origin: DVec2,
    pub cell: DVec2,
    pub cols: u32,
    pub rows: u32,
}

impl Grid {
    /// A grid of `cols` × `rows` cells exactly covering `area`.
    pub fn covering(area: Rect, cols: u32, rows: u32) -> Grid {
        let cols = cols.max(1);
        let rows = rows.max(1);
        Grid {
            origin: area.min,
            cell: area.size() / DVec2::new(f64::from(cols), f64::from(rows)),
            cols,
            rows,
        }
    }

    pub fn cells(&self) -> usize {
        self.cols as usize * self.rows as usize
    }

    /// The cell `index` (row-major, row 0 at the bottom) as a rectangle.
    pub fn cell_rect(&self, index: usize) -> Rect {
        let (col, row) = (index % self.cols as usize, index / self.cols as usize);
        let min = self.origin + self.cell * DVec2::new(col as f64, row as f64);
        Rect {
            min,
            max: min + self.cell,
        }
    }

    /// The points cell `index` serves: its rectangle, grown by `outside` on the sides
    /// that are on the grid's border.
    pub fn served_rect(&self, index: usize, outside: f64) -> Rect {
        let (col, row) = (index as u32 % self.cols, index as u32 / self.cols);
        let mut rect = self.cell_rect(index);
        let grow = |on_border: bool| if on_border { outside } else { 0.0 };
        rect.min -= DVec2::new(grow(col == 0), grow(row == 0));
        rect.max += DVec2::new(grow(col + 1 == self.cols), grow(row + 1 == self.rows));
        rect
    }

    /// The index of the cell holding `p`, clamped to the grid like the shader does.
    pub fn cell_index(&self, p: DVec2) -> usize {
        let c = ((p - self.origin) / self.cell).floor();
        let col = c.x.clamp(0.0, f64::from(self.cols - 1)) as usize;
        let row = c.y.clamp(0.0, f64::from(self.rows - 1)) as usize;
        row * self.cols as usize + col
    }
}

/// The curves (by slot, ascending) each cell of `grid` lists, for `mode` and a tie bias
/// of `bias` font units. Cells on the grid's border also serve the points up to
/// `outside` font units beyond it (the shader clamps those to the nearest cell).
pub fn cell_lists(
    layout: &CurveLayout,
    grid: &Grid,
    mode: Mode,
    bias: f64,
    outside: f64,
) -> Vec<Vec<u32>> {
    let curves = layout
        .curves()
        .map(|(slot, q)| Candidate::new(slot, q, mode, grid))
        .collect();
    let mut lister = Lister {
        curves,
        bias,
        closest: 0,
        grid: *grid,
        outside,
        lists: vec![Vec::new(); grid.cells()],
    };
    let everything: Vec<usize> = (0..lister.curves.len()).collect();
    lister.list_block(0..grid.cols, 0..grid.rows, &everything);
    lister.lists
}

/// How many times a cell with a long list is split in four to tighten it: its list is
/// then the union of its quarters' lists, each bounded by a smaller reach.
const SPLITS: u32 = 1;
/// Lists up to this long are kept as they are.
const SHORT_LIST: usize = 4;

struct Lister {
    curves: Vec<Candidate>,
    bias: f64,
    /// The curve that bounded the last reach: it usually bounds the next one tightly
    /// too, and starting from it lets the box test skip most of the others.
    closest: usize,
    grid: Grid,
    outside: f64,
    /// The result, by cell.
    lists: Vec<Vec<u32>>,
}

impl Lister {
    /// Lists the cells of a block of the grid from `candidates`, which hold every curve
    /// they need. A block needs what its cells need (it contains them), so halving
    /// blocks down to single cells narrows the candidates as it goes: each cell looks at
    /// the curves near it rather than at the whole glyph.
    fn list_block(&mut self, cols: Range<u32>, rows: Range<u32>, candidates: &[usize]) {
        let width = self.grid.cols;
        let corner = move |col: u32, row: u32| (row * width + col) as usize;
        let first = self
            .grid
            .served_rect(corner(cols.start, rows.start), self.outside);
        let last = self
            .grid
            .served_rect(corner(cols.end - 1, rows.end - 1), self.outside);
        // Grown by the pad: the shader picks a point's cell in f32.
        let pad = self.grid.cell * CELL_PAD;
        let block = Rect {
            min: first.min - pad,
            max: last.max + pad,
        };
        if cols.len() == 1 && rows.len() == 1 {
            let mut slots: Vec<u32> = self
                .needed(block, candidates, SPLITS)
                .into_iter()
                .map(|k| self.curves[k].slot)
                .collect();
            slots.sort_unstable();
            self.lists[corner(cols.start, rows.start)] = slots;
            return;
        }
        let listed = self.needed(block, candidates, 0);
        if cols.len() >= rows.len() {
            let middle = cols.start + cols.len() as u32 / 2;
            self.list_block(cols.start..middle, rows.clone(), &listed);
            self.list_block(middle..cols.end, rows, &listed);
        } else {
            let middle = rows.start + rows.len() as u32 / 2;
            self.list_block(cols.clone(), rows.start..middle, &listed);
            self.list_block(cols, middle..rows.end, &listed);
        }
    }

    /// The curves (indices into `curves`, ascending) that can be nearest, or tie with
    /// the nearest, for some point of `cell`, among `candidates`, which must hold them.
    fn needed(&mut self, cell: Rect, candidates: &[usize], splits: u32) -> Vec<usize> {
        let corners = cell.corners();
        let mut reach = f64::INFINITY;
        if candidates.contains(&self.closest) {
            reach = self.curves[self.closest].farthest_from(&corners);
        }
        for &k in candidates {
            let c = &self.curves[k];
            // No point of a curve is nearer to the cell than its box.
            if rect_distance(&cell, &c.bounds) < reach {
                let bound = c.farthest_from(&corners);
                if bound < reach {
                    (reach, self.closest) = (bound, k);
                }
            }
        }
        let limit = reach + self.bias;
        let listed: Vec<usize> = candidates
            .iter()
            .copied()
            .filter(|&k| rect_distance(&cell, &self.curves[k].bounds) <= limit)
            .filter(|&k| self.curves[k].distance_to_rect(&cell) <= limit)
            .collect();
        if splits == 0 || listed.len() <= SHORT_LIST {
            return listed;
        }
        // A quarter needs a subset of this list: its reach is no larger (a curve left
        // out here is farther than this reach) and its distances no smaller.
        let half = cell.size() * 0.5;
        let mut union: Vec<usize> = (0..4)
            .flat_map(|k| {
                let min = cell.min + half * DVec2::new(f64::from(k & 1), f64::from(k >> 1));
                self.needed(
                    Rect {
                        min,
                        max: min + half,
                    },
                    &listed,
                    splits - 1,
                )
            })
            .collect();
        union.sort_unstable();
        union.dedup();
        union
    }
}

/// A curve as the listing sees it.
struct Candidate {
    slot: u32,
    /// Points on the curve (or chord) that bound the distance from above.
    samples: Vec<DVec2>,
    /// Segments within `slack` of the curve (or the chord itself): the distance to them
    /// minus `slack` bounds the distance from below.
    polyline: Vec<DVec2>,
    slack: f64,
    bounds: Rect,
}

impl Candidate {
    fn new(slot: u32, q: Quad, mode: Mode, grid: &Grid) -> Candidate {
        let (samples, polyline, slack) = match mode {
            Mode::Estimate => (vec![q[0], (q[0] + q[2]) * 0.5, q[2]], vec![q[0], q[2]], 0.0),
            Mode::Exact => {
                let curve = lyon_quad(q);
                let samples = [0.0, 0.25, 0.5, 0.75, 1.0]
                    .map(|t| from_lyon(curve.sample(t)))
                    .to_vec();
                // Flattening error small against a cell: it only loosens the bound.
                let slack = grid.cell.min_element() / 64.0;
                let mut polyline = vec![q[0]];
                curve.for_each_flattened(slack, &mut |line| polyline.push(from_lyon(line.to)));
                (samples, polyline, slack)
            }
        };
        let bounds =
            Rect::enclosing(polyline.iter().copied().chain(q)).expect("a curve has points");
        Candidate {
            slot,
            samples,
            polyline,
            slack,
            bounds,
        }
    }

    /// An upper bound of this curve's distance from any point of the rectangle with
    /// these corners.
    fn farthest_from(&self, corners: &[DVec2; 4]) -> f64 {
        self.samples
            .iter()
            .map(|q| corners.iter().map(|c| c.distance(*q)).fold(0.0, f64::max))
            .fold(f64::INFINITY, f64::min)
    }

    /// A lower bound of this curve's distance to `rect`.
    fn distance_to_rect(&self, rect: &Rect) -> f64 {
        let to_polyline = self
            .polyline
            .windows(2)
            .map(|w| rect_segment_distance(rect, w[0], w[1]))
            .fold(f64::INFINITY, f64::min);
        (to_polyline - self.slack).max(0.0)
    }
}

/// The winding bands (exact mode's, the estimate's with `ties=winding`): for each grid row, the curves whose control points'
/// y-range meets the row (grown by the cell pad), sorted by their right end, decreasing.
pub fn row_bands(layout: &CurveLayout, grid: &Grid) -> Vec<Vec<u32>> {
    let pad = grid.cell.y * CELL_PAD;
    let mut by_right_end: Vec<(f64, u32, Rect)> = layout
        .curves()
        .map(|(slot, q)| {
            let b = Rect::enclosing(q).expect("three points");
            (b.max.x, slot, b)
        })
        .collect();
    by_right_end.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    (0..grid.rows)
        .map(|row| {
            let low = grid.origin.y + grid.cell.y * f64::from(row) - pad;
            let high = low + grid.cell.y + 2.0 * pad;
            by_right_end
                .iter()
                .filter(|(_, _, b)| b.min.y <= high && b.max.y >= low)
                .map(|&(_, slot, _)| slot)
                .collect()
        })
        .collect()
}

/// Distance between two rectangles (0 when they meet).
fn rect_distance(a: &Rect, b: &Rect) -> f64 {
    let gap = (a.min - b.max).max(b.min - a.max).max(DVec2::ZERO);
    gap.length()
}

fn point_rect_distance(p: DVec2, rect: &Rect) -> f64 {
    (rect.min - p).max(p - rect.max).max(DVec2::ZERO).length()
}

/// Distance between a rectangle and the segment a–b (0 when they meet).
fn rect_segment_distance(rect: &Rect, a: DVec2, b: DVec2) -> f64 {
    if segment_meets_rect(rect, a, b) {
        return 0.0;
    }
    // Apart, the nearest pair has an endpoint of the segment or a corner of the
    // rectangle in it.
    let segment = LineSegment {
        from: to_lyon(a),
        to: to_lyon(b),
    };
    let from_corners = rect
        .corners()
        .map(|c| segment.distance_to_point(to_lyon(c)))
        .into_iter()
        .fold(f64::INFINITY, f64::min);
    from_corners
        .min(point_rect_distance(a, rect))
        .min(point_rect_distance(b, rect))
}

/// Whether the segment a–b meets the rectangle: Liang–Barsky clipping.
fn segment_meets_rect(rect: &Rect, a: DVec2, b: DVec2) -> bool {
    let d = b - a;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (delta, low, high, start) in [
        (d.x, rect.min.x, rect.max.x, a.x),
        (d.y, rect.min.y, rect.max.y, a.y),
    ] {
        if delta == 0.0 {
            if start < low || start > high {
                return false;
            }
            continue;
        }
        let (mut enter, mut leave) = ((low - start) / delta, (high - start) / delta);
        if enter > leave {
            std::mem::swap(&mut enter, &mut leave);
        }
        t0 = t0.max(enter);
        t1 = t1.min(leave);
        if t0 > t1 {
            return false;
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::geometry::DEFAULT_QUAD_TOLERANCE_EM;

    /// The nearest curve over the whole glyph, by the mode's distance.
    fn nearest(layout: &CurveLayout, p: DVec2, mode: Mode) -> (u32, f64) {
        layout
            .curves()
            .map(|(slot, q)| (slot, mode_distance(q, p, mode)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap()
    }

    fn mode_distance(q: Quad, p: DVec2, mode: Mode) -> f64 {
        match mode {
            Mode::Estimate => LineSegment {
                from: to_lyon(q[0]),
                to: to_lyon(q[2]),
            }
            .distance_to_point(to_lyon(p)),
            Mode::Exact => lyon_quad(q).distance_to_point(to_lyon(p)),
        }
    }

    /// Deterministic points spread over a rectangle (a 2D Halton sequence).
    fn spread(rect: &Rect, n: usize) -> impl Iterator<Item = DVec2> + '_ {
        let halton = |mut i: usize, base: usize| {
            let (mut f, mut r) = (1.0, 0.0);
            while i > 0 {
                f /= base as f64;
                r += f * (i % base) as f64;
                i /= base;
            }
            r
        };
        (1..=n).map(move |i| rect.min + rect.size() * DVec2::new(halton(i, 2), halton(i, 3)))
    }

    #[test]
    fn every_point_finds_its_nearest_curve_and_its_ties_in_its_cell() {
        let bias = 2.0;
        for (font_index, text) in [(0, "&g@S"), (1, "Qa§g"), (3, "\u{0995}")] {
            let font = crate::font::shipped(font_index);
            let tolerance = DEFAULT_QUAD_TOLERANCE_EM * font.units_per_em();
            for c in text.chars() {
                let outline = font
                    .outline(font.glyph_for_char(c).unwrap())
                    .to_quadratics(tolerance);
                let layout = CurveLayout::new(&outline);
                let bounds = outline.control_bounds().unwrap();
                // Points up to 100 units outside the grid, which the border cells serve.
                let outside = 100.0;
                let area = Rect {
                    min: bounds.min - outside,
                    max: bounds.max + outside,
                };
                for mode in [Mode::Estimate, Mode::Exact] {
                    let grid = Grid::covering(outline.control_bounds().unwrap(), 7, 9);
                    let lists = cell_lists(&layout, &grid, mode, bias, outside);
                    for p in spread(&area, 3000) {
                        let list = &lists[grid.cell_index(p)];
                        let (_, best) = nearest(&layout, p, mode);
                        for (slot, q) in layout.curves() {
                            if mode_distance(q, p, mode) <= best + bias {
                                assert!(
                                    list.contains(&slot),
                                    "{c:?} {mode:?}: curve {slot} at {p} is within the bias \
                                     of the nearest but not listed"
                                );
                            }
                        }
                    }
                    let mean =
                        lists.iter().map(Vec::len).sum::<usize>() as f64 / lists.len() as f64;
                    assert!(
                        mean < layout.curve_slots.len() as f64 * 0.6,
                        "{c:?} {mode:?}: cells list {mean} of {} curves on average",
                        layout.curve_slots.len()
                    );
                }
            }
        }
    }

    #[test]
    fn bands_hold_every_curve_a_horizontal_line_through_the_row_meets() {
        let font = crate::font::default_font();
        let outline = font.outline(font.glyph_for_char('@').unwrap());
        let layout = CurveLayout::new(&outline);
        let grid = Grid::covering(outline.control_bounds().unwrap(), 5, 6);
        let bands = row_bands(&layout, &grid);
        for (row, band) in bands.iter().enumerate() {
            let rect = grid.cell_rect(row * grid.cols as usize);
            for (slot, q) in layout.curves() {
                let curve = lyon_quad(q);
                let (low, high) = curve.bounding_range_y();
                if low <= rect.max.y && high >= rect.min.y {
                    assert!(band.contains(&slot), "row {row} lacks curve {slot}");
                }
            }
            let right: Vec<f64> = band
                .iter()
                .map(|&s| layout.curve(s).iter().map(|p| p.x).fold(f64::MIN, f64::max))
                .collect();
            assert!(right.windows(2).all(|w| w[0] >= w[1]), "row {row} unsorted");
        }
    }

    #[test]
    fn rectangle_segment_distances() {
        let r = Rect {
            min: DVec2::ZERO,
            max: DVec2::new(2.0, 1.0),
        };
        let d = |a: (f64, f64), b: (f64, f64)| {
            rect_segment_distance(&r, DVec2::new(a.0, a.1), DVec2::new(b.0, b.1))
        };
        assert_eq!(d((-1.0, 0.5), (3.0, 0.5)), 0.0, "crosses");
        assert_eq!(d((0.5, 0.5), (0.6, 0.6)), 0.0, "inside");
        assert!((d((3.0, -1.0), (3.0, 2.0)) - 1.0).abs() < 1e-12, "beside");
        // Diagonal past the corner (2, 1): the corner is nearest.
        let expected = (3.5f64 - 3.0) / 2f64.sqrt();
        assert!((d((3.5, 0.0), (0.0, 3.5)) - expected).abs() < 1e-12);
    }
}
