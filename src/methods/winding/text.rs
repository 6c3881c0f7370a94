//! Text in colour, drawn with `winding`'s exact coverage into a render pass the caller
//! owns: the library other wgpu and egui apps use, re-exported as [`crate::text`]
//! (docs/library.md).
//!
//! One implementation: the explorer's `winding` row and this renderer prepare glyphs
//! with the same [`GlyphData::push`], join overlapping instances and merge overlapping
//! contours the same way (`between=union`, `overlaps=merge`), and draw coverage with the
//! same shader and pipelines into the same kind of half-float target, one layer a run,
//! its instances added (so glyphs sharing a pixel sum to their union's coverage, as in
//! the row). `render` then blends each run's colour over the caller's target through its
//! coverage (`winding_text.wgsl`), once. The caller places each run with its own
//! transform.
//!
//! What is kept between frames: every glyph prepared (per font and outline, so a glyph
//! met again in any run is not prepared again), every run's layout (per font and
//! content), and the instances last written. A frame whose runs are the same as the last
//! frame's uploads nothing; a frame that only moves, turns or recolours its runs uploads
//! only the instances ([`TextRenderer::last_uploads`] counts both).
// What other apps call: every public item says what it is.
#![deny(missing_docs)]

use std::collections::HashMap;
use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use std::ops::Range;
use std::sync::Arc;

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
    /// The glyph's id in the run's font.
    pub id: u16,
    /// Its pen position, text-space pixels right of the run's origin.
    pub x: f32,
    /// Its pen position, text-space pixels below the run's origin (y down).
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
    /// Per-instance transforms and colours and the target size (only when they changed).
    pub instance_bytes: u64,
}

/// A run's layout in font units: (prepared glyph, pen position) per instance, shared
/// by the cache and each frame that draws it.
type RunLayout = Arc<[(u32, DVec2)]>;

/// Draws text with `winding`'s exact box-filter coverage into a caller's render pass.
///
/// ```no_run
/// # fn demo(device: &wgpu::Device, queue: &wgpu::Queue, encoder: &mut wgpu::CommandEncoder, pass: &mut wgpu::RenderPass<'_>) -> Result<(), glyphscope::Error> {
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
/// text.prepare(encoder, [800, 600], &[run])?;
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
    /// What the instance buffer holds: the instances, the target size and the runs'
    /// colours.
    written: (Vec<GpuInstance>, [u32; 2], Vec<[f32; 4]>),
    /// Each run's coverage, a layer a run, and the composite's bind group over it.
    layers: Option<Layers>,
    composite: Option<(wgpu::BindGroupLayout, wgpu::RenderPipeline)>,
    uploads: Uploads,
}

/// The runs' coverage layers and colours as the composite reads them.
struct Layers {
    size: [u32; 2],
    count: u32,
    views: Vec<wgpu::TextureView>,
    colours: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
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
            written: (Vec::new(), [0, 0], Vec::new()),
            layers: None,
            composite: None,
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
    /// changed since the last call, and records into `encoder` the passes that draw each
    /// run's coverage into the renderer's own target (submit it before, or with, the
    /// encoder of the pass given to [`render`](Self::render); an unchanged frame records
    /// none). Bad input — an unknown font, empty content, a glyph
    /// id the font lacks, a size or colour out of range, a transform that is not finite,
    /// cannot be inverted or puts text behind the eye — is an [`Error::Input`], and the
    /// last prepared frame stays as it was.
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
        let glyphs_before = self.bounds.len();
        let view = Rect {
            min: DVec2::ZERO,
            max: DVec2::new(f64::from(viewport[0]), f64::from(viewport[1])),
        };
        let mut staged: Vec<((usize, Variant), GpuInstance)> = Vec::new();
        let mut colours = Vec::with_capacity(runs.len());
        for (k, run) in runs.iter().enumerate() {
            let to_text = check_run(k, run, self.fonts.len())?;
            let units_per_em = self.fonts[run.font.0].units_per_em();
            let layout = self.layout(run)?;
            let s = f64::from(run.size_px) / units_per_em;
            colours.push(premultiplied(run.color, self.format.is_srgb()));
            for &(glyph, pen) in layout.iter() {
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
                staged.push(((k, variant), GpuInstance::new(&to_image, glyph)));
            }
        }
        // Per run, one draw per variant.
        staged.sort_by_key(|&(key, _)| key);
        let mut groups: Vec<((usize, Variant), Range<u32>)> = Vec::new();
        for (index, &(key, _)) in (0u32..).zip(&staged) {
            match groups.last_mut() {
                Some((last, range)) if *last == key => range.end = index + 1,
                _ => groups.push((key, index..index + 1)),
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
                && viewport == self.written.1
                && colours == self.written.2
                && self.uploads.glyph_bytes == 0;
            if same {
                return Ok(());
            }
            self.uploads.instance_bytes = self.instances.write(&gpu, viewport, &instances);
            let layers = self.layers(viewport, runs.len() as u32);
            gpu.queue
                .write_buffer(&layers.colours, 0, bytemuck::cast_slice(&colours));
            self.uploads.instance_bytes += size_of_val(colours.as_slice()) as u64;
            self.draw_coverage(encoder, &groups, runs.len());
            self.written = (instances, viewport, colours);
            Ok(())
        })
    }

    /// The coverage layers for `count` runs on a target of `size`, made anew when they
    /// no longer fit.
    fn layers(&mut self, size: [u32; 2], count: u32) -> &Layers {
        let fits = self
            .layers
            .as_ref()
            .is_some_and(|l| l.size == size && l.count >= count.max(1));
        if !fits {
            self.composite();
            let device = &self.gpu.device;
            let count = count.max(1).next_power_of_two();
            let texture = device.create_texture(&wgpu::TextureDescriptor {
                label: Some("text coverage"),
                size: wgpu::Extent3d {
                    width: size[0],
                    height: size[1],
                    depth_or_array_layers: count,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: Channels::Coverage.format(),
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                    | wgpu::TextureUsages::TEXTURE_BINDING,
                view_formats: &[],
            });
            let layer_view = |layer| {
                texture.create_view(&wgpu::TextureViewDescriptor {
                    dimension: Some(wgpu::TextureViewDimension::D2),
                    base_array_layer: layer,
                    array_layer_count: Some(1),
                    ..Default::default()
                })
            };
            let views = (0..count).map(layer_view).collect();
            let array = texture.create_view(&wgpu::TextureViewDescriptor {
                dimension: Some(wgpu::TextureViewDimension::D2Array),
                ..Default::default()
            });
            let colours = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("text colours"),
                size: u64::from(count) * 16,
                usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let layout = &self.composite.as_ref().expect("made above").0;
            let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("text composite"),
                layout,
                entries: &[
                    wgpu::BindGroupEntry {
                        binding: 0,
                        resource: wgpu::BindingResource::TextureView(&array),
                    },
                    wgpu::BindGroupEntry {
                        binding: 1,
                        resource: colours.as_entire_binding(),
                    },
                ],
            });
            self.layers = Some(Layers {
                size,
                count,
                views,
                colours,
                bind_group,
            });
        }
        self.layers.as_ref().expect("made above")
    }

    /// Records each run's coverage into its layer, its instances added as the `winding`
    /// row adds them.
    fn draw_coverage(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        groups: &[((usize, Variant), Range<u32>)],
        runs: usize,
    ) {
        let gpu = self.gpu.clone();
        let pipelines: Vec<_> = groups
            .iter()
            .map(|&((_, variant), _)| {
                self.winding
                    .pipeline(&gpu, Output::Coverage, variant, Channels::Coverage)
            })
            .collect();
        let (Some(layers), Some(glyphs)) = (&self.layers, &self.glyph_group) else {
            return;
        };
        for run in 0..runs {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("text coverage"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &layers.views[run],
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                ..Default::default()
            });
            pass.set_bind_group(0, self.instances.bind_group(), &[]);
            pass.set_bind_group(1, glyphs, &[]);
            for (((k, _), range), pipeline) in groups.iter().zip(&pipelines) {
                if *k == run {
                    pass.set_pipeline(pipeline);
                    pass.draw(0..4, range.clone());
                }
            }
        }
    }

    /// The composite's layout and pipeline, for the caller's format.
    fn composite(&mut self) -> &(wgpu::BindGroupLayout, wgpu::RenderPipeline) {
        let (gpu, format) = (&self.gpu, self.format);
        self.composite.get_or_insert_with(|| {
            let device = &gpu.device;
            let entry = |binding, ty| wgpu::BindGroupLayoutEntry {
                binding,
                visibility: wgpu::ShaderStages::FRAGMENT,
                ty,
                count: None,
            };
            let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("text composite"),
                entries: &[
                    entry(
                        0,
                        wgpu::BindingType::Texture {
                            sample_type: wgpu::TextureSampleType::Float { filterable: false },
                            view_dimension: wgpu::TextureViewDimension::D2Array,
                            multisampled: false,
                        },
                    ),
                    entry(
                        1,
                        wgpu::BindingType::Buffer {
                            ty: wgpu::BufferBindingType::Storage { read_only: true },
                            has_dynamic_offset: false,
                            min_binding_size: None,
                        },
                    ),
                ],
            });
            let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("text composite"),
                bind_group_layouts: &[None, None, Some(&layout)],
                immediate_size: 0,
            });
            let module = super::SHADER.module(device);
            // Each run's colour, premultiplied, over what the caller drew.
            let pipeline = kit::PipelineBuilder::new("text composite", &pipeline_layout, &module)
                .entry_points("vs_composite", "fs_composite")
                .topology(wgpu::PrimitiveTopology::TriangleList)
                .build_into(
                    device,
                    wgpu::ColorTargetState {
                        format,
                        blend: Some(wgpu::BlendState::PREMULTIPLIED_ALPHA_BLENDING),
                        write_mask: wgpu::ColorWrites::ALL,
                    },
                );
            (layout, pipeline)
        })
    }

    /// Records the prepared runs into `pass`, which must draw into a target of the
    /// format given to [`new`](Self::new), of the viewport given to
    /// [`prepare`](Self::prepare) (the pass's default viewport). Draws nothing before
    /// the first `prepare`.
    pub fn render(&self, pass: &mut wgpu::RenderPass<'_>) {
        let (Some(layers), Some((_, pipeline))) = (&self.layers, &self.composite) else {
            return;
        };
        pass.set_pipeline(pipeline);
        pass.set_bind_group(2, &layers.bind_group, &[]);
        pass.draw(0..3, 0..self.written.2.len() as u32);
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
            .collect::<Vec<_>>()
            .into();
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
