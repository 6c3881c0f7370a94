//! The one transform convention of the project.
//!
//! A point (x, y) in font units (y up) of a glyph whose origin is at pen position
//! (px, py) maps to image pixel coordinates (y down)
//!
//!   X = ox + (a·(x+px) + b·(y+py))·s,   Y = oy − (c·(x+px) + d·(y+py))·s,
//!
//! with s = size_px_per_em / units_per_em, (ox, oy) the baseline origin and [a b; c d]
//! the matrix. Pixel (i, j) covers [i, i+1) × [j, j+1). An optional perspective tilt
//! then turns the image plane about the horizontal line through the image centre.
//!
//! The world offset moves the scene and the view by the same amount, so it must not
//! change the image: it exists to test precision far from the origin. Transforms are
//! composed in f64 and handed out per glyph, relative to the glyph's own origin and the
//! view's corner, so f32 GPU code only ever sees small local numbers.

use glam::{DMat2, DMat3, DVec2, DVec3};

use crate::Error;
use crate::geometry::{Rect, project};
use crate::scene::Scene;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Image size in pixels.
    pub width: u32,
    pub height: u32,
    pub size_px_per_em: f64,
    /// Baseline origin (ox, oy) of the scene's first line, in image pixels.
    pub origin: DVec2,
    /// [a b; c d], applied to font units (y up) before the y flip.
    pub matrix: DMat2,
    /// Added to both the scene's and the view's world position (pixels).
    pub world_offset: DVec2,
    /// Perspective tilt about the image's horizontal centre line, degrees, |tilt| < 90.
    pub tilt_deg: f64,
    /// Set when this image is a window of a larger frame (see [`Camera::window`]): the
    /// tilt stays the frame's, so each pixel shows what it shows in the frame.
    pub crop: Option<Crop>,
}

/// Where a cropped camera's image lies in its frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crop {
    /// The frame pixel at this image's (0, 0).
    pub offset: DVec2,
    pub frame_width: u32,
    pub frame_height: u32,
}

/// Largest image side accepted anywhere (GPU targets and the reference alike).
pub const MAX_IMAGE_SIDE: u32 = 16384;
/// Largest size accepted: beyond it a single glyph's flattened outline would not fit
/// in memory, and no view can show more than a sliver of it.
pub const MAX_SIZE_PX_PER_EM: f64 = 1.0e6;

impl Camera {
    pub fn new(width: u32, height: u32, size_px_per_em: f64, origin: DVec2) -> Self {
        Camera {
            width,
            height,
            size_px_per_em,
            origin,
            matrix: DMat2::IDENTITY,
            world_offset: DVec2::ZERO,
            tilt_deg: 0.0,
            crop: None,
        }
    }

    /// The camera of the `width`×`height` pixels of this image from (`x`, `y`): each of
    /// its pixels is exactly the image's pixel (x + i, y + j), under a tilt too.
    pub fn window(&self, x: u32, y: u32, width: u32, height: u32) -> Camera {
        let shift = DVec2::new(f64::from(x), f64::from(y));
        let crop = match self.crop {
            Some(c) => Crop {
                offset: c.offset + shift,
                ..c
            },
            None => Crop {
                offset: shift,
                frame_width: self.width,
                frame_height: self.height,
            },
        };
        Camera {
            width,
            height,
            origin: self.origin - shift,
            crop: Some(crop),
            ..*self
        }
    }

    /// The matrix [a b; c d] from its entries in reading order.
    pub fn matrix_from_rows(a: f64, b: f64, c: f64, d: f64) -> DMat2 {
        DMat2::from_cols(DVec2::new(a, c), DVec2::new(b, d))
    }

    /// Rejects sizes, matrices and image sizes nothing sensible can be drawn with.
    pub fn validate(&self) -> Result<(), Error> {
        let s = self.size_px_per_em;
        if !s.is_finite() || s <= 0.0 {
            return Err(Error::Input(format!(
                "size must be a positive number of px/em, got {s}"
            )));
        }
        if s > MAX_SIZE_PX_PER_EM {
            return Err(Error::Input(format!(
                "size {s} px/em is over the limit of {MAX_SIZE_PX_PER_EM} px/em"
            )));
        }
        if self.width == 0 || self.height == 0 {
            return Err(Error::Input(format!(
                "image size {}x{} is empty",
                self.width, self.height
            )));
        }
        if self.width > MAX_IMAGE_SIDE || self.height > MAX_IMAGE_SIDE {
            return Err(Error::Input(format!(
                "image size {}x{} is over the limit of {MAX_IMAGE_SIDE}x{MAX_IMAGE_SIDE}",
                self.width, self.height
            )));
        }
        let m = self.matrix.to_cols_array();
        let finite = m
            .iter()
            .chain(self.origin.as_ref())
            .chain(self.world_offset.as_ref());
        if !finite.copied().all(f64::is_finite) || !self.tilt_deg.is_finite() {
            return Err(Error::Input(
                "matrix, origin, offset and tilt must be finite".into(),
            ));
        }
        if self.matrix.determinant() == 0.0 {
            return Err(Error::Input(
                "the matrix is singular: it would flatten the text".into(),
            ));
        }
        if self.tilt_deg.abs() >= 90.0 {
            return Err(Error::Input(format!(
                "tilt {}° must lie strictly between -90° and 90°",
                self.tilt_deg
            )));
        }
        Ok(())
    }

    /// The image region [0, width] × [0, height] grown by `pixels` on every side.
    pub fn grown_view(&self, pixels: f64) -> Rect {
        Rect {
            min: DVec2::splat(-pixels),
            max: DVec2::new(f64::from(self.width), f64::from(self.height)) + pixels,
        }
    }

    /// Pixels per font unit.
    pub fn scale(&self, units_per_em: f64) -> f64 {
        self.size_px_per_em / units_per_em
    }

    /// The projective map from a glyph's local font units (origin at its pen position
    /// `pen`) to image pixels. Composed in f64; its entries are small even when the
    /// world offset is huge, because the offset cancels before anything is rounded.
    pub fn glyph_to_image(&self, units_per_em: f64, pen: DVec2) -> DMat3 {
        let s = self.scale(units_per_em);
        let flip = DMat2::from_cols(DVec2::new(s, 0.0), DVec2::new(0.0, -s));
        let linear = flip * self.matrix;
        let world = self.origin + self.world_offset + linear * pen;
        let translation = world - self.world_offset;
        let affine = DMat3::from_cols(
            linear.x_axis.extend(0.0),
            linear.y_axis.extend(0.0),
            translation.extend(1.0),
        );
        self.perspective() * affine
    }

    /// The tilt as a homography of image pixels: the image plane turned by the tilt
    /// about its horizontal centre line, seen by a pinhole at distance max(W, H) — of
    /// the frame a window was cropped from, moved to the window's pixels.
    pub fn perspective(&self) -> DMat3 {
        if self.tilt_deg == 0.0 {
            return DMat3::IDENTITY;
        }
        let (width, height, offset) = match self.crop {
            Some(c) => (c.frame_width, c.frame_height, c.offset),
            None => (self.width, self.height, DVec2::ZERO),
        };
        let centre = DVec2::new(f64::from(width), f64::from(height)) * 0.5 - offset;
        let focal = f64::from(width.max(height));
        let (sin, cos) = self.tilt_deg.to_radians().sin_cos();
        let to_centre = DMat3::from_translation(-centre);
        let from_centre = DMat3::from_translation(centre);
        let tilt = DMat3::from_cols(
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(0.0, cos, sin / focal),
            DVec3::new(0.0, 0.0, 1.0),
        );
        from_centre * tilt * to_centre
    }

    /// The scene's ink box (its glyphs' control-point bounds) in image pixels, or an
    /// error if the tilt puts part of it behind the eye.
    pub fn ink_bounds(&self, scene: &Scene) -> Result<Rect, Error> {
        let mut bounds: Option<Rect> = None;
        for instance in &scene.instances {
            let to_image = self.glyph_to_image(scene.units_per_em, instance.position);
            let glyph = &scene.glyphs[instance.glyph as usize];
            let b = Camera::project_bounds(&to_image, &glyph.bounds)?;
            bounds = Some(bounds.map_or(b, |r| r.union(b)));
        }
        bounds.ok_or_else(|| Error::Input("nothing to draw".into()))
    }

    /// Image-space bounds of a local-space rectangle under `glyph_to_image`, or an error
    /// if the tilt puts part of it behind the eye.
    pub fn project_bounds(to_image: &DMat3, local: &Rect) -> Result<Rect, Error> {
        for corner in local.corners() {
            let w = to_image.row(2).dot(corner.extend(1.0));
            if w.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
                return Err(Error::Input(
                    "the tilt puts part of the text behind the eye; tilt less".into(),
                ));
            }
        }
        // A homography with w > 0 maps the rectangle to the convex hull of its corners.
        Ok(Rect::enclosing(local.corners().map(|c| project(to_image, c))).expect("four corners"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn follows_the_documented_convention() {
        let mut cam = Camera::new(100, 100, 20.0, DVec2::new(10.0, 50.0));
        cam.matrix = Camera::matrix_from_rows(1.0, 0.5, -0.25, 2.0);
        let upem = 1000.0;
        let pen = DVec2::new(300.0, -100.0);
        let m = cam.glyph_to_image(upem, pen);
        let (x, y) = (123.0, 456.0);
        let s = 20.0 / 1000.0;
        let (gx, gy) = (x + pen.x, y + pen.y);
        let expected = DVec2::new(
            10.0 + (gx + 0.5 * gy) * s,
            50.0 - (-0.25 * gx + 2.0 * gy) * s,
        );
        assert!((project(&m, DVec2::new(x, y)) - expected).length() < 1e-12);
    }

    #[test]
    fn world_offset_cancels() {
        let mut cam = Camera::new(64, 64, 48.0, DVec2::new(3.25, 40.5));
        cam.matrix = Camera::matrix_from_rows(0.8, -0.6, 0.6, 0.8);
        let pen = DVec2::new(1234.0, 0.0);
        let near = cam.glyph_to_image(2048.0, pen);
        cam.world_offset = DVec2::new(1.0e6, -1.0e6);
        let far = cam.glyph_to_image(2048.0, pen);
        let diff = (near - far)
            .to_cols_array()
            .into_iter()
            .fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(diff < 1e-9, "world offset changed the transform by {diff}");
    }

    #[test]
    fn tilt_keeps_the_centre_line_and_shrinks_the_far_side() {
        let mut cam = Camera::new(200, 100, 10.0, DVec2::ZERO);
        cam.tilt_deg = 30.0;
        let p = cam.perspective();
        let centre = project(&p, DVec2::new(100.0, 50.0));
        assert!((centre - DVec2::new(100.0, 50.0)).length() < 1e-12);
        let left_top = project(&p, DVec2::new(0.0, 0.0));
        let left_bottom = project(&p, DVec2::new(0.0, 100.0));
        // Positive tilt: the top edge (y < centre) comes nearer, the bottom recedes.
        assert!(left_top.x < 0.0 && left_bottom.x > 0.0);
    }

    #[test]
    fn a_window_shows_the_frames_own_pixels_under_a_tilt() {
        let mut frame = Camera::new(300, 200, 40.0, DVec2::new(20.0, 150.0));
        frame.matrix = Camera::matrix_from_rows(0.9, 0.3, -0.2, 1.1);
        frame.tilt_deg = 35.0;
        let window = frame.window(120, 30, 17, 11).window(5, 2, 4, 4);
        assert_eq!((window.width, window.height), (4, 4));
        let (a, b) = (
            frame.glyph_to_image(1000.0, DVec2::new(700.0, 0.0)),
            window.glyph_to_image(1000.0, DVec2::new(700.0, 0.0)),
        );
        for p in [
            DVec2::new(0.0, 0.0),
            DVec2::new(300.0, 700.0),
            DVec2::new(-50.0, 1200.0),
        ] {
            let expected = project(&a, p) - DVec2::new(125.0, 32.0);
            assert!((project(&b, p) - expected).length() < 1e-9, "{p}");
        }
    }

    #[test]
    fn validation_rejects_bad_cameras() {
        let ok = Camera::new(10, 10, 12.0, DVec2::ZERO);
        assert!(ok.validate().is_ok());
        for size in [0.0, -1.0, f64::NAN, f64::INFINITY, 2.0e6] {
            assert!(
                Camera {
                    size_px_per_em: size,
                    ..ok
                }
                .validate()
                .is_err(),
                "{size}"
            );
        }
        assert!(Camera { width: 0, ..ok }.validate().is_err());
        assert!(Camera { width: 16385, ..ok }.validate().is_err());
        assert!(
            Camera {
                matrix: DMat2::ZERO,
                ..ok
            }
            .validate()
            .is_err()
        );
        assert!(
            Camera {
                tilt_deg: 90.0,
                ..ok
            }
            .validate()
            .is_err()
        );
    }
}
