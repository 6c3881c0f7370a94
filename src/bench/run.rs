//! Measuring: every method at every setting through [`measure::measure`], the function
//! `render --stats` uses, with the reference rasterized once per scene and camera and
//! shared by every measurement.

use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;

use super::method_settings;
use super::motion;
use super::scaling::{self, ScalingPoint, Series};
use super::scenes::{self, BenchScene};
use super::winding_cost::{self, WindingCost};
use crate::Error;
use crate::camera::Camera;
use crate::gpu::GpuContext;
use crate::measure::{self, FrameTiming, Measured};
use crate::methods::info::{MethodInfo, Role};
use crate::methods::params::{assignments, settings_text};
use crate::methods::{self, atlas, registry, winding};
use crate::metrics::{self, ErrorStats};
use crate::motion::run::MethodSpec;
use crate::scene::Scene;

/// How each measurement is timed: in `rounds` that interleave a view's measurements,
/// each round preparing the method anew and timing `per_round` frames after its warm-up. On a
/// shared machine load comes and goes; interleaved, it falls on every method alike
/// rather than on whichever ran at the time, and the median of the rounds' medians
/// drops a round that a burst of load spoiled.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Rounds {
    pub rounds: usize,
    pub per_round: FrameTiming,
}

/// The full run: 3 rounds of 7 frames (21 in all, as `render --stats` times).
pub const FULL_ROUNDS: Rounds = Rounds {
    rounds: 3,
    per_round: FrameTiming {
        warmup: 3,
        frames: 7,
    },
};

/// `--quick`: three rounds of three frames each after the full run's warm-up. On
/// lavapipe the first frames after a method is prepared run slow on the small scenes
/// (the atlas on `rotated`: 4.1–4.3 ms for the three frames after one warm-up frame,
/// 2.5 ms after), and a median of three such frames measured the warm-up, not the
/// method. One round measured whatever load the machine had while each case ran: three
/// one-round runs of the same build put `winding` on `rotated` at 1.32×, 2.16× and
/// 3.04× the atlas (a slow spell of a few seconds covering one case's frames).
pub const QUICK_ROUNDS: Rounds = Rounds {
    rounds: 3,
    per_round: FrameTiming {
        warmup: 3,
        frames: 3,
    },
};

/// What to measure.
#[derive(Clone, Debug)]
pub struct BenchOptions {
    pub quick: bool,
    /// Scene names; empty for all.
    pub scenes: Vec<String>,
    /// Method names (the benched methods of the registry, and the reference); empty
    /// for all.
    pub methods: Vec<String>,
    /// Timed frames per case, over all rounds, overriding the default (21, or 3 with
    /// `quick`; for the scaling series, 5, or 2 with `quick`).
    pub frames: Option<usize>,
    /// Points per scaling series, overriding the default (11, or 3 with `quick`).
    pub scaling_points: Option<usize>,
}

/// Which camera a scene is measured through (its view: the scene seen through it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum SceneCamera {
    /// The scene's own camera; the atlas is cached at this size.
    Own,
    /// After caching: zoomed 2.5× and turned 30°; the atlas keeps the cache made for
    /// the scene's own size.
    Moved,
}

impl SceneCamera {
    /// As the report's tables name it.
    pub fn name(self) -> &'static str {
        match self {
            SceneCamera::Own => "own",
            SceneCamera::Moved => "moved",
        }
    }
}

/// One scene through one of its cameras.
#[derive(Clone, Debug, Serialize)]
pub struct SceneInfo {
    pub name: String,
    #[serde(rename = "view")]
    pub scene_camera: SceneCamera,
    pub about: String,
    pub width: u32,
    pub height: u32,
    pub size_px_per_em: f64,
    pub instances: usize,
    pub distinct_glyphs: usize,
    /// The size the atlas caches glyphs at for this scene (both views).
    pub atlas_cache_px_per_em: f64,
    /// The `render` arguments of the view (without --method and --param).
    pub render_args: Vec<String>,
}

/// One method at one setting in one view of one scene.
#[derive(Clone, Debug, Serialize)]
pub struct Measurement {
    pub scene: String,
    #[serde(rename = "view")]
    pub scene_camera: SceneCamera,
    pub method: String,
    pub params: Vec<(String, String)>,
    /// Median GPU time of a frame (the reference: its CPU time), ms.
    pub gpu_ms: Option<f64>,
    /// Fastest and slowest timed frame, ms.
    pub gpu_ms_range: Option<(f64, f64)>,
    /// How the frames were timed (None for the reference).
    pub gpu_clock: Option<String>,
    /// The CPU's work of recording each frame (culling, meshing, instance writes), ms.
    pub cpu_frame_ms: Option<f64>,
    /// What one frame costs in all, GPU + CPU per frame (the reference: its
    /// rasterization), ms: what cases are ranked and divided by.
    pub frame_ms: Option<f64>,
    /// The method's `prepare`, ms (the reference: 0).
    pub cpu_prepare_ms: f64,
    /// The reference's rasterization, ms.
    pub cpu_render_ms: Option<f64>,
    /// Meshes built on the CPU (tessellation), ms, whenever they were built.
    pub mesh_build_ms: Option<f64>,
    pub gpu_bytes: u64,
    pub curves_per_pixel: Option<methods::CurveCost>,
    /// Outline points the meshes are built on (tessellation).
    pub mesh_points: Option<usize>,
    /// A peer's own text layout against glyphscope's shaping (glyphon).
    pub layout_offset: Option<methods::LayoutOffset>,
    pub error: ErrorStats,
}

impl Measurement {
    /// `k=v, k=v`, or `default`.
    pub fn settings(&self) -> String {
        settings_text(&self.params, PER_SCENE_PARAMS)
    }

    /// Whether this is the baseline every time is divided by.
    pub fn is_baseline(&self) -> bool {
        self.method == registry::baseline().name && self.settings() == "default"
    }

    /// Whether this is the reference's own row (its CPU time, no GPU time).
    pub fn is_reference(&self) -> bool {
        self.method == registry::REFERENCE.name
    }
}

/// One view of a scene, ready to measure methods in: its reference drawn once.
struct ViewUnderTest<'a> {
    scene_name: &'a str,
    scene_camera: SceneCamera,
    scene: Scene,
    camera: Camera,
    reference: Measured,
}

impl ViewUnderTest<'_> {
    /// Measures `method` with `params` here, its error against the reference.
    fn measure(
        &self,
        gpu: &GpuContext,
        method: &MethodInfo,
        params: Vec<(String, String)>,
        timing: FrameTiming,
    ) -> Result<Measurement, Error> {
        let reference = &self.reference;
        let (stats, error) = if method.is_reference() {
            let exact = metrics::compare(&reference.image, &reference.image)?;
            (reference.stats.clone(), exact)
        } else {
            let (scene, camera) = (&self.scene, &self.camera);
            let measured = measure::measure(Some(gpu), scene, camera, method, &params, timing)?;
            let error = metrics::compare(&measured.image, &reference.image)?;
            (measured.stats, error)
        };
        Ok(Measurement {
            scene: self.scene_name.to_owned(),
            scene_camera: self.scene_camera,
            method: method.name.to_owned(),
            params,
            gpu_ms: stats.gpu_ms.or(stats.cpu_render_ms),
            gpu_ms_range: stats.gpu_ms_range,
            gpu_clock: stats.gpu_clock,
            cpu_frame_ms: stats.cpu_frame_ms,
            frame_ms: stats.frame_ms.or(stats.cpu_render_ms),
            cpu_prepare_ms: stats.cpu_prepare_ms,
            cpu_render_ms: stats.cpu_render_ms,
            mesh_build_ms: stats.mesh.as_ref().map(|m| m.cpu_build_ms),
            gpu_bytes: stats.gpu_bytes,
            curves_per_pixel: stats.curves_per_pixel,
            mesh_points: stats.mesh.as_ref().map(|m| m.points),
            layout_offset: stats.layout_offset,
            error,
        })
    }
}

/// The parameters the bench sets per scene rather than per setting, left out of a
/// setting's name: the atlas's cache size, the same for every case of a scene.
pub const PER_SCENE_PARAMS: &[&str] = &["cache_px_per_em"];

/// A view of a scene a peer refused to draw, and why (its documented limit).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Refusal {
    pub scene: String,
    #[serde(rename = "view")]
    pub scene_camera: SceneCamera,
    pub method: String,
    pub params: Vec<(String, String)>,
    pub reason: String,
}

/// Everything one run measured.
#[derive(Clone, Debug, Serialize)]
pub struct BenchResult {
    pub adapter: String,
    /// How GPU time was measured (timestamp queries, or the CPU clock).
    pub gpu_clock: Option<String>,
    pub quick: bool,
    pub timing: Rounds,
    pub scenes: Vec<SceneInfo>,
    #[serde(rename = "cases")]
    pub measurements: Vec<Measurement>,
    /// What a peer could not draw, with its reason: shown as "n/a — reason".
    pub refusals: Vec<Refusal>,
    /// How each method is timed at each point of the scaling series.
    pub scaling_timing: FrameTiming,
    /// The scaling series' points, series after series.
    pub scaling: Vec<ScalingPoint>,
    /// Where `winding`'s time goes, per scene and view, where `winding` was measured.
    pub winding_costs: Vec<WindingCost>,
    /// Each method at its default through the camera paths of [`motion::PATHS`], on
    /// the scenes of [`motion::SCENES`] that were run.
    pub motion: Vec<motion::MotionCase>,
}

/// `names` in order, each once: a name given twice is measured once.
fn distinct<T: PartialEq>(names: &[T]) -> Vec<&T> {
    let mut once: Vec<&T> = Vec::with_capacity(names.len());
    for name in names {
        if !once.contains(&name) {
            once.push(name);
        }
    }
    once
}

/// What the options choose: the standard scenes, the scaling series and the methods.
struct Plan {
    scenes: Vec<BenchScene>,
    series: Vec<Series>,
    methods: Vec<&'static MethodInfo>,
    scaling_points: usize,
}

impl Plan {
    /// The methods the scaling series measure: the GPU ones (the reference has no GPU
    /// cost to grow).
    fn scaling_methods(&self) -> Vec<&'static MethodInfo> {
        self.methods
            .iter()
            .copied()
            .filter(|m| !m.is_reference())
            .collect()
    }
}

/// Checks the options, naming what is unknown.
fn check(options: &BenchOptions) -> Result<Plan, Error> {
    let all_names = || {
        scenes::SCENE_NAMES
            .iter()
            .copied()
            .chain(Series::ALL.map(Series::name))
    };
    let names: Vec<&str> = if options.scenes.is_empty() {
        all_names().collect()
    } else {
        distinct(&options.scenes)
            .into_iter()
            .map(String::as_str)
            .collect()
    };
    let (mut chosen, mut series) = (Vec::new(), Vec::new());
    for name in names {
        if let Some(one) = Series::named(name) {
            series.push(one);
        } else if scenes::SCENE_NAMES.contains(&name) {
            chosen.push(scenes::scene(name)?);
        } else {
            return Err(Error::Input(format!(
                "unknown scene '{name}'; choose from: {}",
                all_names().collect::<Vec<_>>().join(", ")
            )));
        }
    }
    let measurable = || std::iter::once(&registry::REFERENCE).chain(registry::benched());
    let methods = if options.methods.is_empty() {
        measurable().collect()
    } else {
        distinct(&options.methods)
            .into_iter()
            .map(|name| {
                measurable().find(|m| m.name == name).ok_or_else(|| {
                    let names: Vec<_> = measurable().map(|m| m.name).collect();
                    Error::Input(format!(
                        "the bench has no method '{name}'; choose from: {}",
                        names.join(", ")
                    ))
                })
            })
            .collect::<Result<Vec<_>, _>>()?
    };
    if options.frames == Some(0) {
        return Err(Error::Input("--frames must be at least 1".into()));
    }
    let scaling_points = match options.scaling_points {
        None if options.quick => scaling::QUICK_POINTS,
        None => scaling::FULL_POINTS,
        Some(n) if (2..=scaling::MAX_POINTS).contains(&n) => n,
        Some(n) => {
            return Err(Error::Input(format!(
                "--scaling-points must be from 2 to {}, got {n}",
                scaling::MAX_POINTS
            )));
        }
    };
    let mut plan = Plan {
        scenes: chosen,
        series,
        methods,
        scaling_points,
    };
    if plan.scaling_methods().is_empty() && !plan.series.is_empty() {
        // Asked for by name, a series with nothing to measure is a mistake; by default,
        // the reference alone simply has no scaling to show.
        if !options.scenes.is_empty() {
            return Err(Error::Input(
                "the scaling series measure GPU methods, and --methods names none".into(),
            ));
        }
        plan.series.clear();
    }
    Ok(plan)
}

/// The settings measured in `view`: every setting in the scene's own view; after
/// caching, the atlas's settings and each other method's default (how they fare under
/// the same zoom and turn) — with `quick`, only `winding`'s, the contrast.
fn settings_for(
    method: &MethodInfo,
    view: SceneCamera,
    quick: bool,
    cache_px_per_em: f64,
) -> Vec<Vec<(String, String)>> {
    if method.is_reference() {
        return vec![Vec::new()];
    }
    let is_baseline = method.role == Role::Baseline;
    let mut all = method_settings::settings(method, quick);
    if view == SceneCamera::Moved && !is_baseline {
        let kept = if quick && method.name != QUICK_MOVED_CONTRAST && !method.is_peer() {
            0
        } else {
            1
        };
        all.truncate(kept);
    }
    if is_baseline {
        for params in &mut all {
            params.push(("cache_px_per_em".into(), cache_px_per_em.to_string()));
        }
    }
    all
}

/// In the view after caching, `--quick` keeps one method's default beside the atlas and
/// the peers: the contrast.
const QUICK_MOVED_CONTRAST: &str = winding::NAME;

/// Runs the bench, showing progress on stderr when it is a terminal.
pub fn run(options: &BenchOptions) -> Result<BenchResult, Error> {
    let plan = check(options)?;
    let (chosen, methods) = (&plan.scenes, &plan.methods);
    let base = if options.quick {
        QUICK_ROUNDS
    } else {
        FULL_ROUNDS
    };
    let scaling_base = if options.quick {
        scaling::QUICK_TIMING
    } else {
        scaling::FULL_TIMING
    };
    let scaling_timing = FrameTiming {
        frames: options.frames.unwrap_or(scaling_base.frames),
        ..scaling_base
    };
    let scaling_methods = plan.scaling_methods();
    let timing = match options.frames {
        Some(frames) => Rounds {
            per_round: FrameTiming {
                frames: frames.div_ceil(base.rounds),
                ..base.per_round
            },
            ..base
        },
        None => base,
    };
    let gpu = GpuContext::new()?;
    let per_view = |view| -> usize {
        methods
            .iter()
            .map(|m| settings_for(m, view, options.quick, 0.0).len())
            .sum()
    };
    let total =
        chosen.len() * (per_view(SceneCamera::Own) + per_view(SceneCamera::Moved)) * timing.rounds
            + plan.series.len() * plan.scaling_points * scaling_methods.len();
    // Hidden by indicatif itself when stderr is not a terminal.
    let progress = ProgressBar::new(total as u64).with_style(
        ProgressStyle::with_template("{elapsed_precise} {wide_bar} {pos}/{len} {msg}")
            .expect("a valid template"),
    );
    let mut result = BenchResult {
        adapter: gpu.adapter_name(),
        gpu_clock: None,
        quick: options.quick,
        timing,
        scenes: Vec::new(),
        measurements: Vec::new(),
        refusals: Vec::new(),
        scaling_timing,
        scaling: Vec::new(),
        winding_costs: Vec::new(),
        motion: Vec::new(),
    };
    for bench_scene in chosen {
        let (_, own_camera) = bench_scene.args.build()?;
        let cache = atlas::auto_cache_size(own_camera.size_px_per_em);
        for view in [SceneCamera::Own, SceneCamera::Moved] {
            let args = match view {
                SceneCamera::Own => bench_scene.args.clone(),
                SceneCamera::Moved => scenes::moved_args(&bench_scene.args, &own_camera),
            };
            let (scene, camera) = args.build()?;
            progress.set_message(format!("{} ({view:?}): reference", bench_scene.name));
            let reference = measure::measure(
                None,
                &scene,
                &camera,
                &registry::REFERENCE,
                &[],
                timing.per_round,
            )?;
            result.scenes.push(SceneInfo {
                name: bench_scene.name.into(),
                scene_camera: view,
                about: bench_scene.about.into(),
                width: camera.width,
                height: camera.height,
                size_px_per_em: camera.size_px_per_em,
                instances: scene.instances.len(),
                distinct_glyphs: scene.glyphs.len(),
                atlas_cache_px_per_em: cache,
                render_args: args.command_line(),
            });
            let here = ViewUnderTest {
                scene_name: bench_scene.name,
                scene_camera: view,
                scene,
                camera,
                reference,
            };
            let plan: Vec<(&MethodInfo, Vec<(String, String)>)> = methods
                .iter()
                .flat_map(|m| {
                    settings_for(m, view, options.quick, cache)
                        .into_iter()
                        .map(move |p| (*m, p))
                })
                .collect();
            let mut rounds = Vec::with_capacity(timing.rounds);
            for _ in 0..timing.rounds {
                let mut round = Vec::with_capacity(plan.len());
                for (method, params) in &plan {
                    let settings: Vec<String> = assignments(params).collect();
                    progress.set_message(format!(
                        "{} ({view:?}): {} {}",
                        bench_scene.name,
                        method.name,
                        settings.join(" ")
                    ));
                    match here.measure(&gpu, method, params.clone(), timing.per_round) {
                        Ok(measured) => round.push(measured),
                        // A peer's documented limit: a result, said once per view.
                        Err(Error::Refused(reason)) => {
                            let refusal = Refusal {
                                scene: bench_scene.name.into(),
                                scene_camera: view,
                                method: method.name.into(),
                                params: params.clone(),
                                reason,
                            };
                            if !result.refusals.contains(&refusal) {
                                result.refusals.push(refusal);
                            }
                        }
                        Err(e) => return Err(e),
                    }
                    progress.inc(1);
                }
                rounds.push(round);
            }
            if methods.iter().any(|m| m.name == winding::NAME) {
                progress.set_message(format!(
                    "{} ({view:?}): where winding's time goes",
                    bench_scene.name
                ));
                let view_name = (bench_scene.name, view);
                result.winding_costs.push(winding_cost::measure(
                    &gpu,
                    view_name,
                    &here.scene,
                    &here.camera,
                    timing,
                )?);
            }
            if view == SceneCamera::Own && motion::SCENES.contains(&bench_scene.name) {
                progress.set_message(format!("{}: in motion", bench_scene.name));
                let defaults: Vec<MethodSpec> = methods
                    .iter()
                    .filter(|m| !m.is_reference())
                    .map(|m| MethodSpec {
                        name: m.name.into(),
                        params: settings_for(m, view, options.quick, cache).swap_remove(0),
                    })
                    .collect();
                let frames = match options.quick {
                    true => motion::QUICK_FRAMES,
                    false => motion::FRAMES,
                };
                result.motion.extend(motion::measure(
                    &gpu,
                    bench_scene.name,
                    &here.scene,
                    &here.camera,
                    &defaults,
                    frames,
                )?);
            }
            for case in combine_rounds(rounds) {
                if result.gpu_clock.is_none() {
                    result.gpu_clock.clone_from(&case.gpu_clock);
                }
                result.measurements.push(case);
            }
        }
    }
    for &series in &plan.series {
        let works = series.points(plan.scaling_points, options.quick);
        let points = scaling::measure_series(
            &gpu,
            series,
            &scaling_methods,
            &works,
            scaling_timing,
            &progress,
        )?;
        if result.gpu_clock.is_none() {
            result.gpu_clock = points
                .iter()
                .flat_map(|p| &p.costs)
                .find_map(|c| c.gpu_clock.clone());
        }
        result.scaling.extend(points);
    }
    progress.finish_and_clear();
    Ok(result)
}

/// Each case's figures over the rounds it was timed in: the median of the rounds'
/// median GPU and preparation times, the fastest and slowest frame of all; the image
/// (and so the error) is the same every round.
fn combine_rounds(rounds: Vec<Vec<Measurement>>) -> Vec<Measurement> {
    let mut rounds = rounds.into_iter();
    let Some(first) = rounds.next() else {
        return Vec::new();
    };
    let rest: Vec<Vec<Measurement>> = rounds.collect();
    first
        .into_iter()
        .enumerate()
        .map(|(i, case)| {
            let all: Vec<&Measurement> = std::iter::once(&case)
                .chain(rest.iter().map(|r| &r[i]))
                .collect();
            let gpu_ms = metrics::median(all.iter().filter_map(|c| c.gpu_ms));
            let cpu_frame_ms = metrics::median(all.iter().filter_map(|c| c.cpu_frame_ms));
            let frame_ms = metrics::median(all.iter().filter_map(|c| c.frame_ms));
            let cpu_prepare_ms =
                metrics::median(all.iter().map(|c| c.cpu_prepare_ms)).unwrap_or(0.0);
            let ranges = all.iter().filter_map(|c| c.gpu_ms_range);
            let gpu_ms_range = ranges.reduce(|a, b| (a.0.min(b.0), a.1.max(b.1)));
            Measurement {
                gpu_ms,
                cpu_frame_ms,
                frame_ms,
                gpu_ms_range,
                cpu_prepare_ms,
                ..case.clone()
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn timed(gpu_ms: f64, range: (f64, f64), cpu_prepare_ms: f64) -> Measurement {
        Measurement {
            scene: "page".into(),
            scene_camera: SceneCamera::Own,
            method: crate::methods::winding::INFO.name.into(),
            params: Vec::new(),
            gpu_ms: Some(gpu_ms),
            gpu_ms_range: Some(range),
            gpu_clock: None,
            cpu_frame_ms: Some(0.0),
            frame_ms: Some(gpu_ms),
            cpu_prepare_ms,
            cpu_render_ms: None,
            mesh_build_ms: None,
            gpu_bytes: 1,
            curves_per_pixel: None,
            mesh_points: None,
            layout_offset: None,
            error: ErrorStats::default(),
        }
    }

    #[test]
    fn rounds_combine_into_medians_and_the_full_range() {
        let combined = combine_rounds(vec![
            vec![timed(10.0, (9.0, 12.0), 3.0)],
            vec![timed(30.0, (25.0, 40.0), 1.0)],
            vec![timed(11.0, (8.0, 11.5), 2.0)],
        ]);
        assert_eq!(combined.len(), 1);
        assert_eq!(combined[0].gpu_ms, Some(11.0), "a spoiled round is dropped");
        assert_eq!(combined[0].gpu_ms_range, Some((8.0, 40.0)));
        assert_eq!(combined[0].cpu_prepare_ms, 2.0);
    }
}
