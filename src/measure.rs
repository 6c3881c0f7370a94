//! One measured frame: a method's image of a scene and what drawing it cost — the one
//! measurement `render --stats`, the bench, the app's sweep and the tests share, so
//! their figures agree.

use web_time::Instant;

use serde::Serialize;

use crate::Error;
use crate::camera::Camera;
use crate::coverage::{CoverageImage, ValueRange};
use crate::gpu::{Channels, CoverageTarget, GpuContext};
use crate::methods;
use crate::methods::frame::{self, FrameTime, ms_since};
use crate::methods::info::MethodInfo;
use crate::metrics::{self, ErrorStats};
use crate::reference;
use crate::scene::Scene;

/// What `render --stats` writes.
#[derive(Clone, Debug, Default, Serialize)]
pub struct RenderStats {
    pub method: String,
    pub params: Vec<(String, String)>,
    pub adapter: String,
    /// Median GPU time of one frame after a warm-up; None for CPU methods.
    pub gpu_ms: Option<f64>,
    /// (min, max) of the timed frames.
    pub gpu_ms_range: Option<(f64, f64)>,
    /// `gpu_ms` with its 95 % interval, a bootstrap over the timed frames
    /// ([`crate::intervals`]).
    pub gpu_ms_interval: Option<crate::intervals::Interval>,
    /// How the frames were timed: timestamp queries, or the CPU's clock where the
    /// device has none.
    pub gpu_clock: Option<String>,
    /// Frames recorded into each timed submission: more than 1 where a frame is short
    /// (`frame::SHORT_FRAME_MS`).
    pub frames_per_submission: Option<u32>,
    /// Untimed frames drawn before the timed ones: the asked warm-up, and more while
    /// the frame time was still falling.
    pub warmup_frames: Option<usize>,
    /// Median CPU time of recording one frame (the method's `encode`: culling, sorting,
    /// mesh building, instance writes), in the same frames; None for CPU methods.
    pub cpu_frame_ms: Option<f64>,
    /// What one frame costs in all: `gpu_ms` + `cpu_frame_ms` (the CPU records the
    /// next frame while the GPU draws this one only where work is pipelined; the
    /// bench ranks by this sum so per-frame CPU work is never left out).
    pub frame_ms: Option<f64>,
    /// Font outlines and scene for the reference; plus the method's GPU data for GPU
    /// methods.
    pub cpu_prepare_ms: f64,
    /// The reference's rasterization time; None for GPU methods.
    pub cpu_render_ms: Option<f64>,
    /// GPU memory the method holds once it has drawn: its scene data and intermediate
    /// attachments (the coverage target not counted).
    pub gpu_bytes: u64,
    /// The part of `gpu_bytes` that caches rasterized glyphs (the atlas's texture), for
    /// methods that keep such a cache.
    pub cache_bytes: Option<u64>,
    pub width: u32,
    pub height: u32,
    pub size_px_per_em: f64,
    pub instances: usize,
    pub distinct_glyphs: usize,
    /// Sum of coverage over the image, pixels.
    pub covered_area_px: f64,
    /// The coverage values as the method wrote them, before overlapping instances'
    /// sums above 1 are taken down to their union: a value below 0, or not finite, is
    /// an artifact (see [`crate::metrics::ErrorStats`]).
    pub coverage_range: Option<ValueRange>,
    /// Error against the reference, when `--error-image` asked for it.
    pub error: Option<ErrorStats>,
    /// Curves evaluated per covered pixel, for methods with that notion.
    pub curves_per_pixel: Option<methods::CurveCost>,
    /// The meshes built, for methods that draw meshes.
    pub mesh: Option<methods::MeshStats>,
    /// For a peer that lays text out itself (glyphon): how far its glyphs lie from
    /// glyphscope's shaping. The error figures include that difference.
    pub layout_offset: Option<methods::LayoutOffset>,
}

/// How many frames are timed, after how many untimed warm-up frames (shaders compile
/// lazily on the first frames).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct FrameTiming {
    pub warmup: usize,
    pub frames: usize,
}

/// `render --stats` times 21 frames after 5 warm-up frames.
pub const RENDER_TIMING: FrameTiming = FrameTiming {
    warmup: 5,
    frames: 21,
};

/// How `gpu_ms` was measured.
pub const CLOCK_TIMESTAMPS: &str = "timestamp queries";
pub const CLOCK_WALL: &str = "wall clock of submit and wait (no timestamp queries)";

/// A method's image of a scene and what was measured drawing it.
pub struct Measured {
    pub image: CoverageImage,
    /// The overlay picture, when the `overlay` parameter asked for one.
    pub overlay: Option<image::RgbImage>,
    /// Everything but `error`; `cpu_prepare_ms` is the method's own preparation.
    pub stats: RenderStats,
}

/// Draws `scene` through `camera` with method `method` and measures it: the one
/// measurement `render --stats` and the bench share, so their figures agree. `gpu` is
/// needed for every method but the reference.
pub fn measure(
    gpu: Option<&GpuContext>,
    scene: &Scene,
    camera: &Camera,
    info: &MethodInfo,
    params: &[(String, String)],
    timing: FrameTiming,
) -> Result<Measured, Error> {
    let mut stats = measure_stats_shell(info, params, scene, camera);
    // Checked for the reference too, which takes none.
    let checked = info.parse_params(params)?;
    let mut overlay = None;
    let image = if info.is_reference() {
        stats.adapter = "cpu (exact reference rasterizer)".into();
        let start = Instant::now();
        let image = reference::rasterize(scene, camera)?;
        stats.cpu_render_ms = Some(ms_since(start));
        image
    } else {
        let mut method = info.create(params)?;
        let gpu = gpu.ok_or_else(|| Error::Gpu("a GPU method needs a GPU context".into()))?;
        stats.adapter = gpu.adapter_name();
        let overlay_drawn = checked.word("overlay").is_some_and(|o| o != "none");
        let channels = Channels::for_overlay(overlay_drawn);
        let target = CoverageTarget::new(gpu, camera.width, camera.height, channels)?;
        let start = Instant::now();
        method.prepare(gpu, scene)?;
        stats.cpu_prepare_ms = ms_since(start);
        frame::render_frame(gpu, method.as_mut(), &target, camera)?;
        let raw = target.readback(gpu)?;
        stats.coverage_range = Some(raw.range());
        let image = raw.clamp_to_union();
        if overlay_drawn {
            overlay = Some(crate::coverage::read_overlay(gpu, &target)?);
        }
        stats.curves_per_pixel = method.curves_per_pixel(gpu, camera)?;
        let timed = time_frames(gpu, method.as_mut(), &target, camera, timing)?;
        timed.write_into(&mut stats);
        // After the frames: what a method allocates on its first frame (intermediate
        // attachments, meshes that depend on the camera) counts too.
        stats.gpu_bytes = method.gpu_bytes();
        stats.cache_bytes = method.cache_bytes();
        stats.mesh = method.mesh_stats();
        stats.layout_offset = method.layout_offset();
        image
    };
    if stats.coverage_range.is_none() {
        stats.coverage_range = Some(image.range());
    }
    stats.covered_area_px = image.sum();
    Ok(Measured {
        image,
        overlay,
        stats,
    })
}

/// The stats of a measurement before anything is measured: what the scene and camera
/// say.
fn measure_stats_shell(
    info: &MethodInfo,
    params: &[(String, String)],
    scene: &Scene,
    camera: &Camera,
) -> RenderStats {
    RenderStats {
        method: info.name.to_owned(),
        params: params.to_vec(),
        width: camera.width,
        height: camera.height,
        size_px_per_em: camera.size_px_per_em,
        instances: scene.instances.len(),
        distinct_glyphs: scene.glyphs.len(),
        ..RenderStats::default()
    }
}

impl RenderStats {
    /// The stats of frames timed alone (no image, no scene figures): what the bench's
    /// later rounds keep of a case.
    pub fn timed_only(params: &[(String, String)], cpu_prepare_ms: f64) -> RenderStats {
        RenderStats {
            params: params.to_vec(),
            cpu_prepare_ms,
            ..RenderStats::default()
        }
    }
}

/// Frames timed, by which clock, and how.
pub struct Timed {
    pub times: Vec<FrameTime>,
    pub clock: &'static str,
    pub frames_per_submission: u32,
    pub warmup_frames: usize,
}

impl Timed {
    /// The medians of the GPU, CPU and whole frame times, the range of the GPU times.
    pub fn write_into(&self, stats: &mut RenderStats) {
        let times = &self.times;
        let gpu_ms = || times.iter().map(|t| t.gpu_ms);
        let Some(median) = metrics::median(gpu_ms()) else {
            return;
        };
        let range = gpu_ms().fold((f64::INFINITY, 0.0f64), |(lo, hi), t| {
            (lo.min(t), hi.max(t))
        });
        stats.gpu_ms = Some(median);
        stats.gpu_ms_range = Some(range);
        stats.gpu_ms_interval = crate::intervals::median_interval(&gpu_ms().collect::<Vec<_>>());
        stats.gpu_clock = Some(self.clock.to_owned());
        stats.cpu_frame_ms = metrics::median(times.iter().map(|t| t.cpu_ms));
        stats.frame_ms = metrics::median(times.iter().map(|t| t.gpu_ms + t.cpu_ms));
        stats.frames_per_submission = Some(self.frames_per_submission);
        stats.warmup_frames = Some(self.warmup_frames);
    }
}

/// GPU and CPU time of `timing.frames` frames after at least `timing.warmup` untimed
/// ones (see [`frame::time_frames_settled`]), by timestamp queries or, where the device
/// has none, the CPU's clock. The target holds the last frame.
pub fn time_frames(
    gpu: &GpuContext,
    method: &mut dyn methods::Method,
    target: &CoverageTarget,
    camera: &Camera,
    timing: FrameTiming,
) -> Result<Timed, Error> {
    match frame::time_frames_settled(gpu, method, target, camera, timing.warmup, timing.frames)? {
        Some(t) => Ok(Timed {
            times: t.times,
            clock: CLOCK_TIMESTAMPS,
            frames_per_submission: t.frames_per_submission,
            warmup_frames: t.warmup_frames,
        }),
        None => Ok(Timed {
            times: wall_clock_frames(gpu, method, target, camera, timing)?,
            clock: CLOCK_WALL,
            frames_per_submission: 1,
            warmup_frames: timing.warmup,
        }),
    }
}

/// A method's frame time alone, prepared anew: what the bench's later rounds measure
/// once a case's image and error are known from its first.
pub fn time_only(
    gpu: &GpuContext,
    scene: &Scene,
    camera: &Camera,
    info: &MethodInfo,
    params: &[(String, String)],
    timing: FrameTiming,
) -> Result<RenderStats, Error> {
    let mut stats = measure_stats_shell(info, params, scene, camera);
    let mut method = info.create(params)?;
    let target = CoverageTarget::new(gpu, camera.width, camera.height, Channels::Coverage)?;
    let start = Instant::now();
    method.prepare(gpu, scene)?;
    stats.cpu_prepare_ms = ms_since(start);
    time_frames(gpu, method.as_mut(), &target, camera, timing)?.write_into(&mut stats);
    Ok(stats)
}

/// Frame times from the CPU's clock, for devices without timestamp queries: each frame
/// from encoding to the GPU going idle, so its "GPU" time includes the submission's
/// overhead and the recording; the recording alone is its CPU time.
fn wall_clock_frames(
    gpu: &GpuContext,
    method: &mut dyn methods::Method,
    target: &CoverageTarget,
    camera: &Camera,
    timing: FrameTiming,
) -> Result<Vec<FrameTime>, Error> {
    for _ in 0..timing.warmup {
        frame::render_frame(gpu, method, target, camera)?;
    }
    (0..timing.frames)
        .map(|_| {
            let start = Instant::now();
            let mut encoder = gpu.device.create_command_encoder(&Default::default());
            method.encode(gpu, &mut encoder, target, camera)?;
            let cpu_ms = ms_since(start);
            gpu.queue.submit([encoder.finish()]);
            gpu.wait_idle()?;
            Ok(FrameTime {
                gpu_ms: ms_since(start) - cpu_ms,
                cpu_ms,
            })
        })
        .collect()
}
