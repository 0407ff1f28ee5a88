//! The claims report: every claim has a computation, every verdict is pinned, every
//! reproduced claim is within its tolerance, and the committed REPORT.md is current.

use racket_impact::report::{check_claims_file, document, evaluate, Verdict};

#[test]
fn claims_file_is_well_formed() {
    let claims = check_claims_file().unwrap();
    assert!(claims.len() >= 30, "only {} claims", claims.len());
    for c in &claims {
        assert!(!c.note.trim().is_empty() && c.note != "TBD", "{}: empty note", c.id);
    }
}

#[test]
fn every_verdict_is_pinned_and_reproduced_claims_are_within_tolerance() {
    let rows = evaluate().unwrap();
    for r in &rows {
        assert!(r.ours.is_finite(), "{}: ours is not finite", r.claim.id);
        assert_eq!(
            r.verdict, r.claim.expected,
            "{}: verdict flipped (paper {}, ours {}, error {}, tolerance {})",
            r.claim.id, r.claim.paper, r.ours, r.error, r.tolerance
        );
        if r.verdict == Verdict::Reproduced {
            assert!(r.error.abs() <= r.tolerance, "{}", r.claim.id);
        }
    }
    let committed = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/REPORT.md")).unwrap();
    assert!(
        committed == document(&rows).unwrap(),
        "REPORT.md is stale: run `make figures` (or `racket-impact report`)"
    );
}

#[test]
fn paper_claims_of_section_4_are_all_listed() {
    let ids: Vec<String> = check_claims_file().unwrap().into_iter().map(|c| c.id).collect();
    for id in [
        "concrete_tau",
        "concrete_e",
        "clamped_tau_ks2e4",
        "clamped_e_ks2e4",
        "clamped_tau_ks4e4",
        "clamped_e_ks4e4",
        "modes_f1",
        "modes_f2",
        "modes_node",
        "modes_f1_ei384",
        "fig4_tau",
        "fig4_e_a",
        "fig4_ke_ball",
        "fig5_centre_e_a_soft",
        "fig5_centre_e_a_stiff",
        "fig5_dead_spot",
        "fig5_node_f_vib",
        "fig5_centre_tau_soft",
        "fig5_centre_tau_stiff",
        "speeds_ks_half_e_a_gain",
        "speeds_ks_half_serve_gain",
        "speeds_ks_half_forehand_gain",
        "speeds_60_50_serve_gain",
        "speeds_60_50_forehand_gain",
        "speeds_60_50_tau_change",
        "fig6_vibration_gone_at_10ms",
        "fig8_theta_r4_50lb",
        "fig8_theta_gain_ks_half",
        "speeds_50_60_theta_change",
        "fig9_e_a_ei150",
        "fig9_e_a_ei384",
        "fig9_serve_gain",
    ] {
        assert!(ids.iter().any(|i| i == id), "claim {id} missing");
    }
}
