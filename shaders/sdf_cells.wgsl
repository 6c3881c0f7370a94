// Method `sdf-cells` (compiled after common.wgsl): a signed distance to the outline from
// the curves listed in the pixel's cell, turned into coverage by the pixel's footprint.
//
// Per distinct glyph (`GlyphCells`): a grid over the outline; the glyph's points in the
// layout of kocsis1david's font-demo (curve i starts at points[i], an even index;
// points[i - 2 ..= i + 4] hold its previous and next curves too: each contour's points
// begin with a copy of its last curve and end with a copy of its first); per cell one
// u32, either font-demo's
// packed word (three runs of consecutive curves) or an escape to a list of slots
// (slot = point index / 2).
// Exact mode adds one band per grid row for the winding number. All math is in the
// glyph's own font units, y up: the numbers stay small wherever the glyph is.

struct GlyphCells {
    grid_min: vec2<f32>,
    cell_size: vec2<f32>,
    cols: u32,
    rows: u32,
    // First point in `points`, first word in `words`.
    point_base: u32,
    word_base: u32,
    // Band headers, from word_base: (offset from word_base, count) per grid row.
    band_offset: u32,
}

struct Settings {
    // 0 estimate, 1 exact.
    mode: u32,
    // 0 picture, 1 equal-distance overlay, 2 cell grid, 3 cost heat map, 4 raw cost.
    output: u32,
    // Lengths in font units.
    bias: f32,
    dilate: f32,
    outline: f32,
    glow: f32,
    // Estimate: 1 where tied curves whose sides disagree leave the sign to the winding
    // number (the default), 0 to font-demo's merge alone.
    ties_by_winding: u32,
}

@group(1) @binding(0) var<storage, read> glyphs: array<GlyphCells>;
@group(1) @binding(1) var<storage, read> points: array<vec2<f32>>;
@group(1) @binding(2) var<storage, read> words: array<u32>;
@group(1) @binding(3) var<uniform> settings: Settings;

const MODE_EXACT = 1u;
const OUTPUT_EQUAL_DISTANCE = 1u;
const OUTPUT_CELL_GRID = 2u;
const OUTPUT_COST_HEAT_MAP = 3u;
const OUTPUT_COST_COUNT = 4u;
// Stands for "no curve yet": finite, so that no infinity meets a zero.
const FAR = 1e30;

// The grid's rectangle (which includes what the effects draw), grown by the pixel
// footprint: one quad per instance.
@vertex
fn vs_main(@builtin(vertex_index) vertex: u32, @builtin(instance_index) index: u32) -> GlyphQuad {
    let inst = instances[index];
    let g = glyphs[inst.glyph];
    let grid_max = g.grid_min + g.cell_size * vec2<f32>(f32(g.cols), f32(g.rows));
    return glyph_quad(inst, g.grid_min, grid_max, vertex, frame.size, true);
}

// ---- Cells -------------------------------------------------------------------------

struct CellCurves {
    // font-demo's packed word, or 0 for a list.
    word: u32,
    // Index in `words` of the list's first slot.
    list: u32,
    count: u32,
}

fn cell_index(g: GlyphCells, p: vec2<f32>) -> u32 {
    let c = floor((p - g.grid_min) / g.cell_size);
    // Pixels beyond the grid (the pixel dilation) take the nearest border cell, whose
    // list was built to serve them.
    let col = u32(clamp(c.x, 0.0, f32(g.cols - 1u)));
    let row = u32(clamp(c.y, 0.0, f32(g.rows - 1u)));
    return row * g.cols + col;
}

fn cell_curves(g: GlyphCells, index: u32) -> CellCurves {
    let word = words[g.word_base + index];
    let lengths = vec3<u32>(word & 3u, (word >> 2u) & 7u, (word >> 5u) & 7u);
    if (word & 0xFFu) == 0u && word != 0u {
        // No lengths but an offset: the list encoding, `count` then the slots.
        let at = g.word_base + (word >> 8u);
        return CellCurves(0u, at + 1u, words[at]);
    }
    return CellCurves(word, 0u, lengths.x + lengths.y + lengths.z);
}

// The point index where the k-th curve of a cell starts.
fn cell_curve(g: GlyphCells, cell: CellCurves, k: u32) -> u32 {
    if cell.word == 0u {
        return g.point_base + 2u * words[cell.list + k];
    }
    // font-demo's three loops: lengths in bits 0-1, 2-4, 5-7; begins (slots) in the
    // bytes above.
    let len0 = cell.word & 3u;
    let len1 = (cell.word >> 2u) & 7u;
    var run = 0u;
    var offset = k;
    if k >= len0 + len1 {
        run = 2u;
        offset = k - len0 - len1;
    } else if k >= len0 {
        run = 1u;
        offset = k - len0;
    }
    let begin = (cell.word >> (8u + 8u * run)) & 0xFFu;
    return g.point_base + 2u * (begin + offset);
}

// ---- Distances ---------------------------------------------------------------------

// What a pass over a cell's curves finds.
struct Field {
    // Signed distance (font units), positive inside.
    value: f32,
    // Unit direction in which `value` grows fastest (local).
    gradient: vec2<f32>,
    // The two smallest unsigned distances (the mode's own measure).
    nearest: f32,
    second: f32,
    // Curves evaluated.
    cost: u32,
    // Estimate: the curve that gave `value`, and the part of the outline it stands for.
    owner: Curve,
    part: Part,
    // Estimate: the nearest chord distance of a curve whose side says p is inside, and
    // of one that says outside (of those within `bias` of the nearest when seen).
    nearest_inside: f32,
    nearest_outside: f32,
}

// Estimate: a curve as the estimate reads it, with what its joins need of its
// neighbours (the layout stores them beside it: `points[i - 2 ..= i + 4]`).
struct Curve {
    start: vec2<f32>,
    control: vec2<f32>,
    end: vec2<f32>,
    // The previous curve's start and control point.
    previous_start: vec2<f32>,
    previous_control: vec2<f32>,
    // The next curve's control point and end.
    next_control: vec2<f32>,
    next_end: vec2<f32>,
}

fn load_curve(i: u32) -> Curve {
    return Curve(points[i], points[i + 1u], points[i + 2u], points[i - 2u], points[i - 1u],
        points[i + 3u], points[i + 4u]);
}

// Estimate: the part of the outline a curve's side comes from.
struct Part {
    // The distance to its chord.
    udist: f32,
    // Whether p projects inside the chord: the side is the curve's own tangent line.
    inner: bool,
    // Where the side is a corner's (p nearest to both curves at their join): that point,
    // and a direction along the bisector of the narrower wedge between the two curves;
    // else NO_CORNER.
    corner: vec2<f32>,
    wedge: vec2<f32>,
    // The lines the side is made of, as in `Side`.
    lines: Lines,
}

const NO_CORNER = vec2<f32>(FAR, FAR);

fn keep_two_smallest(field: ptr<function, Field>, d: f32) {
    if d < (*field).nearest {
        (*field).second = (*field).nearest;
        (*field).nearest = d;
    } else {
        (*field).second = min((*field).second, d);
    }
}

// From font-demo: where p projects on the chord a→b, as a parameter clamped to [0, 1].
fn calc_t(a: vec2<f32>, b: vec2<f32>, p: vec2<f32>) -> f32 {
    let dir = b - a;
    // A closed curve (a == b) projects to its start.
    return clamp(dot(p - a, dir) / max(dot(dir, dir), 1e-30), 0.0, 1.0);
}

// Whether curve a runs straight into curve b along one contour: b starts where a ends
// and its control point is a's successor's. Equal ends alone do not say it: where two
// contours touch, their curves share ends too.
fn precedes(a: Curve, b: Curve) -> bool {
    return all(a.end == b.start) && all(a.next_control == b.control);
}

// Where v lies between the ends of a curve whose side is the line (value, gradient at
// p) through v, as an edge is where another contour's corner touches it, that line's
// inward normal; else zero. "Through" is to 1e-3 of p's distance from v plus a few f32
// steps at v's coordinates: a corner on a curved edge is seen only as far as the
// tangent at p's projection passes through it.
fn normal_through(start: vec2<f32>, end: vec2<f32>, value: f32, gradient: vec2<f32>, v: vec2<f32>, p: vec2<f32>) -> vec2<f32> {
    let t = calc_t(start, end, v);
    let steps = 4.0 * 1.2e-7 * max(abs(v.x), abs(v.y));
    let through = abs(value + dot(gradient, v - p)) <= 1e-3 * distance(p, v) + steps;
    return select(vec2<f32>(0.0), gradient, t > 0.0 && t < 1.0 && through);
}

// A tie at the join where a curve starting at `a` runs into the curve from `b` to `c`
// (a seen from that curve's chord, on its right where the outline turns right): min
// where the outline turns right (convex: inside both), else max.
fn merge_at_join(a: vec2<f32>, b: vec2<f32>, c: vec2<f32>, kept: f32, bez: f32) -> f32 {
    let chord = c - b;
    let turn = dot(vec2<f32>(chord.y, -chord.x), a - b);
    return select(min(bez, kept), max(bez, kept), turn <= 0.0);
}

// The lines a side is made of, by their inward normals: a corner's two, inside both
// (convex) or either; a tangent line's one, twice.
struct Lines {
    first: vec2<f32>,
    second: vec2<f32>,
    convex: bool,
}

// Whether the direction w from a side's lines' meeting point points inside them.
fn inside_along(lines: Lines, w: vec2<f32>) -> bool {
    let first = dot(lines.first, w) > 0.0;
    let second = dot(lines.second, w) > 0.0;
    return select(first || second, first && second, lines.convex);
}

// A signed distance, the unit direction in which it grows, and whether a corner gave it
// (p nearest to both curves meeting there at their join).
struct Side {
    value: f32,
    gradient: vec2<f32>,
    corner: bool,
    // For a corner: along the bisector of the narrower wedge between its two curves.
    wedge: vec2<f32>,
    lines: Lines,
}

// The signed distance from p to the line a→b, positive on its right (y up), as
// font-demo's `dist_to_line`.
fn side_of_line(a: vec2<f32>, b: vec2<f32>, p: vec2<f32>) -> Side {
    let dir = normalize(b - a);
    let gradient = vec2<f32>(dir.y, -dir.x);
    return Side(dot(gradient, p - a), gradient, false, vec2<f32>(0.0), Lines(gradient, gradient, true));
}

// font-demo's side of p for a curve: its tangent line at t, the parameter where p
// projects on its chord. Where the control point sits on an endpoint that tangent
// vanishes at the end and the chord stands in.
fn tangent_side(c: Curve, t: f32, p: vec2<f32>) -> Side {
    let q0 = mix(c.start, c.control, t);
    let q1 = mix(c.control, c.end, t);
    let degenerate = all(q0 == q1);
    return side_of_line(select(q0, c.start, degenerate), select(q1, c.end, degenerate), p);
}

// The side of p at a join v where the outline comes in from `before` and leaves towards
// `after` (the tangents' far points), for a curve whose chord is nearest to p at v
// (`own`: its tangent side). Past both tangents there, v is the nearest point of both
// curves and their corner decides: p is inside both tangent lines where the outline
// turns right (convex), inside either where it turns left. Elsewhere `own` stands, as in
// font-demo.
fn join_side(before: vec2<f32>, v: vec2<f32>, after: vec2<f32>, far: vec4<f32>, p: vec2<f32>, own: Side) -> Side {
    let into = normalize(v - before);
    let out = normalize(after - v);
    if dot(p - v, into) < 0.0 || dot(p - v, out) > 0.0 {
        return own;
    }
    let into_gradient = vec2<f32>(into.y, -into.x);
    let out_gradient = vec2<f32>(out.y, -out.x);
    let incoming = dot(into_gradient, p - v);
    let outgoing = dot(out_gradient, p - v);
    // Convex where the outline turns right (y up) from one tangent to the other. At a
    // cusp the two tangents lie on one line, the outline doubling back along it (a
    // star's spike at its tip), and their turn is rounding's: the curves' far ends,
    // `far` (the incoming curve's start, the outgoing curve's end), say which way it
    // bends.
    let turn = into.x * out.y - into.y * out.x;
    let far_turn = cross2(v - far.xy, far.zw - v);
    let convex = select(turn < 0.0, far_turn < 0.0, abs(turn) < 1e-4);
    let lines = Lines(into_gradient, out_gradient, convex);
    if (incoming < outgoing) == convex {
        return Side(incoming, into_gradient, true, out - into, lines);
    }
    return Side(outgoing, out_gradient, true, out - into, lines);
}

// Where two contours touch, at a corner of one lying on the other (the lobes of a
// figure-8 once merged, squares meeting at a corner, a tip on an edge): whether the
// other part's lines hold the corner's narrower wedge. Where they do not, the two fills
// meet only at the point and p is inside either (max); where they do, the wedge is a hole
// in the other's fill and p is inside both (min).
fn merge_touching(other_holds_wedge: bool, kept: f32, value: f32) -> f32 {
    return select(max(value, kept), min(value, kept), other_holds_wedge);
}

// How curve c's side merges with the value so far when c is within `bias` of the curve
// that gave it (the owner).
fn merge_tie(c: Curve, part: Part, side: Side, p: vec2<f32>, field: Field) -> f32 {
    let owner = field.owner;
    let kept = field.value;
    // One runs into the other: the corner at their join. font-demo asks how the
    // previous curve turns into this one, which is the other join when this curve runs
    // into the owner (the last curve of a contour meeting its first).
    let into_owner = precedes(c, owner);
    let at_join = merge_at_join(select(c.previous_start, c.start, into_owner),
        select(c.start, owner.start, into_owner), select(c.end, owner.end, into_owner), kept,
        side.value);
    if into_owner || precedes(owner, c) {
        return at_join;
    }
    // A corner of one on the other (this curve's on the owner, else the owner's on this
    // curve): at the other's end, the other's own lines there; between its ends, its
    // tangent at the corner.
    let mine = part.corner;
    let theirs = field.part.corner;
    let my_corner = all(mine != NO_CORNER);
    let their_corner = all(theirs != NO_CORNER);
    let v = select(theirs, mine, my_corner);
    let start = select(c.start, owner.start, my_corner);
    let end = select(c.end, owner.end, my_corner);
    let normal = normal_through(start, end, select(side.value, kept, my_corner),
        select(side.gradient, field.gradient, my_corner), v, p);
    let on_end = all(start == v) || all(end == v);
    if (my_corner || their_corner) && (on_end || any(normal != vec2<f32>(0.0))) {
        var lines = Lines(normal, normal, true);
        if on_end {
            lines = part.lines;
            if my_corner {
                lines = field.part.lines;
            }
        }
        let wedge = select(field.part.wedge, part.wedge, my_corner);
        return merge_touching(inside_along(lines, wedge), kept, side.value);
    }
    // Parts of the outline that do not meet. A side is right where its part is the
    // nearest when p projects inside the part's chord, or past both tangents at its
    // corner; the other end of a curve only stands in. Two that p projects inside: the
    // nearer decides; one, against a stand-in: that one.
    if part.inner && field.part.inner {
        return select(side.value, kept, part.udist >= field.part.udist);
    }
    if part.inner && !field.part.inner && !their_corner && part.udist <= field.part.udist {
        return side.value;
    }
    if field.part.inner && !part.inner && !my_corner && field.part.udist <= part.udist {
        return kept;
    }
    return at_join;
}

// font-demo's `process_bezier2`: the curve nearest by its chord gives the distance to
// its tangent line at t; curves within `bias` of the one that gave it tie and merge
// (`merge_tie`). Where the chord's nearest point is an end, the curve's side is read at
// the join there (`join_side`; font-demo leaves that to the tie with the neighbour,
// which need not be the curve that gave the value). A tie is judged against the curve
// that gave the value, not the nearest seen: along a chain of curves each within `bias`
// of the last, a far curve's side would otherwise stand over a nearer one's.
fn estimate_curve(p: vec2<f32>, i: u32, field: ptr<function, Field>) {
    let c = load_curve(i);
    let t = calc_t(c.start, c.end, p);
    let udist = distance(mix(c.start, c.end, t), p);
    let min_udist = (*field).nearest;
    keep_two_smallest(field, udist);
    if udist > min_udist + settings.bias {
        return;
    }
    var side = tangent_side(c, t, p);
    let at_start = t <= 0.0;
    let v = select(c.end, c.start, at_start);
    if at_start || t >= 1.0 {
        // The join's tangents; the chord stands in for one that vanishes.
        let own_in = select(c.control, c.start, all(c.control == c.end));
        let own_out = select(c.control, c.end, all(c.control == c.start));
        let previous_in = select(c.previous_control, c.previous_start, all(c.previous_control == c.start));
        let next_out = select(c.next_control, c.next_end, all(c.next_control == c.end));
        let far = select(vec4<f32>(c.start, c.next_end), vec4<f32>(c.previous_start, c.end), at_start);
        side = join_side(select(own_in, previous_in, at_start), v, select(next_out, own_out, at_start), far, p, side);
    }
    let part = Part(udist, t > 0.0 && t < 1.0, select(NO_CORNER, v, side.corner), side.wedge,
        side.lines);
    if side.value > 0.0 {
        (*field).nearest_inside = min((*field).nearest_inside, udist);
    } else {
        (*field).nearest_outside = min((*field).nearest_outside, udist);
    }
    var merged = side.value;
    if udist >= (*field).part.udist - settings.bias {
        merged = merge_tie(c, part, side, p, *field);
    }
    if merged == side.value {
        (*field).gradient = side.gradient;
        (*field).owner = c;
        (*field).part = part;
    }
    (*field).value = merged;
}

// The parameter in [0, 1] of the point of the quadratic (p0, p1, p2) nearest to p.
// B(t) = p0 + 2ta + t²b; the nearest point solves the cubic (B(t) − p)·B'(t) = 0,
// t³ + 3kx t² + 3ky t + kz = 0 after dividing by b·b, solved in closed form (Cardano,
// after Inigo Quilez's sdBezier). Near-straight curves, where b·b vanishes, start from
// the chord instead. One Newton step on the undivided cubic then polishes each root;
// the better of the raw and polished roots is kept, so a step that overshoots costs
// nothing. Clamped roots cover the endpoints.
fn nearest_on_quadratic(p0: vec2<f32>, p1: vec2<f32>, p2: vec2<f32>, p: vec2<f32>) -> f32 {
    let a = p1 - p0;
    let b = p0 - 2.0 * p1 + p2;
    let d = p0 - p;
    let c3 = dot(b, b);
    let c2 = 3.0 * dot(a, b);
    let c1 = 2.0 * dot(a, a) + dot(d, b);
    let c0 = dot(d, a);
    var roots = vec2<f32>(0.0);
    if c3 <= 1e-6 * dot(a, a) {
        roots = vec2<f32>(calc_t(p0, p2, p));
    } else {
        let kk = 1.0 / c3;
        let kx = kk * dot(a, b);
        let ky = kk * c1 / 3.0;
        let kz = kk * c0;
        let pp = ky - kx * kx;
        let q = kx * (2.0 * kx * kx - 3.0 * ky) + kz;
        let h = q * q + 4.0 * pp * pp * pp;
        if h >= 0.0 {
            // One real root.
            let s = sqrt(h);
            let x = (vec2<f32>(s, -s) - q) * 0.5;
            let uv = sign(x) * pow(abs(x), vec2<f32>(1.0 / 3.0));
            roots = vec2<f32>(uv.x + uv.y - kx);
        } else {
            // Three real roots; the middle one is a farthest point.
            let z = sqrt(-pp);
            let v = acos(clamp(q / (pp * z * 2.0), -1.0, 1.0)) / 3.0;
            let m = cos(v);
            let n = sin(v) * 1.732050808;
            roots = vec2<f32>(m + m, -n - m) * z - kx;
        }
    }
    var best = 0.0;
    var best_d2 = FAR;
    for (var k = 0u; k < 2u; k++) {
        let t = clamp(roots[k], 0.0, 1.0);
        let f = ((c3 * t + c2) * t + c1) * t + c0;
        let df = (3.0 * c3 * t + 2.0 * c2) * t + c1;
        let polished = clamp(t - f / select(df, 1.0, df == 0.0), 0.0, 1.0);
        for (var j = 0u; j < 2u; j++) {
            let u = select(t, polished, j == 1u);
            let e = d + (2.0 * a + b * u) * u;
            let d2 = dot(e, e);
            if d2 < best_d2 {
                best_d2 = d2;
                best = u;
            }
        }
    }
    return best;
}

fn exact_curve(p: vec2<f32>, i: u32, field: ptr<function, Field>) {
    let p0 = points[i];
    let p1 = points[i + 1u];
    let p2 = points[i + 2u];
    let t = nearest_on_quadratic(p0, p1, p2, p);
    let away = p - (p0 + (2.0 * (p1 - p0) + (p0 - 2.0 * p1 + p2) * t) * t);
    let d = length(away);
    if d < (*field).nearest && d > 0.0 {
        (*field).gradient = away / d;
    }
    keep_two_smallest(field, d);
}

// Signed crossings of the ray from the origin towards +x by the quadratic (p0, p1, p2),
// given relative to the ray's start: +1 for each crossing downwards, −1 upwards.
//
// Which roots count is `crossing_class` (common.wgsl): y(t) = a t² − 2b t + c has its
// downward crossing at t1 = (b − √D)/a and its upward one at t2 = (b + √D)/a. D = b² − ac is computed as
// y1² − y0·y2, which is never negative when the endpoints lie on opposite sides (one
// crossing for sure); when they lie on the same side, D ≤ 0 means the curve only
// touches or misses the ray. The roots are taken in the form that does not cancel
// (c/q and q/a, q = b ± √D), so nearly straight curves lose no precision.
fn quadratic_ray_crossings(p0: vec2<f32>, p1: vec2<f32>, p2: vec2<f32>) -> i32 {
    let roots = crossing_class(p0.y, p1.y, p2.y);
    let down = (roots & 1u) != 0u;
    let up = (roots & 2u) != 0u;
    let discriminant = p1.y * p1.y - p0.y * p2.y;
    if !(down || up) || (down && up && discriminant <= 0.0) {
        return 0;
    }
    let a = p0.y - 2.0 * p1.y + p2.y;
    let b = p0.y - p1.y;
    let c = p0.y;
    let root = sqrt(max(discriminant, 0.0));
    let q = b + select(-root, root, b >= 0.0);
    // t1 = c/q and t2 = q/a for b ≥ 0, the other way round for b < 0.
    let near = c / select(q, 1.0, q == 0.0);
    let far = q / select(a, 1.0, a == 0.0);
    let t1 = select(far, near, b >= 0.0);
    let t2 = select(near, far, b >= 0.0);
    let ax = p0.x - 2.0 * p1.x + p2.x;
    let bx = p1.x - p0.x;
    var w = 0;
    if down && (ax * t1 + 2.0 * bx) * t1 + p0.x > 0.0 {
        w += 1;
    }
    if up && (ax * t2 + 2.0 * bx) * t2 + p0.x > 0.0 {
        w -= 1;
    }
    return w;
}

struct Winding {
    number: i32,
    // Curves evaluated.
    cost: u32,
}

// Nonzero winding number at p from its row's band; the band is sorted by decreasing
// right end, so the first curve wholly left of p ends the walk.
fn winding_number(g: GlyphCells, p: vec2<f32>) -> Winding {
    let row = u32(clamp(floor((p.y - g.grid_min.y) / g.cell_size.y), 0.0, f32(g.rows - 1u)));
    let header = g.word_base + g.band_offset + 2u * row;
    let start = g.word_base + words[header];
    let count = words[header + 1u];
    var w = Winding(0, 0u);
    for (var k = 0u; k < count; k++) {
        let i = g.point_base + 2u * words[start + k];
        let p0 = points[i] - p;
        let p1 = points[i + 1u] - p;
        let p2 = points[i + 2u] - p;
        if max(max(p0.x, p1.x), p2.x) <= 0.0 {
            break;
        }
        w.cost += 1u;
        w.number += quadratic_ray_crossings(p0, p1, p2);
    }
    return w;
}

fn signed_distance(g: GlyphCells, p: vec2<f32>) -> Field {
    let far = vec2<f32>(FAR);
    var field = Field(-FAR, vec2<f32>(1.0, 0.0), FAR, FAR, 0u, Curve(far, far, far, far, far, far, far),
        Part(FAR, false, NO_CORNER, vec2<f32>(0.0), Lines(vec2<f32>(0.0), vec2<f32>(0.0), true)),
        FAR, FAR);
    let cell = cell_curves(g, cell_index(g, p));
    field.cost = cell.count;
    for (var k = 0u; k < cell.count; k++) {
        let i = cell_curve(g, cell, k);
        if settings.mode == MODE_EXACT {
            exact_curve(p, i, &field);
        } else {
            estimate_curve(p, i, &field);
        }
    }
    if settings.mode == MODE_EXACT {
        let winding = winding_number(g, p);
        field.cost += winding.cost;
        let inside = winding.number != 0;
        field.value = select(-field.nearest, field.nearest, inside);
        field.gradient = select(-field.gradient, field.gradient, inside);
    } else if settings.ties_by_winding != 0u && field.nearest < FAR
        && (max(field.nearest_inside, field.nearest_outside) <= field.nearest + settings.bias
            || !field.part.inner) {
        // The side came from a rule rather than from the nearest curve's own tangent
        // line: curves within `bias` of the nearest disagree (whatever order the cell
        // lists them in) and font-demo's rules for their join chose one, or p lies past
        // the ends of the nearest chord and the corner there decided.
        // Where the corner is not one join of one contour (contours touching or
        // crossing, curves halved, cusps) a rule can choose the wrong side and read the
        // pixel a whole pixel off. The winding number along the row says which side p
        // is on; the distance stands (tied curves are equally near). It costs 5 % more
        // curves on the bench's page (4.48 → 4.73 per pixel; the ties alone, 4.51).
        let winding = winding_number(g, p);
        field.cost += winding.cost;
        if (field.value > 0.0) != (winding.number != 0) {
            field.value = -field.value;
            field.gradient = -field.gradient;
        }
    }
    return field;
}

// ---- Coverage ----------------------------------------------------------------------

// Box-filter coverage of the unit pixel by the half-plane of points within `d` pixels
// of its centre along the unit normal n: the distribution of n·x over the pixel is a
// trapezoid of width |nx| + |ny|, and this is its integral — exact for a straight edge
// at any angle, and the plain ramp clamp(d + 0.5) for an axis-aligned one.
fn edge_coverage(d: f32, n: vec2<f32>) -> f32 {
    let wide = max(abs(n.x), abs(n.y));
    let narrow = min(abs(n.x), abs(n.y));
    let u = d + 0.5 * (wide + narrow);
    if u <= 0.0 {
        return 0.0;
    }
    if u >= wide + narrow {
        return 1.0;
    }
    if u < narrow {
        return u * u / (2.0 * wide * narrow);
    }
    if u > wide {
        let v = wide + narrow - u;
        return 1.0 - v * v / (2.0 * wide * narrow);
    }
    return (u - 0.5 * narrow) / wide;
}

const INK = vec3<f32>(1.0, 1.0, 1.0);
const OUTLINE_COLOR = vec3<f32>(1.0, 0.62, 0.18);
const GLOW_COLOR = vec3<f32>(0.25, 0.85, 1.0);
const PURPLE = vec3<f32>(0.62, 0.12, 0.85);
const GRID_LINE = vec3<f32>(1.0, 0.25, 0.2);

@fragment
fn fs_main(in: GlyphQuad) -> @location(0) vec4<f32> {
    let p = quad_local(in);
    // Font units per pixel step, here (perspective included): the footprint. Taken
    // before any branch, where derivatives are defined.
    let dx = dpdx(p);
    let dy = dpdy(p);
    let g = glyphs[in.glyph];
    let field = signed_distance(g, p);

    // The distance in pixels along the field's gradient, and that gradient in pixels.
    let slope = vec2<f32>(dot(dx, field.gradient), dot(dy, field.gradient));
    let units_per_pixel = max(length(slope), 1e-20);
    let normal = slope / units_per_pixel;
    let value = field.value + settings.dilate;
    let fill = edge_coverage(value / units_per_pixel, normal);
    // The fill and the outline's stroke together: the stroke runs outside the edge.
    let outer = edge_coverage((value + settings.outline) / units_per_pixel, normal);
    var shape = fill;
    var color = INK * fill;
    if settings.outline > 0.0 {
        // The stroke alone: the glyph drawn hollow.
        shape = outer - fill;
        color = OUTLINE_COLOR * shape;
    }
    var alpha = shape;
    if settings.glow > 0.0 {
        // Fades from the outer edge to nothing `glow` farther out, behind the shape.
        let fade = 1.0 - clamp(-(value + settings.outline) / settings.glow, 0.0, 1.0);
        let glow = 0.6 * fade * fade * (1.0 - outer);
        alpha += glow;
        color += GLOW_COLOR * glow;
    }

    switch settings.output {
        case OUTPUT_EQUAL_DISTANCE: {
            // Where the two nearest curves are as near as each other, within the bias:
            // font-demo's purple regions, where ties are merged.
            if field.second - field.nearest <= settings.bias {
                color = mix(color, PURPLE, 0.85);
            }
        }
        case OUTPUT_CELL_GRID: {
            let cell = (p - g.grid_min) / g.cell_size;
            let count = cell_curves(g, cell_index(g, p)).count;
            // White at the most curves a packed cell of font-demo holds.
            color = mix(color, heat_color(f32(count) / 17.0), 0.45);
            // Distance to the nearest cell border in pixels, per axis.
            let rate = vec2<f32>(length(vec2<f32>(dx.x, dy.x)), length(vec2<f32>(dx.y, dy.y))) / g.cell_size;
            let border = min(fract(cell), 1.0 - fract(cell)) / rate;
            if min(border.x, border.y) < 0.5 {
                color = GRID_LINE;
            }
        }
        case OUTPUT_COST_HEAT_MAP: {
            color = mix(heat_color(f32(field.cost) / COST_SCALE), color, 0.25);
        }
        case OUTPUT_COST_COUNT: {
            color = vec3<f32>(f32(field.cost), 0.0, 0.0);
        }
        default: {
            // No overlay: coverage in every channel, as `common.wgsl` asks.
            color = vec3<f32>(alpha);
        }
    }
    return vec4<f32>(color, alpha);
}
