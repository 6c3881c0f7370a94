//! The whole GPU path — context, target, the `Method` trait, blending, readback — checked
//! against the CPU reference with the `bounds` method on glyphs that are rectangles,
//! where its box-filter coverage is exact.
//!
//! These tests need an adapter. Without one they fail with the message that says how
//! to get one (CI installs lavapipe), rather than skip and pass silently.

mod common;

use common::{cameras, gpu, render};
use glam::DVec2;
use glyphscope::camera::Camera;
use glyphscope::coverage::CoverageImage;
use glyphscope::geometry::{Contour, Outline, Segment};
use glyphscope::gpu::{Channels, CoverageTarget, GpuContext};
use glyphscope::methods::frame::{render_frame, time_frames};
use glyphscope::methods::{Method, registry};
use glyphscope::scene::Scene;
use glyphscope::{Error, reference};

/// Half-float coverage holds about 3 decimal digits.
const MAX_ERROR: f32 = 2e-3;

/// A closed rectangle of four lines, either way round (nonzero fills both alike).
fn rectangle(min: DVec2, max: DVec2, clockwise: bool) -> Outline {
    let mut corners = [min, DVec2::new(max.x, min.y), max, DVec2::new(min.x, max.y)];
    if clockwise {
        corners.reverse();
    }
    let segments = (0..4)
        .map(|k| Segment::Line(corners[k], corners[(k + 1) % 4]))
        .collect();
    Outline {
        contours: vec![Contour { segments }],
    }
}

/// Rectangles at sub-pixel positions for a 37×23 view at 10 px/em (0.01 px per unit):
/// two that share an edge, a sliver under half a pixel wide, a clockwise one, one
/// smaller than a pixel and one that runs off the right edge. None overlap, so the
/// reference's union and the GPU's sum agree.
fn small_scene() -> Scene {
    let r =
        |x0, y0, x1, y1, clockwise| rectangle(DVec2::new(x0, y0), DVec2::new(x1, y1), clockwise);
    Scene::from_outlines(
        1000.0,
        vec![
            (r(0.0, 0.0, 430.0, 710.0, false), DVec2::new(13.7, 0.0)),
            (r(0.0, 0.0, 270.0, 710.0, false), DVec2::new(443.7, 0.0)),
            (r(0.0, -200.0, 37.0, 1300.0, false), DVec2::new(900.25, 0.0)),
            (
                r(-120.0, -380.0, 640.0, 220.0, true),
                DVec2::new(1250.6, 153.1),
            ),
            (r(0.0, 0.0, 55.0, 45.0, false), DVec2::new(2100.3, 800.7)),
            (
                r(0.0, -300.0, 1200.0, 1500.0, false),
                DVec2::new(2300.9, 0.3),
            ),
        ],
    )
}

/// A row of 24 rectangles of assorted sizes across a 301×41 view at 24 px/em: wide
/// enough that a row of the target is not a multiple of 256 bytes (301 × 8 = 2408).
/// Every fourth one touches its left neighbour.
fn wide_scene() -> Scene {
    let mut placed = Vec::new();
    let mut x = 37.3;
    for k in 0..24 {
        let k = f64::from(k);
        let width = 90.0 + (k * 157.0) % 610.0;
        let bottom = -350.0 + (k * 83.0) % 300.0;
        let top = 300.0 + (k * 211.0) % 2100.0;
        let clockwise = k % 3.0 == 0.0;
        let outline = rectangle(DVec2::new(0.0, bottom), DVec2::new(width, top), clockwise);
        placed.push((outline, DVec2::new(x, (k * 0.37) % 1.0)));
        let gap = if k % 4.0 == 2.0 {
            0.0
        } else {
            113.7 + (k * 29.0) % 80.0
        };
        x += width + gap;
    }
    Scene::from_outlines(2048.0, placed)
}

/// The diagnostic that draws each glyph's dilated quad: the GPU path with no method's
/// own work in it.
fn bounds() -> Box<dyn Method> {
    registry::create("bounds", &[]).unwrap()
}

fn max_abs_difference(a: &CoverageImage, b: &CoverageImage) -> f32 {
    assert_eq!((a.width, a.height), (b.width, b.height));
    a.data
        .iter()
        .zip(&b.data)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f32::max)
}

/// Renders `scene` under every camera and compares with the reference.
fn check_against_reference(scene: &Scene, base: Camera) {
    for (name, camera) in cameras(base) {
        let expected = reference::rasterize(scene, &camera).unwrap();
        let actual = render(bounds().as_mut(), scene, &camera);
        let error = max_abs_difference(&actual, &expected);
        let (sum, expected_sum) = (actual.sum(), expected.sum());
        let view = format!("{}x{}", camera.width, camera.height);
        eprintln!(
            "{view} {name}: max error {error:.2e}, coverage {sum:.4} px (reference {expected_sum:.4})"
        );
        assert!(
            expected_sum > 10.0,
            "{view} {name}: the scene is barely in view"
        );
        assert!(
            error < MAX_ERROR,
            "{view} {name}: max error {error} over {MAX_ERROR}"
        );
        assert!(
            (sum - expected_sum).abs() <= 1e-3 * expected_sum,
            "{view} {name}: coverage sums to {sum} px, the reference to {expected_sum}"
        );
    }
    // Moving the scene and the view together must change nothing but the last bits of
    // the f32 corners (here it changes nothing at all).
    let far = Camera {
        world_offset: DVec2::new(1e5, -1e5),
        ..base
    };
    let shift = max_abs_difference(
        &render(bounds().as_mut(), scene, &far),
        &render(bounds().as_mut(), scene, &base),
    );
    eprintln!(
        "{}x{} far world offset vs none: max difference {shift:.2e}",
        base.width, base.height
    );
    assert!(shift < 1e-3, "the world offset changed coverage by {shift}");
}

#[test]
fn bounds_matches_the_reference_on_an_odd_sized_target() {
    check_against_reference(
        &small_scene(),
        Camera::new(37, 23, 10.0, DVec2::new(2.3, 17.6)),
    );
}

#[test]
fn bounds_matches_the_reference_on_a_target_with_padded_rows() {
    check_against_reference(
        &wide_scene(),
        Camera::new(301, 41, 24.0, DVec2::new(0.45, 31.3)),
    );
}

#[test]
fn each_frame_starts_from_a_clear_target() {
    let gpu = gpu();
    let camera = Camera::new(37, 23, 10.0, DVec2::new(2.3, 17.6));
    let target = CoverageTarget::new(gpu, camera.width, camera.height, Channels::Coverage).unwrap();
    let mut method = registry::create("bounds", &[]).unwrap();
    method.prepare(gpu, &small_scene()).unwrap();
    render_frame(gpu, method.as_mut(), &target, &camera).unwrap();
    assert!(target.readback(gpu).unwrap().sum() > 10.0);
    // The same method and target, now with nothing to draw.
    method
        .prepare(gpu, &Scene::from_outlines(1000.0, Vec::new()))
        .unwrap();
    render_frame(gpu, method.as_mut(), &target, &camera).unwrap();
    assert_eq!(target.readback(gpu).unwrap().sum(), 0.0);
}

#[test]
fn timestamps_give_finite_positive_frame_times() {
    let gpu = gpu();
    let camera = Camera::new(37, 23, 10.0, DVec2::new(2.3, 17.6));
    let mut method = registry::create("bounds", &[]).unwrap();
    method.prepare(gpu, &small_scene()).unwrap();
    let target = CoverageTarget::new(gpu, camera.width, camera.height, Channels::Coverage).unwrap();
    assert!(
        gpu.has_timestamps(),
        "{} has no timestamp queries",
        gpu.adapter_name()
    );
    let times = time_frames(gpu, method.as_mut(), &target, &camera, 2, 5)
        .unwrap()
        .unwrap();
    eprintln!("{}: frame times {times:?} ms", gpu.adapter_name());
    assert_eq!(times.len(), 5);
    assert!(
        times.iter().all(|t| t.gpu_ms.is_finite()
            && t.gpu_ms > 0.0
            && t.cpu_ms.is_finite()
            && t.cpu_ms > 0.0),
        "frame times {times:?} ms"
    );
}

#[test]
fn a_target_larger_than_the_device_allows_is_an_input_error() {
    let gpu = gpu();
    let side = gpu.max_texture_side() + 1;
    assert!(matches!(
        CoverageTarget::new(gpu, side, 1, Channels::Coverage),
        Err(Error::Input(_))
    ));
}

/// The app renders on eframe's device: a device opened elsewhere with the same
/// descriptor, wrapped by `from_device`, draws exactly what `GpuContext::new`'s draws
/// and times frames too. (The one test that opens a second device: that is what it
/// checks; every other test uses `common::gpu`.)
#[test]
fn a_device_opened_elsewhere_renders_the_same() {
    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let adapter = pollster::block_on(instance.request_adapter(&Default::default()))
        .expect("an adapter (on Debian: apt-get install mesa-vulkan-drivers)");
    let (device, queue) =
        pollster::block_on(adapter.request_device(&GpuContext::device_descriptor(&adapter)))
            .unwrap();
    let outside = GpuContext::from_device(instance, adapter, device, queue);
    assert!(outside.has_timestamps(), "{}", outside.adapter_name());
    let scene = small_scene();
    let camera = Camera::new(37, 23, 10.0, DVec2::new(2.3, 17.6));
    let mut method = registry::create("bounds", &[]).unwrap();
    method.prepare(&outside, &scene).unwrap();
    let target =
        CoverageTarget::new(&outside, camera.width, camera.height, Channels::Coverage).unwrap();
    render_frame(&outside, method.as_mut(), &target, &camera).unwrap();
    let image = target.readback(&outside).unwrap();
    assert_eq!(image, render(bounds().as_mut(), &scene, &camera));
    assert!(image.sum() > 10.0, "nothing drawn");
}

/// A frame without an overlay draws into a coverage-only target (one half float a
/// pixel), a frame with one into a picture (rgba): the coverage must be the same bits in
/// either, for every method, with and without each of its overlays. It fails where a
/// shader writes anything but its coverage into red when it draws no overlay (the rule
/// in common.wgsl), or draws an overlay's colour into a coverage-only target. vello is
/// left out: its own frames differ from run to run on some scenes.
#[test]
fn a_coverage_only_target_holds_the_picture_targets_coverage_bit_for_bit() {
    let gpu = gpu();
    let scene = Scene::from_text(&glyphscope::font::shipped(0), "Hamburg ffi").unwrap();
    let camera = Camera::new(140, 30, 18.0, DVec2::new(2.3, 22.6));
    let mut checked = 0;
    for info in registry::METHODS
        .iter()
        .filter(|m| !m.is_reference() && m.name != "vello")
    {
        let overlays = registry::create(info.name, &[]).unwrap().overlays();
        let choices = std::iter::once("none").chain(overlays.iter().map(|o| o.name()));
        for overlay in choices {
            let params = if overlay == "none" {
                vec![]
            } else {
                vec![("overlay".to_string(), overlay.to_string())]
            };
            let [lean, picture] = [Channels::Coverage, Channels::Picture].map(|channels| {
                let mut method = registry::create(info.name, &params).unwrap();
                method.prepare(gpu, &scene).unwrap();
                let target =
                    CoverageTarget::new(gpu, camera.width, camera.height, channels).unwrap();
                render_frame(gpu, method.as_mut(), &target, &camera).unwrap();
                target.readback(gpu).unwrap()
            });
            assert!(
                picture.sum() > 50.0,
                "{} overlay={overlay}: nothing drawn",
                info.name
            );
            let same = lean
                .data
                .iter()
                .zip(&picture.data)
                .all(|(a, b)| a.to_bits() == b.to_bits());
            assert!(
                same,
                "{} overlay={overlay}: the two targets' coverage differs",
                info.name
            );
            checked += 1;
        }
    }
    assert!(checked >= 12, "only {checked} methods and overlays checked");
}
