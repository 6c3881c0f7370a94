//! The texture every method renders its coverage into, and reading it back.

use std::sync::{Arc, Mutex};

use super::context::GpuContext;
use crate::Error;
use crate::coverage::CoverageImage;

/// A coverage target: coverage in alpha, premultiplied overlay colour in rgb.
pub struct CoverageTarget {
    pub texture: wgpu::Texture,
    pub view: wgpu::TextureView,
    pub width: u32,
    pub height: u32,
}

impl CoverageTarget {
    /// Half floats: blendable everywhere, exact for 0 and 1, and about 3 decimal digits
    /// in between — finer than the 8 bits an image is saved with.
    pub const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

    /// The colour state of pipelines that add their coverage up: where instances'
    /// quads overlap, disjoint glyphs sum to the union's coverage, as in the reference.
    pub const ADDITIVE: wgpu::ColorTargetState = {
        let add = wgpu::BlendComponent {
            src_factor: wgpu::BlendFactor::One,
            dst_factor: wgpu::BlendFactor::One,
            operation: wgpu::BlendOperation::Add,
        };
        wgpu::ColorTargetState {
            format: Self::FORMAT,
            blend: Some(wgpu::BlendState {
                color: add,
                alpha: add,
            }),
            write_mask: wgpu::ColorWrites::ALL,
        }
    };

    /// Bytes of one texel of [`Self::FORMAT`].
    const TEXEL_BYTES: u32 = 8;

    pub fn new(gpu: &GpuContext, width: u32, height: u32) -> Result<CoverageTarget, Error> {
        let max = gpu.max_texture_side();
        if width == 0 || height == 0 || width > max || height > max {
            return Err(Error::Input(format!(
                "target size {width}x{height} is not possible on this GPU: each side must be \
                 1 to {max} pixels"
            )));
        }
        gpu.catching_errors("creating the coverage target", || {
            let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
                label: Some("coverage target"),
                size: wgpu::Extent3d {
                    width,
                    height,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: Self::FORMAT,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                    | wgpu::TextureUsages::TEXTURE_BINDING
                    | wgpu::TextureUsages::COPY_SRC,
                view_formats: &[],
            });
            let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
            Ok(CoverageTarget {
                texture,
                view,
                width,
                height,
            })
        })
    }

    /// A render pass drawing straight into this target, cleared to transparent: the
    /// pass of methods that need no multisampling and no stencil.
    pub fn clearing_pass<'e>(
        &self,
        encoder: &'e mut wgpu::CommandEncoder,
        label: &str,
    ) -> wgpu::RenderPass<'e> {
        clearing_pass(encoder, &self.view, label, None)
    }

    /// Copies the coverage (alpha) back as f32, exactly as the method wrote it: nothing
    /// clamped, so that a value out of [0, 1] or not finite can be seen (see
    /// [`CoverageImage::range`]) before [`CoverageImage::clamp_to_union`] unites
    /// overlapping instances.
    pub fn readback(&self, gpu: &GpuContext) -> Result<CoverageImage, Error> {
        Ok(coverage_of(
            self.width,
            self.height,
            &self.read_texels(gpu)?,
        ))
    }

    /// Copies the overlay picture (rgb, premultiplied, over black) back as 8-bit sRGB-less
    /// RGB, clamped.
    pub fn readback_color(&self, gpu: &GpuContext) -> Result<image::RgbImage, Error> {
        let texels = self.read_texels(gpu)?;
        let bytes = texels
            .iter()
            .flat_map(|t| [t[0], t[1], t[2]])
            .map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8)
            .collect();
        Ok(image::RgbImage::from_raw(self.width, self.height, bytes).expect("size matches"))
    }

    /// Every texel as f32 rgba, row-major.
    pub(crate) fn read_texels(&self, gpu: &GpuContext) -> Result<Vec<[f32; 4]>, Error> {
        let bytes = gpu.catching_errors("reading the coverage target back", || {
            let buffer = self.copy_to_buffer(gpu);
            gpu.read_buffer(&buffer)
        })?;
        Ok(texels_of(&bytes, self.width, self.padded_row_bytes()))
    }

    /// Starts reading the coverage back without waiting for it: the copy is submitted
    /// and the buffer mapped when the GPU gets there; [`PendingReadback::take`] gives the
    /// image on a later frame. What the explorer reads back within its frame loop, on
    /// the desktop and on the web (where nothing can wait for the GPU) alike.
    pub fn start_readback(&self, gpu: &GpuContext) -> Result<PendingReadback, Error> {
        let buffer = gpu.catching_errors("reading the coverage target back", || {
            Ok(self.copy_to_buffer(gpu))
        })?;
        let state = Arc::new(Mutex::new(None));
        let answer = state.clone();
        buffer.map_async(wgpu::MapMode::Read, .., move |result| {
            *answer.lock().unwrap_or_else(|p| p.into_inner()) = Some(result);
        });
        Ok(PendingReadback {
            buffer,
            state,
            width: self.width,
            height: self.height,
            padded_row_bytes: self.padded_row_bytes(),
        })
    }

    fn padded_row_bytes(&self) -> u32 {
        // Buffer rows of a texture copy must start on 256-byte boundaries.
        (self.width * Self::TEXEL_BYTES).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT)
    }

    /// A mappable buffer holding a copy of the target, the copy submitted.
    fn copy_to_buffer(&self, gpu: &GpuContext) -> wgpu::Buffer {
        let padded_row_bytes = self.padded_row_bytes();
        let buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("coverage readback"),
            size: u64::from(padded_row_bytes) * u64::from(self.height),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let mut encoder = gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("readback"),
            });
        encoder.copy_texture_to_buffer(
            self.texture.as_image_copy(),
            wgpu::TexelCopyBufferInfo {
                buffer: &buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(padded_row_bytes),
                    rows_per_image: None,
                },
            },
            wgpu::Extent3d {
                width: self.width,
                height: self.height,
                depth_or_array_layers: 1,
            },
        );
        gpu.queue.submit([encoder.finish()]);
        buffer
    }
}

/// Half-float rgba rows, each padded to `padded_row_bytes`, as f32 texels.
fn texels_of(bytes: &[u8], width: u32, padded_row_bytes: u32) -> Vec<[f32; 4]> {
    let row_bytes = (width * CoverageTarget::TEXEL_BYTES) as usize;
    let mut texels = Vec::new();
    for row in bytes.chunks_exact(padded_row_bytes as usize) {
        // rgba, two bytes each, little-endian.
        texels.extend(
            row[..row_bytes]
                .chunks_exact(CoverageTarget::TEXEL_BYTES as usize)
                .map(|t| [0, 2, 4, 6].map(|i| half::f16::from_le_bytes([t[i], t[i + 1]]).to_f32())),
        );
    }
    texels
}

/// The coverage (alpha) of a target's texels.
fn coverage_of(width: u32, height: u32, texels: &[[f32; 4]]) -> CoverageImage {
    CoverageImage {
        width,
        height,
        data: texels.iter().map(|t| t[3]).collect(),
    }
}

/// A read-back under way (see [`CoverageTarget::start_readback`]).
pub struct PendingReadback {
    buffer: wgpu::Buffer,
    state: Arc<Mutex<Option<Result<(), wgpu::BufferAsyncError>>>>,
    width: u32,
    height: u32,
    padded_row_bytes: u32,
}

impl PendingReadback {
    /// Whether the GPU has answered (the image can be taken). Never waits.
    pub fn is_answered(&self, gpu: &GpuContext) -> bool {
        // Non-blocking; a page's browser delivers answers between frames by itself.
        let _ = gpu.device.poll(wgpu::PollType::Poll);
        self.state
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .is_some()
    }

    /// The coverage as the method wrote it, once [`PendingReadback::is_answered`]; an
    /// error before.
    pub fn take(self) -> Result<CoverageImage, Error> {
        let answer = self
            .state
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .take()
            .ok_or_else(|| Error::Gpu("a read-back was taken before the GPU answered".into()))?;
        let unreadable = |e: &dyn std::fmt::Display| {
            Error::Gpu(format!("cannot read a buffer back from the GPU: {e}"))
        };
        answer.map_err(|e| unreadable(&e))?;
        let bytes = self
            .buffer
            .get_mapped_range(..)
            .map_err(|e| unreadable(&e))?
            .to_vec();
        self.buffer.unmap();
        let texels = texels_of(&bytes, self.width, self.padded_row_bytes);
        Ok(coverage_of(self.width, self.height, &texels))
    }
}

/// A render pass drawing into `view` with no depth or stencil, cleared to transparent,
/// timed by `timestamps` where given.
pub fn clearing_pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    view: &wgpu::TextureView,
    label: &str,
    timestamps: Option<wgpu::RenderPassTimestampWrites<'_>>,
) -> wgpu::RenderPass<'e> {
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some(label),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations {
                load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                store: wgpu::StoreOp::Store,
            },
        })],
        depth_stencil_attachment: None,
        timestamp_writes: timestamps,
        occlusion_query_set: None,
        multiview_mask: None,
    })
}
