//! What each method claims about its error (as its README section states it), as data
//! the sweep checks. A claim has a bound and a scope; outside its scope the method
//! documents a known limitation, and the table still shows the measured numbers.

use super::cases::{Case, Trait};

/// A method's claim: no pixel off by more than `max_error` on every case but those
/// with one of the `except` traits (its documented limitations), or on none; on its
/// limitations, no pixel off by more than `limitation_max` where that is given, so a
/// regression inside a limitation still breaks the claim.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Claim {
    /// None: the method claims no bound; its errors are documented limitations.
    pub max_error: Option<f64>,
    pub except: &'static [Trait],
    /// The looser bound that still holds on the limitations (None: none does).
    pub limitation_max: Option<f64>,
    /// The claim, and its limitations, in the README's words.
    pub statement: &'static str,
}

impl Claim {
    /// Whether `case` is one of this claim's documented limitations.
    pub fn is_limitation(&self, case: &Case) -> bool {
        self.max_error.is_none() || case.traits.iter().any(|t| self.except.contains(t))
    }

    /// The bound this claim sets on `case`, if any.
    pub fn bound(&self, case: &Case) -> Option<f64> {
        if self.is_limitation(case) {
            self.limitation_max
        } else {
            self.max_error
        }
    }
}

/// One method at one setting, as the sweep runs it.
#[derive(Clone, Copy, Debug)]
pub struct Variant {
    /// Its column in the table.
    pub label: &'static str,
    /// The name `methods::create` takes.
    pub method: &'static str,
    pub params: &'static [(&'static str, &'static str)],
    pub claim: Claim,
}

impl Variant {
    pub fn params(&self) -> Vec<(String, String)> {
        self.params
            .iter()
            .map(|&(k, v)| (k.to_owned(), v.to_owned()))
            .collect()
    }
}

/// Every method, at its defaults, and sdf-cells in both modes.
pub const VARIANTS: &[Variant] = &[
    Variant {
        label: "winding",
        method: "winding",
        params: &[],
        claim: Claim {
            max_error: Some(0.5),
            except: &[Trait::DenseOverlaps],
            // Measured 0.717 on 256 stacked contours.
            limitation_max: Some(0.8),
            statement: "no pixel off by more than 0.5 anywhere; a window crossed by more \
                        than 8 edges falls back to its averaged winding",
        },
    },
    Variant {
        label: "sdf-cells",
        method: "sdf-cells",
        params: &[],
        claim: Claim {
            max_error: None,
            except: &[],
            limitation_max: None,
            statement: "estimate (the seed's): artifacts where the nearest chord's tangent \
                        puts a pixel on the wrong side, and cracks along overlaps",
        },
    },
    Variant {
        label: "sdf-cells exact",
        method: "sdf-cells",
        params: &[("mode", "exact")],
        claim: Claim {
            max_error: Some(0.5),
            except: &[Trait::Overlapping, Trait::SubpixelDetail],
            // Measured 0.500 on overlaps, 0.620 on sub-pixel detail.
            limitation_max: Some(0.8),
            statement: "no pixel off by more than 0.5 on outlines without overlapping \
                        contours; one edge per pixel, so detail under a pixel (a contour \
                        or several edges inside one) reads up to 0.5 + w/2",
        },
    },
    Variant {
        label: "xor-stencil",
        method: "xor-stencil",
        params: &[],
        claim: Claim {
            max_error: Some(0.5),
            except: &[Trait::DenseOverlaps],
            // A wrapped counter reads a covered pixel as empty: no bound.
            limitation_max: None,
            statement: "within half a level of the reference with four or more samples; \
                        8-bit counters read a winding of 256 as 0",
        },
    },
    Variant {
        label: "tessellation",
        method: "tessellation",
        params: &[],
        claim: Claim {
            max_error: Some(0.5),
            except: &[Trait::SubpixelDetail],
            // Measured 0.692 at 2 px/em.
            limitation_max: Some(0.8),
            statement: "screen-space subdivision with 4x MSAA: no pixel off by more than 0.5; \
                        four point samples cannot resolve several edges inside one pixel",
        },
    },
];
