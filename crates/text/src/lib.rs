#![doc = include_str!("../README.md")]
//!
//! The renderer is [`TextRenderer`]; errors are values ([`Error`]), never panics. The
//! algorithm underneath is the explorer's `winding` row, defined here once
//! ([`winding::Winding`]): the explorer's registry entry adds its parameters, claims
//! and bench settings to it, nothing else.

pub mod winding;

/// The matrix type of [`TextRun::transform`], re-exported so that an app builds one
/// with the same version of glam.
pub use glam;
pub use glyphscope_core::Error;
pub use winding::text::{Content, FontId, Held, PositionedGlyph, TextRenderer, TextRun, Uploads};

// The layers below as this crate's files name them (`crate::geometry`, `crate::gpu`):
// the paths the files had when they were one crate's modules.
use glyphscope_core::{camera, font, geometry, scene};
use glyphscope_gpu as gpu;
