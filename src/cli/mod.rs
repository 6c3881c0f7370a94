//! The command line: each subcommand's arguments and their help (a file each), mapped
//! to the plain options of the module that does its work (`render`,
//! `stability::command`, `bench::run_to`, `motion::command`, `survey`, `info`), which
//! runs it and returns what is printed here or turned into the exit code; `--quick`
//! picks an [`Effort`](crate::effort::Effort) here, once. The binary dispatches to the
//! `run_*` functions.

mod adapter;
mod bench;
mod info;
mod motion;
mod render;
mod stability;
mod survey;

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};

pub use adapter::AdapterArgs;
pub use bench::{BenchArgs, run_bench};
pub use info::{InfoArgs, run_info};
pub use motion::{MotionArgs, run_motion};
pub use render::{RenderArgs, run_render};
pub use stability::{StabilityArgs, run_stability};
pub use survey::{SurveyArgs, SurveyCommand, run_survey};

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

#[derive(Args, Clone, Debug)]
pub struct ScreenshotsArgs {
    /// Folder to write the PNGs into.
    #[arg(long, default_value = "screenshots")]
    pub out: PathBuf,
}
