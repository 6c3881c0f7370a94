use std::process::ExitCode;

use clap::Parser;
use glyphscope::cli::{Cli, Command};

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Some(Command::Render(args)) => glyphscope::cli::run_render(args),
        Some(Command::Bench(args)) => glyphscope::cli::run_bench(args),
        None => run_app(),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
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
