//! The `glyphscope` binary as a user runs it, from the repository root (the bench's
//! scenes read fonts/), writing into a scratch folder of this test binary's own.

use std::io::Read;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

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

/// The binary run with `args`, to its end or for `limit` at most: a run still going
/// then is killed and returned as None, so a hang fails the test that asked instead of
/// hanging the suite.
pub fn run_within(args: &[&str], limit: Duration) -> Option<Output> {
    let mut command = bin();
    command.args(args);
    output_within(command, limit)
}

/// `command` (the binary with its arguments and environment) run to its end or for
/// `limit` at most, as [`run_within`] runs it.
#[allow(dead_code)]
pub fn output_within(mut command: Command, limit: Duration) -> Option<Output> {
    let mut child = command
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    // Both pipes are drained while it runs, so a child that writes much never blocks
    // on a full pipe and looks hung.
    let drain = |pipe: Option<Box<dyn Read + Send>>| {
        std::thread::spawn(move || {
            let mut bytes = Vec::new();
            if let Some(mut pipe) = pipe {
                pipe.read_to_end(&mut bytes).expect("the pipe reads");
            }
            bytes
        })
    };
    let stdout = drain(child.stdout.take().map(|p| Box::new(p) as _));
    let stderr = drain(child.stderr.take().map(|p| Box::new(p) as _));
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("the child can be waited for") {
            break Some(status);
        }
        if started.elapsed() > limit {
            child.kill().expect("the child can be killed");
            child.wait().expect("the killed child can be waited for");
            break None;
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let (stdout, stderr) = (stdout.join().unwrap(), stderr.join().unwrap());
    status.map(|status| Output {
        status,
        stdout,
        stderr,
    })
}
