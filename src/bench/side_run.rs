//! What the bench's side runs (`--harness`, `--library`) share: the scenes named (or
//! the run's defaults), the rounds, a device with timestamp queries, and the one report
//! each writes into `--out`.

use std::path::{Path, PathBuf};

use super::result::Rounds;
use super::run::rounds;
use super::scenes::{self, BenchScene};
use crate::Error;
use crate::camera::Camera;
use crate::effort::Effort;
use crate::gpu::{CoverageTarget, GpuContext};
use crate::methods::{Method, frame};
use crate::metrics;
use crate::scene::Scene;

/// A side run's scenes, rounds and device.
pub struct SideRun {
    pub scenes: Vec<BenchScene>,
    pub timing: Rounds,
    pub gpu: GpuContext,
    /// ` --scenes a,b` where scenes were named, for the report's command line.
    pub scenes_flag: String,
}

impl SideRun {
    /// Checks the options and opens the device named by `adapter` (see
    /// [`GpuContext::open`]); `what` says what needs its timestamps.
    pub fn open(
        scene_names: &[String],
        defaults: &[&str],
        effort: &Effort,
        frames: Option<usize>,
        adapter: Option<&str>,
        what: &str,
    ) -> Result<SideRun, Error> {
        let names: Vec<&str> = if scene_names.is_empty() {
            defaults.to_vec()
        } else {
            scene_names.iter().map(String::as_str).collect()
        };
        let scenes = names
            .iter()
            .map(|name| scenes::scene(name))
            .collect::<Result<Vec<_>, _>>()?;
        if frames == Some(0) {
            return Err(Error::Input("--frames must be at least 1".into()));
        }
        let gpu = GpuContext::open(adapter)?;
        if !gpu.has_timestamps() {
            return Err(Error::Gpu(format!(
                "'{}' has no timestamp queries: {what}",
                gpu.adapter_name()
            )));
        }
        let scenes_flag = if scene_names.is_empty() {
            String::new()
        } else {
            format!(" --scenes {}", names.join(","))
        };
        Ok(SideRun {
            scenes,
            timing: rounds(effort, frames),
            gpu,
            scenes_flag,
        })
    }
}

/// Writes `report` as `out/file` (the folder made if needed); its path.
pub fn write_report(out: &Path, file: &str, report: &str) -> Result<PathBuf, Error> {
    let cannot =
        |e: std::io::Error| Error::Output(format!("cannot write into '{}': {e}", out.display()));
    std::fs::create_dir_all(out).map_err(cannot)?;
    let path = out.join(file);
    std::fs::write(&path, report).map_err(cannot)?;
    Ok(path)
}

/// One round of a side run's case: `method` prepared for `scene`, then its frames timed
/// through `camera` into `target` after the round's warm-up; the medians of its GPU and
/// CPU milliseconds, or `Err(reason)` where it refuses the view (glyphon: a tilt),
/// which its row shows as n/a. Any other error ends the run.
pub fn time_round(
    gpu: &GpuContext,
    timing: &Rounds,
    method: &mut dyn Method,
    scene: &Scene,
    target: &CoverageTarget,
    camera: &Camera,
) -> Result<Result<(f64, f64), String>, Error> {
    let per_round = timing.per_round;
    let drawn = method.prepare(gpu, scene).and_then(|()| {
        frame::time_frames(
            gpu,
            method,
            target,
            camera,
            per_round.warmup,
            per_round.frames,
        )
    });
    match drawn {
        Ok(times) => {
            let times = times.expect("side runs open devices with timestamps");
            let median = |ms: &dyn Fn(&frame::FrameTime) -> f64| {
                metrics::median(times.iter().map(ms)).unwrap_or(f64::NAN)
            };
            Ok(Ok((median(&|t| t.gpu_ms), median(&|t| t.cpu_ms))))
        }
        Err(Error::Refused(why)) => Ok(Err(why)),
        Err(e) => Err(e),
    }
}
