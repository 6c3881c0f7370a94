//! Each glyph's triangles, built on the CPU — a fan from each contour's first point over
//! every segment's chord, and a Loop–Blinn triangle per quadratic — at a cubic →
//! quadratic tolerance chosen from the zoom, and their buffers on the GPU.

use std::ops::Range;

use glam::DVec2;

use crate::geometry::{DEFAULT_QUAD_TOLERANCE_EM, Outline, Segment};
use crate::gpu::GpuContext;
use crate::scene::Scene;

/// A glyph's triangles in font units.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Triangles {
    /// (contour's first point, segment start, segment end) for every segment.
    pub fan: Vec<[[f32; 2]; 3]>,
    /// (p0, p1, p2) of every quadratic, for the Loop–Blinn test.
    pub curves: Vec<[[f32; 2]; 3]>,
}

impl Triangles {
    /// The triangles of `outline` with its cubics replaced by quadratics within
    /// `tolerance` (font units). Triangles with two bit-identical corners cover no sample
    /// under any transform and are left out; every other one is kept, however thin, so
    /// that the ones left share their edges exactly.
    pub fn of(outline: &Outline, tolerance: f64) -> Triangles {
        let point = |p: DVec2| [p.x as f32, p.y as f32];
        let mut triangles = Triangles::default();
        let push = |list: &mut Vec<[[f32; 2]; 3]>, corners: [DVec2; 3]| {
            let [a, b, c] = corners.map(point);
            if a != b && b != c && c != a {
                list.push([a, b, c]);
            }
        };
        for contour in &outline.to_quadratics(tolerance).contours {
            let Some(anchor) = contour.segments.first().map(Segment::start) else {
                continue;
            };
            for segment in &contour.segments {
                push(&mut triangles.fan, [anchor, segment.start(), segment.end()]);
                if let Segment::Quad(p0, p1, p2) = *segment {
                    push(&mut triangles.curves, [p0, p1, p2]);
                }
            }
        }
        triangles
    }
}

/// How often to halve the cubic → quadratic tolerance for a view whose largest scale
/// is `px_per_em`: the project's default is 1/16 px at 4096 px/em, and halving it until
/// it is 1/16 px at this scale too keeps zooming in from showing the conversion (a
/// fixed tolerance would not, as jwmcglynn's Donner SVG renderer found before its change
/// "Keep cubic fills accurate at high zoom"). Eight halvings reach 10⁶ px/em, the largest
/// size; further, the tolerance would pass the f32 precision of the points.
pub fn tolerance_halvings(px_per_em: f64) -> u32 {
    (px_per_em / 4096.0).log2().ceil().clamp(0.0, 8.0) as u32
}

/// What `xor-stencil` uploads for a scene at one conversion tolerance: every distinct
/// glyph's triangles, as points, and its bounds.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GeometryData {
    /// Glyph bounds (min x, min y, max x, max y), font units.
    pub bounds: Vec<[f32; 4]>,
    /// Three points per fan triangle, then per Loop–Blinn triangle.
    pub fan_points: Vec<[f32; 2]>,
    pub curve_points: Vec<[f32; 2]>,
    /// Per distinct glyph, its points in `fan_points` and `curve_points`.
    pub fan_ranges: Vec<Range<u32>>,
    pub curve_ranges: Vec<Range<u32>>,
}

impl GeometryData {
    /// The triangles of every distinct glyph of `scene`, its cubics converted with the
    /// default tolerance halved `halvings` times (see [`tolerance_halvings`]).
    pub fn of_scene(scene: &Scene, halvings: u32) -> GeometryData {
        let tolerance =
            DEFAULT_QUAD_TOLERANCE_EM / f64::from(1u32 << halvings) * scene.units_per_em;
        let mut data = GeometryData::default();
        let append = |points: &mut Vec<[f32; 2]>, triangles: &[[[f32; 2]; 3]]| {
            let start = points.len() as u32;
            points.extend(triangles.iter().flatten());
            start..points.len() as u32
        };
        for glyph in &scene.glyphs {
            let triangles = Triangles::of(&glyph.outline, tolerance);
            data.fan_ranges
                .push(append(&mut data.fan_points, &triangles.fan));
            data.curve_ranges
                .push(append(&mut data.curve_points, &triangles.curves));
            let b = glyph.bounds;
            data.bounds
                .push([b.min.x, b.min.y, b.max.x, b.max.y].map(|v| v as f32));
        }
        data
    }
}

/// Every distinct glyph's triangles and bounds on the GPU, at one conversion tolerance.
pub(super) struct Geometry {
    /// Halvings of the default cubic → quadratic tolerance (see [`tolerance_halvings`]).
    pub(super) halvings: u32,
    /// Per distinct glyph, its points in the fan and curve buffers.
    pub(super) fan_ranges: Vec<Range<u32>>,
    pub(super) curve_ranges: Vec<Range<u32>>,
    /// Glyph bounds, fan points, curve points.
    pub(super) buffers: [wgpu::Buffer; 3],
}

impl Geometry {
    pub(super) fn new(gpu: &GpuContext, scene: &Scene, halvings: u32) -> Geometry {
        const STORAGE: wgpu::BufferUsages = wgpu::BufferUsages::STORAGE;
        let data = GeometryData::of_scene(scene, halvings);
        Geometry {
            halvings,
            buffers: [
                gpu.buffer_of("xor-stencil bounds", &data.bounds, STORAGE),
                gpu.buffer_of("xor-stencil fan", &data.fan_points, STORAGE),
                gpu.buffer_of("xor-stencil curves", &data.curve_points, STORAGE),
            ],
            fan_ranges: data.fan_ranges,
            curve_ranges: data.curve_ranges,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangles_count_one_fan_triangle_per_segment_off_the_anchor() {
        // A square with one curved side: 4 segments, of which 2 touch the anchor.
        let p = |x, y| DVec2::new(x, y);
        let outline = Outline {
            contours: vec![crate::geometry::Contour {
                segments: vec![
                    Segment::Line(p(0.0, 0.0), p(10.0, 0.0)),
                    Segment::Quad(p(10.0, 0.0), p(15.0, 5.0), p(10.0, 10.0)),
                    Segment::Line(p(10.0, 10.0), p(0.0, 10.0)),
                    Segment::Line(p(0.0, 10.0), p(0.0, 0.0)),
                ],
            }],
        };
        let t = Triangles::of(&outline, 0.01);
        assert_eq!(t.fan.len(), 2);
        assert_eq!(t.curves, vec![[[10.0, 0.0], [15.0, 5.0], [10.0, 10.0]]]);
    }
}
