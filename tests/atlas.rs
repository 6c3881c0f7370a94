//! Method `atlas`, the baseline: exact where it draws what it cached (the cached size,
//! pens on the phases it cached), off by the phase elsewhere at that size, and far off
//! once the camera zooms and turns — where drawing from outlines (`winding`) is not.

mod common;

use common::gpu;
use glam::DVec2;
use glyphscope::camera::Camera;
use glyphscope::methods::atlas::{self, AUTO_CACHE_MAX_PX_PER_EM, Atlas};
use glyphscope::methods::frame::render_image;
use glyphscope::methods::{Method, registry};
use glyphscope::metrics::{ErrorStats, compare};
use glyphscope::reference;
use glyphscope::scene::Scene;

const SIZE: f64 = 16.0;

fn params(list: &[(&str, &str)]) -> Vec<(String, String)> {
    list.iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect()
}

/// The atlas with parameters `list`.
fn atlas_with(list: &[(&str, &str)]) -> Atlas {
    Atlas::new(&atlas::INFO.parse_params(&params(list)).unwrap())
}

fn error(method: &mut dyn Method, scene: &Scene, camera: &Camera) -> ErrorStats {
    method.prepare(gpu(), scene).unwrap();
    let image = render_image(gpu(), method, camera).unwrap();
    compare(&image, &reference::rasterize(scene, camera).unwrap()).unwrap()
}

fn error_of(name: &str, list: &[(&str, &str)], scene: &Scene, camera: &Camera) -> ErrorStats {
    error(
        registry::create(name, &params(list)).unwrap().as_mut(),
        scene,
        camera,
    )
}

/// Every glyph of "Hamburgefonstiv&@gQ§8" in a row, each pen `offset` pixels past a
/// whole pixel at `SIZE` px/em (DejaVu Sans: 2048 units per em, 128 units a pixel).
fn row(offset: DVec2) -> (Scene, Camera) {
    let mut scene =
        Scene::from_text(&glyphscope::font::default_font(), "Hamburgefonstiv&@gQ§8").unwrap();
    let units_per_px = scene.units_per_em / SIZE;
    for (i, instance) in scene.instances.iter_mut().enumerate() {
        let pen = DVec2::new(14.0 * i as f64, 0.0) + offset * DVec2::new(1.0, -1.0);
        instance.position = pen * units_per_px;
    }
    let camera = Camera::new(330, 30, SIZE, DVec2::new(3.0, 22.0));
    (scene, camera)
}

/// What this checks: at the cached size, with pens on whole pixels, the atlas draws
/// the bitmaps it cached — the reference's own coverage — and storing, packing and
/// sampling them loses nothing beyond 8 bits. It cannot say the coverage is right,
/// since the bitmaps are the reference's: `matches_hand_worked_coverage_at_the_cached_size`
/// does.
#[test]
fn reproduces_its_cached_bitmaps_at_the_cached_size() {
    let (scene, camera) = row(DVec2::ZERO);
    for subpixel in ["4", "1", "off"] {
        let e = error_of("atlas", &[("subpixel", subpixel)], &scene, &camera);
        println!(
            "pens on whole pixels, subpixel={subpixel}: max {:.2}/255, MAE {:.3}/255",
            e.max * 255.0,
            e.mae_255
        );
        // 8-bit texels: each bitmap within 1/510 of the exact coverage, two meeting in
        // a pixel within 1/255, plus the half-float target's rounding (measured with
        // `cargo test --release --test atlas reproduces -- --nocapture`).
        assert!(e.max < 1.2 / 255.0, "subpixel={subpixel}: {e:?}");
        assert!(e.mae_255 < 0.05, "subpixel={subpixel}: {e:?}");
    }
}

/// The box-filtered coverage of the pixel [i, i + 1] × [j, j + 1] (image pixels) by the
/// rectangle [x0, x1] × [y0, y1]: the product of the two overlaps, in closed form.
fn rectangle_coverage(i: u32, j: u32, (x0, x1): (f64, f64), (y0, y1): (f64, f64)) -> f64 {
    let overlap = |k: u32, a: f64, b: f64| {
        let k = f64::from(k);
        ((k + 1.0).min(b) - k.max(a)).max(0.0)
    };
    overlap(i, x0, x1) * overlap(j, y0, y1)
}

/// Against values worked by hand, not the reference: two copies of a rectangle at one
/// font unit a pixel, edges at quarter pixels, the second pen a quarter pixel past a
/// whole one (a cached phase). A pixel cut by an edge at x = 2.25 is 0.75 covered, a
/// corner pixel cut at 2.25 and 3.25 is 0.5625, one cut at 9.5 and 10.5 is 0.25.
#[test]
fn matches_hand_worked_coverage_at_the_cached_size() {
    use glyphscope::geometry::Outline;
    use glyphscope::stability::hard_cases::{polygon, rect};
    // 16 units per em at 16 px/em; the camera puts font y = 14 on the image's top row.
    let (x0, y0, x1, y1) = (2.25, 3.5, 9.5, 10.75);
    let outline = || Outline {
        contours: vec![polygon(&rect(x0, y0, x1, y1))],
    };
    let second_pen = 12.25;
    let scene = Scene::from_outlines(
        16.0,
        vec![
            (outline(), DVec2::ZERO),
            (outline(), DVec2::new(second_pen, 0.0)),
        ],
    );
    let camera = Camera::new(26, 14, 16.0, DVec2::new(0.0, 14.0));
    // Image rows run down: font y becomes 14 − y.
    let rows = (14.0 - y1, 14.0 - y0);
    let mut atlas = registry::create("atlas", &params(&[("subpixel", "4")])).unwrap();
    atlas.prepare(gpu(), &scene).unwrap();
    let image = render_image(gpu(), atlas.as_mut(), &camera).unwrap();
    let mut checked = [0usize; 3];
    for j in 0..camera.height {
        for i in 0..camera.width {
            let expected = rectangle_coverage(i, j, (x0, x1), rows)
                + rectangle_coverage(i, j, (x0 + second_pen, x1 + second_pen), rows);
            let drawn = f64::from(image.data[(j * camera.width + i) as usize]);
            // 8-bit texels (within 1/510) and the half-float target's rounding.
            assert!(
                (drawn - expected).abs() < 1.2 / 255.0,
                "pixel ({i}, {j}): drawn {drawn}, expected {expected}"
            );
            for (k, value) in [0.75, 0.5625, 0.25].into_iter().enumerate() {
                checked[k] += usize::from(expected == value);
            }
        }
    }
    // The hand-worked pixels are among those checked: 0.75 along both copies' left
    // edges, 0.5625 and 0.25 at corners.
    assert!(checked.iter().all(|&n| n >= 2), "{checked:?}");
}

/// On a cached phase other than zero, and a different one along each axis, the atlas
/// draws exactly what it cached: a phase row and column swapped would be off here.
#[test]
fn exact_on_cached_quarter_phases() {
    for offset in [DVec2::new(0.25, 0.5), DVec2::new(0.75, 0.25)] {
        let (scene, camera) = row(offset);
        let e = error_of("atlas", &[("subpixel", "4")], &scene, &camera);
        assert!(e.max < 1.2 / 255.0, "pens off by {offset}: {e:?}");
        assert!(e.mae_255 < 0.05, "pens off by {offset}: {e:?}");
    }
}

#[test]
fn between_phases_the_error_is_the_snap() {
    // Pens a third of a pixel and more off the grid in x and y.
    let (scene, camera) = row(DVec2::new(0.37, 0.29));
    let quarter = error_of("atlas", &[("subpixel", "4")], &scene, &camera);
    let whole = error_of("atlas", &[("subpixel", "1")], &scene, &camera);
    let resampled = error_of("atlas", &[("subpixel", "off")], &scene, &camera);
    for (what, e) in [
        ("4×4 phases", &quarter),
        ("whole pixels", &whole),
        ("resampled", &resampled),
    ] {
        println!(
            "pens (0.37, 0.29) px off the grid, {what}: MAE {:.2}/255, max {:.3}",
            e.mae_255, e.max
        );
    }
    // Snapped to a quarter pixel, a glyph moves by at most 1/8 px along each axis: no
    // pixel's coverage changes by more than a pixel-wide strip 1/8 + 1/8 wide.
    assert!(quarter.max <= 0.25, "{quarter:?}");
    // Measured by `cargo test --release --test atlas between_phases -- --nocapture`.
    assert!(quarter.mae_255 < 3.0, "{quarter:?}");
    assert_worse(whole.mae_255, 2.0, quarter.mae_255, "whole pixels' MAE");
    assert_worse(resampled.mae_255, 2.0, quarter.mae_255, "resampling's MAE");
}

/// `worse` is over `factor` times `better`.
fn assert_worse(worse: f64, factor: f64, better: f64, what: &str) {
    assert!(worse > factor * better, "{what}: {worse} vs {better}");
}

/// What the project exists to show: cached at 16 px/em, the atlas cannot follow the
/// camera; drawn from the outlines, the glyphs stay exact.
#[test]
fn worse_than_winding_once_the_camera_zooms_and_turns() {
    let (scene, mut camera) = row(DVec2::ZERO);
    let (sin, cos) = 30f64.to_radians().sin_cos();
    camera.size_px_per_em = SIZE * 2.5;
    camera.matrix = Camera::matrix_from_rows(cos, -sin, sin, cos);
    camera.width = 720;
    camera.height = 420;
    camera.origin = DVec2::new(20.0, 80.0);
    let cache = SIZE.to_string();
    let atlas = error_of(
        "atlas",
        &[("cache_px_per_em", cache.as_str())],
        &scene,
        &camera,
    );
    let winding = error_of("winding", &[], &scene, &camera);
    for (what, e) in [("atlas", &atlas), ("winding", &winding)] {
        println!(
            "cached at 16 px/em, seen ×2.5 and turned 30°, {what}: MAE {:.3}/255, max {:.3}, {} pixels > 0.25",
            e.mae_255, e.max, e.pixels_over_025
        );
    }
    // Measured (a mostly blank view) by `cargo test --release --test atlas
    // worse_than_winding -- --nocapture`.
    assert!(atlas.pixels_over_025 > 100, "{atlas:?}");
    assert_eq!(winding.pixels_over_025, 0, "{winding:?}");
    assert_worse(
        atlas.mae_255,
        10.0,
        winding.mae_255,
        "atlas vs winding, MAE",
    );
    assert_worse(atlas.max, 2.0, winding.max, "atlas vs winding, max");
}

#[test]
fn auto_caches_at_the_first_frame_size_up_to_a_limit() {
    let (scene, mut camera) = row(DVec2::ZERO);
    let mut atlas = atlas_with(&[]);
    atlas.prepare(gpu(), &scene).unwrap();
    assert_eq!(
        atlas.cached_px_per_em(),
        None,
        "nothing cached before a frame"
    );
    render_image(gpu(), &mut atlas, &camera).unwrap();
    assert_eq!(atlas.cached_px_per_em(), Some(SIZE));
    // A later frame at another size keeps the cache: that is what an atlas does.
    camera.size_px_per_em = 3.0 * SIZE;
    render_image(gpu(), &mut atlas, &camera).unwrap();
    assert_eq!(atlas.cached_px_per_em(), Some(SIZE));

    let mut huge = atlas_with(&[]);
    let one = Scene::from_text(&glyphscope::font::default_font(), "l").unwrap();
    huge.prepare(gpu(), &one).unwrap();
    let far_in = Camera::new(64, 64, 20_000.0, DVec2::new(-100.0, 20_000.0));
    render_image(gpu(), &mut huge, &far_in).unwrap();
    assert_eq!(huge.cached_px_per_em(), Some(AUTO_CACHE_MAX_PX_PER_EM));
}

#[test]
fn bad_parameters_are_rejected() {
    for (key, value, expect) in [
        ("subpixel", "3", "subpixel=3"),
        ("cache_px_per_em", "0", "cache_px_per_em=0"),
        ("cache_px_per_em", "5000", "cache_px_per_em=5000"),
        ("cache_px_per_em", "big", "cache_px_per_em=big"),
        ("cache_px_per_em", "NaN", "cache_px_per_em=NaN"),
        ("phases", "4", "no parameter 'phases'"),
    ] {
        let err = registry::create("atlas", &params(&[(key, value)]))
            .err()
            .unwrap_or_else(|| panic!("{key}={value} accepted"));
        assert!(matches!(err, glyphscope::Error::Input(_)));
        assert!(err.to_string().contains(expect), "{err}");
    }
}

/// A cache that cannot fit one texture is refused from the glyphs' sizes, before any of
/// them is rasterized: 40 distinct glyphs at 4096 px/em in 4 × 4 phases would need
/// 640 bitmaps of about 4000² texels (about 10 GB of rasterizing) before the old check
/// ran. Hand-worked: one 'M' at 4096 px/em alone is ~3500 × 3000 texels, 16 phases of it
/// ~170 M texels, past a 16384² texture (268 M) already with two glyphs' worth.
#[test]
fn a_cache_too_large_for_one_texture_is_refused_before_rasterizing() {
    let font = glyphscope::font::default_font();
    let scene = Scene::from_text(&font, "ABCDEFGHIJKLMNOPQRSTabcdefghijklmnopqrst").unwrap();
    let mut atlas = atlas_with(&[("cache_px_per_em", "4096")]);
    // A cache size given is built by `prepare`.
    let err = atlas.prepare(gpu(), &scene).unwrap_err();
    assert!(matches!(err, glyphscope::Error::Input(_)), "{err}");
    assert!(err.to_string().contains("do not fit"), "{err}");
}
