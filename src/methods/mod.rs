//! The rendering methods, one module each, behind one trait. The CLI, the bench, the
//! tests and the app all drive them through [`Method`] and render with the same code.

use crate::Error;
use crate::camera::Camera;
use crate::gpu::{CoverageTarget, GpuContext};
use crate::scene::Scene;

/// A GPU glyph-rendering method.
///
/// Life cycle: `prepare` once per scene (and again only when the scene or the method's
/// parameters change), then `encode` once per frame for whatever camera is current.
///
/// `Send`, so that a method can live where its frames are recorded: in the app, egui's
/// paint callbacks (whose resources must be `Send + Sync`) and background threads.
pub trait Method: Send {
    /// The name `--method` takes.
    fn name(&self) -> &'static str;

    /// Builds GPU data for the scene: once per distinct glyph, plus whatever per-instance
    /// data does not depend on the camera.
    fn prepare(&mut self, gpu: &GpuContext, scene: &Scene) -> Result<(), Error>;

    /// Records one frame into `target`: clears it, then draws the prepared scene as
    /// seen by `camera`. Coverage goes to the alpha channel, premultiplied overlay
    /// colour (if any) to rgb. The method keeps any intermediate targets it needs
    /// (MSAA, stencil) itself, sized to `target`.
    fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        camera: &Camera,
    ) -> Result<(), Error>;

    /// GPU memory held for the prepared scene, and for the intermediate targets (MSAA,
    /// stencil) kept from the last frame, bytes.
    fn gpu_bytes(&self) -> u64;

    /// The part of [`Method::gpu_bytes`] that caches rasterized glyphs, for methods that
    /// keep such a cache (the atlas's texture): the memory that grows with the size
    /// glyphs are cached at rather than with the outlines.
    fn cache_bytes(&self) -> Option<u64> {
        None
    }

    /// The overlays this method can draw (chosen with the `overlay` parameter).
    fn overlays(&self) -> &'static [Overlay] {
        &[]
    }

    /// Curves evaluated per covered pixel in a frame seen by `camera`, for methods that
    /// evaluate curves per pixel; measured by the method itself (it may render a pass of
    /// its own to count them).
    fn curves_per_pixel(
        &mut self,
        _gpu: &GpuContext,
        _camera: &Camera,
    ) -> Result<Option<CurveCost>, Error> {
        Ok(None)
    }

    /// The meshes a method built from the outlines on the CPU, for methods that draw
    /// meshes: per glyph points, triangles and error figures, and the time spent.
    fn mesh_stats(&self) -> Option<MeshStats> {
        None
    }

    /// For a peer, the GPU time of the last `encode` that the frame's timestamps do not
    /// see as the peer's own: the work it submitted itself (vello's API submits its own
    /// command buffers; timed by timestamps in submissions just before and after them),
    /// and glyphscope's copy of its picture into the coverage target (timed in its pass),
    /// which is the harness's, not the peer's. None for glyphscope's own methods.
    fn peer_gpu_time(&mut self, _gpu: &GpuContext) -> Result<Option<PeerGpuTime>, Error> {
        Ok(None)
    }

    /// For a peer that lays text out itself (glyphon): how far its glyphs' positions
    /// lie from glyphscope's shaping, in pixels, measured glyph by glyph in the last
    /// frame. Error figures include the difference; this says how much of them it is.
    fn layout_offset(&self) -> Option<LayoutOffset> {
        None
    }
}

/// See [`Method::peer_gpu_time`], ms.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PeerGpuTime {
    /// Work the peer submitted on its own queue submissions.
    pub submitted_ms: f64,
    /// The copy of its picture into the coverage target.
    pub copy_ms: f64,
}

/// How far a peer's own text layout puts glyphs from glyphscope's shaping (pixels):
/// as laid out, and as finally placed after the peer snaps them to its pixel grid.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct LayoutOffset {
    /// Glyphs compared (those with ink, matched in order).
    pub glyphs: usize,
    /// Glyphs whose id differs from glyphscope's at the same place in the text.
    pub mismatched: usize,
    /// Pen positions as the peer's layout gives them.
    pub laid_out_mean_px: f64,
    pub laid_out_max_px: f64,
    /// Pen positions where the peer draws the glyphs, after its own snapping.
    pub placed_mean_px: f64,
    pub placed_max_px: f64,
}

/// Meshes a method holds for the current scene (see [`Method::mesh_stats`]).
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct MeshStats {
    /// Totals over `glyphs`.
    pub points: usize,
    pub triangles: usize,
    /// CPU time spent building meshes since `prepare`, whenever it was spent, ms.
    pub cpu_build_ms: f64,
    /// One entry per mesh held: per distinct glyph, and per scale bucket where the mesh
    /// depends on the scale.
    pub glyphs: Vec<GlyphMeshStats>,
}

/// One glyph's mesh.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct GlyphMeshStats {
    /// The glyph's id in its font.
    pub glyph_id: u16,
    /// log2 of the pixels per font unit the mesh was built for, if it depends on scale.
    pub scale_bucket: Option<i32>,
    /// Outline points the mesh is built on.
    pub points: usize,
    pub triangles: usize,
    /// The method's own area-error figure, if it has one.
    pub area_error: Option<f64>,
}

/// Curves a method evaluated per pixel with nonzero coverage.
pub use crate::gpu::kit::CurveCost;

/// A debug picture a method draws instead of plain coverage. With an overlay on, the
/// target's rgb holds the complete picture to show (premultiplied, over black) and its
/// alpha still holds coverage.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Overlay {
    /// Pixels where the two nearest curves' distances tie (the purple regions of
    /// kocsis1david's font-demo).
    EqualDistance,
    /// Cell borders, each cell tinted by how many curves it lists.
    CellGrid,
    /// Pixels near each curve tinted by its 3-bit sign class for the ray through them.
    CurveClasses,
    /// Curves evaluated per pixel, on a colour scale.
    CostHeatMap,
    /// Triangles as wireframe, by kind.
    TriangleWireframe,
    /// Where curves were subdivided.
    SubdivisionPoints,
}

impl Overlay {
    pub const ALL: [Overlay; 6] = [
        Overlay::EqualDistance,
        Overlay::CellGrid,
        Overlay::CurveClasses,
        Overlay::CostHeatMap,
        Overlay::TriangleWireframe,
        Overlay::SubdivisionPoints,
    ];

    /// The value `--param overlay=` takes.
    pub fn name(self) -> &'static str {
        match self {
            Overlay::EqualDistance => "purple",
            Overlay::CellGrid => "cells",
            Overlay::CurveClasses => "classes",
            Overlay::CostHeatMap => "cost",
            Overlay::TriangleWireframe => "wireframe",
            Overlay::SubdivisionPoints => "points",
        }
    }
}

/// The `overlay` parameter's value among `supported` (None for absent or `none`).
pub fn parse_overlay(
    method: &str,
    value: Option<&str>,
    supported: &[Overlay],
) -> Result<Option<Overlay>, Error> {
    match value {
        None | Some("none") => Ok(None),
        Some(v) => supported
            .iter()
            .copied()
            .find(|o| o.name() == v)
            .map(Some)
            .ok_or_else(|| {
                let names: Vec<_> = supported.iter().map(|o| o.name()).collect();
                Error::Input(format!(
                    "method '{method}' has no overlay '{v}'; it has: none{}{}",
                    if names.is_empty() { "" } else { ", " },
                    names.join(", ")
                ))
            }),
    }
}

/// Parameters as `k=v, k=v`, or `default` when there are none: how tables and reports
/// name a setting.
pub fn settings_text<'a>(params: impl IntoIterator<Item = &'a (String, String)>) -> String {
    let shown: Vec<String> = params
        .into_iter()
        .map(|(k, v)| format!("{k}={v}"))
        .collect();
    if shown.is_empty() {
        "default".into()
    } else {
        shown.join(", ")
    }
}

/// The value of parameter `key`, if given (the last one wins).
pub fn param<'a>(params: &'a Params, key: &str) -> Option<&'a str> {
    params
        .iter()
        .rev()
        .find(|(k, _)| k == key)
        .map(|(_, v)| v.as_str())
}

/// A `--param KEY=VALUE` list, in the order given.
pub type Params = [(String, String)];

/// Creates the GPU method called `name` (see [`registry`]). The reference is not a GPU
/// method: callers ask the registry whether a name is the reference and handle it.
pub fn create(name: &str, params: &Params) -> Result<Box<dyn Method>, Error> {
    let info = registry::find(name)?;
    let create = info.create.ok_or_else(|| {
        Error::Input(format!("'{name}' is drawn on the CPU, not by a GPU method"))
    })?;
    create(params)
}

/// One parameter a method takes, described for controls and help.
#[derive(Clone, Copy, Debug)]
pub struct ParamSpec {
    pub key: &'static str,
    /// The values offered; the first is the default.
    pub choices: &'static [&'static str],
    /// Whole numbers in this range are accepted too (e.g. a band count), when given.
    pub range: Option<(u32, u32)>,
    /// What it does and what it costs.
    pub help: &'static str,
}

/// The parameters of method `name` (none for unknown names and the reference).
pub fn param_specs(name: &str) -> &'static [ParamSpec] {
    registry::find(name).map_or(&[], |m| m.params)
}

/// The error of a method asked to draw before `prepare`: a caller's bug, reported
/// rather than panicking.
pub fn not_prepared(method: &str) -> Error {
    Error::Gpu(format!(
        "method '{method}' was asked to draw before `prepare`"
    ))
}

/// Rejects parameters a method does not take, naming the ones it does.
pub fn reject_unknown_params(method: &str, params: &Params, known: &[&str]) -> Result<(), Error> {
    for (key, _) in params {
        if !known.contains(&key.as_str()) {
            return Err(Error::Input(if known.is_empty() {
                format!("method '{method}' takes no parameters (got '{key}')")
            } else {
                format!(
                    "method '{method}' has no parameter '{key}'; it takes: {}",
                    known.join(", ")
                )
            }));
        }
    }
    Ok(())
}

pub mod atlas;
pub mod bounds;
pub mod frame;
pub mod instances;
pub mod peers;
pub mod registry;
pub mod sdf_cells;
pub mod tessellation;
pub mod winding;
pub mod xor_stencil;
