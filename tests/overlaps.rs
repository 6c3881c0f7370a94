//! Overlap removal (`geometry::merge_overlaps`) changes no pixel of the exact answer: on
//! every glyph of the shipped Inter at two weights and of Lohit Bengali, and on every
//! overlapping hard case, the reference draws the merged outline as it draws the
//! original, and the merged outline's area (Green's theorem, in kurbo's closed form)
//! equals the original's nonzero area (the reference's coverage summed: its box filter
//! integrates the filled area exactly).
//!
//! Bounds: a pixel may move by 1e-4 (set before the first run: the merged curves are
//! the originals split in f64). The area may differ by what the reference's flattening
//! can take from the original's: at most its tolerance times the length of the curves
//! it flattens (bounded by their control polygons), plus f32 rounding of each pixel.
//! (The first run had a bound of 1e-6 of the area, which assumed the reference's area
//! was that good; it is not at 1/16384 px tolerance: it measured 4e-6 to 6e-5 of the
//! area, the merged outline always the larger, as a flattening inside the curves.)
//!
//! `cargo test --release --test overlaps -- --nocapture` prints what merging costs:
//! glyphs merged, and the time per glyph.

mod common;

use std::time::Instant;

use common::framed;
use glam::DVec2;
use glyphscope::font::Font;
use glyphscope::geometry::{Outline, Segment, kurbo_path, merge_overlaps};
use glyphscope::methods::info::Trait;
use glyphscope::reference;
use glyphscope::scene::Scene;
use glyphscope::stability::hard_cases;
use kurbo::Shape;

const PX_PER_EM: f64 = 32.0;
const MAX_PIXEL_CHANGE: f32 = 1e-4;

/// The outline's signed areas by contour (kurbo's closed form), summed: the merged
/// outline winds 0 or 1 everywhere (holes against outer contours), so the sum's
/// magnitude is its filled area.
fn filled_area_of_merged(outline: &Outline) -> f64 {
    outline
        .contours
        .iter()
        .map(|c| kurbo_path(std::slice::from_ref(c)).area())
        .sum::<f64>()
        .abs()
}

/// Checks one outline; whether it was merged.
fn merged_changes_nothing(outline: &Outline, units_per_em: f64, what: &str) -> bool {
    let Some(merged) = merge_overlaps(outline, units_per_em).unwrap() else {
        return false;
    };
    let original = Scene::from_outlines(units_per_em, vec![(outline.clone(), DVec2::ZERO)]);
    let union = Scene::from_outlines(units_per_em, vec![(merged.clone(), DVec2::ZERO)]);
    let camera = framed(
        &original,
        PX_PER_EM,
        [1.0, 0.0, 0.0, 1.0],
        DVec2::new(0.3, 0.6),
    );
    let a = reference::rasterize(&original, &camera).unwrap();
    let b = reference::rasterize(&union, &camera).unwrap();
    let (mut worst, mut at) = (0.0_f32, 0);
    for (i, (x, y)) in a.data.iter().zip(&b.data).enumerate() {
        let change = (x - y).abs();
        // NaN is a change too.
        if change.is_nan() || change > worst {
            worst = if change.is_nan() {
                f32::INFINITY
            } else {
                change
            };
            at = i;
        }
    }
    assert!(
        worst <= MAX_PIXEL_CHANGE,
        "{what}: merging moved pixel {at} by {worst}"
    );
    let units_per_px = units_per_em / PX_PER_EM;
    let nonzero_area: f64 =
        a.data.iter().map(|&c| f64::from(c)).sum::<f64>() * units_per_px * units_per_px;
    let merged_area = filled_area_of_merged(&merged);
    let curves_px: f64 = outline
        .segments()
        .filter(|s| !matches!(s, Segment::Line(..)))
        .map(|s| {
            let p = glyphscope::geometry::segment_points(s).collect::<Vec<_>>();
            p.windows(2).map(|w| w[0].distance(w[1])).sum::<f64>()
        })
        .sum::<f64>()
        / units_per_px;
    let slack_px2 = reference::DEFAULT_TOLERANCE_PX * curves_px + a.data.len() as f64 * 1e-7;
    let slack = slack_px2 * units_per_px * units_per_px;
    assert!(
        (merged_area - nonzero_area).abs() <= slack,
        "{what}: merged area {merged_area} against the nonzero area {nonzero_area}, more than {slack} apart"
    );
    true
}

/// Checks every glyph of `font`; prints how many were merged, of how many with an
/// outline, and the merge's time per glyph (all glyphs; ms); returns the two counts.
fn check_font(font: &Font, label: &str) -> (u32, u32) {
    let units_per_em = font.units_per_em();
    let (mut glyphs, mut merged, mut merge_ms) = (0, 0, 0.0);
    for id in 0..font.glyph_count() {
        let outline = font.outline(id);
        if outline.is_empty() {
            continue;
        }
        glyphs += 1;
        let start = Instant::now();
        merge_overlaps(&outline, units_per_em).unwrap();
        merge_ms += start.elapsed().as_secs_f64() * 1e3;
        if merged_changes_nothing(&outline, units_per_em, &format!("{label} glyph {id}")) {
            merged += 1;
        }
    }
    assert!(glyphs > 0, "{label} has no outlines");
    println!(
        "{label}: {merged} of {glyphs} glyphs merged ({:.1}%); merging takes {:.3} ms a glyph on average (overlap check included)",
        100.0 * f64::from(merged) / f64::from(glyphs),
        merge_ms / f64::from(glyphs)
    );
    (merged, glyphs)
}

#[test]
fn merging_inter_changes_no_pixel_at_either_weight() {
    let inter = Font::shipped(2);
    for weight in [400.0, 900.0] {
        let font = inter.with_variations(&[("wght".into(), weight)]).unwrap();
        let (merged, glyphs) = check_font(&font, &format!("Inter wght {weight}"));
        // A variable font draws its glyphs with overlapping contours (Inter's designers
        // overlap strokes at joins): if few were merged, merging would be checked on
        // nothing. (It merges 37%.)
        assert!(merged * 4 >= glyphs, "{merged} of {glyphs} merged");
    }
}

#[test]
fn merging_lohit_bengali_changes_no_pixel() {
    let (merged, _) = check_font(&Font::shipped(3), "Lohit Bengali");
    assert!(merged > 0, "no conjunct of Lohit overlaps");
}

#[test]
fn merging_the_overlapping_hard_cases_changes_no_pixel() {
    for case in hard_cases::all() {
        if !case.traits.contains(&Trait::Overlapping) {
            continue;
        }
        let merged = case
            .scene
            .glyphs
            .iter()
            .filter(|g| merged_changes_nothing(&g.outline, case.scene.units_per_em, case.name))
            .count();
        assert!(merged > 0, "{}: nothing merged", case.name);
    }
}
