//! The settings each method is measured at: a curated sweep across its speed/accuracy
//! trade (see each method's README section for what the parameters do), a handful of
//! them marked for `--quick`.

/// The methods the bench compares, the baseline last. `bounds` is a diagnostic, not a
/// way to draw text, and is left out; the reference's CPU time is reported beside them.
pub const BENCH_METHODS: &[&str] = &[
    "winding",
    "sdf-cells",
    "xor-stencil",
    "tessellation",
    "atlas",
];

/// The method every time is divided by, at its defaults (4 × 4 sub-pixel phases).
pub const BASELINE: &str = "atlas";

struct Setting {
    params: &'static [(&'static str, &'static str)],
    /// Measured by `--quick` too.
    quick: bool,
}

const fn at(params: &'static [(&'static str, &'static str)], quick: bool) -> Setting {
    Setting { params, quick }
}

// Per method, its default first.

// Samples and rays are the trade; bands change only the time (the same image), shown
// on the cheapest setting (without bands a page costs ~10× as much).
const WINDING: &[Setting] = &[
    at(&[], true),
    at(&[("samples", "1")], true),
    at(&[("samples", "4")], false),
    at(&[("rays", "1")], false),
    at(&[("rays", "1"), ("samples", "1")], true),
    at(&[("rays", "1"), ("samples", "1"), ("bands", "off")], false),
];
const SDF_CELLS: &[Setting] = &[at(&[], true), at(&[("mode", "exact")], true)];
// Samples × jittered passes: from aliased to 16 coverage levels and beyond.
const XOR_STENCIL: &[Setting] = &[
    at(&[], true),
    at(&[("msaa", "1"), ("passes", "1")], true),
    at(&[("msaa", "4"), ("passes", "1")], false),
    at(&[("msaa", "1"), ("passes", "4")], false),
    at(&[("msaa", "1"), ("passes", "16")], false),
];
// MSAA is the accuracy; the tolerance and subdivision mode move the points.
const TESSELLATION: &[Setting] = &[
    at(&[], true),
    at(&[("msaa", "1")], true),
    at(&[("tolerance_px", "0.25")], false),
    at(&[("tolerance_px", "0.05")], false),
    at(&[("subdivision", "asa"), ("threshold", "13")], false),
    at(&[("subdivision", "fsa"), ("steps", "4")], false),
];
// The cache size is added per scene: the scene's own.
const ATLAS: &[Setting] = &[
    at(&[], true),
    at(&[("subpixel", "1")], true),
    at(&[("subpixel", "off")], false),
];

fn settings(method: &str) -> &'static [Setting] {
    match method {
        "winding" => WINDING,
        "sdf-cells" => SDF_CELLS,
        "xor-stencil" => XOR_STENCIL,
        "tessellation" => TESSELLATION,
        "atlas" => ATLAS,
        _ => &[],
    }
}

/// The parameter sets `method` is measured at (all, or the quick ones), as `--param`
/// lists; the default first.
pub fn sweep(method: &str, quick: bool) -> Vec<Vec<(String, String)>> {
    settings(method)
        .iter()
        .filter(|s| s.quick || !quick)
        .map(|s| owned(s.params))
        .collect()
}

pub fn owned(params: &[(&str, &str)]) -> Vec<(String, String)> {
    params
        .iter()
        .map(|&(k, v)| (k.to_owned(), v.to_owned()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::methods;

    /// Every setting is one `create` accepts, and every method has its default first.
    #[test]
    fn every_setting_is_valid() {
        for method in BENCH_METHODS {
            let all = sweep(method, false);
            assert!(all[0].is_empty(), "{method}: default first");
            assert!(
                sweep(method, true).len() >= 2,
                "{method}: quick sweeps a trade"
            );
            for params in all {
                methods::create(method, &params).unwrap();
            }
        }
    }
}
