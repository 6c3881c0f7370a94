//! Measuring: every case through `cli::measure`, the function `render --stats` uses, with
//! the reference rasterized once per scene and view and shared by every case.

use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;

use super::scenes::{self, BenchScene};
use super::sweep::{self, BENCH_METHODS};
use crate::Error;
use crate::cli::{self, FrameTiming, RENDER_TIMING, RenderArgs};
use crate::gpu::GpuContext;
use crate::methods::{self, atlas};
use crate::metrics::{self, ErrorStats};

/// `--quick`: a few frames after a short warm-up.
pub const QUICK_TIMING: FrameTiming = FrameTiming {
    warmup: 1,
    frames: 3,
};

/// What to measure.
#[derive(Clone, Debug)]
pub struct BenchOptions {
    pub quick: bool,
    /// Scene names; empty for all.
    pub scenes: Vec<String>,
    /// Method names (of [`BENCH_METHODS`] and `reference`); empty for all.
    pub methods: Vec<String>,
    /// Timed frames per case, overriding the default (21, or 3 with `quick`).
    pub frames: Option<usize>,
}

/// Which view of a scene a case was measured in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum View {
    /// The scene's own camera; the atlas is cached at this size.
    Own,
    /// After caching: zoomed 2.5× and turned 30°; the atlas keeps the cache made for
    /// the scene's own size.
    Moved,
}

/// One scene in one view.
#[derive(Clone, Debug, Serialize)]
pub struct SceneInfo {
    pub name: String,
    pub view: View,
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
pub struct Case {
    pub scene: String,
    pub view: View,
    pub method: String,
    pub params: Vec<(String, String)>,
    /// Median GPU time of a frame (the reference: its CPU time), ms.
    pub gpu_ms: Option<f64>,
    /// Fastest and slowest timed frame, ms.
    pub gpu_ms_range: Option<(f64, f64)>,
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
    pub error: ErrorStats,
}

impl Case {
    /// `k=v, k=v`, or `default`.
    pub fn settings(&self) -> String {
        let shown: Vec<String> = self
            .params
            .iter()
            .filter(|(k, _)| k != "cache_px_per_em")
            .map(|(k, v)| format!("{k}={v}"))
            .collect();
        if shown.is_empty() {
            "default".into()
        } else {
            shown.join(", ")
        }
    }

    /// Whether this is the baseline every time is divided by.
    pub fn is_baseline(&self) -> bool {
        self.method == sweep::BASELINE.0 && self.settings() == "default"
    }
}

/// Everything one run measured.
#[derive(Clone, Debug, Serialize)]
pub struct BenchResult {
    pub adapter: String,
    /// How GPU time was measured (timestamp queries, or the CPU clock).
    pub gpu_clock: Option<String>,
    pub quick: bool,
    pub warmup_frames: usize,
    pub timed_frames: usize,
    pub scenes: Vec<SceneInfo>,
    pub cases: Vec<Case>,
}

/// Checks the options, naming what is unknown.
fn check(options: &BenchOptions) -> Result<(Vec<BenchScene>, Vec<String>), Error> {
    let names: Vec<&str> = if options.scenes.is_empty() {
        scenes::SCENE_NAMES.to_vec()
    } else {
        options.scenes.iter().map(String::as_str).collect()
    };
    let chosen = names
        .into_iter()
        .map(scenes::scene)
        .collect::<Result<Vec<_>, _>>()?;
    let methods: Vec<String> = if options.methods.is_empty() {
        std::iter::once("reference")
            .chain(BENCH_METHODS.iter().copied())
            .map(String::from)
            .collect()
    } else {
        options.methods.clone()
    };
    for method in &methods {
        if method != "reference" && !BENCH_METHODS.contains(&method.as_str()) {
            return Err(Error::Input(format!(
                "the bench has no method '{method}'; choose from: reference, {}",
                BENCH_METHODS.join(", ")
            )));
        }
    }
    if options.frames == Some(0) {
        return Err(Error::Input("--frames must be at least 1".into()));
    }
    Ok((chosen, methods))
}

/// The settings measured in `view`: every setting in the scene's own view; after
/// caching, the atlas's settings and each other method's default (how they fare under
/// the same zoom and turn) — with `quick`, only `winding`'s, the contrast.
fn settings_for(
    method: &str,
    view: View,
    quick: bool,
    cache_px_per_em: f64,
) -> Vec<Vec<(String, String)>> {
    if method == "reference" {
        return vec![Vec::new()];
    }
    let mut all = sweep::sweep(method, quick);
    if view == View::Moved && method != "atlas" {
        let kept = if quick && method != "winding" { 0 } else { 1 };
        all.truncate(kept);
    }
    if method == "atlas" {
        for params in &mut all {
            params.push(("cache_px_per_em".into(), cache_px_per_em.to_string()));
        }
    }
    all
}

/// Runs the bench, showing progress on stderr when it is a terminal.
pub fn run(options: &BenchOptions) -> Result<BenchResult, Error> {
    let (chosen, methods) = check(options)?;
    let base = if options.quick {
        QUICK_TIMING
    } else {
        RENDER_TIMING
    };
    let timing = FrameTiming {
        frames: options.frames.unwrap_or(base.frames),
        ..base
    };
    let gpu = GpuContext::new()?;
    let per_view = |view| -> usize {
        methods
            .iter()
            .map(|m| settings_for(m, view, options.quick, 0.0).len())
            .sum()
    };
    let total = chosen.len() * (per_view(View::Own) + per_view(View::Moved));
    // Hidden by indicatif itself when stderr is not a terminal.
    let progress = ProgressBar::new(total as u64).with_style(
        ProgressStyle::with_template("{elapsed_precise} {wide_bar} {pos}/{len} {msg}")
            .expect("a valid template"),
    );
    let mut result = BenchResult {
        adapter: gpu.adapter_name(),
        gpu_clock: None,
        quick: options.quick,
        warmup_frames: timing.warmup,
        timed_frames: timing.frames,
        scenes: Vec::new(),
        cases: Vec::new(),
    };
    for bench_scene in &chosen {
        let (_, own_camera) = cli::scene_and_camera(&bench_scene.args)?;
        let cache = atlas::auto_cache_size(own_camera.size_px_per_em);
        for view in [View::Own, View::Moved] {
            let args = match view {
                View::Own => bench_scene.args.clone(),
                View::Moved => scenes::moved_args(&bench_scene.args, &own_camera),
            };
            let (scene, camera) = cli::scene_and_camera(&args)?;
            progress.set_message(format!("{} ({view:?}): reference", bench_scene.name));
            let reference = cli::measure(None, &scene, &camera, "reference", &[], timing)?;
            result.scenes.push(SceneInfo {
                name: bench_scene.name.into(),
                view,
                about: bench_scene.about.into(),
                width: camera.width,
                height: camera.height,
                size_px_per_em: camera.size_px_per_em,
                instances: scene.instances.len(),
                distinct_glyphs: scene.glyphs.len(),
                atlas_cache_px_per_em: cache,
                render_args: render_command(&args),
            });
            for method in &methods {
                for params in settings_for(method, view, options.quick, cache) {
                    progress.set_message(format!(
                        "{} ({view:?}): {method} {}",
                        bench_scene.name,
                        params
                            .iter()
                            .map(|(k, v)| format!("{k}={v}"))
                            .collect::<Vec<_>>()
                            .join(" ")
                    ));
                    let (measured, error) = if method == "reference" {
                        let exact = metrics::compare(&reference.image, &reference.image)?;
                        (reference.stats.clone(), exact)
                    } else {
                        let m = cli::measure(Some(&gpu), &scene, &camera, method, &params, timing)?;
                        let error = metrics::compare(&m.image, &reference.image)?;
                        (m.stats, error)
                    };
                    if result.gpu_clock.is_none() {
                        result.gpu_clock.clone_from(&measured.gpu_clock);
                    }
                    result.cases.push(Case {
                        scene: bench_scene.name.into(),
                        view,
                        method: method.clone(),
                        params,
                        gpu_ms: measured.gpu_ms.or(measured.cpu_render_ms),
                        gpu_ms_range: measured.gpu_ms_range,
                        cpu_prepare_ms: measured.cpu_prepare_ms,
                        cpu_render_ms: measured.cpu_render_ms,
                        mesh_build_ms: measured.mesh.as_ref().map(|m| m.cpu_build_ms),
                        gpu_bytes: measured.gpu_bytes,
                        curves_per_pixel: measured.curves_per_pixel,
                        mesh_points: measured.mesh.as_ref().map(|m| m.points),
                        error,
                    });
                    progress.inc(1);
                }
            }
        }
    }
    progress.finish_and_clear();
    Ok(result)
}

/// The `render` arguments that draw a view (add `--method` and `--param`s).
fn render_command(args: &RenderArgs) -> Vec<String> {
    let mut out = Vec::new();
    if let Some(font) = &args.font {
        out.extend(["--font".into(), font.display().to_string()]);
    }
    if let Some(text) = &args.text {
        out.extend(["--text".into(), text.clone()]);
    }
    out.extend(["--size".into(), args.size.to_string()]);
    let pair = |v: glam::DVec2| format!("{},{}", v.x, v.y);
    if let (Some(w), Some(h)) = (args.width, args.height) {
        out.extend([
            "--width".into(),
            w.to_string(),
            "--height".into(),
            h.to_string(),
        ]);
    }
    if let Some(origin) = args.origin {
        out.extend(["--origin".into(), pair(origin)]);
    }
    if let Some(m) = args.matrix {
        out.extend(["--matrix".into(), m.map(|v| v.to_string()).join(",")]);
    }
    if args.tilt != 0.0 {
        out.extend(["--tilt".into(), args.tilt.to_string()]);
    }
    for (tag, value) in &args.variation {
        out.extend(["--variation".into(), format!("{tag}={value}")]);
    }
    out
}
