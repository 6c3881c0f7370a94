// Method `tessellation` (compiled after common.wgsl): each glyph's polygon — its curves
// cut into straight steps and triangulated on the CPU — drawn as triangles in font units,
// placed by each instance's transform. The hardware's MSAA samples give the coverage.
//
// Triangles write their samples rather than add to them: lyon's nonzero triangles do not
// overlap within a glyph, and where instances overlap their samples then unite, as the
// reference unites them.

// The polyline points, for the points overlay.
@group(1) @binding(0) var<storage, read> markers: array<Marker>;

struct Marker {
    position: vec2<f32>,
    // 0: an outline point, 1: a virtual midpoint, 2: a subdivision step.
    kind: u32,
}

// The overlay pictures: the fill in grey, edges and points in colour over it.
const FILL = vec3<f32>(0.35, 0.35, 0.38);
const EDGE = vec3<f32>(1.0, 0.55, 0.1);
// Half the side of a point's square, pixels.
const MARKER_RADIUS = 1.5;

// The instance's index includes the draw's first instance: each draw covers one group
// of instances sharing a mesh.
@vertex
fn vs_mesh(@location(0) local: vec2<f32>, @builtin(instance_index) instance: u32) -> @builtin(position) vec4<f32> {
    return image_to_clip(instances[instance].to_image * vec3<f32>(local, 1.0), frame.size);
}

// Whether an overlay is drawn: the fill is then its grey backdrop; else coverage, in
// every channel (see common.wgsl).
override OVERLAY: bool = false;

@fragment
fn fs_fill() -> @location(0) vec4<f32> {
    if OVERLAY {
        return vec4<f32>(FILL, 1.0);
    }
    return vec4<f32>(1.0);
}

// Drawn as a line list over the fill, into rgb only: coverage stays the fill's.
@fragment
fn fs_edge() -> @location(0) vec4<f32> {
    return vec4<f32>(EDGE, 1.0);
}

struct MarkerVaryings {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) color: vec3<f32>,
}

// Six vertices per point — two triangles of a square a few pixels wide around it, in
// image space — pulled from `markers` by vertex index (which includes the draw's first
// vertex, so each mesh's points start where the draw says).
@vertex
fn vs_marker(@builtin(vertex_index) vertex: u32, @builtin(instance_index) instance: u32) -> MarkerVaryings {
    var corners = array<vec2<f32>, 6>(
        vec2<f32>(-1.0, -1.0), vec2<f32>(1.0, -1.0), vec2<f32>(1.0, 1.0),
        vec2<f32>(-1.0, -1.0), vec2<f32>(1.0, 1.0), vec2<f32>(-1.0, 1.0),
    );
    var colors = array<vec3<f32>, 3>(
        vec3<f32>(1.0, 0.85, 0.2),
        vec3<f32>(1.0, 0.3, 0.9),
        vec3<f32>(0.2, 0.8, 1.0),
    );
    let marker = markers[vertex / 6u];
    let centre = project(instances[instance].to_image, marker.position);
    var out: MarkerVaryings;
    out.position = image_to_clip(vec3<f32>(centre + MARKER_RADIUS * corners[vertex % 6u], 1.0), frame.size);
    out.color = colors[min(marker.kind, 2u)];
    return out;
}

@fragment
fn fs_marker(in: MarkerVaryings) -> @location(0) vec4<f32> {
    return vec4<f32>(in.color, 1.0);
}
