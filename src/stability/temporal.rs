//! The hard cases in motion: each drifts 1/16 px a frame along 30° from the view the
//! sweep starts from, every method drawing every frame, and each method's temporal error
//! (see [`crate::metrics::temporal`]) is held to its temporal claim where it makes one
//! ([`crate::methods::info::Claim::temporal`]) and shown where it does not.

use std::fmt::Write as _;

use glam::DVec2;
use serde::Serialize;

use super::claims::Variant;
use super::hard_cases::HardCase;
use crate::Error;
use crate::gpu::GpuContext;
use crate::methods::info::Bound;
use crate::motion::MotionPath;
use crate::motion::run::{self, MethodSpec};

/// 1/16 px a frame along 30°: between every sub-pixel phase, across rows and columns.
pub const PATH: &str = crate::motion::DRIFT_30;

/// One variant's temporal error on one case.
#[derive(Clone, Debug, Serialize)]
pub struct TemporalOutcome {
    pub case: &'static str,
    pub variant: &'static str,
    /// Means over the frame pairs, 1/255; the largest change of any pixel beyond the
    /// reference's; pixels over 0.1 per pair.
    pub mae_255: f64,
    pub edge_mae_255: f64,
    pub max: f64,
    pub pixels_over_per_pair: f64,
    pub pairs: usize,
    /// The temporal claim on this case: none on a limitation, or for a method that
    /// makes none.
    pub bound: Option<Bound>,
    /// A peer's documented limit met on the path.
    pub refused: Option<String>,
    /// A failure to prepare or draw, which breaks a claim.
    pub failure: Option<String>,
}

impl TemporalOutcome {
    pub fn breaks_claim(&self) -> bool {
        self.bound.is_some_and(|b| {
            self.failure.is_some()
                || (self.refused.is_none() && !b.holds(self.max, self.mae_255, self.edge_mae_255))
        })
    }
}

/// Drifts every case of `cases` with every variant of `variants` for `frames` frames.
pub fn run(
    gpu: &GpuContext,
    cases: &[HardCase],
    variants: &[Variant],
    frames: usize,
    mut progress: impl FnMut(&str),
) -> Result<Vec<TemporalOutcome>, Error> {
    let path = MotionPath::parse(PATH)?;
    let specs: Vec<MethodSpec> = variants
        .iter()
        .map(|v| MethodSpec {
            name: v.method.into(),
            params: v.params(),
        })
        .collect();
    let mut outcomes = Vec::new();
    for case in cases {
        progress(case.name);
        let outcome = |variant: &Variant| TemporalOutcome {
            case: case.name,
            variant: variant.label,
            mae_255: 0.0,
            edge_mae_255: 0.0,
            max: 0.0,
            pixels_over_per_pair: 0.0,
            pairs: 0,
            bound: variant
                .claim
                .temporal
                .filter(|_| !variant.claim.is_limitation(case.traits)),
            refused: None,
            failure: None,
        };
        let result = case.camera(0.0, DVec2::ZERO).and_then(|camera| {
            run::run(
                Some(gpu),
                &case.scene,
                &camera,
                &path,
                frames,
                &specs,
                |_| {},
            )
        });
        match result {
            Ok(result) => {
                for (variant, m) in variants.iter().zip(result.methods) {
                    let t = m.temporal;
                    outcomes.push(TemporalOutcome {
                        mae_255: t.mae_255,
                        edge_mae_255: t.edge_mae_255,
                        max: t.max,
                        pixels_over_per_pair: t.pixels_over_per_pair,
                        pairs: t.pairs,
                        refused: m.refused,
                        ..outcome(variant)
                    });
                }
            }
            // The case's view, or drawing it with some method, failed: every claim on the
            // case is in doubt, and the other cases still run.
            Err(e) => outcomes.extend(variants.iter().map(|v| TemporalOutcome {
                failure: Some(e.to_string()),
                ..outcome(v)
            })),
        }
    }
    Ok(outcomes)
}

/// The outcomes that break a temporal claim, one line each.
pub fn broken_claims(outcomes: &[TemporalOutcome]) -> Vec<String> {
    outcomes
        .iter()
        .filter(|o| o.breaks_claim())
        .filter_map(|o| {
            let b = o.bound?;
            Some(match &o.failure {
                Some(failure) => format!("{} × {} in motion: failed: {failure}", o.case, o.variant),
                None => format!(
                    "{} × {} in motion: claims a temporal error ≤ {} and a mean ≤ {}/255, \
                     measured {:.4} and {:.3}/255",
                    o.case, o.variant, b.max, b.mae_255, o.max, o.mae_255
                ),
            })
        })
        .collect()
}

/// Per variant, over every case: the claim and its worst value in scope, the largest
/// temporal error and mean of any case, and how many cases have a pixel changing by
/// more than 0.1 beyond the reference.
pub fn summary_table(outcomes: &[TemporalOutcome]) -> String {
    let mut out = String::from(
        "| method | temporal claim (worst in its scope) | worst max (case) | worst MAE /255 (case) | cases with a pixel > 0.1 |\n\
         |---|---|---:|---:|---:|\n",
    );
    let mut variants: Vec<&str> = Vec::new();
    for o in outcomes {
        if !variants.contains(&o.variant) {
            variants.push(o.variant);
        }
    }
    for variant in variants {
        let drawn: Vec<&TemporalOutcome> = outcomes
            .iter()
            .filter(|o| o.variant == variant && o.pairs > 0)
            .collect();
        let worst = |of: &[&TemporalOutcome], key: fn(&TemporalOutcome) -> f64| {
            of.iter()
                .max_by(|a, b| key(a).total_cmp(&key(b)))
                .map_or("—".into(), |o| format!("{:.4} ({})", key(o), o.case))
        };
        let claimed: Vec<&TemporalOutcome> = drawn
            .iter()
            .copied()
            .filter(|o| o.bound.is_some())
            .collect();
        let claim = match claimed.first().and_then(|o| o.bound) {
            Some(b) => format!(
                "≤ {}, ≤ {}/255: {} and {}",
                b.max,
                b.mae_255,
                worst(&claimed, |o| o.max),
                worst(&claimed, |o| o.mae_255)
            ),
            None => "—".into(),
        };
        let flipping = drawn
            .iter()
            .filter(|o| o.pixels_over_per_pair > 0.0)
            .count();
        let _ = writeln!(
            out,
            "| {variant} | {claim} | {} | {} | {flipping} of {} |",
            worst(&drawn, |o| o.max),
            worst(&drawn, |o| o.mae_255),
            drawn.len()
        );
    }
    out
}

/// One row per (case, variant): temporal MAE over the frame and its edges, max, pixels
/// over 0.1 per pair, the claim and whether it held.
pub fn table(outcomes: &[TemporalOutcome], frames: usize) -> String {
    let mut out = format!(
        "In motion: each case drifting `{PATH}` for {} frames; temporal error |Δm − Δr| \
         between consecutive frames, means over the pairs.\n\n\
         | case | method | temporal MAE /255 | edge MAE /255 | max | > 0.1 per pair | claim (max, MAE) | |\n\
         |---|---|---:|---:|---:|---:|---|---|\n",
        frames
    );
    for o in outcomes {
        let claim = o
            .bound
            .map_or("—".into(), |b| format!("≤ {}, ≤ {}", b.max, b.mae_255));
        let verdict = match () {
            _ if o.failure.is_some() => "failed",
            _ if o.refused.is_some() && o.pairs == 0 => "n/a",
            _ if o.breaks_claim() => "BROKEN",
            _ if o.bound.is_some() => "ok",
            _ => "shown",
        };
        let _ = writeln!(
            out,
            "| {} | {} | {:.3} | {:.2} | {:.4} | {:.1} | {claim} | {verdict} |",
            o.case, o.variant, o.mae_255, o.edge_mae_255, o.max, o.pixels_over_per_pair
        );
    }
    out
}
