//! Helpers shared by the integration tests: synthetic outlines and scenes laid out so
//! that one font unit is one pixel, cameras that frame a scene, the GPU.
#![allow(dead_code)] // each test binary uses its own subset

use std::sync::OnceLock;

use glam::DVec2;
use glyphscope::camera::Camera;
use glyphscope::geometry::{Contour, Outline, Segment};
use glyphscope::gpu::GpuContext;
use glyphscope::scene::Scene;

/// The GPU, opened once per test binary. Without an adapter the tests that need it fail
/// with the message that says how to get one (CI installs lavapipe) rather than skip
/// and pass silently.
pub fn gpu() -> &'static GpuContext {
    static GPU: OnceLock<GpuContext> = OnceLock::new();
    GPU.get_or_init(|| GpuContext::new().unwrap_or_else(|e| panic!("{e}")))
}

/// A closed polygon contour through `points` (font units, y up).
pub fn polygon(points: &[(f64, f64)]) -> Contour {
    let p: Vec<DVec2> = points.iter().map(|&(x, y)| DVec2::new(x, y)).collect();
    Contour {
        segments: (0..p.len())
            .map(|i| Segment::Line(p[i], p[(i + 1) % p.len()]))
            .collect(),
    }
}

/// An outline of several polygons.
pub fn polygons(contours: &[&[(f64, f64)]]) -> Outline {
    Outline {
        contours: contours.iter().map(|c| polygon(c)).collect(),
    }
}

/// An axis-aligned rectangle, counter-clockwise in y-up coordinates.
pub fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<(f64, f64)> {
    vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
}

/// A scene holding `outline` once at the origin, where 1 font unit = 1 px.
pub fn single(outline: Outline) -> Scene {
    Scene::from_outlines(1000.0, vec![(outline, DVec2::ZERO)])
}

/// A camera with 1 px per font unit whose baseline origin is at the image's bottom-left
/// corner, so font (x, y) lands at image (x, height − y).
pub fn unit_camera(width: u32, height: u32) -> Camera {
    Camera::new(width, height, 1000.0, DVec2::new(0.0, f64::from(height)))
}

/// A camera that frames `scene` with a margin, at `size`, under `matrix` (rows a, b, c,
/// d), shifted by `subpixel`.
pub fn framed(scene: &Scene, size: f64, matrix: [f64; 4], subpixel: DVec2) -> Camera {
    let mut cam = Camera::new(1, 1, size, DVec2::ZERO);
    cam.matrix = Camera::matrix_from_rows(matrix[0], matrix[1], matrix[2], matrix[3]);
    let mut lo = DVec2::splat(f64::INFINITY);
    let mut hi = DVec2::splat(f64::NEG_INFINITY);
    for inst in &scene.instances {
        let m = cam.glyph_to_image(scene.units_per_em, inst.position);
        let b = Camera::project_bounds(&m, &scene.glyphs[inst.glyph as usize].bounds).unwrap();
        lo = lo.min(b.min);
        hi = hi.max(b.max);
    }
    cam.origin = DVec2::splat(2.0) - lo + subpixel;
    let extent = hi - lo + 5.0;
    cam.width = extent.x.ceil() as u32;
    cam.height = extent.y.ceil() as u32;
    cam
}
