//! The command line: each subcommand's arguments and their help, mapped to the plain
//! options of the module that does its work (`render`, `stability::command`,
//! `bench::run_to`, `motion::command`, `info`), which runs it and returns what is
//! printed here or turned into the exit code; `--quick` picks an [`Effort`] here,
//! once. The binary dispatches to the `run_*` functions.

use std::path::{Path, PathBuf};

use clap::{Args, Parser, Subcommand};

use crate::Error;
use crate::effort::Effort;
use crate::info::InfoOptions;
use crate::magnify::{self, Focus};
use crate::methods::registry;
use crate::motion::command::{MotionOptions, animated_methods};
use crate::motion::{MotionPath, run::MethodSpec};
use crate::render::{PictureOverlay, RenderOptions};
use crate::stability::command::StabilityOptions;
use crate::view_args::{ViewArgs, parse_key_value, parse_variation};

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
    /// Every glyph of your fonts, by glyph id, at several sizes and transforms, through
    /// every method against the reference: survey.csv, survey.json, survey.md (each
    /// method's worst glyphs with explorer links) and contact sheets; exit 1 when a
    /// method breaks its claim on some glyph. `survey merge` joins shards' folders.
    Survey(Box<SurveyArgs>),
    /// Print which outline table a font uses (and why), its units per em and axes, and
    /// for the glyphs asked for their advance, lsb, xMin and the shift applied to them;
    /// with --gpu, the adapter the other commands draw with.
    Info(InfoArgs),
}

impl Command {
    /// The adapter the command asks for by name, if any: the binary offers SwiftShader
    /// to the Vulkan loader only then (see [`crate::gpu::offer_swiftshader`]).
    pub fn adapter(&self) -> Option<&str> {
        match self {
            Command::Render(args) => args.adapter.adapter.as_deref(),
            Command::Bench(args) => args.adapter.adapter.as_deref(),
            Command::Motion(args) => args.adapter.adapter.as_deref(),
            Command::Info(args) => args.adapter.adapter.as_deref(),
            Command::Survey(args) => args.adapter.adapter.as_deref(),
            Command::Screenshots(_) | Command::Stability(_) => None,
        }
    }
}

/// The adapter a command draws with, for the commands that time or compare drawings.
#[derive(Args, Clone, Debug)]
pub struct AdapterArgs {
    /// Draw with the adapter whose name contains NAME (case-insensitive), e.g.
    /// `swiftshader` (Chromium's software Vulkan, where Debian's chromium is installed)
    /// or `llvmpipe`; overrides WGPU_ADAPTER_NAME. The default is wgpu's choice. A name
    /// that matches none lists the adapters found.
    #[arg(long, value_name = "NAME")]
    pub adapter: Option<String>,
}

#[derive(Args, Clone, Debug)]
pub struct ScreenshotsArgs {
    /// Folder to write the PNGs into.
    #[arg(long, default_value = "screenshots")]
    pub out: PathBuf,
}

#[derive(Args, Clone, Debug)]
pub struct InfoArgs {
    /// Font file (.ttf/.otf); the embedded DejaVu Sans when absent.
    #[arg(long)]
    pub font: Option<PathBuf>,
    /// Also report the glyphs this text shapes to, in order of first use.
    #[arg(long, conflicts_with = "glyph_id")]
    pub text: Option<String>,
    /// Also report this glyph, by its id in the font.
    #[arg(long)]
    pub glyph_id: Option<u32>,
    /// Variable-font axis values, TAG=VALUE[,TAG=VALUE...]; a short tag is space-padded.
    #[arg(long, value_delimiter = ',', value_parser = parse_variation)]
    pub variation: Vec<(String, f32)>,
    /// Report the GPU adapter instead of a font: its name, backend, driver and device
    /// type, as `render`, `bench` and `motion` would open it (with the same --adapter).
    #[arg(long, conflicts_with_all = ["font", "text", "glyph_id", "variation"])]
    pub gpu: bool,
    #[command(flatten)]
    pub adapter: AdapterArgs,
    /// With --gpu: refuse (one line, exit 2) where the adapter is a CPU implementation
    /// such as lavapipe or SwiftShader, whose timings say nothing of a GPU.
    #[arg(long, requires = "gpu")]
    pub require_hardware: bool,
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
    /// rotated, latin-modern, inter-900, bengali, arabic, and the scaling series glyph-count
    /// (100 → 30 000 glyphs of the page) and px-per-em (one word at 4 → 4 096 px/em).
    #[arg(long, value_delimiter = ',')]
    pub scenes: Vec<String>,
    /// Methods to run, comma-separated (default: all, the peers included): reference,
    /// winding, sdf-cells, xor-stencil, tessellation, atlas, vello, glyphon, vello-cpu.
    #[arg(long, value_delimiter = ',')]
    pub methods: Vec<String>,
    /// Frames timed per case in each of its least rounds, over them (default 35 in 5
    /// rounds; 9 in 3 with --quick), more where its frames are short;
    /// per point of a scaling series (default 5; 2 with --quick).
    #[arg(long)]
    pub frames: Option<usize>,
    /// Points per scaling series, on a log scale (default 11; 3 with --quick, which
    /// also stops the series at 3 000 glyphs and 256 px/em).
    #[arg(long)]
    pub scaling_points: Option<usize>,
    /// Seconds a case whose ratio to the atlas or glyphon is not yet within ±5 % is
    /// timed on for, over further rounds (default 30; 25 with --quick); 0 times the
    /// least rounds only.
    #[arg(long)]
    pub settle_cap: Option<f64>,
    /// Folder for bench.md, bench.csv, bench.json, scaling.csv and the SVG plots.
    #[arg(long, default_value = "bench-out")]
    pub out: PathBuf,
    /// Only where the atlas's frame goes, step by step, against glyphon's (harness.md;
    /// scenes page and tiny unless --scenes names others; no --methods).
    #[arg(long, conflicts_with_all = ["methods", "scaling_points"])]
    pub harness: bool,
    /// Only what the text library (`glyphscope::text`) costs per frame, beside the
    /// `winding` row, the atlas and glyphon (library.md; scenes page and rotated unless
    /// --scenes names others; no --methods)
    #[arg(long, conflicts_with_all = ["harness", "methods"])]
    pub library: bool,
    #[command(flatten)]
    pub adapter: AdapterArgs,
}

/// `glyphscope survey`'s arguments; `survey merge` instead joins shards.
#[derive(Args, Clone, Debug)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct SurveyArgs {
    #[command(subcommand)]
    pub merge: Option<SurveyCommand>,
    /// Font files (.ttf, .otf, .ttc, .otc) or folders of them (searched with their
    /// subfolders); every face of a collection is surveyed.
    #[arg(long, num_args = 1.., required = true)]
    pub fonts: Vec<PathBuf>,
    /// Sizes in px/em, comma-separated (default 9,12,24,48).
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    pub sizes: Vec<f64>,
    /// Transforms, comma-separated: still, rotate:DEG, skew:K or rotate:DEG+skew:K
    /// (default still,rotate:30).
    #[arg(long, value_delimiter = ',')]
    pub transforms: Vec<String>,
    /// Methods, comma-separated, each NAME or NAME:KEY=VALUE:… (default: every method,
    /// the atlas and every peer, at their default settings). A method named at a
    /// setting its registry row claims for is held to that claim.
    #[arg(long, value_delimiter = ',')]
    pub methods: Vec<String>,
    /// A variable-font instance surveyed besides the default, TAG=VALUE[,TAG=VALUE…];
    /// repeat for more. A font without its axes is surveyed at its default only.
    #[arg(long = "instances", value_parser = parse_instance)]
    pub instances: Vec<Vec<(String, f32)>>,
    /// Only glyph ids FIRST-LAST (or one id).
    #[arg(long, value_parser = parse_glyph_range)]
    pub glyphs: Option<(u16, u16)>,
    /// Survey only shard I of N (0 ≤ I < N): the fonts whose place in the sorted list of
    /// files is I mod N. Join the shards' folders with `survey merge`.
    #[arg(long, value_parser = parse_shard)]
    pub shard: Option<(usize, usize)>,
    /// The folder for the results; a run stopped part way resumes from what it holds.
    #[arg(long, required = true)]
    pub out: Option<PathBuf>,
    #[command(flatten)]
    pub adapter: AdapterArgs,
}

/// `glyphscope survey merge`.
#[derive(Subcommand, Clone, Debug)]
pub enum SurveyCommand {
    /// Join the folders of a survey's shards into the outputs one run would write.
    Merge {
        /// The shards' --out folders.
        #[arg(required = true)]
        dirs: Vec<PathBuf>,
        /// The folder for the merged outputs.
        #[arg(long)]
        out: PathBuf,
    },
}

fn parse_instance(text: &str) -> Result<Vec<(String, f32)>, String> {
    text.split(',').map(parse_variation).collect()
}

fn parse_glyph_range(text: &str) -> Result<(u16, u16), String> {
    let id = |t: &str| {
        t.trim()
            .parse::<u16>()
            .map_err(|_| format!("'{t}' is not a glyph id (0 to 65535)"))
    };
    match text.split_once('-') {
        Some((a, b)) => Ok((id(a)?, id(b)?)),
        None => id(text).map(|g| (g, g)),
    }
}

fn parse_shard(text: &str) -> Result<(usize, usize), String> {
    let (i, n) = text
        .split_once('/')
        .ok_or_else(|| format!("'{text}' is not I/N"))?;
    let number = |t: &str| {
        t.trim()
            .parse::<usize>()
            .map_err(|_| format!("'{t}' is not a whole number"))
    };
    let (i, n) = (number(i)?, number(n)?);
    if i >= n {
        return Err(format!(
            "shard {i} of {n}: I must be under N (shards count from 0)"
        ));
    }
    Ok((i, n))
}

/// `glyphscope survey` (or `survey merge`): the path of survey.md on stdout. Returns
/// whether every claim held.
pub fn run_survey(args: &SurveyArgs) -> Result<bool, Error> {
    if let Some(SurveyCommand::Merge { dirs, out }) = &args.merge {
        return crate::survey::merge(dirs, out);
    }
    let plan = crate::survey::plan::Plan::new(
        &args.sizes,
        &args.transforms,
        &args.methods,
        args.instances.clone(),
        args.glyphs,
    )?;
    crate::survey::run(&crate::survey::SurveyOptions {
        fonts: args.fonts.clone(),
        plan,
        shard: args.shard,
        out: args.out.clone().expect("clap requires --out"),
        adapter: args.adapter.adapter.clone(),
    })
}

/// `glyphscope bench`: runs the bench and writes its outputs; the path of the report on
/// stdout.
pub fn run_bench(args: &BenchArgs) -> Result<(), Error> {
    // The side runs: one report each, the same options.
    type SideRun =
        fn(&[String], bool, Option<usize>, Option<&str>, &Path) -> Result<PathBuf, Error>;
    let side_run: Option<SideRun> = if args.library {
        Some(crate::bench::library::run_to)
    } else if args.harness {
        Some(crate::bench::harness::run_to)
    } else {
        None
    };
    if let Some(run_to) = side_run {
        let report = run_to(
            &args.scenes,
            args.quick,
            args.frames,
            args.adapter.adapter.as_deref(),
            &args.out,
        )?;
        println!("{}", report.display());
        return Ok(());
    }
    let options = crate::bench::BenchOptions {
        quick: args.quick,
        scenes: args.scenes.clone(),
        methods: args.methods.clone(),
        frames: args.frames,
        scaling_points: args.scaling_points,
        settle_cap_s: args.settle_cap,
        adapter: args.adapter.adapter.clone(),
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
    #[command(flatten)]
    pub adapter: AdapterArgs,
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
    /// The method that draws it; one of the registry's (see `--help`), with its
    /// parameters after colons if wanted (`msdf:field=sdf`, as `motion` and `bench`
    /// take them).
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
    #[command(flatten)]
    pub adapter: AdapterArgs,
}

/// `--method`'s help: the registry's names and summaries.
fn method_help() -> String {
    format!(
        "The method that draws it: {}. Its parameters may follow its name after colons \
         (NAME:KEY=VALUE:…), as --param gives them",
        registry::help()
    )
}

/// `glyphscope render`: renders the view and writes the PNG and what else is asked for.
pub fn run_render(args: &RenderArgs) -> Result<(), Error> {
    // `NAME:KEY=VALUE:…`, then `--param`s, which win where both set a key.
    let spec = MethodSpec::parse(&args.method)?;
    crate::render::run(&RenderOptions {
        view: args.view.clone(),
        case: args.case.clone(),
        method: spec.name,
        params: [spec.params, args.params.clone()].concat(),
        out: args.out.clone(),
        stats: args.stats.clone(),
        error_image: args.error_image.clone(),
        magnify: args.magnify,
        focus: args.focus,
        overlays: args.overlays.clone(),
        adapter: args.adapter.adapter.clone(),
    })
}

/// `glyphscope stability`: runs the sweep and the motion stage, printing their tables.
/// Returns whether every claim held (broken claims are printed to stderr).
pub fn run_stability(args: &StabilityArgs) -> Result<bool, Error> {
    crate::stability::command::run(&StabilityOptions {
        effort: Effort::of(args.quick),
        cases: args.cases.clone(),
        methods: args.methods.clone(),
        out: args.out.clone(),
    })
}

/// `glyphscope motion`: runs the methods through the path, writes the report and the
/// animated picture, prints the summary table. The arguments are read in the order
/// their errors are said: the path, the methods, `--animate`, then the view.
pub fn run_motion(args: &MotionArgs) -> Result<(), Error> {
    let path = MotionPath::parse(&args.path)?;
    let methods = args
        .method
        .iter()
        .map(|m| MethodSpec::parse(m))
        .collect::<Result<Vec<_>, _>>()?;
    let animated = animated_methods(&args.animate, &methods)?;
    let (scene, camera) = match &args.case {
        Some(name) => crate::named_views::build(name)?,
        None => args.view.build()?,
    };
    let command = std::env::args()
        .skip(1)
        .map(|a| if a.contains(' ') { format!("'{a}'") } else { a })
        .collect::<Vec<_>>()
        .join(" ");
    let summary = crate::motion::command::run(&MotionOptions {
        scene,
        camera,
        path,
        frames: args.frames as usize,
        methods,
        animated,
        animate_frames: args.animate_frames as usize,
        magnify: args.magnify,
        focus: args.focus,
        out: args.out.clone(),
        command: format!("glyphscope {command}"),
        adapter: args.adapter.adapter.clone(),
    })?;
    print!("{summary}");
    Ok(())
}

/// `glyphscope info`: prints the font's report, or with `--gpu` the adapter's.
pub fn run_info(args: &InfoArgs) -> Result<(), Error> {
    let adapter = args.adapter.adapter.as_deref();
    if args.gpu {
        print!("{}", crate::info::gpu(adapter, args.require_hardware)?);
        return Ok(());
    }
    if adapter.is_some() {
        return Err(Error::Input(
            "info --adapter chooses the adapter that --gpu reports: add --gpu".into(),
        ));
    }
    print!(
        "{}",
        crate::info::run(&InfoOptions {
            font: args.font.clone(),
            text: args.text.clone(),
            glyph_id: args.glyph_id,
            variation: args.variation.clone(),
        })?
    );
    Ok(())
}
