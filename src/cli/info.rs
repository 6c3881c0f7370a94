//! `glyphscope info`: a font's tables and placement, or the GPU adapter.

use std::path::PathBuf;

use clap::Args;

use super::adapter::AdapterArgs;
use crate::Error;
use crate::info::InfoOptions;
use crate::view_args::parse_variation;

#[derive(Args, Clone, Debug)]
pub struct InfoArgs {
    /// Font file (.ttf/.otf); the embedded DejaVu Sans when absent.
    #[arg(long)]
    pub font: Option<PathBuf>,
    /// Also report the glyphs this text shapes to, in order of first use.
    #[arg(long, conflicts_with = "glyph_id")]
    pub text: Option<String>,
    /// Also report this glyph, by its id in the font.
    #[arg(long)]
    pub glyph_id: Option<u32>,
    /// Variable-font axis values, TAG=VALUE[,TAG=VALUE...]; a short tag is space-padded.
    #[arg(long, value_delimiter = ',', value_parser = parse_variation)]
    pub variation: Vec<(String, f32)>,
    /// Report the GPU adapter instead of a font: its name, backend, driver and device
    /// type, as `render`, `bench` and `motion` would open it (with the same --adapter).
    #[arg(long, conflicts_with_all = ["font", "text", "glyph_id", "variation"])]
    pub gpu: bool,
    #[command(flatten)]
    pub adapter: AdapterArgs,
    /// With --gpu: refuse (one line, exit 2) where the adapter is a CPU implementation
    /// such as lavapipe or SwiftShader, whose timings say nothing of a GPU.
    #[arg(long, requires = "gpu")]
    pub require_hardware: bool,
}

/// `glyphscope info`: prints the font's report, or with `--gpu` the adapter's.
pub fn run_info(args: &InfoArgs) -> Result<(), Error> {
    let adapter = args.adapter.adapter.as_deref();
    if args.gpu {
        print!("{}", crate::info::gpu(adapter, args.require_hardware)?);
        return Ok(());
    }
    if adapter.is_some() {
        return Err(Error::Input(
            "info --adapter chooses the adapter that --gpu reports: add --gpu".into(),
        ));
    }
    print!(
        "{}",
        crate::info::run(&InfoOptions {
            font: args.font.clone(),
            text: args.text.clone(),
            glyph_id: args.glyph_id,
            variation: args.variation.clone(),
        })?
    );
    Ok(())
}
