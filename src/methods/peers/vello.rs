//! `vello`: linebender's GPU compute 2D renderer, a peer. The scene's glyphs are drawn
//! with `Scene::draw_glyphs` from the same font bytes and variation coordinates, by
//! glyph id at glyphscope's shaped positions, under the camera's affine map, unhinted;
//! a scene of synthetic outlines (no font) is filled as paths. Vello renders into a
//! storage texture and submits its own command buffers: its GPU time is read from
//! timestamps in submissions just before and after its own.
//!
//! On a software device (lavapipe) its fine-rasterization stage costs a fixed time per
//! pixel, large next to the glyphs' own cost; the first frame of each anti-aliasing
//! mode compiles its shaders for several seconds. Both are vello's, measured as they are.

use ::vello::{AaConfig, AaSupport, RenderParams, Renderer, RendererOptions};
use glam::{DMat2, DVec2};
use peniko::{Color, Fill};

use super::linebender::{AffinePlacement, LinebenderScene};
use super::observed;
use super::picture::PeerImage;
use crate::Error;
use crate::camera::Camera;
use crate::gpu::timing::Timestamps;
use crate::gpu::{CoverageTarget, GpuContext};
use crate::methods::info::{MethodInfo, Role, bench_at};
use crate::methods::params::{ParamSpec, Params};
use crate::methods::{Method, PeerGpuTime, not_prepared};
use crate::scene::Scene;

/// `vello`'s row in the registry.
pub const INFO: MethodInfo = MethodInfo {
    name: NAME,
    summary: "peer: linebender's vello 0.11, GPU compute paths (area AA or MSAA8/16), \
              glyphs from the same font bytes",
    role: Role::Peer,
    shader: Some(super::SHADER),
    params: PARAMS,
    colour: [227, 119, 194],
    bench: &[
        bench_at(&[], true),
        bench_at(&[("aa", "msaa8")], false),
        bench_at(&[("aa", "msaa16")], false),
    ],
    claims: &[observed(NAME)],
    constructor: Some(&|params| Ok(Box::new(Vello::new(params)))),
};

pub const NAME: &str = "vello";

const PARAMS: &[ParamSpec] = &[ParamSpec {
    key: "aa",
    choices: &["area", "msaa8", "msaa16"],
    numbers: None,
    help: "vello's anti-aliasing: area (analytic, its default) integrates the winding \
           number over each pixel; msaa8 and msaa16 count samples, right where contours \
           overlap, at more cost.",
}];

pub struct Vello {
    aa: AaConfig,
    renderer: Option<Renderer>,
    prepared: Option<LinebenderScene>,
    image: Option<PeerImage>,
    /// Timestamps around vello's own submissions, written anew each frame: what lies
    /// between them is the span of `render_to_texture` — vello's recording on the CPU
    /// (resolving the scene, encoding its passes) and then its GPU work.
    timestamps: Option<Timestamps>,
}

impl Vello {
    pub fn new(params: &Params) -> Vello {
        let aa = match params.word("aa") {
            Some("msaa8") => AaConfig::Msaa8,
            Some("msaa16") => AaConfig::Msaa16,
            _ => AaConfig::Area,
        };
        Vello {
            aa,
            renderer: None,
            prepared: None,
            image: None,
            timestamps: None,
        }
    }

    /// The vello scene of one frame.
    fn encode_scene(&self, camera: &Camera) -> Result<::vello::Scene, Error> {
        let prepared = self.prepared.as_ref().ok_or_else(|| not_prepared(NAME))?;
        let mut out = ::vello::Scene::new();
        match prepared {
            LinebenderScene::Glyphs {
                font,
                coords,
                ids,
                scene,
            } => {
                let place = AffinePlacement::of(NAME, scene, camera)?;
                // Vello scales the outline (y up) to `font_size`, applies the glyph
                // transform, then flips y and moves it to the glyph's position: the
                // glyph transform is the camera's map of one font unit, less that
                // scale, with the flip undone.
                let font_size = camera.size_px_per_em;
                let unflip = DMat2::from_diagonal(DVec2::new(1.0, -1.0));
                let glyph = unflip * place.linear * (scene.units_per_em / font_size);
                let glyphs = ids
                    .iter()
                    .zip(&place.pens)
                    .map(|(&id, pen)| ::vello::Glyph {
                        id,
                        x: pen.x as f32,
                        y: pen.y as f32,
                    });
                out.draw_glyphs(font)
                    .font_size(font_size as f32)
                    .glyph_transform(Some(super::linebender::affine(glyph, DVec2::ZERO)))
                    .normalized_coords(coords)
                    .hint(false)
                    .brush(Color::WHITE)
                    .draw(Fill::NonZero, glyphs);
            }
            LinebenderScene::Paths { paths, scene } => {
                let place = AffinePlacement::of(NAME, scene, camera)?;
                for (instance, pen) in scene.instances.iter().zip(&place.pens) {
                    let to_image = super::linebender::affine(place.linear, *pen);
                    let path = &paths[instance.glyph as usize];
                    out.fill(Fill::NonZero, to_image, Color::WHITE, None, path);
                }
            }
        }
        Ok(out)
    }
}

impl Method for Vello {
    fn name(&self) -> &'static str {
        NAME
    }

    fn prepare(&mut self, gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        if self.renderer.is_none() {
            // Only the chosen mode's pipelines: each costs seconds of shader compilation
            // on a software device.
            let antialiasing_support = AaSupport {
                area: self.aa == AaConfig::Area,
                msaa8: self.aa == AaConfig::Msaa8,
                msaa16: self.aa == AaConfig::Msaa16,
            };
            let options = RendererOptions {
                antialiasing_support,
                ..Default::default()
            };
            let renderer = Renderer::new(&gpu.device, options)
                .map_err(|e| Error::Gpu(format!("vello cannot start: {e}")))?;
            self.renderer = Some(renderer);
        }
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
        let vello_scene = self.encode_scene(camera)?;
        let mut image = PeerImage::sized(self.image.take(), gpu, NAME, target.width, target.height);
        let params = RenderParams {
            base_color: Color::TRANSPARENT,
            width: target.width,
            height: target.height,
            antialiasing_method: self.aa,
        };
        if self.timestamps.is_none() && gpu.has_timestamps() {
            self.timestamps = Some(Timestamps::new(gpu, "vello's submissions", 2));
        }
        let stamp = |index: u32| {
            if let Some(t) = &self.timestamps {
                let mut e = gpu.device.create_command_encoder(&Default::default());
                t.write(&mut e, index);
                gpu.queue.submit([e.finish()]);
            }
        };
        stamp(0);
        let renderer = self.renderer.as_mut().ok_or_else(|| not_prepared(NAME))?;
        renderer
            .render_to_texture(&gpu.device, &gpu.queue, &vello_scene, &image.view, &params)
            .map_err(|e| Error::Gpu(format!("vello failed: {e}")))?;
        stamp(1);
        image.copy_into(gpu, encoder, target);
        self.image = Some(image);
        Ok(())
    }

    fn peer_gpu_time(&mut self, gpu: &GpuContext) -> Result<Option<PeerGpuTime>, Error> {
        let submitted_ms = match &self.timestamps {
            Some(t) => t.read_intervals(gpu)?.first().copied().unwrap_or(0.0),
            None => 0.0,
        };
        super::picture::gpu_time(self.image.as_ref(), gpu, submitted_ms)
    }

    /// Only the texture vello renders into: its renderer's buffers are allocated per
    /// frame inside it, and its API does not say how large they are.
    fn gpu_bytes(&self) -> u64 {
        self.image.as_ref().map_or(0, PeerImage::bytes)
    }
}
