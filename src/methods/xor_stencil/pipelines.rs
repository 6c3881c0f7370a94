//! The render pipelines and their stencil states: the fan and curve triangles counted
//! into the stencil, even-odd's layer fold, and the cover that turns the stencil into
//! coverage.

use super::jitter::{jitter_buffer, jitter_stride};
use super::overlay::wireframe_pipelines;
use super::{FillRule, NAME, SHADER, Settings};
use crate::gpu::GpuContext;
use crate::gpu::kit::{self, ColorOut, PipelineBuilder, Slot};
use crate::methods::Overlay;

/// Stencil bit that marks, under even-odd, samples some earlier layer covered.
pub(super) const COVERED_BIT: u32 = 0x80;

/// Every pipeline of the method, built once per device and settings, and the jitter
/// uniforms of its passes.
pub(super) struct Pipelines {
    pub(super) layout: wgpu::BindGroupLayout,
    /// For the counting pipeline, built later.
    pub(super) pipeline_layout: wgpu::PipelineLayout,
    pub(super) shader: wgpu::ShaderModule,
    pub(super) fan: wgpu::RenderPipeline,
    pub(super) curve: wgpu::RenderPipeline,
    /// Even-odd only: a layer's odd samples → `COVERED_BIT`.
    pub(super) fold_layer: Option<wgpu::RenderPipeline>,
    pub(super) cover: wgpu::RenderPipeline,
    pub(super) wireframe: Option<[wgpu::RenderPipeline; 2]>,
    /// For `curves_per_pixel`, built when first asked.
    pub(super) count: Option<wgpu::RenderPipeline>,
    /// One `Jitter` per pass, and an unshifted one for the overlay, `jitter_stride`
    /// bytes apart.
    pub(super) jitter: wgpu::Buffer,
    pub(super) jitter_stride: u64,
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
pub(super) const STENCIL_ONLY: ColorOut = ColorOut::Replace(wgpu::ColorWrites::empty());
/// Colour output of the overlay's lines: rgb replaced, alpha (coverage) kept.
pub(super) const REPLACE_RGB: ColorOut = ColorOut::Replace(wgpu::ColorWrites::COLOR);

/// Compiles one pipeline of the method: its shader, layout and sample count.
pub(super) struct Builder<'a> {
    pub(super) device: &'a wgpu::Device,
    pub(super) layout: &'a wgpu::PipelineLayout,
    pub(super) shader: &'a wgpu::ShaderModule,
    pub(super) samples: u32,
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
            .topology(topology)
            .samples(self.samples)
            .color(color);
        match stencil {
            Some(stencil) => builder.stencil(stencil),
            None => builder,
        }
        .build(self.device)
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
        let shader = SHADER.module(device);
        let builder = Builder {
            device,
            layout: &pipeline_layout,
            shader: &shader,
            samples: settings.samples,
        };

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
        let wireframe = (settings.overlay == Some(Overlay::TriangleWireframe))
            .then(|| wireframe_pipelines(&builder));
        let jitter_stride = jitter_stride(device);
        Pipelines {
            jitter: jitter_buffer(gpu, settings, jitter_stride as usize),
            jitter_stride,
            layout,
            pipeline_layout,
            shader,
            fan,
            curve,
            fold_layer,
            cover,
            wireframe,
            count: None,
        }
    }
}
