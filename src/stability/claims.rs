//! What each method claims about its error (as its README section states it), as data
//! the sweep checks. A claim has a bound and a scope; outside its scope the method
//! documents a known limitation, and the table still shows the measured numbers.

use super::cases::{Case, Trait};

/// A method's claim: no pixel off by more than `max_error` on every case but those
/// with one of the `except` traits (its documented limitations), or on none.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Claim {
    /// None: the method claims no bound; its errors are documented limitations.
    pub max_error: Option<f64>,
    pub except: &'static [Trait],
    /// The claim, and its limitations, in the README's words.
    pub statement: &'static str,
}

impl Claim {
    /// The bound this claim sets on `case`, or None where the case is a limitation.
    pub fn bound(&self, case: &Case) -> Option<f64> {
        let excluded = case.traits.iter().any(|t| self.except.contains(t));
        self.max_error.filter(|_| !excluded)
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
            statement: "screen-space subdivision with 4x MSAA: no pixel off by more than 0.5; \
                        four point samples cannot resolve several edges inside one pixel",
        },
    },
];
