//! The text library, `glyphscope-text`, re-exported: sharp text at any zoom, rotation
//! or perspective in your own wgpu or egui app, `winding`'s exact box-filter coverage
//! drawn in colour into a render pass you own. An app adds that crate alone (one line,
//! none of the explorer's dependencies); the explorer's examples and tests reach it here.
//!
#![doc = include_str!("../docs/library.md")]

pub use glyphscope_text::*;
