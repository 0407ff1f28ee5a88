use racket_impact::*;
fn main() {
    let mut p = Params::paper();
    let args: Vec<String> = std::env::args().collect();
    if args.len() > 1 { p.numerics.segments = args[1].parse().unwrap(); }
    if args.len() > 2 { p.numerics.load = args[2].parse().unwrap(); }
    let m = Model::new(&p).unwrap();
    println!("dt {} limit {} f1 {}", m.dt, m.dt_limit, m.f1_hz);
    let t = std::time::Instant::now();
    let r = m.run().unwrap();
    println!("{:?} {:?}", r, t.elapsed());
    for frac in [1.0, 0.5, 0.25] {
        let mut q = p; q.numerics.dt = Some(m.dt * frac);
        let r = simulate(&q).unwrap();
        println!("dt*{frac}: e_a {:.10} tau {:.10e} theta {:.8} Eerr {:.2e} Perr {:.2e} fvib {:.6} peak {:.6}", r.e_a, r.tau_s, r.theta_end_deg, r.energy_error, r.momentum_error, r.f_vib, r.f_vib_peak_pe);
    }
    let b = model::beam::Beam::new(&p.racket, 39);
    let modes = b.modes();
    println!("f1 {} f2 {} nodes {:?}", modes.frequency_hz(1), modes.frequency_hz(2), modes.node_positions(1, &b.x));
    let c = model::reduced::concrete_drop(&p.ball, params::drop_speed(2.54));
    println!("{c:?}");
    for ks in [2e4, 4e4] { println!("{:?}", model::reduced::clamped_drop(&p.ball, &params::Strings{ks}, params::drop_speed(2.54))); }
}
