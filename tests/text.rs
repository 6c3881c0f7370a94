//! The text library as a caller sees it (`glyphscope::text`): text composited over a
//! coloured background in an sRGB target equals the reference coverage composited the
//! same way; two runs of two fonts and colours in one pass; a transform changed every
//! frame re-uploads instances, never outlines, and an unchanged frame uploads nothing;
//! hundreds of labels, still and in motion (drawn straight into the target where the
//! runs' order allows, through the pages elsewhere), are the reference composited in
//! order; blank runs draw nothing; bad input is an error value.
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
use glyphscope::text::{Content, FontId, PositionedGlyph, TextRenderer, TextRun};

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
/// (coverage, sRGB colour): the worst excess over the bound (≤ 0 holds) and where. A
/// layer's share of the bound is the claim where its text may reach — its inked
/// pixels' box grown by two — and nothing elsewhere: a run draws nothing past the
/// pixels its glyphs touch, so with hundreds of layers the bound does not grow with
/// their count.
fn worst_excess(pixels: &[u8], layers: &[(&[f32], [f32; 3])]) -> (f64, usize) {
    let (w, h) = (WIDTH as i64, HEIGHT as i64);
    let boxes: Vec<Option<[i64; 4]>> = layers
        .iter()
        .map(|(coverage, _)| {
            let mut inked = (0..coverage.len() as i64).filter(|&i| coverage[i as usize] > 0.0);
            let first = inked.next()?;
            let (mut x0, mut y0) = (first % w, first / w);
            let (mut x1, mut y1) = (x0, y0);
            for i in inked {
                (x0, y0, x1, y1) = (x0.min(i % w), y0.min(i / w), x1.max(i % w), y1.max(i / w));
            }
            Some([x0 - 2, y0 - 2, x1 + 2, y1 + 2])
        })
        .collect();
    let (mut worst, mut at) = (f64::NEG_INFINITY, 0);
    for i in 0..(w * h) as usize {
        let (x, y) = (i as i64 % w, i as i64 / w);
        let mut expected = BACKGROUND.map(|c| decode(f64::from(c)));
        let mut bound = [0.0; 3];
        // The target rounds to 8 bits after each run blended over it: a step per run
        // that reaches the pixel (one at least, for the background).
        let mut blends = 1.0f64;
        for ((coverage, colour), reach) in layers.iter().zip(&boxes) {
            let near = reach
                .is_some_and(|[x0, y0, x1, y1]| (x0..=x1).contains(&x) && (y0..=y1).contains(&y));
            if near {
                blends += 1.0;
            }
            let c = f64::from(coverage[i]);
            for k in 0..3 {
                let colour = decode(f64::from(colour[k]));
                if near {
                    bound[k] += CLAIM * (colour - expected[k]).abs();
                }
                expected[k] = expected[k] * (1.0 - c) + colour * c;
            }
        }
        for k in 0..3 {
            let got = decode(f64::from(pixels[4 * i + k]) / 255.0);
            // One step of the 8-bit encoding either side of the expected value.
            let e = encode(expected[k]);
            let step = (decode((e + 1.0 / 255.0).min(1.0)) - expected[k])
                .max(expected[k] - decode((e - 1.0 / 255.0).max(0.0)));
            let excess = (got - expected[k]).abs() - (bound[k] + step * (blends - 1.0).max(1.0));
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
    let dejavu = glyphscope::font::default_font();
    let latin = glyphscope::font::shipped(1);
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
    match text.prepare(&mut encoder(), [u32::MAX, HEIGHT], &[good]) {
        Err(Error::Input(message)) => assert!(message.contains("largest texture"), "{message}"),
        other => panic!("a viewport past any texture: {other:?}"),
    }
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

/// A fixed pseudo-random sequence (the same labels every run).
struct Sequence(u64);

impl Sequence {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    fn between(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}

const WORDS: &[&str] = &[
    "File",
    "Edit",
    "View",
    "Window",
    "Help",
    "Open…",
    "Save as",
    "42.0 px",
    "Zoom 110%",
    "Layers",
    "Brush",
    "Ähnlich",
    "fjord",
    "Wavy",
    "rnrn",
    "iiil",
    "Quit",
    "Ω≈ç√",
];

/// Labels as a UI has them: words of 10–32 px over the target and past its edges,
/// overlapping one another, a quarter of them turned, each in its own colour.
fn labels(count: usize, seed: u64) -> Vec<(String, f32, Mat3, [f32; 3])> {
    let mut random = Sequence(seed);
    (0..count)
        .map(|_| {
            let word = WORDS[(random.next() * WORDS.len() as f64) as usize % WORDS.len()];
            let size = random.between(10.0, 32.0) as f32;
            let at = vec2(
                random.between(-40.0, f64::from(WIDTH) + 10.0) as f32,
                random.between(0.0, f64::from(HEIGHT) + 20.0) as f32,
            );
            let turn = if random.next() < 0.25 {
                random.between(-0.8, 0.8) as f32
            } else {
                0.0
            };
            let colour = [random.next(), random.next(), random.next()].map(|c| c as f32);
            (
                word.to_owned(),
                size,
                Mat3::from_translation(at) * Mat3::from_angle(turn),
                colour,
            )
        })
        .collect()
}

/// `labels` as runs of `font`, each moved down by `shift` pixels, its colour times
/// `shade`.
fn label_runs(
    labels: &[(String, f32, Mat3, [f32; 3])],
    font: FontId,
    shift: f32,
    shade: f32,
) -> Vec<TextRun<'_>> {
    labels
        .iter()
        .map(|(word, size, transform, colour)| TextRun {
            font,
            content: Content::Text(word),
            size_px: *size,
            transform: Mat3::from_translation(vec2(0.0, shift)) * *transform,
            color: [colour[0] * shade, colour[1] * shade, colour[2] * shade, 1.0],
        })
        .collect()
}

/// The reference coverage of each of `runs` (labels: text through an affine map).
fn label_coverages(font: &Font, runs: &[TextRun<'_>]) -> Vec<Vec<f32>> {
    runs.iter()
        .map(|run| {
            let Content::Text(word) = run.content else {
                unreachable!("labels are text")
            };
            reference_of_label(font, word, run.size_px, run.transform)
        })
        .collect()
}

/// Asserts that `pixels` are `coverages` composited over the background in order, each
/// in its run's colour, within the composite bound.
fn assert_composited_in_order(
    pixels: &[u8],
    coverages: &[Vec<f32>],
    runs: &[TextRun<'_>],
    what: &str,
) {
    let layers: Vec<(&[f32], [f32; 3])> = coverages
        .iter()
        .map(Vec::as_slice)
        .zip(runs.iter().map(|r| [r.color[0], r.color[1], r.color[2]]))
        .collect();
    let (worst, at) = worst_excess(pixels, &layers);
    println!("{what}: the worst pixel is {worst:.2e} from the bound (≤ 0 holds)");
    assert!(worst <= 0.0, "{what}: pixel {at} past the bound by {worst}");
}

/// The reference coverage of a label drawn through `transform` (an affine map of text
/// space, y down): the camera's matrix is the same map on font units, y up.
fn reference_of_label(font: &Font, text: &str, size: f32, transform: Mat3) -> Vec<f32> {
    let scene = Scene::from_text(font, text).unwrap();
    let origin = transform.z_axis;
    let mut camera = Camera::new(
        WIDTH,
        HEIGHT,
        f64::from(size),
        DVec2::new(f64::from(origin.x), f64::from(origin.y)),
    );
    // y up to y down and back around the text-space map: F L F, F = diag(1, -1).
    let (x, y) = (transform.x_axis, transform.y_axis);
    camera.matrix = Camera::matrix_from_rows(
        f64::from(x.x),
        -f64::from(y.x),
        -f64::from(x.y),
        f64::from(y.y),
    );
    reference::rasterize(&scene, &camera).unwrap().data
}

/// A UI's empty label (a search box before anything is typed, a counter not yet
/// shown) is no error: runs of empty or blank text, or of no glyphs, draw nothing, and
/// the runs beside them draw exactly what they draw alone.
#[test]
fn blank_runs_draw_nothing_and_are_no_error() {
    let mut text = renderer();
    let font = text
        .add_font(glyphscope::font::DEFAULT_FONT_BYTES.to_vec())
        .unwrap();
    let run = |content| TextRun {
        font,
        content,
        size_px: 24.0,
        transform: Mat3::from_translation(vec2(10.0, 60.0)),
        color: [0.9, 0.2, 0.1, 1.0],
    };
    let alone = draw(&mut text, &[run(Content::Text("Search"))]);
    let mut beside_blanks = renderer();
    let font_again = beside_blanks
        .add_font(glyphscope::font::DEFAULT_FONT_BYTES.to_vec())
        .unwrap();
    assert_eq!(font_again, font);
    let runs = [
        run(Content::Text("")),
        run(Content::Text("Search")),
        run(Content::Text("   \n ")),
        run(Content::Glyphs(&[])),
    ];
    let with_blanks = draw(&mut beside_blanks, &runs);
    assert!(with_blanks == alone, "blank runs changed the pixels");
    // And a frame of nothing but blank runs draws the background alone.
    let blank = draw(&mut beside_blanks, &[run(Content::Text(""))]);
    let background = blank.chunks(4).all(|p| p == &blank[..4]);
    assert!(background, "a blank frame drew something");
}

/// Three hundred labels — more than the 256 layers the first version could hold, runs
/// overlapping, cut by the target's edges and turned — composited in order equal the
/// reference composited label over label; an unchanged frame draws the same pixels;
/// a frame that only recolours the labels draws the new colours.
#[test]
fn hundreds_of_labels_are_the_reference_composited_in_order() {
    let font = glyphscope::font::default_font();
    let mut text = renderer();
    let id = text
        .add_font(glyphscope::font::DEFAULT_FONT_BYTES.to_vec())
        .unwrap();
    let labels = labels(300, 7);
    let runs = |shade: f32| label_runs(&labels, id, 0.0, shade);
    // Recolouring leaves the coverages as they are.
    let coverages = label_coverages(&font, &runs(1.0));
    let check = |pixels: &[u8], shade: f32, what: &str| {
        assert_composited_in_order(pixels, &coverages, &runs(shade), what);
    };
    let first = draw(&mut text, &runs(1.0));
    check(&first, 1.0, "300 labels");
    let held = text.held();
    println!("held: {held:?}");
    // A trim keeps the instances the frame drew (it once counted only those drawn
    // straight into the target, none in a first frame, and gave the rest back).
    text.trim();
    assert_eq!(text.held().instance_bytes, held.instance_bytes);
    // Unchanged: nothing uploaded or drawn but the composite, the same pixels.
    let again = draw(&mut text, &runs(1.0));
    assert_eq!(text.last_uploads(), Default::default());
    assert!(
        first == again,
        "an unchanged frame draws what the last one drew"
    );
    // Recoloured: only the records, and the new colours.
    let darker = draw(&mut text, &runs(0.5));
    let uploads = text.last_uploads();
    assert_eq!(uploads.glyph_bytes, 0);
    assert!(
        uploads.instance_bytes > 0 && uploads.instance_bytes < 300 * 64,
        "{uploads:?}"
    );
    check(&darker, 0.5, "300 labels recoloured");
    // The labels' pixels, not 300 viewports: the pages hold at most three times the
    // labels' boxes (each grown by two pixels a side) and one page of slack, where
    // 300 layers of the viewport were 300 × 76 800 bytes.
    let boxes: u64 = coverages
        .iter()
        .map(|c| {
            let inked = (0..c.len()).filter(|&i| c[i] > 0.0);
            let (mut x0, mut y0, mut x1, mut y1) = (u64::MAX, u64::MAX, 0, 0);
            for i in inked {
                let (x, y) = ((i as u64) % u64::from(WIDTH), (i as u64) / u64::from(WIDTH));
                (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
            }
            if x0 == u64::MAX {
                0
            } else {
                (x1 - x0 + 5) * (y1 - y0 + 5)
            }
        })
        .sum();
    let page = u64::from(WIDTH.next_multiple_of(64) * HEIGHT.next_multiple_of(64));
    let bound = 2 * (3 * boxes + page) + 512 * 48 + 16;
    println!(
        "boxes {boxes} px: coverage held {} of at most {bound} bytes",
        held.coverage_bytes
    );
    assert!(held.coverage_bytes <= bound, "{held:?}");
}

/// Labels in motion: from the second frame in a row that moves them, the glyphs whose
/// runs' order allows it are drawn straight into the target. That frame is the
/// reference composited label over label (where glyphs of a label or of two labels
/// share a pixel, blending them one after the other would be off by up to a quarter of
/// coverage: the bound holds only if those went through the pages); the first still
/// frame after it, everything through the pages, draws the same pixels within one step
/// of the encoding; the next uploads nothing.
#[test]
fn labels_in_motion_are_the_reference_drawn_straight_or_through_the_pages() {
    let font = glyphscope::font::default_font();
    let mut text = renderer();
    let id = text
        .add_font(glyphscope::font::DEFAULT_FONT_BYTES.to_vec())
        .unwrap();
    // Sparse enough that many glyphs share no pixel, dense enough that many do.
    let labels = labels(40, 23);
    let runs = |shift: f32| label_runs(&labels, id, shift, 1.0);
    let coverages = label_coverages(&font, &runs(0.37));
    let check = |pixels: &[u8], what: &str| {
        assert_composited_in_order(pixels, &coverages, &runs(0.37), what);
    };
    draw(&mut text, &runs(0.0));
    assert_eq!(
        text.direct_glyphs(),
        0,
        "a first frame draws into the pages"
    );
    let moving = draw(&mut text, &runs(0.37));
    let direct = text.direct_glyphs();
    println!("moving: {direct} glyphs drawn straight into the target");
    assert!(direct > 0, "a moving frame's lone glyphs skip the pages");
    // And the others went through them: more instances written than drawn straight.
    let instance = 112;
    let uploaded = text.last_uploads().instance_bytes;
    assert!(
        uploaded > (direct as u64 + 1) * instance,
        "{uploaded} bytes"
    );
    check(&moving, "moving");
    let still = draw(&mut text, &runs(0.37));
    assert_eq!(
        text.direct_glyphs(),
        0,
        "a still frame draws into the pages"
    );
    check(&still, "still");
    let apart = (moving.iter().zip(&still))
        .filter(|(a, b)| a.abs_diff(**b) > 1)
        .count();
    assert_eq!(
        apart, 0,
        "channels more than a step apart, moving and still"
    );
    let again = draw(&mut text, &runs(0.37));
    assert_eq!(text.last_uploads(), Default::default());
    assert!(
        again == still,
        "an unchanged frame draws what the last one drew"
    );
}

/// Glyphs a `prepare` laid out for one run are uploaded even when a later run of the
/// same call fails: the next good frame draws them (it drew garbage or nothing once).
#[test]
fn glyphs_of_a_failed_prepare_are_uploaded_by_the_next() {
    let font = glyphscope::font::default_font();
    let mut text = renderer();
    let id = text
        .add_font(glyphscope::font::DEFAULT_FONT_BYTES.to_vec())
        .unwrap();
    let run = |content, size_px| TextRun {
        font: id,
        content,
        size_px,
        transform: Mat3::from_translation(vec2(12.0, 70.0)),
        color: [0.05, 0.05, 0.05, 1.0],
    };
    // Glyphs uploaded once, so a later frame does not upload merely for having none.
    text.prepare(
        &mut encoder(),
        [WIDTH, HEIGHT],
        &[run(Content::Text("ab"), 20.0)],
    )
    .unwrap();
    let failing = [
        run(Content::Text("Quartz"), 40.0),
        run(Content::Text("x"), f32::NAN),
    ];
    assert!(
        text.prepare(&mut encoder(), [WIDTH, HEIGHT], &failing)
            .is_err()
    );
    let pixels = draw(&mut text, &[run(Content::Text("Quartz"), 40.0)]);
    let coverage = reference_coverage(&font, "Quartz", 40.0, DVec2::new(12.0, 70.0));
    let (worst, at) = worst_excess(&pixels, &[(&coverage, [0.05; 3])]);
    assert!(worst <= 0.0, "pixel {at} past the bound by {worst}");
}

/// Text that changes every frame, trimmed every frame, holds what the frames draw: the
/// layouts of the last frames, and glyphs once those no longer drawn outnumber them;
/// what is drawn after a compaction is still the reference.
#[test]
fn trimmed_every_frame_dynamic_text_holds_only_what_it_draws() {
    let font = glyphscope::font::default_font();
    let mut text = renderer();
    let id = text
        .add_font(glyphscope::font::DEFAULT_FONT_BYTES.to_vec())
        .unwrap();
    let still = TextRun {
        font: id,
        content: Content::Text("Status:"),
        size_px: 18.0,
        transform: Mat3::from_translation(vec2(8.0, 30.0)),
        color: [0.9, 0.9, 0.9, 1.0],
    };
    // A new word every frame, of letters from Latin, Greek and Cyrillic (some 400 glyphs
    // over the frames), and a counter.
    let letters: Vec<char> = ('A'..='z')
        .chain('Α'..='ω')
        .chain('А'..='я')
        .chain('À'..='ÿ')
        .filter(|c| c.is_alphabetic())
        .collect();
    let mut most_layouts = 0;
    let mut most_glyphs = 0;
    let mut last = (String::new(), String::new());
    for frame in 0..160usize {
        let word: String = (0..3)
            .map(|k| letters[(frame * 3 + k) % letters.len()])
            .collect();
        let counter = format!("{frame} frames");
        let runs = [
            still,
            TextRun {
                content: Content::Text(&word),
                transform: Mat3::from_translation(vec2(90.0, 30.0)),
                ..still
            },
            TextRun {
                content: Content::Text(&counter),
                transform: Mat3::from_translation(vec2(8.0, 80.0)),
                ..still
            },
        ];
        text.prepare(&mut encoder(), [WIDTH, HEIGHT], &runs)
            .unwrap();
        text.trim();
        most_layouts = most_layouts.max(text.cached_layouts());
        most_glyphs = most_glyphs.max(text.prepared_glyphs());
        last = (word, counter);
    }
    println!("most layouts kept {most_layouts}, most glyphs kept {most_glyphs}");
    assert!(most_layouts <= 6, "layouts kept: {most_layouts}");
    // 160 frames met some 400 glyphs; a compaction keeps at most what is drawn plus
    // the slack before the next (64, or as many as are drawn).
    assert!(most_glyphs <= 160, "glyphs kept: {most_glyphs}");
    let runs = [
        TextRun {
            content: Content::Text(&last.0),
            transform: Mat3::from_translation(vec2(90.0, 30.0)),
            ..still
        },
        TextRun {
            content: Content::Text(&last.1),
            transform: Mat3::from_translation(vec2(8.0, 80.0)),
            ..still
        },
    ];
    let pixels = draw(&mut text, &runs);
    let a = reference_coverage(&font, &last.0, 18.0, DVec2::new(90.0, 30.0));
    let b = reference_coverage(&font, &last.1, 18.0, DVec2::new(8.0, 80.0));
    let (worst, at) = worst_excess(&pixels, &[(&a, [0.9; 3]), (&b, [0.9; 3])]);
    assert!(
        worst <= 0.0,
        "after compactions: pixel {at} past the bound by {worst}"
    );
}

/// Two hundred labels scrolled by 0.37 px a frame for eight frames, trimmed after each,
/// as a scrolling UI draws them (each frame's coverage drawn anew into repacked pages),
/// and every other frame half of them only recoloured: the last frame equals the
/// reference of the labels where they are then.
#[test]
fn scrolled_labels_are_the_reference_where_they_end() {
    let font = glyphscope::font::default_font();
    let mut text = renderer();
    let id = text
        .add_font(glyphscope::font::DEFAULT_FONT_BYTES.to_vec())
        .unwrap();
    let labels = labels(200, 11);
    let at = |frame: usize, transform: Mat3| {
        Mat3::from_translation(vec2(0.0, 0.37 * frame as f32)) * transform
    };
    let runs = |frame: usize| -> Vec<TextRun<'_>> {
        labels
            .iter()
            .enumerate()
            .map(|(k, (word, size, transform, colour))| {
                // Odd labels stay put and change colour; even ones scroll.
                let (transform, shade) = if k % 2 == 0 {
                    (at(frame, *transform), 1.0)
                } else {
                    (*transform, if frame.is_multiple_of(2) { 1.0 } else { 0.6 })
                };
                TextRun {
                    font: id,
                    content: Content::Text(word),
                    size_px: *size,
                    transform,
                    color: [colour[0] * shade, colour[1] * shade, colour[2] * shade, 1.0],
                }
            })
            .collect()
    };
    let last = 8;
    for frame in 0..last {
        text.prepare(&mut encoder(), [WIDTH, HEIGHT], &runs(frame))
            .unwrap();
        text.trim();
    }
    let pixels = draw(&mut text, &runs(last));
    let coverages = label_coverages(&font, &runs(last));
    assert_composited_in_order(
        &pixels,
        &coverages,
        &runs(last),
        "200 labels after 8 frames of scrolling",
    );
}
