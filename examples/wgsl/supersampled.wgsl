// claim: max=0.3 mae=8
//
// An example of your own method for `glyphscope --method wgsl:examples/wgsl/supersampled.wgsl`
// (docs/your-method.md): a pixel's coverage as the share of a 4×4 grid of samples that
// lie inside the glyph under the nonzero rule, each sample's winding number counted
// along a ray towards +x through the curves of its horizontal band.
//
// The claim above holds it to no pixel off by more than 0.3 (16 samples resolve a
// straight edge to about 1/4) and a mean error of 8/255.

const SIDE: u32 = 4u;

fn user_coverage(g: Glyph, p: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> f32 {
    var inside = 0u;
    for (var i = 0u; i < SIDE; i++) {
        for (var j = 0u; j < SIDE; j++) {
            // Sample centres of the grid's cells, the pixel spanning [-0.5, 0.5]².
            let cell = (vec2<f32>(f32(i), f32(j)) + 0.5) / f32(SIDE) - 0.5;
            let s = p + cell.x * jx + cell.y * jy;
            inside += u32(winding_at(g, s) != 0);
        }
    }
    return f32(inside) / f32(SIDE * SIDE);
}

// The winding number of the glyph's outline around `s`: each curve's crossings of the
// ray from `s` towards +x, the roots that count chosen by `crossing_class` (the
// prelude's root-eligibility table), descending ones +1 and ascending ones −1.
fn winding_at(g: Glyph, s: vec2<f32>) -> i32 {
    let band = band_for(g, s, 0u);
    var winding = 0;
    for (var k = 0u; k < band.count; k++) {
        let c = band_curve(band.by_max + k);
        let p0 = c.p0p1.xy - s;
        let p1 = c.p0p1.zw - s;
        let p2 = c.p2 - s;
        let roots = crossing_class(p0.y, p1.y, p2.y);
        if roots == 0u {
            continue;
        }
        // y(t) = a t² − 2 b t + y0: roots t1 = (b − √d) / a and t2 = (b + √d) / a,
        // d = b² − a y0, in the stable form that never subtracts near-equal numbers:
        // with q = b + sign(b) √d, one root is y0 / q and the other q / a. A line
        // (a = 0) has one root, y0 / 2b, and one bit of its class set; the other
        // "root" is infinite or NaN and fails the test below.
        let a = p0.y - 2.0 * p1.y + p2.y;
        let b = p0.y - p1.y;
        let d = sqrt(max(b * b - a * p0.y, 0.0));
        let q = b + select(-d, d, b >= 0.0);
        var t1 = p0.y / q;
        var t2 = q / a;
        if b < 0.0 {
            t1 = q / a;
            t2 = p0.y / q;
        }
        if (roots & 1u) != 0u && x_at(p0.x, p1.x, p2.x, t1) > 0.0 {
            winding += 1;
        }
        if (roots & 2u) != 0u && x_at(p0.x, p1.x, p2.x, t2) > 0.0 {
            winding -= 1;
        }
    }
    return winding;
}

fn x_at(x0: f32, x1: f32, x2: f32, t: f32) -> f32 {
    let u = 1.0 - t;
    return u * u * x0 + 2.0 * u * t * x1 + t * t * x2;
}
