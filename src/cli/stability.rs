//! `glyphscope stability`: the hard cases through every method against its claims.

use std::path::PathBuf;

use clap::Args;

use crate::Error;
use crate::effort::Effort;
use crate::stability::command::StabilityOptions;

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
