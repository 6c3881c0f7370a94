// Method `winding` (compiled after common.wgsl): the coverage of each pixel from the
// winding number of its glyph's quadratic curves. Two anti-aliasing algorithms, chosen
// per pipeline by the `AREA` override (`aa=`), share this file:
//
// - winding.wgsl (this file): what both use: the curve, glyph and band data and their
//   bindings, the pipeline overrides, the vertex stage, the walk direction, the fill
//   rule, and `fs_main`, which calls the chosen algorithm and draws the overlays
//   (curve classes, cost heat map, curve count).
// - winding_area.wgsl, `aa=area` (the default, `AREA`): the exact box-filter integral
//   of the winding number over the pixel, curve by curve (`area_pixel`).
// - winding_rays.wgsl, `aa=rays`: the roots of the curves along rays cast from the
//   sample along x and y, each crossing anti-aliased by its tangent line, the two rays
//   blended by how well each sees an edge (`rays_pixel`).
//
// The three files are one module (method_shader! in crates/gpu/src/shaders.rs concatenates
// them): each calls into the others by name.
//
// Every computation is in the glyph's local coordinates (font units), relative to the
// point being shaded.

// A curve as `curve_at` reads it from the curve texture (GpuCurve in bands.rs), three
// texels: the first two hold the points and marks, the third the bounds only aa=rays
// needs (a load no code uses is compiled away). aa=area reads its curves inline in the
// band lists instead (`band_ends`, `band_curve_inline`).
struct Curve {
    p0p1: vec4<f32>,
    p2: vec2<f32>,
    // 1 where the curve may separate other winding levels than 0 and the fill
    // (overlapping contours): aa=area integrates the pixels it crosses in sub-pixels.
    overlaps: f32,
    // The glyph's curve this one is a piece of (the prep splits curves where x or y
    // turns): pieces of one curve cannot make three winding levels between them.
    parent: u32,
    // The control points' largest x and y: where aa=rays' rays cast towards + stop.
    max_xy: vec2<f32>,
    // Their smallest x and y, for rays cast towards −x or −y.
    min_xy: vec2<f32>,
}

struct Glyph {
    // Control-point bounds: min.xy, max.xy.
    bounds: vec4<f32>,
    // Horizontal band count, vertical band count (aa=area: the segments each band is
    // split into along x and the levels split, `area_band`), first band in `bands`.
    band_count_h: u32,
    band_count_v: u32,
    first_band: u32,
    // Font units per em, to tell small text from large.
    units_per_em: f32,
}

// A band lists the curves that rays inside it can cross, twice: sorted by descending
// max (for rays cast towards +) and by ascending min (for rays cast towards −), so a
// ray stops at the first curve that lies wholly behind it. A glyph's bands (`Layout`
// in bands.rs), from `first_band`: for aa=rays its horizontal bands, its vertical ones,
// then one of all its curves (`band_for`); for aa=area (no vertical bands) its
// horizontal bands, the one of all its curves, then coarser levels (`area_band`), each
// band followed by its segments' lists in a glyph split along x (kept once, by_min =
// by_max: walked towards + alone).
struct Band {
    by_max: u32,
    by_min: u32,
    count: u32,
}

@group(1) @binding(0) var<storage, read> glyphs: array<Glyph>;
// The bands, the band lists and the curves are data textures (kit::data_texture): a
// fragment reads its band, and its walk a list entry and a curve at every step; a
// software device fetches texels for a SIMD group at once where it reads a storage
// buffer lane by lane (crates/text/src/winding/uploaded.rs).
@group(1) @binding(1) var band_texels: texture_2d<u32>;
@group(1) @binding(2) var band_curves: texture_2d<u32>;
@group(1) @binding(3) var curve_texels: texture_2d<u32>;
// aa=area reads its band lists' curves inline, two texels an entry: the end points
// (p0.xy, p2.xy), which bound a monotone piece (bands.rs keeps the control point within
// them) and so tell where it lies against the pixel and add a piece wholly right of it;
// and the rest (p1.xy, overlaps, parent), read only for the pieces across the pixel
// (`area_winding`). 1-texel stand-ins for aa=rays.
@group(1) @binding(4) var band_end_texels: texture_2d<u32>;
@group(1) @binding(5) var band_middle_texels: texture_2d<u32>;

// Texels a row of a data texture, as a shift: kit::DATA_TEXTURE_WIDTH = 4096.
const DATA_ROW_SHIFT: u32 = 12u;

fn data_texel(data: texture_2d<u32>, index: u32) -> vec4<u32> {
    let row_mask = (1u << DATA_ROW_SHIFT) - 1u;
    return textureLoad(data, vec2<u32>(index & row_mask, index >> DATA_ROW_SHIFT), 0);
}

fn curve_at(index: u32) -> Curve {
    let a = data_texel(curve_texels, 3u * index);
    let b = data_texel(curve_texels, 3u * index + 1u);
    let c = data_texel(curve_texels, 3u * index + 2u);
    return Curve(bitcast<vec4<f32>>(a), bitcast<vec2<f32>>(b.xy), bitcast<f32>(b.z), b.w, bitcast<vec2<f32>>(c.xy), bitcast<vec2<f32>>(c.zw));
}

fn band_at(index: u32) -> Band {
    let t = data_texel(band_texels, index);
    return Band(t.x, t.y, t.z);
}

// Entry `entry` of the band lists: a curve.
fn band_curve(entry: u32) -> Curve {
    return curve_at(data_texel(band_curves, entry).x);
}

// Entry `entry`'s curve's end points, p0.xy and p2.xy (aa=area only).
fn band_ends(entry: u32) -> vec4<f32> {
    return bitcast<vec4<f32>>(data_texel(band_end_texels, entry));
}

// Entry `entry`'s curve whole, its end points `ends` read already (aa=area only).
fn band_curve_inline(entry: u32, ends: vec4<f32>) -> Curve {
    let m = data_texel(band_middle_texels, entry);
    return Curve(vec4<f32>(ends.xy, bitcast<vec2<f32>>(m.xy)), ends.zw, bitcast<f32>(m.z), m.w, vec2<f32>(0.0), vec2<f32>(0.0));
}

// Pipeline constants: one pipeline per parameter combination, no per-pixel branching
// on them.
override AREA: bool = false;      // aa=area: the exact box integral; no rays
override RAYS: u32 = 2u;          // 1: along x only; 2: x and y, combined by weight
override SLUG: bool = false;      // rays=slug: two rays combined as Slug's shader does
override SAMPLES: u32 = 0u;       // 1, 4 (2×2 sub-pixels tiling the pixel), 0: auto
override EVEN_ODD: bool = false;  // fill rule; nonzero by default
override AXIS: bool = false;      // aa=area: the instances' axes are the image's (no
                                  // rotation, skew or tilt): the pixel is a rectangle
override SQUARE: bool = false;   // aa=area, not AXIS: the instances' pixel steps lean
                                  // apart (crates/core/src/geometry: steps_lean_apart), so a
                                  // curve across a pixel is integrated in the pixel's
                                  // own square frame (`across_square`)
override GRID: bool = true;       // aa=area: the draw's glyphs may need the sub-pixel
                                  // grid (some curves marked as overlapping)
override USE_BANDS: bool = true;  // false: every curve of the glyph for every ray
override OVERLAY: u32 = 0u;       // 0 none, 1 curve classes, 2 cost heat map, 3 count,
                                  // 4 and 5 the cost breakdown's counts, 6 the text
                                  // library's colour over the caller's target
// aa=area cut short, for the cost breakdown (crates/text/src/winding/cost.rs) to time each
// stage by the difference from the one before: 0 writes 1 at once (rasterizing, the
// quads), 1 stops after the per-fragment setup (derivatives, the pixel's frame, its
// band), 2 after the band walk (each entry's curve ends loaded, mapped and sorted into
// its zone, no term), 3 adds the terms of the curves right of the pixel, 4 is the whole
// shader (the second pass: the curves across the pixel loaded whole and integrated).
override STAGE: u32 = 4u;
// A user's method (`--method wgsl:PATH`): `user_coverage` of the user's file (see
// winding_user.wgsl) instead of either algorithm, on the same quads, data and target.
override USER: bool = false;

// The glyph quad, carrying its glyph's record as flat varyings: read once per vertex
// rather than once per fragment (a software device reads storage lane by lane, each
// lane's word in turn).
struct WindingQuad {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) to_local_0: vec3<f32>,
    @location(1) @interpolate(flat) to_local_1: vec3<f32>,
    @location(2) @interpolate(flat) to_local_2: vec3<f32>,
    @location(3) @interpolate(flat) bounds: vec4<f32>,
    // band_count_h, band_count_v, first_band
    @location(4) @interpolate(flat) bands: vec3<u32>,
    @location(5) @interpolate(flat) units_per_em: f32,
    // The instance's premultiplied colour (OVERLAY 6 alone reads it).
    @location(6) @interpolate(flat) colour: vec4<f32>,
}

// One quad per instance over the glyph's control-point bounds.
@vertex
fn vs_main(@builtin(vertex_index) vertex: u32, @builtin(instance_index) index: u32) -> WindingQuad {
    let inst = instances[index];
    let g = glyphs[inst.glyph];
    let q = glyph_quad(inst, g.bounds.xy, g.bounds.zw, vertex, frame.size, true);
    let counts = vec3<u32>(g.band_count_h, g.band_count_v, g.first_band);
    let c = inst.colour;
    let colour = vec4<f32>(vec4<u32>(c.x & 0xffffu, c.x >> 16u, c.y & 0xffffu, c.y >> 16u)) / 65535.0;
    return WindingQuad(q.position, q.to_local_0, q.to_local_1, q.to_local_2, g.bounds, counts, g.units_per_em, colour);
}

// A pixel's coverage, and how many curves it evaluated (the cost overlays).
struct Coverage {
    value: f32,
    evaluated: u32,
}

// Cast towards the nearer side of the glyph: fewer curves lie that way.
fn direction_for(g: Glyph, sample_local: vec2<f32>, axis: u32) -> f32 {
    let centre = 0.5 * (g.bounds.xy + g.bounds.zw);
    let along = select(sample_local.x - centre.x, sample_local.y - centre.y, axis == 1u);
    return select(-1.0, 1.0, along >= 0.0 || !USE_BANDS);
}

// Coverage of a (possibly averaged, hence fractional) winding number under the fill
// rule.
fn fill(winding: f32) -> f32 {
    let w = abs(winding);
    if EVEN_ODD {
        // Distance to the nearest even winding: 0 → 0, 1 → 1, 2 → 0.
        return abs(w - 2.0 * round(0.5 * w));
    }
    return min(w, 1.0);
}

@fragment
fn fs_main(in: WindingQuad) -> @location(0) vec4<f32> {
    if STAGE == 0u {
        return vec4<f32>(1.0);
    }
    let g = Glyph(in.bounds, in.bands.x, in.bands.y, in.bands.z, in.units_per_em);
    var local: vec2<f32>;
    var jx: vec2<f32>;
    var jy: vec2<f32>;
    if AXIS {
        // An instance that keeps the image's axes is affine: a pixel step in local
        // units is a column of its map, exactly and the same in every pixel, where
        // derivatives are differences of rounded neighbours and a projection divides.
        let w = 1.0 / in.to_local_2.z;
        jx = in.to_local_0.xy * w;
        jy = in.to_local_1.xy * w;
        local = in.position.x * jx + in.position.y * jy + in.to_local_2.xy * w;
    } else {
        // (quad_local reads only the position and the map; the glyph came as its record.)
        local = quad_local(GlyphQuad(in.position, in.to_local_0, in.to_local_1, in.to_local_2, 0u));
        // One pixel step in local units, x and y: the footprint under the full
        // transform, perspective included.
        jx = dpdx(local);
        jy = dpdy(local);
    }
    // The algorithm: winding_area.wgsl's or winding_rays.wgsl's.
    var c: Coverage;
    if USER {
        c = Coverage(user_coverage(g, local, jx, jy), 0u);
    } else if AREA {
        c = area_pixel(g, local, jx, jy);
    } else {
        c = rays_pixel(g, local, jx, jy);
    }
    let coverage = c.value;
    let evaluated = c.evaluated;

    if OVERLAY == 1u {
        let root_class = nearest_class(g, local, jx, jy);
        var picture = vec3<f32>(0.5 * coverage);
        if root_class < 8u {
            picture = CLASS_COLORS[root_class];
        }
        return vec4<f32>(picture, coverage);
    }
    if OVERLAY == 2u {
        // The glyph stays readable: brighter where covered. The raw count is in the
        // alpha-free red channel of a separate pass (see `curves_per_pixel`).
        let heat = heat_color(f32(evaluated) / COST_SCALE);
        return vec4<f32>(heat * (0.45 + 0.55 * coverage), coverage);
    }
    if OVERLAY == 3u {
        // Counting pass: the number of curves evaluated, exact in the half-float target
        // up to 2048 (kit::EXACT_COUNT_LIMIT); counts past it are reported as at least that.
        return vec4<f32>(f32(evaluated), 0.0, 0.0, coverage);
    }
    // The cost breakdown's two counting passes, summed over overlapping quads by the
    // additive target: the curves visited by zone, and the fragments by what they
    // found (`breakdown_tally`, set by aa=area).
    if OVERLAY == 4u {
        return vec4<f32>(f32(evaluated), f32(breakdown_tally.x), f32(breakdown_tally.y), coverage);
    }
    if OVERLAY == 5u {
        return vec4<f32>(1.0, f32(coverage == 0.0), f32(coverage == 1.0), f32(breakdown_tally.z));
    }
    if OVERLAY == 6u {
        // The text library's glyph drawn straight into the caller's target, blended as
        // its page would composite it: the coverage rounded to a half float (11
        // significant bits, subnormal below 2^-14) as the page stores it, so that a
        // moving frame drawn this way and a still one composited from the pages agree.
        // No blend where the glyph leaves the pixel as it was.
        let parts = frexp(coverage);
        let e = max(parts.exp, -13);
        let stored = min(ldexp(round(ldexp(coverage, 11 - e)), e - 11), 1.0);
        if stored == 0.0 {
            discard;
        }
        return in.colour * stored;
    }
    return vec4<f32>(coverage);
}

// Colours of the eight sign classes (y0 > 0, y1 > 0, y2 > 0 as bits 0, 1, 2): grey
// for the two that never count, warm for the descending root only, cool for the
// ascending root only, violet for both.
const CLASS_COLORS = array<vec3<f32>, 8>(
    vec3<f32>(0.35, 0.35, 0.35), // 000: wholly below: no root
    vec3<f32>(1.0, 0.35, 0.2),   // 001: t1
    vec3<f32>(0.75, 0.3, 1.0),   // 010: both
    vec3<f32>(1.0, 0.75, 0.1),   // 011: t1
    vec3<f32>(0.2, 0.6, 1.0),    // 100: t2
    vec3<f32>(1.0, 0.4, 0.85),   // 101: both
    vec3<f32>(0.2, 0.9, 0.7),    // 110: t2
    vec3<f32>(0.7, 0.7, 0.7),    // 111: wholly above: no root
);

// The sign class of the curve nearest the pixel (within 3 px) for the x-ray through its
// centre, or 8 when no curve is that near. Brute force over the glyph: an overlay.
fn nearest_class(g: Glyph, p: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> u32 {
    let det = jx.x * jy.y - jy.x * jx.y;
    let to_pixels = mat2x2<f32>(vec2<f32>(jy.y, -jx.y), vec2<f32>(-jy.x, jx.x)) * (1.0 / det);
    // aa=area's bands are each followed by their segments (`area_band`).
    let split = select(1u, 1u + (g.band_count_v & 0xffffu), g.band_count_v >> 16u > 0u);
    let all = band_at(g.first_band + select(g.band_count_h + g.band_count_v, g.band_count_h * split, AREA));
    var best = 3.0;
    var root_class = 8u;
    for (var i = 0u; i < all.count; i++) {
        let c = band_curve(all.by_max + i);
        let p0 = c.p0p1.xy - p;
        let p1 = c.p0p1.zw - p;
        let p2 = c.p2 - p;
        for (var k = 0u; k <= 16u; k++) {
            let t = f32(k) / 16.0;
            let on_curve = mix(mix(p0, p1, t), mix(p1, p2, t), t);
            let distance = length(to_pixels * on_curve);
            if distance < best {
                best = distance;
                root_class = u32(p0.y > 0.0) | (u32(p1.y > 0.0) << 1u) | (u32(p2.y > 0.0) << 2u);
            }
        }
    }
    return root_class;
}
