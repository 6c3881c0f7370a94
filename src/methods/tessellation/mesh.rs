//! A glyph's polylines as triangles: lyon's sweep-line fill tessellator under the
//! nonzero rule, fed the polylines as they are (only lines, so lyon flattens nothing),
//! with intersections handled, so overlapping and self-intersecting contours fill as
//! the font means them. Also the triangle edges for the wireframe overlay and the
//! polyline points for the points overlay.

use std::collections::HashSet;

use glam::DVec2;
use lyon_tessellation::math::point;
use lyon_tessellation::{
    BuffersBuilder, FillOptions, FillTessellator, FillVertex, Orientation, TessellationError,
    VertexBuffers,
};

use super::subdivision::Polylines;

/// A polyline point as `tessellation.wgsl` reads it (`Marker`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Marker {
    pub position: [f32; 2],
    /// A [`PointKind`](super::subdivision::PointKind).
    pub kind: u32,
    _pad: u32,
}

/// One glyph's mesh, in its font units.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GlyphMesh {
    pub vertices: Vec<[f32; 2]>,
    /// Three vertex indices per triangle.
    pub triangles: Vec<u32>,
    /// Two vertex indices per distinct triangle edge.
    pub edges: Vec<u32>,
    pub markers: Vec<Marker>,
}

impl GlyphMesh {
    /// Triangulates `polylines`. lyon merges vertices closer than half of `snap` (outline
    /// units): pass a distance small against a pixel.
    ///
    /// lyon's sweep runs along y; where several vertices of a concave notch share their
    /// heights, it has been seen to join them across the notch — DejaVu Sans's 𐌔
    /// (U+10314): the zigzag's vertices pair up at y = 400, 750 and 1100, and the vertical
    /// sweep fills the triangle (404, 400), (500, 750), (404, 1100), outside the outline.
    /// So each mesh is checked: every triangle of some area must lie where the polylines'
    /// winding is nonzero. One that fails is made again with the sweep along x, and that
    /// one is kept if it passes (else the first, which the error figures then report).
    pub fn tessellate(polylines: &Polylines, snap: f32) -> Result<GlyphMesh, TessellationError> {
        let along_y = GlyphMesh::swept(polylines, snap, Orientation::Vertical)?;
        if along_y.fills_only_inside(polylines) {
            return Ok(along_y);
        }
        let along_x = GlyphMesh::swept(polylines, snap, Orientation::Horizontal)?;
        Ok(if along_x.fills_only_inside(polylines) {
            along_x
        } else {
            along_y
        })
    }

    /// Whether every triangle whose area is not negligible has its centre where the
    /// polylines' nonzero winding is (in f64, from the polylines themselves).
    pub fn fills_only_inside(&self, polylines: &Polylines) -> bool {
        let vertex = |i: u32| {
            let [x, y] = self.vertices[i as usize];
            DVec2::new(f64::from(x), f64::from(y))
        };
        let scale = polylines
            .contours
            .iter()
            .flatten()
            .fold(0.0f64, |m, (p, _)| m.max(p.abs().max_element()))
            .max(1.0);
        self.triangles.chunks_exact(3).all(|t| {
            let (a, b, c) = (vertex(t[0]), vertex(t[1]), vertex(t[2]));
            let area = 0.5 * (b - a).perp_dot(c - a).abs();
            // Slivers along an edge carry no coverage, and their centre may round
            // either way.
            area <= 1e-6 * scale * scale || winding(polylines, (a + b + c) / 3.0) != 0
        })
    }

    fn swept(
        polylines: &Polylines,
        snap: f32,
        orientation: Orientation,
    ) -> Result<GlyphMesh, TessellationError> {
        let mut buffers: VertexBuffers<[f32; 2], u32> = VertexBuffers::new();
        let mut output = BuffersBuilder::new(&mut buffers, |v: FillVertex| v.position().to_array());
        let options = FillOptions::non_zero()
            .with_tolerance(snap)
            .with_sweep_orientation(orientation);
        let mut tessellator = FillTessellator::new();
        let mut path = tessellator.builder(&options, &mut output);
        let as_point = |p: glam::DVec2| point(p.x as f32, p.y as f32);
        for contour in polylines.contours.iter().filter(|c| c.len() > 2) {
            path.begin(as_point(contour[0].0));
            for &(p, _) in &contour[1..] {
                path.line_to(as_point(p));
            }
            path.end(true);
        }
        path.build()?;

        let mut seen = HashSet::new();
        let mut edges = Vec::new();
        for t in buffers.indices.chunks_exact(3) {
            for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
                if seen.insert((a.min(b), a.max(b))) {
                    edges.extend([a, b]);
                }
            }
        }
        let markers = polylines
            .contours
            .iter()
            .flatten()
            .map(|&(p, kind)| Marker {
                position: p.as_vec2().to_array(),
                kind: kind as u32,
                _pad: 0,
            })
            .collect();
        Ok(GlyphMesh {
            vertices: buffers.vertices,
            triangles: buffers.indices,
            edges,
            markers,
        })
    }

    pub fn triangle_count(&self) -> usize {
        self.triangles.len() / 3
    }

    /// Total area of the triangles, outline units squared.
    pub fn area(&self) -> f64 {
        self.triangles
            .chunks_exact(3)
            .map(|t| {
                let [a, b, c] = [t[0], t[1], t[2]]
                    .map(|i| glam::DVec2::from_array(self.vertices[i as usize].map(f64::from)));
                (b - a).perp_dot(c - a).abs() / 2.0
            })
            .sum()
    }
}

/// The nonzero winding number of the closed polylines about `p` (crossings of the ray
/// along +x, each edge half-open in y so a vertex on the ray counts once).
pub fn winding(polylines: &Polylines, p: DVec2) -> i32 {
    let mut winding = 0;
    for contour in polylines.contours.iter().filter(|c| c.len() > 2) {
        for (k, &(a, _)) in contour.iter().enumerate() {
            let b = contour[(k + 1) % contour.len()].0;
            let side = (b - a).perp_dot(p - a);
            if a.y <= p.y && b.y > p.y && side > 0.0 {
                winding += 1;
            } else if b.y <= p.y && a.y > p.y && side < 0.0 {
                winding -= 1;
            }
        }
    }
    winding
}

#[cfg(test)]
mod tests {
    use glam::DVec2;

    use super::*;
    use crate::methods::tessellation::subdivision::PointKind;

    fn polygon(points: &[(f64, f64)]) -> Vec<(DVec2, PointKind)> {
        points
            .iter()
            .map(|&(x, y)| (DVec2::new(x, y), PointKind::On))
            .collect()
    }

    fn tessellate(contours: Vec<Vec<(DVec2, PointKind)>>) -> GlyphMesh {
        let polylines = Polylines {
            contours,
            area_error: None,
        };
        GlyphMesh::tessellate(&polylines, 1e-3).unwrap()
    }

    #[test]
    fn nonzero_fills_overlaps_and_self_intersections() {
        // Two squares wound the same way, overlapping by a quarter: even-odd would leave
        // the overlap empty (area 700), nonzero fills the union (area 700 + 100).
        let a = polygon(&[(0.0, 0.0), (20.0, 0.0), (20.0, 20.0), (0.0, 20.0)]);
        let b = polygon(&[(10.0, 10.0), (30.0, 10.0), (30.0, 30.0), (10.0, 30.0)]);
        assert!((tessellate(vec![a.clone(), b]).area() - 700.0).abs() < 1e-3);
        // A square with a hole wound the other way: the hole stays empty.
        let hole = polygon(&[(5.0, 5.0), (5.0, 15.0), (15.0, 15.0), (15.0, 5.0)]);
        assert!((tessellate(vec![a, hole]).area() - 300.0).abs() < 1e-3);
        // A pentagram drawn in one stroke: its centre has winding 2, so nonzero fills it.
        let star: Vec<(f64, f64)> = (0..5)
            .map(|k| {
                let angle =
                    std::f64::consts::FRAC_PI_2 + f64::from(k * 2) * std::f64::consts::TAU / 5.0;
                (100.0 * angle.cos(), 100.0 * angle.sin())
            })
            .collect();
        let mesh = tessellate(vec![polygon(&star)]);
        // The star's outline: ten vertices alternating between radius r and `inner`.
        let r = 100.0_f64;
        let inner =
            r * (2.0 * std::f64::consts::PI / 5.0).cos() / (std::f64::consts::PI / 5.0).cos();
        let star_area = 5.0 * r * inner * (std::f64::consts::PI / 5.0).sin();
        assert!(
            (mesh.area() - star_area).abs() < 1e-2 * star_area,
            "{} vs {star_area}",
            mesh.area()
        );
    }

    #[test]
    fn edges_are_listed_once() {
        let square = polygon(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]);
        let mesh = tessellate(vec![square]);
        assert_eq!(mesh.triangle_count(), 2);
        // Four sides and the diagonal.
        assert_eq!(mesh.edges.len(), 2 * 5);
        assert_eq!(mesh.markers.len(), 4);
    }
}
