// Method `xor-stencil` (compiled after common.wgsl): Evan Wallace's fill, counted in the
// stencil buffer.
//
// Each contour becomes a fan of triangles (anchor, segment start, segment end) — the
// polygon through the segments' endpoints — plus one Loop–Blinn triangle per quadratic,
// (p0, p1, p2) with (u, v) = (0, 0), (½, 0), (1, 1), that keeps only its samples with
// u² − v < 0: the region between the chord and the curve. Every triangle adds its
// orientation (±1) to the stencil of the samples it covers (nonzero), or flips bit 0
// (even-odd): what is left is the outline's winding number, or its parity, per sample.
// A cover quad per instance then turns the stencil into coverage and clears it again.
//
// Every triangle's position goes through `to_clip` and is `@invariant`: an edge that two
// triangles share (fan spokes, a chord under both its fan triangle and its curve
// triangle) is rasterized from bit-identical vertices, so the rasterizer's tie rule
// gives each sample on it to exactly one side and no sample is counted twice or never.

// Control-point bounds of each distinct glyph: min in xy, max in zw (font units).
@group(1) @binding(0) var<storage, read> glyph_bounds: array<vec4<f32>>;
// Fan triangles, three points each, every glyph's run starting at a multiple of 3.
@group(1) @binding(1) var<storage, read> fan_points: array<vec2<f32>>;
// Loop–Blinn triangles (p0, p1, p2) of the quadratics, the same way.
@group(1) @binding(2) var<storage, read> curve_points: array<vec2<f32>>;
@group(1) @binding(3) var<uniform> jitter: Jitter;

struct Jitter {
    // This pass's sub-pixel shift of the whole image, pixels.
    offset: vec2<f32>,
    // Coverage one covered sample adds in this pass: 1 / passes.
    weight: f32,
    _pad: f32,
}

// Grey level of coverage in the overlay picture: 1 without an overlay, so that the cover
// writes coverage in every channel (see common.wgsl).
override TINT: f32 = 1.0;

// A local point of `inst` in clip space, shifted by this pass's jitter. The shift is
// applied to the homogeneous image point (x·w, y·w, w) so perspective stays exact.
fn to_clip(inst: GlyphInstance, local: vec2<f32>) -> vec4<f32> {
    let h = inst.to_image * vec3<f32>(local, 1.0);
    return image_to_clip(vec3<f32>(h.xy + jitter.offset * h.z, h.z), frame.size);
}

struct Position {
    @builtin(position) @invariant position: vec4<f32>,
}

@vertex
fn vs_fan(@builtin(vertex_index) vertex: u32, @builtin(instance_index) instance: u32) -> Position {
    let inst = instances[instance];
    return Position(to_clip(inst, fan_points[vertex]));
}

// The stencil pipelines write no colour (their write mask is empty).
@fragment
fn fs_stencil_only() -> @location(0) vec4<f32> {
    return vec4<f32>(0.0);
}

struct CurveVaryings {
    @builtin(position) @invariant position: vec4<f32>,
    // Interpolated per sample: with MSAA the curve cuts each pixel at sample resolution,
    // as the triangles' straight edges do.
    @location(0) @interpolate(perspective, sample) uv: vec2<f32>,
}

@vertex
fn vs_curve(@builtin(vertex_index) vertex: u32, @builtin(instance_index) instance: u32) -> CurveVaryings {
    let inst = instances[instance];
    // Runs start at multiples of 3, so vertex % 3 is the corner within the triangle.
    let corner = vertex % 3u;
    let uv = array<vec2<f32>, 3>(vec2<f32>(0.0, 0.0), vec2<f32>(0.5, 0.0), vec2<f32>(1.0, 1.0));
    return CurveVaryings(to_clip(inst, curve_points[vertex]), uv[corner]);
}

@fragment
fn fs_curve(in: CurveVaryings) -> @location(0) vec4<f32> {
    // u² − v < 0 between the chord (u = v) and the curve (v = u²); the control point's
    // side (u² > v) is outside. Perspective-correct (u, v) keeps this exact under tilt.
    if in.uv.x * in.uv.x - in.uv.y >= 0.0 {
        discard;
    }
    return vec4<f32>(0.0);
}

// Counts the samples `fs_curve` tests (one u² − v each) for `curves_per_pixel`: one in
// alpha on every covered sample of a curve triangle; the resolve averages them.
@fragment
fn fs_count() -> @location(0) vec4<f32> {
    return vec4<f32>(0.0, 0.0, 0.0, 1.0);
}

// One quad per instance over its control-point bounds, grown by what a pixel can reach
// (`dilated_corner`): it covers every sample any of its triangles can have touched.
// Four vertices, a strip.
@vertex
fn vs_cover(@builtin(vertex_index) vertex: u32, @builtin(instance_index) instance: u32) -> Position {
    let inst = instances[instance];
    let bounds = glyph_bounds[inst.glyph];
    // Strip order 0, 1, 3, 2 goes round the rectangle's corners 0, 1, 2, 3.
    let corner = array<u32, 4>(0u, 1u, 3u, 2u)[vertex];
    let local = dilated_corner(inst, bounds.xy, bounds.zw, corner, true, 0.0);
    return Position(to_clip(inst, local));
}

// Each sample whose stencil passes adds this pass's share of coverage (the stencil test
// lets each sample through once a pass; the pass then clears it).
@fragment
fn fs_cover() -> @location(0) vec4<f32> {
    return vec4<f32>(vec3<f32>(TINT * jitter.weight), jitter.weight);
}

struct WireVaryings {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) color: vec3<f32>,
}

// Three lines (six vertices) per triangle: vertex → triangle, edge, end.
fn wire_point(vertex: u32) -> u32 {
    let triangle = vertex / 6u;
    let edge = (vertex % 6u) / 2u;
    return 3u * triangle + (edge + vertex % 2u) % 3u;
}

@vertex
fn vs_wire_fan(@builtin(vertex_index) vertex: u32, @builtin(instance_index) instance: u32) -> WireVaryings {
    let inst = instances[instance];
    return WireVaryings(to_clip(inst, fan_points[wire_point(vertex)]), vec3<f32>(0.25, 0.6, 1.0));
}

@vertex
fn vs_wire_curve(@builtin(vertex_index) vertex: u32, @builtin(instance_index) instance: u32) -> WireVaryings {
    let inst = instances[instance];
    return WireVaryings(to_clip(inst, curve_points[wire_point(vertex)]), vec3<f32>(1.0, 0.45, 0.1));
}

@fragment
fn fs_wire(in: WireVaryings) -> @location(0) vec4<f32> {
    return vec4<f32>(in.color, 1.0);
}
