//! What one output's runs of a [`Design`] say: its mean, standard deviation and quantiles over
//! the A and B blocks, and each input's first-order (Saltelli 2010) and total (Jansen 1999)
//! Sobol' index, with percentile bootstrap confidence intervals over the base rows.

use serde::Serialize;

use super::Design;

/// Bootstrap resamples of the base rows behind each confidence interval.
pub const BOOTSTRAP: usize = 500;
/// Coverage of the confidence intervals.
pub const CONFIDENCE: f64 = 0.95;

/// An index with its bootstrap confidence interval (all NaN for an output that does not vary).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Index {
    /// The estimate from all base rows.
    pub value: f64,
    /// Lower end of the [`CONFIDENCE`] interval.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
}

/// One output under the input uncertainty.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Summary {
    /// Mean over the A and B runs (2N independent points).
    pub mean: f64,
    /// Standard deviation over them (n - 1 in the denominator).
    pub sd: f64,
    /// 5 % quantile (linear interpolation between order statistics).
    pub q05: f64,
    /// Median.
    pub q50: f64,
    /// 95 % quantile.
    pub q95: f64,
    /// First-order index of each input, in the design's order.
    pub first: Vec<Index>,
    /// Total index of each input.
    pub total: Vec<Index>,
}

/// The `q` quantile of sorted values (linear between order statistics, "type 7").
pub fn quantile_sorted(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let h = q * (sorted.len() - 1) as f64;
    let (i, w) = (h.floor() as usize, h - h.floor());
    let next = sorted[(i + 1).min(sorted.len() - 1)];
    sorted[i] + w * (next - sorted[i])
}

/// A small deterministic generator for the bootstrap (SplitMix64).
struct SplitMix(u64);

impl SplitMix {
    fn below(&mut self, n: usize) -> usize {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        ((u128::from(z) * n as u128) >> 64) as usize
    }
}

/// First-order and total indices from the base rows `rows` (repeats allowed):
/// `S_i = mean((f_B - m) (f_ABi - f_A)) / V` (Saltelli 2010, with the output centred on the
/// mean m of the A and B values, as SALib does: the same expectation, far less variance for
/// an output whose mean is large against its spread) and `ST_i = mean((f_A - f_ABi)^2) / (2 V)`
/// (Jansen 1999), with `V` the variance of the A and B values of those rows.
fn indices(runs: &[f64], design: &Design, rows: &[usize]) -> (Vec<f64>, Vec<f64>) {
    let n = design.samples();
    let (a, b) = (&runs[..n], &runs[n..2 * n]);
    let m = rows.len() as f64;
    let mean = rows.iter().map(|&j| a[j] + b[j]).sum::<f64>() / (2.0 * m);
    let var = rows.iter().map(|&j| (a[j] - mean).powi(2) + (b[j] - mean).powi(2)).sum::<f64>() / (2.0 * m - 1.0);
    // an output that does not vary has no indices (its variance is rounding noise, if any)
    let first_value = a[rows[0]];
    let constant = rows.iter().all(|&j| a[j] == first_value && b[j] == first_value);
    let undefined = constant || !(var > 0.0 && var.is_finite());
    (0..design.inputs())
        .map(|i| {
            if undefined {
                return (f64::NAN, f64::NAN);
            }
            let ab = &runs[(2 + i) * n..(3 + i) * n];
            let first = rows.iter().map(|&j| (b[j] - mean) * (ab[j] - a[j])).sum::<f64>() / m / var;
            let total = rows.iter().map(|&j| (a[j] - ab[j]).powi(2)).sum::<f64>() / (2.0 * m) / var;
            (first, total)
        })
        .unzip()
}

/// Summarise one output from its value at every run of `design` (in run order); the bootstrap
/// draws from `seed`.
pub fn summarise(design: &Design, runs: &[f64], seed: u64) -> Summary {
    assert_eq!(runs.len(), design.runs(), "one value per run");
    let n = design.samples();
    let mut ab: Vec<f64> = runs[..2 * n].to_vec();
    let mean = ab.iter().sum::<f64>() / ab.len() as f64;
    let sd = if ab.len() > 1 {
        (ab.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (ab.len() - 1) as f64).sqrt()
    } else {
        0.0
    };
    ab.sort_by(f64::total_cmp);
    let all: Vec<usize> = (0..n).collect();
    let (first, total) = indices(runs, design, &all);
    let mut rng = SplitMix(seed ^ 0x5eed_b007_5742_a11e);
    let d = design.inputs();
    let mut boot_first = vec![Vec::with_capacity(BOOTSTRAP); d];
    let mut boot_total = vec![Vec::with_capacity(BOOTSTRAP); d];
    let mut rows = vec![0; n];
    for _ in 0..BOOTSTRAP {
        rows.iter_mut().for_each(|r| *r = rng.below(n));
        let (f, t) = indices(runs, design, &rows);
        for i in 0..d {
            boot_first[i].push(f[i]);
            boot_total[i].push(t[i]);
        }
    }
    let tail = (1.0 - CONFIDENCE) / 2.0;
    let with_ci = |value: f64, mut boot: Vec<f64>| {
        boot.sort_by(f64::total_cmp);
        Index { value, lo: quantile_sorted(&boot, tail), hi: quantile_sorted(&boot, 1.0 - tail) }
    };
    Summary {
        mean,
        sd,
        q05: quantile_sorted(&ab, 0.05),
        q50: quantile_sorted(&ab, 0.50),
        q95: quantile_sorted(&ab, 0.95),
        first: first.into_iter().zip(boot_first).map(|(v, b)| with_ci(v, b)).collect(),
        total: total.into_iter().zip(boot_total).map(|(v, b)| with_ci(v, b)).collect(),
    }
}
