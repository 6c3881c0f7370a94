//! Sharp text at any zoom, rotation or perspective in your own wgpu or egui app:
//! `winding`'s exact box-filter coverage, drawn in colour into a render pass you own.
//!
//! Create a [`TextRenderer`] for your device and target format, add fonts, and each
//! frame [`prepare`](TextRenderer::prepare) runs of text — each with its font, content,
//! size, a 3×3 projective transform and a colour — then [`render`](TextRenderer::render)
//! them into your pass. Errors are values ([`crate::Error`]), never panics.
//!
#![doc = include_str!("../docs/library.md")]

pub use crate::methods::winding::text::{
    Content, FontId, Held, PositionedGlyph, TextRenderer, TextRun, Uploads,
};
