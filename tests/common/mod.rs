//! Helpers shared by the integration tests: synthetic outlines and scenes laid out so
//! that one font unit is one pixel, cameras that frame a scene, the GPU, a method's
//! frame drawn on it, and the binary as a user runs it (`binary`).
#![allow(dead_code, unused_imports)] // each test binary uses its own subset

pub mod binary;

use std::sync::OnceLock;

use glam::DVec2;
use glyphscope::camera::Camera;
use glyphscope::coverage::CoverageImage;
use glyphscope::geometry::Outline;
use glyphscope::gpu::{Channels, CoverageTarget, GpuContext};
use glyphscope::methods::{Method, frame};
use glyphscope::scene::Scene;
/// A scene holding an outline once at the origin, where 1 font unit = 1 px.
pub use glyphscope::stability::hard_cases::synthetic_scene as single;
pub use glyphscope::stability::hard_cases::{polygon, rect};

/// The GPU, opened once per test binary. Without an adapter the tests that need it fail
/// with the message that says how to get one (CI installs lavapipe) rather than skip
/// and pass silently.
pub fn gpu() -> &'static GpuContext {
    static GPU: OnceLock<GpuContext> = OnceLock::new();
    GPU.get_or_init(|| GpuContext::new().unwrap_or_else(|e| panic!("{e}")))
}

/// `method` prepared for `scene` and drawn through `camera` on the shared GPU: its
/// coverage, read back.
pub fn render(method: &mut dyn Method, scene: &Scene, camera: &Camera) -> CoverageImage {
    method.prepare(gpu(), scene).unwrap();
    frame::render_image(gpu(), method, camera).unwrap()
}

/// As [`render`], with the frame's overlay picture (rgb) read back beside the coverage.
pub fn render_with_picture(
    method: &mut dyn Method,
    scene: &Scene,
    camera: &Camera,
) -> (CoverageImage, image::RgbImage) {
    let gpu = gpu();
    method.prepare(gpu, scene).unwrap();
    let target = CoverageTarget::new(gpu, camera.width, camera.height, Channels::Picture).unwrap();
    frame::render_frame(gpu, method, &target, camera).unwrap();
    (
        target.readback(gpu).unwrap(),
        glyphscope::coverage::read_overlay(gpu, &target).unwrap(),
    )
}

/// An outline of several polygons.
pub fn polygons(contours: &[&[(f64, f64)]]) -> Outline {
    Outline {
        contours: contours.iter().map(|c| polygon(c)).collect(),
    }
}

/// A camera with 1 px per font unit whose baseline origin is at the image's bottom-left
/// corner, so font (x, y) lands at image (x, height − y).
pub fn unit_camera(width: u32, height: u32) -> Camera {
    Camera::new(width, height, 1000.0, DVec2::new(0.0, f64::from(height)))
}

/// A camera that frames `scene` with a margin, at `size`, under `matrix`.
pub fn framed(scene: &Scene, size: f64, matrix: [f64; 4], subpixel: DVec2) -> Camera {
    let mut cam = Camera::new(1, 1, size, DVec2::ZERO);
    cam.matrix = Camera::matrix_from_rows(matrix[0], matrix[1], matrix[2], matrix[3]);
    let ink = cam.ink_bounds(scene).unwrap();
    cam.origin = DVec2::splat(2.0) - ink.min + subpixel;
    let extent = ink.size() + 5.0;
    cam.width = extent.x.ceil() as u32;
    cam.height = extent.y.ceil() as u32;
    cam
}

/// The transforms every scene is checked under, on a camera of the given view.
pub fn cameras(base: Camera) -> Vec<(&'static str, Camera)> {
    let (sin, cos) = 30f64.to_radians().sin_cos();
    let skew = 0.3;
    // A 30° rotation after a horizontal skew.
    let rotated = Camera::matrix_from_rows(cos, cos * skew - sin, sin, sin * skew + cos);
    // Upside down about the baseline, which moves down to keep the scene in view: a
    // negative determinant turns the corners' order around.
    let mirrored = Camera {
        matrix: Camera::matrix_from_rows(1.0, 0.0, 0.0, -1.0),
        origin: DVec2::new(base.origin.x, f64::from(base.height) - base.origin.y),
        ..base
    };
    vec![
        ("identity", base),
        (
            "rotation and skew",
            Camera {
                matrix: rotated,
                ..base
            },
        ),
        ("mirrored", mirrored),
        (
            "tilt 25°",
            Camera {
                tilt_deg: 25.0,
                ..base
            },
        ),
        (
            "far world offset",
            Camera {
                world_offset: DVec2::new(1e5, -1e5),
                ..base
            },
        ),
    ]
}

/// Runs a WGSL function on the GPU for tests that hold a shader to its CPU mirror:
/// `source` is the shader with a compute entry point `probe` (workgroup size 64)
/// appended, reading one input per invocation from the storage buffer at
/// (`group`, `binding`) and writing `output_bytes` per input to (`group`, `binding` + 1).
/// Returns the outputs as f32s, in order.
pub fn run_probe(
    gpu: &GpuContext,
    source: String,
    (group, binding): (u32, u32),
    inputs: &[u8],
    count: usize,
    output_bytes: u64,
) -> Vec<f32> {
    use wgpu::util::DeviceExt;
    let device = &gpu.device;
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("probe"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some("probe"),
        layout: None,
        module: &module,
        entry_point: Some("probe"),
        compilation_options: Default::default(),
        cache: None,
    });
    let input = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("probe inputs"),
        contents: inputs,
        usage: wgpu::BufferUsages::STORAGE,
    });
    let size = count as u64 * output_bytes;
    let output = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("probe outputs"),
        size,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("probe readback"),
        size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("probe"),
        layout: &pipeline.get_bind_group_layout(group),
        entries: &[
            wgpu::BindGroupEntry {
                binding,
                resource: input.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: binding + 1,
                resource: output.as_entire_binding(),
            },
        ],
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(group, &bind_group, &[]);
        pass.dispatch_workgroups(count.div_ceil(64) as u32, 1, 1);
    }
    encoder.copy_buffer_to_buffer(&output, 0, &readback, 0, size);
    gpu.queue.submit([encoder.finish()]);
    readback.map_async(wgpu::MapMode::Read, .., |mapped| mapped.unwrap());
    device.poll(wgpu::PollType::wait_indefinitely()).unwrap();
    let view = readback.get_mapped_range(..).unwrap();
    view.chunks_exact(4)
        .map(|b| f32::from_ne_bytes(b.try_into().expect("four bytes")))
        .collect()
}
