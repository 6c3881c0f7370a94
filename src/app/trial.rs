//! A user's shader drawn once in a process of its own before the explorer draws it. A
//! loop that never returns would keep the explorer's device busy for good, and its
//! window with it (a software device has no GPU timeout); a command line ends itself
//! past its frame limit instead (`methods::user::exit_on_hang`). So each text of a
//! user's file that compiles is first drawn by `glyphscope render --case tiny` in a
//! child process; where the child passes its frame limit, the pane shows its error over
//! the last version that passed, which keeps drawing. A save costs the pane that run
//! (about a second on lavapipe) before it is drawn. The trial draws `tiny` only: a loop
//! that never ends on some other glyph or camera alone is not caught.
//!
//! Where the explorer is not the `glyphscope` binary (a test harness runs it inside its
//! own) and neither [`try_with`] nor `GLYPHSCOPE_BIN` names one, and on the web page (no
//! processes), files are drawn untried.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

use crate::methods::user;

/// Where a text of a user's file stands.
#[derive(Clone, Debug, PartialEq)]
pub enum Trial {
    /// Being drawn by the child process.
    Running,
    /// Drawn there, or not tried (see the module's comment).
    Passed,
    /// The child's one-line error.
    Failed(String),
}

/// The frame limit the child runs under, seconds: its `tiny` frame takes well under one
/// on lavapipe with the examples.
const CHILD_FRAME_LIMIT_S: &str = "10";

/// How long a child may run in all (it times several frames) before it is taken to be
/// stuck where no frame limit reaches it, and stopped.
const CHILD_LIMIT: std::time::Duration = std::time::Duration::from_secs(90);

/// A trial started: the file, the hash of the text tried, its outcome once known, and
/// a flag that stops its child when a newer text supersedes it.
struct Started {
    name: String,
    stamp: u64,
    outcome: Arc<Mutex<Option<Trial>>>,
    superseded: Arc<AtomicBool>,
}

/// The trials started, the last text of each file.
static TRIALS: Mutex<Vec<Started>> = Mutex::new(Vec::new());

/// Trials started in this process, for each one's file names.
static COUNT: AtomicUsize = AtomicUsize::new(0);

/// The trial of user's file `name` (`wgsl:PATH`) with text `stamp` (`user::stamp`):
/// started in the background when new, its outcome once the child has ended. The child
/// draws a copy of the text that has that stamp, so what passed is what the pane then
/// makes (the pane checks that it made that text: `user::made_from`); where the file
/// no longer holds it, the trial waits for the next stamp.
pub fn of(name: &str, stamp: u64) -> Trial {
    let Some(binary) = binary() else {
        return Trial::Passed;
    };
    let mut trials = TRIALS.lock().unwrap_or_else(|p| p.into_inner());
    if let Some(t) = trials.iter().find(|t| t.name == name && t.stamp == stamp) {
        return t
            .outcome
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .clone()
            .unwrap_or(Trial::Running);
    }
    let Some(path) = user::path_of(name) else {
        return Trial::Passed;
    };
    let Ok(bytes) = std::fs::read(path) else {
        // Unreadable: the pane's own read says why.
        return Trial::Passed;
    };
    if user::stamp_of(&bytes) != stamp {
        // Saved again since the pane looked: tried once it sees that text.
        return Trial::Running;
    }
    let n = COUNT.fetch_add(1, Ordering::Relaxed);
    let copy =
        std::env::temp_dir().join(format!("glyphscope-trial-{}-{n}.wgsl", std::process::id()));
    if std::fs::write(&copy, &bytes).is_err() {
        return Trial::Passed;
    }
    // One trial per file: the text tried last; an older one's child is stopped.
    for old in trials.iter().filter(|t| t.name == name) {
        old.superseded.store(true, Ordering::Relaxed);
    }
    trials.retain(|t| t.name != name);
    let started = Started {
        name: name.to_owned(),
        stamp,
        outcome: Arc::default(),
        superseded: Arc::default(),
    };
    let (outcome, superseded) = (started.outcome.clone(), started.superseded.clone());
    trials.push(started);
    let (shown, n) = (path.to_owned(), n);
    std::thread::spawn(move || {
        let result = run(&binary, &copy, &shown, n, &superseded);
        let _ = std::fs::remove_file(&copy);
        *outcome.lock().unwrap_or_else(|p| p.into_inner()) = Some(result);
    });
    Trial::Running
}

/// The binary a harness names for the trials ([`try_with`]).
static NAMED: std::sync::OnceLock<std::path::PathBuf> = std::sync::OnceLock::new();

/// Runs the trials with `binary` (the `glyphscope` binary): for a harness that runs the
/// explorer inside a binary of its own. The first call wins.
pub fn try_with(binary: std::path::PathBuf) {
    let _ = NAMED.set(binary);
}

/// The `glyphscope` binary to run the trial with, if there is one.
fn binary() -> Option<std::path::PathBuf> {
    if cfg!(target_arch = "wasm32") {
        return None;
    }
    if let Some(named) = NAMED.get() {
        return Some(named.clone());
    }
    if let Some(named) = std::env::var_os("GLYPHSCOPE_BIN") {
        return Some(named.into());
    }
    let own = std::env::current_exe().ok()?;
    (own.file_stem()? == "glyphscope").then_some(own)
}

/// `glyphscope render --case tiny --method wgsl:COPY` in a child process, to its end
/// (or [`CHILD_LIMIT`], or until a newer text supersedes it). Only a shader that never
/// returns fails the trial: any other failure of the child (no adapter there, a full
/// disk) leaves the pane to draw and report as it would without trials. Its error
/// names the user's file (`shown`), not the copy.
fn run(
    binary: &std::path::Path,
    copy: &std::path::Path,
    shown: &str,
    n: usize,
    superseded: &AtomicBool,
) -> Trial {
    let out = std::env::temp_dir().join(format!("glyphscope-trial-{}-{n}.png", std::process::id()));
    let child = std::process::Command::new(binary)
        .args(["render", "--case", "tiny", "--method"])
        .arg(format!("{}{}", user::PREFIX, copy.display()))
        .arg("--out")
        .arg(&out)
        .env("GLYPHSCOPE_FRAME_LIMIT_S", CHILD_FRAME_LIMIT_S)
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn();
    let Ok(mut child) = child else {
        return Trial::Passed;
    };
    // The child writes one line or so: its pipe never fills while it runs.
    let started = std::time::Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break Some(status),
            Ok(None) if superseded.load(Ordering::Relaxed) || started.elapsed() > CHILD_LIMIT => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            Ok(None) => std::thread::sleep(std::time::Duration::from_millis(50)),
            Err(_) => break None,
        }
    };
    let _ = std::fs::remove_file(&out);
    let mut stderr = String::new();
    if let Some(mut pipe) = child.stderr.take() {
        use std::io::Read;
        let _ = pipe.read_to_string(&mut stderr);
    }
    match status {
        None if superseded.load(Ordering::Relaxed) => Trial::Running,
        None => Trial::Failed(format!(
            "{shown}: a process drawing your shader did not end in {} s: does a loop never \
             end?",
            CHILD_LIMIT.as_secs()
        )),
        Some(_) if stderr.contains(user::HANG) => {
            let line = stderr
                .lines()
                .find(|l| l.contains(user::HANG))
                .unwrap_or_default();
            let line = line.strip_prefix("error: ").unwrap_or(line);
            Trial::Failed(line.replace(&copy.display().to_string(), shown))
        }
        Some(_) => Trial::Passed,
    }
}
