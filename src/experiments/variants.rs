//! Model variants beside the paper's model (issue 6): which of the paper's simplifications
//! matters where.
//!
//! | id | question |
//! |---|---|
//! | `variant_rigid` | the textbook rigid racket against the flexible beam, along the racket |
//! | `variant_grip` | a hand on the grip against the paper's free racket, along the racket |
//! | `variant_strings` | strings that stiffen with deflection against the paper's linear strings, vs speed |
//!
//! All use the paper's racket, ball and numerics (node load, N = 39) with r = 0.

use super::{col, line, node_positions, on_right, paper_params, scaled, styled, sweep, Experiment, CENTRE_X};
use crate::error::Result;
use crate::params::{Frame, Grip, Params, StringLaw};
use crate::render::plot::{Chart, LineStyle, VLine};
use crate::render::table::Table;

/// String stiffness of the comparisons along the racket, N/m (the paper's 60 lb).
const KS: f64 = 4.0e4;

/// Rigid against flexible frame.
pub const RIGID: Experiment = Experiment {
    id: "variant_rigid",
    title: "Rigid racket (closed form) against the flexible beam: e_A along the racket, ks 4e4 N/m, r 0",
    paper_ref: "p. 2: rigid-body models with an assumed COR vs the beam; p. 5: no vibration at the node",
    run: || run_rigid(RIGID.id),
    chart: chart_rigid,
};

/// Hand-held against free racket.
pub const GRIP: Experiment = Experiment {
    id: "variant_grip",
    title: "Hand-held against free racket: e_A along the racket, ks 4e4 N/m, r 0",
    paper_ref: "p. 2: the ball leaves before the impulse reflected off the hand returns (Brody 1997; Cross 1999a)",
    run: || run_grip(GRIP.id),
    chart: chart_grip,
};

/// Stiffening against linear strings.
pub const STRINGS: Experiment = Experiment {
    id: "variant_strings",
    title: "Strings stiffening 10 % at 4 cm against linear strings: e_A at the centre vs incident speed",
    paper_ref: "p. 4: k_s rises ~10 % at large deflections; 'of little consequence'",
    run: || run_strings(STRINGS.id),
    chart: chart_strings,
};

/// The paper's racket at the nodes of its N = 39 beam up to `x_max` (m), r = 0, ks 4e4.
fn along_to(x_max: f64, variant: impl Fn(&mut Params)) -> Vec<Params> {
    let xs = node_positions(&paper_params(0.0, KS));
    xs.iter()
        .filter(|&&x| x <= x_max)
        .map(|&x| {
            let mut p = paper_params(x, KS);
            variant(&mut p);
            p
        })
        .collect()
}

/// [`along_to`] over the whole racket.
fn along(variant: impl Fn(&mut Params)) -> Vec<Params> {
    along_to(f64::INFINITY, variant)
}

fn run_rigid(id: &str) -> Result<Table> {
    let beam = sweep(&along(|_| {}))?;
    let rigid = sweep(&along(|p| p.variants.frame = Frame::Rigid))?;
    let mut t = Table::new(id, &["x_m", "e_a_beam", "e_a_rigid", "f_vib_beam", "tau_s_beam", "tau_s_rigid"]);
    for ((p, b), r) in along(|_| {}).iter().zip(&beam).zip(&rigid) {
        t.push(vec![p.impact.x.into(), b.e_a.into(), r.e_a.into(), b.f_vib.into(), b.tau_s.into(), r.tau_s.into()])?;
    }
    Ok(t)
}

fn chart_rigid(t: &Table) -> Chart {
    let x = scaled(col(t, "x_m"), 100.0);
    Chart {
        title: "Rigid racket vs flexible beam, ks 4e4 N/m, r 0".into(),
        x_label: "impact distance from the tip x (cm)".into(),
        y_label: "e_A,  f(vib)".into(),
        y2_label: Some("impact duration tau (ms)".into()),
        x_log: false,
        x_range: Some((0.0, 71.0)),
        y_range: Some((-0.1, 0.9)),
        y2_range: Some((0.0, 9.0)),
        curves: vec![
            line("e_A, flexible beam (the paper)", x.clone(), col(t, "e_a_beam"), 0),
            styled(line("e_A, rigid racket", x.clone(), col(t, "e_a_rigid"), 4), LineStyle::Dashed),
            line("f(vib), beam", x.clone(), col(t, "f_vib_beam"), 2),
            on_right(styled(line("tau beam (ms)", x.clone(), scaled(col(t, "tau_s_beam"), 1e3), 5), LineStyle::Faint)),
            on_right(styled(line("tau rigid (ms)", x, scaled(col(t, "tau_s_rigid"), 1e3), 6), LineStyle::Faint)),
        ],
        vlines: vec![VLine { x: CENTRE_X * 100.0, label: "mode-1 node (15.8 cm)".into() }],
    }
}

/// A firm grip: ten times the default hand.
const FIRM: f64 = 10.0;

fn run_grip(id: &str) -> Result<Table> {
    // impacts on the head and throat, not on the hand itself
    let base = paper_params(0.0, KS);
    let grip_start = base.racket.length - base.variants.grip_length;
    let free = sweep(&along_to(grip_start, |_| {}))?;
    let hand = sweep(&along_to(grip_start, |p| p.variants.grip = Grip::Hand))?;
    let firm = sweep(&along_to(grip_start, |p| {
        p.variants.grip = Grip::Hand;
        p.variants.hand_stiffness *= FIRM;
        p.variants.hand_damping *= FIRM;
    }))?;
    let mut t =
        Table::new(id, &["x_m", "e_a_free", "e_a_hand", "e_a_firm", "tau_s", "wave_return_s", "f_hand", "f_hand_firm"]);
    for (i, p) in along_to(grip_start, |_| {}).iter().enumerate() {
        let (f, h, m) = (&free[i], &hand[i], &firm[i]);
        t.push(vec![
            p.impact.x.into(),
            f.e_a.into(),
            h.e_a.into(),
            m.e_a.into(),
            f.tau_s.into(),
            wave_return(p, grip_start - p.impact.x, f.tau_s).into(),
            h.f_hand.into(),
            m.f_hand.into(),
        ])?;
    }
    Ok(t)
}

/// Time for a bending wave to run `distance` (m) to the hand and back, s, at the group
/// velocity `2 (EI / (M/L))^(1/4) sqrt(omega)` of the frequency `1 / (2 tau)` that dominates an
/// impact of duration `tau` (bending waves are dispersive; this is the usual estimate). Zero
/// when the impact is on the grip.
fn wave_return(p: &Params, distance: f64, tau: f64) -> f64 {
    if distance <= 0.0 {
        return 0.0;
    }
    let rho_a = p.racket.mass / p.racket.length;
    let omega = std::f64::consts::PI / tau;
    let c_g = 2.0 * (p.racket.ei / rho_a).powf(0.25) * omega.sqrt();
    2.0 * distance / c_g
}

fn chart_grip(t: &Table) -> Chart {
    let x = scaled(col(t, "x_m"), 100.0);
    Chart {
        title: format!(
            "Hand-held vs free racket, ks 4e4 N/m, r 0 (hand: 15 cm grip, mode-1 damping {:.1} %)",
            100.0 * {
                let mut p = paper_params(0.0, KS);
                p.variants.grip = Grip::Hand;
                crate::solver::hand_damping_ratio(&p, 1)
            }
        ),
        x_label: "impact distance from the tip x (cm)".into(),
        y_label: "e_A".into(),
        y2_label: Some("time (ms)".into()),
        x_log: false,
        x_range: Some((0.0, 56.0)),
        y_range: Some((-0.1, 0.9)),
        y2_range: Some((0.0, 12.0)),
        curves: vec![
            line("e_A free (the paper)", x.clone(), col(t, "e_a_free"), 0),
            styled(line("e_A hand 5e3 N/m, 10 N s/m", x.clone(), col(t, "e_a_hand"), 1), LineStyle::Dashed),
            styled(line("e_A firm hand 5e4 N/m, 100 N s/m", x.clone(), col(t, "e_a_firm"), 4), LineStyle::Dashed),
            on_right(styled(
                line("impact duration (ms)", x.clone(), scaled(col(t, "tau_s"), 1e3), 5),
                LineStyle::Faint,
            )),
            on_right(styled(
                line("wave to the hand and back (ms)", x, scaled(col(t, "wave_return_s"), 1e3), 6),
                LineStyle::Faint,
            )),
        ],
        vlines: vec![VLine { x: CENTRE_X * 100.0, label: "mode-1 node (15.8 cm)".into() }],
    }
}

/// Incident speeds of the string comparison, m/s.
fn speeds() -> Vec<f64> {
    (1..=12).map(|i| 5.0 * i as f64).collect()
}

fn run_strings(id: &str) -> Result<Table> {
    let cases = [
        (2.0e4, StringLaw::Linear),
        (2.0e4, StringLaw::Stiffening),
        (KS, StringLaw::Linear),
        (KS, StringLaw::Stiffening),
    ];
    let mut params = Vec::new();
    for &v1 in &speeds() {
        for &(ks, law) in &cases {
            let mut p = paper_params(CENTRE_X, ks);
            p.impact.v1 = v1;
            p.variants.strings = law;
            params.push(p);
        }
    }
    let results = sweep(&params)?;
    let mut t = Table::new(
        id,
        &[
            "v1_m_s",
            "e_a_linear_2e4",
            "e_a_stiffening_2e4",
            "e_a_linear_4e4",
            "e_a_stiffening_4e4",
            "tau_s_stiffening_4e4",
        ],
    );
    for (i, v1) in speeds().iter().enumerate() {
        let r = &results[4 * i..4 * i + 4];
        t.push(vec![
            (*v1).into(),
            r[0].e_a.into(),
            r[1].e_a.into(),
            r[2].e_a.into(),
            r[3].e_a.into(),
            r[3].tau_s.into(),
        ])?;
    }
    Ok(t)
}

fn chart_strings(t: &Table) -> Chart {
    let v = col(t, "v1_m_s");
    Chart {
        title: "Stiffening strings (+10 % at 4 cm) vs linear, centre x 15.8 cm, r 0".into(),
        x_label: "incident ball speed v1 (m/s)".into(),
        y_label: "e_A".into(),
        y2_label: None,
        x_log: false,
        x_range: Some((0.0, 62.0)),
        y_range: Some((0.40, 0.48)),
        y2_range: None,
        curves: vec![
            line("linear, ks 2e4", v.clone(), col(t, "e_a_linear_2e4"), 0),
            styled(line("stiffening, ks 2e4", v.clone(), col(t, "e_a_stiffening_2e4"), 0), LineStyle::Dashed),
            line("linear, ks 4e4", v.clone(), col(t, "e_a_linear_4e4"), 4),
            styled(line("stiffening, ks 4e4", v, col(t, "e_a_stiffening_4e4"), 4), LineStyle::Dashed),
        ],
        vlines: vec![],
    }
}
