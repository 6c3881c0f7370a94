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

    /// Glyphs of the prepared scene this method leaves undrawn, each with why: a peer
    /// that draws text (glyphon) cannot reach a glyph no character maps to. The rest of
    /// the scene is drawn.
    fn refused_glyphs(&self) -> Vec<(u16, String)> {
        Vec::new()
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

pub use crate::gpu::Overlay;

pub use crate::gpu::not_prepared;

pub mod atlas;
pub mod bounds;
pub mod frame;
pub mod glyph_atlas;
pub mod guarded;
pub mod info;
pub mod params;
pub mod peers;
pub mod registry;
pub mod sample_pattern;
pub mod sdf_cells;
pub mod tessellation;
pub mod user;
pub mod winding;
pub mod xor_stencil;
