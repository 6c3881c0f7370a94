//! The parameters of `xor-stencil` — fill rule, MSAA samples, jittered passes and
//! overlay — and the settings they choose.

use crate::methods::Overlay;
use crate::methods::params::{Numbers, ParamSpec, Params};

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
        numbers: None,
        help: "nonzero counts front faces up and back faces down (overlapping contours \
               unite); evenodd flips one stencil bit per triangle (overlaps cancel).",
    },
    ParamSpec {
        key: "msaa",
        choices: &["4", "1"],
        numbers: None,
        help: "Hardware samples per pixel. Nearly free on real GPUs; on lavapipe the 4x \
               buffer costs ~75 MB and a large resolve.",
    },
    ParamSpec {
        key: "passes",
        choices: &["4", "1", "8", "16"],
        numbers: Some(Numbers::Whole {
            min: 1,
            max: MAX_PASSES,
        }),
        help: "Jittered passes accumulated (N-rooks pattern). Each pass redraws every \
               triangle: cost grows linearly, error falls about as 1/√N.",
    },
    ParamSpec {
        key: "overlay",
        choices: &["none", "wireframe"],
        numbers: None,
        help: "wireframe: fan triangles blue, Loop–Blinn curve triangles orange.",
    },
];
pub(super) const OVERLAYS: &[Overlay] = &[Overlay::TriangleWireframe];

impl Settings {
    pub fn from_params(params: &Params) -> Settings {
        let defaults = Settings::default();
        Settings {
            fill: match params.word("fill") {
                Some("evenodd") => FillRule::EvenOdd,
                _ => FillRule::NonZero,
            },
            samples: if params.word("msaa") == Some("1") {
                1
            } else {
                4
            },
            passes: params.whole("passes").unwrap_or(defaults.passes),
            overlay: params.word("overlay").and_then(Overlay::named),
        }
    }
}
