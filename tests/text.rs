//! The text library as a caller sees it (`glyphscope::text`): text composited over a
//! coloured background in an sRGB target equals the reference coverage composited the
//! same way; two runs of two fonts and colours in one pass; a transform changed every
//! frame re-uploads instances, never outlines, and an unchanged frame uploads nothing;
//! bad input is an error value.
//!
//! The composite bound, set before the first run: per pixel, in linear light, the
//! method's claim (0.02 of coverage) times the contrast between text and background,
//! plus one step of the 8-bit sRGB encoding at that value (the target's rounding).

mod common;

use glam::{DVec2, Mat3, vec2};
use glyphscope::Error;
use glyphscope::camera::Camera;
use glyphscope::font::Font;
use glyphscope::reference;
use glyphscope::scene::Scene;
use glyphscope::text::{Content, PositionedGlyph, TextRenderer, TextRun};

const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;
const WIDTH: u32 = 320;
const HEIGHT: u32 = 120;
/// The background, sRGB.
const BACKGROUND: [f32; 3] = [0.2, 0.45, 0.7];
/// `winding`'s claim: no pixel's coverage off by more than this.
const CLAIM: f64 = 0.02;

fn decode(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

fn encode(l: f64) -> f64 {
    if l <= 0.0031308 {
        l * 12.92
    } else {
        1.055 * l.powf(1.0 / 2.4) - 0.055
    }
}

/// Draws `runs` over the background into a fresh target; its pixels as sRGB bytes.
fn draw(text: &mut TextRenderer, runs: &[TextRun<'_>]) -> Vec<u8> {
    let gpu = common::gpu();
    let (device, queue) = (&gpu.device, &gpu.queue);
    let mut encoder = device.create_command_encoder(&Default::default());
    text.prepare(&mut encoder, [WIDTH, HEIGHT], runs).unwrap();
    let size = wgpu::Extent3d {
        width: WIDTH,
        height: HEIGHT,
        depth_or_array_layers: 1,
    };
    let target = device.create_texture(&wgpu::TextureDescriptor {
        label: None,
        size,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: FORMAT,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let view = target.create_view(&Default::default());
    let row = (WIDTH * 4).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: u64::from(row * HEIGHT),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    {
        // The clear colour is linear: the target encodes it.
        let [r, g, b] = BACKGROUND.map(|c| decode(f64::from(c)));
        let ops = wgpu::Operations {
            load: wgpu::LoadOp::Clear(wgpu::Color { r, g, b, a: 1.0 }),
            store: wgpu::StoreOp::Store,
        };
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &view,
                depth_slice: None,
                resolve_target: None,
                ops,
            })],
            ..Default::default()
        });
        text.render(&mut pass);
    }
    encoder.copy_texture_to_buffer(
        target.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &buffer,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(row),
                rows_per_image: None,
            },
        },
        size,
    );
    queue.submit([encoder.finish()]);
    buffer
        .slice(..)
        .map_async(wgpu::MapMode::Read, |r| r.unwrap());
    device.poll(wgpu::PollType::wait_indefinitely()).unwrap();
    let mapped = buffer.slice(..).get_mapped_range().unwrap();
    (0..HEIGHT as usize)
        .flat_map(|y| mapped[y * row as usize..][..WIDTH as usize * 4].to_vec())
        .collect()
}

/// The reference coverage of `text` in `font` at `size`, its baseline starting at
/// `origin` (pixels, y down), unturned: what the library is given as a translation.
fn reference_coverage(font: &Font, text: &str, size: f64, origin: DVec2) -> Vec<f32> {
    let scene = Scene::from_text(font, text).unwrap();
    let camera = Camera::new(WIDTH, HEIGHT, size, origin);
    reference::rasterize(&scene, &camera).unwrap().data
}

/// Each pixel against the reference composited over the background, layer by layer
/// (coverage, sRGB colour): the worst excess over the bound (≤ 0 holds) and where.
fn worst_excess(pixels: &[u8], layers: &[(&[f32], [f32; 3])]) -> (f64, usize) {
    let (mut worst, mut at) = (f64::NEG_INFINITY, 0);
    for i in 0..(WIDTH * HEIGHT) as usize {
        let mut expected = BACKGROUND.map(|c| decode(f64::from(c)));
        let mut bound = [0.0; 3];
        for (coverage, colour) in layers {
            let c = f64::from(coverage[i]);
            for k in 0..3 {
                let colour = decode(f64::from(colour[k]));
                bound[k] += CLAIM * (colour - expected[k]).abs();
                expected[k] = expected[k] * (1.0 - c) + colour * c;
            }
        }
        for k in 0..3 {
            let got = decode(f64::from(pixels[4 * i + k]) / 255.0);
            // One step of the 8-bit encoding either side of the expected value.
            let e = encode(expected[k]);
            let step = (decode((e + 1.0 / 255.0).min(1.0)) - expected[k])
                .max(expected[k] - decode((e - 1.0 / 255.0).max(0.0)));
            let excess = (got - expected[k]).abs() - (bound[k] + step);
            // NaN is an excess too.
            if excess.is_nan() || excess > worst {
                worst = if excess.is_nan() {
                    f64::INFINITY
                } else {
                    excess
                };
                at = i;
            }
        }
    }
    (worst, at)
}

/// An encoder for a `prepare` whose passes the test does not submit.
fn encoder() -> wgpu::CommandEncoder {
    common::gpu()
        .device
        .create_command_encoder(&Default::default())
}

fn renderer() -> TextRenderer {
    let gpu = common::gpu();
    TextRenderer::new(&gpu.device, &gpu.queue, FORMAT)
}

/// One run, and two runs of two fonts and colours in one pass, composited over the
/// background as the reference's coverage composites: within the bound everywhere.
#[test]
fn text_over_a_background_is_the_reference_composited() {
    let dejavu = Font::default_font();
    let latin = Font::shipped(1);
    let mut text = renderer();
    let a = text
        .add_font(glyphscope::font::DEFAULT_FONT_BYTES.to_vec())
        .unwrap();
    let b = text
        .add_font(std::fs::read("fonts/lmroman10-regular.otf").unwrap())
        .unwrap();
    let red = [0.9, 0.15, 0.1];
    let yellow = [1.0, 0.9, 0.3];
    let first = TextRun {
        font: a,
        content: Content::Text("Hamburgefonstiv"),
        size_px: 24.0,
        transform: Mat3::from_translation(vec2(10.25, 40.5)),
        color: [red[0], red[1], red[2], 1.0],
    };
    let second = TextRun {
        font: b,
        content: Content::Text("Quixotic & gjy"),
        size_px: 30.0,
        transform: Mat3::from_translation(vec2(12.0, 95.75)),
        color: [yellow[0], yellow[1], yellow[2], 1.0],
    };
    let one = draw(&mut text, &[first]);
    let coverage_a = reference_coverage(&dejavu, "Hamburgefonstiv", 24.0, DVec2::new(10.25, 40.5));
    let (worst, at) = worst_excess(&one, &[(&coverage_a, red)]);
    println!("one run: the worst pixel is {worst:.2e} from the bound (≤ 0 holds)");
    assert!(
        worst <= 0.0,
        "one run: pixel {at} past the bound by {worst}"
    );
    let both = draw(&mut text, &[first, second]);
    let coverage_b = reference_coverage(&latin, "Quixotic & gjy", 30.0, DVec2::new(12.0, 95.75));
    let (worst, at) = worst_excess(&both, &[(&coverage_a, red), (&coverage_b, yellow)]);
    println!("two runs: the worst pixel is {worst:.2e} from the bound (≤ 0 holds)");
    assert!(
        worst <= 0.0,
        "two runs: pixel {at} past the bound by {worst}"
    );
    // Small text whose glyphs share pixels (at 9 px/em, "rn" and "ll" meet within one):
    // each run's coverage adds its glyphs before its colour is blended, so the shared
    // pixels are their union, not their colours laid over each other.
    let small = TextRun {
        content: Content::Text("minimum rnrn illlli wavvy"),
        size_px: 9.0,
        transform: Mat3::from_translation(vec2(5.5, 60.25)),
        ..first
    };
    let tight = draw(&mut text, &[small]);
    let coverage_small = reference_coverage(
        &dejavu,
        "minimum rnrn illlli wavvy",
        9.0,
        DVec2::new(5.5, 60.25),
    );
    let (worst, at) = worst_excess(&tight, &[(&coverage_small, red)]);
    println!("glyphs sharing pixels: the worst pixel is {worst:.2e} from the bound");
    assert!(
        worst <= 0.0,
        "9 px/em: pixel {at} past the bound by {worst}"
    );
    // Without the text (the background alone), the check fails: it can.
    let (blank, _) = worst_excess(&draw(&mut text, &[]), &[(&coverage_a, red)]);
    assert!(blank > 0.0, "{blank}");
    // The text is there: the check is not of a blank frame.
    let covered = coverage_a.iter().filter(|&&c| c > 0.5).count();
    assert!(covered > 500, "{covered}");
}

/// A frame whose runs did not change uploads nothing; turning the text every frame
/// uploads instances only, never the outlines; new text uploads its new glyphs.
#[test]
fn unchanged_frames_upload_nothing_and_moving_text_only_its_instances() {
    let mut text = renderer();
    let font = text
        .add_font(glyphscope::font::DEFAULT_FONT_BYTES.to_vec())
        .unwrap();
    let run = |angle: f32, content| TextRun {
        font,
        content,
        size_px: 20.0,
        transform: Mat3::from_translation(vec2(40.0, 60.0)) * Mat3::from_angle(angle),
        color: [0.0, 0.0, 0.0, 1.0],
    };
    let words = Content::Text("spin spin");
    text.prepare(&mut encoder(), [WIDTH, HEIGHT], &[run(0.0, words)])
        .unwrap();
    let first = text.last_uploads();
    assert!(
        first.glyph_bytes > 0 && first.instance_bytes > 0,
        "{first:?}"
    );
    let glyphs = text.prepared_glyphs();
    assert_eq!(glyphs, 4, "s p i n: each glyph once");
    text.prepare(&mut encoder(), [WIDTH, HEIGHT], &[run(0.0, words)])
        .unwrap();
    assert_eq!(text.last_uploads(), Default::default());
    for frame in 1..5 {
        text.prepare(
            &mut encoder(),
            [WIDTH, HEIGHT],
            &[run(frame as f32 * 0.3, words)],
        )
        .unwrap();
        let uploads = text.last_uploads();
        assert_eq!(uploads.glyph_bytes, 0, "frame {frame}");
        assert!(uploads.instance_bytes > 0, "frame {frame}");
    }
    // New glyphs are prepared and uploaded; known ones are not prepared again.
    text.prepare(
        &mut encoder(),
        [WIDTH, HEIGHT],
        &[run(0.0, Content::Text("spins pins"))],
    )
    .unwrap();
    assert_eq!(text.prepared_glyphs(), glyphs, "no new letter");
    assert_eq!(text.last_uploads().glyph_bytes, 0);
    text.prepare(
        &mut encoder(),
        [WIDTH, HEIGHT],
        &[run(0.0, Content::Text("spun"))],
    )
    .unwrap();
    assert_eq!(text.prepared_glyphs(), glyphs + 1, "u");
    assert!(text.last_uploads().glyph_bytes > 0);
}

/// Bad input is an error value naming what is wrong, and the renderer stays usable.
#[test]
fn bad_input_is_an_error_not_a_panic() {
    let mut text = renderer();
    assert!(matches!(
        text.add_font(b"not a font".to_vec()),
        Err(Error::Font(_))
    ));
    let font = text
        .add_font(glyphscope::font::DEFAULT_FONT_BYTES.to_vec())
        .unwrap();
    let good = TextRun {
        font,
        content: Content::Text("ok"),
        size_px: 16.0,
        transform: Mat3::IDENTITY,
        color: [0.0, 0.0, 0.0, 1.0],
    };
    let nan = Mat3::from_cols_array(&[f32::NAN, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]);
    let missing = [PositionedGlyph {
        id: 65_000,
        x: 0.0,
        y: 0.0,
    }];
    for (what, run, expect) in [
        (
            "NaN in the transform",
            TextRun {
                transform: nan,
                ..good
            },
            "not finite",
        ),
        (
            "a flat transform",
            TextRun {
                transform: Mat3::ZERO,
                ..good
            },
            "invertible",
        ),
        (
            "an empty string",
            TextRun {
                content: Content::Text(""),
                ..good
            },
            "nothing",
        ),
        (
            "a zero size",
            TextRun {
                size_px: 0.0,
                ..good
            },
            "size",
        ),
        (
            "a colour past 1",
            TextRun {
                color: [2.0, 0.0, 0.0, 1.0],
                ..good
            },
            "colour",
        ),
        (
            "a glyph the font lacks",
            TextRun {
                content: Content::Glyphs(&missing),
                ..good
            },
            "65000",
        ),
        (
            "text behind the eye",
            TextRun {
                transform: Mat3::from_cols_array(&[1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, -1.0]),
                ..good
            },
            "behind the eye",
        ),
    ] {
        match text.prepare(&mut encoder(), [WIDTH, HEIGHT], &[good, run]) {
            Err(Error::Input(message)) => {
                assert!(message.contains(expect), "{what}: {message}");
                assert!(!message.contains('\n'), "{what}: one line");
            }
            other => panic!("{what}: {other:?}"),
        }
    }
    assert!(
        text.prepare(&mut encoder(), [0, HEIGHT], &[good]).is_err(),
        "an empty viewport"
    );
    let unknown = TextRun {
        font: text
            .add_font(glyphscope::font::DEFAULT_FONT_BYTES.to_vec())
            .unwrap(),
        ..good
    };
    assert!(
        text.prepare(&mut encoder(), [WIDTH, HEIGHT], &[unknown])
            .is_ok()
    );
    text.prepare(&mut encoder(), [WIDTH, HEIGHT], &[good])
        .unwrap();
}
