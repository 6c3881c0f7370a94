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

use glyphscope_core::Error;
use glyphscope_core::camera::Camera;
use glyphscope_core::geometry::{Rect, keeps_axes, steps_lean_apart};
use glyphscope_core::scene::Scene;
use glyphscope_gpu::instances::Instances;
use glyphscope_gpu::kit::{self, CurveCost, PipelineBuilder};
use glyphscope_gpu::shaders::Shader;
use glyphscope_gpu::{Channels, CoverageTarget, GpuContext, Overlay};

/// The method's name: `--method winding`, and the label of its GPU objects.
pub const NAME: &str = "winding";
/// Its shader: the shared part, then each algorithm's file, then the text library's.
pub const SHADER: Shader = glyphscope_gpu::method_shader!(
    "winding.wgsl",
    "winding_rays.wgsl",
    "winding_area.wgsl",
    "winding_text.wgsl",
    "winding_user.wgsl"
);

/// The stand-in for a user's `user_coverage` that [`SHADER`] ends with: a user's method
/// is [`SHADER`] with this file replaced by theirs ([`user_source`]).
pub const USER_STAND_IN: &str = include_str!("../../shaders/winding_user.wgsl");

/// The full source of a user's method: [`SHADER`]'s, the user's WGSL (defining
/// `user_coverage`, docs/your-method.md) in place of [`USER_STAND_IN`]. The user's text
/// comes last, so its line `n` is the source's line `n + ` [`user_line_offset`].
pub fn user_source(user_wgsl: &str) -> String {
    let source = SHADER.source();
    let prelude = source
        .strip_suffix(USER_STAND_IN)
        .expect("SHADER ends with the user stand-in");
    format!("{prelude}{user_wgsl}")
}

/// Lines of [`user_source`] before the user's first.
pub fn user_line_offset() -> usize {
    user_source("").lines().count()
}

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
    /// Draw each word as one glyph under one quad (`quads=word`,
    /// [`Scene::with_words_joined`]; the overlapping groups are joined with it).
    pub join_words: bool,
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
            join_words: false,
            bands: Some(BandCount::Auto),
            overlay: None,
        }
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
    /// A user's method: its full source ([`user_source`]), compiled with `USER` set.
    user: Option<std::sync::Arc<str>>,
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
    /// The renderer with `settings`, drawing the whole shader.
    pub fn new(settings: Settings) -> Winding {
        Winding::staged(settings, Stage::Full)
    }

    /// A user's method: `source` ([`user_source`] of their file, checked by the caller)
    /// drawn as `winding` draws, on `aa=rays`' data (every curve whole, in bands along x
    /// and y) with `user_coverage` in place of the algorithm.
    pub fn with_user_source(source: String) -> Winding {
        let settings = Settings {
            aa: Antialiasing::Rays,
            samples: 1,
            ..Settings::default()
        };
        Winding {
            user: Some(source.into()),
            ..Winding::staged(settings, Stage::Full)
        }
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
            ("USER", f64::from(u8::from(self.user.is_some()))),
        ];
        let module = match &self.user {
            Some(source) => gpu
                .device
                .create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: Some("user method"),
                    source: wgpu::ShaderSource::Wgsl(std::borrow::Cow::Borrowed(source)),
                }),
            None => SHADER.module(&gpu.device),
        };
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
            .ok_or_else(|| glyphscope_gpu::not_prepared(NAME))?;
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

/// The life cycle of a method (the explorer's `Method` trait calls these): `prepare`
/// once per scene, then `encode` once per frame for whatever camera is current.
impl Winding {
    /// Builds the GPU data of `scene`: per distinct glyph its curves and bands, per
    /// instance its transform.
    pub fn prepare(&mut self, gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        let band_count = self.settings.bands.unwrap_or(BandCount::Fixed(1));
        let layout = match self.settings.aa {
            Antialiasing::Rays => Layout::Rays,
            Antialiasing::Area => Layout::Area,
        };
        let scene = if self.settings.join_words {
            std::borrow::Cow::Owned(scene.with_words_joined().0)
        } else {
            scene.joined_if(self.settings.join_instances)
        };
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

    /// Records one frame into `target` (cleared first) as `camera` sees the prepared
    /// scene: coverage, or the overlay its channels show.
    pub fn encode(
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

    /// GPU memory held for the prepared scene, bytes.
    pub fn gpu_bytes(&self) -> u64 {
        self.prepared.as_ref().map_or(0, |p| p.bytes)
    }

    /// Curves evaluated per covered pixel in a frame `camera` sees, counted by a pass
    /// of the shader that writes its count instead of coverage.
    pub fn curves_per_pixel(
        &mut self,
        gpu: &GpuContext,
        camera: &Camera,
    ) -> Result<CurveCost, Error> {
        kit::count_curves(gpu, (camera.width, camera.height), |encoder, target| {
            self.draw(gpu, encoder, target, camera, Output::CurveCount)
                .map(drop)
        })
    }
}
