// The peers (compiled after common.wgsl): vello, glyphon and vello_cpu each draw white
// on transparent black into an Rgba8Unorm texture of their own; this pass copies its
// alpha, linear coverage, into the coverage target, texel for pixel (in every channel:
// a coverage-only target keeps the first). Nothing from `@group(0)` is read.

@group(1) @binding(0) var peer_image: texture_2d<f32>;

// One triangle that covers the whole target.
@vertex
fn vs_main(@builtin(vertex_index) vertex: u32) -> @builtin(position) vec4<f32> {
    let corner = vec2<f32>(f32((vertex << 1u) & 2u), f32(vertex & 2u));
    return vec4<f32>(corner * 2.0 - 1.0, 0.0, 1.0);
}

@fragment
fn fs_main(@builtin(position) pixel: vec4<f32>) -> @location(0) vec4<f32> {
    let texel = textureLoad(peer_image, vec2<i32>(pixel.xy), 0);
    return vec4<f32>(texel.a);
}
