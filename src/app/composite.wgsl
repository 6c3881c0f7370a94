// Draws a pane of the explorer: a coverage texture (a method's target, or the reference
// uploaded into one) turned into the picture to show, each texel a block of
// `block`×`block` framebuffer pixels (1 unless magnified; nearest, never filtered).
// Prefixed with crates/gpu/shaders/common.wgsl for `heat_color`.

struct Composite {
    // The pane's top-left corner in framebuffer pixels, and its size.
    origin: vec2<f32>,
    size: vec2<f32>,
    // Linear-light colours.
    text: vec4<f32>,
    background: vec4<f32>,
    // 0 coverage, 1 the method's overlay picture, 2 signed difference first − second,
    // 3 the cost heat map's colour scale (left to right).
    mode: u32,
    // 1 where the framebuffer encodes sRGB itself.
    srgb_target: u32,
    // Difference at full intensity.
    difference_scale: f32,
    // Framebuffer pixels per texel side: the magnifier draws each texel as a block.
    block: f32,
    // Mode 0 only: `DisplayMode::shader_index`, and the stem darkening
    // (`display::CoverageAdjust`): pixels added per edge, then the exponent.
    display: u32,
    edge_darkening: f32,
    darkening_exponent: f32,
    // 1: the magnifier's pixel grid is drawn (from `magnify::GRID_FROM`).
    grid: u32,
}

@group(0) @binding(0) var<uniform> composite: Composite;
@group(0) @binding(1) var first: texture_2d<f32>;
@group(0) @binding(2) var second: texture_2d<f32>;

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32) -> @builtin(position) vec4<f32> {
    // One triangle covering the viewport, which egui sets to the pane.
    let uv = vec2<f32>(f32((vertex << 1u) & 2u), f32(vertex & 2u));
    return vec4<f32>(uv * vec2<f32>(2.0, -2.0) + vec2<f32>(-1.0, 1.0), 0.0, 1.0);
}

fn srgb_encode(linear: vec3<f32>) -> vec3<f32> {
    let c = clamp(linear, vec3<f32>(0.0), vec3<f32>(1.0));
    return select(1.055 * pow(c, vec3<f32>(1.0 / 2.4)) - 0.055, 12.92 * c, c <= vec3<f32>(0.0031308));
}

fn srgb_decode(encoded: vec3<f32>) -> vec3<f32> {
    let c = clamp(encoded, vec3<f32>(0.0), vec3<f32>(1.0));
    return select(pow((c + 0.055) / 1.055, vec3<f32>(2.4)), c / 12.92, c <= vec3<f32>(0.04045));
}

fn luminance(rgb: vec3<f32>) -> f32 {
    return dot(rgb, vec3<f32>(0.2126, 0.7152, 0.0722));
}

// What a pixel of `coverage` shows, sRGB-encoded; `display::display_color` in Rust is its
// mirror and documents each mode. Display only: error figures never see this.
fn display_color(coverage: f32, text: vec3<f32>, background: vec3<f32>, display: u32, edge_darkening: f32, darkening_exponent: f32) -> vec3<f32> {
    var c = clamp(coverage, 0.0, 1.0);
    if c > 0.0 && c < 1.0 {
        c = pow(min(c + edge_darkening, 1.0), darkening_exponent);
    }
    if display == 1u {
        return mix(srgb_encode(background), srgb_encode(text), c);
    }
    var weight = c;
    if display == 2u {
        let lb = luminance(background);
        let lt = luminance(text);
        if abs(lt - lb) >= 1e-6 {
            let g = 1.8; // display::PERCEPTUAL_GAMMA
            let blended = pow(mix(pow(lb, 1.0 / g), pow(lt, 1.0 / g), c), g);
            weight = (blended - lb) / (lt - lb);
        }
    }
    return srgb_encode(mix(background, text, weight));
}

// `value` holds what the pixel should read as stored bytes (/255); an sRGB framebuffer
// would encode it again, so it gets the decoded value.
fn as_stored(value: vec3<f32>) -> vec4<f32> {
    if composite.srgb_target == 1u {
        return vec4<f32>(srgb_decode(value), 1.0);
    }
    return vec4<f32>(clamp(value, vec3<f32>(0.0), vec3<f32>(1.0)), 1.0);
}

// The grid over magnified pixels: each block's first row and column in grey at 60%
// (stored values). Drawn here, not as egui lines: hundreds of lines a frame are slow on
// llvmpipe.
fn with_grid(stored: vec3<f32>, local: vec2<f32>) -> vec3<f32> {
    let within = local - floor(local / composite.block) * composite.block;
    if composite.grid == 1u && min(within.x, within.y) < 1.0 {
        return mix(stored, vec3<f32>(110.0 / 255.0), 0.6);
    }
    return stored;
}

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let local = position.xy - composite.origin;
    if composite.mode == 3u {
        return as_stored(heat_color(local.x / composite.size.x));
    }
    let texel = vec2<i32>(floor(local / composite.block));
    let a = textureLoad(first, texel, 0);
    var shown: vec3<f32>;
    if composite.mode == 1u {
        // Overlay pictures are written as display values, as the CLI saves them.
        shown = a.rgb;
    } else if composite.mode == 2u {
        // The colours of `metrics::error_image`: red where `first` covers more.
        let b = textureLoad(second, texel, 0);
        let e = clamp((clamp(a.a, 0.0, 1.0) - clamp(b.a, 0.0, 1.0)) / composite.difference_scale, -1.0, 1.0);
        shown = vec3<f32>(max(e, 0.0), 0.0, max(-e, 0.0));
    } else {
        shown = display_color(a.a, composite.text.rgb, composite.background.rgb, composite.display, composite.edge_darkening, composite.darkening_exponent);
    }
    return as_stored(with_grid(shown, local));
}
