//! `xor-stencil`: Evan Wallace's "easy scalable text rendering", counted in the stencil
//! buffer (seed 003, "A more beautiful algorithm").
//!
//! Each contour is drawn as a fan of triangles from its first point over every segment's
//! chord — the polygon through the segment endpoints — plus one Loop–Blinn triangle
//! (p0, p1, p2) per quadratic that keeps only the samples between the chord and the
//! curve (u² − v < 0). Summed with their orientations, these triangles give every
//! sample the outline's exact winding number: the stencil adds +1 for front faces and
//! −1 for back faces (nonzero, 8-bit wrapping counters), or flips a bit (even-odd, the
//! seed's XOR). A cover quad per instance then writes coverage where the stencil says
//! "inside" and clears it. No curve is solved and no epsilon decides anything: what is
//! inside is decided per sample by the rasterizer's own tie rules on shared edges.
//!
//! Anti-aliasing is by point samples, box-filtered: hardware MSAA (`msaa`, 1 or 4)
//! and `passes` jittered repetitions of the whole frame, each adding 1/passes of
//! coverage (Wallace used 6). One frame is one render pass; a pass's covers clear the
//! stencil for the next. See [`jitter_offsets`] for the sample pattern.
//!
//! Cubics are drawn as quadratics within [`DEFAULT_QUAD_TOLERANCE_EM`], tightened as the
//! view zooms in past 4096 px/em so that the conversion stays within 1/16 px. The 8-bit
//! counters are wrong only where the winding number is a nonzero multiple of 256
//! (Wallace's 4-bit ones, at multiples of 16).
//!
//! Instances: under nonzero, all instances count into one stencil, so where instances
//! overlap their windings add, exactly as the reference sums them. Even-odd is a
//! per-outline rule, so there instances are split into layers whose members cannot
//! touch; each layer's parity is folded into a "covered" stencil bit before the next
//! layer draws, and overlapping glyphs unite instead of cancelling.

use std::ops::Range;

use glam::DVec2;

use super::instances::Instances;
use super::{
    CurveCost, Method, Overlay, ParamSpec, Params, param, parse_overlay, reject_unknown_params,
};
use crate::Error;
use crate::camera::Camera;
use crate::geometry::{DEFAULT_QUAD_TOLERANCE_EM, Outline, Rect, Segment, jacobian_bound};
use crate::gpu::msaa::{Attachments, STENCIL_FORMAT};
use crate::gpu::{CoverageTarget, GpuContext};
use crate::scene::Scene;

/// Which samples an outline fills.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FillRule {
    /// Winding number ≠ 0 (fonts' rule, and the reference's).
    NonZero,
    /// Odd winding number.
    EvenOdd,
}

/// The method's parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub fill: FillRule,
    /// MSAA samples per pixel: 1 or 4 (what every WebGPU device has for a blendable
    /// half-float target).
    pub samples: u32,
    /// Jittered passes per frame, 1 to [`MAX_PASSES`].
    pub passes: u32,
    pub overlay: Option<Overlay>,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            fill: FillRule::NonZero,
            samples: 4,
            passes: 4,
            overlay: None,
        }
    }
}

pub const MAX_PASSES: u32 = 64;
/// The parameters `xor-stencil` takes.
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        key: "fill",
        choices: &["nonzero", "evenodd"],
        range: None,
        help: "nonzero counts front faces up and back faces down (overlapping contours \
               unite); evenodd flips one stencil bit per triangle (overlaps cancel).",
    },
    ParamSpec {
        key: "msaa",
        choices: &["4", "1"],
        range: None,
        help: "Hardware samples per pixel. Nearly free on real GPUs; on lavapipe the 4x \
               buffer costs ~75 MB and a large resolve.",
    },
    ParamSpec {
        key: "passes",
        choices: &["4", "1", "8", "16"],
        range: Some((1, MAX_PASSES)),
        help: "Jittered passes accumulated (N-rooks pattern). Each pass redraws every \
               triangle: cost grows linearly, error falls about as 1/√N.",
    },
    ParamSpec {
        key: "overlay",
        choices: &["none", "wireframe"],
        range: None,
        help: "wireframe: fan triangles blue, Loop–Blinn curve triangles orange.",
    },
];
const OVERLAYS: &[Overlay] = &[Overlay::TriangleWireframe];

impl Settings {
    pub fn from_params(params: &Params) -> Result<Settings, Error> {
        let keys: Vec<&str> = PARAMS.iter().map(|p| p.key).collect();
        reject_unknown_params("xor-stencil", params, &keys)?;
        let mut settings = Settings::default();
        if let Some(fill) = param(params, "fill") {
            settings.fill = match fill {
                "nonzero" => FillRule::NonZero,
                "evenodd" => FillRule::EvenOdd,
                _ => {
                    return Err(Error::Input(format!(
                        "xor-stencil: fill must be nonzero or evenodd, got '{fill}'"
                    )));
                }
            };
        }
        if let Some(msaa) = param(params, "msaa") {
            settings.samples = match msaa {
                "1" => 1,
                "4" => 4,
                _ => {
                    return Err(Error::Input(format!(
                        "xor-stencil: msaa must be 1 or 4, got '{msaa}'"
                    )));
                }
            };
        }
        if let Some(passes) = param(params, "passes") {
            settings.passes = passes
                .parse()
                .ok()
                .filter(|p| (1..=MAX_PASSES).contains(p))
                .ok_or_else(|| {
                    Error::Input(format!(
                        "xor-stencil: passes must be a whole number from 1 to {MAX_PASSES}, \
                         got '{passes}'"
                    ))
                })?;
        }
        settings.overlay = parse_overlay("xor-stencil", param(params, "overlay"), OVERLAYS)?;
        Ok(settings)
    }
}

/// A glyph's triangles in font units.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Triangles {
    /// (contour's first point, segment start, segment end) for every segment.
    pub fan: Vec<[[f32; 2]; 3]>,
    /// (p0, p1, p2) of every quadratic, for the Loop–Blinn test.
    pub curves: Vec<[[f32; 2]; 3]>,
}

impl Triangles {
    /// The triangles of `outline` with its cubics replaced by quadratics within
    /// `tolerance` (font units). Triangles with two bit-identical corners cover no sample
    /// under any transform and are left out; every other one is kept, however thin, so
    /// that the ones left share their edges exactly.
    pub fn of(outline: &Outline, tolerance: f64) -> Triangles {
        let point = |p: DVec2| [p.x as f32, p.y as f32];
        let mut triangles = Triangles::default();
        let push = |list: &mut Vec<[[f32; 2]; 3]>, corners: [DVec2; 3]| {
            let [a, b, c] = corners.map(point);
            if a != b && b != c && c != a {
                list.push([a, b, c]);
            }
        };
        for contour in &outline.to_quadratics(tolerance).contours {
            let Some(anchor) = contour.segments.first().map(Segment::start) else {
                continue;
            };
            for segment in &contour.segments {
                push(&mut triangles.fan, [anchor, segment.start(), segment.end()]);
                if let Segment::Quad(p0, p1, p2) = *segment {
                    push(&mut triangles.curves, [p0, p1, p2]);
                }
            }
        }
        triangles
    }
}

/// The sub-pixel offsets of `passes` jittered passes over `samples` MSAA samples,
/// centred on the pixel centre in a cell of side 1/samples.
///
/// The pattern is N-rooks (one point in each row and each column of an N×N grid, so an
/// axis-aligned edge is resolved to 1/N) with samples spread as far apart as a local
/// search finds: from the best affine permutation i ↦ (k·i + c) mod N, swaps of two
/// rows while they increase the smallest distance between two points (or keep it and
/// make it rarer). For N = 4 that is the rotated grid of 4× MSAA; for 6, the best of
/// all 720 patterns.
///
/// With 4 samples, whose standard positions lie at 1/8, 3/8, 5/8 and 7/8 in both axes,
/// offsets within ±1/8 keep every sample inside its pixel, as the box filter needs;
/// the frame's samples then form a 4N-rooks pattern, but one gathered in four
/// quarter-pixel squares (see the README for what that costs).
pub fn jitter_offsets(passes: u32, samples: u32) -> Vec<DVec2> {
    let n = passes.max(1) as usize;
    let point = |i: usize, row: usize| {
        DVec2::new((i as f64 + 0.5) / n as f64, (row as f64 + 0.5) / n as f64)
    };
    // (smallest squared distance between two points, minus how many pairs have it).
    let spread = |rows: &[usize]| -> (f64, i64) {
        let (mut closest, mut count) = (f64::INFINITY, 0);
        for i in 0..n {
            for j in i + 1..n {
                let d = point(i, rows[i]).distance_squared(point(j, rows[j]));
                if d < closest {
                    (closest, count) = (d, 0);
                }
                count -= i64::from(d == closest);
            }
        }
        (closest, count)
    };
    let better = |a: (f64, i64), b: (f64, i64)| a.0 > b.0 || (a.0 == b.0 && a.1 > b.1);
    let gcd = |mut a: usize, mut b: usize| {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    let mut rows: Vec<usize> = (0..n).collect();
    let mut score = spread(&rows);
    for step in (1..n).filter(|&k| gcd(k, n) == 1) {
        for shift in 0..n {
            let candidate: Vec<usize> = (0..n).map(|i| (i * step + shift) % n).collect();
            let s = spread(&candidate);
            if better(s, score) {
                (rows, score) = (candidate, s);
            }
        }
    }
    let mut improved = true;
    while improved {
        improved = false;
        for a in 0..n {
            for b in a + 1..n {
                rows.swap(a, b);
                let s = spread(&rows);
                if better(s, score) {
                    score = s;
                    improved = true;
                } else {
                    rows.swap(a, b);
                }
            }
        }
    }
    let cell = 1.0 / f64::from(samples);
    (0..n).map(|i| (point(i, rows[i]) - 0.5) * cell).collect()
}

/// Assigns each instance a layer such that no two instances of a layer have bounds
/// (pen position + control bounds, grown by `gap` font units) that touch; greedy, left
/// to right. Instances of one layer then never share a sample, however the camera maps
/// the scene: it maps the whole plane by one invertible transform.
fn disjoint_layers(scene: &Scene, gap: f64) -> Vec<u32> {
    let rects: Vec<Rect> = scene
        .instances
        .iter()
        .map(|i| {
            let b = scene.glyphs[i.glyph as usize].bounds;
            Rect {
                min: b.min + i.position - gap,
                max: b.max + i.position + gap,
            }
        })
        .collect();
    let mut order: Vec<usize> = (0..rects.len()).collect();
    order.sort_by(|&a, &b| rects[a].min.x.total_cmp(&rects[b].min.x));
    // Per layer, its members that may still reach instances further right.
    let mut open: Vec<Vec<Rect>> = Vec::new();
    let mut layers = vec![0; rects.len()];
    for i in order {
        let rect = rects[i];
        let mut chosen = None;
        for (layer, members) in open.iter_mut().enumerate() {
            members.retain(|m| m.max.x > rect.min.x);
            if !members.iter().any(|m| m.overlaps(&rect)) {
                chosen = Some(layer);
                break;
            }
        }
        let layer = chosen.unwrap_or_else(|| {
            open.push(Vec::new());
            open.len() - 1
        });
        open[layer].push(rect);
        layers[i] = layer as u32;
    }
    layers
}

/// The `Jitter` uniform of `xor_stencil.wgsl`, one per pass at the device's uniform
/// offset alignment.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct Jitter {
    offset: [f32; 2],
    weight: f32,
    tint: f32,
}

/// Grey level of coverage under the wireframe, so that the lines stand out.
const OVERLAY_TINT: f32 = 0.45;

/// Stencil bit that marks, under even-odd, samples some earlier layer covered.
const COVERED_BIT: u32 = 0x80;

pub struct XorStencil {
    settings: Settings,
    /// Built on the first `prepare`; they depend on the device and the settings only.
    pipelines: Option<Pipelines>,
    prepared: Option<Prepared>,
    attachments: Option<Attachments>,
}

impl XorStencil {
    pub fn new(params: &Params) -> Result<XorStencil, Error> {
        Ok(XorStencil::with_settings(Settings::from_params(params)?))
    }

    pub fn with_settings(settings: Settings) -> XorStencil {
        XorStencil {
            settings,
            pipelines: None,
            prepared: None,
            attachments: None,
        }
    }
}

struct Pipelines {
    layout: wgpu::BindGroupLayout,
    /// For the counting pipeline, built later.
    pipeline_layout: wgpu::PipelineLayout,
    shader: wgpu::ShaderModule,
    fan: wgpu::RenderPipeline,
    curve: wgpu::RenderPipeline,
    /// Even-odd only: a layer's odd samples → `COVERED_BIT`.
    fold_layer: Option<wgpu::RenderPipeline>,
    cover: wgpu::RenderPipeline,
    wireframe: Option<[wgpu::RenderPipeline; 2]>,
    /// For `curves_per_pixel`, built when first asked.
    count: Option<wgpu::RenderPipeline>,
    /// One `Jitter` per pass, and an unshifted one for the overlay, `jitter_stride`
    /// bytes apart.
    jitter: wgpu::Buffer,
    jitter_stride: u64,
}

struct Prepared {
    /// The scene with its instances ordered by (layer, glyph).
    scene: Scene,
    instances: Instances,
    /// (layer, glyph) of each instance.
    keys: Vec<(u32, u32)>,
    /// Whether any glyph has cubics: only then does the geometry depend on the zoom.
    has_cubics: bool,
    geometry: Geometry,
    bind_group: wgpu::BindGroup,
    /// This frame's draws: runs of visible instances with one (layer, glyph).
    runs: Vec<Run>,
    /// How many instances this frame draws.
    visible: u32,
}

#[derive(Clone, Debug)]
struct Run {
    layer: u32,
    glyph: usize,
    instances: Range<u32>,
}

/// Stencil state for both faces alike.
fn stencil(face: wgpu::StencilFaceState, read_mask: u32, write_mask: u32) -> wgpu::StencilState {
    wgpu::StencilState {
        front: face,
        back: face,
        read_mask,
        write_mask,
    }
}

fn face(
    compare: wgpu::CompareFunction,
    fail_op: wgpu::StencilOperation,
    pass_op: wgpu::StencilOperation,
) -> wgpu::StencilFaceState {
    wgpu::StencilFaceState {
        compare,
        fail_op,
        depth_fail_op: wgpu::StencilOperation::Keep,
        pass_op,
    }
}

/// What a pipeline does to colour.
enum ColorOut {
    /// Nothing: stencil only.
    None,
    /// Adds to rgba.
    Add,
    /// Replaces rgb, keeps alpha (coverage).
    ReplaceRgb,
}

/// Compiles one pipeline of the method.
struct Builder<'a> {
    device: &'a wgpu::Device,
    layout: &'a wgpu::PipelineLayout,
    shader: &'a wgpu::ShaderModule,
    samples: u32,
}

impl Builder<'_> {
    /// A pipeline with entry points `vertex` and `fragment`; `stencil` None for passes
    /// without a stencil attachment.
    fn build(
        &self,
        label: &str,
        (vertex, fragment): (&str, &str),
        topology: wgpu::PrimitiveTopology,
        stencil: Option<wgpu::StencilState>,
        color: ColorOut,
    ) -> wgpu::RenderPipeline {
        let add = wgpu::BlendComponent {
            src_factor: wgpu::BlendFactor::One,
            dst_factor: wgpu::BlendFactor::One,
            operation: wgpu::BlendOperation::Add,
        };
        let (blend, write_mask) = match color {
            ColorOut::None => (None, wgpu::ColorWrites::empty()),
            ColorOut::Add => (
                Some(wgpu::BlendState {
                    color: add,
                    alpha: add,
                }),
                wgpu::ColorWrites::ALL,
            ),
            ColorOut::ReplaceRgb => (None, wgpu::ColorWrites::COLOR),
        };
        self.device
            .create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(self.layout),
                vertex: wgpu::VertexState {
                    module: self.shader,
                    entry_point: Some(vertex),
                    compilation_options: Default::default(),
                    buffers: &[],
                },
                primitive: wgpu::PrimitiveState {
                    topology,
                    // Both faces count, with opposite signs under nonzero.
                    cull_mode: None,
                    ..Default::default()
                },
                depth_stencil: stencil.map(|stencil| wgpu::DepthStencilState {
                    format: STENCIL_FORMAT,
                    depth_write_enabled: None,
                    depth_compare: None,
                    stencil,
                    bias: Default::default(),
                }),
                multisample: wgpu::MultisampleState {
                    count: self.samples,
                    ..Default::default()
                },
                fragment: Some(wgpu::FragmentState {
                    module: self.shader,
                    entry_point: Some(fragment),
                    compilation_options: Default::default(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format: CoverageTarget::FORMAT,
                        blend,
                        write_mask,
                    })],
                }),
                multiview_mask: None,
                cache: None,
            })
    }
}

impl Pipelines {
    fn new(gpu: &GpuContext, settings: &Settings) -> Pipelines {
        let device = &gpu.device;
        let storage = |binding| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::VERTEX,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only: true },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let uniform = |binding, dynamic| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: dynamic,
                min_binding_size: None,
            },
            count: None,
        };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("xor-stencil"),
            entries: &[
                storage(0),
                uniform(1, false),
                storage(2),
                storage(3),
                storage(4),
                uniform(5, true),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("xor-stencil"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let shader = crate::gpu::shaders::create_module(device, "xor_stencil.wgsl");
        let builder = Builder {
            device,
            layout: &pipeline_layout,
            shader: &shader,
            samples: settings.samples,
        };

        use wgpu::CompareFunction::{Always, NotEqual};
        use wgpu::PrimitiveTopology::{LineList, TriangleList, TriangleStrip};
        use wgpu::StencilOperation::{DecrementWrap, IncrementWrap, Invert, Keep, Replace, Zero};
        let count = match settings.fill {
            // Front faces add one, back faces take one away: the winding number, mod 256.
            FillRule::NonZero => wgpu::StencilState {
                front: face(Always, Keep, IncrementWrap),
                back: face(Always, Keep, DecrementWrap),
                read_mask: 0xff,
                write_mask: 0xff,
            },
            // Bit 0 flips: the parity. The covered bit is left alone.
            FillRule::EvenOdd => stencil(face(Always, Keep, Invert), 0, 1),
        };
        let fan = builder.build(
            "xor-stencil fan",
            ("vs_fan", "fs_stencil_only"),
            TriangleList,
            Some(count.clone()),
            ColorOut::None,
        );
        let curve = builder.build(
            "xor-stencil curves",
            ("vs_curve", "fs_curve"),
            TriangleList,
            Some(count),
            ColorOut::None,
        );
        // Under even-odd, a layer's odd samples become exactly COVERED_BIT (the stencil
        // reference while it draws): parity cleared, covered set, whatever was there.
        let fold_layer = (settings.fill == FillRule::EvenOdd).then(|| {
            builder.build(
                "xor-stencil layer",
                ("vs_cover", "fs_stencil_only"),
                TriangleStrip,
                Some(stencil(face(NotEqual, Keep, Replace), 1, 0xff)),
                ColorOut::None,
            )
        });
        let cover_mask = match settings.fill {
            FillRule::NonZero => 0xff,
            FillRule::EvenOdd => COVERED_BIT,
        };
        // Stencil reference 0: samples whose masked stencil is nonzero get this pass's
        // coverage, and are cleared for the next pass.
        let cover = builder.build(
            "xor-stencil cover",
            ("vs_cover", "fs_cover"),
            TriangleStrip,
            Some(stencil(face(NotEqual, Keep, Zero), cover_mask, 0xff)),
            ColorOut::Add,
        );
        let wireframe = (settings.overlay == Some(Overlay::TriangleWireframe)).then(|| {
            ["vs_wire_fan", "vs_wire_curve"].map(|vertex| {
                builder.build(
                    "xor-stencil lines",
                    (vertex, "fs_wire"),
                    LineList,
                    Some(wgpu::StencilState::default()),
                    ColorOut::ReplaceRgb,
                )
            })
        });
        let jitter_stride = u64::from(device.limits().min_uniform_buffer_offset_alignment)
            .max(size_of::<Jitter>() as u64);
        Pipelines {
            jitter: jitter_buffer(gpu, settings, jitter_stride as usize),
            jitter_stride,
            layout,
            pipeline_layout,
            shader,
            fan,
            curve,
            fold_layer,
            cover,
            wireframe,
            count: None,
        }
    }
}

/// The `Jitter` entries of every pass of `settings`, and an unshifted one last.
fn jitter_buffer(gpu: &GpuContext, settings: &Settings, stride: usize) -> wgpu::Buffer {
    let offsets = jitter_offsets(settings.passes, settings.samples);
    let tint = if settings.overlay.is_some() {
        OVERLAY_TINT
    } else {
        1.0
    };
    let weight = 1.0 / settings.passes as f32;
    let mut bytes = vec![0u8; stride * (offsets.len() + 1)];
    for (k, offset) in offsets.iter().chain([&DVec2::ZERO]).enumerate() {
        let entry = Jitter {
            offset: offset.as_vec2().to_array(),
            weight,
            tint,
        };
        bytes[k * stride..][..size_of::<Jitter>()].copy_from_slice(bytemuck::bytes_of(&entry));
    }
    let buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("xor-stencil jitter"),
        size: bytes.len() as u64,
        usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    gpu.queue.write_buffer(&buffer, 0, &bytes);
    buffer
}

/// How often to halve the cubic → quadratic tolerance for a view whose largest scale
/// is `px_per_em`: the project's default is 1/16 px at 4096 px/em, and halving it until
/// it is 1/16 px at this scale too keeps zooming in from showing the conversion (a
/// fixed tolerance would not: donner#1158). Eight halvings reach 10⁶ px/em, the largest
/// size; further, the tolerance would pass the f32 precision of the points.
pub fn tolerance_halvings(px_per_em: f64) -> u32 {
    (px_per_em / 4096.0).log2().ceil().clamp(0.0, 8.0) as u32
}

/// What `xor-stencil` uploads for a scene at one conversion tolerance: every distinct
/// glyph's triangles, as points, and its bounds.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GeometryData {
    /// Glyph bounds (min x, min y, max x, max y), font units.
    pub bounds: Vec<[f32; 4]>,
    /// Three points per fan triangle, then per Loop–Blinn triangle.
    pub fan_points: Vec<[f32; 2]>,
    pub curve_points: Vec<[f32; 2]>,
    /// Per distinct glyph, its points in `fan_points` and `curve_points`.
    pub fan_ranges: Vec<Range<u32>>,
    pub curve_ranges: Vec<Range<u32>>,
}

impl GeometryData {
    /// The triangles of every distinct glyph of `scene`, its cubics converted with the
    /// default tolerance halved `halvings` times (see [`tolerance_halvings`]).
    pub fn of_scene(scene: &Scene, halvings: u32) -> GeometryData {
        let tolerance =
            DEFAULT_QUAD_TOLERANCE_EM / f64::from(1u32 << halvings) * scene.units_per_em;
        let mut data = GeometryData::default();
        let append = |points: &mut Vec<[f32; 2]>, triangles: &[[[f32; 2]; 3]]| {
            let start = points.len() as u32;
            points.extend(triangles.iter().flatten());
            start..points.len() as u32
        };
        for glyph in &scene.glyphs {
            let triangles = Triangles::of(&glyph.outline, tolerance);
            data.fan_ranges
                .push(append(&mut data.fan_points, &triangles.fan));
            data.curve_ranges
                .push(append(&mut data.curve_points, &triangles.curves));
            let b = glyph.bounds;
            data.bounds
                .push([b.min.x, b.min.y, b.max.x, b.max.y].map(|v| v as f32));
        }
        data
    }
}

/// Every distinct glyph's triangles and bounds on the GPU, at one conversion tolerance.
struct Geometry {
    /// Halvings of the default cubic → quadratic tolerance (see [`tolerance_halvings`]).
    halvings: u32,
    /// Per distinct glyph, its points in the fan and curve buffers.
    fan_ranges: Vec<Range<u32>>,
    curve_ranges: Vec<Range<u32>>,
    /// Glyph bounds, fan points, curve points.
    buffers: [wgpu::Buffer; 3],
}

impl Geometry {
    fn new(gpu: &GpuContext, scene: &Scene, halvings: u32) -> Geometry {
        const STORAGE: wgpu::BufferUsages = wgpu::BufferUsages::STORAGE;
        let data = GeometryData::of_scene(scene, halvings);
        Geometry {
            halvings,
            buffers: [
                gpu.buffer_of("xor-stencil bounds", &data.bounds, STORAGE),
                gpu.buffer_of("xor-stencil fan", &data.fan_points, STORAGE),
                gpu.buffer_of("xor-stencil curves", &data.curve_points, STORAGE),
            ],
            fan_ranges: data.fan_ranges,
            curve_ranges: data.curve_ranges,
        }
    }
}

fn bind_group(
    gpu: &GpuContext,
    pipelines: &Pipelines,
    instances: &Instances,
    geometry: &Geometry,
) -> wgpu::BindGroup {
    let [bounds, fan, curves] = &geometry.buffers;
    gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("xor-stencil"),
        layout: &pipelines.layout,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: instances.buffer().as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: instances.frame().as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: bounds.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 3,
                resource: fan.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 4,
                resource: curves.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 5,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: &pipelines.jitter,
                    offset: 0,
                    size: wgpu::BufferSize::new(size_of::<Jitter>() as u64),
                }),
            },
        ],
    })
}

impl Prepared {
    fn new(gpu: &GpuContext, pipelines: &Pipelines, fill: FillRule, scene: &Scene) -> Prepared {
        // Instances ordered by (layer, glyph): each run is one draw.
        let layers = match fill {
            FillRule::NonZero => vec![0; scene.instances.len()],
            FillRule::EvenOdd => disjoint_layers(scene, scene.units_per_em / 1024.0),
        };
        let mut order: Vec<usize> = (0..scene.instances.len()).collect();
        order.sort_by_key(|&i| (layers[i], scene.instances[i].glyph));
        let keys = order
            .iter()
            .map(|&i| (layers[i], scene.instances[i].glyph))
            .collect();
        let scene = Scene {
            units_per_em: scene.units_per_em,
            glyphs: scene.glyphs.clone(),
            instances: order.iter().map(|&i| scene.instances[i]).collect(),
        };
        let instances = Instances::new(gpu, &scene);
        let geometry = Geometry::new(gpu, &scene, 0);
        let bind_group = bind_group(gpu, pipelines, &instances, &geometry);
        Prepared {
            has_cubics: scene.glyphs.iter().any(|g| {
                g.outline
                    .segments()
                    .any(|s| matches!(s, Segment::Cubic(..)))
            }),
            scene,
            instances,
            keys,
            geometry,
            bind_group,
            runs: Vec::new(),
            visible: 0,
        }
    }

    /// Writes this frame's instances, finds its runs, and converts the cubics again if
    /// the zoom asks for another tolerance.
    fn update(
        &mut self,
        gpu: &GpuContext,
        pipelines: &Pipelines,
        camera: &Camera,
    ) -> Result<(), Error> {
        // The jitter moves the image by under half a pixel.
        self.visible = self.instances.update(gpu, camera, 0.5)?;
        self.runs.clear();
        let mut px_per_em = 0.0f64;
        for (slot, &index) in self.instances.written().iter().enumerate() {
            let (layer, glyph) = self.keys[index as usize];
            let (glyph, slot) = (glyph as usize, slot as u32);
            match self.runs.last_mut() {
                Some(run) if run.layer == layer && run.glyph == glyph => {
                    run.instances.end = slot + 1
                }
                _ => self.runs.push(Run {
                    layer,
                    glyph,
                    instances: slot..slot + 1,
                }),
            }
            if self.has_cubics {
                let pen = self.scene.instances[index as usize].position;
                let to_image = camera.glyph_to_image(self.scene.units_per_em, pen);
                let bounds = self.scene.glyphs[glyph].bounds;
                px_per_em =
                    px_per_em.max(jacobian_bound(&to_image, &bounds) * self.scene.units_per_em);
            }
        }
        let halvings = tolerance_halvings(px_per_em);
        if halvings != self.geometry.halvings {
            self.geometry = Geometry::new(gpu, &self.scene, halvings);
            self.bind_group = bind_group(gpu, pipelines, &self.instances, &self.geometry);
        }
        Ok(())
    }

    fn bytes(&self) -> u64 {
        self.instances.bytes()
            + self
                .geometry
                .buffers
                .iter()
                .map(wgpu::Buffer::size)
                .sum::<u64>()
    }
}

/// Dynamic offset of pass `k`'s `Jitter`.
fn jitter_offset(pipelines: &Pipelines, k: u32) -> u32 {
    (u64::from(k) * pipelines.jitter_stride) as u32
}

/// Records every pass of a frame: per layer the fan and curve triangles into the stencil
/// (and, under even-odd, the layer folded into the covered bit), then the covers.
fn record_passes(
    pass: &mut wgpu::RenderPass<'_>,
    pipelines: &Pipelines,
    prepared: &Prepared,
    passes: u32,
) {
    for k in 0..passes {
        pass.set_bind_group(0, &prepared.bind_group, &[jitter_offset(pipelines, k)]);
        for layer in prepared.runs.chunk_by(|a, b| a.layer == b.layer) {
            for (pipeline, ranges) in [
                (&pipelines.fan, &prepared.geometry.fan_ranges),
                (&pipelines.curve, &prepared.geometry.curve_ranges),
            ] {
                pass.set_pipeline(pipeline);
                for run in layer {
                    let points = &ranges[run.glyph];
                    if !points.is_empty() {
                        pass.draw(points.clone(), run.instances.clone());
                    }
                }
            }
            if let Some(fold) = &pipelines.fold_layer {
                pass.set_pipeline(fold);
                pass.set_stencil_reference(COVERED_BIT);
                let first = layer[0].instances.start;
                let last = layer[layer.len() - 1].instances.end;
                pass.draw(0..4, first..last);
            }
        }
        pass.set_pipeline(&pipelines.cover);
        pass.set_stencil_reference(0);
        pass.draw(0..4, 0..prepared.visible);
    }
}

impl Method for XorStencil {
    fn name(&self) -> &'static str {
        "xor-stencil"
    }

    fn prepare(&mut self, gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        gpu.catching_errors("preparing 'xor-stencil'", || {
            let pipelines = self
                .pipelines
                .get_or_insert_with(|| Pipelines::new(gpu, &self.settings));
            self.prepared = Some(Prepared::new(gpu, pipelines, self.settings.fill, scene));
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
        let (Some(pipelines), Some(prepared)) = (&self.pipelines, &mut self.prepared) else {
            return Err(super::not_prepared("xor-stencil"));
        };
        prepared.update(gpu, pipelines, camera)?;
        let attachments = Attachments::fit(
            self.attachments.take(),
            gpu,
            target,
            self.settings.samples,
            true,
        );
        {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("xor-stencil"),
                color_attachments: &[Some(
                    attachments.color(target, wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT)),
                )],
                depth_stencil_attachment: attachments.stencil(true),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            if prepared.visible > 0 {
                record_passes(&mut pass, pipelines, prepared, self.settings.passes);
                if let Some(lines) = &pipelines.wireframe {
                    let unshifted = jitter_offset(pipelines, self.settings.passes);
                    pass.set_bind_group(0, &prepared.bind_group, &[unshifted]);
                    for (pipeline, ranges) in lines.iter().zip([
                        &prepared.geometry.fan_ranges,
                        &prepared.geometry.curve_ranges,
                    ]) {
                        pass.set_pipeline(pipeline);
                        for run in &prepared.runs {
                            // Six line vertices per triangle's three points.
                            let points = &ranges[run.glyph];
                            if !points.is_empty() {
                                pass.draw(2 * points.start..2 * points.end, run.instances.clone());
                            }
                        }
                    }
                }
            }
        }
        self.attachments = Some(attachments);
        Ok(())
    }

    fn gpu_bytes(&self) -> u64 {
        let jitter = self.pipelines.as_ref().map_or(0, |p| p.jitter.size());
        let prepared = self.prepared.as_ref().map_or(0, Prepared::bytes);
        let attachments = self.attachments.as_ref().map_or(0, Attachments::bytes);
        jitter + prepared + attachments
    }

    fn overlays(&self) -> &'static [Overlay] {
        OVERLAYS
    }

    /// Loop–Blinn evaluations (u² − v, one per covered sample of a curve triangle, in
    /// every pass) per covered pixel, counted by drawing the frame's curve triangles
    /// into an additive target with the frame's samples and jitter.
    fn curves_per_pixel(
        &mut self,
        gpu: &GpuContext,
        camera: &Camera,
    ) -> Result<Option<CurveCost>, Error> {
        let target = CoverageTarget::new(gpu, camera.width, camera.height)?;
        crate::gpu::render_frame(gpu, self, &target, camera)?;
        let coverage = target.readback(gpu)?;
        let samples = self.settings.samples;
        gpu.catching_errors("counting curve evaluations", || {
            let (Some(pipelines), Some(prepared)) = (&mut self.pipelines, &self.prepared) else {
                unreachable!("render_frame succeeded, so the method is prepared");
            };
            if pipelines.count.is_none() {
                let builder = Builder {
                    device: &gpu.device,
                    layout: &pipelines.pipeline_layout,
                    shader: &pipelines.shader,
                    samples,
                };
                pipelines.count = Some(builder.build(
                    "xor-stencil count",
                    ("vs_curve", "fs_count"),
                    wgpu::PrimitiveTopology::TriangleList,
                    None,
                    ColorOut::Add,
                ));
            }
            let pipelines = &*pipelines;
            let multisampled = Attachments::fit(None, gpu, &target, samples, false);
            let mut encoder = gpu
                .device
                .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                    label: Some("xor-stencil count"),
                });
            {
                let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                    label: Some("xor-stencil count"),
                    color_attachments: &[Some(
                        multisampled.color(&target, wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT)),
                    )],
                    depth_stencil_attachment: None,
                    timestamp_writes: None,
                    occlusion_query_set: None,
                    multiview_mask: None,
                });
                pass.set_pipeline(pipelines.count.as_ref().expect("built above"));
                // `render_frame` left this camera's instances and runs in place.
                for k in 0..self.settings.passes {
                    pass.set_bind_group(0, &prepared.bind_group, &[jitter_offset(pipelines, k)]);
                    for run in &prepared.runs {
                        let points = &prepared.geometry.curve_ranges[run.glyph];
                        if !points.is_empty() {
                            pass.draw(points.clone(), run.instances.clone());
                        }
                    }
                }
            }
            gpu.queue.submit([encoder.finish()]);
            gpu.wait_idle()
        })?;
        // The resolve averaged the samples' counts.
        let counts = target.read_texels(gpu)?;
        let (mut total, mut covered, mut max) = (0.0, 0u64, 0u32);
        for (texel, &c) in counts.iter().zip(&coverage.data) {
            if c > 0.0 {
                let n = f64::from(texel[3]) * f64::from(samples);
                total += n;
                covered += 1;
                max = max.max(n.round() as u32);
            }
        }
        Ok(Some(CurveCost {
            mean: if covered > 0 {
                total / covered as f64
            } else {
                0.0
            },
            max,
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Smallest distance between two of `points`.
    fn closest(points: &[DVec2]) -> f64 {
        let mut d = f64::INFINITY;
        for (i, a) in points.iter().enumerate() {
            for b in &points[i + 1..] {
                d = d.min(a.distance(*b));
            }
        }
        d
    }

    #[test]
    fn jitter_finds_the_rotated_grid_and_the_best_six() {
        // Four passes: the rotated grid of 4x MSAA (rows 2, 0, 3, 1 or its mirror).
        let four = jitter_offsets(4, 1);
        let d = closest(&four);
        assert!(
            (d - (1.0f64 / 16.0 + 1.0 / 4.0).sqrt()).abs() < 1e-12,
            "{four:?}"
        );
        // Six: as far apart as the best of all 720 rooks patterns (among the 6^6 row
        // choices, those that use every row).
        let mut best = 0.0f64;
        for code in 0..6usize.pow(6) {
            let rows: Vec<usize> = (0..6).map(|i| code / 6usize.pow(i) % 6).collect();
            if (0..6).all(|r| rows.contains(&r)) {
                let p: Vec<DVec2> = (0..6)
                    .map(|i| DVec2::new(i as f64 + 0.5, rows[i] as f64 + 0.5) / 6.0)
                    .collect();
                best = best.max(closest(&p));
            }
        }
        assert!((closest(&jitter_offsets(6, 1)) - best).abs() < 1e-12);
    }

    #[test]
    fn jitter_is_a_rooks_pattern_inside_the_pixel() {
        for samples in [1, 4] {
            for passes in 1..=20 {
                let offsets = jitter_offsets(passes, samples);
                assert_eq!(offsets.len(), passes as usize);
                let cell = 1.0 / f64::from(samples);
                // Every offset keeps a sample inside its pixel: the 4x standard
                // positions are 1/8 from the borders.
                for o in &offsets {
                    assert!(o.x.abs() < cell / 2.0 && o.y.abs() < cell / 2.0, "{o}");
                }
                // One per row and one per column of the passes × passes grid.
                for axis in [0, 1] {
                    let mut rows: Vec<i64> = offsets
                        .iter()
                        .map(|o| ((o[axis] / cell + 0.5) * f64::from(passes)).floor() as i64)
                        .collect();
                    rows.sort();
                    assert_eq!(rows, (0..i64::from(passes)).collect::<Vec<_>>());
                }
            }
        }
        assert_eq!(jitter_offsets(1, 1), vec![DVec2::ZERO]);
    }

    #[test]
    fn layers_hold_instances_that_cannot_touch() {
        let font = crate::font::Font::default_font();
        let scene = Scene::from_text(&font, "ffi WAVE\nfjord Tj").unwrap();
        let gap = scene.units_per_em / 1024.0;
        let layers = disjoint_layers(&scene, gap);
        let rect = |i: usize| {
            let inst = scene.instances[i];
            let b = scene.glyphs[inst.glyph as usize].bounds;
            Rect {
                min: b.min + inst.position - gap,
                max: b.max + inst.position + gap,
            }
        };
        let n = scene.instances.len();
        for a in 0..n {
            for b in a + 1..n {
                if layers[a] == layers[b] {
                    assert!(
                        !rect(a).overlaps(&rect(b)),
                        "{a} and {b} share layer {}",
                        layers[a]
                    );
                }
            }
        }
        let count = layers.iter().max().unwrap() + 1;
        assert!((2..=4).contains(&count), "{count} layers");
    }

    #[test]
    fn triangles_count_one_fan_triangle_per_segment_off_the_anchor() {
        // A square with one curved side: 4 segments, of which 2 touch the anchor.
        let p = |x, y| DVec2::new(x, y);
        let outline = Outline {
            contours: vec![crate::geometry::Contour {
                segments: vec![
                    Segment::Line(p(0.0, 0.0), p(10.0, 0.0)),
                    Segment::Quad(p(10.0, 0.0), p(15.0, 5.0), p(10.0, 10.0)),
                    Segment::Line(p(10.0, 10.0), p(0.0, 10.0)),
                    Segment::Line(p(0.0, 10.0), p(0.0, 0.0)),
                ],
            }],
        };
        let t = Triangles::of(&outline, 0.01);
        assert_eq!(t.fan.len(), 2);
        assert_eq!(t.curves, vec![[[10.0, 0.0], [15.0, 5.0], [10.0, 10.0]]]);
    }
}
