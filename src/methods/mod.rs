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
pub trait Method {
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

    /// GPU memory held for the prepared scene, bytes.
    fn gpu_bytes(&self) -> u64;

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
}

/// Curves a method evaluated per pixel with nonzero coverage.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct CurveCost {
    pub mean: f64,
    pub max: u32,
}

/// A debug picture a method draws instead of plain coverage. With an overlay on, the
/// target's rgb holds the complete picture to show (premultiplied, over black) and its
/// alpha still holds coverage.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Overlay {
    /// Pixels where the two nearest curves' distances tie (the seed's purple regions).
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

/// Every method name `--method` accepts, the CPU reference included.
pub const METHOD_NAMES: &[&str] = &[
    "reference",
    "bounds",
    "winding",
    "sdf-cells",
    "xor-stencil",
    "tessellation",
];

/// Creates a GPU method by name. The reference is not a GPU method: callers handle it.
pub fn create(name: &str, params: &Params) -> Result<Box<dyn Method>, Error> {
    let issue = match name {
        "bounds" => return Ok(Box::new(bounds::Bounds::new(params)?)),
        "winding" => 3,
        "sdf-cells" => return Ok(Box::new(sdf_cells::SdfCells::new(params)?)),
        "xor-stencil" => 5,
        "tessellation" => 6,
        _ => {
            return Err(Error::Input(format!(
                "unknown method '{name}'; choose one of: {}",
                METHOD_NAMES.join(", ")
            )));
        }
    };
    Err(Error::Input(format!(
        "method '{name}' is not implemented yet (issue #{issue})"
    )))
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

pub mod bounds;
pub mod instances;
pub mod sdf_cells;
