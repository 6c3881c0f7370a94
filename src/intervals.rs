//! Medians with their 95 % intervals, and when a ratio is settled: the bench times a
//! view's cases in interleaved rounds, each
//! round giving every case one figure (the median of its frames), and a case's ratio to
//! another is the median over the rounds of the ratio of their figures in the same
//! round — paired, so that a slow spell of the machine that slows both sides of a round
//! leaves the ratio alone. Its 95 % interval is a percentile bootstrap over the rounds
//! (resampling them with replacement, the median taken again each time); a ratio is
//! settled once that interval lies within ±[`TARGET`] of its value. The run keeps timing
//! the cases whose ratios are not settled, with the cases they are divided by, until
//! they are or until each has had its time ([`crate::effort::Effort`]'s cap), and says
//! which were not.

use serde::Serialize;

/// How close a settled ratio's 95 % interval lies to its value: ±5 %.
pub const TARGET: f64 = 0.05;

/// Bootstrap resamples an interval is drawn from.
const RESAMPLES: usize = 2000;

/// A figure with its 95 % interval, from the rounds that measured it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Interval {
    /// The median over the rounds.
    pub value: f64,
    pub low: f64,
    pub high: f64,
    /// Rounds it was measured in.
    pub rounds: usize,
    /// Whether `low` and `high` lie within ±[`TARGET`] of `value`.
    pub settled: bool,
}

impl Interval {
    /// `2.67 (2.60–2.75)`, with `*` after it where it is not settled; `decimals` for
    /// all three figures.
    pub fn cell(&self, decimals: usize) -> String {
        format!(
            "{:.decimals$} ({:.decimals$}–{:.decimals$}){}",
            self.value,
            self.low,
            self.high,
            if self.settled { "" } else { "*" }
        )
    }

    /// The interval's half-width over its value, the larger side: 0.03 for ±3 %.
    pub fn spread(&self) -> f64 {
        ((self.high - self.value).max(self.value - self.low)) / self.value.abs()
    }
}

/// The median of `values` with its bootstrap interval; None for no values or for any
/// value that is not finite (a figure the code cannot vouch for is not summarized).
pub fn median_interval(values: &[f64]) -> Option<Interval> {
    if values.is_empty() || !values.iter().all(|v| v.is_finite()) {
        return None;
    }
    let value = median(&mut values.to_vec());
    let mut random = SplitMix(values.len() as u64 ^ value.to_bits());
    let mut medians = Vec::with_capacity(RESAMPLES);
    let mut sample = vec![0.0; values.len()];
    for _ in 0..RESAMPLES {
        for slot in &mut sample {
            *slot = values[random.below(values.len())];
        }
        medians.push(median(&mut sample));
    }
    medians.sort_by(f64::total_cmp);
    let low = medians[(0.025 * RESAMPLES as f64) as usize];
    let high = medians[((0.975 * RESAMPLES as f64) as usize).min(RESAMPLES - 1)];
    let settled = value > 0.0 && low >= value * (1.0 - TARGET) && high <= value * (1.0 + TARGET);
    Some(Interval {
        value,
        low,
        high,
        rounds: values.len(),
        settled,
    })
}

/// The ratio of `numerator` to `denominator` per round, over the rounds where both
/// were measured (index by index), with its interval.
pub fn paired_ratio(numerator: &[Option<f64>], denominator: &[Option<f64>]) -> Option<Interval> {
    let ratios: Vec<f64> = numerator
        .iter()
        .zip(denominator)
        .filter_map(|(n, d)| Some((*n)? / (*d)?))
        .collect();
    median_interval(&ratios)
}

/// The middle value (the mean of the two middle ones for an even count). Reorders
/// `values`.
fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n % 2 == 1 {
        values[n / 2]
    } else {
        0.5 * (values[n / 2 - 1] + values[n / 2])
    }
}

/// A small deterministic generator (SplitMix64), so that a report's intervals are the
/// same for the same rounds.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identical_rounds_settle_at_their_value() {
        let i = median_interval(&[2.0; 5]).unwrap();
        assert_eq!((i.value, i.low, i.high, i.rounds), (2.0, 2.0, 2.0, 5));
        assert!(i.settled);
    }

    #[test]
    fn scattered_rounds_do_not_settle() {
        // Hand-worked: rounds 1.0, 1.5, 2.0 — the median 1.5; a resample of three
        // draws can have a median of 1.0 or 2.0 (each with probability 7/27), so the
        // 2.5 % and 97.5 % points are the extremes, ±33 % of the value.
        let i = median_interval(&[1.0, 2.0, 1.5]).unwrap();
        assert_eq!(i.value, 1.5);
        assert_eq!((i.low, i.high), (1.0, 2.0));
        assert!(!i.settled);
        assert!((i.spread() - 1.0 / 3.0).abs() < 1e-12);
    }

    #[test]
    fn many_close_rounds_settle_and_an_outlier_does_not_move_the_median() {
        let mut rounds: Vec<f64> = (0..15).map(|k| 3.0 + 0.01 * f64::from(k % 5)).collect();
        rounds.push(9.0);
        let i = median_interval(&rounds).unwrap();
        assert!((3.0..=3.04).contains(&i.value), "{i:?}");
        assert!(i.settled, "{i:?}");
    }

    #[test]
    fn a_ratio_pairs_rounds_and_skips_those_missing_a_side() {
        // A machine twice as slow in round 2 slows both sides: the ratio stays 2.
        let case = [Some(2.0), Some(4.0), None, Some(2.0)];
        let base = [Some(1.0), Some(2.0), Some(7.0), Some(1.0)];
        let r = paired_ratio(&case, &base).unwrap();
        assert_eq!((r.value, r.rounds), (2.0, 3));
        assert!(r.settled);
    }

    #[test]
    fn nothing_finite_is_no_interval() {
        assert_eq!(median_interval(&[]), None);
        assert_eq!(median_interval(&[1.0, f64::NAN]), None);
        assert_eq!(paired_ratio(&[Some(1.0)], &[None]), None);
        assert_eq!(paired_ratio(&[Some(1.0)], &[Some(0.0)]), None);
    }
}
