//! One glyph's distance field, made by fdsm (a Rust port of Viktor Chlumský's msdfgen)
//! the way msdfgen makes one: the outline moved into field texels, edges coloured
//! (msdfgen's simple colouring, its default 3-radian corner angle), the field sampled
//! at each texel centre, msdfgen's error correction (for msdf and mtsdf, where asked),
//! then the sign made to agree with the nonzero fill, quantized to 8 bits a channel.
//!
//! A field value v in [0, 1] encodes a signed distance d (texels, positive inside) as
//! v = d / range + 1/2, clamped: the field holds distances within ±range/2 texels.

use fdsm::bezier::scanline::FillRule;
use fdsm::bezier::{Point, Segment as FieldSegment};
use fdsm::correct_error::{ErrorCorrectionConfig, correct_error_msdf, correct_error_mtsdf};
use fdsm::generate::{generate_msdf, generate_mtsdf, generate_sdf};
use fdsm::render::{correct_sign_msdf, correct_sign_mtsdf, correct_sign_sdf};
use fdsm::shape::{Contour as FieldContour, Shape};
use glam::DVec2;
use image::{ImageBuffer, Luma, Pixel, Rgb, Rgba};

use crate::Error;
use crate::geometry::{Outline, Rect, Segment, segment_points};

/// msdfgen's default corner angle (3 rad): edges meeting at a sharper turn than this
/// are a corner, and take different colours on either side.
const CORNER_ANGLE_RAD: f64 = 3.0;
/// msdfgen's default seed for the colouring.
const COLOURING_SEED: u64 = 0;

/// Which field: the single-channel SDF of Valve's 2007 paper, Chlumský's multi-channel
/// MSDF, or the MSDF with the true distance in a fourth channel (MTSDF).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FieldKind {
    Sdf,
    Msdf,
    Mtsdf,
}

impl FieldKind {
    /// Bytes a texel: wgpu has no three-channel texture, so msdf's three take four, as in
    /// every engine's RGBA atlas.
    pub fn texel_bytes(self) -> usize {
        match self {
            FieldKind::Sdf => 1,
            FieldKind::Msdf | FieldKind::Mtsdf => 4,
        }
    }

    /// Linear, never sRGB: the channels are distances.
    pub fn format(self) -> wgpu::TextureFormat {
        match self {
            FieldKind::Sdf => wgpu::TextureFormat::R8Unorm,
            FieldKind::Msdf | FieldKind::Mtsdf => wgpu::TextureFormat::Rgba8Unorm,
        }
    }
}

/// How a field is made.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FieldSpec {
    pub kind: FieldKind,
    /// Field texels per em.
    pub texels_per_em: f64,
    /// The range of distances the field holds, texels, from −range/2 to +range/2.
    pub range: f64,
    /// msdfgen's error correction (msdf and mtsdf only).
    pub correction: bool,
}

impl FieldSpec {
    /// Texels kept around the glyph's ink: half the range, where the field reaches
    /// its outside value, and one more so that bilinear taps at the border read it.
    pub fn pad(&self) -> f64 {
        (self.range / 2.0).ceil() + 1.0
    }
}

/// One glyph's field.
#[derive(Clone, Debug)]
pub struct GlyphField {
    pub width: u32,
    pub height: u32,
    /// `width × height` texels of [`FieldKind::texel_bytes`] each, rows top first as in
    /// an image (fdsm makes them bottom first: they are turned over).
    pub texels: Vec<u8>,
    /// Where the glyph's local origin lies in the field, texels, x right and y down.
    pub origin: DVec2,
}

#[cfg(test)]
impl GlyphField {
    /// Texel (x, y)'s bytes.
    pub fn texel(&self, kind: FieldKind, x: u32, y: u32) -> &[u8] {
        let n = kind.texel_bytes();
        let at = (y as usize * self.width as usize + x as usize) * n;
        &self.texels[at..at + n]
    }
}

/// The largest side of one glyph's field, texels: its f32 image, made before it is
/// quantized, then holds at most 4096² texels of 16 bytes (268 MB).
pub const MAX_FIELD_SIDE: u32 = 4096;
/// The most texels the fields of one scene may have together (128 MB at four bytes a
/// texel): fdsm's time grows with them (every texel measures every edge), and past
/// this a scene's preparation would take minutes, so it is refused instead.
pub const MAX_ATLAS_TEXELS: u64 = 1 << 25;

/// The size of the field of an outline with ink `bounds` (font units; None for an
/// empty outline) for a font of `units_per_em`, texels: worked out before anything is
/// made, so that an atlas that cannot fit is refused at once. Errors over
/// [`MAX_FIELD_SIDE`] a side.
pub fn size(
    bounds: Option<Rect>,
    units_per_em: f64,
    spec: &FieldSpec,
) -> Result<(u32, u32), Error> {
    let Some(bounds) = bounds else {
        return Ok((1, 1));
    };
    let extent = bounds.size() * spec.texels_per_em / units_per_em + 2.0 * spec.pad();
    let (width, height) = (extent.x.ceil(), extent.y.ceil());
    let side = f64::from(MAX_FIELD_SIDE);
    if !(width <= side && height <= side) {
        // A limit of the technique, as a peer's are: refused, naming it.
        return Err(Error::Refused(format!(
            "msdf: a field of {width}×{height} texels is over {side} a side; ask for \
             fewer texels per em (em_px) or a smaller range"
        )));
    }
    Ok((width as u32, height as u32))
}

/// The field of `outline` (with ink `bounds`, font units) for a font of
/// `units_per_em`, of the [`size`] it has.
pub fn generate(
    outline: &Outline,
    bounds: Rect,
    units_per_em: f64,
    spec: &FieldSpec,
) -> Result<GlyphField, Error> {
    let scale = spec.texels_per_em / units_per_em;
    let pad = spec.pad();
    let (width, height) = size((!outline.is_empty()).then_some(bounds), units_per_em, spec)?;
    // Where the local origin lies in fdsm's texels, y up from the field's bottom edge.
    let origin = if outline.is_empty() {
        DVec2::ZERO
    } else {
        DVec2::splat(pad) - bounds.min * scale
    };
    let shape = field_shape(outline, |p| {
        Point::new(origin.x + p.x * scale, origin.y + p.y * scale)
    });
    let bottom_first = if shape.contours.is_empty() {
        // Nothing to measure a distance to: the outside value everywhere.
        vec![0; width as usize * height as usize * spec.kind.texel_bytes()]
    } else {
        // fdsm's colouring and distance code index segments freely: a panic there is a
        // peer's failure, refused in one line, never glyphscope's crash.
        std::panic::catch_unwind(|| field_texels(shape, width, height, spec)).map_err(|_| {
            Error::Refused(
                "msdf: fdsm failed (panicked) making a glyph's distance field".to_string(),
            )
        })?
    };
    let row_bytes = width as usize * spec.kind.texel_bytes();
    let texels = bottom_first
        .chunks_exact(row_bytes)
        .rev()
        .flatten()
        .copied()
        .collect();
    Ok(GlyphField {
        width,
        height,
        texels,
        origin: DVec2::new(origin.x, f64::from(height) - origin.y),
    })
}

/// fdsm's shape of `outline`, each point moved by `to_texels`; segments of zero length
/// and contours left with none are dropped (their distance is undefined).
fn field_shape(outline: &Outline, to_texels: impl Fn(DVec2) -> Point) -> Shape<FieldContour> {
    let contours = outline
        .contours
        .iter()
        .map(|contour| FieldContour {
            segments: contour
                .segments
                .iter()
                .filter(|s| segment_points(s).any(|p| p != s.start()))
                .map(|s| match *s {
                    Segment::Line(a, b) => FieldSegment::line(to_texels(a), to_texels(b)),
                    Segment::Quad(a, b, c) => {
                        FieldSegment::quad(to_texels(a), to_texels(b), to_texels(c))
                    }
                    Segment::Cubic(a, b, c, d) => {
                        FieldSegment::cubic(to_texels(a), to_texels(b), to_texels(c), to_texels(d))
                    }
                })
                .collect(),
        })
        .filter(|c: &FieldContour| !c.segments.is_empty())
        .collect();
    Shape { contours }
}

/// The field's bytes, made in f32 (error correction works on f32 channels only) and
/// quantized as msdfgen stores a byte.
fn field_texels(shape: Shape<FieldContour>, width: u32, height: u32, spec: &FieldSpec) -> Vec<u8> {
    let range = spec.range;
    match spec.kind {
        FieldKind::Sdf => {
            let prepared = shape.prepare();
            let mut field = ImageBuffer::<Luma<f32>, Vec<f32>>::new(width, height);
            generate_sdf(&prepared, range, &mut field);
            correct_sign_sdf(&mut field, &prepared, FillRule::Nonzero);
            quantized(&field, 1)
        }
        FieldKind::Msdf => {
            let coloured =
                Shape::edge_coloring_simple(shape, CORNER_ANGLE_RAD.sin(), COLOURING_SEED);
            let prepared = coloured.prepare();
            let mut field = ImageBuffer::<Rgb<f32>, Vec<f32>>::new(width, height);
            generate_msdf(&prepared, range, &mut field);
            if spec.correction {
                // Before the sign correction, as fdsm requires.
                let config = ErrorCorrectionConfig::default();
                correct_error_msdf(&mut field, &coloured, &prepared, range, &config);
            }
            correct_sign_msdf(&mut field, &prepared, FillRule::Nonzero);
            quantized(&field, 3)
        }
        FieldKind::Mtsdf => {
            let coloured =
                Shape::edge_coloring_simple(shape, CORNER_ANGLE_RAD.sin(), COLOURING_SEED);
            let prepared = coloured.prepare();
            let mut field = ImageBuffer::<Rgba<f32>, Vec<f32>>::new(width, height);
            generate_mtsdf(&prepared, range, &mut field);
            if spec.correction {
                let config = ErrorCorrectionConfig::default();
                correct_error_mtsdf(&mut field, &coloured, &prepared, range, &config);
            }
            correct_sign_mtsdf(&mut field, &prepared, FillRule::Nonzero);
            quantized(&field, 4)
        }
    }
}

/// Each channel as a byte, four a texel for three channels or more (the fourth 255 for
/// an msdf: opaque, unused), rounded to nearest. NaN (a degenerate distance) reads as
/// outside.
fn quantized<P: Pixel<Subpixel = f32>>(
    field: &ImageBuffer<P, Vec<f32>>,
    channels: usize,
) -> Vec<u8> {
    let stored = if channels == 1 { 1 } else { 4 };
    let mut bytes = Vec::with_capacity(field.width() as usize * field.height() as usize * stored);
    let byte = |v: f32| {
        if v.is_nan() {
            0
        } else {
            (v.clamp(0.0, 1.0) * 255.0).round() as u8
        }
    };
    for pixel in field.pixels() {
        let values = pixel.channels();
        bytes.extend(values.iter().take(channels).map(|&v| byte(v)));
        bytes.extend(std::iter::repeat_n(255, stored - channels));
    }
    bytes
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Contour;

    /// A square from (0, 0) to (side, side), counter-clockwise (filled under nonzero).
    fn square(side: f64) -> Outline {
        let corners = [(0.0, 0.0), (side, 0.0), (side, side), (0.0, side)];
        let points: Vec<DVec2> = corners.iter().map(|&(x, y)| DVec2::new(x, y)).collect();
        Outline {
            contours: vec![Contour {
                segments: (0..4)
                    .map(|i| Segment::Line(points[i], points[(i + 1) % 4]))
                    .collect(),
            }],
        }
    }

    /// The value a field stores for the signed distance `d` texels: worked by hand from
    /// the encoding v = d / range + 1/2, not from fdsm.
    fn encoded(d: f64, range: f64) -> f64 {
        (d / range + 0.5).clamp(0.0, 1.0)
    }

    fn median(a: f64, b: f64, c: f64) -> f64 {
        a.max(b).min(a.min(b).max(c))
    }

    /// Along the middle row of a 10-texel square, the distance to the square is the
    /// distance to its left edge, x texels (positive inside), for every texel centre
    /// within 4.5 texels of that edge: the top and bottom edges are 4.5 away and the
    /// right edge farther. Every kind of field holds it within one byte's rounding.
    #[test]
    fn a_squares_field_holds_the_hand_worked_distance_to_its_edge() {
        let units_per_em = 100.0;
        let outline = square(100.0);
        let bounds = outline.control_bounds().expect("points");
        for kind in [FieldKind::Sdf, FieldKind::Msdf, FieldKind::Mtsdf] {
            for range in [2.0, 4.0, 8.0] {
                let spec = FieldSpec {
                    kind,
                    texels_per_em: 10.0,
                    range,
                    correction: true,
                };
                let field = generate(&outline, bounds, units_per_em, &spec).expect("made");
                let pad = spec.pad();
                assert_eq!(field.width as f64, 10.0 + 2.0 * pad);
                assert_eq!(field.height, field.width);
                // The origin is the square's bottom-left corner, y counted down.
                assert_eq!(field.origin, DVec2::new(pad, f64::from(field.height) - pad));
                // The row 4.5 texels above the square's bottom edge, counted from the top.
                let row = field.height - 1 - (4.0 + pad) as u32;
                let mut checked = 0;
                for column in 0..field.width {
                    let d = f64::from(column) + 0.5 - pad;
                    if d.abs() > range / 2.0 + 1.0 || d > 4.5 {
                        continue;
                    }
                    let t = field.texel(kind, column, row);
                    let v = |i: usize| f64::from(t[i]) / 255.0;
                    let stored = match kind {
                        FieldKind::Sdf => v(0),
                        FieldKind::Msdf | FieldKind::Mtsdf => median(v(0), v(1), v(2)),
                    };
                    let want = encoded(d, range);
                    // Rounding to a byte: half a step, and a hair for f32.
                    assert!(
                        (stored - want).abs() <= 0.5 / 255.0 + 1e-6,
                        "{kind:?} range {range}: texel {column} (d = {d}) holds {stored}, \
                         by hand {want}"
                    );
                    if kind == FieldKind::Mtsdf {
                        assert!((v(3) - want).abs() <= 0.5 / 255.0 + 1e-6, "true distance");
                    }
                    checked += 1;
                }
                assert!(
                    checked >= 3,
                    "{kind:?} range {range}: {checked} texels checked"
                );
            }
        }
    }

    #[test]
    fn an_empty_outline_makes_one_outside_texel_and_a_huge_one_is_refused() {
        let spec = FieldSpec {
            kind: FieldKind::Msdf,
            texels_per_em: 32.0,
            range: 4.0,
            correction: true,
        };
        let rect = Rect {
            min: DVec2::ZERO,
            max: DVec2::ZERO,
        };
        let empty = generate(&Outline::default(), rect, 1000.0, &spec).expect("made");
        assert_eq!((empty.width, empty.height), (1, 1));
        assert_eq!(empty.texel(FieldKind::Msdf, 0, 0)[..3], [0, 0, 0]);
        let outline = square(1000.0);
        let bounds = outline.control_bounds().expect("points");
        let refused = generate(&outline, bounds, 1.0, &spec);
        assert!(matches!(refused, Err(Error::Refused(_))), "{refused:?}");
    }

    #[test]
    fn zero_length_segments_are_dropped_before_fdsm_sees_them() {
        let p = DVec2::new(5.0, 5.0);
        let mut outline = square(10.0);
        outline.contours[0].segments.insert(1, Segment::Line(p, p));
        outline.contours.push(Contour {
            segments: vec![Segment::Quad(p, p, p)],
        });
        let shape = field_shape(&outline, |q| Point::new(q.x, q.y));
        assert_eq!(shape.contours.len(), 1);
        assert_eq!(shape.contours[0].segments.len(), 4);
    }
}
