//! `glyphscope stability`: the sweep, then the hard cases in motion, each stage's tables
//! printed as it ends (the sweep's come before the slower motion stage), the report
//! written, and every broken claim said.

use std::path::PathBuf;

use super::sweep::{self, SweepSize};
use super::{broken_claims, long_table, margin_table, select_cases, select_variants};
use super::{temporal, write_report};
use crate::Error;
use crate::effort::Effort;
use crate::gpu::GpuContext;

/// What to run and where to write it.
#[derive(Clone, Debug)]
pub struct StabilityOptions {
    /// The cameras and frames of the run.
    pub effort: Effort,
    /// Only these cases (by name); all when None.
    pub cases: Option<Vec<String>>,
    /// Only these variants (by label, or a method's name for all of its); all when
    /// None.
    pub methods: Option<Vec<String>>,
    /// Where the worst frames, error maps and tables go, if anywhere.
    pub out: Option<PathBuf>,
}

/// Runs the sweep and the motion stage, printing the tables on stdout and the progress
/// and broken claims on stderr, and writes the report. Returns whether every claim held.
pub fn run(options: &StabilityOptions) -> Result<bool, Error> {
    let cases = select_cases(options.cases.as_deref())?;
    let variants = select_variants(options.methods.as_deref())?;
    let size = SweepSize::of(&options.effort);
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
    let outcomes = sweep::run(&gpu, &cases, &variants, &size, |case| eprintln!("  {case}"))?;
    print!("{}", long_table(&outcomes));
    print!("\n{}", margin_table(&outcomes));
    let motion_frames = options.effort.stability_motion_frames;
    eprintln!("in motion: {} frames of {}", motion_frames, temporal::PATH);
    let in_motion = temporal::run(&gpu, &cases, &variants, motion_frames, |case| {
        eprintln!("  {case}")
    })?;
    print!(
        "\n{}\n{}",
        temporal::table(&in_motion, motion_frames),
        temporal::summary_table(&in_motion)
    );
    if let Some(dir) = &options.out {
        // Only the full sweep of every case and method finds the worst cameras.
        let full =
            options.effort == Effort::FULL && options.cases.is_none() && options.methods.is_none();
        let device = gpu.adapter_name();
        write_report(
            dir,
            &outcomes,
            &in_motion,
            motion_frames,
            full.then_some(device.as_str()),
        )?;
    }
    let mut broken = broken_claims(&outcomes);
    broken.extend(temporal::broken_claims(&in_motion));
    for line in &broken {
        eprintln!("claim broken: {line}");
    }
    Ok(broken.is_empty())
}
