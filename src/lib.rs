//! glyphscope's render core: fonts and shaping, Bézier geometry, scenes, the camera
//! convention, the exact CPU reference, error metrics, the GPU context and the methods.
//! It builds and runs without the UI (`--no-default-features`).

#[cfg(feature = "app")]
pub mod app;
pub mod bench;
pub mod camera;
pub mod cli;
pub mod coverage;
pub mod effort;
pub mod font;
pub mod geometry;
pub mod gpu;
pub mod info;
pub mod intervals;
pub mod link_text;
pub mod magnify;
pub mod measure;
pub mod methods;
pub mod metrics;
pub mod motion;
pub mod named_views;
pub mod outline_overlay;
pub mod reference;
pub mod render;
pub mod scene;
pub mod shaping;
pub mod stability;
pub mod survey;
pub mod text;
pub mod view_args;

/// Every failure the core reports. Each message is one line a user can act on.
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
