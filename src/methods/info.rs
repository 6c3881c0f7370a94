//! A method's row, as everything that lists methods sees it: its name, role, shader,
//! parameters, plot colour, bench settings and claims ([`MethodInfo`]), and the types
//! a row is written with. Each method writes its own row; [`super::registry`] lists
//! them.

use super::Method;
use super::params::{ParamSpec, Params};
use crate::Error;
use crate::gpu::shaders::Shader;

/// What a method is for, which decides where it appears.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// The exact CPU rasterizer every method is measured against.
    Reference,
    /// A way to draw text from outlines on the GPU: benched, swept, claimed.
    Method,
    /// What the methods are compared with (the atlas); the bench divides times by it.
    Baseline,
    /// A check of the GPU path, not a way to draw text (`bounds`): drawn and tested,
    /// not benched.
    Diagnostic,
    /// A renderer people use instead (vello, glyphon, vello_cpu), measured as it is:
    /// benched beside the methods, run through the stability sweep as an observed row,
    /// never claimed for.
    Peer,
}

/// Makes a GPU method from its parameters, checked against its rows: a row writes a
/// closure (`&|params| …`); a user's method (`wgsl:PATH`) one holding its source.
pub type Constructor = &'static (dyn Fn(&Params) -> Result<Box<dyn Method>, Error> + Sync);

/// One method, as everything that lists methods sees it.
pub struct MethodInfo {
    /// The name `--method` takes.
    pub name: &'static str,
    /// One line: how it draws. Shown in `--help` and the app's menus.
    pub summary: &'static str,
    pub role: Role,
    /// Its WGSL (None for the CPU reference).
    pub shader: Option<Shader>,
    pub params: &'static [ParamSpec],
    /// Its colour in plots, (r, g, b).
    pub colour: [u8; 3],
    /// The settings the bench measures it at, its default first (empty: not benched).
    pub bench: &'static [BenchSetting],
    /// What the stability sweep checks of it: each setting with its claim.
    pub claims: &'static [ClaimedSetting],
    /// Builds it from its parameters (None for the reference, which is not a GPU
    /// method); see [`MethodInfo::create`].
    pub constructor: Option<Constructor>,
}

impl std::fmt::Debug for MethodInfo {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("MethodInfo")
            .field("name", &self.name)
            .field("role", &self.role)
            .finish_non_exhaustive()
    }
}

impl MethodInfo {
    pub fn is_reference(&self) -> bool {
        self.role == Role::Reference
    }

    /// Whether the bench measures it (a drawing method, the baseline or a peer).
    pub fn is_benched(&self) -> bool {
        matches!(self.role, Role::Method | Role::Baseline | Role::Peer)
    }

    pub fn is_peer(&self) -> bool {
        self.role == Role::Peer
    }

    /// `given` (`--param` pairs) checked against this method's parameters.
    pub fn parse_params(&self, given: &[(String, String)]) -> Result<Params, Error> {
        Params::parse(self.name, self.params, given)
    }

    /// The GPU method, made with the parameters `given`.
    pub fn create(&self, given: &[(String, String)]) -> Result<Box<dyn Method>, Error> {
        let params = self.parse_params(given)?;
        let constructor = self.constructor.ok_or_else(|| {
            Error::Input(format!(
                "'{}' is drawn on the CPU, not by a GPU method",
                self.name
            ))
        })?;
        // Behind the net: a panic in the row, now or in any later call, is an error
        // naming it (`guarded`).
        let made = super::guarded::catching(|| constructor(&params)).map_err(|cause| {
            Error::Refused(format!(
                "{} failed to start (a panic, caught: {cause})",
                self.name
            ))
        })?;
        made.map(super::guarded::Guarded::wrap)
    }
}

/// One setting the bench measures a method at.
#[derive(Clone, Copy, Debug)]
pub struct BenchSetting {
    pub params: &'static [(&'static str, &'static str)],
    /// Measured by `--quick` too.
    pub quick: bool,
}

/// A bench setting: `params`, measured by `--quick` when `quick`.
pub const fn bench_at(
    params: &'static [(&'static str, &'static str)],
    quick: bool,
) -> BenchSetting {
    BenchSetting { params, quick }
}

/// One setting of a method the stability sweep runs, with what it claims there.
#[derive(Clone, Copy, Debug)]
pub struct ClaimedSetting {
    /// Its column in the stability table.
    pub label: &'static str,
    pub params: &'static [(&'static str, &'static str)],
    pub claim: Claim,
}

/// A method's claim: within `bound` on every case but those with one of the `except`
/// traits (its documented limitations), or on none; on its limitations, within
/// `limitation` where that is given, so a regression inside a limitation still breaks
/// the claim.
///
/// **The margin rule**: every bound is written down before the sweep that checks it,
/// from what the method is expected to do, so that the worst value measured stays at
/// or under [`MARGIN`] of it (the full sweep prints each claim's share in its report).
/// A bound just over one measured value claims nothing but that measurement.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Claim {
    /// None: the method claims no bound; its errors are documented limitations.
    pub bound: Option<Bound>,
    pub except: &'static [Trait],
    /// The looser bound that still holds on the limitations (None: none does).
    pub limitation: Option<Bound>,
    /// Outside the limitations, a bound on the temporal error (see
    /// [`crate::metrics::temporal`]) as each case drifts 1/16 px a frame
    /// (`stability::temporal`): its largest and its mean over the frame pairs, 1/255.
    /// None: the method claims nothing about motion; its figures are still shown.
    pub temporal: Option<Bound>,
    /// The claim, and its limitations, in the words of the method's page in docs/methods/.
    pub statement: &'static str,
}

/// The share of a bound the worst measured value may reach: the margin rule.
pub const MARGIN: f64 = 0.8;

/// What a claim bounds on one case, over every camera the sweep sees it through.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Bound {
    /// No pixel off by more than this (coverage, 0..1).
    pub max: f64,
    /// The mean absolute error, in 1/255, over the pixels `over` says: a bound on the
    /// maximum alone lets a method round every pixel to 0 or 1 (off by at most 0.5)
    /// pass.
    pub mae_255: f64,
    /// Which pixels `mae_255` averages over.
    #[serde(default)]
    pub over: MeanOver,
}

/// The pixels a claim's mean error is taken over.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum MeanOver {
    /// Every pixel of the frame (or the survey's slot).
    #[default]
    Frame,
    /// The edge pixels alone ([`crate::metrics::ErrorStats::edge`]). For a method whose
    /// error lives on edge pixels by nature (point samples, MSAA), the mean over a frame
    /// grows with the share of edge pixels, so one bound cannot mean the same on a
    /// sparse glyph and a dense one; the mean over the edge pixels can.
    EdgePixels,
    /// No bound on the mean: the claim is on the maximum alone, which coverage rounded
    /// to 0 or 1 also keeps (its statement says so). For a method that reads one
    /// distance per pixel, whose error on a stroke thinner than a pixel is rounding's.
    Unbounded,
}

/// A bound on the largest error and on the mean one over the frame (1/255).
pub const fn within(max: f64, mae_255: f64) -> Bound {
    Bound {
        max,
        mae_255,
        over: MeanOver::Frame,
    }
}

/// A bound on the largest error and on the mean one over the edge pixels (1/255).
pub const fn within_on_edges(max: f64, edge_mae_255: f64) -> Bound {
    Bound {
        max,
        mae_255: edge_mae_255,
        over: MeanOver::EdgePixels,
    }
}

/// A bound on the largest error alone ([`MeanOver::Unbounded`]).
pub const fn within_max_only(max: f64) -> Bound {
    Bound {
        max,
        mae_255: 0.0,
        over: MeanOver::Unbounded,
    }
}

impl Bound {
    /// Of a frame's mean error `mae_255` and its mean over the edge pixels
    /// `edge_mae_255`, the one this bound is on.
    pub fn mean_of(&self, mae_255: f64, edge_mae_255: f64) -> f64 {
        match self.over {
            MeanOver::Frame | MeanOver::Unbounded => mae_255,
            MeanOver::EdgePixels => edge_mae_255,
        }
    }

    /// Whether a largest error `max` and the mean errors over the frame (`mae_255`) and
    /// over its edge pixels (`edge_mae_255`) keep to this bound. A NaN compares false
    /// with everything, so it never does.
    pub fn holds(&self, max: f64, mae_255: f64, edge_mae_255: f64) -> bool {
        let mean = self.mean_of(mae_255, edge_mae_255);
        // Unbounded, the mean is still checked for NaN: a NaN breaks every claim.
        let mean_kept = match self.over {
            MeanOver::Unbounded => !mean.is_nan(),
            _ => mean <= self.mae_255,
        };
        max <= self.max && mean_kept
    }

    /// The name of the mean this bound is on: "MAE" or "edge MAE".
    pub fn mean_name(&self) -> &'static str {
        match self.over {
            MeanOver::Frame => "MAE",
            MeanOver::EdgePixels => "edge MAE",
            MeanOver::Unbounded => "mean",
        }
    }
}

impl std::fmt::Display for Bound {
    /// "max ≤ M and MAE ≤ A/255", or "edge MAE" for a bound over edge pixels: no comma,
    /// so that it stays one field of a CSV split on commas alone.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.over == MeanOver::Unbounded {
            return write!(f, "max ≤ {} (the mean not bounded)", self.max);
        }
        write!(
            f,
            "max ≤ {} and {} ≤ {}/255",
            self.max,
            self.mean_name(),
            self.mae_255
        )
    }
}

impl Claim {
    /// Whether an outline with `traits` is one of this claim's documented limitations.
    pub fn is_limitation(&self, traits: &[Trait]) -> bool {
        self.bound.is_none() || traits.iter().any(|t| self.except.contains(t))
    }

    /// The bound this claim sets on an outline with `traits`, if any.
    pub fn bound(&self, traits: &[Trait]) -> Option<Bound> {
        if self.is_limitation(traits) {
            self.limitation
        } else {
            self.bound
        }
    }
}

/// A property of an outline that a method's claim may leave out of its scope. Each
/// says what the outline is, never how a method fails on it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Trait {
    /// Contours overlap or cross themselves: a distance to the outline is not a
    /// distance to the filled area's boundary.
    Overlapping,
    /// The ink of neighbouring glyphs overlaps (letters joining, vowel signs over their
    /// bases, box-drawing characters meeting, a kerned pair): a method that draws glyph
    /// by glyph and composites them counts the shared ink twice.
    OverlappingGlyphs,
    /// Separate contours meet at a point or along an edge without overlapping: the
    /// outline's boundary there is made of two contours' edges.
    TouchingContours,
    /// Several edges, or a whole contour, inside one pixel: one distance per pixel (or
    /// four point samples) cannot resolve them.
    SubpixelDetail,
    /// More than 8 edges cross one pixel somewhere (at the case's size): more than a
    /// ray keeps sorted in its pixel window.
    CrowdedPixels,
    /// Somewhere the winding number exceeds 255, the largest an 8-bit counter holds.
    DeepWinding,
    /// A view so deep into one glyph (10⁶ px/em) that f32 font units resolve only about
    /// 1/32 px there: a method that places edges in local coordinates cannot place them
    /// closer than that.
    BeyondF32,
}
