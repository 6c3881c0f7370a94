//! GPU time per frame, from timestamps written on the command encoder just before and
//! just after a method records its frame.

use super::{CoverageTarget, GpuContext, check_frame, render_frame};
use crate::Error;
use crate::camera::Camera;
use crate::methods::Method;

/// Bytes of one resolved timestamp.
const TIMESTAMP_BYTES: u64 = 8;

/// GPU time of `frames` frames, in milliseconds each, after `warmup` untimed frames.
/// `Ok(None)` when the device has no timestamp queries.
///
/// Only the GPU work the method records on the encoder is timed: data it uploads with
/// `Queue::write_buffer` is copied before the encoder runs, and CPU time is not counted.
pub fn time_frames(
    gpu: &GpuContext,
    method: &mut dyn Method,
    target: &CoverageTarget,
    camera: &Camera,
    warmup: usize,
    frames: usize,
) -> Result<Option<Vec<f64>>, Error> {
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
) -> Result<Vec<f64>, Error> {
    let queries = 2 * frames;
    let bytes = u64::from(queries) * TIMESTAMP_BYTES;
    let resolved_bytes = gpu.catching_errors(&format!("timing '{}'", method.name()), || {
        let timestamps = gpu.device.create_query_set(&wgpu::QuerySetDescriptor {
            label: Some("frame timestamps"),
            ty: wgpu::QueryType::Timestamp,
            count: queries,
        });
        for frame in 0..frames {
            let mut encoder = gpu
                .device
                .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                    label: Some("timed frame"),
                });
            encoder.write_timestamp(&timestamps, 2 * frame);
            method.encode(gpu, &mut encoder, target, camera)?;
            encoder.write_timestamp(&timestamps, 2 * frame + 1);
            gpu.queue.submit([encoder.finish()]);
            // One frame at a time, as `render_frame` draws them: no frame's work overlaps
            // the next one's timestamps.
            gpu.wait_idle()?;
        }
        let resolved = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("resolved timestamps"),
            size: bytes,
            usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let readable = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("timestamp readback"),
            size: bytes,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let mut encoder = gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("resolve timestamps"),
            });
        encoder.resolve_query_set(&timestamps, 0..queries, &resolved, 0);
        encoder.copy_buffer_to_buffer(&resolved, 0, &readable, 0, bytes);
        gpu.queue.submit([encoder.finish()]);
        gpu.read_buffer(&readable)
    })?;

    let ms_per_tick = f64::from(gpu.queue.get_timestamp_period()) * 1e-6;
    let ticks: Vec<u64> = resolved_bytes
        .chunks_exact(TIMESTAMP_BYTES as usize)
        .map(|b| u64::from_le_bytes(b.try_into().expect("eight bytes")))
        .collect();
    Ok(ticks
        .chunks_exact(2)
        .map(|frame| frame[1].saturating_sub(frame[0]) as f64 * ms_per_tick)
        .collect())
}
