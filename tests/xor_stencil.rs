//! `xor-stencil` checked two ways.
//!
//! 1. Sample for sample: the method point-samples the outline, so a CPU point sampler
//!    at the very same positions (the 4× standard sample positions shifted by the jitter
//!    offsets) must agree with it everywhere but on samples that lie within the
//!    rasterizer's sub-pixel precision of an edge. This isolates the method's logic —
//!    fan and Loop–Blinn triangles, winding or parity in the stencil, layers, covers,
//!    passes — from its sampling error, with a tolerance of single samples.
//! 2. Against the exact reference: the area error, which shrinks as samples grow.
//!
//! These tests need an adapter (CI installs lavapipe).

mod common;

use common::*;
use glam::{DMat3, DVec2};
use glyphscope::camera::Camera;
use glyphscope::coverage::CoverageImage;
use glyphscope::font::SHIPPED_FONTS;
use glyphscope::geometry::{Contour, Outline, Segment, project};
use glyphscope::gpu::{Channels, CoverageTarget};
use glyphscope::methods::frame::render_frame;
use glyphscope::methods::xor_stencil::{self, FillRule, Settings, XorStencil, jitter_offsets};
use glyphscope::methods::{Method, Overlay, registry};
use glyphscope::metrics::compare;
use glyphscope::reference;
use glyphscope::scene::Scene;

const UPRIGHT: [f64; 4] = [1.0, 0.0, 0.0, 1.0];

fn settings(fill: FillRule, samples: u32, passes: u32) -> Settings {
    Settings {
        fill,
        samples,
        passes,
        overlay: None,
    }
}

fn render(scene: &Scene, camera: &Camera, settings: Settings) -> CoverageImage {
    common::render(&mut XorStencil::with_settings(settings), scene, camera)
}

/// Where the frame samples each pixel, relative to its corner: the Vulkan / D3D
/// standard positions for 4× MSAA (the centre for 1×), each shifted against every
/// pass's jitter (moving the image by +o samples it at −o).
fn sample_positions(samples: u32, passes: u32) -> Vec<DVec2> {
    let standard: &[(f64, f64)] = match samples {
        1 => &[(0.5, 0.5)],
        4 => &[
            (0.375, 0.125),
            (0.875, 0.375),
            (0.125, 0.625),
            (0.625, 0.875),
        ],
        _ => unreachable!(),
    };
    let mut positions = Vec::new();
    for offset in jitter_offsets(passes, samples) {
        for &(x, y) in standard {
            positions.push(DVec2::new(x, y) - offset);
        }
    }
    positions
}

/// The instances' outlines in image space as closed polylines within 1e-5 px of the
/// curves, one list of edges per instance.
fn image_edges(scene: &Scene, camera: &Camera) -> Vec<Vec<(DVec2, DVec2)>> {
    scene
        .instances
        .iter()
        .map(|inst| {
            let m: DMat3 = camera.glyph_to_image(scene.units_per_em, inst.position);
            let tolerance = 1e-5 / camera.scale(scene.units_per_em);
            let mut edges = Vec::new();
            for segment in scene.glyphs[inst.glyph as usize].outline.segments() {
                let mut previous = project(&m, segment.start());
                segment.flatten(tolerance, &mut |p| {
                    let p = project(&m, p);
                    edges.push((previous, p));
                    previous = p;
                });
            }
            edges
        })
        .collect()
}

/// CPU point sampling at `positions` in every pixel: nonzero over the summed winding of
/// all instances (as the reference sums them), or even-odd per instance, united.
fn point_sampled(
    edges: &[Vec<(DVec2, DVec2)>],
    camera: &Camera,
    positions: &[DVec2],
    fill: FillRule,
) -> CoverageImage {
    let (w, h) = (camera.width as usize, camera.height as usize);
    let mut inside = vec![0u32; w * h];
    for j in 0..h {
        for p in positions {
            let y = j as f64 + p.y;
            // (x, direction, instance) of every crossing of this sample row.
            let mut crossings: Vec<(f64, i32, usize)> = Vec::new();
            for (k, edges) in edges.iter().enumerate() {
                for &(a, b) in edges {
                    // Half-open in y, so a vertex on the row counts once.
                    if (a.y <= y) != (b.y <= y) {
                        let x = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
                        crossings.push((x, if b.y > a.y { 1 } else { -1 }, k));
                    }
                }
            }
            crossings.sort_by(|a, b| a.0.total_cmp(&b.0));
            let mut winding = vec![0i32; edges.len()];
            let (mut next, mut total) = (0, 0);
            for i in 0..w {
                let x = i as f64 + p.x;
                while next < crossings.len() && crossings[next].0 < x {
                    let (_, d, k) = crossings[next];
                    winding[k] += d;
                    total += d;
                    next += 1;
                }
                let covered = match fill {
                    FillRule::NonZero => total != 0,
                    FillRule::EvenOdd => winding.iter().any(|v| v % 2 != 0),
                };
                inside[j * w + i] += u32::from(covered);
            }
        }
    }
    let n = positions.len() as f32;
    CoverageImage {
        width: camera.width,
        height: camera.height,
        data: inside.iter().map(|&c| c as f32 / n).collect(),
    }
}

/// How many of pixel (i, j)'s samples lie within `near` px of an edge.
fn samples_near_edges(
    edges: &[Vec<(DVec2, DVec2)>],
    positions: &[DVec2],
    (i, j): (usize, usize),
    near: f64,
) -> u32 {
    let corner = DVec2::new(i as f64, j as f64);
    positions
        .iter()
        .filter(|&&p| {
            let sample = corner + p;
            edges.iter().flatten().any(|&(a, b)| {
                let ab = b - a;
                let t = ((sample - a).dot(ab) / ab.length_squared().max(1e-300)).clamp(0.0, 1.0);
                (a + ab * t).distance(sample) < near
            })
        })
        .count() as u32
}

/// How far from an edge a sample may land on the other side: rasterizers snap vertices
/// to a sub-pixel grid (8 bits, 1/256 px, on lavapipe and desktop GPUs), which moves an
/// edge by up to √2/512 px, and f32 transforms move it by about 1e-4 px more.
const NEAR_EDGE_PX: f64 = 1.0 / 128.0;

/// Compares the GPU image with CPU point sampling at the same positions: a pixel may
/// differ only by samples that lie within [`NEAR_EDGE_PX`] of an edge (plus half-float
/// rounding).
fn check_sample_for_sample(what: &str, scene: &Scene, camera: &Camera, settings: Settings) {
    check_samples_near(what, scene, camera, settings, NEAR_EDGE_PX)
}

/// [`check_sample_for_sample`], letting samples within `near` px of an edge differ.
fn check_samples_near(what: &str, scene: &Scene, camera: &Camera, settings: Settings, near: f64) {
    let positions = sample_positions(settings.samples, settings.passes);
    let edges = image_edges(scene, camera);
    let expected = point_sampled(&edges, camera, &positions, settings.fill);
    let got = render(scene, camera, settings);
    let n = positions.len() as f32;
    for (k, (&g, &e)) in got.data.iter().zip(&expected.data).enumerate() {
        let samples_off = ((g - e).abs() * n - 2e-3 * n).ceil().max(0.0) as u32;
        if samples_off == 0 {
            continue;
        }
        let pixel = (k % camera.width as usize, k / camera.width as usize);
        let close = samples_near_edges(&edges, &positions, pixel, near);
        assert!(
            samples_off <= close,
            "{what}: pixel {pixel:?} is {g}, point sampling gives {e}: {samples_off} \
             sample(s) off, {close} near an edge",
        );
    }
    assert!(expected.sum() > 20.0, "{what}: barely anything in view");
}

#[test]
fn real_glyphs_sample_for_sample() {
    // DejaVu (quadratics), Latin Modern (cubics), Inter (overlapping contours), a
    // Bengali conjunct; one and four samples, one to three passes.
    for (font, text, size) in [
        (0, "g@S&", 23.0),
        (1, "Qa§g", 31.0),
        (2, "B\u{e9}4W", 27.0),
        (3, "\u{0995}\u{09CD}\u{09B7}", 35.0),
    ] {
        let scene = Scene::from_text(&glyphscope::font::shipped(font), text).unwrap();
        let base = framed(&scene, size, UPRIGHT, DVec2::new(0.31, 0.57));
        for (name, camera) in cameras(base) {
            for (samples, passes) in [(1, 1), (4, 1), (1, 3), (4, 2)] {
                let what = format!(
                    "{} {text:?} {name}, {samples} samples x {passes} passes",
                    SHIPPED_FONTS[font].0
                );
                let settings = settings(FillRule::NonZero, samples, passes);
                check_sample_for_sample(&what, &scene, &camera, settings);
            }
        }
    }
}

#[test]
fn even_odd_sample_for_sample() {
    // Inter's overlapping contours: where they overlap, even-odd leaves a hole.
    let black = glyphscope::font::shipped(2)
        .with_variations(&[("wght".to_string(), 900.0)])
        .unwrap();
    let scene = Scene::from_text(&black, "B\u{e9}4Wx").unwrap();
    let camera = framed(&scene, 29.0, UPRIGHT, DVec2::new(0.43, 0.21));
    let nonzero = render(&scene, &camera, settings(FillRule::NonZero, 4, 1));
    let even_odd = render(&scene, &camera, settings(FillRule::EvenOdd, 4, 1));
    let holes = nonzero.sum() - even_odd.sum();
    assert!(
        holes > 20.0,
        "even-odd removed only {holes} px from Inter's overlaps"
    );
    for (name, camera) in cameras(camera) {
        for (samples, passes) in [(1, 1), (4, 3)] {
            let what = format!("Inter even-odd {name}, {samples} samples x {passes} passes");
            check_sample_for_sample(
                &what,
                &scene,
                &camera,
                settings(FillRule::EvenOdd, samples, passes),
            );
        }
    }
}

/// `n` squares in one outline, nested, each `step` smaller, all counter-clockwise but
/// those listed in `reversed`.
fn nested_squares(n: usize, step: f64, reversed: &[usize]) -> Outline {
    let contours = (0..n)
        .map(|k| {
            let d = step * k as f64;
            let mut square = rect(d, d, 200.0 - d, 200.0 - d);
            if reversed.contains(&k) {
                square.reverse();
            }
            polygon(&square)
        })
        .collect();
    Outline { contours }
}

#[test]
fn winding_numbers_beyond_a_nibble() {
    // 20 nested squares: winding 20 in the middle, where Wallace's 4-bit counters wrap
    // to 4 — harmless — but 16 nested would wrap to 0. The stencil's 8-bit counter
    // wraps only at multiples of 256. Square 7 runs the other way, so winding goes
    // 1, 2, … 6, 7, 6, 7, … and never returns to 0; even-odd sees the rings. Edges lie
    // on pixel borders, so coverage is exact at any sample count.
    let outline = nested_squares(20, 5.0, &[7]);
    let scene = Scene::from_outlines(1000.0, vec![(outline, DVec2::new(3.0, 2.0))]);
    let camera = unit_camera(210, 210);
    for fill in [FillRule::NonZero, FillRule::EvenOdd] {
        for (samples, passes) in [(1, 1), (4, 2)] {
            let what = format!("nested squares {fill:?}, {samples} samples x {passes} passes");
            check_sample_for_sample(&what, &scene, &camera, settings(fill, samples, passes));
        }
    }
    // Nonzero fills it all, as the reference does.
    let got = render(&scene, &camera, settings(FillRule::NonZero, 4, 1));
    let expected = reference::rasterize(&scene, &camera).unwrap();
    let error = compare(&got, &expected).unwrap();
    assert!(error.max < 2e-3, "axis-aligned squares: {error:?}");
    // Exactly 16 nested squares, one direction: winding 16 in the middle.
    let sixteen = Scene::from_outlines(1000.0, vec![(nested_squares(16, 5.0, &[]), DVec2::ZERO)]);
    let middle = render(
        &sixteen,
        &unit_camera(200, 200),
        settings(FillRule::NonZero, 1, 1),
    );
    assert_eq!(middle.get(100, 100), 1.0, "winding 16 wrapped to 0");
}

#[test]
fn overlapping_instances_unite_under_even_odd() {
    // Two instances of one square-with-a-hole overlapping (as kerned or stacked glyphs
    // do): even-odd is per outline, so the overlap is covered, not cancelled. Under
    // nonzero the instances' windings add, as the reference adds them.
    let ring = || polygons(&[&rect(0.0, 0.0, 60.0, 60.0), &rect(20.0, 20.0, 40.0, 40.0)]);
    let scene = Scene::from_outlines(
        1000.0,
        vec![
            (ring(), DVec2::new(5.2, 4.9)),
            (ring(), DVec2::new(35.7, 20.35)),
            (ring(), DVec2::new(95.7, 4.9)),
        ],
    );
    let camera = unit_camera(160, 90);
    for fill in [FillRule::EvenOdd, FillRule::NonZero] {
        for (samples, passes) in [(1, 1), (4, 2)] {
            let what = format!("overlapping rings {fill:?}, {samples} samples x {passes} passes");
            check_sample_for_sample(&what, &scene, &camera, settings(fill, samples, passes));
        }
    }
    // Pixel (52, 45), font (52.5, 44.5), lies in both rings' bodies: filled, where one
    // parity for both instances would cancel it.
    let got = render(&scene, &camera, settings(FillRule::EvenOdd, 1, 1));
    assert_eq!(got.get(52, 45), 1.0);
}

/// Area error against the exact reference on real glyphs, straight at 13 px/em and
/// rotated at 37: (mean in 1/255 over the framed image, max).
fn reference_error(settings: Settings) -> (f64, f64) {
    let scene = Scene::from_text(&glyphscope::font::shipped(0), "Hamburgefonstiv @g").unwrap();
    let (mut mean, mut max) = (0.0, 0.0f64);
    let cases = [
        (13.0, [1.0, 0.0, 0.0, 1.0]),
        (37.0, [0.94, -0.34, 0.34, 0.94]),
    ];
    for (size, [a, b, c, d]) in cases {
        let mut camera = framed(&scene, size, UPRIGHT, DVec2::new(0.27, 0.61));
        camera.matrix = Camera::matrix_from_rows(a, b, c, d);
        // Room for the rotated line, which climbs by sin 20° of its length.
        let climb = f64::from(camera.width) * b.abs();
        camera.height += climb.ceil() as u32;
        camera.origin.y += climb;
        let expected = reference::rasterize(&scene, &camera).unwrap();
        let e = compare(&render(&scene, &camera, settings), &expected).unwrap();
        mean += e.mae_255 / cases.len() as f64;
        max = max.max(e.max);
    }
    (mean, max)
}

#[test]
fn area_error_shrinks_as_samples_grow() {
    // Point sampling converges to the box filter: N samples in a rooks pattern put an
    // edge's coverage within about 1/N, and the mean error halves as samples quadruple.
    // Only the samples separate the method from the reference: at 64 samples nothing
    // systematic (curves, cubic conversion, precision) is left above 0.1.
    let ladder = [(1, 1), (4, 1), (4, 4), (1, 16), (1, 64)];
    let errors: Vec<(f64, f64)> = ladder
        .iter()
        .map(|&(samples, passes)| reference_error(settings(FillRule::NonZero, samples, passes)))
        .collect();
    for ((samples, passes), (mean, max)) in ladder.iter().zip(&errors) {
        eprintln!("{samples} samples x {passes} passes: mean {mean:.2}/255, max {max:.3}");
    }
    for (k, pair) in errors.windows(2).enumerate() {
        assert!(
            pair[1].0 < pair[0].0 && pair[1].1 <= pair[0].1,
            "no better from {:?} to {:?}: {:?} -> {:?}",
            ladder[k],
            ladder[k + 1],
            pair[0],
            pair[1]
        );
    }
    let (mean, max) = errors[errors.len() - 1];
    assert!(
        mean < 0.5 && max < 0.1,
        "64 samples: mean {mean}/255, max {max}"
    );
}

#[test]
fn default_settings_beat_skia_1x() {
    // The bar is Skia's anti-aliasing at one sample a pixel on real glyphs: the worst
    // mean and max error it reaches, the bounds asserted below. The defaults (4 samples
    // x 4 passes) stay under both.
    let defaults = Settings::from_params(&xor_stencil::INFO.parse_params(&[]).unwrap());
    assert_eq!((defaults.samples, defaults.passes), (4, 4));
    let (mean, max) = reference_error(defaults);
    eprintln!("defaults: mean {mean:.2}/255, max {max:.3}");
    assert!(mean < 3.3 && max < 0.33, "mean {mean}/255, max {max}");
}

#[test]
fn wireframe_overlay_draws_both_kinds_and_keeps_coverage() {
    let scene = Scene::from_text(&glyphscope::font::shipped(0), "g@").unwrap();
    let camera = framed(&scene, 60.0, UPRIGHT, DVec2::new(0.5, 0.25));
    let params = [("overlay".to_string(), "wireframe".to_string())];
    let mut method = registry::create("xor-stencil", &params).unwrap();
    assert_eq!(method.overlays(), &[Overlay::TriangleWireframe]);
    let (with_overlay, picture) = render_with_picture(method.as_mut(), &scene, &camera);
    let plain = render(&scene, &camera, Settings::default());
    assert_eq!(with_overlay, plain, "the overlay changed coverage");
    // Fan lines are blue, curve-triangle lines orange; coverage shows in grey.
    let count = |pick: fn(&[u8; 3]) -> bool| picture.pixels().filter(|p| pick(&p.0)).count();
    let fan = count(|&[r, g, b]| b > 200 && r < 100 && g > 100);
    let curves = count(|&[r, g, b]| r > 200 && g > 80 && g < 160 && b < 60);
    let grey = count(|&[r, g, b]| r == g && g == b && r > 90 && r < 130);
    assert!(
        fan > 100 && curves > 100 && grey > 100,
        "fan {fan}, curves {curves}, grey {grey}"
    );
    assert!(
        registry::create("xor-stencil", &[("overlay".into(), "cells".into())]).is_err(),
        "an overlay it cannot draw"
    );
}

#[test]
fn curve_evaluations_are_counted_per_sample_and_pass() {
    // A lens of two quadratics: its two Loop–Blinn triangles meet along the chord and
    // together hold the whole lens, so each covered sample is evaluated exactly once a
    // pass. A rectangle has no curves at all.
    let p = |x, y| DVec2::new(x, y);
    let lens = Outline {
        contours: vec![Contour {
            segments: vec![
                Segment::Quad(p(0.0, 0.0), p(50.0, 60.0), p(100.0, 0.0)),
                Segment::Quad(p(100.0, 0.0), p(50.0, -60.0), p(0.0, 0.0)),
            ],
        }],
    };
    let scene = Scene::from_outlines(1000.0, vec![(lens, DVec2::new(5.3, 40.2))]);
    let camera = unit_camera(112, 80);
    let gpu = gpu();
    for (samples, passes) in [(1, 1), (4, 1), (4, 3)] {
        let mut method = XorStencil::with_settings(settings(FillRule::NonZero, samples, passes));
        method.prepare(gpu, &scene).unwrap();
        let cost = method.curves_per_pixel(gpu, &camera).unwrap().unwrap();
        let per_pixel = samples * passes;
        eprintln!("{samples} x {passes}: {cost:?}");
        assert_eq!(cost.max, per_pixel);
        // Edge pixels have fewer covered samples, but never fewer than one.
        assert!(
            cost.mean > 0.85 * f64::from(per_pixel) && cost.mean <= f64::from(per_pixel),
            "{cost:?}"
        );
    }
    let square = Scene::from_outlines(
        1000.0,
        vec![(
            polygons(&[&rect(0.0, 0.0, 50.0, 50.0)]),
            DVec2::new(10.0, 10.0),
        )],
    );
    let mut method = XorStencil::with_settings(Settings::default());
    method.prepare(gpu, &square).unwrap();
    let cost = method.curves_per_pixel(gpu, &camera).unwrap().unwrap();
    assert_eq!((cost.mean, cost.max), (0.0, 0));
}

#[test]
fn frames_start_clear_and_culled_scenes_draw_nothing() {
    let gpu = gpu();
    let scene = Scene::from_text(&glyphscope::font::shipped(0), "ab").unwrap();
    let camera = framed(&scene, 20.0, UPRIGHT, DVec2::ZERO);
    let target = CoverageTarget::new(gpu, camera.width, camera.height, Channels::Coverage).unwrap();
    for fill in [FillRule::NonZero, FillRule::EvenOdd] {
        let mut method = XorStencil::with_settings(settings(fill, 4, 2));
        method.prepare(gpu, &scene).unwrap();
        render_frame(gpu, &mut method, &target, &camera).unwrap();
        let first = target.readback(gpu).unwrap();
        assert!(first.sum() > 20.0);
        // The same frame again: the stencil was left clear, the target is cleared.
        render_frame(gpu, &mut method, &target, &camera).unwrap();
        assert_eq!(target.readback(gpu).unwrap(), first);
        // The scene moved out of view.
        let away = Camera {
            origin: camera.origin + DVec2::new(-500.0, 0.0),
            ..camera
        };
        render_frame(gpu, &mut method, &target, &away).unwrap();
        assert_eq!(target.readback(gpu).unwrap().sum(), 0.0);
        // An empty scene.
        method
            .prepare(gpu, &Scene::from_outlines(1000.0, Vec::new()))
            .unwrap();
        render_frame(gpu, &mut method, &target, &camera).unwrap();
        assert_eq!(target.readback(gpu).unwrap().sum(), 0.0);
    }
}

#[test]
fn parameters_are_checked() {
    let make = |key: &str, value: &str| {
        registry::create("xor-stencil", &[(key.to_string(), value.to_string())]).map(|_| ())
    };
    for (key, value) in [
        ("fill", "nonzero"),
        ("fill", "evenodd"),
        ("msaa", "1"),
        ("msaa", "4"),
        ("passes", "1"),
        ("passes", "64"),
        ("overlay", "none"),
    ] {
        make(key, value).unwrap_or_else(|e| panic!("{key}={value}: {e}"));
    }
    for (key, value, message) in [
        ("fill", "winding", "nonzero or evenodd"),
        ("msaa", "8", "1 or 4"),
        ("passes", "0", "1 to 64"),
        ("passes", "65", "1 to 64"),
        ("passes", "2.5", "1 to 64"),
        ("rays", "2", "takes: fill, msaa, passes, overlay"),
    ] {
        let e = make(key, value).unwrap_err().to_string();
        assert!(e.contains(message), "{key}={value}: {e}");
    }
}

#[test]
fn extreme_zoom_on_the_edge_of_an_o() {
    // A 64×64 view on the left edge of an 'o' at 20 000 and 300 000 px/em: the fan
    // triangles reach far outside the view and are clipped. DejaVu's quadratics stay
    // exact at any zoom (Loop–Blinn tests the curve itself). Latin Modern's cubics are
    // converted again as the zoom grows, so they stay within the conversion's 1/16 px
    // (at the default tolerance they would be 0.3 and 4.6 px off).
    for (font, near) in [(0, NEAR_EDGE_PX), (1, 1.0 / 16.0)] {
        let font = glyphscope::font::shipped(font);
        let id = font.glyph_for_char('o').unwrap();
        let scene = Scene::from_glyph_id(&font, id.into()).unwrap();
        for size in [20_000.0, 300_000.0] {
            let mut camera = Camera::new(64, 64, size, DVec2::ZERO);
            let s = camera.scale(scene.units_per_em);
            let bounds = scene.glyphs[0].bounds;
            camera.origin = DVec2::new(
                32.3 - bounds.min.x * s,
                32.6 + (bounds.min.y + bounds.max.y) * 0.5 * s,
            );
            let what = format!("{} 'o' at {size} px/em", font.name());
            let settings = settings(FillRule::NonZero, 4, 2);
            check_samples_near(&what, &scene, &camera, settings, near);
            let covered = render(&scene, &camera, settings).sum() / 4096.0;
            assert!(
                covered > 0.2 && covered < 0.8,
                "{what}: view not on the edge ({covered})"
            );
        }
    }
}

/// The method's accuracy bound: real glyphs of every font at 8–400 px/em, upright,
/// rotated and skewed, at sub-pixel offsets, against the exact reference: no pixel off by
/// more than 0.5 with 4x MSAA or 4+ passes. Prints the mean error per setting.
#[test]
fn within_half_a_level_of_the_reference_with_four_or_more_samples() {
    let (sin, cos) = 30f64.to_radians().sin_cos();
    let transforms = [UPRIGHT, [cos, -sin, sin, cos], [1.0, 0.4, 0.0, 1.0]];
    let texts = ["g&@e", "Qa§f", "BéW4", "\u{0995}\u{09CD}\u{09B7}"];
    let ladder = [(4, 1), (1, 4), (4, 4), (1, 16)];
    println!(
        "| font | px/em | {} |",
        ladder.map(|(m, p)| format!("msaa {m} × {p}")).join(" | ")
    );
    for (font, text) in texts.iter().enumerate() {
        for size in [8.0, 16.0, 48.0, 400.0] {
            // Two glyphs hold thousands of edge pixels at 400 px/em.
            let text: String = text
                .chars()
                .take(if size > 100.0 { 2 } else { 4 })
                .collect();
            let scene = Scene::from_text(&glyphscope::font::shipped(font), &text).unwrap();
            let mut row = Vec::new();
            for (samples, passes) in ladder {
                let mut method =
                    XorStencil::with_settings(settings(FillRule::NonZero, samples, passes));
                method.prepare(gpu(), &scene).unwrap();
                let (mut mean, mut max) = (0.0, 0.0f64);
                for (k, matrix) in transforms.iter().enumerate() {
                    for offset in 0..4 {
                        let subpixel =
                            DVec2::new(0.25 * offset as f64 + 0.07, 0.3 * k as f64 + 0.11);
                        let camera = framed(&scene, size, *matrix, subpixel);
                        let got =
                            glyphscope::methods::frame::render_image(gpu(), &mut method, &camera)
                                .unwrap();
                        let e =
                            compare(&got, &reference::rasterize(&scene, &camera).unwrap()).unwrap();
                        assert_eq!(
                            e.pixels_over_05, 0,
                            "{} at {size} px/em, msaa {samples} × {passes}: max {}",
                            SHIPPED_FONTS[font].0, e.max
                        );
                        mean += e.mae_255 / 12.0;
                        max = max.max(e.max);
                    }
                }
                row.push(format!("{mean:.2}/255, max {max:.2}"));
            }
            println!(
                "| {} | {size} | {} |",
                SHIPPED_FONTS[font].0,
                row.join(" | ")
            );
        }
    }
}

/// A pentagram: nonzero fills its centre (winding 2), even-odd leaves it empty.
#[test]
fn self_intersecting_star() {
    let scene = glyphscope::stability::hard_cases::by_name("pentagram")
        .unwrap()
        .scene;
    let camera = unit_camera(22, 22);
    let nonzero = render(&scene, &camera, settings(FillRule::NonZero, 4, 4));
    let even_odd = render(&scene, &camera, settings(FillRule::EvenOdd, 4, 4));
    assert_eq!(nonzero.get(11, 11), 1.0, "nonzero fills the centre");
    assert_eq!(
        even_odd.get(11, 11),
        0.0,
        "even-odd leaves the centre empty"
    );
    // One star point (winding 1) is filled by both.
    assert_eq!((nonzero.get(10, 6), even_odd.get(10, 6)), (1.0, 1.0));
    let e = compare(&nonzero, &reference::rasterize(&scene, &camera).unwrap()).unwrap();
    assert_eq!(e.pixels_over_05, 0, "{e:?}");
}
