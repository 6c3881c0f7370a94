//! `msdf`: a distance-field atlas, the field's answer to text that moves, zooms, turns
//! and tilts (game UIs, map labels, 3D text) — a peer, measured as its authors publish
//! it. Each distinct glyph's field is made once on the CPU by fdsm (a Rust port of
//! Viktor Chlumský's msdfgen, [`field`]), packed into one texture, and each instance
//! draws one quad with msdfgen's published shader (`shaders/msdf.wgsl`): the median of
//! the channels, a ramp one screen pixel wide whose slope comes from the derivatives.
//!
//! Unlike glyphon it draws through the quads every glyphscope method shares, so any
//! camera the project has (affine and perspective); unlike the atlas baseline its
//! texture holds distances, not coverage, so it stays sharp when magnified — but
//! rounds corners, loses strokes thinner than a texel or two, and breaks up when
//! minified below its range (no mipmaps in msdfgen's recipe).

pub mod field;
pub mod params;

use std::borrow::Cow;

use rayon::prelude::*;

use self::field::FieldKind;
use self::params::{NAME, OVERLAYS, PARAMS, Settings};
use super::observed;
use crate::Error;
use crate::camera::Camera;
use crate::gpu::instances::Instances;
use crate::gpu::kit::PipelineBuilder;
use crate::gpu::shaders::Shader;
use crate::gpu::{CoverageTarget, GpuContext};
use crate::methods::glyph_atlas::{self, AtlasPipeline, Entry};
use crate::methods::info::{ClaimedSetting, MethodInfo, Role, bench_at};
use crate::methods::{Method, Overlay, not_prepared};
use crate::scene::Scene;

/// `msdf`'s row in the registry.
pub const INFO: MethodInfo = MethodInfo {
    name: NAME,
    summary: "peer: a distance-field atlas, msdfgen's recipe (fields by fdsm 0.8, the \
              published median shader): msdf, mtsdf or single-channel sdf, any camera",
    role: Role::Peer,
    shader: Some(SHADER),
    params: PARAMS,
    colour: [140, 86, 75],
    // msdfgen's common settings (32 and 48 texels per em, ranges 4 and 8) for each
    // field, and the two known to fail: 16 texels per em, and msdf-atlas-gen's default
    // range of 2.
    bench: &[
        bench_at(&[], true),
        bench_at(&[("field", "sdf")], true),
        bench_at(&[("field", "mtsdf")], false),
        bench_at(&[("range", "8")], false),
        bench_at(&[("em_px", "48")], false),
        bench_at(&[("em_px", "48"), ("range", "8")], false),
        bench_at(&[("field", "sdf"), ("em_px", "48"), ("range", "8")], false),
        bench_at(
            &[("field", "mtsdf"), ("em_px", "48"), ("range", "8")],
            false,
        ),
        bench_at(&[("em_px", "16")], false),
        bench_at(&[("range", "2")], false),
    ],
    claims: CLAIMS,
    constructor: Some(&|params| Ok(Box::new(Msdf::new(Settings::from_params(params))))),
};

/// Observed rows of the stability sweep: the default, and the settings its known
/// failures are named by (a coarse field, overlapping contours kept).
const CLAIMS: &[ClaimedSetting] = &[
    observed(NAME),
    ClaimedSetting {
        label: "msdf em_px=16",
        params: &[("em_px", "16")],
        ..observed(NAME)
    },
    ClaimedSetting {
        label: "msdf overlaps=keep",
        params: &[("overlaps", "keep")],
        ..observed(NAME)
    },
];

const SHADER: Shader = crate::method_shader!("msdf.wgsl", "glyph_atlas.wgsl");

pub struct Msdf {
    settings: Settings,
    pipeline: Option<AtlasPipeline>,
    prepared: Option<Prepared>,
}

struct Prepared {
    instances: Instances,
    bind_group: wgpu::BindGroup,
    /// Instances, field entries and the texture.
    bytes: u64,
    /// The texture alone.
    texture_bytes: u64,
}

impl Msdf {
    pub fn new(settings: Settings) -> Msdf {
        Msdf {
            settings,
            pipeline: None,
            prepared: None,
        }
    }

    fn pipeline(&mut self, gpu: &GpuContext) -> &AtlasPipeline {
        self.pipeline
            .get_or_insert_with(|| AtlasPipeline::new(gpu, NAME, &SHADER))
    }
}

/// `scene` as its fields are made from: overlapping contours merged where asked.
fn field_scene<'a>(scene: &'a Scene, settings: &Settings) -> Cow<'a, Scene> {
    if settings.merge_overlaps {
        Cow::Owned(scene.with_overlaps_merged())
    } else {
        Cow::Borrowed(scene)
    }
}

impl Method for Msdf {
    fn name(&self) -> &'static str {
        NAME
    }

    fn prepare(&mut self, gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        let settings = self.settings;
        let max_side = gpu.max_texture_side();
        let source = field_scene(scene, &settings);
        let upem = source.units_per_em;
        // Packed from the sizes alone, before fdsm makes anything: an atlas that cannot
        // fit is refused at once.
        let sizes = source
            .glyphs
            .iter()
            .map(|g| {
                field::size(
                    (!g.outline.is_empty()).then_some(g.bounds),
                    upem,
                    &settings.field,
                )
            })
            .collect::<Result<Vec<_>, _>>()?;
        let texels: u64 = sizes
            .iter()
            .map(|&(w, h)| u64::from(w) * u64::from(h))
            .sum();
        if texels > field::MAX_ATLAS_TEXELS {
            return Err(Error::Refused(format!(
                "msdf: the fields at {} texels per em would hold {texels} texels, over the \
                 {} glyphscope makes for one scene; ask for fewer (em_px)",
                settings.field.texels_per_em,
                field::MAX_ATLAS_TEXELS
            )));
        }
        let packed = glyph_atlas::pack(&sizes, max_side).ok_or_else(|| {
            Error::Refused(format!(
                "msdf: the fields at {} texels per em do not fit in one {max_side}×{max_side} \
                 texture; ask for fewer (em_px)",
                settings.field.texels_per_em
            ))
        })?;
        // Each glyph's field is its own: made on every core (one by one on the web page).
        let fields = source
            .glyphs
            .par_iter()
            .map(|g| field::generate(&g.outline, g.bounds, upem, &settings.field))
            .collect::<Vec<_>>()
            // The first glyph's error, whichever thread met it first: the same every run.
            .into_iter()
            .collect::<Result<Vec<_>, _>>()?;
        let kind = settings.field.kind;
        let texels = packed.fill(
            fields.iter().map(|f| (f.width, &f.texels[..])),
            kind.texel_bytes(),
        );
        let texels_per_unit = settings.field.texels_per_em / scene.units_per_em;
        let entries: Vec<Entry> = fields
            .iter()
            .zip(&packed.corners)
            .map(|(f, &corner)| Entry::new((f.width, f.height), corner, f.origin, texels_per_unit))
            .collect();
        self.pipeline(gpu);
        let pipeline = self.pipeline.as_ref().expect("made above");
        let prepared = gpu.catching_errors("preparing 'msdf'", || {
            let instances = Instances::new(gpu, scene);
            let texture = packed.upload(gpu, NAME, kind.format(), &texels);
            let entry_buffer = gpu.buffer_of("msdf fields", &entries, wgpu::BufferUsages::STORAGE);
            let bind_group = pipeline.bind_group(gpu, NAME, &entry_buffer, &texture);
            let texture_bytes = packed.bytes(kind.texel_bytes() as u64);
            Ok(Prepared {
                bytes: instances.bytes() + entry_buffer.size() + texture_bytes,
                instances,
                bind_group,
                texture_bytes,
            })
        })?;
        self.prepared = Some(prepared);
        Ok(())
    }

    fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        camera: &Camera,
    ) -> Result<(), Error> {
        let overlay = match target.channels.shown(self.settings.overlay) {
            None => 0.0,
            Some(Overlay::FieldChannels) => 1.0,
            // `Settings` admits only the overlays in `params::OVERLAYS`.
            Some(_) => 2.0,
        };
        let spec = self.settings.field;
        let (Some(pipeline), Some(prepared)) = (&mut self.pipeline, &mut self.prepared) else {
            return Err(not_prepared(NAME));
        };
        let draw = pipeline.pipelines.get(target.channels, |channels| {
            let constants = [
                (
                    "CHANNELS",
                    if spec.kind == FieldKind::Sdf {
                        1.0
                    } else {
                        3.0
                    },
                ),
                ("RANGE", spec.range),
                ("OVERLAY", overlay),
            ];
            PipelineBuilder::new(NAME, &pipeline.pipeline_layout, &pipeline.module)
                .constants(&constants)
                .build(&gpu.device, channels)
        });
        let visible = prepared.instances.update(gpu, camera, 1.0)?;
        let mut pass = target.clearing_pass(encoder, NAME);
        if visible > 0 {
            pass.set_pipeline(draw);
            pass.set_bind_group(0, prepared.instances.bind_group(), &[]);
            pass.set_bind_group(1, &prepared.bind_group, &[]);
            pass.draw(0..4, 0..visible);
        }
        Ok(())
    }

    fn gpu_bytes(&self) -> u64 {
        self.prepared.as_ref().map_or(0, |p| p.bytes)
    }

    fn cache_bytes(&self) -> Option<u64> {
        self.prepared.as_ref().map(|p| p.texture_bytes)
    }

    fn overlays(&self) -> &'static [Overlay] {
        OVERLAYS
    }
}
