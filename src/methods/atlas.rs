//! `atlas`: the baseline users would otherwise pick, and the speed floor — each
//! distinct glyph rasterized once on the CPU at a cached size, packed into one texture,
//! drawn as one bilinearly filtered quad per instance (`shaders/atlas.wgsl`).
//!
//! The bitmaps are exact: the project's reference rasterizer makes them. So the atlas's
//! error is only what caching costs: at the cached size, where a pen lands between the
//! phases it was cached at (a shift of up to 1/(2N) px with N phases, 1/2 px when
//! snapped to whole pixels); once the camera zooms or rotates, resampling a bitmap made
//! for another grid. That second error is why glyphs are drawn from outlines at all.
//!
//! Placement: like the text renderers that keep sub-pixel variants (Skia keeps 4 in x),
//! each glyph is cached at N × N phases (N = `subpixel`, default 4, in x and y alike,
//! because the bench's pages do not put baselines on whole pixels either) and each
//! instance's pen snaps to the nearest 1/N px; `subpixel=1` is the classic whole-pixel
//! atlas; `subpixel=off` resamples the phase-0 bitmap at the exact position.

use glam::DVec2;
use rayon::prelude::*;

use super::Method;
use super::glyph_atlas::{self, AtlasPipeline, Entry};
use super::info::{MethodInfo, Role, bench_at};
use super::params::{Numbers, ParamSpec, Params};
use crate::Error;
use crate::camera::Camera;
use crate::coverage::Png as _;
use crate::gpu::instances::Instances;
use crate::gpu::kit::PipelineBuilder;
use crate::gpu::shaders::Shader;
use crate::gpu::{CoverageTarget, GpuContext};
use crate::reference;
use crate::scene::{Glyph, Instance, Scene};

/// `atlas`' row in the registry: the baseline every bench time is divided by.
pub const INFO: MethodInfo = MethodInfo {
    name: NAME,
    summary: "the baseline: each glyph rasterized once by the reference into a texture \
              atlas at 4 × 4 sub-pixel phases, one bilinear quad per glyph",
    role: Role::Baseline,
    shader: Some(SHADER),
    params: PARAMS,
    colour: [255, 127, 14],
    // The cache size is added per scene: the scene's own.
    bench: &[
        bench_at(&[], true),
        bench_at(&[("subpixel", "1")], true),
        bench_at(&[("subpixel", "off")], false),
    ],
    // Exact only at the size it cached: it claims nothing under a moving camera.
    claims: &[],
    constructor: Some(&|params| Ok(Box::new(Atlas::new(params)))),
};

pub const NAME: &str = "atlas";
const SHADER: Shader = crate::method_shader!("atlas.wgsl", "glyph_atlas.wgsl");

/// Caching never goes above this size by itself: a glyph at 20 000 px/em would need a
/// bitmap of hundreds of megabytes. Beyond it the atlas magnifies, as real ones do.
pub const AUTO_CACHE_MAX_PX_PER_EM: f64 = 512.0;
/// The largest size `cache_px_per_em` takes.
const MAX_CACHE_PX_PER_EM: f64 = 4096.0;
/// Zero texels around each bitmap: bilinear taps at its edge read zero, never a
/// neighbour.
const PAD_TEXELS: i64 = 1;

pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        key: "subpixel",
        choices: &["4", "1", "2", "off"],
        numbers: None,
        help: "Sub-pixel phases per axis: each glyph cached N×N times, pens snapped to the \
               nearest 1/N px. 1: whole pixels (classic atlas); off: the exact position, \
               resampled. N² times the CPU rasterization and atlas memory.",
    },
    ParamSpec {
        key: "cache_px_per_em",
        choices: &["auto"],
        numbers: Some(Numbers::Real {
            min: 1.0,
            max: MAX_CACHE_PX_PER_EM,
            unit: "px/em",
        }),
        help: "The size glyphs are cached at; auto: the first frame's size (at most 512 \
               px/em). Drawn at any other size, the bitmaps are resampled.",
    },
];

/// What the parameters choose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// Phases per axis; 0 for no snapping.
    pub phases: u32,
    /// None: the first frame's size, capped at [`AUTO_CACHE_MAX_PX_PER_EM`].
    pub cache_px_per_em: Option<f64>,
}

impl Settings {
    pub fn from_params(params: &Params) -> Settings {
        Settings {
            phases: match params.word("subpixel") {
                Some("1") => 1,
                Some("2") => 2,
                Some("off") => 0,
                _ => 4,
            },
            cache_px_per_em: params.real("cache_px_per_em"),
        }
    }
}

/// The size `cache_px_per_em=auto` caches at for a first frame at `px_per_em`.
pub fn auto_cache_size(px_per_em: f64) -> f64 {
    px_per_em.min(AUTO_CACHE_MAX_PX_PER_EM)
}

/// How much of a frame the atlas draws: all of it but in the bench's harness breakdown
/// ([`crate::bench::harness`]), which times each step on its own.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    /// The target cleared, nothing drawn.
    Cleared,
    /// The quads, each fragment writing coverage 1: rasterizing, the target and its blend.
    Quads,
    /// Each fragment also maps its pixel centre to local coordinates.
    Mapped,
    /// The whole frame: the bitmap sampled there.
    Full,
    /// The whole frame, but each fragment's local position interpolated from the quad's
    /// corners instead of mapped.
    Interpolated,
}

impl Stage {
    /// `STAGE` in atlas.wgsl (its fragment cut short), and the entry points.
    fn shader(self) -> (f64, (&'static str, &'static str)) {
        let main = ("vs_main", "fs_main");
        match self {
            Stage::Cleared | Stage::Full => (3.0, main),
            Stage::Quads => (1.0, main),
            Stage::Mapped => (2.0, main),
            Stage::Interpolated => (3.0, ("vs_interpolated", "fs_interpolated")),
        }
    }
}

pub struct Atlas {
    settings: Settings,
    stage: Stage,
    pipeline: Option<AtlasPipeline>,
    prepared: Option<Prepared>,
}

struct Prepared {
    scene: Scene,
    instances: Instances,
    /// Built for the first frame when the cache size is automatic.
    cache: Option<Cache>,
}

/// The atlas on the GPU.
struct Cache {
    px_per_em: f64,
    bind_group: wgpu::BindGroup,
    /// Everything the atlas holds: instances, entries and the texture.
    bytes: u64,
    /// The texture alone, one byte a texel.
    texture_bytes: u64,
}

/// One glyph's coverage at one phase, 8 bits a texel.
struct Bitmap {
    width: u32,
    height: u32,
    coverage: Vec<u8>,
    /// Where the glyph's local origin lies in the bitmap, pixels, y down.
    origin: DVec2,
}

impl Atlas {
    pub fn new(params: &Params) -> Atlas {
        Atlas::staged(params, Stage::Full)
    }

    /// An atlas that draws `stage` of a frame.
    pub fn staged(params: &Params, stage: Stage) -> Atlas {
        Atlas {
            settings: Settings::from_params(params),
            stage,
            pipeline: None,
            prepared: None,
        }
    }

    /// The size the glyphs are cached at, once they are.
    pub fn cached_px_per_em(&self) -> Option<f64> {
        self.prepared
            .as_ref()
            .and_then(|p| p.cache.as_ref())
            .map(|c| c.px_per_em)
    }

    fn pipeline(&mut self, gpu: &GpuContext) -> &AtlasPipeline {
        self.pipeline
            .get_or_insert_with(|| AtlasPipeline::new(gpu, NAME, &SHADER))
    }

    /// Rasterizes, packs and uploads every glyph of the prepared scene at `px_per_em`.
    fn build_cache(&mut self, gpu: &GpuContext, px_per_em: f64) -> Result<(), Error> {
        let phases = self.settings.phases;
        self.pipeline(gpu);
        let (Some(pipeline), Some(prepared)) = (&self.pipeline, &mut self.prepared) else {
            return Err(super::not_prepared(NAME));
        };
        let scene = &prepared.scene;
        let per_glyph = (phases.max(1) * phases.max(1)) as usize;
        let mut sizes = Vec::with_capacity(scene.glyphs.len() * per_glyph);
        for glyph in &scene.glyphs {
            let frame = BitmapFrame::of(glyph, scene.units_per_em, px_per_em)?;
            sizes.extend(std::iter::repeat_n((frame.width, frame.height), per_glyph));
        }
        let packed = glyph_atlas::pack(&sizes, gpu.max_texture_side()).ok_or_else(|| {
            Error::Input(format!(
                "atlas: the glyphs at {px_per_em} px/em with subpixel={phases} do not fit in \
                 one {0}×{0} texture; cache smaller (cache_px_per_em) or with fewer phases",
                gpu.max_texture_side()
            ))
        })?;
        let bitmaps = rasterize_glyphs(scene, px_per_em, phases)?;
        let texels = packed.fill(bitmaps.iter().map(|b| (b.width, &b.coverage[..])), 1);
        let texels_per_unit = px_per_em / prepared.scene.units_per_em;
        let entries: Vec<Entry> = bitmaps
            .iter()
            .zip(&packed.corners)
            .map(|(b, &corner)| Entry::new((b.width, b.height), corner, b.origin, texels_per_unit))
            .collect();
        let cache = gpu.catching_errors("building the atlas", || {
            // One byte a texel: coverage is all an atlas of grey glyphs holds, 8 bits are
            // what every atlas stores (within 1/510 of the exact value), and R8Unorm is
            // filterable on every device.
            let texture = packed.upload(gpu, "atlas", wgpu::TextureFormat::R8Unorm, &texels);
            let entry_buffer =
                gpu.buffer_of("atlas entries", &entries, wgpu::BufferUsages::STORAGE);
            let bind_group = pipeline.bind_group(gpu, NAME, &entry_buffer, &texture);
            let texture_bytes = packed.bytes(1);
            Ok(Cache {
                px_per_em,
                bind_group,
                bytes: prepared.instances.bytes() + entry_buffer.size() + texture_bytes,
                texture_bytes,
            })
        })?;
        prepared.cache = Some(cache);
        Ok(())
    }
}

/// Every glyph of `scene` at `px_per_em`, `phases` × `phases` times (once for 0), in
/// the order the shader indexes them: glyph, then phase row, then phase column. The
/// bitmaps are independent, so they are made on every core (on the web page, where
/// threads cannot start, rayon makes them one by one).
fn rasterize_glyphs(scene: &Scene, px_per_em: f64, phases: u32) -> Result<Vec<Bitmap>, Error> {
    let steps = phases.max(1);
    let frames = scene
        .glyphs
        .iter()
        .map(|glyph| BitmapFrame::of(glyph, scene.units_per_em, px_per_em))
        .collect::<Result<Vec<_>, _>>()?;
    let jobs: Vec<(usize, u32, u32)> = (0..scene.glyphs.len())
        .flat_map(|g| {
            (0..steps).flat_map(move |row| (0..steps).map(move |column| (g, row, column)))
        })
        .collect();
    let made: Vec<Result<Bitmap, Error>> = jobs
        .into_par_iter()
        .map(|(g, row, column)| {
            let alone = Scene {
                units_per_em: scene.units_per_em,
                glyphs: vec![scene.glyphs[g].clone()],
                instances: vec![Instance {
                    glyph: 0,
                    position: DVec2::ZERO,
                }],
                source: None,
            };
            let frame = &frames[g];
            let phase = DVec2::new(f64::from(column), f64::from(row)) / f64::from(steps);
            let origin = frame.origin + phase;
            let camera = Camera::new(frame.width, frame.height, px_per_em, origin);
            let image = reference::rasterize(&alone, &camera)?;
            Ok(Bitmap {
                width: image.width,
                height: image.height,
                coverage: image.to_gray8().into_raw(),
                origin,
            })
        })
        .collect();
    // The first glyph's error, whichever thread met it first: the same every run.
    made.into_iter().collect()
}

/// Where a glyph's bitmaps sit: whole pixels around its ink at the cached size, the
/// padding, and one more for the phase shift.
struct BitmapFrame {
    width: u32,
    height: u32,
    /// The glyph's origin in the bitmap at phase 0, pixels (y down).
    origin: DVec2,
}

impl BitmapFrame {
    fn of(glyph: &Glyph, units_per_em: f64, px_per_em: f64) -> Result<BitmapFrame, Error> {
        let s = px_per_em / units_per_em;
        let (left, right) = (glyph.bounds.min.x * s, glyph.bounds.max.x * s);
        let (bottom, top) = (glyph.bounds.min.y * s, glyph.bounds.max.y * s);
        let width = right.ceil() - left.floor() + (2 * PAD_TEXELS + 1) as f64;
        let height = top.ceil() - bottom.floor() + (2 * PAD_TEXELS + 1) as f64;
        let side = f64::from(crate::camera::MAX_IMAGE_SIDE);
        if width > side || height > side {
            return Err(Error::Input(format!(
                "atlas: glyph {} at {px_per_em} px/em needs a {width}×{height} bitmap, over \
                 {side} a side; cache smaller (cache_px_per_em)",
                glyph.id
            )));
        }
        Ok(BitmapFrame {
            width: width as u32,
            height: height as u32,
            origin: DVec2::new(
                PAD_TEXELS as f64 - left.floor(),
                PAD_TEXELS as f64 + top.ceil(),
            ),
        })
    }
}

impl Method for Atlas {
    fn name(&self) -> &'static str {
        NAME
    }

    fn prepare(&mut self, gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        let instances =
            gpu.catching_errors("preparing 'atlas'", || Ok(Instances::new(gpu, scene)))?;
        self.prepared = Some(Prepared {
            scene: scene.clone(),
            instances,
            cache: None,
        });
        // A fixed size is cached now, so that `prepare` holds all the CPU work.
        match self.settings.cache_px_per_em {
            Some(size) => self.build_cache(gpu, size),
            None => Ok(()),
        }
    }

    fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        camera: &Camera,
    ) -> Result<(), Error> {
        let prepared = self
            .prepared
            .as_ref()
            .ok_or_else(|| super::not_prepared(NAME))?;
        if prepared.cache.is_none() {
            self.build_cache(gpu, auto_cache_size(camera.size_px_per_em))?;
        }
        let phases = self.settings.phases;
        let (stage, entry_points) = self.stage.shader();
        let (Some(pipeline), Some(prepared)) = (&mut self.pipeline, &mut self.prepared) else {
            return Err(super::not_prepared(NAME));
        };
        let draw = pipeline.pipelines.get(target.channels, |channels| {
            let constants = [("PHASES", f64::from(phases)), ("STAGE", stage)];
            PipelineBuilder::new(NAME, &pipeline.pipeline_layout, &pipeline.module)
                .entry_points(entry_points.0, entry_points.1)
                .constants(&constants)
                .build(&gpu.device, channels)
        });
        // A pixel of margin: snapping moves a glyph by up to half a pixel.
        let visible = prepared.instances.update(gpu, camera, 1.0)?;
        let cache = prepared.cache.as_ref().expect("built above");
        let mut pass = target.clearing_pass(encoder, NAME);
        if visible > 0 && self.stage != Stage::Cleared {
            pass.set_pipeline(draw);
            pass.set_bind_group(0, prepared.instances.bind_group(), &[]);
            pass.set_bind_group(1, &cache.bind_group, &[]);
            pass.draw(0..4, 0..visible);
        }
        Ok(())
    }

    fn gpu_bytes(&self) -> u64 {
        self.prepared
            .as_ref()
            .and_then(|p| p.cache.as_ref())
            .map_or(0, |c| c.bytes)
    }

    fn cache_bytes(&self) -> Option<u64> {
        self.prepared
            .as_ref()
            .and_then(|p| p.cache.as_ref())
            .map(|c| c.texture_bytes)
    }
}
