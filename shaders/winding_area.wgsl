// Method `winding`, `aa=area` (the default; `AREA`, called by `fs_main` in
// winding.wgsl): the exact box-filter integral of the winding number over the pixel.
//
// By Green's theorem the pixel-averaged winding number is a sum over curves,
// F = Σ_curves ∫ G dv, G the length of the pixel's horizontal chord left of a point, in
// a frame where the glyph's rows stay rows (for the bands) and the pixel is the
// parallelogram {(σ, slope·σ + τ) : |σ|, |τ| ≤ ½}: exact under rotation, skew and
// mirroring. A curve wholly right of the pixel adds the pixel's area between its end
// heights, one wholly left, below or above it nothing (`area_zone`); one across it is
// split where u or v turns into monotone pieces, each cut at the pixel's columns and
// corner heights by one root and integrated in closed form (`across_term`). Coverage
// is fill(F), exact wherever the pixel holds two adjacent winding levels; where a
// curve marked as overlapping meets another in the pixel (three levels may meet), the
// mean over a grid of sub-pixels, each integrated the same way (`area_pixel`).
//
// Mirrored function for function, in f64, by src/methods/winding/area.rs, whose
// comments derive it.

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

// What aa=area found in this fragment, for the cost breakdown's counting passes
// (OVERLAY 4 and 5): the curves it visited wholly right of the pixel, those across it,
// and 1 where it integrated the sub-pixel grid.
var<private> breakdown_tally: vec3<u32>;

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
    if STAGE == 1u {
        // Setup only: the result must still depend on it.
        result.winding = f32(band.count) + near_end + frame.slope;
        return result;
    }
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
        if STAGE == 2u {
            // The walk without its terms.
            result.winding += f32(zone);
            continue;
        }
        if zone == ZONE_RIGHT {
            result.winding += area_below(q.p2.y, frame.slope) - area_below(q.p0.y, frame.slope);
            breakdown_tally.x++;
        } else if zone == ZONE_ACROSS && STAGE != 3u {
            result.winding += across_term(q, frame.slope);
            breakdown_tally.y++;
            across++;
            marked = marked || c.overlaps != 0.0;
        }
    }
    result.mixed = marked && across >= 2u;
    return result;
}

// The side of the grid of sub-pixels aa=area integrates where three winding levels
// may meet in a pixel: on the stability suite's overlaps 4×4 keeps every pixel within
// 0.016 (`glyphscope stability --methods winding`), where 2×2 was measured 8× worse.
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
    breakdown_tally.z = 1u;
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
