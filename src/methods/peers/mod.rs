//! The peers: the renderers people use, measured beside glyphscope's own methods
//! through their public APIs, at their own settings, on the same device and against the
//! same reference — `vello` (linebender's GPU compute renderer), `glyphon` (the common
//! wgpu text renderer: cosmic-text layout, swash rasterization, a glyph atlas) and
//! `vello-cpu` (linebender's CPU sparse-strips rasterizer, which egui uses too).
//!
//! Each draws white on transparent black into a texture of its own (the format its API
//! renders to); one pass here copies that texture's alpha — linear coverage, no sRGB
//! step — into the coverage target, so the frame loop, readback and metrics are the
//! same as every method's. What a peer cannot draw is refused with
//! [`Error::Refused`], naming its limit.

pub mod glyphon;
pub mod msdf;
pub mod vello;
pub mod vello_cpu;

use glam::{DMat2, DVec2};

use super::info::{Claim, ClaimedSetting};
use crate::Error;
use crate::camera::Camera;
use crate::gpu::kit::{self, ColorOut, PerTarget, PipelineBuilder, Slot};
use crate::gpu::shaders::Shader;

use crate::gpu::timing::Timestamps;
use crate::gpu::{CoverageTarget, GpuContext, clearing_pass};
use crate::methods::PeerGpuTime;
use crate::scene::{Scene, SceneSource};

/// The copy pass every peer shares.
pub const SHADER: Shader = crate::method_shader!("peers.wgsl");

/// The stability sweep runs a peer as an observed row: its figures beside the
/// project's methods, no claim of glyphscope's on it.
pub const fn observed(label: &'static str) -> ClaimedSetting {
    ClaimedSetting {
        label,
        params: &[],
        claim: Claim {
            bound: None,
            except: &[],
            limitation: None,
            temporal: None,
            statement: "observed: a peer, measured as it is; glyphscope claims nothing of it",
        },
    }
}

/// The texture a peer draws into, the size of the frame, and the pass that copies its
/// coverage into the target.
pub struct PeerImage {
    pub texture: wgpu::Texture,
    pub view: wgpu::TextureView,
    pub width: u32,
    pub height: u32,
    copy: CopyPass,
    /// Around the copy pass, where the device has timestamps: the harness's time, which
    /// the frame loop takes out of the peer's.
    copy_timestamps: Option<Timestamps>,
}

/// What a peer's texture may be used as: a render attachment (glyphon), a storage
/// texture (vello's compute stages), a copy destination (vello_cpu's upload).
pub const PEER_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

struct CopyPass {
    layout: wgpu::PipelineLayout,
    module: wgpu::ShaderModule,
    pipelines: PerTarget<wgpu::RenderPipeline>,
    bind_group: wgpu::BindGroup,
}

impl PeerImage {
    /// A texture `width`×`height`, kept while the frame size stays the same.
    pub fn sized(
        kept: Option<PeerImage>,
        gpu: &GpuContext,
        label: &str,
        width: u32,
        height: u32,
    ) -> PeerImage {
        if let Some(image) = kept.filter(|i| (i.width, i.height) == (width, height)) {
            return image;
        }
        let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
            label: Some(label),
            size: wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: PEER_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                | wgpu::TextureUsages::STORAGE_BINDING
                | wgpu::TextureUsages::TEXTURE_BINDING
                | wgpu::TextureUsages::COPY_DST,
            view_formats: &[],
        });
        let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
        let copy = CopyPass::new(gpu, label, &view);
        let copy_timestamps = gpu
            .has_timestamps()
            .then(|| Timestamps::new(gpu, "peer copy", 2));
        PeerImage {
            texture,
            view,
            width,
            height,
            copy,
            copy_timestamps,
        }
    }

    /// Bytes the texture holds.
    pub fn bytes(&self) -> u64 {
        u64::from(self.width) * u64::from(self.height) * 4
    }

    /// Records the copy of this texture's alpha into `target`, which it overwrites.
    pub fn copy_into(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
    ) {
        let copy = &mut self.copy;
        let pipeline = copy.pipelines.get(target.channels, |channels| {
            PipelineBuilder::new("peer coverage", &copy.layout, &copy.module)
                .topology(wgpu::PrimitiveTopology::TriangleList)
                .color(ColorOut::Replace(wgpu::ColorWrites::ALL))
                .build(&gpu.device, channels)
        });
        let timestamps = self.copy_timestamps.as_ref().map(|t| t.pass_writes(0));
        let mut pass = clearing_pass(encoder, &target.view, "peer coverage", timestamps);
        pass.set_pipeline(pipeline);
        pass.set_bind_group(1, &self.copy.bind_group, &[]);
        pass.draw(0..3, 0..1);
    }

    /// The last copy's GPU time, ms (0 without timestamps), once the GPU has done it.
    pub fn copy_ms(&self, gpu: &GpuContext) -> Result<f64, Error> {
        match &self.copy_timestamps {
            Some(t) => Ok(t.read_intervals(gpu)?.first().copied().unwrap_or(0.0)),
            None => Ok(0.0),
        }
    }

    /// A render pass drawing into this texture, cleared to transparent.
    pub fn clearing_pass<'e>(
        &self,
        encoder: &'e mut wgpu::CommandEncoder,
        label: &str,
    ) -> wgpu::RenderPass<'e> {
        clearing_pass(encoder, &self.view, label, None)
    }
}

/// [`Method::peer_gpu_time`](crate::methods::Method::peer_gpu_time) of a peer whose
/// picture is `image` (None before its first frame) and whose own submissions took
/// `submitted_ms`.
pub fn gpu_time(
    image: Option<&PeerImage>,
    gpu: &GpuContext,
    submitted_ms: f64,
) -> Result<Option<PeerGpuTime>, Error> {
    let copy_ms = image.map_or(Ok(0.0), |i| i.copy_ms(gpu))?;
    Ok(Some(PeerGpuTime {
        submitted_ms,
        copy_ms,
    }))
}

impl CopyPass {
    fn new(gpu: &GpuContext, label: &str, view: &wgpu::TextureView) -> CopyPass {
        let module = SHADER.module(&gpu.device);
        let group = kit::layout(gpu, label, &[Slot::Texture]);
        // Only `@group(1)`: the copy reads no glyph instances.
        let layout = gpu
            .device
            .create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some(label),
                bind_group_layouts: &[None, Some(&group)],
                immediate_size: 0,
            });
        let bind_group = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(label),
            layout: &group,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::TextureView(view),
            }],
        });
        CopyPass {
            layout,
            module,
            pipelines: PerTarget::default(),
            bind_group,
        }
    }
}

/// Where a scene's glyphs land in the image under an affine camera: one linear map for
/// every glyph (font units, y up → pixels, y down) and each instance's pen in pixels.
pub struct AffinePlacement {
    /// Font units to pixels, including the flip to y down.
    pub linear: DMat2,
    /// Each instance's pen position in image pixels, in the scene's instance order.
    pub pens: Vec<DVec2>,
}

impl AffinePlacement {
    /// The placement of `scene` through `camera`, or `peer`'s refusal of a tilt, which
    /// needs a perspective divide an affine renderer does not have.
    pub fn of(peer: &str, scene: &Scene, camera: &Camera) -> Result<AffinePlacement, Error> {
        if camera.tilt_deg != 0.0 {
            return Err(Error::Refused(format!(
                "{peer} draws affine transforms only: a tilt ({}°) needs perspective",
                camera.tilt_deg
            )));
        }
        let upem = scene.units_per_em;
        let pens = scene
            .instances
            .iter()
            .map(|i| {
                let to_image = camera.glyph_to_image(upem, i.position);
                to_image.z_axis.truncate()
            })
            .collect();
        let to_image = camera.glyph_to_image(upem, DVec2::ZERO);
        let linear = DMat2::from_cols(to_image.x_axis.truncate(), to_image.y_axis.truncate());
        Ok(AffinePlacement { linear, pens })
    }
}

/// What the linebender peers (vello, vello_cpu) draw of a scene: the font's glyphs by
/// id, from the same bytes and variation coordinates, or — for synthetic outlines, which
/// no font holds — the outlines as paths.
pub enum LinebenderScene {
    Glyphs {
        font: ::vello::peniko::FontData,
        coords: Vec<i16>,
        /// Each instance's glyph id.
        ids: Vec<u32>,
        scene: Scene,
    },
    Paths {
        /// One per distinct glyph, in font units (y up).
        paths: Vec<::vello::kurbo::BezPath>,
        scene: Scene,
    },
}

impl LinebenderScene {
    pub fn of(scene: &Scene) -> LinebenderScene {
        match &scene.source {
            Some(source) => {
                let (font, coords) = font_data(source);
                LinebenderScene::Glyphs {
                    font,
                    coords,
                    ids: scene
                        .instances
                        .iter()
                        .map(|i| u32::from(scene.glyphs[i.glyph as usize].id))
                        .collect(),
                    scene: scene.clone(),
                }
            }
            None => LinebenderScene::Paths {
                paths: scene
                    .glyphs
                    .iter()
                    .map(|g| crate::geometry::kurbo_path(&g.outline.contours))
                    .collect(),
                scene: scene.clone(),
            },
        }
    }
}

/// The font of a scene made from one, as the linebender crates take it (the same
/// bytes), and its variation coordinates, normalized as the font's `fvar` and `avar`
/// define them.
pub fn font_data(source: &SceneSource) -> (::vello::peniko::FontData, Vec<i16>) {
    let bytes = source.font.data();
    let blob = ::vello::peniko::Blob::new(std::sync::Arc::new(bytes));
    let coords = source
        .font
        .face()
        .variation_coordinates()
        .iter()
        .map(|c| c.get())
        .collect();
    (::vello::peniko::FontData::new(blob, 0), coords)
}

/// A kurbo affine map from a 2×2 linear part and a translation.
pub fn affine(linear: DMat2, translation: DVec2) -> ::vello::kurbo::Affine {
    ::vello::kurbo::Affine::new([
        linear.x_axis.x,
        linear.x_axis.y,
        linear.y_axis.x,
        linear.y_axis.y,
        translation.x,
        translation.y,
    ])
}
