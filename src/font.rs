//! Font loading: faces from bytes or files, variable-font instances, glyph outlines.
//!
//! Outlines are kept exactly as the font stores them — lines, quadratics and cubics in
//! font units, y up — with contour starts taken from the font's own `move_to`, never
//! inferred from equal points, and no orientation assumed.

use std::path::Path;
use std::sync::Arc;

use glam::DVec2;

use crate::Error;
use crate::geometry::{Contour, Outline, Segment};

/// DejaVu Sans, embedded so that everything works without `--font`.
pub const DEFAULT_FONT_BYTES: &[u8] = include_bytes!("../fonts/DejaVuSans.ttf");
pub const DEFAULT_FONT_NAME: &str = "DejaVu Sans";

/// The fonts shipped in `fonts/`, embedded: (name, file name, bytes). Each is there for
/// a reason the methods must face: TrueType quadratics, CFF cubics, a variable font
/// whose glyphs overlap, and a complex script.
pub const SHIPPED_FONTS: &[(&str, &str, &[u8])] = &[
    (DEFAULT_FONT_NAME, "DejaVuSans.ttf", DEFAULT_FONT_BYTES),
    (
        "Latin Modern Roman 10",
        "lmroman10-regular.otf",
        include_bytes!("../fonts/lmroman10-regular.otf"),
    ),
    (
        "Inter (variable)",
        "Inter-roman.var.ttf",
        include_bytes!("../fonts/Inter-roman.var.ttf"),
    ),
    (
        "Lohit Bengali",
        "Lohit-Bengali.ttf",
        include_bytes!("../fonts/Lohit-Bengali.ttf"),
    ),
];

/// A glyph index in its font.
pub type GlyphId = u16;

/// A variation axis of a variable font.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    pub tag: String,
    pub min: f32,
    pub default: f32,
    pub max: f32,
}

/// A parsed font face at one variation instance. Cheap to clone.
#[derive(Clone)]
pub struct Font {
    data: Arc<[u8]>,
    name: String,
    units_per_em: f64,
    glyph_count: u16,
    /// (tag, value) pairs applied to every face this font hands out.
    variations: Vec<(ttf_parser::Tag, f32)>,
}

impl std::fmt::Debug for Font {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Font")
            .field("name", &self.name)
            .field("variations", &self.variations)
            .finish()
    }
}

impl Font {
    /// The embedded default font.
    pub fn default_font() -> Self {
        Self::shipped(0)
    }

    /// The `index`-th of [`SHIPPED_FONTS`].
    pub fn shipped(index: usize) -> Self {
        let (name, _, bytes) = SHIPPED_FONTS[index];
        Self::from_bytes(bytes.to_vec(), name).expect("shipped fonts parse")
    }

    /// Reads and parses a font file; the error names the file and what went wrong.
    pub fn from_path(path: &Path) -> Result<Self, Error> {
        let data = std::fs::read(path)
            .map_err(|e| Error::Font(format!("cannot read font file '{}': {e}", path.display())))?;
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_else(|| path.display().to_string());
        Self::from_bytes(data, &name)
    }

    /// Parses font bytes (the first face of a collection).
    pub fn from_bytes(data: Vec<u8>, name: &str) -> Result<Self, Error> {
        let face = ttf_parser::Face::parse(&data, 0)
            .map_err(|e| Error::Font(format!("'{name}' is not a usable font: {e}")))?;
        let units_per_em = f64::from(face.units_per_em());
        let glyph_count = face.number_of_glyphs();
        if glyph_count == 0 {
            return Err(Error::Font(format!("'{name}' has no glyphs")));
        }
        // rustybuzz must accept it too, or shaping would fail later with a vaguer message.
        if rustybuzz::Face::from_slice(&data, 0).is_none() {
            return Err(Error::Font(format!(
                "'{name}' cannot be shaped (rustybuzz rejects it)"
            )));
        }
        Ok(Self {
            data: data.into(),
            name: name.to_owned(),
            units_per_em,
            glyph_count,
            variations: Vec::new(),
        })
    }

    pub fn name(&self) -> &str {
        &self.name
    }

    pub fn units_per_em(&self) -> f64 {
        self.units_per_em
    }

    pub fn glyph_count(&self) -> u16 {
        self.glyph_count
    }

    /// The variation axes, empty for a static font.
    pub fn axes(&self) -> Vec<Axis> {
        self.face()
            .variation_axes()
            .into_iter()
            .map(|a| Axis {
                tag: a.tag.to_string(),
                min: a.min_value,
                default: a.def_value,
                max: a.max_value,
            })
            .collect()
    }

    /// The current variation values, as (tag, value).
    pub fn variations(&self) -> Vec<(String, f32)> {
        self.variations
            .iter()
            .map(|(t, v)| (t.to_string(), *v))
            .collect()
    }

    /// This font at another variation instance. Each axis must exist and the value must
    /// lie within its range.
    pub fn with_variations(&self, values: &[(String, f32)]) -> Result<Self, Error> {
        let axes = self.axes();
        let mut font = self.clone();
        for (tag, value) in values {
            let axis = axes.iter().find(|a| &a.tag == tag).ok_or_else(|| {
                let known: Vec<_> = axes.iter().map(|a| a.tag.as_str()).collect();
                Error::Input(if known.is_empty() {
                    format!(
                        "font '{}' is not variable: it has no axis '{tag}'",
                        self.name
                    )
                } else {
                    format!(
                        "font '{}' has no variation axis '{tag}' (it has: {})",
                        self.name,
                        known.join(", ")
                    )
                })
            })?;
            if !value.is_finite() || *value < axis.min || *value > axis.max {
                return Err(Error::Input(format!(
                    "{tag}={value} is outside the axis range {}..{}",
                    axis.min, axis.max
                )));
            }
            let tag = ttf_parser::Tag::from_bytes_lossy(tag.as_bytes());
            font.variations.retain(|(t, _)| *t != tag);
            font.variations.push((tag, *value));
        }
        Ok(font)
    }

    /// A ttf-parser face at this font's variation instance.
    pub fn face(&self) -> ttf_parser::Face<'_> {
        let mut face = ttf_parser::Face::parse(&self.data, 0).expect("parsed when loaded");
        for (tag, value) in &self.variations {
            face.set_variation(*tag, *value);
        }
        face
    }

    /// A rustybuzz face at this font's variation instance.
    pub fn shaping_face(&self) -> rustybuzz::Face<'_> {
        let mut face = rustybuzz::Face::from_slice(&self.data, 0).expect("checked when loaded");
        let variations: Vec<_> = self
            .variations
            .iter()
            .map(|(tag, value)| rustybuzz::Variation {
                tag: *tag,
                value: *value,
            })
            .collect();
        face.set_variations(&variations);
        face
    }

    /// The glyph for a character, or an error that names the character.
    pub fn glyph_for_char(&self, c: char) -> Result<GlyphId, Error> {
        self.face().glyph_index(c).map(|g| g.0).ok_or_else(|| {
            Error::Input(format!(
                "character {c:?} (U+{:04X}) is not in font '{}'",
                u32::from(c),
                self.name
            ))
        })
    }

    /// Checks a glyph id against the font's glyph count.
    pub fn check_glyph_id(&self, id: u32) -> Result<GlyphId, Error> {
        if id < u32::from(self.glyph_count) {
            Ok(id as GlyphId)
        } else {
            Err(Error::Input(format!(
                "glyph id {id} is out of range: font '{}' has glyphs 0..{}",
                self.name,
                self.glyph_count - 1
            )))
        }
    }

    /// The glyph's outline in font units (empty for blank glyphs such as space).
    pub fn outline(&self, glyph: GlyphId) -> Outline {
        let mut builder = OutlineCollector::default();
        self.face()
            .outline_glyph(ttf_parser::GlyphId(glyph), &mut builder);
        builder.finish()
    }

    /// Horizontal metrics used for line layout: (ascender, descender, line gap), font units.
    pub fn line_metrics(&self) -> (f64, f64, f64) {
        let face = self.face();
        (
            f64::from(face.ascender()),
            f64::from(face.descender()),
            f64::from(face.line_gap()),
        )
    }
}

/// Collects ttf-parser's outline callbacks into contours. A contour begins at each
/// `move_to` and ends at `close` (or the next `move_to`), closed by a line if the font
/// left a gap.
#[derive(Default)]
struct OutlineCollector {
    contours: Vec<Contour>,
    segments: Vec<Segment>,
    start: DVec2,
    current: DVec2,
}

impl OutlineCollector {
    fn end_contour(&mut self) {
        if self.segments.is_empty() {
            return;
        }
        if self.current != self.start {
            self.segments.push(Segment::Line(self.current, self.start));
        }
        self.contours.push(Contour {
            segments: std::mem::take(&mut self.segments),
        });
        self.current = self.start;
    }

    fn finish(mut self) -> Outline {
        self.end_contour();
        Outline {
            contours: self.contours,
        }
    }
}

fn point(x: f32, y: f32) -> DVec2 {
    DVec2::new(f64::from(x), f64::from(y))
}

impl ttf_parser::OutlineBuilder for OutlineCollector {
    fn move_to(&mut self, x: f32, y: f32) {
        self.end_contour();
        self.start = point(x, y);
        self.current = self.start;
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let p = point(x, y);
        self.segments.push(Segment::Line(self.current, p));
        self.current = p;
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let p = point(x, y);
        self.segments
            .push(Segment::Quad(self.current, point(x1, y1), p));
        self.current = p;
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let p = point(x, y);
        self.segments.push(Segment::Cubic(
            self.current,
            point(x1, y1),
            point(x2, y2),
            p,
        ));
        self.current = p;
    }

    fn close(&mut self) {
        self.end_contour();
    }
}
