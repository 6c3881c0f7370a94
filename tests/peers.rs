//! The peers (vello, glyphon, vello_cpu) drawn through their public APIs: where they
//! draw, what they refuse, how their time is taken, and vello_cpu as an independent
//! check of the reference.

mod common;

use std::time::Instant;

use glam::DVec2;
use glyphscope::Error;
use glyphscope::camera::Camera;
use glyphscope::gpu::{Channels, CoverageTarget};
use glyphscope::measure::{self, FrameTiming};
use glyphscope::methods::{frame, peers, registry};
use glyphscope::metrics;
use glyphscope::reference;
use glyphscope::scene::Scene;
use glyphscope::view_args::ViewArgs;

const ONE_FRAME: FrameTiming = FrameTiming {
    warmup: 0,
    frames: 1,
};

/// vello_cpu flattens curves to lines within 0.25 px (its `flatten.rs`: `TOL`) and
/// writes 8-bit premultiplied pixels. A chord within 0.25 px of its curve changes a
/// pixel's coverage by at most the area between them inside the pixel: at most 0.25
/// px across a length of at most √2 px (the pixel's diagonal); the 8-bit store adds at
/// most one step. So on glyphs without overlapping contours (where area coverage is
/// exact) no pixel of vello_cpu's may differ from an exact reference by more than
/// 0.25·√2 + 1/255 — a bound set from vello_cpu's documented precision alone, which
/// checks the reference against a rasterizer written by other people. (A pixel crossed
/// by several flattened edges could exceed it without either side being wrong; the
/// views here are of glyphs at sizes where that does not happen, and a failure would
/// name the pixel to look at.)
const VELLO_CPU_BOUND: f64 = 0.25 * std::f64::consts::SQRT_2 + 1.0 / 255.0;

fn views() -> Vec<(&'static str, ViewArgs)> {
    let text = |t: &str, size| ViewArgs::text(t, size);
    vec![
        ("DejaVu at 8 px/em", text("Hamburgefonstiv", 8.0)),
        ("DejaVu at 16 px/em", text("Hamburgefonstiv ag", 16.0)),
        ("DejaVu at 40 px/em", text("ag&Qx", 40.0)),
        (
            "DejaVu turned 30°",
            ViewArgs {
                matrix: Some([0.866, -0.5, 0.5, 0.866]),
                ..text("Rotated", 40.0)
            },
        ),
        (
            "Latin Modern cubics at 24 px/em",
            ViewArgs {
                font: Some("fonts/lmroman10-regular.otf".into()),
                ..text("Quixotic", 24.0)
            },
        ),
    ]
}

#[test]
fn vello_cpu_agrees_with_the_reference_within_its_flattening_tolerance() {
    let gpu = common::gpu();
    let info = registry::find(peers::vello_cpu::NAME).unwrap();
    for quality in ["speed", "quality"] {
        for (what, view) in views() {
            let (scene, camera) = view.build().unwrap();
            let exact = reference::rasterize(&scene, &camera).unwrap();
            let params = [("mode".to_string(), quality.to_string())];
            let drawn = measure::measure(Some(gpu), &scene, &camera, info, &params, ONE_FRAME)
                .unwrap_or_else(|e| panic!("{what}: {e}"));
            let error = metrics::compare(&drawn.image, &exact).unwrap();
            println!(
                "vello-cpu mode={quality} on {what}: max {:.3}, MAE {:.2}/255, edge MAE {:.2}/255",
                error.max, error.mae_255, error.edge.mae_255
            );
            assert!(
                error.max <= VELLO_CPU_BOUND,
                "{what}, mode={quality}: off by {:.3} at {:?}, past {VELLO_CPU_BOUND:.3}",
                error.max,
                error.worst_pixel
            );
            assert!(error.edge.pixels > 0, "{what}: no edge drawn");
        }
    }
}

/// Each peer draws the text, where the reference has ink; vello (area anti-aliasing,
/// flattening within 0.25 px as vello_cpu does) keeps to vello_cpu's bound too.
#[test]
fn every_peer_draws_text_where_the_reference_does() {
    let gpu = common::gpu();
    let (scene, camera) = ViewArgs::text("Hamburgefonstiv ag", 24.0).build().unwrap();
    let exact = reference::rasterize(&scene, &camera).unwrap();
    for info in registry::METHODS.iter().filter(|m| m.is_peer()) {
        let drawn = measure::measure(Some(gpu), &scene, &camera, info, &[], ONE_FRAME)
            .unwrap_or_else(|e| panic!("{}: {e}", info.name));
        let (ink, exact_ink) = (drawn.image.sum(), exact.sum());
        assert!(
            (ink - exact_ink).abs() < 0.05 * exact_ink,
            "{}: {ink} px of ink, the reference {exact_ink}",
            info.name
        );
        let error = metrics::compare(&drawn.image, &exact).unwrap();
        println!(
            "{}: max {:.3}, MAE {:.2}/255",
            info.name, error.max, error.mae_255
        );
        if info.name != peers::glyphon::NAME {
            assert!(error.max <= VELLO_CPU_BOUND, "{}: {}", info.name, error.max);
        }
    }
}

/// What a peer cannot draw is an `Error::Refused` that names the peer and its limit,
/// in one line: a tilt for every peer but msdf (perspective), a turn for glyphon (an atlas
/// places bitmaps), a scene with no font or no text for glyphon, an axis other than
/// weight for glyphon.
#[test]
fn peers_refuse_what_their_apis_cannot_draw() {
    let gpu = common::gpu();
    let refused = |name: &str, scene: &Scene, camera: &Camera| -> String {
        let mut method = registry::create(name, &[]).unwrap();
        let result = method
            .prepare(gpu, scene)
            .and_then(|()| frame::render_image(gpu, method.as_mut(), camera).map(|_| ()));
        match result {
            Err(Error::Refused(reason)) => {
                assert!(reason.contains(name) && !reason.contains('\n'), "{reason}");
                reason
            }
            other => panic!("{name}: {other:?}"),
        }
    };
    let (text, upright) = ViewArgs::text("Tilted", 24.0).build().unwrap();
    let tilted = Camera {
        tilt_deg: 20.0,
        ..upright
    };
    // msdf draws through the quads every method shares, a tilt too; the others refuse.
    for info in registry::METHODS.iter().filter(|m| m.is_peer()) {
        if info.name == peers::msdf::params::NAME {
            let mut msdf = registry::create(info.name, &[]).unwrap();
            msdf.prepare(gpu, &text).unwrap();
            let image = frame::render_image(gpu, msdf.as_mut(), &tilted).unwrap();
            assert!(image.sum() > 0.0, "msdf draws the tilted text");
            continue;
        }
        assert!(refused(info.name, &text, &tilted).contains("tilt"));
    }
    let turned = Camera {
        matrix: Camera::matrix_from_rows(0.866, -0.5, 0.5, 0.866),
        ..upright
    };
    assert!(refused(peers::glyphon::NAME, &text, &turned).contains("uniform scale"));
    let synthetic = common::single(common::polygons(&[&[
        (0.0, 0.0),
        (100.0, 0.0),
        (0.0, 100.0),
    ]]));
    assert!(refused(peers::glyphon::NAME, &synthetic, &upright).contains("no font"));
    // The shipped variable font has a weight axis only: the rule is checked on the
    // variations themselves.
    let inter = glyphscope::font::SHIPPED_FONTS
        .iter()
        .position(|f| f.1 == "Inter-roman.var.ttf")
        .expect("Inter is shipped");
    let axes = glyphscope::font::shipped(inter).axes();
    let weight = |variations: &[(&str, f32)]| {
        let variations: Vec<(String, f32)> =
            variations.iter().map(|&(t, v)| (t.to_owned(), v)).collect();
        peers::glyphon::weight_for(&variations, &axes)
    };
    let reason = weight(&[("wght", 700.0), ("opsz", 32.0)])
        .unwrap_err()
        .to_string();
    assert!(
        reason.contains("weight only") && reason.contains("'opsz'"),
        "{reason}"
    );
    assert!(
        weight(&[("wght", 650.5)])
            .unwrap_err()
            .to_string()
            .contains("whole")
    );
    assert_eq!(weight(&[("wght", 900.0)]).unwrap().map(|w| w.0), Some(900));
    // No weight set: the axis's own default, the instance the reference draws.
    let default = axes
        .iter()
        .find(|a| a.tag == "wght")
        .map(|a| a.default as u16);
    assert!(default.is_some(), "the shipped Inter has a weight axis");
    assert_eq!(weight(&[]).unwrap().map(|w| w.0), default);
    // The linebender peers fill synthetic outlines as paths: no refusal there.
    for name in [peers::vello::NAME, peers::vello_cpu::NAME] {
        let mut method = registry::create(name, &[]).unwrap();
        method.prepare(gpu, &synthetic).unwrap();
        let image = frame::render_image(gpu, method.as_mut(), &upright).unwrap();
        assert!(image.sum() > 0.0, "{name}");
    }
}

/// A scene of glyphs drawn by their ids (the survey's): glyphon draws a glyph that a
/// character maps to as that character alone, where the reference draws the glyph, and
/// refuses, glyph by glyph, one that no character reaches (.notdef), drawing nothing
/// there.
#[test]
fn glyphon_draws_a_glyph_by_id_through_its_character() {
    use glyphscope::scene::{Glyph, Instance};
    let gpu = common::gpu();
    let font = glyphscope::font::default_font();
    let glyph = |id: u16| {
        let outline = font.outline(id);
        let bounds = outline.control_bounds().expect("the glyph has ink");
        Glyph::new(id, outline, bounds)
    };
    let g = font.glyph_for_char('g').unwrap();
    // .notdef (a box in DejaVu) at the origin, 'g' 1 500 units (29.3 px) to its right.
    let scene = Scene::from_font_glyphs(
        &font,
        vec![glyph(0), glyph(g)],
        vec![
            Instance {
                glyph: 0,
                position: DVec2::ZERO,
            },
            Instance {
                glyph: 1,
                position: DVec2::new(1500.0, 0.0),
            },
        ],
    );
    let camera = Camera::new(90, 60, 40.0, DVec2::new(10.0, 40.0));
    let mut glyphon = registry::create(peers::glyphon::NAME, &[]).unwrap();
    glyphon.prepare(gpu, &scene).unwrap();
    let image = frame::render_image(gpu, glyphon.as_mut(), &camera).unwrap();
    let refused = glyphon.refused_glyphs();
    assert_eq!(refused.len(), 1, "{refused:?}");
    assert_eq!(refused[0].0, 0);
    assert!(refused[0].1.contains("no character"), "{}", refused[0].1);
    let reference = reference::rasterize(&scene, &camera).unwrap();
    // Ink left and right of x = 37 (the box spans about x 12..30, the 'g' 40..62).
    let ink = |image: &glyphscope::coverage::CoverageImage, right: bool| -> f64 {
        (0..image.height)
            .flat_map(|y| (0..image.width).map(move |x| (x, y)))
            .filter(|&(x, _)| (x >= 37) == right)
            .map(|(x, y)| f64::from(image.data[(y * image.width + x) as usize]))
            .sum()
    };
    assert_eq!(
        ink(&image, false),
        0.0,
        "nothing where the refused glyph is"
    );
    assert!(ink(&reference, false) > 20.0, "the reference draws the box");
    let (theirs, ours) = (ink(&image, true), ink(&reference, true));
    // The same glyph at the same place: its ink within 5 % (hinting moves edges a
    // little, glyphon's whole-pixel baseline here moves nothing: the origin's y is whole),
    // and a mean error of a few levels, where a misplaced glyph would be off by tens.
    assert!(
        (theirs - ours).abs() < 0.05 * ours,
        "{theirs} against {ours}"
    );
    let right = |image: &glyphscope::coverage::CoverageImage| {
        let mut part = glyphscope::coverage::CoverageImage::new(image.width - 37, image.height);
        for y in 0..image.height {
            for x in 37..image.width {
                part.data[(y * part.width + x - 37) as usize] =
                    image.data[(y * image.width + x) as usize];
            }
        }
        part
    };
    let stats = metrics::compare(&right(&image), &right(&reference)).unwrap();
    assert!(stats.mae_255 < 10.0, "{stats:?}");
}

/// vello submits its own command buffers; the time the frame loop takes for them is the
/// span between timestamps in submissions just before and after `render_to_texture`:
/// vello's recording on the CPU, then its GPU work. With the queue drained first, that
/// span and the copy's pass cannot exceed the frame's wall time (a timer that counted
/// another frame's work, or the wrong queries, would), and the span is not nothing.
#[test]
fn vellos_own_submissions_are_timed_within_the_frames_wall_time() {
    let gpu = common::gpu();
    assert!(
        gpu.has_timestamps(),
        "{} offers no timestamp queries, which time vello's submissions (lavapipe, which \
         CI installs, offers them)",
        gpu.adapter_name()
    );
    let (scene, camera) = ViewArgs::text("Hamburgefonstiv", 32.0).build().unwrap();
    let mut method = registry::create(peers::vello::NAME, &[]).unwrap();
    method.prepare(gpu, &scene).unwrap();
    let target = CoverageTarget::new(gpu, camera.width, camera.height, Channels::Coverage).unwrap();
    // Shaders compile on the first frame.
    frame::render_frame(gpu, method.as_mut(), &target, &camera).unwrap();
    method.peer_gpu_time(gpu).unwrap();
    for _ in 0..3 {
        let start = Instant::now();
        frame::render_frame(gpu, method.as_mut(), &target, &camera).unwrap();
        let wall_ms = start.elapsed().as_secs_f64() * 1e3;
        let time = method.peer_gpu_time(gpu).unwrap().expect("a peer's time");
        println!(
            "vello: submitted {:.3} ms, copy {:.3} ms, wall {wall_ms:.3} ms",
            time.submitted_ms, time.copy_ms
        );
        assert!(time.submitted_ms > 0.0);
        assert!(
            time.submitted_ms + time.copy_ms <= wall_ms,
            "{time:?} > {wall_ms}"
        );
    }
}

/// glyphon lays the text out itself (cosmic-text); with the same font, size and line
/// height its pens fall where glyphscope's shaping puts them (the first baseline is
/// anchored at the scene's origin, so that part is by construction; the rest — advances,
/// line spacing — is measured), and where it draws them after its own snapping they are
/// at most half a quarter-pixel bin away in x and, in y, the rounded top, the rounded
/// baseline of the glyph's line and of the first line: √(⅛² + (3·½)²) px.
#[test]
fn glyphon_lays_the_text_out_where_glyphscope_shapes_it() {
    let gpu = common::gpu();
    let view = ViewArgs {
        origin: Some(DVec2::new(3.3, 20.6)),
        ..ViewArgs::text(
            "Hamburgefonstiv\nPack my box with five dozen liquor jugs.",
            18.0,
        )
    };
    let (scene, camera) = view.build().unwrap();
    let info = registry::find(peers::glyphon::NAME).unwrap();
    let drawn = measure::measure(Some(gpu), &scene, &camera, info, &[], ONE_FRAME).unwrap();
    let offset = drawn
        .stats
        .layout_offset
        .expect("glyphon measures its layout");
    println!("{offset:?}");
    assert_eq!(offset.glyphs, scene.instances.len());
    assert_eq!(offset.mismatched, 0);
    assert!(offset.laid_out_max_px < 0.01, "{offset:?}");
    let snapping = (1.0f64 / 64.0 + 1.5 * 1.5).sqrt();
    assert!(offset.placed_max_px <= snapping, "{offset:?}");
    assert!(
        offset.placed_max_px > 0.0,
        "the origin is off the pixel grid"
    );
}
