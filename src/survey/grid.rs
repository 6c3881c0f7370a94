//! Glyphs laid out in frames so that every pixel belongs to one glyph: each glyph gets a
//! slot, its ink box (as the camera turns it) plus [`MARGIN`] clear pixels on each
//! side, and slots fill rows left to right, rows fill frames. Each glyph sits at its
//! own sub-pixel offset in its slot, fixed by its id, so a font is seen at every
//! phase of the pixel grid, reproducibly.

use glam::{DMat2, DVec2};

use crate::Error;
use crate::camera::Camera;
use crate::geometry::Rect;

/// Clear pixels between a glyph's ink box and its slot's edge: the reference's
/// coverage ends at the ink box, and no method's blur reaches 3 px past it.
pub const MARGIN: u32 = 3;
/// The largest side of a frame, pixels.
pub const MAX_FRAME_SIDE: u32 = 2048;

/// Where one glyph is drawn in its frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slot {
    /// Which of the glyphs laid out.
    pub glyph: usize,
    /// The slot's top-left pixel and size in the frame.
    pub x: u32,
    pub y: u32,
    pub width: u32,
    pub height: u32,
    /// The glyph's pen position, font units (the scene's instance position).
    pub pen: DVec2,
    /// Where the pen lands, in the slot's pixels: what a link's origin reproduces.
    pub origin_in_slot: DVec2,
}

/// One frame of slots.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub width: u32,
    pub height: u32,
    pub slots: Vec<Slot>,
}

/// A glyph's sub-pixel offset in its slot, from its id: the fractional parts of
/// id·(φ − 1) and id·(φ − 1)², in 64ths of a pixel, which spread any run of ids
/// evenly over the pixel.
pub fn subpixel_offset(id: u16) -> DVec2 {
    let golden = 0.618_033_988_749_894_9_f64;
    let frac = |v: f64| ((v.fract() * 64.0).floor()) / 64.0;
    DVec2::new(
        frac(f64::from(id) * golden),
        frac(f64::from(id) * golden * golden),
    )
}

/// Lays out glyphs (`(id, control bounds)` in font units) seen at `size_px_per_em`
/// through `matrix`, in order, into frames of at most [`MAX_FRAME_SIDE`] a side. A
/// glyph too large for a frame of its own is returned apart, by its index.
pub fn layout(
    glyphs: &[(u16, Rect)],
    units_per_em: f64,
    size_px_per_em: f64,
    matrix: DMat2,
) -> Result<(Vec<Frame>, Vec<usize>), Error> {
    let mut camera = Camera::new(1, 1, size_px_per_em, DVec2::ZERO);
    camera.matrix = matrix;
    camera.validate()?;
    let linear = camera.glyph_to_image(units_per_em, DVec2::ZERO);
    let to_pixels = DMat2::from_cols(linear.x_axis.truncate(), linear.y_axis.truncate());
    let to_pen = to_pixels.inverse();
    let mut frames: Vec<Frame> = Vec::new();
    let mut too_large = Vec::new();
    let (mut x, mut y, mut row_height) = (0u32, 0u32, 0u32);
    let mut current = Frame {
        width: 0,
        height: 0,
        slots: Vec::new(),
    };
    for (index, &(id, bounds)) in glyphs.iter().enumerate() {
        let ink = Camera::project_bounds(&linear, &bounds)?;
        let size = ink.size();
        // The ink spans [offset, offset + size] past the margin: one pixel more than
        // its size, rounded up, holds it at any offset.
        let side = |extent: f64| extent.ceil() + f64::from(1 + 2 * MARGIN);
        // Compared before any cast: a glyph millions of pixels across is too large, not
        // a wrapped-around small slot.
        if !(side(size.x) <= f64::from(MAX_FRAME_SIDE) && side(size.y) <= f64::from(MAX_FRAME_SIDE))
        {
            too_large.push(index);
            continue;
        }
        let (width, height) = (side(size.x) as u32, side(size.y) as u32);
        if x + width > MAX_FRAME_SIDE {
            (x, y) = (0, y + row_height);
            row_height = 0;
        }
        if y + height > MAX_FRAME_SIDE {
            frames.push(std::mem::replace(
                &mut current,
                Frame {
                    width: 0,
                    height: 0,
                    slots: Vec::new(),
                },
            ));
            (x, y, row_height) = (0, 0, 0);
        }
        let origin_in_slot = DVec2::splat(f64::from(MARGIN)) + subpixel_offset(id) - ink.min;
        let slot_corner = DVec2::new(f64::from(x), f64::from(y));
        current.slots.push(Slot {
            glyph: index,
            x,
            y,
            width,
            height,
            pen: to_pen * (slot_corner + origin_in_slot),
            origin_in_slot,
        });
        current.width = current.width.max(x + width);
        current.height = current.height.max(y + height);
        x += width;
        row_height = row_height.max(height);
    }
    if !current.slots.is_empty() {
        frames.push(current);
    }
    Ok((frames, too_large))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(side: f64) -> Rect {
        Rect {
            min: DVec2::ZERO,
            max: DVec2::splat(side),
        }
    }

    /// Slots never overlap, stay inside their frame, and hold their glyph's ink with
    /// the margin clear on every side, still and turned.
    #[test]
    fn slots_hold_their_ink_with_a_clear_margin_and_never_overlap() {
        let glyphs: Vec<(u16, Rect)> = (0..1000)
            .map(|i| (i, square(1000.0 + 2.0 * f64::from(i))))
            .collect();
        for degrees in [0.0_f64, 30.0] {
            let matrix = DMat2::from_angle(degrees.to_radians());
            let (frames, too_large) = layout(&glyphs, 1000.0, 48.0, matrix).unwrap();
            assert!(too_large.is_empty());
            assert!(
                frames.len() > 1,
                "1000 glyphs of 48–144 px fill more than one frame"
            );
            let mut camera = Camera::new(1, 1, 48.0, DVec2::ZERO);
            camera.matrix = matrix;
            for frame in &frames {
                assert!(frame.width <= MAX_FRAME_SIDE && frame.height <= MAX_FRAME_SIDE);
                for (k, a) in frame.slots.iter().enumerate() {
                    assert!(a.x + a.width <= frame.width && a.y + a.height <= frame.height);
                    let to_image = camera.glyph_to_image(1000.0, a.pen);
                    let ink = Camera::project_bounds(&to_image, &glyphs[a.glyph].1).unwrap();
                    let m = f64::from(MARGIN);
                    assert!(
                        ink.min.x >= f64::from(a.x) + m - 1e-9,
                        "{degrees}: {ink:?} {a:?}"
                    );
                    assert!(ink.min.y >= f64::from(a.y) + m - 1e-9);
                    assert!(ink.max.x <= f64::from(a.x + a.width) - m + 1e-9);
                    assert!(ink.max.y <= f64::from(a.y + a.height) - m + 1e-9);
                    let origin = to_image.z_axis.truncate();
                    let expected = DVec2::new(f64::from(a.x), f64::from(a.y)) + a.origin_in_slot;
                    assert!(origin.distance(expected) < 1e-9);
                    for b in &frame.slots[k + 1..] {
                        let apart = a.x + a.width <= b.x
                            || b.x + b.width <= a.x
                            || a.y + a.height <= b.y
                            || b.y + b.height <= a.y;
                        assert!(apart, "{a:?} overlaps {b:?}");
                    }
                }
            }
        }
        let (frames, too_large) =
            layout(&[(0, square(1e5))], 1000.0, 48.0, DMat2::IDENTITY).unwrap();
        assert!(frames.is_empty());
        assert_eq!(too_large, [0]);
    }

    #[test]
    fn offsets_are_64ths_and_spread_over_the_pixel() {
        let offsets: Vec<DVec2> = (0..64).map(subpixel_offset).collect();
        assert!(
            offsets
                .iter()
                .all(|o| (o * 64.0).fract() == DVec2::ZERO && o.max_element() < 1.0)
        );
        let quarters = |f: fn(&DVec2) -> f64| {
            (0..4).all(|q| {
                offsets
                    .iter()
                    .filter(|o| (f(o) * 4.0).floor() as i32 == q)
                    .count()
                    >= 12
            })
        };
        assert!(quarters(|o| o.x) && quarters(|o| o.y));
    }
}
