//! What the peers that draw a picture share (glyphon, vello, vello-cpu): the texture a
//! peer draws into, the pass that copies its coverage into the coverage target, and
//! the peer's own GPU time with that copy taken out.

use super::SHADER;
use crate::Error;
use crate::gpu::kit::{self, ColorOut, PerTarget, PipelineBuilder, Slot};
use crate::gpu::timing::Timestamps;
use crate::gpu::{CoverageTarget, GpuContext, clearing_pass};
use crate::methods::PeerGpuTime;

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
