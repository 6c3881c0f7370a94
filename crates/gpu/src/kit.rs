//! The few builders every method's GPU setup is made of: bind group layouts and bind
//! groups numbered by position, the fixed `@group(0)` every method shares (the
//! `Frame` uniform and the `GlyphInstance` array of `common.wgsl`), one render pipeline
//! builder, and the curves-per-pixel tally.

use super::{
    context::GpuContext,
    msaa::STENCIL_FORMAT,
    target::{Channels, CoverageTarget},
};
use glyphscope_core::Error;

/// A binding of a layout built by [`layout`], at its position in the list.
#[derive(Clone, Copy, Debug)]
pub enum Slot {
    Uniform,
    /// A uniform bound with a dynamic offset (one slice of a larger buffer per draw).
    DynamicUniform,
    /// A read-only storage buffer.
    Storage,
    /// A filterable float 2D texture.
    Texture,
    /// A filtering sampler.
    Sampler,
    /// An unsigned-integer 2D texture read texel by texel (`textureLoad`): a list of
    /// records laid out by [`data_texture`].
    DataTexture,
}

impl Slot {
    fn binding_type(self) -> wgpu::BindingType {
        let buffer = |ty, has_dynamic_offset| wgpu::BindingType::Buffer {
            ty,
            has_dynamic_offset,
            min_binding_size: None,
        };
        match self {
            Slot::Uniform => buffer(wgpu::BufferBindingType::Uniform, false),
            Slot::DynamicUniform => buffer(wgpu::BufferBindingType::Uniform, true),
            Slot::Storage => buffer(wgpu::BufferBindingType::Storage { read_only: true }, false),
            Slot::Texture => wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: true },
                view_dimension: wgpu::TextureViewDimension::D2,
                multisampled: false,
            },
            Slot::Sampler => wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
            Slot::DataTexture => wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Uint,
                view_dimension: wgpu::TextureViewDimension::D2,
                multisampled: false,
            },
        }
    }
}

/// Texels a row of a [`data_texture`]: texel `i` lies at (i mod this, i / this). A
/// power of two within WebGPU's least 2D texture size (8192), so that a shader finds a
/// texel by a mask and a shift (`data_texel` in crates/text/shaders/winding.wgsl).
pub const DATA_TEXTURE_WIDTH: u32 = 4096;

/// A texture holding `items` as a list of texels of `format` (`R32Uint`, 4 bytes, or
/// `Rgba32Uint`, 16; an item may span several texels), row after row of
/// [`DATA_TEXTURE_WIDTH`], the last row padded with zeros; and its bytes. A list too
/// long for the device's tallest texture is an [`Error::Gpu`] that says so.
///
/// Why a texture rather than a storage buffer: a software device (lavapipe) reads a
/// storage buffer at a per-lane index lane by lane, word by word, where it fetches
/// texels for all lanes of a SIMD group at once (see docs/methods/winding.md).
pub fn data_texture<T: bytemuck::Pod>(
    gpu: &GpuContext,
    label: &str,
    items: &[T],
    format: wgpu::TextureFormat,
) -> Result<(wgpu::Texture, u64), Error> {
    let texel = u64::from(
        format
            .block_copy_size(None)
            .expect("an uncompressed format"),
    );
    let mut bytes: Vec<u8> = bytemuck::cast_slice(items).to_vec();
    assert_eq!(
        bytes.len() as u64 % texel,
        0,
        "{label}: items fill whole texels"
    );
    let width = u64::from(DATA_TEXTURE_WIDTH);
    let rows = (bytes.len() as u64 / texel).div_ceil(width).max(1);
    let most = u64::from(gpu.max_texture_side());
    if rows > most {
        return Err(Error::Gpu(format!(
            "{label}: {} texels need {rows} rows of {width}, past this device's {most}",
            bytes.len() as u64 / texel
        )));
    }
    bytes.resize((rows * width * texel) as usize, 0);
    let texture = sampled_texture(
        gpu,
        label,
        [DATA_TEXTURE_WIDTH, rows as u32],
        format,
        &bytes,
    );
    Ok((texture, bytes.len() as u64))
}

/// A sampled 2D texture of `format`, `size` texels, holding `texels` row after row.
pub fn sampled_texture(
    gpu: &GpuContext,
    label: &str,
    size: [u32; 2],
    format: wgpu::TextureFormat,
    texels: &[u8],
) -> wgpu::Texture {
    let extent = wgpu::Extent3d {
        width: size[0],
        height: size[1],
        depth_or_array_layers: 1,
    };
    let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some(label),
        size: extent,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    let texel_bytes = format.block_copy_size(None).unwrap_or(1);
    gpu.queue.write_texture(
        texture.as_image_copy(),
        texels,
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(size[0] * texel_bytes),
            rows_per_image: None,
        },
        extent,
    );
    texture
}

/// A bind group layout whose binding `i` is `slots[i]`, seen by both stages.
pub fn layout(gpu: &GpuContext, label: &str, slots: &[Slot]) -> wgpu::BindGroupLayout {
    let entries: Vec<_> = (0u32..)
        .zip(slots)
        .map(|(binding, slot)| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
            ty: slot.binding_type(),
            count: None,
        })
        .collect();
    gpu.device
        .create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some(label),
            entries: &entries,
        })
}

/// A bind group whose binding `i` is `resources[i]`.
pub fn bind_group(
    gpu: &GpuContext,
    label: &str,
    layout: &wgpu::BindGroupLayout,
    resources: &[wgpu::BindingResource],
) -> wgpu::BindGroup {
    let entries: Vec<_> = (0u32..)
        .zip(resources)
        .map(|(binding, resource)| wgpu::BindGroupEntry {
            binding,
            resource: resource.clone(),
        })
        .collect();
    gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some(label),
        layout,
        entries: &entries,
    })
}

/// The layout of `@group(0)` in every method shader: binding 0 the `Frame` uniform,
/// binding 1 the `GlyphInstance` array.
pub fn frame_layout(gpu: &GpuContext) -> wgpu::BindGroupLayout {
    layout(gpu, "frame and instances", &[Slot::Uniform, Slot::Storage])
}

/// A pipeline layout of `@group(0)` = [`frame_layout`] and the method's own `@group(1)`
/// (if it binds anything more).
pub fn pipeline_layout(
    gpu: &GpuContext,
    label: &str,
    own: Option<&wgpu::BindGroupLayout>,
) -> wgpu::PipelineLayout {
    let frame = frame_layout(gpu);
    gpu.device
        .create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(label),
            bind_group_layouts: &[Some(&frame), own],
            immediate_size: 0,
        })
}

/// What a pipeline does to the target's colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorOut {
    /// Adds to rgba: where quads overlap, disjoint glyphs sum to their union's coverage.
    Add,
    /// Writes the channels of the mask (a picture's: alpha is coverage), replacing what
    /// was there.
    Replace(wgpu::ColorWrites),
}

/// One render pipeline drawing into a coverage target (or its multisampled twin). By
/// default: `vs_main` and `fs_main`, a triangle strip (one quad per instance), one
/// sample, no stencil, colour added.
pub struct PipelineBuilder<'a> {
    label: &'a str,
    layout: &'a wgpu::PipelineLayout,
    module: &'a wgpu::ShaderModule,
    entry_points: (&'a str, &'a str),
    constants: &'a [(&'a str, f64)],
    buffers: &'a [Option<wgpu::VertexBufferLayout<'a>>],
    topology: wgpu::PrimitiveTopology,
    samples: u32,
    stencil: Option<wgpu::StencilState>,
    color: ColorOut,
}

impl<'a> PipelineBuilder<'a> {
    pub fn new(
        label: &'a str,
        layout: &'a wgpu::PipelineLayout,
        module: &'a wgpu::ShaderModule,
    ) -> Self {
        PipelineBuilder {
            label,
            layout,
            module,
            entry_points: ("vs_main", "fs_main"),
            constants: &[],
            buffers: &[],
            topology: wgpu::PrimitiveTopology::TriangleStrip,
            samples: 1,
            stencil: None,
            color: ColorOut::Add,
        }
    }

    pub fn label(mut self, label: &'a str) -> Self {
        self.label = label;
        self
    }

    pub fn entry_points(mut self, vertex: &'a str, fragment: &'a str) -> Self {
        self.entry_points = (vertex, fragment);
        self
    }

    /// Values of the shader's `override` constants.
    pub fn constants(mut self, constants: &'a [(&'a str, f64)]) -> Self {
        self.constants = constants;
        self
    }

    pub fn vertex_buffers(mut self, buffers: &'a [Option<wgpu::VertexBufferLayout<'a>>]) -> Self {
        self.buffers = buffers;
        self
    }

    pub fn topology(mut self, topology: wgpu::PrimitiveTopology) -> Self {
        self.topology = topology;
        self
    }

    pub fn samples(mut self, samples: u32) -> Self {
        self.samples = samples;
        self
    }

    /// Tests and writes a [`STENCIL_FORMAT`] attachment.
    pub fn stencil(mut self, stencil: wgpu::StencilState) -> Self {
        self.stencil = Some(stencil);
        self
    }

    pub fn color(mut self, color: ColorOut) -> Self {
        self.color = color;
        self
    }

    /// The pipeline, for targets of `channels` (a frame's target decides: see
    /// [`PerTarget`]).
    pub fn build(&self, device: &wgpu::Device, channels: Channels) -> wgpu::RenderPipeline {
        let target = match self.color {
            ColorOut::Add => channels.additive(),
            ColorOut::Replace(mask) => wgpu::ColorTargetState {
                format: channels.format(),
                blend: None,
                write_mask: channels.write_mask(mask),
            },
        };
        self.build_into(device, target)
    }

    /// The pipeline, drawing into a target that is not a coverage target (a caller's
    /// colour target, `target` saying its format and blending).
    pub fn build_into(
        &self,
        device: &wgpu::Device,
        target: wgpu::ColorTargetState,
    ) -> wgpu::RenderPipeline {
        let options = wgpu::PipelineCompilationOptions {
            constants: self.constants,
            ..Default::default()
        };
        device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(self.label),
            layout: Some(self.layout),
            vertex: wgpu::VertexState {
                module: self.module,
                entry_point: Some(self.entry_points.0),
                compilation_options: options.clone(),
                buffers: self.buffers,
            },
            // No culling: meshes whose faces count with opposite signs need both.
            primitive: wgpu::PrimitiveState {
                topology: self.topology,
                ..Default::default()
            },
            depth_stencil: self.stencil.clone().map(|stencil| wgpu::DepthStencilState {
                format: STENCIL_FORMAT,
                depth_write_enabled: None,
                depth_compare: None,
                stencil,
                bias: Default::default(),
            }),
            multisample: wgpu::MultisampleState {
                count: self.samples,
                ..Default::default()
            },
            fragment: Some(wgpu::FragmentState {
                module: self.module,
                entry_point: Some(self.entry_points.1),
                compilation_options: options,
                targets: &[Some(target)],
            }),
            multiview_mask: None,
            cache: None,
        })
    }
}

/// Something a method builds for each kind of target it is given (its pipelines),
/// built on the first frame into such a target and kept: the target's [`Channels`]
/// decide, so that one method draws a lean coverage-only frame for the bench and a
/// picture for the explorer without being told.
pub struct PerTarget<T>([Option<T>; 2]);

impl<T> Default for PerTarget<T> {
    fn default() -> Self {
        PerTarget([None, None])
    }
}

impl<T> PerTarget<T> {
    /// The one for targets of `channels`, built with `build` the first time.
    pub fn get(&mut self, channels: Channels, build: impl FnOnce(Channels) -> T) -> &T {
        let slot = &mut self.0[match channels {
            Channels::Coverage => 0,
            Channels::Picture => 1,
        }];
        slot.get_or_insert_with(|| build(channels))
    }
}

/// Curves evaluated per pixel with nonzero coverage, for methods that count them: `draw`
/// records a frame into a fresh picture target the camera's size that writes each pixel's count
/// to red and its coverage to alpha (the method's counting output).
pub fn count_curves(
    gpu: &GpuContext,
    size: (u32, u32),
    draw: impl FnOnce(&mut wgpu::CommandEncoder, &CoverageTarget) -> Result<(), Error>,
) -> Result<CurveCost, Error> {
    let texels = counting_pass(gpu, size, draw)?;
    Ok(tally(
        texels.iter().filter(|t| t[3] > 0.0).map(|t| t[0]),
        1.0,
    ))
}

/// The texels `draw` leaves in a fresh target of `width` × `height`, as written: a
/// counting output's raw per-pixel sums (the target adds overlapping quads up).
pub fn counting_pass(
    gpu: &GpuContext,
    (width, height): (u32, u32),
    draw: impl FnOnce(&mut wgpu::CommandEncoder, &CoverageTarget) -> Result<(), Error>,
) -> Result<Vec<[f32; 4]>, Error> {
    let target = CoverageTarget::new(gpu, width, height, Channels::Picture)?;
    gpu.catching_errors("counting per pixel", || {
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        draw(&mut encoder, &target)?;
        gpu.queue.submit([encoder.finish()]);
        gpu.wait_idle()
    })?;
    target.read_texels(gpu)
}

/// The largest count the counting passes hold exactly: their target is
/// a [`Channels::Picture`] target's, half floats, which hold every integer up to 2¹¹ and only
/// every other one past it (then every fourth, …, and nothing past 65 504).
pub const EXACT_COUNT_LIMIT: f32 = 2048.0;

/// Mean and most of the curves counted at each covered pixel, from the count target's
/// raw values, each worth `scale` curves (the samples a resolve averaged). A value at
/// [`EXACT_COUNT_LIMIT`] or past it (or not finite) is no longer the count: it is taken
/// as the limit and reported in `saturated`, so the figures become lower bounds that
/// say so, rather than rounded numbers that look exact.
pub fn tally(raw_counts: impl Iterator<Item = f32>, scale: f64) -> CurveCost {
    let (mut sum, mut covered, mut max, mut saturated) = (0.0, 0u64, 0u32, 0u64);
    for raw in raw_counts {
        // Written so that NaN, too, is not exact.
        let exact = raw < EXACT_COUNT_LIMIT;
        if !exact {
            saturated += 1;
        }
        let n = f64::from(if exact { raw } else { EXACT_COUNT_LIMIT }) * scale;
        sum += n;
        covered += 1;
        max = max.max(n.round() as u32);
    }
    CurveCost {
        mean: if covered > 0 {
            sum / covered as f64
        } else {
            0.0
        },
        max,
        saturated,
    }
}

/// What [`count_curves`] tallied: mean and most curves per covered pixel.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct CurveCost {
    /// A lower bound where `saturated` is not 0.
    pub mean: f64,
    /// At least this many where `saturated` is not 0 (see [`CurveCost::max_text`]).
    pub max: u32,
    /// Covered pixels whose count reached [`EXACT_COUNT_LIMIT`], counted as the limit.
    pub saturated: u64,
}

impl CurveCost {
    /// `max` as reports print it: "≥ 2048" where a count reached the exact limit.
    pub fn max_text(&self) -> String {
        if self.saturated > 0 {
            format!("≥ {}", self.max)
        } else {
            self.max.to_string()
        }
    }
}
