//! The `glyphscope` binary: a subcommand runs headless through `cli` (no display is
//! opened); no subcommand opens the explorer. Errors print one line and exit 2.

use std::process::ExitCode;

use clap::Parser;
use glyphscope::cli::{Cli, Command};

fn main() -> ExitCode {
    let cli = Cli::parse();
    if let Some(command) = &cli.command {
        keep_the_gpu_off_the_display();
        // A user's shader that never returns ends the command with its error.
        glyphscope::methods::user::exit_on_hang();
        if command.adapter().is_some() || std::env::var_os("WGPU_ADAPTER_NAME").is_some() {
            // SAFETY: as in `keep_the_gpu_off_the_display`, no thread has started yet.
            unsafe { glyphscope::gpu::offer_swiftshader() };
        }
    }
    if cli.command.is_some() && cli.view.is_some() {
        eprintln!("error: --view opens the explorer: give it without a subcommand");
        return ExitCode::from(2);
    }
    let result = match &cli.command {
        Some(Command::Render(args)) => glyphscope::cli::run_render(args).map(|()| true),
        Some(Command::Bench(args)) => glyphscope::cli::run_bench(args).map(|()| true),
        // Exit 1, distinct from bad input's 2, when a method breaks a claimed bound.
        Some(Command::Stability(args)) => glyphscope::cli::run_stability(args),
        Some(Command::Screenshots(args)) => run_screenshots(args).map(|()| true),
        Some(Command::Motion(args)) => glyphscope::cli::run_motion(args).map(|()| true),
        Some(Command::Info(args)) => glyphscope::cli::run_info(args).map(|()| true),
        // Exit 1 when a method breaks its claim on some glyph.
        Some(Command::Survey(args)) => glyphscope::cli::run_survey(args),
        None => run_app(cli.view.as_deref()).map(|()| true),
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

/// A subcommand draws offscreen and opens no display. wgpu still enables every window
/// system's Vulkan surface extension the loader offers, and Mesa's device-select layer,
/// seeing Wayland's enabled, connects to a Wayland display to find the default GPU: with
/// none, libwayland prints "XDG_RUNTIME_DIR is invalid or not set" on every command.
/// `NODEVICE_SELECT=1` is that layer's own off switch; wgpu chooses the adapter itself
/// (`WGPU_ADAPTER_NAME`). Left alone where the user asks the layer for a GPU
/// (`MESA_VK_DEVICE_SELECT`) or set the switch either way; the app, which opens a window,
/// never comes here.
fn keep_the_gpu_off_the_display() {
    let asked = |name: &str| std::env::var_os(name).is_some();
    if !asked("MESA_VK_DEVICE_SELECT") && !asked("NODEVICE_SELECT") {
        // SAFETY: the first thing `main` does after parsing the arguments, before this
        // process starts a thread (wgpu, the bench and the sweep start theirs later), so
        // nothing reads the environment concurrently.
        unsafe { std::env::set_var("NODEVICE_SELECT", "1") };
    }
}

#[cfg(feature = "app")]
fn run_app(view: Option<&str>) -> Result<(), glyphscope::Error> {
    glyphscope::app::run(view)
}

#[cfg(not(feature = "app"))]
fn run_app(_: Option<&str>) -> Result<(), glyphscope::Error> {
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
