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
use std::sync::Mutex;

use super::info::{
    BenchSetting, Bound, Claim, ClaimedSetting, Constructor, MethodInfo, Role, bench_at, within,
};
use super::{CurveCost, Method, Overlay};
use crate::Error;
use crate::camera::Camera;
use crate::gpu::{CoverageTarget, GpuContext};
use crate::scene::Scene;
use glyphscope_text::winding::{self, Winding};

/// How a method name asks for a user's file: `wgsl:PATH`.
pub const PREFIX: &str = "wgsl:";

/// A user's method is benched at its one setting, in `--quick` too.
const BENCH: &[BenchSetting] = &[bench_at(&[], true)];

/// The rows made so far: per path, the row of the file's text as last read (with a
/// hash of that text). A row lives as long as the process, as the registry's do; a file
/// edited while the explorer runs gets a new row at each edit it is read after (its
/// source, some 70 kB, kept with it).
static ROWS: Mutex<Vec<(u64, &'static MethodInfo)>> = Mutex::new(Vec::new());

/// Per path, the last text refused (its hash) and why.
static REFUSED: Mutex<Vec<(String, u64, String)>> = Mutex::new(Vec::new());

/// A hash of the text of the user's file `name` (`wgsl:PATH`) as it is now, None where
/// it cannot be read: what the explorer watches to reload a pane when it is saved.
pub fn stamp(name: &str) -> Option<u64> {
    let path = name.strip_prefix(PREFIX)?;
    std::fs::read(path).ok().map(|bytes| fnv1a(&bytes))
}

/// FNV-1a, 64 bits: a file's text told apart from its edits.
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// The row of the user's method `name` (`wgsl:PATH`) for the file's text as it is now:
/// read, checked and its claim taken when the text is new, the same row while it is
/// not.
pub fn find(name: &str) -> Result<&'static MethodInfo, Error> {
    let path = name
        .strip_prefix(PREFIX)
        .filter(|p| !p.is_empty())
        .ok_or_else(|| Error::Input(format!("'{name}': give the file as wgsl:PATH")))?;
    let text = std::fs::read_to_string(path)
        .map_err(|e| Error::Input(format!("{path}: cannot read your method: {e}")))?;
    let hash = fnv1a(text.as_bytes());
    let mut rows = ROWS.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    let known = rows.iter().position(|(_, r)| r.name == name);
    if let Some(k) = known
        && rows[k].0 == hash
    {
        return Ok(rows[k].1);
    }
    // A text already refused is refused again without checking it again: the explorer
    // asks every frame while a broken save is on screen.
    let mut refused = REFUSED
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    if let Some((_, _, why)) = refused.iter().find(|(n, h, _)| n == name && *h == hash) {
        return Err(Error::Input(why.clone()));
    }
    let source = winding::user_source(&text);
    let checked = check(Path::new(path), &source).and_then(|()| claim_of(path, &text));
    refused.retain(|(n, _, _)| n != name);
    let claim = match checked {
        Ok(claim) => claim,
        Err(e) => {
            refused.push((name.to_owned(), hash, e.to_string()));
            return Err(e);
        }
    };
    drop(refused);
    // One name per path, however often the file changes.
    let name: &'static str = match known {
        Some(k) => rows[k].1.name,
        None => Box::leak(name.to_owned().into_boxed_str()),
    };
    let source: &'static str = Box::leak(source.into_boxed_str());
    let constructor: Constructor = Box::leak(Box::new(
        move |_: &super::params::Params| -> Result<Box<dyn Method>, Error> {
            Ok(Box::new(UserMethod {
                name,
                winding: Winding::with_user_source(source.to_owned()),
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
    match known {
        Some(k) => rows[k] = (hash, row),
        None => rows.push((hash, row)),
    }
    Ok(row)
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
/// in 1/255); without one, none: the method is observed.
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
            "{path}: the claim '{}' {why}: write `// claim: max=M mae=A` (M in coverage, 0 to 1; A in 1/255)",
            line.trim()
        ))
    };
    let (mut max, mut mae) = (None, None);
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
            _ => return Err(bad(&format!("has '{key}={value}'"))),
        }
    }
    let (Some(max), Some(mae)) = (max, mae) else {
        return Err(bad("lacks max or mae"));
    };
    let bound: Bound = within(max, mae);
    let statement: &'static str = Box::leak(
        format!("your claim: no pixel off by more than {max}, mean error within {mae}/255")
            .into_boxed_str(),
    );
    Ok(Claim {
        bound: Some(bound),
        except: &[],
        limitation: None,
        temporal: None,
        statement,
    })
}

/// A user's method: `winding`'s renderer with their `user_coverage`, under their name.
struct UserMethod {
    name: &'static str,
    winding: Winding,
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
        self.winding.encode(gpu, encoder, target, camera)
    }

    fn gpu_bytes(&self) -> u64 {
        self.winding.gpu_bytes()
    }

    fn overlays(&self) -> &'static [Overlay] {
        &[]
    }

    fn curves_per_pixel(
        &mut self,
        _gpu: &GpuContext,
        _camera: &Camera,
    ) -> Result<Option<CurveCost>, Error> {
        // The user's function counts nothing.
        Ok(None)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn claims_are_read_from_the_header_or_refused_in_one_line() {
        let claim = claim_of("f.wgsl", "// claim: max=0.3 mae=8\nfn f() {}").unwrap();
        assert_eq!(claim.bound, Some(within(0.3, 8.0)));
        assert!(claim_of("f.wgsl", "fn f() {}").unwrap().bound.is_none());
        for bad in [
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
}
