// claim: max=0.6 mae=6
//
// "GPU Font Rendering" (the gpu-font-rendering readme, by GreenLightning, after Will
// Dobbie's "GPU text rendering with vector textures") rewritten as your own method
// (docs/your-method.md): the winding number along a ray from the pixel's centre,
// anti-aliased by a window one pixel wide around the ray's start — a crossing inside
// the window changes the winding number only by the share of the window behind it —
// and, for anti-aliasing in both directions, a second ray along y, the two averaged.
//
// The claim above was set before measuring. A straight edge across one ray is exact
// for that ray; the other ray, running along the edge, sees it whole or not at all,
// so their mean can be off by up to half of what the blind ray misses: a stroke
// thinner than a pixel along a ray is off by (1 − its width) / 2, below 0.5. Corners
// and curves within the window add a little: 0.6. `winding`'s `aa=rays` is this
// method with each ray weighted by how well it sees the edge (docs/methods/winding.md).

fn user_coverage(g: Glyph, p: vec2<f32>, jx: vec2<f32>, jy: vec2<f32>) -> f32 {
    // The window: the pixel's extent along x and along y, in font units.
    let window = vec2<f32>(abs(jx.x) + abs(jy.x), abs(jx.y) + abs(jy.y));
    let along_x = ray_winding(g, p, window.x, 0u);
    let along_y = ray_winding(g, p, window.y, 1u);
    return 0.5 * (min(abs(along_x), 1.0) + min(abs(along_y), 1.0));
}

// The winding number around `p` counted along a ray towards + along `axis` (0: x, 1:
// y), each crossing by the share of the window (`window` font units wide, centred on
// `p`) that lies behind it: a whole crossing past the window's far side, none before
// its near side.
fn ray_winding(g: Glyph, p: vec2<f32>, window: f32, axis: u32) -> f32 {
    // A horizontal band for the x ray, a vertical one for the y ray: every curve that
    // can cross it.
    let band = band_for(g, p, axis);
    var winding = 0.0;
    for (var k = 0u; k < band.count; k++) {
        let c = band_curve(band.by_max + k);
        // In the ray's frame (x along the ray): the y ray swaps the axes, which
        // mirrors the outline and flips the winding number's sign; `abs` above
        // undoes that.
        let r = ray_crossings(along(c.p0p1.xy - p, axis), along(c.p0p1.zw - p, axis), along(c.p2 - p, axis));
        let share = clamp(r.x / window + 0.5, vec2<f32>(0.0), vec2<f32>(1.0));
        winding += select(0.0, share.x, (r.counted & 1u) != 0u);
        winding -= select(0.0, share.y, (r.counted & 2u) != 0u);
    }
    return winding;
}

fn along(v: vec2<f32>, axis: u32) -> vec2<f32> {
    return select(v, v.yx, axis == 1u);
}
