//! The hard cases in motion: each drifts 1/16 px a frame along 30° from the view the
//! sweep starts from, every method drawing every frame, and each method's temporal error
//! (see [`crate::metrics::temporal`]) is held to its temporal claim where it makes one
//! ([`crate::methods::registry::Claim::temporal`]) and shown where it does not.

use std::fmt::Write as _;

use glam::DVec2;
use serde::Serialize;

use super::claims::Variant;
use super::hard_cases::HardCase;
use crate::Error;
use crate::gpu::GpuContext;
use crate::methods::registry::Bound;
use crate::motion::MotionPath;
use crate::motion::run::{self, MethodSpec};

/// 1/16 px a frame along 30°: between every sub-pixel phase, across rows and columns.
pub const PATH: &str = "drift:0.05412658773652741,-0.03125";
/// Frames per case: 16, 8 with `--quick`.
pub const FRAMES: usize = 16;
pub const QUICK_FRAMES: usize = 8;

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
            self.failure.is_some() || (self.refused.is_none() && !b.holds(self.max, self.mae_255))
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
        let camera = case.camera(0.0, DVec2::ZERO)?;
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
        match run::run(
            Some(gpu),
            &case.scene,
            &camera,
            &path,
            frames,
            &specs,
            |_| {},
        ) {
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
            // Drawing failed for some method: every claim on the case is in doubt.
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
        .map(|o| match (&o.failure, o.bound) {
            (Some(failure), _) => {
                format!("{} × {} in motion: failed: {failure}", o.case, o.variant)
            }
            (None, Some(b)) => format!(
                "{} × {} in motion: claims a temporal error ≤ {} and a mean ≤ {}/255, \
                 measured {:.4} and {:.3}/255",
                o.case, o.variant, b.max, b.mae_255, o.max, o.mae_255
            ),
            (None, None) => String::new(),
        })
        .collect()
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
