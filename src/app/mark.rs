//! The mark: a frame drawn around the block of the pixel the view opened on — the worst
//! pixel a first start, a case, `W` or stepping went to, or the focus a link names —
//! in every pane, outside the block so that the pixel's own value shows whole. It stays
//! while the view it was made for is shown and goes once the camera, the scene or the
//! motion frame changes; a pane's method or overlay changing keeps it (the pixel is the
//! same pixel).

use eframe::egui;

use super::explorer::Explorer;
use super::state::Mark;
use crate::magnify::Window;

/// The frame's colour: orange, which reads on white and on black.
pub const MARK_COLOR: egui::Color32 = egui::Color32::from_rgb(255, 140, 0);
/// The thin dark edge on either side of it, which keeps it apart from orange-ish pixels.
pub const MARK_EDGE: egui::Color32 = egui::Color32::from_rgb(20, 20, 20);
/// The orange frame's width, screen pixels; the dark edge is one pixel each side of it.
const MARK_WIDTH: f32 = 2.0;

impl Explorer {
    /// Marks ×1 pane pixel `pixel` for the view the settings show now.
    pub(super) fn mark_pixel(&mut self, pixel: (u32, u32)) {
        self.mark = Some(Mark {
            pixel,
            camera: self.settings.camera,
            scene: self.settings.scene.clone(),
            frame: self.playback.frame,
        });
    }

    /// The marked pixel (×1 pane pixels), while the view it was marked in is shown.
    pub fn marked_pixel(&self) -> Option<(u32, u32)> {
        self.mark
            .as_ref()
            .filter(|m| {
                m.camera == self.settings.camera
                    && m.scene == self.settings.scene
                    && m.frame == self.playback.frame
            })
            .map(|m| m.pixel)
    }

    /// Drops the mark once the view has moved on, so that coming back to the same
    /// camera does not bring it back; once a frame.
    pub(super) fn forget_the_mark_once_the_view_moves(&mut self) {
        if self.marked_pixel().is_none() {
            self.mark = None;
        }
    }

    /// The mark over the pane drawn at `rect` (points), whose pixels are `window`'s
    /// at `ppp` pixels per point, if the marked pixel is among them.
    pub(super) fn paint_mark(&self, painter: &egui::Painter, rect: egui::Rect, ppp: f32) {
        let (Some(pixel), Some(window)) = (self.marked_pixel(), self.canvas.window) else {
            return;
        };
        if let Some(block) = mark_block(rect, window, ppp, pixel) {
            let px = 1.0 / ppp;
            // The dark edge under the whole width, then the orange inside it: dark,
            // orange, dark, from the block's edge out.
            painter.rect_stroke(
                block,
                0.0,
                egui::Stroke::new(MARK_WIDTH * px + 2.0 * px, MARK_EDGE),
                egui::StrokeKind::Outside,
            );
            painter.rect_stroke(
                block.expand(px),
                0.0,
                egui::Stroke::new(MARK_WIDTH * px, MARK_COLOR),
                egui::StrokeKind::Outside,
            );
        }
    }
}

/// Where ×1 pane pixel `pixel` is drawn in a pane at `rect` (points) showing `window`
/// at `ppp` pixels per point: its N×N block, or None when the window does not hold it.
pub fn mark_block(
    rect: egui::Rect,
    window: Window,
    ppp: f32,
    (x, y): (u32, u32),
) -> Option<egui::Rect> {
    let inside = (window.x0..window.x0 + window.cols).contains(&x)
        && (window.y0..window.y0 + window.rows).contains(&y);
    if !inside {
        return None;
    }
    let step = window.factor as f32 / ppp;
    Some(egui::Rect::from_min_size(
        rect.min + egui::vec2((x - window.x0) as f32, (y - window.y0) as f32) * step,
        egui::vec2(step, step),
    ))
}
