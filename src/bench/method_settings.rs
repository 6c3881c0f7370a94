//! The settings each method is measured at: a curated sweep across its speed/accuracy
//! trade, listed in its registry row (see each method's page in docs/methods/ for what
//! the parameters do), a handful of them marked for `--quick`.

use crate::methods::info::MethodInfo;
use crate::methods::params::owned;

/// The parameter sets `method` is measured at (all, or the quick ones), as `--param`
/// lists; the default first.
pub fn settings(method: &MethodInfo, quick: bool) -> Vec<Vec<(String, String)>> {
    method
        .bench
        .iter()
        .filter(|s| s.quick || !quick)
        .map(|s| owned(s.params))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::methods::registry;

    /// Every setting is one `create` accepts, and every method has its default first;
    /// `--quick` sweeps a trade of each of glyphscope's methods, and takes a peer at
    /// its default.
    #[test]
    fn every_setting_is_valid() {
        for method in registry::benched() {
            let name = method.name;
            let all = settings(method, false);
            assert!(all[0].is_empty(), "{name}: default first");
            let quick = if method.is_peer() { 1 } else { 2 };
            assert!(
                settings(method, true).len() >= quick,
                "{name}: quick sweeps a trade"
            );
            for params in all {
                method.create(&params).unwrap();
            }
        }
    }
}
