//! `vello-cpu`: linebender's CPU sparse-strips rasterizer (vello_cpu; egui draws its own
//! glyphs with an earlier version), a peer. The scene's glyphs are drawn with
//! `RenderContext::glyph_run` from the same font bytes and variation coordinates, by
//! glyph id at glyphscope's shaped positions, under the camera's affine map, unhinted,
//! on one thread; a scene of synthetic outlines is filled as paths. The whole
//! rasterization is the frame's CPU time; the pixmap's upload runs before the frame,
//! untimed, and the copy into the coverage target is the harness's.

use glam::{DMat2, DVec2};
use peniko::Fill;
use vello_cpu::color::palette::css::WHITE;
use vello_cpu::{Pixmap, RasterizerSettings, RenderContext, RenderMode, Resources};

use super::linebender::{AffinePlacement, LinebenderScene};
use super::observed;
use super::picture::PeerImage;
use crate::Error;
use crate::camera::Camera;
use crate::gpu::{CoverageTarget, GpuContext};
use crate::methods::info::{MethodInfo, Role, bench_at};
use crate::methods::params::{ParamSpec, Params};
use crate::methods::{Method, PeerGpuTime, not_prepared};
use crate::scene::Scene;

/// `vello-cpu`'s row in the registry.
pub const INFO: MethodInfo = MethodInfo {
    name: NAME,
    summary: "peer: linebender's vello_cpu 0.3, CPU sparse strips (as egui uses), \
              glyphs from the same font bytes, one thread",
    role: Role::Peer,
    shader: Some(super::SHADER),
    params: PARAMS,
    colour: [188, 189, 34],
    bench: &[bench_at(&[], true), bench_at(&[("mode", "quality")], false)],
    claims: &[observed(NAME)],
    constructor: Some(&|params| Ok(Box::new(VelloCpu::new(params)))),
};

pub const NAME: &str = "vello-cpu";

const PARAMS: &[ParamSpec] = &[ParamSpec {
    key: "mode",
    choices: &["speed", "quality"],
    numbers: None,
    help: "vello_cpu's render mode: speed (its default) rasterizes with u8/u16 \
           arithmetic, quality with f32.",
}];

pub struct VelloCpu {
    mode: RenderMode,
    prepared: Option<LinebenderScene>,
    image: Option<PeerImage>,
    resources: Resources,
    context: Option<RenderContext>,
    /// The last frame's pixels, kept to reuse the allocation.
    pixmap: Option<Pixmap>,
}

impl VelloCpu {
    pub fn new(params: &Params) -> VelloCpu {
        let mode = match params.word("mode") {
            Some("quality") => RenderMode::OptimizeQuality,
            _ => RenderMode::OptimizeSpeed,
        };
        VelloCpu {
            mode,
            prepared: None,
            image: None,
            resources: Resources::new(),
            context: None,
            pixmap: None,
        }
    }

    /// Rasterizes one frame into `pixmap`.
    fn rasterize(&mut self, camera: &Camera, pixmap: &mut Pixmap) -> Result<(), Error> {
        let prepared = self.prepared.as_ref().ok_or_else(|| not_prepared(NAME))?;
        let (width, height) = (pixmap.width(), pixmap.height());
        // One context kept across frames, as an application would: reset, or resized.
        let ctx = match &mut self.context {
            Some(ctx) if (ctx.width(), ctx.height()) == (width, height) => {
                ctx.reset();
                ctx
            }
            context => context.insert(RenderContext::new(width, height)),
        };
        ctx.set_paint(WHITE);
        ctx.set_fill_rule(Fill::NonZero);
        match prepared {
            LinebenderScene::Glyphs {
                font,
                coords,
                ids,
                scene,
            } => {
                let place = AffinePlacement::of(NAME, scene, camera)?;
                // glifo flips the outline (y up) to y down at `font_size`, then applies
                // the glyph transform: the camera's map of one font unit, less that
                // scale, after the flip.
                let font_size = camera.size_px_per_em;
                let flip = DMat2::from_diagonal(DVec2::new(1.0, -1.0));
                let glyph = place.linear * flip * (scene.units_per_em / font_size);
                let glyphs = ids
                    .iter()
                    .zip(&place.pens)
                    .map(|(&id, pen)| vello_cpu::Glyph {
                        id,
                        x: pen.x as f32,
                        y: pen.y as f32,
                    });
                ctx.glyph_run(&mut self.resources, font)
                    .font_size(font_size as f32)
                    .glyph_transform(super::linebender::affine(glyph, DVec2::ZERO))
                    .normalized_coords(coords)
                    .hint(false)
                    .fill_glyphs(glyphs)
                    .map_err(|e| Error::Gpu(format!("vello_cpu cannot draw the glyphs: {e:?}")))?;
            }
            LinebenderScene::Paths { paths, scene } => {
                let place = AffinePlacement::of(NAME, scene, camera)?;
                for (instance, pen) in scene.instances.iter().zip(&place.pens) {
                    ctx.set_transform(super::linebender::affine(place.linear, *pen));
                    ctx.fill_path(&paths[instance.glyph as usize]);
                }
            }
        }
        ctx.flush();
        let settings = RasterizerSettings {
            render_mode: self.mode,
            ..Default::default()
        };
        ctx.render_with(pixmap, &mut self.resources, settings);
        Ok(())
    }
}

impl Method for VelloCpu {
    fn name(&self) -> &'static str {
        NAME
    }

    fn prepare(&mut self, _gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        self.prepared = Some(LinebenderScene::of(scene));
        Ok(())
    }

    fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        camera: &Camera,
    ) -> Result<(), Error> {
        let side = |pixels: u32| {
            u16::try_from(pixels).map_err(|_| {
                Error::Refused(format!(
                    "vello-cpu draws at most {} pixels a side (got {pixels})",
                    u16::MAX
                ))
            })
        };
        let (width, height) = (side(target.width)?, side(target.height)?);
        let mut pixmap = match self.pixmap.take() {
            Some(p) if (p.width(), p.height()) == (width, height) => p,
            _ => Pixmap::new(width, height),
        };
        self.rasterize(camera, &mut pixmap)?;
        let mut image = PeerImage::sized(self.image.take(), gpu, NAME, target.width, target.height);
        gpu.queue.write_texture(
            wgpu::TexelCopyTextureInfo {
                texture: &image.texture,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            pixmap.data_as_u8_slice(),
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(4 * target.width),
                rows_per_image: Some(target.height),
            },
            wgpu::Extent3d {
                width: target.width,
                height: target.height,
                depth_or_array_layers: 1,
            },
        );
        image.copy_into(gpu, encoder, target);
        self.image = Some(image);
        self.pixmap = Some(pixmap);
        Ok(())
    }

    fn peer_gpu_time(&mut self, gpu: &GpuContext) -> Result<Option<PeerGpuTime>, Error> {
        super::picture::gpu_time(self.image.as_ref(), gpu, 0.0)
    }

    /// The texture its pixels are uploaded to (the pixmap itself is as large, on the
    /// CPU).
    fn gpu_bytes(&self) -> u64 {
        self.image.as_ref().map_or(0, PeerImage::bytes)
    }
}
