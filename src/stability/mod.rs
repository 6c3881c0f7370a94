//! Numerical stability: the named hard cases ([`hard_cases`]), what each method claims
//! ([`claims`]), the sweep that measures them against the reference ([`sweep`]), the
//! same cases in motion ([`temporal`]), and the report `glyphscope stability` prints
//! and writes.

pub mod claims;
pub mod command;
pub mod hard_cases;
pub mod outcome;
pub mod sweep;
pub mod temporal;
pub mod worst_cameras;

use std::fmt::Write as _;
use std::path::Path;

use crate::Error;
use crate::coverage::Png as _;
use crate::methods::info::{MARGIN, MeanOver};
use crate::metrics;
use claims::Variant;
use hard_cases::HardCase;
use outcome::Outcome;

/// The cases called `names` (all when None), or an input error naming the unknown one.
pub fn select_cases(names: Option<&[String]>) -> Result<Vec<HardCase>, Error> {
    let all = hard_cases::all();
    let Some(names) = names else { return Ok(all) };
    names
        .iter()
        .map(|name| {
            all.iter().find(|c| c.name == name).cloned().ok_or_else(|| {
                Error::Input(format!(
                    "unknown case '{name}'; the cases are: {}",
                    hard_cases::names().join(", ")
                ))
            })
        })
        .collect()
}

/// The variants named by `names` (all when None): a variant's label picks it, a method
/// name picks all its variants, and `wgsl:PATH` a user's file with its claim.
pub fn select_variants(names: Option<&[String]>) -> Result<Vec<Variant>, Error> {
    let mut all = claims::variants();
    let Some(names) = names else {
        return Ok(all);
    };
    // A user's file (`wgsl:PATH`, with `:claim=MAX/MAE` where given) is picked by its
    // row's name, the path.
    let mut names = names.to_vec();
    for name in &mut names {
        if name.starts_with(crate::methods::user::PREFIX) {
            let row = crate::methods::registry::find(name)?;
            all.extend(claims::variants_of(row));
            *name = row.name.to_owned();
        }
    }
    for name in &names {
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
        .map(|o| match (&o.failure, o.bound) {
            (Some(failure), _) => format!("{} × {}: failed: {failure}", o.case, o.variant),
            (None, Some(bound)) => format!(
                "{} × {}: claims {bound}, measured max {:.3}, MAE {:.2}/255 and edge MAE \
                 {:.2}/255 ({} artifact pixels; worst at {})",
                o.case,
                o.variant,
                o.max,
                o.mae_255,
                o.edge_mae_255,
                o.artifact_pixels,
                worst_location(o)
            ),
            (None, None) => unreachable!("an outcome with no bound and no failure holds"),
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
        _ if o.observed && o.failure.is_some() => "failed (observed)",
        _ if o.refused.is_some() && o.frames == 0 => "n/a",
        _ if o.observed => "observed",
        (true, _) => "BROKEN",
        (false, false) => "ok",
        (false, true) => "limitation",
    }
}

/// One row per (case, variant): MAE over the frame and over its edge pixels, max,
/// pixels off by more than 0.25 and 0.5, where it was worst, the claim.
pub fn long_table(outcomes: &[Outcome]) -> String {
    let mut out = String::from(
        "| case | method | MAE /255 | edge MAE /255 | max | px > 0.25 | px > 0.5 | worst at (rotation, offset, pixel) | claim | verdict |\n\
         |---|---|---:|---:|---:|---:|---:|---|---|---|\n",
    );
    for o in outcomes {
        let claim = match (o.limitation, o.bound) {
            (false, Some(b)) => b.to_string(),
            (true, Some(b)) => format!("limitation, {b}"),
            (_, None) if o.observed => "none (observed)".to_owned(),
            (_, None) => "limitation".to_owned(),
        };
        if let (Some(reason), 0) = (&o.refused, o.frames) {
            writeln!(
                out,
                "| {} | {} | n/a — {reason} | | | | | | {claim} | n/a |",
                o.case, o.variant
            )
            .expect("writing to a String");
            continue;
        }
        let claim = match &o.refused {
            Some(reason) => format!(
                "{claim}; {} cameras drawn, the rest n/a — {reason}",
                o.frames
            ),
            None => claim,
        };
        writeln!(
            out,
            "| {} | {} | {:.2} | {:.2} | {:.3} | {} | {} | {} | {claim} | {} |",
            o.case,
            o.variant,
            o.mae_255,
            o.edge_mae_255,
            o.max,
            o.pixels_over_025,
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
                    if o.refused.is_some() && o.frames == 0 {
                        return "n/a".to_owned();
                    }
                    // Drawn through some cameras only.
                    let part = if o.refused.is_some() {
                        " (part n/a)"
                    } else {
                        ""
                    };
                    let mark = match verdict(o) {
                        "BROKEN" => "!",
                        "limitation" => "*",
                        _ => "",
                    };
                    format!(
                        "{:.2} · {:.3} · {}{mark}{part}",
                        o.mae_255, o.max, o.artifact_pixels
                    )
                });
            out += &format!(" {cell} |");
        }
        out.push('\n');
    }
    out
}

/// Per claim, the worst values measured on the cases it bounds (its claimed cases,
/// then its limitations) as a share of the bound: the margin rule asks for at most
/// [`MARGIN`]; a share over it is marked "over".
pub fn margin_table(outcomes: &[Outcome]) -> String {
    let mut out = String::from(
        "| method | cases | bound | worst max (share) | worst mean /255 (share) | margin rule |\n\
         |---|---|---|---|---|---|\n",
    );
    let mut variants: Vec<&str> = Vec::new();
    for o in outcomes {
        if !variants.contains(&o.variant) {
            variants.push(o.variant);
        }
    }
    for variant in variants {
        for limitation in [false, true] {
            let cells: Vec<&Outcome> = outcomes
                .iter()
                .filter(|o| o.variant == variant && o.limitation == limitation)
                .collect();
            let Some(bound) = cells.first().and_then(|o| o.bound) else {
                continue;
            };
            let worst = |value: fn(&Outcome) -> f64| {
                cells
                    .iter()
                    .map(|o| (value(o), o.case))
                    .max_by(|a, b| a.0.total_cmp(&b.0))
                    .expect("a bound comes from a cell")
            };
            let (max, max_case) = worst(|o| o.max);
            let (mae, mae_case) = if bound.over == MeanOver::EdgePixels {
                worst(|o| o.edge_mae_255)
            } else {
                worst(|o| o.mae_255)
            };
            let max_share = max / bound.max;
            // A claim on the maximum alone has no share of a mean to keep.
            let (mae_share, mae_cell) = match bound.over {
                MeanOver::Unbounded => (0.0, format!("{mae:.2} {mae_case} (not bounded)")),
                _ => {
                    let share = mae / bound.mae_255;
                    (
                        share,
                        format!("{mae:.2} {mae_case} ({:.0}%)", 100.0 * share),
                    )
                }
            };
            let kept = max_share <= MARGIN && mae_share <= MARGIN;
            writeln!(
                out,
                "| {variant} | {} | {bound} | {max:.3} {max_case} ({:.0}%) | {mae_cell} | {} |",
                if limitation { "limitations" } else { "claimed" },
                100.0 * max_share,
                if kept { "kept" } else { "over" }
            )
            .expect("writing to a String");
        }
    }
    out
}

/// Writes, under `dir`, each (case, variant)'s worst frame and its signed error map
/// (red: too much coverage, blue: too little, full at 0.5), the tables (with each
/// claim's margin) as Markdown, the outcomes as JSON, and — for the full sweep of every
/// case and method, measured on `full_sweep_device` — the worst cameras as the CSV the
/// CI grid reads ([`worst_cameras`]).
pub fn write_report(
    dir: &Path,
    outcomes: &[Outcome],
    in_motion: &[temporal::TemporalOutcome],
    motion_frames: usize,
    full_sweep_device: Option<&str>,
) -> Result<(), Error> {
    let output = |path: &Path, e: &dyn std::fmt::Display| {
        Error::Output(format!("cannot write '{}': {e}", path.display()))
    };
    std::fs::create_dir_all(dir).map_err(|e| output(dir, &e))?;
    for o in outcomes {
        let Some((image, reference)) = &o.worst_images else {
            continue;
        };
        // A user's method's label is its path (`wgsl:dir/file.wgsl`): no folders.
        let variant = o.variant.replace(' ', "-").replace(['/', ':', '\\'], "_");
        let stem = format!("{}--{variant}", o.case);
        image.save_png(&dir.join(format!("{stem}.png")))?;
        let path = dir.join(format!("{stem}-error.png"));
        metrics::error_image(image, reference, 0.5)
            .save(&path)
            .map_err(|e| output(&path, &e))?;
    }
    let markdown = format!(
        "MAE /255 (mean over frames) · max · artifact pixels (> 0.5, summed over frames); \
         * limitation, ! broken claim\n\n{}\n{}\n{}\n{}",
        matrix_table(outcomes),
        margin_table(outcomes),
        long_table(outcomes),
        temporal::summary_table(in_motion) + "\n" + &temporal::table(in_motion, motion_frames)
    );
    let path = dir.join("stability.md");
    std::fs::write(&path, markdown).map_err(|e| output(&path, &e))?;
    if let Some(device) = full_sweep_device {
        let path = dir.join("worst-cameras.csv");
        let csv = worst_cameras::to_csv(outcomes, device);
        std::fs::write(&path, csv).map_err(|e| output(&path, &e))?;
    }
    let path = dir.join("stability.json");
    let json = serde_json::to_string_pretty(&serde_json::json!({
        "outcomes": outcomes,
        "in_motion": in_motion,
    }))
    .expect("outcomes serialize");
    std::fs::write(&path, json + "\n").map_err(|e| output(&path, &e))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::methods::info::within;
    use outcome::Worst;

    fn outcome(max: f64, bound: Option<f64>) -> Outcome {
        Outcome {
            case: "a-case",
            variant: "a-method",
            mae_255: 1.0,
            edge_mae_255: 10.0,
            max,
            pixels_over_025: 5,
            artifact_pixels: 3,
            frames: 8,
            worst: Worst::default(),
            limitation: bound.is_none(),
            bound: bound.map(|max| within(max, 2.0)),
            failure: None,
            refused: None,
            observed: false,
            worst_images: None,
        }
    }

    /// The file the full sweep writes reads back as the cameras it was written from
    /// (an infinite error included), and a sweep that finds an error on a pair the
    /// file lacks, more or less error than the file lists, or NaN, shows it stale; so
    /// does a listed pair that did not run.
    #[test]
    fn worst_cameras_round_trip_and_go_stale() {
        let worst = Outcome {
            worst: Worst {
                rotation_deg: 89.9,
                subpixel: (0.25, 0.75),
                pixel: (3, 4),
            },
            ..outcome(0.123_456_789, Some(0.5))
        };
        let invalid = Outcome {
            case: "b-case",
            ..outcome(f64::INFINITY, None)
        };
        let outcomes = [worst.clone(), outcome(0.0, None), invalid.clone()];
        let csv: &'static str =
            Box::leak(worst_cameras::to_csv(&outcomes, "some GPU").into_boxed_str());
        assert!(csv.contains("# device: some GPU\n"));
        let mut cameras = worst_cameras::parse(csv).unwrap();
        assert_eq!(cameras.len(), 2);
        assert_eq!(cameras.pop().map(|c| c.max), Some(f64::INFINITY));
        assert_eq!(
            cameras,
            [worst_cameras::WorstCamera {
                case: "a-case",
                variant: "a-method",
                rotation_deg: 89.9,
                subpixel: (0.25, 0.75),
                max: 0.123_456_789,
            }]
        );
        assert!(worst_cameras::stale_entries(&cameras, std::slice::from_ref(&worst)).is_empty());
        let step = worst_cameras::STALE_TOLERANCE;
        for max in [
            0.123_456_789 + 1.5 * step,
            0.123_456_789 - 1.5 * step,
            f64::NAN,
        ] {
            let found = Outcome {
                worst: worst.worst,
                ..outcome(max, Some(0.5))
            };
            let stale = worst_cameras::stale_entries(&cameras, &[found]);
            assert_eq!(stale.len(), 1, "{max}: {stale:?}");
        }
        let elsewhere = Outcome {
            variant: "another-method",
            ..outcome(0.01, Some(0.5))
        };
        let stale = worst_cameras::stale_entries(&cameras, &[elsewhere]);
        assert_eq!(stale.len(), 2, "{stale:?}");
        assert!(stale[0].contains("no worst camera is listed"), "{stale:?}");
        assert!(stale[1].contains("no such pair ran"), "{stale:?}");
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
    fn a_claim_breaks_past_its_mean_error_too() {
        let mae = |mae_255| Outcome {
            mae_255,
            ..outcome(0.1, Some(0.5))
        };
        assert!(!mae(2.0).breaks_claim());
        assert!(mae(2.01).breaks_claim());
        assert!(mae(f64::NAN).breaks_claim());
        let broken = broken_claims(&[mae(3.0)]);
        assert!(broken[0].contains("MAE ≤ 2/255") && broken[0].contains("3.00/255"));
    }

    #[test]
    fn the_margin_table_marks_a_bound_kept_under_its_margin_only() {
        let table = margin_table(&[outcome(0.4, Some(0.5))]);
        assert!(
            table.contains("| kept |") && table.contains("(80%)"),
            "{table}"
        );
        let table = margin_table(&[outcome(0.41, Some(0.5))]);
        assert!(table.contains("| over |"), "{table}");
    }

    #[test]
    fn case_names_are_unique() {
        let mut names = hard_cases::names();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), hard_cases::all().len());
    }
}
