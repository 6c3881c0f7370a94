//! `glyphon`: the common wgpu text renderer, a peer — cosmic-text shapes and lays out
//! the scene's text, swash rasterizes each glyph into a texture atlas, one instanced
//! quad draws each glyph. It is given the same font bytes (alone in its font system),
//! the scene's text, its size in pixels and a line height equal to glyphscope's; its
//! text area is placed so that its first baseline starts where the scene's does. Where
//! its layout then puts each glyph, against glyphscope's shaping, is measured
//! ([`Method::layout_offset`]) and stated beside its error figures, which include it.
//!
//! A scene of glyphs drawn by their ids (the survey's) is drawn as text too: each
//! instance whose glyph a character maps to (the font's cmap) is that character alone in
//! a text area of its own, placed at the instance's pen, as long as shaping it gives that
//! glyph alone; the others are refused one by one ([`Method::refused_glyphs`]), since
//! glyphon has no way to draw a glyph by its id.
//!
//! An atlas draws translation and uniform scale only: any other camera is refused, as
//! is a scene with no font (synthetic outlines) and a font varied on an axis other than
//! weight (cosmic-text sets `wght` alone).

use std::sync::Arc;

use glam::DVec2;
use glyphon::cosmic_text::CacheKeyFlags;
use glyphon::{
    Attrs, Buffer, Cache, Color, ColorMode, Family, FontSystem, Metrics, Resolution, Shaping,
    SwashCache, TextArea, TextAtlas, TextBounds, TextRenderer, Viewport, Weight,
};

use super::observed;
use super::picture::PeerImage;
use crate::Error;
use crate::camera::Camera;
use crate::gpu::{CoverageTarget, GpuContext};
use crate::methods::info::{MethodInfo, Role, bench_at};
use crate::methods::params::{ParamSpec, Params};
use crate::methods::{LayoutOffset, Method, PeerGpuTime, not_prepared};
use crate::scene::Scene;

/// `glyphon`'s row in the registry.
pub const INFO: MethodInfo = MethodInfo {
    name: NAME,
    summary: "peer: glyphon 0.12, the common wgpu text renderer (cosmic-text layout, swash \
              rasterization, a glyph atlas); translation and uniform scale only",
    role: Role::Peer,
    shader: Some(super::SHADER),
    params: PARAMS,
    colour: [23, 190, 207],
    bench: &[bench_at(&[], true), bench_at(&[("hint", "off")], false)],
    claims: &[observed(NAME)],
    constructor: Some(&|params| Ok(Box::new(Glyphon::new(params)))),
};

pub const NAME: &str = "glyphon";

const PARAMS: &[ParamSpec] = &[ParamSpec {
    key: "hint",
    choices: &["on", "off"],
    numbers: None,
    help: "swash's hinting of the glyph bitmaps (cosmic-text's DISABLE_HINTING flag when \
           off): on is glyphon's default; off draws the outlines as they are.",
}];

pub struct Glyphon {
    hint: bool,
    prepared: Option<Prepared>,
    /// Glyphs of the last scene prepared that no character reaches, with why (kept when
    /// the whole scene is refused for them).
    refused: Vec<(u16, String)>,
    image: Option<PeerImage>,
    /// The last frame's text area top-left (exact, drawn) and camera, for
    /// [`Method::layout_offset`].
    last_frame: Option<(DVec2, DVec2, Camera)>,
}

struct Prepared {
    font_system: FontSystem,
    swash: SwashCache,
    atlas: TextAtlas,
    viewport: Viewport,
    renderer: TextRenderer,
    /// The scene's text as one label at its origin, or (a scene of glyphs by id) one
    /// label per instance glyphon can reach.
    labels: Vec<Label>,
    /// Whether the labels are the scene's text (else one glyph each).
    is_text: bool,
    /// The metrics the buffers were last laid out at.
    laid_out_at: Option<Metrics>,
    scene: Scene,
    /// Lines advance by this many font units (glyphscope's shaping).
    line_advance_units: f64,
    /// The widest or tallest glyph's control box, font units.
    largest_glyph_units: f64,
}

impl Glyphon {
    pub fn new(params: &Params) -> Glyphon {
        Glyphon {
            hint: params.word("hint") != Some("off"),
            prepared: None,
            refused: Vec::new(),
            image: None,
            last_frame: None,
        }
    }
}

/// Text glyphon lays out and draws in an area of its own.
struct Label {
    buffer: Buffer,
    /// Where its first baseline starts in the scene, font units.
    pen: DVec2,
}

/// The weight cosmic-text is to set for a font varied by `variations` with `axes`: the
/// `wght` value, or the axis's own default when none is set (cosmic-text always sets
/// `wght` from the weight it is given); None for a font without a weight axis. Refused:
/// any other axis set, which cosmic-text cannot set, and a fractional weight, which it
/// cannot express.
pub fn weight_for(
    variations: &[(String, f32)],
    axes: &[crate::font::Axis],
) -> Result<Option<Weight>, Error> {
    if let Some((tag, _)) = variations.iter().find(|(tag, _)| tag.trim() != "wght") {
        return Err(Error::Refused(format!(
            "glyphon (cosmic-text) varies fonts by weight only: '{}' is set",
            tag.trim()
        )));
    }
    let set = variations
        .iter()
        .find(|(tag, _)| tag.trim() == "wght")
        .map(|v| v.1);
    let default = axes
        .iter()
        .find(|a| a.tag.trim() == "wght")
        .map(|a| a.default);
    match set.or(default) {
        Some(w) if w.fract() != 0.0 => Err(Error::Refused(format!(
            "glyphon (cosmic-text) takes whole weights only: wght {w}"
        ))),
        Some(w) => Ok(Some(Weight(w as u16))),
        None => Ok(None),
    }
}

/// The line advance, in font units, glyphon is given for `font` (glyphscope's: ascender
/// − descender + line gap), refused unless positive. cosmic-text 0.19 cannot lay out
/// lines that are not: `Buffer::set_metrics` panics on a line height of 0, and
/// `Buffer::shape_until_scroll` never ends on a negative one in a buffer of unbounded
/// height, as glyphon's is here — it scrolls past the first line (whose height is not
/// above the scroll offset, 0), finds the laid-out height short of the unbounded view,
/// scrolls back up by an infinite amount to the first line, and starts again.
fn positive_line_advance(font: &crate::font::Font) -> Result<f64, Error> {
    let (ascender, descender, line_gap) = font.line_metrics();
    let advance = ascender - descender + line_gap;
    if advance > 0.0 {
        return Ok(advance);
    }
    Err(Error::Refused(format!(
        "glyphon cannot lay out this font: its lines would be {advance} units high \
         (ascender {ascender}, descender {descender}, line gap {line_gap}), and \
         cosmic-text's layout never ends on a line height ≤ 0"
    )))
}

/// The font size, in pixels, glyphon draws `camera` at: the camera's map must be a
/// uniform scale (and translation); anything else is refused.
fn font_size_px(camera: &Camera, units_per_em: f64) -> Result<f64, Error> {
    if camera.tilt_deg != 0.0 {
        return Err(Error::Refused(format!(
            "glyphon draws translation and uniform scale only: a tilt ({}°) needs perspective",
            camera.tilt_deg
        )));
    }
    let m = camera.matrix;
    let scale = m.x_axis.x;
    let uniform = m.x_axis.y == 0.0 && m.y_axis.x == 0.0 && m.y_axis.y == scale && scale > 0.0;
    if !uniform {
        return Err(Error::Refused(format!(
            "glyphon draws translation and uniform scale only: the camera's matrix \
             [{:.3} {:.3}; {:.3} {:.3}] turns, skews or mirrors",
            m.x_axis.x, m.y_axis.x, m.x_axis.y, m.y_axis.y
        )));
    }
    Ok(camera.scale(units_per_em) * scale * units_per_em)
}

impl Prepared {
    /// Lays the text out at `font_size` pixels per em if it is not already: the text
    /// is set once, a new size only changes the metrics, as an application zooming
    /// its text would.
    fn lay_out(&mut self, font_size: f64) -> Result<(), Error> {
        let line_height = self.line_advance_units / self.scene.units_per_em * font_size;
        let metrics = Metrics::new(font_size as f32, line_height as f32);
        if self.laid_out_at == Some(metrics) {
            return Ok(());
        }
        // cosmic-text's `Buffer::set_metrics` panics on a font size or line height of 0:
        // positive in f64 (prepare checked the line advance), a tiny size can still
        // round to 0 in f32.
        if !(metrics.font_size > 0.0 && metrics.line_height > 0.0) {
            return Err(Error::Refused(format!(
                "glyphon cannot lay out text at {font_size:e} px/em: its size or line height \
                 rounds to 0 in cosmic-text's f32 metrics"
            )));
        }
        for label in &mut self.labels {
            label.buffer.set_metrics(metrics);
            label
                .buffer
                .shape_until_scroll(&mut self.font_system, false);
        }
        self.laid_out_at = Some(metrics);
        Ok(())
    }

    /// Each glyph of glyphon's layout: its id, its pen as laid out from the exact
    /// top-left `area`, and its pen where glyphon draws it from the top-left `drawn` —
    /// x in quarter-pixel bins, the area's y truncated and the line's baseline rounded
    /// to whole pixels, as its `prepare` places glyphs.
    fn laid_out(buffer: &Buffer, area: DVec2, drawn: DVec2) -> Vec<(u16, DVec2, DVec2)> {
        let mut out = Vec::new();
        for run in buffer.layout_runs() {
            for g in run.glyphs {
                let pen = DVec2::new(
                    f64::from(g.x + g.font_size * g.x_offset),
                    f64::from(run.line_y + g.y - g.font_size * g.y_offset),
                );
                let physical = g.physical((drawn.x as f32, drawn.y as f32), 1.0);
                let placed = DVec2::new(
                    f64::from(physical.x) + f64::from(physical.cache_key.x_bin.as_float()),
                    f64::from(physical.y) + f64::from(run.line_y.round()),
                );
                out.push((g.glyph_id, area + pen, placed));
            }
        }
        out
    }

    /// The text area's top-left that puts a label's first baseline at its pen in the
    /// scene as `camera` sees it, its top on the nearest whole pixel: glyphon truncates
    /// the area's top (and draws each line's baseline at its rounded offset), so a
    /// whole top is where its first baseline lands nearest the scene's.
    /// Also returns the exact top-left, where the layout's own positions are measured
    /// from: (exact, drawn).
    fn area_origin(&self, label: &Label, camera: &Camera) -> (DVec2, DVec2) {
        let origin = camera
            .glyph_to_image(self.scene.units_per_em, label.pen)
            .z_axis
            .truncate();
        let first_baseline = label.buffer.layout_runs().next().map_or(0.0, |r| r.line_y);
        let exact = origin - DVec2::new(0.0, f64::from(first_baseline));
        let top = origin.y - f64::from(first_baseline.round());
        (exact, DVec2::new(origin.x, top.round()))
    }
}

/// A font system holding `font` alone (no system font to fall back on or be matched
/// instead), its family name and the weight cosmic-text is to ask for.
fn font_system_of(font: &crate::font::Font) -> Result<(FontSystem, String, Weight), Error> {
    let weight = weight_for(&font.variations(), &font.axes())?;
    let bytes: Arc<dyn AsRef<[u8]> + Send + Sync> = Arc::new(font.data());
    let mut db = glyphon::fontdb::Database::new();
    db.load_font_source(glyphon::fontdb::Source::Binary(bytes));
    let font_system = FontSystem::new_with_locale_and_db("en-US".into(), db);
    let face = font_system.db().faces().next().ok_or_else(|| {
        Error::Font(format!(
            "glyphon's font database cannot read '{}'",
            font.name()
        ))
    })?;
    let family = face
        .families
        .first()
        .map(|f| f.0.clone())
        .unwrap_or_default();
    // A font with no weight axis: the face's own weight, which cosmic-text matches.
    let weight = weight.unwrap_or(face.weight);
    Ok((font_system, family, weight))
}

/// glyphon's atlas (in the peers' picture format, blending in linear light as the web
/// does), its viewport and a renderer, as its examples make them.
fn atlas_viewport_renderer(gpu: &GpuContext) -> (TextAtlas, Viewport, TextRenderer) {
    let cache = Cache::new(&gpu.device);
    let mut atlas = TextAtlas::with_color_mode(
        &gpu.device,
        &gpu.queue,
        &cache,
        super::picture::PEER_FORMAT,
        ColorMode::Web,
    );
    let renderer = TextRenderer::new(
        &mut atlas,
        &gpu.device,
        wgpu::MultisampleState::default(),
        None,
    );
    let viewport = Viewport::new(&gpu.device, &cache);
    (atlas, viewport, renderer)
}

/// Renders what glyphon prepared into its picture (`image`, made or resized for
/// `target`), trims its atlas as glyphon's own examples do after each frame (glyphs not
/// drawn in it may be evicted, so the atlas does not fill up with every size and bin ever
/// drawn), and copies the picture into `target`.
fn draw_and_copy(
    image: &mut Option<PeerImage>,
    gpu: &GpuContext,
    encoder: &mut wgpu::CommandEncoder,
    target: &CoverageTarget,
    renderer: &TextRenderer,
    atlas: &mut TextAtlas,
    viewport: &Viewport,
) -> Result<(), Error> {
    let mut picture = PeerImage::sized(image.take(), gpu, NAME, target.width, target.height);
    {
        let mut pass = picture.clearing_pass(encoder, NAME);
        renderer
            .render(atlas, viewport, &mut pass)
            .map_err(|e| Error::Gpu(format!("glyphon cannot draw: {e}")))?;
    }
    atlas.trim();
    picture.copy_into(gpu, encoder, target);
    *image = Some(picture);
    Ok(())
}

/// glyphon as an app draws a UI with it: a buffer per label, laid out once, and every
/// frame a text area per label prepared and rendered (the `ui` scene of `glyphscope
/// bench --library`). Moving, the labels scroll down by 0.37 px a frame.
pub struct GlyphonLabels {
    font: crate::font::Font,
    /// (text, px per em, first baseline's start x and y in target pixels).
    labels: Vec<(String, f32, f32, f32)>,
    moving: bool,
    frame: u64,
    state: Option<LabelsState>,
    image: Option<PeerImage>,
}

struct LabelsState {
    font_system: FontSystem,
    swash: SwashCache,
    atlas: TextAtlas,
    viewport: Viewport,
    renderer: TextRenderer,
    /// Per label: its buffer and the top of its text area above its first baseline.
    buffers: Vec<(Buffer, f32)>,
}

impl GlyphonLabels {
    pub fn new(
        font: crate::font::Font,
        labels: Vec<(String, f32, f32, f32)>,
        moving: bool,
    ) -> Self {
        GlyphonLabels {
            font,
            labels,
            moving,
            frame: 0,
            state: None,
            image: None,
        }
    }
}

impl Method for GlyphonLabels {
    fn name(&self) -> &'static str {
        if self.moving {
            "glyphon, labels moving"
        } else {
            "glyphon, labels still"
        }
    }

    fn prepare(&mut self, gpu: &GpuContext, _scene: &Scene) -> Result<(), Error> {
        let line_advance = positive_line_advance(&self.font)? / self.font.units_per_em();
        let (mut font_system, family, weight) = font_system_of(&self.font)?;
        let (atlas, viewport, renderer) = atlas_viewport_renderer(gpu);
        let attrs = Attrs::new().family(Family::Name(&family)).weight(weight);
        let buffers = self
            .labels
            .iter()
            .map(|(text, size, _, _)| {
                let metrics = Metrics::new(*size, *size * line_advance as f32);
                let mut buffer = Buffer::new(&mut font_system, metrics);
                buffer.set_size(None, None);
                buffer.set_text(text, &attrs, Shaping::Advanced, None);
                buffer.shape_until_scroll(&mut font_system, false);
                let baseline = buffer.layout_runs().next().map_or(0.0, |r| r.line_y);
                (buffer, baseline)
            })
            .collect();
        self.state = Some(LabelsState {
            font_system,
            swash: SwashCache::new(),
            atlas,
            viewport,
            renderer,
            buffers,
        });
        Ok(())
    }

    fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        _camera: &Camera,
    ) -> Result<(), Error> {
        let state = self.state.as_mut().ok_or_else(|| not_prepared(NAME))?;
        self.frame += 1;
        let scroll = if self.moving {
            0.37 * self.frame as f32
        } else {
            0.0
        };
        state.viewport.update(
            &gpu.queue,
            Resolution {
                width: target.width,
                height: target.height,
            },
        );
        let areas =
            state
                .buffers
                .iter()
                .zip(&self.labels)
                .map(|((buffer, baseline), (_, _, x, y))| TextArea {
                    buffer,
                    left: *x,
                    top: *y - *baseline + scroll,
                    scale: 1.0,
                    bounds: TextBounds::default(),
                    default_color: Color::rgb(255, 255, 255),
                    custom_glyphs: &[],
                });
        state
            .renderer
            .prepare(
                &gpu.device,
                &gpu.queue,
                &mut state.font_system,
                &mut state.atlas,
                &state.viewport,
                areas,
                &mut state.swash,
            )
            .map_err(|e| match e {
                glyphon::PrepareError::AtlasFull => {
                    Error::Refused("glyphon's atlas cannot hold the labels' glyphs".into())
                }
            })?;
        let (renderer, atlas, viewport) = (&state.renderer, &mut state.atlas, &state.viewport);
        draw_and_copy(
            &mut self.image,
            gpu,
            encoder,
            target,
            renderer,
            atlas,
            viewport,
        )
    }

    fn peer_gpu_time(&mut self, gpu: &GpuContext) -> Result<Option<PeerGpuTime>, Error> {
        super::picture::gpu_time(self.image.as_ref(), gpu, 0.0)
    }

    /// Only the texture glyphon draws into: its atlas's size is not in its API.
    fn gpu_bytes(&self) -> u64 {
        self.image.as_ref().map_or(0, PeerImage::bytes)
    }
}

impl Method for Glyphon {
    fn name(&self) -> &'static str {
        NAME
    }

    fn prepare(&mut self, gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        self.refused.clear();
        let refuse = |why: &str| {
            Err(Error::Refused(format!(
                "glyphon draws a font's text only: {why}"
            )))
        };
        let Some(source) = &scene.source else {
            return refuse("this scene's outlines come from no font");
        };
        let (mut font_system, family, weight) = font_system_of(&source.font)?;
        let line_advance_units = positive_line_advance(&source.font)?;
        let flags = if self.hint {
            CacheKeyFlags::empty()
        } else {
            CacheKeyFlags::DISABLE_HINTING
        };
        let attrs = Attrs::new()
            .family(Family::Name(&family))
            .weight(weight)
            .cache_key_flags(flags);
        // `shaped`: shaped now, to read which glyphs it gives (a glyph by id); the text is
        // shaped once at the frame's size otherwise (`lay_out`).
        let mut label = |text: &str, pen: DVec2, shaped: bool| {
            // No wrapping: each line of the text is one line of the layout.
            let mut buffer = Buffer::new_empty(Metrics::new(16.0, 16.0));
            buffer.set_size(None, None);
            buffer.set_text(text, &attrs, Shaping::Advanced, None);
            if shaped {
                buffer.shape_until_scroll(&mut font_system, false);
            }
            Label { buffer, pen }
        };
        let (mut labels, mut refused): (Vec<Label>, Vec<(u16, String)>) = (Vec::new(), Vec::new());
        match &source.text {
            Some(text) => labels.push(label(text, DVec2::ZERO, false)),
            None => {
                let chars = source.font.chars_of_glyphs();
                for instance in &scene.instances {
                    let id = scene.glyphs[instance.glyph as usize].id;
                    let Some(candidates) = chars.get(&id) else {
                        refused.push((
                            id,
                            "glyphon draws text: no character maps to this glyph".into(),
                        ));
                        continue;
                    };
                    // The first character that shapes to this glyph alone.
                    let made = candidates.iter().find_map(|c| {
                        let made = label(&c.to_string(), instance.position, true);
                        let shaped: Vec<u16> = made
                            .buffer
                            .layout_runs()
                            .flat_map(|run| run.glyphs.iter().map(|g| g.glyph_id))
                            .collect();
                        (shaped == [id]).then_some(made)
                    });
                    match made {
                        Some(made) => labels.push(made),
                        None => refused.push((
                            id,
                            "glyphon draws text: shaping each character that maps to this \
                             glyph gives another glyph, or more than one"
                                .into(),
                        )),
                    }
                }
            }
        }
        // A scene glyphon can draw none of is refused whole, never drawn blank.
        self.refused = refused;
        if let ([], [(_, why), ..]) = (labels.as_slice(), self.refused.as_slice()) {
            return Err(Error::Refused(why.clone()));
        }
        let (atlas, viewport, renderer) = atlas_viewport_renderer(gpu);
        self.prepared = Some(Prepared {
            font_system,
            swash: SwashCache::new(),
            atlas,
            viewport,
            renderer,
            labels,
            is_text: source.text.is_some(),
            laid_out_at: None,
            scene: scene.clone(),
            line_advance_units,
            largest_glyph_units: scene
                .glyphs
                .iter()
                .map(|g| g.bounds.size().max_element())
                .fold(0.0, f64::max),
        });
        Ok(())
    }

    fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        camera: &Camera,
    ) -> Result<(), Error> {
        let prepared = self.prepared.as_mut().ok_or_else(|| not_prepared(NAME))?;
        let font_size = font_size_px(camera, prepared.scene.units_per_em)?;
        // swash rasterizes each glyph whole into the atlas: one larger than the atlas's
        // largest texture cannot be drawn (and swash's rasterizer does not survive it).
        let largest = prepared.largest_glyph_units * font_size / prepared.scene.units_per_em;
        let atlas_side = f64::from(gpu.max_texture_side());
        if largest + 2.0 > atlas_side {
            return Err(Error::Refused(format!(
                "glyphon rasterizes whole glyphs into its atlas: a glyph here is {largest:.0} \
                 px across, past the largest atlas texture ({atlas_side} px)"
            )));
        }
        prepared.lay_out(font_size)?;
        let origins: Vec<(DVec2, DVec2)> = prepared
            .labels
            .iter()
            .map(|label| prepared.area_origin(label, camera))
            .collect();
        prepared.viewport.update(
            &gpu.queue,
            Resolution {
                width: target.width,
                height: target.height,
            },
        );
        let text_areas = prepared
            .labels
            .iter()
            .zip(&origins)
            .map(|(label, (_, area))| TextArea {
                buffer: &label.buffer,
                left: area.x as f32,
                top: area.y as f32,
                scale: 1.0,
                bounds: TextBounds::default(),
                default_color: Color::rgb(255, 255, 255),
                custom_glyphs: &[],
            });
        prepared
            .renderer
            .prepare(
                &gpu.device,
                &gpu.queue,
                &mut prepared.font_system,
                &mut prepared.atlas,
                &prepared.viewport,
                text_areas,
                &mut prepared.swash,
            )
            .map_err(|e| match e {
                glyphon::PrepareError::AtlasFull => Error::Refused(format!(
                    "glyphon's atlas cannot hold the glyphs in view at {font_size:.0} px/em \
                     (its largest texture is {} px a side)",
                    gpu.max_texture_side()
                )),
            })?;
        let (renderer, atlas, viewport) =
            (&prepared.renderer, &mut prepared.atlas, &prepared.viewport);
        draw_and_copy(
            &mut self.image,
            gpu,
            encoder,
            target,
            renderer,
            atlas,
            viewport,
        )?;
        self.last_frame = match (prepared.is_text, origins.first()) {
            (true, Some(&(exact, area))) => Some((exact, area, *camera)),
            _ => None,
        };
        Ok(())
    }

    fn peer_gpu_time(&mut self, gpu: &GpuContext) -> Result<Option<PeerGpuTime>, Error> {
        super::picture::gpu_time(self.image.as_ref(), gpu, 0.0)
    }

    /// Only the texture glyphon draws into: its atlas's size is not in its API.
    fn gpu_bytes(&self) -> u64 {
        self.image.as_ref().map_or(0, PeerImage::bytes)
    }

    fn refused_glyphs(&self) -> Vec<(u16, String)> {
        self.refused.clone()
    }

    fn layout_offset(&self) -> Option<LayoutOffset> {
        let prepared = self.prepared.as_ref()?;
        let (exact, drawn, camera) = self.last_frame.as_ref()?;
        let scene = &prepared.scene;
        let ink: std::collections::HashSet<u16> = scene.glyphs.iter().map(|g| g.id).collect();
        let theirs = Prepared::laid_out(&prepared.labels.first()?.buffer, *exact, *drawn)
            .into_iter()
            .filter(|(id, _, _)| ink.contains(id));
        let ours = scene.instances.iter().map(|i| {
            let pen = camera
                .glyph_to_image(scene.units_per_em, i.position)
                .z_axis
                .truncate();
            (scene.glyphs[i.glyph as usize].id, pen)
        });
        let (mut glyphs, mut mismatched) = (0, 0);
        let (mut laid_out, mut placed) = ((0.0, 0.0f64), (0.0, 0.0f64));
        let add = |sum_max: &mut (f64, f64), distance: f64| {
            sum_max.0 += distance;
            sum_max.1 = sum_max.1.max(distance);
        };
        for ((their_id, pen, drawn), (our_id, ours)) in theirs.zip(ours) {
            glyphs += 1;
            mismatched += usize::from(their_id != our_id);
            add(&mut laid_out, pen.distance(ours));
            add(&mut placed, drawn.distance(ours));
        }
        let mean = |sum: f64| if glyphs > 0 { sum / glyphs as f64 } else { 0.0 };
        Some(LayoutOffset {
            glyphs,
            mismatched,
            laid_out_mean_px: mean(laid_out.0),
            laid_out_max_px: laid_out.1,
            placed_mean_px: mean(placed.0),
            placed_max_px: placed.1,
        })
    }
}
