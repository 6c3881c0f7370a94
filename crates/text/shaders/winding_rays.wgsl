// Method `winding`, `aa=rays` (`AREA` false; called by `fs_main` in winding.wgsl): the
// winding number at a sample from the roots of its glyph's quadratic curves along a ray
// cast towards the nearer side of the glyph, anti-aliased per crossing.
//
// Which roots count follows from the sign bits of the control points' y relative to the
// ray alone (`crossing_class`); roots come from the stable form of the quadratic
// formula, so lines need no threshold. A crossing within one pixel of the sample counts
// the exact box-filter share of the pixel on the sample's side of the curve's tangent
// line there (`crossing_coverage`); the window's crossings are sorted and each stretch
// between them put through the fill rule (`ray_coverage`), crossings beyond it count
// whole. A ray along x and one along y (`RAYS`) are blended by how well each sees an
// edge (`combine_rays`), or as Slug's shader does (`SLUG`); small text takes four
// sub-pixels (`SAMPLES`).
//
// Every computation is in the glyph's local coordinates (font units), relative to the
// sample point.

// `SAMPLES` auto: four sub-samples where a pixel spans more than this part of an em
// (text under 32 px/em, or the far side of a tilt), where one sample's error is
// several times four's (`glyphscope bench --scenes tiny`: `aa=rays` against
// `aa=rays, samples=1`); one elsewhere.
const AUTO_SAMPLES_EM_PER_PIXEL: f32 = 1.0 / 32.0;

// aa=rays' coverage of the pixel centred on local `centre` whose one-pixel steps are
// `jx`, `jy`: one sample at the centre, or four where `SAMPLES` asks for them.
fn rays_pixel(g: Glyph, centre: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> Coverage {
    let pixel_in_em = max(length(jx), length(jy)) / g.units_per_em;
    if SAMPLES == 4u || (SAMPLES == 0u && pixel_in_em > AUTO_SAMPLES_EM_PER_PIXEL) {
        // Four sub-pixels at ±¼ px, each with its own half-pixel footprint: together
        // they tile the pixel, so the result stays a box filter.
        var coverage = 0.0;
        var evaluated = 0u;
        for (var k = 0u; k < 4u; k++) {
            let offset = vec2<f32>(f32(k & 1u), f32(k >> 1u)) * 0.5 - 0.25;
            let c = coverage_at(g, centre + offset.x * jx + offset.y * jy, 0.5 * jx, 0.5 * jy);
            coverage += 0.25 * c.value;
            evaluated += c.evaluated;
        }
        return Coverage(coverage, evaluated);
    }
    return coverage_at(g, centre, jx, jy);
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

// The band of `g` holding `sample_local` across a ray along `axis`.
fn band_for(g: Glyph, sample_local: vec2<f32>, axis: u32) -> Band {
    if !USE_BANDS {
        // Every curve: the band after the vertical ones lists them all.
        return band_at(g.first_band + g.band_count_h + g.band_count_v);
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
        return band_at(first);
    }
    let index = u32(clamp(floor((across - lo) / (hi - lo) * f32(count)), 0.0, f32(count - 1u)));
    return band_at(first + index);
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
        let c = band_curve(start + i);
        // Bands are sorted so that once a curve lies wholly behind the sample (beyond
        // the window), every later one does too.
        let far_end = select(select(c.max_xy.x, c.max_xy.y, axis == 1u), -select(c.min_xy.x, c.min_xy.y, axis == 1u), direction < 0.0);
        if USE_BANDS && far_end < s.x - reach {
            break;
        }
        ray.evaluated++;
        let p0 = ray_frame(c.p0p1.xy, axis, direction) - s;
        let p1 = ray_frame(c.p0p1.zw, axis, direction) - s;
        let p2 = ray_frame(c.p2, axis, direction) - s;

        let crossings = ray_crossings(p0, p1, p2);
        let a = p0 - 2.0 * p1 + p2;
        let b = p0 - p1;
        if (crossings.counted & 1u) != 0u {
            let t1 = crossings.t.x;
            add_crossing(&ray, crossings.x.x, a * t1 - b, jx, jy, reach, pixels_per_unit, pixels_per_unit_across, 1.0);
        }
        if (crossings.counted & 2u) != 0u {
            let t2 = crossings.t.y;
            add_crossing(&ray, crossings.x.y, a * t2 - b, jx, jy, reach, pixels_per_unit, pixels_per_unit_across, -1.0);
        }
    }
    return ray;
}

// Where a quadratic crosses the ray along +x from the origin (its control points
// relative to the ray's start, in the ray's frame): which crossings count (`counted`,
// from `crossing_class`: bit 0 the descending crossing, +1 to the winding number; bit 1
// the ascending one, −1), their parameters `t` and their distances `x` along the ray
// (either sign: behind the start too), descending first. A documented helper of the
// prelude a user's method may call (docs/your-method.md).
struct RayCrossings {
    counted: u32,
    t: vec2<f32>,
    x: vec2<f32>,
}

fn ray_crossings(p0: vec2<f32>, p1: vec2<f32>, p2: vec2<f32>) -> RayCrossings {
    var out: RayCrossings;
    let root_class = crossing_class(p0.y, p1.y, p2.y);
    if root_class == 0u {
        return out;
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
    // below they would not cancel exactly, so none counts.
    if root_class == 3u && discriminant <= 0.0 {
        return out;
    }
    // A single crossing always exists; rounding may only push d below zero.
    let d = sqrt(max(discriminant, 0.0));
    let q = b.y + select(-d, d, b.y >= 0.0);
    // t1 is the root where y' = 2(a t − b) = −2√d (descending), t2 where it is +2√d.
    let t1 = select(q / a.y, p0.y / q, b.y >= 0.0);
    let t2 = select(p0.y / q, q / a.y, b.y >= 0.0);
    out.counted = root_class;
    out.t = vec2<f32>(t1, t2);
    out.x = vec2<f32>((a.x * t1 - 2.0 * b.x) * t1 + p0.x, (a.x * t2 - 2.0 * b.x) * t2 + p0.x);
    return out;
}

// The winding number of `g`'s outline around the point `s` (glyph units): its curves'
// crossings ahead of `s` on the ray towards +x through its horizontal band, descending
// ones +1 and ascending ones −1. A documented helper of the prelude for a user's method
// that samples (docs/your-method.md); the rows integrate instead.
fn sample_winding(g: Glyph, s: vec2<f32>) -> i32 {
    let band = band_for(g, s, 0u);
    var winding = 0;
    for (var k = 0u; k < band.count; k++) {
        let c = band_curve(band.by_max + k);
        let r = ray_crossings(c.p0p1.xy - s, c.p0p1.zw - s, c.p2 - s);
        winding += select(0, 1, (r.counted & 1u) != 0u && r.x.x > 0.0);
        winding -= select(0, 1, (r.counted & 2u) != 0u && r.x.y > 0.0);
    }
    return winding;
}

// Coordinates seen by a ray cast along `axis` (0: x, 1: y) towards `direction` (±1):
// the ray runs along +x of the returned frame. Swapping or mirroring reverses the
// winding's sign, which the fill rule's absolute value absorbs.
fn ray_frame(v: vec2<f32>, axis: u32, direction: f32) -> vec2<f32> {
    let along = select(v, v.yx, axis == 1u);
    return vec2<f32>(along.x * direction, along.y);
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
