//! The work estimates held against the work measured (issue 48, item 4): random runs of every
//! command whose work is estimated (`sweep`, `map`, `uncertainty`), over both solvers, both
//! grips, stiff and soft contacts, light and heavy rackets, coarse and fine beams, long and
//! short series of impacts. Each run's estimate (CPU seconds, `Work::estimate`) is taken from its
//! request before it runs, then the run is timed by the CPU its threads use (Linux: every
//! thread's `/proc/self/task/*/schedstat`), so a busy machine does not skew the ratio.
//!
//! `cargo run --release -p racket-impact-bench --bin estimates -- RUNS SEED [MAX_CPU_S]` prints
//! one CSV line per run (`command,estimate_cpu_s,measured_cpu_s,ratio,args`) and then the ratio's
//! spread, over every run and over the runs of at least 0.1 CPU-s; runs estimated above
//! `MAX_CPU_S` (default 20) are drawn again, so the study stays short. `USUAL=1` leaves out very
//! stiff contacts and free rackets above 50 kg. `estimates impacts N SEED` measures single
//! impacts instead (the data the constants of `study::work` were fitted to).
//!
//! Measured on the development machine (2 cores shared with other work), measured / estimated
//! CPU (an upper bound within a factor of 3 is a ratio in [1/3, 1]):
//!
//! | set (runs, seed) | runs | min | median | 99 % | max | in [1/3, 1] | above 1 |
//! |---|---|---|---|---|---|---|---|
//! | before (150, 7), every run | 150 | 0.14 | 1.50 | 13.5 | 16.2 | 18.0 % | 112 |
//! | usual (`USUAL=1`, 200, 14), every run | 200 | 0.17 | 0.51 | 0.97 | 1.25 | 91.0 % | 2 |
//! | usual, runs of >= 0.1 CPU-s | 88 | 0.20 | 0.51 | 0.71 | 0.73 | 98.9 % | 0 |
//! | wide (200, 13), every run | 200 | 0.13 | 0.49 | 1.07 | 1.45 | 88.5 % | 3 |
//! | wide, runs of >= 0.1 CPU-s | 108 | 0.13 | 0.49 | 1.10 | 1.45 | 88.9 % | 3 |
//!
//! The wide set adds very stiff contacts (k1 up to 1e9, ks up to 1e10 N/m) and free rackets up
//! to 1000 kg: there the search after an impact samples its whole window or a few narrow ones
//! from one point of the face to the next, which no count before the run tells (the estimate
//! counts the whole where the impact is under 5 % of the fundamental period, 0.13 to 0.3 of
//! the time taken on heavy rackets); the runs above 1 are oblique balls on very stiff contacts.
//! Below 0.1 CPU-s the ratio spreads more (a run's set-up against a clock of 4 ms ticks).
//!
//! The random numbers are SplitMix64, a few lines here rather than a dependency of the
//! benchmarks' package for one loop.

use racket_impact::command::map::Map;
use racket_impact::command::sweep::SweepRequest;
use racket_impact::command::uncertainty::Uncertainty;
use racket_impact::command::{execute, Control, Given, Request};
use racket_impact::intake::Sources;
use racket_impact::params::Overrides;

/// SplitMix64.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn log(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + self.unit() * (hi.ln() - lo.ln())).exp()
    }
    fn int(&mut self, lo: u64, hi: u64) -> u64 {
        lo + self.next() % (hi - lo + 1)
    }
    fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }
}

/// The CPU time every thread of this process has used, s.
fn cpu_s() -> f64 {
    racket_impact::study::work::process_cpu_s().expect("the CPU time of the threads (Linux /proc)")
}

/// Whether the runs are drawn from the usual set only (`USUAL=1`): no very stiff contact and no
/// free racket above 50 kg, where the search after an impact may or may not sample its whole
/// window (its estimate then counts the whole, and may be several times the time taken).
fn usual() -> bool {
    std::env::var("USUAL").is_ok_and(|v| v == "1")
}

/// A run's parameters at random: the solver, the grip, the contact, the racket and the beam.
fn params(rng: &mut Rng, map: bool) -> Vec<(&'static str, String)> {
    let mut out = Vec::new();
    let hand = rng.chance(0.35);
    if hand {
        out.push(("grip", "hand".to_string()));
    }
    if !map {
        // (a map chooses its own solver)
        let modal = !hand && rng.chance(0.5);
        out.push(("solver", if modal { "modal" } else { "fd" }.to_string()));
    }
    // stiff and soft contacts (now and then a very stiff one: an impact of microseconds), light
    // and heavy rackets, coarse and fine beams
    if !usual() && rng.chance(0.1) {
        out.push(("ks", format!("{:.4e}", rng.log(1e6, 1e10))));
        out.push(("k1", format!("{:.4e}", rng.log(1e6, 1e9))));
    } else {
        out.push(("ks", format!("{:.4e}", rng.log(3e3, 1e6))));
        out.push(("k1", format!("{:.4e}", rng.log(1e4, 3e5))));
    }
    if rng.chance(0.3) {
        out.push(("mass", format!("{:.4e}", rng.log(0.2, if hand || usual() { 50.0 } else { 1e3 }))));
    }
    if rng.chance(0.3) {
        out.push(("ei", format!("{:.4e}", rng.log(20.0, 2e3))));
    }
    if rng.chance(0.4) {
        out.push(("segments", rng.int(10, 120).to_string()));
    }
    if rng.chance(0.2) {
        out.push(("angle-deg", format!("{:.1}", rng.unit() * 60.0)));
    }
    if rng.chance(0.15) && !map {
        out.push(("strings", "stiffening".to_string()));
    }
    out
}

fn sources(command: &'static str, pairs: &[(&'static str, String)]) -> Sources {
    let mut flags = Overrides::default();
    for (k, v) in pairs {
        flags.set(k, v).expect("a valid value");
    }
    Sources { flags, command, ..Sources::default() }
}

/// A run, measured: the CPU seconds it took (NaN where it failed).
type Run = Box<dyn FnOnce(&Control) -> f64>;

/// One random run: its command, its arguments in words, the run and its request's estimate.
fn draw(rng: &mut Rng) -> Option<(String, String, Run, f64)> {
    let threads = racket_impact::command::threads();
    match rng.int(0, 2) {
        0 => {
            let fixed = params(rng, false);
            let n = rng.log(1.0, 3000.0).round() as u64;
            let mut pairs: Vec<String> = fixed.iter().flat_map(|(k, v)| [format!("--{k}"), v.clone()]).collect();
            pairs.extend(["--x".to_string(), format!("0.05:0.25:{n}")]);
            let mut given = Given::new(racket_impact::command::sweep::OPTIONS);
            given.set("long", "true").ok()?;
            let request = SweepRequest::new(None, None, &pairs, &given).ok()?;
            let streaming = request.stream(|c| c.len(), |_: &[usize]| Ok(()));
            let estimate = streaming.work(threads)?.estimate.cpu_s;
            let run: Run = Box::new(move |ctl| timed(|| execute(streaming, ctl).is_ok()));
            Some(("sweep".into(), pairs.join(" "), run, estimate))
        }
        1 => {
            let fixed = params(rng, true);
            let (nx, nr) = (rng.int(2, 41), rng.int(2, 31));
            let mut given = Given::new(racket_impact::command::map::OPTIONS);
            given.set("nx", nx.to_string()).ok()?;
            given.set("nr", nr.to_string()).ok()?;
            given.set("long", "true").ok()?;
            if fixed.iter().any(|(k, _)| *k == "angle-deg") && rng.chance(0.5) {
                given.set("quantity", "spin").ok()?;
            }
            let request = Map::new(&sources("map", &fixed), &given).ok()?;
            let estimate = request.work(threads)?.estimate.cpu_s;
            let words = format!("--nx {nx} --nr {nr} {}", words(&fixed));
            let run: Run = Box::new(move |ctl| timed(|| execute(request, ctl).is_ok()));
            Some(("map".into(), words, run, estimate))
        }
        _ => {
            let fixed = params(rng, false);
            let vary = ["ks", "mb", "v1", "k1"];
            let d = rng.int(1, 3) as usize;
            let samples = rng.log(1.0, 200.0).round() as u64;
            let mut given = Given::new(racket_impact::command::uncertainty::OPTIONS);
            let mut varied = Vec::new();
            for key in vary.iter().take(d) {
                if fixed.iter().any(|(k, _)| k == key) {
                    continue;
                }
                given.set("vary", *key).ok()?;
                varied.push(*key);
            }
            given.set("samples", samples.to_string()).ok()?;
            given.set("long", "true").ok()?;
            let request = Uncertainty::new(&sources("uncertainty", &fixed), &given).ok()?;
            let estimate = request.work(threads)?.estimate.cpu_s;
            let words = format!("--vary {} --samples {samples} {}", varied.join(","), words(&fixed));
            let run: Run = Box::new(move |ctl| timed(|| execute(request, ctl).is_ok()));
            Some(("uncertainty".into(), words, run, estimate))
        }
    }
}

fn words(pairs: &[(&'static str, String)]) -> String {
    pairs.iter().map(|(k, v)| format!("--{k} {v}")).collect::<Vec<_>>().join(" ")
}

/// The CPU seconds `f` takes (NaN where it fails: such a run is not counted).
fn timed(f: impl FnOnce() -> bool) -> f64 {
    let start = cpu_s();
    let ok = f();
    let spent = cpu_s() - start;
    if ok {
        spent
    } else {
        f64::NAN
    }
}

/// One impact at random, measured cold (its racket's modes and set-up built) and warm (from the
/// caches): its features, the two CPU times and the estimate, one CSV line.
fn impact_line(rng: &mut Rng) -> Option<String> {
    use racket_impact::solve::fd::FdModel;
    use racket_impact::solve::modal::ModalModel;
    let mut fixed = params(rng, false);
    fixed.push(("x", format!("{:.4}", 0.05 + 0.2 * rng.unit())));

    let p = sources("simulate", &fixed).params().ok()?;
    let w = racket_impact::study::work::impact(&p)?;
    let (mut contact, mut held, mut dt, mut nodes, mut modes, mut samples) = (0.0, 0.0, 0.0, 0, 0, 0.0);
    if let Ok(m) = FdModel::new(&p) {
        (contact, held) = m.expected_steps();
        dt = m.dt;
        nodes = m.beam().nodes();
    }
    let mut mp = p;
    mp.numerics.solver = racket_impact::params::SolverKind::Modal;
    if let Ok(m) = ModalModel::new(&mp) {
        modes = m.retained_modes();
        samples = m.free_vibration_work();
    }
    let prepared = racket_impact::solve::prepared::PreparedImpact::new(&p).ok()?;
    let tau_f1 =
        prepared.time_limit_s / racket_impact::solve::prepared::IMPACT_TIME_LIMIT_HALF_PERIODS * prepared.f1_hz;
    let t0 = cpu_s();
    let r = racket_impact::solve::simulate(&p).ok()?;
    let t1 = cpu_s();
    // (the clock ticks in milliseconds: repeated until it has run 50 ms)
    let mut reps = 0;
    let mut t2 = t1;
    while t2 - t1 < 0.05 {
        racket_impact::solve::simulate(&p).ok()?;
        reps += 1;
        t2 = cpu_s();
    }
    let t2 = t1 + (t2 - t1) / reps as f64;
    Some(format!(
        "{:?},{:?},{},{:.4e},{:.4e},{:.4e},{:.4e},{},{},{:.4e},{:.4e},{:.4e},{:.4e},{:.4e},\"{}\"",
        p.numerics.solver,
        p.variants.grip,
        fixed.iter().any(|(k, _)| *k == "strings"),
        dt,
        contact,
        held,
        r.tau_s / dt.max(1e-300),
        nodes,
        modes,
        samples,
        t1 - t0,
        t2 - t1,
        w.cpu_s,
        tau_f1,
        words(&fixed)
    ))
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.get(1).map(String::as_str) == Some("impacts") {
        let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(100);
        let mut rng = Rng(args.get(3).and_then(|s| s.parse().ok()).unwrap_or(1));
        println!("solver,grip,stiffening,dt,contact_steps,held_steps,tau_steps,nodes,modes,mode_samples,cold_s,warm_s,estimate_s,tau_f1,args");
        let mut k = 0;
        while k < n {
            if let Some(line) = impact_line(&mut rng) {
                println!("{line}");
                k += 1;
            }
        }
        return;
    }
    let runs: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(100);
    let seed: u64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(1);
    let max_cpu_s: f64 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(20.0);
    let mut rng = Rng(seed);
    let mut ratios = Vec::new();
    println!("command,estimate_cpu_s,measured_cpu_s,ratio,args");
    while ratios.len() < runs {
        let Some((command, words, run, estimate)) = draw(&mut rng) else { continue };
        if !(estimate > 0.0 && estimate <= max_cpu_s) {
            continue;
        }
        let measured = run(&Control::new());
        if !measured.is_finite() {
            continue;
        }
        let ratio = measured / estimate;
        let long = estimate >= FLOOR_CPU_S || measured >= FLOOR_CPU_S;
        println!("{command},{estimate:.4e},{measured:.4e},{ratio:.4},\"{words}\"");
        ratios.push((long, ratio));
    }
    summary("every run", &mut ratios.iter().map(|(_, r)| *r).collect::<Vec<_>>());
    let timed: Vec<f64> = ratios.iter().filter(|(long, _)| *long).map(|(_, r)| *r).collect();
    summary(&format!("runs of at least {FLOOR_CPU_S} CPU-s (estimated or measured)"), &mut timed.clone());
}

/// Runs shorter than this (CPU seconds, both estimated and measured) are told apart: the clock
/// ticks in milliseconds and nobody waits for them.
const FLOOR_CPU_S: f64 = 0.1;

/// The spread of `ratios` on stderr, and how many lie in [1/3, 1] (the estimate an upper bound
/// within a factor of 3).
fn summary(what: &str, ratios: &mut [f64]) {
    if ratios.is_empty() {
        return;
    }
    ratios.sort_by(f64::total_cmp);
    let q = |p: f64| ratios[((ratios.len() - 1) as f64 * p).round() as usize];
    let held = ratios.iter().filter(|r| (1.0 / 3.0..=1.0).contains(*r)).count();
    let over = ratios.iter().filter(|r| **r > 1.0).count();
    eprintln!(
        "{what}: {} runs, measured / estimated CPU min {:.3}, 1 % {:.3}, median {:.3}, 99 % {:.3}, max {:.3}; \
         within [1/3, 1] (an upper bound within a factor 3): {} ({:.1} %); above the estimate: {over}",
        ratios.len(),
        q(0.0),
        q(0.01),
        q(0.5),
        q(0.99),
        q(1.0),
        held,
        100.0 * held as f64 / ratios.len() as f64
    );
}
