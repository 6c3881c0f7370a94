// claim: max=0.5 mae=8
//
// A deliberately naive method (docs/your-method.md): a pixel is covered, wholly, when
// its centre is inside the glyph under the nonzero rule (one ray towards +x from the
// centre, no anti-aliasing). It is the first thing one writes, and the claim above is
// what one believes of it: a pixel whose centre is inside is at least half covered and
// one whose centre is outside at most half, so no pixel is off by more than 0.5.
//
// The belief is wrong, and the survey shows it: a stroke thinner than a pixel that
// misses the centre leaves a pixel mostly covered drawn empty, a pixel whose centre
// sits just outside an inner corner is three quarters covered, and a curve bulging
// past the centre does the same. `glyphscope survey --methods
// wgsl:examples/methods/one_ray.wgsl` marks those glyph views broken and exits 1.

fn user_coverage(g: Glyph, p: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> f32 {
    // The prelude's winding number at the centre (`sample_winding`: one ray towards +x).
    return select(0.0, 1.0, sample_winding(g, p) != 0);
}
