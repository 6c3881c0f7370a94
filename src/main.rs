use std::process::ExitCode;

use clap::Parser;
use glyphscope::cli::{Cli, Command};

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Some(Command::Render(args)) => glyphscope::cli::run_render(args).map(|()| true),
        Some(Command::Bench(args)) => glyphscope::cli::run_bench(args).map(|()| true),
        // Exit 1, distinct from bad input's 2, when a method breaks a claimed bound.
        Some(Command::Stability(args)) => glyphscope::cli::run_stability(args),
        Some(Command::Screenshots(args)) => run_screenshots(args).map(|()| true),
        Some(Command::Info(args)) => glyphscope::info::run(args).map(|()| true),
        None => run_app().map(|()| true),
    };
    match result {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

#[cfg(feature = "app")]
fn run_app() -> Result<(), glyphscope::Error> {
    glyphscope::app::run()
}

#[cfg(not(feature = "app"))]
fn run_app() -> Result<(), glyphscope::Error> {
    Err(glyphscope::Error::Input(
        "this build has no app (built without the `app` feature); use a subcommand such as \
         `render`, see --help"
            .into(),
    ))
}

#[cfg(feature = "app")]
fn run_screenshots(args: &glyphscope::cli::ScreenshotsArgs) -> Result<(), glyphscope::Error> {
    glyphscope::app::screenshots::write_all(&args.out).map(drop)
}

#[cfg(not(feature = "app"))]
fn run_screenshots(_: &glyphscope::cli::ScreenshotsArgs) -> Result<(), glyphscope::Error> {
    Err(glyphscope::Error::Input(
        "this build has no app (built without the `app` feature), so no screenshots of it".into(),
    ))
}
