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
        "sdf-cells" => 4,
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
