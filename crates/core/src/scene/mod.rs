//! A scene: glyph instances (which glyph, where) and the set of distinct glyphs they
//! use. Methods build their GPU data once per distinct glyph and reuse it for every
//! instance and frame.
//!
//! `model` holds the scene itself; `joined` rewrites one so that instances whose ink
//! overlaps are one glyph. This file only names them.

mod joined;
mod model;

pub use joined::{JoinCounts, WORD_GAP_EM};
pub use model::{Glyph, Instance, Scene, SceneSource};
