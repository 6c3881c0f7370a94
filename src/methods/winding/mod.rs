//! `winding`: the coverage of each pixel from the winding number of its glyph's
//! quadratic curves (GreenLightning's "GPU Font Rendering" and Steffen Haug's "Graphics
//! project"; Eric Lengyel's Slug and Windfoil are the state of the art: docs/sources.md).
//!
//! - By default (`aa=area`) the exact box-filter integral of the winding number over
//!   the pixel, by Green's theorem over each curve, in the pixel's own frame (so exact
//!   under rotation, skew and mirroring): see [`area`]. Overlapping contours are drawn
//!   from their union (`overlaps=merge`); kept (`overlaps=keep`, or `fill=evenodd`),
//!   where their curves cross the pixel, 4×4 sub-pixels, each integrated the same way.
//! - Or (`aa=rays`) from the roots along rays through the pixel. Which roots count
//!   follows from the sign bits of the control points' y relative to the ray alone (the
//!   `0x2E74` table): no epsilon decides a crossing. Roots come from the stable form of
//!   the quadratic formula, relative to the sample point, so lines and near-lines need
//!   no threshold. A crossing within one pixel along the ray adds the exact box-filter
//!   coverage of the curve's tangent line there, with the pixel footprint taken from
//!   the local coordinates' screen derivatives (rotation, skew, zoom and perspective
//!   included). Two rays (x and y) are blended by how well each sees an edge (near, and
//!   across it), since a ray is blind to edges running along it; a ray sees at least as
//!   well as the other ray's crossings, taken as straight lines, say it must.
//!   `rays=slug` combines the two rays as Slug's published pixel shader does, for
//!   comparison.
//! - Bands let a pixel visit only the curves at its height, walked towards the nearer
//!   side of the glyph, stopping at the first curve wholly behind it.
//! - Each instance's quad grows by exactly the pixel footprint (`dilated_corner`).

pub mod area;
mod bands;
pub mod cost;
mod overlaps;
pub mod text;
mod uploaded;

pub use bands::{BandCount, GlyphData, Layout, MAX_BANDS};
use uploaded::Uploaded;

use super::info::{Claim, ClaimedSetting, MethodInfo, Role, Trait, bench_at, within};
use super::instances::Instances;
use super::params::{BETWEEN, Numbers, ParamSpec, Params, Value};
use super::{CurveCost, Method, Overlay};
use crate::Error;
use crate::camera::Camera;
use crate::geometry::{Rect, keeps_axes, steps_lean_apart};
use crate::gpu::kit::{self, PipelineBuilder};
use crate::gpu::shaders::Shader;
use crate::gpu::{Channels, CoverageTarget, GpuContext};
use crate::scene::Scene;

/// `winding`'s row in the registry.
pub const INFO: MethodInfo = MethodInfo {
    name: NAME,
    summary: "winding number of quadratic curves: its exact box-filter integral over \
              each pixel by Green's theorem (aa=area), or from roots along x and y rays \
              anti-aliased per crossing (aa=rays, Slug's family)",
    role: Role::Method,
    shader: Some(SHADER),
    params: PARAMS,
    colour: [31, 119, 180],
    // The exact integral, then the rays: samples and rays are their trade; bands change
    // only the time (the same image), shown on the cheapest setting (without bands a
    // page costs far more: `glyphscope render --case page --method winding --param
    // bands=off --stats S.json` beside the same without it).
    bench: &[
        bench_at(&[], true),
        bench_at(&[("samples", "1")], false),
        bench_at(&[("aa", "rays")], true),
        bench_at(&[("aa", "rays"), ("samples", "1")], true),
        bench_at(&[("aa", "rays"), ("samples", "4")], false),
        bench_at(&[("rays", "slug")], false),
        bench_at(&[("rays", "1")], false),
        bench_at(&[("rays", "1"), ("samples", "1")], true),
        bench_at(&[("rays", "1"), ("samples", "1"), ("bands", "off")], false),
        // What joining overlapping instances costs: the same frame with their coverage
        // added instead (a page without overlaps draws the same instances either way).
        bench_at(&[("between", "add")], false),
    ],
    // Bounds set by the margin rule (info::Claim) from the sweep before them.
    claims: &[
        ClaimedSetting {
            label: NAME,
            params: &[],
            claim: Claim {
                // Exact but for f32 and the half-float target (steps of 4.9e-4 below
                // 1); overlapping contours in scope since they are drawn from their union
                // (`overlaps=merge`, the default), the bound kept. Last measured
                // (`glyphscope stability --methods winding`): max 0.012 (cubic-loop),
                // MAE 0.05/255 (cubic-cusp).
                bound: Some(within(0.02, 0.1)),
                except: &[Trait::BeyondF32],
                // Where an edge is placed to 1/32 px; last measured (the same command):
                // max 0.025 (glyph-max-size-edge). Set when overlaps, kept, were its
                // cases: three winding levels meeting in a sub-pixel, max 0.111, MAE
                // 0.40/255 (winding-256).
                limitation: Some(within(0.25, 0.6)),
                // Set before the first temporal sweep, equal to the still bound: stricter
                // than that bound implies (|e₁ − e₀| ≤ 2·0.02), because an exact method's
                // error is the same small rounding in consecutive frames, not a sign
                // that flips as the text moves.
                temporal: Some(within(0.02, 0.1)),
                statement: "no pixel off by more than 0.02 where f32 font units resolve \
                            the pixel, overlapping contours drawn from their union, and none \
                            changing between frames 1/16 px apart by more than 0.02 beyond \
                            the reference's change",
            },
        },
        ClaimedSetting {
            label: "winding aa=rays",
            params: &[("aa", "rays")],
            claim: Claim {
                // Last measured (`glyphscope stability --methods 'winding aa=rays'`):
                // max 0.475 (thin-stem). The MAE of a frame that is all edges is the
                // error per edge pixel, 1.14/255 on the bench's page (`glyphscope bench
                // --scenes page`, edge MAE; a
                // frame-wide 0.6/255, from cases with blank space around their edges,
                // broke on the first case of 3 px squares, slanted-ulp-segments: 1.19):
                // 1.14 / 0.8 by the margin rule, rounded up.
                bound: Some(within(0.6, 1.5)),
                except: &[Trait::CrowdedPixels],
                // Last measured (the same stability command): max 0.250 (winding-256,
                // merged), MAE 1.40/255 (glyphs-2px); set when winding-256 was kept as
                // drawn: max 0.717, MAE 6.26/255.
                limitation: Some(within(0.9, 8.0)),
                temporal: None,
                statement: "no pixel off by more than 0.6 where at most 8 edges cross a \
                            pixel; a window crossed by more falls back to its averaged \
                            winding",
            },
        },
    ],
    constructor: Some(|params| Ok(Box::new(Winding::new(params)?))),
};

pub const NAME: &str = "winding";
const SHADER: Shader = crate::method_shader!(
    "winding.wgsl",
    "winding_rays.wgsl",
    "winding_area.wgsl",
    "winding_text.wgsl"
);

/// The overlays `winding` draws.
pub const OVERLAYS: &[Overlay] = &[Overlay::CurveClasses, Overlay::CostHeatMap];

/// The parameters `winding` takes.
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        key: "aa",
        choices: &["area", "rays"],
        numbers: None,
        help: "area: the exact box-filter integral of the winding number over the pixel, \
               by Green's theorem over each curve, for less than rays with one sample \
               cost; rays: coverage from the crossings of \
               rays through the pixel.",
    },
    ParamSpec {
        key: "rays",
        choices: &["2", "1", "slug"],
        numbers: None,
        help: "Selects aa=rays. 2: rays along x and y, weighted by which sees the edge \
               best; 1: x only (aliases edges near horizontal). 2 costs about twice the \
               curves. slug: x and y rays combined as Slug's published shader does \
               (a one-pixel window per axis, weights from the nearest root), one \
               sample unless samples says otherwise: for comparison.",
    },
    ParamSpec {
        key: "samples",
        choices: &["auto", "1", "4"],
        numbers: None,
        help: "4 sub-pixels tiling the pixel cut small-size error ~4x for ~3.5x the \
               curves; auto uses 4 where a pixel spans over 1/32 em. With aa=area: 4 \
               integrates 4×4 sub-pixels everywhere, 1 never, auto only in the pixels \
               where a curve of overlapping contours meets another.",
    },
    ParamSpec {
        key: "bands",
        choices: &["auto", "off"],
        numbers: Some(Numbers::Whole {
            min: 1,
            max: MAX_BANDS,
        }),
        help: "Bands let a pixel visit only the curves at its height; off visits every \
               curve of the glyph (same image, ~10x the cost).",
    },
    ParamSpec {
        key: "fill",
        choices: &["nonzero", "evenodd"],
        numbers: None,
        help: "Fill rule. Fonts mean nonzero.",
    },
    ParamSpec {
        key: "overlaps",
        choices: &["merge", "keep"],
        numbers: None,
        help: "merge (the default with fill=nonzero): a glyph whose contours overlap is \
               drawn from their nonzero union (geometry::merge_overlaps), so aa=area needs \
               no sub-pixels there; keep (the default with fill=evenodd): from the \
               contours as the font has them.",
    },
    BETWEEN,
    ParamSpec {
        key: "overlay",
        choices: &["none", "classes", "cost"],
        numbers: None,
        help: "classes: each curve's sign class for the ray through the pixel; cost: \
               curves evaluated per pixel.",
    },
];

/// The curve classes' colours as the class overlay draws them (index: y0 > 0, y1 > 0,
/// y2 > 0 relative to the ray, as bits 0, 1, 2) and which roots each class counts: the
/// legend of the overlay.
pub const CLASS_LEGEND: [([f32; 3], &str); 8] = [
    ([0.35, 0.35, 0.35], "000 below: no root"),
    ([1.0, 0.35, 0.2], "001 t1 (descending)"),
    ([0.75, 0.3, 1.0], "010 both roots"),
    ([1.0, 0.75, 0.1], "011 t1 (descending)"),
    ([0.2, 0.6, 1.0], "100 t2 (ascending)"),
    ([1.0, 0.4, 0.85], "101 both roots"),
    ([0.2, 0.9, 0.7], "110 t2 (ascending)"),
    ([0.7, 0.7, 0.7], "111 above: no root"),
];

/// How a pixel's coverage is found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Antialiasing {
    /// From the crossings of rays through the pixel, each anti-aliased by its tangent.
    Rays,
    /// The exact integral of the winding number over the pixel ([`area`]).
    Area,
}

/// Which rays `aa=rays` casts, and how their coverages combine.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rays {
    /// Along x only.
    X,
    /// Along x and y, weighted by how well each sees the edge (this project's combine).
    XY,
    /// Along x and y, combined as Slug's published pixel shader does.
    Slug,
}

/// What the `--param`s choose.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Settings {
    pub aa: Antialiasing,
    pub rays: Rays,
    /// 1 or 4 sub-pixel samples; 0: 4 where a pixel spans over 1/32 em, else 1.
    pub samples: u32,
    pub even_odd: bool,
    /// Draw each glyph from the nonzero union of its contours (`overlaps=merge`, the
    /// default under the nonzero rule).
    pub merge_overlaps: bool,
    /// Draw each group of instances whose ink overlaps as one glyph (`between=union`,
    /// the default under the nonzero rule).
    pub join_instances: bool,
    /// None: no bands, every curve for every ray.
    pub bands: Option<BandCount>,
    pub overlay: Option<Overlay>,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            aa: Antialiasing::Area,
            rays: Rays::XY,
            samples: 0,
            even_odd: false,
            merge_overlaps: true,
            join_instances: true,
            bands: Some(BandCount::Auto),
            overlay: None,
        }
    }
}

impl Settings {
    /// The settings `params` choose; refused where two parameters contradict each
    /// other.
    pub fn from_params(params: &Params) -> Result<Settings, Error> {
        let mut s = Settings::default();
        let aa = params.given("aa").and_then(Value::word);
        if aa == Some("rays") {
            s.aa = Antialiasing::Rays;
        }
        if let Some(rays) = params.given("rays").and_then(Value::word) {
            // A ray count asks for rays.
            if aa == Some("area") {
                return Err(Error::Input(format!(
                    "winding: rays={rays} does not apply to aa=area, which casts no rays"
                )));
            }
            s.aa = Antialiasing::Rays;
            s.rays = match rays {
                "1" => Rays::X,
                "slug" => {
                    // Slug's shader takes one sample per pixel.
                    s.samples = 1;
                    Rays::Slug
                }
                _ => Rays::XY,
            };
        }
        if let Some(samples) = params.given("samples").and_then(Value::word) {
            s.samples = match samples {
                "1" => 1,
                "4" => 4,
                _ => 0,
            };
        }
        s.even_odd = params.word("fill") == Some("evenodd");
        // Merged unless the fill is even-odd, whose image the nonzero union is not.
        s.merge_overlaps = match params.given("overlaps").and_then(Value::word) {
            Some("merge") if s.even_odd => {
                return Err(Error::Input(
                    "winding: overlaps=merge takes the nonzero union, which fill=evenodd \
                     would not draw the same"
                        .into(),
                ));
            }
            Some(overlaps) => overlaps == "merge",
            None => !s.even_odd,
        };
        // Joined unless the fill is even-odd, under which a group's outlines drawn
        // together would cancel where they overlap.
        s.join_instances = match params.given("between").and_then(Value::word) {
            Some("union") if s.even_odd => {
                return Err(Error::Input(
                    "winding: between=union draws overlapping instances as one glyph, \
                     which fill=evenodd would empty where they overlap"
                        .into(),
                ));
            }
            Some(between) => between == "union",
            None => !s.even_odd,
        };
        s.bands = match params.get("bands") {
            Some(Value::Whole(n)) => Some(BandCount::Fixed(n)),
            Some(Value::Word("off")) => None,
            _ => Some(BandCount::Auto),
        };
        s.overlay = params.word("overlay").and_then(Overlay::named);
        Ok(s)
    }
}

/// The specialisation of `aa=area`'s shader a draw takes, as its `AXIS` and `GRID`
/// constants: instances are drawn in one draw per variant.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Variant {
    /// The instance's axes are the image's: the pixel is a rectangle in its frame.
    axis: bool,
    /// Otherwise, the instance's pixel steps lean apart over the view: a curve across a
    /// pixel is integrated in the pixel's square frame.
    square: bool,
    /// The glyph's pixels may need the sub-pixel grid.
    grid: bool,
}

impl Settings {
    /// The variant that draws an instance of a glyph with (`marked`) or without curves
    /// marked as overlapping, through `to_image`, into `view` (the target's pixels).
    /// `aa=rays` reads none of its constants.
    fn variant(&self, marked: bool, to_image: &glam::DMat3, view: &Rect) -> Variant {
        if self.aa != Antialiasing::Area {
            return Variant {
                axis: false,
                square: false,
                grid: false,
            };
        }
        let axis = keeps_axes(to_image);
        Variant {
            axis,
            square: !axis && steps_lean_apart(to_image, view),
            grid: match self.samples {
                1 => false,
                4 => true,
                _ => marked,
            },
        }
    }
}

/// Where the fragment shader stops (`STAGE` in winding.wgsl).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Stage {
    /// Writes 1 at once: rasterizing the quads and blending.
    Quads,
    /// After the per-fragment setup: derivatives, the pixel's frame, its band.
    Setup,
    /// After the band walk: each visited entry's end points loaded, mapped into the
    /// pixel's frame and sorted into its zone, no term added.
    Walk,
    /// With the terms of the curves wholly right of the pixel, not those across it.
    Right,
    /// The whole shader: the second pass over the curves across the pixel (each loaded
    /// whole and integrated), the fill rule, the sub-pixel grid where it is needed.
    Full,
}

impl Stage {
    /// In the order the shader runs them.
    pub const ALL: [Stage; 5] = [
        Stage::Quads,
        Stage::Setup,
        Stage::Walk,
        Stage::Right,
        Stage::Full,
    ];

    fn constant(self) -> f64 {
        match self {
            Stage::Quads => 0.0,
            Stage::Setup => 1.0,
            Stage::Walk => 2.0,
            Stage::Right => 3.0,
            Stage::Full => 4.0,
        }
    }
}

/// What the fragment shader draws, as its `OVERLAY` constant.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Output {
    Coverage,
    Overlay(Overlay),
    /// Curves evaluated per pixel in red, for `curves_per_pixel`.
    CurveCount,
    /// The cost breakdown's counting passes ([`cost`]).
    CurveTally,
    FragmentTally,
    /// The text library's glyphs that share no pixel with another glyph: each
    /// instance's colour times its coverage, over the caller's colour target.
    TextColour,
}

impl Output {
    fn constant(self) -> f64 {
        match self {
            Output::Coverage => 0.0,
            Output::Overlay(Overlay::CurveClasses) => 1.0,
            Output::Overlay(_) => 2.0,
            Output::CurveCount => 3.0,
            Output::CurveTally => 4.0,
            Output::FragmentTally => 5.0,
            Output::TextColour => 6.0,
        }
    }
}

pub struct Winding {
    settings: Settings,
    /// Where the shader stops: [`Stage::Full`] but for the cost breakdown.
    stage: Stage,
    layout: Option<(wgpu::BindGroupLayout, wgpu::PipelineLayout)>,
    /// The pipelines made so far: drawing, and counting once `curves_per_pixel` or the
    /// cost breakdown asks, per variant drawn and format of target drawn into.
    pipelines: Vec<((Output, Variant, wgpu::TextureFormat), wgpu::RenderPipeline)>,
    prepared: Option<Prepared>,
}

struct Prepared {
    instances: Instances,
    /// Per distinct glyph, whether it has curves marked as overlapping.
    marked: Vec<bool>,
    /// Holds the glyph buffers (a bind group keeps what it binds alive).
    bind_group: wgpu::BindGroup,
    bytes: u64,
}

impl Winding {
    pub fn new(params: &Params) -> Result<Winding, Error> {
        Ok(Winding::staged(Settings::from_params(params)?, Stage::Full))
    }

    pub fn settings(&self) -> Settings {
        self.settings
    }

    fn layout(&mut self, gpu: &GpuContext) -> &(wgpu::BindGroupLayout, wgpu::PipelineLayout) {
        self.layout.get_or_insert_with(|| {
            let group = uploaded::group_layout(gpu, NAME);
            let layout = kit::pipeline_layout(gpu, NAME, Some(&group));
            (group, layout)
        })
    }

    fn pipeline(
        &mut self,
        gpu: &GpuContext,
        output: Output,
        variant: Variant,
        channels: Channels,
    ) -> wgpu::RenderPipeline {
        self.pipeline_into(gpu, output, variant, channels.additive())
    }

    /// The pipeline drawing `output` of `variant` into a target `target` describes:
    /// [`pipeline`](Self::pipeline)'s coverage targets, or (for the text library) a
    /// caller's colour target.
    fn pipeline_into(
        &mut self,
        gpu: &GpuContext,
        output: Output,
        variant: Variant,
        target: wgpu::ColorTargetState,
    ) -> wgpu::RenderPipeline {
        let key = (output, variant, target.format);
        if let Some((_, pipeline)) = self.pipelines.iter().find(|(k, _)| *k == key) {
            return pipeline.clone();
        }
        let s = self.settings;
        let constants = [
            ("AREA", f64::from(u8::from(s.aa == Antialiasing::Area))),
            ("RAYS", f64::from(if s.rays == Rays::X { 1 } else { 2 })),
            ("SLUG", f64::from(u8::from(s.rays == Rays::Slug))),
            ("SAMPLES", f64::from(s.samples)),
            ("EVEN_ODD", f64::from(u8::from(s.even_odd))),
            ("AXIS", f64::from(u8::from(variant.axis))),
            ("SQUARE", f64::from(u8::from(variant.square))),
            ("GRID", f64::from(u8::from(variant.grid))),
            ("USE_BANDS", f64::from(u8::from(s.bands.is_some()))),
            ("OVERLAY", output.constant()),
            ("STAGE", self.stage.constant()),
        ];
        let module = SHADER.module(&gpu.device);
        let layout = &self.layout(gpu).1;
        let pipeline = PipelineBuilder::new(NAME, layout, &module)
            .constants(&constants)
            .build_into(&gpu.device, target);
        self.pipelines.push((key, pipeline.clone()));
        pipeline
    }

    /// Records the draw of every visible instance with `output`'s pipelines, one draw
    /// per [`Variant`]; returns how many instances it draws.
    fn draw(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        camera: &Camera,
        output: Output,
    ) -> Result<u32, Error> {
        let settings = self.settings;
        let prepared = self
            .prepared
            .as_mut()
            .ok_or_else(|| super::not_prepared(NAME))?;
        let marked = &prepared.marked;
        // Pixel centres, and the helper lanes' beside the last column and row (their
        // derivatives are differences with them).
        let view = camera.grown_view(1.0);
        let groups = prepared
            .instances
            .update_grouped(gpu, camera, 0.0, |glyph, to_image| {
                settings.variant(marked[glyph as usize], to_image, &view)
            })?;
        let draws: Vec<_> = groups
            .into_iter()
            .map(|(variant, range)| (self.pipeline(gpu, output, variant, target.channels), range))
            .collect();
        let prepared = self.prepared.as_ref().expect("checked above");
        let mut pass = target.clearing_pass(encoder, NAME);
        pass.set_bind_group(0, prepared.instances.bind_group(), &[]);
        pass.set_bind_group(1, &prepared.bind_group, &[]);
        for (pipeline, range) in &draws {
            pass.set_pipeline(pipeline);
            pass.draw(0..4, range.clone());
        }
        Ok(draws.last().map_or(0, |(_, range)| range.end))
    }
}

impl Method for Winding {
    fn name(&self) -> &'static str {
        NAME
    }

    fn prepare(&mut self, gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        let band_count = self.settings.bands.unwrap_or(BandCount::Fixed(1));
        let layout = match self.settings.aa {
            Antialiasing::Rays => Layout::Rays,
            Antialiasing::Area => Layout::Area,
        };
        let scene = scene.joined_if(self.settings.join_instances);
        let merged;
        let outlines = if self.settings.merge_overlaps {
            merged = scene.with_overlaps_merged();
            &merged
        } else {
            &scene
        };
        let data = GlyphData::of_scene(outlines, band_count, layout);
        gpu.catching_errors("preparing 'winding'", || {
            let instances = Instances::new(gpu, &scene);
            let uploaded = Uploaded::new(gpu, NAME, &data, &self.layout(gpu).0)?;
            self.prepared = Some(Prepared {
                bytes: instances.bytes() + uploaded.bytes,
                instances,
                marked: data.marked.clone(),
                bind_group: uploaded.bind_group,
            });
            Ok(())
        })
    }

    fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        camera: &Camera,
    ) -> Result<(), Error> {
        let output = target
            .channels
            .shown(self.settings.overlay)
            .map_or(Output::Coverage, Output::Overlay);
        self.draw(gpu, encoder, target, camera, output).map(drop)
    }

    fn gpu_bytes(&self) -> u64 {
        self.prepared.as_ref().map_or(0, |p| p.bytes)
    }

    fn overlays(&self) -> &'static [Overlay] {
        OVERLAYS
    }

    fn curves_per_pixel(
        &mut self,
        gpu: &GpuContext,
        camera: &Camera,
    ) -> Result<Option<CurveCost>, Error> {
        kit::count_curves(gpu, (camera.width, camera.height), |encoder, target| {
            self.draw(gpu, encoder, target, camera, Output::CurveCount)
                .map(drop)
        })
        .map(Some)
    }
}
