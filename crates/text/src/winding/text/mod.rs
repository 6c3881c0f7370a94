//! Text in colour, drawn with `winding`'s exact coverage into a render pass the caller
//! owns: the library other wgpu and egui apps use, re-exported at the crate's root
//! (docs/library.md).
//!
//! One implementation: the explorer's `winding` row and this renderer prepare glyphs
//! with the same [`GlyphData::push`](super::GlyphData::push), join overlapping
//! instances and merge overlapping contours the same way (`between=union`,
//! `overlaps=merge`), and draw coverage with the same shader and pipelines into the same
//! kind of half-float target, its instances added (so glyphs sharing a pixel sum to
//! their union's coverage, as in the row). Each run's coverage goes into its own
//! rectangle of pixels — the pixels its glyphs touch, within the viewport — packed with
//! the other runs' into pages (`pages.rs`); `render` then blends each run's colour over
//! the caller's target through its rectangle (`winding_text.wgsl`), once, in the runs'
//! order. So a frame's cost grows with the pixels the text covers, as an atlas's does,
//! and runs are limited by memory alone.
//!
//! Text in motion skips the pages where it can: in a frame whose runs moved, as they
//! did in the frame before, a glyph that meets no glyph of its own run (whose coverage
//! it would have to be added to) and would not have to land over a glyph that goes
//! through the pages (`sharing.rs`) is drawn by `render` straight into the caller's
//! target in its run's colour — exact there, since its coverage is the pixel's, and in
//! the runs' order within its draw. That drops, for most of a UI's glyphs, the page's
//! clear, its half-float blend and the composite. A frame that follows a still one, or
//! the first still frame after motion, draws everything into the pages, which the still
//! frames after it composite without drawing anything.
//!
//! What is kept between frames: every glyph prepared (per font and outline, so a glyph
//! met again in any run is not prepared again), every run's layout (per font and
//! content), and the runs as last drawn. A frame whose runs are the same as the last
//! frame's uploads and draws nothing but the composite (the first after motion draws
//! them into the pages once); one that only recolours them
//! uploads the composite's records; one that moves them draws their coverage anew
//! ([`TextRenderer::last_uploads`] counts the bytes). [`TextRenderer::trim`] drops what
//! no frame used since the last trim.
// What other apps call: every public item says what it is.
#![deny(missing_docs)]

mod glyphs;
mod layouts;
mod pages;
mod sharing;

use std::ops::Range;
use std::sync::Arc;

use glam::{DMat3, DVec2, DVec3, Mat3};

use super::{Output, Settings, Variant, Winding};
use crate::Error;
use crate::camera::Camera;
use crate::font::Font;
use crate::geometry::{Rect, keeps_axes};
use crate::gpu::instances::{GpuInstance, Instances};
use crate::gpu::{Channels, GpuContext};
use crate::scene::{Glyph, Instance, Scene};
use glyphs::PreparedGlyphs;
pub use layouts::PositionedGlyph;
use layouts::{ContentRef, LayoutCache, RunLayout};
use pages::{Composite, CompositeRun, Pages, PixelRect, Placement};
use sharing::GlyphKey;

/// A font added to a [`TextRenderer`] ([`TextRenderer::add_font`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FontId(usize);

/// What a run draws.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Content<'a> {
    /// A string, shaped by glyphscope's shaping (rustybuzz; `\n` starts a new line one
    /// line height down).
    Text(&'a str),
    /// Glyphs already shaped, by id and position.
    Glyphs(&'a [PositionedGlyph]),
}

/// One run of text: a font, what it draws, at what size, where and in what colour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TextRun<'a> {
    /// The font, as [`TextRenderer::add_font`] returned it.
    pub font: FontId,
    /// The text or glyphs drawn.
    pub content: Content<'a>,
    /// Pixels per em in the run's text space.
    pub size_px: f32,
    /// From the run's text space (pixels, y down, its first baseline's start at the
    /// origin) to the target's pixels: any 3×3 projective map whose bottom row keeps the
    /// text in front of the eye. `Mat3::IDENTITY` draws the run at the target's top
    /// left corner, its baseline on y = 0.
    pub transform: Mat3,
    /// Colour, not premultiplied: sRGB components on an sRGB target (blended in linear
    /// light, as the target converts), the target's own components on any other; alpha
    /// last. Each in 0..=1.
    pub color: [f32; 4],
}

/// What the last [`TextRenderer::prepare`] uploaded, bytes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Uploads {
    /// Glyph outlines and bands (only when a glyph not met before was prepared).
    pub glyph_bytes: u64,
    /// Per-instance transforms, the runs' rectangles and colours, and the target size
    /// (only when they changed).
    pub instance_bytes: u64,
}

/// What a [`TextRenderer`] holds on the GPU, bytes ([`TextRenderer::held`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Held {
    /// Every prepared glyph's outline and bands.
    pub glyph_bytes: u64,
    /// The instance buffers (the pages' and the target's).
    pub instance_bytes: u64,
    /// The pages the runs' coverage is drawn into (half-float, the pixels the text
    /// covers, packed), and the runs' composite records.
    pub coverage_bytes: u64,
}

impl Held {
    /// All of it.
    pub fn total(&self) -> u64 {
        self.glyph_bytes + self.instance_bytes + self.coverage_bytes
    }
}

/// Draws text with `winding`'s exact box-filter coverage into a caller's render pass.
///
/// ```no_run
/// # fn demo(device: &wgpu::Device, queue: &wgpu::Queue, encoder: &mut wgpu::CommandEncoder, pass: &mut wgpu::RenderPass<'_>) -> Result<(), glyphscope_text::Error> {
/// use glyphscope_text::{Content, TextRenderer, TextRun, glam};
/// let mut text = TextRenderer::new(device, queue, wgpu::TextureFormat::Bgra8UnormSrgb);
/// let font = text.add_font(std::fs::read("fonts/DejaVuSans.ttf").unwrap())?;
/// let run = TextRun {
///     font,
///     content: Content::Text("Sharp at any zoom"),
///     size_px: 32.0,
///     transform: glam::Mat3::from_translation(glam::vec2(20.0, 60.0)),
///     color: [0.1, 0.1, 0.1, 1.0],
/// };
/// text.prepare(encoder, [800, 600], &[run])?;
/// text.render(pass);
/// // Once the frame is drawn: forget what it did not use.
/// text.trim();
/// # Ok(()) }
/// ```
pub struct TextRenderer {
    gpu: GpuContext,
    format: wgpu::TextureFormat,
    winding: Winding,
    fonts: Vec<Font>,
    glyphs: PreparedGlyphs,
    layouts: LayoutCache,
    instances: Instances,
    /// The instances of the glyphs `render` draws straight into the caller's target.
    direct_instances: Instances,
    /// Whether a `trim` asked the direct instances' buffer to shrink: done at the next
    /// frame that draws, since `render` may still draw from it until then.
    shrink_direct: bool,
    composite: Option<Composite>,
    pages: Option<Pages>,
    /// Whether the pages are far more than the frames use (see `trim`).
    shrink_pages: bool,
    /// `prepare`s so far, and the count at the last `trim`.
    frame: u64,
    trimmed_at: u64,
    drawn: Drawn,
    /// This frame's work, kept to reuse its allocations.
    work: Work,
    uploads: Uploads,
}

/// What the GPU holds from the last `prepare` that drew.
#[derive(Default)]
struct Drawn {
    /// Whether the pages and records below are what `runs` describe.
    valid: bool,
    viewport: [u32; 2],
    runs: Vec<DrawnRun>,
    /// The composite's records, and each one's run.
    records: Vec<CompositeRun>,
    record_runs: Vec<u32>,
    /// Pages the last drawn frame used, and the height of them it used.
    pages_used: u32,
    height_used: u32,
    instances: usize,
    /// Whether the runs of the last frame that drew had moved since the frame before.
    moved: bool,
    /// The glyphs drawn straight into the caller's target: per variant, its pipeline
    /// and instances (empty where everything went through the pages), and the glyph
    /// data they read (kept here: a `trim` may compact the renderer's).
    direct: Vec<(wgpu::RenderPipeline, Range<u32>)>,
    direct_glyphs: Option<wgpu::BindGroup>,
    direct_instances: usize,
}

/// A run as last drawn: what decides whether its coverage must be drawn anew.
struct DrawnRun {
    font: usize,
    layout: RunLayout,
    size_px: u32,
    transform: [u32; 9],
    colour: [u32; 4],
}

impl DrawnRun {
    fn same_place(&self, run: &TextRun<'_>, layout: &RunLayout) -> bool {
        self.font == run.font.0
            && Arc::ptr_eq(&self.layout, layout)
            && self.size_px == run.size_px.to_bits()
            && self.transform == run.transform.to_cols_array().map(f32::to_bits)
    }
}

/// A run placed this frame: its glyphs' maps in `Work::glyphs`, and its rectangle of
/// pixels where any glyph of it reaches the viewport.
struct PlacedRun {
    glyphs: Range<usize>,
    /// The pixels of its glyphs that go through the pages.
    rect: Option<PixelRect>,
    /// Drawn alone, clipped to its rectangle: a run whose glyphs may reach past it (cut
    /// by the viewport, or turned, skewed or in perspective, where a quad's dilated
    /// corners reach further than its glyph's pixels).
    clipped: bool,
}

#[derive(Default)]
struct Work {
    /// Per run: its layout, transform and font units per text-space pixel.
    runs: Vec<(RunLayout, DMat3, f64)>,
    placed: Vec<PlacedRun>,
    /// (prepared glyph, local → target pixels) of the glyphs reaching the viewport.
    glyphs: Vec<(u32, DMat3)>,
    /// Each of those glyphs' box of ink in target pixels; where it may be drawn
    /// straight into the target, its variant there, its pixels, its run and kind, and
    /// whether it must go through the pages all the same (`sharing.rs`).
    ink: Vec<Rect>,
    variants: Vec<Variant>,
    boxes: Vec<PixelRect>,
    keys: Vec<GlyphKey>,
    paged: Vec<bool>,
    grid: sharing::Grid,
    rects: Vec<PixelRect>,
    order: Vec<u32>,
    placements: Vec<Placement>,
    /// (page, the clipped run's number + 1 or 0, variant) and the instance.
    staged: Vec<(DrawKey, GpuInstance)>,
    instances: Vec<GpuInstance>,
    /// The glyphs drawn straight into the target, by variant.
    staged_direct: Vec<(Variant, GpuInstance)>,
}

/// How instances are grouped into draws: per page, the unclipped runs together, each
/// clipped run alone (its number + 1), one draw per variant.
type DrawKey = (u32, u32, Variant);

impl TextRenderer {
    /// A renderer drawing into targets of `format` on `device`, uploading through
    /// `queue`.
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, format: wgpu::TextureFormat) -> Self {
        let gpu = GpuContext::from_device_and_queue(device.clone(), queue.clone());
        let instances = Instances::placed_by_caller(&gpu, 256);
        let direct_instances = Instances::placed_by_caller(&gpu, 256);
        TextRenderer {
            winding: Winding::staged(Settings::default(), super::Stage::Full),
            gpu,
            format,
            fonts: Vec::new(),
            glyphs: PreparedGlyphs::default(),
            layouts: LayoutCache::default(),
            instances,
            direct_instances,
            shrink_direct: false,
            composite: None,
            pages: None,
            shrink_pages: false,
            frame: 0,
            trimmed_at: 0,
            drawn: Drawn::default(),
            work: Work::default(),
            uploads: Uploads::default(),
        }
    }

    /// The same renderer with its coverage shader cut short after `stage`: for
    /// measuring where a frame's time goes (the explorer's bench breaks a moving frame
    /// down this way). What it draws is not text but at [`Stage::Full`](super::Stage::Full).
    pub fn cut_after(mut self, stage: super::Stage) -> Self {
        self.winding = Winding::staged(Settings::default(), stage);
        self
    }

    /// Reads a font (TrueType, OpenType with CFF or CFF2 outlines, the first face of a
    /// collection) for runs to draw with. An unreadable font is an [`Error::Font`].
    pub fn add_font(&mut self, bytes: Vec<u8>) -> Result<FontId, Error> {
        let font = Font::from_bytes(bytes, &format!("font {}", self.fonts.len()))?;
        self.fonts.push(font);
        Ok(FontId(self.fonts.len() - 1))
    }

    /// Adds a font already read with `glyphscope_core::font::Font` (a face of a
    /// collection, or a variable font's instance, kept as read).
    pub fn add_parsed_font(&mut self, font: Font) -> FontId {
        self.fonts.push(font);
        FontId(self.fonts.len() - 1)
    }

    /// Lays out and places `runs` for a target of `viewport` pixels, uploading only what
    /// changed since the last call, and records into `encoder` the passes that draw the
    /// runs' coverage into the renderer's own pages (submit it before, or with, the
    /// encoder of the pass given to [`render`](Self::render); a frame whose runs did not
    /// move records none). Runs are drawn in order, each over those before it; a run
    /// whose content draws nothing (empty or blank text, no glyphs) is no error and
    /// draws nothing, as a UI's empty label. Bad input
    /// — an unknown font, a glyph id the font lacks, a size or colour out
    /// of range, a transform that is not finite, cannot be inverted or puts text behind
    /// the eye, a viewport past the device's largest texture — is an [`Error::Input`], and
    /// the last prepared frame stays as it was. Submit `encoder`: a later frame whose runs
    /// did not move draws nothing anew and composites what these passes drew.
    pub fn prepare(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        viewport: [u32; 2],
        runs: &[TextRun<'_>],
    ) -> Result<(), Error> {
        if viewport.contains(&0) {
            return Err(Error::Input(format!(
                "the viewport is {}×{} pixels: nothing can be drawn into it",
                viewport[0], viewport[1]
            )));
        }
        let side = self.gpu.max_texture_side();
        if viewport.iter().any(|&v| v > side) {
            return Err(Error::Input(format!(
                "the viewport is {}×{} pixels: past this device's largest texture, {side} a side",
                viewport[0], viewport[1]
            )));
        }
        self.frame += 1;
        self.uploads = Uploads::default();
        let mut work = std::mem::take(&mut self.work);
        let result = self.prepare_with(&mut work, encoder, viewport, runs);
        self.work = work;
        result
    }

    fn prepare_with(
        &mut self,
        work: &mut Work,
        encoder: &mut wgpu::CommandEncoder,
        viewport: [u32; 2],
        runs: &[TextRun<'_>],
    ) -> Result<(), Error> {
        // Every run checked and laid out before anything drawn changes.
        work.runs.clear();
        for (k, run) in runs.iter().enumerate() {
            let to_text = check_run(k, run, self.fonts.len())?;
            let layout = self.layout(run)?;
            let scale = f64::from(run.size_px) / self.fonts[run.font.0].units_per_em();
            work.runs.push((layout, to_text, scale));
        }
        let drawn = &self.drawn;
        let in_place = drawn.valid
            && drawn.viewport == viewport
            && drawn.runs.len() == runs.len()
            && !self.glyphs.need_upload()
            && (drawn.runs.iter().zip(runs).zip(&work.runs))
                .all(|((d, run), (layout, _, _))| d.same_place(run, layout));
        if in_place && self.drawn.direct.is_empty() {
            return self.recolour(runs);
        }
        // Runs that moved in the last frame too are taken to be in motion: their lone
        // glyphs go straight into the target. Otherwise (the first frame, motion just
        // begun, or just stopped) everything goes into the pages, for still frames to
        // composite.
        let direct = !in_place && self.drawn.valid && self.drawn.moved;

        let page = self.page_size(viewport);
        let (pages_needed, height_used) = self.place(work, viewport, page, direct)?;
        let gpu = self.gpu.clone();
        let limit = gpu.device.limits().max_texture_array_layers;
        if pages_needed > limit {
            return Err(Error::Input(format!(
                "the runs' pixels fill {pages_needed} pages of {}×{}: past this device's \
                 {limit} texture layers (draw fewer or smaller runs per frame)",
                page[0], page[1]
            )));
        }
        gpu.catching_errors("preparing text", || {
            // One page only as tall as its shelves: clearing and drawing a few labels'
            // page costs their pixels, not the viewport's.
            let needed = [
                page[0],
                height_used.max(1).next_multiple_of(64).min(page[1]),
            ];
            self.commit(work, encoder, viewport, (needed, page), pages_needed, runs)
        })
        .inspect(|()| self.drawn.moved = !in_place)
        .inspect_err(|_| {
            // What the GPU holds is not what `drawn` says: the next frame draws anew.
            self.drawn.valid = false;
            self.pages = None;
            self.glyphs.forget_upload();
        })
    }

    /// Only colours changed (or nothing): the composite's records rewritten if so.
    fn recolour(&mut self, runs: &[TextRun<'_>]) -> Result<(), Error> {
        let srgb = self.format.is_srgb();
        let drawn = &mut self.drawn;
        drawn.moved = false;
        let mut changed = false;
        for (d, run) in drawn.runs.iter_mut().zip(runs) {
            let colour = run.color.map(f32::to_bits);
            changed |= d.colour != colour;
            d.colour = colour;
        }
        if !changed {
            return Ok(());
        }
        for (record, &run) in drawn.records.iter_mut().zip(&drawn.record_runs) {
            record.colour = premultiplied(runs[run as usize].color, srgb);
        }
        let pages = self.pages.as_ref().expect("drawn frames have pages");
        self.uploads.instance_bytes = pages.write(&self.gpu, drawn.viewport, &drawn.records);
        Ok(())
    }

    /// The pages' size for `viewport`: the viewport rounded up to 64 pixels (a run's
    /// rectangle lies within the viewport, so any fits).
    fn page_size(&self, viewport: [u32; 2]) -> [u32; 2] {
        let side = self.gpu.max_texture_side();
        viewport.map(|v| v.next_multiple_of(64).min(side).max(v))
    }

    /// Places every run: each glyph's map into the target, the run's rectangle of
    /// pixels, and where it goes in the pages; returns the pages needed and the height
    /// they use. With `direct`, the glyphs that share no pixel with another are left
    /// out of the rectangles (`render` draws them into the target). Fails, leaving what
    /// is drawn as it was, where a transform puts text behind the eye.
    fn place(
        &self,
        work: &mut Work,
        viewport: [u32; 2],
        page: [u32; 2],
        direct: bool,
    ) -> Result<(u32, u32), Error> {
        work.placed.clear();
        work.glyphs.clear();
        work.ink.clear();
        work.rects.clear();
        let view = [f64::from(viewport[0]), f64::from(viewport[1])];
        for (k, (layout, to_text, scale)) in work.runs.iter().enumerate() {
            let first = work.glyphs.len();
            for &(glyph, pen) in layout.iter() {
                // Font units (y up) to text space (pixels, y down), then the run's map.
                let local = DMat3::from_cols(
                    DVec3::new(*scale, 0.0, 0.0),
                    DVec3::new(0.0, -scale, 0.0),
                    DVec3::new(pen.x * scale, -pen.y * scale, 1.0),
                );
                let to_image = *to_text * local;
                let bounds =
                    Camera::project_bounds(&to_image, self.glyphs.bounds(glyph)).map_err(|_| {
                        Error::Input(format!("run {k}: its transform puts text behind the eye"))
                    })?;
                if !(bounds.min.is_finite() && bounds.max.is_finite()) {
                    return Err(Error::Input(format!(
                        "run {k}: its transform sends text past any number"
                    )));
                }
                // A glyph whose pixels (its box grown by one) miss the viewport draws
                // nothing there.
                let reaches = bounds.max.x + 1.0 > 0.0
                    && bounds.min.x - 1.0 < view[0]
                    && bounds.max.y + 1.0 > 0.0
                    && bounds.min.y - 1.0 < view[1];
                if reaches {
                    work.glyphs.push((glyph, to_image));
                    work.ink.push(bounds);
                }
            }
            work.placed.push(PlacedRun {
                glyphs: first..work.glyphs.len(),
                rect: None,
                clipped: !keeps_axes(to_text),
            });
        }
        work.paged.clear();
        if direct {
            // Each glyph's variant as drawn into the target, chosen over its run's ink
            // as the pages choose it over the run's rectangle.
            work.variants.clear();
            work.keys.clear();
            for (k, placed) in work.placed.iter_mut().enumerate() {
                let glyphs = placed.glyphs.clone();
                let Some(ink) = work.ink[glyphs.clone()].iter().copied().reduce(Rect::union) else {
                    continue;
                };
                for (glyph, to_image) in &work.glyphs[glyphs] {
                    let marked = self.glyphs.marked(*glyph);
                    let variant = self.winding.settings.variant(marked, to_image, &ink);
                    work.variants.push(variant);
                    let kind = kind_of(variant);
                    work.keys.push(GlyphKey {
                        run: k as u32,
                        kind,
                    });
                }
            }
            work.boxes.clear();
            work.boxes.extend(
                work.ink
                    .iter()
                    .zip(&work.glyphs)
                    .map(|(ink, (_, to_image))| {
                        // In perspective the shader's pixel footprint may reach a pixel
                        // further (`sharing::pixels_of_ink`).
                        let affine = to_image.x_axis.z == 0.0 && to_image.y_axis.z == 0.0;
                        let grow = if affine { 0.0 } else { 1.0 };
                        sharing::pixels_of_ink(
                            ink.min.to_array(),
                            ink.max.to_array(),
                            viewport,
                            grow,
                        )
                    }),
            );
            work.grid
                .mark(&work.boxes, &work.keys, viewport, &mut work.paged);
        }
        for placed in &mut work.placed {
            let mut paged: Option<Rect> = None;
            for i in placed.glyphs.clone() {
                if !direct || work.paged[i] {
                    let bounds = work.ink[i];
                    paged = Some(paged.map_or(bounds, |r| r.union(bounds)));
                }
            }
            let (rect, cut) = paged.map_or((None, false), |ink| pixel_rect(&ink, viewport));
            if let Some(rect) = rect {
                work.rects.push(rect);
            }
            placed.rect = rect;
            placed.clipped |= cut;
        }
        Ok(pages::pack(
            &work.rects,
            page,
            &mut work.order,
            &mut work.placements,
        ))
    }

    /// Uploads what changed and records the coverage passes: every placed glyph drawn
    /// into its run's rectangle in the pages.
    fn commit(
        &mut self,
        work: &mut Work,
        encoder: &mut wgpu::CommandEncoder,
        viewport: [u32; 2],
        (page, most): ([u32; 2], [u32; 2]),
        pages_needed: u32,
        runs: &[TextRun<'_>],
    ) -> Result<(), Error> {
        let gpu = self.gpu.clone();
        if self.glyphs.need_upload() {
            let layout = &self.winding.layout(&gpu).0;
            self.uploads.glyph_bytes = self.glyphs.upload(&gpu, layout)?;
        }
        let composite = self.composite.get_or_insert_with(|| {
            Composite::new(&gpu, &super::SHADER.module(&gpu.device), self.format)
        });
        let current = self.pages.take().filter(|_| !self.shrink_pages);
        self.shrink_pages = false;
        let pages = Pages::fitting(
            current,
            &gpu,
            composite,
            page,
            most,
            pages_needed,
            work.rects.len(),
        );
        let page = pages.size;

        // Each glyph in its run's rectangle of the pages: the run's pixels moved there
        // by whole pixels, so that each pixel's coverage is the one it has on screen.
        let srgb = self.format.is_srgb();
        let drawn = &mut self.drawn;
        drawn.records.clear();
        drawn.record_runs.clear();
        work.staged.clear();
        work.staged_direct.clear();
        // Drawn straight into the target: a glyph `place` did not send through the
        // pages (none where it tested nothing, `paged` then being empty).
        let direct = |i: usize| work.paged.get(i) == Some(&false);
        let mut visible = 0usize;
        for (k, placed) in work.placed.iter().enumerate() {
            let colour = premultiplied(runs[k].color, srgb);
            for i in placed.glyphs.clone().filter(|&i| direct(i)) {
                let (glyph, to_image) = work.glyphs[i];
                let instance = GpuInstance::new(&to_image, glyph).coloured(colour);
                work.staged_direct.push((work.variants[i], instance));
            }
            let Some(rect) = placed.rect else { continue };
            let placement = work.placements[visible];
            visible += 1;
            // A clipped run is drawn alone: its number among the drawn runs, plus one.
            let alone = if placed.clipped { visible as u32 } else { 0 };
            let offset = [
                f64::from(placement.origin[0]) - f64::from(rect.x0),
                f64::from(placement.origin[1]) - f64::from(rect.y0),
            ];
            let to_page = DMat3::from_translation(DVec2::from(offset));
            let in_page = Rect {
                min: DVec2::new(
                    f64::from(placement.origin[0]),
                    f64::from(placement.origin[1]),
                ),
                max: DVec2::new(
                    f64::from(placement.origin[0] + rect.width()),
                    f64::from(placement.origin[1] + rect.height()),
                ),
            };
            for i in placed.glyphs.clone().filter(|&i| !direct(i)) {
                let (glyph, to_image) = work.glyphs[i];
                let to_page = to_page * to_image;
                let variant =
                    self.winding
                        .settings
                        .variant(self.glyphs.marked(glyph), &to_page, &in_page);
                work.staged.push((
                    (placement.page, alone, variant),
                    GpuInstance::new(&to_page, glyph),
                ));
            }
            drawn
                .records
                .push(CompositeRun::new(rect, placement, colour));
            drawn.record_runs.push(k as u32);
        }
        // Stable: within a draw, instances keep the runs' order.
        work.staged.sort_by_key(|&(key, _)| key);
        let mut groups: Vec<(DrawKey, Range<u32>)> = Vec::new();
        work.instances.clear();
        for (index, &(key, instance)) in (0u32..).zip(&work.staged) {
            work.instances.push(instance);
            match groups.last_mut() {
                Some((last, range)) if *last == key => range.end = index + 1,
                _ => groups.push((key, index..index + 1)),
            }
        }
        self.uploads.instance_bytes = self.instances.write(&gpu, page, &work.instances)
            + pages.write(&gpu, viewport, &drawn.records);

        // The direct glyphs, one draw per variant (a stable sort: each in the runs'
        // order), for `render`.
        work.staged_direct.sort_by_key(|&(variant, _)| variant);
        let paged_instances = work.instances.len();
        work.instances.clear();
        drawn.direct.clear();
        for (index, &(variant, instance)) in (0u32..).zip(&work.staged_direct) {
            work.instances.push(instance);
            match drawn.direct.last_mut() {
                Some((_, range)) if work.staged_direct[range.start as usize].0 == variant => {
                    range.end = index + 1;
                }
                _ => {
                    let over_target = wgpu::ColorTargetState {
                        format: self.format,
                        blend: Some(wgpu::BlendState::PREMULTIPLIED_ALPHA_BLENDING),
                        write_mask: wgpu::ColorWrites::ALL,
                    };
                    let pipeline =
                        self.winding
                            .pipeline_into(&gpu, Output::TextColour, variant, over_target);
                    drawn.direct.push((pipeline, index..index + 1));
                }
            }
        }
        // Room a trim found far past what frames use, given back now that the last
        // frame's `render` is recorded (wgpu keeps the old buffer for it).
        if std::mem::take(&mut self.shrink_direct) {
            self.direct_instances
                .shrink_to(&gpu, work.instances.len().max(256));
        }
        if !work.instances.is_empty() {
            self.uploads.instance_bytes +=
                self.direct_instances.write(&gpu, viewport, &work.instances);
        }
        drawn.direct_instances = work.instances.len();
        drawn.direct_glyphs = Some(self.glyphs.bind_group().expect("uploaded above").clone());

        // The passes: each page cleared, then its draws.
        let pipelines: Vec<wgpu::RenderPipeline> = groups
            .iter()
            .map(|&((_, _, variant), _)| {
                self.winding
                    .pipeline(&gpu, Output::Coverage, variant, Channels::Coverage)
            })
            .collect();
        let glyph_group = self.glyphs.bind_group().expect("uploaded above");
        for page_index in 0..pages_needed {
            let mut pass = crate::gpu::clearing_pass(
                encoder,
                &pages.views[page_index as usize],
                "text coverage",
                None,
            );
            pass.set_bind_group(0, self.instances.bind_group(), &[]);
            pass.set_bind_group(1, glyph_group, &[]);
            for (((page_of, alone, _), range), pipeline) in groups.iter().zip(&pipelines) {
                if *page_of != page_index {
                    continue;
                }
                let (x, y, w, h) = match alone {
                    0 => (0, 0, page[0], page[1]),
                    number => {
                        let p = work.placements[*number as usize - 1];
                        let r = &work.rects[*number as usize - 1];
                        (p.origin[0], p.origin[1], r.width(), r.height())
                    }
                };
                pass.set_scissor_rect(x, y, w, h);
                pass.set_pipeline(pipeline);
                pass.draw(0..4, range.clone());
            }
        }

        drawn.runs.clear();
        drawn.runs.extend(
            runs.iter()
                .zip(&work.runs)
                .map(|(run, (layout, _, _))| DrawnRun {
                    font: run.font.0,
                    layout: layout.clone(),
                    size_px: run.size_px.to_bits(),
                    transform: run.transform.to_cols_array().map(f32::to_bits),
                    colour: run.color.map(f32::to_bits),
                }),
        );
        drawn.viewport = viewport;
        drawn.pages_used = pages_needed;
        drawn.height_used = height_used(&page, pages_needed, &work.placements, &work.rects);
        drawn.instances = paged_instances;
        drawn.valid = true;
        self.pages = Some(pages);
        Ok(())
    }

    /// Records the prepared runs into `pass`, which must draw into a target of the
    /// format given to [`new`](Self::new), of the viewport given to
    /// [`prepare`](Self::prepare) (the pass's default viewport). Draws nothing before
    /// the first `prepare`. It sets its own pipelines and bind groups 0 to 2 on the
    /// pass: set yours again after it.
    pub fn render(&self, pass: &mut wgpu::RenderPass<'_>) {
        let drawn = &self.drawn;
        if !drawn.valid {
            return;
        }
        // The direct glyphs first, each draw in the runs' order; the pages' runs over
        // them in order (`sharing.rs` sent through the pages every glyph that must be
        // over a paged one).
        if let (false, Some(glyphs)) = (drawn.direct.is_empty(), &drawn.direct_glyphs) {
            pass.set_bind_group(0, self.direct_instances.bind_group(), &[]);
            pass.set_bind_group(1, glyphs, &[]);
            for (pipeline, range) in &drawn.direct {
                pass.set_pipeline(pipeline);
                pass.draw(0..4, range.clone());
            }
        }
        if let (Some(pages), Some(composite), false) =
            (&self.pages, &self.composite, drawn.records.is_empty())
        {
            pages.composite(composite, pass, drawn.records.len() as u32);
        }
    }

    /// Forgets what no `prepare` used since the last trim — layouts, then the glyphs
    /// only they drew (once those are many), and room in the pages and buffers far past
    /// what the last frame needed — as glyphon's `TextAtlas::trim`. Call it once a
    /// frame, after the frame's `prepare`s: text that changes every frame (a clock, a
    /// counter, a search box) then holds what the frames draw, not everything ever drawn.
    /// Layouts and glyphs dropped are made again if a later frame needs them.
    pub fn trim(&mut self) {
        let evicted = self.layouts.evict_unused(self.trimmed_at);
        self.trimmed_at = self.frame;
        if evicted > 0 {
            let mut used = vec![false; self.glyphs.len()];
            for layout in self.layouts.layouts() {
                for &(glyph, _) in layout.iter() {
                    used[glyph as usize] = true;
                }
            }
            let kept = used.iter().filter(|&&u| u).count();
            // Compacting prepares every kept glyph again: only once the glyphs no layout
            // draws are as many as those kept.
            // The coverage drawn stays for `render`; the next `prepare` finds the
            // layouts renumbered and the glyphs to upload, and draws anew.
            if self.glyphs.len() - kept > kept.max(64) {
                let new_index = self.glyphs.compact(&used);
                self.layouts.renumber(&new_index);
            }
        }
        // The next frame that draws makes smaller pages.
        let drawn = &self.drawn;
        self.shrink_pages = self.pages.as_ref().is_some_and(|p| {
            p.count > 2 * drawn.pages_used.max(1) || p.size[1] > 2 * drawn.height_used.max(64)
        });
        let instances = self.drawn.instances.max(256);
        self.instances.shrink_to(&self.gpu, instances);
        self.shrink_direct = true;
    }

    /// What the last [`prepare`](Self::prepare) uploaded.
    pub fn last_uploads(&self) -> Uploads {
        self.uploads
    }

    /// Glyphs the last [`prepare`](Self::prepare) that drew left for
    /// [`render`](Self::render) to draw straight into the target (a `prepare` that
    /// failed left the frame before as it was): in a frame of text in motion, those no
    /// glyph of their own run and no glyph going through the pages reach. The others go
    /// through the renderer's pages.
    pub fn direct_glyphs(&self) -> usize {
        if self.drawn.valid {
            self.drawn.direct_instances
        } else {
            0
        }
    }

    /// Glyphs the last [`prepare`](Self::prepare) that drew placed in the viewport: those
    /// [`direct_glyphs`](Self::direct_glyphs) counts and those in the pages.
    pub fn drawn_glyphs(&self) -> usize {
        if self.drawn.valid {
            self.drawn.instances + self.drawn.direct_instances
        } else {
            0
        }
    }

    /// What the renderer holds on the GPU now.
    pub fn held(&self) -> Held {
        Held {
            glyph_bytes: self.glyphs.gpu_bytes(),
            instance_bytes: self.instances.bytes() + self.direct_instances.bytes(),
            coverage_bytes: self.pages.as_ref().map_or(0, Pages::gpu_bytes),
        }
    }

    /// Glyphs prepared and kept (each distinct outline of each font, joined groups
    /// included).
    pub fn prepared_glyphs(&self) -> usize {
        self.glyphs.len()
    }

    /// Run layouts kept (per font and content).
    pub fn cached_layouts(&self) -> usize {
        self.layouts.len()
    }

    /// The run's layout in font units, from the cache or shaped, joined and merged now
    /// (its new glyphs prepared).
    fn layout(&mut self, run: &TextRun<'_>) -> Result<RunLayout, Error> {
        let content = match run.content {
            Content::Text(text) => ContentRef::Text(text),
            Content::Glyphs(glyphs) => ContentRef::Glyphs(glyphs, run.size_px),
        };
        let font_index = run.font.0;
        if let Some(layout) = self.layouts.get(font_index, content, self.frame) {
            return Ok(layout);
        }
        let font = &self.fonts[font_index];
        let scene = match run.content {
            Content::Text(text) => Scene::from_text_or_blank(font, text)?,
            Content::Glyphs(glyphs) => scene_of_glyphs(font, glyphs, run.size_px)?,
        };
        // As the `winding` row draws by default: overlapping instances joined, then every
        // glyph's overlapping contours merged (only for glyphs not prepared before).
        let drawn = scene.joined_if(true);
        let glyph_indices: Vec<u32> = drawn
            .glyphs
            .iter()
            .map(|glyph| self.glyphs.index_of(font_index, glyph, drawn.units_per_em))
            .collect();
        let layout: RunLayout = drawn
            .instances
            .iter()
            .map(|i| (glyph_indices[i.glyph as usize], i.position))
            .collect();
        self.layouts
            .insert(font_index, content, layout.clone(), self.frame);
        Ok(layout)
    }
}

/// A variant as a number: glyphs of one number are drawn straight into the target by
/// one draw.
fn kind_of(variant: Variant) -> u32 {
    u32::from(variant.axis) | (u32::from(variant.square) << 1) | (u32::from(variant.grid) << 2)
}

/// The height of the pages `placements` of `rects` use.
fn height_used(page: &[u32; 2], pages: u32, placements: &[Placement], rects: &[PixelRect]) -> u32 {
    if pages > 1 {
        return page[1];
    }
    (placements.iter().zip(rects))
        .map(|(p, r)| p.origin[1] + r.height())
        .max()
        .unwrap_or(0)
}

/// The whole pixels `ink` (a glyph box in target pixels) may touch, grown by one, within
/// the viewport; and whether the viewport cut it. None where nothing is left.
fn pixel_rect(ink: &Rect, viewport: [u32; 2]) -> (Option<PixelRect>, bool) {
    let [w, h] = viewport.map(f64::from);
    let (x0, y0) = (ink.min.x.floor() - 1.0, ink.min.y.floor() - 1.0);
    let (x1, y1) = (ink.max.x.ceil() + 1.0, ink.max.y.ceil() + 1.0);
    let cut = x0 < 0.0 || y0 < 0.0 || x1 > w || y1 > h;
    let rect = PixelRect {
        x0: x0.clamp(0.0, w) as u32,
        y0: y0.clamp(0.0, h) as u32,
        x1: x1.clamp(0.0, w) as u32,
        y1: y1.clamp(0.0, h) as u32,
    };
    let empty = rect.x0 >= rect.x1 || rect.y0 >= rect.y1;
    (if empty { None } else { Some(rect) }, cut)
}

/// Checks a run's font, size, colour and transform; returns the transform in f64.
fn check_run(k: usize, run: &TextRun<'_>, fonts: usize) -> Result<DMat3, Error> {
    let bad = |what: String| Error::Input(format!("run {k}: {what}"));
    if run.font.0 >= fonts {
        return Err(bad(format!("font {} was not added", run.font.0)));
    }
    if !(run.size_px.is_finite() && run.size_px > 0.0) {
        return Err(bad(format!(
            "size {} px is not a positive number",
            run.size_px
        )));
    }
    if !run.color.iter().all(|c| (0.0..=1.0).contains(c)) {
        return Err(bad(format!(
            "colour {:?} is not four numbers in 0..=1",
            run.color
        )));
    }
    let m = DMat3::from_cols_array(&run.transform.to_cols_array().map(f64::from));
    let finite = m.to_cols_array().iter().all(|v| v.is_finite());
    let det = m.determinant();
    if !finite || !det.is_finite() || det == 0.0 {
        return Err(bad(format!(
            "its transform {:?} is not finite and invertible",
            run.transform.to_cols_array()
        )));
    }
    if let Content::Glyphs(glyphs) = run.content
        && !glyphs.iter().all(|g| g.x.is_finite() && g.y.is_finite())
    {
        return Err(bad("a glyph's position is not finite".into()));
    }
    Ok(m)
}

/// A scene of glyphs by id at pens given in text-space pixels at `size_px`.
fn scene_of_glyphs(font: &Font, glyphs: &[PositionedGlyph], size_px: f32) -> Result<Scene, Error> {
    let to_units = font.units_per_em() / f64::from(size_px);
    let mut distinct: std::collections::HashMap<u16, Option<u32>> = Default::default();
    let mut scene_glyphs = Vec::new();
    let mut instances = Vec::new();
    for g in glyphs {
        let id = font.check_glyph_id(u32::from(g.id))?;
        let slot = *distinct.entry(g.id).or_insert_with(|| {
            let outline = font.outline(id);
            let bounds = outline.control_bounds()?;
            scene_glyphs.push(Glyph::new(id, outline, bounds));
            Some(scene_glyphs.len() as u32 - 1)
        });
        // A glyph without ink (a space) draws nothing.
        if let Some(glyph) = slot {
            let position = DVec2::new(f64::from(g.x) * to_units, -f64::from(g.y) * to_units);
            instances.push(Instance { glyph, position });
        }
    }
    Ok(Scene::from_font_glyphs(font, scene_glyphs, instances))
}

/// `color` premultiplied by its alpha, its components decoded from sRGB to linear light
/// first where the target is sRGB (the target encodes what is blended into it).
fn premultiplied(color: [f32; 4], srgb_target: bool) -> [f32; 4] {
    let decode = |c: f32| {
        if !srgb_target {
            c
        } else if c <= 0.04045 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    };
    let a = color[3];
    // In 65535ths, as a glyph drawn straight into the target carries its colour
    // (`GpuInstance::coloured`): the pages' composite then blends the same colour.
    [
        decode(color[0]) * a,
        decode(color[1]) * a,
        decode(color[2]) * a,
        a,
    ]
    .map(|c| (c * 65535.0).round() / 65535.0)
}
