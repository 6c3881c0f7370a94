//! Intermediate attachments a method keeps beside the coverage target: a multisampled
//! colour buffer (resolved into the target at the end of a pass) and a stencil buffer.

use super::{
    context::GpuContext,
    target::{Channels, CoverageTarget},
};

/// Stencil format every method uses: lavapipe and every desktop GPU have it.
pub const STENCIL_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Stencil8;

/// Multisampled colour and/or stencil attachments matching a coverage target's size
/// and channels.
/// With one sample and no stencil there is nothing to keep: passes draw straight into
/// the target.
pub struct Attachments {
    width: u32,
    height: u32,
    samples: u32,
    channels: Channels,
    color: Option<wgpu::TextureView>,
    stencil: Option<wgpu::TextureView>,
}

impl Attachments {
    /// Attachments for `target` with `samples` samples per pixel (1 or 4) and a stencil
    /// buffer if asked for, reusing `current` when it already fits.
    pub fn fit(
        current: Option<Attachments>,
        gpu: &GpuContext,
        target: &CoverageTarget,
        samples: u32,
        stencil: bool,
    ) -> Attachments {
        if let Some(a) = current
            && (
                a.width,
                a.height,
                a.samples,
                a.channels,
                a.stencil.is_some(),
            ) == (
                target.width,
                target.height,
                samples,
                target.channels,
                stencil,
            )
        {
            return a;
        }
        let texture = |label, format| {
            gpu.device
                .create_texture(&wgpu::TextureDescriptor {
                    label: Some(label),
                    size: wgpu::Extent3d {
                        width: target.width,
                        height: target.height,
                        depth_or_array_layers: 1,
                    },
                    mip_level_count: 1,
                    sample_count: samples,
                    dimension: wgpu::TextureDimension::D2,
                    format,
                    usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                    view_formats: &[],
                })
                .create_view(&Default::default())
        };
        Attachments {
            width: target.width,
            height: target.height,
            samples,
            channels: target.channels,
            color: (samples > 1)
                .then(|| texture("multisampled coverage", target.channels.format())),
            stencil: stencil.then(|| texture("stencil", STENCIL_FORMAT)),
        }
    }

    pub fn samples(&self) -> u32 {
        self.samples
    }

    /// The colour attachment of a pass that ends in `target`: the multisampled buffer
    /// resolved into the target, or the target itself.
    pub fn color<'a>(
        &'a self,
        target: &'a CoverageTarget,
        load: wgpu::LoadOp<wgpu::Color>,
    ) -> wgpu::RenderPassColorAttachment<'a> {
        let (view, resolve_target) = match &self.color {
            Some(multisampled) => (multisampled, Some(&target.view)),
            None => (&target.view, None),
        };
        wgpu::RenderPassColorAttachment {
            view,
            depth_slice: None,
            resolve_target,
            ops: wgpu::Operations {
                load,
                store: wgpu::StoreOp::Store,
            },
        }
    }

    /// The stencil attachment (cleared to 0 when `clear`), if these attachments have one.
    pub fn stencil(&self, clear: bool) -> Option<wgpu::RenderPassDepthStencilAttachment<'_>> {
        self.stencil
            .as_ref()
            .map(|view| wgpu::RenderPassDepthStencilAttachment {
                view,
                depth_ops: None,
                stencil_ops: Some(wgpu::Operations {
                    load: if clear {
                        wgpu::LoadOp::Clear(0)
                    } else {
                        wgpu::LoadOp::Load
                    },
                    store: wgpu::StoreOp::Store,
                }),
            })
    }

    /// GPU memory held, bytes (the target itself not counted).
    pub fn bytes(&self) -> u64 {
        let pixels = u64::from(self.width) * u64::from(self.height) * u64::from(self.samples);
        let color = if self.color.is_some() {
            pixels * u64::from(self.channels.texel_bytes())
        } else {
            0
        };
        let stencil = if self.stencil.is_some() { pixels } else { 0 };
        color + stencil
    }
}
