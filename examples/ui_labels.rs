//! A UI's labels drawn by `glyphscope::text` or by glyphon, as an app draws them, timed
//! and weighed: the client that docs/library.md's cost table comes from.
//!
//! ```text
//! cargo run --release --example ui_labels -- --renderer library --labels 500
//! cargo run --release --example ui_labels -- --renderer glyphon --labels 2000
//! ```
//!
//! N labels of 10–32 px (the `ui` scene's, `glyphscope::bench::ui`) into a 1920×1080
//! `Rgba8UnormSrgb` target: first still, then scrolled by 0.37 px a frame. Each frame is
//! what an app does — prepare, render into its pass, submit, wait for the GPU — and its
//! wall time is measured; the median of `--frames` frames after 5 warm-up frames is
//! printed for each, with the process's resident memory before the renderer was made
//! and after its last frame (on a software GPU the GPU's memory is the process's), and
//! for the library what it says it holds (`TextRenderer::held`), and the CPU time the
//! whole process spent per moving frame (every thread: on a software GPU that is the
//! GPU's work too, a figure less moved by other processes than wall time). One line of JSON, so
//! that `tools/ui-labels.sh` can run one renderer per process and tabulate them.

use std::sync::Arc;
use std::time::Instant;

use glyphscope::bench::ui;
use glyphscope::font::Font;
use glyphscope::gpu::GpuContext;
use glyphscope::text::{Content, TextRenderer, TextRun};

const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;
const WARMUP: usize = 5;
/// The scroll each moving frame adds, pixels.
const SCROLL: f32 = 0.37;

/// One of the two renderers, drawing the labels scrolled by `scroll` into `view`.
trait Labels {
    fn frame(&mut self, encoder: &mut wgpu::CommandEncoder, view: &wgpu::TextureView, scroll: f32);
    fn held_bytes(&self) -> Option<u64>;
    /// The library's glyphs in the last frame: all of them, and those drawn straight
    /// into the target.
    fn glyphs(&self) -> Option<(usize, usize)>;
}

struct Library {
    text: TextRenderer,
    font: glyphscope::text::FontId,
    labels: Vec<ui::Label>,
}

impl Labels for Library {
    fn frame(&mut self, encoder: &mut wgpu::CommandEncoder, view: &wgpu::TextureView, scroll: f32) {
        let runs: Vec<TextRun<'_>> = self
            .labels
            .iter()
            .map(|label| TextRun {
                font: self.font,
                content: Content::Text(&label.text),
                size_px: label.size_px,
                transform: glam::Mat3::from_translation(glam::vec2(label.x, label.y + scroll)),
                color: [0.1, 0.1, 0.12, 1.0],
            })
            .collect();
        self.text
            .prepare(encoder, ui::SIZE, &runs)
            .expect("the labels are good input");
        let mut pass = clearing_pass(encoder, view);
        self.text.render(&mut pass);
        drop(pass);
        self.text.trim();
    }

    fn held_bytes(&self) -> Option<u64> {
        Some(self.text.held().total())
    }

    fn glyphs(&self) -> Option<(usize, usize)> {
        Some((self.text.drawn_glyphs(), self.text.direct_glyphs()))
    }
}

struct Glyphon {
    device: wgpu::Device,
    queue: wgpu::Queue,
    font_system: glyphon::FontSystem,
    swash: glyphon::SwashCache,
    atlas: glyphon::TextAtlas,
    viewport: glyphon::Viewport,
    renderer: glyphon::TextRenderer,
    /// Per label: its buffer, laid out once, its left and its text area's top.
    buffers: Vec<(glyphon::Buffer, f32, f32)>,
}

impl Glyphon {
    fn new(gpu: &GpuContext, font_bytes: Vec<u8>, labels: &[ui::Label]) -> Glyphon {
        use glyphon::{Attrs, Buffer, Cache, Family, FontSystem, Metrics, Shaping};
        let mut db = glyphon::fontdb::Database::new();
        db.load_font_source(glyphon::fontdb::Source::Binary(Arc::new(font_bytes)));
        let mut font_system = FontSystem::new_with_locale_and_db("en-US".into(), db);
        let family = font_system
            .db()
            .faces()
            .next()
            .expect("the font reads")
            .families[0]
            .0
            .clone();
        let cache = Cache::new(&gpu.device);
        let mut atlas = glyphon::TextAtlas::new(&gpu.device, &gpu.queue, &cache, FORMAT);
        let renderer = glyphon::TextRenderer::new(
            &mut atlas,
            &gpu.device,
            wgpu::MultisampleState::default(),
            None,
        );
        let viewport = glyphon::Viewport::new(&gpu.device, &cache);
        let attrs = Attrs::new().family(Family::Name(&family));
        let buffers = labels
            .iter()
            .map(|label| {
                let metrics = Metrics::new(label.size_px, label.size_px * 1.2);
                let mut buffer = Buffer::new(&mut font_system, metrics);
                buffer.set_size(None, None);
                buffer.set_text(&label.text, &attrs, Shaping::Advanced, None);
                buffer.shape_until_scroll(&mut font_system, false);
                let baseline = buffer.layout_runs().next().map_or(0.0, |r| r.line_y);
                (buffer, label.x, label.y - baseline)
            })
            .collect();
        Glyphon {
            device: gpu.device.clone(),
            queue: gpu.queue.clone(),
            font_system,
            swash: glyphon::SwashCache::new(),
            atlas,
            viewport,
            renderer,
            buffers,
        }
    }
}

impl Labels for Glyphon {
    fn frame(&mut self, encoder: &mut wgpu::CommandEncoder, view: &wgpu::TextureView, scroll: f32) {
        self.viewport.update(
            &self.queue,
            glyphon::Resolution {
                width: ui::SIZE[0],
                height: ui::SIZE[1],
            },
        );
        let areas = self
            .buffers
            .iter()
            .map(|(buffer, left, top)| glyphon::TextArea {
                buffer,
                left: *left,
                top: *top + scroll,
                scale: 1.0,
                bounds: glyphon::TextBounds::default(),
                default_color: glyphon::Color::rgb(26, 26, 31),
                custom_glyphs: &[],
            });
        self.renderer
            .prepare(
                &self.device,
                &self.queue,
                &mut self.font_system,
                &mut self.atlas,
                &self.viewport,
                areas,
                &mut self.swash,
            )
            .expect("glyphon's atlas holds the labels");
        let mut pass = clearing_pass(encoder, view);
        self.renderer
            .render(&self.atlas, &self.viewport, &mut pass)
            .expect("glyphon draws");
        drop(pass);
        self.atlas.trim();
    }

    fn held_bytes(&self) -> Option<u64> {
        None
    }

    fn glyphs(&self) -> Option<(usize, usize)> {
        None
    }
}

fn clearing_pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    view: &wgpu::TextureView,
) -> wgpu::RenderPass<'e> {
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("labels"),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations {
                load: wgpu::LoadOp::Clear(wgpu::Color::WHITE),
                store: wgpu::StoreOp::Store,
            },
        })],
        ..Default::default()
    })
}

/// The CPU time the whole process has used, every thread (on a software GPU the GPU's
/// work too), milliseconds (Linux: /proc/self/stat, in clock ticks of 10 ms; None
/// elsewhere).
fn process_cpu_ms() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // Fields after the command name, which is in parentheses and may hold spaces.
    let fields: Vec<&str> = stat.rsplit_once(')')?.1.split_whitespace().collect();
    // utime and stime are the stat's fields 14 and 15, the 12th and 13th after ')'.
    let ticks: u64 = fields.get(11)?.parse::<u64>().ok()? + fields.get(12)?.parse::<u64>().ok()?;
    Some(ticks as f64 * 10.0)
}

/// The process's resident memory, bytes (Linux: /proc/self/statm; None elsewhere).
fn resident_bytes() -> Option<u64> {
    let statm = std::fs::read_to_string("/proc/self/statm").ok()?;
    let pages: u64 = statm.split_whitespace().nth(1)?.parse().ok()?;
    Some(pages * 4096)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let mut renderer = "library".to_owned();
    let mut count = ui::LABELS;
    let mut frames = 30usize;
    let mut args = std::env::args().skip(1);
    while let Some(flag) = args.next() {
        let value = args.next().unwrap_or_default();
        match flag.as_str() {
            "--renderer" => renderer = value,
            "--labels" => count = value.parse().unwrap_or(0),
            "--frames" => frames = value.parse().unwrap_or(0),
            _ => {
                eprintln!(
                    "ui_labels: unknown option '{flag}' (--renderer library|glyphon, --labels N, --frames N)"
                );
                std::process::exit(2);
            }
        }
    }
    if count == 0 || frames == 0 || !["library", "glyphon"].contains(&renderer.as_str()) {
        eprintln!("ui_labels: --renderer library|glyphon, --labels and --frames at least 1");
        std::process::exit(2);
    }
    let gpu = match GpuContext::new() {
        Ok(gpu) => gpu,
        Err(e) => {
            eprintln!("ui_labels: {e}");
            std::process::exit(2);
        }
    };
    let Ok(font_bytes) = std::fs::read("fonts/DejaVuSans.ttf") else {
        eprintln!("ui_labels: cannot read fonts/DejaVuSans.ttf: run it from the project's root");
        std::process::exit(2);
    };
    let font = Font::from_bytes(font_bytes.clone(), "DejaVu Sans").expect("the font reads");
    let labels = ui::labels(&font, count, ui::SIZE).expect("the labels lay out");
    let target = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some("ui"),
        size: wgpu::Extent3d {
            width: ui::SIZE[0],
            height: ui::SIZE[1],
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: FORMAT,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
        view_formats: &[],
    });
    let view = target.create_view(&Default::default());
    let before = resident_bytes();

    let mut drawing: Box<dyn Labels> = if renderer == "library" {
        let mut text = TextRenderer::new(&gpu.device, &gpu.queue, FORMAT);
        let font = text.add_font(font_bytes).expect("the font reads");
        Box::new(Library { text, font, labels })
    } else {
        Box::new(Glyphon::new(&gpu, font_bytes, &labels))
    };
    let mut time = |scroll: &dyn Fn(usize) -> f32| -> f64 {
        let mut times = Vec::with_capacity(frames);
        for frame in 0..WARMUP + frames {
            let start = Instant::now();
            let mut encoder = gpu.device.create_command_encoder(&Default::default());
            drawing.frame(&mut encoder, &view, scroll(frame));
            gpu.queue.submit([encoder.finish()]);
            gpu.device
                .poll(wgpu::PollType::wait_indefinitely())
                .expect("the GPU finishes");
            if frame >= WARMUP {
                times.push(start.elapsed().as_secs_f64() * 1e3);
            }
        }
        median(times)
    };
    let still = time(&|_| 0.0);
    let cpu_before = process_cpu_ms();
    let moving = time(&|frame| SCROLL * (frame + 1) as f32);
    // Per frame of the moving phase, warm-up frames included (as many as were timed).
    let moving_cpu = match (cpu_before, process_cpu_ms()) {
        (Some(b), Some(a)) => format!("{:.2}", (a - b) / (WARMUP + frames) as f64),
        _ => "null".into(),
    };
    let after = resident_bytes();
    let growth = match (before, after) {
        (Some(b), Some(a)) => format!("{:.1}", (a as f64 - b as f64) / 1e6),
        _ => "null".into(),
    };
    let held = drawing
        .held_bytes()
        .map_or("null".into(), |b| format!("{:.1}", b as f64 / 1e6));
    let (glyphs, direct) = drawing
        .glyphs()
        .map_or(("null".into(), "null".into()), |(all, direct)| {
            (all.to_string(), direct.to_string())
        });
    println!(
        "{{\"renderer\": \"{renderer}\", \"labels\": {count}, \"still_ms\": {still:.2}, \
         \"moving_ms\": {moving:.2}, \"moving_cpu_ms\": {moving_cpu}, \
         \"resident_growth_mb\": {growth}, \"held_mb\": {held}, \
         \"glyphs\": {glyphs}, \"direct_glyphs\": {direct}, \"adapter\": \"{}\"}}",
        gpu.adapter_name()
    );
}
