//! Proofs of the reference rasterizer: it is the ground truth for every error figure,
//! so it is checked against closed-form areas and against an independent point-sampling
//! rasterizer on real glyphs.

mod common;

use common::*;
use glam::{DMat3, DVec2};
use glyphscope::camera::Camera;
use glyphscope::coverage::CoverageImage;
use glyphscope::font::SHIPPED_FONTS;
use glyphscope::geometry::{Outline, project};
use glyphscope::metrics::compare;
use glyphscope::reference::{rasterize, rasterize_with_tolerance};
use glyphscope::scene::Scene;

/// Area of a polygon (image coordinates) inside pixel (i, j): Sutherland–Hodgman against
/// the convex pixel square, which is exact in area for any simple polygon.
fn clipped_area(poly: &[DVec2], i: u32, j: u32) -> f64 {
    let (x0, y0) = (f64::from(i), f64::from(j));
    let planes: [(DVec2, f64); 4] = [
        (DVec2::X, x0),
        (-DVec2::X, -(x0 + 1.0)),
        (DVec2::Y, y0),
        (-DVec2::Y, -(y0 + 1.0)),
    ];
    let mut pts = poly.to_vec();
    for (n, d) in planes {
        let inside = |p: DVec2| p.dot(n) >= d;
        let mut out = Vec::new();
        for k in 0..pts.len() {
            let (a, b) = (pts[k], pts[(k + 1) % pts.len()]);
            if inside(a) {
                out.push(a);
            }
            if inside(a) != inside(b) {
                let t = (d - a.dot(n)) / (b - a).dot(n);
                out.push(a + (b - a) * t);
            }
        }
        pts = out;
        if pts.is_empty() {
            return 0.0;
        }
    }
    let twice: f64 = (0..pts.len())
        .map(|k| pts[k].perp_dot(pts[(k + 1) % pts.len()]))
        .sum();
    (twice * 0.5).abs()
}

/// Exact coverage image of a union of disjoint simple polygons given in image space.
fn exact_image(width: u32, height: u32, polys: &[Vec<DVec2>]) -> CoverageImage {
    let mut img = CoverageImage::new(width, height);
    for j in 0..height {
        for i in 0..width {
            img.data[(j * width + i) as usize] =
                polys.iter().map(|p| clipped_area(p, i, j)).sum::<f64>() as f32;
        }
    }
    img
}

fn to_image(camera: &Camera, pts: &[(f64, f64)]) -> Vec<DVec2> {
    let m = camera.glyph_to_image(1000.0, DVec2::ZERO);
    pts.iter()
        .map(|&(x, y)| project(&m, DVec2::new(x, y)))
        .collect()
}

fn assert_close(got: &CoverageImage, want: &CoverageImage, bound: f64, what: &str) {
    let s = compare(got, want).unwrap();
    assert!(
        s.max <= bound,
        "{what}: max error {} at {:?} (bound {bound})",
        s.max,
        s.worst_pixel
    );
    assert!(want.sum() > 1.0, "{what}: the expected image is empty");
}

/// The tolerance the reference promises: 1/1024 of a pixel's area. Polygons have no
/// flattening error at all, so they must be exact to rounding.
const EXACT: f64 = 1e-9;

#[test]
fn squares_at_subpixel_offsets() {
    for k in 0..16 {
        let (dx, dy) = (f64::from(k) / 16.0 + 0.03, f64::from(k % 5) / 5.0 + 0.011);
        let r = rect(3.0 + dx, 2.0 + dy, 11.7 + dx, 9.2 + dy);
        let cam = unit_camera(16, 14);
        let got = rasterize(&single(polygons(&[&r])), &cam).unwrap();
        assert_close(
            &got,
            &exact_image(16, 14, &[to_image(&cam, &r)]),
            EXACT,
            "square",
        );
    }
}

#[test]
fn rotated_and_skewed_squares() {
    for (k, angle) in [1.0f64, 30.0, 45.0, 89.9, 123.4].into_iter().enumerate() {
        let (s, c) = angle.to_radians().sin_cos();
        let mut cam = unit_camera(24, 24);
        cam.matrix = Camera::matrix_from_rows(c, -s + 0.2 * k as f64, s, c);
        cam.origin = DVec2::new(12.3 + 0.1 * k as f64, 12.7);
        let r = rect(-6.0, -5.0, 5.5, 6.25);
        let got = rasterize(&single(polygons(&[&r])), &cam).unwrap();
        assert_close(
            &got,
            &exact_image(24, 24, &[to_image(&cam, &r)]),
            EXACT,
            "rotated square",
        );
    }
}

#[test]
fn concave_polygon_either_orientation() {
    let l_shape = [
        (1.0, 1.0),
        (9.3, 1.0),
        (9.3, 4.6),
        (4.2, 4.6),
        (4.2, 10.1),
        (1.0, 10.1),
    ];
    let reversed: Vec<_> = l_shape.iter().rev().copied().collect();
    for pts in [l_shape.to_vec(), reversed] {
        let cam = unit_camera(12, 12);
        let got = rasterize(&single(polygons(&[&pts])), &cam).unwrap();
        assert_close(
            &got,
            &exact_image(12, 12, &[to_image(&cam, &pts)]),
            EXACT,
            "L shape",
        );
    }
}

#[test]
fn overlapping_same_direction_squares_are_a_union() {
    // Nonzero: the overlap has winding 2 and counts once. Signed-area accumulation would
    // count it twice.
    let a = rect(1.25, 1.5, 8.5, 7.75);
    let b = rect(4.5, 3.25, 11.75, 10.5);
    let cam = unit_camera(13, 12);
    let got = rasterize(&single(polygons(&[&a, &b])), &cam).unwrap();
    // Union = A + (B minus A), the latter as two disjoint rectangles.
    let b_right = rect(8.5, 3.25, 11.75, 10.5);
    let b_top = rect(4.5, 7.75, 8.5, 10.5);
    let want = exact_image(
        13,
        12,
        &[
            to_image(&cam, &a),
            to_image(&cam, &b_right),
            to_image(&cam, &b_top),
        ],
    );
    assert_close(&got, &want, EXACT, "overlapping squares");
    assert!(got.data.iter().all(|&v| v <= 1.0));
}

#[test]
fn figure_eight_covers_both_lobes() {
    // A bowtie: its lobes wind +1 and −1, both nonzero.
    let bowtie = [(1.0, 1.0), (11.0, 9.0), (11.0, 1.0), (1.0, 9.0)];
    let cam = unit_camera(12, 10);
    let got = rasterize(&single(polygons(&[&bowtie])), &cam).unwrap();
    let centre = (6.0, 5.0);
    let lobes = [
        vec![(1.0, 1.0), centre, (1.0, 9.0)],
        vec![(11.0, 1.0), (11.0, 9.0), centre],
    ];
    let want = exact_image(
        12,
        10,
        &[to_image(&cam, &lobes[0]), to_image(&cam, &lobes[1])],
    );
    assert_close(&got, &want, EXACT, "figure eight");
}

#[test]
fn pentagram_centre_is_filled_under_nonzero() {
    let star: Vec<(f64, f64)> = (0..5)
        .map(|k| {
            let a = std::f64::consts::FRAC_PI_2 + f64::from(k * 2) * std::f64::consts::TAU / 5.0;
            (10.3 + 9.0 * a.cos(), 10.1 + 9.0 * a.sin())
        })
        .collect();
    let cam = unit_camera(21, 21);
    let got = rasterize(&single(polygons(&[&star])), &cam).unwrap();
    // The same star as a simple 10-gon: outer points alternating with the inner
    // pentagon's corners (where the lines cross).
    // The inner pentagon's corners, where the star's lines cross, lie at R·cos72°/cos36°.
    let inner_radius = 9.0 * 72f64.to_radians().cos() / 36f64.to_radians().cos();
    let outline: Vec<(f64, f64)> = (0..10)
        .map(|k| {
            let a = std::f64::consts::FRAC_PI_2 + f64::from(k) * std::f64::consts::TAU / 10.0;
            let r = if k % 2 == 0 { 9.0 } else { inner_radius };
            (10.3 + r * a.cos(), 10.1 + r * a.sin())
        })
        .collect();
    let want = exact_image(21, 21, &[to_image(&cam, &outline)]);
    assert_close(&got, &want, 1e-7, "pentagram");
}

/// An independent rasterizer: nonzero point sampling on an n×n grid per pixel, by
/// scanlines through the sample rows (crossings sorted, winding swept). Shares nothing
/// with the reference but flattening, which it does 16x finer.
fn supersample(scene: &Scene, cam: &Camera, n: usize) -> CoverageImage {
    #[allow(non_snake_case)]
    let N = n;
    let mut edges: Vec<(DVec2, DVec2)> = Vec::new();
    for inst in &scene.instances {
        let m: DMat3 = cam.glyph_to_image(scene.units_per_em, inst.position);
        for seg in scene.glyphs[inst.glyph as usize].outline.segments() {
            let mut prev = project(&m, seg.start());
            seg.flatten(1e-3 / cam.scale(scene.units_per_em) / 16.0, &mut |p| {
                let p = project(&m, p);
                edges.push((prev, p));
                prev = p;
            });
        }
    }
    let (w, h) = (cam.width as usize, cam.height as usize);
    let mut counts = vec![0u32; w * h];
    let mut crossings: Vec<(f64, i32)> = Vec::new();
    for row in 0..h * N {
        let y = (row as f64 + 0.5) / N as f64;
        crossings.clear();
        for &(a, b) in &edges {
            // Half-open in y so a vertex on the line counts once.
            if (a.y <= y) != (b.y <= y) {
                let x = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
                crossings.push((x, if b.y > a.y { 1 } else { -1 }));
            }
        }
        crossings.sort_by(|p, q| p.0.total_cmp(&q.0));
        let (mut k, mut winding) = (0, 0);
        for col in 0..w * N {
            let x = (col as f64 + 0.5) / N as f64;
            while k < crossings.len() && crossings[k].0 < x {
                winding += crossings[k].1;
                k += 1;
            }
            if winding != 0 {
                counts[(row / N) * w + col / N] += 1;
            }
        }
    }
    CoverageImage {
        width: cam.width,
        height: cam.height,
        data: counts.iter().map(|&c| c as f32 / (N * N) as f32).collect(),
    }
}

#[test]
fn converges_with_supersampling_on_real_glyphs() {
    let (s30, c30) = 30f64.to_radians().sin_cos();
    let matrices = [
        [1.0, 0.0, 0.0, 1.0],
        [c30, -s30, s30, c30],
        [1.0, 0.35, 0.0, 1.0],
    ];
    let mut worst_mean: f64 = 0.0;
    for (font_index, text) in [
        (0, "g&@"),
        (1, "Qa§"),
        (2, "Bé4"),
        (3, "\u{0995}\u{09CD}\u{09B7}"),
    ] {
        let font = glyphscope::font::shipped(font_index);
        let scene = Scene::from_text(&font, text).unwrap();
        for (k, size) in [6.0, 17.0, 48.0, 130.0].into_iter().enumerate() {
            let matrix = matrices[k % matrices.len()];
            let cam = framed(&scene, size, matrix, DVec2::new(0.37, 0.61));
            let got = rasterize(&scene, &cam).unwrap();
            let what = format!("{} {text:?} at {size} px/em", SHIPPED_FONTS[font_index].0);
            // n×n samples quantize an edge's position to 1/n px: up to 1/(2n) of a
            // pixel's area per edge through it (two edges share a pixel at 6 px/em),
            // less on average, and the difference
            // must shrink as n grows (`cargo test --release --test reference converges --
            // --nocapture` prints it).
            for (n, mean_bound, max_bound) in [(16, 1.0, 0.04), (64, 0.3, 2.0 / 128.0)] {
                let s = compare(&got, &supersample(&scene, &cam, n)).unwrap();
                assert!(
                    s.mae_255 < mean_bound,
                    "{what}, {n}x{n}: mean {} /255",
                    s.mae_255
                );
                assert!(
                    s.max < max_bound,
                    "{what}, {n}x{n}: max {} at {:?}",
                    s.max,
                    s.worst_pixel
                );
                if n == 16 {
                    worst_mean = worst_mean.max(s.mae_255);
                }
            }
        }
    }
    println!("worst mean difference from 256-sample supersampling: {worst_mean:.3}/255");
}

#[test]
fn flattening_error_is_below_a_1024th() {
    // Tightening the tolerance 16x barely moves anything: the default is converged.
    let scene = Scene::from_text(&glyphscope::font::shipped(1), "Sog").unwrap();
    for size in [3.0, 40.0, 700.0] {
        let cam = framed(&scene, size, [1.0, 0.2, -0.1, 1.0], DVec2::new(0.3, 0.8));
        let fine = rasterize_with_tolerance(&scene, &cam, 1.0 / 262144.0).unwrap();
        let default = rasterize(&scene, &cam).unwrap();
        let s = compare(&default, &fine).unwrap();
        assert!(s.max < 1.0 / 1024.0, "{size} px/em: {}", s.max);
    }
}

#[test]
fn world_offset_changes_nothing() {
    let scene = Scene::from_text(&glyphscope::font::default_font(), "Ag").unwrap();
    let mut cam = framed(&scene, 37.0, [0.9, 0.3, -0.2, 1.1], DVec2::new(0.25, 0.5));
    let near = rasterize(&scene, &cam).unwrap();
    for offset in [1.0e5, 1.0e6] {
        cam.world_offset = DVec2::new(offset, -offset);
        let far = rasterize(&scene, &cam).unwrap();
        assert!(compare(&far, &near).unwrap().max < 1e-6, "offset {offset}");
    }
}

#[test]
fn perspective_tilt_matches_supersampling() {
    let scene = Scene::from_text(&glyphscope::font::default_font(), "Tilt").unwrap();
    let mut cam = framed(&scene, 40.0, [1.0, 0.0, 0.0, 1.0], DVec2::ZERO);
    cam.tilt_deg = 35.0;
    let got = rasterize(&scene, &cam).unwrap();
    let s = compare(&got, &supersample(&scene, &cam, 64)).unwrap();
    assert!(s.mae_255 < 0.3 && s.max < 0.012, "{s:?}");
}

#[test]
fn view_on_the_edge_of_a_huge_glyph() {
    // 20 000 px/em with a 64×64 view on the bowl of an 'o': only curves near the view
    // are flattened; those left of it become chords. Compare with supersampling of the
    // same view.
    let scene = Scene::from_glyph_id(
        &glyphscope::font::default_font(),
        glyphscope::font::default_font()
            .glyph_for_char('o')
            .unwrap()
            .into(),
    )
    .unwrap();
    let mut cam = Camera::new(64, 64, 20_000.0, DVec2::ZERO);
    let s = cam.scale(scene.units_per_em);
    let bounds = scene.glyphs[0].bounds;
    // Put the left edge of the bowl, at mid-height, in the middle of the view.
    cam.origin = DVec2::new(
        32.0 - bounds.min.x * s,
        32.0 + (bounds.min.y + bounds.max.y) * 0.5 * s,
    );
    let got = rasterize(&scene, &cam).unwrap();
    let covered = got.sum() / 4096.0;
    assert!(
        covered > 0.2 && covered < 0.8,
        "view not on the edge: {covered}"
    );
    let st = compare(&got, &supersample(&scene, &cam, 64)).unwrap();
    assert!(st.max < 0.012, "{st:?}");
}

#[test]
fn empty_outline_scene_renders_blank() {
    let scene = Scene::from_outlines(1000.0, vec![(Outline::default(), DVec2::ZERO)]);
    assert!(scene.instances.is_empty());
    assert_eq!(rasterize(&scene, &unit_camera(4, 4)).unwrap().sum(), 0.0);
}

/// Twice the signed area a segment sweeps about the origin, ∫ B × B′ dt (Green's
/// theorem), by 3-point Gauss–Legendre quadrature: B × B′ is a polynomial of degree 1,
/// 3 or 5 for a line, quadratic or cubic, which 3 points integrate exactly. Written from
/// the Bézier forms here, independently of the crate's flattening and rasterizer.
fn swept_area_x2(points: &[DVec2]) -> f64 {
    let bezier = |t: f64| -> (DVec2, DVec2) {
        match *points {
            [a, b] => (a + (b - a) * t, b - a),
            [a, b, c] => {
                let s = 1.0 - t;
                (
                    a * s * s + b * 2.0 * s * t + c * t * t,
                    (b - a) * 2.0 * s + (c - b) * 2.0 * t,
                )
            }
            [a, b, c, d] => {
                let s = 1.0 - t;
                (
                    a * s * s * s + b * 3.0 * s * s * t + c * 3.0 * s * t * t + d * t * t * t,
                    (b - a) * 3.0 * s * s + (c - b) * 6.0 * s * t + (d - c) * 3.0 * t * t,
                )
            }
            _ => unreachable!("a segment has 2 to 4 points"),
        }
    };
    let half = (0.6f64).sqrt() / 2.0;
    [
        (0.5 - half, 5.0 / 18.0),
        (0.5, 8.0 / 18.0),
        (0.5 + half, 5.0 / 18.0),
    ]
    .iter()
    .map(|&(t, w)| {
        let (p, d) = bezier(t);
        w * p.perp_dot(d)
    })
    .sum()
}

/// Independently of any sampler: the reference's total coverage is the outline's exact
/// area, from Green's theorem on its lines, quadratics and cubics (DejaVu's quadratics
/// and Latin Modern's cubics, glyphs without overlaps), to within what its flattening
/// is documented to move — at most the tolerance times the outline's length, which the
/// control polygon bounds — plus f32 storage's rounding of each pixel.
#[test]
fn covered_area_is_the_exact_outline_area() {
    use glyphscope::geometry::Segment;
    use glyphscope::reference::DEFAULT_TOLERANCE_PX;
    for (font, text) in [
        (glyphscope::font::default_font(), "g&@S"),
        (glyphscope::font::shipped(1), "Qa§g"),
    ] {
        let scene = Scene::from_text(&font, text).unwrap();
        let size = 40.0;
        let camera = Camera::new(220, 80, size, DVec2::new(10.0, 60.0));
        let px_per_unit = size / scene.units_per_em;
        let (mut area_px, mut length_px) = (0.0, 0.0);
        for instance in &scene.instances {
            let outline = &scene.glyphs[instance.glyph as usize].outline;
            for segment in outline.segments() {
                let points = match *segment {
                    Segment::Line(a, b) => vec![a, b],
                    Segment::Quad(a, b, c) => vec![a, b, c],
                    Segment::Cubic(a, b, c, d) => vec![a, b, c, d],
                };
                area_px += swept_area_x2(&points) / 2.0 * px_per_unit * px_per_unit;
                length_px +=
                    points.windows(2).map(|w| w[0].distance(w[1])).sum::<f64>() * px_per_unit;
            }
        }
        // TrueType winds outer contours clockwise, CFF counter-clockwise: without
        // overlaps the filled area is the signed sum's magnitude either way.
        let area_px = area_px.abs();
        let image = rasterize(&scene, &camera).unwrap();
        let (w, h) = (camera.width as usize, camera.height as usize);
        let border =
            (0..w * h).filter(|&k| k % w == 0 || k % w == w - 1 || k < w || k >= w * (h - 1));
        assert!(
            border.map(|k| image.data[k]).all(|v| v == 0.0),
            "{text}: ink clipped"
        );
        let covered: f64 = image.data.iter().map(|&v| f64::from(v)).sum();
        let bound =
            DEFAULT_TOLERANCE_PX * length_px + image.data.len() as f64 * f64::from(f32::EPSILON);
        println!(
            "{text}: area {area_px:.4} px², covered {covered:.4}, off {:.2e} (bound {bound:.2e}, relative {:.1e})",
            (covered - area_px).abs(),
            (covered - area_px).abs() / area_px
        );
        assert!(
            area_px > 500.0,
            "{text}: {area_px} px²: the glyphs are in view"
        );
        assert!(
            (covered - area_px).abs() <= bound,
            "{text}: covered {covered}, area {area_px}, bound {bound}"
        );
    }
}
