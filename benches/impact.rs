//! Criterion benchmarks (`make bench`): one impact at the paper's settings (and, on the modal
//! solver, the same impact oblique and spinning), a fine `hat` beam,
//! a 100-point Fig 5-style sweep, sweeps of 1000 points with their set-up as the `sweep` command
//! runs them (per-point cost: the reciprocal of the throughput), every experiment's table
//! without PNG encoding, and the PNG rendering alone.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use racket_impact::experiments;
use racket_impact::params::{LoadRule, Params};
use racket_impact::solve::{simulate, FdModel};

fn paper_impact(c: &mut Criterion) {
    let p = Params::paper();
    c.bench_function("fig4_impact_n39_node", |b| b.iter(|| simulate(std::hint::black_box(&p)).unwrap()));
    let model = FdModel::new(&p).unwrap();
    c.bench_function("fig4_impact_n39_node_prepared", |b| b.iter(|| model.run().unwrap()));
    // the explicit scheme at 0.9 of its stability limit (the default step also resolves the
    // contact oscillation to 2e-3 rad per step, about 8 times finer, for 1e-5 accuracy)
    let mut coarse = p;
    coarse.numerics.dt = Some(0.9 * model.dt_limit);
    let coarse = FdModel::new(&coarse).unwrap();
    c.bench_function("fig4_impact_n39_node_prepared_dt_0.9_limit", |b| b.iter(|| coarse.run().unwrap()));
    let mut modal = p;
    modal.numerics.solver = racket_impact::params::SolverKind::Modal;
    c.bench_function("fig4_impact_n39_node_modal", |b| b.iter(|| simulate(std::hint::black_box(&modal)).unwrap()));
    let prepared = racket_impact::solve::modal::ModalModel::new(&modal).unwrap();
    c.bench_function("fig4_impact_n39_node_modal_prepared", |b| b.iter(|| prepared.run().unwrap()));
    // the same impact arriving at 30 deg with 2000 rpm of topspin: the tangential law (the
    // default law with the calibrated kt) follows the normal force piece by piece
    let mut oblique = modal;
    oblique.oblique.angle_deg = 30.0;
    oblique.oblique.spin_rpm = 2000.0;
    let prepared_oblique = racket_impact::solve::modal::ModalModel::new(&oblique).unwrap();
    c.bench_function("fig4_impact_n39_node_modal_prepared_oblique_30deg", |b| {
        b.iter(|| prepared_oblique.run().unwrap())
    });
    // the same under the elastic law (the default before issue 29; its cost is the yardstick of
    // the default's)
    let mut elastic = oblique;
    elastic.oblique.tangential = racket_impact::params::TangentialLaw::Elastic;
    let prepared_elastic = racket_impact::solve::modal::ModalModel::new(&elastic).unwrap();
    c.bench_function("fig4_impact_n39_node_modal_prepared_oblique_30deg_elastic", |b| {
        b.iter(|| prepared_elastic.run().unwrap())
    });
    // the same with all four tangential mechanisms (`--tangential physical`)
    let mut physical = oblique;
    physical.oblique.tangential = racket_impact::params::TangentialLaw::Physical;
    let prepared_physical = racket_impact::solve::modal::ModalModel::new(&physical).unwrap();
    c.bench_function("fig4_impact_n39_node_modal_prepared_oblique_30deg_physical", |b| {
        b.iter(|| prepared_physical.run().unwrap())
    });
    let mut fine = p;
    fine.numerics.segments = 160;
    fine.numerics.load = LoadRule::Hat;
    let mut group = c.benchmark_group("fine");
    group.sample_size(10);
    group.bench_function("fig4_impact_n160_hat", |b| b.iter(|| simulate(std::hint::black_box(&fine)).unwrap()));
    group.finish();
}

fn sweeps(c: &mut Criterion) {
    let mut group = c.benchmark_group("sweep");
    group.sample_size(10);
    let params: Vec<Params> = (0..100)
        .map(|i| {
            let mut p = Params::paper();
            p.impact.r = 0.0;
            p.impact.x = 0.71 * i as f64 / 99.0;
            p
        })
        .collect();
    group.bench_function("fig5_style_100_positions_parallel", |b| {
        b.iter(|| experiments::sweep(std::hint::black_box(&params)).unwrap())
    });
    // the same with the modal solver (what `racket-impact sweep` uses by default)
    let modal: Vec<Params> = params
        .iter()
        .map(|p| {
            let mut p = *p;
            p.numerics.solver = racket_impact::params::SolverKind::Modal;
            p
        })
        .collect();
    group.bench_function("fig5_style_100_positions_parallel_modal", |b| {
        b.iter(|| experiments::sweep(std::hint::black_box(&modal)).unwrap())
    });
    let ctx = experiments::Context::paper();
    group.bench_function("all_experiment_tables_no_png", |b| {
        b.iter(|| experiments::registry().iter().map(|e| (e.run)(&ctx).unwrap().rows.len()).sum::<usize>())
    });
    group.finish();
}

fn png(c: &mut Criterion) {
    let dir = std::env::temp_dir().join(format!("racket-impact-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let ctx = experiments::Context::paper();
    let charts: Vec<_> =
        experiments::registry().iter().map(|e| (e.id, (e.chart)(&ctx, &(e.run)(&ctx).unwrap()))).collect();
    let mut group = c.benchmark_group("png");
    group.sample_size(10);
    group.bench_function("render_all_figures", |b| {
        b.iter(|| {
            for (id, chart) in &charts {
                racket_impact::render::plot::render_png(id, chart, &dir.join(format!("{id}.png"))).unwrap();
            }
        })
    });
    group.finish();
    let _ = std::fs::remove_dir_all(&dir);
}

/// Sweeps of 10 x 10 x 10 impacts through the code path of the `sweep` command (parameters of
/// each point from its flags, a model prepared per point, the CSV rows formatted; nothing
/// written): over the impact point and the string stiffness, where every point needs its own
/// set-up, and over the impact point and the ball speed, where the set-up of one point serves
/// the ten speeds. Criterion's throughput is points per second.
fn sweep_points(c: &mut Criterion) {
    use racket_impact::study::sweep::Sweep;
    let mut group = c.benchmark_group("sweep_per_point");
    group.sample_size(10);
    let cases: [(&str, [&str; 6]); 2] = [
        ("x_r_ks_10x10x10", ["--x", "0.02:0.30:10", "--r", "0:0.08:10", "--ks", "1e4:5e4:10"]),
        ("x_r_v1_10x10x10", ["--x", "0.02:0.30:10", "--r", "0:0.08:10", "--v1", "5:40:10"]),
    ];
    for (name, pairs) in cases {
        let pairs: Vec<String> = pairs.iter().map(|s| s.to_string()).collect();
        let sweep = Sweep::from_pairs(None, None, &pairs).unwrap();
        group.throughput(Throughput::Elements(sweep.len()));
        group.bench_function(name, |b| {
            b.iter(|| {
                let mut rows = 0;
                sweep
                    .run(
                        |chunk| {
                            rows += chunk.len();
                            Ok(())
                        },
                        |_| {},
                    )
                    .unwrap();
                rows
            })
        });
    }
    group.finish();
}

criterion_group!(benches, paper_impact, sweep_points, sweeps, png);
criterion_main!(benches);
