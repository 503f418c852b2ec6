//! Medians and quantiles: the one definition of each, over a slice, and a
//! [`Quantiles`] that takes values one at a time in bounded memory (a
//! batch's summary over a stream of any length).

use std::collections::BTreeMap;

/// The median of `values` (0 of none): the middle one, or the mean of the
/// middle two. Sorts them.
pub fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    match n {
        0 => 0.0,
        _ if n % 2 == 1 => values[n / 2],
        _ => 0.5 * (values[n / 2 - 1] + values[n / 2]),
    }
}

/// The `quantile` (0 to 1) of `values` (not empty) by the nearest rank.
pub fn quantile(values: &[f64], quantile: f64) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    nearest_rank(&sorted, quantile)
}

/// The `quantile` of `sorted` (not empty) by the nearest rank.
fn nearest_rank(sorted: &[f64], quantile: f64) -> f64 {
    sorted[(quantile * (sorted.len() - 1) as f64).round() as usize]
}

/// Values kept exactly, up to this many; past it, in buckets.
const EXACT: usize = 1 << 16;
/// A bucket's relative half-width: a quantile past [`EXACT`] values is
/// within 1e-4 of its value (0.1 mm in 1 m), far below any digit shown.
const ALPHA: f64 = 1e-4;
/// Sizes below this count as zero (a bucket's index would be unbounded).
const TINY: f64 = 1e-9;

/// Finite values whose medians and quantiles are asked for: exact for up to
/// 65,536 values, and past them within a relative 1e-4 in memory bounded by
/// the values' spread, not their number (logarithmic buckets, as DDSketch
/// keeps them: Masson, Rim & Lee, VLDB 2019; at most ~1.4e5 buckets a sign
/// between 1e-9 and 1e5). Mergeable: a batch's pieces each keep one.
#[derive(Clone, Debug, Default)]
pub struct Quantiles {
    exact: Vec<f64>,
    /// Past [`EXACT`]: counts by signed bucket (negative values' buckets
    /// below zero's), and of values near zero.
    buckets: BTreeMap<i64, u64>,
    zeros: u64,
    count: usize,
}

/// ln((1 + α)/(1 − α)): a bucket's width in ln |value|.
fn gamma_ln() -> f64 {
    ((1.0 + ALPHA) / (1.0 - ALPHA)).ln()
}

impl Quantiles {
    pub fn len(&self) -> usize {
        self.count
    }

    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// Takes `value` (a value that is not finite is left out).
    pub fn push(&mut self, value: f64) {
        if !value.is_finite() {
            return;
        }
        self.count += 1;
        if self.buckets.is_empty() && self.zeros == 0 && self.exact.len() < EXACT {
            self.exact.push(value);
            return;
        }
        for held in std::mem::take(&mut self.exact) {
            self.bucket(held);
        }
        self.bucket(value);
    }

    fn bucket(&mut self, value: f64) {
        if value.abs() < TINY {
            self.zeros += 1;
            return;
        }
        // Offset so that every size from TINY up has a positive index.
        let index = ((value.abs() / TINY).ln() / gamma_ln()).ceil() as i64 + 1;
        *self
            .buckets
            .entry(index * value.signum() as i64)
            .or_default() += 1;
    }

    /// A bucket's value: the one within α of every size in it, as DDSketch
    /// answers (2γ^m/(γ + 1) for sizes in (γ^(m−1), γ^m]).
    fn value_of(index: i64) -> f64 {
        let m = (index.abs() - 1) as f64;
        let gamma = gamma_ln().exp();
        (TINY * 2.0 * (gamma_ln() * m).exp() / (gamma + 1.0)).copysign(index as f64)
    }

    /// Adds another's values.
    pub fn merge(&mut self, other: &Quantiles) {
        if other.buckets.is_empty() && other.zeros == 0 {
            other.exact.iter().for_each(|v| self.push(*v));
            return;
        }
        for held in std::mem::take(&mut self.exact) {
            self.bucket(held);
        }
        other.exact.iter().for_each(|v| self.bucket(*v));
        for (index, n) in &other.buckets {
            *self.buckets.entry(*index).or_default() += n;
        }
        self.zeros += other.zeros;
        self.count += other.count;
    }

    /// The value of rank `rank` (0-based) in sorted order, past exact.
    fn ranked(&self, rank: usize) -> f64 {
        let (rank, mut seen, mut zeros_counted) = (rank as u64, 0, false);
        for (index, n) in &self.buckets {
            if *index > 0 && !zeros_counted {
                (seen, zeros_counted) = (seen + self.zeros, true);
                if seen > rank {
                    return 0.0;
                }
            }
            seen += n;
            if seen > rank {
                return Self::value_of(*index);
            }
        }
        0.0
    }

    /// The median (0 of none), as [`median`] gives it while exact.
    pub fn median(&self) -> f64 {
        if self.buckets.is_empty() && self.zeros == 0 {
            return median(&mut self.exact.clone());
        }
        let n = self.count;
        match n % 2 {
            1 => self.ranked(n / 2),
            _ => 0.5 * (self.ranked(n / 2 - 1) + self.ranked(n / 2)),
        }
    }

    /// The `quantile` (0 to 1) by the nearest rank, as [`quantile`] gives it
    /// while exact; 0 of none.
    pub fn quantile(&self, quantile: f64) -> f64 {
        if self.count == 0 {
            return 0.0;
        }
        if self.buckets.is_empty() && self.zeros == 0 {
            return self::quantile(&self.exact, quantile);
        }
        self.ranked((quantile * (self.count - 1) as f64).round() as usize)
    }

    /// The median of the values' sizes (|value|).
    pub fn median_abs(&self) -> f64 {
        let mut sizes = Quantiles::default();
        if self.buckets.is_empty() && self.zeros == 0 {
            self.exact.iter().for_each(|v| sizes.push(v.abs()));
        } else {
            sizes.count = self.count;
            sizes.zeros = self.zeros;
            for (index, n) in &self.buckets {
                *sizes.buckets.entry(index.abs()).or_default() += n;
            }
        }
        sizes.median()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn medians_and_quantiles_of_a_slice() {
        assert_eq!(median(&mut [3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&mut [4.0, 1.0, 2.0, 3.0]), 2.5);
        assert_eq!(median(&mut []), 0.0);
        let values: Vec<f64> = (0..101).map(f64::from).collect();
        assert_eq!(quantile(&values, 0.99), 99.0);
        assert_eq!(quantile(&values, 0.0), 0.0);
    }

    #[test]
    fn a_stream_is_exact_while_short_and_within_its_accuracy_past_it() {
        let mut uniform = crate::xorshift::uniform(7);
        let values: Vec<f64> = (0..300_000).map(|_| 200.0 * uniform() - 60.0).collect();
        let (mut short, mut long, mut halves) = (
            Quantiles::default(),
            Quantiles::default(),
            [Quantiles::default(), Quantiles::default()],
        );
        for (i, v) in values.iter().enumerate() {
            if i < 1000 {
                short.push(*v);
            }
            long.push(*v);
            halves[i % 2].push(*v);
        }
        assert_eq!(short.median(), median(&mut values[..1000].to_vec()));
        let abs: Vec<f64> = values.iter().map(|v| v.abs()).collect();
        let exact = (median(&mut values.clone()), median(&mut abs.clone()));
        let [mut a, b] = halves;
        a.merge(&b);
        for sketch in [&long, &a] {
            assert_eq!(sketch.len(), values.len());
            assert!(
                (sketch.median() - exact.0).abs() <= 2.0 * ALPHA * exact.0.abs(),
                "{}",
                sketch.median()
            );
            assert!((sketch.median_abs() - exact.1).abs() <= 2.0 * ALPHA * exact.1);
            let q = quantile(&values, 0.99);
            assert!((sketch.quantile(0.99) - q).abs() <= 2.0 * ALPHA * q.abs());
        }
        // Memory held by the spread, not the count.
        assert!(long.buckets.len() < 200_000 && long.exact.is_empty());
    }
}
