//! Short turns of a phasor without a trigonometric call: `sin x` and `cos x` by as many Taylor
//! terms as rounding needs for `|x| <= 1` (the free vibration's sampling and Newton steps, the
//! compression phase's Newton steps), `sin_cos` beyond.

/// `1/((2n)(2n+1))` and `1/((2n-1)(2n))` for `n = 1..=11`: the ratios of successive Taylor
/// terms of `sin` and `cos`.
const SIN_RATIO: [f64; 11] = ratios(0.0);
const COS_RATIO: [f64; 11] = ratios(-1.0);

const fn ratios(offset: f64) -> [f64; 11] {
    let mut r = [0.0; 11];
    let mut n = 1;
    while n <= 11 {
        let k = 2.0 * n as f64;
        r[n - 1] = 1.0 / ((k + offset) * (k + 1.0 + offset));
        n += 1;
    }
    r
}

/// Taylor terms of `sin` and `cos` for rounding-level accuracy up to `|x| = x_max` (the first
/// neglected term is at most 1.6e-24, at `x_max = 1`), or 0 beyond 1.
pub fn series_terms(x_max: f64) -> usize {
    match x_max {
        x if x <= 1e-4 => 2,
        x if x <= 1e-3 => 3,
        x if x <= 1e-2 => 4,
        x if x <= 0.1 => 6,
        x if x <= 0.5 => 9,
        x if x <= 1.0 => 11,
        _ => 0,
    }
}

/// `(sin x, cos x)` by `terms` terms of their Taylor series ([`series_terms`]), or by
/// `sin_cos` when `terms` is 0.
pub fn small_sin_cos(x: f64, terms: usize) -> (f64, f64) {
    if terms == 0 {
        return x.sin_cos();
    }
    let x2 = x * x;
    let (mut s, mut c) = (1.0, 1.0);
    // sin x = x (1 - x^2/(2 3) (1 - x^2/(4 5) (1 - ...))), cos x = 1 - x^2/(1 2) (1 - x^2/(3 4) (...))
    for n in (0..terms).rev() {
        s = 1.0 - x2 * SIN_RATIO[n] * s;
        c = 1.0 - x2 * COS_RATIO[n] * c;
    }
    (x * s, c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_rotations_match_sin_cos() {
        let xs = (-1000..=1000).map(|i| i as f64 * 1e-3 * 1.0000001);
        for x in xs.chain([1e-4, 1e-3, 1e-2, 0.1, 0.5].iter().flat_map(|&x| [x, -x, 0.99 * x])) {
            let (s, c) = small_sin_cos(x, series_terms(x.abs()));
            assert!((s - x.sin()).abs() <= 2e-16 && (c - x.cos()).abs() <= 2e-16, "{x}");
        }
    }
}
