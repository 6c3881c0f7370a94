//! `glyphscope bench`: the interleaved timing run, or one of its side runs.

use std::path::{Path, PathBuf};

use clap::Args;

use super::adapter::AdapterArgs;
use crate::Error;
use crate::effort::Effort;

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
    /// winding, sdf-cells, xor-stencil, tessellation, atlas, vello, glyphon, vello-cpu,
    /// msdf, and your own as wgsl:PATH (docs/your-method.md).
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

/// `glyphscope bench`: runs the bench and writes its outputs; the path of the report on
/// stdout.
pub fn run_bench(args: &BenchArgs) -> Result<(), Error> {
    // The side runs: one report each, the same options.
    type SideRun =
        fn(&[String], &Effort, Option<usize>, Option<&str>, &Path) -> Result<PathBuf, Error>;
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
            &Effort::of(args.quick),
            args.frames,
            args.adapter.adapter.as_deref(),
            &args.out,
        )?;
        println!("{}", report.display());
        return Ok(());
    }
    let options = crate::bench::BenchOptions {
        effort: Effort::of(args.quick),
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
