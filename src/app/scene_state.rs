//! The font and scene the explorer shows, built from [`SceneSettings`] (font file,
//! variations, text or one glyph) and rebuilt only when they change. A font or scene
//! that cannot be built is kept as its error, for the controls to show.

use std::sync::Arc;

use super::settings::{FontChoice, SceneSettings};
use crate::camera::Camera;
use crate::font::{Font, SHIPPED_FONTS, axis_tag};
use crate::named_views;
use crate::scene::Scene;

/// The scene built from [`SceneSettings`], rebuilt only when they change.
#[derive(Default)]
pub struct SceneState {
    built_for: Option<SceneSettings>,
    font: Option<(FontChoice, Result<Font, String>)>,
    scene: Option<Result<Arc<Scene>, String>>,
    /// The scene with overlapping contours merged, made the first time a pane asks.
    merged: std::cell::OnceCell<Arc<Scene>>,
    /// A named view's own camera, when the scene is one.
    case_camera: Option<Camera>,
    generation: u64,
}

impl SceneState {
    pub fn sync(&mut self, wanted: &SceneSettings) {
        if self.is_built_for(wanted) {
            return;
        }
        self.built_for = Some(wanted.clone());
        self.generation += 1;
        self.merged = Default::default();
        if self.font.as_ref().map(|(c, _)| c) != Some(&wanted.font) {
            let font = match &wanted.font {
                FontChoice::Shipped(i) if *i < SHIPPED_FONTS.len() => Ok(crate::font::shipped(*i)),
                FontChoice::Shipped(i) => Err(format!("there is no shipped font {i}")),
                FontChoice::File(path) => Font::from_path(path).map_err(|e| e.to_string()),
                FontChoice::Opened { name, bytes } => {
                    Font::from_bytes(bytes.0.to_vec(), name).map_err(|e| e.to_string())
                }
            };
            self.font = Some((wanted.font.clone(), font));
        }
        self.case_camera = None;
        if let Some(name) = &wanted.case {
            let built = named_views::build(name).map_err(|e| e.to_string());
            self.scene = Some(built.map(|(scene, camera)| {
                self.case_camera = Some(camera);
                Arc::new(scene)
            }));
            return;
        }
        let font = self.font.as_ref().expect("set above").1.clone();
        self.scene = Some(font.and_then(|font| build_scene(&font, wanted)));
    }

    /// The camera of the named view the scene is, if it is one.
    pub fn case_camera(&self) -> Option<&Camera> {
        self.case_camera.as_ref()
    }

    pub fn is_built_for(&self, wanted: &SceneSettings) -> bool {
        self.built_for.as_ref() == Some(wanted)
    }

    /// Counts the rebuilds: what was made for an earlier scene carries a smaller number.
    pub fn generation(&self) -> u64 {
        self.generation
    }

    pub fn font(&self) -> Option<&Font> {
        self.font.as_ref().and_then(|(_, f)| f.as_ref().ok())
    }

    pub fn scene(&self) -> Option<&Arc<Scene>> {
        self.scene.as_ref().and_then(|s| s.as_ref().ok())
    }

    /// The scene with overlapping contours merged (see [`Scene::with_overlaps_merged`]).
    pub fn merged_scene(&self) -> Option<&Arc<Scene>> {
        let scene = self.scene()?;
        Some(
            self.merged
                .get_or_init(|| Arc::new(scene.with_overlaps_merged())),
        )
    }

    /// Why the scene could not be built (a font that fails fails the scene built from
    /// it; a case's scene needs no font).
    pub fn problem(&self) -> Option<String> {
        self.scene.as_ref().and_then(|s| s.as_ref().err().cloned())
    }

    pub fn units_per_em(&self) -> f64 {
        self.scene().map_or(1000.0, |s| s.units_per_em)
    }
}

fn build_scene(font: &Font, wanted: &SceneSettings) -> Result<Arc<Scene>, String> {
    // Axes the font lacks (left from another font) are ignored, not an error.
    let axes = font.axes();
    let variations: Vec<(String, f32)> = wanted
        .variations
        .iter()
        .filter(|(tag, _)| axis_tag(tag).is_ok_and(|tag| axes.iter().any(|a| a.tag == tag)))
        .cloned()
        .collect();
    let font = font
        .with_variations(&variations)
        .map_err(|e| e.to_string())?;
    let scene = if wanted.glyph_mode {
        let spec = wanted.glyph.trim();
        let id = match spec.strip_prefix('#') {
            Some(n) => n
                .trim()
                .parse::<u32>()
                .map_err(|_| format!("'{spec}': give a character, or # and a glyph id"))?,
            None => {
                let c = spec
                    .chars()
                    .next()
                    .ok_or("glyph mode: give a character or #id")?;
                u32::from(font.glyph_for_char(c).map_err(|e| e.to_string())?)
            }
        };
        Scene::from_glyph_id(&font, id)
    } else {
        Scene::from_text(&font, &wanted.text)
    };
    scene.map(Arc::new).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn glyph_mode_takes_a_character_or_an_id() {
        let font = crate::font::default_font();
        let mut s = SceneSettings {
            glyph_mode: true,
            glyph: "g".into(),
            ..Default::default()
        };
        let by_char = build_scene(&font, &s).unwrap();
        s.glyph = format!("#{}", by_char.glyphs[0].id);
        let by_id = build_scene(&font, &s).unwrap();
        assert_eq!(by_char.glyphs[0].id, by_id.glyphs[0].id);
        s.glyph = "#99999".into();
        assert!(build_scene(&font, &s).unwrap_err().contains("out of range"));
    }
}
