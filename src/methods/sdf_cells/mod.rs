//! `sdf-cells`: a signed distance to the outline, per pixel, from the few curves listed
//! in the pixel's cell of a grid over its glyph (kocsis1david's font-demo, and Clément
//! Bœsch's "GPU-computed distances" article for exact distances and the effects).
//!
//! - **estimate** (font-demo's): the curve nearest by its chord decides; the distance is
//!   to its tangent line at the chord's projection parameter, and near-ties (`bias`) are
//!   merged by min or max according to how the outline turns at the tied curves' join.
//!   Cheap; curves are halved until flat (`flatness`) so that the chord and the tangent
//!   line stay near the curve, and where a rule rather than the tangent line gives the
//!   side (ties that disagree, a pixel past the chord's ends) the winding number along
//!   the row does (`ties=winding`).
//! - **exact**: true distance to each quadratic (a cubic solved per curve) and the
//!   inside/outside from the winding number along a ray to +x, never from the nearest
//!   curve.
//!
//! Anti-aliasing takes the distance in pixels from the real footprint: the local
//! gradient of the distance mapped through the derivatives of the pixel's local
//! coordinates, so zoom, rotation, skew and perspective are all accounted for, and the
//! coverage is the box filter's exact value for a straight edge at that angle. Effects
//! (dilate/erode, outline, glow) act on the same distance.
//!
//! CPU side per distinct glyph: [`curves`] lays the quadratics out, [`cells`] chooses
//! what each cell lists, [`encoding`] packs it (font-demo's u32) or lists it, [`glyph`]
//! puts these together. Shader: `shaders/sdf_cells.wgsl`.

pub mod cells;
pub mod curves;
pub mod encoding;
pub mod glyph;
pub mod params;

use glam::DMat2;

use super::info::{
    Claim, ClaimedSetting, MethodInfo, Role, Trait, bench_at, within, within_max_only,
};
use super::params::Params;
use super::{CurveCost, Method, Overlay};
use crate::Error;
use crate::camera::Camera;
use crate::gpu::instances::Instances;
use crate::gpu::kit::{self, PerTarget, PipelineBuilder, Slot};
use crate::gpu::shaders::Shader;
use crate::gpu::{CoverageTarget, GpuContext};
use crate::scene::Scene;
use cells::Mode;
use glyph::PreparedGlyph;
pub use params::Settings;

/// `sdf-cells`' row in the registry.
pub const INFO: MethodInfo = MethodInfo {
    name: params::NAME,
    summary: "signed distance to the few curves listed in the pixel's cell of a grid over \
              its glyph (font-demo's method), estimated or exact",
    role: Role::Method,
    shader: Some(SHADER),
    params: params::PARAMS,
    colour: [44, 160, 44],
    bench: &[bench_at(&[], true), bench_at(&[("mode", "exact")], true)],
    // Bounds set by the margin rule (info::Claim) from the sweep before them.
    claims: &[
        ClaimedSetting {
            label: params::NAME,
            params: &[],
            claim: Claim {
                // Set before the survey that checks it, from what a right sign gives:
                // a pixel whose centre lies inside at distance d from the outline holds
                // the disc of radius d, so its coverage is at least πd² (d ≤ 1/2), while
                // the estimate reads the coverage of a straight edge at distance d, at
                // most 1 − (1/√2 − d)² (a diagonal edge; above d ≈ 0.42 an axis-aligned
                // edge's 1/2 + d is more, past the peak); the difference peaks at
                // d = (1/√2)/(1 + π), 0.62 — and outside, the same by symmetry; a pixel
                // read on the wrong side of its edge is not bounded at all. The
                // remaining 0.18 is for the tangent line's distance error (0.13 px at
                // the diagonal's slope of √2), which halving the curves to 0.004 em
                // keeps small near the outline — an allowance, checked by the survey and
                // the sweep, not derived. The mean is not bounded: one distance per pixel
                // cannot resolve a stroke thinner than the pixel, which reads up to 0.5
                // off on every pixel of it, as coverage rounded to 0 or 1 can (which
                // keeps this claim; the estimate does not claim to beat it there).
                //
                // Without the winding number at ties and corners (`ties=merge`, the
                // method as font-demo publishes it) `glyphscope survey --fonts fonts`
                // found 76 views with a pixel over 0.5 (up to 1.0: β, ✇, ◈, Latin
                // Modern's S and №), the wrong side chosen where curves tie.
                bound: Some(within_max_only(0.8)),
                except: &[],
                limitation: None,
                temporal: None,
                statement: "estimate (font-demo's), overlapping contours merged, curves \
                            halved to within 0.004 em of their chords, and the winding \
                            number deciding the side where curves tie or a corner decides: \
                            no pixel off by more than 0.8 (a right side's worst, 0.62, and \
                            an allowance for the tangent line's distance); the mean is not \
                            bounded (a hairline reads up to 0.5 off, as rounding does)",
            },
        },
        ClaimedSetting {
            label: "sdf-cells exact",
            params: &[("mode", "exact")],
            claim: Claim {
                // Overlapping contours in scope since they are merged first, the bound
                // kept. Last measured (`cargo run --release -- stability --methods
                // sdf-cells`): see docs/stability.md.
                bound: Some(within(0.65, 2.0)),
                except: &[Trait::SubpixelDetail],
                // Last measured, by the same sweep: max 0.620 (glyphs-2px), MAE
                // 7.36/255 (glyphs-2px); set when winding-256 was not merged: 66.01/255.
                limitation: Some(within(0.8, 85.0)),
                temporal: None,
                statement: "overlapping contours merged first: no pixel off by more than \
                            0.65; one edge per pixel, so detail under a pixel (a contour \
                            or several edges inside one) reads up to 0.5 + w/2",
            },
        },
    ],
    constructor: Some(&|params| Ok(Box::new(SdfCells::new(params)))),
};

const SHADER: Shader = crate::method_shader!("sdf_cells.wgsl");

pub struct SdfCells {
    settings: Settings,
    /// Built on the first `prepare`; it depends on the device only.
    pipeline: Option<Pipeline>,
    prepared: Option<PreparedScene>,
}

/// What the fragment shader writes (`Settings.output` in the shader).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u32)]
enum Output {
    Picture = 0,
    EqualDistance = 1,
    CellGrid = 2,
    CostHeatMap = 3,
    /// Curves evaluated, raw, in red: what `curves_per_pixel` reads back.
    CostCount = 4,
}

impl Output {
    fn of(overlay: Option<Overlay>) -> Output {
        match overlay {
            None => Output::Picture,
            Some(Overlay::EqualDistance) => Output::EqualDistance,
            Some(Overlay::CellGrid) => Output::CellGrid,
            // `Settings` only admits the overlays in `params::OVERLAYS`.
            Some(_) => Output::CostHeatMap,
        }
    }
}

/// `GlyphCells` in the shader.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuGlyph {
    pub grid_min: [f32; 2],
    pub cell_size: [f32; 2],
    pub cols: u32,
    pub rows: u32,
    pub point_base: u32,
    pub word_base: u32,
    pub band_offset: u32,
    _pad: u32,
}

/// `Settings` in the shader; lengths in font units.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
struct GpuSettings {
    mode: u32,
    output: u32,
    bias: f32,
    dilate: f32,
    outline: f32,
    glow: f32,
    ties_by_winding: u32,
    _pad: u32,
}

struct Pipeline {
    layout: wgpu::PipelineLayout,
    shader: wgpu::ShaderModule,
    pipelines: PerTarget<wgpu::RenderPipeline>,
    bind_group_layout: wgpu::BindGroupLayout,
}

struct PreparedScene {
    instances: Instances,
    glyphs: wgpu::Buffer,
    points: wgpu::Buffer,
    words: wgpu::Buffer,
    settings: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    units_per_em: f64,
    summary: Summary,
}

/// What `prepare` built, for reports.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct Summary {
    pub glyphs: usize,
    pub cells: usize,
    /// Cells font-demo's packed word cannot hold, listed instead.
    pub escaped_cells: usize,
    /// Curves listed, over all cells.
    pub listed: usize,
    /// Glyph records, points and cell words uploaded.
    pub glyph_bytes: usize,
}

impl SdfCells {
    pub fn new(params: &Params) -> SdfCells {
        SdfCells {
            settings: Settings::from_params(params),
            pipeline: None,
            prepared: None,
        }
    }

    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// What the last `prepare` built.
    pub fn summary(&self) -> Option<Summary> {
        self.prepared.as_ref().map(|p| p.summary)
    }

    fn gpu_settings(&self, units_per_em: f64, output: Output) -> GpuSettings {
        let em = |v: f64| (v * units_per_em) as f32;
        let effects = &self.settings.effects;
        GpuSettings {
            mode: match self.settings.mode {
                Mode::Estimate => 0,
                Mode::Exact => 1,
            },
            output: output as u32,
            bias: em(self.settings.bias_em),
            dilate: em(effects.dilate),
            outline: em(effects.outline),
            glow: em(effects.glow),
            ties_by_winding: u32::from(self.settings.ties_by_winding),
            _pad: 0,
        }
    }

    /// Records one frame writing `output`.
    fn draw(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        camera: &Camera,
        output: Output,
    ) -> Result<(), Error> {
        let reach_px = self.settings.reach_em() * camera.size_px_per_em * magnification(camera);
        let settings = self
            .prepared
            .as_ref()
            .map(|s| self.gpu_settings(s.units_per_em, output));
        let (Some(pipeline), Some(scene), Some(settings)) =
            (&mut self.pipeline, &mut self.prepared, settings)
        else {
            return Err(Error::Gpu(
                "method 'sdf-cells' was asked to draw before `prepare`".into(),
            ));
        };
        let count = scene.instances.update(gpu, camera, reach_px)?;
        gpu.queue
            .write_buffer(&scene.settings, 0, bytemuck::bytes_of(&settings));
        // Coverage adds up where quads overlap, and so does the cost the cost pass
        // counts.
        let draw = pipeline.pipelines.get(target.channels, |channels| {
            PipelineBuilder::new(params::NAME, &pipeline.layout, &pipeline.shader)
                .build(&gpu.device, channels)
        });
        let mut pass = target.clearing_pass(encoder, params::NAME);
        if count > 0 {
            pass.set_pipeline(draw);
            pass.set_bind_group(0, scene.instances.bind_group(), &[]);
            pass.set_bind_group(1, &scene.bind_group, &[]);
            pass.draw(0..4, 0..count);
        }
        Ok(())
    }
}

/// An upper bound of how many pixels one pixel-per-em unit can span under the camera's
/// matrix and tilt: for culling instances whose effects reach into the view.
fn magnification(camera: &Camera) -> f64 {
    let m: DMat2 = camera.matrix;
    // The largest singular value is at most the Frobenius norm.
    let linear = m.x_axis.length_squared() + m.y_axis.length_squared();
    let tilt = if camera.tilt_deg == 0.0 { 1.0 } else { 4.0 };
    linear.sqrt() * tilt
}

impl Pipeline {
    fn new(gpu: &GpuContext) -> Pipeline {
        let shader = SHADER.module(&gpu.device);
        // glyphs, points, words, settings (`@group(1)` of sdf_cells.wgsl).
        let slots = [Slot::Storage, Slot::Storage, Slot::Storage, Slot::Uniform];
        let bind_group_layout = kit::layout(gpu, params::NAME, &slots);
        let layout = kit::pipeline_layout(gpu, params::NAME, Some(&bind_group_layout));
        Pipeline {
            layout,
            shader,
            pipelines: PerTarget::default(),
            bind_group_layout,
        }
    }
}

/// Every distinct glyph's data concatenated as the shader reads it.
pub struct SceneData {
    pub glyphs: Vec<GpuGlyph>,
    pub points: Vec<[f32; 2]>,
    pub words: Vec<u32>,
    pub summary: Summary,
}

impl SceneData {
    /// What `sdf-cells` uploads for `scene` with `settings`: every distinct glyph
    /// prepared, then laid out in the shader's buffers.
    pub fn of_scene(scene: &Scene, settings: &Settings) -> Result<SceneData, Error> {
        let merged;
        let scene = match settings.overlaps {
            params::Overlaps::Merge => {
                merged = scene.with_overlaps_merged();
                &merged
            }
            params::Overlaps::Keep => scene,
        };
        let prepared = scene
            .glyphs
            .iter()
            .map(|g| PreparedGlyph::new(&g.outline, scene.units_per_em, settings))
            .collect::<Result<Vec<_>, Error>>()?;
        Ok(SceneData::new(&prepared))
    }

    fn new(prepared: &[PreparedGlyph]) -> SceneData {
        let mut data = SceneData {
            glyphs: Vec::with_capacity(prepared.len()),
            points: Vec::new(),
            words: Vec::new(),
            summary: Summary::default(),
        };
        for glyph in prepared {
            let point_base = data.points.len() as u32;
            let word_base = data.words.len() as u32;
            data.points
                .extend(glyph.layout.points.iter().map(|p| p.as_vec2().to_array()));
            data.words.extend(&glyph.cells.words);
            let band_offset = data.words.len() as u32 - word_base;
            // Band headers (offset from the glyph's first word, count), then the bands.
            let mut offset = band_offset + 2 * glyph.bands.len() as u32;
            for band in &glyph.bands {
                data.words.extend([offset, band.len() as u32]);
                offset += band.len() as u32;
            }
            data.words.extend(glyph.bands.iter().flatten());
            let grid = &glyph.grid;
            data.glyphs.push(GpuGlyph {
                grid_min: grid.origin.as_vec2().to_array(),
                cell_size: grid.cell.as_vec2().to_array(),
                cols: grid.cols,
                rows: grid.rows,
                point_base,
                word_base,
                band_offset,
                _pad: 0,
            });
            data.summary.glyphs += 1;
            data.summary.cells += grid.cells();
            data.summary.escaped_cells += glyph.cells.escaped;
            data.summary.listed += glyph.lists.iter().map(Vec::len).sum::<usize>();
        }
        data.summary.glyph_bytes = std::mem::size_of_val(data.glyphs.as_slice())
            + std::mem::size_of_val(data.points.as_slice())
            + std::mem::size_of_val(data.words.as_slice());
        data
    }
}

impl Method for SdfCells {
    fn name(&self) -> &'static str {
        params::NAME
    }

    fn prepare(&mut self, gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        gpu.catching_errors("preparing 'sdf-cells'", || {
            if self.pipeline.is_none() {
                self.pipeline = Some(Pipeline::new(gpu));
            }
            let pipeline = self.pipeline.as_ref().expect("just built");
            let scene = scene.joined_if(self.settings.join_instances);
            let data = SceneData::of_scene(&scene, &self.settings)?;
            let instances = Instances::new(gpu, &scene);
            let storage = wgpu::BufferUsages::STORAGE;
            let glyphs = gpu.buffer_of("sdf-cells glyphs", &data.glyphs, storage);
            let points = gpu.buffer_of("sdf-cells points", &data.points, storage);
            let words = gpu.buffer_of("sdf-cells words", &data.words, storage);
            let settings = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("sdf-cells settings"),
                size: size_of::<GpuSettings>() as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let bind_group = kit::bind_group(
                gpu,
                params::NAME,
                &pipeline.bind_group_layout,
                &[&glyphs, &points, &words, &settings].map(wgpu::Buffer::as_entire_binding),
            );
            self.prepared = Some(PreparedScene {
                instances,
                glyphs,
                points,
                words,
                settings,
                bind_group,
                units_per_em: scene.units_per_em,
                summary: data.summary,
            });
            Ok(())
        })
    }

    fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        camera: &Camera,
    ) -> Result<(), Error> {
        let output = Output::of(target.channels.shown(self.settings.overlay));
        self.draw(gpu, encoder, target, camera, output)
    }

    fn gpu_bytes(&self) -> u64 {
        self.prepared.as_ref().map_or(0, |s| {
            s.instances.bytes()
                + s.glyphs.size()
                + s.points.size()
                + s.words.size()
                + s.settings.size()
        })
    }

    fn overlays(&self) -> &'static [Overlay] {
        params::OVERLAYS
    }

    /// Renders a pass that writes, per pixel, the curves every instance evaluated there
    /// (cell curves plus, in exact mode, the winding band's curves up to the early exit),
    /// and averages it over the pixels with coverage.
    fn curves_per_pixel(
        &mut self,
        gpu: &GpuContext,
        camera: &Camera,
    ) -> Result<Option<CurveCost>, Error> {
        kit::count_curves(gpu, (camera.width, camera.height), |encoder, target| {
            self.draw(gpu, encoder, target, camera, Output::CostCount)
        })
        .map(Some)
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec2;

    use super::INFO;
    use crate::methods::sample_pattern::area_below;

    /// The estimate's bound: a pixel read on the right side, at the right distance d
    /// from the outline, is off by at most the coverage of a straight edge at d (what
    /// it reads, largest for a diagonal one) less πd² (what the disc of radius d about
    /// its centre, inside the outline, covers at least). Hand-worked: 0.62 at
    /// d = (1/√2)/(1 + π); the claim leaves 0.18 of its 0.8 to the distance's error.
    #[test]
    fn the_estimates_bound_is_a_right_sides_worst_and_a_distance_error() {
        let mut worst = 0.0f64;
        for k in 0..=500 {
            let d = 0.5 * f64::from(k) / 500.0;
            for a in 0..=90 {
                let n = DVec2::from_angle(f64::from(a).to_radians());
                // The part of the pixel within d of its centre along n, past the edge.
                let centre = n.dot(DVec2::splat(0.5));
                let read = area_below(n, centre + d);
                worst = worst.max(read - std::f64::consts::PI * d * d);
            }
        }
        let peak = 0.5f64.sqrt() / (1.0 + std::f64::consts::PI);
        let closed = 1.0 - (0.5f64.sqrt() - peak).powi(2) - std::f64::consts::PI * peak * peak;
        assert!((worst - closed).abs() < 1e-3, "{worst} against {closed}");
        assert!((closed - 0.621).abs() < 1e-3, "{closed}");
        let bound = INFO.claims[0]
            .claim
            .bound
            .expect("the estimate claims a bound");
        assert_eq!(bound.max, 0.8);
        assert!(bound.max - closed > 0.15);
    }
}
