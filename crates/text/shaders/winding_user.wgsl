// A user's method (`--method wgsl:PATH`, docs/your-method.md): the coverage of a pixel of
// glyph `g`, its centre `p` in the glyph's font units (y up, relative to the glyph's
// origin), `jx` and `jy` one pixel step along the image's x and y in the same units (the
// footprint's Jacobian, perspective included). A user's file replaces this stand-in,
// which no built-in pipeline calls (`USER` is false for them).
fn user_coverage(g: Glyph, p: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> f32 {
    return 0.0;
}
