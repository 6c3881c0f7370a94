// Shared by every method shader (prepended to each one by `gpu::shaders`, after the
// one line it writes from Rust: `const COST_SCALE: f32`, the curves per pixel at the top
// of the cost heat map's scale, which the app's legend reads from the same constant).
//
// What a fragment writes: coverage in alpha and an overlay's premultiplied colour in
// rgb. A fragment that draws no overlay writes its coverage in every channel, because a
// coverage-only target (`gpu::Channels::Coverage`, what every frame without an overlay
// draws into) keeps one channel: the first.
//
// Conventions: a glyph's local coordinates are its font units, y up, origin at its pen
// position. Image coordinates are pixels, y down, pixel (i, j) covering [i, i+1) × [j, j+1).
// `to_image` maps local → image as a homography (column vectors, w in the last row); it is
// composed on the CPU in f64, relative to the glyph and the view, so its entries are small.

struct GlyphInstance {
    to_image: mat3x3<f32>,
    to_local: mat3x3<f32>,
    // Index of the distinct glyph this instance draws.
    glyph: u32,
    // The text library's colour for a glyph drawn straight into the caller's target:
    // premultiplied, four 16-bit fractions of 65535; unused by the rows.
    colour: vec2<u32>,
}

struct Frame {
    // Target size in pixels.
    size: vec2<f32>,
}

// `@group(0)` of every method shader; each method binds its own data at `@group(1)`.
@group(0) @binding(0) var<uniform> frame: Frame;
@group(0) @binding(1) var<storage, read> instances: array<GlyphInstance>;

// A homogeneous image point (X·w, Y·w, w) → clip space, keeping w (the quad's corners
// under perspective; the methods interpolate no varyings, see `quad_local`).
fn image_to_clip(h: vec3<f32>, size: vec2<f32>) -> vec4<f32> {
    return vec4<f32>(2.0 * h.x / size.x - h.z, h.z - 2.0 * h.y / size.y, 0.0, h.z);
}

fn project(m: mat3x3<f32>, p: vec2<f32>) -> vec2<f32> {
    let h = m * vec3<f32>(p, 1.0);
    return h.xy / h.z;
}

// Corner `k` (0: min, 1: (max.x, min.y), 2: max, 3: (min.x, max.y)) of a local rectangle.
fn rect_corner(rect_min: vec2<f32>, rect_max: vec2<f32>, k: u32) -> vec2<f32> {
    let pick = vec2<f32>(f32(k == 1u || k == 2u), f32(k >= 2u));
    return mix(rect_min, rect_max, pick);
}

// Corner `k` of the local rectangle, moved so that the image of the rectangle grows by
// exactly what a pixel can reach (with `footprint`): each edge moves out by the support
// distance of the pixel square along its normal, ½(|nx| + |ny|) — ½ px for an
// axis-aligned edge, ½√2 at 45° — plus `margin` pixels. Every pixel whose square touches
// the rectangle then has its centre inside the grown quad, under any rotation, skew or
// perspective, with no fixed em margin wasting fill. Without `footprint`, only the
// margin: for a rectangle that already holds everything a pixel centre can see (a
// bitmap with its zero border). Returns the moved corner in local coordinates.
fn dilated_corner(inst: GlyphInstance, rect_min: vec2<f32>, rect_max: vec2<f32>, k: u32, footprint: bool, margin: f32) -> vec2<f32> {
    let previous = project(inst.to_image, rect_corner(rect_min, rect_max, (k + 3u) % 4u));
    let here = project(inst.to_image, rect_corner(rect_min, rect_max, k));
    let next = project(inst.to_image, rect_corner(rect_min, rect_max, (k + 1u) % 4u));
    let opposite = project(inst.to_image, rect_corner(rect_min, rect_max, (k + 2u) % 4u));
    // The image's winding (mirroring matrices and the y flip reverse it) says which side
    // of each edge is outside.
    let turn = sign(cross2(here - previous, next - here) + cross2(opposite - next, previous - opposite));
    let n_in = outward_normal(here - previous, turn);
    let n_out = outward_normal(next - here, turn);
    let reach = select(0.0, 0.5, footprint);
    let d_in = margin + reach * (abs(n_in.x) + abs(n_in.y));
    let d_out = margin + reach * (abs(n_out.x) + abs(n_out.y));
    // Move the corner to where both shifted edges meet: n_in·Δ = d_in, n_out·Δ = d_out.
    let det = cross2(n_in, n_out);
    var delta = n_in * d_in + n_out * d_out;
    if abs(det) > 1e-3 {
        delta = vec2<f32>(d_in * n_out.y - d_out * n_in.y, d_out * n_in.x - d_in * n_out.x) / det;
    }
    return project(inst.to_local, here + delta);
}

// What a quad method's fragments receive: the instance's image → local map (the same at
// every vertex) and which distinct glyph it draws. A fragment maps its own pixel centre
// through the map (`quad_local`) instead of interpolating a local position: interpolated,
// the position would move with the rasterizer's snapping of the quad's corners, up to
// 1/32 px where the snap is 1/16 px (SwiftShader's 4 bits of sub-pixel precision;
// lavapipe and desktop GPUs have 8), and every method would draw the glyph that far off.
struct GlyphQuad {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) to_local_0: vec3<f32>,
    @location(1) @interpolate(flat) to_local_1: vec3<f32>,
    @location(2) @interpolate(flat) to_local_2: vec3<f32>,
    @location(3) @interpolate(flat) glyph: u32,
}

// How far past the pixel footprint the quad reaches, in pixels: more than the corners can
// move when the rasterizer snaps them (≤ 1/32 px at 4 bits), so snapping never drops a
// pixel the glyph touches.
const SNAP_MARGIN: f32 = 0.0625;

// Strip vertex `vertex` (0–3) of the quad covering the local rectangle of instance
// `inst`, grown by the pixel footprint where `footprint` (see `dilated_corner`) and by
// the snap margin: strip vertices 0, 1, 2, 3 take corners 0, 1, 3, 2 (a Gray code), two
// triangles.
fn glyph_quad(inst: GlyphInstance, rect_min: vec2<f32>, rect_max: vec2<f32>, vertex: u32, size: vec2<f32>, footprint: bool) -> GlyphQuad {
    let local = dilated_corner(inst, rect_min, rect_max, vertex ^ (vertex >> 1u), footprint, SNAP_MARGIN);
    var out: GlyphQuad;
    out.position = image_to_clip(inst.to_image * vec3<f32>(local, 1.0), size);
    out.to_local_0 = inst.to_local[0];
    out.to_local_1 = inst.to_local[1];
    out.to_local_2 = inst.to_local[2];
    out.glyph = inst.glyph;
    return out;
}

// The local position of the fragment's pixel centre (perspective included).
fn quad_local(q: GlyphQuad) -> vec2<f32> {
    return project(mat3x3<f32>(q.to_local_0, q.to_local_1, q.to_local_2), q.position.xy);
}

// Which roots of a quadratic count as crossings of a ray along +x through the origin,
// from the signs of its control points' y alone (Slug's root-eligibility table): with
// k = [y0 > 0] + 2[y1 > 0] + 4[y2 > 0], bit 0 of the class is the descending root t1
// (y' < 0), real for k in {1, 2, 3, 5}, and bit 1 the ascending root t2, for k in
// {2, 4, 5, 6}: bits of 0x2E and 0x74, interleaved as 0x2E74. An endpoint on the ray
// counts as "below", so a ray through a shared endpoint or along a horizontal segment
// counts it exactly once, whatever rounding does to the roots; no epsilon decides.
fn crossing_class(y0: f32, y1: f32, y2: f32) -> u32 {
    let k = u32(y0 > 0.0) | (u32(y1 > 0.0) << 1u) | (u32(y2 > 0.0) << 2u);
    return (0x2E74u >> (2u * k)) & 3u;
}

fn cross2(a: vec2<f32>, b: vec2<f32>) -> f32 {
    return a.x * b.y - a.y * b.x;
}

fn outward_normal(edge: vec2<f32>, turn: f32) -> vec2<f32> {
    let length = max(length(edge), 1e-30);
    return turn * vec2<f32>(edge.y, -edge.x) / length;
}

// The cost heat map's colour scale, shared by every method that draws one: t in [0, 1]
// from dark blue through green and yellow to white (monotone in lightness, so it reads
// in greyscale too).
fn heat_color(t: f32) -> vec3<f32> {
    let x = clamp(t, 0.0, 1.0);
    let r = clamp(1.8 * x - 0.5, 0.0, 1.0);
    let g = clamp(1.6 * x - 0.1, 0.0, 1.0) * (0.85 + 0.15 * x);
    let b = clamp(0.55 - 1.2 * abs(x - 0.25), 0.0, 1.0) + clamp(2.5 * x - 1.5, 0.0, 1.0);
    return vec3<f32>(r, g, min(b, 1.0));
}
