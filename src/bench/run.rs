//! Measuring: every method at every setting through [`measure::measure`], the function
//! `render --stats` uses, with the reference rasterized once per scene and camera and
//! shared by every measurement.

use indicatif::{ProgressBar, ProgressStyle};

use super::method_settings::{self, CONTRAST};
use super::motion;
use super::result::{BenchResult, Measurement, Refusal, Rounds, SceneCamera, SceneInfo, Series};
use super::scaling;
use super::scenes::{self, BenchScene};
use super::winding_cost;
use crate::Error;
use crate::camera::Camera;
use crate::effort::Effort;
use crate::gpu::GpuContext;
use crate::measure::{self, FrameTiming, Measured};
use crate::methods::info::{MethodInfo, Role};
use crate::methods::params::assignments;
use crate::methods::registry;
use crate::metrics;
use crate::motion::run::MethodSpec;
use crate::scene::Scene;

/// Untimed frames before each round's timed ones, in a full run and with `--quick`
/// alike (shaders compile lazily on the first frames).
pub const WARMUP_FRAMES: usize = 3;

/// The rounds a case is timed in: [`Effort`]'s, with `frames` (the whole run's timed
/// frames per case, `--frames`) spread over them where given.
pub fn rounds(effort: &Effort, frames: Option<usize>) -> Rounds {
    Rounds {
        rounds: effort.bench_rounds,
        per_round: FrameTiming {
            warmup: WARMUP_FRAMES,
            frames: frames.map_or(effort.bench_frames_per_round, |frames| {
                frames.div_ceil(effort.bench_rounds)
            }),
        },
    }
}

/// What to measure.
#[derive(Clone, Debug)]
pub struct BenchOptions {
    pub quick: bool,
    /// Scene names; empty for all.
    pub scenes: Vec<String>,
    /// Method names (the benched methods of the registry, and the reference); empty
    /// for all.
    pub methods: Vec<String>,
    /// Timed frames per case, over all rounds, overriding [`Effort`]'s (21, or 9
    /// with `quick`; for the scaling series, 5, or 2 with `quick`).
    pub frames: Option<usize>,
    /// Points per scaling series, overriding [`Effort`]'s (11, or 3 with `quick`).
    pub scaling_points: Option<usize>,
    /// A part of the name of the adapter to measure on (see [`GpuContext::open`]).
    pub adapter: Option<String>,
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
fn check(options: &BenchOptions, effort: &Effort) -> Result<Plan, Error> {
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
        None => effort.bench_scaling_points,
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
/// the same zoom and turn) — with `quick`, only the peers' and [`CONTRAST`]'s.
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
        let kept = if quick && method.name != CONTRAST.name && !method.is_peer() {
            0
        } else {
            1
        };
        all.truncate(kept);
    }
    if is_baseline {
        for params in &mut all {
            params.push(method_settings::baseline_cache_param(cache_px_per_em));
        }
    }
    all
}

/// Runs the bench, showing progress on stderr when it is a terminal.
pub fn run(options: &BenchOptions) -> Result<BenchResult, Error> {
    let effort = Effort::of(options.quick);
    let plan = check(options, &effort)?;
    let (chosen, methods) = (&plan.scenes, &plan.methods);
    let scaling_timing = FrameTiming {
        warmup: scaling::WARMUP_FRAMES,
        frames: options.frames.unwrap_or(effort.bench_scaling_frames),
    };
    let scaling_methods = plan.scaling_methods();
    let timing = rounds(&effort, options.frames);
    let gpu = GpuContext::open(options.adapter.as_deref())?;
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
        let cache = method_settings::baseline_cache_size(own_camera.size_px_per_em);
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
            if methods.iter().any(|m| m.name == winding_cost::METHOD.name) {
                progress.set_message(format!(
                    "{} ({view:?}): where {}'s time goes",
                    bench_scene.name,
                    winding_cost::METHOD.name
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
                result.motion.extend(motion::measure(
                    &gpu,
                    bench_scene.name,
                    &here.scene,
                    &here.camera,
                    &defaults,
                    effort.bench_motion_frames,
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
        let works = series.points(plan.scaling_points, &effort);
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
    use crate::metrics::ErrorStats;

    fn timed(gpu_ms: f64, range: (f64, f64), cpu_prepare_ms: f64) -> Measurement {
        Measurement {
            scene: "page".into(),
            scene_camera: SceneCamera::Own,
            method: registry::baseline().name.into(),
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
