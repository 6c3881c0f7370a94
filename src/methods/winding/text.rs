//! Text in colour, drawn with `winding`'s exact coverage into a render pass the caller
//! owns: the library other wgpu and egui apps use, re-exported as [`crate::text`]
//! (docs/library.md).
//!
//! One implementation: the explorer's `winding` row and this renderer prepare glyphs
//! with the same [`GlyphData::push`], join overlapping instances and merge overlapping
//! contours the same way (`between=union`, `overlaps=merge`), and draw with the same
//! shader and pipelines. The row writes coverage into its own target; here the shader's
//! `Text` output writes each instance's premultiplied colour times that coverage, blended
//! over the caller's target, and the caller places each run with its own transform.
//!
//! What is kept between frames: every glyph prepared (per font and outline, so a glyph
//! met again in any run is not prepared again), every run's layout (per font and
//! content), and the instances last written. A frame whose runs are the same as the last
//! frame's uploads nothing; a frame that only moves, turns or recolours its runs uploads
//! only the instances ([`TextRenderer::last_uploads`] counts both).

use std::collections::HashMap;
use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use std::ops::Range;

use glam::{DMat3, DVec2, DVec3, Mat3};

use super::{BandCount, GlyphData, Layout, NAME, Output, Settings, Variant, Winding};
use crate::Error;
use crate::camera::Camera;
use crate::font::Font;
use crate::geometry::Rect;
use crate::gpu::{Channels, GpuContext, kit};
use crate::methods::instances::{GpuInstance, Instances};
use crate::scene::{Glyph, Instance, Scene};

/// A font added to a [`TextRenderer`] ([`TextRenderer::add_font`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FontId(usize);

/// One glyph of a run given by id: its id in the font and its pen position in the run's
/// text space (pixels at the run's size, x right, y down, the run's origin at 0, 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PositionedGlyph {
    pub id: u16,
    pub x: f32,
    pub y: f32,
}

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
    pub font: FontId,
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
    /// Per-instance transforms and colours and the target size (only when they changed).
    pub instance_bytes: u64,
}

/// A run's layout in font units: (prepared glyph, pen position) per instance.
type RunLayout = Vec<(u32, DVec2)>;

/// Draws text with `winding`'s exact box-filter coverage into a caller's render pass.
///
/// ```no_run
/// # fn demo(device: &wgpu::Device, queue: &wgpu::Queue, pass: &mut wgpu::RenderPass<'_>) -> Result<(), glyphscope::Error> {
/// use glyphscope::text::{Content, TextRenderer, TextRun};
/// let mut text = TextRenderer::new(device, queue, wgpu::TextureFormat::Bgra8UnormSrgb);
/// let font = text.add_font(std::fs::read("fonts/DejaVuSans.ttf").unwrap())?;
/// let run = TextRun {
///     font,
///     content: Content::Text("Sharp at any zoom"),
///     size_px: 32.0,
///     transform: glam::Mat3::from_translation(glam::vec2(20.0, 60.0)),
///     color: [0.1, 0.1, 0.1, 1.0],
/// };
/// text.prepare([800, 600], &[run])?;
/// text.render(pass);
/// # Ok(()) }
/// ```
pub struct TextRenderer {
    gpu: GpuContext,
    format: wgpu::TextureFormat,
    winding: Winding,
    fonts: Vec<Font>,
    /// Every glyph prepared so far, by font and outline.
    glyphs: GlyphData,
    glyph_index: HashMap<(usize, u64), u32>,
    bounds: Vec<Rect>,
    /// The glyph buffers' bind group (every glyph prepared when it was made).
    glyph_group: Option<wgpu::BindGroup>,
    layouts: HashMap<(usize, LayoutKey), RunLayout>,
    instances: Instances,
    /// What the instance buffer holds: the instances and the target size.
    written: (Vec<GpuInstance>, [u32; 2]),
    draws: Vec<(wgpu::RenderPipeline, Range<u32>)>,
    uploads: Uploads,
}

/// A run's content as a layout cache key: the string, or the glyphs with their positions
/// in font units' bits (the size turns pixels into font units).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum LayoutKey {
    Text(String),
    Glyphs(Vec<(u16, [u64; 2])>),
}

impl TextRenderer {
    /// A renderer drawing into targets of `format` on `device`, uploading through
    /// `queue`.
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, format: wgpu::TextureFormat) -> Self {
        let gpu = GpuContext::from_device_and_queue(device.clone(), queue.clone());
        let instances = Instances::placed_by_caller(&gpu, 256);
        TextRenderer {
            winding: Winding::staged(Settings::default(), super::Stage::Full),
            gpu,
            format,
            fonts: Vec::new(),
            glyphs: GlyphData::default(),
            glyph_index: HashMap::new(),
            bounds: Vec::new(),
            glyph_group: None,
            layouts: HashMap::new(),
            instances,
            written: (Vec::new(), [0, 0]),
            draws: Vec::new(),
            uploads: Uploads::default(),
        }
    }

    /// Reads a font (TrueType, OpenType with CFF or CFF2 outlines, the first face of a
    /// collection) for runs to draw with. An unreadable font is an [`Error::Font`].
    pub fn add_font(&mut self, bytes: Vec<u8>) -> Result<FontId, Error> {
        let font = Font::from_bytes(bytes, &format!("font {}", self.fonts.len()))?;
        self.fonts.push(font);
        Ok(FontId(self.fonts.len() - 1))
    }

    /// Adds a font glyphscope has already read (its variations kept): the bench's way
    /// to draw its scenes' fonts through the library.
    pub(crate) fn add_parsed_font(&mut self, font: Font) -> FontId {
        self.fonts.push(font);
        FontId(self.fonts.len() - 1)
    }

    /// Lays out and places `runs` for a target of `viewport` pixels, uploading only what
    /// changed since the last call. Bad input — an unknown font, empty content, a glyph
    /// id the font lacks, a size or colour out of range, a transform that is not finite,
    /// cannot be inverted or puts text behind the eye — is an [`Error::Input`], and the
    /// last prepared frame stays as it was.
    pub fn prepare(&mut self, viewport: [u32; 2], runs: &[TextRun<'_>]) -> Result<(), Error> {
        if viewport.contains(&0) {
            return Err(Error::Input(format!(
                "the viewport is {}×{} pixels: nothing can be drawn into it",
                viewport[0], viewport[1]
            )));
        }
        let glyphs_before = self.bounds.len();
        let view = Rect {
            min: DVec2::ZERO,
            max: DVec2::new(f64::from(viewport[0]), f64::from(viewport[1])),
        };
        let mut staged: Vec<(Variant, GpuInstance)> = Vec::new();
        for (k, run) in runs.iter().enumerate() {
            let to_text = check_run(k, run, self.fonts.len())?;
            let units_per_em = self.fonts[run.font.0].units_per_em();
            let layout = self.layout(run)?;
            let s = f64::from(run.size_px) / units_per_em;
            let colour = premultiplied(run.color, self.format.is_srgb());
            for &(glyph, pen) in &layout {
                // Font units (y up) to text space (pixels, y down), then the run's map.
                let local = DMat3::from_cols(
                    DVec3::new(s, 0.0, 0.0),
                    DVec3::new(0.0, -s, 0.0),
                    DVec3::new(pen.x * s, -pen.y * s, 1.0),
                );
                let to_image = to_text * local;
                Camera::project_bounds(&to_image, &self.bounds[glyph as usize]).map_err(|_| {
                    Error::Input(format!("run {k}: its transform puts text behind the eye"))
                })?;
                let marked = self.glyphs.marked[glyph as usize];
                let variant = self.winding.settings.variant(marked, &to_image, &view);
                staged.push((variant, GpuInstance::new(&to_image, glyph, colour)));
            }
        }
        // One draw per variant, runs in order within it.
        staged.sort_by_key(|&(variant, _)| variant);
        let mut groups: Vec<(Variant, Range<u32>)> = Vec::new();
        for (index, &(variant, _)) in (0u32..).zip(&staged) {
            match groups.last_mut() {
                Some((last, range)) if *last == variant => range.end = index + 1,
                _ => groups.push((variant, index..index + 1)),
            }
        }
        let instances: Vec<GpuInstance> = staged.into_iter().map(|(_, i)| i).collect();

        self.uploads = Uploads::default();
        let gpu = self.gpu.clone();
        gpu.catching_errors("preparing text", || {
            if self.bounds.len() != glyphs_before || self.glyph_group.is_none() {
                self.upload_glyphs();
            }
            let same = bytemuck::cast_slice::<_, u8>(&instances)
                == bytemuck::cast_slice::<_, u8>(&self.written.0)
                && viewport == self.written.1;
            if !same {
                self.uploads.instance_bytes = self.instances.write(&gpu, viewport, &instances);
                self.written = (instances, viewport);
            }
            self.draws = groups
                .into_iter()
                .map(|(variant, range)| {
                    let output = Output::Text(self.format);
                    let pipeline = self
                        .winding
                        .pipeline(&gpu, output, variant, Channels::Coverage);
                    (pipeline, range)
                })
                .collect();
            Ok(())
        })
    }

    /// Records the prepared runs into `pass`, which must draw into a target of the
    /// format given to [`new`](Self::new), of the viewport given to
    /// [`prepare`](Self::prepare) (the pass's default viewport). Draws nothing before
    /// the first `prepare`.
    pub fn render(&self, pass: &mut wgpu::RenderPass<'_>) {
        let Some(glyphs) = &self.glyph_group else {
            return;
        };
        pass.set_bind_group(0, self.instances.bind_group(), &[]);
        pass.set_bind_group(1, glyphs, &[]);
        for (pipeline, range) in &self.draws {
            pass.set_pipeline(pipeline);
            pass.draw(0..4, range.clone());
        }
    }

    /// What the last [`prepare`](Self::prepare) uploaded.
    pub fn last_uploads(&self) -> Uploads {
        self.uploads
    }

    /// Glyphs prepared so far (each distinct outline of each font, joined groups
    /// included).
    pub fn prepared_glyphs(&self) -> usize {
        self.bounds.len()
    }

    /// The run's layout in font units, from the cache or shaped, joined and merged now
    /// (its new glyphs prepared).
    fn layout(&mut self, run: &TextRun<'_>) -> Result<RunLayout, Error> {
        let font = &self.fonts[run.font.0];
        let key = match run.content {
            Content::Text(text) => LayoutKey::Text(text.to_owned()),
            Content::Glyphs(glyphs) => {
                let to_units = font.units_per_em() / f64::from(run.size_px);
                LayoutKey::Glyphs(
                    glyphs
                        .iter()
                        .map(|g| {
                            let pen = [f64::from(g.x) * to_units, -f64::from(g.y) * to_units];
                            (g.id, pen.map(f64::to_bits))
                        })
                        .collect(),
                )
            }
        };
        if let Some(layout) = self.layouts.get(&(run.font.0, key.clone())) {
            return Ok(layout.clone());
        }
        let scene = match &key {
            LayoutKey::Text(text) => Scene::from_text(font, text)?,
            LayoutKey::Glyphs(glyphs) => scene_of_glyphs(font, glyphs)?,
        };
        // As the `winding` row draws by default: overlapping instances joined, then every
        // glyph's overlapping contours merged.
        let drawn = scene.joined_if(true).with_overlaps_merged();
        let font_index = run.font.0;
        let glyph_indices: Vec<u32> = drawn
            .glyphs
            .iter()
            .map(|glyph| self.prepared(font_index, glyph, drawn.units_per_em))
            .collect();
        let layout: RunLayout = drawn
            .instances
            .iter()
            .map(|i| (glyph_indices[i.glyph as usize], i.position))
            .collect();
        self.layouts.insert((font_index, key), layout.clone());
        Ok(layout)
    }

    /// The index of `glyph` of font `font` among the prepared glyphs, preparing it if it
    /// was not met before.
    fn prepared(&mut self, font: usize, glyph: &Glyph, units_per_em: f64) -> u32 {
        let key = (font, outline_key(glyph));
        if let Some(&index) = self.glyph_index.get(&key) {
            return index;
        }
        let index = self
            .glyphs
            .push(&glyph.outline, units_per_em, BandCount::Auto, Layout::Area);
        self.bounds.push(glyph.bounds);
        self.glyph_index.insert(key, index);
        index
    }

    /// Uploads every prepared glyph's buffers (new ones were prepared).
    fn upload_glyphs(&mut self) {
        let gpu = &self.gpu;
        let data = &self.glyphs;
        let storage = wgpu::BufferUsages::STORAGE;
        let buffers = [
            gpu.buffer_of("text glyphs", &data.glyphs, storage),
            gpu.buffer_of("text bands", &data.bands, storage),
            gpu.buffer_of("text band curves", &data.band_curves, storage),
            gpu.buffer_of("text curves", &data.curves, storage),
        ];
        self.uploads.glyph_bytes = buffers.iter().map(wgpu::Buffer::size).sum();
        let group = &self.winding.layout(gpu).0;
        self.glyph_group = Some(kit::bind_group(
            gpu,
            NAME,
            group,
            &buffers.each_ref().map(wgpu::Buffer::as_entire_binding),
        ));
    }
}

/// Checks a run's font, size, colour and transform; returns the transform in f64.
fn check_run(k: usize, run: &TextRun<'_>, fonts: usize) -> Result<DMat3, Error> {
    let bad = |what: String| Error::Input(format!("run {k}: {what}"));
    if run.font.0 >= fonts {
        return Err(bad(format!("font {} was not added", run.font.0)));
    }
    let empty = match run.content {
        Content::Text(text) => text.trim().is_empty(),
        Content::Glyphs(glyphs) => glyphs.is_empty(),
    };
    if empty {
        return Err(bad("it draws nothing (empty text)".into()));
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

/// A scene of glyphs by id at pens in font units.
fn scene_of_glyphs(font: &Font, glyphs: &[(u16, [u64; 2])]) -> Result<Scene, Error> {
    let mut distinct: HashMap<u16, Option<u32>> = HashMap::new();
    let mut scene_glyphs = Vec::new();
    let mut instances = Vec::new();
    for &(id, pen) in glyphs {
        let id = font.check_glyph_id(u32::from(id))?;
        let slot = *distinct.entry(id).or_insert_with(|| {
            let outline = font.outline(id);
            let bounds = outline.control_bounds()?;
            scene_glyphs.push(Glyph::new(id, outline, bounds));
            Some(scene_glyphs.len() as u32 - 1)
        });
        // A glyph without ink (a space) draws nothing.
        if let Some(glyph) = slot {
            let position = DVec2::new(f64::from_bits(pen[0]), f64::from_bits(pen[1]));
            instances.push(Instance { glyph, position });
        }
    }
    Ok(Scene::from_font_glyphs(font, scene_glyphs, instances))
}

/// A glyph's identity within its font: its id and every point of its outline (a group
/// of joined instances carries its first glyph's id, so the outline tells groups apart).
fn outline_key(glyph: &Glyph) -> u64 {
    let mut hasher = DefaultHasher::new();
    glyph.id.hash(&mut hasher);
    for segment in glyph.outline.segments() {
        for p in crate::geometry::segment_points(segment) {
            p.x.to_bits().hash(&mut hasher);
            p.y.to_bits().hash(&mut hasher);
        }
    }
    hasher.finish()
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
    [
        decode(color[0]) * a,
        decode(color[1]) * a,
        decode(color[2]) * a,
        a,
    ]
}
