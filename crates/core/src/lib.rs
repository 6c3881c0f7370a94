//! glyphscope's CPU core: fonts and shaping, Bézier geometry, scenes, the camera
//! convention and coverage images. Nothing here touches a GPU; the GPU kit
//! (`glyphscope-gpu`), the text library (`glyphscope-text`) and the explorer build on it.

pub mod camera;
pub mod coverage;
pub mod font;
pub mod geometry;
pub mod scene;
pub mod shaping;

/// Every failure glyphscope reports. Each message is one line a user can act on.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// Bad input from the user: text, sizes, glyph ids, parameters.
    #[error("{0}")]
    Input(String),
    /// A font that cannot be read or parsed.
    #[error("{0}")]
    Font(String),
    /// No usable GPU, or the GPU failed.
    #[error("{0}")]
    Gpu(String),
    /// A result that cannot be written.
    #[error("{0}")]
    Output(String),
    /// A view a peer renderer cannot draw through its public API (glyphon: anything but
    /// translation and uniform scale; vello: perspective): its documented limit, which
    /// tables show as "n/a — reason", never as a failure or a blank image.
    #[error("{0}")]
    Refused(String),
    /// A result the code cannot vouch for (a value no correct computation gives):
    /// reported, never hidden by a clamp and never a panic.
    #[error("{0}")]
    Internal(String),
}
