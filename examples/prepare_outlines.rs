//! Times outline extraction and cubic→quadratic conversion for every glyph of each
//! shipped font, and counts what the conversion produces.
//!
//!     cargo run --release --example prepare_outlines

use std::time::Instant;

use glyphscope::font::SHIPPED_FONTS;
use glyphscope::geometry::{DEFAULT_QUAD_TOLERANCE_EM, Segment};

fn main() {
    println!(
        "| font | glyphs | outlines ms | + quadratics ms | cubics | → quadratics/lines | tolerance (em) |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|");
    for (index, (name, _, _)) in SHIPPED_FONTS.iter().enumerate() {
        let font = glyphscope::font::shipped(index);
        let tolerance = DEFAULT_QUAD_TOLERANCE_EM * font.units_per_em();
        // Best of a few runs: the first touches cold pages of the font data.
        let mut best = (f64::INFINITY, f64::INFINITY);
        let (mut cubics, mut pieces) = (0, 0);
        for _ in 0..5 {
            let start = Instant::now();
            let outlines: Vec<_> = (0..font.glyph_count()).map(|g| font.outline(g)).collect();
            let outline_ms = start.elapsed().as_secs_f64() * 1e3;
            let quads: Vec<_> = outlines
                .iter()
                .map(|o| o.to_quadratics(tolerance))
                .collect();
            let total_ms = start.elapsed().as_secs_f64() * 1e3;
            best = (best.0.min(outline_ms), best.1.min(total_ms));
            cubics = outlines
                .iter()
                .flat_map(|o| o.segments())
                .filter(|s| matches!(s, Segment::Cubic(..)))
                .count();
            let all: usize = quads.iter().map(|o| o.segments().count()).sum();
            let before: usize = outlines.iter().map(|o| o.segments().count()).sum();
            pieces = all - (before - cubics);
        }
        println!(
            "| {name} | {} | {:.1} | {:.1} | {cubics} | {pieces} | {:.2e} |",
            font.glyph_count(),
            best.0,
            best.1,
            DEFAULT_QUAD_TOLERANCE_EM
        );
    }
}
