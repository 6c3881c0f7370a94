//! Everything one run measured, as `bench.json` holds it: the standard scenes' cases
//! and refusals, the scaling series' points, winding's cost breakdown and the methods
//! in motion. Every part of the bench reads these types; none of them measures or
//! writes anything.

use serde::Serialize;

use crate::intervals::Interval;

use super::method_settings;
use crate::measure::FrameTiming;
use crate::methods::registry;
use crate::methods::winding::cost::CostCounts;
use crate::methods::{CurveCost, LayoutOffset};
use crate::metrics::{ErrorStats, TemporalSummary};
use crate::motion::run::MethodSpec;

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
    /// rasterization), ms: what cases are ranked and divided by. The median of the
    /// rounds' medians.
    pub frame_ms: Option<f64>,
    /// `frame_ms` with its 95 % interval over the rounds (`settle`).
    pub frame_ms_interval: Option<Interval>,
    /// This case's frame over the atlas baseline's, round by round: the median of the
    /// rounds' ratios and its 95 % interval (None for the baseline itself).
    pub ratio_atlas: Option<Interval>,
    /// The same over glyphon's default, where glyphon drew the view.
    pub ratio_glyphon: Option<Interval>,
    /// Rounds the case was timed in, each preparing it anew.
    pub rounds: usize,
    /// Frames recorded into each timed submission (more than 1 for short frames).
    pub frames_per_submission: Option<u32>,
    /// The most untimed warm-up frames a round drew (the asked ones, and more while the
    /// frame time was falling).
    pub warmup_frames: Option<usize>,
    /// The method's `prepare`, ms (the reference: 0).
    pub cpu_prepare_ms: f64,
    /// The reference's rasterization, ms.
    pub cpu_render_ms: Option<f64>,
    /// Meshes built on the CPU (tessellation), ms, whenever they were built.
    pub mesh_build_ms: Option<f64>,
    pub gpu_bytes: u64,
    pub curves_per_pixel: Option<CurveCost>,
    /// Outline points the meshes are built on (tessellation).
    pub mesh_points: Option<usize>,
    /// A peer's own text layout against glyphscope's shaping (glyphon).
    pub layout_offset: Option<LayoutOffset>,
    pub error: ErrorStats,
}

impl Measurement {
    /// `k=v, k=v`, or `default`.
    pub fn settings(&self) -> String {
        method_settings::setting_name(&self.params)
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

/// What a scaling series varies (what each measures: `scaling`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Series {
    GlyphCount,
    PxPerEm,
}

impl Series {
    pub const ALL: [Series; 2] = [Series::GlyphCount, Series::PxPerEm];

    /// The name `--scenes` takes.
    pub fn name(self) -> &'static str {
        match self {
            Series::GlyphCount => "glyph-count",
            Series::PxPerEm => "px-per-em",
        }
    }

    /// The series called `name`, if one is.
    pub fn named(name: &str) -> Option<Series> {
        Series::ALL.into_iter().find(|s| s.name() == name)
    }

    /// The work axis, as tables and plots label it.
    pub fn work_label(self) -> &'static str {
        match self {
            Series::GlyphCount => "glyphs",
            Series::PxPerEm => "px/em",
        }
    }
}

/// One method at one point of a scaling series.
#[derive(Clone, Debug, Serialize)]
pub struct MethodCost {
    pub method: String,
    /// How the frames were timed (timestamp queries, or the CPU's clock).
    pub gpu_clock: Option<String>,
    /// Median GPU time of a frame, ms.
    pub gpu_ms: Option<f64>,
    /// Median CPU time of recording a frame, ms.
    pub cpu_frame_ms: Option<f64>,
    /// Median of GPU + CPU per frame, ms: what methods are compared by.
    pub frame_ms: Option<f64>,
    /// GPU memory held once drawn.
    pub gpu_bytes: u64,
    /// The part of `gpu_bytes` that caches rasterized glyphs (the atlas's texture).
    pub cache_bytes: Option<u64>,
}

/// One point of a scaling series: its frame and every method's cost there.
#[derive(Clone, Debug, Serialize)]
pub struct ScalingPoint {
    pub series: Series,
    /// The work on the series' axis: glyphs drawn, or px/em.
    pub work: f64,
    pub size_px_per_em: f64,
    pub glyphs: usize,
    pub width: u32,
    pub height: u32,
    /// Covered pixels (the sum of coverage), the median over the methods' images.
    pub covered_px: f64,
    /// The size the atlas caches at here (its default: the frame's, capped).
    pub atlas_cache_px_per_em: f64,
    pub costs: Vec<MethodCost>,
}

impl ScalingPoint {
    /// `method`'s cost here, if it was measured.
    pub fn cost(&self, method: &str) -> Option<&MethodCost> {
        self.costs.iter().find(|c| c.method == method)
    }
}

/// Where `winding`'s default spends a frame in one view of one scene
/// (`winding_cost`).
#[derive(Clone, Debug, Serialize)]
pub struct WindingCost {
    pub scene: String,
    #[serde(rename = "view")]
    pub scene_camera: SceneCamera,
    pub counts: CostCounts,
    /// GPU time of a frame with the shader stopping after each stage, in
    /// `Stage::ALL`'s order, ms: the median of the rounds' medians. None where the
    /// device has no timestamp queries.
    pub stage_gpu_ms: Option<[f64; 5]>,
}

/// One method through one camera path of one scene (`motion`).
#[derive(Clone, Debug, Serialize)]
pub struct MotionCase {
    pub scene: String,
    /// The path's name in `motion::PATHS`, and the path.
    pub path_name: String,
    pub path: String,
    pub frames: usize,
    pub method: MethodSpec,
    /// Mean over frames of each frame's MAE against the reference, 1/255, and the
    /// largest pixel error of any frame.
    pub still_mae_255: f64,
    pub still_max: f64,
    pub temporal: TemporalSummary,
    /// A peer's documented limit met on this path.
    pub refused: Option<String>,
}

/// Everything one run measured.
#[derive(Clone, Debug, Serialize)]
pub struct BenchResult {
    pub adapter: String,
    /// What kind of device `adapter` is, and what its figures can tell
    /// ([`crate::info::AdapterClass`]).
    pub adapter_class: crate::info::AdapterClass,
    /// Seconds a case whose ratios were not settled was timed for, at most.
    pub settle_cap_s: f64,
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
    /// Each method at its default through the camera paths of `motion::PATHS`, on the
    /// scenes of `motion::SCENES` that were run.
    pub motion: Vec<MotionCase>,
}

impl BenchResult {
    /// The baseline's case in `scene`'s `view`, if it was measured there: what every
    /// time of that view is divided by.
    pub fn baseline_in(&self, scene: &str, view: SceneCamera) -> Option<&Measurement> {
        self.measurements
            .iter()
            .find(|c| c.scene == scene && c.scene_camera == view && c.is_baseline())
    }

    /// The default case of `method` in `scene`'s `view`, if it was measured there.
    pub fn default_case_in(
        &self,
        method: &str,
        scene: &str,
        view: SceneCamera,
    ) -> Option<&Measurement> {
        self.measurements.iter().find(|c| {
            c.scene == scene
                && c.scene_camera == view
                && c.method == method
                && c.settings() == "default"
        })
    }

    /// Why `method`'s default could not draw `scene`'s `view`, if it refused it.
    pub fn refusal_in(&self, method: &str, scene: &str, view: SceneCamera) -> Option<&Refusal> {
        self.refusals.iter().find(|r| {
            r.scene == scene
                && r.scene_camera == view
                && r.method == method
                && method_settings::setting_name(&r.params) == "default"
        })
    }
}
