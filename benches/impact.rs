//! Criterion benchmarks: one impact at the paper's settings, a fine `hat` beam, and a sweep.

use criterion::{criterion_group, criterion_main, Criterion};
use racket_impact::params::{LoadRule, Params};
use racket_impact::solver::{simulate, Model};

fn paper_impact(c: &mut Criterion) {
    let p = Params::paper();
    c.bench_function("fig4_impact_n39_node", |b| b.iter(|| simulate(std::hint::black_box(&p)).unwrap()));
    let model = Model::new(&p).unwrap();
    c.bench_function("fig4_impact_n39_node_prepared", |b| b.iter(|| model.run().unwrap()));
    let mut fine = p;
    fine.numerics.segments = 160;
    fine.numerics.load = LoadRule::Hat;
    c.bench_function("fig4_impact_n160_hat", |b| b.iter(|| simulate(std::hint::black_box(&fine)).unwrap()));
}

fn sweep(c: &mut Criterion) {
    let mut group = c.benchmark_group("sweep");
    group.sample_size(10);
    group.bench_function("fig5_style_40_positions", |b| {
        b.iter(|| {
            (0..=39)
                .map(|i| {
                    let mut p = Params::paper();
                    p.impact.r = 0.0;
                    p.impact.x = 0.71 * i as f64 / 39.0;
                    simulate(&p).unwrap().e_a
                })
                .sum::<f64>()
        })
    });
    group.finish();
}

criterion_group!(benches, paper_impact, sweep);
criterion_main!(benches);
