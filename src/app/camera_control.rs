//! Steering the shared camera: drag to pan, wheel to zoom about the cursor, rotate, skew
//! and tilt about the view's centre, reset and fit. The render core's [`Camera`] is built
//! from [`CameraSettings`] for each pane's size.

use glam::{DMat2, DVec2};

use super::settings::{CameraSettings, CaseFrame, MIN_SIZE_PX_PER_EM};
use crate::camera::{Camera, Crop, MAX_SIZE_PX_PER_EM};
use crate::geometry::project;
use crate::magnify::{MAX_FACTOR, Window};
use crate::motion::MotionPath;
use crate::scene::Scene;

/// Space left around the text when the view is fitted to it, pixels.
const FIT_MARGIN_PX: f64 = 16.0;

impl CameraSettings {
    /// [a b; c d]: the skew, then the rotation.
    pub fn matrix(&self) -> DMat2 {
        let (sin, cos) = self.rotation_deg.to_radians().sin_cos();
        let rotation = Camera::matrix_from_rows(cos, -sin, sin, cos);
        rotation * Camera::matrix_from_rows(1.0, self.skew, 0.0, 1.0)
    }

    /// The camera for a pane of `width`×`height` pixels.
    pub fn camera(&self, width: u32, height: u32) -> Camera {
        let mut camera = Camera::new(
            width,
            height,
            self.size_px_per_em,
            DVec2::from_array(self.origin),
        );
        camera.matrix = self.matrix();
        camera.tilt_deg = self.tilt_deg;
        camera.world_offset = DVec2::from_array(self.world_offset);
        camera.crop = self.case_frame.map(|f| Crop {
            offset: DVec2::from_array(f.offset),
            frame_width: f.width,
            frame_height: f.height,
        });
        camera
    }

    /// The settings that show `frame` (a named view's camera) in a `width`×`height`
    /// pane, each pane pixel one of the frame's, the frame centred by whole pixels;
    /// None when its matrix is not a rotation after a skew (as every named view's is).
    pub fn of_frame(frame: &Camera, width: u32, height: u32) -> Option<CameraSettings> {
        // [a b; c d] = R(θ)·[1 k; 0 1]: the first column is R's, of length 1.
        let m = frame.matrix;
        let first = m.x_axis;
        let rotation_deg = first.y.atan2(first.x).to_degrees();
        let (sin, cos) = rotation_deg.to_radians().sin_cos();
        let unturned = Camera::matrix_from_rows(cos, sin, -sin, cos) * m.y_axis;
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * (1.0 + b.abs());
        if !close(first.length(), 1.0) || !close(unturned.y, 1.0) {
            return None;
        }
        let offset = ((DVec2::new(f64::from(frame.width), f64::from(frame.height))
            - DVec2::new(f64::from(width), f64::from(height)))
            / 2.0)
            .floor();
        let settings = CameraSettings {
            size_px_per_em: frame.size_px_per_em,
            origin: (frame.origin - offset).to_array(),
            rotation_deg,
            skew: unturned.x,
            tilt_deg: frame.tilt_deg,
            world_offset: frame.world_offset.to_array(),
            case_frame: Some(CaseFrame {
                width: frame.width,
                height: frame.height,
                offset: offset.to_array(),
            }),
            ..CameraSettings::default()
        };
        Some(settings)
    }

    /// The camera a pane of `width`×`height` pixels draws, and the window of its ×1
    /// pixels that is: at ×1 the pane's own; magnified ×N, the ⌈W/N⌉×⌈H/N⌉ pixels
    /// around the focus, which the pane shows as N×N blocks. Each drawn pixel is the one
    /// the ×1 pane shows there (under a tilt too): magnifying changes no value.
    pub fn pane_camera(&self, width: u32, height: u32) -> (Camera, Window) {
        self.pane_camera_moved(width, height, None)
    }

    /// [`CameraSettings::pane_camera`] at frame `n` of a motion path: the whole pane
    /// moves, then the magnifier's window is cut from it.
    pub fn pane_camera_moved(
        &self,
        width: u32,
        height: u32,
        motion: Option<(&MotionPath, i64)>,
    ) -> (Camera, Window) {
        let mut frame = self.camera(width, height);
        if let Some((path, n)) = motion {
            frame = path.camera_at(&frame, n);
        }
        let pixel = |v: f64, size: u32| v.floor().clamp(0.0, f64::from(size - 1)) as u32;
        let focus = (pixel(self.focus[0], width), pixel(self.focus[1], height));
        let window = Window::around(width, height, self.magnify, focus);
        if window.factor == 1 {
            return (frame, window);
        }
        let camera = frame.window(window.x0, window.y0, window.cols, window.rows);
        (camera, window)
    }

    /// Sets the magnification to `factor` keeping the ×1 pixel under `cursor` (pane
    /// pixels, as drawn) under it.
    pub fn magnify_about(&mut self, factor: u32, cursor: DVec2, width: u32, height: u32) {
        let (_, before) = self.pane_camera(width, height);
        let under = DVec2::new(f64::from(before.x0), f64::from(before.y0))
            + cursor / f64::from(before.factor);
        self.magnify = factor.clamp(1, MAX_FACTOR);
        let n = f64::from(self.magnify);
        let (cols, rows) = (
            f64::from(width.div_ceil(self.magnify)),
            f64::from(height.div_ceil(self.magnify)),
        );
        // Window::around starts the window half its size before the focus.
        let start = under - cursor / n;
        self.focus = [
            start.x + (cols / 2.0).floor() + 0.5,
            start.y + (rows / 2.0).floor() + 0.5,
        ];
    }

    /// Moves a named view's window so that its frame pixel `pixel` is in a pane of
    /// `pane` pixels: centred along a side where the frame is larger than the pane,
    /// the window kept inside the frame there; a side the pane holds whole keeps its
    /// centring. Each pane pixel stays one of the frame's.
    pub fn show_frame_pixel(&mut self, pixel: (u32, u32), pane: (u32, u32)) {
        let Some(frame) = &mut self.case_frame else {
            return;
        };
        let place = |offset: f64, pixel: u32, pane: u32, frame: u32| {
            if frame <= pane {
                return offset;
            }
            let centred = f64::from(pixel) - f64::from(pane / 2);
            centred.clamp(0.0, f64::from(frame - pane))
        };
        let old = DVec2::from_array(frame.offset);
        let new = DVec2::new(
            place(old.x, pixel.0, pane.0, frame.width),
            place(old.y, pixel.1, pane.1, frame.height),
        );
        frame.offset = new.to_array();
        self.origin = (DVec2::from_array(self.origin) + old - new).to_array();
    }

    /// Font units → pixels, before the tilt: image = origin + linear · (x, y).
    fn linear(&self, units_per_em: f64) -> DMat2 {
        let s = self.size_px_per_em / units_per_em;
        DMat2::from_cols(DVec2::new(s, 0.0), DVec2::new(0.0, -s)) * self.matrix()
    }

    /// Where screen point `pixel` of a `width`×`height` pane lies before the tilt: the
    /// anchor that keeps what is under the cursor there (the tilt, which zoom, rotation
    /// and skew leave alone, maps one to the other). The pane's centre is its own.
    pub fn untilted(&self, pixel: DVec2, width: u32, height: u32) -> DVec2 {
        project(&self.camera(width, height).perspective().inverse(), pixel)
    }

    /// Applies `change`, keeping the scene point at `anchor` (pixels before the tilt:
    /// see [`CameraSettings::untilted`]) where it is.
    fn keeping(&mut self, anchor: DVec2, units_per_em: f64, change: impl FnOnce(&mut Self)) {
        let before = self.linear(units_per_em);
        let world = before.inverse() * (anchor - DVec2::from_array(self.origin));
        change(self);
        let after = self.linear(units_per_em);
        if after.determinant().is_finite() && after.determinant() != 0.0 {
            self.origin = (anchor - after * world).to_array();
        }
    }

    pub fn pan(&mut self, delta: DVec2) {
        self.origin = (DVec2::from_array(self.origin) + delta).to_array();
    }

    /// Multiplies the size by `factor` (clamped to the zoom range) about `anchor`.
    pub fn zoom(&mut self, factor: f64, anchor: DVec2, units_per_em: f64) {
        self.keeping(anchor, units_per_em, |c| {
            c.size_px_per_em =
                (c.size_px_per_em * factor).clamp(MIN_SIZE_PX_PER_EM, MAX_SIZE_PX_PER_EM);
        });
    }

    /// Sets the size, zooming about `anchor`.
    pub fn set_size(&mut self, size: f64, anchor: DVec2, units_per_em: f64) {
        self.zoom(size / self.size_px_per_em, anchor, units_per_em);
    }

    pub fn rotate(&mut self, degrees: f64, anchor: DVec2, units_per_em: f64) {
        self.keeping(anchor, units_per_em, |c| {
            c.rotation_deg = (c.rotation_deg + degrees + 180.0).rem_euclid(360.0) - 180.0;
        });
    }

    pub fn set_skew(&mut self, skew: f64, anchor: DVec2, units_per_em: f64) {
        self.keeping(anchor, units_per_em, |c| c.skew = skew);
    }

    /// Back to no rotation, skew, tilt or world offset (and out of a named view's
    /// frame), the size kept, the text's top-left corner at the margin.
    pub fn reset(&mut self, scene: &Scene) {
        *self = CameraSettings {
            size_px_per_em: self.size_px_per_em,
            ..CameraSettings::default()
        };
        self.place_ink_at_margin(scene);
    }

    /// Resets and picks the size at which the whole scene fits a pane of `size` pixels.
    pub fn fit(&mut self, scene: &Scene, size: DVec2) {
        self.reset(scene);
        let Some(ink) = scene.ink_bounds() else {
            return;
        };
        let room = (size - 2.0 * FIT_MARGIN_PX).max(DVec2::ONE);
        let em = ink.size().max(DVec2::splat(1.0)) / scene.units_per_em;
        self.size_px_per_em = (room / em)
            .min_element()
            .clamp(MIN_SIZE_PX_PER_EM, MAX_SIZE_PX_PER_EM);
        self.place_ink_at_margin(scene);
    }

    fn place_ink_at_margin(&mut self, scene: &Scene) {
        if let Some(ink) = scene.ink_bounds() {
            let s = self.size_px_per_em / scene.units_per_em;
            self.origin = [FIT_MARGIN_PX - ink.min.x * s, FIT_MARGIN_PX + ink.max.y * s];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Where font point `p` of a glyph at the origin lands.
    fn image_of(c: &CameraSettings, p: DVec2) -> DVec2 {
        project(&c.camera(800, 600).glyph_to_image(1000.0, DVec2::ZERO), p)
    }

    #[test]
    fn zoom_and_rotation_keep_the_anchor_fixed() {
        let mut c = CameraSettings::default();
        let anchor = DVec2::new(321.5, 123.25);
        let linear = c.linear(1000.0);
        let world = linear.inverse() * (anchor - DVec2::from_array(c.origin));
        c.zoom(7.5, anchor, 1000.0);
        assert!((image_of(&c, world) - anchor).length() < 1e-9);
        c.rotate(33.0, anchor, 1000.0);
        c.set_skew(0.4, anchor, 1000.0);
        assert!((image_of(&c, world) - anchor).length() < 1e-9);
    }

    #[test]
    fn zoom_keeps_the_point_under_the_cursor_under_a_tilt() {
        let mut c = CameraSettings {
            tilt_deg: 40.0,
            ..CameraSettings::default()
        };
        let cursor = DVec2::new(700.5, 80.25);
        let anchor = c.untilted(cursor, 800, 600);
        let world = c.linear(1000.0).inverse() * (anchor - DVec2::from_array(c.origin));
        assert!((image_of(&c, world) - cursor).length() < 1e-9);
        c.zoom(7.5, anchor, 1000.0);
        assert!((image_of(&c, world) - cursor).length() < 1e-9);
        // Without the untilting the point drifts: the test can tell.
        c.zoom(2.0, cursor, 1000.0);
        assert!((image_of(&c, world) - cursor).length() > 1.0);
    }

    #[test]
    fn zoom_in_and_out_by_powers_of_two_returns_exactly() {
        let start = CameraSettings::default();
        let mut c = start;
        let anchor = DVec2::new(400.0, 300.0);
        for _ in 0..11 {
            c.zoom(2.0, anchor, 2048.0);
        }
        assert_eq!(c.size_px_per_em, 48.0 * 2048.0);
        for _ in 0..11 {
            c.zoom(0.5, anchor, 2048.0);
        }
        assert_eq!(c, start);
    }

    #[test]
    fn zoom_stays_within_range() {
        let mut c = CameraSettings::default();
        c.zoom(1e9, DVec2::ZERO, 1000.0);
        assert_eq!(c.size_px_per_em, MAX_SIZE_PX_PER_EM);
        c.zoom(1e-12, DVec2::ZERO, 1000.0);
        assert_eq!(c.size_px_per_em, MIN_SIZE_PX_PER_EM);
    }

    /// Every named view placed in a pane: each pane pixel sees what the frame's pixel
    /// `offset` further on sees — under skew, rotation, tilt and a 1e6 px world offset —
    /// magnified too; and the frame is centred by whole pixels.
    #[test]
    fn a_named_view_in_a_pane_keeps_its_frame_pixels() {
        for view in crate::named_views::all() {
            let (scene, frame) = crate::named_views::build(view.name).unwrap();
            for (w, h) in [(431, 617), (frame.width, frame.height), (40, 30)] {
                let c = CameraSettings::of_frame(&frame, w, h)
                    .unwrap_or_else(|| panic!("{}: not a rotation after a skew", view.name));
                let offset = DVec2::from_array(c.case_frame.unwrap().offset);
                assert_eq!(offset, offset.floor(), "{}", view.name);
                let centred = (DVec2::new(f64::from(frame.width), f64::from(frame.height))
                    - DVec2::new(f64::from(w), f64::from(h)))
                    / 2.0;
                assert!(
                    (offset - centred).abs().max_element() < 1.0,
                    "{}",
                    view.name
                );
                // Moved to show a far pixel, the window stays inside the frame along a side
                // larger than the pane, shows the pixel, and keeps the mapping.
                for pixel in [(0, 0), (frame.width - 1, frame.height - 1)] {
                    let mut moved = c;
                    moved.show_frame_pixel(pixel, (w, h));
                    let o = DVec2::from_array(moved.case_frame.unwrap().offset);
                    let at = DVec2::new(f64::from(pixel.0), f64::from(pixel.1)) - o;
                    assert!(at.x >= 0.0 && at.y >= 0.0, "{}: {at}", view.name);
                    assert!(
                        at.x < f64::from(w) && at.y < f64::from(h),
                        "{}: {at}",
                        view.name
                    );
                    for (offset, pane, side) in [(o.x, w, frame.width), (o.y, h, frame.height)] {
                        assert_eq!(offset, offset.floor());
                        if side > pane {
                            assert!((0.0..=f64::from(side - pane)).contains(&offset));
                        }
                    }
                    let upem = scene.units_per_em;
                    let pen = scene.instances[0].position;
                    let p = DVec2::new(300.0, 200.0);
                    let expected = project(&frame.glyph_to_image(upem, pen), p) - o;
                    let got = project(&moved.camera(w, h).glyph_to_image(upem, pen), p);
                    let tolerance = 1e-9 * (1.0 + frame.world_offset.length());
                    assert!((got - expected).length() <= tolerance, "{}", view.name);
                }
                let mut magnified = c;
                magnified.magnify = 8;
                magnified.focus = [f64::from(w) / 3.0, f64::from(h) / 2.0];
                let (window_camera, window) = magnified.pane_camera(w, h);
                let shift = DVec2::new(f64::from(window.x0), f64::from(window.y0));
                for instance in scene.instances.iter().take(50) {
                    let upem = scene.units_per_em;
                    let in_frame = frame.glyph_to_image(upem, instance.position);
                    let in_pane = c.camera(w, h).glyph_to_image(upem, instance.position);
                    let in_window = window_camera.glyph_to_image(upem, instance.position);
                    for p in [
                        DVec2::ZERO,
                        DVec2::new(500.0, -300.0),
                        DVec2::new(-40.0, 700.0),
                    ] {
                        let expected = project(&in_frame, p) - offset;
                        let tolerance = 1e-9 * (1.0 + frame.world_offset.length());
                        for (got, what) in [
                            (project(&in_pane, p), "pane"),
                            (project(&in_window, p) + shift, "window"),
                        ] {
                            assert!(
                                (got - expected).length() <= tolerance,
                                "{} in a {w}×{h} {what}: {got} against {expected}",
                                view.name
                            );
                        }
                    }
                }
            }
        }
    }
}
