//! `bounds`: a diagnostic method that draws each glyph instance's control-point
//! rectangle as one quad, with exact box-filter coverage.
//!
//! Its coverage is exact, so it proves the GPU path — transform convention, instance
//! quads, target, blending, readback — against the CPU reference on scenes whose glyphs
//! are rectangles. It is a check, not a speed floor: the per-pixel clipping loop is
//! heavy (its time on a scene: `glyphscope render --method bounds --stats S.json`).
//!
//! Per frame the CPU maps each rectangle's corners to image pixels in f64 and uploads
//! them, relative to an integer pixel near the instance, as f32; the fragment shader
//! clips each pixel square to the corners' quadrilateral (`shaders/bounds.wgsl`).

use glam::DVec2;

use super::Method;
use super::info::{MethodInfo, Role};
use crate::Error;
use crate::camera::Camera;
use crate::geometry::{Rect, project};
use crate::gpu::kit::{self, PerTarget, PipelineBuilder, Slot};
use crate::gpu::shaders::Shader;
use crate::gpu::{CoverageTarget, GpuContext};
use crate::scene::Scene;

/// `bounds`' row in the registry: a diagnostic, not benched.
pub const INFO: MethodInfo = MethodInfo {
    name: NAME,
    summary: "diagnostic: each glyph's control-point box with exact box-filter coverage, \
              a check of the GPU path",
    role: Role::Diagnostic,
    shader: Some(SHADER),
    params: &[],
    colour: [127, 127, 127],
    bench: &[],
    claims: &[],
    constructor: Some(&|_| Ok(Box::<Bounds>::default())),
};

pub const NAME: &str = "bounds";
const SHADER: Shader = crate::method_shader!("bounds.wgsl");

#[derive(Default)]
pub struct Bounds {
    /// Built on the first `prepare`; it depends on the device only.
    pipeline: Option<QuadPipeline>,
    /// What `prepare` keeps of the scene.
    prepared: Option<PreparedScene>,
}

struct QuadPipeline {
    layout: wgpu::PipelineLayout,
    shader: wgpu::ShaderModule,
    pipelines: PerTarget<wgpu::RenderPipeline>,
    /// The target size, for the vertex shader's pixel → clip-space step.
    view_buffer: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
}

struct PreparedScene {
    units_per_em: f64,
    /// Each instance's pen position and local rectangle: all that does not depend on
    /// the camera.
    placed: Vec<(DVec2, Rect)>,
    /// One [`QuadInstance`] per instance, rewritten every frame.
    quad_buffer: wgpu::Buffer,
    /// This frame's quads, kept to reuse the allocation.
    quads: Vec<QuadInstance>,
}

/// One quad as the vertex shader reads it (`Instance` in `bounds.wgsl`).
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct QuadInstance {
    /// An integer pixel near the instance; the corners are relative to it.
    origin: [i32; 2],
    /// The rectangle's corners in image pixels, in order around it.
    corners: [[f32; 2]; 4],
}

const QUAD_ATTRIBUTES: [wgpu::VertexAttribute; 3] =
    wgpu::vertex_attr_array![0 => Sint32x2, 1 => Float32x4, 2 => Float32x4];

impl QuadPipeline {
    fn new(gpu: &GpuContext) -> QuadPipeline {
        let device = &gpu.device;
        let shader = SHADER.module(device);
        // Only the `Frame` uniform of `@group(0)`: the corners come per instance, mapped
        // on the CPU.
        let bind_group_layout = kit::layout(gpu, NAME, &[Slot::Uniform]);
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(NAME),
            bind_group_layouts: &[Some(&bind_group_layout)],
            immediate_size: 0,
        });
        let view_buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("bounds view"),
            size: size_of::<[f32; 2]>() as wgpu::BufferAddress,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group = kit::bind_group(
            gpu,
            NAME,
            &bind_group_layout,
            &[view_buffer.as_entire_binding()],
        );
        QuadPipeline {
            layout,
            shader,
            pipelines: PerTarget::default(),
            view_buffer,
            bind_group,
        }
    }
}

impl Method for Bounds {
    fn name(&self) -> &'static str {
        NAME
    }

    fn prepare(&mut self, gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        gpu.catching_errors("preparing 'bounds'", || {
            if self.pipeline.is_none() {
                self.pipeline = Some(QuadPipeline::new(gpu));
            }
            let placed: Vec<(DVec2, Rect)> = scene
                .instances
                .iter()
                .map(|i| (i.position, scene.glyphs[i.glyph as usize].bounds))
                .collect();
            let quad_buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("bounds quads"),
                size: (placed.len() * size_of::<QuadInstance>()) as wgpu::BufferAddress,
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            self.prepared = Some(PreparedScene {
                units_per_em: scene.units_per_em,
                quads: Vec::with_capacity(placed.len()),
                placed,
                quad_buffer,
            });
            Ok(())
        })
    }

    fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        camera: &Camera,
    ) -> Result<(), Error> {
        let (Some(pipeline), Some(scene)) = (&mut self.pipeline, &mut self.prepared) else {
            return Err(super::not_prepared(NAME));
        };
        let view = Rect {
            min: DVec2::ZERO,
            max: DVec2::new(f64::from(target.width), f64::from(target.height)),
        };
        scene.quads.clear();
        for &(pen, rect) in &scene.placed {
            let to_image = camera.glyph_to_image(scene.units_per_em, pen);
            // Also rejects a tilt that puts a corner behind the eye.
            let image_bounds = Camera::project_bounds(&to_image, &rect)?;
            if !image_bounds.overlaps(&view) {
                continue;
            }
            // An integer pixel at the instance's corner or the view's, whichever is
            // further in: the f32 corners relative to it are as small as the instance,
            // however far from the world origin it lies.
            let origin = image_bounds.min.max(view.min).floor();
            let corners = rect
                .corners()
                .map(|c| (project(&to_image, c) - origin).as_vec2().to_array());
            scene.quads.push(QuadInstance {
                origin: [origin.x as i32, origin.y as i32],
                corners,
            });
        }
        let size = [target.width as f32, target.height as f32];
        gpu.queue
            .write_buffer(&pipeline.view_buffer, 0, bytemuck::cast_slice(&size));
        if !scene.quads.is_empty() {
            gpu.queue
                .write_buffer(&scene.quad_buffer, 0, bytemuck::cast_slice(&scene.quads));
        }

        let draw = pipeline.pipelines.get(target.channels, |channels| {
            let quads = wgpu::VertexBufferLayout {
                array_stride: size_of::<QuadInstance>() as wgpu::BufferAddress,
                step_mode: wgpu::VertexStepMode::Instance,
                attributes: &QUAD_ATTRIBUTES,
            };
            PipelineBuilder::new(NAME, &pipeline.layout, &pipeline.shader)
                .vertex_buffers(&[Some(quads)])
                .build(&gpu.device, channels)
        });
        let mut pass = target.clearing_pass(encoder, NAME);
        if !scene.quads.is_empty() {
            pass.set_pipeline(draw);
            pass.set_bind_group(0, &pipeline.bind_group, &[]);
            pass.set_vertex_buffer(0, scene.quad_buffer.slice(..));
            pass.draw(0..4, 0..scene.quads.len() as u32);
        }
        Ok(())
    }

    fn gpu_bytes(&self) -> u64 {
        let view = self.pipeline.as_ref().map_or(0, |p| p.view_buffer.size());
        let quads = self.prepared.as_ref().map_or(0, |s| s.quad_buffer.size());
        view + quads
    }
}
