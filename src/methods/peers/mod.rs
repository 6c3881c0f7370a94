//! The peers: the renderers people use, measured beside glyphscope's own methods
//! through their public APIs, at their own settings, on the same device and against the
//! same reference — `vello` (linebender's GPU compute renderer), `glyphon` (the common
//! wgpu text renderer: cosmic-text layout, swash rasterization, a glyph atlas) and
//! `vello-cpu` (linebender's CPU sparse-strips rasterizer, which egui uses too).
//!
//! Each draws white on transparent black into a texture of its own (the format its API
//! renders to); one pass here copies that texture's alpha — linear coverage, no sRGB
//! step — into the coverage target, so the frame loop, readback and metrics are the
//! same as every method's. What a peer cannot draw is refused with
//! [`Error::Refused`](crate::Error::Refused), naming its limit.
//!
//! Each peer sits behind a cargo feature of its own (`glyphon`, `vello`, `vello-cpu`,
//! `msdf`; `peers`, on by default, asks for all four): a build without one has no row
//! for it, and compiles none of its crates. What the picture-drawing peers share is in
//! `picture.rs` (their texture and its copy into the coverage target), what the two
//! linebender renderers share in `linebender.rs` (the scene and camera as their types).

// Each peer is compiled only when its feature is on (all four by default: `peers`).
#[cfg(feature = "glyphon")]
pub mod glyphon;
#[cfg(any(feature = "vello", feature = "vello-cpu"))]
pub mod linebender;
#[cfg(feature = "msdf")]
pub mod msdf;
#[cfg(any(feature = "glyphon", feature = "vello", feature = "vello-cpu"))]
pub mod picture;
#[cfg(feature = "vello")]
pub mod vello;
#[cfg(feature = "vello-cpu")]
pub mod vello_cpu;

use super::info::{Claim, ClaimedSetting};
use crate::gpu::shaders::Shader;

/// The copy pass every peer shares.
pub const SHADER: Shader = crate::method_shader!("peers.wgsl");

/// The stability sweep runs a peer as an observed row: its figures beside the
/// project's methods, no claim of glyphscope's on it.
pub const fn observed(label: &'static str) -> ClaimedSetting {
    ClaimedSetting {
        label,
        params: &[],
        claim: Claim {
            bound: None,
            except: &[],
            limitation: None,
            temporal: None,
            statement: "observed: a peer, measured as it is; glyphscope claims nothing of it",
        },
    }
}
