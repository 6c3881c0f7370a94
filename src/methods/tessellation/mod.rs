//! `tessellation` (after Jeff Boody's Glyph): each curve is cut into straight steps,
//! the polygons are triangulated on the CPU, and the GPU draws the triangles with
//! hardware MSAA as the anti-aliasing.
//!
//! - `subdivision=fsa` (`steps=N`): N equal steps per curve; `asa` (`threshold=T`):
//!   1 to 16 steps by Glyph's average-area-error rule; `screen` (`tolerance_px=D`,
//!   the default): never more than D pixels from the curve under the current
//!   transform ([`subdivision`]). A mode's own parameter, given alone, picks the mode.
//! - Triangles from lyon's fill tessellator, nonzero, intersections handled ([`mesh`]).
//! - `msaa=4` (default) or `1`: the samples per pixel of the method's own target.
//! - Overlays: `wireframe` (triangle edges) and `points` (outline points, virtual
//!   midpoints and subdivision steps in three colours).
//!
//! Meshes are built once per distinct glyph in `prepare` for `fsa` and `asa`. The
//! screen-space mode depends on the scale, so its meshes are built per glyph and per
//! scale bucket — the power of two at or above the most pixels a font unit spans
//! anywhere on the instance — when a frame first needs them, with the tolerance that
//! keeps the bucket's largest scale within D pixels (`store.rs`).

pub mod mesh;
mod store;
pub mod subdivision;

use web_time::Instant;

use glam::{DMat2, DMat3, DVec2};

use self::mesh::GlyphMesh;
use self::store::{MeshKey, MeshStore};
use self::subdivision::{GLYPH_TABLE_EM_PER_HEIGHT, Polylines, Subdivision, TaggedContour};
use super::info::{Claim, ClaimedSetting, MethodInfo, Role, Trait, bench_at, within_on_edges};
use super::params::{Numbers, ParamSpec, Params, Value};
use super::sample_pattern::ALIASED_EDGE_MAE_255;
use super::{GlyphMeshStats, MeshStats, Method, Overlay};
use crate::Error;
use crate::camera::Camera;
use crate::font::GlyphId;
use crate::geometry::{Rect, project};
use crate::gpu::instances::Instances;
use crate::gpu::kit::{self, ColorOut, PerTarget, PipelineBuilder, Slot};
use crate::gpu::msaa::Attachments;
use crate::gpu::shaders::Shader;
use crate::gpu::{Channels, CoverageTarget, GpuContext};
use crate::scene::Scene;

/// `tessellation`'s row in the registry.
pub const INFO: MethodInfo = MethodInfo {
    name: NAME,
    summary: "outlines subdivided adaptively to a screen-space tolerance, triangulated, \
              drawn with MSAA (jeffboody's Glyph)",
    role: Role::Method,
    shader: Some(SHADER),
    params: PARAMS,
    colour: [148, 103, 189],
    // MSAA is the accuracy; the tolerance and subdivision mode move the points.
    bench: &[
        bench_at(&[], true),
        bench_at(&[("msaa", "1")], true),
        bench_at(&[("tolerance_px", "0.25")], false),
        bench_at(&[("tolerance_px", "0.05")], false),
        bench_at(&[("subdivision", "asa"), ("threshold", "13")], false),
        bench_at(&[("subdivision", "fsa"), ("steps", "4")], false),
    ],
    claims: &[ClaimedSetting {
        label: NAME,
        params: &[],
        claim: Claim {
            // The maxima set by the margin rule (info::Claim); last measured by
            // `cargo run --release -- stability --methods tessellation`: max 0.474
            // (strong-skew); on its limitations 0.692 (glyphs-2px). The mean is over
            // edge pixels, where MSAA's error lives: over a glyph's slot it grows with
            // the share of edge pixels, and 6/255 there broke on 742 glyphs dense in
            // edges (`glyphscope survey --fonts fonts`). Claimed: the samples beat
            // aliasing, under one centre sample's mean error on a straight edge
            // (49/255, `ALIASED_EDGE_MAE_255`), which coverage rounded to 0 or 1
            // breaks; 4x MSAA is off by 0.070 on average there (18/255), and the
            // flattening adds 0.052 on average at most
            // (`edge_errors_of_msaa_and_the_tolerance`). On its limitations, several
            // edges in a pixel, the mean is held only to the claimed set's worst pixel
            // on one straight edge, 0.45 (115/255). Both set after the survey had shown
            // edge means up to 47.5/255 claimed and 64.2/255 on limitations, from the
            // rule, not from them.
            bound: Some(within_on_edges(0.6, ALIASED_EDGE_MAE_255)),
            except: &[Trait::SubpixelDetail],
            limitation: Some(within_on_edges(0.9, LIMITATION_EDGE_MAE_255)),
            temporal: None,
            statement: "screen-space subdivision with 4x MSAA: no pixel off by more than \
                        0.6, and edge pixels off by less on average than one sample at the \
                        centre is on a straight edge (49/255); four point samples cannot \
                        resolve several edges inside one pixel (0.9 there, 115/255 on \
                        average)",
        },
    }],
    constructor: Some(&|params| Ok(Box::new(Tessellation::new(params)?))),
};

const SHADER: Shader = crate::method_shader!("tessellation.wgsl");

pub const NAME: &str = "tessellation";
const OVERLAYS: &[Overlay] = &[Overlay::TriangleWireframe, Overlay::SubdivisionPoints];

/// The bound on the mean error over edge pixels on glyphs with detail under a pixel
/// (its limitation), 1/255: the worst a pixel crossed by one straight edge can be off,
/// 4x MSAA's 0.309 plus the area the default tolerance can move in a pixel (0.1 × √2),
/// rounded up.
pub const LIMITATION_EDGE_MAE_255: f64 = 115.0;

/// Glyph's default for FSA, and the subdivision its errors are measured against.
pub const DEFAULT_STEPS: u32 = subdivision::BEST_STEPS;
/// Glyph's threshold for "nearly equivalent quality" (artifacts begin between 3 and 13).
pub const DEFAULT_THRESHOLD: f64 = 3.0;
/// The screen-space tolerance's default: the 0.1-pixel budget that jwmcglynn's Donner SVG
/// renderer holds its fills to at any zoom (its change "Keep cubic fills accurate at high
/// zoom").
pub const DEFAULT_TOLERANCE_PX: f64 = 0.1;

/// lyon merges vertices closer than half its tolerance: 2⁻²¹ em (0.01 px at
/// 20 000 px/em), or an eighth of the screen-space tolerance where that is finer, but
/// not below 2⁻²² em, about two f32 steps of a coordinate near 1 em.
const SNAP_EM: f64 = 1.0 / (1u32 << 21) as f64;
const SNAP_FLOOR_EM: f64 = 1.0 / (1u32 << 22) as f64;

/// Pixels the points overlay draws beyond a glyph's bounds.
const MARKER_MARGIN_PX: f64 = 2.0;

/// How curves are cut, as the parameters give it.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Setting {
    Fixed { steps: u32 },
    Adaptive { threshold: f64 },
    Screen { tolerance_px: f64 },
}

pub struct Tessellation {
    setting: Setting,
    samples: u32,
    overlay: Option<Overlay>,
    /// Built on the first `prepare`; depends on the device, the sample count and whether
    /// an overlay is drawn.
    pipelines: Option<Pipelines>,
    scene: Option<PreparedScene>,
    attachments: Option<Attachments>,
}

struct Pipelines {
    layout: wgpu::BindGroupLayout,
    pipeline_layout: wgpu::PipelineLayout,
    shader: wgpu::ShaderModule,
    samples: u32,
    overlay: Option<Overlay>,
    draws: PerTarget<Draws>,
}

/// The pipelines of a frame into one kind of target.
struct Draws {
    fill: wgpu::RenderPipeline,
    edges: wgpu::RenderPipeline,
    markers: wgpu::RenderPipeline,
}

struct PreparedScene {
    units_per_em: f64,
    glyphs: Vec<PreparedGlyph>,
    instances: Instances,
    meshes: MeshStore,
    /// The packed markers; remade when the meshes are repacked.
    bind_group: Option<wgpu::BindGroup>,
    frame: u64,
    build_ms: f64,
}

struct PreparedGlyph {
    id: GlyphId,
    bounds: Rect,
    /// The outline as points and tags, Glyph's input.
    contours: Vec<TaggedContour>,
}

/// The parameters `tessellation` takes.
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        key: "subdivision",
        choices: &["screen", "asa", "fsa"],
        numbers: None,
        help: "screen: never more than tolerance_px from the curve under the current \
               transform (re-tessellates per power-of-two zoom); asa: the adaptive steps \
               of Jeff Boody's Glyph; fsa: N equal steps per curve.",
    },
    ParamSpec {
        key: "steps",
        choices: &["16", "1", "2", "4", "8"],
        numbers: Some(Numbers::Whole { min: 1, max: 1024 }),
        help: "fsa: steps per curve. More steps, more triangles; 16 is the best in Jeff \
               Boody's Glyph.",
    },
    ParamSpec {
        key: "threshold",
        choices: &["3", "1", "13", "20"],
        numbers: Some(Numbers::Real {
            min: 0.0,
            max: f64::INFINITY,
            unit: "",
        }),
        help: "asa: area error per length allowed, in tenths of a unit with the glyph \
               1000 units tall, as in Jeff Boody's Glyph; Glyph sees artifacts begin \
               between 3 and 13.",
    },
    ParamSpec {
        key: "tolerance_px",
        choices: &["0.1", "0.05", "0.25"],
        numbers: Some(Numbers::Real {
            min: 0.01,
            max: 16.0,
            unit: "pixels",
        }),
        help: "screen: largest distance from the true curve, pixels. Halving it costs \
               about 20% more points.",
    },
    ParamSpec {
        key: "msaa",
        choices: &["4", "1"],
        numbers: None,
        help: "Samples per pixel of the method's own target: 4 quantizes coverage to \
               quarters; 1 aliases. 4x costs a large resolve on software GPUs.",
    },
    ParamSpec {
        key: "overlay",
        choices: &["none", "wireframe", "points"],
        numbers: None,
        help: "wireframe: the triangles; points: on-curve, virtual midpoints and \
               subdivision steps.",
    },
];

impl Tessellation {
    pub fn new(params: &Params) -> Result<Tessellation, Error> {
        let steps = params.given("steps").and_then(Value::whole);
        let threshold = params.given("threshold").and_then(Value::real);
        let tolerance_px = params.given("tolerance_px").and_then(Value::real);
        // Each mode's own parameter; given without `subdivision`, it picks its mode.
        let given: Vec<(&str, &str)> = [
            ("steps", "fsa", steps.is_some()),
            ("threshold", "asa", threshold.is_some()),
            ("tolerance_px", "screen", tolerance_px.is_some()),
        ]
        .into_iter()
        .filter(|&(_, _, is_given)| is_given)
        .map(|(key, mode, _)| (key, mode))
        .collect();
        let (mode, why) = match (
            params.given("subdivision").and_then(Value::word),
            given.first(),
        ) {
            (Some(mode), _) => (mode, String::new()),
            (None, Some(&(key, mode))) => (mode, format!(" (implied by {key})")),
            (None, None) => ("screen", String::new()),
        };
        if let Some((key, owner)) = given.iter().find(|(_, owner)| *owner != mode) {
            return Err(Error::Input(format!(
                "method '{NAME}': {key} applies to subdivision={owner}, not to subdivision={mode}{why}"
            )));
        }
        let setting = match mode {
            "fsa" => Setting::Fixed {
                steps: steps.unwrap_or(DEFAULT_STEPS),
            },
            "asa" => Setting::Adaptive {
                threshold: threshold.unwrap_or(DEFAULT_THRESHOLD),
            },
            _ => Setting::Screen {
                tolerance_px: tolerance_px.unwrap_or(DEFAULT_TOLERANCE_PX),
            },
        };
        Ok(Tessellation {
            setting,
            samples: if params.word("msaa") == Some("1") {
                1
            } else {
                4
            },
            overlay: params.word("overlay").and_then(Overlay::named),
            pipelines: None,
            scene: None,
            attachments: None,
        })
    }
}

impl Setting {
    fn depends_on_scale(&self) -> bool {
        matches!(self, Setting::Screen { .. })
    }

    /// The mesh an instance drawn through `to_image` needs: scale-independent, or the
    /// power of two at or above the most pixels one font unit spans on its bounds.
    fn scale_bucket(&self, to_image: &DMat3, bounds: &Rect) -> Option<i32> {
        self.depends_on_scale()
            .then(|| max_local_scale(to_image, bounds).log2().ceil() as i32)
    }

    /// The subdivision of a mesh for `bucket`, in font units.
    fn subdivision(&self, bucket: Option<i32>) -> Subdivision {
        match (*self, bucket) {
            (Setting::Fixed { steps }, _) => Subdivision::Fixed(steps),
            (Setting::Adaptive { threshold }, _) => Subdivision::Adaptive(threshold),
            (Setting::Screen { tolerance_px }, bucket) => {
                Subdivision::Tolerance(tolerance_px * (-f64::from(bucket.unwrap_or(0))).exp2())
            }
        }
    }
}

/// The most image pixels one local unit can span anywhere on `bounds` under the
/// homography `m`: a bound on the largest singular value of its Jacobian over the
/// rectangle. With A the upper-left 2×2 of m, h its perspective row and f(p) the image
/// point, J(p) = (A − f(p)·hᵀ)/w(p); with f₀ the image of the centre,
/// ‖J‖ ≤ (‖A − f₀hᵀ‖ + max‖f − f₀‖·‖h‖) / min w. w is affine and (w > 0) the image of the
/// rectangle is the convex hull of its corners', so the corners give both extremes. Exact
/// for affine maps.
pub fn max_local_scale(m: &DMat3, bounds: &Rect) -> f64 {
    let a = DMat2::from_cols(m.x_axis.truncate(), m.y_axis.truncate());
    let h = DVec2::new(m.x_axis.z, m.y_axis.z);
    let w = |p: DVec2| h.dot(p) + m.z_axis.z;
    let centre = project(m, (bounds.min + bounds.max) * 0.5);
    let reach = bounds
        .corners()
        .map(|c| project(m, c).distance(centre))
        .into_iter()
        .fold(0.0, f64::max);
    let w_min = bounds
        .corners()
        .map(w)
        .into_iter()
        .fold(f64::INFINITY, f64::min);
    let centred = a - DMat2::from_cols(centre * h.x, centre * h.y);
    (spectral_norm(&centred) + reach * h.length()) / w_min
}

/// The largest singular value of a 2×2 matrix.
fn spectral_norm(m: &DMat2) -> f64 {
    let [a, c, b, d] = m.to_cols_array();
    let sum = a * a + b * b + c * c + d * d;
    let det = a * d - b * c;
    ((sum + (sum * sum - 4.0 * det * det).max(0.0).sqrt()) / 2.0).sqrt()
}

/// What `tessellation` builds on the CPU for one glyph (its contours as points and
/// tags, in a font of `units_per_em`): the subdivided polylines and their triangles.
pub fn glyph_mesh(
    contours: &[TaggedContour],
    units_per_em: f64,
    subdivision: Subdivision,
) -> Result<(Polylines, GlyphMesh), lyon_tessellation::TessellationError> {
    let height = units_per_em / GLYPH_TABLE_EM_PER_HEIGHT;
    let polylines = subdivision::subdivide(contours, subdivision, height);
    let snap_em = match subdivision {
        Subdivision::Tolerance(distance) => {
            (distance / units_per_em / 8.0).clamp(SNAP_FLOOR_EM, SNAP_EM)
        }
        _ => SNAP_EM,
    };
    let mesh = GlyphMesh::tessellate(&polylines, (snap_em * units_per_em) as f32)?;
    Ok((polylines, mesh))
}

impl PreparedScene {
    /// Builds the mesh of `key` if missing.
    fn build(&mut self, key: MeshKey, setting: &Setting) -> Result<(), Error> {
        if self.meshes.contains(&key) {
            return Ok(());
        }
        let start = Instant::now();
        let glyph = &self.glyphs[key.glyph as usize];
        let subdivision = setting.subdivision(key.scale_bucket);
        let (polylines, mesh) = glyph_mesh(&glyph.contours, self.units_per_em, subdivision)
            .map_err(|e| {
                Error::Font(format!(
                    "glyph {} could not be triangulated: {e:?}",
                    glyph.id
                ))
            })?;
        let stats = GlyphMeshStats {
            glyph_id: glyph.id,
            scale_bucket: key.scale_bucket,
            points: polylines.points(),
            triangles: mesh.triangle_count(),
            area_error: polylines.area_error,
        };
        self.meshes.insert(key, mesh, stats, self.frame);
        self.build_ms += start.elapsed().as_secs_f64() * 1e3;
        Ok(())
    }

    /// Repacks the meshes if needed, and remakes the bind group that names them.
    fn pack(&mut self, gpu: &GpuContext, layout: &wgpu::BindGroupLayout) {
        if !self.meshes.pack(gpu, self.frame) && self.bind_group.is_some() {
            return;
        }
        let markers = &self.meshes.packed().expect("just packed").markers;
        self.bind_group = Some(kit::bind_group(
            gpu,
            NAME,
            layout,
            &[markers.as_entire_binding()],
        ));
    }
}

impl Pipelines {
    fn new(gpu: &GpuContext, samples: u32, overlay: Option<Overlay>) -> Pipelines {
        let shader = SHADER.module(&gpu.device);
        // The markers (`@group(1)` of tessellation.wgsl).
        let layout = kit::layout(gpu, NAME, &[Slot::Storage]);
        let pipeline_layout = kit::pipeline_layout(gpu, NAME, Some(&layout));
        Pipelines {
            layout,
            pipeline_layout,
            shader,
            samples,
            overlay,
            draws: PerTarget::default(),
        }
    }

    /// The pipelines drawing into targets of `channels`.
    fn draws(&mut self, gpu: &GpuContext, channels: Channels) -> &Draws {
        let Pipelines {
            pipeline_layout,
            shader,
            samples,
            overlay,
            ..
        } = self;
        self.draws.get(channels, |channels| {
            let positions = [Some(wgpu::VertexBufferLayout {
                array_stride: size_of::<[f32; 2]>() as wgpu::BufferAddress,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &wgpu::vertex_attr_array![0 => Float32x2],
            })];
            let shown = channels.shown(*overlay).is_some();
            let constants = [("OVERLAY", f64::from(u8::from(shown)))];
            // No blending: a sample is covered or not (see the shader).
            let pipeline = |label, vertex_entry, buffers, topology, fragment_entry, write_mask| {
                PipelineBuilder::new(label, pipeline_layout, shader)
                    .entry_points(vertex_entry, fragment_entry)
                    .constants(&constants)
                    .vertex_buffers(buffers)
                    .topology(topology)
                    .samples(*samples)
                    .color(ColorOut::Replace(write_mask))
                    .build(&gpu.device, channels)
            };
            use wgpu::{ColorWrites, PrimitiveTopology};
            Draws {
                fill: pipeline(
                    "tessellation fill",
                    "vs_mesh",
                    &positions,
                    PrimitiveTopology::TriangleList,
                    "fs_fill",
                    ColorWrites::ALL,
                ),
                edges: pipeline(
                    "tessellation edges",
                    "vs_mesh",
                    &positions,
                    PrimitiveTopology::LineList,
                    "fs_edge",
                    ColorWrites::COLOR,
                ),
                markers: pipeline(
                    "tessellation points",
                    "vs_marker",
                    &[],
                    PrimitiveTopology::TriangleList,
                    "fs_marker",
                    ColorWrites::COLOR,
                ),
            }
        })
    }
}

impl Method for Tessellation {
    fn name(&self) -> &'static str {
        NAME
    }

    fn prepare(&mut self, gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        gpu.catching_errors("preparing 'tessellation'", || {
            let pipelines = self
                .pipelines
                .get_or_insert_with(|| Pipelines::new(gpu, self.samples, self.overlay));
            let glyphs = scene
                .glyphs
                .iter()
                .map(|g| PreparedGlyph {
                    id: g.id,
                    bounds: g.bounds,
                    contours: TaggedContour::from_outline(&g.outline),
                })
                .collect();
            let mut prepared = PreparedScene {
                units_per_em: scene.units_per_em,
                glyphs,
                instances: Instances::new(gpu, scene),
                meshes: MeshStore::default(),
                bind_group: None,
                frame: 0,
                build_ms: 0.0,
            };
            // Scale-independent meshes are built now, once per distinct glyph.
            if !self.setting.depends_on_scale() {
                for glyph in 0..scene.glyphs.len() as u32 {
                    prepared.build(
                        MeshKey {
                            glyph,
                            scale_bucket: None,
                        },
                        &self.setting,
                    )?;
                }
            }
            prepared.pack(gpu, &pipelines.layout);
            self.scene = Some(prepared);
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
        let (Some(pipelines), Some(scene)) = (&mut self.pipelines, &mut self.scene) else {
            return Err(super::not_prepared(NAME));
        };
        scene.frame += 1;
        let setting = self.setting;
        let glyphs = &scene.glyphs;
        let margin = match self.overlay {
            Some(Overlay::SubdivisionPoints) => MARKER_MARGIN_PX,
            _ => 0.0,
        };
        let groups = scene
            .instances
            .update_grouped(gpu, camera, margin, |glyph, to_image| MeshKey {
                glyph,
                scale_bucket: setting.scale_bucket(to_image, &glyphs[glyph as usize].bounds),
            })?;
        for &(key, _) in &groups {
            scene.build(key, &setting)?;
            scene.meshes.touch(&key, scene.frame);
        }
        scene.pack(gpu, &pipelines.layout);

        let draws = pipelines.draws(gpu, target.channels);
        let attachments =
            Attachments::fit(self.attachments.take(), gpu, target, self.samples, false);
        let attachments = self.attachments.insert(attachments);
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some(NAME),
            color_attachments: &[Some(
                attachments.color(target, wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT)),
            )],
            depth_stencil_attachment: None,
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        if groups.is_empty() {
            return Ok(());
        }
        let packed = scene.meshes.packed().expect("packed above");
        pass.set_bind_group(0, scene.instances.bind_group(), &[]);
        pass.set_bind_group(1, scene.bind_group.as_ref(), &[]);
        pass.set_vertex_buffer(0, packed.vertices.slice(..));
        pass.set_pipeline(&draws.fill);
        pass.set_index_buffer(packed.triangles.slice(..), wgpu::IndexFormat::Uint32);
        for (key, instances) in &groups {
            let ranges = scene.meshes.ranges(key).expect("built above");
            pass.draw_indexed(
                ranges.triangles.clone(),
                ranges.base_vertex,
                instances.clone(),
            );
        }
        match target.channels.shown(self.overlay) {
            Some(Overlay::TriangleWireframe) => {
                pass.set_pipeline(&draws.edges);
                pass.set_index_buffer(packed.edges.slice(..), wgpu::IndexFormat::Uint32);
                for (key, instances) in &groups {
                    let ranges = scene.meshes.ranges(key).expect("built above");
                    pass.draw_indexed(ranges.edges.clone(), ranges.base_vertex, instances.clone());
                }
            }
            Some(Overlay::SubdivisionPoints) => {
                pass.set_pipeline(&draws.markers);
                for (key, instances) in &groups {
                    let markers = &scene.meshes.ranges(key).expect("built above").markers;
                    pass.draw(6 * markers.start..6 * markers.end, instances.clone());
                }
            }
            _ => {}
        }
        Ok(())
    }

    fn gpu_bytes(&self) -> u64 {
        let scene = self
            .scene
            .as_ref()
            .map_or(0, |s| s.instances.bytes() + s.meshes.bytes());
        let attachments = self.attachments.as_ref().map_or(0, Attachments::bytes);
        scene + attachments
    }

    fn overlays(&self) -> &'static [Overlay] {
        OVERLAYS
    }

    fn mesh_stats(&self) -> Option<MeshStats> {
        let scene = self.scene.as_ref()?;
        let glyphs: Vec<GlyphMeshStats> = scene.meshes.stats().cloned().collect();
        Some(MeshStats {
            points: glyphs.iter().map(|g| g.points).sum(),
            triangles: glyphs.iter().map(|g| g.triangles).sum(),
            cpu_build_ms: scene.build_ms,
            glyphs,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edge_errors_of_msaa_and_the_tolerance() {
        use crate::methods::sample_pattern::{
            STANDARD_4X, mean_straight_edge_error, worst_straight_edge_error,
        };
        let worst = worst_straight_edge_error(&STANDARD_4X);
        assert!((worst - 0.3086).abs() < 0.0005, "{worst}");
        let moved = DEFAULT_TOLERANCE_PX * 2f64.sqrt();
        assert_eq!(LIMITATION_EDGE_MAE_255, ((worst + moved) * 255.0).ceil());
        // On average on one straight edge 4x MSAA beats one centre sample by more than
        // the flattening adds on average: a chord within the tolerance h of its arc
        // leaves between them at most (2/3)·h·ℓ of a pixel crossed along ℓ, the mean
        // chord of a unit square being π/4 (Cauchy: π·area / perimeter).
        let mean = mean_straight_edge_error(&STANDARD_4X);
        assert!((mean - 0.0696).abs() < 0.001, "{mean}");
        let flattening = 2.0 / 3.0 * DEFAULT_TOLERANCE_PX * std::f64::consts::FRAC_PI_4;
        assert!(mean + flattening < ALIASED_EDGE_MAE_255 / 255.0, "{mean}");
    }

    /// The largest singular value of the map's Jacobian at `p`, by central differences.
    fn sampled_scale(m: &DMat3, p: DVec2) -> f64 {
        let h = 1e-3;
        let dx = (project(m, p + DVec2::X * h) - project(m, p - DVec2::X * h)) / (2.0 * h);
        let dy = (project(m, p + DVec2::Y * h) - project(m, p - DVec2::Y * h)) / (2.0 * h);
        spectral_norm(&DMat2::from_cols(dx, dy))
    }

    #[test]
    fn local_scale_bounds_the_jacobian_and_is_exact_for_affine_maps() {
        let bounds = Rect {
            min: DVec2::new(-100.0, -300.0),
            max: DVec2::new(1200.0, 1500.0),
        };
        let mut camera = Camera::new(800, 600, 40.0, DVec2::new(100.0, 400.0));
        camera.matrix = Camera::matrix_from_rows(0.9, -0.4, 0.3, 1.2);
        let grid = (0..=20).flat_map(|i| {
            (0..=20).map(move |j| {
                bounds.min + bounds.size() * DVec2::new(f64::from(i), f64::from(j)) / 20.0
            })
        });
        for tilt in [0.0, 40.0, -60.0] {
            camera.tilt_deg = tilt;
            let m = camera.glyph_to_image(2048.0, DVec2::new(5000.0, -900.0));
            let bound = max_local_scale(&m, &bounds);
            let sampled = grid
                .clone()
                .map(|p| sampled_scale(&m, p))
                .fold(0.0, f64::max);
            assert!(
                sampled <= bound * (1.0 + 1e-6),
                "tilt {tilt}: {sampled} > {bound}"
            );
            if tilt == 0.0 {
                assert!(
                    (bound - sampled).abs() < 1e-6 * bound,
                    "{bound} vs {sampled}"
                );
            } else {
                assert!(
                    bound < 2.0 * sampled,
                    "tilt {tilt}: {bound} loose against {sampled}"
                );
            }
        }
    }
}
