//! The GPU kit every method builds on, knowing nothing of the methods themselves: the
//! device ([`GpuContext`]), the coverage target they render into ([`CoverageTarget`]),
//! MSAA attachments, shaders, timestamp queries, and the helpers that build bind groups
//! and pipelines. The frame loop that drives a method is [`crate::methods::frame`].

mod context;
pub mod kit;
pub mod msaa;
pub mod shaders;
mod target;
pub mod timing;

pub use context::{GpuContext, SWIFTSHADER_MANIFEST, offer_swiftshader};
pub use target::{Channels, CoverageTarget, PendingReadback, clearing_pass};
