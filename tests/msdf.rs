//! Peer `msdf`: the distance-field atlas drawn with msdfgen's shader. Its drawn coverage
//! of a straight edge is held to a bound worked out by hand from the recipe before it
//! was measured, against the exact reference; the same check fails the coverage atlas
//! magnified, so it can fail; and overlapping contours kept show the failure msdfgen
//! documents, merged they do not.

mod common;

use common::{polygon, rect, render, single};
use glam::DVec2;
use glyphscope::camera::Camera;
use glyphscope::geometry::{Outline, project};
use glyphscope::methods::registry;
use glyphscope::reference;
use glyphscope::scene::Scene;

/// Field texels per em and range (texels) of the checks: msdf's defaults.
const EM_PX: f64 = 32.0;
const RANGE: f64 = 4.0;
/// Drawn at 64 px/em: 2 px per field texel, so a screen range of RANGE × 2 = 8 px.
const SIZE: f64 = 64.0;
const SCREEN_RANGE: f64 = RANGE * SIZE / EM_PX;

/// How far the drawn coverage of a straight edge, away from corners, may be from the
/// exact box filter, worked from the recipe before measuring. Coverage is
/// clamp(R (sd − 1/2) + 1/2) with R = SCREEN_RANGE, and a straight edge's distance is
/// linear across texels, so bilinear filtering adds nothing but:
/// - the byte each channel is stored in: sd off by up to 0.5/255;
/// - the filter's weights, which GPUs hold to 8 bits: up to half of 1/256 of the
///   difference between neighbouring texels, 1/RANGE;
///
/// Each times R, and 1/1000 for the half-float target. Along an axis the ramp one pixel
/// wide *is* the box filter; at θ to the axes it is not: with d the distance from the
/// pixel's centre to the edge, the box filter covers (1 + √2 d)²/2 at 45° where the
/// ramp gives d + 1/2, at most (√2 − 1)²/4 = 0.0429 apart (d = −(√2 − 1)/2).
fn edge_bound(ramp_vs_box: f64) -> f64 {
    SCREEN_RANGE * (0.5 / 255.0 + 0.5 / 256.0 / RANGE) + 1e-3 + ramp_vs_box
}

fn params(list: &[(&str, &str)]) -> Vec<(String, String)> {
    list.iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect()
}

/// A camera at SIZE turned by `degrees`, moved by `subpixel`, framing `scene`.
fn turned(scene: &Scene, degrees: f64, subpixel: DVec2) -> Camera {
    let (sin, cos) = degrees.to_radians().sin_cos();
    common::framed(scene, SIZE, [cos, -sin, sin, cos], subpixel)
}

/// The largest error of `name` (with `list`) against the reference over the pixels
/// whose centres lie within 1 px of the square's edges and at least `corner_px` from
/// its corners; and how many such pixels there are.
fn edge_error(
    name: &str,
    list: &[(&str, &str)],
    scene: &Scene,
    side: f64,
    camera: &Camera,
) -> (f64, usize) {
    let mut method = registry::create(name, &params(list)).unwrap();
    let image = render(method.as_mut(), scene, camera);
    let exact = reference::rasterize(scene, camera).unwrap();
    let to_image = camera.glyph_to_image(scene.units_per_em, DVec2::ZERO);
    let corners: Vec<DVec2> = [(0.0, 0.0), (side, 0.0), (side, side), (0.0, side)]
        .iter()
        .map(|&(x, y)| project(&to_image, DVec2::new(x, y)))
        .collect();
    let px_per_unit = SIZE / scene.units_per_em;
    let corner_px = (RANGE / 2.0 + 1.0) * SIZE / EM_PX + 2.0;
    let (mut worst, mut pixels) = (0.0f64, 0);
    for y in 0..camera.height {
        for x in 0..camera.width {
            let centre = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
            let near_corner = corners.iter().any(|c| c.distance(centre) < corner_px);
            // Distance to the nearest edge, a segment between two corners' images.
            let to_edge = (0..4)
                .map(|i| {
                    let (a, b) = (corners[i], corners[(i + 1) % 4]);
                    let t = ((centre - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
                    centre.distance(a + (b - a) * t)
                })
                .fold(f64::INFINITY, f64::min);
            if near_corner || to_edge > 1.0 {
                continue;
            }
            let error = f64::from(image.get(x, y)) - f64::from(exact.get(x, y));
            // NaN is never within a bound.
            worst = if error.is_nan() {
                f64::INFINITY
            } else {
                worst.max(error.abs())
            };
            pixels += 1;
        }
    }
    assert!(
        px_per_unit * side > 4.0 * corner_px,
        "the edges reach past their corners"
    );
    (worst, pixels)
}

#[test]
fn a_straight_edge_is_the_box_filter_within_the_ramps_worked_bound() {
    let side = 800.0;
    let scene = single(Outline {
        contours: vec![polygon(&rect(0.0, 0.0, side, side))],
    });
    let ramp_at_45 = (2f64.sqrt() - 1.0).powi(2) / 4.0;
    for (degrees, ramp_vs_box) in [(0.0, 0.0), (45.0, ramp_at_45)] {
        for subpixel in [DVec2::ZERO, DVec2::new(0.3, 0.7), DVec2::new(0.55, 0.15)] {
            let camera = turned(&scene, degrees, subpixel);
            let bound = edge_bound(ramp_vs_box);
            for field in ["msdf", "mtsdf", "sdf"] {
                let (worst, pixels) =
                    edge_error("msdf", &[("field", field)], &scene, side, &camera);
                assert!(pixels > 40, "{field} at {degrees}°: {pixels} edge pixels");
                assert!(
                    worst <= bound,
                    "{field} at {degrees}°, offset {subpixel}: {worst:.4} from the box \
                     filter, over the worked bound {bound:.4}"
                );
            }
            // The check can fail: a coverage atlas cached at the field's size and drawn
            // twice as large resamples its bitmap, and misses the same bound.
            let (worst, _) = edge_error(
                "atlas",
                &[("cache_px_per_em", "32"), ("subpixel", "off")],
                &scene,
                side,
                &camera,
            );
            assert!(
                worst > 2.0 * bound,
                "the atlas magnified at {degrees}°: {worst:.4}"
            );
        }
    }
}

/// Two squares wound the same way, overlapping: kept, each contour's edges inside the
/// other's square are still edges to the field, and the median dips there (msdfgen
/// issue 110); merged into their union first, they are gone.
#[test]
fn overlapping_contours_kept_break_the_field_and_merged_do_not() {
    let scene = single(Outline {
        contours: vec![
            polygon(&rect(0.0, 0.0, 300.0, 300.0)),
            polygon(&rect(150.0, 150.0, 450.0, 450.0)),
        ],
    });
    let camera = turned(&scene, 0.0, DVec2::new(0.25, 0.5));
    let exact = reference::rasterize(&scene, &camera).unwrap();
    let to_local = camera
        .glyph_to_image(scene.units_per_em, DVec2::ZERO)
        .inverse();
    // Pixels whose centres lie 20 units (1.3 px) or more inside either square: the
    // union's inside, the hidden edges across it included, where the exact coverage is 1.
    let deep = |p: DVec2, lo: f64, hi: f64| {
        p.cmpge(DVec2::splat(lo + 20.0)).all() && p.cmple(DVec2::splat(hi - 20.0)).all()
    };
    let worst_inside = |overlaps: &str| {
        let mut method = registry::create("msdf", &params(&[("overlaps", overlaps)])).unwrap();
        let image = render(method.as_mut(), &scene, &camera);
        let (mut worst, mut pixels) = (0.0f64, 0);
        for y in 0..camera.height {
            for x in 0..camera.width {
                let p = project(
                    &to_local,
                    DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5),
                );
                if !(deep(p, 0.0, 300.0) || deep(p, 150.0, 450.0)) {
                    continue;
                }
                assert_eq!(exact.get(x, y), 1.0);
                let error = (f64::from(image.get(x, y)) - 1.0).abs();
                worst = if error.is_nan() {
                    f64::INFINITY
                } else {
                    worst.max(error)
                };
                pixels += 1;
            }
        }
        assert!(pixels > 300, "{pixels} pixels inside");
        worst
    };
    let kept = worst_inside("keep");
    let merged = worst_inside("merge");
    assert!(kept > 0.25, "kept: the hidden edges show, off by {kept:.3}");
    assert!(merged <= 1e-3, "merged: off by {merged:.4} inside");
}
