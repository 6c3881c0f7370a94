//! The outline overlay: the font's own contours, exactly as the scene holds them, seen
//! through the pane's camera, with on-curve points filled and off-curve (control) points
//! hollow on their handles. Drawn with egui shapes over any method.

use eframe::egui;
use glam::{DMat3, DVec2};

use crate::camera::Camera;
use crate::geometry::{Rect, Segment, project, segment_points};
use crate::scene::Scene;

/// More glyphs than this in view and the outlines would be a grey wash (and slow).
pub const MAX_OUTLINED_GLYPHS: usize = 400;
/// Points are drawn once a glyph is at least this many pixels across.
const POINTS_FROM_PX: f64 = 40.0;
/// Flattening tolerance, pixels.
const TOLERANCE_PX: f64 = 0.2;

const OUTLINE: egui::Color32 = egui::Color32::from_rgb(255, 170, 0);
const HANDLE: egui::Color32 = egui::Color32::from_rgb(120, 170, 255);

/// Draws the outline of the instances in view; returns how many glyphs were in view, or
/// an error message when there were too many to draw.
pub fn paint(
    painter: &egui::Painter,
    scene: &Scene,
    camera: &Camera,
    pixels_per_point: f32,
) -> Result<usize, String> {
    let view = Rect {
        min: DVec2::ZERO,
        max: DVec2::new(f64::from(camera.width), f64::from(camera.height)),
    };
    let mut visible = Vec::new();
    for instance in &scene.instances {
        let to_image = camera.glyph_to_image(scene.units_per_em, instance.position);
        let glyph = &scene.glyphs[instance.glyph as usize];
        let bounds = Camera::project_bounds(&to_image, &glyph.bounds).map_err(|e| e.to_string())?;
        if bounds.overlaps(&view) {
            visible.push((to_image, instance.glyph as usize, bounds));
        }
    }
    if visible.len() > MAX_OUTLINED_GLYPHS {
        return Err(format!(
            "outline: {} glyphs in view, zoom in to under {MAX_OUTLINED_GLYPHS}",
            visible.len()
        ));
    }
    let origin = painter.clip_rect().min;
    let to_screen = |p: DVec2| origin + egui::vec2(p.x as f32, p.y as f32) / pixels_per_point;
    // Lines are clipped in f64 to a little more than the view, so that at 100 000 px/em
    // nothing far off-screen reaches egui's f32 tessellator.
    let clip = Rect {
        min: view.min - 4.0,
        max: view.max + 4.0,
    };
    let line = egui::Stroke::new(1.0, OUTLINE);
    let handle = egui::Stroke::new(1.0, HANDLE);
    for (to_image, glyph, bounds) in &visible {
        let outline = &scene.glyphs[*glyph].outline;
        let tolerance = local_tolerance(to_image, &scene.glyphs[*glyph].bounds);
        let with_points = bounds.size().max_element() >= POINTS_FROM_PX;
        for segment in outline.segments() {
            let hull = Rect::enclosing(segment_points(segment).map(|p| project(to_image, p)))
                .expect("a segment has points");
            if !hull.overlaps(&clip) {
                continue;
            }
            let mut previous = project(to_image, segment.start());
            segment.flatten(tolerance, &mut |p| {
                let p = project(to_image, p);
                if let Some((a, b)) = clip_line(previous, p, &clip) {
                    painter.line_segment([to_screen(a), to_screen(b)], line);
                }
                previous = p;
            });
            if with_points {
                paint_points(painter, segment, to_image, &clip, &to_screen, handle);
            }
        }
    }
    Ok(visible.len())
}

fn paint_points(
    painter: &egui::Painter,
    segment: &Segment,
    to_image: &DMat3,
    clip: &Rect,
    to_screen: &impl Fn(DVec2) -> egui::Pos2,
    handle: egui::Stroke,
) {
    let start = project(to_image, segment.start());
    let end = project(to_image, segment.end());
    let controls: Vec<DVec2> = match segment {
        Segment::Line(..) => Vec::new(),
        Segment::Quad(_, c, _) => vec![project(to_image, *c)],
        Segment::Cubic(_, c1, c2, _) => vec![project(to_image, *c1), project(to_image, *c2)],
    };
    // Handles run from each end to its neighbouring control point.
    let mut handles = Vec::new();
    if let (Some(first), Some(last)) = (controls.first(), controls.last()) {
        handles.push((start, *first));
        handles.push((*last, end));
        if controls.len() == 2 {
            handles.push((controls[0], controls[1]));
        }
    }
    for (a, b) in handles {
        if let Some((a, b)) = clip_line(a, b, clip) {
            painter.line_segment(
                [to_screen(a), to_screen(b)],
                egui::Stroke::new(0.5, handle.color),
            );
        }
    }
    let inside = |p: DVec2| p.cmpge(clip.min).all() && p.cmple(clip.max).all();
    if inside(start) {
        painter.circle_filled(to_screen(start), 2.5, OUTLINE);
    }
    for c in controls.into_iter().filter(|&c| inside(c)) {
        painter.circle_stroke(to_screen(c), 2.5, handle);
    }
}

/// Font units per pixel of `to_image` over `bounds`, times the tolerance: the smallest
/// scale anywhere over the glyph, so no part is flattened coarser than the tolerance.
fn local_tolerance(to_image: &DMat3, bounds: &Rect) -> f64 {
    let corners = bounds.corners().map(|c| project(to_image, c));
    let local = bounds.size().max(DVec2::splat(1e-9));
    let image = Rect::enclosing(corners).expect("four corners").size();
    let scale = (image / local).max_element().max(1e-12);
    TOLERANCE_PX / scale
}

/// The part of segment a–b inside `rect` (Liang–Barsky), if any.
fn clip_line(a: DVec2, b: DVec2, rect: &Rect) -> Option<(DVec2, DVec2)> {
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
    (t0 <= t1).then(|| (a + d * t0, a + d * t1))
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
        let (a, b) = clip_line(DVec2::new(-1e7, 5.0), DVec2::new(1e7, 5.0), &rect).unwrap();
        assert!((a - DVec2::new(0.0, 5.0)).length() < 1e-6);
        assert!((b - DVec2::new(10.0, 5.0)).length() < 1e-6);
        assert!(clip_line(DVec2::new(-5.0, -5.0), DVec2::new(-1.0, 20.0), &rect).is_none());
        let inside = clip_line(DVec2::new(1.0, 2.0), DVec2::new(3.0, 4.0), &rect).unwrap();
        assert_eq!(inside, (DVec2::new(1.0, 2.0), DVec2::new(3.0, 4.0)));
    }
}
