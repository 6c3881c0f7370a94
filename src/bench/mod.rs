//! `glyphscope bench`: every method at a sweep of its settings on the standard scenes,
//! GPU time against error, side by side with the atlas baseline, in one command.
//!
//! Its files import one way, from the leaves up; none imports a file above it:
//!
//! - leaves: [`scenes`] (the standard scenes, each a `render` command line),
//!   [`method_settings`] (the settings each method is measured at), [`numbers`] (how
//!   reports write a figure), and [`result`] (everything a run measured, as
//!   `bench.json` holds it; it reads `method_settings`' way of naming a setting);
//! - sections, each measuring and writing its own part of the report:
//!   [`scaling`] (how each method's cost grows with the glyphs and with the size),
//!   [`winding_cost`] (where `winding`'s default spends a frame, stage by stage),
//!   [`motion`] (every method's temporal error as text drifts and turns: page, tiny);
//! - [`harness`]: `bench --harness` alone, the atlas's frame step by step against
//!   glyphon's (it names both: it breaks the baseline's frame down);
//! - `run`: measuring the standard scenes through the same function as
//!   `render --stats`, and each section where it applies, with the numbers of
//!   [`crate::effort::Effort`] that `--quick` picks;
//! - [`report`] (the Markdown report, its scene tables and each section's part in
//!   turn, CSV and JSON) and [`plot`] (SVG plots);
//! - this file: [`run_to`], the run and every file it writes.
//!
//! Methods come from the registry: every benched row, the baseline by its role. The
//! bench names a method only for that method's own business, each in one place: the
//! baseline's glyph cache and [`method_settings::CONTRAST`] (`method_settings`), and
//! winding's stage breakdown ([`winding_cost::METHOD`], its record in `result`). In
//! its outputs, the report's prose and column heads call the baseline `atlas`, and the
//! outline-points plot is named for `tessellation`, the one method that reports
//! outline points.

pub mod harness;
pub mod library;
pub mod method_settings;
pub mod motion;
pub mod numbers;
pub mod plot;
pub mod report;
pub mod result;
pub mod run;
pub mod scaling;
pub mod scenes;
pub mod side_run;
pub mod ui;
pub mod winding_cost;

use std::path::Path;

use crate::Error;
pub use result::BenchResult;
use result::Series;
pub use run::{BenchOptions, run};

/// The files every bench run writes into its output folder.
pub const REPORTS: &[&str] = &["bench.md", "bench.json"];
/// The table and plots a run writes when it measured a standard scene.
pub const SCENE_OUTPUTS: &[&str] = &["bench.csv", "time-vs-error.svg", "tessellation-points.svg"];
/// What a run writes when it measured a scaling series.
pub const SCALING_OUTPUTS: &[&str] = &[
    "scaling.csv",
    "scaling-glyph-count.svg",
    "scaling-px-per-em.svg",
];

/// Runs the bench and writes into `out` (created if missing) the [`REPORTS`], and the
/// [`SCENE_OUTPUTS`] and [`SCALING_OUTPUTS`] where it measured scenes and scaling series:
/// a plot with nothing to show is not drawn. The folder is checked before anything is
/// measured, so a bad path fails at once.
pub fn run_to(options: &BenchOptions, out: &Path) -> Result<BenchResult, Error> {
    let cannot =
        |e: std::io::Error| Error::Output(format!("cannot write into '{}': {e}", out.display()));
    std::fs::create_dir_all(out).map_err(cannot)?;
    // Fails now, not after the run, where the folder is not writable.
    let probe = out.join(".glyphscope-bench-probe");
    std::fs::write(&probe, b"").map_err(cannot)?;
    std::fs::remove_file(&probe).map_err(cannot)?;

    let result = run(options)?;
    let write = |name: &str, text: String| std::fs::write(out.join(name), text).map_err(cannot);
    write("bench.md", report::markdown(&result))?;
    write("bench.json", report::json(&result))?;
    if !result.measurements.is_empty() {
        write("bench.csv", report::csv(&result))?;
        plot::time_against_error(&result, &out.join("time-vs-error.svg"))?;
        plot::points_against_error(&result, &out.join("tessellation-points.svg"))?;
    }
    if !result.scaling.is_empty() {
        write("scaling.csv", scaling::csv(&result.scaling))?;
        for series in Series::ALL {
            let points = scaling::series_points(&result.scaling, series);
            if !points.is_empty() {
                let file = format!("scaling-{}.svg", series.name());
                plot::scaling(&points, &result.adapter, &out.join(file))?;
            }
        }
    }
    Ok(result)
}
