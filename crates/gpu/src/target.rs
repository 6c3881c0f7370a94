//! The texture every method renders its coverage into, and reading it back.

use std::sync::{Arc, Mutex};

use super::context::GpuContext;
use glyphscope_core::Error;
use glyphscope_core::coverage::CoverageImage;

/// What a coverage target holds besides coverage, chosen by whoever makes the target
/// for what it will read back.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Channels {
    /// Coverage alone, one half float a pixel (`R16Float`): every frame that draws no
    /// overlay. Each fragment's blend reads and writes 2 bytes, not 8 — the difference
    /// that made the harness, not the methods, most of the atlas's time (docs/methods/
    /// atlas.md, "Where the atlas's time goes").
    Coverage,
    /// Coverage in alpha and an overlay's premultiplied colour in rgb (`Rgba16Float`):
    /// frames that draw an overlay, the counting passes (a count in red), and the
    /// explorer's panes, which switch overlays on and off.
    Picture,
}

impl Channels {
    /// The channels a frame needs: a picture where it draws an overlay.
    pub fn for_overlay(overlay: bool) -> Channels {
        if overlay {
            Channels::Picture
        } else {
            Channels::Coverage
        }
    }

    /// The overlay a frame into a target of these channels draws: none into a
    /// coverage-only target, which has nowhere to put its colour (the frame draws the
    /// coverage alone, exactly as with no overlay).
    pub fn shown<T>(self, overlay: Option<T>) -> Option<T> {
        overlay.filter(|_| self == Channels::Picture)
    }

    /// Half floats either way: blendable everywhere, exact for 0 and 1, and about 3
    /// decimal digits in between — finer than the 8 bits an image is saved with. Both
    /// formats round a blend's sum the same way, so a method's coverage is the same bits
    /// in either.
    pub fn format(self) -> wgpu::TextureFormat {
        match self {
            Channels::Coverage => wgpu::TextureFormat::R16Float,
            Channels::Picture => wgpu::TextureFormat::Rgba16Float,
        }
    }

    /// Bytes of one texel of [`Channels::format`].
    pub fn texel_bytes(self) -> u32 {
        match self {
            Channels::Coverage => 2,
            Channels::Picture => 8,
        }
    }

    /// The colour state of pipelines that add their coverage up: where instances'
    /// quads overlap, disjoint glyphs sum to the union's coverage, as in the reference.
    pub fn additive(self) -> wgpu::ColorTargetState {
        let add = wgpu::BlendComponent {
            src_factor: wgpu::BlendFactor::One,
            dst_factor: wgpu::BlendFactor::One,
            operation: wgpu::BlendOperation::Add,
        };
        wgpu::ColorTargetState {
            format: self.format(),
            blend: Some(wgpu::BlendState {
                color: add,
                alpha: add,
            }),
            write_mask: wgpu::ColorWrites::ALL,
        }
    }

    /// The channels of this target a pipeline writing `mask` of a picture's channels
    /// writes: a coverage target's one channel (red) stands for a picture's alpha, and
    /// an overlay's rgb has nowhere to go.
    pub fn write_mask(self, mask: wgpu::ColorWrites) -> wgpu::ColorWrites {
        match self {
            Channels::Picture => mask,
            Channels::Coverage if mask.contains(wgpu::ColorWrites::ALPHA) => wgpu::ColorWrites::RED,
            Channels::Coverage => wgpu::ColorWrites::empty(),
        }
    }
}

/// A coverage target: coverage, and with [`Channels::Picture`] an overlay's colour.
pub struct CoverageTarget {
    pub texture: wgpu::Texture,
    pub view: wgpu::TextureView,
    pub width: u32,
    pub height: u32,
    pub channels: Channels,
}

impl CoverageTarget {
    pub fn new(
        gpu: &GpuContext,
        width: u32,
        height: u32,
        channels: Channels,
    ) -> Result<CoverageTarget, Error> {
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
                format: channels.format(),
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
                channels,
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

    /// Copies the overlay picture (rgb, premultiplied, over black) back as 8-bit RGB,
    /// sRGB-less and clamped: `width × height` pixels of 3 bytes, row-major. Only a
    /// [`Channels::Picture`] target has one.
    pub fn readback_rgb8(&self, gpu: &GpuContext) -> Result<Vec<u8>, Error> {
        if self.channels != Channels::Picture {
            return Err(Error::Gpu(
                "a coverage-only target holds no overlay picture to read back".into(),
            ));
        }
        let texels = self.read_texels(gpu)?;
        Ok(texels
            .iter()
            .flat_map(|t| [t[0], t[1], t[2]])
            .map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8)
            .collect())
    }

    /// Every texel as f32 rgba, row-major; a coverage-only target's as (0, 0, 0, coverage).
    pub fn read_texels(&self, gpu: &GpuContext) -> Result<Vec<[f32; 4]>, Error> {
        let bytes = gpu.catching_errors("reading the coverage target back", || {
            let buffer = self.copy_to_buffer(gpu);
            gpu.read_buffer(&buffer)
        })?;
        Ok(texels_of(
            &bytes,
            self.width,
            self.padded_row_bytes(),
            self.channels,
        ))
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
            channels: self.channels,
        })
    }

    fn padded_row_bytes(&self) -> u32 {
        // Buffer rows of a texture copy must start on 256-byte boundaries.
        (self.width * self.channels.texel_bytes())
            .next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT)
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

/// Half-float rows of `channels`, each padded to `padded_row_bytes`, as f32 rgba texels.
fn texels_of(bytes: &[u8], width: u32, padded_row_bytes: u32, channels: Channels) -> Vec<[f32; 4]> {
    let texel_bytes = channels.texel_bytes() as usize;
    let row_bytes = width as usize * texel_bytes;
    let half = |t: &[u8], i: usize| half::f16::from_le_bytes([t[i], t[i + 1]]).to_f32();
    let mut texels = Vec::new();
    for row in bytes.chunks_exact(padded_row_bytes as usize) {
        // Two bytes a channel, little-endian.
        let texel = row[..row_bytes].chunks_exact(texel_bytes);
        match channels {
            Channels::Coverage => texels.extend(texel.map(|t| [0.0, 0.0, 0.0, half(t, 0)])),
            Channels::Picture => texels.extend(texel.map(|t| [0, 2, 4, 6].map(|i| half(t, i)))),
        }
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
    channels: Channels,
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
        let texels = texels_of(&bytes, self.width, self.padded_row_bytes, self.channels);
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
