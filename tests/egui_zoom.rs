//! `examples/egui_zoom` driven headless through egui_kittest on the test GPU: at 20×,
//! the library's label is sharp (its edge pixels' coverage within a few 255ths of the
//! reference's) where egui's, the same text in the same font, is a magnified bitmap
//! (its edges off by far more once aligned as well as they can be).
//!
//! Coverage is read back from the screen as the target blends: (background − pixel) /
//! (background − ink), in linear light on an sRGB target and in the stored values on
//! any other. The bounds, set before the first run: the library's edge MAE within
//! 4/255 (its claim, 0.02 coverage, at most 5.1/255, and 8-bit output), egui's at least
//! 3 times the library's and over 8/255 (a bitmap of 14 px magnified 20× spreads each
//! edge over some 20 pixels).

#[path = "../examples/egui_zoom/zoom.rs"]
mod zoom;

mod common;

use egui_kittest::Harness;
use egui_kittest::wgpu::WgpuTestRenderer;
use glam::DVec2;
use glyphscope::camera::Camera;
use glyphscope::coverage::CoverageImage;
use glyphscope::metrics;
use glyphscope::reference;
use glyphscope::scene::Scene;
use zoom::ZoomApp;

const SIZE: [f32; 2] = [960.0, 360.0];
const ZOOM: f32 = 20.0;

fn decode(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// The app showing `size` scene points about `centre` (egui fits them to the screen).
fn zoomed(centre: egui::Pos2, size: egui::Vec2) -> Harness<'static, ZoomApp> {
    let mut harness = Harness::builder()
        .with_size(SIZE)
        .renderer(WgpuTestRenderer::from_setup(
            glyphscope::app::wgpu_setup_on(common::gpu()),
        ))
        .build_eframe(|cc| ZoomApp::new(cc).unwrap());
    harness.step();
    harness.state_mut().scene_rect = egui::Rect::from_center_size(centre, size);
    for _ in 0..3 {
        harness.step();
    }
    harness
}

/// The app zoomed to 20× on `centre` (scene points); the screen as coverage.
fn coverage_at(centre: egui::Pos2) -> (CoverageImage, glam::Mat3) {
    let mut harness = zoomed(centre, egui::vec2(SIZE[0], SIZE[1]) / ZOOM);
    let screen = harness.render().unwrap();
    let srgb = harness.state().format.is_srgb();
    let lin = |v: u8| {
        if srgb {
            decode(f64::from(v) / 255.0)
        } else {
            f64::from(v) / 255.0
        }
    };
    let background = lin(235);
    let ink = lin(zoom::INK[1]);
    let data = screen
        .pixels()
        .map(|p| ((background - lin(p[1])) / (background - ink)) as f32)
        .collect();
    let image = CoverageImage {
        width: screen.width(),
        height: screen.height(),
        data,
    };
    (image, harness.state().scene_to_screen)
}

/// The reference of the first label at 20× with its baseline's start at `origin`
/// (screen pixels), on a frame of `image`'s size.
fn reference_at(image: &CoverageImage, origin: DVec2) -> CoverageImage {
    let font = glyphscope::font::default_font();
    let scene = Scene::from_text(&font, zoom::LABELS[0]).unwrap();
    let size = f64::from(zoom::SIZE * ZOOM);
    reference::rasterize(
        &scene,
        &Camera::new(image.width, image.height, size, origin),
    )
    .unwrap()
}

/// The centre of a frame's coverage (its first moment), pixels.
fn centroid(image: &CoverageImage) -> DVec2 {
    let (mut sum, mut weight) = (DVec2::ZERO, 0.0);
    for (i, &c) in image.data.iter().enumerate() {
        let c = f64::from(c.clamp(0.0, 1.0));
        let p = DVec2::new(
            (i % image.width as usize) as f64 + 0.5,
            (i / image.width as usize) as f64 + 0.5,
        );
        sum += c * p;
        weight += c;
    }
    sum / weight
}

#[test]
fn at_20x_the_library_is_sharp_where_egui_magnifies_a_bitmap() {
    // The library's first label, "Ham" of "Hamburgefonstiv".
    let pen = ZoomApp::library_pen(0);
    let (library, to_screen) = coverage_at(pen + egui::vec2(18.0, -4.0));
    let origin = to_screen
        .transform_point2(glam::vec2(pen.x, pen.y))
        .as_dvec2();
    let expected = reference_at(&library, origin);
    let ours = metrics::compare(&library, &expected).unwrap();

    // egui's first label, the same letters: its top left corner at the scene's origin,
    // so its baseline about an ascent (0.93 em in DejaVu Sans) lower; then aligned to the
    // reference by the centre of its coverage, twice (each step sees the same letters).
    let (egui_image, to_screen) = coverage_at(egui::pos2(18.0, 10.0));
    let baseline = glam::vec2(0.0, 0.93 * zoom::SIZE);
    let mut origin = to_screen.transform_point2(baseline).as_dvec2();
    let mut aligned = reference_at(&egui_image, origin);
    for _ in 0..2 {
        origin += centroid(&egui_image) - centroid(&aligned);
        aligned = reference_at(&egui_image, origin);
    }
    let theirs = metrics::compare(&egui_image, &aligned).unwrap();
    println!(
        "at 20×: the library's edge MAE {:.2}/255 (max {:.3}), egui's {:.2}/255 (max {:.3}), \
         over {} and {} edge pixels",
        ours.edge.mae_255,
        ours.max,
        theirs.edge.mae_255,
        theirs.max,
        ours.edge.pixels,
        theirs.edge.pixels
    );
    assert!(ours.edge.pixels > 500, "the label is in view: {ours:?}");
    assert!(ours.edge.mae_255 <= 4.0, "{ours:?}");
    assert!(
        theirs.edge.mae_255 > 8.0 && theirs.edge.mae_255 > 3.0 * ours.edge.mae_255,
        "{theirs:?}"
    );
}

/// Writes `screenshots/egui-zoom.png`: the two columns at 5×, the end of egui's labels
/// beside the start of the library's (`cargo test --release --test egui_zoom --
/// --ignored screenshot`).
#[test]
#[ignore = "writes the README's picture"]
fn screenshot() {
    let mut harness = zoomed(egui::pos2(190.0, 22.0), egui::vec2(192.0, 72.0));
    harness
        .render()
        .unwrap()
        .save("screenshots/egui-zoom.png")
        .unwrap();
}
