//! Method shaders as they are compiled: each file in `shaders/` prefixed with the shared
//! `common.wgsl`. The naga test validates exactly these sources.

/// Shared WGSL prepended to every method shader.
pub const COMMON_WGSL: &str = include_str!("../../shaders/common.wgsl");

/// Every method shader, by file name. A new shader is added here, and only here.
pub const METHOD_SHADERS: &[(&str, &str)] = &[
    ("atlas.wgsl", include_str!("../../shaders/atlas.wgsl")),
    ("bounds.wgsl", include_str!("../../shaders/bounds.wgsl")),
    ("winding.wgsl", include_str!("../../shaders/winding.wgsl")),
    (
        "tessellation.wgsl",
        include_str!("../../shaders/tessellation.wgsl"),
    ),
    (
        "xor_stencil.wgsl",
        include_str!("../../shaders/xor_stencil.wgsl"),
    ),
    (
        "sdf_cells.wgsl",
        include_str!("../../shaders/sdf_cells.wgsl"),
    ),
];

/// The full source of a method shader, common part included.
pub fn source(file: &str) -> String {
    let (_, body) = METHOD_SHADERS
        .iter()
        .find(|(name, _)| *name == file)
        .unwrap_or_else(|| panic!("shader '{file}' is not in METHOD_SHADERS"));
    format!("{COMMON_WGSL}\n{body}")
}

/// Compiles a method shader on `device`.
pub fn create_module(device: &wgpu::Device, file: &str) -> wgpu::ShaderModule {
    device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(file),
        source: wgpu::ShaderSource::Wgsl(source(file).into()),
    })
}
