//! The `ui` scene of `glyphscope bench --library`, and the labels of
//! `examples/ui_labels.rs`: a UI's worth of short labels — each one or two words at one
//! of the sizes a UI uses, 10–32 px, laid out in rows over a 1920×1080 target as a
//! settings panel, a file list or a node editor lays them — drawn as an app draws
//! them, a run (or a glyphon buffer) per label.
//!
//! The labels are made by a fixed sequence (the same every run), their rows as tall as
//! their text needs, so that labels never overlap until the target is full; past that
//! (thousands of labels) the rows start again from the top a few pixels lower, over the
//! first ones. Their reference is one synthetic scene of every label's glyphs in the
//! target's pixels ([`scene`]), which the atlas baseline draws too.

use std::collections::HashMap;

use glam::DVec2;

use crate::Error;
use crate::camera::Camera;
use crate::font::Font;
use crate::geometry::{Contour, Outline, Rect};
use crate::scene::{Glyph, Instance, Scene};

/// The target the labels are laid out on.
pub const SIZE: [u32; 2] = [1920, 1080];
/// The labels of the `ui` scene.
pub const LABELS: usize = 500;
/// The synthetic scene's units per em: its units are the target's pixels (the camera
/// draws it at one pixel a unit), and 32 is the largest label size, so that what a
/// method scales by the em (tolerances, the atlas's cache size) is what it is at 32 px.
pub const SCENE_UNITS_PER_EM: f64 = 32.0;

/// One label: its text, its size and where its first baseline starts, target pixels.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    pub text: String,
    pub size_px: f32,
    pub x: f32,
    pub y: f32,
}

/// What labels say: the words of menus, panels and lists.
const WORDS: &[&str] = &[
    "File",
    "Edit",
    "View",
    "Window",
    "Help",
    "Open",
    "Save",
    "Export",
    "Layers",
    "Brush",
    "Opacity",
    "Blend",
    "Normal",
    "Multiply",
    "Width",
    "Height",
    "Position",
    "Rotation",
    "Scale",
    "Anchor",
    "Visible",
    "Locked",
    "Name",
    "Type",
    "Size",
    "Modified",
    "Today",
    "Yesterday",
    "12:04",
    "3.2 MB",
    "42 px",
    "110%",
    "Settings",
    "Fonts",
    "Kerning",
    "Tracking",
    "Baseline",
    "Glyphs",
    "Outline",
    "Fill",
    "Stroke",
    "Shadow",
    "Node",
    "Input",
    "Output",
    "Mix",
    "Color",
    "Vector",
    "Math",
    "Texture",
    "Search…",
    "Cancel",
    "Apply",
    "OK",
    "Street",
    "Avenue",
    "Quartz",
    "Wave",
    "Jump",
    "Fjord",
];

/// The sizes a UI's labels take, pixels per em.
const SIZES: &[f32] = &[
    10.0, 11.0, 12.0, 13.0, 14.0, 16.0, 18.0, 20.0, 24.0, 28.0, 32.0,
];

/// A fixed pseudo-random sequence (a 64-bit LCG): the same labels every run.
struct Sequence(u64);

impl Sequence {
    fn below(&mut self, n: usize) -> usize {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((self.0 >> 33) as usize) % n
    }
}

/// `count` labels in `font` over a target of `size` pixels: rows left to right, each
/// row's labels at one size, a gap of half an em between labels; when the rows reach
/// the bottom they start again at the top, 7 px lower and 11 px further right.
pub fn labels(font: &Font, count: usize, size: [u32; 2]) -> Result<Vec<Label>, Error> {
    let mut random = Sequence(0x5EED_0F1A_B315);
    let [width, height] = size.map(|v| v as f32);
    let (ascender, descender, _) = font.line_metrics();
    let units = font.units_per_em();
    let mut out = Vec::with_capacity(count);
    let mut pass = 0u32;
    let (mut x, mut row_top) = (0.0f32, 0.0f32);
    let mut row_size = SIZES[random.below(SIZES.len())];
    let mut widths: HashMap<String, f64> = HashMap::new();
    while out.len() < count {
        let words = 1 + random.below(2);
        let text: Vec<&str> = (0..words)
            .map(|_| WORDS[random.below(WORDS.len())])
            .collect();
        let text = text.join(" ");
        let advance_units = match widths.get(&text) {
            Some(&w) => w,
            None => {
                let w = ink_right(font, &text)?;
                widths.insert(text.clone(), w);
                w
            }
        };
        let line = row_size * ((ascender - descender) / units) as f32 * 1.2;
        let label_width = (advance_units / units) as f32 * row_size;
        let margin = 8.0 + (pass as f32 * 11.0) % 40.0;
        if x == 0.0 {
            x = margin;
        }
        if x + label_width > width - 8.0 {
            if x == margin {
                // Wider than a row: not a label a UI would have.
                continue;
            }
            // The next row, at a size of its own.
            row_top += line;
            x = margin;
            row_size = SIZES[random.below(SIZES.len())];
            continue;
        }
        if row_top + line > height {
            pass += 1;
            row_top = (pass as f32 * 7.0) % 30.0;
            x = 0.0;
            continue;
        }
        let baseline = row_top + row_size * (ascender / units) as f32 * 1.1;
        out.push(Label {
            text,
            size_px: row_size,
            x,
            y: baseline,
        });
        x += label_width + row_size * 0.5;
    }
    Ok(out)
}

/// How far right of its pen `text`'s ink reaches, font units.
fn ink_right(font: &Font, text: &str) -> Result<f64, Error> {
    let scene = Scene::from_text(font, text)?;
    Ok(scene
        .instances
        .iter()
        .map(|i| i.position.x + scene.glyphs[i.glyph as usize].bounds.max.x)
        .fold(0.0, f64::max))
}

/// Whether any two labels' ink boxes (grown by a pixel) overlap: then the scene's
/// reference, which fills the union of everything drawn, is not what compositing the
/// labels one over another gives, and errors against it are not the methods'.
pub fn any_overlap(font: &Font, labels: &[Label]) -> Result<bool, Error> {
    let boxes: Vec<Rect> = labels
        .iter()
        .map(|l| {
            let scene = Scene::from_text(font, &l.text)?;
            let camera = label_camera(l, SIZE);
            Ok(grown(camera.ink_bounds(&scene)?, 1.0))
        })
        .collect::<Result<_, Error>>()?;
    Ok(crate::geometry::overlapping_groups(&boxes)
        .iter()
        .any(|g| g.len() > 1))
}

fn grown(r: Rect, by: f64) -> Rect {
    Rect {
        min: r.min - by,
        max: r.max + by,
    }
}

/// The camera drawing `label`'s text alone (font units) into a target of `size`.
fn label_camera(label: &Label, size: [u32; 2]) -> Camera {
    Camera::new(
        size[0],
        size[1],
        f64::from(label.size_px),
        DVec2::new(f64::from(label.x), f64::from(label.y)),
    )
}

/// Every label's glyphs in one synthetic scene whose units are the target's pixels
/// (y up; draw it with [`camera`]): each glyph at each size once, as an atlas caches
/// it.
pub fn scene(font: &Font, labels: &[Label]) -> Result<Scene, Error> {
    let units = font.units_per_em();
    let mut glyphs = Vec::new();
    let mut index: HashMap<(u32, u32), u32> = HashMap::new();
    let mut instances = Vec::new();
    for label in labels {
        let text = Scene::from_text(font, &label.text)?;
        let k = f64::from(label.size_px) / units;
        for instance in &text.instances {
            let glyph = &text.glyphs[instance.glyph as usize];
            let key = (glyph.id as u32, label.size_px.to_bits());
            let slot = *index.entry(key).or_insert_with(|| {
                let outline = Outline {
                    contours: glyph
                        .outline
                        .contours
                        .iter()
                        .map(|c| Contour {
                            segments: c.segments.iter().map(|s| s.map(|p| p * k)).collect(),
                        })
                        .collect(),
                };
                let bounds = Rect {
                    min: glyph.bounds.min * k,
                    max: glyph.bounds.max * k,
                };
                glyphs.push(Glyph::new(glyph.id, outline, bounds));
                glyphs.len() as u32 - 1
            });
            // Image (x, y) is scene (x, −y): the pen, y up.
            let pen = DVec2::new(
                f64::from(label.x) + instance.position.x * k,
                -f64::from(label.y) + instance.position.y * k,
            );
            instances.push(Instance {
                glyph: slot,
                position: pen,
            });
        }
    }
    Ok(Scene {
        units_per_em: SCENE_UNITS_PER_EM,
        glyphs,
        instances,
        source: None,
    })
}

/// The camera of [`scene`]: one pixel a unit, the target's top left at the origin.
pub fn camera() -> Camera {
    Camera::new(SIZE[0], SIZE[1], SCENE_UNITS_PER_EM, DVec2::ZERO)
}
