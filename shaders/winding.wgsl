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
    // 1 where the curve may separate other winding levels than 0 and the fill
    // (overlapping contours): aa=area integrates the pixels it crosses in sub-pixels.
    overlaps: f32,
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
override AREA: bool = false;      // aa=area: the exact box integral; no rays
override RAYS: u32 = 2u;          // 1: along x only; 2: x and y, combined by weight
override SLUG: bool = false;      // rays=slug: two rays combined as Slug's shader does
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
    if SLUG {
        // Slug's combine: a crossing counts the part of a one-pixel window along the
        // ray that lies before it, whatever the edge's slant; the ray's weight is its
        // nearest crossing's closeness (1 at the sample, 0 from half a pixel on).
        let r = x * pixels_per_unit;
        (*ray).average += sign * saturate(r + 0.5);
        (*ray).sight = max((*ray).sight, saturate(1.0 - 2.0 * abs(r)));
        return;
    }
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
    // Slug measures the window by the screen-space extent of a pixel along the ray's
    // axis (`fwidth`), which exceeds the true one under rotation.
    let pixels_per_unit = select(length(vec2<f32>(jy.y, -jx.y)) / max(abs(det), 1e-30), 1.0 / (abs(jx.x) + abs(jy.x)), SLUG);
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
    let first = g.first_band + select(0u, g.band_count_h, axis == 1u);
    // A glyph flat across the ray (every point on one line) has bands of zero height,
    // all holding the same curves: take the first. Dividing by its zero extent gives
    // NaN on that line, whose conversion to u32 is undefined, and a band index out of
    // range reads another glyph's curves.
    if !(hi > lo) {
        return bands[first];
    }
    let index = u32(clamp(floor((across - lo) / (hi - lo) * f32(count)), 0.0, f32(count - 1u)));
    return bands[first + index];
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
    if RAYS == 1u {
        return Coverage(ray_coverage(x_ray), x_ray.evaluated);
    }
    let y_ray = cast_ray(sample, jx, jy, band_for(g, sample, 1u), 1u, direction_for(g, sample, 1u));
    let evaluated = x_ray.evaluated + y_ray.evaluated;
    if SLUG {
        // Slug's weighted blend of the two rays' windings, never below the smaller of
        // them, before the fill rule.
        let x_winding = x_ray.average;
        let y_winding = y_ray.average;
        let total = max(x_ray.sight + y_ray.sight, 1.0 / 65536.0);
        let blend = abs(x_winding * x_ray.sight + y_winding * y_ray.sight) / total;
        return Coverage(fill(max(blend, min(abs(x_winding), abs(y_winding)))), evaluated);
    }
    let x_coverage = ray_coverage(x_ray);
    let y_coverage = ray_coverage(y_ray);
    // A ray sees an edge at least as well as the other ray's crossings, taken as the
    // straight lines of their tangents, say it must: where it meets nothing there, the
    // edge ends or turns away before reaching it, and it is the other ray's tangent
    // line, run on across the pixel, that misleads. (By its own crossings alone, a ray
    // that meets nothing would weigh 0, and a crossing the other ray meets along
    // itself, however faintly seen, would take all the weight.) For a straight edge the
    // expected sight is the sight itself: nothing changes.
    let x_sight = max(x_ray.sight, y_ray.other_sight);
    let y_sight = max(y_ray.sight, x_ray.other_sight);
    return Coverage(combine_rays(x_coverage, y_coverage, x_sight, y_sight), evaluated);
}

// Below this total weight the blend of the two rays leans towards their plain average,
// reaching it at 0 (see `combine_rays`).
const RAYS_TRUST_RAMP: f32 = 0.125;

// The two rays' coverages blended by their sights (each in [0, 1]). Each ray is exact
// for the straight edges it crosses near the sample and blind to edges running along
// it, which are exactly the edges the other ray sees best: so a ray is trusted by how
// well it sees an edge, discounted by how well the other ray sees one it cannot.
// Where neither sees better than the other (no edge near, both blind; or a corner at
// the sample, both fully sighted) the weights' total falls to 0 and their ratio means
// nothing: the blend eases into the plain average over `RAYS_TRUST_RAMP` of total
// weight, so that it stays continuous (a weight of 1e-7 once handed a ray everything,
// a weight of 0 half). Above the ramp the weighted mean is untouched.
fn combine_rays(x_coverage: f32, y_coverage: f32, x_sight: f32, y_sight: f32) -> f32 {
    let x_weight = x_sight * (1.0 - y_sight);
    let y_weight = y_sight * (1.0 - x_sight);
    let total = x_weight + y_weight;
    let average = 0.5 * (x_coverage + y_coverage);
    let trust = smoothstep(0.0, RAYS_TRUST_RAMP, total);
    // Tested on `trust`, not `total`: a total too small for trust to leave 0 gives no
    // 0/0, even where the GPU flushes tiny weights to zero.
    if trust == 0.0 {
        return average;
    }
    let weighted = (x_coverage * x_weight + y_coverage * y_weight) / total;
    return mix(average, weighted, trust);
}

// ---- aa=area: the exact box-filter integral of the winding number over the pixel ----
//
// Mirrored function for function, in f64, by src/methods/winding/area.rs, whose
// comments derive it. In short: F = Σ_curves ∫ G dv, G the length of the pixel's
// horizontal chord left of a point, in a frame where the glyph's rows stay rows (for
// the bands) and the pixel is the parallelogram {(σ, slope·σ + τ) : |σ|, |τ| ≤ ½}.

struct Bezier {
    p0: vec2<f32>,
    p1: vec2<f32>,
    p2: vec2<f32>,
}

// Local offsets from the pixel's centre → the pixel's frame (see `frame_map`).
struct PixelFrame {
    direction: f32,
    shear: f32,
    u_scale: f32,
    v_scale: f32,
    slope: f32,
    // False for a pixel that covers no area.
    valid: bool,
}

fn pixel_frame(jx_local: vec2<f32>, jy_local: vec2<f32>, direction: f32) -> PixelFrame {
    let jx = vec2<f32>(direction * jx_local.x, jx_local.y);
    let jy = vec2<f32>(direction * jy_local.x, jy_local.y);
    // `b` becomes the vertical sides: the step with more height, so the other one's
    // slope is at most 1.
    let swap = abs(jx.y) > abs(jy.y);
    let a = select(jx, jy, swap);
    let b = select(jy, jx, swap);
    let det = a.x * b.y - a.y * b.x;
    var f: PixelFrame;
    if det == 0.0 || b.y == 0.0 {
        return f;
    }
    f.direction = direction;
    f.shear = b.x / b.y;
    f.u_scale = abs(b.y) / abs(det);
    let a_u = (a.x - f.shear * a.y) * f.u_scale;
    let a_v = a.y / abs(b.y);
    f.v_scale = select(1.0, -1.0, a_u * a_v < 0.0) / abs(b.y);
    f.slope = abs(a_u * a_v);
    f.valid = true;
    return f;
}

fn frame_map(f: PixelFrame, offset: vec2<f32>) -> vec2<f32> {
    let x = f.direction * offset.x;
    return vec2<f32>((x - f.shear * offset.y) * f.u_scale, offset.y * f.v_scale);
}

// The heights of the pixel's four corners, lowest first.
fn frame_levels(slope: f32) -> vec4<f32> {
    let h = 0.5 * slope;
    return vec4<f32>(-0.5 - h, -0.5 + h, 0.5 - h, 0.5 + h);
}

// Area of the pixel below height `v`.
fn area_below(v: f32, slope: f32) -> f32 {
    let levels = frame_levels(slope);
    if v <= levels.x {
        return 0.0;
    }
    if v >= levels.w {
        return 1.0;
    }
    if v < levels.y {
        return (v - levels.x) * (v - levels.x) / (2.0 * slope);
    }
    if v > levels.z {
        return 1.0 - (levels.w - v) * (levels.w - v) / (2.0 * slope);
    }
    return v - levels.y + 0.5 * slope;
}

const ZONE_OUTSIDE: u32 = 0u;
const ZONE_RIGHT: u32 = 1u;
const ZONE_ACROSS: u32 = 2u;

// Where a curve's control points lie against the pixel: outside its heights or left of
// it (no term), wholly right of it (its area between the ends' heights), or across.
fn area_zone(c: Bezier, slope: f32) -> u32 {
    let levels = frame_levels(slope);
    let lo = min(min(c.p0, c.p1), c.p2);
    let hi = max(max(c.p0, c.p1), c.p2);
    if hi.y <= levels.x || lo.y >= levels.w || hi.x <= -0.5 {
        return ZONE_OUTSIDE;
    }
    if lo.x >= 0.5 {
        return ZONE_RIGHT;
    }
    return ZONE_ACROSS;
}

fn blossom(c: Bezier, a: f32, b: f32) -> vec2<f32> {
    return c.p0 * ((1.0 - a) * (1.0 - b)) + c.p1 * ((1.0 - a) * b + a * (1.0 - b)) + c.p2 * (a * b);
}

fn subcurve(c: Bezier, a: f32, b: f32) -> Bezier {
    return Bezier(blossom(c, a, a), blossom(c, a, b), blossom(c, b, b));
}

fn xs(c: Bezier) -> vec3<f32> {
    return vec3<f32>(c.p0.x, c.p1.x, c.p2.x);
}

fn ys(c: Bezier) -> vec3<f32> {
    return vec3<f32>(c.p0.y, c.p1.y, c.p2.y);
}

// Where a quadratic (control values) turns, or 1 when it does not inside (0, 1).
fn turn(c: vec3<f32>) -> f32 {
    let denominator = c.x - 2.0 * c.y + c.z;
    if denominator == 0.0 {
        return 1.0;
    }
    let t = (c.x - c.y) / denominator;
    return select(1.0, t, t > 0.0 && t < 1.0);
}

// The parameter where a quadratic monotone on [0, 1] takes `value` (0 or 1 when it
// stays on one side), by the stable form of the quadratic formula.
fn t_at(c: vec3<f32>, value: f32) -> f32 {
    let increasing = c.z >= c.x;
    if value <= min(c.x, c.z) {
        return select(1.0, 0.0, increasing);
    }
    if value >= max(c.x, c.z) {
        return select(0.0, 1.0, increasing);
    }
    let a = c.x - 2.0 * c.y + c.z;
    let b = 2.0 * (c.y - c.x);
    let k = c.x - value;
    let root = sqrt(max(b * b - 4.0 * a * k, 0.0));
    let denominator = b + select(-root, root, increasing);
    if denominator == 0.0 {
        return clamp((value - c.x) / (c.z - c.x), 0.0, 1.0);
    }
    return clamp(-2.0 * k / denominator, 0.0, 1.0);
}

// ∫₀¹ x(t) y′(t) dt of a quadratic Bézier, exactly.
fn integral_x_dy(x: vec3<f32>, y: vec3<f32>) -> f32 {
    let d0 = y.y - y.x;
    let d1 = y.z - y.y;
    return (x.x * (3.0 * d0 + d1) + 2.0 * x.y * (d0 + d1) + x.z * (d0 + 3.0 * d1)) / 6.0;
}

// ∫ ramp(ℓ(t)) y′(t) dt over a quadratic piece (ℓ its x, y its y), split where ℓ
// turns so that each part crosses ℓ = 0 once at most.
fn ramp_integral(c: Bezier) -> f32 {
    let t = turn(xs(c));
    var total = 0.0;
    var a = 0.0;
    var b = t;
    loop {
        let part = subcurve(c, a, b);
        let l = xs(part);
        var low = 0.0;
        var high = 1.0;
        if l.x < 0.0 || l.z < 0.0 {
            if l.z > l.x {
                low = t_at(l, 0.0);
            } else {
                high = t_at(l, 0.0);
            }
        }
        if high > low && (l.x > 0.0 || l.z > 0.0) {
            let positive = subcurve(part, low, high);
            total += integral_x_dy(xs(positive), ys(positive));
        }
        if b >= 1.0 {
            break;
        }
        a = b;
        b = 1.0;
    }
    return total;
}

// ∫ G dv along a piece monotone in u and v within the pixel's columns (|u| ≤ ½): with
// α = u + ½, α between heights v0 and v2, plus ramp(α − (v − v2)/slope) across the top
// side, less ramp(α − (v − v0)/slope) across the bottom one.
fn inside_term(c: Bezier, slope: f32) -> f32 {
    let levels = frame_levels(slope);
    // The slabs: between v0 and v2 (upright), across the top side, across the bottom.
    let lows = vec3<f32>(levels.x, levels.z, levels.x);
    let highs = vec3<f32>(levels.z, levels.w, levels.y);
    let v = ys(c);
    var term = 0.0;
    let slabs = select(1u, 3u, slope > 0.0);
    for (var k = 0u; k < slabs; k++) {
        let low = lows[k];
        let high = highs[k];
        let a = t_at(v, low);
        let b = t_at(v, high);
        if max(a, b) <= min(a, b) {
            continue;
        }
        let s = subcurve(c, min(a, b), max(a, b));
        let y = ys(s);
        var l = xs(s) + 0.5;
        if k > 0u {
            l -= (y - low) / slope;
        }
        let part = ramp_integral(Bezier(vec2<f32>(l.x, y.x), vec2<f32>(l.y, y.y), vec2<f32>(l.z, y.z)));
        term += select(part, -part, k == 2u);
    }
    return term;
}

// ∫ G dv along a piece monotone in u and v: right of the pixel by its area, inside its
// columns by `inside_term`, left of it nothing.
fn piece_term(c: Bezier, slope: f32) -> f32 {
    let u = xs(c);
    let t_left = t_at(u, -0.5);
    let t_right = t_at(u, 0.5);
    let increasing = u.z >= u.x;
    let right_from = select(0.0, t_right, increasing);
    let right_to = select(t_right, 1.0, increasing);
    var term = 0.0;
    if right_to > right_from {
        term += area_below(blossom(c, right_to, right_to).y, slope) - area_below(blossom(c, right_from, right_from).y, slope);
    }
    if max(t_left, t_right) > min(t_left, t_right) {
        term += inside_term(subcurve(c, min(t_left, t_right), max(t_left, t_right)), slope);
    }
    return term;
}

// ∫ G dv along a curve across the pixel, split where u or v turns.
fn across_term(c: Bezier, slope: f32) -> f32 {
    let t_u = turn(xs(c));
    let t_v = turn(ys(c));
    let splits = vec3<f32>(min(t_u, t_v), max(t_u, t_v), 1.0);
    var term = 0.0;
    var a = 0.0;
    for (var k = 0u; k < 3u && a < 1.0; k++) {
        let b = splits[k];
        if b > a {
            term += piece_term(subcurve(c, a, b), slope);
        }
        a = b;
    }
    return term;
}

// How far aa=area's bands reach beyond their boundaries, in bands (AREA_REACH in
// bands.rs): a pixel whose centre is in a band lies within its reach when half its
// height is at most this many bands.
const AREA_REACH: f32 = 0.5;

// The band holding every curve at the height of a pixel centred on `centre`, up to
// `half_height` above and below it: the finest level whose bands are at least the
// pixel's height (a band reaches half a band beyond its boundaries; see bands.rs).
fn area_band(g: Glyph, centre: vec2<f32>, half_height: f32) -> Band {
    // Level 0, then the band of all curves, then the coarser levels.
    let all = bands[g.first_band + g.band_count_h];
    var height = (g.bounds.w - g.bounds.y) / f32(g.band_count_h);
    if !USE_BANDS || !(height > 0.0) {
        return all;
    }
    var first = g.first_band;
    var count = g.band_count_h;
    var next = g.first_band + g.band_count_h + 1u;
    while count > 1u && AREA_REACH * height < half_height {
        first = next;
        height *= 2.0;
        count = (count + 1u) / 2u;
        next = first + count;
    }
    let index = u32(clamp(floor((centre.y - g.bounds.y) / height), 0.0, f32(count - 1u)));
    return bands[first + index];
}

struct AreaWinding {
    // F, the winding number averaged over the pixel.
    winding: f32,
    evaluated: u32,
    // Whether three winding levels may meet in the pixel: a curve marked as overlapping
    // and another one reach into it (one curve alone cannot make three levels; the
    // bands of a glyph with marked curves keep every curve, flat ones too).
    mixed: bool,
}

// F over the pixel centred on local `centre` whose one-pixel steps are `jx`, `jy`.
fn area_winding(g: Glyph, centre: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> AreaWinding {
    var result: AreaWinding;
    let direction = direction_for(g, centre, 0u);
    let frame = pixel_frame(jx, jy, direction);
    if !frame.valid {
        return result;
    }
    let band = area_band(g, centre, 0.5 * (abs(jx.y) + abs(jy.y)));
    // A curve wholly behind the pixel's nearest point along the walk adds nothing, and
    // the band is sorted so that every later one lies behind it too.
    let near_end = direction * centre.x - 0.5 * (abs(jx.x) + abs(jy.x));
    let start = select(band.by_max, band.by_min, direction < 0.0);
    var across = 0u;
    var marked = false;
    for (var i = 0u; i < band.count; i++) {
        let c = curves[band_curves[start + i]];
        let far_end = select(c.p2_max.z, -c.min_xy.x, direction < 0.0);
        if USE_BANDS && far_end < near_end {
            break;
        }
        result.evaluated++;
        let q = Bezier(frame_map(frame, c.p0p1.xy - centre), frame_map(frame, c.p0p1.zw - centre), frame_map(frame, c.p2_max.xy - centre));
        let zone = area_zone(q, frame.slope);
        if zone == ZONE_RIGHT {
            result.winding += area_below(q.p2.y, frame.slope) - area_below(q.p0.y, frame.slope);
        } else if zone == ZONE_ACROSS {
            result.winding += across_term(q, frame.slope);
            across++;
            marked = marked || c.overlaps != 0.0;
        }
    }
    result.mixed = marked && across >= 2u;
    return result;
}

// The side of the grid of sub-pixels aa=area integrates where three winding levels
// may meet in a pixel: on the stability suite's overlaps, 2×2 leaves up to 0.125 of a
// pixel wrong, 4×4 0.016.
const AREA_GRID: u32 = 4u;

// aa=area's coverage of the pixel: fill(F), or where three winding levels may meet in
// it (or always, with SAMPLES = 4), the mean over a grid of sub-pixels, each integrated
// exactly the same way (never with SAMPLES = 1).
fn area_pixel(g: Glyph, centre: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> Coverage {
    var evaluated = 0u;
    if SAMPLES != 4u {
        let whole = area_winding(g, centre, jx, jy);
        if SAMPLES == 1u || !whole.mixed {
            return Coverage(fill(whole.winding), whole.evaluated);
        }
        evaluated = whole.evaluated;
    }
    let step = 1.0 / f32(AREA_GRID);
    var value = 0.0;
    for (var k = 0u; k < AREA_GRID * AREA_GRID; k++) {
        let offset = (vec2<f32>(f32(k % AREA_GRID), f32(k / AREA_GRID)) + 0.5) * step - 0.5;
        let cell = area_winding(g, centre + offset.x * jx + offset.y * jy, step * jx, step * jy);
        value += fill(cell.winding);
        evaluated += cell.evaluated;
    }
    return Coverage(value * step * step, evaluated);
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
    if AREA {
        let c = area_pixel(g, in.local, jx, jy);
        coverage = c.value;
        evaluated = c.evaluated;
    } else if SAMPLES == 4u || (SAMPLES == 0u && pixel_in_em > AUTO_SAMPLES_EM_PER_PIXEL) {
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
        // Counting pass: the number of curves evaluated, exact in the half-float target
        // up to 2048 (kit::EXACT_COUNT_LIMIT); counts past it are reported as at least that.
        return vec4<f32>(f32(evaluated), 0.0, 0.0, coverage);
    }
    return vec4<f32>(coverage);
}
