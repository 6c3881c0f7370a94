//! `glyphscope render`: one view drawn by one method, and what is asked of it.

use std::path::PathBuf;

use clap::Args;

use super::adapter::{AdapterArgs, VIEW_OPTIONS};
use crate::Error;
use crate::magnify::{self, Focus};
use crate::methods::registry;
use crate::motion::run::MethodSpec;
use crate::render::{PictureOverlay, RenderOptions};
use crate::view_args::{ViewArgs, parse_key_value};

/// `glyphscope render`'s arguments: a view, the method that draws it, and what to write.
#[derive(Args, Clone, Debug)]
pub struct RenderArgs {
    #[command(flatten)]
    pub view: ViewArgs,
    /// A named view instead of the view options: a hard case of `glyphscope stability`
    /// (unturned, at sub-pixel offset 0) or a bench scene (page, tiny, headlines, …),
    /// the views the explorer's Cases menu loads.
    #[arg(long, conflicts_with_all = VIEW_OPTIONS)]
    pub case: Option<String>,
    /// The method that draws it; one of the registry's (see `--help`), with its
    /// parameters after colons if wanted (`msdf:field=sdf`, as `motion` and `bench`
    /// take them).
    #[arg(long, help = method_help())]
    pub method: String,
    /// Method parameter KEY=VALUE; repeat for several.
    #[arg(long = "param", value_parser = parse_key_value)]
    pub params: Vec<(String, String)>,
    /// Output PNG: grayscale coverage, or the overlay's picture in colour when the
    /// `overlay` parameter is given.
    #[arg(long)]
    pub out: PathBuf,
    /// Also write statistics as JSON: times, GPU memory, and the error against the
    /// reference (whole frame and edge pixels); for a user's file with a claim, whether
    /// the frame keeps to it.
    #[arg(long)]
    pub stats: Option<PathBuf>,
    /// Also render the reference and write the signed error (red: too much coverage,
    /// blue: too little, full intensity at 0.5); the statistics gain the error figures.
    #[arg(long)]
    pub error_image: Option<PathBuf>,
    /// Magnify: the PNG, of the frame's size, shows the pixels around `--focus`, each as
    /// an N×N block (1 to 64), with a pixel grid from 8 and each pixel's coverage (and
    /// error, with `--overlay error`) written in its block from 32.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=i64::from(magnify::MAX_FACTOR)))]
    pub magnify: u32,
    /// The pixel the magnified picture is centred on: `worst` (the largest error against
    /// the reference, the default) or X,Y.
    #[arg(long)]
    pub focus: Option<Focus>,
    /// What the (magnified) picture draws over the pixels, comma-separated: `error` (the
    /// signed error against the reference instead of the coverage), `outline` (the exact
    /// curves and their points).
    #[arg(long = "overlay", value_delimiter = ',')]
    pub overlays: Vec<PictureOverlay>,
    #[command(flatten)]
    pub adapter: AdapterArgs,
}

/// `--method`'s help: the registry's names and summaries.
fn method_help() -> String {
    format!(
        "The method that draws it: {}. Its parameters may follow its name after colons \
         (NAME:KEY=VALUE:…), as --param gives them",
        registry::help()
    )
}

/// `glyphscope render`: renders the view and writes the PNG and what else is asked for.
pub fn run_render(args: &RenderArgs) -> Result<(), Error> {
    // `NAME:KEY=VALUE:…`, then `--param`s, which win where both set a key.
    // A user's file takes `--param claim=MAX/MAE` as it takes `:claim=` after its path.
    let mut method = args.method.clone();
    let mut params = args.params.clone();
    if crate::methods::user::split(method.trim()).is_some() {
        params.retain(|(key, value)| {
            let claim = key == "claim";
            if claim {
                method = format!("{}:claim={value}", method.trim());
            }
            !claim
        });
    }
    let spec = MethodSpec::parse(&method)?;
    crate::render::run(&RenderOptions {
        view: args.view.clone(),
        case: args.case.clone(),
        method: spec.name,
        params: [spec.params, params].concat(),
        out: args.out.clone(),
        stats: args.stats.clone(),
        error_image: args.error_image.clone(),
        magnify: args.magnify,
        focus: args.focus,
        overlays: args.overlays.clone(),
        adapter: args.adapter.adapter.clone(),
    })
}
