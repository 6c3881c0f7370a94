//! Method `sdf-cells` against the exact reference and against what its own data says:
//! every glyph of every shipped font prepares; exact mode stays within half a pixel of
//! the reference on glyphs without overlapping contours, at 16, 48 and 400 px/em,
//! rotated and at sub-pixel offsets; the overlays mark what they claim to.
//!
//! The GPU tests need an adapter (CI installs lavapipe) and fail without one.

mod common;

use common::*;
use glam::DVec2;
use glyphscope::camera::Camera;
use glyphscope::coverage::CoverageImage;
use glyphscope::font::{Font, GlyphId, SHIPPED_FONTS};
use glyphscope::geometry::{DEFAULT_QUAD_TOLERANCE_EM, Outline, Segment, project};
use glyphscope::methods::params::{Params, owned};
use glyphscope::methods::sdf_cells::cells::Mode;
use glyphscope::methods::sdf_cells::curves::CurveLayout;
use glyphscope::methods::sdf_cells::glyph::PreparedGlyph;
use glyphscope::methods::sdf_cells::{self, SdfCells, Settings};
use glyphscope::methods::{CurveCost, Method};
use glyphscope::metrics::{ErrorStats, compare};
use glyphscope::reference;
use glyphscope::scene::Scene;

fn params(pairs: &[(&str, &str)]) -> Params {
    sdf_cells::INFO.parse_params(&owned(pairs)).unwrap()
}

/// Coverage, the rgb picture, and the method (for its cost and summary).
fn render(
    scene: &Scene,
    camera: &Camera,
    pairs: &[(&str, &str)],
) -> (CoverageImage, image::RgbImage, SdfCells) {
    let mut method = SdfCells::new(&params(pairs));
    let (coverage, picture) = render_with_picture(&mut method, scene, camera);
    (coverage, picture, method)
}

fn quadratic_outline(font: &Font, id: GlyphId) -> Outline {
    font.outline(id)
        .to_quadratics(DEFAULT_QUAD_TOLERANCE_EM * font.units_per_em())
}

// ---- Every glyph --------------------------------------------------------------------

/// Glyphs in each shipped font, blank ones included.
const GLYPH_COUNTS: [u16; 4] = [6253, 821, 2548, 488];

fn prepare_every_glyph(mode: &str) {
    let settings = Settings::from_params(&params(&[("mode", mode)]));
    let (mut past_slots, mut with_escapes, mut total) = (0, 0, 0);
    for (index, (name, _, _)) in SHIPPED_FONTS.iter().enumerate() {
        let font = glyphscope::font::shipped(index);
        assert_eq!(font.glyph_count(), GLYPH_COUNTS[index], "{name}");
        let (mut prepared, mut blank, mut cells, mut escaped) = (0, 0, 0, 0);
        for id in 0..font.glyph_count() {
            let outline = font.outline(id);
            if outline.is_empty() {
                blank += 1;
                continue;
            }
            let glyph = PreparedGlyph::new(&outline, font.units_per_em(), &settings)
                .unwrap_or_else(|e| panic!("{name} glyph {id}: {e}"));
            let has_curves = !glyph.layout.curve_slots.is_empty();
            for (cell, needed) in glyph.lists.iter().enumerate() {
                // Every cell has a nearest curve, and its encoding reaches every curve
                // it needs, and nothing but curves.
                assert!(!needed.is_empty() || !has_curves, "{name} {id}: empty cell");
                let visited = glyph.cells.cell_slots(cell);
                assert!(
                    needed.iter().all(|s| visited.contains(s)),
                    "{name} {id} cell {cell}: encoding lost a curve"
                );
                assert!(
                    visited
                        .iter()
                        .all(|&s| glyph.layout.slot_contour[s as usize].is_some()),
                    "{name} {id} cell {cell}: a run reads a slot that is no curve"
                );
            }
            if settings.mode == Mode::Exact {
                assert_eq!(glyph.bands.len(), glyph.grid.rows as usize);
            }
            prepared += 1;
            cells += glyph.grid.cells();
            escaped += glyph.cells.escaped;
            past_slots += usize::from(glyph.layout.slots() > 256);
            with_escapes += usize::from(glyph.cells.escaped > 0);
        }
        assert_eq!(prepared + blank, usize::from(font.glyph_count()));
        total += prepared;
        eprintln!(
            "{mode} {name}: {prepared} glyphs prepared + {blank} blank; {cells} cells, \
             {escaped} listed past font-demo's word"
        );
    }
    eprintln!(
        "{mode}: {total} glyphs; {past_slots} past font-demo's 512 points, \
         {with_escapes} with cells past its 17 curves or 3 runs"
    );
    // The fallback is exercised, not just present.
    assert!(past_slots > 0 && with_escapes > 0);
}

#[test]
fn every_glyph_of_every_shipped_font_prepares_for_the_estimate() {
    prepare_every_glyph("estimate");
}

#[test]
fn every_glyph_of_every_shipped_font_prepares_for_exact_distances() {
    prepare_every_glyph("exact");
}

// ---- Against the reference -----------------------------------------------------------

/// One method instance reused across scenes (its pipeline compiles once).
struct Renderer {
    method: SdfCells,
}

impl Renderer {
    fn new(pairs: &[(&str, &str)]) -> Renderer {
        Renderer {
            method: SdfCells::new(&params(pairs)),
        }
    }

    fn coverage(&mut self, scene: &Scene, camera: &Camera) -> CoverageImage {
        common::render(&mut self.method, scene, camera)
    }

    fn error(&mut self, scene: &Scene, camera: &Camera) -> ErrorStats {
        let image = self.coverage(scene, camera);
        compare(&image, &reference::rasterize(scene, camera).unwrap()).unwrap()
    }
}

/// Upright and rotated by 30°, both at sub-pixel offsets.
fn transforms() -> [([f64; 4], DVec2); 2] {
    let (s, c) = 30f64.to_radians().sin_cos();
    [
        ([1.0, 0.0, 0.0, 1.0], DVec2::new(0.37, 0.61)),
        ([c, -s, s, c], DVec2::new(0.11, 0.83)),
    ]
}

/// Glyphs with what breaks renderers: thin joins and tight curves (DejaVu), hairlines
/// and sharp serifs from cubics (Latin Modern), a variable font, a Bengali conjunct.
const SAMPLES: [(usize, &str); 4] = [
    (0, "g&@§"),
    (1, "Qa§g"),
    (2, "Bé4g@"),
    (3, "\u{0995}\u{09CD}\u{09B7}"),
];

#[test]
fn exact_mode_is_within_half_a_pixel_of_the_reference() {
    let mut exact = Renderer::new(&[("mode", "exact")]);
    let mut checked = 0;
    for (index, text) in SAMPLES {
        let font = glyphscope::font::shipped(index);
        for glyph in Scene::from_text(&font, text).unwrap().glyphs {
            let overlaps = reference::overlapping_contours(&quadratic_outline(&font, glyph.id));
            let scene = Scene::from_glyph_id(&font, u32::from(glyph.id)).unwrap();
            for size in [16.0, 48.0, 400.0] {
                for (matrix, subpixel) in transforms() {
                    let camera = framed(&scene, size, matrix, subpixel);
                    let e = exact.error(&scene, &camera);
                    let what = format!(
                        "{} glyph {} at {size} px/em, matrix {matrix:?}",
                        SHIPPED_FONTS[index].0, glyph.id
                    );
                    eprintln!("{what}: max {:.3}, MAE {:.3}/255", e.max, e.mae_255);
                    if !overlaps {
                        assert!(e.max <= 0.5, "{what}: {e:?}");
                        // Hairlines at 16 px/em (Latin Modern) reach 2.4/255 on a tight
                        // frame: see each render's line printed by
                        // `cargo test --release --test sdf_cells -- --nocapture exact_mode`.
                        assert!(e.mae_255 < 4.0, "{what}: {e:?}");
                        checked += 1;
                    }
                }
            }
        }
    }
    assert!(checked >= 60, "only {checked} renders without overlaps");
}

#[test]
fn the_standard_page_exact_clean_estimate_with_its_measured_artifacts() {
    let text = glyphscope::bench::scenes::PAGE_TEXT;
    let scene = Scene::from_text(&glyphscope::font::default_font(), text).unwrap();
    let camera = Camera::new(1920, 1080, 16.0, DVec2::new(24.0, 40.0));
    let expected = reference::rasterize(&scene, &camera).unwrap();
    let estimate = compare(
        &Renderer::new(&[("mode", "estimate")]).coverage(&scene, &camera),
        &expected,
    );
    let exact = compare(
        &Renderer::new(&[("mode", "exact")]).coverage(&scene, &camera),
        &expected,
    );
    let (estimate, exact) = (estimate.unwrap(), exact.unwrap());
    eprintln!("page, estimate: {estimate:?}\npage, exact: {exact:?}");
    assert_eq!(exact.pixels_over_05, 0);
    assert!(exact.mae_255 < 0.35 && exact.max < 0.45, "{exact:?}");
    // Measured (`cargo run --release --example sdf_cells_report -- page`): 2 pixels over
    // 0.5 (on 'ç'), where the nearest chord belongs to a curve whose tangent line puts
    // the pixel on the wrong side. More is a regression.
    assert!(estimate.pixels_over_05 <= 10, "{estimate:?}");
    assert!(estimate.mae_255 < 0.45, "{estimate:?}");
}

#[test]
fn the_estimate_halves_curves_until_their_chords_hold_them() {
    // The shapes the survey found the estimate a whole pixel off on: a ring an em wide
    // drawn with few quadratics, and tightly bent thin strokes.
    for name in ["large-circle", "bent-strokes"] {
        let case = glyphscope::stability::hard_cases::by_name(name).unwrap();
        let camera = case.camera(0.0, DVec2::new(0.25, 0.5)).unwrap();
        let expected = reference::rasterize(&case.scene, &camera).unwrap();
        let error = |pairs: &[(&str, &str)]| {
            compare(
                &Renderer::new(pairs).coverage(&case.scene, &camera),
                &expected,
            )
            .unwrap()
        };
        let published = error(&[("flatness", "off")]);
        let halved = error(&[]);
        eprintln!("{name}: as published {published:?}\nhalved {halved:?}");
        // font-demo as published: a chord far from its curve picks the wrong curve, or
        // its tangent line the wrong side, and some pixel reads more than half off ...
        assert!(published.pixels_over_05 > 0, "{name}: {published:?}");
        // ... and with its own remedy, each curve within 0.004 em of its chord, none.
        assert_eq!(halved.pixels_over_05, 0, "{name}: {halved:?}");
        assert!(halved.max <= 0.5, "{name}: {halved:?}");
    }
}

#[test]
fn the_estimate_reads_a_cusp_by_its_curves_far_ends() {
    // At each spike's tip the two curves arrive along one line: their tangents' turn is
    // rounding's, and read as concave it put a bar of full coverage across the tip (29
    // pixels over 0.5 on ✦ at 48 px/em before the far ends decided).
    let case = glyphscope::stability::hard_cases::by_name("star-tips").unwrap();
    for offset in [DVec2::ZERO, DVec2::new(0.25, 0.5)] {
        let camera = case.camera(0.0, offset).unwrap();
        let expected = reference::rasterize(&case.scene, &camera).unwrap();
        let error = compare(
            &Renderer::new(&[]).coverage(&case.scene, &camera),
            &expected,
        );
        let error = error.unwrap();
        assert_eq!(error.pixels_over_05, 0, "{offset}: {error:?}");
    }
}

/// Where the side comes from a rule — curves tied within `bias` that disagree, or a pixel
/// past the ends of the nearest chord — the winding number gives it (`ties=winding`, the
/// default). font-demo's rules alone (`ties=merge`) read a pixel a whole pixel off on
/// each of these: a triangle's tip on an arc, and Latin Modern's S and № at 48 px/em (a
/// pixel under the S's tail, one inside the №'s stem), at the survey's offsets.
#[test]
fn the_estimate_takes_the_side_from_the_winding_number_where_a_rule_gave_it() {
    let tip = glyphscope::stability::hard_cases::by_name("tip-on-arc").unwrap();
    let tip_camera = tip.camera(0.0, DVec2::ZERO).unwrap();
    let latin = Font::from_path(std::path::Path::new("fonts/lmroman10-regular.otf")).unwrap();
    let glyph = |id: u32, origin: (f64, f64)| {
        let scene = Scene::from_glyph_id(&latin, id).unwrap();
        (scene, Camera::new(40, 52, 48.0, origin.into()))
    };
    let views = [
        ("tip-on-arc", (tip.scene.clone(), tip_camera)),
        ("S", glyph(97, (1.2495, 36.886875))),
        ("numero", glyph(420, (1.1145, 36.781875))),
    ];
    let mut winding = Renderer::new(&[]);
    let mut merge = Renderer::new(&[("ties", "merge")]);
    for (name, (scene, camera)) in &views {
        let expected = reference::rasterize(scene, camera).unwrap();
        let published = compare(&merge.coverage(scene, camera), &expected).unwrap();
        assert!(published.max > 0.8, "{name}, ties=merge: {published:?}");
        let sided = compare(&winding.coverage(scene, camera), &expected).unwrap();
        assert!(sided.max <= 0.5, "{name}: {sided:?}");
    }
}

#[test]
fn glyphs_past_font_demos_limits_render_with_every_encoding() {
    // DejaVu glyphs past the 256 slots (512 points) of kocsis1david's font-demo: found,
    // not assumed.
    let font = glyphscope::font::default_font();
    let big: Vec<GlyphId> = (0..font.glyph_count())
        .filter(|&id| CurveLayout::new(&quadratic_outline(&font, id)).slots() > 256)
        .take(2)
        .collect();
    assert_eq!(big.len(), 2, "DejaVu Sans has glyphs past 512 points");
    let mut renderers: Vec<(&str, Renderer)> = ["auto", "packed", "list"]
        .into_iter()
        .map(|e| (e, Renderer::new(&[("mode", "exact"), ("encoding", e)])))
        .collect();
    for id in big {
        let scene = Scene::from_glyph_id(&font, u32::from(id)).unwrap();
        let camera = framed(&scene, 64.0, [1.0, 0.0, 0.0, 1.0], DVec2::new(0.3, 0.7));
        let expected = reference::rasterize(&scene, &camera).unwrap();
        let mut images = Vec::new();
        for (encoding, renderer) in &mut renderers {
            let image = renderer.coverage(&scene, &camera);
            let e = compare(&image, &expected).unwrap();
            let summary = renderer.method.summary().unwrap();
            eprintln!(
                "glyph {id}, encoding={encoding}: {summary:?}, max {:.3}",
                e.max
            );
            assert!(e.max <= 0.5, "glyph {id}, encoding={encoding}: {e:?}");
            if *encoding == "list" {
                assert_eq!(summary.escaped_cells, summary.cells);
            } else {
                assert!(
                    summary.escaped_cells > 0,
                    "past 256 slots, some cells escape"
                );
            }
            images.push(image);
        }
        // Exact distances do not depend on which superset of the needed curves a
        // cell visits.
        for other in &images[1..] {
            assert!(compare(other, &images[0]).unwrap().max < 2e-3);
        }
    }
}

// ---- Overlays ------------------------------------------------------------------------

/// The two smallest distances from `p` to the curves of `layout`, in f64, by the
/// mode's measure: to the chord for the estimate, to the curve for exact distances.
fn two_nearest(layout: &CurveLayout, p: DVec2, mode: Mode) -> (f64, f64) {
    let point = lyon_geom::point(p.x, p.y);
    let mut best = (f64::INFINITY, f64::INFINITY);
    for (_, q) in layout.curves() {
        let [a, b, c] = q.map(|v| lyon_geom::point(v.x, v.y));
        let d = match mode {
            Mode::Estimate => lyon_geom::LineSegment { from: a, to: c }.distance_to_point(point),
            Mode::Exact => lyon_geom::QuadraticBezierSegment {
                from: a,
                ctrl: b,
                to: c,
            }
            .distance_to_point(point),
        };
        if d < best.0 {
            best = (d, best.0);
        } else if d < best.1 {
            best.1 = d;
        }
    }
    best
}

/// The overlay's purple (mixed 85% over the picture): blue well above green.
fn is_purple(pixel: &image::Rgb<u8>) -> bool {
    i32::from(pixel[2]) - i32::from(pixel[1]) > 76
}

/// Renders `scene` with the purple overlay and checks it against the tie set computed
/// in f64 over the glyph's box, from the curves as the method lays them out: pixels whose two nearest distances differ by less than
/// `bias − margin` are purple, those differing by more than `bias + margin` are not.
/// Returns how many pixels were purple.
fn check_tie_set(
    scene: &Scene,
    camera: &Camera,
    (mode, flatness): (&str, &str),
    bias_em: f64,
    margin: f64,
) -> usize {
    let bias_text = bias_em.to_string();
    let (_, picture, method) = render(
        scene,
        camera,
        &[
            ("mode", mode),
            ("flatness", flatness),
            ("overlay", "purple"),
            ("bias", &bias_text),
        ],
    );
    let glyph = &scene.glyphs[0];
    // The curves as the method lays them out (the estimate's halved to its flatness).
    let layout = PreparedGlyph::new(&glyph.outline, scene.units_per_em, method.settings())
        .unwrap()
        .layout;
    let to_local = camera
        .glyph_to_image(scene.units_per_em, scene.instances[0].position)
        .inverse();
    let bias = bias_em * scene.units_per_em;
    let (mut purple, mut checked) = (0, 0);
    for (x, y, pixel) in picture.enumerate_pixels() {
        let p = project(
            &to_local,
            DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5),
        );
        if p.cmplt(glyph.bounds.min).any() || p.cmpgt(glyph.bounds.max).any() {
            continue;
        }
        let (first, second) = two_nearest(&layout, p, method.settings().mode);
        let gap = second - first;
        if (gap - bias).abs() < margin {
            continue;
        }
        checked += 1;
        assert_eq!(
            is_purple(pixel),
            gap < bias,
            "{mode}: pixel ({x}, {y}) at {p}: distances {first} and {second}, bias {bias}"
        );
        purple += usize::from(gap < bias);
    }
    assert!(checked > picture.len() / 3 / 4, "most pixels are decided");
    purple
}

/// font-demo's figure: two quadratics turning left at p2 (here closed by three lines
/// far from p2), one font unit per pixel.
fn font_demo_example() -> Scene {
    let p = [
        (20.0, 40.0),
        (60.0, 140.0),
        (100.0, 80.0),
        (140.0, 20.0),
        (180.0, 120.0),
    ]
    .map(|(x, y)| DVec2::new(x, y));
    let corner = |x, y| DVec2::new(x, y);
    let segments = vec![
        Segment::Quad(p[0], p[1], p[2]),
        Segment::Quad(p[2], p[3], p[4]),
        Segment::Line(p[4], corner(180.0, 230.0)),
        Segment::Line(corner(180.0, 230.0), corner(20.0, 230.0)),
        Segment::Line(corner(20.0, 230.0), p[0]),
    ];
    single(Outline {
        contours: vec![glyphscope::geometry::Contour { segments }],
    })
}

#[test]
fn purple_marks_font_demos_tie_regions_and_nothing_else() {
    let scene = font_demo_example();
    let camera = unit_camera(200, 250);
    for mode in ["estimate", "exact"] {
        // A 2-unit bias: wide enough to see, small against the curves; font-demo's two
        // curves as it draws them, not halved.
        let purple = check_tie_set(&scene, &camera, (mode, "off"), 0.002, 0.05);
        eprintln!("font-demo example, {mode}: {purple} purple pixels");
        assert!(purple > 200, "{mode}: the tie regions are there");
    }
}

#[test]
fn purple_marks_the_tie_regions_of_a_real_glyph() {
    let font = glyphscope::font::default_font();
    let scene = Scene::from_glyph_id(&font, u32::from(font.glyph_for_char('a').unwrap())).unwrap();
    // About 10 font units per pixel, turned so nothing lines up with the pixels.
    let camera = framed(
        &scene,
        200.0,
        [0.96, -0.28, 0.28, 0.96],
        DVec2::new(0.3, 0.6),
    );
    for mode in ["estimate", "exact"] {
        // The estimate's curves halved to its default flatness.
        let purple = check_tie_set(&scene, &camera, (mode, "0.004"), 0.004, 0.5);
        eprintln!("DejaVu 'a', {mode}: {purple} purple pixels");
        assert!(purple > 300, "{mode}: the tie regions are there");
    }
}

/// Renders one glyph of DejaVu Sans upright, prepared as the renderer prepares it, and
/// hands each pixel's local centre to `check` with the pixel's coverage and colour.
fn for_each_pixel(
    c: char,
    pairs: &[(&str, &str)],
    mut check: impl FnMut(&PreparedGlyph, DVec2, f32, &image::Rgb<u8>),
) -> (CurveCost, Camera) {
    let font = glyphscope::font::default_font();
    let scene = Scene::from_glyph_id(&font, u32::from(font.glyph_for_char(c).unwrap())).unwrap();
    let camera = framed(&scene, 150.0, [1.0, 0.0, 0.0, 1.0], DVec2::new(0.25, 0.5));
    let (coverage, picture, mut method) = render(&scene, &camera, pairs);
    let settings = *method.settings();
    let glyph =
        PreparedGlyph::new(&scene.glyphs[0].outline, scene.units_per_em, &settings).unwrap();
    let to_local = camera
        .glyph_to_image(scene.units_per_em, DVec2::ZERO)
        .inverse();
    for (x, y, pixel) in picture.enumerate_pixels() {
        let p = project(
            &to_local,
            DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5),
        );
        check(&glyph, p, coverage.get(x, y), pixel);
    }
    let cost = method.curves_per_pixel(gpu(), &camera).unwrap().unwrap();
    (cost, camera)
}

#[test]
fn cell_overlay_draws_the_grid_and_tints_cells_by_their_curves() {
    let scale = 150.0 / 2048.0;
    // Outside the ink, by cell: the tint seen, and the cell's curve count.
    let mut tints: std::collections::HashMap<usize, (image::Rgb<u8>, usize)> = Default::default();
    let (mut lines, mut unlined) = (0, 0);
    for_each_pixel(
        'a',
        &[("overlay", "cells"), ("grid", "6")],
        |glyph, p, coverage, pixel| {
            let grid = &glyph.grid;
            let quad = glyph.quad();
            if p.cmplt(quad.min).any() || p.cmpgt(quad.max).any() {
                return;
            }
            // Pixels from the nearest cell border, along x and y.
            let f = (p - grid.origin) / grid.cell;
            let border = (f - f.round()).abs() * grid.cell * scale;
            let near = border.min_element();
            let red = pixel.0 == [255, 64, 51];
            if (near - 0.5).abs() > 0.05 {
                assert_eq!(red, near < 0.5, "pixel at {p}: {near:.3} px from a border");
                lines += usize::from(red);
            }
            if near > 1.0 && coverage == 0.0 {
                let index = grid.cell_index(p);
                let count = glyph.cells.cell_slots(index).len();
                let seen = tints.entry(index).or_insert((*pixel, count));
                assert_eq!(seen.0, *pixel, "one tint per cell");
                unlined += 1;
            }
        },
    );
    assert!(
        lines > 500 && unlined > 500,
        "{lines} line pixels, {unlined} tinted"
    );
    // The heat scale is monotone in lightness: more curves, lighter tint.
    let mut by_count: Vec<(usize, u32)> = tints
        .values()
        .map(|(pixel, count)| (*count, pixel.0.iter().map(|&v| u32::from(v)).sum()))
        .collect();
    by_count.sort();
    assert!(
        by_count
            .windows(2)
            .all(|w| w[0].0 == w[1].0 || w[0].1 <= w[1].1),
        "{by_count:?}"
    );
    assert!(by_count.first().unwrap().0 < by_count.last().unwrap().0);
}

#[test]
fn curves_per_pixel_counts_what_the_cells_and_bands_hold() {
    // The estimate walks its bands only where a rule gives a pixel's side
    // (`ties=winding`), which the CPU does not mirror: counted here with font-demo's
    // rules alone, no bands; exact mode walks them at every pixel.
    for (mode, ties) in [("estimate", "merge"), ("exact", "winding")] {
        let (mut sum, mut covered, mut max) = (0usize, 0usize, 0usize);
        let params = [("mode", mode), ("ties", ties)];
        let (cost, _) = for_each_pixel('g', &params, |glyph, p, coverage, _| {
            if coverage <= 0.0 {
                return;
            }
            let mut count = glyph.cells.cell_slots(glyph.grid.cell_index(p)).len();
            if !glyph.bands.is_empty() {
                // The band walk stops at the first curve wholly left of p.
                let row = glyph.grid.cell_index(p) / glyph.grid.cols as usize;
                count += glyph.bands[row]
                    .iter()
                    .take_while(|&&s| glyph.layout.curve(s).iter().any(|q| q.x > p.x))
                    .count();
            }
            sum += count;
            covered += 1;
            max = max.max(count);
        });
        let mean = sum as f64 / covered as f64;
        eprintln!("{mode}: GPU {cost:?}, expected mean {mean:.3}, max {max}");
        assert!(
            (cost.mean - mean).abs() < 0.01 * mean,
            "{mode}: {cost:?} vs {mean}"
        );
        assert!(
            cost.max.abs_diff(max as u32) <= 1,
            "{mode}: {cost:?} vs {max}"
        );
    }
}

// ---- Footprint anti-aliasing, transforms, effects ----------------------------------------

/// Polygons whose vertices and horizontal edges sit on pixel centres (one unit per pixel
/// upright): rays through shared endpoints and along horizontal edges, a hole, both
/// orientations.
fn polygon_scene() -> (Scene, Vec<DVec2>) {
    let l_shape = [
        (10.5, 10.5),
        (60.5, 10.5),
        (60.5, 30.5),
        (30.5, 30.5),
        (30.5, 70.5),
        (10.5, 70.5),
    ];
    let triangle = [(70.5, 2.5), (110.5, 2.5), (90.5, 37.5)];
    let frame = rect(40.0, 40.0, 110.0, 95.0);
    // A hole the other way round.
    let hole: Vec<(f64, f64)> = rect(55.5, 50.5, 95.5, 80.5).into_iter().rev().collect();
    let outline = polygons(&[&l_shape, &triangle, &frame, &hole]);
    let vertices = outline.segments().map(|s| s.start()).collect();
    (single(outline), vertices)
}

#[test]
fn straight_edges_get_the_exact_box_filter_under_any_transform() {
    let (scene, vertices) = polygon_scene();
    let base = unit_camera(120, 100);
    let (s, c) = 30f64.to_radians().sin_cos();
    let cameras = [
        ("upright", base),
        (
            "rotated and skewed",
            Camera {
                matrix: Camera::matrix_from_rows(c, c * 0.3 - s, s, s * 0.3 + c),
                origin: DVec2::new(40.0, 90.0),
                width: 150,
                height: 150,
                ..base
            },
        ),
        (
            "zoomed 3.7×",
            Camera {
                size_px_per_em: 3700.0,
                origin: DVec2::new(-120.3, 420.6),
                width: 300,
                height: 300,
                ..base
            },
        ),
        (
            "tilted 25°",
            Camera {
                tilt_deg: 25.0,
                ..base
            },
        ),
        (
            "mirrored",
            Camera {
                matrix: Camera::matrix_from_rows(-1.0, 0.0, 0.0, 1.0),
                origin: DVec2::new(120.0, 100.0),
                ..base
            },
        ),
    ];
    for mode in ["estimate", "exact"] {
        let mut renderer = Renderer::new(&[("mode", mode)]);
        for (name, camera) in &cameras {
            let image = renderer.coverage(&scene, camera);
            let expected = reference::rasterize(&scene, camera).unwrap();
            assert!(expected.sum() > 2000.0, "{name}: the polygons are in view");
            let to_image = camera.glyph_to_image(scene.units_per_em, DVec2::ZERO);
            let corners: Vec<DVec2> = vertices.iter().map(|&v| project(&to_image, v)).collect();
            let (mut worst, mut worst_anywhere) = (0.0f32, 0.0f32);
            for y in 0..camera.height {
                for x in 0..camera.width {
                    let e = (image.get(x, y) - expected.get(x, y)).abs();
                    worst_anywhere = worst_anywhere.max(e);
                    let centre = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
                    // Distance AA rounds corners: judge edges away from them.
                    if corners.iter().all(|v| v.distance(centre) > 1.5) {
                        worst = worst.max(e);
                    }
                }
            }
            eprintln!("{mode}, {name}: {worst:.4} along edges, {worst_anywhere:.3} anywhere");
            assert!(worst < 0.005, "{mode}, {name}: {worst} along edges");
            assert!(worst_anywhere <= 0.5, "{mode}, {name}: {worst_anywhere}");
        }
    }
}

#[test]
fn a_far_world_offset_changes_nothing() {
    let font = glyphscope::font::shipped(1);
    let scene = Scene::from_text(&font, "Sg").unwrap();
    let near = framed(&scene, 37.0, [0.9, 0.3, -0.2, 1.1], DVec2::new(0.25, 0.5));
    let far = Camera {
        world_offset: DVec2::new(1e5, -1e5),
        ..near
    };
    for mode in ["estimate", "exact"] {
        let mut renderer = Renderer::new(&[("mode", mode)]);
        let shift = compare(
            &renderer.coverage(&scene, &far),
            &renderer.coverage(&scene, &near),
        );
        assert!(shift.unwrap().max < 2e-3, "{mode}");
    }
}

/// A closed polygon approximating the square [50, 250]² grown by `r` (rounded corners;
/// 64 chords per quarter circle stay within 0.002 units of the arc for r ≤ 20).
fn rounded_square(r: f64) -> Vec<(f64, f64)> {
    let corners = [(50.0, 50.0), (250.0, 50.0), (250.0, 250.0), (50.0, 250.0)];
    let mut points = Vec::new();
    for (k, (x, y)) in corners.into_iter().enumerate() {
        for step in 0..=64 {
            let angle = (180.0 + 90.0 * k as f64 + 90.0 * f64::from(step) / 64.0).to_radians();
            points.push((x + r * angle.cos(), y + r * angle.sin()));
        }
    }
    points
}

#[test]
fn effects_follow_the_exact_distance() {
    let square = single(polygons(&[&rect(50.0, 50.0, 250.0, 250.0)]));
    let camera = unit_camera(300, 300);
    let reference_of = |points: &[(f64, f64)]| {
        reference::rasterize(&single(polygons(&[points])), &camera).unwrap()
    };
    let coverage = |pairs: &[(&str, &str)]| {
        let mut all = vec![("mode", "exact")];
        all.extend_from_slice(pairs);
        render(&square, &camera, &all).0
    };
    // Dilation rounds the corners with the distance's circles; erosion keeps them sharp.
    let dilated = compare(
        &coverage(&[("dilate", "0.02")]),
        &reference_of(&rounded_square(20.0)),
    );
    let eroded = compare(
        &coverage(&[("dilate", "-0.02")]),
        &reference_of(&rect(70.0, 70.0, 230.0, 230.0)),
    );
    eprintln!("dilated: {dilated:?}\neroded: {eroded:?}");
    assert!(dilated.unwrap().max < 0.02);
    assert!(eroded.unwrap().max < 0.02);
    // An outline 10 units wide: the grown shape less the glyph.
    let ring = coverage(&[("outline", "0.01")]);
    let (outer, inner) = (
        reference_of(&rounded_square(10.0)),
        reference_of(&rect(50.0, 50.0, 250.0, 250.0)),
    );
    let mut worst = 0.0f32;
    for (k, v) in ring.data.iter().enumerate() {
        worst = worst.max((v - (outer.data[k] - inner.data[k])).abs());
    }
    assert!(worst < 0.02, "outline off by {worst}");
    // A glow fading to nothing 30 units out: 0.6 (1 − d/30)² beyond the edge's pixel.
    let glow = coverage(&[("glow", "0.03")]);
    for (k, &v) in glow.data.iter().enumerate() {
        let centre = DVec2::new((k % 300) as f64 + 0.5, 300.0 - ((k / 300) as f64 + 0.5));
        let outside = (DVec2::splat(50.0) - centre).max(centre - DVec2::splat(250.0));
        let d = outside.max(DVec2::ZERO).length().max(outside.max_element());
        let expected = if d <= -1.0 {
            1.0
        } else if d >= 1.0 {
            0.6 * (1.0 - (d / 30.0).min(1.0)).powi(2)
        } else {
            continue;
        };
        assert!(
            (f64::from(v) - expected).abs() < 0.01,
            "glow at {centre}: {v}, not {expected}"
        );
    }
    // With an outline the glyph is hollow and the glow starts at the stroke's outer edge.
    let both = coverage(&[("outline", "0.01"), ("glow", "0.03")]);
    let at = |x: u32, y: u32| both.get(x, 300 - 1 - y);
    assert_eq!(at(150, 150), 0.0, "nothing inside the stroke");
    assert!((at(150, 255) - 1.0).abs() < 2e-3, "the stroke");
    let expected = 0.6 * (1.0 - 15.5 / 30.0f32).powi(2);
    assert!(
        (at(150, 275) - expected).abs() < 0.01,
        "{} vs {expected}",
        at(150, 275)
    );
}

// ---- Overlapping contours ------------------------------------------------------------------

/// The nonzero winding number of a polyline outline at `p` (ray to +x, half-open).
fn winding(polylines: &[Vec<DVec2>], p: DVec2) -> i32 {
    let mut w = 0;
    for line in polylines {
        for pair in line.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            if (a.y > p.y) != (b.y > p.y) {
                let x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
                if x > p.x {
                    w += if b.y > a.y { 1 } else { -1 };
                }
            }
        }
    }
    w
}

#[test]
fn overlapping_contours_crack_only_along_the_curves_inside_the_fill() {
    let font = glyphscope::font::shipped(2);
    // As the font draws them; the default merges them first (checked at the end).
    let mut exact = Renderer::new(&[("mode", "exact"), ("overlaps", "keep")]);
    let mut merged = Renderer::new(&[("mode", "exact")]);
    let mut cracked = 0;
    for c in "etfQ&".chars() {
        let id = font.glyph_for_char(c).unwrap();
        let outline = quadratic_outline(&font, id);
        assert!(
            reference::overlapping_contours(&outline),
            "Inter {c:?} has overlapping contours"
        );
        let scene = Scene::from_glyph_id(&font, u32::from(id)).unwrap();
        let camera = framed(&scene, 200.0, [1.0, 0.0, 0.0, 1.0], DVec2::new(0.4, 0.1));
        let to_image = camera.glyph_to_image(scene.units_per_em, DVec2::ZERO);
        // Points of curves with fill on both sides: where a distance field cracks.
        let polylines: Vec<Vec<DVec2>> = outline
            .contours
            .iter()
            .map(|contour| {
                let mut points = vec![contour.segments[0].start()];
                for s in &contour.segments {
                    s.flatten(0.05, &mut |p| points.push(p));
                }
                points
            })
            .collect();
        let mut inside_curves = Vec::new();
        for line in &polylines {
            for pair in line.windows(2) {
                let normal = (pair[1] - pair[0]).perp().normalize_or_zero() * 2.0;
                // A sample every 2 units, a fifth of a pixel.
                let steps = (pair[0].distance(pair[1]) / 2.0).ceil().max(1.0) as u32;
                for k in 0..steps {
                    let q = pair[0].lerp(pair[1], f64::from(k) / f64::from(steps));
                    if winding(&polylines, q + normal) != 0 && winding(&polylines, q - normal) != 0
                    {
                        inside_curves.push(project(&to_image, q));
                    }
                }
            }
        }
        let image = exact.coverage(&scene, &camera);
        let expected = reference::rasterize(&scene, &camera).unwrap();
        // Elsewhere exact mode stays under 0.45 (corners of the 16 px/em samples, as
        // `cargo test --release --test sdf_cells -- --nocapture exact_mode` prints); a
        // crack inside the fill reads 0.5 where an inner curve passes through the centre.
        let mut bad = 0;
        for y in 0..camera.height {
            for x in 0..camera.width {
                let e = (image.get(x, y) - expected.get(x, y)).abs();
                if e > 0.45 {
                    let centre = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
                    let near = inside_curves
                        .iter()
                        .map(|q| q.distance(centre))
                        .fold(f64::MAX, f64::min);
                    assert!(
                        near < 1.5,
                        "Inter {c:?}: pixel ({x}, {y}) off by {e}, {near} px from any inner curve"
                    );
                    bad += 1;
                }
            }
        }
        let e = compare(&image, &expected).unwrap();
        eprintln!(
            "Inter {c:?} at 200 px/em: {bad} pixels off by > 0.45 along inner curves ({} > 0.25), max {:.3}",
            e.pixels_over_025, e.max
        );
        cracked += bad;
        // Merged first (the default), no pixel is off by more than exact mode's 0.45
        // elsewhere.
        let e = compare(&merged.coverage(&scene, &camera), &expected).unwrap();
        eprintln!("  merged: max {:.3}, {} > 0.25", e.max, e.pixels_over_025);
        assert!(e.max <= 0.45, "Inter {c:?} merged: max {}", e.max);
    }
    // The weakness is real, and shown.
    assert!(cracked > 20, "{cracked}");
}

// ---- Contours of either direction, segments shorter than f32 can point -------------------

/// The estimate through the stability sweep's CI cameras on `case`: the outcome of its
/// worst frame, artifact pixels (off by more than 0.5) summed over the frames.
fn estimate_on_case(case: &str) -> glyphscope::stability::outcome::Outcome {
    use glyphscope::stability::{self, sweep};
    let cases = stability::select_cases(Some(&[case.into()])).unwrap();
    let variants: Vec<_> = stability::select_variants(Some(&["sdf-cells".into()]))
        .unwrap()
        .into_iter()
        .filter(|v| v.params.is_empty())
        .collect();
    assert_eq!(variants.len(), 1, "the estimate is sdf-cells' default");
    let outcomes = sweep::run(
        gpu(),
        &cases,
        &variants,
        &sweep::SweepSize::of(&glyphscope::effort::Effort::QUICK),
        |_| {},
    );
    let outcome = outcomes.unwrap().remove(0);
    assert!(outcome.failure.is_none(), "{:?}", outcome.failure);
    // One frame in full, whole frame and edge pixels (> 0.25 and > 0.5 counted), for
    // docs/methods/sdf-cells.md: the case's own view at offset 0, upright.
    let camera = cases[0].camera(0.0, DVec2::ZERO).unwrap();
    let e = Renderer::new(&[]).error(&cases[0].scene, &camera);
    eprintln!(
        "{case}, estimate, upright at offset 0: MAE {:.2}/255, max {:.3}, {} px > 0.25, {} > 0.5; \
         edge pixels ({}): MAE {:.2}/255, {} > 0.25, {} > 0.5",
        e.mae_255,
        e.max,
        e.pixels_over_025,
        e.pixels_over_05,
        e.edge.pixels,
        e.edge.mae_255,
        e.edge.pixels_over_025,
        e.edge.pixels_over_05
    );
    outcome
}

/// The outcome in one line: MAE, max, pixels over 0.5, where it was worst.
fn summary(case: &str, o: &glyphscope::stability::outcome::Outcome) -> String {
    format!(
        "{case}, estimate: MAE {:.2}/255, max {:.3}, {} pixels over 0.5, worst at {:?}",
        o.mae_255, o.max, o.artifact_pixels, o.worst
    )
}

/// Separate contours wound opposite ways are all filled under nonzero; the estimate
/// turned every contour by the glyph's total orientation, so those wound against it had
/// their fill on the left and drew inverted: empty inside, their cells' boxes filled
/// around. Each contour is now turned by the winding around it. Like the plain squares
/// of the other synthetic cases (no pixel over 0.5), no pixel may be off by more than
/// 0.5.
#[test]
fn the_estimate_fills_contours_wound_either_way() {
    let case = "opposite-wound-contours";
    let outcome = estimate_on_case(case);
    eprintln!("{}", summary(case, &outcome));
    assert!(outcome.max.is_finite(), "{}", summary(case, &outcome));
    assert_eq!(outcome.artifact_pixels, 0, "{}", summary(case, &outcome));
}

/// A segment 2–4 f32 steps long cutting a square's corner reached the shader with its
/// direction rounded to almost anything, and the estimate took the side of the pixels
/// beyond the corner from it. Segments under 10 steps are now merged into the next one:
/// the squares draw as squares, no pixel off by more than 0.5.
#[test]
fn the_estimate_ignores_segments_too_short_for_f32_to_point() {
    let case = "slanted-ulp-segments";
    let outcome = estimate_on_case(case);
    eprintln!("{}", summary(case, &outcome));
    assert!(outcome.max.is_finite(), "{}", summary(case, &outcome));
    assert_eq!(outcome.artifact_pixels, 0, "{}", summary(case, &outcome));
}

// ---- Command line ----------------------------------------------------------------------

#[test]
fn the_command_line_renders_overlays_and_rejects_bad_parameters() {
    let dir = std::env::temp_dir().join(format!("glyphscope-sdf-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (out, stats) = (dir.join("cells.png"), dir.join("cells.json"));
    let run = |extra: &[&str]| {
        let mut args = vec![
            "render",
            "--text",
            "Sg",
            "--size",
            "40",
            "--method",
            "sdf-cells",
        ];
        args.extend_from_slice(extra);
        args.extend_from_slice(&["--out", out.to_str().unwrap()]);
        std::process::Command::new(env!("CARGO_BIN_EXE_glyphscope"))
            .args(&args)
            .output()
            .unwrap()
    };
    let ok = run(&[
        "--param",
        "mode=exact",
        "--param",
        "overlay=cells",
        "--stats",
        stats.to_str().unwrap(),
    ]);
    assert!(
        ok.status.success(),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );
    assert_eq!(image::open(&out).unwrap().color(), image::ColorType::Rgb8);
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
    assert!(json["curves_per_pixel"]["mean"].as_f64().unwrap() > 1.0);
    assert!(json["gpu_ms"].as_f64().is_some());
    for (bad, expect) in [
        ("mode=fast", "estimate or exact"),
        ("grid=0", "1 to 64"),
        ("encoding=zip", "auto, packed or list"),
        ("glow=-1", "number of em"),
        (
            "overlay=wireframe",
            "overlay must be none, purple, cells or cost",
        ),
    ] {
        std::fs::remove_file(&out).ok();
        let failed = run(&["--param", bad]);
        let stderr = String::from_utf8_lossy(&failed.stderr);
        assert_eq!(failed.status.code(), Some(2), "{bad}: {stderr}");
        assert!(
            stderr.contains(expect) && !stderr.contains("panicked"),
            "{bad}: {stderr}"
        );
        assert!(!out.exists(), "{bad}: an image was written");
    }
}
