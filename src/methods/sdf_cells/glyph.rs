//! One distinct glyph made ready for the shader: its curves laid out, its grid chosen,
//! its cells listed and encoded, and its winding bands (exact mode; the estimate with
//! `ties=winding`).

use glam::DVec2;

use super::cells::{Grid, Mode, cell_lists, row_bands};
use super::curves::CurveLayout;
use super::encoding::{EncodedCells, MAX_BEGIN_SLOT};
use super::params::{EncodingChoice, GridChoice, Settings};
use crate::Error;
use crate::geometry::{DEFAULT_QUAD_TOLERANCE_EM, Outline, Rect};

/// Border cells also serve points this far outside the grid (em): the pixels the quad
/// is dilated by at small sizes (half a pixel's diagonal plus the rasterizer's snap
/// margin, `SNAP_MARGIN` in common.wgsl, is 0.8 px at 45°: 1/12 em at 9.6 px/em).
pub const OUTSIDE_EM: f64 = 1.0 / 12.0;
/// The automatic grid aims at this many cells per curve, in square-ish cells.
const CELLS_PER_CURVE: f64 = 4.0;
/// The most cells along a side the automatic grid uses (a forced grid may use more).
const MAX_AUTO_SIDE: u32 = 32;
/// How far `encoding=packed` refines an automatic grid to make a glyph fit.
const MAX_PACKING_SIDE: u32 = 64;

#[derive(Clone, Debug)]
pub struct PreparedGlyph {
    pub layout: CurveLayout,
    pub grid: Grid,
    /// The curves each cell needs (by slot), before encoding.
    pub lists: Vec<Vec<u32>>,
    pub cells: EncodedCells,
    /// The winding bands, one per grid row: exact mode's sign everywhere, the
    /// estimate's where tied curves disagree (`ties=winding`); else empty.
    pub bands: Vec<Vec<u32>>,
}

impl PreparedGlyph {
    /// Fails only for a glyph whose lists outgrow what an escape word can address
    /// (some 16 million words: thousands of curves in each of thousands of cells).
    pub fn new(
        outline: &Outline,
        units_per_em: f64,
        settings: &Settings,
    ) -> Result<PreparedGlyph, Error> {
        let mut quadratics = outline.to_quadratics(DEFAULT_QUAD_TOLERANCE_EM * units_per_em);
        if let (Mode::Estimate, Some(flatness)) = (settings.mode, settings.flatness_em) {
            quadratics = quadratics.halved_until_flat(flatness * units_per_em);
        }
        let layout = CurveLayout::new(&quadratics);
        let curves = layout.curve_slots.len();
        // The grid covers the outline plus what the effects draw around it.
        let reach = settings.reach_em() * units_per_em;
        let bounds = Rect::enclosing(layout.points.iter().copied()).unwrap_or(Rect {
            min: DVec2::ZERO,
            max: DVec2::ZERO,
        });
        let area = Rect {
            min: bounds.min - reach,
            max: bounds.max + reach,
        };
        let bias = settings.bias_em * units_per_em;
        let outside = OUTSIDE_EM * units_per_em;
        let build = |grid: Grid| {
            let lists = cell_lists(&layout, &grid, settings.mode, bias, outside);
            (grid, lists)
        };
        let (mut grid, mut lists) = build(match settings.grid {
            GridChoice::Fixed(n) => Grid::covering(area, n, n),
            GridChoice::Auto => square_grid(area, auto_side(area, curves)),
        });
        let too_long = || {
            Error::Input(format!(
                "a glyph of {curves} curves lists more than the list encoding can address \
                 with this grid; choose a coarser one"
            ))
        };
        let pack = settings.encoding != EncodingChoice::List;
        let mut cells = EncodedCells::new(&lists, &layout, pack).ok_or_else(too_long)?;
        // `packed`: refine an automatic grid until the packed word of kocsis1david's
        // font-demo holds every cell, for glyphs whose curves all begin within its reach.
        while settings.encoding == EncodingChoice::Packed
            && settings.grid == GridChoice::Auto
            && layout
                .curve_slots
                .last()
                .is_none_or(|&last| last <= MAX_BEGIN_SLOT)
            && cells.escaped > 0
            && grid.cols.max(grid.rows) < MAX_PACKING_SIDE
        {
            // Smaller cells list fewer curves: 1.5 times finer per step.
            let finer = (f64::from(grid.cols.max(grid.rows)) * 1.5).ceil() as u32;
            (grid, lists) = build(square_grid(area, finer.min(MAX_PACKING_SIDE)));
            cells = EncodedCells::new(&lists, &layout, true).ok_or_else(too_long)?;
        }
        // The estimate reads a winding number only where tied curves disagree.
        let bands = match settings.mode {
            Mode::Exact => row_bands(&layout, &grid),
            Mode::Estimate if settings.ties_by_winding => row_bands(&layout, &grid),
            Mode::Estimate => Vec::new(),
        };
        Ok(PreparedGlyph {
            layout,
            grid,
            lists,
            cells,
            bands,
        })
    }

    /// The rectangle the quad covers before pixel dilation (font units): the grid.
    pub fn quad(&self) -> Rect {
        let size =
            self.grid.cell * DVec2::new(f64::from(self.grid.cols), f64::from(self.grid.rows));
        Rect {
            min: self.grid.origin,
            max: self.grid.origin + size,
        }
    }
}

/// Cells along the longer side for about `CELLS_PER_CURVE` square cells per curve. The
/// cell count follows the curve count because a cell's list shrinks with its size only
/// until it holds the curves nearest to it.
fn auto_side(area: Rect, curves: usize) -> u32 {
    let size = area.size().max(DVec2::splat(1e-9));
    let cells = (curves as f64 * CELLS_PER_CURVE).max(1.0);
    let cell = (size.x * size.y / cells).sqrt();
    ((size.max_element() / cell).round() as u32).clamp(1, MAX_AUTO_SIDE)
}

/// `long_side` cells along the longer side of `area`, as square as they can be.
fn square_grid(area: Rect, long_side: u32) -> Grid {
    let size = area.size().max(DVec2::splat(1e-9));
    let cell = size.max_element() / f64::from(long_side);
    let count = |extent: f64| ((extent / cell).round() as u32).max(1);
    Grid::covering(area, count(size.x), count(size.y))
}
