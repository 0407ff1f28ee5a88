//! The claims report: every claim has a computation, every verdict is pinned, every
//! reproduced claim is within its tolerance, and the committed REPORT.md is current.

mod common;

use racket_impact::report::{check_claims_file, evaluate, Verdict};

#[test]
fn claims_file_is_well_formed() {
    let claims = check_claims_file().unwrap();
    assert!(claims.len() >= 50, "only {} claims", claims.len());
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
            "{}: verdict flipped (paper {}, ours {}, error {:?}, tolerance {:?})",
            r.claim.id, r.claim.paper, r.ours, r.error, r.tolerance
        );
        if let (Verdict::Reproduced, Some(e), Some((_, tol))) = (r.verdict, r.error, r.tolerance) {
            assert!(e.abs() <= tol, "{}", r.claim.id);
        }
        assert_eq!(
            r.converged_verdict, r.claim.expected_converged,
            "{}: converged verdict flipped (paper {}, converged {:?}, band {:?})",
            r.claim.id, r.claim.paper, r.converged, r.band
        );
    }
    // the committed REPORT.md is this build's: the binary's `report` (the document `make figures`
    // kept for this build, src/cli/cache.rs, else computed by the binary: one computation of the
    // whole document for the suite, about 40 CPU-seconds)
    let committed = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/REPORT.md")).unwrap();
    let printed = common::run(&["report", "--no-write"]);
    assert!(printed.status.success(), "{}", String::from_utf8_lossy(&printed.stderr));
    assert!(
        committed.as_bytes() == printed.stdout,
        "REPORT.md is stale: run `make figures` (or `racket-impact report`)"
    );
}

/// What a claim's value is computed from decides whether it has a converged value: every claim
/// whose computation runs a beam (an impact or an eigenproblem, directly or through the values
/// it does arithmetic on) has one, computed on the converged beam only; a claim that runs none
/// has none.
#[test]
fn no_claim_computed_from_a_beam_run_lacks_a_converged_value() {
    use racket_impact::experiments::claims::{claims, computations};
    use racket_impact::experiments::{Context, Scheme};
    let rows = evaluate().unwrap();
    let claims = claims().unwrap();
    let mut beam = 0;
    for (pc, r) in computations(&claims).unwrap().into_iter().zip(&rows) {
        let ctx = Context::paper().recording();
        (pc.ours)(&ctx).unwrap();
        let runs = ctx.runs.taken();
        assert_eq!(
            r.converged.is_some(),
            !runs.is_empty(),
            "{}: converged {:?}, {} beam runs",
            pc.id,
            r.converged,
            runs.len()
        );
        assert!(runs.iter().all(|run| run.under(Scheme::Paper)), "{}: a run off the paper's scheme", pc.id);
        let fine = Context::paper().converged().recording();
        (pc.ours)(&fine).unwrap();
        assert!(fine.runs.taken().iter().all(|run| run.under(Scheme::Converged)), "{}: not converged", pc.id);
        beam += usize::from(!runs.is_empty());
    }
    assert!(beam >= 30, "only {beam} claims run a beam");
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

/// The committed `figures/robustness.csv` (tests/golden.rs holds it to what the code computes).
fn robustness_rows() -> Vec<std::collections::HashMap<String, String>> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/figures/robustness.csv");
    let mut rdr = csv::Reader::from_path(path).unwrap();
    rdr.deserialize().map(|r| r.unwrap()).collect()
}

#[test]
fn every_claim_has_its_conclusion_judged_beside_its_number() {
    let rows = robustness_rows();
    assert_eq!(rows.len(), check_claims_file().unwrap().len());
    for r in &rows {
        let (share, verdict) = (&r["conclusion_share"], r["conclusion_verdict"].as_str());
        assert!(!r["conclusion"].is_empty(), "{}: no conclusion", r["id"]);
        // an empty share is exactly an independent conclusion
        assert_eq!(share.is_empty(), verdict == "independent", "{}: share {share:?}, verdict {verdict}", r["id"]);
        if let Ok(s) = share.parse::<f64>() {
            assert!((0.0..=1.0).contains(&s), "{}: share {s}", r["id"]);
        }
    }
}

#[test]
fn the_headline_conclusions_stand_where_their_numbers_do_not() {
    let rows = robustness_rows();
    let row = |id: &str| rows.iter().find(|r| r["id"] == id).unwrap_or_else(|| panic!("{id} missing"));
    // the paper's headline claims: (id, conclusion share, verdict on the number)
    for (id, share, number) in [
        ("speeds_ks_half_e_a_gain", "1", "part"),
        ("speeds_ks_half_serve_gain", "1", "holds"),
        // the tension calibration's shape, drawn between the paper's two readings, spans the
        // paper's 0.7 and 1.1 % (ours 0.54 / 0.83 %, the 2e4-6e4 line 0.85 / 1.3 %)
        ("speeds_60_50_serve_gain", "1", "part"),
        ("speeds_60_50_forehand_gain", "1", "part"),
        ("fig9_serve_gain", "1", "part"),
    ] {
        let r = row(id);
        assert_eq!((r["conclusion_share"].as_str(), r["conclusion_verdict"].as_str()), (share, "holds"), "{id}");
        assert_eq!(r["verdict"], number, "{id}");
    }
    // where the conclusion is contested, pinned as computed
    // held at node 5's 9.10 cm in every draw, Fig 4's e_A stays under half the centre's (it was
    // contested while a drawn length moved its load to another node)
    assert_eq!(row("fig4_e_a")["conclusion_verdict"], "holds");
    assert_eq!(row("fig6_vibration_gone_at_10ms")["conclusion_verdict"], "contested");
    // "about 10 deg", read as every "about" is (within 10 %): about half the samples
    assert_eq!(row("fig8_theta_r4_50lb")["conclusion_verdict"], "contested");
    // the paper's arithmetic (a 19 % rise is a 16 % cut, not "about 20 %") and ours bending
    // below proportional to r fail in every sample, with a negative margin
    for id in ["conclusions_theta_cut_ks_double", "fig8_theta_r_proportional"] {
        assert_eq!(row(id)["conclusion_verdict"], "fails", "{id}");
        assert!(row(id)["conclusion_margin"].parse::<f64>().unwrap() < 0.0, "{id}");
    }
    // a conclusion that holds by construction is labelled so
    for id in ["modes_f1", "modes_f2", "concrete_e", "intro_swing_angle", "fig8_theta_v1_proportional"] {
        assert_eq!(row(id)["by_construction"], "yes", "{id}");
    }
    assert_eq!(row("serve_peak_force")["by_construction"], "no");
}

#[test]
fn arithmetic_on_inputs_or_other_claims_is_a_consistency_check() {
    use racket_impact::report::Kind;
    let claims = check_claims_file().unwrap();
    for id in ["concrete_e", "ball_p_for_e_0_762", "modes_period", "intro_swing_angle", "fig9_serve_gain"] {
        let c = claims.iter().find(|c| c.id == id).unwrap();
        assert_eq!(c.kind, Kind::Consistency, "{id}");
    }
    for id in ["concrete_tau", "fig4_e_a", "speeds_60_50_serve_gain", "fig8_theta_r4_50lb"] {
        let c = claims.iter().find(|c| c.id == id).unwrap();
        assert_eq!(c.kind, Kind::Reproduction, "{id}");
    }
}

/// The paper's notation as the claims file writes it: LaTeX and Unicode symbols become plain
/// forms (`$k_{\rm s}$` is `k_s`, `4×10^4` is `4e4`, `N m⁻¹` is `N/m`, `°` is ` deg`, `τ` is `tau`,
/// `\pm` is `+-`), emphasis marks and doubled spaces are dropped, and a space before a comma or
/// full stop goes (the text's line breaks leave some). Applied to both sides, so a quote is found
/// only if its words are the paper's, in the paper's order.
fn transliterated(text: &str) -> String {
    let mut t = text.to_string();
    for (from, to) in [
        ("\u{2019}", "'"),
        ("\u{2018}", "'"),
        ("\u{2013}", "-"),
        ("\u{2014}", "-"),
        ("\\rm", ""),
        ("\\mathrm", ""),
        ("\\text", ""),
        ("\\times", "×"),
        ("\\pm", "+-"),
        ("\\tau", "tau"),
        ("\\theta", "theta"),
        ("τ", "tau"),
        ("θ", "theta"),
        ("°", " deg"),
        ("⁻¹", "^-1"),
        ("$", ""),
        ("{", ""),
        ("}", ""),
        ("*", ""),
    ] {
        t = t.replace(from, to);
    }
    let mut t = t.split_whitespace().collect::<Vec<_>>().join(" ");
    // "4 × 10^4" and "4×10^4" are "4e4"
    while let Some(k) = t.find("10^").filter(|&k| t[..k].trim_end().ends_with('×')) {
        let mantissa_end = t[..k].trim_end().len() - '×'.len_utf8();
        let mantissa = t[..mantissa_end].trim_end();
        let exponent: String = t[k + 3..].chars().take_while(char::is_ascii_digit).collect();
        t = format!("{mantissa}e{exponent}{}", &t[k + 3 + exponent.len()..]);
    }
    for (from, to) in [("N m^-1", "N/m"), ("rad s^-1", "rad/s"), ("m s^-1", "m/s"), (" ,", ","), (" .", ".")] {
        t = t.replace(from, to);
    }
    t
}

/// Every quote of the claims file is the paper's words (`data/paper/cross2000.txt`, the text the
/// project was given), piece by piece: pieces joined by " / ", each maybe opening with a label
/// in brackets that says where it stands.
#[test]
fn paper_quotes_are_the_papers_words() {
    let paper = transliterated(include_str!("../data/paper/cross2000.txt"));
    assert!(paper.contains("k_s is typically between 2e4 and 6e4 N/m for string tensions"), "transliteration");
    assert!(paper.contains("e = 0.745 +- 0.017") && paper.contains("an angle of about 9 deg during"));
    let mut pieces = 0;
    for c in check_claims_file().unwrap() {
        for piece in c.quote.split(" / ") {
            let words = match piece.strip_prefix('(') {
                Some(rest) if rest.contains(") ") => rest.split_once(") ").unwrap().1,
                _ => piece,
            };
            let words = transliterated(words);
            assert!(words.split_whitespace().count() >= 3, "{}: the piece '{piece}' is too short to be a quote", c.id);
            assert!(paper.contains(&words), "{}: '{words}' is not in the paper's text", c.id);
            pieces += 1;
        }
    }
    assert!(pieces >= 54, "{pieces} pieces");
}

/// Every claim says how its value is read (`impact` or `curve`, the column has no default), and
/// the words that decide it are words of its quote.
#[test]
fn every_claims_reading_is_decided_by_its_quote() {
    use racket_impact::experiments::claims::Reading;
    let claims = check_claims_file().unwrap();
    for c in &claims {
        let words = c.reading_words.trim();
        assert!(words.split_whitespace().count() >= 3, "{}: no words decide its reading ({words:?})", c.id);
        assert!(c.quote.contains(words), "{}: '{words}' is not in its quote '{}'", c.id, c.quote);
    }
    // a value the paper read off Fig 5 at the centre of the strings is read off our curve; one of
    // an impact it set up (Fig 4's caption, Fig 8's 15.8 cm) is computed at the node it loads
    let reading = |id: &str| claims.iter().find(|c| c.id == id).unwrap().reading;
    assert_eq!(reading("fig5_centre_e_a_soft"), Reading::Curve);
    assert_eq!(reading("fig4_e_a"), Reading::Impact);
    assert_eq!(reading("fig8_theta_r4_50lb"), Reading::Impact);
    // a claims file whose row does not say how it is read, or says it another way, does not parse
    use racket_impact::experiments::claims::parse_claims;
    let text = racket_impact::report::CLAIMS_CSV;
    assert!(parse_claims(text).is_ok());
    for (from, to) in [(",curve,", ",,"), (",curve,", ",node,"), (",impact,", ",Impact,")] {
        assert!(text.contains(from));
        assert!(parse_claims(&text.replacen(from, to, 1)).is_err(), "{from} -> {to} parsed");
    }
    let no_column = text.replacen(",reading,", ",reading_dropped,", 1);
    assert!(parse_claims(&no_column).is_err(), "a file without the reading column parsed");
}
