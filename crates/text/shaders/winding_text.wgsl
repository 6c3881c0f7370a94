// `glyphscope::text`'s composite: each run's exact coverage, accumulated by `winding`
// in its own rectangle of a half-float page (instances added, as the row adds them, so
// glyphs sharing a pixel sum to their union; rectangles packed apart, so runs never
// add into each other), blended once in the run's colour over the caller's target.
// One quad per run, over the run's own pixels only, in the runs' order: colour over
// colour where runs overlap.

struct CompositeRun {
    // The run's pixels in the caller's target: min.xy, max.xy (whole pixels).
    screen: vec4<f32>,
    // Where its coverage lies: page texel = target pixel + offset.
    offset: vec2<i32>,
    page: u32,
    _pad: u32,
    // Premultiplied.
    colour: vec4<f32>,
}

@group(2) @binding(0) var run_coverage: texture_2d_array<f32>;
@group(2) @binding(1) var<storage, read> runs: array<CompositeRun>;
// The caller's target size in pixels.
@group(2) @binding(2) var<uniform> target_size: vec4<f32>;

// The run's record is read once per vertex and handed to its fragments flat: a
// storage read per fragment costs a software rasterizer more than the blend.
struct CompositeVertex {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) colour: vec4<f32>,
    @location(1) @interpolate(flat) offset_page: vec3<i32>,
}

@vertex
fn vs_composite(@builtin(vertex_index) vertex: u32, @builtin(instance_index) run: u32) -> CompositeVertex {
    let r = runs[run];
    // Strip corners 0..3: (min, min), (max, min), (min, max), (max, max).
    let pick = vec2<f32>(f32(vertex & 1u), f32(vertex >> 1u));
    let xy = mix(r.screen.xy, r.screen.zw, pick);
    let clip = vec2<f32>(2.0 * xy.x / target_size.x - 1.0, 1.0 - 2.0 * xy.y / target_size.y);
    return CompositeVertex(vec4<f32>(clip, 0.0, 1.0), r.colour, vec3<i32>(r.offset, i32(r.page)));
}

@fragment
fn fs_composite(in: CompositeVertex) -> @location(0) vec4<f32> {
    let texel = vec2<i32>(in.position.xy) + in.offset_page.xy;
    let coverage = min(textureLoad(run_coverage, texel, in.offset_page.z, 0).r, 1.0);
    return in.colour * coverage;
}
