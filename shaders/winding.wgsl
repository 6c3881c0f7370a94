// Method `winding` (compiled after common.wgsl): the winding number of each pixel from
// the roots of its glyph's quadratic curves along a ray, anti-aliased per crossing.
//
// Every computation is in the glyph's local coordinates (font units), relative to the
// sample point.

struct Curve {
    // p0.xy, p1.xy
    p0p1: vec4<f32>,
    // p2.xy, then the curve's largest x and y (control-point bounds), for early exits
    p2_max: vec4<f32>,
    // the curve's smallest x and y, for rays cast towards −x or −y
    min_xy: vec2<f32>,
}

struct Glyph {
    // Control-point bounds: min.xy, max.xy.
    bounds: vec4<f32>,
    // Horizontal band count, vertical band count, first band in `bands`.
    band_count_h: u32,
    band_count_v: u32,
    first_band: u32,
    // Font units per em, to tell small text from large.
    units_per_em: f32,
}

// A band lists the curves that rays inside it can cross, twice: sorted by descending
// max (for rays cast towards +) and by ascending min (for rays cast towards −), so a
// ray stops at the first curve that lies wholly behind it.
struct Band {
    by_max: u32,
    by_min: u32,
    count: u32,
}

@group(1) @binding(0) var<storage, read> glyphs: array<Glyph>;
@group(1) @binding(1) var<storage, read> bands: array<Band>;
@group(1) @binding(2) var<storage, read> band_curves: array<u32>;
@group(1) @binding(3) var<storage, read> curves: array<Curve>;

// Pipeline constants: one pipeline per parameter combination, no per-pixel branching
// on them.
override RAYS: u32 = 2u;          // 1: along x only; 2: x and y, combined by weight
override SAMPLES: u32 = 0u;       // 1, 4 (2×2 sub-pixels tiling the pixel), 0: auto
override EVEN_ODD: bool = false;  // fill rule; nonzero by default
override USE_BANDS: bool = true;  // false: every curve of the glyph for every ray
override OVERLAY: u32 = 0u;       // 0 none, 1 curve classes, 2 cost heat map

// `SAMPLES` auto: four sub-samples where a pixel spans more than this part of an em
// (text under 32 px/em, or the far side of a tilt), where one sample's error reaches
// 1–4/255 on average; one elsewhere.
const AUTO_SAMPLES_EM_PER_PIXEL: f32 = 1.0 / 32.0;

// One quad per instance over the glyph's control-point bounds.
@vertex
fn vs_main(@builtin(vertex_index) vertex: u32, @builtin(instance_index) index: u32) -> GlyphQuad {
    let inst = instances[index];
    let g = glyphs[inst.glyph];
    return glyph_quad(inst, g.bounds.xy, g.bounds.zw, vertex, frame.size);
}

// Crossings a ray keeps from within its window; past this many (only when a pixel
// holds several tiny glyph features) the ray falls back to averaging its winding.
const MAX_WINDOW_CROSSINGS: u32 = 8u;

// What one ray learned: the winding of crossings beyond its window; each crossing
// inside the window as its position `at` (the pixel share on the sample's side of the
// edge, so a lone crossing covers exactly that much) and its sign; how well it sees
// an edge at the sample (1 for an edge across the ray through the sample, falling to
// 0 for edges a pixel away or running along the ray); how well the other ray should
// see one, judging by this ray's crossings; and how many curves it evaluated.
struct Ray {
    beyond: f32,
    at: array<f32, MAX_WINDOW_CROSSINGS>,
    sign: array<f32, MAX_WINDOW_CROSSINGS>,
    count: u32,
    // The winding averaged over the window, for the fallback.
    average: f32,
    sight: f32,
    other_sight: f32,
    evaluated: u32,
}

// `pixels_per_unit_across`: pixels per local unit along the other ray.
fn add_crossing(ray: ptr<function, Ray>, x: f32, tangent: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>, reach: f32, pixels_per_unit: f32, pixels_per_unit_across: f32, sign: f32) {
    (*ray).sight = max((*ray).sight, sight(x * pixels_per_unit, tangent));
    if abs(x) > reach {
        // Beyond the window: the whole window is on one side of it.
        (*ray).beyond += select(0.0, sign, x > 0.0);
        (*ray).average += select(0.0, sign, x > 0.0);
        return;
    }
    // Within the window only: bands skip the curves wholly behind it, so a farther
    // crossing would make the image depend on the bands.
    (*ray).other_sight = max((*ray).other_sight, other_sight(x, tangent, pixels_per_unit_across));
    let share = crossing_coverage(x, tangent, jx, jy);
    (*ray).average += sign * share;
    if (*ray).count < MAX_WINDOW_CROSSINGS {
        (*ray).at[(*ray).count] = share;
        (*ray).sign[(*ray).count] = sign;
    }
    (*ray).count++;
}

// The share of the window whose winding the fill rule counts: the crossings sorted
// along the window, and the winding of each stretch between them summed up from the
// far end. Exact where contours overlap (a stretch wound twice counts once), where
// adding shares up would count it twice.
fn ray_coverage(ray: Ray) -> f32 {
    if ray.count > MAX_WINDOW_CROSSINGS {
        return fill(ray.average);
    }
    var at = ray.at;
    var sign = ray.sign;
    // Insertion sort: a handful of crossings at most.
    for (var i = 1u; i < ray.count; i++) {
        let a = at[i];
        let s = sign[i];
        var j = i;
        while j > 0u && at[j - 1u] > a {
            at[j] = at[j - 1u];
            sign[j] = sign[j - 1u];
            j--;
        }
        at[j] = a;
        sign[j] = s;
    }
    // From the far end (share 1) back to the sample's side (share 0): a stretch beyond
    // every crossing has only the winding from beyond the window.
    var winding = ray.beyond;
    var end = 1.0;
    var covered = 0.0;
    for (var k = ray.count; k > 0u; k--) {
        covered += (end - at[k - 1u]) * fill(winding);
        winding += sign[k - 1u];
        end = at[k - 1u];
    }
    return covered + end * fill(winding);
}

// Coordinates seen by a ray cast along `axis` (0: x, 1: y) towards `direction` (±1):
// the ray runs along +x of the returned frame. Swapping or mirroring reverses the
// winding's sign, which the fill rule's absolute value absorbs.
fn ray_frame(v: vec2<f32>, axis: u32, direction: f32) -> vec2<f32> {
    let along = select(v, v.yx, axis == 1u);
    return vec2<f32>(along.x * direction, along.y);
}

// Fraction of the pixel box where v + a·s + b·t > 0, for s, t uniform in [−½, ½]
// and a ≥ b ≥ 0: the exact box-filter coverage of a straight edge whose signed
// distance function, in pixel steps, has gradient (a, b).
fn box_fraction(v: f32, a: f32, b: f32) -> f32 {
    let half_sum = 0.5 * (a + b);
    let half_diff = 0.5 * (a - b);
    if v >= half_sum {
        return 1.0;
    }
    if v <= -half_sum {
        return 0.0;
    }
    if abs(v) <= half_diff {
        return 0.5 + v / a;
    }
    // The corner regions: a triangle of the box, quadratic in v (b > 0 here).
    let from_edge = half_sum - abs(v);
    let triangle = from_edge * from_edge / (2.0 * a * b);
    return select(triangle, 1.0 - triangle, v > 0.0);
}

// The share of the pixel on the sample's side of a crossing at `x` (ray frame,
// relative to the sample) within the window: the side of the curve's tangent line
// there, measured across the pixel's footprint along that line's normal (`jx`, `jy`:
// local offsets of one pixel step in x and y, ray frame).
fn crossing_coverage(x: f32, tangent: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> f32 {
    let normal = vec2<f32>(tangent.y, -tangent.x);
    let ga = abs(dot(normal, jx));
    let gb = abs(dot(normal, jy));
    if ga + gb == 0.0 {
        // A degenerate tangent (a zero-length control leg): count the crossing whole.
        return select(0.0, 1.0, x > 0.0);
    }
    return box_fraction(abs(normal.x) * x, max(ga, gb), min(ga, gb));
}

// How well a crossing `pixels` away along the ray, with this tangent, shows an edge
// at the sample: near, and across the ray rather than along it.
fn sight(pixels: f32, tangent: vec2<f32>) -> f32 {
    let across = abs(tangent.y) / max(length(tangent), 1e-30);
    return saturate(1.0 - abs(pixels)) * across;
}

// The sight the other ray (along this frame's y, through the sample) would have of a
// crossing `x` units away along this ray if the edge were the straight line of its
// tangent: that line meets the other ray |x·t.y / t.x| units from the sample, where
// the other ray sees it across by |t.x| / |t|. `sight` of that crossing, written
// without the division, so a tangent along y (t.x = 0) gives 0 rather than 0 / 0.
fn other_sight(x: f32, tangent: vec2<f32>, pixels_per_unit_across: f32) -> f32 {
    let pixels_along_times_across = abs(x * tangent.y) * pixels_per_unit_across;
    return max(abs(tangent.x) - pixels_along_times_across, 0.0) / max(length(tangent), 1e-30);
}

// Casts one ray from `sample` (local) along `axis` towards `direction`, through the
// curves of `band` (or of the whole glyph).
fn cast_ray(sample_local: vec2<f32>, jx_local: vec2<f32>, jy_local: vec2<f32>, band: Band, axis: u32, direction: f32) -> Ray {
    let s = ray_frame(sample_local, axis, direction);
    let jx = ray_frame(jx_local, axis, direction);
    let jy = ray_frame(jy_local, axis, direction);
    // Local length of one pixel along the ray: the window within which crossings
    // count fractionally. The inverse Jacobian's first column is the pixel step that
    // moves one local unit along the ray.
    let det = jx.x * jy.y - jy.x * jx.y;
    let pixels_per_unit = length(vec2<f32>(jy.y, -jx.y)) / max(abs(det), 1e-30);
    let reach = 1.0 / pixels_per_unit;
    // Its second column: the same along the frame's y, the other ray's direction.
    let pixels_per_unit_across = length(vec2<f32>(-jy.x, jx.x)) / max(abs(det), 1e-30);

    let start = select(band.by_max, band.by_min, direction < 0.0);
    var ray: Ray;
    for (var i = 0u; i < band.count; i++) {
        let c = curves[band_curves[start + i]];
        // Bands are sorted so that once a curve lies wholly behind the sample (beyond
        // the window), every later one does too.
        let far_end = select(select(c.p2_max.z, c.p2_max.w, axis == 1u), -select(c.min_xy.x, c.min_xy.y, axis == 1u), direction < 0.0);
        if USE_BANDS && far_end < s.x - reach {
            break;
        }
        ray.evaluated++;
        let p0 = ray_frame(c.p0p1.xy, axis, direction) - s;
        let p1 = ray_frame(c.p0p1.zw, axis, direction) - s;
        let p2 = ray_frame(c.p2_max.xy, axis, direction) - s;

        // Which roots count (`crossing_class`): bit 0 the descending crossing t1, bit
        // 1 the ascending one t2.
        let root_class = crossing_class(p0.y, p1.y, p2.y);
        if root_class == 0u {
            continue;
        }
        // y(t) = a t² − 2 b t + c. Roots t = (b ∓ √d)/a, in the stable form q/a, c/q:
        // as a → 0 the eligible root is always the finite c/q, so lines encoded as
        // quadratics need no threshold.
        let a = p0 - 2.0 * p1 + p2;
        let b = p0 - p1;
        let discriminant = b.y * b.y - a.y * p0.y;
        // Both roots are candidates only when the middle point is across the ray from
        // both ends; with no real root the curve turns back before reaching the ray (or
        // touches it), and its two crossings would cancel anyway. In the stable form
        // below they would not cancel exactly, so skip them here.
        if root_class == 3u && discriminant <= 0.0 {
            continue;
        }
        // A single crossing always exists; rounding may only push d below zero.
        let d = sqrt(max(discriminant, 0.0));
        let q = b.y + select(-d, d, b.y >= 0.0);
        // t1 is the root where y' = 2(a t − b) = −2√d (descending), t2 where it is +2√d.
        let t1 = select(q / a.y, p0.y / q, b.y >= 0.0);
        let t2 = select(p0.y / q, q / a.y, b.y >= 0.0);
        if (root_class & 1u) != 0u {
            let x = (a.x * t1 - 2.0 * b.x) * t1 + p0.x;
            add_crossing(&ray, x, a * t1 - b, jx, jy, reach, pixels_per_unit, pixels_per_unit_across, 1.0);
        }
        if (root_class & 2u) != 0u {
            let x = (a.x * t2 - 2.0 * b.x) * t2 + p0.x;
            add_crossing(&ray, x, a * t2 - b, jx, jy, reach, pixels_per_unit, pixels_per_unit_across, -1.0);
        }
    }
    return ray;
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

// The band of `g` holding `coordinate` across a ray along `axis`.
fn band_for(g: Glyph, sample_local: vec2<f32>, axis: u32) -> Band {
    if !USE_BANDS {
        // Every curve: the band after the vertical ones lists them all.
        return bands[g.first_band + g.band_count_h + g.band_count_v];
    }
    let count = select(g.band_count_h, g.band_count_v, axis == 1u);
    let lo = select(g.bounds.y, g.bounds.x, axis == 1u);
    let hi = select(g.bounds.w, g.bounds.z, axis == 1u);
    let across = select(sample_local.y, sample_local.x, axis == 1u);
    let index = u32(clamp(floor((across - lo) / (hi - lo) * f32(count)), 0.0, f32(count - 1u)));
    return bands[g.first_band + select(0u, g.band_count_h, axis == 1u) + index];
}

// Cast towards the nearer side of the glyph: fewer curves lie that way.
fn direction_for(g: Glyph, sample_local: vec2<f32>, axis: u32) -> f32 {
    let centre = 0.5 * (g.bounds.xy + g.bounds.zw);
    let along = select(sample_local.x - centre.x, sample_local.y - centre.y, axis == 1u);
    return select(-1.0, 1.0, along >= 0.0 || !USE_BANDS);
}

struct Coverage {
    value: f32,
    evaluated: u32,
}

// Coverage of the pixel part around `sample` whose one-pixel steps are `jx`, `jy`.
fn coverage_at(g: Glyph, sample: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> Coverage {
    let x_ray = cast_ray(sample, jx, jy, band_for(g, sample, 0u), 0u, direction_for(g, sample, 0u));
    let x_coverage = ray_coverage(x_ray);
    if RAYS == 1u {
        return Coverage(x_coverage, x_ray.evaluated);
    }
    let y_ray = cast_ray(sample, jx, jy, band_for(g, sample, 1u), 1u, direction_for(g, sample, 1u));
    let y_coverage = ray_coverage(y_ray);
    let evaluated = x_ray.evaluated + y_ray.evaluated;
    // Each ray is exact for the straight edges it crosses near the sample and blind to
    // edges running along it, which are exactly the edges the other ray sees best.
    // So trust a ray by how well it sees an edge, discounted by how well the other ray
    // sees one it cannot. A ray sees an edge at least as well as the other ray's
    // crossings, taken as the straight lines of their tangents, say it must: where it
    // meets nothing there, the edge ends or turns away before reaching it, and it is
    // the other ray's tangent line, run on across the pixel, that misleads. (By its
    // own crossings alone, a ray that meets nothing would weigh 0, and a crossing the
    // other ray meets along itself, however faintly seen, would take all the weight.)
    // For a straight edge the expected sight is the sight itself: nothing changes.
    let x_sight = max(x_ray.sight, y_ray.other_sight);
    let y_sight = max(y_ray.sight, x_ray.other_sight);
    let x_weight = x_sight * (1.0 - y_sight);
    let y_weight = y_sight * (1.0 - x_sight);
    let total = x_weight + y_weight;
    if total == 0.0 {
        // Neither ray sees an edge better than the other (no edge near, or a corner
        // at the sample): average them.
        return Coverage(0.5 * (x_coverage + y_coverage), evaluated);
    }
    let value = (x_coverage * x_weight + y_coverage * y_weight) / total;
    return Coverage(value, evaluated);
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
    let all = bands[g.first_band + g.band_count_h + g.band_count_v];
    var best = 3.0;
    var root_class = 8u;
    for (var i = 0u; i < all.count; i++) {
        let c = curves[band_curves[all.by_max + i]];
        let p0 = c.p0p1.xy - p;
        let p1 = c.p0p1.zw - p;
        let p2 = c.p2_max.xy - p;
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

@fragment
fn fs_main(in: GlyphQuad) -> @location(0) vec4<f32> {
    let g = glyphs[in.glyph];
    // One pixel step in local units, x and y: the footprint under the full transform,
    // perspective included.
    let jx = dpdx(in.local);
    let jy = dpdy(in.local);
    var coverage = 0.0;
    var evaluated = 0u;
    let pixel_in_em = max(length(jx), length(jy)) / g.units_per_em;
    if SAMPLES == 4u || (SAMPLES == 0u && pixel_in_em > AUTO_SAMPLES_EM_PER_PIXEL) {
        // Four sub-pixels at ±¼ px, each with its own half-pixel footprint: together
        // they tile the pixel, so the result stays a box filter.
        for (var k = 0u; k < 4u; k++) {
            let offset = vec2<f32>(f32(k & 1u), f32(k >> 1u)) * 0.5 - 0.25;
            let c = coverage_at(g, in.local + offset.x * jx + offset.y * jy, 0.5 * jx, 0.5 * jy);
            coverage += 0.25 * c.value;
            evaluated += c.evaluated;
        }
    } else {
        let c = coverage_at(g, in.local, jx, jy);
        coverage = c.value;
        evaluated = c.evaluated;
    }

    if OVERLAY == 1u {
        let root_class = nearest_class(g, in.local, jx, jy);
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
        // Counting pass: the number of curves evaluated, exact in half floats.
        return vec4<f32>(f32(evaluated), 0.0, 0.0, coverage);
    }
    return vec4<f32>(coverage);
}
