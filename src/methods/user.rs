//! Your own method: a WGSL file that defines `user_coverage`, drawn as `winding` draws
//! (the same instances, quads, dilation, joined glyphs, curve and band data and coverage
//! target) with the user's function in place of the algorithm, and measured by every
//! command that names a method: `--method wgsl:PATH` (docs/your-method.md).
//!
//! The file is read and checked with naga once per process and path: one that does not
//! parse or validate is one line naming the file, the line and column in it, and
//! naga's message. A comment `// claim: max=M mae=A` in the file holds it to that bound
//! (M in coverage, A in 1/255) wherever the survey and the stability sweep measure it;
//! without one it is observed, as a peer is.

use std::path::Path;
use std::sync::{Mutex, OnceLock};
use std::time::Duration;

use super::Method;
use super::info::{
    BenchSetting, Bound, Claim, ClaimedSetting, Constructor, MeanOver, MethodInfo, Role, bench_at,
    within, within_on_edges,
};
use crate::Error;
use crate::camera::Camera;
use crate::gpu::{CoverageTarget, GpuContext};
use crate::scene::Scene;
use glyphscope_text::winding::{self, Winding};

/// How a method name asks for a user's file: `wgsl:PATH`.
pub const PREFIX: &str = "wgsl:";

/// A user's method is benched at its one setting, in `--quick` too.
const BENCH: &[BenchSetting] = &[bench_at(&[], true)];

/// The rows made so far: per path and claim given, the row of the file's text as last
/// read. A row lives as long as the process, as the registry's do; a file
/// edited while the explorer runs gets a new row at each edit it is read after (its
/// source, some 70 kB, kept with it).
static ROWS: Mutex<Vec<Row>> = Mutex::new(Vec::new());

/// A row made: the hash of the file's text it was made from, the claim given for it on
/// the command line (`claim=MAX/MAE`; None: the file's header holds it), and the row.
struct Row {
    hash: u64,
    claim_given: Option<String>,
    row: &'static MethodInfo,
}

/// Per path and claim given, the last text refused and why.
static REFUSED: Mutex<Vec<Refused>> = Mutex::new(Vec::new());

struct Refused {
    name: String,
    claim_given: Option<String>,
    /// The hash of the text refused.
    hash: u64,
    why: String,
}

/// A hash of the text of the user's file `name` (`wgsl:PATH`) as it is now, None where
/// it cannot be read: what the explorer watches to reload a pane when it is saved.
pub fn stamp(name: &str) -> Option<u64> {
    let path = path_of(name)?;
    std::fs::read(path).ok().map(|bytes| fnv1a(&bytes))
}

/// The file's path in `name` (`wgsl:PATH`, `wgsl:PATH:claim=…`).
pub fn path_of(name: &str) -> Option<&str> {
    split(name)?.0.strip_prefix(PREFIX)
}

/// The hash of the text the row for `name` (`wgsl:PATH[:claim=…]`) was last made from,
/// as [`stamp`] gives it: what the explorer checks a method it made against the text it
/// tried (`app::trial`), since the file may change between the two reads.
pub fn made_from(name: &str) -> Option<u64> {
    let (path_name, rest) = split(name)?;
    let claim = rest
        .split(':')
        .find_map(|part| part.strip_prefix("claim="))
        .map(str::to_owned);
    let rows = ROWS.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    rows.iter()
        .find(|r| r.row.name == path_name && r.claim_given == claim)
        .map(|r| r.hash)
}

/// [`stamp`] of a file's bytes read already.
pub fn stamp_of(bytes: &[u8]) -> u64 {
    fnv1a(bytes)
}

/// FNV-1a, 64 bits: a file's text told apart from its edits.
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// `text` split after a user's file (`wgsl:PATH`) from what follows it (`:KEY=VALUE…`),
/// or None where `text` does not name one. The path ends at `.wgsl` where a colon or
/// the end follows it (so it may hold colons, as `C:\x.wgsl` does), else at the next
/// colon.
pub fn split(text: &str) -> Option<(&str, &str)> {
    let after = text.strip_prefix(PREFIX)?;
    let end = after
        .match_indices(".wgsl")
        .map(|(at, ext)| at + ext.len())
        .find(|&end| after[end..].is_empty() || after[end..].starts_with(':'))
        .or_else(|| after.find(':'))
        .unwrap_or(after.len());
    Some(text.split_at(PREFIX.len() + end))
}

/// The row of the user's method `name` (`wgsl:PATH`, or `wgsl:PATH:claim=MAX/MAE`) for
/// the file's text as it is now: read, checked and its claim taken when the text is
/// new, the same row while it is not. A `claim=` given after the path overrides the
/// file's header line.
pub fn find(name: &str) -> Result<&'static MethodInfo, Error> {
    let (path_name, rest) = split(name).unwrap_or((name, ""));
    let mut claim = None;
    for part in rest.split(':').filter(|p| !p.is_empty()) {
        match part.split_once('=') {
            Some(("claim", value)) => claim = Some(value),
            _ => {
                return Err(Error::Input(format!(
                    "'{name}': a user's method takes one parameter, claim=MAX/MAE, not '{part}'"
                )));
            }
        }
    }
    find_claimed(path_name, claim)
}

/// The row of `name` (`wgsl:PATH`) held to `claim` (`MAX/MAE`, as `--param claim=`
/// gives it) where given, else to the file's header line.
pub fn find_claimed(name: &str, claim: Option<&str>) -> Result<&'static MethodInfo, Error> {
    let path = name
        .strip_prefix(PREFIX)
        .filter(|p| !p.is_empty())
        .ok_or_else(|| Error::Input(format!("'{name}': give the file as wgsl:PATH")))?;
    // A claim given is read first: a bad one is refused without reading the file, and
    // a good one stands in for the file's line, which is then not read at all.
    let given = claim.map(|c| given_claim(name, c)).transpose()?;
    let text = std::fs::read_to_string(path)
        .map_err(|e| Error::Input(format!("{path}: cannot read your method: {e}")))?;
    let hash = fnv1a(text.as_bytes());
    let claim_given = claim.map(str::to_owned);
    let mut rows = ROWS.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    let known = rows
        .iter()
        .position(|r| r.row.name == name && r.claim_given == claim_given);
    if let Some(k) = known
        && rows[k].hash == hash
    {
        return Ok(rows[k].row);
    }
    // A text already refused is refused again without checking it again: the explorer
    // asks every frame while a broken save is on screen.
    let mut refused = REFUSED
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    let this = |r: &Refused| r.name == name && r.claim_given == claim_given;
    if let Some(r) = refused.iter().find(|r| this(r) && r.hash == hash) {
        return Err(Error::Input(r.why.clone()));
    }
    let source = winding::user_source(&text);
    let checked = check(Path::new(path), &source).and_then(|()| match given {
        Some(given) => Ok(given),
        None => claim_of(path, &text),
    });
    refused.retain(|r| !this(r));
    let claim = match checked {
        Ok(claim) => claim,
        Err(e) => {
            refused.push(Refused {
                name: name.to_owned(),
                claim_given,
                hash,
                why: e.to_string(),
            });
            return Err(e);
        }
    };
    drop(refused);
    // One name per path, however often the file changes and whatever claims it is
    // held to.
    let name: &'static str = match rows.iter().find(|r| r.row.name == name) {
        Some(r) => r.row.name,
        None => Box::leak(name.to_owned().into_boxed_str()),
    };
    let source: &'static str = Box::leak(source.into_boxed_str());
    let constructor: Constructor = Box::leak(Box::new(
        move |_: &super::params::Params| -> Result<Box<dyn Method>, Error> {
            Ok(Box::new(UserMethod {
                name,
                winding: Winding::with_user_source(source.to_owned()),
                limit: frame_limit(),
            }))
        },
    ));
    let claims: &'static [ClaimedSetting] = Box::leak(Box::new([ClaimedSetting {
        label: name,
        params: &[],
        claim,
    }]));
    let row: &'static MethodInfo = Box::leak(Box::new(MethodInfo {
        name,
        summary: "your method: user_coverage of a WGSL file, on winding's quads and data",
        role: Role::Method,
        shader: None,
        params: &[],
        colour: [140, 86, 75],
        bench: BENCH,
        claims,
        constructor: Some(constructor),
    }));
    let made = Row {
        hash,
        claim_given,
        row,
    };
    match known {
        Some(k) => rows[k] = made,
        None => rows.push(made),
    }
    Ok(row)
}

/// How long a wait for a frame drawn with a user's method may take before the shader
/// is taken to never return: `GLYPHSCOPE_FRAME_LIMIT_S` seconds where that is set (a
/// positive number), else 60 — far past a frame of the bench's largest scene with a
/// heavy method on a software device.
pub fn frame_limit() -> Duration {
    std::env::var("GLYPHSCOPE_FRAME_LIMIT_S")
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
        .filter(|s| s.is_finite() && *s > 0.0)
        .map_or(Duration::from_secs(60), Duration::from_secs_f64)
}

/// What the error says of a user's shader that kept the GPU past [`frame_limit`] (the
/// explorer's trial run looks for it).
pub const HANG: &str = "has not finished a frame";

/// What this process does when a user's shader keeps the GPU past [`frame_limit`]:
/// set by the command line ([`exit_on_hang`]); without it the wait fails with an error.
static ON_HANG: OnceLock<fn(&str)> = OnceLock::new();

/// A command line's answer to a shader that never returns: the one-line error and exit
/// 2, at once. Not a return through `main`: dropping the device would wait for the
/// shader, and so would the exit handlers of a software device's threads, so the
/// process ends without them (`_exit`).
pub fn exit_on_hang() {
    let _ = ON_HANG.set(|message| {
        use std::io::Write;
        let mut stderr = std::io::stderr().lock();
        let _ = writeln!(stderr, "error: {message}");
        let _ = stderr.flush();
        let _ = std::io::stdout().flush();
        #[cfg(unix)]
        // SAFETY: `_exit` ends the process at once; nothing after it runs.
        unsafe {
            libc::_exit(2)
        };
        #[cfg(not(unix))]
        std::process::exit(2);
    });
}

/// What a user's file must define, as an error names it.
const CONTRACT: &str = "it must define fn user_coverage(g: Glyph, p: vec2<f32>, jx: vec2<f32>, \
                        jy: vec2<f32>) -> f32 (docs/your-method.md)";

/// The full source parsed and validated by naga, as wgpu would; an error is one line:
/// `PATH:LINE:COLUMN: message`, the line counted in the user's file. An error the
/// prelude meets (the function missing, or declared otherwise) names the contract.
fn check(path: &Path, source: &str) -> Result<(), Error> {
    let offset = winding::user_line_offset();
    let at = |location: Option<naga::SourceLocation>, message: String| {
        let path = path.display();
        Error::Input(match location {
            Some(l) if l.line_number as usize > offset => format!(
                "{path}:{}:{}: {message}",
                l.line_number as usize - offset,
                l.line_position
            ),
            _ => format!("{path}: {CONTRACT}: {message}"),
        })
    };
    let module = naga::front::wgsl::parse_str(source)
        .map_err(|e| at(e.location(source), e.message().to_owned()))?;
    let mut validator = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::default(),
    );
    validator.validate(&module).map_err(|e| {
        // naga keeps the failing function's span first and the statement's after it:
        // the innermost one in the user's text is the place to show.
        let location = e
            .spans()
            .map(|(span, _)| span.location(source))
            .filter(|l| l.line_number as usize > offset)
            .last()
            .or_else(|| e.spans().next().map(|(span, _)| span.location(source)));
        // Its message and every cause under it ("function … is invalid: …").
        let mut message = e.as_inner().to_string();
        let mut cause = std::error::Error::source(e.as_inner());
        while let Some(c) = cause {
            message = format!("{message}: {c}");
            cause = c.source();
        }
        at(location, message)
    })?;
    Ok(())
}

/// The claim a `// claim: max=M mae=A` line of `text` makes (`Bound` M in coverage, A
/// in 1/255, the mean over the frame), or `max=M edge_mae=A` (the mean over the edge
/// pixels, where a sampled method's error lives); without one, none: the method is
/// observed.
fn claim_of(path: &str, text: &str) -> Result<Claim, Error> {
    let Some(line) = text
        .lines()
        .find_map(|l| l.trim().strip_prefix("//")?.trim().strip_prefix("claim:"))
    else {
        return Ok(Claim {
            bound: None,
            except: &[],
            limitation: None,
            temporal: None,
            statement: "observed: your method makes no claim (add `// claim: max=M mae=A`)",
        });
    };
    let bad = |why: &str| {
        Error::Input(format!(
            "{path}: the claim '{}' {why}: write `// claim: max=M mae=A` or `max=M edge_mae=A` (M in coverage, 0 to 1; A in 1/255)",
            line.trim()
        ))
    };
    let (mut max, mut mae, mut edge_mae) = (None, None, None);
    for part in line.split_whitespace() {
        let (key, value) = part
            .split_once('=')
            .ok_or_else(|| bad("is not KEY=VALUE"))?;
        let value: f64 = value
            .parse()
            .map_err(|_| bad("has a value that is not a number"))?;
        if !value.is_finite() || value < 0.0 {
            return Err(bad("has a value that is not a finite number ≥ 0"));
        }
        match key {
            "max" if value <= 1.0 => max = Some(value),
            "mae" => mae = Some(value),
            "edge_mae" => edge_mae = Some(value),
            _ => return Err(bad(&format!("has '{key}={value}'"))),
        }
    }
    let bound = match (max, mae, edge_mae) {
        (Some(max), Some(mae), None) => within(max, mae),
        (Some(max), None, Some(edge)) => within_on_edges(max, edge),
        (_, Some(_), Some(_)) => return Err(bad("has both mae and edge_mae")),
        _ => return Err(bad("lacks max or mae")),
    };
    Ok(claim_within(bound, "your claim"))
}

/// The claim `MAX/MAE` given after a user's file (`wgsl:PATH:claim=MAX/MAE`, or
/// `--param claim=MAX/MAE`), which overrides its header line; `MAX/MAE/edges` bounds
/// the mean over the edge pixels instead of the frame.
fn given_claim(name: &str, text: &str) -> Result<Claim, Error> {
    let bad = |why: &str| {
        Error::Input(format!(
            "{name}: claim={text} {why}: write claim=MAX/MAE or MAX/MAE/edges (MAX in coverage, 0 to 1; MAE in 1/255), e.g. claim=0.3/8"
        ))
    };
    let (rest, on_edges) = match text.strip_suffix("/edges") {
        Some(rest) => (rest, true),
        None => (text, false),
    };
    let (max, mae) = rest.split_once('/').ok_or_else(|| bad("is not MAX/MAE"))?;
    let number = |t: &str| {
        t.parse::<f64>()
            .ok()
            .filter(|v| v.is_finite() && *v >= 0.0)
            .ok_or_else(|| bad(&format!("has '{t}', not a finite number ≥ 0")))
    };
    let (max, mae) = (number(max)?, number(mae)?);
    if max > 1.0 {
        return Err(bad("has a MAX over 1"));
    }
    let bound = if on_edges {
        within_on_edges(max, mae)
    } else {
        within(max, mae)
    };
    Ok(claim_within(bound, "your claim (given with the method)"))
}

/// A claim of `bound`, stated as `whose` it is.
fn claim_within(bound: Bound, whose: &str) -> Claim {
    let mean = match bound.over {
        MeanOver::EdgePixels => "mean error over edge pixels",
        _ => "mean error",
    };
    let statement: &'static str = Box::leak(
        format!(
            "{whose}: no pixel off by more than {}, {mean} within {}/255",
            bound.max, bound.mae_255
        )
        .into_boxed_str(),
    );
    Claim {
        bound: Some(bound),
        except: &[],
        limitation: None,
        temporal: None,
        statement,
    }
}

/// A user's method: `winding`'s renderer with their `user_coverage`, under their name.
struct UserMethod {
    name: &'static str,
    winding: Winding,
    /// [`frame_limit`], read once when the method is made.
    limit: Duration,
}

impl Method for UserMethod {
    fn name(&self) -> &'static str {
        self.name
    }

    fn prepare(&mut self, gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        self.winding.prepare(gpu, scene)
    }

    fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        camera: &Camera,
    ) -> Result<(), Error> {
        // The waits for this device from now on are bounded, and a hang is told as this
        // file's (the last user's method drawn): a loop in it that never ends would
        // otherwise hang a software device (lavapipe has no GPU timeout) and this
        // process with it.
        let (limit, name) = (self.limit, self.name);
        gpu.guard_waits(limit, move |waited| {
            let message = format!(
                "{}: your shader {HANG} in {:.0} s: does a loop never end? (the limit: \
                 GLYPHSCOPE_FRAME_LIMIT_S, {:.0} s)",
                path_of(name).unwrap_or(name),
                waited.as_secs_f64(),
                limit.as_secs_f64()
            );
            if let Some(on_hang) = ON_HANG.get() {
                on_hang(&message);
            }
        });
        self.winding.encode(gpu, encoder, target, camera)
    }

    // No overlays and no curve count: the user's function counts nothing (the trait's
    // defaults).
    fn gpu_bytes(&self) -> u64 {
        self.winding.gpu_bytes()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn claims_are_read_from_the_header_or_refused_in_one_line() {
        let claim = claim_of("f.wgsl", "// claim: max=0.3 mae=8\nfn f() {}").unwrap();
        assert_eq!(claim.bound, Some(within(0.3, 8.0)));
        let edges = claim_of("f.wgsl", "// claim: max=0.5 edge_mae=40\nfn f() {}").unwrap();
        assert_eq!(edges.bound, Some(within_on_edges(0.5, 40.0)));
        assert!(
            edges.statement.contains("over edge pixels"),
            "{}",
            edges.statement
        );
        assert!(claim_of("f.wgsl", "fn f() {}").unwrap().bound.is_none());
        for bad in [
            "max=0.5 mae=1 edge_mae=2",
            "max=2 mae=1",
            "max=0.1",
            "max=x mae=1",
            "max=0.1 mae=NaN",
            "size=3",
        ] {
            let e = claim_of("f.wgsl", &format!("// claim: {bad}")).unwrap_err();
            let text = e.to_string();
            assert!(
                text.starts_with("f.wgsl: the claim") && !text.contains('\n'),
                "{text}"
            );
        }
    }

    #[test]
    fn a_claim_given_with_the_method_is_read_or_refused_in_one_line() {
        let claim = given_claim("wgsl:f.wgsl", "0.05/0.5").unwrap();
        assert_eq!(claim.bound, Some(within(0.05, 0.5)));
        let edges = given_claim("wgsl:f.wgsl", "0.5/40/edges").unwrap();
        assert_eq!(edges.bound, Some(within_on_edges(0.5, 40.0)));
        for bad in [
            "2/1",
            "0.1",
            "x/1",
            "NaN/1",
            "0.1/-1",
            "0.1/inf",
            "0.1/1/frame",
        ] {
            let text = given_claim("wgsl:f.wgsl", bad).unwrap_err().to_string();
            assert!(
                text.starts_with("wgsl:f.wgsl: claim=") && !text.contains('\n'),
                "{text}"
            );
        }
        // The path ends at `.wgsl` before a colon, so what follows is its parameters.
        assert_eq!(
            split("wgsl:C:\\a.wgsl:claim=0.1/2"),
            Some(("wgsl:C:\\a.wgsl", ":claim=0.1/2"))
        );
        assert_eq!(split("winding"), None);
        // The explorer watches the file itself, whatever follows its path.
        assert_eq!(path_of("wgsl:a.wgsl:claim=0.1/2"), Some("a.wgsl"));
        assert_eq!(path_of("wgsl:a.wgsl"), Some("a.wgsl"));
    }
}
