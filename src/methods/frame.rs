//! The frame loop every caller shares: a prepared [`Method`] drawn once
//! ([`render_frame`], [`render_image`]) or many times under timestamp queries
//! ([`time_frames`]). The CLI, the bench, the app and the tests all draw through these,
//! so a method is measured exactly as it is checked.

use web_time::Instant;

use super::Method;
use crate::Error;
use crate::camera::Camera;
use crate::coverage::CoverageImage;
use crate::gpu::timing::Timestamps;
use crate::gpu::{Channels, CoverageTarget, GpuContext};

/// Encodes one frame of `method` into `target`, submits it and waits for the GPU.
pub fn render_frame(
    gpu: &GpuContext,
    method: &mut dyn Method,
    target: &CoverageTarget,
    camera: &Camera,
) -> Result<(), Error> {
    encode_frame(gpu, method, target, camera, true)
}

/// Encodes one frame of `method` into `target` and submits it, without waiting: what
/// the explorer draws offscreen within its frame loop, then reads back asynchronously.
pub fn submit_frame(
    gpu: &GpuContext,
    method: &mut dyn Method,
    target: &CoverageTarget,
    camera: &Camera,
) -> Result<(), Error> {
    encode_frame(gpu, method, target, camera, false)
}

fn encode_frame(
    gpu: &GpuContext,
    method: &mut dyn Method,
    target: &CoverageTarget,
    camera: &Camera,
    wait: bool,
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
        if wait { gpu.wait_idle() } else { Ok(()) }
    })
}

/// Renders one frame of a prepared `method` into a new coverage-only target the camera's
/// size and reads its coverage back as the method wrote it (nothing clamped).
pub fn render_image(
    gpu: &GpuContext,
    method: &mut dyn Method,
    camera: &Camera,
) -> Result<CoverageImage, Error> {
    let target = CoverageTarget::new(gpu, camera.width, camera.height, Channels::Coverage)?;
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

/// The time of one frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameTime {
    /// The GPU work the method recorded, by timestamps (data it uploads with
    /// `Queue::write_buffer` is copied before the encoder runs and is not in it), and
    /// for a peer, what it submitted on its own less the harness's copy of its picture
    /// ([`Method::peer_gpu_time`]).
    pub gpu_ms: f64,
    /// The CPU work of recording the frame: the method's `encode` — culling, sorting,
    /// building meshes, writing instances — everything it does per frame (for a method
    /// that submits on its own, less the GPU time its submissions waited for).
    pub cpu_ms: f64,
}

/// GPU and CPU time of `frames` frames after `warmup` untimed frames. `Ok(None)` when
/// the device has no timestamp queries.
pub fn time_frames(
    gpu: &GpuContext,
    method: &mut dyn Method,
    target: &CoverageTarget,
    camera: &Camera,
    warmup: usize,
    frames: usize,
) -> Result<Option<Vec<FrameTime>>, Error> {
    if !gpu.has_timestamps() {
        return Ok(None);
    }
    check_frame(target, camera)?;
    // First frames pay for lazy shader compilation and first-use allocations.
    for _ in 0..warmup {
        render_frame(gpu, method, target, camera)?;
    }
    // A query set holds at most QUERY_SET_MAX_QUERIES timestamps: two a frame.
    let batch_limit = wgpu::QUERY_SET_MAX_QUERIES / 2;
    let mut times = Vec::with_capacity(frames);
    while times.len() < frames {
        let batch = u32::try_from(frames - times.len())
            .unwrap_or(u32::MAX)
            .min(batch_limit);
        times.extend(time_batch(gpu, method, target, camera, batch)?);
    }
    Ok(Some(times))
}

fn time_batch(
    gpu: &GpuContext,
    method: &mut dyn Method,
    target: &CoverageTarget,
    camera: &Camera,
    frames: u32,
) -> Result<Vec<FrameTime>, Error> {
    gpu.catching_errors(&format!("timing '{}'", method.name()), || {
        let timestamps = Timestamps::new(gpu, "frame timestamps", 2 * frames);
        let mut frame_ms = Vec::with_capacity(frames as usize);
        for frame in 0..frames {
            let mut encoder = gpu
                .device
                .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                    label: Some("timed frame"),
                });
            timestamps.write(&mut encoder, 2 * frame);
            let start = Instant::now();
            method.encode(gpu, &mut encoder, target, camera)?;
            let encode_ms = ms_since(start);
            timestamps.write(&mut encoder, 2 * frame + 1);
            gpu.queue.submit([encoder.finish()]);
            // One frame at a time, as `render_frame` draws them: no frame's work overlaps
            // the next one's timestamps.
            gpu.wait_idle()?;
            let wall_ms = ms_since(start);
            let own = method.peer_gpu_time(gpu)?;
            frame_ms.push((encode_ms, own.map(|own| (own, wall_ms))));
        }
        let gpu_ms = timestamps.read_intervals(gpu)?;
        Ok(gpu_ms
            .into_iter()
            .zip(frame_ms)
            .map(|(recorded_ms, (encode_ms, peer))| match peer {
                None => FrameTime {
                    gpu_ms: recorded_ms,
                    cpu_ms: encode_ms,
                },
                // A peer: its own submissions count, the harness's copy does not. Where
                // the driver executes a submission inside it (a software device),
                // `encode` waited for that work, so the CPU time is the frame's wall time
                // less all GPU time, if that is less.
                Some((t, wall_ms)) => FrameTime {
                    gpu_ms: (recorded_ms + t.submitted_ms - t.copy_ms).max(0.0),
                    cpu_ms: if t.submitted_ms > 0.0 {
                        encode_ms
                            .min(wall_ms - recorded_ms - t.submitted_ms)
                            .max(0.0)
                    } else {
                        encode_ms
                    },
                },
            })
            .collect())
    })
}

/// Milliseconds since `start`.
pub fn ms_since(start: Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
}
