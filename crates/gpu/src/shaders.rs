//! Shaders as they are compiled: a method's file or files of its crate's `shaders/`,
//! concatenated in order and prefixed with the shared `common.wgsl` (this crate's). Each
//! method names its own files ([`crate::method_shader!`]); the naga test validates
//! exactly these sources, for every method of the registry.

/// Shared WGSL prepended to every shader.
pub const COMMON_WGSL: &str = include_str!("../shaders/common.wgsl");

/// Curves evaluated per pixel at the top of every cost heat map's scale: `COST_SCALE`
/// in the shaders, and the legend's label.
pub const COST_SCALE_CURVES: u32 = 16;

/// One shader module: one or more WGSL files of `shaders/`, their text included in the
/// binary. A method with several algorithms keeps each in a file of its own beside the
/// shared part (`winding`): still one module, whose files call each other by name.
#[derive(Clone, Copy, Debug)]
pub struct Shader {
    /// Its first file's name in `shaders/`: the module's label.
    pub file: &'static str,
    /// Every file of it, `file` first, in the order `body` concatenates them.
    pub files: &'static [&'static str],
    /// The files' text, concatenated (a line break between two), without the common
    /// part.
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

/// The [`Shader`] of `shaders/$file`, or of several files of `shaders/` concatenated in
/// the order given (the first names the module): the `shaders/` folder of the crate
/// whose code names it (each crate packages its own shaders).
#[macro_export]
macro_rules! method_shader {
    ($file:literal $(, $more:literal)* $(,)?) => {
        $crate::shaders::Shader {
            file: $file,
            files: &[$file $(, $more)*],
            body: concat!(
                include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/shaders/", $file))
                $(, "\n", include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/shaders/", $more)))*
            ),
        }
    };
}
