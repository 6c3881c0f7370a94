//! How the bench's reports write numbers: every table and sentence of `bench.md` that
//! shows a time, a size or a memory figure formats it here, so one figure reads alike
//! in every section.

/// Three significant digits (at least one decimal below 100).
pub fn sig(v: f64) -> String {
    if v >= 100.0 {
        format!("{v:.0}")
    } else if v >= 10.0 {
        format!("{v:.1}")
    } else if v >= 1.0 {
        format!("{v:.2}")
    } else {
        format!("{v:.3}")
    }
}

/// A memory figure in binary kilobytes (`"612 kB"`, whole) up to a binary megabyte,
/// then in binary megabytes (`"71.5 MB"`, one decimal); none held is `"—"`. The
/// report's units are written kB and MB, though they count 1024 and 2²⁰ bytes.
pub fn kb_or_mb(bytes: u64) -> String {
    match bytes {
        0 => "—".into(),
        b if b >= 1 << 20 => format!("{:.1} MB", b as f64 / f64::from(1 << 20)),
        b => format!("{:.0} kB", b as f64 / 1024.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Worked by hand: the digits kept at each decade, and the units' boundaries.
    #[test]
    fn figures_read_as_written_by_hand() {
        assert_eq!(sig(361.059), "361");
        assert_eq!(sig(20.46), "20.5");
        assert_eq!(sig(2.494), "2.49");
        assert_eq!(sig(0.6331), "0.633");
        assert_eq!(kb_or_mb(0), "—");
        // 625 664 B = 611 × 1024.
        assert_eq!(kb_or_mb(625_664), "611 kB");
        assert_eq!(kb_or_mb((1 << 20) - 1), "1024 kB");
        assert_eq!(kb_or_mb(1 << 20), "1.0 MB");
        // 71.5 × 2²⁰ = 74 973 184 B.
        assert_eq!(kb_or_mb(74_973_184), "71.5 MB");
    }
}
