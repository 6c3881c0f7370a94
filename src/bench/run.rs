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
use crate::gpu::{Channels, CoverageTarget};
use crate::intervals;
use crate::measure::{self, FrameTiming, Measured};
use crate::methods::frame::{self, ms_since};
use crate::methods::info::{MethodInfo, Role};
use crate::methods::params::assignments;
use crate::methods::registry;
use crate::metrics;
use crate::motion::run::MethodSpec;
use crate::scene::Scene;
use web_time::Instant;

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
    /// How much to measure: what `--quick` picks.
    pub effort: Effort,
    /// Scene names; empty for all.
    pub scenes: Vec<String>,
    /// Method names (the benched methods of the registry, and the reference); empty
    /// for all.
    pub methods: Vec<String>,
    /// Timed frames per case, over all rounds, overriding [`Effort`]'s
    /// (`bench_rounds` × `bench_frames_per_round`; for the scaling series,
    /// `bench_scaling_frames`).
    pub frames: Option<usize>,
    /// Points per scaling series, overriding [`Effort`]'s `bench_scaling_points`.
    pub scaling_points: Option<usize>,
    /// Seconds an unsettled case is timed on for, overriding [`Effort`]'s
    /// `bench_settle_cap_s`; 0 for the least rounds only.
    pub settle_cap_s: Option<f64>,
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
            frame_ms_interval: None,
            ratio_atlas: None,
            ratio_glyphon: None,
            rounds: 1,
            frames_per_submission: stats.frames_per_submission,
            warmup_frames: stats.warmup_frames,
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
                // A user's file is measured as the rows are (`wgsl:PATH`).
                if name.starts_with(crate::methods::user::PREFIX) {
                    return registry::find(name);
                }
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
    if let Some(cap) = options.settle_cap_s
        && !(cap >= 0.0 && cap.is_finite())
    {
        return Err(Error::Input(format!(
            "--settle-cap must be a number of seconds, 0 or more, got {cap}"
        )));
    }
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
    effort: &Effort,
    cache_px_per_em: f64,
) -> Vec<Vec<(String, String)>> {
    if method.is_reference() {
        return vec![Vec::new()];
    }
    let is_baseline = method.role == Role::Baseline;
    let mut all = method_settings::settings(method, effort.bench_every_setting);
    if view == SceneCamera::Moved && !is_baseline {
        // After caching, --quick keeps the contrast, the peers and a user's file (its
        // one setting is why it was named).
        let kept = if !effort.bench_every_setting
            && method.name != CONTRAST.name
            && !method.is_peer()
            && !method.name.starts_with(crate::methods::user::PREFIX)
        {
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
    let effort = options.effort;
    let plan = check(options, &effort)?;
    let (chosen, methods) = (&plan.scenes, &plan.methods);
    let scaling_timing = FrameTiming {
        warmup: scaling::WARMUP_FRAMES,
        frames: options.frames.unwrap_or(effort.bench_scaling_frames),
    };
    let scaling_methods = plan.scaling_methods();
    let timing = rounds(&effort, options.frames);
    let settle_cap_s = options.settle_cap_s.unwrap_or(effort.bench_settle_cap_s);
    let gpu = GpuContext::open(options.adapter.as_deref())?;
    let per_view = |view| -> usize {
        methods
            .iter()
            .map(|m| settings_for(m, view, &effort, 0.0).len())
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
        adapter_class: gpu
            .adapter_info()
            .map_or(crate::info::AdapterClass::Other, |i| {
                crate::info::AdapterClass::of(&i)
            }),
        settle_cap_s,
        gpu_clock: None,
        quick: effort == Effort::QUICK,
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
                    settings_for(m, view, &effort, cache)
                        .into_iter()
                        .map(move |p| (*m, p))
                })
                .collect();
            // The first round: each case's image, error and first timing.
            let mut first = Vec::with_capacity(plan.len());
            for (method, params) in &plan {
                let settings: Vec<String> = assignments(params).collect();
                progress.set_message(format!(
                    "{} ({view:?}): {} {}",
                    bench_scene.name,
                    method.name,
                    settings.join(" ")
                ));
                match here.measure(&gpu, method, params.clone(), timing.per_round) {
                    Ok(measured) => first.push((*method, measured)),
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
                progress.inc(timing.rounds as u64);
            }
            progress.set_message(format!(
                "{} ({view:?}): settling the ratios",
                bench_scene.name
            ));
            let cases = settle_rounds(&gpu, &here, first, timing, settle_cap_s)?;
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
                        params: settings_for(m, view, &effort, cache).swap_remove(0),
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
            for case in cases {
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

/// One case's timing, round by round: per round, the medians of its frames (GPU + CPU,
/// GPU, CPU) or None where it was not timed in that round.
struct CaseRounds<'a> {
    method: &'a MethodInfo,
    first: Measurement,
    frame: Vec<Option<f64>>,
    gpu: Vec<Option<f64>>,
    cpu: Vec<Option<f64>>,
    range: Option<(f64, f64)>,
    prepare: Vec<f64>,
    per_submission: Option<u32>,
    warmup: Option<usize>,
    /// Seconds spent timing it.
    spent_s: f64,
}

impl CaseRounds<'_> {
    fn push(&mut self, frame: Option<f64>, gpu: Option<f64>, cpu: Option<f64>) {
        self.frame.push(frame);
        self.gpu.push(gpu);
        self.cpu.push(cpu);
    }

    /// Whether its ratio to each of `anchors` (other than itself) is settled, or, with
    /// none to divide by, its own frame time.
    fn settled(&self, anchors: &[&CaseRounds<'_>]) -> bool {
        let others: Vec<_> = anchors
            .iter()
            .filter(|a| !std::ptr::eq(**a, self))
            .collect();
        if others.is_empty() {
            let frames: Vec<f64> = self.frame.iter().flatten().copied().collect();
            return intervals::median_interval(&frames).is_some_and(|i| i.settled);
        }
        others
            .iter()
            .all(|a| intervals::paired_ratio(&self.frame, &a.frame).is_some_and(|r| r.settled))
    }
}

/// Times a view's cases in further rounds, interleaved, each preparing the method anew,
/// until every ratio to the anchors (the atlas baseline's default and glyphon's) is
/// settled (`settle`) or each unsettled case has been timed for `cap_s` seconds; at
/// least `timing.rounds` rounds in all. Returns the cases with their figures over all
/// their rounds and their ratios' intervals. The reference (no GPU time) is measured
/// once.
fn settle_rounds(
    gpu: &GpuContext,
    view: &ViewUnderTest<'_>,
    first: Vec<(&MethodInfo, Measurement)>,
    timing: Rounds,
    cap_s: f64,
) -> Result<Vec<Measurement>, Error> {
    let mut cases: Vec<CaseRounds<'_>> = first
        .into_iter()
        .map(|(method, m)| CaseRounds {
            method,
            frame: vec![m.frame_ms],
            gpu: vec![m.gpu_ms],
            cpu: vec![m.cpu_frame_ms],
            range: m.gpu_ms_range,
            prepare: vec![m.cpu_prepare_ms],
            per_submission: m.frames_per_submission,
            warmup: m.warmup_frames,
            spent_s: 0.0,
            first: m,
        })
        .collect();
    let is_anchor = |c: &Measurement| c.is_baseline() || is_shipped_default(c);
    let timed: Vec<usize> = (0..cases.len())
        .filter(|&i| !cases[i].first.is_reference() && cases[i].first.frame_ms.is_some())
        .collect();
    let anchors: Vec<usize> = timed
        .iter()
        .copied()
        .filter(|&i| is_anchor(&cases[i].first))
        .collect();
    let budget_s = cap_s * timed.len() as f64;
    let started = Instant::now();
    for round in 1.. {
        let anchor_refs: Vec<&CaseRounds<'_>> = anchors.iter().map(|&i| &cases[i]).collect();
        let unsettled: Vec<usize> = timed
            .iter()
            .copied()
            .filter(|&i| !cases[i].settled(&anchor_refs) && cases[i].spent_s < cap_s)
            .collect();
        let least_done = round >= timing.rounds;
        if least_done && (unsettled.is_empty() || started.elapsed().as_secs_f64() > budget_s) {
            break;
        }
        let this_round: Vec<usize> = timed
            .iter()
            .copied()
            .filter(|i| !least_done || unsettled.contains(i) || anchors.contains(i))
            .collect();
        // Each round starts one case later, so that no case always follows the same one.
        let start = round % this_round.len().max(1);
        for case in cases.iter_mut() {
            case.push(None, None, None);
        }
        let order: Vec<usize> = (0..this_round.len())
            .map(|k| this_round[(start + k) % this_round.len()])
            .collect();
        let figures = time_round(gpu, view, &order, &cases, timing.per_round)?;
        for (i, (stats, spent_s)) in order.into_iter().zip(figures) {
            let case = &mut cases[i];
            case.spent_s += spent_s;
            let last = case.frame.len() - 1;
            case.frame[last] = stats.frame_ms;
            case.gpu[last] = stats.gpu_ms;
            case.cpu[last] = stats.cpu_frame_ms;
            case.prepare.push(stats.cpu_prepare_ms);
            if let Some((lo, hi)) = stats.gpu_ms_range {
                case.range = Some(case.range.map_or((lo, hi), |(a, b)| (a.min(lo), b.max(hi))));
            }
            case.warmup = case.warmup.max(stats.warmup_frames);
            case.per_submission = case.per_submission.max(stats.frames_per_submission);
        }
    }
    let find = |pick: &dyn Fn(&Measurement) -> bool| {
        anchors.iter().copied().find(|&i| pick(&cases[i].first))
    };
    let baseline = find(&|c| c.is_baseline());
    let shipped = find(&is_shipped_default);
    let ratio = |i: usize, over: Option<usize>| {
        over.filter(|&o| o != i)
            .and_then(|o| intervals::paired_ratio(&cases[i].frame, &cases[o].frame))
    };
    Ok((0..cases.len())
        .map(|i| {
            let c = &cases[i];
            if !timed.contains(&i) {
                return c.first.clone();
            }
            let values = |v: &[Option<f64>]| v.iter().flatten().copied().collect::<Vec<_>>();
            let frames = values(&c.frame);
            Measurement {
                gpu_ms: metrics::median(values(&c.gpu)),
                cpu_frame_ms: metrics::median(values(&c.cpu)),
                frame_ms: metrics::median(frames.iter().copied()),
                frame_ms_interval: intervals::median_interval(&frames),
                gpu_ms_range: c.range,
                cpu_prepare_ms: metrics::median(c.prepare.iter().copied()).unwrap_or(0.0),
                ratio_atlas: ratio(i, baseline),
                ratio_glyphon: ratio(i, shipped),
                rounds: frames.len(),
                frames_per_submission: c.per_submission,
                warmup_frames: c.warmup,
                ..c.first.clone()
            }
        })
        .collect())
}

/// A case's part of a timing round lasts at least this long (ms), in more frames than
/// asked where its frames are short, up to [`MOST_FRAMES_PER_ROUND`].
const ROUND_MS: f64 = 150.0;
const MOST_FRAMES_PER_ROUND: usize = 40;

/// One round of `order`'s cases: each prepared anew and warmed up, then their frames
/// timed in turn — frame 1 of every case, then frame 2 of every case… — so that a
/// slow spell of the machine falls on all of them alike and leaves their ratios alone.
/// Each case's figures, and the seconds its part of the round took. Where the device
/// has no timestamp queries, each case is timed whole in turn by the CPU's clock.
fn time_round(
    gpu: &GpuContext,
    view: &ViewUnderTest<'_>,
    order: &[usize],
    cases: &[CaseRounds<'_>],
    timing: FrameTiming,
) -> Result<Vec<(measure::RenderStats, f64)>, Error> {
    let (scene, camera) = (&view.scene, &view.camera);
    if !gpu.has_timestamps() {
        return order
            .iter()
            .map(|&i| {
                let began = Instant::now();
                let case = &cases[i];
                let stats = measure::time_only(
                    gpu,
                    scene,
                    camera,
                    case.method,
                    &case.first.params,
                    timing,
                )?;
                Ok((stats, began.elapsed().as_secs_f64()))
            })
            .collect();
    }
    let target = CoverageTarget::new(gpu, camera.width, camera.height, Channels::Coverage)?;
    let mut running = Vec::with_capacity(order.len());
    for &i in order {
        let began = Instant::now();
        let case = &cases[i];
        let mut method = case.method.create(&case.first.params)?;
        let prepare = Instant::now();
        method.prepare(gpu, scene)?;
        let prepare_ms = ms_since(prepare);
        let warmed = frame::warm_up(gpu, method.as_mut(), &target, camera, timing.warmup)?;
        running.push((
            method,
            warmed,
            prepare_ms,
            Vec::new(),
            began.elapsed().as_secs_f64(),
        ));
    }
    // A short frame is timed more often, so that each case's part of a round lasts
    // about as long as a long frame's and its median is as steady.
    let slots = |w: &frame::WarmedUp| {
        let per_frame = w.frame_ms.max(1e-3);
        timing
            .frames
            .max((ROUND_MS / per_frame).ceil() as usize)
            .min(MOST_FRAMES_PER_ROUND)
    };
    let most = running.iter().map(|r| slots(&r.1)).max().unwrap_or(0);
    for slot in 0..most {
        for (method, warmed, _, times, spent_s) in &mut running {
            if slot >= slots(warmed) {
                continue;
            }
            let began = Instant::now();
            times.extend(frame::time_submissions(
                gpu,
                method.as_mut(),
                &target,
                camera,
                1,
                warmed.frames_per_submission,
            )?);
            *spent_s += began.elapsed().as_secs_f64();
        }
    }
    Ok(running
        .into_iter()
        .zip(order)
        .map(|((_, warmed, prepare_ms, times, spent_s), &i)| {
            let mut stats = measure::RenderStats::timed_only(&cases[i].first.params, prepare_ms);
            measure::Timed {
                times,
                clock: measure::CLOCK_TIMESTAMPS,
                frames_per_submission: warmed.frames_per_submission,
                warmup_frames: warmed.frames,
            }
            .write_into(&mut stats);
            (stats, spent_s)
        })
        .collect())
}

/// Whether `case` is glyphon's default, the other figure every case is divided by.
fn is_shipped_default(case: &Measurement) -> bool {
    case.method == super::method_settings::SHIPPED && case.settings() == "default"
}
