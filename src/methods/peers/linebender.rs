//! What the two linebender renderers share (vello, vello-cpu): where the glyphs land
//! under an affine camera, and the scene as their types take it (peniko's font data,
//! kurbo's paths and affine maps).

use glam::{DMat2, DVec2};

use crate::Error;
use crate::camera::Camera;
use crate::scene::{Scene, SceneSource};

/// Where a scene's glyphs land in the image under an affine camera: one linear map for
/// every glyph (font units, y up → pixels, y down) and each instance's pen in pixels.
pub struct AffinePlacement {
    /// Font units to pixels, including the flip to y down.
    pub linear: DMat2,
    /// Each instance's pen position in image pixels, in the scene's instance order.
    pub pens: Vec<DVec2>,
}

impl AffinePlacement {
    /// The placement of `scene` through `camera`, or `peer`'s refusal of a tilt, which
    /// needs a perspective divide an affine renderer does not have.
    pub fn of(peer: &str, scene: &Scene, camera: &Camera) -> Result<AffinePlacement, Error> {
        if camera.tilt_deg != 0.0 {
            return Err(Error::Refused(format!(
                "{peer} draws affine transforms only: a tilt ({}°) needs perspective",
                camera.tilt_deg
            )));
        }
        let upem = scene.units_per_em;
        let pens = scene
            .instances
            .iter()
            .map(|i| {
                let to_image = camera.glyph_to_image(upem, i.position);
                to_image.z_axis.truncate()
            })
            .collect();
        let to_image = camera.glyph_to_image(upem, DVec2::ZERO);
        let linear = DMat2::from_cols(to_image.x_axis.truncate(), to_image.y_axis.truncate());
        Ok(AffinePlacement { linear, pens })
    }
}

/// What the linebender peers (vello, vello_cpu) draw of a scene: the font's glyphs by
/// id, from the same bytes and variation coordinates, or — for synthetic outlines, which
/// no font holds — the outlines as paths.
pub enum LinebenderScene {
    Glyphs {
        font: peniko::FontData,
        coords: Vec<i16>,
        /// Each instance's glyph id.
        ids: Vec<u32>,
        scene: Scene,
    },
    Paths {
        /// One per distinct glyph, in font units (y up).
        paths: Vec<kurbo::BezPath>,
        scene: Scene,
    },
}

impl LinebenderScene {
    pub fn of(scene: &Scene) -> LinebenderScene {
        match &scene.source {
            Some(source) => {
                let (font, coords) = font_data(source);
                LinebenderScene::Glyphs {
                    font,
                    coords,
                    ids: scene
                        .instances
                        .iter()
                        .map(|i| u32::from(scene.glyphs[i.glyph as usize].id))
                        .collect(),
                    scene: scene.clone(),
                }
            }
            None => LinebenderScene::Paths {
                paths: scene
                    .glyphs
                    .iter()
                    .map(|g| crate::geometry::kurbo_path(&g.outline.contours))
                    .collect(),
                scene: scene.clone(),
            },
        }
    }
}

/// The font of a scene made from one, as the linebender crates take it (the same
/// bytes), and its variation coordinates, normalized as the font's `fvar` and `avar`
/// define them.
pub fn font_data(source: &SceneSource) -> (peniko::FontData, Vec<i16>) {
    let bytes = source.font.data();
    let blob = peniko::Blob::new(std::sync::Arc::new(bytes));
    let coords = source
        .font
        .face()
        .variation_coordinates()
        .iter()
        .map(|c| c.get())
        .collect();
    (peniko::FontData::new(blob, 0), coords)
}

/// A kurbo affine map from a 2×2 linear part and a translation.
pub fn affine(linear: DMat2, translation: DVec2) -> kurbo::Affine {
    kurbo::Affine::new([
        linear.x_axis.x,
        linear.x_axis.y,
        linear.y_axis.x,
        linear.y_axis.y,
        translation.x,
        translation.y,
    ])
}
