// Shared by the methods that draw from a texture of per-glyph images (compiled after
// common.wgsl, with `atlas.wgsl` or `msdf.wgsl`): the images packed by
// `methods::glyph_atlas`, one `Entry` each, one quad per instance.

// One glyph image in the atlas.
struct Entry {
    // The image's rectangle (its border included) in the glyph's local font units:
    // min.xy, max.xy. The quad covers it.
    quad: vec4<f32>,
    // Where the glyph's local origin lies in the atlas, in texels (x right, y down),
    // and texels per font unit.
    origin: vec2<f32>,
    texels_per_unit: f32,
    _pad: f32,
    // The image's texels in the atlas: min.xy, max.xy (texel edges).
    texels: vec4<f32>,
}

@group(1) @binding(0) var<storage, read> entries: array<Entry>;
@group(1) @binding(1) var atlas: texture_2d<f32>;
@group(1) @binding(2) var atlas_sampler: sampler;

// What the fragments receive: the quad (its map to local coordinates) and its image's
// frame in the atlas, read once per vertex rather than once per fragment.
struct AtlasQuad {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) to_local_0: vec3<f32>,
    @location(1) @interpolate(flat) to_local_1: vec3<f32>,
    @location(2) @interpolate(flat) to_local_2: vec3<f32>,
    // `Entry.origin` and `texels_per_unit`.
    @location(3) @interpolate(flat) origin: vec3<f32>,
    // The image's texel centres at its edges: where a sample is kept (see
    // `atlas_sample`).
    @location(4) @interpolate(flat) inside: vec4<f32>,
}

// Strip vertex `vertex` of the quad of instance `inst` over entry `e`, grown by the
// pixel footprint where `footprint` (see `glyph_quad`).
fn entry_quad(inst: GlyphInstance, e: Entry, vertex: u32, footprint: bool) -> AtlasQuad {
    let q = glyph_quad(inst, e.quad.xy, e.quad.zw, vertex, frame.size, footprint);
    let inside = vec4<f32>(e.texels.xy + 0.5, e.texels.zw - 0.5);
    return AtlasQuad(q.position, q.to_local_0, q.to_local_1, q.to_local_2, vec3<f32>(e.origin, e.texels_per_unit), inside);
}

// The atlas texel position that shows local point `local` (y flips: the images' rows
// run down, the glyph's y up).
fn atlas_texel(origin: vec3<f32>, local: vec2<f32>) -> vec2<f32> {
    return origin.xy + vec2<f32>(local.x, -local.y) * origin.z;
}

// The atlas bilinearly sampled at `texel`, kept on the image's own texels (its border
// included): pixels of the quad beyond them read that border, never a neighbour.
fn atlas_sample(inside: vec4<f32>, texel: vec2<f32>) -> vec4<f32> {
    let kept = clamp(texel, inside.xy, inside.zw);
    let size = vec2<f32>(textureDimensions(atlas));
    return textureSampleLevel(atlas, atlas_sampler, kept / size, 0.0);
}
