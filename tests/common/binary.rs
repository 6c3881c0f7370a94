//! The `glyphscope` binary as a user runs it, from the repository root (the bench's
//! scenes read fonts/), writing into a scratch folder of this test binary's own.

use std::path::PathBuf;
use std::process::{Command, Output};

/// The binary, to be given arguments (and environment) before it runs.
pub fn bin() -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_glyphscope"));
    cmd.current_dir(env!("CARGO_MANIFEST_DIR"));
    cmd
}

/// A path named `name` in a temporary folder of this test binary and process.
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "glyphscope-{}-{}",
        env!("CARGO_CRATE_NAME"),
        std::process::id()
    ));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// The binary run with `args`, to its end.
pub fn run(args: &[&str]) -> Output {
    bin().args(args).output().expect("the binary runs")
}
