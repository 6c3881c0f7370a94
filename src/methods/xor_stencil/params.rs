//! `--param` values of `xor-stencil`, checked: fill rule, MSAA samples, jittered passes
//! and overlay.

use crate::Error;
use crate::methods::{Overlay, ParamSpec, Params, param, parse_overlay, reject_unknown_params};

pub const NAME: &str = "xor-stencil";

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
pub(super) const OVERLAYS: &[Overlay] = &[Overlay::TriangleWireframe];

impl Settings {
    pub fn from_params(params: &Params) -> Result<Settings, Error> {
        let keys: Vec<&str> = PARAMS.iter().map(|p| p.key).collect();
        reject_unknown_params(super::NAME, params, &keys)?;
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
        settings.overlay = parse_overlay(super::NAME, param(params, "overlay"), OVERLAYS)?;
        Ok(settings)
    }
}
