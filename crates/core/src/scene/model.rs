//! A scene: glyph instances (which glyph, where) and the set of distinct glyphs they
//! use, as shaped text, a glyph by its id or synthetic outlines.

use std::collections::HashMap;
use std::sync::{Arc, OnceLock};

use glam::DVec2;

use crate::Error;
use crate::font::{Font, GlyphId};
use crate::geometry::{Outline, Rect};
use crate::shaping;

/// A distinct glyph: its outline in font units and the bounds of its control points.
#[derive(Clone, Debug)]
pub struct Glyph {
    pub id: GlyphId,
    pub outline: Outline,
    pub bounds: Rect,
    /// The outline is a nonzero union of contours ([`Scene::with_overlaps_merged`]):
    /// its winding number is 0 or its fill sign everywhere, and its contours meet, if
    /// at all, only by touching.
    pub merged: bool,
    /// The outline's nonzero union where it differs from the outline, taken on first use
    /// and shared by every copy of the glyph: the methods that merge overlaps, their
    /// re-preparations when a parameter changes, and the explorer's overlay take it once.
    union: Arc<OnceLock<Option<Outline>>>,
}

impl Glyph {
    pub fn new(id: GlyphId, outline: Outline, bounds: Rect) -> Glyph {
        Glyph {
            id,
            outline,
            bounds,
            merged: false,
            union: Arc::default(),
        }
    }

    /// [`crate::geometry::merge_overlaps`] of the outline, once: None where the outline
    /// is its own union, or where the union cannot be taken (the glyph is then drawn as
    /// the font has it).
    pub fn union(&self, units_per_em: f64) -> Option<&Outline> {
        self.union
            .get_or_init(|| {
                crate::geometry::merge_overlaps(&self.outline, units_per_em)
                    .ok()
                    .flatten()
            })
            .as_ref()
    }
}

/// One drawn copy of a glyph.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Instance {
    /// Index into [`Scene::glyphs`].
    pub glyph: u32,
    /// The glyph's origin in font units, y up.
    pub position: DVec2,
}

#[derive(Clone, Debug)]
pub struct Scene {
    pub units_per_em: f64,
    /// Distinct glyphs with ink, in order of first use.
    pub glyphs: Vec<Glyph>,
    /// Instances of glyphs with ink (blank glyphs such as spaces are left out).
    pub instances: Vec<Instance>,
    /// The font (and text) the scene was made from; None for synthetic outlines.
    pub source: Option<SceneSource>,
}

/// What a scene was made from, for renderers that take a font's glyphs, or its text,
/// rather than outlines: the peers draw from the same font bytes and variations.
#[derive(Clone, Debug)]
pub struct SceneSource {
    pub font: Font,
    /// The text shaped, lines separated by '\n'; None for a glyph drawn by its id.
    pub text: Option<String>,
}

impl Scene {
    /// The same scene with each glyph whose contours overlap replaced by their nonzero
    /// union ([`crate::geometry::merge_overlaps`]): what a method with `overlaps=merge`
    /// draws from. A glyph whose union cannot be taken is kept as it is.
    pub fn with_overlaps_merged(&self) -> Scene {
        let glyphs = self
            .glyphs
            .iter()
            .map(|glyph| match glyph.union(self.units_per_em) {
                Some(union) => Glyph {
                    merged: true,
                    ..Glyph::new(glyph.id, union.clone(), glyph.bounds)
                },
                None => glyph.clone(),
            })
            .collect();
        Scene {
            units_per_em: self.units_per_em,
            glyphs,
            instances: self.instances.clone(),
            source: self.source.clone(),
        }
    }

    /// Shapes `text` (possibly several lines) in `font`. Text that draws nothing (only
    /// blank glyphs) is an error: a scene to look at has something in it.
    pub fn from_text(font: &Font, text: &str) -> Result<Scene, Error> {
        let scene = Self::from_text_or_blank(font, text)?;
        if scene.instances.is_empty() {
            return Err(Error::Input(
                "the text draws nothing (it is empty, or only blank glyphs)".into(),
            ));
        }
        Ok(scene)
    }

    /// Shapes `text` in `font` as [`Scene::from_text`] does, but text that draws
    /// nothing (empty, or only blank glyphs) is an empty scene: a UI's empty label.
    pub fn from_text_or_blank(font: &Font, text: &str) -> Result<Scene, Error> {
        if shaping::line_breaks(text).trim().is_empty() {
            return Ok(Self::build(font, std::iter::empty()));
        }
        let shaped = shaping::shape(font, text)?;
        let mut scene = Self::build(font, shaped.iter().map(|g| (g.glyph, g.position)));
        if let Some(source) = &mut scene.source {
            source.text = Some(shaping::line_breaks(text));
        }
        Ok(scene)
    }

    /// One glyph, by id, at the origin.
    pub fn from_glyph_id(font: &Font, id: u32) -> Result<Scene, Error> {
        let id = font.check_glyph_id(id)?;
        let scene = Self::build(font, [(id, DVec2::ZERO)]);
        if scene.instances.is_empty() {
            return Err(Error::Input(format!(
                "glyph {id} of '{}' has no outline",
                font.name()
            )));
        }
        Ok(scene)
    }

    fn build(font: &Font, placed: impl IntoIterator<Item = (GlyphId, DVec2)>) -> Scene {
        let mut slots: HashMap<GlyphId, Option<u32>> = HashMap::new();
        let mut glyphs = Vec::new();
        let mut instances = Vec::new();
        for (id, position) in placed {
            let slot = *slots.entry(id).or_insert_with(|| {
                let outline = font.outline(id);
                let bounds = outline.control_bounds()?;
                glyphs.push(Glyph::new(id, outline, bounds));
                Some(glyphs.len() as u32 - 1)
            });
            if let Some(glyph) = slot {
                instances.push(Instance { glyph, position });
            }
        }
        Self::from_font_glyphs(font, glyphs, instances)
    }

    /// Glyphs of `font` already read (each with ink), placed by `instances`: a scene
    /// built from outlines checked once and shared by many frames (the survey's).
    pub fn from_font_glyphs(font: &Font, glyphs: Vec<Glyph>, instances: Vec<Instance>) -> Scene {
        Scene {
            units_per_em: font.units_per_em(),
            glyphs,
            instances,
            source: Some(SceneSource {
                font: font.clone(),
                text: None,
            }),
        }
    }

    /// A synthetic scene: each outline is its own distinct glyph, placed at its position.
    /// Empty outlines are left out.
    pub fn from_outlines(units_per_em: f64, placed: Vec<(Outline, DVec2)>) -> Scene {
        let mut glyphs = Vec::new();
        let mut instances = Vec::new();
        for (outline, position) in placed {
            let Some(bounds) = outline.control_bounds() else {
                continue;
            };
            instances.push(Instance {
                glyph: glyphs.len() as u32,
                position,
            });
            glyphs.push(Glyph::new(glyphs.len() as GlyphId, outline, bounds));
        }
        Scene {
            units_per_em,
            glyphs,
            instances,
            source: None,
        }
    }

    /// Bounds of all instances' control points, font units.
    pub fn ink_bounds(&self) -> Option<Rect> {
        self.instances
            .iter()
            .map(|i| {
                let b = self.glyphs[i.glyph as usize].bounds;
                Rect {
                    min: b.min + i.position,
                    max: b.max + i.position,
                }
            })
            .reduce(Rect::union)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distinct_glyphs_are_shared_by_instances() {
        let scene = Scene::from_text(&Font::default_font(), "abab a").unwrap();
        assert_eq!(scene.glyphs.len(), 2);
        assert_eq!(scene.instances.len(), 5, "the space draws nothing");
        assert_eq!(scene.instances[0].glyph, scene.instances[2].glyph);
    }

    /// The union is taken once per glyph and shared by the scene's copies (each method
    /// that merges gets its own copy of the scene); a glyph that is its own union stays.
    #[test]
    fn a_glyphs_union_is_taken_once_for_every_copy() {
        let square = |x: f64| {
            let p = [(x, 0.0), (x + 100.0, 0.0), (x + 100.0, 100.0), (x, 100.0)]
                .map(|(x, y)| DVec2::new(x, y));
            crate::geometry::Contour {
                segments: (0..4)
                    .map(|i| crate::geometry::Segment::Line(p[i], p[(i + 1) % 4]))
                    .collect(),
            }
        };
        let overlapping = Outline {
            contours: vec![square(0.0), square(50.0)],
        };
        let alone = Outline {
            contours: vec![square(0.0)],
        };
        let scene = Scene::from_outlines(
            1000.0,
            vec![
                (overlapping.clone(), DVec2::ZERO),
                (alone.clone(), DVec2::ZERO),
            ],
        );
        assert!(scene.glyphs.iter().all(|g| g.union.get().is_none()));
        let merged = scene.clone().with_overlaps_merged();
        let union = crate::geometry::merge_overlaps(&overlapping, 1000.0)
            .unwrap()
            .unwrap();
        assert_eq!(merged.glyphs[0].outline, union);
        assert_eq!(merged.glyphs[1].outline, alone);
        // The original saw its copy's union: the next merge takes none again.
        assert_eq!(scene.glyphs[0].union.get(), Some(&Some(union)));
        assert_eq!(scene.glyphs[1].union.get(), Some(&None));
    }

    #[test]
    fn bengali_shapes_into_conjuncts() {
        let font = Font::shipped(3);
        // ক + ্ + ষ (three code points) form the conjunct ক্ষ: fewer glyphs than
        // characters, and a glyph that none of the three characters maps to alone.
        let text = "\u{0995}\u{09CD}\u{09B7}";
        let scene = Scene::from_text(&font, text).unwrap();
        assert!(
            scene.instances.len() < 3,
            "{} glyphs",
            scene.instances.len()
        );
        let singles: Vec<_> = text
            .chars()
            .map(|c| font.glyph_for_char(c).unwrap())
            .collect();
        assert!(
            scene.glyphs.iter().any(|g| !singles.contains(&g.id)),
            "no conjunct glyph"
        );
        // DejaVu Sans has no Bengali: the error names the character.
        let err = Scene::from_text(&Font::default_font(), text)
            .unwrap_err()
            .to_string();
        assert!(err.contains("U+0995"), "{err}");
    }

    #[test]
    fn glyph_id_out_of_range_is_an_error() {
        let font = Font::default_font();
        let err = Scene::from_glyph_id(&font, 70_000).unwrap_err().to_string();
        assert!(err.contains("out of range"), "{err}");
    }
}
