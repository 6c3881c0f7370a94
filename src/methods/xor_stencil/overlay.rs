//! The `wireframe` overlay: every fan triangle's edges in blue and every Loop–Blinn
//! triangle's in orange, drawn unshifted over coverage dimmed so that the lines stand out.

use super::jitter::jitter_offset;
use super::passes::draw_runs;
use super::pipelines::{Builder, Pipelines, REPLACE_RGB};
use super::prepared::Prepared;

/// Grey level of coverage under the wireframe, so that the lines stand out.
pub(super) const OVERLAY_TINT: f32 = 0.45;

/// The line pipelines of the fan triangles and of the curve triangles.
pub(super) fn wireframe_pipelines(builder: &Builder) -> [wgpu::RenderPipeline; 2] {
    ["vs_wire_fan", "vs_wire_curve"].map(|vertex| {
        builder.build(
            "xor-stencil lines",
            (vertex, "fs_wire"),
            wgpu::PrimitiveTopology::LineList,
            Some(wgpu::StencilState::default()),
            REPLACE_RGB,
        )
    })
}

/// Draws the edges of every visible instance's triangles with `lines`, after the
/// `passes` jittered passes, at the unshifted `Jitter` that follows theirs.
pub(super) fn record_wireframe(
    pass: &mut wgpu::RenderPass<'_>,
    lines: &[wgpu::RenderPipeline; 2],
    pipelines: &Pipelines,
    prepared: &Prepared,
    passes: u32,
) {
    let unshifted = jitter_offset(pipelines, passes);
    pass.set_bind_group(0, prepared.instances.bind_group(), &[]);
    pass.set_bind_group(1, &prepared.bind_group, &[unshifted]);
    for (pipeline, ranges) in lines.iter().zip([
        &prepared.geometry.fan_ranges,
        &prepared.geometry.curve_ranges,
    ]) {
        pass.set_pipeline(pipeline);
        // Six line vertices per triangle's three points.
        draw_runs(pass, &prepared.runs, ranges, 2);
    }
}
