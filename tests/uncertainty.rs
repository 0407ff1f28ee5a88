//! The `uncertainty` command end to end: its JSON shape, determinism for a seed, `--out`
//! written atomically, `--claims`, and every bad spec refused in one line with exit 2 and no
//! file written.

mod common;

use common::Scratch;
use std::process::Output;

#[test]
fn json_has_the_documented_shape_and_a_seed_fixes_it() {
    let args = [
        "uncertainty",
        "--x",
        "0.06",
        "--vary",
        "ks=uniform:2e4:6e4",
        "--vary",
        "p=normal:2.55:0.05",
        "--samples",
        "32",
        "--seed",
        "7",
        "--format",
        "json",
    ];
    let out = common::run(&args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!((v["samples"].as_u64(), v["seed"].as_u64()), (Some(32), Some(7)));
    // the fixed parameters are recorded beside the varied ones
    assert!(v["params"]["strings"]["ks"].is_number() && v["params"]["impact"]["x"].is_number(), "{v}");
    assert_eq!(v["inputs"][0]["key"], "ks");
    assert_eq!(v["inputs"][1]["dist"], "normal:2.55:0.05");
    let e_a = &v["outputs"]["e_a"];
    for key in ["mean", "sd", "q05", "q50", "q95"] {
        assert!(e_a[key].is_number(), "{key}");
    }
    for key in ["first_order", "total_order"] {
        assert!(e_a[key]["ks"].is_number() && e_a[key]["p"].is_number(), "{key}");
    }
    for key in ["first_order_ci", "total_order_ci"] {
        let ci = e_a[key]["ks"].as_array().unwrap();
        assert!(ci[0].as_f64().unwrap() <= ci[1].as_f64().unwrap(), "{key}");
    }
    // at 6 cm from the tip e_A rises steeply as the strings soften: ks carries its variance
    assert!(e_a["total_order"]["ks"].as_f64().unwrap() > e_a["total_order"]["p"].as_f64().unwrap());
    assert_eq!(common::run(&args).stdout, out.stdout, "same seed, same bytes");
    let other: Vec<&str> = args.iter().map(|a| if *a == "7" { "8" } else { a }).collect();
    assert_ne!(common::run(&other).stdout, out.stdout, "another seed, other samples");
}

#[test]
fn out_writes_the_file_and_csv_has_one_row_per_output() {
    let s = Scratch::new("out");
    let path = s.arg("u.csv");
    let out = common::run(&[
        "uncertainty",
        "--vary",
        "mb=uniform:0.0558:0.0576",
        "--samples",
        "8",
        "--format",
        "csv",
        "--out",
        &path,
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(out.stdout.is_empty());
    let csv = std::fs::read_to_string(&path).unwrap();
    assert!(csv.starts_with("output,unit,mean,sd,q05,q50,q95,first_mb,first_mb_lo,first_mb_hi,total_mb"), "{csv}");
    assert!(csv.lines().any(|l| l.starts_with("e_a,")));
}

#[test]
fn claims_give_every_claim_a_verdict() {
    let out = common::run(&["uncertainty", "--claims", "--samples", "2", "--format", "csv"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let csv = String::from_utf8(out.stdout).unwrap();
    let mut lines = csv.lines();
    let head = lines.next().unwrap();
    assert!(
        head.starts_with(
            "id,unit,paper,band_lo,band_hi,nominal,numerical,q05,q50,q95,verdict,conclusion,conclusion_share,conclusion_verdict,top_input"
        ),
        "{head}"
    );
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 64);
    assert!(rows.iter().all(|r| ["holds", "part", "not at all", "independent", "no number"]
        .iter()
        .any(|v| r.contains(&format!(",{v},")))));
}

#[test]
fn claims_that_no_sampled_input_moves_are_independent_not_holding_or_failing() {
    let out = common::run(&["uncertainty", "--claims", "--samples", "2", "--format", "csv"]);
    let csv = String::from_utf8(out.stdout).unwrap();
    let verdict = |id: &str| {
        let row = csv.lines().find(|l| l.starts_with(&format!("{id},"))).unwrap();
        row.split(',').nth(10).unwrap().to_string()
    };
    for id in ["ball_p_for_e_0_762", "fig8_theta_v1_proportional"] {
        assert_eq!(verdict(id), "independent", "{id}");
    }
    let independent = csv.lines().skip(1).filter(|l| l.split(',').nth(10) == Some("independent")).count();
    assert_eq!(independent, 2, "{csv}");
    assert_ne!(verdict("serve_peak_force"), "independent");
    // the tension calibration's shape is drawn: the paper's two statements about ks move with it
    for id in ["strings_ks_40lb", "strings_ks_80lb"] {
        assert_ne!(verdict(id), "independent", "{id}");
    }
    // the text output counts the verdicts, the independent ones apart
    let out = common::run(&["uncertainty", "--claims", "--samples", "2"]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("not at all; 2 do not depend on the sampled inputs (independent)"), "{text}");
    assert!(text.contains("hold by construction (not counted)"), "{text}");
    let json = common::run(&["uncertainty", "--claims", "--samples", "2", "--format", "json"]);
    let v: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    let v1 = &v["outputs"]["fig8_theta_v1_proportional"];
    assert_eq!(v1["verdict"], "independent");
    // so is its conclusion: no share, no margin; and it holds by construction
    assert_eq!(v1["conclusion_verdict"], "independent");
    assert!(v1["conclusion_share"].is_null() && v1["conclusion_margin"].is_null());
    assert_eq!(v1["by_construction"], true);
    assert!(v["outputs"]["serve_peak_force"]["conclusion_share"].is_number());
    assert!(v["outputs"]["serve_peak_force"]["conclusion_margin"].is_number());
    assert_eq!(v["outputs"]["serve_peak_force"]["conclusion_check"], "> 1000");
    assert!(v["conclusion_verdicts"]["by_construction"].as_u64().unwrap() > 0);
    assert_eq!(v["verdicts"]["independent"], 2);
    // (each verdict is checked again at twice the samples: one that changes there is counted
    // as borderline, apart from the others)
    let total: u64 = ["holds", "part", "not at all", "independent", "no number", "borderline"]
        .iter()
        .map(|k| v["verdicts"][k].as_u64().unwrap())
        .sum();
    assert_eq!(total, 64);
}

#[test]
fn bad_specs_are_refused_in_one_line_and_nothing_is_written() {
    let s = Scratch::new("bad");
    let path = s.arg("never.json");
    let cases: [(&[&str], &str); 16] = [
        (&["--vary", "kz=uniform:1:2"], "unknown parameter 'kz'"),
        (&["--vary", "ks=uniform:5e4:2e4"], "invalid ks = uniform:5e4:2e4: the range needs LO < HI"),
        (&["--vary", "ks=normal:4e4:-5"], "a normal needs SD > 0"),
        (&["--vary", "ks=uniform:0.5:2e4"], "1 <= ks <= 1e12 N/m"),
        (&["--vary", "p=uniform:0.8:2"], "1 < p <= 10"),
        (&["--vary", "ks=uniform:2e4:3e4", "--vary", "ks=uniform:3e4:4e4"], "ks is varied twice"),
        (
            &["--vary", "ks=uniform:2e4:3e4", "--samples", "0"],
            "invalid samples = 0: must be a whole number, 1 <= samples <= 65536",
        ),
        (&["--vary", "ks=uniform:2e4:3e4", "--samples", "100000"], "samples <= 65536"),
        (&["--vary", "ks=uniform:2e4:3e4", "--ks", "3e4"], "ks is both fixed (--ks) and varied"),
        (&["--vary", "load=uniform:1:2"], "only real-valued parameters"),
        (&["--claims", "--vary", "ks=uniform:2e4:3e4"], "invalid claims"),
        // an input the model does not read is refused as the same fixed flag is
        (&["--vary", "mu=uniform:0.2:0.5"], "mu is used only for an oblique or spinning ball"),
        (&["--vary", "dt=uniform:1e-7:1e-6"], "dt is used only with solver = fd"),
        (&["--vary", "hand-damping=uniform:1:20"], "hand-damping is used only with grip = hand"),
        // and a friction the named string sets from its database entry
        (
            &["--string", "alu-rough-16", "--angle-deg", "30", "--vary", "mu=uniform:0.2:0.5"],
            "mu is set by string = alu-rough-16",
        ),
        (&[], "give at least one --vary KEY=DIST"),
    ];
    for (args, want) in cases {
        let mut all = vec!["uncertainty"];
        all.extend_from_slice(args);
        all.extend_from_slice(&["--format", "json", "--out", &path]);
        let out = common::run(&all);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(want), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}");
        assert!(!std::path::Path::new(&path).exists(), "{args:?} wrote a file");
    }
}

#[test]
fn help_lists_exactly_what_the_command_accepts() {
    let help = String::from_utf8(common::run(&["uncertainty", "--help"]).stdout).unwrap();
    // the solver default it states is the one it runs
    assert!(help.contains("[default: modal; fd where a hand grip or stiffening strings need it]"), "{help}");
    for option in
        ["--vary", "--samples", "--seed", "--format", "--out", "--claims", "--racket", "--config", "--ks", "--mb"]
    {
        assert!(help.contains(option), "{option} missing from --help");
    }
    for declared in ["ks ~ uniform:36000:44000", "p ~ uniform:2.44445:2.7737"] {
        assert!(help.contains(declared), "{declared} missing from --help");
    }
}

/// A drawn input whose draws reach outside the usual range `simulate` warns with earns one
/// warning line per key, naming what was judged (a uniform's bounds, a normal's mean +- 3 sd)
/// and the same usual range; draws inside it, none; the run's result is unchanged.
#[test]
fn draws_outside_the_usual_range_earn_one_warning_per_key() {
    let stderr = |o: &Output| String::from_utf8_lossy(&o.stderr).into_owned();
    let warns =
        |o: &Output| stderr(o).lines().filter(|l| l.starts_with("warning:")).map(String::from).collect::<Vec<_>>();
    let base = ["uncertainty", "--solver", "modal", "--samples", "64"];
    let run = |vary: &[&str]| {
        let mut args = base.to_vec();
        for v in vary {
            args.extend(["--vary", v]);
        }
        let o = common::run(&args);
        assert!(o.status.success(), "{vary:?}: {}", stderr(&o));
        o
    };
    let quiet = run(&["ks=uniform:2e4:6e4", "mb=normal:0.057:0.001"]);
    assert!(warns(&quiet).is_empty(), "{:?}", warns(&quiet));
    // ks from 1e3 (below 5e3); mb 0.15 +- 3 x 0.025 reaches 0.225 (above 0.2); k1 inside
    let o = run(&["ks=uniform:1e3:6e4", "mb=normal:0.15:0.025", "k1=loguniform:2e4:4e4"]);
    let w = warns(&o);
    assert_eq!(w.len(), 2, "{w:?}");
    assert!(w[0].starts_with("warning: ks = uniform:1000:60000") && w[0].contains("(its bounds)"), "{}", w[0]);
    assert!(
        w[1].starts_with("warning: mb = normal:0.15:0.025") && w[1].contains("0.075..0.225 kg (mean +- 3 sd)"),
        "{}",
        w[1]
    );
    // the usual ranges are simulate's
    let sim = common::run(&["simulate", "--ks", "1000", "--mb", "0.24"]);
    for (line, key) in w.iter().zip(["ks", "mb"]) {
        let usual = line.split("outside the usual ").nth(1).unwrap().split(" of ").next().unwrap();
        assert!(
            stderr(&sim).lines().any(|l| l.starts_with(&format!("warning: {key} =")) && l.contains(usual)),
            "{usual}: {}",
            stderr(&sim)
        );
    }
    // a normal judged at 3 sd: 0.15 +- 3 x 0.016 stays inside
    assert!(warns(&run(&["mb=normal:0.15:0.016"])).is_empty());
    let q = common::run(&[&base[..], &["--quiet", "--vary", "ks=uniform:1e3:6e4"]].concat());
    assert!(q.stderr.is_empty() && q.stdout == run(&["ks=uniform:1e3:6e4"]).stdout);
}

#[test]
fn too_few_samples_warn_once_and_the_text_says_the_indices_mean_nothing() {
    for args in [
        &["uncertainty", "--vary", "ks=uniform:2e4:6e4", "--samples", "1"][..],
        &["uncertainty", "--claims", "--samples", "2", "--format", "csv"][..],
    ] {
        let loud = common::run(args);
        assert!(loud.status.success());
        let err = String::from_utf8(loud.stderr).unwrap();
        let warnings: Vec<&str> = err.lines().filter(|l| l.starts_with("warning:")).collect();
        assert_eq!(warnings.len(), 1, "{args:?}: {err}");
        assert!(warnings[0].contains("below 64 base samples") && warnings[0].contains("1/sqrt(N)"), "{}", warnings[0]);
        let quiet = common::run(&[&["--quiet"], args].concat());
        assert!(quiet.stderr.is_empty(), "{}", String::from_utf8_lossy(&quiet.stderr));
        assert_eq!(quiet.stdout, loud.stdout, "the warning changed the result");
    }
    let text =
        String::from_utf8(common::run(&["uncertainty", "--vary", "ks=uniform:2e4:6e4", "--samples", "1"]).stdout)
            .unwrap();
    assert!(text.contains("NOT MEANINGFUL at 1 base samples (fewer than 64)"), "{text}");
    let text = String::from_utf8(common::run(&["uncertainty", "--claims", "--samples", "2"]).stdout).unwrap();
    assert!(text.contains("NOT MEANINGFUL at 2 base samples"), "{text}");
    // and it is data: the JSON's diagnostics carry it (with --quiet too)
    let json =
        common::run(&["--quiet", "uncertainty", "--vary", "ks=uniform:2e4:6e4", "--samples", "1", "--format", "json"]);
    let json: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    let told = json["diagnostics"].as_array().unwrap();
    assert!(told.iter().any(|d| d["field"] == "samples" && d["kind"] == "unusual"), "{told:?}");
    // at the minimum: no warning, no remark
    let ok = common::run(&["uncertainty", "--vary", "ks=uniform:2e4:6e4", "--samples", "64"]);
    assert!(!String::from_utf8(ok.stderr).unwrap().contains("warning:"));
    assert!(!String::from_utf8(ok.stdout).unwrap().contains("NOT MEANINGFUL"));
}

/// The CSV's index columns spell a key with underscores, as the other CSVs and the JSON do
/// (`first_angle_deg`, not `first_angle-deg`).
#[test]
fn csv_index_columns_spell_keys_with_underscores() {
    let out = common::run(&[
        "uncertainty",
        "--x",
        "0.158",
        "--vary",
        "angle-deg=uniform:10:30",
        "--samples",
        "64",
        "--format",
        "csv",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let csv = String::from_utf8(out.stdout).unwrap();
    let head = csv.lines().next().unwrap();
    assert!(head.ends_with(
        "first_angle_deg,first_angle_deg_lo,first_angle_deg_hi,total_angle_deg,total_angle_deg_lo,total_angle_deg_hi"
    ), "{head}");
    assert!(!head.contains('-'), "{head}");
}

/// The positions every claim's impacts load (m from the tip, to 1e-9), each once, on a context
/// under the claim's reading; `None` for a claim that loads none.
fn loaded_positions(
    claims: &[racket_impact::experiments::claims::Claim],
    ctx: &racket_impact::experiments::Context,
) -> Vec<Vec<i64>> {
    use racket_impact::experiments::{claims::computations, Context};
    let ctx = ctx.clone().remembering();
    computations(claims)
        .unwrap()
        .iter()
        .zip(claims)
        .map(|(pc, c)| {
            let mine = Context { scheme: c.reading.scheme(), ..ctx.clone() }.recording();
            (pc.ours)(&mine).unwrap();
            let mut at: Vec<i64> =
                mine.runs.taken().iter().filter_map(|r| r.x_load).map(|x| (x * 1e9).round() as i64).collect();
            at.sort_unstable();
            at.dedup();
            at
        })
        .collect()
}

/// The robustness study draws the racket's length, but no draw moves a claim's load: each
/// impact is loaded at the physical point the claim's nominal run loads (Fig 4's 9.10 cm, node 5
/// of the paper's beam, at every drawn length), so that no input's share carries the grid. Each
/// input is moved to either end of its range in turn, the length among them; the same draws on a
/// context that does not hold its loads move them (the check can fail).
#[test]
fn a_sampled_claims_loaded_position_does_not_move_with_a_sampled_input() {
    use racket_impact::experiments::claims::claims;
    use racket_impact::experiments::robustness::{context_at, inputs, sampling};
    use racket_impact::experiments::Context;
    use racket_impact::params::uncertainty::Dist;
    let claims = claims().unwrap();
    let inputs = inputs();
    let nominal: Vec<f64> = inputs.iter().map(|i| i.uncertainty.unwrap().nominal).collect();
    let base = sampling(&Context::paper());
    let at_nominal = loaded_positions(&claims, &context_at(&base, &inputs, &nominal).unwrap());
    let fig4 = claims.iter().position(|c| c.id == "fig4_e_a").unwrap();
    assert_eq!(at_nominal[fig4], vec![(0.71 * 5.0 / 39.0 * 1e9_f64).round() as i64], "Fig 4 loads node 5's 9.10 cm");
    assert!(at_nominal.iter().filter(|a| !a.is_empty()).count() >= 40);
    let mut moved_without_holding = 0;
    for (k, input) in inputs.iter().enumerate() {
        let Dist::Uniform { lo, hi } = input.uncertainty.unwrap().dist else { continue };
        for end in [lo, hi] {
            let mut x = nominal.clone();
            x[k] = end;
            let drawn = loaded_positions(&claims, &context_at(&base, &inputs, &x).unwrap());
            for (c, (a, b)) in claims.iter().zip(at_nominal.iter().zip(&drawn)) {
                assert_eq!(a, b, "{}: its loads move when {} = {end}", c.id, input.key);
            }
            if input.key == "length" {
                let free = Context { grid_length: None, ..base.clone() };
                let drawn = loaded_positions(&claims, &context_at(&free, &inputs, &x).unwrap());
                moved_without_holding += at_nominal.iter().zip(&drawn).filter(|(a, b)| a != b).count();
            }
        }
    }
    assert!(
        moved_without_holding >= 40,
        "without holding, a drawn length moved only {moved_without_holding} claims' loads"
    );
}
