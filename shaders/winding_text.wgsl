// `glyphscope::text`'s composite: each run's exact coverage, accumulated by `winding`
// in its own layer of a half-float array (instances added, as the row adds them, so
// glyphs sharing a pixel sum to their union), blended once in the run's colour over
// the caller's target. Drawn as one fullscreen triangle per run, in order.

@group(2) @binding(0) var run_coverage: texture_2d_array<f32>;
// Per run, its premultiplied colour.
@group(2) @binding(1) var<storage, read> run_colours: array<vec4<f32>>;

struct CompositeVertex {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) run: u32,
}

@vertex
fn vs_composite(@builtin(vertex_index) vertex: u32, @builtin(instance_index) run: u32) -> CompositeVertex {
    // One triangle covering the viewport: (-1, -1), (3, -1), (-1, 3).
    let xy = vec2<f32>(f32((vertex << 1u) & 2u), f32(vertex & 2u)) * 2.0 - 1.0;
    return CompositeVertex(vec4<f32>(xy, 0.0, 1.0), run);
}

@fragment
fn fs_composite(in: CompositeVertex) -> @location(0) vec4<f32> {
    let pixel = vec2<i32>(in.position.xy);
    let coverage = min(textureLoad(run_coverage, pixel, i32(in.run), 0).r, 1.0);
    return run_colours[in.run] * coverage;
}
