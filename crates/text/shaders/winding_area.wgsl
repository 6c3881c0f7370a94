// Method `winding`, `aa=area` (the default; `AREA`, called by `fs_main` in
// winding.wgsl): the exact box-filter integral of the winding number over the pixel.
//
// By Green's theorem the pixel-averaged winding number is a sum over curves,
// F = Σ_curves ∫ G dv, G the length of the pixel's horizontal chord left of a point, in
// a frame that keeps the glyph's axes (its rows stay rows, for the bands) and scales
// the pixel, a parallelogram there, to area 1: exact under rotation, skew and
// mirroring. A curve wholly right of the pixel adds the pixel's area between its end
// heights, one wholly left, below or above it nothing (`area_zone`). The prep splits
// every curve where x or y turns, so each is monotone in both and meets the pixel's
// bounding box in one stretch: cut out, it adds four ramp integrals, one per segment of
// the pixel's sides (`across_term`), or where the pixel is a rectangle (`AXIS`), one
// integral (`across_axis`); the part right of the pixel adds its area between heights.
// Where the instance's pixel steps lean apart (`SQUARE`: rotations, mirrors, most
// tilts), a curve across the pixel is integrated in the pixel's own square instead,
// corrected back to the rows' form at its ends (`across_square`): fewer roots.
// Coverage is fill(F), exact wherever the pixel holds two adjacent winding levels;
// where a curve marked as overlapping meets another in the pixel (three levels may
// meet), the mean over a grid of sub-pixels, each integrated the same way
// (`area_pixel`; only in draws of glyphs with marked curves, `GRID`).
//
// Every branch a lane of a SIMD group takes, the group runs (on a software device,
// all of them): the terms are written without loops, each curve once through the same
// straight code.
//
// Mirrored function for function, in f64, by crates/text/src/winding/area.rs, whose
// comments derive it.

struct Bezier {
    p0: vec2<f32>,
    p1: vec2<f32>,
    p2: vec2<f32>,
}

// Local offsets from the pixel's centre → the pixel's frame (see `frame_map`): local
// axes kept (x mirrored towards the walk), scaled so that the pixel, the parallelogram
// spanned by its one-pixel steps, has area 1; u stays monotone along a curve monotone
// in x. Its corners are ±`bottom` (the lowest and the highest) and ±`left`: the
// boundary runs from the bottom corner to the top one on the left through `left`, on
// the right through −`left`. It spans u in [−`reach`, `reach`].
struct PixelFrame {
    direction: f32,
    scale: f32,
    bottom: vec2<f32>,
    left: vec2<f32>,
    reach: f32,
    // For `area_below`: the chord's full width, the height over which it grows from 0
    // at the bottom corner (and shrinks to 0 at the top), and the coefficient of the
    // area's square there, width / (2·rise).
    width: f32,
    rise: f32,
    growth: f32,
    // For `SQUARE`: the pixel's own coordinates α = alpha_of·q, β = beta_of·q of a
    // point q of this frame, in which the pixel is the square |α|, |β| ≤ ½: α along its
    // shallower step (pointing right), β along its steeper one (pointing up), det 1.
    alpha_of: vec2<f32>,
    beta_of: vec2<f32>,
    // For `rows_correction`: 1 / beta_of.x, and −beta_of.x / alpha_of.x.
    inverse_beta_u: f32,
    correction_scale: f32,
    // False for a pixel that covers no area.
    valid: bool,
}

fn pixel_frame(jx_local: vec2<f32>, jy_local: vec2<f32>, direction: f32) -> PixelFrame {
    var jx = vec2<f32>(direction * jx_local.x, jx_local.y);
    var jy = vec2<f32>(direction * jy_local.x, jy_local.y);
    if AXIS {
        // The instance's axes are the image's: each step runs along one local axis, and
        // what the derivatives show of the other is interpolation's rounding.
        jx = select(vec2<f32>(0.0, jx.y), vec2<f32>(jx.x, 0.0), abs(jx.x) >= abs(jx.y));
        jy = select(vec2<f32>(0.0, jy.y), vec2<f32>(jy.x, 0.0), abs(jy.x) > abs(jy.y));
    }
    let det = abs(jx.x * jy.y - jx.y * jy.x);
    var f: PixelFrame;
    if !(det > 0.0) {
        return f;
    }
    f.direction = direction;
    f.scale = inverseSqrt(det);
    let a = 0.5 * f.scale * jx;
    let b = 0.5 * f.scale * jy;
    // Each half-step taken downwards gives the lowest corner; one of them upwards, a
    // middle one; of that one and its opposite, the one left of the diagonal from the
    // bottom corner to the top one (through the centre) is on the left side.
    let a_down = select(a, -a, a.y > 0.0);
    let b_down = select(b, -b, b.y > 0.0);
    f.bottom = a_down + b_down;
    let middle = a_down - b_down;
    f.left = select(-middle, middle, middle.x * f.bottom.y > middle.y * f.bottom.x);
    f.reach = max(abs(f.bottom.x), abs(middle.x));
    f.width = 1.0 / (abs(f.left.y) - f.bottom.y);
    f.rise = -(abs(f.left.y) + f.bottom.y);
    f.growth = 0.5 * f.width / f.rise;
    if SQUARE {
        // The steeper step pointing up and the other pointing right span the pixel with
        // a positive determinant, 1 (the frame's scale): the square frame's axes, whose
        // inverse is their adjugate.
        let b_steeper = abs(b.y) * abs(a.x) >= abs(a.y) * abs(b.x);
        var up = 2.0 * select(a, b, b_steeper);
        var right = 2.0 * select(b, a, b_steeper);
        up = select(up, -up, up.y < 0.0);
        right = select(right, -right, right.x < 0.0);
        f.alpha_of = vec2<f32>(up.y, -up.x);
        f.beta_of = vec2<f32>(-right.y, right.x);
        f.inverse_beta_u = select(1.0 / f.beta_of.x, 0.0, f.beta_of.x == 0.0);
        f.correction_scale = -f.beta_of.x / f.alpha_of.x;
    }
    f.valid = true;
    return f;
}

fn frame_map(f: PixelFrame, offset: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(f.direction * offset.x, offset.y) * f.scale;
}

// Area of the pixel below height `v`: its chord grows from 0 at the bottom corner to
// its full width at the lower of the middle corners, stays there up to the higher one,
// and shrinks to 0 at the top. A rectangle's (`AXIS`) is its height below v.
fn area_below(v: f32, f: PixelFrame) -> f32 {
    let low = f.bottom.y;
    if AXIS {
        return clamp((v - low) * f.width, 0.0, 1.0);
    }
    let middle = abs(f.left.y);
    var area = f.width * (v + middle + 0.5 * f.rise);
    area = select(area, f.growth * (v - low) * (v - low), v < -middle);
    area = select(area, 1.0 - f.growth * (v + low) * (v + low), v > middle);
    area = select(area, 0.0, v <= low);
    return select(area, 1.0, v >= -low);
}

const ZONE_OUTSIDE: u32 = 0u;
const ZONE_RIGHT: u32 = 1u;
const ZONE_ACROSS: u32 = 2u;

// Where a curve's control points lie against the pixel: outside its heights or left of
// it (no term), wholly right of it (its area between the ends' heights), or across.
fn area_zone(c: Bezier, f: PixelFrame) -> u32 {
    let lo = min(min(c.p0, c.p1), c.p2);
    let hi = max(max(c.p0, c.p1), c.p2);
    if hi.y <= f.bottom.y || lo.y >= -f.bottom.y || hi.x <= -f.reach {
        return ZONE_OUTSIDE;
    }
    if lo.x >= f.reach {
        return ZONE_RIGHT;
    }
    return ZONE_ACROSS;
}

fn blossom_value(c: vec3<f32>, a: f32, b: f32) -> f32 {
    return c.x * ((1.0 - a) * (1.0 - b)) + c.y * ((1.0 - a) * b + a * (1.0 - b)) + c.z * (a * b);
}

fn blossom(c: Bezier, a: f32, b: f32) -> vec2<f32> {
    return vec2<f32>(blossom_value(xs(c), a, b), blossom_value(ys(c), a, b));
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

// The parameter where a quadratic monotone on [0, 1] takes `value` (0 or 1 when it
// stays on one side), by the stable form of the quadratic formula.
fn t_at(c: vec3<f32>, value: f32) -> f32 {
    let increasing = c.z >= c.x;
    let a = c.x - 2.0 * c.y + c.z;
    let b = 2.0 * (c.y - c.x);
    let k = c.x - value;
    let root = sqrt(max(b * b - 4.0 * a * k, 0.0));
    let denominator = b + select(-root, root, increasing);
    // Where rounding has flattened the piece, the chord's answer: one division either
    // way (a lane runs both sides of a branch).
    let flat = denominator == 0.0;
    var t = clamp(select(-2.0 * k, value - c.x, flat) / select(denominator, c.z - c.x, flat), 0.0, 1.0);
    // Past either end, that end (and nothing a division by 0 left there).
    t = select(t, 1.0, select(value <= c.z, value >= c.z, increasing));
    return select(t, 0.0, select(value >= c.x, value <= c.x, increasing));
}

// ∫₀¹ x(t) y′(t) dt of a quadratic Bézier, exactly.
fn integral_x_dy(x: vec3<f32>, y: vec3<f32>) -> f32 {
    let d0 = y.y - y.x;
    let d1 = y.z - y.y;
    return (x.x * (3.0 * d0 + d1) + 2.0 * x.y * (d0 + d1) + x.z * (d0 + 3.0 * d1)) / 6.0;
}

// The curve at t.
fn point_at(c: Bezier, t: f32) -> vec2<f32> {
    return blossom(c, t, t);
}

// ∫ G dv along a curve across the pixel when the pixel is a rectangle (`AXIS`), G the
// length of its chord left of u: u − left inside its columns, their width right of
// them, 0 left. A curve monotone in u and v meets the rectangle in one stretch, [the
// later entry, the earlier exit]; right of it, it adds the width times the height it
// climbs within the rows.
fn across_axis(c: Bezier, f: PixelFrame) -> f32 {
    let u = xs(c);
    let v = ys(c);
    let left = -f.reach;
    let low = f.bottom.y;
    let tv = vec2<f32>(t_at(v, low), t_at(v, -low));
    let tu = vec2<f32>(t_at(u, left), t_at(u, -left));
    let rows = vec2<f32>(min(tv.x, tv.y), max(tv.x, tv.y));
    let enter = max(rows.x, min(tu.x, tu.y));
    let inside = subcurve(c, enter, max(enter, min(rows.y, max(tu.x, tu.y))));
    let increasing = u.z >= u.x;
    let right_from = select(0.0, tu.y, increasing);
    let right_to = select(tu.y, 1.0, increasing);
    let climbed = clamp(point_at(c, right_to).y, low, -low) - clamp(point_at(c, right_from).y, low, -low);
    return integral_x_dy(xs(inside) - left, ys(inside)) - 2.0 * left * climbed;
}

// ∫ ramp(ℓ) v′ dt over t in [t0, t1], ℓ = u − k·v − offset, for a piece given by the
// monomial coefficients (t², t, 1) of u and v. Taken about t0, so that the sums hold
// only values from within [t0, t1] (the antiderivative from 0 would carry the rest of
// the piece into them). ℓ may turn: its roots cut the stretch in three, each wholly on
// one side, added where ℓ is positive.
fn ramp_over(u: vec3<f32>, v: vec3<f32>, k: f32, offset: f32, t0: f32, t1: f32) -> f32 {
    let m = u - k * v;
    // ℓ(t0 + τ) and v′(t0 + τ) as polynomials in τ.
    let l = vec3<f32>(m.x, 2.0 * m.x * t0 + m.y, (m.x * t0 + m.y) * t0 + m.z - offset);
    let d = 2.0 * v.x;
    let e = d * t0 + v.y;
    // ℓ's roots, past the stretch for one that does not exist (ℓ of one sign, or a line).
    let span = t1 - t0;
    let roots = clamp(sorted_roots(l, span), vec2<f32>(0.0), vec2<f32>(span));
    let cuts = vec4<f32>(0.0, roots, span);
    // ℓ·v′, a cubic, and its antiderivative at the cuts.
    let cubic = product_antiderivative(l, d, e);
    let h = (((cubic.x * cuts + cubic.y) * cuts + cubic.z) * cuts + cubic.w) * cuts;
    let mids = 0.5 * (cuts.xyz + cuts.yzw);
    let sign = (l.x * mids + l.y) * mids + l.z;
    let parts = h.yzw - h.xyz;
    return dot(select(vec3<f32>(0.0), parts, sign > vec3<f32>(0.0)), vec3<f32>(1.0));
}

// The roots of the quadratic with monomials `l` (t², t, 1), in order, by the stable
// form of the quadratic formula (finite as it degenerates to a line); `missing` for one
// that does not exist.
fn sorted_roots(l: vec3<f32>, missing: f32) -> vec2<f32> {
    let discriminant = l.y * l.y - 4.0 * l.x * l.z;
    let root = sqrt(max(discriminant, 0.0));
    let q = -0.5 * (l.y + select(-root, root, l.y >= 0.0));
    var roots = vec2<f32>(select(missing, l.z / q, q != 0.0), select(missing, q / l.x, l.x != 0.0));
    roots = select(roots, vec2<f32>(missing), discriminant < 0.0);
    return vec2<f32>(min(roots.x, roots.y), max(roots.x, roots.y));
}

// The coefficients (t⁴, t³, t², t) of the antiderivative from 0 of l(t)·(e + d·t), l a
// quadratic's monomials: the integral of a coordinate against another's slope.
fn product_antiderivative(l: vec3<f32>, d: f32, e: f32) -> vec4<f32> {
    return vec4<f32>(l.x * d, l.x * e + l.y * d, l.y * e + l.z * d, l.z * e) * vec4<f32>(0.25, 1.0 / 3.0, 0.5, 1.0);
}

// Monomial coefficients (t², t, 1) of a quadratic given by its control values.
fn monomial(c: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(c.x - 2.0 * c.y + c.z, 2.0 * (c.y - c.x), c.x);
}

// ∫ ramp(u − edge(v)) v′ dt over the heights of the pixel's edge from corner `p` to
// corner `q`, along the piece (monomials `u`, `v`) whose parameters at those heights
// are `tp` and `tq`. An edge near level runs far in u for little height: its ramp is
// taken of ℓ scaled down by its slope (ramp(a·ℓ) = a·ramp(ℓ) for a > 0), so that no
// large multiple of v is subtracted from anything.
fn edge_ramp(u: vec3<f32>, v: vec3<f32>, p: vec2<f32>, q: vec2<f32>, tp: f32, tq: f32) -> f32 {
    let run = q.x - p.x;
    let rise = q.y - p.y;
    if !(rise > 0.0) {
        // A level edge spans no height.
        return 0.0;
    }
    // ℓ = u − p.x − (v − p.y)·run/rise, taken as ℓ·a with a = rise/max(|run|, rise)
    // (positive: the edges run upwards from the bottom corner), which multiplies no
    // coordinate by more than 1.
    let a = rise / max(abs(run), rise);
    let b = run / max(abs(run), rise);
    return ramp_over(a * u, v, b, a * p.x - b * p.y, min(tp, tq), max(tp, tq)) / a;
}

// ∫ G dv along a curve across the pixel, G = ramp(u − lo(v)) − ramp(u − hi(v)) with lo
// and hi the pixel's left and right edges, each two segments between the bottom and
// top corners. Right of the pixel's columns G is the whole chord (the pixel's area
// between heights), left of them 0. The stretch within the pixel's bounding box (one
// stretch: u and v are monotone, the prep splits curves where x or y turns) is cut out
// first, so u and v stay within a pixel, and integrated as four ramps, one per edge
// segment.
fn across_term(c: Bezier, f: PixelFrame) -> f32 {
    let u = xs(c);
    let v = ys(c);
    let low = f.bottom.y;
    let tu = vec2<f32>(t_at(u, -f.reach), t_at(u, f.reach));
    let tv = vec2<f32>(t_at(v, low), t_at(v, -low));
    let increasing = u.z >= u.x;
    let right_from = select(0.0, tu.y, increasing);
    let right_to = select(tu.y, 1.0, increasing);
    let right = area_below(point_at(c, right_to).y, f) - area_below(point_at(c, right_from).y, f);
    let enter = max(min(tu.x, tu.y), min(tv.x, tv.y));
    let box = subcurve(c, enter, max(enter, min(max(tu.x, tu.y), max(tv.x, tv.y))));
    let bv = ys(box);
    // The parameters on the box's piece where v is at the corners' heights.
    let rising = bv.z >= bv.x;
    let t = vec4<f32>(select(1.0, 0.0, rising), t_at(bv, f.left.y), t_at(bv, -f.left.y), select(0.0, 1.0, rising));
    let pu = monomial(xs(box));
    let pv = monomial(bv);
    let bottom = f.bottom;
    let top = -f.bottom;
    return right
        + edge_ramp(pu, pv, bottom, f.left, t.x, t.y)
        + edge_ramp(pu, pv, f.left, top, t.y, t.w)
        - edge_ramp(pu, pv, bottom, -f.left, t.x, t.z)
        - edge_ramp(pu, pv, -f.left, top, t.z, t.w);
}

// ∫ G dv along a curve across the pixel, in the pixel's square frame (`SQUARE`: the
// instance's steps lean apart, see `steps_lean_apart` in crates/core/src/geometry/mod.rs). Two
// 1-forms have the pixel's indicator as their derivative: ω_rows = G dv, the one the
// bands need (it vanishes off the pixel's rows and left of it), and ω_square = c(α)
// c′(β) dβ with c(x) = clamp(x + ½, 0, 1), the square's own. Their difference is exact,
// dψ (`rows_correction`), so a curve adds ∫ ω_square + ψ(end) − ψ(start). Where the
// curve turns in β, it adds instead ∫ ω_swapped = −∫ c(β) c′(α) dα, whose difference
// from ω_square is d(c(α) c(β)): the steps lean apart, so a curve monotone in x and y
// turns in α or in β, never both, and the form it is integrated by has its edge
// coordinate monotone (`clamp_term`). Two levels' roots and two clips, where the
// parallelogram's four sides took four ramps and six roots (`across_term`).
fn across_square(c: Bezier, f: PixelFrame) -> f32 {
    let s0 = vec2<f32>(dot(f.alpha_of, c.p0), dot(f.beta_of, c.p0));
    let s1 = vec2<f32>(dot(f.alpha_of, c.p1), dot(f.beta_of, c.p1));
    let s2 = vec2<f32>(dot(f.alpha_of, c.p2), dot(f.beta_of, c.p2));
    let alpha = vec3<f32>(s0.x, s1.x, s2.x);
    let beta = vec3<f32>(s0.y, s1.y, s2.y);
    // A coordinate's derivative is linear in t: it changes sign where its ends' signs
    // differ. The form taken is the one whose edge coordinate turns less: where a step
    // lies within rounding of an axis, the shader's derivatives may tilt it across,
    // and a piece starting along that axis then turns in β by a hair.
    let beta_turn = (beta.y - beta.x) * (beta.z - beta.y);
    let swap = beta_turn < 0.0 && beta_turn < (alpha.y - alpha.x) * (alpha.z - alpha.y);
    let term = clamp_term(select(alpha, beta, swap), select(beta, alpha, swap));
    let c0 = clamp(s0 + 0.5, vec2<f32>(0.0), vec2<f32>(1.0));
    let c2 = clamp(s2 + 0.5, vec2<f32>(0.0), vec2<f32>(1.0));
    let square = select(term, c2.x * c2.y - c0.x * c0.y - term, swap);
    return square + rows_correction(c.p2, f) - rows_correction(c.p0, f);
}

// ∫ c(A) dclamp(B, −½, ½) along a curve whose control values are `a` and `b`, B
// monotone: its stretch within the strip |B| ≤ ½ is cut out (blossoming), its ends put
// on the strip's edges exactly (or left at the curve's), so that the integral spans the
// strip's height however long the curve and however coarse its parameter there; A's
// roots at ±½ cut the stretch into parts on which c(A) is 0, A + ½ or 1, each part's
// integral from values local to the square.
fn clamp_term(a: vec3<f32>, b: vec3<f32>) -> f32 {
    let tb = vec2<f32>(t_at(b, -0.5), t_at(b, 0.5));
    let t0 = min(tb.x, tb.y);
    let t1 = max(tb.x, tb.y);
    let l = monomial(vec3<f32>(blossom_value(a, t0, t0), blossom_value(a, t0, t1), blossom_value(a, t1, t1)));
    let pb = monomial(vec3<f32>(clamp(b.x, -0.5, 0.5), blossom_value(b, t0, t1), clamp(b.z, -0.5, 0.5)));
    // B′ = e + d·t.
    let d = 2.0 * pb.x;
    let e = pb.y;
    // The cuts inside [0, 1], in order: the four roots merged from two sorted pairs.
    let roots = level_roots(l);
    let inner = vec2<f32>(max(roots.x, roots.z), min(roots.y, roots.w));
    let cuts = vec4<f32>(min(roots.x, roots.z), min(inner.x, inner.y), max(inner.x, inner.y), max(roots.y, roots.w));
    // At each cut and at 1, the antiderivatives from 0 of (A + ½)·B′ (a cubic) and of B′.
    let cubic = product_antiderivative(l + vec3<f32>(0.0, 0.0, 0.5), d, e);
    let h = (((cubic.x * cuts + cubic.y) * cuts + cubic.z) * cuts + cubic.w) * cuts;
    let h_end = cubic.x + cubic.y + cubic.z + cubic.w;
    let climb = (0.5 * d * cuts + e) * cuts;
    let climb_end = 0.5 * d + e;
    // The five parts, each by A at its middle: 0 below −½, (A + ½)·B′ between, B′ above.
    let mids = 0.5 * (vec4<f32>(0.0, cuts.xyz) + cuts);
    let at = (l.x * mids + l.y) * mids + l.z;
    var parts = select(h - vec4<f32>(0.0, h.xyz), climb - vec4<f32>(0.0, climb.xyz), at > vec4<f32>(0.5));
    parts = select(parts, vec4<f32>(0.0), at < vec4<f32>(-0.5));
    let last_mid = 0.5 * (cuts.w + 1.0);
    let last_at = (l.x * last_mid + l.y) * last_mid + l.z;
    var last = select(h_end - h.w, climb_end - climb.w, last_at > 0.5);
    last = select(last, 0.0, last_at < -0.5);
    return dot(parts, vec4<f32>(1.0)) + last;
}

// The roots in [0, 1] where the quadratic with monomials `l` takes −½ (x, y) and ½ (z,
// w), each pair in order (1 for one that does not exist).
fn level_roots(l: vec3<f32>) -> vec4<f32> {
    let low = sorted_roots(l + vec3<f32>(0.0, 0.0, 0.5), 1.0);
    let high = sorted_roots(l - vec3<f32>(0.0, 0.0, 0.5), 1.0);
    return clamp(vec4<f32>(low, high), vec4<f32>(0.0), vec4<f32>(1.0));
}

// ψ at a point q of the row frame, dψ = ω_rows − ω_square, 0 far left: along q's row
// ω_rows vanishes (dv = 0), so ψ is −∫ c(α) c′(β) dβ from the row's far left to q. On
// the row β runs linearly (β_u = beta_of.x): the strip |β| ≤ ½ is the row's stretch
// [lo, hi], and there α grows by α_u = alpha_of.x (> 0) a unit of u, so the integral
// is (β_u / α_u)·∫ c(α) dα between the stretch's start and q (clamped into it). A row
// along the strip (β_u = 0) adds nothing to ω_square: ψ = 0.
fn rows_correction(q: vec2<f32>, f: PixelFrame) -> f32 {
    let s1 = (-0.5 - f.beta_of.y * q.y) * f.inverse_beta_u;
    let s2 = (0.5 - f.beta_of.y * q.y) * f.inverse_beta_u;
    let lo = min(s1, s2);
    let hi = max(s1, s2);
    let start = f.alpha_of.x * lo + f.alpha_of.y * q.y;
    let end = f.alpha_of.x * clamp(q.x, lo, hi) + f.alpha_of.y * q.y;
    var value = f.correction_scale * (clamp_antiderivative(end) - clamp_antiderivative(start));
    // Where the row meets the strip past α = ½, c = 1 there and the integral is the
    // strip's height crossed, from β's values (α far from the square would cancel).
    let crossed = clamp(dot(f.beta_of, q), -0.5, 0.5) - select(0.5, -0.5, f.beta_of.x > 0.0);
    value = select(value, -crossed, start > 0.5);
    return select(value, 0.0, f.beta_of.x == 0.0);
}

// ∫ c(x) dx from far below, c(x) = clamp(x + ½, 0, 1).
fn clamp_antiderivative(x: f32) -> f32 {
    return select(select(0.5 * (x + 0.5) * (x + 0.5), x, x > 0.5), 0.0, x < -0.5);
}

// How far aa=area's bands reach beyond their boundaries, in bands (AREA_REACH in
// bands.rs): a pixel whose centre is in a band lies within its reach when half its
// height is at most this many bands.
const AREA_REACH: f32 = 1.5;

// `area_band`'s choice: the list, and whether it is a segment's (walked towards +x).
struct ChosenBand {
    band: Band,
    segment: bool,
}

// The band holding every curve at the height of a pixel centred on `centre`, up to
// `half_height` above and below it: the finest level whose bands are at least the
// pixel's height over 2·AREA_REACH (see bands.rs). In a glyph whose bands are split
// into segments along x (`band_count_v`: their count in its low 16 bits, bands.rs:
// `segment_curves`), each band of the levels split (the finest, up to the count in its
// high 16 bits) is followed by its segments, and a pixel up to `half_width` either side of `centre`
// that fits one (its right edge within the segment, its left within two segments of the
// boundary, a 256th of a segment inside both) takes that segment's list, walked towards
// +x. One read, of the list chosen.
fn area_band(g: Glyph, centre: vec2<f32>, half_width: f32, half_height: f32) -> ChosenBand {
    var height = (g.bounds.w - g.bounds.y) / f32(g.band_count_h);
    // Segments per band, and how many levels from the finest have them.
    let segments = g.band_count_v & 0xffffu;
    let split_levels = g.band_count_v >> 16u;
    var per_band = select(1u, 1u + segments, split_levels > 0u);
    // Level 0, then the band of all curves, then the coarser levels.
    let all = g.first_band + g.band_count_h * per_band;
    var first = g.first_band;
    var count = g.band_count_h;
    var next = all + 1u;
    var level = 0u;
    while count > 1u && AREA_REACH * height < half_height {
        first = next;
        height *= 2.0;
        count = (count + 1u) / 2u;
        level++;
        per_band = select(1u, 1u + segments, level < split_levels);
        next = first + count * per_band;
    }
    // A glyph of no height makes `index` garbage (0/0), thrown away by the select: one
    // read either way, where an early return would add a read of its own.
    let index = u32(clamp(floor((centre.y - g.bounds.y) / height), 0.0, f32(count - 1u)));
    // The segment whose boundary is the first at least a 256th of a segment right of
    // the pixel.
    let width = (g.bounds.z - g.bounds.x) / f32(max(segments, 1u));
    let right = centre.x + half_width;
    let j = clamp(ceil((right - g.bounds.x) / width + 1.0 / 256.0), 1.0, f32(max(segments, 1u)));
    let boundary = g.bounds.x + j * width;
    let banded = USE_BANDS && height > 0.0;
    let segment = banded && per_band > 1u && right <= boundary - width / 256.0
        && centre.x - half_width >= boundary - 2.0 * width + width / 256.0;
    let chosen = first + index * per_band + select(0u, u32(j), segment);
    return ChosenBand(band_at(select(all, chosen, banded)), segment);
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
    // and another one reach into it (one curve alone, in however many pieces, cannot
    // make three levels; the bands of a glyph with marked curves keep every curve, flat
    // ones too).
    mixed: bool,
}

// F over the pixel centred on local `centre` whose one-pixel steps are `jx`, `jy`, in
// two passes over the pixel's band. The walk reads each entry's end points alone
// (`band_ends`): a monotone piece lies within their box, which says where it lies
// against the pixel, and a piece wholly right of it adds its area between their
// heights. It notes the first and the last entry across the pixel; the second pass
// reads whole curves over that stretch only and adds their terms. A SIMD device runs
// every branch some lane takes for the whole group (a software one, every branch): with
// the terms inside the walk, each step paid for the across term; now the walk's steps
// are one texel and a few products, and the across terms run over the short stretch of
// entries that cross the pixel (lavapipe: 500 moving labels, docs/library.md).
fn area_winding(g: Glyph, centre: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> AreaWinding {
    var result: AreaWinding;
    let half_width = 0.5 * (abs(jx.x) + abs(jy.x));
    let chosen = area_band(g, centre, half_width, 0.5 * (abs(jx.y) + abs(jy.y)));
    let band = chosen.band;
    let direction = select(direction_for(g, centre, 0u), 1.0, chosen.segment);
    let frame = pixel_frame(jx, jy, direction);
    if !frame.valid {
        return result;
    }
    // A curve wholly behind the pixel's nearest point along the walk adds nothing, and
    // the band is sorted so that every later one lies behind it too (`behind`).
    let near_end = direction * centre.x - half_width;
    let start = select(band.by_max, band.by_min, direction < 0.0);
    if STAGE == 1u {
        // Setup only: the result must still depend on all of it.
        result.winding = f32(band.count) + near_end + frame.scale + frame.bottom.x + frame.left.y + frame.reach + frame.width + frame.rise + frame.growth + frame.alpha_of.x + frame.beta_of.y + frame.inverse_beta_u + frame.correction_scale;
        return result;
    }
    // The entries across the pixel: the first, the last, and which of the 32 from the
    // first on (bit k: entry first + k), so that the second pass steps from one to the
    // next (past the 32, entry by entry).
    var across = 0u;
    var first_across = 0u;
    var last_across = 0u;
    var across_bits = 0u;
    // The walk is tested at its bottom, on the next entry read ahead: a SIMD device
    // runs a loop until no lane is left in it, and the pass in which the last lanes
    // leave a loop tested at its top runs the whole body for none of them (lavapipe:
    // `rotated` 5.74 -> 5.35 ms, see docs/bench.md). Measured on lavapipe alone: a gain
    // from how one SIMD implementation runs loops, not checked on SwiftShader or a GPU.
    var i = 0u;
    var ends = band_ends(start);
    if band.count > 0u && !behind(ends, direction, near_end) {
        loop {
            result.evaluated++;
            let q0 = frame_map(frame, ends.xy - centre);
            let q2 = frame_map(frame, ends.zw - centre);
            let zone = area_zone(Bezier(q0, q0, q2), frame);
            if STAGE == 2u {
                // The walk without its terms.
                result.winding += f32(zone);
            } else if zone == ZONE_RIGHT {
                result.winding += area_below(q2.y, frame) - area_below(q0.y, frame);
                breakdown_tally.x++;
            }
            let is_across = zone == ZONE_ACROSS;
            first_across = select(first_across, i, across == 0u);
            let offset = i - first_across;
            across_bits |= select(0u, 1u << min(offset, 31u), is_across && offset < 32u);
            last_across = select(last_across, i, is_across);
            across += u32(is_across);
            i++;
            ends = band_ends(start + min(i, band.count - 1u));
            if i >= band.count || behind(ends, direction, near_end) {
                break;
            }
        }
    }
    if STAGE < 4u || across == 0u {
        return result;
    }
    // Whether pieces of two different curves cross the pixel.
    var distinct = false;
    var marked = false;
    var first_parent = 0u;
    var seen = 0u;
    var k = first_across;
    loop {
        let c = band_curve_inline(start + k, band_ends(start + k));
        let q = Bezier(frame_map(frame, c.p0p1.xy - centre), frame_map(frame, c.p0p1.zw - centre), frame_map(frame, c.p2 - centre));
        // The walk's zone again, from the same points by the same operations (a
        // subtraction and products, which no compiler fuses into another rounding): it
        // tells entries past the 32 noted, stepped one by one, from those across.
        if area_zone(q, frame) == ZONE_ACROSS {
            if AXIS {
                result.winding += across_axis(q, frame);
            } else if SQUARE {
                result.winding += across_square(q, frame);
            } else {
                result.winding += across_term(q, frame);
            }
            breakdown_tally.y++;
            distinct = distinct || (seen > 0u && c.parent != first_parent);
            first_parent = select(first_parent, c.parent, seen == 0u);
            seen++;
            marked = marked || c.overlaps != 0.0;
        }
        // The next entry across: the next bit noted, or past them entry by entry.
        let offset = k - first_across;
        across_bits &= ~select(0u, 1u << min(offset, 31u), offset < 32u);
        k = select(max(k + 1u, first_across + 32u), first_across + countTrailingZeros(across_bits), across_bits != 0u);
        if k > last_across {
            break;
        }
    }
    result.mixed = marked && distinct;
    return result;
}

// Whether the curve whose end points are `ends` (p0.xy, p2.xy) lies wholly behind the
// pixel's nearest point along the walk (its control point lies between them).
fn behind(ends: vec4<f32>, direction: f32, near_end: f32) -> bool {
    let along = direction * vec2<f32>(ends.x, ends.z);
    return USE_BANDS && max(along.x, along.y) < near_end;
}

// The side of the grid of sub-pixels aa=area integrates where three winding levels
// may meet in a pixel: on the stability suite's overlaps 4×4 keeps every pixel within
// 0.016 (`glyphscope stability --methods winding`), where 2×2 was measured 8× worse.
const AREA_GRID: u32 = 4u;

// aa=area's coverage of the pixel: fill(F), or where three winding levels may meet in
// it (or always, with SAMPLES = 4), the mean over a grid of sub-pixels, each integrated
// exactly the same way (never with SAMPLES = 1, nor in a draw of glyphs without marked
// curves: `GRID`).
fn area_pixel(g: Glyph, centre: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> Coverage {
    var evaluated = 0u;
    if SAMPLES != 4u {
        let whole = area_winding(g, centre, jx, jy);
        if !GRID || !whole.mixed {
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
