//! `glyphscope survey` and `survey merge`: every glyph of the user's fonts.

use std::path::PathBuf;

use clap::{Args, Subcommand};

use super::adapter::AdapterArgs;
use crate::Error;
use crate::view_args::parse_variation;

/// `glyphscope survey`'s arguments; `survey merge` instead joins shards.
#[derive(Args, Clone, Debug)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct SurveyArgs {
    #[command(subcommand)]
    pub merge: Option<SurveyCommand>,
    /// Font files (.ttf, .otf, .ttc, .otc) or folders of them (searched with their
    /// subfolders); every face of a collection is surveyed.
    #[arg(long, num_args = 1.., required = true)]
    pub fonts: Vec<PathBuf>,
    /// Sizes in px/em, comma-separated (default 9,12,24,48).
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    pub sizes: Vec<f64>,
    /// Transforms, comma-separated: still, rotate:DEG, skew:K or rotate:DEG+skew:K
    /// (default still,rotate:30).
    #[arg(long, value_delimiter = ',')]
    pub transforms: Vec<String>,
    /// Methods, comma-separated, each NAME or NAME:KEY=VALUE:… (default: every method,
    /// the atlas and every peer, at their default settings). A method named at a
    /// setting its registry row claims for is held to that claim.
    #[arg(long, value_delimiter = ',')]
    pub methods: Vec<String>,
    /// A variable-font instance surveyed besides the default, TAG=VALUE[,TAG=VALUE…];
    /// repeat for more. A font without its axes is surveyed at its default only.
    #[arg(long = "instances", value_parser = parse_instance)]
    pub instances: Vec<Vec<(String, f32)>>,
    /// Only glyph ids FIRST-LAST (or one id).
    #[arg(long, value_parser = parse_glyph_range)]
    pub glyphs: Option<(u16, u16)>,
    /// Survey only shard I of N (0 ≤ I < N): the fonts whose place in the sorted list of
    /// files is I mod N. Join the shards' folders with `survey merge`.
    #[arg(long, value_parser = parse_shard)]
    pub shard: Option<(usize, usize)>,
    /// The folder for the results; a run stopped part way resumes from what it holds.
    #[arg(long, required = true)]
    pub out: Option<PathBuf>,
    #[command(flatten)]
    pub adapter: AdapterArgs,
}

/// `glyphscope survey merge`.
#[derive(Subcommand, Clone, Debug)]
pub enum SurveyCommand {
    /// Join the folders of a survey's shards into the outputs one run would write.
    Merge {
        /// The shards' --out folders.
        #[arg(required = true)]
        dirs: Vec<PathBuf>,
        /// The folder for the merged outputs.
        #[arg(long)]
        out: PathBuf,
    },
}

fn parse_instance(text: &str) -> Result<Vec<(String, f32)>, String> {
    text.split(',').map(parse_variation).collect()
}

fn parse_glyph_range(text: &str) -> Result<(u16, u16), String> {
    let id = |t: &str| {
        t.trim()
            .parse::<u16>()
            .map_err(|_| format!("'{t}' is not a glyph id (0 to 65535)"))
    };
    match text.split_once('-') {
        Some((a, b)) => Ok((id(a)?, id(b)?)),
        None => id(text).map(|g| (g, g)),
    }
}

fn parse_shard(text: &str) -> Result<(usize, usize), String> {
    let (i, n) = text
        .split_once('/')
        .ok_or_else(|| format!("'{text}' is not I/N"))?;
    let number = |t: &str| {
        t.trim()
            .parse::<usize>()
            .map_err(|_| format!("'{t}' is not a whole number"))
    };
    let (i, n) = (number(i)?, number(n)?);
    if i >= n {
        return Err(format!(
            "shard {i} of {n}: I must be under N (shards count from 0)"
        ));
    }
    Ok((i, n))
}

/// `glyphscope survey` (or `survey merge`): the path of survey.md on stdout. Returns
/// whether every claim held.
pub fn run_survey(args: &SurveyArgs) -> Result<bool, Error> {
    if let Some(SurveyCommand::Merge { dirs, out }) = &args.merge {
        return crate::survey::merge(dirs, out);
    }
    let plan = crate::survey::plan::Plan::new(
        &args.sizes,
        &args.transforms,
        &args.methods,
        args.instances.clone(),
        args.glyphs,
    )?;
    crate::survey::run(&crate::survey::SurveyOptions {
        fonts: args.fonts.clone(),
        plan,
        shard: args.shard,
        out: args.out.clone().expect("clap requires --out"),
        adapter: args.adapter.adapter.clone(),
    })
}
