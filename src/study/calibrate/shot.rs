//! From a measured row to the impact that measured it: the shot's conditions (speed, angle,
//! incoming spin, tension, string, how the racket was held, where it was hit) on the
//! parameters a command starts from, and the result field its quantity is. A row whose shot the
//! model cannot run (a ratio or threshold over several impacts, a support the model has no
//! variant for, a string without friction data) is refused with the reason.

use crate::error::{Error, Result};
use crate::numfmt::quoted;
use crate::params::{ks_from_tension_lb, strings, Grip, Params, SolverKind, StringName};
use crate::solve::outcome::{Field, FIELDS};
use crate::study::measured::Measured;

/// A head-clamped racket: a frame too heavy to move or twist and too stiff to bend stands for
/// the clamp: its mass, kg.
pub const CLAMPED_MASS: f64 = 1.0e6;
/// The clamped frame's moment of inertia about its long axis, kg m^2.
pub const CLAMPED_IX: f64 = 1.0e4;
/// The clamped frame's bending stiffness, N m^2 (the largest valid): its first mode near
/// 190 Hz keeps the modal solver's free vibration after the impact short (a frame this heavy
/// with the paper's EI rings at 0.07 Hz, which costs the solver 16 times as much to follow)
/// and, at this mass, moves the ball's spin by about 1e-6 of itself.
pub const CLAMPED_EI: f64 = 1.0e9;

/// The parameter keys every row sets (its shot): not flags of `calibrate`.
pub const ROW_SETS: [&str; 4] = ["v1", "angle-deg", "spin-rpm", "grip"];

/// The supports (`support` column) the model has a racket for.
pub const SUPPORTS: [&str; 4] = ["clamped", "clamped_head", "free", "hand_held"];

/// Clamp the frame of `p` (the rig of the TWU spin table and of Cross's head-clamped tests).
pub fn clamp(p: &mut Params) {
    p.racket.mass = CLAMPED_MASS;
    p.racket.ix = CLAMPED_IX;
    p.racket.ei = CLAMPED_EI;
}

/// The column of `row` that sets parameter `key` in its shot, if it does (a flag or config
/// value for it then does not reach that row).
pub fn sets(row: &Measured, key: &str) -> Option<&'static str> {
    let clamped = matches!(row.support.trim(), "clamped" | "clamped_head");
    let named = !row.string.trim().is_empty();
    match key {
        "v1" => Some("ball_speed_m_s"),
        "angle-deg" => Some("angle_deg"),
        "spin-rpm" => Some("spin_in_rpm"),
        "ks" if row.tension_lb.is_some() => Some("string_tension_lb"),
        "x" if row.impact_x_from_tip_m.is_some() => Some("impact_x_from_tip_m"),
        "r" if row.impact_r_m.is_some() => Some("impact_r_m"),
        "string" | "mu" | "mu-ss" if named => Some("string"),
        "mass" | "ix" | "ei" if clamped => Some("support"),
        _ => None,
    }
}

/// The error of a row the model cannot run.
fn refuse(row: &Measured, why: impl Into<String>) -> Error {
    Error::invalid("row", &row.id, why)
}

/// The string a row names: its `--string` id or its name in data/strings (a row's string may
/// add the gauge or material after the name, as the TWU table's do); `None` for no string.
pub fn string_of(row: &Measured) -> Result<StringName> {
    let text = row.string.trim();
    if text.is_empty() {
        return Ok(StringName::None);
    }
    let entry = strings::all().iter().find(|e| text == e.id || text.starts_with(&e.name)).ok_or_else(|| {
        let known: Vec<&str> = strings::all().iter().map(|e| e.id.as_str()).collect();
        refuse(
            row,
            format!(
                "string '{}' is not in data/strings (its friction is unknown; known: {})",
                quoted(text),
                known.join(", ")
            ),
        )
    })?;
    strings::parse(&entry.id)
}

/// The result field a row's quantity is, with its unit checked against the row's (a pure
/// number's unit may be empty, `1` or `ratio`).
pub fn field_of(row: &Measured) -> Result<&'static Field> {
    let field = FIELDS.iter().find(|f| f.key == row.quantity).ok_or_else(|| {
        refuse(
            row,
            format!(
                "quantity '{}' is not a result of one impact (a ratio, threshold or statistic over several impacts \
                 or strokes is not a shot the model can run); give one of the result fields, e.g. spin_out_rpm, \
                 rebound_angle_deg, e_a, e_t",
                quoted(&row.quantity)
            ),
        )
    })?;
    let pure = |u: &str| u.is_empty() || u == "1" || u == "ratio";
    let unit = row.unit.trim();
    if !(unit == field.unit || (field.unit.is_empty() && pure(unit))) {
        let want = if field.unit.is_empty() { "empty, 1 or ratio" } else { field.unit };
        return Err(refuse(row, format!("unit '{}' is not the unit of {} ({want})", quoted(unit), field.key)));
    }
    Ok(field)
}

/// The impact of a row on `base`: its speed, angle from the normal and incoming spin (empty:
/// none), its tension (empty: `base`'s string stiffness), its string (empty: `base`'s friction),
/// its support (clamped, free, hand-held: the grip is the row's; a hand-held row runs the fd
/// solver) and impact point (empty: `base`'s). The parameters are validated.
pub fn shot(base: &Params, row: &Measured) -> Result<Params> {
    let mut p = *base;
    p.impact.v1 = row.ball_speed_m_s.ok_or_else(|| refuse(row, "no ball speed (column ball_speed_m_s)"))?;
    p.oblique.angle_deg = row.angle_deg.unwrap_or(0.0);
    p.oblique.spin_rpm = row.spin_in_rpm.unwrap_or(0.0);
    if let Some(t) = row.tension_lb {
        if !(t.is_finite() && t > 0.0) {
            return Err(refuse(row, format!("string tension {t} lb is not a positive number")));
        }
        p.strings.ks = ks_from_tension_lb(t);
    }
    let string = string_of(row)?;
    if string != StringName::None {
        p.oblique.string = string;
        (p.oblique.mu, p.oblique.mu_ss) = p.oblique.friction();
    }
    match row.support.trim() {
        "clamped" | "clamped_head" => {
            p.variants.grip = Grip::Free;
            clamp(&mut p);
        }
        "free" => p.variants.grip = Grip::Free,
        "hand_held" => {
            p.variants.grip = Grip::Hand;
            // the modal solver has no hand: such a row runs the explicit one
            p.numerics.solver = SolverKind::Fd;
        }
        "" => return Err(refuse(row, format!("no support: say how the racket was held ({})", SUPPORTS.join(", ")))),
        other => {
            return Err(refuse(
                row,
                format!("support '{}' has no racket in the model (it has {})", quoted(other), SUPPORTS.join(", ")),
            ))
        }
    }
    if let Some(x) = row.impact_x_from_tip_m {
        p.impact.x = x;
    }
    if let Some(r) = row.impact_r_m {
        p.impact.r = r;
    }
    p.validate().map_err(|e| refuse(row, format!("its shot is not a valid impact: {e}")))?;
    Ok(p)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::measured;

    fn row(text: &str) -> Measured {
        let head = "id,quantity,value,unit,ball_speed_m_s,angle_deg,spin_in_rpm,string_tension_lb,string,support";
        measured::parse(&format!("{head}\n{text}\n"), "lab.csv").unwrap().remove(0)
    }

    #[test]
    fn a_table_row_is_the_clamped_shot_on_its_string() {
        let p = shot(
            &Params::paper(),
            &row("L1,spin_out_rpm,1700,rpm,25.03,40,-3820,52,Luxilon ALU Power 16 (polyester),clamped"),
        )
        .unwrap();
        assert_eq!((p.impact.v1, p.oblique.angle_deg, p.oblique.spin_rpm), (25.03, 40.0, -3820.0));
        assert_eq!(p.strings.ks, ks_from_tension_lb(52.0));
        assert_eq!(p.oblique.string, StringName::AluPower16);
        assert_eq!(p.oblique.mu, strings::entry(StringName::AluPower16).unwrap().mu);
        assert_eq!((p.racket.mass, p.racket.ix, p.racket.ei), (CLAMPED_MASS, CLAMPED_IX, CLAMPED_EI));
        // the string's id names it too
        let q =
            shot(&Params::paper(), &row("L1,spin_out_rpm,1700,rpm,25.03,40,-3820,52,alu-power-16,clamped")).unwrap();
        assert_eq!(p, q);
    }

    #[test]
    fn a_row_the_model_cannot_run_is_refused_with_the_reason() {
        let base = Params::paper();
        let cases = [
            ("L1,spin_ratio,1.2,ratio,25,40,0,,,clamped", "not a result of one impact"),
            ("L1,spin_out_rpm,1700,deg,25,40,0,,,clamped", "unit 'deg'"),
            ("L1,spin_out_rpm,1700,rpm,,40,0,,,clamped", "no ball speed"),
            ("L1,spin_out_rpm,1700,rpm,25,40,0,,,", "no support"),
            ("L1,spin_out_rpm,1700,rpm,25,40,0,,,clamped_handle", "support 'clamped_handle'"),
            ("L1,spin_out_rpm,1700,rpm,25,40,0,,Mystery 17,clamped", "not in data/strings"),
            ("L1,spin_out_rpm,1700,rpm,25,95,0,,,clamped", "not a valid impact"),
        ];
        for (text, says) in cases {
            let msg = shot(&base, &row(text)).and_then(|_| field_of(&row(text)).map(|_| ())).unwrap_err().to_string();
            assert!(msg.contains("L1") && msg.contains(says), "{text}: {msg}");
        }
        assert_eq!(field_of(&row("L1,e_a,0.4,,25,0,0,,,free")).unwrap().key, "e_a");
    }
}
