// Method `bounds` (compiled after common.wgsl): each glyph instance's control-point rectangle, one quad per instance,
// with exact box-filter coverage.
//
// The rectangle's image is a convex quadrilateral (under any affine map, and under the
// camera's tilt too: a homography with w > 0 maps a rectangle to the convex hull of its
// projected corners). A pixel's coverage is the area of the pixel square clipped to that
// quadrilateral: Sutherland–Hodgman against its four edges, then the shoelace formula.

// Corners are relative to an integer pixel `origin` near the instance, so that f32 holds
// them to a tiny fraction of a pixel anywhere in a 16384-pixel image.
struct Instance {
    @location(0) origin: vec2<i32>,
    @location(1) corners01: vec4<f32>,
    @location(2) corners23: vec4<f32>,
}

struct Varyings {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) origin: vec2<i32>,
    @location(1) @interpolate(flat) corners01: vec4<f32>,
    @location(2) @interpolate(flat) corners23: vec4<f32>,
}

// A convex polygon clipped by four half-planes gains at most one vertex per plane.
const MAX_VERTICES = 8u;

// Draws the corners' bounding box grown by one pixel: every pixel the quadrilateral
// touches has its centre inside it, whatever the rounding. Four vertices, a strip.
@vertex
fn vs_main(@builtin(vertex_index) vertex: u32, instance: Instance) -> Varyings {
    let c0 = instance.corners01.xy;
    let c1 = instance.corners01.zw;
    let c2 = instance.corners23.xy;
    let c3 = instance.corners23.zw;
    let low = min(min(c0, c1), min(c2, c3)) - 1.0;
    let high = max(max(c0, c1), max(c2, c3)) + 1.0;
    let pick = vec2<f32>(f32(vertex & 1u), f32(vertex >> 1u));
    let pixel = vec2<f32>(instance.origin) + mix(low, high, pick);
    // Pixels are y down, clip space is y up.
    let clip = vec2<f32>(2.0 * pixel.x / frame.size.x - 1.0, 1.0 - 2.0 * pixel.y / frame.size.y);

    var out: Varyings;
    out.position = vec4<f32>(clip, 0.0, 1.0);
    out.origin = instance.origin;
    out.corners01 = instance.corners01;
    out.corners23 = instance.corners23;
    return out;
}

// Area of the unit square [0, 1]² inside the convex quadrilateral `quad` (either
// orientation).
fn unit_square_area_inside(quad: array<vec2<f32>, 4>) -> f32 {
    var corners = quad;
    // Twice the quadrilateral's signed area: its sign says which side of each edge is in.
    var doubled_area = 0.0;
    for (var k = 0u; k < 4u; k++) {
        doubled_area += cross2(corners[k], corners[(k + 1u) % 4u]);
    }
    if doubled_area == 0.0 {
        return 0.0;
    }
    let orientation = sign(doubled_area);

    var polygon: array<vec2<f32>, MAX_VERTICES>;
    polygon[0] = vec2<f32>(0.0, 0.0);
    polygon[1] = vec2<f32>(1.0, 0.0);
    polygon[2] = vec2<f32>(1.0, 1.0);
    polygon[3] = vec2<f32>(0.0, 1.0);
    var count = 4u;
    for (var edge = 0u; edge < 4u; edge++) {
        let a = corners[edge];
        let direction = corners[(edge + 1u) % 4u] - a;
        var clipped: array<vec2<f32>, MAX_VERTICES>;
        var kept = 0u;
        for (var k = 0u; k < count; k++) {
            let p = polygon[k];
            let q = polygon[(k + 1u) % count];
            // Positive inside the half-plane.
            let dp = orientation * cross2(direction, p - a);
            let dq = orientation * cross2(direction, q - a);
            if dp >= 0.0 && kept < MAX_VERTICES {
                clipped[kept] = p;
                kept++;
            }
            // Rounding near a corner can make extra sign changes; the bound on `kept`
            // then drops a sliver of no measurable area rather than overflow.
            if (dp >= 0.0) != (dq >= 0.0) && kept < MAX_VERTICES {
                clipped[kept] = mix(p, q, dp / (dp - dq));
                kept++;
            }
        }
        polygon = clipped;
        count = kept;
    }

    var doubled = 0.0;
    for (var k = 0u; k < count; k++) {
        doubled += cross2(polygon[k], polygon[(k + 1u) % count]);
    }
    // The clipped polygon keeps the square's counter-clockwise orientation.
    return max(0.5 * doubled, 0.0);
}

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    // This pixel's corner relative to the instance origin: integers, exact in f32.
    let pixel = floor(in.position.xy) - vec2<f32>(in.origin);
    let quad = array<vec2<f32>, 4>(
        in.corners01.xy - pixel,
        in.corners01.zw - pixel,
        in.corners23.xy - pixel,
        in.corners23.zw - pixel,
    );
    let coverage = unit_square_area_inside(quad);
    return vec4<f32>(coverage);
}
