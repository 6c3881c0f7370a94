//! The command line. `glyphscope render` is the command every later issue and every
//! outside check drives; it lives in the library so tests call exactly what users run.

use std::path::PathBuf;
use std::time::Instant;

use clap::{Args, Parser, Subcommand};
use glam::DVec2;
use serde::Serialize;

use crate::Error;
use crate::camera::{Camera, MAX_IMAGE_SIDE, MAX_SIZE_PX_PER_EM};
use crate::coverage::CoverageImage;
use crate::font::Font;
use crate::gpu::{self, CoverageTarget, GpuContext};
use crate::methods;
use crate::metrics::{self, ErrorStats};
use crate::reference;
use crate::scene::Scene;
use crate::stability::{self, sweep::SweepSize};

#[derive(Parser, Debug)]
#[command(
    name = "glyphscope",
    version,
    about = "Explore how GPUs draw glyphs from their outlines"
)]
pub struct Cli {
    /// With no command, the interactive explorer opens.
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Render text or a glyph to an 8-bit grayscale PNG of linear coverage.
    Render(Box<RenderArgs>),
    /// Regenerate the README's screenshots of the explorer, headlessly.
    Screenshots(ScreenshotsArgs),
    /// Sweep the hard cases through every method against the reference; exit 1 when a
    /// method breaks a bound it claims.
    Stability(StabilityArgs),
    /// Measure every method against the reference and the atlas baseline on the standard
    /// scenes: a Markdown table, CSV, JSON and plots. Run it from the repository root
    /// (the scenes read fonts/).
    Bench(BenchArgs),
}

#[derive(Args, Clone, Debug)]
pub struct ScreenshotsArgs {
    /// Folder to write the PNGs into.
    #[arg(long, default_value = "screenshots")]
    pub out: PathBuf,
}

#[derive(Args, Clone, Debug)]
pub struct StabilityArgs {
    /// The CI size: 4 sub-pixel offsets × 2 rotations instead of 16 × 4.
    #[arg(long)]
    pub quick: bool,
    /// Only these cases (comma-separated names).
    #[arg(long, value_delimiter = ',')]
    pub cases: Option<Vec<String>>,
    /// Only these methods (labels such as 'sdf-cells exact', or method names).
    #[arg(long, value_delimiter = ',')]
    pub methods: Option<Vec<String>>,
    /// Write each worst frame, its error map, and the table (Markdown, JSON) here.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

#[derive(Args, Clone, Debug)]
pub struct BenchArgs {
    /// A few settings per method and few frames: a run of a couple of minutes.
    #[arg(long)]
    pub quick: bool,
    /// Scenes to run, comma-separated (default: all): page, tiny, headlines, edge,
    /// rotated, latin-modern, inter-900, bengali.
    #[arg(long, value_delimiter = ',')]
    pub scenes: Vec<String>,
    /// Methods to run, comma-separated (default: all): reference, winding, sdf-cells,
    /// xor-stencil, tessellation, atlas.
    #[arg(long, value_delimiter = ',')]
    pub methods: Vec<String>,
    /// Frames timed per case, over its rounds (default 21 in 3 rounds; 3 with --quick).
    #[arg(long)]
    pub frames: Option<usize>,
    /// Folder for bench.md, bench.csv, bench.json and the SVG plots.
    #[arg(long, default_value = "bench-out")]
    pub out: PathBuf,
}

/// `glyphscope bench`: runs the bench and writes its outputs; the path of the report on
/// stdout.
pub fn run_bench(args: &BenchArgs) -> Result<(), Error> {
    let options = crate::bench::BenchOptions {
        quick: args.quick,
        scenes: args.scenes.clone(),
        methods: args.methods.clone(),
        frames: args.frames,
    };
    crate::bench::run_to(&options, &args.out)?;
    println!("{}", args.out.join("bench.md").display());
    Ok(())
}

#[derive(Args, Clone, Debug)]
pub struct RenderArgs {
    /// Font file (.ttf/.otf); the embedded DejaVu Sans when absent.
    #[arg(long)]
    pub font: Option<PathBuf>,
    /// Text to shape; '\n' (or a literal backslash-n) starts a new line.
    #[arg(
        long,
        required_unless_present = "glyph_id",
        conflicts_with = "glyph_id"
    )]
    pub text: Option<String>,
    /// One glyph by its id in the font.
    #[arg(long)]
    pub glyph_id: Option<u32>,
    /// Size in pixels per em.
    #[arg(long, allow_negative_numbers = true)]
    pub size: f64,
    /// reference, bounds, winding, sdf-cells, xor-stencil, tessellation or atlas.
    #[arg(long)]
    pub method: String,
    /// Image width; by default the ink box plus a margin.
    #[arg(long)]
    pub width: Option<u32>,
    /// Image height; by default the ink box plus a margin.
    #[arg(long)]
    pub height: Option<u32>,
    /// Baseline origin X,Y in pixels; by default the ink box starts at the margin.
    #[arg(long, value_parser = parse_pair, allow_hyphen_values = true)]
    pub origin: Option<DVec2>,
    /// Matrix A,B,C,D: X = ox + (A·x + B·y)·s, Y = oy − (C·x + D·y)·s.
    #[arg(long, value_parser = parse_matrix, allow_hyphen_values = true)]
    pub matrix: Option<[f64; 4]>,
    /// Moves scene and view together by DX,DY pixels (the image must not change).
    #[arg(long, value_parser = parse_pair, allow_hyphen_values = true)]
    pub world_offset: Option<DVec2>,
    /// Perspective tilt in degrees about the image's horizontal centre line.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub tilt: f64,
    /// Variable-font axis values, TAG=VALUE[,TAG=VALUE...] (e.g. wght=700).
    #[arg(long, value_delimiter = ',', value_parser = parse_variation)]
    pub variation: Vec<(String, f32)>,
    /// Method parameter KEY=VALUE; repeat for several.
    #[arg(long = "param", value_parser = parse_key_value)]
    pub params: Vec<(String, String)>,
    /// Output PNG: grayscale coverage, or the overlay's picture in colour when the
    /// `overlay` parameter is given.
    #[arg(long)]
    pub out: PathBuf,
    /// Also write statistics as JSON.
    #[arg(long)]
    pub stats: Option<PathBuf>,
    /// Also render the reference and write the signed error (red: too much coverage,
    /// blue: too little, full intensity at 0.5); the statistics gain the error figures.
    #[arg(long)]
    pub error_image: Option<PathBuf>,
}

impl RenderArgs {
    /// `render --text TEXT --size SIZE --method reference` in the default font and
    /// frame, with no output: the start of a scene built in code.
    pub fn text(text: &str, size: f64) -> RenderArgs {
        RenderArgs {
            font: None,
            text: Some(text.to_owned()),
            glyph_id: None,
            size,
            method: "reference".into(),
            width: None,
            height: None,
            origin: None,
            matrix: None,
            world_offset: None,
            tilt: 0.0,
            variation: Vec::new(),
            params: Vec::new(),
            out: PathBuf::new(),
            stats: None,
            error_image: None,
        }
    }
}

/// Margin around the ink box of a default frame, pixels.
pub const FRAME_MARGIN_PX: f64 = 4.0;

/// What `render --stats` writes.
#[derive(Clone, Debug, Serialize)]
pub struct RenderStats {
    pub method: String,
    pub params: Vec<(String, String)>,
    pub adapter: String,
    /// Median GPU time of one frame after a warm-up; None for CPU methods.
    pub gpu_ms: Option<f64>,
    /// (min, max) of the timed frames.
    pub gpu_ms_range: Option<(f64, f64)>,
    /// How the frames were timed: timestamp queries, or the CPU's clock where the
    /// device has none.
    pub gpu_clock: Option<String>,
    /// Font outlines and scene for the reference; plus the method's GPU data for GPU
    /// methods.
    pub cpu_prepare_ms: f64,
    /// The reference's rasterization time; None for GPU methods.
    pub cpu_render_ms: Option<f64>,
    /// GPU memory the method holds once it has drawn: its scene data and intermediate
    /// attachments (the coverage target not counted).
    pub gpu_bytes: u64,
    pub width: u32,
    pub height: u32,
    pub size_px_per_em: f64,
    pub instances: usize,
    pub distinct_glyphs: usize,
    /// Sum of coverage over the image, pixels.
    pub covered_area_px: f64,
    /// Error against the reference, when `--error-image` asked for it.
    pub error: Option<ErrorStats>,
    /// Curves evaluated per covered pixel, for methods with that notion.
    pub curves_per_pixel: Option<methods::CurveCost>,
    /// The meshes built, for methods that draw meshes.
    pub mesh: Option<methods::MeshStats>,
}

/// A rendered image, its statistics, and the reference it was compared with (if any).
pub struct Rendered {
    pub image: CoverageImage,
    /// The overlay picture, when the `overlay` parameter asked for one.
    pub overlay: Option<image::RgbImage>,
    pub reference: Option<CoverageImage>,
    pub stats: RenderStats,
}

/// Loads the font, applying `--variation` values.
pub fn load_font(args: &RenderArgs) -> Result<Font, Error> {
    let font = match &args.font {
        Some(path) => Font::from_path(path)?,
        None => Font::default_font(),
    };
    if args.variation.is_empty() {
        Ok(font)
    } else {
        font.with_variations(&args.variation)
    }
}

/// Builds the scene and camera that `args` describe, checking every input.
pub fn scene_and_camera(args: &RenderArgs) -> Result<(Scene, Camera), Error> {
    let size = args.size;
    if !size.is_finite() || size <= 0.0 {
        return Err(Error::Input(format!(
            "--size must be a positive number of px/em, got {size}"
        )));
    }
    if size > MAX_SIZE_PX_PER_EM {
        return Err(Error::Input(format!(
            "--size {size} is over the limit of {MAX_SIZE_PX_PER_EM}"
        )));
    }
    if !methods::METHOD_NAMES.contains(&args.method.as_str()) {
        return Err(Error::Input(format!(
            "unknown method '{}'; choose one of: {}",
            args.method,
            methods::METHOD_NAMES.join(", ")
        )));
    }
    let font = load_font(args)?;
    let scene = match (&args.text, args.glyph_id) {
        (Some(text), _) => Scene::from_text(&font, text)?,
        (None, Some(id)) => Scene::from_glyph_id(&font, id)?,
        (None, None) => return Err(Error::Input("give --text or --glyph-id".into())),
    };
    let mut camera = Camera::new(1, 1, size, DVec2::ZERO);
    if let Some([a, b, c, d]) = args.matrix {
        camera.matrix = Camera::matrix_from_rows(a, b, c, d);
    }
    camera.validate()?;
    // The frame: ink bounds under the matrix, before any tilt (which turns about the
    // frame's centre and so needs the frame first).
    let ink = camera.ink_bounds(&scene)?;
    camera.origin = args
        .origin
        .unwrap_or(DVec2::splat(FRAME_MARGIN_PX) - ink.min);
    let ink_max = ink.max + camera.origin;
    let side = |given: Option<u32>, extent: f64, flag: &str| -> Result<u32, Error> {
        if let Some(v) = given {
            return Ok(v);
        }
        let v = (extent.max(0.0) + FRAME_MARGIN_PX).ceil();
        if v > f64::from(MAX_IMAGE_SIDE) {
            return Err(Error::Input(format!(
                "the text is {v} px {flag} at this size, over the limit of {MAX_IMAGE_SIDE}; \
                 pass --width and --height to view part of it"
            )));
        }
        Ok(v.max(1.0) as u32)
    };
    camera.width = side(args.width, ink_max.x, "wide")?;
    camera.height = side(args.height, ink_max.y, "tall")?;
    camera.world_offset = args.world_offset.unwrap_or(DVec2::ZERO);
    camera.tilt_deg = args.tilt;
    camera.validate()?;
    // Fails early, with a clear message, if the tilt puts ink behind the eye.
    camera.ink_bounds(&scene)?;
    Ok((scene, camera))
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

/// Renders what `args` describe (nothing is written).
pub fn render(args: &RenderArgs) -> Result<Rendered, Error> {
    let start = Instant::now();
    let (scene, camera) = scene_and_camera(args)?;
    let scene_ms = ms_since(start);
    let gpu = match args.method.as_str() {
        "reference" => None,
        _ => Some(GpuContext::new()?),
    };
    let Measured {
        image,
        overlay,
        mut stats,
    } = measure(
        gpu.as_ref(),
        &scene,
        &camera,
        &args.method,
        &args.params,
        RENDER_TIMING,
    )?;
    stats.cpu_prepare_ms += scene_ms;
    let reference = match &args.error_image {
        Some(_) if args.method == "reference" => Some(image.clone()),
        Some(_) => Some(reference::rasterize(&scene, &camera)?),
        None => None,
    };
    if let Some(reference) = &reference {
        stats.error = Some(metrics::compare(&image, reference)?);
    }
    Ok(Rendered {
        image,
        overlay,
        reference,
        stats,
    })
}

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
    method: &str,
    params: &[(String, String)],
    timing: FrameTiming,
) -> Result<Measured, Error> {
    let mut stats = RenderStats {
        method: method.to_owned(),
        params: params.to_vec(),
        adapter: String::new(),
        gpu_ms: None,
        gpu_ms_range: None,
        gpu_clock: None,
        cpu_prepare_ms: 0.0,
        cpu_render_ms: None,
        gpu_bytes: 0,
        width: camera.width,
        height: camera.height,
        size_px_per_em: camera.size_px_per_em,
        instances: scene.instances.len(),
        distinct_glyphs: scene.glyphs.len(),
        covered_area_px: 0.0,
        error: None,
        curves_per_pixel: None,
        mesh: None,
    };
    let mut overlay = None;
    let image = if method == "reference" {
        methods::reject_unknown_params("reference", params, &[])?;
        stats.adapter = "cpu (exact reference rasterizer)".into();
        let start = Instant::now();
        let image = reference::rasterize(scene, camera)?;
        stats.cpu_render_ms = Some(ms_since(start));
        image
    } else {
        let mut method = methods::create(method, params)?;
        let gpu = gpu.ok_or_else(|| Error::Gpu("a GPU method needs a GPU context".into()))?;
        stats.adapter = gpu.adapter_name();
        let target = CoverageTarget::new(gpu, camera.width, camera.height)?;
        let start = Instant::now();
        method.prepare(gpu, scene)?;
        stats.cpu_prepare_ms = ms_since(start);
        gpu::render_frame(gpu, method.as_mut(), &target, camera)?;
        let image = target.readback(gpu)?;
        if methods::param(params, "overlay").is_some_and(|v| v != "none") {
            overlay = Some(target.readback_color(gpu)?);
        }
        stats.curves_per_pixel = method.curves_per_pixel(gpu, camera)?;
        let (mut times, clock) = match gpu::time_frames(
            gpu,
            method.as_mut(),
            &target,
            camera,
            timing.warmup,
            timing.frames,
        )? {
            Some(times) => (times, CLOCK_TIMESTAMPS),
            None => (
                wall_clock_frames(gpu, method.as_mut(), &target, camera, timing)?,
                CLOCK_WALL,
            ),
        };
        times.sort_by(f64::total_cmp);
        if let (Some(first), Some(last)) = (times.first(), times.last()) {
            stats.gpu_ms = metrics::median(times.iter().copied());
            stats.gpu_ms_range = Some((*first, *last));
            stats.gpu_clock = Some(clock.to_owned());
        }
        // After the frames: what a method allocates on its first frame (intermediate
        // attachments, meshes that depend on the camera) counts too.
        stats.gpu_bytes = method.gpu_bytes();
        stats.mesh = method.mesh_stats();
        image
    };
    stats.covered_area_px = image.sum();
    Ok(Measured {
        image,
        overlay,
        stats,
    })
}

/// Frame times from the CPU's clock, for devices without timestamp queries: each frame
/// from encoding to the GPU going idle, so it includes the submission's overhead.
fn wall_clock_frames(
    gpu: &GpuContext,
    method: &mut dyn methods::Method,
    target: &CoverageTarget,
    camera: &Camera,
    timing: FrameTiming,
) -> Result<Vec<f64>, Error> {
    for _ in 0..timing.warmup {
        gpu::render_frame(gpu, method, target, camera)?;
    }
    (0..timing.frames)
        .map(|_| {
            let start = Instant::now();
            gpu::render_frame(gpu, method, target, camera)?;
            Ok(ms_since(start))
        })
        .collect()
}

/// `glyphscope render`: renders, then writes the PNG and, if asked, the statistics.
pub fn run_render(args: &RenderArgs) -> Result<(), Error> {
    let rendered = render(args)?;
    match &rendered.overlay {
        // An overlay is a picture, not coverage: it is written in colour.
        Some(picture) => picture
            .save(&args.out)
            .map_err(|e| Error::Output(format!("cannot write '{}': {e}", args.out.display())))?,
        None => rendered.image.save_png(&args.out)?,
    }
    if let (Some(path), Some(reference)) = (&args.error_image, &rendered.reference) {
        metrics::error_image(&rendered.image, reference, 0.5)
            .save(path)
            .map_err(|e| Error::Output(format!("cannot write '{}': {e}", path.display())))?;
    }
    if let Some(path) = &args.stats {
        let json = serde_json::to_string_pretty(&rendered.stats).expect("stats serialize");
        std::fs::write(path, json + "\n")
            .map_err(|e| Error::Output(format!("cannot write '{}': {e}", path.display())))?;
    }
    Ok(())
}

/// `glyphscope stability`: runs the sweep, prints the table and writes the report.
/// Returns whether every claim held (broken claims are printed to stderr).
pub fn run_stability(args: &StabilityArgs) -> Result<bool, Error> {
    let cases = stability::select_cases(args.cases.as_deref())?;
    let variants = stability::select_variants(args.methods.as_deref())?;
    let size = if args.quick {
        SweepSize::quick()
    } else {
        SweepSize::full()
    };
    let gpu = GpuContext::new()?;
    eprintln!(
        "{} cases × {} methods × {} cameras on {}",
        cases.len(),
        variants.len(),
        size.cameras(),
        gpu.adapter_name()
    );
    let outcomes =
        stability::sweep::run(&gpu, &cases, &variants, &size, |case| eprintln!("  {case}"))?;
    print!("{}", stability::long_table(&outcomes));
    if let Some(dir) = &args.out {
        stability::write_report(dir, &outcomes)?;
    }
    let broken = stability::broken_claims(&outcomes);
    for line in &broken {
        eprintln!("claim broken: {line}");
    }
    Ok(broken.is_empty())
}

pub(crate) fn ms_since(start: Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
}

fn parse_number(s: &str) -> Result<f64, String> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("'{s}' is not a number"))?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("'{s}' is not a finite number"))
    }
}

fn parse_numbers<const N: usize>(s: &str) -> Result<[f64; N], String> {
    let parts: Vec<&str> = s.split(',').collect();
    if parts.len() != N {
        return Err(format!("expected {N} comma-separated numbers, got '{s}'"));
    }
    let mut out = [0.0; N];
    for (o, p) in out.iter_mut().zip(parts) {
        *o = parse_number(p)?;
    }
    Ok(out)
}

fn parse_pair(s: &str) -> Result<DVec2, String> {
    parse_numbers::<2>(s).map(DVec2::from_array)
}

fn parse_matrix(s: &str) -> Result<[f64; 4], String> {
    parse_numbers::<4>(s)
}

fn parse_key_value(s: &str) -> Result<(String, String), String> {
    match s.split_once('=') {
        Some((k, v)) if !k.trim().is_empty() => Ok((k.trim().to_owned(), v.trim().to_owned())),
        _ => Err(format!("expected KEY=VALUE, got '{s}'")),
    }
}

fn parse_variation(s: &str) -> Result<(String, f32), String> {
    let (tag, value) = parse_key_value(s)?;
    if tag.len() != 4 || !tag.is_ascii() {
        return Err(format!(
            "axis tag '{tag}' must be 4 ASCII characters (e.g. wght)"
        ));
    }
    let value = parse_number(&value)?;
    Ok((tag, value as f32))
}
