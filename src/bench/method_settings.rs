//! The settings each method is measured at: a curated sweep across its speed/accuracy
//! trade, listed in its registry row (see each method's page in docs/methods/ for what
//! the parameters do), a handful of them marked for `--quick`.
//!
//! The bench finds methods through the registry: every benched row, the baseline by its
//! role. Two of its choices are one method's business and are named here alone: the
//! baseline's glyph cache, pinned at each scene's own size (what "after caching"
//! means: `atlas`' `cache_px_per_em`), [`CONTRAST`], the method `--quick` keeps
//! after caching and the report sets against the peers, and [`SHIPPED`], the peer every
//! time is also divided by (by name: a build without that peer leaves its column
//! empty).

use crate::methods::info::MethodInfo;
use crate::methods::params;
use crate::methods::{atlas, winding};

/// glyphscope's own method that the bench sets beside the baseline and the peers:
/// `--quick` keeps its default after caching, and the report's peers table compares
/// each peer with it.
pub const CONTRAST: &MethodInfo = &winding::INFO;

/// The renderer people ship, the report's second yardstick: every time is also quoted
/// over this peer's default in the same view ("× glyphon"), where it can draw the view
/// and is compiled in (the `glyphon` feature). The atlas is the floor of glyphscope's
/// own harness; this is the floor of what is used.
pub const SHIPPED: &str = "glyphon";

/// The baseline's parameter that pins the size its glyphs are cached at.
const BASELINE_CACHE_KEY: &str = "cache_px_per_em";

/// The size the baseline caches glyphs at, by itself, for a first frame at
/// `px_per_em`: the bench pins it there for both views of a scene.
pub fn baseline_cache_size(px_per_em: f64) -> f64 {
    atlas::auto_cache_size(px_per_em)
}

/// The largest size the baseline caches at by itself; beyond it, it magnifies.
pub const BASELINE_CACHE_MAX_PX_PER_EM: f64 = atlas::AUTO_CACHE_MAX_PX_PER_EM;

/// The parameter that pins the baseline's cache at `px_per_em`.
pub fn baseline_cache_param(px_per_em: f64) -> (String, String) {
    (BASELINE_CACHE_KEY.into(), px_per_em.to_string())
}

/// The parameter sets `method` is measured at (all, or the quick ones), as `--param`
/// lists; the default first.
pub fn settings(method: &MethodInfo, every: bool) -> Vec<Vec<(String, String)>> {
    method
        .bench
        .iter()
        .filter(|s| s.quick || every)
        .map(|s| params::owned(s.params))
        .collect()
}

/// A setting as the report names it: `k=v, k=v`, or `default` (the baseline's cache size, the same for
/// every case of a scene, left out).
pub fn setting_name(params: &[(String, String)]) -> String {
    params::settings_text(params, &[BASELINE_CACHE_KEY])
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
                settings(method, false).len() >= quick,
                "{name}: quick sweeps a trade"
            );
            for params in all {
                method.create(&params).unwrap();
            }
        }
    }

    /// The contrast is one of glyphscope's drawing methods, and the pinned cache is a
    /// setting the baseline accepts.
    #[test]
    fn contrast_and_cache_are_what_they_say() {
        assert_eq!(CONTRAST.role, crate::methods::info::Role::Method);
        registry::baseline()
            .create(&[baseline_cache_param(baseline_cache_size(16.0))])
            .unwrap();
    }
}
