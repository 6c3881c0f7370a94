//! Text → positioned glyphs with rustybuzz: kerning, ligatures and complex scripts from
//! the font's own tables, one shaping run per line. Each glyph advances by
//! [`Font::advance`] plus what shaping added to it, so the pen follows the same phantom
//! points as the outlines.

use std::collections::HashMap;

use glam::DVec2;

use crate::Error;
use crate::font::{Font, GlyphId};

/// A shaped glyph: its id and its origin (pen position plus offsets) in font units,
/// y up, with the first line's baseline at y = 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapedGlyph {
    pub glyph: GlyphId,
    pub position: DVec2,
}

/// `text` with its line breaks as '\n' (a literal backslash-n, for shells, and "\r\n"
/// included): the lines [`shape`] lays out.
pub fn line_breaks(text: &str) -> String {
    text.replace("\\n", "\n").replace("\r\n", "\n")
}

/// Shapes `text`, which may hold several lines separated by '\n' (a literal backslash-n
/// also breaks the line, for shells). Lines advance by the font's ascender − descender
/// + line gap. A character the font lacks is an error naming it, not a .notdef box.
pub fn shape(font: &Font, text: &str) -> Result<Vec<ShapedGlyph>, Error> {
    let text = line_breaks(text);
    if text.trim().is_empty() {
        return Err(Error::Input("the text is empty".into()));
    }
    let face = font.shaping_face();
    let metrics_face = font.face();
    // What each glyph's advance lacks from the font's own, worked out once per glyph.
    let mut corrections: HashMap<GlyphId, f64> = HashMap::new();
    let (ascender, descender, line_gap) = font.line_metrics();
    let line_advance = ascender - descender + line_gap;
    let mut glyphs = Vec::new();
    for (line_index, line) in text.split('\n').enumerate() {
        if line.is_empty() {
            continue;
        }
        let mut buffer = rustybuzz::UnicodeBuffer::new();
        buffer.push_str(line);
        buffer.guess_segment_properties();
        let shaped = rustybuzz::shape(&face, &[], buffer);
        let baseline = -(line_index as f64) * line_advance;
        let mut pen = DVec2::new(0.0, baseline);
        for (info, pos) in shaped.glyph_infos().iter().zip(shaped.glyph_positions()) {
            if info.glyph_id == 0 {
                let c = line[info.cluster as usize..].chars().next().unwrap_or('?');
                // Names the character and the font.
                font.glyph_for_char(c)?;
                return Err(Error::Input(format!(
                    "character {c:?} (U+{:04X}) shapes to no glyph in font '{}'",
                    u32::from(c),
                    font.name()
                )));
            }
            let glyph = info.glyph_id as GlyphId;
            glyphs.push(ShapedGlyph {
                glyph,
                position: pen + DVec2::new(f64::from(pos.x_offset), f64::from(pos.y_offset)),
            });
            // A mark the shaper zeroed keeps its zero.
            let correction = if pos.x_advance == 0 {
                0.0
            } else {
                *corrections.entry(glyph).or_insert_with(|| {
                    font.advance(glyph) - rustybuzz_advance(&metrics_face, glyph)
                })
            };
            pen += DVec2::new(
                f64::from(pos.x_advance) + correction,
                f64::from(pos.y_advance),
            );
        }
    }
    Ok(glyphs)
}

/// The advance rustybuzz 0.20 starts a glyph from (`glyph_advance` in its hb/face.rs):
/// `hmtx` plus `HVAR`, or, in a variable font without `HVAR`, plus the right phantom
/// point's gvar delta alone (FreeType takes pp2 − pp1), or, for a glyph with no gvar
/// data at a non-default instance, its bounding box's xMin + xMax. It also ignores
/// USE_MY_METRICS. [`shape`] replaces it with [`Font::advance`].
fn rustybuzz_advance(face: &ttf_parser::Face, glyph: GlyphId) -> f64 {
    let id = ttf_parser::GlyphId(glyph);
    let tables = face.tables();
    if face.is_variable()
        && face.has_non_default_variation_coordinates()
        && tables.hvar.is_none()
        && face.glyph_phantom_points(id).is_none()
    {
        return face
            .glyph_bounding_box(id)
            .map_or(0.0, |b| f64::from(b.x_min) + f64::from(b.x_max));
    }
    if tables.hmtx.is_some() {
        face.glyph_hor_advance(id).map_or(0.0, f64::from)
    } else {
        f64::from(face.units_per_em())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dejavu() -> Font {
        Font::default_font()
    }

    #[test]
    fn kerning_moves_glyphs_closer() {
        let font = dejavu();
        let av = shape(&font, "AV").unwrap();
        assert!(
            av[1].position.x < font.advance(av[0].glyph),
            "no kerning between A and V"
        );
    }

    #[test]
    fn ligature_merges_glyphs() {
        let font = dejavu();
        // DejaVu Sans has an "fi" ligature.
        assert_eq!(shape(&font, "fi").unwrap().len(), 1);
        assert_eq!(shape(&font, "f i").unwrap().len(), 3);
    }

    #[test]
    fn lines_stack_downwards() {
        let font = dejavu();
        let glyphs = shape(&font, "a\nb\\nc").unwrap();
        assert_eq!(glyphs.len(), 3);
        assert!(glyphs[0].position.y > glyphs[1].position.y);
        assert!(glyphs[1].position.y > glyphs[2].position.y);
        assert_eq!(glyphs[1].position.x, 0.0);
    }

    #[test]
    fn missing_character_is_named() {
        let font = dejavu();
        let err = shape(&font, "a\u{E000}b").unwrap_err().to_string();
        assert!(err.contains("U+E000"), "{err}");
    }

    #[test]
    fn empty_text_is_an_error() {
        assert!(shape(&dejavu(), "").is_err());
        assert!(shape(&dejavu(), " \n ").is_err());
    }
}
