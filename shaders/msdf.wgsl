// Peer `msdf` (compiled after common.wgsl): a distance-field atlas drawn with the shader
// msdfgen publishes (Viktor Chlumský, "Shape Decomposition for Multi-channel Distance
// Fields", and msdfgen's README), its screen range from the derivatives. Each distinct
// glyph has a field made once on the CPU by fdsm; each instance draws one quad that
// samples it bilinearly.

// The fields are `entries` of glyph_atlas.wgsl, one per glyph.

// 1: a single-channel SDF (red); 3: the median of red, green and blue (msdf, mtsdf).
override CHANNELS: u32 = 3u;
// The field's distance range, texels: it holds distances within ±RANGE/2.
override RANGE: f32 = 4.0;
// 0: coverage; 1: the field's channels as colour; 2: which channel the median picks.
override OVERLAY: u32 = 0u;

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32, @builtin(instance_index) index: u32) -> AtlasQuad {
    let inst = instances[index];
    // No pixel footprint: the quad covers the field's rectangle, as engines draw an
    // MSDF glyph (msdf-atlas-gen's plane bounds). Its border lies past range/2 texels
    // from the ink, where the true distance reads "outside"; grown further, the quad
    // would sample the clamped border, whose pseudo-distance channels along an edge's
    // extension need not.
    return entry_quad(inst, entries[inst.glyph], vertex, false);
}

fn median3(v: vec3<f32>) -> f32 {
    return max(min(v.r, v.g), min(max(v.r, v.g), v.b));
}

@fragment
fn fs_main(in: AtlasQuad) -> @location(0) vec4<f32> {
    let local = project(mat3x3<f32>(in.to_local_0, in.to_local_1, in.to_local_2), in.position.xy);
    let texel = atlas_texel(in.origin, local);
    // msdfgen's screen range: screen pixels per field texel along each field axis,
    // averaged over the two, times the range; at least 1. From the length of each
    // axis's gradient, which a turn leaves alone, rather than 1/fwidth (|dx| + |dy|),
    // which counts a pixel √2 too wide at 45°. The floor keeps an edge-on tilt finite.
    let per_pixel = max(sqrt(dpdx(texel) * dpdx(texel) + dpdy(texel) * dpdy(texel)), vec2<f32>(1e-6));
    let screen_range = max(0.5 * dot(vec2<f32>(RANGE), 1.0 / per_pixel), 1.0);
    // Level 0: msdfgen's recipe has no mipmaps (docs/methods/msdf.md says what that
    // does to minified text).
    let sample = atlas_sample(in.inside, texel);
    let sd = select(median3(sample.rgb), sample.r, CHANNELS == 1u);
    // A linear ramp one screen pixel wide across the edge (sd = 1/2).
    let coverage = clamp(screen_range * (sd - 0.5) + 0.5, 0.0, 1.0);
    if OVERLAY == 1u {
        let channels = select(sample.rgb, vec3<f32>(sample.r), CHANNELS == 1u);
        return vec4<f32>(channels, coverage);
    }
    if OVERLAY == 2u {
        // The channel the median takes, in its colour; white where two agree within a
        // byte (nothing to pick). Full inside the glyph, fading out over the range
        // outside it, so that quads that overlap add nothing where their fields are far.
        let picked = vec3<f32>(abs(sample.rgb - vec3<f32>(sd)) < vec3<f32>(0.5 / 255.0));
        let one = select(picked, vec3<f32>(1.0), dot(picked, vec3<f32>(1.0)) > 1.5);
        return vec4<f32>(one * max(coverage, 1.0 - 2.0 * abs(sd - 0.5)), coverage);
    }
    return vec4<f32>(coverage);
}
