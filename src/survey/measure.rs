//! One font file surveyed: each face's glyphs laid out in frames ([`super::grid`]) at
//! every size and transform, the reference and the traits worked out per glyph on every
//! core, every method drawing the whole frame once, and each glyph's slot compared with
//! its reference. Also keeps, per method, the tiles (coverage beside error) of its
//! worst glyphs, for the contact sheets.

use std::collections::HashMap;

use glam::{DMat2, DVec2};
use rayon::prelude::*;

use super::fonts;
use super::grid::{self, Slot};
use super::plan::{MethodRun, Plan, Transform};
use super::row::{Row, Verdict, file_safe};
use super::traits;
use crate::Error;
use crate::camera::Camera;
use crate::coverage::CoverageImage;
use crate::coverage::Png as _;
use crate::font::Font;
use crate::gpu::GpuContext;
use crate::methods::info::Trait;
use crate::methods::{Method, frame};
use crate::metrics::{self, ErrorStats};
use crate::reference;
use crate::scene::{Glyph, Instance, Scene};

/// How many of its worst glyphs each method keeps tiles of, per font: the report
/// shows the worst of all fonts, which are among each font's worst this many.
pub const WORST_KEPT: usize = 20;

/// What one font file gave: its rows, and the tiles of each method's worst glyphs
/// (named by [`tile_name`]).
pub struct FontResult {
    pub rows: Vec<Row>,
    pub tiles: Vec<(String, image::RgbImage)>,
}

/// The file name of a row's tile: its method, face, glyph, size and transform.
pub fn tile_name(row: &Row) -> String {
    let name = format!(
        "{}--{}--{}--{}--{}",
        row.method,
        row.face,
        row.glyph.map_or(String::new(), |g| g.to_string()),
        row.size,
        row.transform
    );
    let safe = file_safe(&name);
    format!("{safe}.png")
}

/// A glyph of a face, read once and shared by every frame.
struct FaceGlyph {
    glyph: Glyph,
    name: String,
    overlapping: bool,
}

/// Surveys every face of `file` by `plan`; `views_done` hears each frame's glyph
/// views as they finish.
pub fn font_file(
    gpu: &GpuContext,
    file: &std::path::Path,
    label: &str,
    plan: &Plan,
    mut views_done: impl FnMut(u64),
) -> FontResult {
    let mut result = FontResult {
        rows: Vec::new(),
        tiles: Vec::new(),
    };
    let (faces, collection) = fonts::faces(file, &plan.instances);
    for face in faces {
        let face_label = face.label(collection);
        match face.font {
            Err(why) => result.rows.push(Row::unmeasured(
                label,
                &face_label,
                Verdict::Unreadable,
                why,
            )),
            Ok(font) => {
                let context = FaceContext {
                    gpu,
                    font: &font,
                    font_label: label,
                    face_label: &face_label,
                    plan,
                };
                context.survey(&mut result, &mut views_done);
            }
        }
    }
    result
}

struct FaceContext<'a> {
    gpu: &'a GpuContext,
    font: &'a Font,
    font_label: &'a str,
    face_label: &'a str,
    plan: &'a Plan,
}

/// A method made for this face, or why it is not drawing.
struct Drawing {
    run: MethodRun,
    method: Result<Box<dyn Method>, (Verdict, String)>,
    /// Its worst rows so far, with their tiles, worst first.
    worst: Vec<(Row, image::RgbImage)>,
    /// The frames it refused or failed to draw: one row per size, transform and
    /// reason (a method that refuses a camera refuses every frame alike). Glyphs it
    /// refuses one by one (glyphon's, no character reaching them) are rows of their own.
    not_drawn: Vec<Row>,
}

impl FaceContext<'_> {
    fn unmeasured(&self, verdict: Verdict, reason: String) -> Row {
        Row::unmeasured(self.font_label, self.face_label, verdict, reason)
    }

    fn survey(&self, result: &mut FontResult, views_done: &mut impl FnMut(u64)) {
        let glyphs = self.read_glyphs(&mut result.rows);
        let mut drawings: Vec<Drawing> = self
            .plan
            .methods
            .iter()
            .map(|run| Drawing {
                method: run
                    .info
                    .create(&run.params)
                    .map_err(|e| (Verdict::Failed, format!("cannot be made: {e}"))),
                run: run.clone(),
                worst: Vec::new(),
                not_drawn: Vec::new(),
            })
            .collect();
        for &size in &self.plan.sizes {
            for transform in &self.plan.transforms {
                self.size_and_transform(&glyphs, size, transform, &mut drawings, result);
                // Blank and unreadable glyphs are views done too.
                views_done(self.plan.glyph_ids(self.font.glyph_count()).count() as u64);
            }
        }
        for drawing in drawings {
            if let Err((verdict, reason)) = &drawing.method {
                let mut row = self.unmeasured(*verdict, reason.clone());
                row.method = drawing.run.label.clone();
                result.rows.push(row);
            }
            result.rows.extend(drawing.not_drawn);
            for (row, tile) in drawing.worst {
                result.tiles.push((tile_name(&row), tile));
            }
        }
    }

    /// The face's glyphs in the plan's range: those with ink, each once; a malformed one
    /// is a row with its reason; blank ones (space) are left out.
    fn read_glyphs(&self, rows: &mut Vec<Row>) -> Vec<FaceGlyph> {
        let ids: Vec<u16> = self.plan.glyph_ids(self.font.glyph_count()).collect();
        let read: Vec<Result<Option<FaceGlyph>, (u16, String)>> = ids
            .par_iter()
            .map(|&id| {
                let outline = self.font.checked_outline(id).map_err(|why| (id, why))?;
                let Some(bounds) = outline.control_bounds() else {
                    return Ok(None);
                };
                Ok(Some(FaceGlyph {
                    overlapping: reference::overlapping_contours(&outline),
                    name: self.font.glyph_name(id).unwrap_or_default(),
                    glyph: Glyph::new(id, outline, bounds),
                }))
            })
            .collect();
        let mut glyphs = Vec::new();
        for r in read {
            match r {
                Ok(Some(g)) => glyphs.push(g),
                Ok(None) => {}
                Err((id, why)) => {
                    let mut row = self.unmeasured(Verdict::Unreadable, why);
                    row.glyph = Some(id);
                    rows.push(row);
                }
            }
        }
        glyphs
    }

    /// Every glyph at one size and transform, through every method.
    fn size_and_transform(
        &self,
        glyphs: &[FaceGlyph],
        size: f64,
        transform: &Transform,
        drawings: &mut [Drawing],
        result: &mut FontResult,
    ) {
        let matrix = transform.matrix();
        let placed: Vec<(u16, crate::geometry::Rect)> = glyphs
            .iter()
            .map(|g| (g.glyph.id, g.glyph.bounds))
            .collect();
        let upem = self.font.units_per_em();
        let (frames, too_large) = match grid::layout(&placed, upem, size, matrix) {
            Ok(laid) => laid,
            Err(e) => {
                let mut row = self.unmeasured(Verdict::Failed, format!("cannot lay out: {e}"));
                (row.size, row.transform) = (size, transform.name.clone());
                result.rows.push(row);
                return;
            }
        };
        for index in too_large {
            let mut row = self.unmeasured(
                Verdict::Unreadable,
                format!(
                    "larger than a {0}×{0} frame at this size",
                    grid::MAX_FRAME_SIDE
                ),
            );
            row.glyph = Some(glyphs[index].glyph.id);
            (row.size, row.transform) = (size, transform.name.clone());
            result.rows.push(row);
        }
        for laid in &frames {
            self.frame(glyphs, laid, size, transform, matrix, drawings, result);
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn frame(
        &self,
        glyphs: &[FaceGlyph],
        laid: &grid::Frame,
        size: f64,
        transform: &Transform,
        matrix: DMat2,
        drawings: &mut [Drawing],
        result: &mut FontResult,
    ) {
        let upem = self.font.units_per_em();
        let scene = Scene::from_font_glyphs(
            self.font,
            laid.slots
                .iter()
                .map(|s| glyphs[s.glyph].glyph.clone())
                .collect(),
            laid.slots
                .iter()
                .enumerate()
                .map(|(k, s)| Instance {
                    glyph: k as u32,
                    position: s.pen,
                })
                .collect(),
        );
        let mut camera = Camera::new(laid.width, laid.height, size, DVec2::ZERO);
        camera.matrix = matrix;
        // Each glyph's reference and traits, alone in a camera of its slot.
        let references: Vec<(Result<CoverageImage, Error>, Vec<Trait>)> = laid
            .slots
            .par_iter()
            .map(|slot| {
                let g = &glyphs[slot.glyph];
                let mut alone = Camera::new(slot.width, slot.height, size, slot.origin_in_slot);
                alone.matrix = matrix;
                let one = Scene::from_outlines(upem, vec![(g.glyph.outline.clone(), DVec2::ZERO)]);
                let to_image = alone.glyph_to_image(upem, DVec2::ZERO);
                let found = traits::of(
                    &g.glyph.outline,
                    g.overlapping,
                    &to_image,
                    alone.scale(upem),
                );
                (reference::rasterize(&one, &alone), found)
            })
            .collect();
        for drawing in drawings.iter_mut() {
            let Ok(method) = &mut drawing.method else {
                continue;
            };
            let image = method
                .prepare(self.gpu, &scene)
                .and_then(|()| frame::render_image(self.gpu, method.as_mut(), &camera));
            let image = match image {
                Ok(image) => image,
                // Said for this frame's size and transform; the method goes on with the
                // other frames. Where it refused some of this frame's glyphs one by one
                // (glyphon's, no character reaching them), every glyph view is a row of
                // its own: the refused ones with their reason, the others with the
                // frame's (a turned camera's, for glyphon).
                Err(e) => {
                    let refused: HashMap<u16, String> =
                        method.refused_glyphs().into_iter().collect();
                    if !refused.is_empty() {
                        for slot in &laid.slots {
                            let g = &glyphs[slot.glyph];
                            let why = refused.get(&g.glyph.id).cloned().unwrap_or(e.to_string());
                            let mut row = self.unmeasured(Verdict::Refused, why);
                            row.glyph = Some(g.glyph.id);
                            row.name = g.name.clone();
                            (row.size, row.transform) = (size, transform.name.clone());
                            row.method = drawing.run.label.clone();
                            result.rows.push(row);
                        }
                        continue;
                    }
                    let verdict = match e {
                        Error::Refused(_) => Verdict::Refused,
                        _ => Verdict::Failed,
                    };
                    let mut row = self.unmeasured(verdict, e.to_string());
                    (row.size, row.transform) = (size, transform.name.clone());
                    row.method = drawing.run.label.clone();
                    let said = drawing.not_drawn.iter().any(|r| {
                        (r.size, &r.transform, &r.reason) == (row.size, &row.transform, &row.reason)
                    });
                    if !said {
                        drawing.not_drawn.push(row);
                    }
                    continue;
                }
            };
            // Glyphs the method left undrawn (glyphon: those no character reaches).
            let refused: HashMap<u16, String> = method.refused_glyphs().into_iter().collect();
            for (slot, (reference, traits)) in laid.slots.iter().zip(&references) {
                let g = &glyphs[slot.glyph];
                let mut row = self.unmeasured(Verdict::Observed, String::new());
                row.glyph = Some(g.glyph.id);
                row.name = g.name.clone();
                (row.size, row.transform) = (size, transform.name.clone());
                row.method = drawing.run.label.clone();
                row.traits = traits::names(traits);
                (row.origin_x, row.origin_y) = slot.origin_in_slot.into();
                if let Some(why) = refused.get(&g.glyph.id) {
                    row.verdict = Verdict::Refused;
                    row.reason = why.clone();
                    result.rows.push(row);
                    continue;
                }
                let reference = match reference {
                    Ok(r) => r,
                    Err(e) => {
                        row.verdict = Verdict::Failed;
                        row.reason = format!("the reference: {e}");
                        result.rows.push(row);
                        continue;
                    }
                };
                let crop = crop(&image, slot);
                let stats = match metrics::compare(&crop, reference) {
                    Ok(stats) => stats,
                    Err(e) => {
                        row.verdict = Verdict::Failed;
                        row.reason = e.to_string();
                        result.rows.push(row);
                        continue;
                    }
                };
                judge(&mut row, &stats, &drawing.run, traits);
                keep_if_worst(&mut drawing.worst, &row, &crop, reference);
                result.rows.push(row);
            }
        }
    }
}

/// Fills `row`'s figures from `stats` and its verdict from the claim of `run` on a
/// glyph with `traits`.
fn judge(row: &mut Row, stats: &ErrorStats, run: &MethodRun, traits: &[Trait]) {
    row.max = stats.max;
    row.mae_255 = stats.mae_255;
    row.edge_mae_255 = stats.edge.mae_255;
    row.over_025 = stats.pixels_over_025;
    row.over_05 = stats.pixels_over_05;
    row.invalid = stats.invalid_pixels;
    (row.worst_x, row.worst_y) = stats.worst_pixel;
    let Some(claim) = run.claim else {
        row.verdict = Verdict::Observed;
        return;
    };
    let bound = claim.bound(traits);
    row.bound = bound.map_or(String::new(), |b| b.to_string());
    let holds = bound.is_none_or(|b| b.holds(stats.max, stats.mae_255, stats.edge.mae_255));
    row.verdict = match (holds, claim.is_limitation(traits)) {
        (false, _) => Verdict::Broken,
        (true, true) => Verdict::Limitation,
        (true, false) => Verdict::Ok,
    };
}

/// A slot's pixels of a frame.
fn crop(image: &CoverageImage, slot: &Slot) -> CoverageImage {
    let mut out = CoverageImage::new(slot.width, slot.height);
    for y in 0..slot.height {
        let from = ((slot.y + y) * image.width + slot.x) as usize;
        let to = (y * slot.width) as usize;
        out.data[to..to + slot.width as usize]
            .copy_from_slice(&image.data[from..from + slot.width as usize]);
    }
    out
}

/// Keeps `row` and its tile (the method's coverage beside its signed error, full at
/// 0.5) among the method's [`WORST_KEPT`] worst.
fn keep_if_worst(
    worst: &mut Vec<(Row, image::RgbImage)>,
    row: &Row,
    image: &CoverageImage,
    reference: &CoverageImage,
) {
    if worst.len() == WORST_KEPT
        && Row::worse(row, &worst[WORST_KEPT - 1].0) != std::cmp::Ordering::Less
    {
        return;
    }
    let at =
        worst.partition_point(|(kept, _)| Row::worse(kept, row) != std::cmp::Ordering::Greater);
    worst.insert(at, (row.clone(), tile(image, reference)));
    worst.truncate(WORST_KEPT);
}

/// Coverage (grey) and signed error (red: too much, blue: too little) side by side,
/// one pixel of white between.
pub fn tile(image: &CoverageImage, reference: &CoverageImage) -> image::RgbImage {
    let (w, h) = (image.width, image.height);
    let mut out = image::RgbImage::from_pixel(2 * w + 1, h, image::Rgb([255, 255, 255]));
    let grey = image.to_gray8();
    let error = metrics::error_image(image, reference, 0.5);
    for y in 0..h {
        for x in 0..w {
            let v = 255 - grey.get_pixel(x, y).0[0];
            out.put_pixel(x, y, image::Rgb([v, v, v]));
            out.put_pixel(w + 1 + x, y, *error.get_pixel(x, y));
        }
    }
    out
}

/// The rows' worst per method (for the report), keyed by method label.
pub fn worst_by_method(rows: &[Row], count: usize) -> HashMap<&str, Vec<&Row>> {
    let mut by: HashMap<&str, Vec<&Row>> = HashMap::new();
    for r in rows.iter().filter(|r| r.is_measured()) {
        by.entry(r.method.as_str()).or_default().push(r);
    }
    for list in by.values_mut() {
        list.sort_by(|a, b| Row::worse(a, b));
        list.truncate(count);
    }
    by
}
