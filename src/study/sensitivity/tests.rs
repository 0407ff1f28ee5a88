//! The estimators on functions whose indices are known in closed form (Ishigami, Sobol' G),
//! and the quantiles on a one-input monotone model.

use std::f64::consts::PI;

use super::*;

fn analyse(samples: u64, dists: &[Dist], seed: u32, f: impl Fn(&[f64]) -> f64 + Sync) -> Summary {
    let design = Design::new(samples, dists.len(), seed).unwrap();
    let rows = run(&design, dists, |x| Ok(vec![f(x)]), |_| {}).unwrap();
    summarise_all(&design, &rows).remove(0)
}

/// Each estimate's bootstrap interval holds the analytic value.
fn assert_within(name: &str, got: &[Index], want: &[f64]) {
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(
            g.lo <= *w && *w <= g.hi,
            "{name} {i}: analytic {w} outside [{}, {}] (estimate {})",
            g.lo,
            g.hi,
            g.value
        );
        assert!(g.hi - g.lo < 0.1, "{name} {i}: interval [{}, {}] too wide to test anything", g.lo, g.hi);
    }
}

#[test]
fn ishigami_indices_are_within_their_intervals() {
    let (a, b) = (7.0, 0.1);
    let u = Dist::Uniform { lo: -PI, hi: PI };
    let s = analyse(4096, &[u; 3], 7, |x| x[0].sin() + a * x[1].sin().powi(2) + b * x[2].powi(4) * x[0].sin());
    // closed forms (Ishigami and Homma 1990; Sobol' and Levitan 1999)
    let pi4 = PI.powi(4);
    let v1 = 0.5 * (1.0 + b * pi4 / 5.0).powi(2);
    let v2 = a * a / 8.0;
    let v13 = b * b * PI.powi(8) * (1.0 / 18.0 - 1.0 / 50.0);
    let v = v1 + v2 + v13;
    assert_within("first", &s.first, &[v1 / v, v2 / v, 0.0]);
    assert_within("total", &s.total, &[(v1 + v13) / v, v2 / v, v13 / v]);
    assert!((s.mean - a / 2.0).abs() < 0.05, "mean {}", s.mean);
    assert!((s.sd - v.sqrt()).abs() < 0.05 * v.sqrt(), "sd {}", s.sd);
}

#[test]
fn sobol_g_indices_are_within_their_intervals() {
    let a = [0.0, 1.0, 4.5, 9.0, 99.0, 99.0];
    let g = |x: &[f64]| x.iter().zip(a).map(|(x, a)| ((4.0 * x - 2.0).abs() + a) / (1.0 + a)).product::<f64>();
    let s = analyse(16384, &[Dist::Uniform { lo: 0.0, hi: 1.0 }; 6], 11, g);
    let vi: Vec<f64> = a.iter().map(|a| 1.0 / (3.0 * (1.0 + a) * (1.0 + a))).collect();
    let v = vi.iter().map(|v| 1.0 + v).product::<f64>() - 1.0;
    let first: Vec<f64> = vi.iter().map(|x| x / v).collect();
    let total: Vec<f64> = vi.iter().map(|x| x * (v + 1.0) / (1.0 + x) / v).collect();
    assert_within("first", &s.first, &first);
    assert_within("total", &s.total, &total);
    assert!((s.mean - 1.0).abs() < 0.01, "mean {}", s.mean);
}

#[test]
fn one_monotone_input_has_the_models_quantiles_and_all_the_variance() {
    let d = Dist::Normal { mean: 1.0, sd: 0.5 };
    let s = analyse(1024, &[d], 3, |x| x[0].exp());
    // q of exp(X) is exp of the q of X; 2048 stratified points resolve a quantile to ~1/2048
    for (q, got) in [(0.05, s.q05), (0.5, s.q50), (0.95, s.q95)] {
        let want = d.quantile(q).exp();
        let slope =
            d.quantile(q).exp() * 0.5 / (0.4 * (-0.5 * crate::params::uncertainty::normal_quantile(q).powi(2)).exp());
        assert!((got - want).abs() < 2.0 * slope / 2048.0, "q{q}: {got} against {want}");
    }
    assert!(s.q05 < s.q50 && s.q50 < s.q95);
    assert!((s.first[0].value - 1.0).abs() < 0.02 && (s.total[0].value - 1.0).abs() < 0.02, "{:?}", s);
}

#[test]
fn a_seed_fixes_every_number_and_another_seed_changes_them() {
    let u = [Dist::Uniform { lo: 0.0, hi: 1.0 }; 2];
    let f = |x: &[f64]| x[0] + x[1] * x[1];
    assert_eq!(analyse(64, &u, 5, f), analyse(64, &u, 5, f));
    assert_ne!(analyse(64, &u, 5, f).mean, analyse(64, &u, 6, f).mean);
}

#[test]
fn the_mixed_blocks_take_one_column_from_b() {
    let design = Design::new(8, 3, 1).unwrap();
    assert_eq!(design.runs(), 8 * 5);
    let (a, b) = (design.point(2), design.point(8 + 2));
    for i in 0..3 {
        let ab = design.point((2 + i) * 8 + 2);
        for k in 0..3 {
            assert_eq!(ab[k], if k == i { b[k] } else { a[k] });
            assert!(ab[k] > 0.0 && ab[k] < 1.0);
        }
    }
}

#[test]
fn sample_counts_are_checked_before_anything_is_allocated() {
    let msg = Design::new(0, 2, 0).unwrap_err().to_string();
    assert_eq!(msg, "invalid samples = 0: must satisfy 1 <= samples <= 65536 (the length of the Sobol' sequence)");
    assert!(Design::new(MAX_SAMPLES + 1, 2, 0).is_err());
    assert!(Design::new(u64::MAX, 2, 0).is_err());
    assert!(Design::new(8, 0, 0).is_err() && Design::new(8, MAX_INPUTS + 1, 0).is_err());
}

#[test]
fn a_constant_output_has_no_indices() {
    let s = analyse(16, &[Dist::Uniform { lo: 0.0, hi: 1.0 }], 1, |_| 0.1 + 0.2);
    assert!(s.sd < 1e-15 && s.q05 == 0.1 + 0.2 && s.q95 == 0.1 + 0.2, "{s:?}");
    assert!(s.first[0].value.is_nan() && s.total[0].lo.is_nan());
}

#[test]
fn the_first_rows_of_a_larger_design_are_the_smaller_design() {
    let dists = [Dist::Uniform { lo: 0.0, hi: 1.0 }; 3];
    let f = |x: &[f64]| Ok(vec![x[0] * x[1] + x[2]]);
    let big = Design::new(32, 3, 9).unwrap();
    let small = Design::new(16, 3, 9).unwrap();
    let rows = run(&big, &dists, f, |_| {}).unwrap();
    let (d, sub) = prefix(&big, &rows, 16).unwrap();
    assert_eq!(d, small);
    assert_eq!(sub, run(&small, &dists, f, |_| {}).unwrap());
}
