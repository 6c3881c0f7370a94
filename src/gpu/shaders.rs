//! Shaders as they are compiled: a file of `shaders/` prefixed with the shared
//! `common.wgsl`. Each method names its own file ([`crate::method_shader!`]); the naga
//! test validates exactly these sources, for every method of the registry.

/// Shared WGSL prepended to every shader.
pub const COMMON_WGSL: &str = include_str!("../../shaders/common.wgsl");

/// Curves evaluated per pixel at the top of every cost heat map's scale: `COST_SCALE`
/// in the shaders, and the legend's label.
pub const COST_SCALE_CURVES: u32 = 16;

/// One WGSL file of `shaders/`, its text included in the binary.
#[derive(Clone, Copy, Debug)]
pub struct Shader {
    /// Its file name in `shaders/`.
    pub file: &'static str,
    /// The file's text, without the common part.
    pub body: &'static str,
}

impl Shader {
    /// The full source, common part included.
    pub fn source(&self) -> String {
        format!(
            "const COST_SCALE: f32 = {COST_SCALE_CURVES}.0;\n{COMMON_WGSL}\n{}",
            self.body
        )
    }

    /// Compiles it on `device`.
    pub fn module(&self, device: &wgpu::Device) -> wgpu::ShaderModule {
        device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(self.file),
            source: wgpu::ShaderSource::Wgsl(self.source().into()),
        })
    }
}

/// The [`Shader`] of `shaders/$file`, wherever the module naming it sits.
#[macro_export]
macro_rules! method_shader {
    ($file:literal) => {
        $crate::gpu::shaders::Shader {
            file: $file,
            body: include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/shaders/", $file)),
        }
    };
}
