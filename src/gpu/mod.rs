//! The GPU side shared by every method: the device ([`GpuContext`]), the coverage
//! target they render into ([`CoverageTarget`]), and the frame loop that drives a
//! [`Method`] once ([`render_frame`]) or many times under timestamp queries
//! ([`time_frames`]). The CLI, the tests and the bench all render through these, so a
//! method is measured exactly as it is checked.

mod context;
pub mod msaa;
pub mod shaders;
mod target;
mod timing;

pub use context::GpuContext;
pub use target::CoverageTarget;
pub use timing::time_frames;

use crate::Error;
use crate::camera::Camera;
use crate::methods::Method;

/// A bind group layout entry for a buffer of type `ty` (uniform or storage) seen by
/// `visibility`, at `binding`: what most methods bind.
pub fn buffer_entry(
    binding: u32,
    visibility: wgpu::ShaderStages,
    ty: wgpu::BufferBindingType,
) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty: wgpu::BindingType::Buffer {
            ty,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

/// Encodes one frame of `method` into `target`, submits it and waits for the GPU.
pub fn render_frame(
    gpu: &GpuContext,
    method: &mut dyn Method,
    target: &CoverageTarget,
    camera: &Camera,
) -> Result<(), Error> {
    check_frame(target, camera)?;
    gpu.catching_errors(&format!("rendering with '{}'", method.name()), || {
        let mut encoder = gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("frame"),
            });
        method.encode(gpu, &mut encoder, target, camera)?;
        gpu.queue.submit([encoder.finish()]);
        gpu.wait_idle()
    })
}

/// Renders one frame of a prepared `method` into a new target the camera's size and
/// reads its coverage back.
pub fn render_image(
    gpu: &GpuContext,
    method: &mut dyn Method,
    camera: &Camera,
) -> Result<crate::coverage::CoverageImage, Error> {
    let target = CoverageTarget::new(gpu, camera.width, camera.height)?;
    render_frame(gpu, method, &target, camera)?;
    target.readback(gpu)
}

/// A frame needs a camera that can be drawn with, looking at exactly the target: the
/// camera's image size fixes the projection (the tilt turns about the image centre).
fn check_frame(target: &CoverageTarget, camera: &Camera) -> Result<(), Error> {
    camera.validate()?;
    if (camera.width, camera.height) != (target.width, target.height) {
        return Err(Error::Input(format!(
            "the camera sees {}x{} pixels but the target is {}x{}",
            camera.width, camera.height, target.width, target.height
        )));
    }
    Ok(())
}
