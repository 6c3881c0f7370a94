//! `glyphscope motion`: methods along a camera path, frame by frame, against the
//! reference.

use std::path::PathBuf;

use clap::Args;

use super::adapter::{AdapterArgs, VIEW_OPTIONS};
use crate::Error;
use crate::magnify::{self, Focus};
use crate::motion::command::{MotionOptions, animated_methods};
use crate::motion::{MotionPath, run::MethodSpec};
use crate::view_args::ViewArgs;

/// `glyphscope motion`'s arguments.
#[derive(Args, Clone, Debug)]
pub struct MotionArgs {
    #[command(flatten)]
    pub view: ViewArgs,
    /// A named view instead of the view options (see `render --case`).
    #[arg(long, conflicts_with_all = VIEW_OPTIONS)]
    pub case: Option<String>,
    /// The camera's path, its speed per frame: drift:DX,DY (pixels), rotate:DEG or
    /// rotate:DEG@X,Y (counter-clockwise, about the image centre or pixel X,Y), zoom:F,
    /// pulse:LOW,HIGH,PERIOD (size between LOW and HIGH times the base), sway:DEG,PERIOD
    /// (tilt ±DEG), joined by '+'.
    #[arg(long, default_value = crate::motion::DRIFT_X, allow_hyphen_values = true)]
    pub path: String,
    /// Frames drawn (the first is the view itself, at a pulse's LOW size).
    #[arg(long, default_value_t = 32, value_parser = clap::value_parser!(u32).range(2..=100_000))]
    pub frames: u32,
    /// Methods, comma-separated, each NAME or NAME:KEY=VALUE:KEY=VALUE (e.g.
    /// winding:aa=rays:samples=1); peers too.
    #[arg(long, value_delimiter = ',', required = true)]
    pub method: Vec<String>,
    /// The methods the animated picture shows beside the reference (default: the first
    /// two of --method), by their place in --method (1, 2, …) or name.
    #[arg(long, value_delimiter = ',')]
    pub animate: Vec<String>,
    /// Frames in the animated picture (the first ones; at most --frames).
    #[arg(long, default_value_t = 32)]
    pub animate_frames: u32,
    /// The animated picture's magnification: each pixel an N×N block, 24×16 pixels a
    /// panel at the default 12.
    #[arg(long, default_value_t = 12, value_parser = clap::value_parser!(u32).range(2..=i64::from(magnify::MAX_FACTOR)))]
    pub magnify: u32,
    /// The pixel the animated picture is centred on: `worst` (where the first animated
    /// method's largest change beyond the reference's in the run is; the default) or
    /// X,Y.
    #[arg(long)]
    pub focus: Option<Focus>,
    /// Folder for motion.csv, motion.md, motion.json, temporal.svg and motion.png.
    #[arg(long, default_value = "motion-out")]
    pub out: PathBuf,
    #[command(flatten)]
    pub adapter: AdapterArgs,
}

/// `glyphscope motion`: runs the methods through the path, writes the report and the
/// animated picture, prints the summary table. The arguments are read in the order
/// their errors are said: the path, the methods, `--animate`, then the view.
pub fn run_motion(args: &MotionArgs) -> Result<(), Error> {
    let path = MotionPath::parse(&args.path)?;
    let methods = args
        .method
        .iter()
        .map(|m| MethodSpec::parse(m))
        .collect::<Result<Vec<_>, _>>()?;
    let animated = animated_methods(&args.animate, &methods)?;
    let (scene, camera) = match &args.case {
        Some(name) => crate::named_views::build(name)?,
        None => args.view.build()?,
    };
    let command = std::env::args()
        .skip(1)
        .map(|a| if a.contains(' ') { format!("'{a}'") } else { a })
        .collect::<Vec<_>>()
        .join(" ");
    let summary = crate::motion::command::run(&MotionOptions {
        scene,
        camera,
        path,
        frames: args.frames as usize,
        methods,
        animated,
        animate_frames: args.animate_frames as usize,
        magnify: args.magnify,
        focus: args.focus,
        out: args.out.clone(),
        command: format!("glyphscope {command}"),
        adapter: args.adapter.adapter.clone(),
    })?;
    print!("{summary}");
    Ok(())
}
