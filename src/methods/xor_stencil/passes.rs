//! Recording a frame: in each jittered pass, every layer's fan and curve triangles
//! counted into the stencil (and under even-odd folded into the covered bit), then the
//! covers that add the pass's coverage where the stencil says inside and clear it.

use std::ops::Range;

use super::jitter::jitter_offset;
use super::pipelines::{COVERED_BIT, Pipelines};
use super::prepared::{Prepared, Run};

/// Records every pass of a frame: per layer the fan and curve triangles into the stencil
/// (and, under even-odd, the layer folded into the covered bit), then the covers.
pub(super) fn record_passes(
    pass: &mut wgpu::RenderPass<'_>,
    pipelines: &Pipelines,
    prepared: &Prepared,
    passes: u32,
) {
    for k in 0..passes {
        pass.set_bind_group(0, prepared.instances.bind_group(), &[]);
        pass.set_bind_group(1, &prepared.bind_group, &[jitter_offset(pipelines, k)]);
        for layer in prepared.runs.chunk_by(|a, b| a.layer == b.layer) {
            for (pipeline, ranges) in [
                (&pipelines.fan, &prepared.geometry.fan_ranges),
                (&pipelines.curve, &prepared.geometry.curve_ranges),
            ] {
                pass.set_pipeline(pipeline);
                draw_runs(pass, layer, ranges, 1);
            }
            if let Some(fold) = &pipelines.fold_layer {
                pass.set_pipeline(fold);
                pass.set_stencil_reference(COVERED_BIT);
                let first = layer[0].instances.start;
                let last = layer[layer.len() - 1].instances.end;
                pass.draw(0..4, first..last);
            }
        }
        pass.set_pipeline(&pipelines.cover);
        pass.set_stencil_reference(0);
        pass.draw(0..4, 0..prepared.visible);
    }
}

/// Draws each of `runs` with its glyph's points in `ranges` (per distinct glyph), as
/// `vertices_per_point` vertices each, skipping glyphs without any.
pub(super) fn draw_runs(
    pass: &mut wgpu::RenderPass<'_>,
    runs: &[Run],
    ranges: &[Range<u32>],
    vertices_per_point: u32,
) {
    for run in runs {
        let points = &ranges[run.glyph];
        if !points.is_empty() {
            let vertices = vertices_per_point * points.start..vertices_per_point * points.end;
            pass.draw(vertices, run.instances.clone());
        }
    }
}
