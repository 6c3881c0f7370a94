//! Timestamp queries: a query set with the buffers that resolve it and bring it back to
//! the CPU. The measured frame loop and the app's live pane timer both time with it.

use super::context::GpuContext;
use glyphscope_core::Error;

/// Bytes of one resolved timestamp.
const TIMESTAMP_BYTES: u64 = 8;

/// `count` timestamps written on command encoders, resolved and read back in pairs:
/// timestamp 2k opens interval k and 2k + 1 closes it.
pub struct Timestamps {
    queries: wgpu::QuerySet,
    resolved: wgpu::Buffer,
    /// Mappable copy of `resolved`.
    pub readable: wgpu::Buffer,
    count: u32,
}

impl Timestamps {
    /// At most [`wgpu::QUERY_SET_MAX_QUERIES`] timestamps; the device must have
    /// timestamp queries ([`GpuContext::has_timestamps`]).
    pub fn new(gpu: &GpuContext, label: &str, count: u32) -> Timestamps {
        let bytes = u64::from(count) * TIMESTAMP_BYTES;
        let buffer = |usage| {
            gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size: bytes,
                usage,
                mapped_at_creation: false,
            })
        };
        Timestamps {
            queries: gpu.device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some(label),
                ty: wgpu::QueryType::Timestamp,
                count,
            }),
            resolved: buffer(wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC),
            readable: buffer(wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ),
            count,
        }
    }

    /// Writes timestamp `index` when the GPU reaches this point of `encoder`.
    pub fn write(&self, encoder: &mut wgpu::CommandEncoder, index: u32) {
        encoder.write_timestamp(&self.queries, index);
    }

    /// Timestamps `index` and `index + 1` written at the start and end of a render pass.
    pub fn pass_writes(&self, index: u32) -> wgpu::RenderPassTimestampWrites<'_> {
        wgpu::RenderPassTimestampWrites {
            query_set: &self.queries,
            beginning_of_pass_write_index: Some(index),
            end_of_pass_write_index: Some(index + 1),
        }
    }

    /// Records the resolve of every timestamp into [`Self::readable`].
    pub fn resolve(&self, encoder: &mut wgpu::CommandEncoder) {
        encoder.resolve_query_set(&self.queries, 0..self.count, &self.resolved, 0);
        let bytes = u64::from(self.count) * TIMESTAMP_BYTES;
        encoder.copy_buffer_to_buffer(&self.resolved, 0, &self.readable, 0, bytes);
    }

    /// Submits the resolve, waits for it and returns each interval's length, ms.
    pub fn read_intervals(&self, gpu: &GpuContext) -> Result<Vec<f64>, Error> {
        let mut encoder = gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("resolve timestamps"),
            });
        self.resolve(&mut encoder);
        gpu.queue.submit([encoder.finish()]);
        Ok(intervals_ms(gpu, &gpu.read_buffer(&self.readable)?))
    }
}

/// Lengths of the intervals in resolved timestamp bytes (pairs of start and end), ms.
pub fn intervals_ms(gpu: &GpuContext, resolved: &[u8]) -> Vec<f64> {
    let ms_per_tick = f64::from(gpu.queue.get_timestamp_period()) * 1e-6;
    let ticks: Vec<u64> = resolved
        .chunks_exact(TIMESTAMP_BYTES as usize)
        .map(|b| u64::from_le_bytes(b.try_into().expect("eight bytes")))
        .collect();
    ticks
        .chunks_exact(2)
        .map(|pair| pair[1].saturating_sub(pair[0]) as f64 * ms_per_tick)
        .collect()
}
