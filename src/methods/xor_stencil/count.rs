//! The count behind `curves_per_pixel`: the frame's curve triangles drawn again, with
//! its samples and jitter, into an additive target instead of the stencil.

use super::params::Settings;
use super::pipelines::{Builder, Pipelines};
use super::prepared::{Prepared, draw_runs};
use crate::Error;
use crate::gpu::kit::{self, ColorOut};
use crate::gpu::msaa::Attachments;
use crate::gpu::{CoverageTarget, GpuContext};
use crate::methods::CurveCost;

/// The mean and largest count over the pixels that `coverage` (the frame just rendered
/// into `target`, one value per pixel) covers. `prepared` must still hold that frame's
/// instances and runs.
pub(super) fn curve_cost(
    gpu: &GpuContext,
    pipelines: &mut Pipelines,
    prepared: &Prepared,
    settings: &Settings,
    target: &CoverageTarget,
    coverage: &[f32],
) -> Result<Option<CurveCost>, Error> {
    let samples = settings.samples;
    gpu.catching_errors("counting curve evaluations", || {
        if pipelines.count.is_none() {
            let builder = Builder {
                device: &gpu.device,
                layout: &pipelines.pipeline_layout,
                shader: &pipelines.shader,
                samples,
                channels: target.channels,
                constants: &[],
            };
            pipelines.count = Some(builder.build(
                "xor-stencil count",
                ("vs_curve", "fs_count"),
                wgpu::PrimitiveTopology::TriangleList,
                None,
                ColorOut::Add,
            ));
        }
        let pipelines = &*pipelines;
        let multisampled = Attachments::fit(None, gpu, target, samples, false);
        let mut encoder = gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("xor-stencil count"),
            });
        {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("xor-stencil count"),
                color_attachments: &[Some(
                    multisampled.color(target, wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT)),
                )],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_pipeline(pipelines.count.as_ref().expect("built above"));
            // `render_frame` left this camera's instances and runs in place.
            for k in 0..settings.passes {
                pass.set_bind_group(0, prepared.instances.bind_group(), &[]);
                pass.set_bind_group(1, &prepared.bind_group, &[pipelines.jitter_offset(k)]);
                draw_runs(
                    &mut pass,
                    &prepared.runs,
                    &prepared.geometry.curve_ranges,
                    1,
                );
            }
        }
        gpu.queue.submit([encoder.finish()]);
        gpu.wait_idle()
    })?;
    // The resolve averaged the samples' counts.
    let counts = target.read_texels(gpu)?;
    Ok(Some(kit::tally(
        counts
            .iter()
            .zip(coverage)
            .filter(|(_, c)| **c > 0.0)
            .map(|(texel, _)| texel[3]),
        f64::from(samples),
    )))
}
