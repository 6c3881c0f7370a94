//! Method `winding` casting rays (`aa=rays`) against the exact reference: real glyphs of every shipped font at
//! 8–400 px/em under rotation and skew at 16 sub-pixel offsets, the hard cases that
//! break ray casting, and what each parameter does.

mod common;

use common::*;
use glam::DVec2;
use glyphscope::camera::Camera;
use glyphscope::font::SHIPPED_FONTS;
use glyphscope::gpu::GpuContext;
use glyphscope::methods::{Method, frame, registry};
use glyphscope::metrics::{ErrorStats, compare};
use glyphscope::reference;
use glyphscope::scene::Scene;
use glyphscope::stability::hard_cases;

/// `winding` casting rays (`aa=rays`): `tests/winding_area.rs` checks its default.
fn winding(params: &[(&str, &str)]) -> Box<dyn Method> {
    let params: Vec<(String, String)> = [("aa", "rays")]
        .iter()
        .chain(params)
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect();
    registry::create("winding", &params).unwrap()
}

/// Error of `winding` with `params` against the reference, for one frame.
fn error(params: &[(&str, &str)], scene: &Scene, cam: &Camera) -> ErrorStats {
    let got = render(winding(params).as_mut(), scene, cam);
    compare(&got, &reference::rasterize(scene, cam).unwrap()).unwrap()
}

/// The 16 sub-pixel offsets of a 4×4 grid, kept off the pixel grid's symmetries.
fn subpixel(k: u32) -> DVec2 {
    DVec2::new(f64::from(k % 4) / 4.0 + 0.03, f64::from(k / 4) / 4.0 + 0.07)
}

/// Worst error and mean MAE over the 16 offsets.
struct Sweep {
    mean_mae: f64,
    max: f64,
    over_half: usize,
}

fn sweep(
    gpu: &GpuContext,
    params: &[(&str, &str)],
    scene: &Scene,
    size: f64,
    matrix: [f64; 4],
) -> Sweep {
    let mut method = winding(params);
    method.prepare(gpu, scene).unwrap();
    let (mut mae, mut max, mut over_half) = (0.0, 0.0f64, 0);
    for k in 0..16 {
        let cam = framed(scene, size, matrix, subpixel(k));
        let got = frame::render_image(gpu, method.as_mut(), &cam).unwrap();
        let s = compare(&got, &reference::rasterize(scene, &cam).unwrap()).unwrap();
        mae += s.mae_255 / 16.0;
        max = max.max(s.max);
        over_half += s.pixels_over_05;
    }
    Sweep {
        mean_mae: mae,
        max,
        over_half,
    }
}

const SAMPLE_TEXT: [&str; 4] = [
    "g&@Se",
    "Qa§gf",
    "BéW4k",
    "\u{0995}\u{09CD}\u{09B7}\u{0999}",
];

fn transforms() -> [(&'static str, [f64; 4]); 3] {
    let (s, c) = 30f64.to_radians().sin_cos();
    [
        ("identity", [1.0, 0.0, 0.0, 1.0]),
        ("rotated 30°", [c, -s, s, c]),
        ("skewed", [1.0, 0.4, 0.0, 1.0]),
    ]
}

#[test]
fn real_glyphs_stay_within_half_a_level_everywhere() {
    let gpu = gpu();
    let mut worst: f64 = 0.0;
    println!("| font | px/em | transform | mean MAE /255 | max | pixels > 0.5 |");
    for (index, text) in SAMPLE_TEXT.iter().enumerate() {
        let font = glyphscope::font::shipped(index);
        for size in [8.0, 16.0, 48.0, 400.0] {
            // At 400 px/em two glyphs hold thousands of edge pixels at every phase.
            let text: String = text
                .chars()
                .take(if size > 100.0 { 2 } else { 5 })
                .collect();
            let scene = Scene::from_text(&font, &text).unwrap();
            for (name, matrix) in transforms() {
                let s = sweep(gpu, &[], &scene, size, matrix);
                println!(
                    "| {} | {size} | {name} | {:.2} | {:.3} | {} |",
                    SHIPPED_FONTS[index].0, s.mean_mae, s.max, s.over_half
                );
                assert_eq!(
                    s.over_half, 0,
                    "{} at {size} px/em, {name}: max {}",
                    SHIPPED_FONTS[index].0, s.max
                );
                worst = worst.max(s.mean_mae);
            }
        }
    }
    assert!(worst <= 2.0, "worst mean error {worst}/255");
}

fn assert_within_half(what: &str, scene: &Scene, cam: &Camera) -> ErrorStats {
    let s = error(&[], scene, cam);
    println!("{what}: MAE {:.3}/255, max {:.3}", s.mae_255, s.max);
    assert_eq!(
        s.pixels_over_05, 0,
        "{what}: max {} at {:?}",
        s.max, s.worst_pixel
    );
    s
}

/// Every hard case of the stability library holds winding's half-level claim there
/// (`tests/stability.rs`); on some it does much better, at the offset where their
/// alignments are exact.
#[test]
fn hard_cases_at_their_exact_alignment() {
    for (name, bound) in [
        // Horizontal edges along pixel-centre rows: an axis-aligned shape is exact.
        ("horizontal-on-sample-row", 0.02),
        // Vertical rays see the "both roots" sign class with no real root beside the
        // curve, and must count nothing.
        ("control-point-past-curve", 0.2),
        ("vertex-on-centre-row", 0.3),
        ("collinear-quadratic", 0.36),
    ] {
        let case = hard_cases::by_name(name).unwrap();
        let cam = case.camera(0.0, DVec2::ZERO).unwrap();
        let s = assert_within_half(name, &case.scene, &cam);
        assert!(s.max < bound, "{name}: {s:?}");
    }
}

/// The sun symbol's pixel that winding once read as 0.20: in the sun symbol at 48 px/em, origin (24, 72), pixel (52, 57)
/// spans font units x 583.3–604.2, y 291.7–312.5 (x = (px − 24) / 0.048, y = (72 − py)
/// / 0.048): inside the ray's bar (y 284–314, x up to 739) and the ring (its hole ends
/// at x 563), so it is wholly covered. The y-ray through its centre passes 0.25 units
/// beside the two vertices where near-vertical cubics meet the bar's edges, and meets
/// both cubics nearly along itself; the x-ray meets nothing. Weighted by their own
/// crossings alone, the rays read 0.20 here.
#[test]
fn a_ray_meeting_curves_along_itself_beside_a_vertex_does_not_outweigh_one_meeting_nothing() {
    let sun = hard_cases::by_name("sun-symbol").unwrap().scene;
    let cam = Camera::new(87, 106, 48.0, DVec2::new(24.0, 72.0));
    let image = render(winding(&[]).as_mut(), &sun, &cam);
    let covered = image.get(52, 57);
    println!("sun symbol, pixel (52, 57): {covered:.3}");
    assert!(
        covered > 0.98,
        "pixel (52, 57) reads {covered}, covered wholly"
    );
}

#[test]
fn far_from_the_origin_nothing_changes() {
    let gpu = gpu();
    let scene = Scene::from_text(&glyphscope::font::default_font(), "Rg").unwrap();
    let mut cam = framed(&scene, 37.0, [0.9, 0.3, -0.2, 1.1], DVec2::new(0.25, 0.5));
    let mut method = winding(&[]);
    let near = render(method.as_mut(), &scene, &cam);
    cam.world_offset = DVec2::new(1.0e5, -1.0e5);
    let far = frame::render_image(gpu, method.as_mut(), &cam).unwrap();
    assert!(
        compare(&far, &near).unwrap().max < 1e-3,
        "a 100 000 px world offset changed the image"
    );
    assert_within_half("100 000 px world offset", &scene, &cam);
}

#[test]
fn a_huge_glyph_viewed_on_its_edge() {
    let font = glyphscope::font::default_font();
    let scene = Scene::from_glyph_id(&font, font.glyph_for_char('o').unwrap().into()).unwrap();
    for (name, matrix) in transforms() {
        let mut cam = Camera::new(64, 64, 20_000.0, DVec2::ZERO);
        cam.matrix = Camera::matrix_from_rows(matrix[0], matrix[1], matrix[2], matrix[3]);
        // Put the bowl's leftmost point in the middle of the view.
        let b = scene.glyphs[0].bounds;
        let edge = glam::DVec2::new(b.min.x, (b.min.y + b.max.y) * 0.5);
        let at = glyphscope::geometry::project(
            &cam.glyph_to_image(scene.units_per_em, DVec2::ZERO),
            edge,
        );
        cam.origin = DVec2::splat(32.3) - at;
        let got = render(winding(&[]).as_mut(), &scene, &cam);
        let covered = got.sum() / 4096.0;
        assert!(
            covered > 0.2 && covered < 0.8,
            "{name}: view not on the edge ({covered})"
        );
        assert_within_half(&format!("20 000 px/em on an edge, {name}"), &scene, &cam);
    }
}

#[test]
fn perspective_tilt() {
    let scene = Scene::from_text(&glyphscope::font::default_font(), "Tilted").unwrap();
    let mut cam = framed(&scene, 60.0, [1.0, 0.0, 0.0, 1.0], DVec2::new(0.3, 0.6));
    cam.tilt_deg = 40.0;
    let s = assert_within_half("40° perspective tilt", &scene, &cam);
    assert!(s.mae_255 < 2.0, "{s:?}");
}

#[test]
fn bands_change_the_cost_not_the_image() {
    let gpu = gpu();
    let scene = Scene::from_text(&glyphscope::font::shipped(1), "Bands &g").unwrap();
    let cam = framed(
        &scene,
        41.0,
        [0.96, -0.28, 0.28, 0.96],
        DVec2::new(0.4, 0.1),
    );
    let mut brute = winding(&[("bands", "off")]);
    let reference_image = render(brute.as_mut(), &scene, &cam);
    let brute_cost = brute.curves_per_pixel(gpu, &cam).unwrap().unwrap();
    for bands in ["auto", "1", "5", "64"] {
        let mut banded = winding(&[("bands", bands)]);
        let got = render(banded.as_mut(), &scene, &cam);
        let diff = compare(&got, &reference_image).unwrap();
        assert!(
            diff.max < 2e-3,
            "bands={bands} changed a pixel by {}",
            diff.max
        );
        let cost = banded.curves_per_pixel(gpu, &cam).unwrap().unwrap();
        assert!(
            cost.mean < brute_cost.mean,
            "bands={bands}: {cost:?} vs brute force {brute_cost:?}"
        );
    }
}

#[test]
fn settings_trade_accuracy_for_cost() {
    let scene = Scene::from_text(&glyphscope::font::default_font(), "Hamburgefonstiv").unwrap();
    let (s, c) = 12f64.to_radians().sin_cos();
    let cam = framed(&scene, 13.0, [c, -s, s, c], DVec2::new(0.37, 0.21));
    let one_ray = error(&[("rays", "1"), ("samples", "1")], &scene, &cam);
    let two_rays = error(&[("samples", "1")], &scene, &cam);
    let four_samples = error(&[("samples", "4")], &scene, &cam);
    let auto = error(&[], &scene, &cam);
    assert_eq!(
        auto, four_samples,
        "13 px/em is small text: auto takes four samples"
    );
    println!("13 px/em, 12°: rays=1 {one_ray:?}\nrays=2 {two_rays:?}\nsamples=4 {four_samples:?}");
    assert!(two_rays.mae_255 < one_ray.mae_255);
    assert!(four_samples.mae_255 < two_rays.mae_255);
    assert!(four_samples.max < two_rays.max);
}

/// Two same-direction squares overlapping, and a pentagram: nonzero fills the overlap
/// and the star's centre; even-odd leaves them empty.
#[test]
fn fill_rules_on_overlaps_and_self_intersections() {
    let squares = hard_cases::by_name("overlapping-same-direction")
        .unwrap()
        .scene;
    let star = single(glyphscope::geometry::Outline {
        contours: vec![hard_cases::pentagram()],
    });
    let cam = unit_camera(22, 22);
    // Pixels (image coordinates) inside the overlap / star centre, and inside one
    // square / one star point only.
    let probes = [(&squares, (11, 11), (4, 18)), (&star, (11, 11), (10, 6))];
    for (scene, shared, single_cover) in probes {
        let nonzero = render(winding(&[]).as_mut(), scene, &cam);
        let even_odd = render(winding(&[("fill", "evenodd")]).as_mut(), scene, &cam);
        assert_eq!(nonzero.get(shared.0, shared.1), 1.0);
        assert_eq!(even_odd.get(shared.0, shared.1), 0.0);
        assert_eq!(nonzero.get(single_cover.0, single_cover.1), 1.0);
        assert_eq!(even_odd.get(single_cover.0, single_cover.1), 1.0);
        // Nonzero is what the reference computes.
        let s = compare(&nonzero, &reference::rasterize(scene, &cam).unwrap()).unwrap();
        assert_eq!(s.pixels_over_05, 0, "{s:?}");
    }
}

#[test]
fn overlays_draw_classes_and_cost() {
    let scene = Scene::from_text(&glyphscope::font::default_font(), "Sg").unwrap();
    let cam = framed(&scene, 80.0, [1.0, 0.0, 0.0, 1.0], DVec2::new(0.5, 0.5));
    let picture = |params: &[(&str, &str)]| {
        let (coverage, picture) = render_with_picture(winding(params).as_mut(), &scene, &cam);
        (picture, coverage)
    };
    let (classes, coverage) = picture(&[("overlay", "classes")]);
    // Every pixel shows either grey coverage or one of the legend's colours, and near
    // the outline the counting classes (not grey) appear.
    let legend: Vec<[u8; 3]> = glyphscope::methods::winding::CLASS_LEGEND
        .iter()
        .map(|(c, _)| c.map(|v| (v * 255.0).round() as u8))
        .collect();
    let tinted = classes
        .pixels()
        .filter(|p| legend[1..7].contains(&p.0))
        .count();
    assert!(
        tinted > 200,
        "only {tinted} pixels tinted by a counting class"
    );
    // The overlay does not change coverage.
    let plain = render(winding(&[]).as_mut(), &scene, &cam);
    assert!(compare(&coverage, &plain).unwrap().max < 1e-3);
    let (cost, _) = picture(&[("overlay", "cost")]);
    let (cost_brute, _) = picture(&[("overlay", "cost"), ("bands", "off")]);
    let brightness = |img: &image::RgbImage| {
        img.pixels()
            .map(|p| p.0.iter().map(|&v| u64::from(v)).sum::<u64>())
            .sum::<u64>()
    };
    assert!(
        brightness(&cost_brute) > brightness(&cost),
        "brute force should look hotter"
    );
}

/// `rays=slug` reproduces Slug's published combine, checked on pixels worked by hand
/// (pixel-centre offsets s, t uniform in [−½, ½]; 1 px per font unit):
/// - a square's corner ¼ px beyond the pixel centre in x and y: each ray's one-pixel
///   window is ¾ inside, its weight 1 − 2·¼ = ½, so Slug gives ¾; the pixel's exact
///   coverage is ¾ · ¾ = 9/16;
/// - a 45° edge s + t < ¼: each ray again ¾ inside with weight ½, so Slug gives ¾;
///   exactly, 1 − (1 − ¼)²/2 = 0.71875.
///
/// `aa=area` must give the exact values, so the probes tell the two apart.
#[test]
fn slug_combine_on_hand_worked_pixels() {
    let square = single(polygons(&[&[
        (4.25, 4.25),
        (30.0, 4.25),
        (30.0, 30.0),
        (4.25, 30.0),
    ]]));
    let triangle = single(polygons(&[&[(0.0, 0.0), (19.25, 0.0), (0.0, 19.25)]]));
    let cam = unit_camera(32, 32);
    // Image pixel (i, j) has its centre at font (i + ½, 32 − j − ½).
    let probes = [
        ("corner", &square, (4, 27), 0.75, 9.0 / 16.0),
        ("45° edge", &triangle, (9, 22), 0.75, 0.71875),
    ];
    for (what, scene, (i, j), slug, exact) in probes {
        let by_slug = render(winding(&[("rays", "slug")]).as_mut(), scene, &cam);
        let area_params = [("aa".to_string(), "area".to_string())];
        let mut area = registry::create("winding", &area_params).unwrap();
        let by_area = render(area.as_mut(), scene, &cam);
        // Half floats hold ¾ and 9/16 exactly and 0.71875 within 2.5e-4.
        let (got_slug, got_area) = (by_slug.get(i, j), by_area.get(i, j));
        assert!(
            (got_slug - slug).abs() < 1e-3,
            "{what}: slug {got_slug}, expected {slug}"
        );
        assert!(
            (got_area - exact).abs() < 1e-3,
            "{what}: area {got_area}, expected {exact}"
        );
    }
}

#[test]
fn bad_parameters_are_clear_errors() {
    for (key, value, expect) in [
        ("rays", "3", "rays=3"),
        ("samples", "2", "samples=2"),
        ("bands", "0", "bands=0"),
        ("bands", "lots", "bands=lots"),
        ("fill", "winding", "fill=winding"),
        ("overlay", "wireframe", "overlay=wireframe is not valid"),
        ("colour", "red", "no parameter 'colour'"),
    ] {
        let params = vec![(key.to_string(), value.to_string())];
        let err = registry::create("winding", &params)
            .err()
            .expect("an error")
            .to_string();
        assert!(err.contains(expect), "{key}={value}: {err}");
    }
}

/// A glyph flat across a ray (every point on one line: zero height, or zero width) has
/// bands of zero extent. Each ray must still read its own glyph's bands, on the flat
/// line itself too, where the band index was 0/0. Pixel centres lie on both flat lines,
/// and the glyph drawn last covers, in its own local units, every point of the flat
/// ones: a band read from it would show as full pixels where the reference has none.
#[test]
fn a_glyph_flat_across_a_ray_reads_its_own_bands() {
    use glyphscope::geometry::{Contour, Outline, Segment};
    let p = |x: f64, y: f64| DVec2::new(x, y);
    let flat = |a: DVec2, b: DVec2| Outline {
        contours: vec![Contour {
            segments: vec![Segment::Quad(a, (a + b) * 0.5, b), Segment::Line(b, a)],
        }],
    };
    let scene = Scene::from_outlines(
        hard_cases::SYNTHETIC_UNITS_PER_EM,
        vec![
            (flat(p(0.0, 0.0), p(100.0, 0.0)), p(0.0, 0.0)),
            (flat(p(0.0, 0.0), p(0.0, 100.0)), p(200.0, -150.0)),
            (
                polygons(&[&rect(-40.0, -40.0, 140.0, 140.0)[..]]),
                p(400.0, -300.0),
            ),
        ],
    );
    // 1 px per unit; font (x, y) at image (x + 10.5, 20.5 − y): both flat lines run
    // through pixel centres.
    let cam = Camera::new(560, 380, 1000.0, DVec2::new(10.5, 20.5));
    let expected = reference::rasterize(&scene, &cam).unwrap();
    for params in [&[][..], &[("samples", "4")], &[("rays", "1")]] {
        let got = render(winding(params).as_mut(), &scene, &cam);
        let s = compare(&got, &expected).unwrap();
        assert_eq!(s.invalid_pixels, 0, "{params:?}: {s:?}");
        // The rays' claim, anywhere in the frame.
        assert!(s.max <= 0.5, "{params:?}: {s:?}");
        // Nothing on the flat glyphs' lines: the reference has nothing there.
        for (x, y) in (0..100)
            .map(|k| (10 + k, 20))
            .chain((0..100).map(|k| (210, 70 + k)))
        {
            assert!(
                got.get(x, y) < 0.01,
                "{params:?}: ({x}, {y}) reads {}",
                got.get(x, y)
            );
        }
    }
}

/// The counting pass writes half floats, exact for every count up to 2048 only: a pixel
/// past that reports its count as a lower bound, saying so, rather than a rounded count
/// that looks exact. Brute force with one ray and one sample evaluates every curve of the
/// glyph once per pixel, so each covered pixel's count is the glyph's curve count.
#[test]
fn curve_counts_past_what_half_floats_hold_are_flagged() {
    let gpu = gpu();
    // Squares 4 units wide, 6 apart, in rows of 32, and a triangle: 4·squares + 3 curves.
    let glyph = |squares: usize| {
        let mut contours: Vec<Vec<(f64, f64)>> = (0..squares)
            .map(|k| {
                let (x, y) = ((k % 32) as f64 * 6.0, (k / 32) as f64 * 6.0);
                rect(x, y, x + 4.0, y + 4.0)
            })
            .collect();
        contours.push(vec![(0.0, -10.0), (8.0, -10.0), (0.0, -4.0)]);
        let contours: Vec<&[(f64, f64)]> = contours.iter().map(Vec::as_slice).collect();
        (single(polygons(&contours)), 4 * squares + 3)
    };
    let params = [("rays", "1"), ("samples", "1"), ("bands", "off")];
    for squares in [509, 625] {
        let (scene, curves) = glyph(squares);
        let cam = framed(&scene, 1000.0, [1.0, 0.0, 0.0, 1.0], DVec2::new(0.5, 0.5));
        let mut method = winding(&params);
        method.prepare(gpu, &scene).unwrap();
        let cost = method.curves_per_pixel(gpu, &cam).unwrap().unwrap();
        if curves < 2048 {
            assert_eq!(cost.saturated, 0, "{curves} curves: {cost:?}");
            assert_eq!(cost.max, curves as u32, "{cost:?}");
            assert!((cost.mean - curves as f64).abs() < 1e-9, "{cost:?}");
        } else {
            // 2503 curves: a half float holds 2502 or 2504, never the count.
            assert!(cost.saturated > 0, "{curves} curves: {cost:?}");
            assert_eq!(cost.max, 2048, "{cost:?}");
            assert_eq!(cost.max_text(), "≥ 2048");
            assert!(cost.mean <= curves as f64, "{cost:?}");
        }
    }
}

/// winding_rays.wgsl's `combine_rays` on the GPU, for each (x coverage, y coverage, x sight,
/// y sight): the shader's own function, run by a compute entry point appended to it.
fn combine_rays(gpu: &GpuContext, inputs: &[[f32; 4]]) -> Vec<f32> {
    let probe = "
@group(0) @binding(8) var<storage, read> probe_inputs: array<vec4<f32>>;
@group(0) @binding(9) var<storage, read_write> probe_outputs: array<f32>;
@compute @workgroup_size(64)
fn probe(@builtin(global_invocation_id) id: vec3<u32>) {
    if id.x < arrayLength(&probe_inputs) {
        let v = probe_inputs[id.x];
        probe_outputs[id.x] = combine_rays(v.x, v.y, v.z, v.w);
    }
}
";
    let shader = registry::find("winding").unwrap().shader.unwrap();
    run_probe(
        gpu,
        format!("{}\n{probe}", shader.source()),
        (0, 8),
        bytemuck::cast_slice(inputs),
        inputs.len(),
        4,
    )
}

/// The two rays' blend is continuous where the weights' total falls to 0 (both rays
/// blind, or a corner at the sample, both fully sighted): a weight of 1e-7 once handed
/// one ray everything, a weight of 0 half (the 0.4998 pixels). Claimed before measuring,
/// from the blend's form: trust rises from 0 to 1 over a ramp R = 1/8 of total weight
/// by smoothstep (slope at most 1.5/R) and moves a value at most ½ from the average;
/// the weighted mean moves at most 1/total per unit of sight, and trust ≤ 3(total/R)²
/// below R: so a unit change of one sight moves the value by at most 0.75/R + 3/R, under
/// 32. Away from the ramp nothing changes: one ray fully sighted and the other blind
/// gives the first ray's coverage, both fully sighted their average.
#[test]
fn the_two_rays_blend_continuously_as_their_weights_vanish() {
    const LIPSCHITZ: f32 = 32.0;
    let step = 1.0 / 4096.0;
    // Sights swept one at a time towards the places where the total vanishes, with the
    // coverages as far apart as they go.
    let mut paths: Vec<Vec<[f32; 4]>> = Vec::new();
    for other in [0.0, 1e-6, 0.01, 0.3, 0.999, 1.0] {
        for (x_coverage, y_coverage) in [(1.0, 0.0), (0.0, 1.0), (0.25, 0.75)] {
            let sights = (0..=4096).map(|k| k as f32 * step);
            paths.push(
                sights
                    .clone()
                    .map(|s| [x_coverage, y_coverage, s, other])
                    .collect(),
            );
            paths.push(sights.map(|s| [x_coverage, y_coverage, other, s]).collect());
        }
    }
    let inputs: Vec<[f32; 4]> = paths.concat();
    let gpu = gpu();
    let values = combine_rays(gpu, &inputs);
    let mut worst = 0.0f32;
    for (k, pair) in inputs.windows(2).enumerate() {
        let (a, b) = (pair[0], pair[1]);
        let (va, vb) = (values[k], values[k + 1]);
        assert!(va.is_finite() && (0.0..=1.0).contains(&va), "{a:?} → {va}");
        if a[..2] != b[..2] || (a[2] != b[2] && a[3] != b[3]) {
            continue; // the next path starts
        }
        let moved = (a[2] - b[2]).abs() + (a[3] - b[3]).abs();
        let slope = (va - vb).abs() / moved;
        worst = worst.max(slope);
        assert!(
            slope <= LIPSCHITZ,
            "{a:?} → {va}, {b:?} → {vb}: slope {slope}"
        );
    }
    println!("steepest slope of the blend per unit of sight: {worst:.2}");
    let settled = combine_rays(
        gpu,
        &[
            [0.3, 1.0, 1.0, 0.0],
            [1.0, 0.3, 0.0, 1.0],
            [0.3, 1.0, 1.0, 1.0],
            [0.3, 1.0, 0.0, 0.0],
        ],
    );
    for (got, want) in settled.iter().zip([0.3, 0.3, 0.65, 0.65]) {
        assert!((got - want).abs() < 1e-6, "{settled:?}");
    }
}
