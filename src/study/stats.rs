//! Statistics of compared values: Spearman's rank correlation and its p-value (Student's t from
//! statrs), and the root-mean-square of errors.

use statrs::distribution::{ContinuousCDF, StudentsT};

/// Spearman's rank correlation of `a` and `b` (ties take their mean rank); 0 where either is
/// constant.
pub fn spearman(a: &[f64], b: &[f64]) -> f64 {
    let ranks = |v: &[f64]| -> Vec<f64> {
        (0..v.len())
            .map(|i| {
                let below = v.iter().filter(|&&x| x < v[i]).count() as f64;
                let equal = v.iter().filter(|&&x| x == v[i]).count() as f64;
                below + (equal + 1.0) / 2.0
            })
            .collect()
    };
    let (ra, rb) = (ranks(a), ranks(b));
    let n = a.len() as f64;
    let mean = (n + 1.0) / 2.0;
    let cov: f64 = ra.iter().zip(&rb).map(|(x, y)| (x - mean) * (y - mean)).sum();
    let var = |r: &[f64]| r.iter().map(|x| (x - mean).powi(2)).sum::<f64>();
    let d = (var(&ra) * var(&rb)).sqrt();
    if d == 0.0 {
        0.0
    } else {
        cov / d
    }
}

/// The two-sided p-value of a rank correlation `rho` over `n` points under the hypothesis of
/// no correlation, through Student's t with `n - 2` degrees of freedom,
/// `t = rho sqrt((n - 2) / (1 - rho^2))` (the usual large-sample form; with ties and a dozen
/// points it is an approximation). NaN below 3 points or for a non-finite `rho`.
pub fn rank_correlation_p(rho: f64, n: usize) -> f64 {
    if n < 3 || !rho.is_finite() {
        return f64::NAN;
    }
    if rho.abs() >= 1.0 {
        return 0.0;
    }
    let nu = (n - 2) as f64;
    let t = rho.abs() * (nu / (1.0 - rho * rho)).sqrt();
    match StudentsT::new(0.0, 1.0, nu) {
        Ok(dist) => (2.0 * dist.sf(t)).clamp(0.0, 1.0),
        Err(_) => f64::NAN,
    }
}

/// The root-mean-square of the finite values of `errors` (NaN if none is finite).
pub fn rms(errors: impl IntoIterator<Item = f64>) -> f64 {
    let e: Vec<f64> = errors.into_iter().filter(|e| e.is_finite()).collect();
    if e.is_empty() {
        f64::NAN
    } else {
        (e.iter().map(|e| e * e).sum::<f64>() / e.len() as f64).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spearman_of_an_order_and_its_reverse() {
        let a = [1.0, 2.0, 3.0, 4.0];
        assert!((spearman(&a, &[10.0, 20.0, 30.0, 40.0]) - 1.0).abs() < 1e-15);
        assert!((spearman(&a, &[4.0, 3.0, 2.0, 1.0]) + 1.0).abs() < 1e-15);
        assert_eq!(spearman(&a, &[5.0; 4]), 0.0);
    }

    /// The p-value against values of Student's t (two-sided): df 12, t = 2.179 at p = 0.05 and
    /// 3.055 at 0.01; df 1 (Cauchy), t = 1 at 0.5; df 3, t = 3.182 at 0.05.
    #[test]
    fn rank_correlation_p_matches_the_t_table() {
        let rho_of = |t: f64, n: usize| t / (t * t + (n - 2) as f64).sqrt();
        assert!((rank_correlation_p(rho_of(2.179, 14), 14) - 0.05).abs() < 2e-4);
        assert!((rank_correlation_p(rho_of(3.055, 14), 14) - 0.01).abs() < 1e-4);
        assert!((rank_correlation_p(rho_of(1.0, 3), 3) - 0.5).abs() < 1e-12);
        assert!((rank_correlation_p(rho_of(3.182, 5), 5) - 0.05).abs() < 2e-4);
        assert!((rank_correlation_p(0.0, 14) - 1.0).abs() < 1e-12);
        assert_eq!(rank_correlation_p(1.0, 14), 0.0);
        assert!(rank_correlation_p(0.5, 2).is_nan());
    }

    #[test]
    fn rms_leaves_out_what_is_undefined() {
        assert_eq!(rms([3.0, f64::NAN, -4.0, 0.0, 0.0, 0.0, 0.0, 0.0]), (25.0f64 / 7.0).sqrt());
        assert!(rms([f64::NAN]).is_nan());
    }
}
