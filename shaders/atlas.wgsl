// Method `atlas` (compiled after common.wgsl): the baseline users would otherwise pick.
// Each glyph was rasterized once on the CPU (exact coverage) at a cached size into a
// texture atlas; here each instance draws one quad that samples its glyph's bitmap with
// bilinear filtering. Exact where the instance lands on the grid it was cached for;
// resampled (blurred, aliased) anywhere else.

// The bitmaps are `entries` of glyph_atlas.wgsl: PHASES × PHASES per glyph.

// Sub-pixel phases per axis: each glyph has PHASES × PHASES bitmaps, and an instance's
// pen snaps to the nearest 1/PHASES pixel, drawing the bitmap of that phase. 0: no
// snapping, the phase-0 bitmap resampled at the exact position.
override PHASES: u32 = 4u;

fn translation(shift: vec2<f32>) -> mat3x3<f32> {
    return mat3x3<f32>(vec3<f32>(1.0, 0.0, 0.0), vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(shift, 1.0));
}

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32, @builtin(instance_index) index: u32) -> AtlasQuad {
    return atlas_quad(vertex, index);
}

// Strip vertex `vertex` of instance `index`'s quad, snapped to its phase.
fn atlas_quad(vertex: u32, index: u32) -> AtlasQuad {
    var inst = instances[index];
    // One bitmap per glyph when nothing snaps (PHASES = 0).
    let phases = max(PHASES, 1u);
    var entry = inst.glyph * phases * phases;
    if PHASES > 0u {
        // The pen's image, moved to the nearest phase: the whole glyph moves with it,
        // as a text renderer places cached bitmaps.
        let pen = project(inst.to_image, vec2<f32>(0.0));
        let steps = f32(phases);
        let snapped = round(pen * steps) / steps;
        let phase = vec2<u32>(round(fract(snapped) * steps)) % phases;
        entry += phase.y * phases + phase.x;
        inst.to_image = translation(snapped - pen) * inst.to_image;
        inst.to_local = inst.to_local * translation(pen - snapped);
    }
    // No pixel footprint: a pixel centre outside the bitmap's rectangle reads its zero
    // border (see `atlas_sample`), so no pixel beyond it can add anything.
    return entry_quad(inst, entries[entry], vertex, false);
}

// How much of the fragment runs: all of it (3) but in the harness breakdown of
// docs/methods/atlas.md, which times the frame cut short after each step: 1 writes
// coverage 1 at once (the quads, the target and its blend), 2 also maps the pixel centre
// to local coordinates.
override STAGE: u32 = 3u;

@fragment
fn fs_main(in: AtlasQuad) -> @location(0) vec4<f32> {
    if STAGE == 1u {
        return vec4<f32>(1.0);
    }
    let local = project(mat3x3<f32>(in.to_local_0, in.to_local_1, in.to_local_2), in.position.xy);
    if STAGE == 2u {
        // Depends on the position, so that the map is not optimized away.
        return vec4<f32>(f32(local.x != 1e30));
    }
    return vec4<f32>(sampled_coverage(in.origin, in.inside, local));
}

// The bitmap's coverage at a local point.
fn sampled_coverage(origin: vec3<f32>, inside: vec4<f32>, local: vec2<f32>) -> f32 {
    return atlas_sample(inside, atlas_texel(origin, local)).r;
}

// The harness breakdown's other way to find a fragment's local position: interpolated
// from the quad's corners, as text renderers do (glyphon interpolates its texture
// coordinates), instead of mapping each pixel centre (which common.wgsl says why every
// method does). Exact for the bench's affine views, not under a tilt.
struct InterpolatedQuad {
    @builtin(position) position: vec4<f32>,
    @location(0) local: vec2<f32>,
    @location(3) @interpolate(flat) origin: vec3<f32>,
    @location(4) @interpolate(flat) inside: vec4<f32>,
}

@vertex
fn vs_interpolated(@builtin(vertex_index) vertex: u32, @builtin(instance_index) index: u32) -> InterpolatedQuad {
    let quad = atlas_quad(vertex, index);
    let to_local = mat3x3<f32>(quad.to_local_0, quad.to_local_1, quad.to_local_2);
    // The corner's image point, back from clip space.
    let w = quad.position.w;
    let image = vec2<f32>(quad.position.x + w, w - quad.position.y) * 0.5 * frame.size / w;
    return InterpolatedQuad(quad.position, project(to_local, image), quad.origin, quad.inside);
}

@fragment
fn fs_interpolated(in: InterpolatedQuad) -> @location(0) vec4<f32> {
    return vec4<f32>(sampled_coverage(in.origin, in.inside, in.local));
}
