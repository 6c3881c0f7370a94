//! `glyphscope bench --harness`: where the atlas's frame goes, step by step, against
//! glyphon's — the frame of the text renderer people ship. Every quad method shares
//! what the atlas's frame is made of besides its one texture fetch (the target, its
//! blend, the quads, the pixel's local position), so this is where the harness's own
//! cost shows; docs/methods/atlas.md quotes it.
//!
//! Each case is the atlas drawn cut short ([`Stage`]) into one kind of target
//! ([`Channels`]): the steps measured in one run, interleaved in rounds as the bench
//! interleaves its cases, each case prepared anew in each round.

use std::fmt::Write as _;
use std::path::Path;

use super::method_settings::{SHIPPED, baseline_cache_param};
use super::side_run::{SideRun, time_round, write_report};
use crate::Error;
use crate::effort::Effort;
use crate::gpu::{Channels, CoverageTarget};
use crate::methods::Method;
use crate::methods::atlas::{self, Atlas, Stage, auto_cache_size};
use crate::metrics;

/// The scenes measured when none are named: the page and the small text, where glyphon
/// draws the bench's own view.
pub const DEFAULT_SCENES: &[&str] = &["page", "tiny"];

/// One case: a stage of the atlas's frame into a kind of target, or glyphon's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Case {
    Atlas(Stage, Channels),
    Glyphon,
}

/// The cases in the report's order: each step's cost is its difference from the row
/// before it on the same target.
const CASES: [Case; 9] = [
    Case::Atlas(Stage::Cleared, Channels::Picture),
    Case::Atlas(Stage::Quads, Channels::Picture),
    Case::Atlas(Stage::Full, Channels::Picture),
    Case::Atlas(Stage::Cleared, Channels::Coverage),
    Case::Atlas(Stage::Quads, Channels::Coverage),
    Case::Atlas(Stage::Mapped, Channels::Coverage),
    Case::Atlas(Stage::Full, Channels::Coverage),
    Case::Atlas(Stage::Interpolated, Channels::Coverage),
    Case::Glyphon,
];

impl Case {
    fn step(self) -> &'static str {
        match self {
            Case::Atlas(Stage::Cleared, _) => "target cleared, nothing drawn",
            Case::Atlas(Stage::Quads, _) => "+ the quads, each fragment writing 1",
            Case::Atlas(Stage::Mapped, _) => "+ the pixel centre mapped to local coordinates",
            Case::Atlas(Stage::Full, _) => "+ the bitmap sampled: the atlas's frame",
            Case::Atlas(Stage::Interpolated, _) => {
                "the atlas's frame, local coordinates interpolated instead of mapped"
            }
            Case::Glyphon => "glyphon's frame (its own atlas, quads and target)",
        }
    }

    fn target(self) -> &'static str {
        match self {
            Case::Atlas(_, Channels::Picture) => "Rgba16Float, added",
            Case::Atlas(_, Channels::Coverage) => "R16Float, added",
            Case::Glyphon => "Rgba8Unorm, alpha-blended",
        }
    }

    fn method(self, cache_px_per_em: f64) -> Result<Box<dyn Method>, Error> {
        let given = [baseline_cache_param(cache_px_per_em)];
        match self {
            Case::Atlas(stage, _) => {
                let params = atlas::INFO.parse_params(&given)?;
                Ok(Box::new(Atlas::staged(&params, stage)))
            }
            // By name: a build without glyphon says so in one line.
            Case::Glyphon => crate::methods::registry::create(SHIPPED, &[]),
        }
    }

    fn channels(self) -> Channels {
        match self {
            Case::Atlas(_, channels) => channels,
            // Its picture is copied into the target after its timed pass, and the copy
            // is not counted (`Method::peer_gpu_time`): the target does not matter.
            Case::Glyphon => Channels::Coverage,
        }
    }
}

/// A case's median GPU and CPU time per frame over the rounds.
struct Timed {
    case: Case,
    gpu_ms: f64,
    cpu_ms: f64,
    /// Why the case could not be drawn (glyphon on a tilted view): its row says n/a.
    refused: Option<String>,
}

/// Measures every case on `scene_names` (their own views) on the adapter named by
/// `adapter` (see [`GpuContext::open`](crate::gpu::GpuContext::open)) and writes `harness.md` into `out`; returns the
/// report's path.
pub fn run_to(
    scene_names: &[String],
    effort: &Effort,
    frames: Option<usize>,
    adapter: Option<&str>,
    out: &Path,
) -> Result<std::path::PathBuf, Error> {
    let SideRun {
        scenes: bench_scenes,
        timing,
        gpu,
        scenes_flag,
    } = SideRun::open(
        scene_names,
        DEFAULT_SCENES,
        effort,
        frames,
        adapter,
        "the harness breakdown times GPU passes",
    )?;
    let mut md = format!(
        "# Where the atlas's time goes\n\n\
         Device: **{}**. `glyphscope bench --harness{}{}`: each case prepared anew in \
         each of {} rounds, its frames timed after {} warm-up frames; the median of the \
         rounds' medians. *GPU ms*: timestamps around the frame; *CPU ms*: recording it. \
         *step*: the difference from the row above on the same target. *× glyphon*: GPU + \
         CPU per frame over glyphon's in the same run.\n",
        gpu.adapter_name(),
        effort.flag,
        scenes_flag,
        timing.rounds,
        timing.per_round.warmup,
    );
    for bench_scene in &bench_scenes {
        let (scene, camera) = bench_scene.args.build()?;
        let cache = auto_cache_size(camera.size_px_per_em);
        let target = |channels| CoverageTarget::new(&gpu, camera.width, camera.height, channels);
        let targets = [target(Channels::Coverage)?, target(Channels::Picture)?];
        let mut samples: Vec<(Vec<f64>, Vec<f64>, Option<String>)> =
            vec![Default::default(); CASES.len()];
        for _ in 0..timing.rounds {
            for (case, (gpu_ms, cpu_ms, refused)) in CASES.iter().zip(&mut samples) {
                if refused.is_some() {
                    continue;
                }
                let mut method = case.method(cache)?;
                let target = &targets[usize::from(case.channels() == Channels::Picture)];
                match time_round(&gpu, &timing, method.as_mut(), &scene, target, &camera)? {
                    Ok((gpu, cpu)) => {
                        gpu_ms.push(gpu);
                        cpu_ms.push(cpu);
                    }
                    // A view the case cannot draw (glyphon: a tilt) is its row's n/a.
                    Err(why) => *refused = Some(why),
                }
            }
        }
        let median = |v: &[f64]| metrics::median(v.iter().copied()).unwrap_or(f64::NAN);
        let timed: Vec<Timed> = CASES
            .iter()
            .zip(&samples)
            .map(|(&case, (gpu_ms, cpu_ms, refused))| Timed {
                case,
                gpu_ms: median(gpu_ms),
                cpu_ms: median(cpu_ms),
                refused: refused.clone(),
            })
            .collect();
        write_scene(
            &mut md,
            bench_scene.name,
            &bench_scene.args.command_line().join(" "),
            &timed,
        );
    }
    write_report(out, "harness.md", &md)
}

/// One scene's table.
fn write_scene(md: &mut String, name: &str, command: &str, timed: &[Timed]) {
    let glyphon = timed
        .iter()
        .find(|t| t.case == Case::Glyphon && t.refused.is_none())
        .map(|t| t.gpu_ms + t.cpu_ms);
    let _ = writeln!(
        md,
        "\n## {name}\n\n`glyphscope render {command}`\n\n\
         | step | target | GPU ms | step ms | CPU ms | × glyphon |\n\
         |---|---|---:|---:|---:|---:|"
    );
    let mut before: Option<&Timed> = None;
    for t in timed {
        if let Some(why) = &t.refused {
            let _ = writeln!(
                md,
                "| {} | {} | n/a — {why} | | | |",
                t.case.step(),
                t.case.target()
            );
            continue;
        }
        let same_target = |b: &&Timed| match (b.case, t.case) {
            (Case::Atlas(_, a), Case::Atlas(_, b)) => a == b,
            _ => false,
        };
        let step = match (t.case, before.filter(same_target)) {
            (_, None) => "—".to_string(),
            (_, Some(b)) => format!("{:+.2}", t.gpu_ms - b.gpu_ms),
        };
        let ratio = glyphon.map_or("—".into(), |g| {
            format!("{:.2}", (t.gpu_ms + t.cpu_ms) / g)
        });
        let _ = writeln!(
            md,
            "| {} | {} | {:.2} | {step} | {:.3} | {ratio} |",
            t.case.step(),
            t.case.target(),
            t.gpu_ms,
            t.cpu_ms,
        );
        before = Some(t);
    }
}
