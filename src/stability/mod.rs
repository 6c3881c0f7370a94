//! Numerical stability: the named hard cases ([`cases`]), what each method claims
//! ([`claims`]), the sweep that measures them against the reference ([`sweep`]), and
//! the report `glyphscope stability` prints and writes.

pub mod cases;
pub mod claims;
pub mod sweep;

use std::fmt::Write as _;
use std::path::Path;

use crate::Error;
use crate::metrics;
use cases::Case;
use claims::Variant;
use sweep::Outcome;

/// The cases called `names` (all when None), or an input error naming the unknown one.
pub fn select_cases(names: Option<&[String]>) -> Result<Vec<Case>, Error> {
    let all = cases::all();
    let Some(names) = names else { return Ok(all) };
    names
        .iter()
        .map(|name| {
            all.iter().find(|c| c.name == name).cloned().ok_or_else(|| {
                Error::Input(format!(
                    "unknown case '{name}'; the cases are: {}",
                    cases::names().join(", ")
                ))
            })
        })
        .collect()
}

/// The variants named by `names` (all when None): a variant's label picks it, a method
/// name picks all its variants.
pub fn select_variants(names: Option<&[String]>) -> Result<Vec<Variant>, Error> {
    let all = claims::variants();
    let Some(names) = names else {
        return Ok(all);
    };
    for name in names {
        if !all.iter().any(|v| v.label == name || v.method == name) {
            let labels: Vec<_> = all.iter().map(|v| v.label).collect();
            return Err(Error::Input(format!(
                "unknown method '{name}'; the stability sweep runs: {}",
                labels.join(", ")
            )));
        }
    }
    Ok(all
        .into_iter()
        .filter(|v| names.iter().any(|n| n == v.label || n == v.method))
        .collect())
}

/// The outcomes that break a claim, one line each: case, method, bound, measured value.
pub fn broken_claims(outcomes: &[Outcome]) -> Vec<String> {
    outcomes
        .iter()
        .filter(|o| o.breaks_claim())
        .map(|o| match &o.failure {
            Some(failure) => format!("{} × {}: failed: {failure}", o.case, o.variant),
            None => format!(
                "{} × {}: claims max error ≤ {}, measured {:.3} ({} artifact pixels; worst at {})",
                o.case,
                o.variant,
                o.bound.unwrap_or(f64::NAN),
                o.max,
                o.artifact_pixels,
                worst_location(o)
            ),
        })
        .collect()
}

fn worst_location(o: &Outcome) -> String {
    let w = &o.worst;
    format!(
        "{}°, offset ({}, {}), pixel ({}, {})",
        w.rotation_deg, w.subpixel.0, w.subpixel.1, w.pixel.0, w.pixel.1
    )
}

fn verdict(o: &Outcome) -> &'static str {
    match (o.breaks_claim(), o.limitation) {
        (true, _) => "BROKEN",
        (false, false) => "ok",
        (false, true) => "limitation",
    }
}

/// One row per (case, variant): MAE, max, artifacts, where it was worst, the claim.
pub fn long_table(outcomes: &[Outcome]) -> String {
    let mut out = String::from(
        "| case | method | MAE /255 | max | artifact px | worst at (rotation, offset, pixel) | claim | verdict |\n\
         |---|---|---:|---:|---:|---|---|---|\n",
    );
    for o in outcomes {
        let claim = match (o.limitation, o.bound) {
            (false, Some(b)) => format!("≤ {b}"),
            (true, Some(b)) => format!("limitation, ≤ {b}"),
            (_, None) => "limitation".to_owned(),
        };
        writeln!(
            out,
            "| {} | {} | {:.2} | {:.3} | {} | {} | {claim} | {} |",
            o.case,
            o.variant,
            o.mae_255,
            o.max,
            o.artifact_pixels,
            worst_location(o),
            verdict(o)
        )
        .expect("writing to a String");
    }
    out
}

/// Cases down, variants across, each cell "MAE · max · artifacts" ("*" marks a
/// documented limitation, "!" a broken claim).
pub fn matrix_table(outcomes: &[Outcome]) -> String {
    let mut variants: Vec<&str> = Vec::new();
    let mut cases: Vec<&str> = Vec::new();
    for o in outcomes {
        if !variants.contains(&o.variant) {
            variants.push(o.variant);
        }
        if !cases.contains(&o.case) {
            cases.push(o.case);
        }
    }
    let mut out = format!("| case | {} |\n|---|", variants.join(" | "));
    out += &"---:|".repeat(variants.len());
    out.push('\n');
    for case in &cases {
        out += &format!("| {case} |");
        for variant in &variants {
            let cell = outcomes
                .iter()
                .find(|o| o.case == *case && o.variant == *variant)
                .map_or("—".to_owned(), |o| {
                    let mark = match verdict(o) {
                        "BROKEN" => "!",
                        "limitation" => "*",
                        _ => "",
                    };
                    format!(
                        "{:.2} · {:.3} · {}{mark}",
                        o.mae_255, o.max, o.artifact_pixels
                    )
                });
            out += &format!(" {cell} |");
        }
        out.push('\n');
    }
    out
}

/// Writes, under `dir`, each (case, variant)'s worst frame and its signed error map
/// (red: too much coverage, blue: too little, full at 0.5), the tables as Markdown and
/// the outcomes as JSON.
pub fn write_report(dir: &Path, outcomes: &[Outcome]) -> Result<(), Error> {
    let output = |path: &Path, e: &dyn std::fmt::Display| {
        Error::Output(format!("cannot write '{}': {e}", path.display()))
    };
    std::fs::create_dir_all(dir).map_err(|e| output(dir, &e))?;
    for o in outcomes {
        let Some((image, reference)) = &o.worst_images else {
            continue;
        };
        let stem = format!("{}--{}", o.case, o.variant.replace(' ', "-"));
        image.save_png(&dir.join(format!("{stem}.png")))?;
        let path = dir.join(format!("{stem}-error.png"));
        metrics::error_image(image, reference, 0.5)
            .save(&path)
            .map_err(|e| output(&path, &e))?;
    }
    let markdown = format!(
        "MAE /255 (mean over frames) · max · artifact pixels (> 0.5, summed over frames); \
         * limitation, ! broken claim\n\n{}\n{}",
        matrix_table(outcomes),
        long_table(outcomes)
    );
    let path = dir.join("stability.md");
    std::fs::write(&path, markdown).map_err(|e| output(&path, &e))?;
    let path = dir.join("stability.json");
    let json = serde_json::to_string_pretty(outcomes).expect("outcomes serialize");
    std::fs::write(&path, json + "\n").map_err(|e| output(&path, &e))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use sweep::Worst;

    fn outcome(max: f64, bound: Option<f64>) -> Outcome {
        Outcome {
            case: "a-case",
            variant: "a-method",
            mae_255: 1.0,
            max,
            artifact_pixels: 3,
            frames: 8,
            worst: Worst::default(),
            limitation: bound.is_none(),
            bound,
            failure: None,
            worst_images: None,
        }
    }

    #[test]
    fn a_claim_breaks_only_past_its_bound_and_nan_breaks_it() {
        assert!(!outcome(0.5, Some(0.5)).breaks_claim());
        assert!(!outcome(0.9, None).breaks_claim(), "a limitation");
        assert!(outcome(f64::NAN, Some(0.5)).breaks_claim());
        let broken = broken_claims(&[outcome(0.61, Some(0.5)), outcome(0.1, Some(0.5))]);
        assert_eq!(broken.len(), 1);
        assert!(broken[0].contains("a-case × a-method") && broken[0].contains("0.610"));
        let failed = Outcome {
            failure: Some("prepare: boom".into()),
            ..outcome(0.0, None)
        };
        assert!(failed.breaks_claim());
    }

    #[test]
    fn case_names_are_unique() {
        let mut names = cases::names();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), cases::all().len());
    }
}
