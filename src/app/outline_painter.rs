//! The outline overlay painted with egui over any method: the curves, their on-curve
//! points filled and control points hollow on their handles (traced by
//! [`crate::outline_overlay`]).

use eframe::egui;
use glam::DVec2;

use crate::camera::Camera;
use crate::geometry::Rect;
use crate::outline_overlay;
use crate::scene::Scene;

/// Flattening tolerance, image pixels.
const TOLERANCE_PX: f64 = 0.2;

const OUTLINE: egui::Color32 = egui::Color32::from_rgb(255, 170, 0);
const HANDLE: egui::Color32 = egui::Color32::from_rgb(120, 170, 255);
/// The merged outline: wide and green under the font's, so that a curve the union
/// dropped (one inside the fill) shows orange alone.
const MERGED: egui::Color32 = egui::Color32::from_rgb(60, 220, 90);

/// How an outline is drawn.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// The font's outline: curves, on-curve points filled, control points on handles.
    Font,
    /// A merged outline: its curves alone, wide.
    Merged,
}

/// Draws the outline of the instances in view, each image pixel `block` framebuffer
/// pixels a side (the magnifier); returns how many glyphs were in view, or an error
/// message when there were too many to draw.
pub fn paint(
    painter: &egui::Painter,
    scene: &Scene,
    camera: &Camera,
    pixels_per_point: f32,
    block: u32,
    style: Style,
) -> Result<usize, String> {
    let view = Rect {
        min: DVec2::ZERO,
        max: DVec2::new(f64::from(camera.width), f64::from(camera.height)),
    };
    let block = f64::from(block);
    let drawing = outline_overlay::trace(scene, camera, &view, TOLERANCE_PX / block, block)?;
    let origin = painter.clip_rect().min;
    let scale = block as f32 / pixels_per_point;
    let to_screen = |p: DVec2| origin + egui::vec2(p.x as f32, p.y as f32) * scale;
    let line = match style {
        Style::Font => egui::Stroke::new(1.0, OUTLINE),
        Style::Merged => egui::Stroke::new(4.0, MERGED),
    };
    for [a, b] in &drawing.lines {
        painter.line_segment([to_screen(*a), to_screen(*b)], line);
    }
    if style == Style::Merged {
        return Ok(drawing.glyphs);
    }
    let handle = egui::Stroke::new(0.5, HANDLE);
    for [a, b] in &drawing.handles {
        painter.line_segment([to_screen(*a), to_screen(*b)], handle);
    }
    for p in &drawing.on_curve {
        painter.circle_filled(to_screen(*p), 2.5, OUTLINE);
    }
    for p in &drawing.off_curve {
        painter.circle_stroke(to_screen(*p), 2.5, egui::Stroke::new(1.0, HANDLE));
    }
    Ok(drawing.glyphs)
}
