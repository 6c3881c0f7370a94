//! Property tests: random outlines — random points, every segment kind, degenerate ones
//! on purpose (zero-length, repeated and nearly repeated points, collinear controls,
//! cusps), coordinates from 1e-6 to the 16-bit range a font can hold — through every
//! method's CPU preparation: no panic, every float the GPU would read finite. A few of
//! them drawn on the GPU: coverage finite and in [0, 1]. Random and damaged font files:
//! a clear error, never a panic.

mod common;

use glam::{DMat2, DVec2};
use glyphscope::Error;
use glyphscope::camera::{Camera, MAX_SIZE_PX_PER_EM};
use glyphscope::font::{Font, SHIPPED_FONTS};
use glyphscope::geometry::{Contour, Outline, Segment};
use glyphscope::methods::sdf_cells::{self, SceneData, Settings};
use glyphscope::methods::tessellation::{
    glyph_mesh,
    subdivision::{Subdivision, TaggedContour},
};
use glyphscope::methods::winding::{BandCount, GlyphData, Layout};
use glyphscope::methods::xor_stencil::{GeometryData, tolerance_halvings};
use glyphscope::methods::{frame, registry};
use glyphscope::reference;
use glyphscope::scene::Scene;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};

/// Deterministic runs (a fixed seed, nothing persisted), `cases` each.
fn config(cases: u32) -> Config {
    Config {
        cases,
        failure_persistence: None,
        rng_seed: RngSeed::Fixed(0x9_5AB1E),
        ..Config::default()
    }
}

/// Where a control point comes from: a fresh point, or one tied to the point before
/// it, so that degenerate segments are common rather than measure-zero.
#[derive(Clone, Copy, Debug)]
enum Point {
    Fresh(f64, f64),
    Repeat,
    Nudge(f64, f64),
}

fn point() -> impl Strategy<Value = Point> {
    let unit = -32768.0..32767.0f64;
    prop_oneof![
        4 => (-1200.0..1200.0f64, -1200.0..1200.0f64).prop_map(|(x, y)| Point::Fresh(x, y)),
        1 => (unit.clone(), unit).prop_map(|(x, y)| Point::Fresh(x.round(), y.round())),
        2 => Just(Point::Repeat),
        2 => (-1e-6..1e-6f64, -1e-6..1e-6f64).prop_map(|(x, y)| Point::Nudge(x, y)),
    ]
}

/// A segment kind and its control points after the start (the last is the end).
fn segment() -> impl Strategy<Value = Vec<Point>> {
    (1usize..=3).prop_flat_map(|n| prop::collection::vec(point(), n))
}

fn resolve(p: Point, previous: DVec2) -> DVec2 {
    match p {
        Point::Fresh(x, y) => DVec2::new(x, y),
        Point::Repeat => previous,
        Point::Nudge(dx, dy) => previous + DVec2::new(dx, dy),
    }
}

/// A closed contour: segments chained end to start, the last one ending at the start.
fn contour() -> impl Strategy<Value = Contour> {
    (
        point(),
        prop::collection::vec(segment(), 1..8),
        any::<bool>(),
    )
        .prop_map(|(start, segments, collinear_last)| {
            let start = resolve(start, DVec2::ZERO);
            let mut at = start;
            let count = segments.len();
            let segments = segments
                .into_iter()
                .enumerate()
                .map(|(k, points)| {
                    let mut ps: Vec<DVec2> = Vec::with_capacity(points.len());
                    for p in &points {
                        let prev = ps.last().copied().unwrap_or(at);
                        ps.push(resolve(*p, prev));
                    }
                    if k + 1 == count {
                        *ps.last_mut().expect("a point") = start;
                        // A collinear last curve (a = 0 exactly: control at the middle).
                        if collinear_last && ps.len() == 2 {
                            ps[0] = (at + start) * 0.5;
                        }
                    }
                    let s = match ps[..] {
                        [b] => Segment::Line(at, b),
                        [c, b] => Segment::Quad(at, c, b),
                        [c1, c2, b] => Segment::Cubic(at, c1, c2, b),
                        _ => unreachable!("one to three points"),
                    };
                    at = s.end();
                    s
                })
                .collect();
            Contour { segments }
        })
}

fn outline() -> impl Strategy<Value = (Outline, f64)> {
    (
        prop::collection::vec(contour(), 1..4),
        prop::sample::select(vec![16.0, 1000.0, 2048.0, 16384.0]),
    )
        .prop_map(|(contours, upem)| (Outline { contours }, upem))
}

fn all_finite<'a>(values: impl IntoIterator<Item = &'a f32>) -> bool {
    values.into_iter().all(|v| v.is_finite())
}

/// Every method's CPU preparation of `scene`, checked: no panic, finite floats,
/// indices in range.
fn check_cpu_preparation(scene: &Scene) {
    for (bands, layout) in [
        (BandCount::Auto, Layout::Rays),
        (BandCount::Fixed(1), Layout::Rays),
        (BandCount::Fixed(64), Layout::Rays),
        (BandCount::Auto, Layout::Area),
        (BandCount::Fixed(7), Layout::Area),
    ] {
        let data = GlyphData::of_scene(scene, bands, layout);
        assert!(
            data.curves
                .iter()
                .all(|c| all_finite(c.p0p1.iter().chain(&c.p2).chain(&c.max_min)))
        );
        assert!(data.glyphs.iter().all(|g| all_finite(&g.bounds)));
        let curves = data.curves.len() as u32;
        assert!(data.band_curves.iter().all(|&c| c < curves));
    }
    for mode in ["estimate", "exact"] {
        let params = sdf_cells::INFO.parse_params(&[("mode".into(), mode.into())]);
        let settings = Settings::from_params(&params.unwrap());
        let data = SceneData::of_scene(scene, &settings).expect("sdf-cells prepares it");
        assert!(all_finite(data.points.iter().flatten()));
        assert!(
            data.glyphs
                .iter()
                .all(|g| all_finite(g.grid_min.iter().chain(&g.cell_size)))
        );
    }
    for px_per_em in [16.0, MAX_SIZE_PX_PER_EM] {
        let data = GeometryData::of_scene(scene, tolerance_halvings(px_per_em));
        assert!(all_finite(data.bounds.iter().flatten()));
        assert!(all_finite(
            data.fan_points.iter().chain(&data.curve_points).flatten()
        ));
    }
    for glyph in &scene.glyphs {
        let contours = TaggedContour::from_outline(&glyph.outline);
        for subdivision in [
            Subdivision::Fixed(16),
            Subdivision::Adaptive(3.0),
            Subdivision::Tolerance(scene.units_per_em / 1e4),
        ] {
            let (_, mesh) = glyph_mesh(&contours, scene.units_per_em, subdivision)
                .unwrap_or_else(|e| panic!("{subdivision:?}: {e:?}"));
            assert!(all_finite(mesh.vertices.iter().flatten()));
            let vertices = mesh.vertices.len() as u32;
            assert!(mesh.triangles.iter().all(|&v| v < vertices));
        }
    }
}

proptest! {
    #![proptest_config(config(256))]

    #[test]
    fn random_outlines_prepare_for_every_method((outline, upem) in outline()) {
        let scene = Scene::from_outlines(upem, vec![(outline, DVec2::ZERO)]);
        prop_assume!(!scene.glyphs.is_empty());
        check_cpu_preparation(&scene);
    }
}

/// A 48×48 view of the whole outline at the size that fits it (the largest accepted
/// for an outline with no extent), rotated a little off the axes.
fn fitting_camera(scene: &Scene) -> Camera {
    let extent_em = scene.glyphs[0].bounds.size().max_element() / scene.units_per_em;
    let size = (40.0 / extent_em).min(MAX_SIZE_PX_PER_EM);
    let mut camera = Camera::new(48, 48, size, DVec2::ZERO);
    let (sin, cos) = 0.3f64.sin_cos();
    camera.matrix = DMat2::from_cols(DVec2::new(cos, sin), DVec2::new(-sin, cos));
    let ink = camera.ink_bounds(scene).expect("no tilt");
    camera.origin = DVec2::splat(24.0) - (ink.min + ink.max) * 0.5;
    camera
}

proptest! {
    #![proptest_config(config(12))]

    #[test]
    fn random_outlines_draw_coverage_in_range((outline, upem) in outline()) {
        let scene = Scene::from_outlines(upem, vec![(outline, DVec2::ZERO)]);
        prop_assume!(!scene.glyphs.is_empty());
        let camera = fitting_camera(&scene);
        let reference = reference::rasterize(&scene, &camera).unwrap();
        let in_range = |v: &f32| (0.0..=1.0).contains(v);
        prop_assert!(reference.data.iter().all(in_range));
        for info in registry::METHODS.iter().filter(|m| !m.is_reference()) {
            let name = info.name;
            let mut method = info.create(&[]).unwrap();
            let drawn = method
                .prepare(common::gpu(), &scene)
                .and_then(|()| frame::render_image(common::gpu(), method.as_mut(), &camera));
            let image = match drawn {
                Ok(image) => image,
                // A peer's documented limit (glyphon draws no outline without a font).
                Err(Error::Refused(reason)) if info.is_peer() => {
                    prop_assert!(reason.contains(name), "{reason}");
                    continue;
                }
                Err(e) => panic!("{name}: {e}"),
            };
            prop_assert!(image.data.iter().all(in_range), "{name}: coverage out of [0, 1]");
        }
    }
}

/// The first face of each shipped font, as bytes.
fn shipped_bytes() -> impl Strategy<Value = Vec<u8>> {
    prop::sample::select((0..SHIPPED_FONTS.len()).collect::<Vec<_>>())
        .prop_map(|i| SHIPPED_FONTS[i].2.to_vec())
}

/// Whatever parses must also hand out outlines and shape text without panicking.
fn use_font(bytes: Vec<u8>) {
    if let Ok(font) = Font::from_bytes(bytes, "fuzzed") {
        for id in 0..font.glyph_count().min(64) {
            let _ = font.outline(id);
        }
        let _ = Scene::from_text(&font, "Ag\u{0995}\u{09CD}\u{09B7}");
    }
}

proptest! {
    #![proptest_config(config(128))]

    #[test]
    fn random_bytes_are_not_a_font(bytes in prop::collection::vec(any::<u8>(), 0..4096)) {
        let err = Font::from_bytes(bytes, "noise.ttf").err();
        prop_assert!(err.is_some_and(|e| e.to_string().contains("noise.ttf")));
    }

    #[test]
    fn truncated_fonts_fail_cleanly(bytes in shipped_bytes(), keep in 0.0..1.0f64) {
        let len = (bytes.len() as f64 * keep) as usize;
        use_font(bytes[..len].to_vec());
    }

    #[test]
    fn damaged_fonts_fail_cleanly(
        mut bytes in shipped_bytes(),
        damage in prop::collection::vec((0.0..1.0f64, any::<u8>()), 1..64),
    ) {
        for (at, value) in damage {
            // Most damage lands in the first few kB, where the table directory and the
            // headers every lookup depends on are.
            let i = (at.powi(4) * bytes.len() as f64) as usize;
            bytes[i] = value;
        }
        use_font(bytes);
    }
}
