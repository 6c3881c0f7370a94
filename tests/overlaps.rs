//! Overlapping ink drawn as its union, within a glyph and between glyphs.
//!
//! Within a glyph: overlap removal (`geometry::merge_overlaps`) changes no pixel of the
//! exact answer: on every glyph of the shipped Inter at two weights and of Lohit
//! Bengali, and on every overlapping hard case, the reference draws the merged outline
//! as it draws the original, and the merged outline's area (Green's theorem, in kurbo's
//! closed form) equals the original's nonzero area (the reference's coverage summed:
//! its box filter integrates the filled area exactly).
//!
//! Bounds: a pixel may move by 1e-4 (set before the first run: the merged curves are
//! the originals split in f64). The area may differ by what the reference's flattening
//! can take from the original's: at most its tolerance times the length of the curves
//! it flattens (bounded by their control polygons), plus f32 rounding of each pixel.
//! (The first run had a bound of 1e-6 of the area, which assumed the reference's area
//! was that good; it is not at 1/16384 px tolerance: it measured 4e-6 to 6e-5 of the
//! area, the merged outline always the larger, as a flattening inside the curves.)
//!
//! Between glyphs: two glyphs' overlapping squares, their coverage worked by hand, drawn
//! by each method that draws instances from outlines; and joining the instances of the
//! hard cases whose glyphs overlap changes no pixel of the reference.
//!
//! `cargo test --release --test overlaps -- --nocapture` prints what merging costs:
//! glyphs merged, and the time per glyph.

mod common;

use std::time::Instant;

use common::{framed, polygon, rect, unit_camera};
use glam::DVec2;
use glyphscope::font::Font;
use glyphscope::geometry::{Outline, Segment, kurbo_path, merge_overlaps};
use glyphscope::methods::info::Trait;
use glyphscope::methods::registry;
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
    let inter = glyphscope::font::shipped(2);
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
    let (merged, _) = check_font(&glyphscope::font::shipped(3), "Lohit Bengali");
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

/// Glyph A, the square [2, 12]², and glyph B, [7.5, 17.5] × [2.5, 12.5] (font units, y
/// up, one unit a pixel), overlap by 4.5 × 9.5. Worked by hand for the pixel [i, i+1] ×
/// [j, j+1] at (i, j): its union coverage, and its coverage added glyph by glyph.
const SQUARES_BY_HAND: [((u32, u32), f32, f32); 9] = [
    // Inside both.
    ((9, 5), 1.0, 2.0),
    // A whole, B's left edge halving it.
    ((7, 5), 1.0, 1.5),
    // Right of A, inside B.
    ((12, 5), 1.0, 1.0),
    // Above A, B's top edge halving it.
    ((9, 12), 0.5, 0.5),
    // B's top left corner: a quarter.
    ((7, 12), 0.25, 0.25),
    // A's bottom row, B's bottom edge halving it.
    ((9, 2), 1.0, 1.5),
    // A's bottom row, B's bottom left corner a quarter of it.
    ((7, 2), 1.0, 1.25),
    // B's right edge halving it.
    ((17, 5), 0.5, 0.5),
    // Left of both.
    ((1, 5), 0.0, 0.0),
];
/// Their union's area (100 + 100 − 4.5 · 9.5) and their areas added.
const UNION_AREA: f64 = 157.25;
const ADDED_AREA: f64 = 200.0;

fn two_squares() -> Scene {
    Scene::from_outlines(
        1000.0,
        vec![
            (
                Outline {
                    contours: vec![polygon(&rect(2.0, 2.0, 12.0, 12.0))],
                },
                DVec2::ZERO,
            ),
            (
                Outline {
                    contours: vec![polygon(&rect(7.5, 2.5, 17.5, 12.5))],
                },
                DVec2::ZERO,
            ),
        ],
    )
}

/// `method` with `params` draws the two squares: each hand-worked pixel within
/// `pixel_slack` of the union (or, with `added`, of the sum), the frame's coverage within
/// `area_slack` px of its area. Where coverage adds up, the raw target holds the sum.
fn check_squares(
    method: &str,
    params: &[(&str, &str)],
    added: bool,
    pixel_slack: f32,
    area_slack: f64,
) {
    let scene = two_squares();
    let height = 16;
    let camera = unit_camera(20, height);
    let params: Vec<(String, String)> = params.iter().map(|&(k, v)| (k.into(), v.into())).collect();
    let mut m = registry::create(method, &params).unwrap();
    let image = common::render(m.as_mut(), &scene, &camera);
    let label = format!("{method} {params:?}");
    for ((i, j), union, sum) in SQUARES_BY_HAND {
        let want = if added { sum } else { union };
        let got = image.get(i, height - 1 - j);
        // NaN fails too.
        assert!(
            (got - want).abs() <= pixel_slack,
            "{label}: pixel ({i}, {j}) reads {got}, worked by hand {want}"
        );
    }
    let area: f64 = image.data.iter().map(|&v| f64::from(v)).sum();
    let want = if added { ADDED_AREA } else { UNION_AREA };
    assert!(
        (area - want).abs() <= area_slack,
        "{label}: coverage sums to {area} px², the area is {want}"
    );
}

/// winding draws the two glyphs' union exactly (its claim, 0.02, on the pixels, and 0.1
/// px² on the area of some 160 covered pixels, each within a half-float step of 4.9e-4);
/// with `between=add` the shared ink counts twice, as glyph-by-glyph compositing counts
/// it. Its rays are held to their own claim, 0.6 (a corner pixel reads 0.5 for 0.25:
/// one ray's crossing fills it), and 2 px² on the area, which a sum would pass by 42.75.
/// `sdf-cells` joins them the same way, held to its exact mode's claim, 0.65 (one
/// distance reads the corner pixel 0.5 for 0.25), and 2 px² on the area.
#[test]
fn two_glyphs_overlapping_are_drawn_as_their_union() {
    check_squares("winding", &[], false, 0.02, 0.1);
    check_squares("winding", &[("between", "add")], true, 0.02, 0.1);
    check_squares("winding", &[("aa", "rays")], false, 0.6, 2.0);
    check_squares("sdf-cells", &[], false, 0.65, 2.0);
    check_squares("sdf-cells", &[("mode", "exact")], false, 0.65, 2.0);
    check_squares("sdf-cells", &[("between", "add")], true, 0.65, 2.0);
}

/// `xor-stencil` and `tessellation` count winding per sample over every instance, so
/// they draw the union without joining anything: inside both squares a pixel reads 1,
/// never 2 (the hand-worked pixels within a quarter, what four samples resolve on an
/// edge at half a pixel, and the area within 2 px², far from the 42.75 a sum would add).
#[test]
fn per_sample_methods_draw_the_union_already() {
    check_squares("xor-stencil", &[], false, 0.25, 2.0);
    check_squares("tessellation", &[], false, 0.25, 2.0);
}

/// Joining the instances of every hard case whose glyphs overlap changes no pixel of
/// the reference, which fills the union of whatever it is given (the same 1e-4 as
/// merging), and joins something in each.
#[test]
fn joining_overlapping_instances_changes_no_pixel_of_the_reference() {
    for case in hard_cases::all() {
        if !case.traits.contains(&Trait::OverlappingGlyphs) {
            continue;
        }
        let (joined, counts) = case.scene.with_overlapping_instances_joined();
        assert!(counts.groups > 0, "{}: nothing joined", case.name);
        let camera = case.camera(30.0, DVec2::new(0.25, 0.5)).unwrap();
        let a = reference::rasterize(&case.scene, &camera).unwrap();
        let b = reference::rasterize(&joined, &camera).unwrap();
        for (i, (x, y)) in a.data.iter().zip(&b.data).enumerate() {
            assert!(
                (x - y).abs() <= MAX_PIXEL_CHANGE,
                "{}: joining moved pixel {i} from {x} to {y}",
                case.name
            );
        }
    }
}
