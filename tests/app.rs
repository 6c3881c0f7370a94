//! The explorer, built as eframe builds it and driven through egui_kittest on the real
//! wgpu device (lavapipe in CI): every method in every layout, every overlay, a font
//! from disk, zoom to 100 000 px/em and back, the speed-vs-error sweep, persistence —
//! each checked on the pixels it puts on the screen.
//!
//! Without a GPU adapter these tests fail (the harness cannot make its device).

mod common;
#[path = "common/explorer.rs"]
mod explorer;

use std::path::PathBuf;
use std::time::{Duration, Instant};

use common::gpu;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use explorer::{harness, settle};
use glyphscope::app::Explorer;
use glyphscope::app::settings::{Layout, PaneOverlay, PaneSettings, PaneSource, Settings};
use glyphscope::coverage::CoverageImage;
use glyphscope::methods::registry::{self, REFERENCE};
use glyphscope::methods::{self, Overlay};
use glyphscope::metrics;

/// The stored byte a coverage shows as, white text on black (sRGB of linear coverage).
fn shown(coverage: f32) -> f32 {
    let c = coverage.clamp(0.0, 1.0);
    let v = if c <= 0.003_130_8 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    };
    v * 255.0
}

/// The part of pane `index` free of its label and legend, in pane pixels.
fn clear_area(
    harness: &Harness<'static, Explorer>,
    index: usize,
) -> (egui::Rect, u32, u32, u32, u32) {
    let rect = harness.state().pane_rects()[index];
    let (w, h) = (rect.width() as u32, rect.height() as u32);
    (rect, 0, 80, w, h - 50)
}

/// Largest difference between the screen over pane `index` and `coverage` shown there.
fn screen_vs_coverage(
    harness: &Harness<'static, Explorer>,
    screen: &image::RgbaImage,
    index: usize,
    coverage: &CoverageImage,
) -> f32 {
    let (rect, x0, y0, x1, y1) = clear_area(harness, index);
    let mut worst = 0.0f32;
    for y in y0..y1 {
        for x in x0..x1 {
            let p = screen.get_pixel(rect.min.x as u32 + x, rect.min.y as u32 + y);
            let expected = shown(coverage.get(x, y));
            for channel in 0..3 {
                worst = worst.max((f32::from(p[channel]) - expected).abs());
            }
        }
    }
    worst
}

fn gpu_methods() -> Vec<&'static str> {
    registry::names()
        .filter(|&n| n != REFERENCE.name && registry::create(n, &[]).is_ok())
        .collect()
}

#[test]
fn every_method_in_every_layout_shows_its_own_coverage() {
    let mut harness = harness(Settings::default());
    let mut names = gpu_methods();
    names.push("reference");
    for (layout, key) in [
        (Layout::Single, egui::Key::Num1),
        (Layout::SideBySide, egui::Key::Num2),
        (Layout::Grid, egui::Key::Num4),
    ] {
        harness.key_press(key);
        harness.step();
        assert_eq!(harness.state().settings.layout, layout);
        for name in &names {
            for pane in 0..layout.panes() {
                harness.state_mut().settings.panes[pane] = PaneSettings::method(name);
            }
            let screen = settle(&mut harness);
            let app = harness.state();
            assert_eq!(app.pane_rects().len(), layout.panes());
            let reference = app.reference_image().expect("settled");
            assert!(reference.sum() > 500.0, "the reference shows the text");
            for pane in 0..layout.panes() {
                assert_eq!(app.pane_problem(pane), None, "{name} in pane {pane}");
                let coverage = if *name == "reference" {
                    reference.clone()
                } else {
                    app.pane_capture(pane).expect("read back at rest")
                };
                assert!(coverage.sum() > 500.0, "{name}: pane {pane} is empty");
                let worst = screen_vs_coverage(&harness, &screen, pane, &coverage);
                assert!(
                    worst <= 1.5,
                    "{name}, {layout:?}, pane {pane}: screen off by {worst}"
                );
                if *name != "reference" {
                    // Counted in the background by the method itself, as the CLI does.
                    let mut method = registry::create(name, &[]).unwrap();
                    method.prepare(gpu(), app.scene().unwrap()).unwrap();
                    let expected = method
                        .curves_per_pixel(gpu(), &app.camera().unwrap())
                        .unwrap();
                    assert_eq!(app.pane_curves(pane), expected, "{name}: curves per pixel");
                    let error = app.pane_error(pane).expect("measured at rest");
                    // `bounds` draws boxes, far from the glyphs; a method of glyphscope's
                    // is close. A peer's error is its own: measured, not bounded here.
                    let is_peer = registry::find(name).is_ok_and(|m| m.is_peer());
                    if *name != "bounds" && !is_peer {
                        assert!(error.mae_255 < 2.0, "{name}: {error:?}");
                    }
                    assert!(error.pixels > 0);
                }
            }
        }
    }
    // Methods that are not implemented yet are offered greyed, with the reason.
    for name in registry::names().filter(|&n| n != REFERENCE.name) {
        if let Err(e) = registry::create(name, &[]) {
            harness.state_mut().settings.panes[0] = PaneSettings::method(name);
            harness.step();
            harness.render().unwrap();
            assert_eq!(harness.state().pane_problem(0), Some(e.to_string()));
        }
    }
}

/// A pane set to a peer draws it on the explorer's device and reports its error
/// against the reference, the same figures `render` gives for the same view: here
/// vello, beside winding in pane A.
#[test]
fn a_pane_set_to_a_peer_draws_and_reports_its_error() {
    let mut settings = Settings {
        layout: Layout::SideBySide,
        ..Settings::default()
    };
    settings.panes[0] = PaneSettings::method(methods::winding::INFO.name);
    settings.panes[1] = PaneSettings::method(methods::peers::vello::NAME);
    let mut harness = harness(settings);
    settle(&mut harness);
    let app = harness.state();
    assert_eq!(app.pane_problem(1), None);
    let coverage = app.pane_capture(1).expect("read back at rest");
    let reference = app.reference_image().expect("settled");
    let expected = metrics::compare(&coverage, &reference).unwrap();
    let error = app.pane_error(1).expect("vello's error, measured at rest");
    assert_eq!(error.pixels, expected.pixels);
    assert!((error.mae_255 - expected.mae_255).abs() < 1e-9, "{error:?}");
    assert!(
        error.mae_255 > 0.0 && error.mae_255.is_finite(),
        "{error:?}"
    );
    // vello flattens within 0.25 px: no pixel is far off (see tests/peers.rs).
    assert!(error.max < 0.36, "{error:?}");
    assert!((coverage.sum() - reference.sum()).abs() < 0.05 * reference.sum());
}

#[test]
fn the_method_picker_switches_the_pane_and_greys_what_is_missing() {
    let mut harness = harness(Settings {
        layout: Layout::Single,
        ..Settings::default()
    });
    harness.run_ok();
    harness.get_by_value("sdf-cells").click();
    harness.run_ok();
    harness.get_by_label("bounds").click();
    harness.run_ok();
    assert_eq!(
        harness.state().settings.panes[0].source,
        PaneSource::Method {
            name: "bounds".into(),
            params: Vec::new()
        }
    );
    harness.get_by_value("bounds").click();
    harness.run_ok();
    for name in registry::names() {
        let disabled = harness.get_by_label(name).accesskit_node().is_disabled();
        assert_eq!(
            disabled,
            registry::create(name, &[]).is_err() && name != REFERENCE.name,
            "{name}"
        );
    }
}

#[test]
fn every_overlay_toggles_and_draws_or_is_greyed_with_a_reason() {
    let mut settings = Settings {
        layout: Layout::Single,
        ..Settings::default()
    };
    settings.scene.glyph_mode = true;
    settings.scene.glyph = "g".into();
    settings.camera.size_px_per_em = 400.0;
    settings.camera.origin = [300.0, 420.0];
    for method in gpu_methods() {
        settings.panes[0] = PaneSettings::method(method);
        let mut harness = harness(settings.clone());
        // Tall enough that the overlay row of the method with the most parameters
        // (sdf-cells) is on screen, where a click reaches it.
        harness.set_size(egui::vec2(explorer::SIZE[0], 1000.0));
        let plain = settle(&mut harness);
        // One glyph drawn by its id: glyphon, which lays text out, draws the character
        // that maps to it.
        assert_eq!(harness.state().pane_problem(0), None, "{method}");
        let supported = registry::create(method, &[]).unwrap().overlays();
        for overlay in Overlay::ALL {
            let button = harness.get_by_label(overlay.name());
            if !supported.contains(&overlay) {
                assert!(
                    button.accesskit_node().is_disabled(),
                    "{method}: {overlay:?}"
                );
                continue;
            }
            button.click();
            let screen = settle(&mut harness);
            assert_eq!(
                harness.state().settings.panes[0].overlay,
                PaneOverlay::Method(overlay.name().into())
            );
            let coloured = screen
                .pixels()
                .filter(|p| p[0].abs_diff(p[1]) > 40 || p[1].abs_diff(p[2]) > 40)
                .count();
            assert!(
                coloured > 1000,
                "{method} {overlay:?}: {coloured} coloured pixels"
            );
            harness.get_by_label(overlay.name()).click();
            harness.step();
        }
        // The error against the reference, coloured exactly like `metrics::error_image`.
        // Methods with many parameters push the overlay row below the panel's fold;
        // scrolling is animated over several frames.
        harness.get_by_label("error").scroll_to_me();
        harness.run_steps(30);
        harness.get_by_label("error").click();
        let screen = settle(&mut harness);
        let app = harness.state();
        let error = metrics::error_image(
            &app.pane_capture(0).unwrap(),
            &app.reference_image().unwrap(),
            app.settings.difference_scale,
        );
        let (rect, x0, y0, x1, y1) = clear_area(&harness, 0);
        let mut worst = 0u8;
        for y in y0..y1 {
            for x in x0..x1 {
                let p = screen.get_pixel(rect.min.x as u32 + x, rect.min.y as u32 + y);
                let e = error.get_pixel(x, y);
                worst = worst.max(p[0].abs_diff(e[0])).max(p[2].abs_diff(e[2]));
            }
        }
        assert!(worst <= 1, "{method}: error overlay off by {worst}");
        harness.get_by_label("error").click();
        // The outline, on top of coverage.
        harness.get_by_label("outline points").scroll_to_me();
        harness.run_steps(30);
        harness.get_by_label("outline points").click();
        let outlined = settle(&mut harness);
        assert!(
            harness.state().settings.panes[0].outline,
            "{method}: outline checkbox not toggled"
        );
        let orange = |img: &image::RgbaImage| {
            img.pixels()
                .filter(|p| p[0] > 200 && (120..220).contains(&p[1]) && p[2] < 80)
                .count()
        };
        assert!(
            orange(&outlined) > 300 && orange(&plain) == 0,
            "{method}: no outline drawn ({} orange pixels with it, {} without)",
            orange(&outlined),
            orange(&plain)
        );
    }
}

#[test]
fn a_font_opens_from_disk() {
    let mut harness = harness(Settings {
        layout: Layout::Single,
        ..Settings::default()
    });
    let before = settle(&mut harness);
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("fonts/lmroman10-regular.otf");
    harness.get_by_label("Open…").click();
    harness.run_ok();
    let text_input = egui::accesskit::Role::TextInput;
    harness.get_by_role_and_label(text_input, "path").focus();
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    harness
        .get_by_role_and_label(text_input, "path")
        .type_text(path.to_str().unwrap());
    harness.run_ok();
    harness.get_by_label("Open").click();
    let after = settle(&mut harness);
    let app = harness.state();
    assert_eq!(app.settings.scene.font.label(), "lmroman10-regular.otf");
    assert_eq!(app.pane_problem(0), None);
    assert!(app.pane_error(0).unwrap().mae_255 < 2.0);
    // The view travels in a link, the font as its path.
    let link = app.link().expect("a font from disk travels as its path");
    let encoded: String = path
        .to_str()
        .unwrap()
        .replace('%', "%25")
        .replace('/', "%2F")
        .replace(' ', "%20");
    assert!(link.starts_with(&format!("#font={encoded}&")), "{link}");
    let changed = before
        .pixels()
        .zip(after.pixels())
        .filter(|(a, b)| a != b)
        .count();
    assert!(
        changed > 5000,
        "the text looks the same in the new font ({changed} px changed)"
    );
}

/// The web page's way in: a font as bytes with a name, no path (its file picker, a drop).
/// The same font file opened as bytes draws exactly what it draws opened from disk; a
/// view with it cannot travel in a link (it has no path, and a link carries no bytes),
/// and says why; a file that is not a font is
/// refused by name and leaves the font as it was.
#[test]
fn a_font_opens_from_bytes_as_from_disk() {
    let single = Settings {
        layout: Layout::Single,
        ..Settings::default()
    };
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("fonts/lmroman10-regular.otf");
    let mut from_disk = harness(single.clone());
    settle(&mut from_disk);
    from_disk.state_mut().open_font(path.clone());
    settle(&mut from_disk);
    let disk_pixels = from_disk.state().pane_capture(0).unwrap();
    drop(from_disk);

    let mut from_bytes = harness(single);
    settle(&mut from_bytes);
    let bytes: std::sync::Arc<[u8]> = std::fs::read(&path).unwrap().into();
    from_bytes
        .state_mut()
        .open_font_bytes("lmroman10-regular.otf".into(), bytes.clone());
    settle(&mut from_bytes);
    let app = from_bytes.state();
    assert_eq!(app.settings.scene.font.label(), "lmroman10-regular.otf");
    assert_eq!(app.pane_problem(0), None);
    assert_eq!(app.pane_capture(0).unwrap(), disk_pixels);
    let why = app.link().unwrap_err();
    assert!(why.contains("opened from this computer"), "{why}");

    let font = app.settings.scene.font.clone();
    from_bytes
        .state_mut()
        .open_font_bytes("notes.txt".into(), bytes);
    settle(&mut from_bytes);
    assert_eq!(from_bytes.state().settings.scene.font, font);
    assert!(
        from_bytes
            .state()
            .status_text()
            .contains("'notes.txt' is not a .ttf/.otf font"),
        "{}",
        from_bytes.state().status_text()
    );
}

/// Orange outline pixels with no green within 4 pixels, and green pixels, in `case`
/// drawn by sdf-cells at ×4 with the font's outline and the merged one: the first counts
/// the curves the union dropped (those inside the fill).
fn merged_outline_on(case: &str) -> (usize, usize, String) {
    let mut settings = Settings {
        layout: Layout::Single,
        ..Settings::default()
    };
    settings.panes[0] = PaneSettings::method(methods::sdf_cells::INFO.name);
    let mut harness = harness(settings);
    settle(&mut harness);
    harness.state_mut().load_case(case);
    settle(&mut harness);
    let app = harness.state_mut();
    app.settings.camera.magnify = 4;
    app.settings.panes[0].outline = true;
    app.settings.panes[0].merged = true;
    let screen = settle(&mut harness);
    let is_green = |p: &image::Rgba<u8>| p[1] > 180 && p[0] < 110 && p[2] < 140;
    let is_orange = |p: &image::Rgba<u8>| p[0] > 220 && (140..200).contains(&p[1]) && p[2] < 60;
    let (w, h) = screen.dimensions();
    let alone = (4..h - 4)
        .flat_map(|y| (4..w - 4).map(move |x| (x, y)))
        .filter(|&(x, y)| is_orange(screen.get_pixel(x, y)))
        .filter(|&(x, y)| {
            (y - 4..=y + 4).all(|v| (x - 4..=x + 4).all(|u| !is_green(screen.get_pixel(u, v))))
        })
        .count();
    let green = screen.pixels().filter(|p| is_green(p)).count();
    (alone, green, harness.state().link().unwrap())
}

/// The merged outline is drawn, green and wide, under the font's orange one: where no
/// glyph has overlapping contours (`strong-skew`, DejaVu) every orange curve has green
/// under it; on `inter-overlaps` the curves inside the fill, which the union drops,
/// stay orange alone. The link carries the choice.
#[test]
fn the_merged_outline_is_drawn_under_the_fonts() {
    let (alone_plain, green_plain, _) = merged_outline_on("strong-skew");
    let (alone, green, link) = merged_outline_on("inter-overlaps");
    println!("orange alone: {alone_plain} on strong-skew, {alone} on inter-overlaps");
    assert!(
        green_plain > 500 && green > 500,
        "green: {green_plain}, {green}"
    );
    assert!(
        alone_plain <= 5 && alone > 20,
        "orange with no green near: {alone_plain} without overlaps, {alone} with"
    );
    assert!(link.contains("&a.merged=1"), "{link}");
}

#[test]
fn zoom_to_100000_px_per_em_and_back() {
    let mut settings = Settings {
        layout: Layout::SideBySide,
        ..Settings::default()
    };
    // An analytic method, so the edge pixel's coverage is exact, not quantized.
    settings.panes[0] = PaneSettings::method("winding");
    settings.panes[1] = PaneSettings::method("reference");
    settings.scene.glyph_mode = true;
    settings.scene.glyph = "l".into();
    // Eleven doublings reach exactly 100 000 px/em.
    settings.camera.size_px_per_em = 100_000.0 / 2048.0;
    let mut harness = harness(settings);
    // The side panel takes its width over the first frames; the panes are measured after.
    settle(&mut harness);
    // Put the stem's left edge 0.05 px right of the pane's centre, where the zoom keys
    // zoom about.
    let app = harness.state();
    let rect = app.pane_rects()[0];
    let scene = app.scene().unwrap().clone();
    let bounds = scene.glyphs[0].bounds;
    let s = app.settings.camera.size_px_per_em / scene.units_per_em;
    let centre = glam::DVec2::new(rect.width() as f64, rect.height() as f64) / 2.0;
    harness.state_mut().settings.camera.origin = [
        centre.x + 0.05 - bounds.min.x * s,
        centre.y + (bounds.min.y + bounds.max.y) / 2.0 * s,
    ];
    let start = settle(&mut harness);
    for _ in 0..11 {
        harness.key_press(egui::Key::Plus);
    }
    let deep = settle(&mut harness);
    let app = harness.state();
    assert_eq!(app.settings.camera.size_px_per_em, 100_000.0);
    // The edge is now 102.4 px right of the centre: empty to its left, ink to its right,
    // and the pixel it runs through covered right of it (0.6 of it for an even pane
    // width, 0.1 for an odd one, whose centre is a half pixel).
    let capture = app.pane_capture(0).unwrap();
    let row = capture.height / 2;
    let at = centre.x + 102.4;
    let (pixel, expected) = (at.floor() as u32, at.floor() + 1.0 - at);

    assert_eq!(capture.get(pixel - 12, row), 0.0);
    assert_eq!(capture.get(pixel + 13, row), 1.0);
    let edge = capture.get(pixel, row);
    assert!(
        (f64::from(edge) - expected).abs() < 0.02,
        "edge pixel {edge}, expected {expected}"
    );
    let error = app.pane_error(0).unwrap();
    assert!(
        error.max < 0.05 && error.mae_255 < 0.1,
        "at 100 000 px/em: {error:?}"
    );
    assert!(screen_vs_coverage(&harness, &deep, 0, &capture) <= 1.5);
    for _ in 0..11 {
        harness.key_press(egui::Key::Minus);
    }
    let back = settle(&mut harness);
    assert_eq!(
        harness.state().settings.camera.size_px_per_em,
        100_000.0 / 2048.0
    );
    let rect = harness.state().pane_rects()[0];
    let mut worst = 0u8;
    for y in rect.min.y as u32 + 80..rect.max.y as u32 - 50 {
        for x in rect.min.x as u32..rect.max.x as u32 {
            let (a, b) = (start.get_pixel(x, y), back.get_pixel(x, y));
            worst = worst.max(a[0].abs_diff(b[0]));
        }
    }
    assert!(worst <= 1, "the view did not come back: off by {worst}");
}

#[test]
fn live_gpu_time_and_the_speed_vs_error_sweep() {
    let mut settings = Settings {
        layout: Layout::Single,
        continuous: true,
        ..Settings::default()
    };
    settings.scene.glyph_mode = true;
    settings.camera.size_px_per_em = 64.0;
    let mut harness = harness(settings);
    for _ in 0..6 {
        harness.step();
        harness.render().unwrap();
    }
    let ms = harness
        .state()
        .pane_gpu_ms(0)
        .expect("timestamps read back");
    assert!(ms > 0.0 && ms.is_finite(), "{ms}");
    harness.state_mut().settings.continuous = false;
    settle(&mut harness);
    harness.key_press(egui::Key::P);
    harness.step();
    harness.get_by_label("Run sweep").click();
    let start = Instant::now();
    harness.step();
    while harness.state().sweep_running() {
        assert!(
            start.elapsed() < Duration::from_secs(90),
            "the sweep never ended"
        );
        std::thread::sleep(Duration::from_millis(50));
        harness.step();
    }
    let points = harness.state().sweep_points().to_vec();
    let expected: usize = gpu_methods()
        .iter()
        .map(|m| {
            1 + registry::param_specs(m)
                .iter()
                .filter(|s| s.key != "overlay")
                .map(|s| s.choices.len() - 1)
                .sum::<usize>()
        })
        .sum();
    // A peer may refuse the view (glyphon: a camera that turns); said, not measured.
    let problems = harness.state().sweep_problems();
    for problem in problems {
        let refusal = [" draws ", " rasterizes ", " varies "]
            .iter()
            .any(|w| problem.contains(w));
        assert!(
            refusal
                && registry::METHODS
                    .iter()
                    .any(|m| m.is_peer() && problem.starts_with(m.name)),
            "{problem}"
        );
    }
    assert_eq!(points.len() + problems.len(), expected, "{problems:?}");
    assert!(
        points
            .iter()
            .all(|p| p.gpu_ms > 0.0 && p.mae_255.is_finite())
    );
    let screen = harness.render().unwrap();
    let plotted = screen
        .pixels()
        .filter(|p| p[0] > 200 && p[1] > 100 && p[1] < 180 && p[2] < 100)
        .count();
    assert!(plotted > 20, "no points drawn in the plot");
}

#[test]
fn settings_are_saved_and_restored() {
    #[derive(Default)]
    struct Memory(std::collections::HashMap<String, String>);
    impl eframe::Storage for Memory {
        fn get_string(&self, key: &str) -> Option<String> {
            self.0.get(key).cloned()
        }
        fn set_string(&mut self, key: &str, value: String) {
            self.0.insert(key.into(), value);
        }
        fn remove_string(&mut self, key: &str) {
            self.0.remove(key);
        }
        fn flush(&mut self) {}
    }
    let mut harness = harness(Settings::default());
    harness.key_press(egui::Key::Num4);
    // A new layout frames the text; the zoom then doubles the framed size.
    harness.step();
    let framed = harness.state().settings.camera.size_px_per_em;
    harness.key_press(egui::Key::Plus);
    harness.step();
    let mut memory = Memory::default();
    eframe::App::save(harness.state_mut(), &mut memory);
    let restored: Settings = eframe::get_value(&memory, eframe::APP_KEY).unwrap();
    assert_eq!(restored, harness.state().settings);
    assert_eq!(restored.layout, Layout::Grid);
    assert_eq!(restored.camera.size_px_per_em, 2.0 * framed);
}

/// The magnifier: Alt + wheel three notches over the text gives ×8 about the cursor,
/// and the panes draw a window of the ×1 pane's own pixels, each as an 8×8 block on the
/// screen; N halves it.
#[test]
fn the_magnifier_shows_the_panes_own_pixels_as_blocks() {
    let mut settings = Settings {
        layout: Layout::Single,
        ..Settings::default()
    };
    settings.panes[0] = PaneSettings::method("winding");
    let mut harness = harness(settings);
    settle(&mut harness);
    let whole = harness.state().pane_capture(0).expect("read back at rest");
    let (rect, _, y0, w, y1) = clear_area(&harness, 0);
    // A covered pixel in the clear part of the pane, to magnify about.
    let target = (y0 + 40..y1 - 40)
        .flat_map(|y| (40..w - 40).map(move |x| (x, y)))
        .find(|&(x, y)| whole.get(x, y) == 1.0)
        .expect("the text covers some pixel");
    let pointer = rect.min + egui::vec2(target.0 as f32 + 0.5, target.1 as f32 + 0.5);
    harness.hover_at(pointer);
    // The pixel inspector's line appears under the view: the pane's height settles.
    for _ in 0..3 {
        harness.step();
    }
    let rect = harness.state().pane_rects()[0];
    for _ in 0..3 {
        harness.event(egui::Event::MouseWheel {
            unit: egui::MouseWheelUnit::Line,
            delta: egui::vec2(0.0, 1.0),
            phase: egui::TouchPhase::Move,
            source: egui::MouseWheelSource::Wheel,
            modifiers: egui::Modifiers::ALT,
        });
        harness.step();
    }
    let window = harness.state().magnified_window().expect("laid out");
    assert_eq!(window.factor, 8);
    let cursor = pointer - rect.min;
    let under = (
        (cursor.x / 8.0) as u32 + window.x0,
        (cursor.y / 8.0) as u32 + window.y0,
    );
    assert!(
        under.0.abs_diff(target.0) <= 1 && under.1.abs_diff(target.1) <= 1,
        "the pixel under the cursor moved from {target:?} to {under:?}"
    );
    // The pointer leaves the view (its inspector would cover blocks), and the view rests.
    harness.hover_at(egui::pos2(2.0, 2.0));
    let screen = settle(&mut harness);
    let app = harness.state();
    let window = app.magnified_window().expect("laid out");
    let rect = app.pane_rects()[0];
    let camera = app.camera().unwrap();
    assert_eq!((camera.width, camera.height), (window.cols, window.rows));
    assert_eq!(
        (
            (rect.width() as u32).div_ceil(8),
            (rect.height() as u32).div_ceil(8)
        ),
        (window.cols, window.rows)
    );
    let magnified = app.pane_capture(0).expect("read back at rest");
    // The window's pixels are the ×1 pane's: the same coverage, drawn again.
    let mut inked = 0;
    for j in 0..window.rows {
        for i in 0..window.cols {
            let (a, b) = (magnified.get(i, j), whole.get(window.x0 + i, window.y0 + j));
            assert!(
                (a - b).abs() <= 2e-3,
                "pixel ({i}, {j}): {a} magnified, {b} at ×1"
            );
            inked += usize::from(a > 0.0);
        }
    }
    assert!(inked > 20, "the window shows the text: {inked} pixels");
    // Each block is its pixel, clear of the label and legend; its first row and column
    // are the grid: grey (110) at 60% over it.
    let mut worst = 0.0f32;
    for j in (y0 / 8 + 1)..(y1 / 8).min(window.rows) {
        for i in 0..(w / 8).min(window.cols) {
            let inside = shown(magnified.get(i, j));
            let grid = 0.4 * inside + 0.6 * 110.0;
            for (dx, dy, expected) in [
                (2, 2, inside),
                (5, 6, inside),
                (7, 3, inside),
                (4, 0, grid),
                (0, 5, grid),
            ] {
                let p = screen.get_pixel(
                    rect.min.x as u32 + i * 8 + dx,
                    rect.min.y as u32 + j * 8 + dy,
                );
                for channel in 0..3 {
                    let d = (f32::from(p[channel]) - expected).abs();
                    worst = worst.max(d);
                }
            }
        }
    }
    assert!(worst <= 1.5, "a block or its grid is off by {worst}");
    harness.key_press(egui::Key::N);
    harness.step();
    assert_eq!(harness.state().magnified_window().unwrap().factor, 4);
}

/// The status bar's "worst pixel k of n: (x, y) error e", read as (k, n, (x, y), e).
fn artifact_status(harness: &Harness<'static, Explorer>) -> (usize, usize, (u32, u32), f64) {
    // A label's text is its node's value in AccessKit.
    let text = harness
        .get_by_label_contains("worst pixel ")
        .accesskit_node()
        .value()
        .unwrap_or_default();
    let parse = || -> Option<(usize, usize, (u32, u32), f64)> {
        let rest = text.strip_prefix("worst pixel ")?;
        let (k, rest) = rest.split_once(" of ")?;
        let (n, rest) = rest.split_once(": (")?;
        let (x, rest) = rest.split_once(", ")?;
        let (y, e) = rest.split_once(") error ")?;
        Some((
            k.parse().ok()?,
            n.parse().ok()?,
            (x.parse().ok()?, y.parse().ok()?),
            e.parse().ok()?,
        ))
    };
    parse().unwrap_or_else(|| panic!("the status bar says {text:?}"))
}

/// W centres the magnifier (×16) on the pixel `metrics::compare` finds worst over the
/// whole ×1 pane — worked out here apart from the app: the method measured afresh as
/// `glyphscope render` does, the CPU reference — and `.` / `,` step through every pixel
/// off by more than 0.25, in descending error, wrapping round.
#[test]
fn worst_pixel_and_stepping_go_to_the_pixels_the_metrics_report() {
    let mut settings = Settings {
        layout: Layout::Single,
        ..Settings::default()
    };
    // Small text, where a method's few badly-off pixels are.
    settings.panes[0] = PaneSettings::method("sdf-cells");
    settings.camera.size_px_per_em = 12.0;
    settings.camera.origin = [16.0, 40.0];
    let mut harness = harness(settings);
    settle(&mut harness);
    let app = harness.state();
    let camera = app.camera().expect("laid out");
    assert_eq!(app.magnified_window().map(|w| w.factor), Some(1));
    let scene = app.scene().expect("the scene builds").clone();
    let info = registry::find("sdf-cells").unwrap();
    let one_frame = glyphscope::measure::FrameTiming {
        warmup: 0,
        frames: 1,
    };
    let image = glyphscope::measure::measure(Some(gpu()), &scene, &camera, info, &[], one_frame)
        .unwrap_or_else(|e| panic!("{e}"))
        .image;
    let reference = glyphscope::reference::rasterize(&scene, &camera).unwrap();
    let stats = metrics::compare(&image, &reference).unwrap();
    let n = stats.pixels_over_025;
    assert!(
        n >= 3,
        "the view needs artifacts to step through: {stats:?}"
    );

    harness.key_press(egui::Key::W);
    let start = Instant::now();
    settle(&mut harness);
    let took = start.elapsed();
    let window = harness.state().magnified_window().expect("laid out");
    assert_eq!(window.factor, 16);
    assert_eq!(window.focus, stats.worst_pixel);
    let rect = harness.state().pane_rects()[0];
    let expected = glyphscope::magnify::Window::around(
        rect.width() as u32,
        rect.height() as u32,
        16,
        stats.worst_pixel,
    );
    // The pane's height is taken now: the status line may have wrapped.
    assert_eq!((window.x0, window.y0), (expected.x0, expected.y0));
    let error_at =
        |(x, y): (u32, u32)| (f64::from(image.get(x, y)) - f64::from(reference.get(x, y))).abs();
    let mut visited = Vec::new();
    let mut previous = f64::INFINITY;
    for k in 1..=n {
        if k > 1 {
            harness.key_press(egui::Key::Period);
            harness.step();
        }
        let (shown_k, shown_n, pixel, shown_error) = artifact_status(&harness);
        assert_eq!((shown_k, shown_n), (k, n));
        let error = error_at(pixel);
        assert!(
            (shown_error - error).abs() <= 5e-4 + 1e-6,
            "{pixel:?}: the status says {shown_error}, the pixel is off by {error}"
        );
        assert!(
            error > 0.25 && error <= previous,
            "{pixel:?} off by {error} after {previous}"
        );
        assert!(!visited.contains(&pixel), "{pixel:?} visited twice");
        assert_eq!(
            harness.state().magnified_window().map(|w| w.focus),
            Some(pixel)
        );
        visited.push(pixel);
        previous = error;
    }
    assert_eq!(visited[0], stats.worst_pixel);
    harness.key_press(egui::Key::Period);
    harness.step();
    assert_eq!(
        artifact_status(&harness).0,
        1,
        "past the last comes the worst again"
    );
    harness.key_press(egui::Key::Comma);
    harness.step();
    assert_eq!(artifact_status(&harness).2, visited[n - 1]);
    eprintln!("worst pixel: {n} pixels over 0.25, found and settled in {took:?}");
}

/// Side by side, winding beside `bounds` (boxes, far from the glyphs' shapes, so a pane
/// showing the wrong one cannot pass), at rest: the screen and both panes' read-backs.
fn winding_beside_bounds() -> (
    Harness<'static, Explorer>,
    image::RgbaImage,
    std::sync::Arc<CoverageImage>,
    std::sync::Arc<CoverageImage>,
) {
    let mut settings = Settings {
        layout: Layout::SideBySide,
        ..Settings::default()
    };
    settings.panes[0] = PaneSettings::method("winding");
    settings.panes[1] = PaneSettings::method("bounds");
    let mut harness = harness(settings);
    let screen = settle(&mut harness);
    let own = harness.state().pane_capture(0).expect("read back at rest");
    let other = harness.state().pane_capture(1).expect("read back at rest");
    (harness, screen, own, other)
}

/// B flips pane A in place to pane B's method (drawn from pane B's own read-back), B
/// again restores it; with one pane shown it flips to the reference.
#[test]
fn blink_alternates_pane_a_with_the_other_rendering() {
    let (mut harness, screen, own, other) = winding_beside_bounds();
    assert!(screen_vs_coverage(&harness, &screen, 0, &own) <= 1.5);
    // The two differ on screen by far more than the tolerance.
    assert!(screen_vs_coverage(&harness, &screen, 0, &other) > 50.0);
    for (press, expected, what) in [(1, &other, "pane B's bounds"), (2, &own, "its own winding")] {
        harness.key_press(egui::Key::B);
        let screen = settle(&mut harness);
        let worst = screen_vs_coverage(&harness, &screen, 0, expected);
        assert!(
            worst <= 1.5,
            "press {press}: pane A should show {what}, off by {worst}"
        );
    }
    harness.key_press(egui::Key::Num1);
    harness.step();
    harness.state_mut().settings.panes[0] = PaneSettings::method("bounds");
    let screen = settle(&mut harness);
    let own = harness.state().pane_capture(0).expect("read back at rest");
    assert!(screen_vs_coverage(&harness, &screen, 0, &own) <= 1.5);
    harness.key_press(egui::Key::B);
    let screen = settle(&mut harness);
    let reference = harness.state().reference_image().expect("settled");
    let worst = screen_vs_coverage(&harness, &screen, 0, &reference);
    assert!(
        worst <= 1.5,
        "one pane: A should show the reference, off by {worst}"
    );
    assert!(screen_vs_coverage(&harness, &screen, 0, &own) > 50.0);
}

/// The view frames the text by itself when the layout or the text changes: the text's
/// ink lies inside the pane and fills it along one side.
#[test]
fn a_new_layout_or_text_is_framed_in_the_panes() {
    let mut harness = harness(Settings::default());
    settle(&mut harness);
    let framed = |harness: &Harness<'static, Explorer>, what: &str| {
        let app = harness.state();
        let camera = app.camera().unwrap();
        let ink = camera.ink_bounds(app.scene().unwrap()).unwrap();
        let (w, h) = (f64::from(camera.width), f64::from(camera.height));
        assert!(
            ink.min.x >= 0.0 && ink.min.y >= 0.0 && ink.max.x <= w && ink.max.y <= h,
            "{what}: ink {ink:?} outside the {w}×{h} pane"
        );
        let fill = (ink.size().x / w).max(ink.size().y / h);
        assert!(fill > 0.8, "{what}: the ink fills {fill:.2} of the pane");
    };
    harness.key_press(egui::Key::Num1);
    settle(&mut harness);
    assert_eq!(harness.state().settings.layout, Layout::Single);
    framed(&harness, "one pane");
    harness.state_mut().settings.scene.text = "Hi".into();
    settle(&mut harness);
    framed(&harness, "new text");
    harness.key_press(egui::Key::Num4);
    settle(&mut harness);
    framed(&harness, "2×2");
}

/// The display mode and stem darkening change the picture, never the error figures:
/// those stay linear coverage against the reference. One harness throughout, so the
/// panes keep their size.
#[test]
fn display_modes_change_the_picture_but_not_the_error_figures() {
    use glyphscope::app::display::{Darkening, DisplayMode};
    let mut harness = harness(Settings {
        // Small enough that both darkenings act (FreeType's: 0.15 px an edge at 12 ppem).
        camera: glyphscope::app::settings::CameraSettings {
            size_px_per_em: 12.0,
            ..Default::default()
        },
        ..Settings::default()
    });
    let linear_screen = settle(&mut harness);
    let linear_error = harness.state().pane_error(0).expect("measured at rest");
    for (display, darkening) in [
        (DisplayMode::Srgb, Darkening::Off),
        (DisplayMode::Gamma, Darkening::Off),
        (DisplayMode::Linear, Darkening::FreeType),
        (DisplayMode::Linear, Darkening::HarfBuzzGpu),
    ] {
        let settings = &mut harness.state_mut().settings;
        settings.display = display;
        settings.darkening = darkening;
        let screen = settle(&mut harness);
        let error = harness.state().pane_error(0).expect("measured at rest");
        assert_eq!(error, linear_error, "{display:?}, {darkening:?}");
        let changed = linear_screen
            .pixels()
            .zip(screen.pixels())
            .filter(|(a, b)| a != b)
            .count();
        assert!(
            changed > 1000,
            "{display:?}, {darkening:?}: {changed} pixels changed"
        );
    }
}

/// Every text egui painted in the last frame, and where (its top-left corner, points).
fn painted_texts(harness: &Harness<'static, Explorer>) -> Vec<(egui::Pos2, String)> {
    fn collect(shape: &egui::Shape, out: &mut Vec<(egui::Pos2, String)>) {
        match shape {
            egui::Shape::Text(text) => out.push((text.pos, text.galley.text().to_owned())),
            egui::Shape::Vec(shapes) => shapes.iter().for_each(|s| collect(s, out)),
            _ => {}
        }
    }
    let mut out = Vec::new();
    for clipped in &harness.output().shapes {
        collect(&clipped.shape, &mut out);
    }
    out
}

/// The orange frames of the mark (`app::MARK_COLOR`) painted in the last frame, each
/// with the pane it lies in and its inner edge (points); the mark is drawn outside
/// that edge.
fn painted_marks(harness: &Harness<'static, Explorer>) -> Vec<(Option<usize>, egui::Rect)> {
    fn collect(shape: &egui::Shape, out: &mut Vec<egui::Rect>) {
        match shape {
            egui::Shape::Rect(r) if r.stroke.color == glyphscope::app::MARK_COLOR => {
                assert_eq!(r.stroke_kind, egui::StrokeKind::Outside, "{r:?}");
                out.push(r.rect);
            }
            egui::Shape::Vec(shapes) => shapes.iter().for_each(|s| collect(s, out)),
            _ => {}
        }
    }
    let mut rects = Vec::new();
    for clipped in &harness.output().shapes {
        collect(&clipped.shape, &mut rects);
    }
    let panes = harness.state().pane_rects();
    rects
        .into_iter()
        .map(|r| (panes.iter().position(|p| p.contains(r.center())), r))
        .collect()
}

/// Every visible pane has the mark around exactly ×1 pixel `pixel`'s N×N block (one
/// screen pixel out, so none of the block is covered), and nothing else is marked.
fn assert_marked(harness: &Harness<'static, Explorer>, pixel: (u32, u32), what: &str) {
    let app = harness.state();
    let window = app.magnified_window().expect("laid out");
    let ppp = harness.ctx.pixels_per_point();
    let step = window.factor as f32 / ppp;
    let marks = painted_marks(harness);
    assert_eq!(
        marks.len(),
        app.pane_rects().len(),
        "{what}: one mark a pane, not {marks:?}"
    );
    for (pane, rect) in app.pane_rects().iter().enumerate() {
        let block = egui::Rect::from_min_size(
            rect.min
                + egui::vec2(
                    pixel.0 as f32 - window.x0 as f32,
                    pixel.1 as f32 - window.y0 as f32,
                ) * step,
            egui::vec2(step, step),
        );
        let inner = block.expand(1.0 / ppp);
        let found: Vec<egui::Rect> = marks
            .iter()
            .filter(|(p, _)| *p == Some(pane))
            .map(|(_, r)| *r)
            .collect();
        assert!(
            found.len() == 1
                && (found[0].min - inner.min).length() < 1e-3
                && (found[0].max - inner.max).length() < 1e-3,
            "{what}: pane {pane} should mark pixel {pixel:?} (block {block:?}), marks {found:?}"
        );
    }
}

/// How far a pane's pixel may be from `render`'s for the same view: one step of the
/// 8-bit PNG `render` writes. The two draw the same pixels through cameras whose
/// translations differ by whole pixels, so only f32 rounding separates them; a wrong
/// offset, crop or tilt moves edge pixels by 0.1 or more.
const SAME_PIXELS: f32 = 1.0 / 255.0;

/// The largest difference between a pane's read-back `shown` (the pixels of `window`)
/// and the frame `image` whose pixel (`offset` + pane pixel) each is, and how many pixels
/// the two share; NaN fails.
fn pane_vs_frame(
    shown: &CoverageImage,
    window: glyphscope::magnify::Window,
    offset: (i64, i64),
    image: &CoverageImage,
) -> (usize, f32) {
    let mut compared = 0;
    let mut worst = 0.0f32;
    for j in 0..shown.height {
        for i in 0..shown.width {
            let x = i64::from(window.x0 + i) + offset.0;
            let y = i64::from(window.y0 + j) + offset.1;
            if x < 0 || y < 0 || x >= i64::from(image.width) || y >= i64::from(image.height) {
                continue;
            }
            let d = (shown.get(i, j) - image.get(x as u32, y as u32)).abs();
            assert!(!d.is_nan(), "NaN at ({x}, {y})");
            worst = worst.max(d);
            compared += 1;
        }
    }
    (compared, worst)
}

/// The Cases menu loads a named view so that each pane pixel is the pixel `glyphscope
/// render --case NAME` draws there (skew, a 1e6 px world offset, rotation with tilt), and
/// magnifies pane A on its worst pixel (×32, values written, outline on): the pixel
/// whose error is the largest `render` reports, also where the frame is larger than the
/// pane (`rotated`).
#[test]
fn a_case_from_the_menu_reproduces_render_and_opens_on_its_worst_pixel() {
    // sdf-cells: a method with real errors on these views, so the worst pixel is one;
    // pane B its error overlay, which writes each pixel's error under its coverage.
    let mut settings = Settings::default();
    settings.panes[0] = PaneSettings::method("sdf-cells");
    settings.panes[1] = PaneSettings {
        overlay: PaneOverlay::Error,
        ..PaneSettings::method("sdf-cells")
    };
    let mut harness = harness(settings);
    settle(&mut harness);
    for name in ["strong-skew", "world-offset-1e6", "rotated"] {
        // The menu opens on the next frame; the item is scrolled to as a user would.
        harness.get_by_label("Cases").click();
        harness.step();
        harness.step();
        harness.get_by_label(name).scroll_to_me();
        for _ in 0..10 {
            harness.step();
        }
        harness.get_by_label(name).click();
        // Settled: placed, magnified on the worst pixel, its numbers in.
        settle(&mut harness);
        let app = harness.state();
        assert_eq!(app.settings.scene.case.as_deref(), Some(name));
        let window = app.magnified_window().expect("laid out");
        assert_eq!(
            window.factor, 32,
            "{name}: magnified enough to write the values"
        );
        assert!(
            app.settings.panes[..2].iter().all(|p| p.outline),
            "{name}: outline on"
        );
        let offset = app
            .settings
            .camera
            .case_frame
            .expect("a case's frame")
            .offset;
        let (ox, oy) = (offset[0] as i64, offset[1] as i64);
        let shown = app.pane_capture(0).expect("read back at rest");

        let rendered = glyphscope::render::render(&glyphscope::render::RenderOptions {
            case: Some(name.into()),
            method: "sdf-cells".into(),
            error_image: Some(PathBuf::from("unused")),
            ..glyphscope::render::RenderOptions::of(glyphscope::view_args::ViewArgs::text("-", 1.0))
        })
        .unwrap_or_else(|e| panic!("{name}: {e}"));
        let (image, reference) = (&rendered.image, rendered.reference.as_ref().unwrap());
        let (compared, worst) = pane_vs_frame(&shown, window, (ox, oy), image);
        assert!(compared > 100, "{name}: only {compared} pixels in common");
        assert!(
            worst <= SAME_PIXELS,
            "{name}: the pane is off from render's image by {worst} (over {compared} pixels)"
        );
        let (pane_w, pane_h) = app.pane_pixels().expect("laid out");
        let sees_whole_frame = ox <= 0
            && oy <= 0
            && i64::from(image.width) - ox <= i64::from(pane_w)
            && i64::from(image.height) - oy <= i64::from(pane_h);
        let stats = rendered.stats.error.expect("compared with the reference");
        let (fx, fy) = window.focus;
        let (x, y) = (i64::from(fx) + ox, i64::from(fy) + oy);
        assert!(
            (0..i64::from(image.width)).contains(&x) && (0..i64::from(image.height)).contains(&y),
            "{name}: the focus ({x}, {y}) is outside render's frame"
        );
        let (x, y) = (x as u32, y as u32);
        let at_focus = (image.get(x, y) - reference.get(x, y)).abs();
        eprintln!(
            "{name}: {compared} pixels within {worst:e} of render's; focus error {at_focus:.4}, \
             render's max {:.4}",
            stats.max
        );
        // The frame's worst, whether the pane holds the whole frame or not.
        assert!(
            (f64::from(at_focus) - stats.max).abs() <= 1e-3,
            "{name}: the magnifier is on a pixel off by {at_focus}, render's worst is {}",
            stats.max
        );
        // The focus pixel's error, as render's numbers give it, is written in its block in
        // pane B (within the 5e-4 the two renderings may differ by, which may round either
        // way).
        let step = window.factor as f32 / harness.ctx.pixels_per_point();
        let block = egui::Rect::from_min_size(
            app.pane_rects()[1].min
                + egui::vec2((fx - window.x0) as f32, (fy - window.y0) as f32) * step,
            egui::vec2(step, step),
        );
        let written: Vec<String> = painted_texts(&harness)
            .into_iter()
            .filter(|(at, _)| block.contains(*at))
            .map(|(_, text)| text)
            .collect();
        let error = image.get(x, y) - reference.get(x, y);
        let labels: Vec<String> = [-5e-4, 0.0, 5e-4]
            .iter()
            .map(|d| glyphscope::magnify::block_labels(0.0, Some(-(error + d)))[1].clone())
            .collect();
        assert!(
            labels.iter().any(|l| written.contains(l)),
            "{name}: none of {labels:?} is written in the focus block, which has {written:?}"
        );
        // The whole pane at ×1, too.
        harness.state_mut().settings.camera.magnify = 1;
        settle(&mut harness);
        let app = harness.state();
        let window = app.magnified_window().expect("laid out");
        let shown = app.pane_capture(0).expect("read back at rest");
        let (compared, worst) = pane_vs_frame(&shown, window, (ox, oy), image);
        eprintln!("{name} at ×1: {compared} pixels within {worst:e} of render's");
        let frame_pixels = (image.width * image.height) as usize;
        let enough = if sees_whole_frame {
            frame_pixels
        } else {
            100_000
        };
        assert!(
            compared >= enough && worst <= SAME_PIXELS,
            "{name} at ×1: {compared} pixels in common, off by {worst}"
        );
    }
}

/// A first start opens side by side, a method beside the reference, on the text at
/// 12 px/em magnified ×8 on pane A's worst pixel — an artifact, not empty space.
#[test]
fn a_first_start_opens_magnified_on_an_artifact() {
    let mut harness = harness(Settings::default());
    harness.state_mut().open_as_on_a_first_start();
    settle(&mut harness);
    let app = harness.state();
    assert_eq!(app.settings.layout, Layout::SideBySide);
    assert!(matches!(&app.settings.panes[1].source,
        PaneSource::Method { name, .. } if name == REFERENCE.name));
    assert_eq!(app.settings.camera.size_px_per_em, 12.0);
    let window = app.magnified_window().expect("laid out");
    assert_eq!(window.factor, 8);
    let (k, n, pixel, error) = artifact_status(&harness);
    assert_eq!((k, pixel), (1, window.focus));
    assert!(
        n > 0 && error > 0.25,
        "{n} pixels over 0.25, the worst off by {error}"
    );
    // The pane shows ink there: the text's edge, not background.
    let shown = app.pane_capture(0).expect("read back at rest");
    let inked = shown.data.iter().filter(|&&c| c > 0.0 && c < 1.0).count();
    assert!(inked > 20, "{inked} edge pixels in the magnified window");
    // The pixel the status bar names is framed in both panes.
    assert_marked(&harness, pixel, "first start");
}

/// The pixel a link's focus names is framed in every pane, exactly around its block; the
/// frame stays while only an overlay changes and goes once the camera moves; W then
/// frames the worst pixel it goes to.
#[test]
fn the_pixel_a_link_or_the_worst_pixel_opens_on_is_marked_until_the_view_moves() {
    let mut harness = harness(Settings::default());
    harness.state_mut().open_link(
        "#size=24&origin=10,60&rotate=0&layout=2&a=sdf-cells&b=reference&magnify=16&focus=30.5,12.5",
    );
    settle(&mut harness);
    assert_eq!(harness.state().status_text(), "");
    assert_eq!(
        harness
            .state()
            .magnified_window()
            .map(|w| (w.factor, w.focus)),
        Some((16, (30, 12)))
    );
    assert_eq!(harness.state().marked_pixel(), Some((30, 12)));
    assert_marked(&harness, (30, 12), "the link's focus");
    // An overlay changes what a pane shows, not which pixel it is.
    harness.key_press(egui::Key::E);
    settle(&mut harness);
    assert_eq!(
        harness.state().settings.panes[0].overlay,
        PaneOverlay::Error
    );
    assert_marked(&harness, (30, 12), "with the error overlay");
    harness.key_press(egui::Key::ArrowLeft);
    settle(&mut harness);
    assert_eq!(painted_marks(&harness), vec![], "panned: the mark is gone");
    assert_eq!(harness.state().marked_pixel(), None);
    harness.key_press(egui::Key::W);
    settle(&mut harness);
    let (_, _, pixel, _) = artifact_status(&harness);
    assert_eq!(harness.state().magnified_window().unwrap().focus, pixel);
    assert_marked(&harness, pixel, "the worst pixel");
    harness.key_press(egui::Key::Plus);
    settle(&mut harness);
    assert_eq!(painted_marks(&harness), vec![], "zoomed: the mark is gone");
}

/// Shift+B blinks pane A on its own, a few times a second (the harness's clock moves
/// 0.25 s a frame): over 3 s both renderings come up, each more than once; Shift+B
/// again stops it, on A's own method.
#[test]
fn shift_b_blinks_pane_a_on_its_own_and_stops() {
    let (mut harness, _, own, other) = winding_beside_bounds();
    let shows = |harness: &mut Harness<'static, Explorer>| {
        harness.step();
        let screen = harness.render().expect("the harness draws with wgpu");
        let to_own = screen_vs_coverage(harness, &screen, 0, &own);
        let to_other = screen_vs_coverage(harness, &screen, 0, &other);
        match (to_own <= 1.5, to_other <= 1.5) {
            (true, false) => "own",
            (false, true) => "other",
            _ => panic!("pane A shows neither rendering ({to_own}, {to_other} off)"),
        }
    };
    harness.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::B);
    let seen: Vec<&str> = (0..12).map(|_| shows(&mut harness)).collect();
    let flips = seen.windows(2).filter(|w| w[0] != w[1]).count();
    assert!(
        seen.iter().filter(|s| **s == "own").count() >= 2
            && seen.iter().filter(|s| **s == "other").count() >= 2
            && flips >= 4,
        "blinking on its own showed {seen:?}"
    );
    harness.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::B);
    let after: Vec<&str> = (0..6).map(|_| shows(&mut harness)).collect();
    assert!(
        after.iter().all(|s| *s == "own"),
        "stopped, it showed {after:?}"
    );
}

/// A case whose method has no pixel off by more than 0.25 (winding on `strong-skew`)
/// still opens on its worst pixel, framed in both panes, and the status bar says none is
/// over the threshold.
#[test]
fn a_case_with_no_pixel_over_the_threshold_opens_on_its_worst() {
    let mut settings = Settings::default();
    settings.panes[0] = PaneSettings::method("winding");
    let mut harness = harness(settings);
    settle(&mut harness);
    harness.state_mut().load_case("strong-skew");
    settle(&mut harness);
    let text = harness
        .get_by_label_contains("worst pixel (")
        .accesskit_node()
        .value()
        .unwrap_or_default();
    let pixel = text
        .strip_prefix("worst pixel (")
        .and_then(|rest| rest.split_once(')'))
        .and_then(|(xy, rest)| {
            let (x, y) = xy.split_once(", ")?;
            rest.contains("none is off by more than 0.25")
                .then_some((x.parse::<u32>().ok()?, y.parse::<u32>().ok()?))
        })
        .unwrap_or_else(|| panic!("the status bar says {text:?}"));
    let window = harness.state().magnified_window().expect("laid out");
    assert_eq!((window.factor, window.focus), (32, pixel));
    // The case's worst pixel is framed in both panes.
    assert_marked(&harness, pixel, "strong-skew's worst");
}

/// Text in motion: each step moves the shared camera by the path's step in every pane
/// (each pane's read-back is its method drawn offscreen at that frame's camera), a step
/// back shows frame 0's pixels again, and playing charts one point per frame in every
/// pane, with the temporal error of each frame after the first.
#[test]
fn motion_steps_plays_and_charts_one_point_per_frame() {
    let mut settings = Settings {
        layout: Layout::SideBySide,
        motion_path: "drift:0.25,0.125".into(),
        ..Settings::default()
    };
    settings.scene.text = "Wave".into();
    settings.panes[0] = PaneSettings::method("atlas");
    settings.panes[1] = PaneSettings::method("winding");
    let mut harness = harness(settings);
    settle(&mut harness);
    let base = harness.state().camera().unwrap();
    let first: Vec<_> = (0..2)
        .map(|i| harness.state().pane_capture(i).expect("read back at rest"))
        .collect();
    let offscreen = |harness: &Harness<'static, Explorer>, pane: usize| {
        let app = harness.state();
        let name = if pane == 0 { "atlas" } else { "winding" };
        let mut method = registry::create(name, &[]).unwrap();
        method.prepare(gpu(), app.scene().unwrap()).unwrap();
        let camera = app.camera().unwrap();
        methods::frame::render_image(gpu(), method.as_mut(), &camera).unwrap()
    };
    harness.key_press(egui::Key::L);
    settle(&mut harness);
    let app = harness.state();
    assert_eq!(app.motion_frame(), 1);
    let moved = app.camera().unwrap();
    let step = moved.origin - base.origin - glam::DVec2::new(0.25, 0.125);
    assert!(step.length() < 1e-9, "frame 1 is off the path by {step}");
    for (pane, first) in first.iter().enumerate() {
        let shown = harness.state().pane_capture(pane).unwrap();
        assert_ne!(*shown, **first, "pane {pane} did not move");
        assert_eq!(*shown, offscreen(&harness, pane), "pane {pane} at frame 1");
    }
    harness.key_press(egui::Key::J);
    settle(&mut harness);
    assert_eq!(harness.state().camera().unwrap(), base);
    for (pane, first) in first.iter().enumerate() {
        assert_eq!(
            harness.state().pane_capture(pane).unwrap(),
            *first,
            "pane {pane} back at frame 0"
        );
    }
    harness.key_press(egui::Key::Space);
    let start = Instant::now();
    while harness.state().motion_frame() < 4 {
        harness.step();
        harness.render().expect("the harness draws with wgpu");
        assert!(
            start.elapsed() < Duration::from_secs(120),
            "playing stalled at frame {}",
            harness.state().motion_frame()
        );
    }
    harness.key_press(egui::Key::Space);
    settle(&mut harness);
    let app = harness.state();
    assert!(!app.is_playing());
    let last = app.motion_frame();
    let expected = base.origin + last as f64 * glam::DVec2::new(0.25, 0.125);
    assert!((app.camera().unwrap().origin - expected).length() < 1e-9);
    for pane in 0..2 {
        let history = app.motion_history(pane);
        let frames: Vec<i64> = history.iter().map(|(n, _)| *n).collect();
        assert_eq!(
            frames,
            (0..=last).collect::<Vec<_>>(),
            "pane {pane}: one point per frame"
        );
        for (n, point) in &history {
            assert!(point.mae_255.is_finite(), "pane {pane} frame {n}");
            assert_eq!(
                point.temporal.is_some(),
                *n > 0,
                "pane {pane} frame {n}: temporal"
            );
        }
    }
    // The atlas snaps to its phases; winding follows the reference.
    let temporal = |pane: usize| -> f64 {
        app.motion_history(pane)
            .iter()
            .filter_map(|(_, p)| p.temporal.map(|t| t.mae_255))
            .sum()
    };
    assert!(
        temporal(0) > 10.0 * temporal(1),
        "atlas {} vs winding {}",
        temporal(0),
        temporal(1)
    );
    let (_, samples) = app
        .motion_pixel_history()
        .expect("the focus pixel is followed");
    assert_eq!(samples.len() as i64, last + 1);
    // Playing opened the Motion window.
    harness.step();
    // Each pane's chart is titled with it (the pixel chart's legend names it too).
    assert!(harness.query_all_by_label("A atlas").count() >= 2);
    assert!(harness.query_all_by_label("B winding").count() >= 2);
}

/// A link whose font is a file's path opens that font on the desktop, as `--view` does,
/// and its `glyph=#ID` the glyph of that id: the scene is that glyph of the file, and
/// the pane draws what the method draws of it apart from the app, pixel for pixel.
#[test]
fn a_link_opens_a_font_by_its_path_and_a_glyph_by_id() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("fonts/DejaVuSans.ttf");
    let encoded = path.to_str().unwrap().replace('/', "%2F");
    let link = format!(
        "#font={encoded}&glyph=%2336&size=48&rotate=0&origin=10,60&magnify=16&focus=20,40\
         &a=winding&b=reference"
    );
    let mut harness = harness(Settings::default());
    harness.state_mut().open_link(&link);
    settle(&mut harness);
    let app = harness.state();
    assert_eq!(app.status_text(), "", "{link}");
    assert_eq!(
        app.settings.scene.font,
        glyphscope::app::settings::FontChoice::File(path.clone())
    );
    assert_eq!(app.settings.camera.size_px_per_em, 48.0);
    let font = glyphscope::font::Font::from_path(&path).unwrap();
    let expected = glyphscope::scene::Scene::from_glyph_id(&font, 36).unwrap();
    let scene = app.scene().expect("the scene builds");
    let ids: Vec<_> = scene.glyphs.iter().map(|g| g.id).collect();
    assert_eq!(ids, [expected.glyphs[0].id], "glyph 36 alone");
    assert_eq!(u32::from(expected.glyphs[0].id), 36);
    assert_eq!(app.pane_problem(0), None);
    let shown = app.pane_capture(0).expect("read back at rest");
    let camera = app.camera().unwrap();
    let mut method = registry::create("winding", &[]).unwrap();
    method.prepare(gpu(), &expected).unwrap();
    let drawn = methods::frame::render_image(gpu(), method.as_mut(), &camera).unwrap();
    assert!(drawn.sum() > 20.0, "the glyph is in the window");
    assert_eq!(*shown, drawn, "pane A of {link}");
    // Its link back carries the path too.
    assert!(
        app.link()
            .unwrap()
            .starts_with(&format!("#font={encoded}&")),
        "{:?}",
        app.link()
    );
}

/// A link is a view: the link copied from an explorer that loaded a case, magnified on
/// its worst pixel, opens in a fresh explorer on the same camera, the same panes and
/// exactly the same pixels, and a font opened over it leaves the case; a malformed link
/// opens the default view and says in the status bar what is wrong.
#[test]
fn a_copied_link_opens_the_same_view_and_a_malformed_one_says_why() {
    let mut first = harness(Settings::default());
    settle(&mut first);
    first.state_mut().load_case("strong-skew");
    settle(&mut first);
    let link = first.state().link().expect("a case travels in a link");
    let (camera, window) = (first.state().camera(), first.state().magnified_window());
    // Pane A draws sdf-cells, pane B the reference.
    let pixels = first.state().pane_capture(0).unwrap();
    let reference = first.state().reference_image().unwrap();
    drop(first);

    let mut second = harness(Settings::default());
    second.state_mut().open_link(&link);
    settle(&mut second);
    let app = second.state();
    assert_eq!(app.settings.scene.case.as_deref(), Some("strong-skew"));
    assert_eq!(app.camera(), camera, "{link}");
    assert_eq!(app.magnified_window(), window);
    assert_eq!(app.pane_capture(0).unwrap(), pixels, "pane A of {link}");
    assert_eq!(
        app.reference_image().unwrap(),
        reference,
        "pane B of {link}"
    );
    assert_eq!(
        app.link().unwrap(),
        link,
        "the link of the opened view is the one opened"
    );
    // A font opened over the case a link opened leaves the case, as over one loaded
    // from the Cases menu.
    let font = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("fonts/lmroman10-regular.otf");
    second.state_mut().open_font(font);
    settle(&mut second);
    assert_eq!(second.state().settings.scene.case, None);
    drop(second);

    let mut bad = harness(Settings::default());
    bad.state_mut().open_link("#case=inter-overlaps&size=-4");
    settle(&mut bad);
    assert_eq!(bad.state().settings, Settings::default());
    let said = bad
        .get_by_label_contains("link: size=-4")
        .accesskit_node()
        .value()
        .unwrap_or_default();
    assert!(said.contains("is not positive"), "{said}");
}

/// A survey's link opens its glyph as the survey measured it: `glyphscope survey` run
/// on a few glyphs of a font given by path, the first link of winding's worst-glyph
/// table opened as `--view` opens it, shows that glyph alone, the pane's error against
/// the reference is the row's (its largest and where), and that pixel is marked.
#[test]
fn a_survey_link_opens_the_glyph_it_names_on_its_worst_pixel() {
    let out = common::binary::scratch("survey-link");
    let font = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("fonts/lmroman10-regular.otf");
    let copy = common::binary::scratch("survey-font.otf");
    std::fs::copy(&font, &copy).unwrap();
    let output = common::binary::run(&[
        "survey",
        "--fonts",
        copy.to_str().unwrap(),
        "--sizes",
        "24",
        "--transforms",
        "rotate:30",
        "--methods",
        "winding:aa=rays",
        "--glyphs",
        "40-60",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        output.status.code().is_some_and(|c| c <= 1),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let md = std::fs::read_to_string(out.join("survey.md")).unwrap();
    let first = md
        .lines()
        .find(|l| l.starts_with("| 1 | "))
        .expect("a worst glyph");
    let cells: Vec<&str> = first.split(" | ").collect();
    let id: u16 = cells[2]
        .trim_start_matches('#')
        .split(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    let max: f64 = cells[5].parse().unwrap();
    let link = first
        .split("--view '")
        .nth(1)
        .unwrap()
        .split('\'')
        .next()
        .unwrap();
    // The row's worst pixel, from the CSV (survey.md rounds).
    let csv = std::fs::read_to_string(out.join("survey.csv")).unwrap();
    let row: Vec<&str> = csv
        .lines()
        .find(|l| l.contains(&format!(",{id},")) && l.contains(",rotate:30,"))
        .unwrap()
        .split(',')
        .collect();
    let (row_max, worst): (f64, (u32, u32)) = (
        row[9].parse().unwrap(),
        (row[15].parse().unwrap(), row[16].parse().unwrap()),
    );
    assert!((row_max - max).abs() < 6e-4, "{row_max} vs {max}");

    let mut harness = harness(Settings::default());
    harness.state_mut().open_link(link);
    settle(&mut harness);
    let app = harness.state();
    assert_eq!(app.status_text(), "", "{link}");
    let scene = app.scene().expect("the scene builds");
    let ids: Vec<_> = scene.glyphs.iter().map(|g| g.id).collect();
    assert_eq!(ids, [id], "{link}");
    // The glyph sits at another place in the survey's frame than in the pane, so f32
    // positions may round differently: the same error to 1/255, at the same pixel.
    let stats = app.pane_error(0).expect("pane A's error at rest");
    assert!(
        (stats.max - row_max).abs() < 4e-3,
        "{} vs the row's {row_max}",
        stats.max
    );
    let margin = 8;
    let pixel = (worst.0 + margin, worst.1 + margin);
    // The magnified pane draws a window of the view: its pixels from the window's corner.
    let camera = app.camera().unwrap();
    let corner = camera
        .crop
        .map_or((0, 0), |c| (c.offset.x as u32, c.offset.y as u32));
    let at = (pixel.0 - corner.0, pixel.1 - corner.1);
    assert_eq!(stats.worst_pixel, at, "{link}");
    let (shown, reference) = (app.pane_capture(0).unwrap(), app.reference_image().unwrap());
    let error = f64::from((shown.get(at.0, at.1) - reference.get(at.0, at.1)).abs());
    assert!(
        (error - row_max).abs() < 4e-3,
        "{error} vs the row's {row_max}"
    );
    assert_eq!(app.marked_pixel(), Some(pixel), "{link}");
}

/// A pane drawing your own WGSL file (`wgsl:PATH`, docs/your-method.md) reloads it when
/// it is saved, on the same pixels, and keeps drawing the last version that compiled
/// beside the error of a save that does not.
#[test]
fn a_users_shader_reloads_when_saved_and_a_broken_or_hanging_save_keeps_the_last_good_one() {
    let dir = std::env::temp_dir().join(format!("glyphscope-app-user-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("mine.wgsl");
    let coverage_of = |value: &str| {
        format!(
            "fn user_coverage(g: Glyph, p: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> f32 {{\n    return {value};\n}}\n"
        )
    };
    std::fs::write(&file, coverage_of("0.0")).unwrap();
    let mut settings = Settings {
        layout: Layout::Single,
        ..Settings::default()
    };
    settings.panes[0] = PaneSettings::method(&format!("wgsl:{}", file.display()));
    let mut harness = harness(settings);
    settle(&mut harness);
    let sum = |harness: &Harness<'static, Explorer>| {
        harness
            .state()
            .pane_capture(0)
            .expect("read back at rest")
            .sum()
    };
    assert_eq!(harness.state().pane_problem(0), None);
    assert_eq!(sum(&harness), 0.0, "a function that covers nothing");
    // Saved: every pixel of every glyph's quad covered, without touching the app.
    std::fs::write(&file, coverage_of("1.0")).unwrap();
    settle(&mut harness);
    assert_eq!(harness.state().pane_problem(0), None);
    let covered = sum(&harness);
    assert!(covered > 100.0, "the saved version draws: {covered}");
    // A save that does not compile: its error, the place in the file, and the last
    // good version still drawn.
    std::fs::write(&file, coverage_of("1.0 +")).unwrap();
    settle(&mut harness);
    let problem = harness.state().pane_problem(0).expect("the error is shown");
    assert!(problem.contains("mine.wgsl:"), "{problem}");
    assert!(problem.contains("last version that compiled"), "{problem}");
    assert_eq!(sum(&harness), covered, "the last good version still drawn");
    // A save that compiles but never returns: drawn first by the binary in a process
    // of its own, which ends itself past its frame limit; the explorer shows why and
    // keeps drawing the last good version, its own device never asked to run it.
    glyphscope::app::try_user_files_with(env!("CARGO_BIN_EXE_glyphscope").into());
    std::fs::write(
        &file,
        "fn user_coverage(g: Glyph, p: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> f32 {\n    var i = 0u;\n    loop {\n        if band_at(g.first_band + (i & 1u)).count == 0xdeadbeefu {\n            break;\n        }\n        i++;\n    }\n    return f32(i);\n}\n",
    )
    .unwrap();
    settle(&mut harness);
    let problem = harness.state().pane_problem(0).expect("the hang is shown");
    assert!(problem.contains("has not finished a frame"), "{problem}");
    assert!(problem.contains("last version that passed"), "{problem}");
    assert_eq!(sum(&harness), covered, "the last good version still drawn");
    // Fixed and saved: tried, passed, drawn.
    std::fs::write(&file, coverage_of("0.0")).unwrap();
    settle(&mut harness);
    assert_eq!(harness.state().pane_problem(0), None);
    assert_eq!(sum(&harness), 0.0, "the fixed version draws");
}
