//! The render pipelines and their stencil states: the fan and curve triangles counted
//! into the stencil, even-odd's layer fold, and the cover that turns the stencil into
//! coverage.

use super::jitter::{jitter_buffer, jitter_stride};
use super::overlay::wireframe_pipelines;
use super::{FillRule, Settings};
use crate::gpu::msaa::STENCIL_FORMAT;
use crate::gpu::{CoverageTarget, GpuContext};
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

/// What a pipeline does to colour.
pub(super) enum ColorOut {
    /// Nothing: stencil only.
    None,
    /// Adds to rgba.
    Add,
    /// Replaces rgb, keeps alpha (coverage).
    ReplaceRgb,
}

/// Compiles one pipeline of the method.
pub(super) struct Builder<'a> {
    pub(super) device: &'a wgpu::Device,
    pub(super) layout: &'a wgpu::PipelineLayout,
    pub(super) shader: &'a wgpu::ShaderModule,
    pub(super) samples: u32,
}

impl Builder<'_> {
    /// A pipeline with entry points `vertex` and `fragment`; `stencil` None for passes
    /// without a stencil attachment.
    pub(super) fn build(
        &self,
        label: &str,
        (vertex, fragment): (&str, &str),
        topology: wgpu::PrimitiveTopology,
        stencil: Option<wgpu::StencilState>,
        color: ColorOut,
    ) -> wgpu::RenderPipeline {
        let add = wgpu::BlendComponent {
            src_factor: wgpu::BlendFactor::One,
            dst_factor: wgpu::BlendFactor::One,
            operation: wgpu::BlendOperation::Add,
        };
        let (blend, write_mask) = match color {
            ColorOut::None => (None, wgpu::ColorWrites::empty()),
            ColorOut::Add => (
                Some(wgpu::BlendState {
                    color: add,
                    alpha: add,
                }),
                wgpu::ColorWrites::ALL,
            ),
            ColorOut::ReplaceRgb => (None, wgpu::ColorWrites::COLOR),
        };
        self.device
            .create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(self.layout),
                vertex: wgpu::VertexState {
                    module: self.shader,
                    entry_point: Some(vertex),
                    compilation_options: Default::default(),
                    buffers: &[],
                },
                primitive: wgpu::PrimitiveState {
                    topology,
                    // Both faces count, with opposite signs under nonzero.
                    cull_mode: None,
                    ..Default::default()
                },
                depth_stencil: stencil.map(|stencil| wgpu::DepthStencilState {
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
                    module: self.shader,
                    entry_point: Some(fragment),
                    compilation_options: Default::default(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format: CoverageTarget::FORMAT,
                        blend,
                        write_mask,
                    })],
                }),
                multiview_mask: None,
                cache: None,
            })
    }
}

impl Pipelines {
    pub(super) fn new(gpu: &GpuContext, settings: &Settings) -> Pipelines {
        let device = &gpu.device;
        let storage = |binding| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::VERTEX,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only: true },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let uniform = |binding, dynamic| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: dynamic,
                min_binding_size: None,
            },
            count: None,
        };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("xor-stencil"),
            entries: &[
                storage(0),
                uniform(1, false),
                storage(2),
                storage(3),
                storage(4),
                uniform(5, true),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("xor-stencil"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let shader = crate::gpu::shaders::create_module(device, "xor_stencil.wgsl");
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
            ColorOut::None,
        );
        let curve = builder.build(
            "xor-stencil curves",
            ("vs_curve", "fs_curve"),
            TriangleList,
            Some(count),
            ColorOut::None,
        );
        // Under even-odd, a layer's odd samples become exactly COVERED_BIT (the stencil
        // reference while it draws): parity cleared, covered set, whatever was there.
        let fold_layer = (settings.fill == FillRule::EvenOdd).then(|| {
            builder.build(
                "xor-stencil layer",
                ("vs_cover", "fs_stencil_only"),
                TriangleStrip,
                Some(stencil(face(NotEqual, Keep, Replace), 1, 0xff)),
                ColorOut::None,
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
