//! The outline overlay's geometry: the font's own contours, exactly as the scene holds
//! them, seen through the camera, in image pixels. The app paints it with egui over a
//! pane, `render --overlay outline` into the magnified picture; both take it from here.

use glam::{DMat3, DVec2};

use crate::camera::Camera;
use crate::geometry::{Rect, Segment, project, segment_points};
use crate::scene::Scene;

/// More glyphs than this in view and the outlines would be a grey wash (and slow).
pub const MAX_OUTLINED_GLYPHS: usize = 400;
/// Points are drawn once a glyph is at least this many drawn pixels across.
const POINTS_FROM_PX: f64 = 40.0;

/// The outline of the glyphs in a window of the image, in image pixels (y down).
#[derive(Clone, Debug, Default)]
pub struct OutlineDrawing {
    /// The curves, flattened, as line pieces clipped to the window.
    pub lines: Vec<[DVec2; 2]>,
    /// From each curve's ends to its control points.
    pub handles: Vec<[DVec2; 2]>,
    /// On-curve points (drawn filled) and control points (drawn hollow) in the window.
    pub on_curve: Vec<DVec2>,
    pub off_curve: Vec<DVec2>,
    /// Glyph instances whose outline reaches the window.
    pub glyphs: usize,
}

/// Traces the outline of every instance reaching `window` (image pixels), flattened
/// within `tolerance_px` image pixels. `drawn_scale` is how many drawn pixels one image
/// pixel becomes (the magnification): points are given once a glyph is large enough on
/// the screen to tell them apart. Too many glyphs in the window is an error message.
pub fn trace(
    scene: &Scene,
    camera: &Camera,
    window: &Rect,
    tolerance_px: f64,
    drawn_scale: f64,
) -> Result<OutlineDrawing, String> {
    let mut visible = Vec::new();
    for instance in &scene.instances {
        let to_image = camera.glyph_to_image(scene.units_per_em, instance.position);
        let glyph = &scene.glyphs[instance.glyph as usize];
        let bounds = Camera::project_bounds(&to_image, &glyph.bounds).map_err(|e| e.to_string())?;
        if bounds.overlaps(window) {
            visible.push((to_image, instance.glyph as usize, bounds));
        }
    }
    if visible.len() > MAX_OUTLINED_GLYPHS {
        return Err(format!(
            "outline: {} glyphs in view, zoom in to under {MAX_OUTLINED_GLYPHS}",
            visible.len()
        ));
    }
    // Clipped in f64 to a little more than the window, so that at 100 000 px/em nothing
    // far off-screen reaches a painter's f32 arithmetic.
    let margin = 4.0 / drawn_scale.max(1.0);
    let clip = Rect {
        min: window.min - margin,
        max: window.max + margin,
    };
    let mut drawing = OutlineDrawing {
        glyphs: visible.len(),
        ..OutlineDrawing::default()
    };
    for (to_image, glyph, bounds) in &visible {
        let glyph_data = &scene.glyphs[*glyph];
        let tolerance = local_tolerance(to_image, &glyph_data.bounds, tolerance_px);
        let with_points = bounds.size().max_element() * drawn_scale >= POINTS_FROM_PX;
        for segment in glyph_data.outline.segments() {
            let hull = Rect::enclosing(segment_points(segment).map(|p| project(to_image, p)))
                .expect("a segment has points");
            if !hull.overlaps(&clip) {
                continue;
            }
            let mut previous = project(to_image, segment.start());
            segment.flatten(tolerance, &mut |p| {
                let p = project(to_image, p);
                if let Some(piece) = clip_line(previous, p, &clip) {
                    drawing.lines.push(piece);
                }
                previous = p;
            });
            if with_points {
                add_points(&mut drawing, segment, to_image, &clip);
            }
        }
    }
    Ok(drawing)
}

fn add_points(drawing: &mut OutlineDrawing, segment: &Segment, to_image: &DMat3, clip: &Rect) {
    let start = project(to_image, segment.start());
    let end = project(to_image, segment.end());
    let controls: Vec<DVec2> = match segment {
        Segment::Line(..) => Vec::new(),
        Segment::Quad(_, c, _) => vec![project(to_image, *c)],
        Segment::Cubic(_, c1, c2, _) => vec![project(to_image, *c1), project(to_image, *c2)],
    };
    // Handles run from each end to its neighbouring control point.
    if let (Some(first), Some(last)) = (controls.first(), controls.last()) {
        let mut handles = vec![(start, *first), (*last, end)];
        if controls.len() == 2 {
            handles.push((controls[0], controls[1]));
        }
        drawing.handles.extend(
            handles
                .into_iter()
                .filter_map(|(a, b)| clip_line(a, b, clip)),
        );
    }
    let inside = |p: &DVec2| p.cmpge(clip.min).all() && p.cmple(clip.max).all();
    if inside(&start) {
        drawing.on_curve.push(start);
    }
    drawing
        .off_curve
        .extend(controls.into_iter().filter(inside));
}

/// Font units per image pixel of `to_image` over `bounds`, times the tolerance: the
/// smallest scale anywhere over the glyph, so no part is flattened coarser than it.
fn local_tolerance(to_image: &DMat3, bounds: &Rect, tolerance_px: f64) -> f64 {
    let corners = bounds.corners().map(|c| project(to_image, c));
    let local = bounds.size().max(DVec2::splat(1e-9));
    let image = Rect::enclosing(corners).expect("four corners").size();
    let scale = (image / local).max_element().max(1e-12);
    tolerance_px / scale
}

/// The part of segment a–b inside `rect` (Liang–Barsky), if any.
fn clip_line(a: DVec2, b: DVec2, rect: &Rect) -> Option<[DVec2; 2]> {
    let d = b - a;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d.x, a.x - rect.min.x),
        (d.x, rect.max.x - a.x),
        (-d.y, a.y - rect.min.y),
        (d.y, rect.max.y - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    (t0 <= t1).then(|| [a + d * t0, a + d * t1])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clipping_keeps_the_part_inside() {
        let rect = Rect {
            min: DVec2::ZERO,
            max: DVec2::splat(10.0),
        };
        let [a, b] = clip_line(DVec2::new(-1e7, 5.0), DVec2::new(1e7, 5.0), &rect).unwrap();
        assert!((a - DVec2::new(0.0, 5.0)).length() < 1e-6);
        assert!((b - DVec2::new(10.0, 5.0)).length() < 1e-6);
        assert!(clip_line(DVec2::new(-5.0, -5.0), DVec2::new(-1.0, 20.0), &rect).is_none());
        let inside = clip_line(DVec2::new(1.0, 2.0), DVec2::new(3.0, 4.0), &rect).unwrap();
        assert_eq!(inside, [DVec2::new(1.0, 2.0), DVec2::new(3.0, 4.0)]);
    }
}
