//! Unit tests of the racket description: conversions, groups of keys, the fit, the presets.

use std::path::Path;

use super::presets::PRESETS;
use super::*;
use crate::error::Result;

fn spec(text: &str) -> Result<RacketSpec> {
    RacketSpec::from_toml_bytes(Path::new("t.toml"), text.as_bytes())
}

const BASE: &str = "length_cm = 71\nmass_g = 340\ntwistweight_kg_cm2 = 15\nei_n_m2 = 150\n";

#[test]
fn balance_points_are_eighths_of_an_inch_from_the_middle() {
    let s = spec(&format!("{BASE}balance_pts_hl = 8\nswingweight_kg_cm2 = 340")).unwrap();
    let r = s.resolve().unwrap();
    let shape = r.shape.unwrap();
    // 8 points head-light = 1 inch towards the butt from 35.5 cm
    assert!((shape.balance_cm - (35.5 - 2.54)).abs() < 1e-12);
    assert!((shape.x_cm - (0.71 - 0.3296)).abs() < 1e-12);
}

#[test]
fn tension_units_convert_to_the_spec_calibration() {
    let ks = |line: &str| spec(&format!("{BASE}{line}")).unwrap().resolve().unwrap().ks;
    assert_eq!(ks("tension_lb = 60"), 4.0e4);
    assert!((ks("tension_kg = 27.2155422") - 4.0e4).abs() < 1e-3, "60 lb is 27.2155422 kgf");
    assert_eq!(ks("string_bed_n_per_m = 3.3e4"), 3.3e4);
    assert!((ks("dt_kp_cm = 40") - 39226.6).abs() < 1e-9);
    assert_eq!(ks(""), 4.0e4);
}

#[test]
fn head_size_and_aspect_give_the_ellipse_of_that_area() {
    let s = spec(&format!("{BASE}head_size_sq_in = 100\nhead_aspect = 1.3")).unwrap();
    let (l, hw) = s.resolve().unwrap().head.unwrap();
    let area_cm2 = std::f64::consts::PI / 4.0 * (l * 100.0) * (2.0 * hw * 100.0);
    assert!((area_cm2 - 645.16).abs() < 1e-9);
    assert!((l / (2.0 * hw) - 1.3).abs() < 1e-12);
}

#[test]
fn groups_of_alternatives_name_their_keys() {
    let both = spec(&format!("{BASE}length_in = 28")).unwrap_err().to_string();
    assert!(both.contains("length_in/length_cm") && both.contains("only one"), "{both}");
    let none = spec("mass_g = 340\ntwistweight_kg_cm2 = 15\nei_n_m2 = 150").unwrap_err().to_string();
    assert!(none.contains("length_in/length_cm = (missing)"), "{none}");
    let half = spec(&format!("{BASE}head_length_cm = 33")).unwrap_err().to_string();
    assert!(half.contains("head_width_cm"), "{half}");
    let mixed = spec(&format!("{BASE}head_length_cm = 33\nhead_width_cm = 25\nhead_aspect = 1.3")).unwrap_err();
    assert!(mixed.to_string().contains("head_length_cm/head_size_sq_in"), "{mixed}");
}

#[test]
fn the_density_fit_is_exact_on_the_discrete_beam() {
    let s = spec(&format!("{BASE}balance_cm = 33\nswingweight_kg_cm2 = 330\nhead_length_cm = 34\nhead_width_cm = 26"))
        .unwrap();
    for n in [8, 39, 161] {
        let rep = s.to_racket(n).unwrap().report;
        for c in [rep.mass_g, rep.balance_cm, rep.swingweight_kg_cm2] {
            assert!(c.rel_error().unwrap().abs() < 1e-12, "{n}: {c:?}");
        }
    }
}

#[test]
fn an_unreachable_swingweight_reports_the_reachable_range() {
    // 340 g balanced 33 cm from the butt: every distribution has SW > M d^2 = 179.9 kg cm^2
    let s = spec(&format!("{BASE}balance_cm = 33\nswingweight_kg_cm2 = 150")).unwrap();
    let msg = s.to_racket(39).unwrap_err().to_string();
    assert!(
        msg.starts_with("invalid swingweight_kg_cm2 = 150:") && msg.contains("179.9 < swingweight_kg_cm2 <"),
        "{msg}"
    );
    // balanced 3 cm from the butt: at most M (d^2 + b (L - b)) = 86.0 kg cm^2
    let s = spec(&format!("{BASE}balance_cm = 3\nswingweight_kg_cm2 = 300")).unwrap();
    let msg = s.to_racket(39).unwrap_err().to_string();
    assert!(msg.contains("at balance_cm = 3 and mass_g = 340") && msg.contains("< 86.02 kg cm^2"), "{msg}");
}

/// The example: a strung 300 g frame balanced 32.5 cm from the butt with a swingweight
/// of 315 kg cm^2, refused by the earlier piecewise-linear density, fits exactly with a
/// plausible density (no warning) whose throat is its lightest part.
#[test]
fn a_real_frame_with_its_mass_in_the_head_loop_fits() {
    let s = spec(
        "length_in = 27\nmass_g = 300\nbalance_cm = 32.5\nswingweight_kg_cm2 = 315\ntwistweight_kg_cm2 = 14\n\
         frequency_hz = 150\nhead_size_sq_in = 100",
    )
    .unwrap();
    let fit = s.to_racket(39).unwrap();
    let rep = &fit.report;
    for c in [rep.mass_g, rep.balance_cm, rep.swingweight_kg_cm2, rep.twistweight_kg_cm2] {
        assert!(c.rel_error().unwrap().abs() < 1e-12, "{c:?}");
    }
    assert!(rep.frequency_hz.rel_error().unwrap().abs() < 1e-9, "{:?}", rep.frequency_hz);
    assert!(density_warning(&fit.racket).is_none(), "{:?}", density_warning(&fit.racket));
    let (throat_at, throat) = rep.density_min_g_per_cm;
    // lightest in the throat, between the head (33.3 cm long) and the handle, at 2-3 g/cm
    assert!((30.0..50.0).contains(&throat_at) && (2.0..3.0).contains(&throat), "{rep:?}");
    assert!(rep.density_g_per_cm[0] > 2.0 * throat && rep.density_g_per_cm[3] > 2.0 * throat, "{rep:?}");
}

/// The middle 80 % of every physical balance-swingweight range (on a grid of masses and
/// balances) fits, exactly on the discrete beam, at two N (the last few per cent next to either
/// limit are beyond the bounded tilt family and refused with that reason).
#[test]
fn the_interior_of_every_realisable_balance_and_swingweight_range_fits() {
    for mass_g in [100.0, 300.0, 400.0] {
        for balance_cm in [20.0, 30.0, 34.0, 38.0, 45.0] {
            let (l, b, m) = (68.58, balance_cm, mass_g / 1000.0);
            let d = b - 10.0;
            let (lo, hi) = (m * d * d, m * (d * d + b * (l - b)));
            for t in [0.1, 0.3, 0.5, 0.7, 0.9] {
                let sw = lo + t * (hi - lo);
                let text = format!(
                    "length_cm = {l}\nmass_g = {mass_g}\nbalance_cm = {b}\nswingweight_kg_cm2 = {sw}\n\
                     twistweight_kg_cm2 = 14\nei_n_m2 = 150"
                );
                for n in [39, 120] {
                    let fit = spec(&text).unwrap().to_racket(n).unwrap_or_else(|e| panic!("{text}\nN={n}: {e}"));
                    let rep = fit.report;
                    for c in [rep.mass_g, rep.balance_cm, rep.swingweight_kg_cm2] {
                        assert!(c.rel_error().unwrap().abs() < 1e-11, "{text}\nN={n}: {c:?}");
                    }
                }
            }
        }
    }
}

#[test]
fn a_head_size_without_an_aspect_takes_the_stated_typical_aspect() {
    let s = spec(&format!("{BASE}head_size_sq_in = 100")).unwrap();
    let (l, hw) = s.resolve().unwrap().head.unwrap();
    assert!((l / (2.0 * hw) - DEFAULT_HEAD_ASPECT).abs() < 1e-12);
    let area_cm2 = std::f64::consts::PI / 4.0 * (l * 100.0) * (2.0 * hw * 100.0);
    assert!((area_cm2 - 645.16).abs() < 1e-9);
    let alone = spec(&format!("{BASE}head_aspect = 1.3")).unwrap_err().to_string();
    assert!(alone.contains("head_size_sq_in = (missing)"), "{alone}");
}

#[test]
fn every_preset_parses_and_validates() {
    assert_eq!(preset_names().len(), PRESETS.len());
    for name in preset_names() {
        let s = preset(name).unwrap_or_else(|| panic!("preset {name} does not parse"));
        s.validate().unwrap();
        assert_eq!(s.name.as_deref(), Some(*name));
    }
}

#[test]
fn every_problem_of_a_description_is_reported_at_once_naming_the_file() {
    let text = "length_cm = 6860\nmass_g = 300\ntwistweight_kg_cm2 = -14\nfrequency_hz = 150\n";
    let parsed: RacketSpec = toml::from_str(text).unwrap();
    // the checks return the problems as a list, the reader puts in the file
    match parsed.validate() {
        Err(crate::Error::Several(problems)) => assert_eq!(problems.len(), 2, "{problems:?}"),
        other => panic!("expected several problems, got {other:?}"),
    }
    let e = spec(text).unwrap_err().to_string();
    assert!(e.starts_with("config file t.toml: 2 problems: invalid length_cm = 6860: "), "{e}");
    assert!(e.contains("; invalid twistweight_kg_cm2 = -14: "), "{e}");
}
