//! glyphscope: the methods and their registry, the exact CPU reference and the error
//! metrics, the peers, the lab (bench, stability, survey, motion) and the explorer, on
//! the layers below it — `glyphscope-core` (fonts, shaping, geometry, scenes, cameras),
//! `glyphscope-gpu` (the GPU kit) and `glyphscope-text` (winding and the text library) —
//! re-exported here under the names they had as this crate's modules. It builds and runs
//! without the UI (`--no-default-features`).

#[cfg(feature = "app")]
pub mod app;
pub mod bench;
pub mod cli;
pub mod coverage;
pub mod effort;
pub mod font;
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
pub mod stability;
pub mod survey;
pub mod text;
pub mod view_args;

pub use glyphscope_core::{Error, camera, geometry, scene, shaping};
pub use glyphscope_gpu as gpu;
pub use glyphscope_gpu::method_shader;
