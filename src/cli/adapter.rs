//! What several subcommands share: the adapter they draw with, and the view options a
//! named view replaces.

use clap::Args;

/// The adapter a command draws with, for the commands that time or compare drawings.
#[derive(Args, Clone, Debug)]
pub struct AdapterArgs {
    /// Draw with the adapter whose name contains NAME (case-insensitive), e.g.
    /// `swiftshader` (Chromium's software Vulkan, where Debian's chromium is installed)
    /// or `llvmpipe`; overrides WGPU_ADAPTER_NAME. The default is wgpu's choice. A name
    /// that matches none lists the adapters found.
    #[arg(long, value_name = "NAME")]
    pub adapter: Option<String>,
}

/// The view options `--case` replaces (a named view is a whole view).
pub(super) const VIEW_OPTIONS: [&str; 11] = [
    "font",
    "text",
    "glyph_id",
    "size",
    "width",
    "height",
    "origin",
    "matrix",
    "world_offset",
    "tilt",
    "variation",
];
