//! What each method claims about its error, as the sweep runs it: every claimed
//! setting of every method in the registry (each method's row states its claims, as
//! its page in docs/methods/ does). Outside a claim's scope the method documents a known
//! limitation, and the table still shows the measured numbers.

use crate::methods::info::{Claim, MethodInfo};
use crate::methods::params::owned;
use crate::methods::registry;

/// One method at one setting, as the sweep runs it.
#[derive(Clone, Copy, Debug)]
pub struct Variant {
    /// Its column in the table.
    pub label: &'static str,
    /// The method's name in the registry.
    pub method: &'static str,
    pub params: &'static [(&'static str, &'static str)],
    pub claim: Claim,
}

impl Variant {
    pub fn params(&self) -> Vec<(String, String)> {
        owned(self.params)
    }
}

/// Every claimed setting of every method, in the registry's order.
pub fn variants() -> Vec<Variant> {
    registry::METHODS
        .iter()
        .flat_map(|m| variants_of(m))
        .collect()
}

/// Every claimed setting of `method` (a registry row, or a user's file's row).
pub fn variants_of(method: &'static MethodInfo) -> impl Iterator<Item = Variant> {
    method.claims.iter().map(move |c| Variant {
        label: c.label,
        method: method.name,
        params: c.params,
        claim: c.claim,
    })
}
