//! `winding aa=area`, the exact box-filter integral per pixel, against the exact
//! reference: real glyphs of every shipped font at 8–400 px/em under rotation, skew and
//! a mirror at 16 sub-pixel offsets; straight edges at any angle and phase; the shader
//! against its f64 mirror on the same curves; overlapping contours; what its settings
//! change.
//!
//! Bounds: where contours do not overlap, the integral is exact, and what is left is
//! f32 arithmetic and the half-float target, whose steps below 1 are 2⁻¹¹ (and the
//! conversion to it may round either way) — hence 0.02/255 mean and 0.02 max over whole
//! images (the bound `aa=area` is held to), and one step plus f32's share where one edge is checked
//! alone.

mod common;

use common::*;
use glam::{DMat2, DVec2};
use glyphscope::camera::Camera;
use glyphscope::font::{Font, SHIPPED_FONTS};
use glyphscope::geometry::{DEFAULT_QUAD_TOLERANCE_EM, Outline, Quad, Segment};
use glyphscope::methods::winding::area;
use glyphscope::methods::{Method, frame, registry};
use glyphscope::metrics::{ErrorStats, compare};
use glyphscope::reference;
use glyphscope::scene::Scene;

/// One step of the half-float target below 1: the conversion to it may round either way.
const TARGET_ROUNDING: f64 = 1.0 / 2048.0;

fn area_method(params: &[(&str, &str)]) -> Box<dyn Method> {
    let params: Vec<(String, String)> = [("aa", "area")]
        .iter()
        .chain(params)
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect();
    registry::create("winding", &params).unwrap()
}

fn error(params: &[(&str, &str)], scene: &Scene, cam: &Camera) -> ErrorStats {
    let got = render(area_method(params).as_mut(), scene, cam);
    compare(&got, &reference::rasterize(scene, cam).unwrap()).unwrap()
}

/// The 16 sub-pixel offsets of a 4×4 grid, kept off the pixel grid's symmetries.
fn subpixel(k: u32) -> DVec2 {
    DVec2::new(f64::from(k % 4) / 4.0 + 0.03, f64::from(k / 4) / 4.0 + 0.07)
}

/// The general frame (rotated, skewed) and the rectangle pixels of the `AXIS` draws:
/// plain, mirrored, a quarter turn (the image's x along the glyph's y) and stretched.
fn transforms() -> [(&'static str, [f64; 4]); 6] {
    let (s, c) = 30f64.to_radians().sin_cos();
    [
        ("identity", [1.0, 0.0, 0.0, 1.0]),
        ("rotated 30°", [c, -s, s, c]),
        ("skewed", [1.0, 0.4, 0.0, 1.0]),
        ("mirrored", [-1.0, 0.0, 0.0, 1.0]),
        ("quarter turn", [0.0, -1.0, 1.0, 0.0]),
        ("stretched", [1.7, 0.0, 0.0, 0.6]),
    ]
}

/// The glyphs of `text` in `font` whose contours overlap (`want_overlaps`) or do not,
/// as placed by shaping: judged by `reference::overlapping_contours`, which measures the
/// filled area with the reference, independently of `aa=area`'s own marks.
fn glyphs_of(font: &Font, text: &str, want_overlaps: bool) -> Scene {
    let shaped = Scene::from_text(font, text).unwrap();
    let tolerance = DEFAULT_QUAD_TOLERANCE_EM * shaped.units_per_em;
    let placed: Vec<(Outline, DVec2)> = shaped
        .instances
        .iter()
        .map(|i| &shaped.glyphs[i.glyph as usize])
        .zip(&shaped.instances)
        .filter(|(g, _)| {
            reference::overlapping_contours(&g.outline.to_quadratics(tolerance)) == want_overlaps
        })
        .map(|(g, i)| (g.outline.clone(), i.position))
        .collect();
    Scene::from_outlines(shaped.units_per_em, placed)
}

/// Texts with each font's hard shapes: quadratic bowls, Latin Modern's cubics, Inter's
/// joins, Bengali conjuncts.
const TEXTS: [&str; 4] = [
    "g&@Se",
    "Qa§gf",
    "BéW4k",
    "\u{0995}\u{09CD}\u{09B7}\u{0999}",
];

#[test]
fn every_font_size_and_transform_is_exact_where_contours_do_not_overlap() {
    println!("| font | px/em | transform | glyphs | worst MAE /255 | max |");
    for (index, text) in TEXTS.iter().enumerate() {
        let font = glyphscope::font::shipped(index);
        let all = glyphs_of(&font, text, false);
        assert!(
            all.instances.len() >= 2,
            "{}: too few plain glyphs",
            SHIPPED_FONTS[index].0
        );
        for size in [8.0, 16.0, 48.0, 400.0] {
            // At 400 px/em two glyphs hold thousands of edge pixels at every phase.
            let scene = if size > 100.0 {
                let placed = all.instances[..2]
                    .iter()
                    .map(|i| (all.glyphs[i.glyph as usize].outline.clone(), i.position))
                    .collect();
                Scene::from_outlines(all.units_per_em, placed)
            } else {
                all.clone()
            };
            let mut method = area_method(&[]);
            method.prepare(gpu(), &scene).unwrap();
            for (name, matrix) in transforms() {
                let (mut worst_mae, mut max) = (0.0f64, 0.0f64);
                for k in 0..16 {
                    let cam = framed(&scene, size, matrix, subpixel(k));
                    let got = frame::render_image(gpu(), method.as_mut(), &cam).unwrap();
                    let s = compare(&got, &reference::rasterize(&scene, &cam).unwrap()).unwrap();
                    assert!(
                        s.mae_255 <= 0.02 && s.max <= 0.02,
                        "{} at {size} px/em, {name}, offset {k}: {s:?}",
                        SHIPPED_FONTS[index].0
                    );
                    worst_mae = worst_mae.max(s.mae_255);
                    max = max.max(s.max);
                }
                println!(
                    "| {} | {size} | {name} | {} | {worst_mae:.4} | {max:.4} |",
                    SHIPPED_FONTS[index].0,
                    scene.instances.len()
                );
            }
        }
    }
}

/// Inter's glyphs whose contours overlap, at its default weight and at 900, at 16 and
/// 48 px/em, under every transform at four offsets, drawn by winding with `params`: each
/// view named, with its error.
fn overlapping_inter_views(params: &[(&str, &str)]) -> Vec<(String, ErrorStats)> {
    let inter = glyphscope::font::shipped(2);
    let mut views = Vec::new();
    for weight in [400.0, 900.0] {
        let font = inter.with_variations(&[("wght".into(), weight)]).unwrap();
        let scene = glyphs_of(&font, "ÖkonomieAB&@Rg48$", true);
        assert!(
            scene.instances.len() >= 3,
            "wght {weight}: too few overlapping glyphs"
        );
        for size in [16.0, 48.0] {
            for (name, matrix) in transforms() {
                for k in [0, 5, 10, 15] {
                    let cam = framed(&scene, size, matrix, subpixel(k));
                    let view = format!("wght {weight}, {size} px/em, {name}, offset {k}");
                    views.push((view, error(params, &scene, &cam)));
                }
            }
        }
    }
    views
}

/// Overlapping contours as the font draws them (`overlaps=keep`): the pixels where
/// their curves meet another are integrated in sub-pixels, and none is off by more than
/// a quarter.
#[test]
fn overlapping_contours_stay_within_a_quarter() {
    for (view, s) in overlapping_inter_views(&[("overlaps", "keep")]) {
        assert_eq!(s.pixels_over_025, 0, "{view}: {s:?}");
    }
}

/// With `overlaps=merge` (the default) the same overlapping glyphs are drawn from their
/// nonzero union: no contours overlap any more, so they meet the bound of glyphs without
/// overlaps (MAE and max ≤ 0.02, as above), not a quarter.
#[test]
fn merged_overlaps_are_exact_like_plain_glyphs() {
    let (mut worst_mae, mut max) = (0.0f64, 0.0f64);
    for (view, s) in overlapping_inter_views(&[]) {
        assert!(s.mae_255 <= 0.02 && s.max <= 0.02, "{view}: {s:?}");
        worst_mae = worst_mae.max(s.mae_255);
        max = max.max(s.max);
    }
    println!("Inter's overlapping glyphs merged: worst MAE {worst_mae:.4}/255, max {max:.4}");
}

/// One edge of a square 400 px across crosses pixel rows and columns at every angle in
/// 5° steps and at 4 phases: each pixel is the reference's to within the target's
/// rounding (and f32's share, far below it).
#[test]
fn a_straight_edge_at_any_angle_and_phase() {
    let square = single(polygons(&[&rect(0.0, 0.0, 400.0, 400.0)]));
    for step in 0..18 {
        let angle = f64::from(step) * 5.0 + 0.3;
        for phase in [0.0, 0.25, 0.5, 0.81] {
            // A 24 px view onto the middle of the square's left side.
            let mut cam = Camera::new(24, 24, 1000.0, DVec2::ZERO);
            let (s, c) = angle.to_radians().sin_cos();
            cam.matrix = Camera::matrix_from_rows(c, -s, s, c);
            let on_edge = cam.matrix * DVec2::new(0.0, 200.0);
            // Font y is up, image y down.
            cam.origin = DVec2::new(12.0 + phase, 12.0) - DVec2::new(on_edge.x, -on_edge.y);
            let s = error(&[], &square, &cam);
            assert!(
                s.max <= TARGET_ROUNDING + 1e-5,
                "{angle}°, phase {phase}: {s:?}"
            );
            let covered = render(area_method(&[]).as_mut(), &square, &cam).sum() / 576.0;
            assert!(
                covered > 0.2 && covered < 0.8,
                "{angle}°: the view is off the edge"
            );
        }
    }
}

/// The shader and its f64 mirror (`area::pixel_winding`) on the very same curves (the
/// f32 control points the GPU holds), pixel by pixel, under a rotation with a skew and
/// a mirror: the shader's formulation is the one the CPU checks against closed forms.
#[test]
fn the_shader_is_its_cpu_mirror() {
    let font = glyphscope::font::shipped(1);
    let scene = Scene::from_text(&font, "Qg").unwrap();
    let glyph = &scene.glyphs[0];
    let tolerance = DEFAULT_QUAD_TOLERANCE_EM * scene.units_per_em;
    let curves: Vec<Quad> = glyph
        .outline
        .to_quadratics(tolerance)
        .segments()
        .filter_map(|s| match *s {
            Segment::Line(a, b) => Some([a, (a + b) * 0.5, b]),
            Segment::Quad(a, b, c) => Some([a, b, c]),
            Segment::Cubic(..) => None,
        })
        .map(|q| q.map(|p| p.as_vec2().as_dvec2()))
        .collect();
    let one = Scene::from_outlines(
        scene.units_per_em,
        vec![(glyph.outline.clone(), DVec2::ZERO)],
    );
    for matrix in [[0.9, 0.5, -0.3, 1.1], [-1.0, 0.2, 0.1, 1.0]] {
        let cam = framed(&one, 21.0, matrix, DVec2::new(0.37, 0.61));
        let got = render(area_method(&[("samples", "1")]).as_mut(), &one, &cam);
        let m = cam.glyph_to_image(one.units_per_em, DVec2::ZERO);
        let to_local = DMat2::from_cols(m.x_axis.truncate(), m.y_axis.truncate()).inverse();
        let origin = m.z_axis.truncate();
        let mut worst: f64 = 0.0;
        for j in 0..cam.height {
            for i in 0..cam.width {
                let centre = to_local * (DVec2::new(f64::from(i), f64::from(j)) + 0.5 - origin);
                let winding =
                    area::pixel_winding(&curves, centre, to_local.x_axis, to_local.y_axis);
                let want = area::fill(winding, false);
                worst = worst.max((f64::from(got.get(i, j)) - want).abs());
            }
        }
        assert!(worst <= TARGET_ROUNDING + 1e-4, "{matrix:?}: {worst}");
    }
}

/// Under a perspective tilt the pixel's Jacobian is the homography's linearisation at
/// its centre; the pixel's true preimage is a slightly different quadrilateral. What
/// that costs stays within the same bound.
#[test]
fn a_perspective_tilt_stays_within_the_bound() {
    let scene = Scene::from_text(&glyphscope::font::default_font(), "Tilted").unwrap();
    for tilt in [20.0, 40.0] {
        let mut cam = framed(&scene, 60.0, [1.0, 0.0, 0.0, 1.0], DVec2::new(0.3, 0.6));
        cam.tilt_deg = tilt;
        let s = error(&[], &scene, &cam);
        println!("tilt {tilt}°: MAE {:.4}/255, max {:.4}", s.mae_255, s.max);
        assert!(s.mae_255 <= 0.02 && s.max <= 0.02, "tilt {tilt}°: {s:?}");
    }
}

#[test]
fn bands_change_the_cost_not_the_image() {
    let scene = Scene::from_text(&glyphscope::font::shipped(1), "Bands &g").unwrap();
    let cam = framed(
        &scene,
        41.0,
        [0.96, -0.28, 0.28, 0.96],
        DVec2::new(0.4, 0.1),
    );
    let mut brute = area_method(&[("bands", "off")]);
    let image = render(brute.as_mut(), &scene, &cam);
    let brute_cost = brute.curves_per_pixel(gpu(), &cam).unwrap().unwrap();
    for bands in ["auto", "1", "5", "64"] {
        let mut banded = area_method(&[("bands", bands)]);
        let got = render(banded.as_mut(), &scene, &cam);
        // Only the order of the sums differs.
        let diff = compare(&got, &image).unwrap();
        assert!(diff.max <= 2.0 * TARGET_ROUNDING, "bands={bands}: {diff:?}");
        let cost = banded.curves_per_pixel(gpu(), &cam).unwrap().unwrap();
        assert!(
            cost.mean < brute_cost.mean,
            "bands={bands}: {cost:?} vs {brute_cost:?}"
        );
    }
}

/// Sub-pixels only where a curve of overlapping contours meets another: on glyphs
/// without overlaps `samples=auto` is `samples=1`, image and cost; on overlapping ones
/// kept as drawn it costs more than one integral and less than sub-pixels everywhere.
#[test]
fn sub_pixels_only_where_overlapping_curves_cross() {
    let cam_of = |scene: &Scene| framed(scene, 24.0, [1.0, 0.0, 0.0, 1.0], DVec2::new(0.2, 0.3));
    let run = |scene: &Scene, samples: &str| {
        let cam = cam_of(scene);
        let mut method = area_method(&[("samples", samples), ("overlaps", "keep")]);
        let image = render(method.as_mut(), scene, &cam);
        let cost = method.curves_per_pixel(gpu(), &cam).unwrap().unwrap();
        (image, cost.mean)
    };
    let plain = glyphs_of(&glyphscope::font::default_font(), "gSe", false);
    let (auto, auto_cost) = run(&plain, "auto");
    let (one, one_cost) = run(&plain, "1");
    assert_eq!(auto, one);
    assert_eq!(auto_cost, one_cost);
    let inter = glyphscope::font::shipped(2)
        .with_variations(&[("wght".into(), 900.0)])
        .unwrap();
    let overlapping = glyphs_of(&inter, "ÖkonomieAB", true);
    let (_, auto_cost) = run(&overlapping, "auto");
    let (_, one_cost) = run(&overlapping, "1");
    let (_, everywhere_cost) = run(&overlapping, "4");
    assert!(
        one_cost < auto_cost && auto_cost < everywhere_cost,
        "{one_cost} {auto_cost} {everywhere_cost}"
    );
}

/// Two same-direction squares overlapping, and a pentagram: nonzero fills the overlap
/// and the star's centre, even-odd leaves them empty, and the edges are exact under
/// both rules.
#[test]
fn fill_rules_on_overlaps_and_self_intersections() {
    let squares = glyphscope::stability::hard_cases::by_name("overlapping-same-direction")
        .unwrap()
        .scene;
    let star = single(Outline {
        contours: vec![glyphscope::stability::hard_cases::pentagram()],
    });
    let cam = unit_camera(22, 22);
    for (scene, shared, single_cover) in [(&squares, (11, 11), (4, 18)), (&star, (11, 11), (10, 6))]
    {
        let nonzero = render(area_method(&[]).as_mut(), scene, &cam);
        let even_odd = render(area_method(&[("fill", "evenodd")]).as_mut(), scene, &cam);
        assert_eq!(nonzero.get(shared.0, shared.1), 1.0);
        assert_eq!(even_odd.get(shared.0, shared.1), 0.0);
        assert_eq!(nonzero.get(single_cover.0, single_cover.1), 1.0);
        assert_eq!(even_odd.get(single_cover.0, single_cover.1), 1.0);
        let s = compare(&nonzero, &reference::rasterize(scene, &cam).unwrap()).unwrap();
        assert_eq!(s.pixels_over_025, 0, "{s:?}");
    }
}

/// The class and cost overlays draw with aa=area too, and leave coverage alone.
#[test]
fn overlays_keep_working() {
    let scene = Scene::from_text(&glyphscope::font::default_font(), "Sg").unwrap();
    let cam = framed(&scene, 80.0, [1.0, 0.0, 0.0, 1.0], DVec2::new(0.5, 0.5));
    let plain = render(area_method(&[]).as_mut(), &scene, &cam);
    let picture = |params: &[(&str, &str)]| {
        let (coverage, picture) = render_with_picture(area_method(params).as_mut(), &scene, &cam);
        (picture, coverage)
    };
    for overlay in ["classes", "cost"] {
        let (colour, coverage) = picture(&[("overlay", overlay)]);
        assert!(compare(&coverage, &plain).unwrap().max <= TARGET_ROUNDING);
        let tinted = colour
            .pixels()
            .filter(|p| p.0[0] != p.0[1] || p.0[1] != p.0[2])
            .count();
        assert!(tinted > 200, "{overlay}: only {tinted} coloured pixels");
    }
}

#[test]
fn bad_settings_are_clear_errors() {
    for (params, expect) in [
        (vec![("aa", "supersample")], "aa=supersample"),
        (
            vec![("aa", "area"), ("rays", "1")],
            "rays=1 does not apply to aa=area",
        ),
        (
            vec![("overlaps", "merge"), ("fill", "evenodd")],
            "overlaps=merge takes the nonzero union",
        ),
        (
            vec![("quads", "word"), ("fill", "evenodd")],
            "quads=word draws each word as one glyph",
        ),
        (
            vec![("quads", "word"), ("between", "add")],
            "it takes neither fill=evenodd nor between=add",
        ),
    ] {
        let params: Vec<(String, String)> = params
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect();
        let err = registry::create("winding", &params)
            .err()
            .expect("an error")
            .to_string();
        assert!(err.contains(expect), "{params:?}: {err}");
    }
}

/// The default is the integral; a ray count alone asks for rays.
#[test]
fn the_default_integrates_and_a_ray_count_casts_rays() {
    use glyphscope::methods::winding::{self, Antialiasing};
    let settings = |params: &[(&str, &str)]| {
        let params: Vec<(String, String)> = params
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect();
        winding::settings_from_params(&winding::INFO.parse_params(&params).unwrap()).unwrap()
    };
    assert_eq!(settings(&[]).aa, Antialiasing::Area);
    assert_eq!(settings(&[("rays", "1")]).aa, Antialiasing::Rays);
    assert_eq!(
        settings(&[("aa", "rays"), ("rays", "2")]).aa,
        Antialiasing::Rays
    );
}

/// The cost breakdown's counts on a 6 × 4 px square placed a quarter pixel off the grid,
/// worked by hand: its quad, grown by half a pixel, holds 7 × 5 pixel centres; the
/// 5 × 3 pixels wholly inside are covered exactly 1 and none is left empty. Every pixel
/// walks towards the nearer side and visits the one vertical edge on that side (the
/// horizontal edges run along the bands and are left out): across the pixel in the two
/// columns the edges pass through, wholly right of it (in the walk's direction) in the
/// other five. The shader cut short after the quads writes 1 in each fragment.
#[test]
fn the_cost_breakdown_counts_what_a_square_makes() {
    use glyphscope::methods::winding::cost::CostCounts;
    use glyphscope::methods::winding::{Settings, Stage, Winding};
    let scene = single(polygons(&[&rect(0.0, 0.0, 6.0, 4.0)]));
    let mut cam = unit_camera(12, 10);
    cam.origin += DVec2::new(2.25, -2.25);
    let mut whole = Winding::staged(Settings::default(), Stage::Full);
    whole.prepare(gpu(), &scene).unwrap();
    let counts = whole.cost_counts(gpu(), &cam).unwrap();
    let expected = CostCounts {
        quads: 1,
        fragments: 35,
        covered_pixels: 35,
        coverage_zero: 0,
        coverage_one: 15,
        grid: 0,
        visited: 35,
        right: 25,
        across: 10,
        inexact: 0,
    };
    assert_eq!(counts, expected);
    assert_eq!(counts.no_term(), 0);
    let mut quads = Winding::staged(Settings::default(), Stage::Quads);
    let image = render(&mut quads, &scene, &cam);
    assert_eq!(image.sum(), 35.0);
}

/// A joined word (`between=union`) is one glyph as wide as the word; its bands are split
/// into segments along x (crates/text/src/winding/bands.rs: `segment_curves`) so that a
/// pixel walks its own stretch of the word. On the bench's Arabic and Bengali scenes it
/// stays exact, and its curves per covered pixel stay within 1.2× those of the same
/// letters drawn added (`between=add`: short walks, but not exact where letters
/// overlap) on average and within 2× at most, the bounds set for them — where the whole
/// word's bands cost 1.8× and 1.6× on average and 15× at most (`glyphscope render
/// --case arabic --method winding --stats S.json`, before the segments), and the
/// segments with a boundary line per piece beside the ink 1.37× and 1.06×.
#[test]
fn a_joined_word_costs_about_what_its_letters_cost() {
    for name in ["arabic", "bengali"] {
        let (scene, cam) = glyphscope::named_views::build(name).unwrap();
        let cost = |params: &[(&str, &str)]| {
            let mut method = area_method(params);
            let image = render(method.as_mut(), &scene, &cam);
            let cost = method.curves_per_pixel(gpu(), &cam).unwrap().unwrap();
            (image, cost)
        };
        let (joined, joined_cost) = cost(&[]);
        let (_, added_cost) = cost(&[("between", "add")]);
        let s = compare(&joined, &reference::rasterize(&scene, &cam).unwrap()).unwrap();
        assert!(s.mae_255 <= 0.02 && s.max <= 0.02, "{name}: {s:?}");
        println!(
            "{name}: joined {:.2} ({}), added {:.2} ({}) curves per covered pixel",
            joined_cost.mean, joined_cost.max, added_cost.mean, added_cost.max
        );
        assert!(
            joined_cost.mean <= 1.2 * added_cost.mean && joined_cost.max <= 2 * added_cost.max,
            "{name}: joined {joined_cost:?}, added {added_cost:?}"
        );
    }
}

/// A union's contours may touch: two squares overlapping and a third meeting the second
/// at a corner make a union of two contours that meet at a point. As a font would give
/// them, touching contours mark their curves (wound against each other they would put
/// three winding levels in a pixel); a union's winding is 0 or its fill sign
/// everywhere, so `winding` marks none of its curves, and pixels holding the point stay
/// exact without the sub-pixel grid, under every transform and at 16 offsets.
#[test]
fn a_union_whose_contours_touch_is_exact_without_sub_pixels() {
    use glyphscope::geometry::Contour;
    use glyphscope::methods::winding::{BandCount, GlyphData, Layout};
    let square = |x: f64, y: f64| Contour {
        segments: [(0.0, 0.0), (400.0, 0.0), (400.0, 400.0), (0.0, 400.0)]
            .iter()
            .zip([(400.0, 0.0), (400.0, 400.0), (0.0, 400.0), (0.0, 0.0)])
            .map(|(&(ax, ay), (bx, by))| {
                Segment::Line(DVec2::new(ax + x, ay + y), DVec2::new(bx + x, by + y))
            })
            .collect(),
    };
    let outline = Outline {
        contours: vec![square(0.0, 0.0), square(200.0, 200.0), square(600.0, 600.0)],
    };
    let scene = Scene::from_outlines(1000.0, vec![(outline, DVec2::ZERO)]);
    let merged = scene.with_overlaps_merged();
    assert!(
        merged.glyphs[0].merged,
        "the squares overlap: a union is taken"
    );
    let union = &merged.glyphs[0].outline;
    assert_eq!(union.contours.len(), 2, "{union:?}");
    let data = GlyphData::of_scene(&merged, BandCount::Auto, Layout::Area);
    assert_eq!(data.marked, [false]);
    let mut given = GlyphData::default();
    given.push(union, 1000.0, BandCount::Auto, Layout::Area);
    assert_eq!(given.marked, [true], "as a font's contours, they touch");
    let mut method = area_method(&[]);
    method.prepare(gpu(), &scene).unwrap();
    for (name, matrix) in transforms() {
        for k in 0..16 {
            let cam = framed(&scene, 24.0, matrix, subpixel(k));
            let got = frame::render_image(gpu(), method.as_mut(), &cam).unwrap();
            let s = compare(&got, &reference::rasterize(&scene, &cam).unwrap()).unwrap();
            assert!(
                s.mae_255 <= 0.02 && s.max <= 0.02,
                "{name}, offset {k}: {s:?}"
            );
        }
    }
}

/// `quads=word` draws each word as one glyph under one quad (`Scene::with_words_joined`):
/// on `tiny`, from under a quarter as many quads (and glyph data of its own, the words'),
/// the image is as exact as with a quad per glyph — within a thousandth of its error
/// (docs/methods/winding.md, "A quad per word", for what it costs and saves).
#[test]
fn a_quad_per_word_is_as_exact() {
    let (scene, cam) = glyphscope::named_views::build("tiny").unwrap();
    let (words, counts) = scene.with_words_joined();
    println!(
        "tiny: {} quads for {} glyphs, {} distinct words",
        words.instances.len(),
        scene.instances.len(),
        counts.distinct
    );
    assert!(
        words.instances.len() * 4 < scene.instances.len(),
        "{} quads for {} glyphs",
        words.instances.len(),
        scene.instances.len()
    );
    let reference = reference::rasterize(&scene, &cam).unwrap();
    let [glyph, word] = ["glyph", "word"].map(|quads| {
        let mut method = area_method(&[("quads", quads)]);
        let s = compare(&render(method.as_mut(), &scene, &cam), &reference).unwrap();
        assert!(s.mae_255 <= 0.1 && s.max <= 0.02, "quads={quads}: {s:?}");
        (s, method.gpu_bytes())
    });
    assert!(
        word.1 > glyph.1,
        "quads=word uploads the words' glyphs: {} bytes against {}",
        word.1,
        glyph.1
    );
    assert!(
        word.0.max <= glyph.0.max + 1e-3 && word.0.mae_255 <= glyph.0.mae_255 + 1e-3,
        "words {:?}, letters {:?}",
        word.0,
        glyph.0
    );
}
