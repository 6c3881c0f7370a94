//! Which of a frame's glyphs can be blended straight into the caller's target, and which
//! must go through the pages.
//!
//! Where no other glyph of its run reaches a glyph's pixels, its coverage there is the
//! run's, so one blend in the run's colour is exact. Glyphs of one run that share a
//! pixel must have their coverages added first (their union's coverage is the sum,
//! where one blend after another gives 1 − (1 − a)(1 − b)): those go through the pages.
//! Runs must still land colour over colour in order where they share a pixel. `render`
//! draws the direct glyphs first, in run order within each draw (one per variant), then
//! composites the pages' runs in order; so a direct glyph is right only if every glyph
//! of an earlier run it meets is direct and drawn in the same draw (the same variant),
//! and a paged glyph over it is always right, being later. Deciding glyph by glyph in
//! run order keeps that: a glyph goes through the pages if it meets a glyph of its own
//! run, a paged glyph of an earlier run, or a direct one of another variant.
//!
//! A glyph's coverage is zero outside the whole pixels its ink's box touches, so two
//! glyphs can share a pixel only where those boxes meet (grown for f32's rounding, and
//! in perspective for the shader's linear footprint): a test on boxes, wrong only the
//! safe way, is enough. Boxes are sorted into a grid of cells so that each is
//! tested against its neighbours only.

use super::pages::PixelRect;

/// The whole pixels a glyph's box of ink from `min` to `max` (target pixels) may reach,
/// within a viewport of `size` pixels: pixel i is touched when i < max and i + 1 > min —
/// more by a thousandth of a pixel and by f32's rounding at that distance (the GPU maps
/// pixels into the glyph in f32), and by `grow` pixels (a glyph seen in perspective:
/// the shader takes a pixel's footprint as the tangent parallelogram at its centre,
/// which may reach past the pixel's own preimage, as the pages' rectangles allow for).
pub fn pixels_of_ink(min: [f64; 2], max: [f64; 2], size: [u32; 2], grow: f64) -> PixelRect {
    let slack = |v: f64| grow + 1e-3 + v.abs() * f64::from(f32::EPSILON) * 4.0;
    let low = |v: f64, n: u32| (v - slack(v)).floor().clamp(0.0, f64::from(n)) as u32;
    let high = |v: f64, n: u32| (v + slack(v)).ceil().clamp(0.0, f64::from(n)) as u32;
    PixelRect {
        x0: low(min[0], size[0]),
        y0: low(min[1], size[1]),
        x1: high(max[0], size[0]),
        y1: high(max[1], size[1]),
    }
}

/// Cells of the grid, pixels a side: a label's glyph falls in one to four of them.
const CELL: u32 = 32;
/// Boxes one cell holds before it stops testing them pairwise: past it (text stacked
/// on text) every box reaching the cell goes through the pages, which is never wrong
/// for a box arriving later, and a frame's cost stays linear in its glyphs.
const CELL_LIMIT: usize = 48;

/// What decides how a glyph may be drawn besides its pixels: its run (the runs' order)
/// and its kind (the draw it would be in: its variant).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GlyphKey {
    pub run: u32,
    pub kind: u32,
}

/// The grid's cells, kept between frames so that a frame allocates nothing.
#[derive(Default)]
pub struct Grid {
    cells: Vec<Vec<u32>>,
    /// Cells past `CELL_LIMIT`: boxes arriving there go through the pages.
    full: Vec<bool>,
}

impl Grid {
    /// Sets `paged[i]` for each of `boxes` (with `keys`, in run order) that must go
    /// through the pages, in a viewport of `size` pixels. Empty boxes meet nothing.
    pub fn mark(
        &mut self,
        boxes: &[PixelRect],
        keys: &[GlyphKey],
        size: [u32; 2],
        paged: &mut Vec<bool>,
    ) {
        debug_assert!(keys.windows(2).all(|k| k[0].run <= k[1].run));
        paged.clear();
        paged.resize(boxes.len(), false);
        let columns = size[0].div_ceil(CELL).max(1);
        let rows = size[1].div_ceil(CELL).max(1);
        let cells = (columns * rows) as usize;
        self.cells
            .resize_with(cells.max(self.cells.len()), Vec::new);
        for cell in &mut self.cells[..cells] {
            cell.clear();
        }
        self.full.clear();
        self.full.resize(cells, false);
        for (i, b) in boxes.iter().enumerate() {
            if b.x0 >= b.x1 || b.y0 >= b.y1 {
                continue;
            }
            let key = keys[i];
            let (cx0, cx1) = (b.x0 / CELL, ((b.x1 - 1) / CELL).min(columns - 1));
            let (cy0, cy1) = (b.y0 / CELL, ((b.y1 - 1) / CELL).min(rows - 1));
            for cy in cy0..=cy1 {
                for cx in cx0..=cx1 {
                    let c = (cy * columns + cx) as usize;
                    let full = self.full[c];
                    let cell = &mut self.cells[c];
                    if full {
                        // Past the limit: this box goes through the pages, and so do
                        // the boxes of its own run it meets (the last ones in before
                        // the cell filled; those after are paged as this one is).
                        paged[i] = true;
                        for &j in cell.iter().rev() {
                            if keys[j as usize].run != key.run {
                                break;
                            }
                            if b.meets(&boxes[j as usize]) {
                                paged[j as usize] = true;
                            }
                        }
                    } else {
                        for &j in cell.iter() {
                            let j = j as usize;
                            if !b.meets(&boxes[j]) {
                                continue;
                            }
                            if keys[j].run == key.run {
                                // Their coverages must be added: both through the pages.
                                paged[i] = true;
                                paged[j] = true;
                            } else if paged[j] || keys[j].kind != key.kind {
                                // Composited after it, or drawn in another draw than it.
                                paged[i] = true;
                            }
                        }
                    }
                    if !full {
                        cell.push(i as u32);
                        self.full[c] = cell.len() > CELL_LIMIT;
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const VIEW: [u32; 2] = [200, 100];

    /// Each box of its own run, all of one kind.
    fn marked(boxes: &[PixelRect]) -> Vec<bool> {
        let keys: Vec<GlyphKey> = (0..boxes.len() as u32)
            .map(|run| GlyphKey { run, kind: 0 })
            .collect();
        marked_with(boxes, &keys)
    }

    fn marked_with(boxes: &[PixelRect], keys: &[GlyphKey]) -> Vec<bool> {
        let mut paged = Vec::new();
        Grid::default().mark(boxes, keys, VIEW, &mut paged);
        paged
    }

    fn key(run: u32, kind: u32) -> GlyphKey {
        GlyphKey { run, kind }
    }

    fn pixels(x0: u32, y0: u32, x1: u32, y1: u32) -> PixelRect {
        PixelRect { x0, y0, x1, y1 }
    }

    #[test]
    fn ink_touches_the_pixels_it_enters() {
        // Ink from 3.2 to 4.7 enters pixels 3 and 4.
        assert_eq!(
            pixels_of_ink([3.2, 7.5], [4.7, 7.6], VIEW, 0.0),
            pixels(3, 7, 5, 8)
        );
        // Ink ending on a pixel's edge may reach into it by the GPU's rounding: counted.
        assert_eq!(
            pixels_of_ink([3.0, 7.0], [5.0, 8.0], VIEW, 0.0),
            pixels(2, 6, 6, 9)
        );
        // Cut by the viewport.
        assert_eq!(
            pixels_of_ink([-4.0, 90.5], [2.5, 130.0], VIEW, 0.0),
            pixels(0, 90, 3, 100)
        );
        // In perspective: a pixel more each side.
        assert_eq!(
            pixels_of_ink([3.2, 7.5], [4.7, 7.6], VIEW, 1.0),
            pixels(2, 6, 6, 9)
        );
    }

    #[test]
    fn glyphs_of_one_run_sharing_a_pixel_go_through_the_pages() {
        // One run: pixels 10..14 and 14..18 of a row are side by side, no pixel in
        // common; the third meets the second in pixel (17, 5); the fourth is apart.
        let boxes = [
            pixels(10, 0, 14, 6),
            pixels(14, 0, 18, 6),
            pixels(17, 5, 20, 9),
            pixels(40, 40, 45, 45),
        ];
        let one_run = [key(0, 0); 4];
        assert_eq!(marked_with(&boxes, &one_run), [false, true, true, false]);
    }

    #[test]
    fn runs_over_runs_are_direct_only_where_the_order_holds() {
        let boxes = [
            // Run 0: two glyphs sharing a pixel (paged), and a lone one.
            pixels(0, 0, 5, 5),
            pixels(4, 0, 9, 5),
            pixels(20, 0, 25, 5),
            // Run 1 over them: over a paged glyph (paged: composited after it), over a
            // direct one of its kind (direct: drawn after it in the same draw).
            pixels(2, 2, 4, 4),
            pixels(21, 1, 23, 3),
            // Run 2, another kind, over run 1's direct glyph: paged (another draw).
            pixels(22, 2, 24, 4),
            // Run 3, of run 2's kind, over nothing: direct.
            pixels(60, 60, 64, 64),
        ];
        let keys = [
            key(0, 0),
            key(0, 0),
            key(0, 0),
            key(1, 0),
            key(1, 0),
            key(2, 1),
            key(3, 1),
        ];
        assert_eq!(
            marked_with(&boxes, &keys),
            [true, true, false, true, false, true, false]
        );
    }

    #[test]
    fn boxes_meeting_across_cells_are_found() {
        // Both span the corner where four cells meet; they overlap in its pixel.
        let corner = CELL;
        let boxes = [
            pixels(corner - 3, corner - 3, corner + 1, corner + 1),
            pixels(corner, corner, corner + 5, corner + 5),
            pixels(corner + 1, corner - 9, corner + 8, corner - 4),
        ];
        let one_run = [key(0, 0); 3];
        assert_eq!(marked_with(&boxes, &one_run), [true, true, false]);
    }

    #[test]
    fn a_crowded_cell_sends_later_boxes_to_the_pages() {
        // Disjoint boxes of one pixel, each its own run, fill the first cell past its
        // limit: those in before it are direct.
        let mut boxes: Vec<PixelRect> = (0..=CELL_LIMIT as u32)
            .map(|k| pixels(k % 30, k / 30 * 2, k % 30 + 1, k / 30 * 2 + 1))
            .collect();
        let mut keys: Vec<GlyphKey> = (0..boxes.len() as u32).map(|r| key(r, 0)).collect();
        let next = keys.len() as u32;
        // A box of a new run meeting none of them, reaching into the full cell: paged.
        boxes.push(pixels(31, 31, 33, 33));
        keys.push(key(next, 0));
        // A later run's box meeting that one in the next cell: paged (over a paged
        // glyph of an earlier run). One elsewhere: direct.
        boxes.push(pixels(32, 32, 34, 34));
        keys.push(key(next + 1, 0));
        boxes.push(pixels(150, 50, 151, 51));
        keys.push(key(next + 2, 0));
        let paged = marked_with(&boxes, &keys);
        let n = paged.len();
        assert!(paged[..n - 3].iter().all(|&p| !p), "{paged:?}");
        assert_eq!(paged[n - 3..], [true, true, false]);
    }

    #[test]
    fn a_full_cell_still_pages_the_glyph_of_the_same_run_it_meets() {
        // One run fills the cell with disjoint boxes, its last one in a corner; its
        // next box arrives at the full cell and meets that last one: both paged (their
        // coverages are summed), the others direct.
        let mut boxes: Vec<PixelRect> = (0..CELL_LIMIT as u32)
            .map(|k| pixels(k % 16, k / 16 * 2, k % 16 + 1, k / 16 * 2 + 1))
            .collect();
        boxes.push(pixels(20, 20, 24, 24));
        boxes.push(pixels(22, 22, 26, 26));
        let one_run = vec![key(0, 0); boxes.len()];
        let paged = marked_with(&boxes, &one_run);
        assert!(paged[..CELL_LIMIT].iter().all(|&p| !p), "{paged:?}");
        assert_eq!(paged[CELL_LIMIT..], [true, true]);
    }

    #[test]
    fn empty_boxes_share_nothing() {
        let boxes = [pixels(5, 5, 5, 9), pixels(0, 0, 20, 20)];
        assert_eq!(marked(&boxes), [false, false]);
    }
}
