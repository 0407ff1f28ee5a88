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
    let s = spec(&format!("{BASE}balance_cm = 33\nswingweight_kg_cm2 = 150")).unwrap();
    let msg = s.to_racket(39).unwrap_err().to_string();
    assert!(msg.starts_with("invalid swingweight_kg_cm2 = 150:") && msg.contains("< swingweight_kg_cm2 <"), "{msg}");
    let s = spec(&format!("{BASE}balance_cm = 3\nswingweight_kg_cm2 = 300")).unwrap();
    let msg = s.to_racket(39).unwrap_err().to_string();
    assert!(msg.starts_with("invalid balance_cm = 3:") && msg.contains("< balance <"), "{msg}");
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
