//! Font loading: faces from bytes or files, variable-font instances, glyph outlines.
//!
//! Outlines keep the font's own segments — lines, quadratics and cubics in font units,
//! y up — with contour starts taken from the font's own `move_to`, never inferred from
//! equal points, and no orientation assumed. Where they go follows FreeType:
//!
//! - The outline table is chosen by sfntVersion: `OTTO` takes `CFF2` or `CFF `, even
//!   when the font also carries `glyf`; any other version takes `glyf`.
//! - A `glyf` glyph is placed by its left phantom point: pp1.x = xMin (the glyph
//!   header's) − lsb (`hmtx`), moved by its `gvar` delta unless the font has `HVAR`, and
//!   taken from the component flagged USE_MY_METRICS in a composite. The outline moves
//!   by −pp1.x; the advance is pp2.x − pp1.x (hmtx's advance plus `HVAR`'s delta where
//!   the font has `HVAR`), rounded to whole units. CFF glyphs are not moved (CFF has no
//!   phantom points) and advance by `hmtx` plus `HVAR`.
//! - Axis tags are four bytes, space-padded: axis `M1` is `'M1  '`.

use std::path::Path;
use std::sync::Arc;

use glam::DVec2;

use crate::Error;
use crate::geometry::{Contour, Outline, Segment};

/// A glyph index in its font.
pub type GlyphId = u16;

/// A variation axis of a variable font.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    /// Four characters, space-padded as the font stores it ('M1  ').
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
    outline_table: OutlineTable,
    /// Which face of a collection (`.ttc`/`.otc`); 0 for a single font.
    face_index: u32,
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
        Self::from_bytes_face(data, name, 0)
    }

    /// How many faces font bytes hold: a collection's count, 1 for a single font, 0 for
    /// bytes that are not a font at all.
    pub fn face_count(data: &[u8]) -> u32 {
        match ttf_parser::fonts_in_collection(data) {
            Some(count) => count,
            None => u32::from(ttf_parser::Face::parse(data, 0).is_ok()),
        }
    }

    /// Parses face `index` of font bytes (0 for a single font).
    pub fn from_bytes_face(data: Vec<u8>, name: &str, index: u32) -> Result<Self, Error> {
        let face = ttf_parser::Face::parse(&data, index)
            .map_err(|e| Error::Font(format!("'{name}' is not a usable font: {e}")))?;
        let units_per_em = f64::from(face.units_per_em());
        let glyph_count = face.number_of_glyphs();
        if glyph_count == 0 {
            return Err(Error::Font(format!("'{name}' has no glyphs")));
        }
        let outline_table = OutlineTable::of(&face, index).map_err(|why| {
            Error::Font(format!(
                "'{name}' has no outlines glyphscope can draw: {why}"
            ))
        })?;
        check_axes(&face).map_err(|why| Error::Font(format!("'{name}': {why}")))?;
        // rustybuzz must accept it too, or shaping would fail later with a vaguer message.
        if rustybuzz::Face::from_slice(&data, index).is_none() {
            return Err(Error::Font(format!(
                "'{name}' cannot be shaped (rustybuzz rejects it)"
            )));
        }
        Ok(Self {
            data: data.into(),
            name: name.to_owned(),
            units_per_em,
            glyph_count,
            outline_table,
            face_index: index,
            variations: Vec::new(),
        })
    }

    /// The font file's bytes, shared.
    pub fn data(&self) -> std::sync::Arc<[u8]> {
        self.data.clone()
    }

    pub fn name(&self) -> &str {
        &self.name
    }

    /// Which face of a collection this is (0 for a single font).
    pub fn face_index(&self) -> u32 {
        self.face_index
    }

    /// The glyph's name in the font (`post` or CFF), if it has one.
    pub fn glyph_name(&self, glyph: GlyphId) -> Option<String> {
        self.face()
            .glyph_name(ttf_parser::GlyphId(glyph))
            .map(str::to_owned)
    }

    pub fn units_per_em(&self) -> f64 {
        self.units_per_em
    }

    pub fn glyph_count(&self) -> u16 {
        self.glyph_count
    }

    /// The table the outlines come from, chosen by sfntVersion.
    pub fn outline_table(&self) -> OutlineTable {
        self.outline_table
    }

    /// The sfntVersion of the face in use, which chose the outline table.
    pub fn sfnt_version(&self) -> Option<[u8; 4]> {
        sfnt_version(&self.data, self.face_index)
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
    /// lie within its range; a tag shorter than four characters is space-padded ('M1'
    /// names axis 'M1  ').
    pub fn with_variations(&self, values: &[(String, f32)]) -> Result<Self, Error> {
        let axes = self.axes();
        let mut font = self.clone();
        for (tag, value) in values {
            let tag = axis_tag(tag)?;
            let axis = axes.iter().find(|a| a.tag == tag).ok_or_else(|| {
                let known: Vec<_> = axes.iter().map(|a| format!("'{}'", a.tag)).collect();
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
                    "'{tag}'={value} is outside the axis range {}..{}",
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
        let mut face =
            ttf_parser::Face::parse(&self.data, self.face_index).expect("parsed when loaded");
        for (tag, value) in &self.variations {
            face.set_variation(*tag, *value);
        }
        face
    }

    /// A rustybuzz face at this font's variation instance.
    pub fn shaping_face(&self) -> rustybuzz::Face<'_> {
        let mut face =
            rustybuzz::Face::from_slice(&self.data, self.face_index).expect("checked when loaded");
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

    /// For each glyph the font's Unicode cmap reaches, the characters that map to it,
    /// smallest first: the way to a glyph for a renderer that draws text only (shaping
    /// may take one character elsewhere and another not). Glyph 0 is left out: a cmap
    /// maps a character it lacks to it.
    pub fn chars_of_glyphs(&self) -> std::collections::HashMap<GlyphId, Vec<char>> {
        let mut chars: std::collections::HashMap<GlyphId, Vec<char>> =
            std::collections::HashMap::new();
        let face = self.face();
        let Some(cmap) = face.tables().cmap else {
            return chars;
        };
        for subtable in cmap.subtables.into_iter().filter(|s| s.is_unicode()) {
            subtable.codepoints(|code| {
                let (Some(c), Some(glyph)) = (char::from_u32(code), subtable.glyph_index(code))
                else {
                    return;
                };
                if glyph.0 == 0 {
                    return;
                }
                chars.entry(glyph.0).or_default().push(c);
            });
        }
        for list in chars.values_mut() {
            list.sort_unstable();
            list.dedup();
        }
        chars
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

    /// The glyph's outline in font units, placed as FreeType places it (see the module
    /// notes); empty for blank glyphs such as space.
    pub fn outline(&self, glyph: GlyphId) -> Outline {
        let face = self.face();
        let id = ttf_parser::GlyphId(glyph);
        let mut builder = OutlineCollector::default();
        match self.outline_table {
            OutlineTable::Glyf => {
                builder.shift_x = -glyf_phantom(&face, glyph).left_x;
                face.outline_glyph(id, &mut builder);
            }
            OutlineTable::Cff => {
                if let Some(cff) = face.tables().cff {
                    let _ = cff.outline(id, &mut builder);
                }
            }
            OutlineTable::Cff2 => {
                if let Some(cff2) = face.tables().cff2 {
                    let _ = cff2.outline(face.variation_coordinates(), id, &mut builder);
                }
            }
        }
        builder.finish()
    }

    /// [`Font::outline`], or why it cannot be trusted: the font gives the glyph a
    /// bounding box but no outline can be read from it (a malformed glyph, which
    /// `outline` reads as blank), or a coordinate is not finite.
    pub fn checked_outline(&self, glyph: GlyphId) -> Result<Outline, String> {
        let outline = self.outline(glyph);
        let id = ttf_parser::GlyphId(glyph);
        if outline.is_empty() && self.face().glyph_bounding_box(id).is_some() {
            return Err(format!(
                "glyph {glyph} has a bounding box but its outline cannot be read"
            ));
        }
        let finite = outline
            .segments()
            .flat_map(crate::geometry::segment_points)
            .all(|p| p.is_finite());
        if !finite {
            return Err(format!("glyph {glyph} has a coordinate that is not finite"));
        }
        Ok(outline)
    }

    /// The glyph's advance width in font units, by the same rules as its outline.
    pub fn advance(&self, glyph: GlyphId) -> f64 {
        let face = self.face();
        match self.outline_table {
            OutlineTable::Glyf => glyf_phantom(&face, glyph).advance,
            OutlineTable::Cff | OutlineTable::Cff2 => hmtx_hvar_advance(&face, glyph),
        }
    }

    /// How the glyph is placed: its advance, the `hmtx` lsb and xMin that set its left
    /// phantom point, and the shift applied to its outline.
    pub fn placement(&self, glyph: GlyphId) -> Placement {
        let face = self.face();
        match self.outline_table {
            OutlineTable::Glyf => {
                let phantom = glyf_phantom(&face, glyph);
                Placement {
                    advance: phantom.advance,
                    lsb: phantom.lsb,
                    x_min: Some(phantom.x_min),
                    shift: -phantom.left_x,
                    metrics_glyph: phantom.metrics_glyph,
                }
            }
            OutlineTable::Cff | OutlineTable::Cff2 => Placement {
                advance: hmtx_hvar_advance(&face, glyph),
                lsb: hmtx_lsb(&face, glyph),
                x_min: None,
                shift: 0.0,
                metrics_glyph: glyph,
            },
        }
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

/// Where a font's outlines come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutlineTable {
    Glyf,
    Cff,
    Cff2,
}

impl OutlineTable {
    /// The table's tag.
    pub fn tag(self) -> &'static str {
        match self {
            OutlineTable::Glyf => "glyf",
            OutlineTable::Cff => "CFF ",
            OutlineTable::Cff2 => "CFF2",
        }
    }

    /// FreeType's choice: an `OTTO` font is read by its CFF driver (CFF2 first), any
    /// other by its TrueType driver, whatever other outline tables the font carries.
    fn of(face: &ttf_parser::Face, index: u32) -> Result<Self, String> {
        let tables = face.tables();
        let version = sfnt_version(face.raw_face().data, index);
        if version == Some(*b"OTTO") {
            if tables.cff2.is_some() {
                Ok(OutlineTable::Cff2)
            } else if tables.cff.is_some() {
                Ok(OutlineTable::Cff)
            } else {
                Err("sfntVersion 'OTTO' but no CFF or CFF2 table".into())
            }
        } else if tables.glyf.is_some() {
            Ok(OutlineTable::Glyf)
        } else {
            Err(format!(
                "sfntVersion {} is not 'OTTO', and there is no glyf table",
                describe_sfnt_version(version)
            ))
        }
    }
}

/// Checks the variation axes as the font's `fvar` table writes them: each axis's
/// minimum, default and maximum finite and in that order. ttf-parser reorders them
/// (its minimum is never above the default), but the other readers a font reaches do
/// not — the peers' rasterizers clamp each axis between its minimum and maximum, and
/// Rust's `clamp` panics where the maximum lies below the minimum (glyphon on a corrupt
/// `fvar`) — so a broken axis is refused here, where every row reads the font.
fn check_axes(face: &ttf_parser::Face<'_>) -> Result<(), String> {
    let Some(fvar) = face.raw_face().table(ttf_parser::Tag::from_bytes(b"fvar")) else {
        return Ok(());
    };
    let u16_at = |at: usize| {
        fvar.get(at..at + 2)
            .map(|b| u16::from_be_bytes([b[0], b[1]]))
    };
    let fixed_at = |at: usize| {
        fvar.get(at..at + 4)
            .map(|b| f64::from(i32::from_be_bytes([b[0], b[1], b[2], b[3]])) / 65536.0)
    };
    let truncated = || "its fvar table (variation axes) is cut short".to_owned();
    let (Some(first), Some(count), Some(size)) = (u16_at(4), u16_at(8), u16_at(10)) else {
        return Err(truncated());
    };
    if count > 0 && size < 20 {
        return Err(format!(
            "its fvar table's axis records are {size} bytes, under 20"
        ));
    }
    for k in 0..usize::from(count) {
        let at = usize::from(first) + k * usize::from(size);
        let tag = fvar
            .get(at..at + 4)
            .map(|t| String::from_utf8_lossy(t).into_owned())
            .ok_or_else(truncated)?;
        let (Some(min), Some(default), Some(max)) =
            (fixed_at(at + 4), fixed_at(at + 8), fixed_at(at + 12))
        else {
            return Err(truncated());
        };
        if !(min <= default && default <= max) {
            return Err(format!(
                "its variation axis '{}' is broken: minimum {min}, default {default}, maximum \
                 {max} (the minimum must not exceed the default, nor the default the maximum)",
                tag.trim()
            ));
        }
    }
    Ok(())
}

/// The sfntVersion of the font's first face (a collection's header points to it).
/// The sfntVersion of face `index` (a collection's `index`-th table directory).
fn sfnt_version(data: &[u8], index: u32) -> Option<[u8; 4]> {
    let at = |offset: usize| -> Option<[u8; 4]> { data.get(offset..offset + 4)?.try_into().ok() };
    let version = at(0)?;
    if &version == b"ttcf" {
        let entry = 12 + 4 * usize::try_from(index).ok()?;
        at(usize::try_from(u32::from_be_bytes(at(entry)?)).ok()?)
    } else {
        Some(version)
    }
}

/// An sfntVersion as people write it: 'OTTO' or 'true' as text, 0x00010000 in hex.
pub fn describe_sfnt_version(version: Option<[u8; 4]>) -> String {
    match version {
        Some(v) if v.iter().all(|b| b.is_ascii_alphanumeric()) => {
            format!("'{}'", String::from_utf8_lossy(&v))
        }
        Some(v) => format!("0x{:08X}", u32::from_be_bytes(v)),
        None => "(unreadable)".into(),
    }
}

/// An OpenType tag from text, as HarfBuzz's tag parsing reads it: surrounding spaces
/// dropped, then 1 to 4 printable ASCII characters padded with spaces to four.
pub fn axis_tag(text: &str) -> Result<String, Error> {
    let trimmed = text.trim();
    let printable = trimmed.bytes().all(|b| b.is_ascii_graphic());
    if trimmed.is_empty() || trimmed.len() > 4 || !printable {
        return Err(Error::Input(format!(
            "axis tag '{text}' must be 1 to 4 ASCII letters, digits or marks \
             (a shorter tag is space-padded: M1 names 'M1  ')"
        )));
    }
    Ok(format!("{trimmed:<4}"))
}

/// How a glyph is placed ([`Font::placement`]), in font units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    pub advance: f64,
    /// The `hmtx` left side bearing of `metrics_glyph`.
    pub lsb: f64,
    /// The `glyf` header's xMin, which sets the left phantom point (0 for a blank glyph,
    /// as FreeType takes it); None for CFF.
    pub x_min: Option<f64>,
    /// Added to every x of the outline: −pp1.x for `glyf`, 0 for CFF.
    pub shift: f64,
    /// The glyph whose metrics these are: the glyph itself, or the component a
    /// composite flags USE_MY_METRICS.
    pub metrics_glyph: GlyphId,
}

/// A `glyf` glyph's horizontal phantom points, as FreeType's TrueType loader sets them.
struct GlyfPhantom {
    /// pp1.x: xMin − lsb, moved by its gvar delta where the font has no HVAR.
    left_x: f64,
    /// pp2.x − pp1.x, rounded to whole units.
    advance: f64,
    lsb: f64,
    x_min: f64,
    metrics_glyph: GlyphId,
}

/// Deepest chain of USE_MY_METRICS components followed (ttf-parser's own limit on
/// component nesting).
const MAX_COMPONENT_DEPTH: usize = 32;

fn glyf_phantom(face: &ttf_parser::Face, glyph: GlyphId) -> GlyfPhantom {
    // A composite takes its phantom points from the component it flags USE_MY_METRICS
    // (the last one, if several are flagged); that component's own are its pp1 and pp2
    // before the component's offset.
    let mut metrics_glyph = glyph;
    for _ in 0..MAX_COMPONENT_DEPTH {
        match glyf_record(face, metrics_glyph).and_then(use_my_metrics_component) {
            Some(component) => metrics_glyph = component,
            None => break,
        }
    }
    let id = ttf_parser::GlyphId(metrics_glyph);
    let tables = face.tables();
    let lsb = hmtx_lsb(face, metrics_glyph);
    let x_min = tables
        .glyf
        .and_then(|glyf| glyf.bbox(id))
        .map_or(0.0, |b| f64::from(b.x_min));
    let default_left = x_min - lsb;
    if tables.hvar.is_some() {
        // FreeType drops the phantom points' gvar deltas when HVAR gives the advance.
        return GlyfPhantom {
            left_x: default_left,
            advance: hmtx_hvar_advance(face, metrics_glyph),
            lsb,
            x_min,
            metrics_glyph,
        };
    }
    let hmtx_advance = tables
        .hmtx
        .and_then(|h| h.advance(id))
        .map_or(0.0, f64::from);
    let (left_delta, right_delta) = face
        .glyph_phantom_points(id)
        .map_or((0.0, 0.0), |p| (f64::from(p.left.x), f64::from(p.right.x)));
    GlyfPhantom {
        left_x: default_left + left_delta,
        // FreeType rounds pp2.x − pp1.x half up, as FT_PIX_ROUND does.
        advance: (hmtx_advance + right_delta - left_delta + 0.5).floor(),
        lsb,
        x_min,
        metrics_glyph,
    }
}

/// The glyph's left side bearing as `hmtx` stores it: FreeType varies neither it nor
/// the phantom point it sets through HVAR.
fn hmtx_lsb(face: &ttf_parser::Face, glyph: GlyphId) -> f64 {
    face.tables()
        .hmtx
        .and_then(|h| h.side_bearing(ttf_parser::GlyphId(glyph)))
        .map_or(0.0, f64::from)
}

/// `hmtx`'s advance plus `HVAR`'s delta, rounded (ttf-parser applies HVAR when the font
/// has it).
fn hmtx_hvar_advance(face: &ttf_parser::Face, glyph: GlyphId) -> f64 {
    face.glyph_hor_advance(ttf_parser::GlyphId(glyph))
        .map_or(0.0, f64::from)
}

/// The glyph's bytes in `glyf`, read through `loca` (ttf-parser keeps a composite's
/// component flags to itself).
fn glyf_record<'a>(face: &ttf_parser::Face<'a>, glyph: GlyphId) -> Option<&'a [u8]> {
    let raw = face.raw_face();
    let loca = ttf_parser::loca::Table::parse(
        std::num::NonZeroU16::new(face.number_of_glyphs())?,
        face.tables().head.index_to_location_format,
        raw.table(ttf_parser::Tag::from_bytes(b"loca"))?,
    )?;
    let range = loca.glyph_range(ttf_parser::GlyphId(glyph))?;
    raw.table(ttf_parser::Tag::from_bytes(b"glyf"))?.get(range)
}

/// The component a composite glyph record flags USE_MY_METRICS (the last, if several);
/// None for a simple glyph or a record cut short.
fn use_my_metrics_component(record: &[u8]) -> Option<GlyphId> {
    const ARG_1_AND_2_ARE_WORDS: u16 = 0x0001;
    const WE_HAVE_A_SCALE: u16 = 0x0008;
    const MORE_COMPONENTS: u16 = 0x0020;
    const WE_HAVE_AN_X_AND_Y_SCALE: u16 = 0x0040;
    const WE_HAVE_A_TWO_BY_TWO: u16 = 0x0080;
    const USE_MY_METRICS: u16 = 0x0200;
    let u16_at = |at: usize| -> Option<u16> {
        Some(u16::from_be_bytes(record.get(at..at + 2)?.try_into().ok()?))
    };
    let number_of_contours = u16_at(0)? as i16;
    if number_of_contours >= 0 {
        return None;
    }
    // Component records follow the 10-byte header.
    let mut at = 10;
    let mut chosen = None;
    loop {
        let flags = u16_at(at)?;
        let component = u16_at(at + 2)?;
        if flags & USE_MY_METRICS != 0 {
            chosen = Some(component);
        }
        let arguments = if flags & ARG_1_AND_2_ARE_WORDS != 0 {
            4
        } else {
            2
        };
        let transform = if flags & WE_HAVE_A_TWO_BY_TWO != 0 {
            8
        } else if flags & WE_HAVE_AN_X_AND_Y_SCALE != 0 {
            4
        } else if flags & WE_HAVE_A_SCALE != 0 {
            2
        } else {
            0
        };
        at += 4 + arguments + transform;
        if flags & MORE_COMPONENTS == 0 {
            return chosen;
        }
    }
}

/// Collects ttf-parser's outline callbacks into contours. A contour begins at each
/// `move_to` and ends at `close` (or the next `move_to`), closed by a line if the font
/// left a gap. Every x is moved by `shift_x`.
#[derive(Default)]
struct OutlineCollector {
    contours: Vec<Contour>,
    segments: Vec<Segment>,
    start: DVec2,
    current: DVec2,
    shift_x: f64,
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

impl OutlineCollector {
    fn point(&self, x: f32, y: f32) -> DVec2 {
        DVec2::new(f64::from(x) + self.shift_x, f64::from(y))
    }
}

impl ttf_parser::OutlineBuilder for OutlineCollector {
    fn move_to(&mut self, x: f32, y: f32) {
        self.end_contour();
        self.start = self.point(x, y);
        self.current = self.start;
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let p = self.point(x, y);
        self.segments.push(Segment::Line(self.current, p));
        self.current = p;
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let p = self.point(x, y);
        self.segments
            .push(Segment::Quad(self.current, self.point(x1, y1), p));
        self.current = p;
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let p = self.point(x, y);
        self.segments.push(Segment::Cubic(
            self.current,
            self.point(x1, y1),
            self.point(x2, y2),
            p,
        ));
        self.current = p;
    }

    fn close(&mut self) {
        self.end_contour();
    }
}

/// The repository's shipped fonts for this crate's own tests, read from `fonts/` at
/// the workspace's top (the crate embeds no font: the explorer does).
#[cfg(test)]
impl Font {
    pub(crate) fn default_font() -> Self {
        Self::shipped(0)
    }

    pub(crate) fn shipped(index: usize) -> Self {
        let file = [
            "DejaVuSans.ttf",
            "lmroman10-regular.otf",
            "Inter-roman.var.ttf",
            "Lohit-Bengali.ttf",
        ][index];
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../fonts")
            .join(file);
        Self::from_path(&path).expect("the repository's shipped fonts parse")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axis_tags_are_space_padded_to_four_bytes() {
        assert_eq!(axis_tag("M1").unwrap(), "M1  ");
        assert_eq!(axis_tag(" HV ").unwrap(), "HV  ");
        assert_eq!(axis_tag("M1  ").unwrap(), "M1  ");
        assert_eq!(axis_tag("wght").unwrap(), "wght");
        for bad in ["", "   ", "wghts", "wé", "a b", "a\tb"] {
            assert!(axis_tag(bad).is_err(), "{bad:?}");
        }
    }

    #[test]
    fn a_collections_sfnt_version_is_its_first_faces() {
        // 'ttcf', version 1.0, one font, its offset table at byte 16.
        let mut data = b"ttcf\0\x01\0\0\0\0\0\x01\0\0\0\x10".to_vec();
        data.extend_from_slice(b"OTTO");
        assert_eq!(sfnt_version(&data, 0), Some(*b"OTTO"));
        assert_eq!(sfnt_version(b"\0\x01\0\0rest", 0), Some([0, 1, 0, 0]));
        assert_eq!(
            sfnt_version(b"ttcf\0\x01\0\0\0\0\0\x01\0\0\xff\xff", 0),
            None
        );
        assert_eq!(describe_sfnt_version(Some(*b"OTTO")), "'OTTO'");
        assert_eq!(describe_sfnt_version(Some([0, 1, 0, 0])), "0x00010000");
    }

    #[test]
    fn the_use_my_metrics_component_is_found_past_other_records() {
        let header = [0xFF, 0xFF, 0, 0, 0, 0, 0, 0, 0, 0]; // numberOfContours −1, bbox
        // Component 7: word arguments (4 bytes) and a scale (2 bytes), more to come.
        let first = [0x00, 0x2B, 0, 7, 0, 1, 0, 2, 0x40, 0];
        // Component 9: byte arguments (2 bytes), USE_MY_METRICS, the last.
        let second = [0x02, 0x02, 0, 9, 1, 2];
        let record = [&header[..], &first, &second].concat();
        assert_eq!(use_my_metrics_component(&record), Some(9));
        // Without the flag there is none; a simple glyph or a cut record has none.
        let unflagged = [&header[..], &first, &[0x00, 0x02, 0, 9, 1, 2]].concat();
        assert_eq!(use_my_metrics_component(&unflagged), None);
        assert_eq!(use_my_metrics_component(&[0, 1, 0, 0]), None);
        assert_eq!(use_my_metrics_component(&record[..14]), None);
    }
}
