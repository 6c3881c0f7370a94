//! Where outlines go: the small fonts in tests/fonts/ (written by tools/make_test_fonts.py,
//! which also checks every number below against FreeType) drawn through `Font`, the one
//! place every method and the reference read outlines from.
//!
//! Each expected coordinate is worked out by hand from the tables the script writes:
//! glyph A is the contour (100,0) (100,500) off(250,700) (400,500) (400,0), xMin 100, with
//! hmtx advance 600 and lsb 40. FreeType puts the left phantom point pp1 at
//! xMin − lsb (+ its gvar delta) and moves the outline by −pp1.x.

use std::path::Path;

use glam::DVec2;
use glyphscope::font::{Axis, Font};
use glyphscope::geometry::Segment;
use glyphscope::shaping;

fn test_font(file: &str) -> Font {
    Font::from_path(
        &Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/fonts")
            .join(file),
    )
    .unwrap()
}

fn at(font: Font, values: &[(&str, f32)]) -> Font {
    let values: Vec<_> = values.iter().map(|(t, v)| (t.to_string(), *v)).collect();
    font.with_variations(&values).unwrap()
}

fn p(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

/// The single contour of glyph `c`, as segments.
fn contour(font: &Font, c: char) -> Vec<Segment> {
    let outline = font.outline(font.glyph_for_char(c).unwrap());
    assert_eq!(outline.contours.len(), 1);
    outline.contours[0].segments.clone()
}

/// Glyph A's arch with its left edge at `left` (every x of the font's A moved by the
/// same amount): (left,0) (left,500) off(left+150,700) (left+300,500) (left+300,0).
fn arch(left: f64) -> Vec<Segment> {
    let right = left + 300.0;
    vec![
        Segment::Line(p(left, 0.0), p(left, 500.0)),
        Segment::Quad(p(left, 500.0), p(left + 150.0, 700.0), p(right, 500.0)),
        Segment::Line(p(right, 500.0), p(right, 0.0)),
        Segment::Line(p(right, 0.0), p(left, 0.0)),
    ]
}

/// The x of each shaped glyph's origin.
fn pen_xs(font: &Font, text: &str) -> Vec<f64> {
    shaping::shape(font, text)
        .unwrap()
        .iter()
        .map(|g| g.position.x)
        .collect()
}

#[test]
fn glyf_outline_is_placed_by_its_left_phantom_point() {
    let font = test_font("placement.ttf");
    // pp1.x = xMin − lsb = 100 − 40 = 60: A moves by −60, its left edge to 40.
    assert_eq!(contour(&font, 'A'), arch(40.0));
    // B is A moved by (200, 0) with USE_MY_METRICS: B takes A's phantom points, so it
    // moves by A's −60 (not by its own lsb 300 − xMin 300 = 0): left edge 200 + 100 − 60.
    assert_eq!(contour(&font, 'B'), arch(240.0));
    // …and A's advance, 600, not B's hmtx 900.
    assert_eq!(pen_xs(&font, "BA"), [0.0, 600.0]);
}

#[test]
fn gvar_phantom_deltas_move_the_outline_and_the_advance() {
    let font = test_font("placement-var.ttf");
    // Default instance: as the static font, shift −60, advance 600.
    assert_eq!(contour(&font, 'A'), arch(40.0));
    assert_eq!(pen_xs(&font, "AA"), [0.0, 600.0]);
    // SHFT 0.5 takes half of each delta: points +10, pp1 +15, pp2 +40. pp1.x =
    // 100 − 40 + 15 = 75, so the left edge is 100 + 10 − 75 = 35; the advance is
    // pp2.x − pp1.x = (60 + 600 + 40) − 75 = 625.
    let font = at(font, &[("SHFT", 0.5)]);
    assert_eq!(contour(&font, 'A'), arch(35.0));
    assert_eq!(pen_xs(&font, "AA"), [0.0, 625.0]);
    // The combining acute's pp1 moves +20 there, so its own advance is 300 − 20 = 280;
    // but the shaper zeroes a mark's advance, and zero it stays.
    assert_eq!(pen_xs(&font, "A\u{301}A")[2], 625.0);
}

#[test]
fn with_hvar_the_horizontal_phantom_points_do_not_vary() {
    // The same gvar plus HVAR (+100 on A's advance at SHFT 1). FreeType then drops the
    // phantom points' gvar deltas: pp1.x stays 100 − 40 = 60 while the points move +10,
    // left edge 100 + 10 − 60 = 50; the advance is 600 + 0.5 × 100 = 650.
    let font = at(test_font("placement-hvar.ttf"), &[("SHFT", 0.5)]);
    assert_eq!(contour(&font, 'A'), arch(50.0));
    assert_eq!(pen_xs(&font, "AA"), [0.0, 650.0]);
}

#[test]
fn otto_font_takes_its_outlines_from_cff_even_beside_glyf() {
    // sfntVersion 'OTTO': A is the CFF triangle (100,0) (300,600) (500,0), not the glyf
    // box (150,0)–(450,400). CFF glyphs are not shifted.
    let font = test_font("both-outlines.otf");
    assert_eq!(
        contour(&font, 'A'),
        [
            Segment::Line(p(100.0, 0.0), p(300.0, 600.0)),
            Segment::Line(p(300.0, 600.0), p(500.0, 0.0)),
            Segment::Line(p(500.0, 0.0), p(100.0, 0.0)),
        ]
    );
}

#[test]
fn two_letter_axis_tags_are_space_padded() {
    // Axes 'M1  ' (0..1) and 'HV  ' (0..100). M1 0.5 moves A's box (100,0)–(400,500) by
    // 0.5 × 100 = +50 in x; HV 50 (normalized 0.5) raises its top by 0.5 × 60 = 30.
    let expected = [
        Segment::Line(p(150.0, 0.0), p(150.0, 530.0)),
        Segment::Line(p(150.0, 530.0), p(450.0, 530.0)),
        Segment::Line(p(450.0, 530.0), p(450.0, 0.0)),
        Segment::Line(p(450.0, 0.0), p(150.0, 0.0)),
    ];
    let short = at(test_font("short-tags.ttf"), &[("M1", 0.5), ("HV", 50.0)]);
    assert_eq!(contour(&short, 'A'), expected);
    let padded = at(
        test_font("short-tags.ttf"),
        &[("M1  ", 0.5), ("HV  ", 50.0)],
    );
    assert_eq!(contour(&padded, 'A'), expected);
}

/// The glyphs of the shipped fonts whose `hmtx` lsb differs from their `glyf` xMin, as
/// fontTools reads the two tables (`TTFont(f)["hmtx"][name][1]` against
/// `TTFont(f)["glyf"][name].xMin`): each is one unit off, so each moves by
/// lsb − xMin = +1. Every other glyph, in every shipped font, keeps its place and its
/// advance.
const SHIPPED_MOVES: &[(&str, u16, &str)] = &[
    (
        "DejaVuSans.ttf",
        1600,
        "uni0EB1, U+0EB1: lsb −1185, xMin −1186",
    ),
    ("DejaVuSans.ttf", 2600, "uni1F32, U+1F32: lsb −79, xMin −80"),
    ("DejaVuSans.ttf", 2601, "uni1F33, U+1F33: lsb −69, xMin −70"),
    ("DejaVuSans.ttf", 2603, "uni1F35, U+1F35: lsb −45, xMin −46"),
    (
        "DejaVuSans.ttf",
        2962,
        "uni20D0, U+20D0: lsb −1005, xMin −1006",
    ),
    (
        "DejaVuSans.ttf",
        3532,
        "uni2422, U+2422: lsb −125, xMin −126",
    ),
    (
        "Lohit-Bengali.ttf",
        143,
        "gandamarkbeng, U+09FB: lsb −41, xMin −42",
    ),
];

/// What a glyph's placement was before outlines were placed: no shift, and ttf-parser's
/// advance (hmtx, plus HVAR where the font has it).
fn moved_from_before(font: &Font, glyph: u16) -> Option<(f64, f64)> {
    let placed = font.placement(glyph);
    let advance_before = font
        .face()
        .glyph_hor_advance(ttf_parser::GlyphId(glyph))
        .map_or(0.0, f64::from);
    (placed.shift != 0.0 || placed.advance != advance_before)
        .then_some((placed.shift, placed.advance - advance_before))
}

#[test]
fn on_the_shipped_fonts_only_glyphs_no_shipped_scene_draws_move() {
    use glyphscope::font::SHIPPED_FONTS;
    for (index, (_, file, _)) in SHIPPED_FONTS.iter().enumerate() {
        let font = glyphscope::font::shipped(index);
        let moved: Vec<_> = (0..font.glyph_count())
            .filter_map(|g| moved_from_before(&font, g).map(|m| (g, m)))
            .collect();
        let expected: Vec<_> = SHIPPED_MOVES
            .iter()
            .filter(|(f, _, _)| f == file)
            .map(|(_, glyph, _)| (*glyph, (1.0, 0.0)))
            .collect();
        assert_eq!(moved, expected, "{file}");
        // Away from the default instance of Inter (which has HVAR, so no phantom point
        // varies) only advances change: those of composites that take their metrics
        // from a USE_MY_METRICS component whose HVAR delta differs from their own.
        for end in [|a: &Axis| a.min, |a: &Axis| a.max] {
            let values: Vec<_> = font
                .axes()
                .iter()
                .map(|a| (a.tag.clone(), end(a)))
                .collect();
            if values.is_empty() {
                continue;
            }
            let instance = font.with_variations(&values).unwrap();
            for glyph in 0..instance.glyph_count() {
                if let Some((shift, _)) = moved_from_before(&instance, glyph) {
                    assert_eq!(shift, 0.0, "{file} {values:?} glyph {glyph}");
                    assert_ne!(instance.placement(glyph).metrics_glyph, glyph);
                }
            }
        }
    }
    // One of those, as FreeType 2.13 reports it: Inter's 'ť' at wght 900 advances by its
    // USE_MY_METRICS component 't' (1140), where HarfBuzz takes the composite's own
    // HVAR advance (1310).
    let inter = glyphscope::font::shipped(2)
        .with_variations(&[("wght".into(), 900.0)])
        .unwrap();
    assert_eq!(inter.advance(inter.glyph_for_char('ť').unwrap()), 1140.0);
    // No standard scene shapes a glyph that moved, at the instance it draws.
    for name in glyphscope::bench::scenes::SCENE_NAMES {
        let args = glyphscope::bench::scenes::scene(name).unwrap().args;
        let font = args.font().unwrap();
        for shaped in shaping::shape(&font, args.text.as_deref().unwrap()).unwrap() {
            assert_eq!(
                moved_from_before(&font, shaped.glyph),
                None,
                "{name}: glyph {}",
                shaped.glyph
            );
        }
    }
}
