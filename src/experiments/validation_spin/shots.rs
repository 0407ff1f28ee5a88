//! The shots of the spin measurements set up on the model: the TWU table's clamped shot (from
//! its measured rows, as `calibrate` reads any row: [`crate::study::calibrate::shot`]), the
//! hand-held and clamped pair of Cross and Lindsey (2011), the grip-stop scan and the tour
//! forehand.

use super::super::{Context, CENTRE_X};
use crate::error::{Error, Result};
use crate::params::{ks_from_tension_lb, strings, Grip, Params, StringName, TangentialLaw};
use crate::solve::simulate;
use crate::solve::swing::Swing;
use crate::study::calibrate::shot;
use crate::study::measured::Measured;

/// The 14 rows of the TWU table.
pub const TABLE_IDS: [&str; 14] =
    ["M001", "M002", "M003", "M004", "M005", "M006", "M007", "M008", "M009", "M010", "M011", "M012", "M013", "M014"];

/// The TWU shot's in-plane direction, degrees from the long axis: across the face (a clamped
/// frame does not move, so the direction only orients the spin).
pub const AZIMUTH_DEG: f64 = 90.0;

/// The TWU shot: 56 mph (25.03 m/s) at 40 deg from the normal with 3820 rpm of backspin
/// (data/measured, rows M001-M014).
pub const TWU_SPEED: f64 = 25.03;
/// See [`TWU_SPEED`].
pub const TWU_ANGLE_DEG: f64 = 40.0;
/// See [`TWU_SPEED`] (negative: backspin).
pub const TWU_SPIN_RPM: f64 = -3820.0;

/// The string of a measured row (its name in the TWU table begins with the table's name).
pub fn string_of(row: &Measured) -> Result<StringName> {
    let entry = strings::all()
        .iter()
        .find(|e| row.string.starts_with(&e.name))
        .ok_or_else(|| Error::invalid("string", &row.string, "not in data/strings"))?;
    strings::parse(&entry.id)
}

/// The string tension of a measured row, lb (an error naming the row if it has none).
pub fn tension_of(row: &Measured) -> Result<f64> {
    row.tension_lb.ok_or_else(|| Error::invalid("measurements", &row.id, "the row states no string tension"))
}

/// The TWU shot's racket support and incoming ball on any parameters: the clamp
/// ([`shot::clamp`]) and the ball of the table.
pub fn set_twu_shot(p: &mut Params) {
    shot::clamp(p);
    p.impact.v1 = TWU_SPEED;
    p.oblique.angle_deg = TWU_ANGLE_DEG;
    p.oblique.azimuth_deg = AZIMUTH_DEG;
    p.oblique.spin_rpm = TWU_SPIN_RPM;
}

/// The TWU shot under `law` on the context's racket at the centre, strung at `tension_lb` with
/// `string` (its friction from data/strings).
pub fn twu_shot(ctx: &Context, law: TangentialLaw, string: StringName, tension_lb: f64) -> Params {
    let mut p = ctx.paper_params(CENTRE_X, ks_from_tension_lb(tension_lb));
    set_twu_shot(&mut p);
    p.oblique.tangential = law;
    p.oblique.string = string;
    (p.oblique.mu, p.oblique.mu_ss) = p.oblique.friction();
    p
}

/// The shot of one table row at `angle_deg` from the normal under `law`.
pub fn table_shot(ctx: &Context, law: TangentialLaw, row: &Measured, angle_deg: f64) -> Result<Params> {
    let mut p = twu_shot(ctx, law, string_of(row)?, tension_of(row)?);
    p.oblique.angle_deg = angle_deg;
    Ok(p)
}

/// The hand-held over clamped spin of Cross and Lindsey (2011, M016): 22.8 m/s at 40 deg; the
/// incoming backspin is not given in the abstract, the TWU table's 3820 rpm stands in; the
/// paper's racket at 60 lb, held in a hand or clamped.
pub fn hand_and_clamped(ctx: &Context, law: TangentialLaw) -> (Params, Params) {
    let mut clamped = twu_shot(ctx, law, StringName::None, 60.0);
    clamped.impact.v1 = 22.8;
    let mut hand = ctx.paper_params(CENTRE_X, ks_from_tension_lb(60.0));
    hand.impact.v1 = 22.8;
    hand.oblique = clamped.oblique;
    hand.variants.grip = Grip::Hand;
    (hand, clamped)
}

/// The smallest whole incidence angle (1-85 deg) at which the ball slides throughout, on the
/// clamped racket at 25 m/s without spin (default string), under the laws and constants of
/// `base` (a TWU shot).
pub fn grip_stop_deg(base: &Params) -> Result<f64> {
    for a in 1..=85 {
        let mut p = *base;
        p.oblique.spin_rpm = 0.0;
        p.oblique.angle_deg = f64::from(a);
        if simulate(&p)?.slip_fraction >= 1.0 - 1e-12 {
            return Ok(f64::from(a));
        }
    }
    Ok(85.0)
}

/// The tour forehand's swing along a path of `path_deg`: a 30 m/s racket against a 20 m/s ball
/// without spin.
pub fn forehand(path_deg: f64) -> Swing {
    Swing { racket_speed: 30.0, path_deg, incoming: 20.0, incoming_spin_rpm: 0.0 }
}

/// The forehand's outgoing spin on `base` (the free paper racket at 60 lb), rpm.
pub fn forehand_spin(base: &Params, path_deg: f64) -> Result<f64> {
    Ok(forehand(path_deg).hit(base)?.spin_rpm)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::measured;

    #[test]
    fn every_table_row_names_a_string_of_the_table() {
        let rows = measured::rows(&TABLE_IDS).unwrap();
        for r in &rows {
            assert!(string_of(r).is_ok(), "{r:?}");
            assert!(r.tension_lb == Some(52.0) || r.tension_lb == Some(62.0));
        }
        assert_eq!(rows.iter().filter(|r| string_of(r).unwrap() == StringName::Tcs16).count(), 2);
    }

    /// A table row read as `calibrate` reads it is the experiment's shot.
    #[test]
    fn calibrate_runs_the_experiment_s_shot() {
        let ctx = Context::paper();
        for row in measured::rows(&TABLE_IDS).unwrap() {
            let mine = table_shot(&ctx, TangentialLaw::Loss, &row, TWU_ANGLE_DEG).unwrap();
            let mut base = ctx.paper_params(CENTRE_X, ks_from_tension_lb(60.0));
            base.oblique.azimuth_deg = AZIMUTH_DEG;
            base.oblique.tangential = TangentialLaw::Loss;
            let theirs = shot::shot(&base, &row).unwrap();
            assert_eq!(mine, theirs, "{}", row.id);
        }
    }
}
