//! The GPU kit every method builds on, knowing nothing of the methods themselves: the
//! device ([`GpuContext`]), the coverage target they render into ([`CoverageTarget`]),
//! MSAA attachments, shaders, timestamp queries, per-instance transforms
//! ([`instances`]), and the helpers that build bind groups and pipelines. The frame loop
//! that drives a method is the explorer's (`glyphscope::methods::frame`).

mod context;
pub mod instances;
pub mod kit;
pub mod msaa;
mod overlay;
pub mod shaders;
mod target;
pub mod timing;

pub use context::{GpuContext, SWIFTSHADER_MANIFEST, offer_swiftshader};
pub use overlay::Overlay;
pub use target::{Channels, CoverageTarget, PendingReadback, clearing_pass};

use glyphscope_core::Error;

/// The error of a method asked to draw before `prepare`: a caller's bug, reported
/// rather than panicking.
pub fn not_prepared(method: &str) -> Error {
    Error::Gpu(format!(
        "method '{method}' was asked to draw before `prepare`"
    ))
}
