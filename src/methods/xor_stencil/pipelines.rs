//! The render pipelines and their stencil states — the fan and curve triangles counted
//! into the stencil, even-odd's layer fold, the cover that turns the stencil into
//! coverage, the wireframe overlay's lines — and the uniform buffer that hands each
//! jittered pass its offset and weight.

use glam::DVec2;

use super::jitter::jitter_offsets;
use super::params::{FillRule, NAME, Settings};
use crate::gpu::kit::{self, ColorOut, PerTarget, PipelineBuilder, Slot};
use crate::gpu::shaders::Shader;
use crate::gpu::{Channels, GpuContext};
use crate::methods::Overlay;

pub(super) const SHADER: Shader = crate::method_shader!("xor_stencil.wgsl");

/// Stencil bit that marks, under even-odd, samples some earlier layer covered.
pub(super) const COVERED_BIT: u32 = 0x80;

/// Every pipeline of the method, built once per device, settings and kind of target, and
/// the jitter uniforms of its passes.
pub(super) struct Pipelines {
    pub(super) layout: wgpu::BindGroupLayout,
    pub(super) pipeline_layout: wgpu::PipelineLayout,
    pub(super) shader: wgpu::ShaderModule,
    settings: Settings,
    draws: PerTarget<Draws>,
    /// For `curves_per_pixel`, built when first asked.
    pub(super) count: Option<wgpu::RenderPipeline>,
    /// One `Jitter` per pass, and an unshifted one for the overlay, `jitter_stride`
    /// bytes apart.
    pub(super) jitter: wgpu::Buffer,
    pub(super) jitter_stride: u64,
}

/// The pipelines of a frame into one kind of target (wgpu's handles: a clone shares
/// them).
#[derive(Clone)]
pub(super) struct Draws {
    pub(super) fan: wgpu::RenderPipeline,
    pub(super) curve: wgpu::RenderPipeline,
    /// Even-odd only: a layer's odd samples → `COVERED_BIT`.
    pub(super) fold_layer: Option<wgpu::RenderPipeline>,
    pub(super) cover: wgpu::RenderPipeline,
    pub(super) wireframe: Option<[wgpu::RenderPipeline; 2]>,
}

/// Stencil state for both faces alike.
fn stencil(face: wgpu::StencilFaceState, read_mask: u32, write_mask: u32) -> wgpu::StencilState {
    wgpu::StencilState {
        front: face,
        back: face,
        read_mask,
        write_mask,
    }
}

fn face(
    compare: wgpu::CompareFunction,
    fail_op: wgpu::StencilOperation,
    pass_op: wgpu::StencilOperation,
) -> wgpu::StencilFaceState {
    wgpu::StencilFaceState {
        compare,
        fail_op,
        depth_fail_op: wgpu::StencilOperation::Keep,
        pass_op,
    }
}

/// Colour output of the passes that only count into the stencil.
const STENCIL_ONLY: ColorOut = ColorOut::Replace(wgpu::ColorWrites::empty());
/// Colour output of the overlay's lines: rgb replaced, alpha (coverage) kept.
const REPLACE_RGB: ColorOut = ColorOut::Replace(wgpu::ColorWrites::COLOR);

/// The line pipelines of the fan triangles and of the curve triangles.
fn wireframe_pipelines(builder: &Builder) -> [wgpu::RenderPipeline; 2] {
    ["vs_wire_fan", "vs_wire_curve"].map(|vertex| {
        builder.build(
            "xor-stencil lines",
            (vertex, "fs_wire"),
            wgpu::PrimitiveTopology::LineList,
            Some(wgpu::StencilState::default()),
            REPLACE_RGB,
        )
    })
}

/// Compiles one pipeline of the method: its shader, layout, sample count and kind of
/// target.
pub(super) struct Builder<'a> {
    pub(super) device: &'a wgpu::Device,
    pub(super) layout: &'a wgpu::PipelineLayout,
    pub(super) shader: &'a wgpu::ShaderModule,
    pub(super) samples: u32,
    pub(super) channels: Channels,
    /// Values of the shader's `override` constants.
    pub(super) constants: &'a [(&'a str, f64)],
}

impl Builder<'_> {
    /// A pipeline with entry points `vertex` and `fragment`; `stencil` None for passes
    /// without a stencil attachment. No face is culled: both count, with opposite signs
    /// under nonzero.
    pub(super) fn build(
        &self,
        label: &str,
        (vertex, fragment): (&str, &str),
        topology: wgpu::PrimitiveTopology,
        stencil: Option<wgpu::StencilState>,
        color: ColorOut,
    ) -> wgpu::RenderPipeline {
        let builder = PipelineBuilder::new(label, self.layout, self.shader)
            .entry_points(vertex, fragment)
            .constants(self.constants)
            .topology(topology)
            .samples(self.samples)
            .color(color);
        match stencil {
            Some(stencil) => builder.stencil(stencil),
            None => builder,
        }
        .build(self.device, self.channels)
    }
}

impl Pipelines {
    pub(super) fn new(gpu: &GpuContext, settings: &Settings) -> Pipelines {
        let device = &gpu.device;
        // Glyph bounds, fan points, curve points, the jitter of each pass (`@group(1)` of
        // xor_stencil.wgsl).
        let slots = [
            Slot::Storage,
            Slot::Storage,
            Slot::Storage,
            Slot::DynamicUniform,
        ];
        let layout = kit::layout(gpu, NAME, &slots);
        let pipeline_layout = kit::pipeline_layout(gpu, NAME, Some(&layout));
        let jitter_stride = jitter_stride(device);
        Pipelines {
            jitter: jitter_buffer(gpu, settings, jitter_stride as usize),
            jitter_stride,
            layout,
            pipeline_layout,
            shader: SHADER.module(device),
            settings: *settings,
            draws: PerTarget::default(),
            count: None,
        }
    }

    /// The pipelines of a frame into targets of `channels`.
    pub(super) fn draws(&mut self, gpu: &GpuContext, channels: Channels) -> Draws {
        let overlay = channels.shown(self.settings.overlay);
        let tint = if overlay.is_some() { OVERLAY_TINT } else { 1.0 };
        let builder = Builder {
            device: &gpu.device,
            layout: &self.pipeline_layout,
            shader: &self.shader,
            samples: self.settings.samples,
            channels,
            constants: &[("TINT", tint)],
        };
        self.draws
            .get(channels, |_| Draws::new(&builder, &self.settings, overlay))
            .clone()
    }

    /// Dynamic offset of pass `k`'s `Jitter` (pass `passes`: the unshifted one).
    pub(super) fn jitter_offset(&self, k: u32) -> u32 {
        (u64::from(k) * self.jitter_stride) as u32
    }
}

impl Draws {
    /// The pipelines of `settings`, drawing `overlay` (none into a coverage-only target).
    fn new(builder: &Builder, settings: &Settings, overlay: Option<Overlay>) -> Draws {
        use wgpu::CompareFunction::{Always, NotEqual};
        use wgpu::PrimitiveTopology::{TriangleList, TriangleStrip};
        use wgpu::StencilOperation::{DecrementWrap, IncrementWrap, Invert, Keep, Replace, Zero};
        let count = match settings.fill {
            // Front faces add one, back faces take one away: the winding number, mod 256.
            FillRule::NonZero => wgpu::StencilState {
                front: face(Always, Keep, IncrementWrap),
                back: face(Always, Keep, DecrementWrap),
                read_mask: 0xff,
                write_mask: 0xff,
            },
            // Bit 0 flips: the parity. The covered bit is left alone.
            FillRule::EvenOdd => stencil(face(Always, Keep, Invert), 0, 1),
        };
        let fan = builder.build(
            "xor-stencil fan",
            ("vs_fan", "fs_stencil_only"),
            TriangleList,
            Some(count.clone()),
            STENCIL_ONLY,
        );
        let curve = builder.build(
            "xor-stencil curves",
            ("vs_curve", "fs_curve"),
            TriangleList,
            Some(count),
            STENCIL_ONLY,
        );
        // Under even-odd, a layer's odd samples become exactly COVERED_BIT (the stencil
        // reference while it draws): parity cleared, covered set, whatever was there.
        let fold_layer = (settings.fill == FillRule::EvenOdd).then(|| {
            builder.build(
                "xor-stencil layer",
                ("vs_cover", "fs_stencil_only"),
                TriangleStrip,
                Some(stencil(face(NotEqual, Keep, Replace), 1, 0xff)),
                STENCIL_ONLY,
            )
        });
        let cover_mask = match settings.fill {
            FillRule::NonZero => 0xff,
            FillRule::EvenOdd => COVERED_BIT,
        };
        // Stencil reference 0: samples whose masked stencil is nonzero get this pass's
        // coverage, and are cleared for the next pass.
        let cover = builder.build(
            "xor-stencil cover",
            ("vs_cover", "fs_cover"),
            TriangleStrip,
            Some(stencil(face(NotEqual, Keep, Zero), cover_mask, 0xff)),
            ColorOut::Add,
        );
        let wireframe =
            (overlay == Some(Overlay::TriangleWireframe)).then(|| wireframe_pipelines(builder));
        Draws {
            fan,
            curve,
            fold_layer,
            cover,
            wireframe,
        }
    }
}

/// Grey level of coverage under the wireframe, so that the lines stand out.
const OVERLAY_TINT: f64 = 0.45;

/// The `Jitter` uniform of `xor_stencil.wgsl`, one per pass at the device's uniform
/// offset alignment.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub(super) struct Jitter {
    offset: [f32; 2],
    weight: f32,
    _pad: f32,
}

/// Bytes between two passes' `Jitter`s: the device's uniform offset alignment.
fn jitter_stride(device: &wgpu::Device) -> u64 {
    u64::from(device.limits().min_uniform_buffer_offset_alignment).max(size_of::<Jitter>() as u64)
}

/// The `Jitter` entries of every pass of `settings`, and an unshifted one last.
fn jitter_buffer(gpu: &GpuContext, settings: &Settings, stride: usize) -> wgpu::Buffer {
    let offsets = jitter_offsets(settings.passes, settings.samples);
    let weight = 1.0 / settings.passes as f32;
    let mut bytes = vec![0u8; stride * (offsets.len() + 1)];
    for (k, offset) in offsets.iter().chain([&DVec2::ZERO]).enumerate() {
        let entry = Jitter {
            offset: offset.as_vec2().to_array(),
            weight,
            _pad: 0.0,
        };
        bytes[k * stride..][..size_of::<Jitter>()].copy_from_slice(bytemuck::bytes_of(&entry));
    }
    let buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("xor-stencil jitter"),
        size: bytes.len() as u64,
        usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    gpu.queue.write_buffer(&buffer, 0, &bytes);
    buffer
}
