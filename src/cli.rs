//! The command line. `glyphscope render` is the command every figure of the docs and
//! every outside check drives; it lives in the library so tests call exactly what users
//! run.

use std::path::PathBuf;
use web_time::Instant;

use clap::{Args, Parser, Subcommand};

use crate::Error;
use crate::coverage::CoverageImage;
use crate::gpu::GpuContext;
use crate::magnify::{self, Focus, Window};
use crate::measure::{self, Measured, RENDER_TIMING, RenderStats};
use crate::methods::frame::ms_since;
use crate::methods::registry;
use crate::metrics;
use crate::outline_overlay;
use crate::reference;
use crate::stability::{self, sweep::SweepSize};
use crate::view_args::{ViewArgs, parse_key_value};

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
    /// Open the explorer on the view a link describes: its URL fragment, as the
    /// explorer's "Copy link" gives it (`#case=inter-overlaps&a=sdf-cells&magnify=32`).
    #[arg(long, allow_hyphen_values = true)]
    pub view: Option<String>,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Render text or a glyph to an 8-bit grayscale PNG of linear coverage.
    Render(Box<RenderArgs>),
    /// Regenerate the screenshots of the explorer in README and docs/, headlessly.
    Screenshots(ScreenshotsArgs),
    /// Sweep the hard cases through every method against the reference; exit 1 when a
    /// method breaks a bound it claims.
    Stability(StabilityArgs),
    /// Measure every method against the reference and the atlas baseline on the standard
    /// scenes: a Markdown table, CSV, JSON and plots. Run it from the repository root
    /// (the scenes read fonts/).
    Bench(BenchArgs),
    /// Move the camera along a path frame by frame and measure what each method does
    /// between frames against the reference (shimmer): per-frame CSV, a summary, an SVG
    /// plot of temporal error and an animated picture of a magnified window.
    Motion(Box<MotionArgs>),
    /// Print which outline table a font uses (and why), its units per em and axes, and
    /// for the glyphs asked for their advance, lsb, xMin and the shift applied to them.
    Info(crate::info::InfoArgs),
}

#[derive(Args, Clone, Debug)]
pub struct ScreenshotsArgs {
    /// Folder to write the PNGs into.
    #[arg(long, default_value = "screenshots")]
    pub out: PathBuf,
}

#[derive(Args, Clone, Debug)]
pub struct StabilityArgs {
    /// The CI size: 4 sub-pixel offsets × 2 rotations instead of 16 × 4, plus the
    /// cameras where the full sweep found each method worst (data/worst-cameras.csv).
    #[arg(long)]
    pub quick: bool,
    /// Only these cases (comma-separated names).
    #[arg(long, value_delimiter = ',')]
    pub cases: Option<Vec<String>>,
    /// Only these methods (labels such as 'sdf-cells exact', or method names).
    #[arg(long, value_delimiter = ',')]
    pub methods: Option<Vec<String>>,
    /// Write each worst frame, its error map, and the table (Markdown, JSON) here; the
    /// full sweep (no --quick, --cases or --methods) also writes worst-cameras.csv,
    /// the cameras the CI grid reruns (copy it to data/).
    #[arg(long)]
    pub out: Option<PathBuf>,
}

#[derive(Args, Clone, Debug)]
pub struct BenchArgs {
    /// A few settings per method and few frames: a run of a couple of minutes.
    #[arg(long)]
    pub quick: bool,
    /// Scenes to run, comma-separated (default: all): page, tiny, headlines, edge,
    /// rotated, latin-modern, inter-900, bengali, and the scaling series glyph-count
    /// (100 → 30 000 glyphs of the page) and px-per-em (one word at 4 → 4 096 px/em).
    #[arg(long, value_delimiter = ',')]
    pub scenes: Vec<String>,
    /// Methods to run, comma-separated (default: all): reference, winding, sdf-cells,
    /// xor-stencil, tessellation, atlas.
    #[arg(long, value_delimiter = ',')]
    pub methods: Vec<String>,
    /// Frames timed per case, over its rounds (default 21 in 3 rounds; 3 with --quick);
    /// per point of a scaling series (default 5; 2 with --quick).
    #[arg(long)]
    pub frames: Option<usize>,
    /// Points per scaling series, on a log scale (default 11; 3 with --quick, which
    /// also stops the series at 3 000 glyphs and 256 px/em).
    #[arg(long)]
    pub scaling_points: Option<usize>,
    /// Folder for bench.md, bench.csv, bench.json, scaling.csv and the SVG plots.
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
        scaling_points: args.scaling_points,
    };
    crate::bench::run_to(&options, &args.out)?;
    println!("{}", args.out.join("bench.md").display());
    Ok(())
}

/// The view options `--case` replaces (a named view is a whole view).
const VIEW_OPTIONS: [&str; 11] = [
    "font",
    "text",
    "glyph_id",
    "size",
    "width",
    "height",
    "origin",
    "matrix",
    "world_offset",
    "tilt",
    "variation",
];

/// `glyphscope motion`'s arguments.
#[derive(Args, Clone, Debug)]
pub struct MotionArgs {
    #[command(flatten)]
    pub view: ViewArgs,
    /// A named view instead of the view options (see `render --case`).
    #[arg(long, conflicts_with_all = VIEW_OPTIONS)]
    pub case: Option<String>,
    /// The camera's path, its speed per frame: drift:DX,DY (pixels), rotate:DEG or
    /// rotate:DEG@X,Y (counter-clockwise, about the image centre or pixel X,Y), zoom:F,
    /// pulse:LOW,HIGH,PERIOD (size between LOW and HIGH times the base), sway:DEG,PERIOD
    /// (tilt ±DEG), joined by '+'.
    #[arg(long, default_value = crate::motion::DRIFT_X, allow_hyphen_values = true)]
    pub path: String,
    /// Frames drawn (the first is the view itself, at a pulse's LOW size).
    #[arg(long, default_value_t = 32, value_parser = clap::value_parser!(u32).range(2..=100_000))]
    pub frames: u32,
    /// Methods, comma-separated, each NAME or NAME:KEY=VALUE:KEY=VALUE (e.g.
    /// winding:aa=rays:samples=1); peers too.
    #[arg(long, value_delimiter = ',', required = true)]
    pub method: Vec<String>,
    /// The methods the animated picture shows beside the reference (default: the first
    /// two of --method), by their place in --method (1, 2, …) or name.
    #[arg(long, value_delimiter = ',')]
    pub animate: Vec<String>,
    /// Frames in the animated picture (the first ones; at most --frames).
    #[arg(long, default_value_t = 32)]
    pub animate_frames: u32,
    /// The animated picture's magnification: each pixel an N×N block, 24×16 pixels a
    /// panel at the default 12.
    #[arg(long, default_value_t = 12, value_parser = clap::value_parser!(u32).range(2..=i64::from(magnify::MAX_FACTOR)))]
    pub magnify: u32,
    /// The pixel the animated picture is centred on: `worst` (where the first animated
    /// method's largest change beyond the reference's in the run is; the default) or
    /// X,Y.
    #[arg(long)]
    pub focus: Option<Focus>,
    /// Folder for motion.csv, motion.md, motion.json, temporal.svg and motion.png.
    #[arg(long, default_value = "motion-out")]
    pub out: PathBuf,
}

/// `glyphscope render`'s arguments: a view, the method that draws it, and what to write.
#[derive(Args, Clone, Debug)]
pub struct RenderArgs {
    #[command(flatten)]
    pub view: ViewArgs,
    /// A named view instead of the view options: a hard case of `glyphscope stability`
    /// (unturned, at sub-pixel offset 0) or a bench scene (page, tiny, headlines, …),
    /// the views the explorer's Cases menu loads.
    #[arg(long, conflicts_with_all = VIEW_OPTIONS)]
    pub case: Option<String>,
    /// The method that draws it; one of the registry's (see `--help`).
    #[arg(long, help = method_help())]
    pub method: String,
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
    /// Magnify: the PNG, of the frame's size, shows the pixels around `--focus`, each as
    /// an N×N block (1 to 64), with a pixel grid from 8 and each pixel's coverage (and
    /// error, with `--overlay error`) written in its block from 32.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=i64::from(magnify::MAX_FACTOR)))]
    pub magnify: u32,
    /// The pixel the magnified picture is centred on: `worst` (the largest error against
    /// the reference, the default) or X,Y.
    #[arg(long)]
    pub focus: Option<Focus>,
    /// What the (magnified) picture draws over the pixels, comma-separated: `error` (the
    /// signed error against the reference instead of the coverage), `outline` (the exact
    /// curves and their points).
    #[arg(long = "overlay", value_delimiter = ',')]
    pub overlays: Vec<PictureOverlay>,
}

/// A layer of `render`'s magnified picture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum PictureOverlay {
    Error,
    Outline,
}

impl RenderArgs {
    /// `view` drawn by the reference, with no output: the start of a render built in
    /// code.
    pub fn of(view: ViewArgs) -> RenderArgs {
        RenderArgs {
            view,
            case: None,
            method: registry::REFERENCE.name.into(),
            params: Vec::new(),
            out: PathBuf::new(),
            stats: None,
            error_image: None,
            magnify: 1,
            focus: None,
            overlays: Vec::new(),
        }
    }

    /// Whether the PNG is the magnifier's picture rather than the frame's coverage.
    pub fn wants_picture(&self) -> bool {
        self.magnify > 1 || self.focus.is_some() || !self.overlays.is_empty()
    }

    fn wants_reference(&self) -> bool {
        self.error_image.is_some()
            || (self.wants_picture()
                && (self.focus.is_none_or(|f| f == Focus::Worst)
                    || self.overlays.contains(&PictureOverlay::Error)))
    }
}

/// `--method`'s help: the registry's names and summaries.
fn method_help() -> String {
    format!("The method that draws it: {}", registry::help())
}

/// A rendered image, its statistics, and the reference it was compared with (if any).
pub struct Rendered {
    pub image: CoverageImage,
    /// The overlay picture, when the `overlay` parameter asked for one.
    pub overlay: Option<image::RgbImage>,
    pub reference: Option<CoverageImage>,
    pub stats: RenderStats,
    /// The magnifier's picture and the pixels it shows, when one was asked for.
    pub picture: Option<(image::RgbImage, Window)>,
}

/// Renders what `args` describe (nothing is written).
pub fn render(args: &RenderArgs) -> Result<Rendered, Error> {
    let method = registry::find(&args.method)?;
    let start = Instant::now();
    let (scene, camera) = match &args.case {
        Some(name) => crate::named_views::build(name)?,
        None => args.view.build()?,
    };
    let scene_ms = ms_since(start);
    let gpu = if method.is_reference() {
        None
    } else {
        Some(GpuContext::new()?)
    };
    let Measured {
        image,
        overlay,
        mut stats,
    } = measure::measure(
        gpu.as_ref(),
        &scene,
        &camera,
        method,
        &args.params,
        RENDER_TIMING,
    )?;
    stats.cpu_prepare_ms += scene_ms;
    let reference = match args.wants_reference() {
        true if method.is_reference() => Some(image.clone()),
        true => Some(reference::rasterize(&scene, &camera)?),
        false => None,
    };
    if let Some(reference) = &reference {
        stats.error = Some(metrics::compare(&image, reference)?);
    }
    let picture = if args.wants_picture() {
        let focus = args.focus.unwrap_or(Focus::Worst);
        let pixel = focus.pixel(image.width, image.height, stats.error.as_ref())?;
        let window = Window::around(image.width, image.height, args.magnify, pixel);
        let outline = if args.overlays.contains(&PictureOverlay::Outline) {
            let tolerance_px = 0.2 / f64::from(window.factor);
            Some(
                outline_overlay::trace(
                    &scene,
                    &camera,
                    &window.rect(),
                    tolerance_px,
                    f64::from(window.factor),
                )
                .map_err(Error::Input)?,
            )
        } else {
            None
        };
        let layers = magnify::Layers {
            overlay: overlay.as_ref(),
            error_against: reference
                .as_ref()
                .filter(|_| args.overlays.contains(&PictureOverlay::Error)),
            outline: outline.as_ref(),
        };
        let picture = magnify::picture(&image, &window, &layers, image.width, image.height);
        Some((picture, window))
    } else {
        None
    };
    Ok(Rendered {
        image,
        overlay,
        reference,
        stats,
        picture,
    })
}

/// `glyphscope render`: renders, then writes the PNG and, if asked, the statistics.
pub fn run_render(args: &RenderArgs) -> Result<(), Error> {
    let rendered = render(args)?;
    let colour = rendered
        .picture
        .as_ref()
        .map(|(picture, _)| picture)
        .or(rendered.overlay.as_ref());
    match colour {
        // A picture is not coverage: it is written in colour.
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
        /// The statistics, and the magnified window where there is one.
        #[derive(serde::Serialize)]
        struct Written<'a> {
            #[serde(flatten)]
            stats: &'a RenderStats,
            #[serde(skip_serializing_if = "Option::is_none")]
            magnified: Option<Window>,
        }
        let written = Written {
            stats: &rendered.stats,
            magnified: rendered.picture.as_ref().map(|(_, window)| *window),
        };
        let json = serde_json::to_string_pretty(&written).expect("stats serialize");
        std::fs::write(path, json + "\n")
            .map_err(|e| Error::Output(format!("cannot write '{}': {e}", path.display())))?;
    }
    Ok(())
}

/// `glyphscope motion`: runs the methods through the path, writes the report and the
/// animated picture, prints the summary table.
pub fn run_motion(args: &MotionArgs) -> Result<(), Error> {
    use crate::motion::{MotionPath, report, run};
    let path = MotionPath::parse(&args.path)?;
    let specs = args
        .method
        .iter()
        .map(|m| run::MethodSpec::parse(m))
        .collect::<Result<Vec<_>, _>>()?;
    let animated = animated_methods(&args.animate, &specs)?;
    let (scene, camera) = match &args.case {
        Some(name) => crate::named_views::build(name)?,
        None => args.view.build()?,
    };
    // A pixel outside the frame is bad input: said before anything is measured.
    let chosen_focus = match args.focus {
        Some(Focus::Pixel(x, y)) => {
            Some(Focus::Pixel(x, y).pixel(camera.width, camera.height, None)?)
        }
        _ => None,
    };
    let needs_gpu = specs.iter().any(|s| s.name != registry::REFERENCE.name);
    let gpu = needs_gpu.then(GpuContext::new).transpose()?;
    let frames = args.frames as usize;
    let bar = indicatif::ProgressBar::new(frames as u64);
    let result = run::run(gpu.as_ref(), &scene, &camera, &path, frames, &specs, |_| {
        bar.inc(1)
    })?;
    bar.finish_and_clear();
    let command = std::env::args()
        .skip(1)
        .map(|a| if a.contains(' ') { format!("'{a}'") } else { a })
        .collect::<Vec<_>>()
        .join(" ");
    report::write(&result, &args.out, &format!("glyphscope {command}"))?;
    // The animated picture: a window around the focus, drawn again for the methods
    // shown (the run keeps no frames).
    let shown = animated
        .iter()
        .filter(|&&k| result.methods[k].refused.is_none())
        .copied()
        .collect::<Vec<_>>();
    if let Some(&first) = shown.first() {
        let animate_frames = (args.animate_frames as usize).clamp(2, frames);
        let panel = 288 / args.magnify;
        let (cols, rows) = (
            panel.min(camera.width),
            (192 / args.magnify).min(camera.height),
        );
        // The pixel of the largest change of the run (the worst pair's worst pixel);
        // the frame's centre when the method changed nothing the reference did not.
        let focus = chosen_focus.unwrap_or_else(|| {
            result.methods[first]
                .frames
                .iter()
                .filter_map(|f| f.temporal.map(|t| (t.max, t.worst_pixel)))
                .filter(|(max, _)| *max > 0.0)
                .max_by(|a, b| a.0.total_cmp(&b.0))
                .map_or((camera.width / 2, camera.height / 2), |w| w.1)
        });
        let x0 = focus.0.saturating_sub(cols / 2).min(camera.width - cols);
        let y0 = focus.1.saturating_sub(rows / 2).min(camera.height - rows);
        let draw = |spec: &run::MethodSpec| {
            run::window_frames(
                gpu.as_ref(),
                &scene,
                &camera,
                &path,
                animate_frames,
                spec,
                (x0, y0, cols, rows),
            )
        };
        let reference_spec = run::MethodSpec::parse(registry::REFERENCE.name)?;
        let reference = draw(&reference_spec)?;
        let mut panels = vec![report::Panel {
            label: "reference".into(),
            frames: reference.clone(),
            against: None,
        }];
        for &k in &shown {
            panels.push(report::Panel {
                label: specs[k].label(),
                frames: draw(&specs[k])?,
                against: Some(reference.clone()),
            });
        }
        report::animation(&panels, args.magnify, &args.out.join("motion.png"))?;
        eprintln!(
            "animated: pixels ({x0}, {y0}) to ({}, {}), frames 0 to {}",
            x0 + cols - 1,
            y0 + rows - 1,
            animate_frames - 1
        );
    }
    print!(
        "{}",
        report::markdown(&result, &format!("glyphscope {command}"))
    );
    Ok(())
}

/// Indices into `specs` of the methods `--animate` names (default the first two).
fn animated_methods(
    names: &[String],
    specs: &[crate::motion::run::MethodSpec],
) -> Result<Vec<usize>, Error> {
    if names.is_empty() {
        return Ok((0..specs.len().min(2)).collect());
    }
    names
        .iter()
        .map(|name| {
            if let Ok(k) = name.trim().parse::<usize>() {
                return (1..=specs.len())
                    .contains(&k)
                    .then_some(k - 1)
                    .ok_or_else(|| {
                        Error::Input(format!(
                            "--animate {k}: --method lists {} methods",
                            specs.len()
                        ))
                    });
            }
            specs
                .iter()
                .position(|s| s.name == name.trim() || s.label() == name.trim())
                .ok_or_else(|| Error::Input(format!("--animate '{name}' is not one of --method")))
        })
        .collect()
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
    let frames: usize = cases.iter().map(|c| size.cameras_for(c).len()).sum();
    eprintln!(
        "{} cases × {} methods, {frames} frames each (cameras per case: {}, a full turn \
         and known worst cameras more) on {}",
        cases.len(),
        variants.len(),
        size.grid_cameras(),
        gpu.adapter_name()
    );
    let outcomes =
        stability::sweep::run(&gpu, &cases, &variants, &size, |case| eprintln!("  {case}"))?;
    print!("{}", stability::long_table(&outcomes));
    print!("\n{}", stability::margin_table(&outcomes));
    let motion_frames = if args.quick {
        stability::temporal::QUICK_FRAMES
    } else {
        stability::temporal::FRAMES
    };
    eprintln!(
        "in motion: {} frames of {}",
        motion_frames,
        stability::temporal::PATH
    );
    let in_motion = stability::temporal::run(&gpu, &cases, &variants, motion_frames, |case| {
        eprintln!("  {case}")
    })?;
    print!(
        "\n{}\n{}",
        stability::temporal::table(&in_motion, motion_frames),
        stability::temporal::summary_table(&in_motion)
    );
    if let Some(dir) = &args.out {
        // Only the full sweep of every case and method finds the worst cameras.
        let full = !args.quick && args.cases.is_none() && args.methods.is_none();
        let device = gpu.adapter_name();
        stability::write_report(
            dir,
            &outcomes,
            &in_motion,
            motion_frames,
            full.then_some(device.as_str()),
        )?;
    }
    let mut broken = stability::broken_claims(&outcomes);
    broken.extend(stability::temporal::broken_claims(&in_motion));
    for line in &broken {
        eprintln!("claim broken: {line}");
    }
    Ok(broken.is_empty())
}
