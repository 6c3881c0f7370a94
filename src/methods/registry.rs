//! The registry: the list of every method's row, and every list of methods derived from
//! it — the CLI's `--method` values and help, the app's menus, the bench's sweep and
//! plot colours, the stability sweep's variants and claims, shader validation. A method
//! is added by writing its module (with its [`MethodInfo`] row, `info.rs`) and one line
//! in [`METHODS`]; nothing else names it.

use super::Method;
use super::info::{MethodInfo, Role};
use super::params::ParamSpec;
use crate::Error;

/// The exact CPU rasterizer: not a GPU method, so it has no constructor; callers ask
/// [`MethodInfo::is_reference`] and rasterize with [`crate::reference`].
pub const REFERENCE: MethodInfo = MethodInfo {
    name: "reference",
    summary: "exact area coverage on the CPU, in f64: what every method is measured against",
    role: Role::Reference,
    shader: None,
    params: &[],
    colour: [0, 0, 0],
    bench: &[],
    claims: &[],
    constructor: None,
};

/// Every method, in the order menus, tables and plots list them.
pub const METHODS: &[&MethodInfo] = &[
    &REFERENCE,
    &super::bounds::INFO,
    &super::winding::INFO,
    &super::sdf_cells::INFO,
    &super::xor_stencil::INFO,
    &super::tessellation::INFO,
    &super::atlas::INFO,
    #[cfg(feature = "vello")]
    &super::peers::vello::INFO,
    #[cfg(feature = "glyphon")]
    &super::peers::glyphon::INFO,
    #[cfg(feature = "vello-cpu")]
    &super::peers::vello_cpu::INFO,
    #[cfg(feature = "msdf")]
    &super::peers::msdf::INFO,
];

/// The GPU method called `name`, made with the parameters `given`. The reference is
/// not a GPU method: callers ask the registry whether a name is the reference and
/// handle it.
pub fn create(name: &str, given: &[(String, String)]) -> Result<Box<dyn Method>, Error> {
    find(name)?.create(given)
}

/// The parameters of method `name` (none for unknown names and the reference).
pub fn param_specs(name: &str) -> &'static [ParamSpec] {
    find(name).map_or(&[], |m| m.params)
}

/// The peers this build leaves out, each with the feature that builds it in.
const LEFT_OUT: &[(&str, &str)] = &[
    #[cfg(not(feature = "vello"))]
    ("vello", "vello"),
    #[cfg(not(feature = "glyphon"))]
    ("glyphon", "glyphon"),
    #[cfg(not(feature = "vello-cpu"))]
    ("vello-cpu", "vello-cpu"),
    #[cfg(not(feature = "msdf"))]
    ("msdf", "msdf"),
];

/// The method called `name`, or an error listing the names there are (or, for a peer
/// this build leaves out, the feature that builds it in). `wgsl:PATH` is a user's
/// method, its row made from the file ([`super::user`]).
pub fn find(name: &str) -> Result<&'static MethodInfo, Error> {
    if name.starts_with(super::user::PREFIX) {
        return super::user::find(name);
    }
    if let Some((_, feature)) = LEFT_OUT.iter().find(|(peer, _)| *peer == name) {
        return Err(Error::Input(format!(
            "'{name}' is a peer this build of glyphscope leaves out: build it with \
             `--features {feature}` (or the default features)"
        )));
    }
    METHODS
        .iter()
        .copied()
        .find(|m| m.name == name)
        .ok_or_else(|| {
            Error::Input(format!(
                "unknown method '{name}'; choose one of: {}",
                names().collect::<Vec<_>>().join(", ")
            ))
        })
}

/// Every method's name, the reference included.
pub fn names() -> impl Iterator<Item = &'static str> {
    METHODS.iter().map(|m| m.name)
}

/// The methods the bench measures, the baseline among them.
pub fn benched() -> impl Iterator<Item = &'static MethodInfo> {
    METHODS.iter().copied().filter(|m| m.is_benched())
}

/// The method every bench time is divided by.
pub fn baseline() -> &'static MethodInfo {
    METHODS
        .iter()
        .copied()
        .find(|m| m.role == Role::Baseline)
        .expect("the registry has a baseline")
}

/// `--method`'s help: each name with its summary.
pub fn help() -> String {
    METHODS
        .iter()
        .map(|m| format!("{}: {}", m.name, m.summary))
        .collect::<Vec<_>>()
        .join("; ")
}
