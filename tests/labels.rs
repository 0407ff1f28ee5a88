//! Results say what they describe and their labels agree with their signs (issue 24, class 5):
//! across impact points, incidence angles, azimuths and spins, the text of `v2_n` says rebound
//! or moving on exactly as its sign does, the rebound angle is the direction of (v2_n, v2_t)
//! and is over 90 degrees exactly when the ball moves on, every oblique output (text, CSV,
//! JSON, map table and title) names the angle, azimuth, spin and friction it was run at, and
//! the spin convention is written next to every spin printed.

mod common;

use common::bin;

use racket_impact::params::{Params, SolverKind};
use racket_impact::render::impact::{recorded_oblique, result_csv, result_text, sign_remark};
use racket_impact::simulate;
use racket_impact::study::map::{FaceMap, Quantity};

/// The paper's racket hit at `x`, `r` (m), 10 m/s, at an angle, azimuth and spin, modal solver.
fn oblique(x: f64, r: f64, angle_deg: f64, azimuth_deg: f64, spin_rpm: f64) -> Params {
    let mut p = Params::paper();
    (p.impact.x, p.impact.r, p.impact.v1) = (x, r, 10.0);
    p.numerics.solver = SolverKind::Modal;
    (p.oblique.angle_deg, p.oblique.azimuth_deg, p.oblique.spin_rpm) = (angle_deg, azimuth_deg, spin_rpm);
    p
}

/// The text line of `label` in a result text.
fn line<'a>(text: &'a str, label: &str) -> &'a str {
    text.lines().find(|l| l.split_whitespace().next() == Some(label)).unwrap_or_else(|| panic!("no {label} in {text}"))
}

#[test]
fn labels_agree_with_signs_across_points_angles_and_spins() {
    let (mut rebounds, mut moves_on) = (0, 0);
    for x in [0.0, 0.01, 0.03, 0.08, 0.158, 0.25, 0.4, 0.6] {
        for r in [0.0, 0.06] {
            for angle in [5.0, 30.0, 60.0, 80.0] {
                for (azimuth, spin) in [(0.0, 0.0), (90.0, 2000.0), (180.0, -3000.0)] {
                    let p = oblique(x, r, angle, azimuth, spin);
                    let res = simulate(&p).unwrap();
                    let text = result_text(&p, &res);
                    let case = format!("x {x} r {r} angle {angle} azimuth {azimuth} spin {spin}");
                    let v2n = line(&text, "v2_n");
                    let angle_line = line(&text, "rebound_angle");
                    assert!(res.v2_n != 0.0, "{case}");
                    if res.v2_n > 0.0 {
                        rebounds += 1;
                        assert!(v2n.contains("> 0, rebounds away from the strings"), "{case}: {v2n}");
                        assert!(res.rebound_angle_deg.abs() < 90.0, "{case}: {}", res.rebound_angle_deg);
                        assert!(!angle_line.contains("over 90"), "{case}: {angle_line}");
                    } else {
                        moves_on += 1;
                        assert!(v2n.contains("< 0, moves on in its incoming direction"), "{case}: {v2n}");
                        assert!(!v2n.contains("rebounds"), "{case}: {v2n}");
                        assert!(res.rebound_angle_deg.abs() > 90.0, "{case}: {}", res.rebound_angle_deg);
                        assert!(angle_line.contains("over 90 since v2_n < 0"), "{case}: {angle_line}");
                    }
                    // the angle is the direction of the outgoing velocity
                    let direction = res.v2_t.atan2(res.v2_n).to_degrees();
                    assert!((direction - res.rebound_angle_deg).abs() < 1e-9, "{case}");
                    assert_eq!(res.v2_n.signum(), res.e_a.signum(), "{case}: v2_n = e_A v_n");
                    // the convention of the spin is written where it is printed
                    assert!(line(&text, "spin_out").contains("topspin relative to the ball's incoming motion"));
                    assert!(text.contains(&format!("azimuth-deg {azimuth} deg")) && text.contains("mu 0.4"), "{text}");
                    // the CSV names what the impact was run at, with these values
                    let csv = result_csv(&p, &res);
                    let mut rows = csv.lines();
                    let (head, row): (Vec<&str>, Vec<&str>) =
                        (rows.next().unwrap().split(',').collect(), rows.next().unwrap().split(',').collect());
                    for (column, value) in recorded_oblique(&p) {
                        let k = head.iter().position(|h| *h == column).unwrap_or_else(|| panic!("{column}: {head:?}"));
                        assert_eq!(row[k].parse::<f64>().unwrap(), value, "{case}: {column}");
                    }
                }
            }
        }
    }
    // the grid covers both signs
    assert!(rebounds > 50 && moves_on > 5, "{rebounds} rebounds, {moves_on} moving on");
}

#[test]
fn sign_remarks_are_only_for_the_fields_they_describe() {
    let p = oblique(0.158, 0.0, 30.0, 0.0, 0.0);
    let res = simulate(&p).unwrap();
    // every field's key is matched: the two described ones carry a remark, no other does
    for field in racket_impact::solve::outcome::FIELDS.iter() {
        let described = ["v2_n_m_per_s", "rebound_angle_deg"].contains(&field.key);
        let remark = sign_remark(field.key, &res);
        if field.key == "v2_n_m_per_s" {
            assert!(!remark.is_empty(), "{}", field.key);
        } else if !described {
            assert_eq!(remark, "", "{}", field.key);
        }
    }
    // at normal incidence the oblique lines are not printed at all
    let normal = simulate(&Params::paper()).unwrap();
    let text = result_text(&Params::paper(), &normal);
    assert!(!text.contains("v2_n") && !text.contains("rebound_angle"), "{text}");
    let csv = result_csv(&Params::paper(), &normal);
    assert!(!csv.lines().next().unwrap().contains("angle_deg,"), "{csv}");
}

#[test]
fn json_outputs_write_their_spin_convention() {
    let out = bin().args(["simulate", "--angle-deg", "30", "--spin-rpm", "500", "--format", "json"]).output().unwrap();
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(v["spin_convention"].as_str().unwrap().contains("along the strings"), "{v}");
    let out = bin()
        .args(["speed", "--swing", "100", "--swing-path-deg", "20", "--incoming-spin-rpm", "1000", "--format", "json"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let convention = v[0]["spin_convention"].as_str().unwrap();
    assert!(convention.contains("court's frame"), "{v}");
    // the incoming spin is printed in the court's frame it was given in, and the parameters'
    // racket-frame copy of it is named as such (a backspin of 1000 rpm in the court's frame is
    // -1000 in the racket's frame for a forward swing)
    assert_eq!(v[0]["incoming_spin_rpm"].as_f64(), Some(1000.0), "{v}");
    assert!(convention.contains("params.oblique.spin_rpm and result.spin_out_rpm: the racket's frame"), "{v}");
    assert_eq!(v[0]["params"]["oblique"]["spin_rpm"].as_f64(), Some(-1000.0), "{v}");
    let out = bin().args(["speed", "--swing", "100", "--swing-path-deg", "20"]).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("> 0 is topspin in the court's frame"), "{text}");
}

#[test]
fn oblique_maps_name_angle_azimuth_spin_and_mu_in_title_and_table() {
    let mut p = oblique(0.158, 0.0, 30.0, 45.0, 1000.0);
    p.oblique.mu = 0.3;
    let map = FaceMap::compute(&p, 9, 5, &mut |_| {}).unwrap();
    let title = map.heatmap(Quantity::Spin, "paper racket").title;
    for needle in ["angle 30 deg", "azimuth 45 deg", "spin 1000 rpm", "mu 0.3"] {
        assert!(title.contains(needle), "{title}");
    }
    let t = map.table();
    for (column, value) in [("angle_deg", 30.0), ("azimuth_deg", 45.0), ("spin_rpm", 1000.0), ("mu", 0.3)] {
        let col = t.column(column).unwrap_or_else(|| panic!("no {column}: {:?}", t.columns));
        assert!(!col.is_empty() && col.iter().all(|v| *v == value), "{column}");
    }
    // its metadata and colour bar say which way the spins count
    let meta = map.metadata("paper racket", Quantity::Spin, (9, 5)).unwrap();
    assert!(meta["spin_convention"].as_str().unwrap().contains("relative to the ball's incoming motion"), "{meta}");
    assert!(Quantity::Spin.symbol().contains("> 0: topspin"));
    assert!(!title.contains("tangential"), "{title}");
    // a tangential law other than the default is named
    let mut physical = p;
    physical.oblique.tangential = racket_impact::params::TangentialLaw::Physical;
    let title = FaceMap::compute(&physical, 9, 5, &mut |_| {}).unwrap().heatmap(Quantity::Spin, "paper racket").title;
    assert!(title.contains("tangential physical"), "{title}");
    // a normal map has none of them
    let normal = FaceMap::compute(&Params::paper(), 9, 5, &mut |_| {}).unwrap();
    assert!(normal.table().column("angle_deg").is_none());
    assert!(normal.metadata("paper", Quantity::Power, (9, 5)).unwrap().get("spin_convention").is_none());
    assert!(!normal.heatmap(Quantity::Power, "paper").title.contains("angle"));
}

/// `e_t` divides by the incoming slip of the contact point: a ball arriving nearly rolling
/// (slip 1e-4 of the incident speed, under the physical law whose offset torque keeps the
/// outgoing slip finite) has it undefined in every output (NaN; text `undefined` with the
/// threshold, JSON null, an empty CSV field, in `simulate` and `sweep`), while at 2 % slip it
/// is a number.
#[test]
fn e_t_is_undefined_when_the_ball_arrives_nearly_rolling() {
    use racket_impact::params::TangentialLaw;
    use racket_impact::render::impact::result_json;
    use racket_impact::solve::oblique::E_T_MIN_SLIP_FRACTION;
    let rolling = |slip: f64| {
        let mut p = oblique(0.158, 0.0, 10.0, 0.0, 0.0);
        p.oblique.tangential = TangentialLaw::Physical;
        let v_t = p.impact.v1 * 10f64.to_radians().sin();
        p.oblique.spin_rpm = (v_t - slip * p.impact.v1) / p.oblique.ball_radius / (std::f64::consts::PI / 30.0);
        p
    };
    let p = rolling(1e-4);
    let r = simulate(&p).unwrap();
    assert!(r.e_t.is_nan(), "e_t = {} at a slip of 1e-4 of the incident speed", r.e_t);
    let text = result_text(&p, &r);
    let l = line(&text, "e_t");
    assert!(l.contains("undefined") && l.contains(&format!("below {} %", 100.0 * E_T_MIN_SLIP_FRACTION)), "{l}");
    assert!(result_json(&p, &r)["e_t"].is_null());
    let csv = result_csv(&p, &r);
    let (head, row) = csv.split_once('\n').unwrap();
    let at = head.split(',').position(|c| c == "e_t").expect("an e_t column");
    assert_eq!(row.trim_end().split(',').nth(at), Some(""), "{csv}");
    let spin = p.oblique.spin_rpm.to_string();
    let o = bin()
        .args(["sweep", "--solver", "modal", "--v1", "10", "--angle-deg", "10", "--tangential", "physical"])
        .args(["--spin-rpm", &format!("{spin},0")])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8(o.stdout).unwrap();
    let mut lines = out.lines();
    let at = lines.next().unwrap().split(',').position(|c| c == "e_t").unwrap();
    let e_t: Vec<&str> = lines.map(|l| l.split(',').nth(at).unwrap()).collect();
    assert_eq!(e_t[0], "", "{out}");
    assert!(e_t[1].parse::<f64>().unwrap().is_finite(), "{out}");
    let r = simulate(&rolling(0.02)).unwrap();
    assert!(r.e_t.is_finite(), "e_t = {} at 2 % slip", r.e_t);
    // drawn across the rolling spin, its summary is undefined and says why
    let o = bin()
        .args(["uncertainty", "--solver", "modal", "--v1", "10", "--angle-deg", "10", "--tangential", "physical"])
        .args([
            "--samples",
            "8",
            "--vary",
            &format!("spin-rpm=uniform:{}:{}", p.oblique.spin_rpm - 10.0, p.oblique.spin_rpm + 10.0),
        ])
        .output()
        .unwrap();
    let out = String::from_utf8(o.stdout).unwrap();
    let l = line(&out, "e_t");
    assert!(l.contains("undefined in some draws") && l.contains("below 1 %"), "{l}");
}

/// The losses of the named tangential mechanisms are reported wherever an impact's results
/// are: simulate's text, JSON and CSV, sweep's columns, uncertainty's outputs and speed's JSON
/// (under a law that has them; under the elastic law, where they do not apply, none has them).
#[test]
fn tangential_losses_are_in_every_output_of_an_impact() {
    let losses = ["f_tangential_damping", "f_string_sliding", "f_rolling"];
    let run = |args: &[&str]| {
        let o = bin().args(args).output().unwrap();
        assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8(o.stdout).unwrap()
    };
    let oblique = ["--angle-deg", "30", "--solver", "modal"];
    for law in ["physical", "elastic"] {
        let with = |cmd: &[&str], extra: &[&str]| -> String {
            let mut args: Vec<&str> = cmd.to_vec();
            args.extend(oblique);
            args.extend(["--tangential", law]);
            args.extend(extra);
            run(&args)
        };
        let outputs = [
            (
                "simulate text",
                with(&["simulate"], &[])
                    .lines()
                    .map(|l| l.split_whitespace().next().unwrap_or("").to_string())
                    .collect::<Vec<_>>()
                    .join(" "),
            ),
            ("simulate json", with(&["simulate"], &["--format", "json"])),
            ("simulate csv", with(&["simulate"], &["--format", "csv"]).lines().next().unwrap().to_string()),
            ("sweep", with(&["sweep"], &["--mu", "0.3,0.4"]).lines().next().unwrap().to_string()),
            (
                "uncertainty",
                with(&["uncertainty"], &["--vary", "mu=uniform:0.3:0.5", "--samples", "4", "--format", "csv"]),
            ),
        ];
        for (what, out) in &outputs {
            let names: Vec<&str> = out.split(|c: char| !(c.is_alphanumeric() || c == '_')).collect();
            for key in losses {
                assert_eq!(names.contains(&key), law == "physical", "{law}: {key} in the {what} output:\n{out}");
            }
        }
    }
    let speed =
        run(&["speed", "--swing", "100", "--swing-path-deg", "20", "--tangential", "physical", "--format", "json"]);
    let v: serde_json::Value = serde_json::from_str(&speed).unwrap();
    for key in losses {
        assert!(v[0]["result"][key].is_number(), "speed json lacks {key}");
    }
}

/// Each energy fraction of an oblique impact names its base: those of the normal motion are of
/// the normal incoming KE (`f_ke_ball` is `(v2_n / v1_n)^2`), the tangential ones of the whole;
/// at normal incidence the base is the one incoming KE and the lines are as before.
#[test]
fn oblique_energy_fractions_name_their_base() {
    let p = oblique(0.158, 0.0, 30.0, 90.0, 0.0);
    let r = simulate(&p).unwrap();
    let text = result_text(&p, &r);
    let ke = line(&text, "f_ke_ball");
    assert!(ke.ends_with("ball rebound KE (v2_n / v1_n)^2, of the normal incoming KE"), "{ke}");
    assert!(!text.contains("of initial ball KE"), "{text}");
    assert!((r.f_ke_ball - (r.v2_n / (10.0 * 30f64.to_radians().cos())).powi(2)).abs() < 1e-9, "{r:?}");
    for label in ["f_ball", "f_rigid", "f_vib", "f_vib_peak_pe", "f_spin"] {
        assert!(line(&text, label).ends_with("of the normal incoming KE)"), "{}", line(&text, label));
    }
    for label in ["f_friction", "f_ball_spin", "f_racket_inplane"] {
        assert!(line(&text, label).ends_with("(of the whole incoming KE)"), "{}", line(&text, label));
    }
    let normal = Params::paper();
    let text = result_text(&normal, &simulate(&normal).unwrap());
    assert!(line(&text, "f_ke_ball").ends_with("of initial ball KE"), "{text}");
    assert!(!text.contains("normal incoming"), "{text}");
}

/// A flag is 0/1 in every CSV: the simulate CSV's `recontact` as the sweep's and the map's.
#[test]
fn flags_are_0_or_1_in_the_simulate_csv_as_in_the_sweep_csv() {
    let column = |csv: &str, key: &str| -> Vec<String> {
        let mut lines = csv.lines();
        let k = lines.next().unwrap().split(',').position(|c| c == key).unwrap_or_else(|| panic!("{key}: {csv}"));
        lines.map(|l| l.split(',').nth(k).unwrap().to_string()).collect()
    };
    let p = Params::paper();
    let mut r = simulate(&p).unwrap();
    assert_eq!(column(&result_csv(&p, &r), "recontact"), ["0"]);
    r.recontact = true;
    assert_eq!(column(&result_csv(&p, &r), "recontact"), ["1"]);
    let sim = bin().args(["simulate", "--format", "csv"]).output().unwrap();
    assert_eq!(column(&String::from_utf8(sim.stdout).unwrap(), "recontact"), ["0"]);
    let sweep = bin().args(["sweep", "--ks", "2e4,4e4"]).output().unwrap();
    assert_eq!(column(&String::from_utf8(sweep.stdout).unwrap(), "recontact"), ["0", "0"]);
}
