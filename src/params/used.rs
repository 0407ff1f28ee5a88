//! Which impacts use a parameter, read from its declaration ([`UsedWhen`] in
//! [`keys`]), and what a value given for one an impact does not use is told, from
//! its [`Role`]: a property of the racket, ball, strings or shot that the impact does not
//! exercise is accepted with one note; an option of a method that the chosen method cannot honour
//! is refused. The same rule holds for a flag, a config file's key, a swept axis and an
//! uncertain input; none is silently ignored.

use super::keys;
use super::spec::{FlagValue, ParamSpec, Role, UsedWhen, Values};
use super::{Params, TangentialLaw};

/// Why an impact does not use a parameter, and whether a value given for it is refused.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Unused {
    /// Why, in words (`used only with grip = hand`).
    pub why: String,
    /// Whether a value given for it is refused: an option of a method ([`Role::MethodOption`])
    /// that the chosen method (a frame, a grip, a law, a solver) cannot honour. Otherwise it is
    /// noted: a property the impact does not exercise, or an option unused only because of
    /// where and how the ball arrives (a tangential law at normal incidence).
    pub refused: bool,
}

/// Why the impact `params` does not use the parameter `spec`, or `None` if it does.
pub fn unused(spec: &ParamSpec, params: &Params) -> Option<Unused> {
    let (why, by_method) = reason(&spec.used_when, params)?;
    Some(Unused { why, refused: by_method && spec.role == Role::MethodOption })
}

/// Why `params` fails `when`, and whether a method's choice is the cause (not the impact).
fn reason(when: &UsedWhen, params: &Params) -> Option<(String, bool)> {
    let on_axis = params.impact.r == 0.0;
    let because = |why: &str| Some((format!("used only {} ({why})", words(when)), false));
    match *when {
        UsedWhen::Always => None,
        UsedWhen::Oblique if params.oblique.is_normal() => {
            because("at normal incidence without spin no tangential force acts")
        }
        UsedWhen::OffAxis if on_axis => because("the impact is at r = 0"),
        UsedWhen::Twisted if on_axis && params.oblique.is_normal() => {
            Some((format!("used only {}: nothing twists the frame at r = 0", words(when)), false))
        }
        UsedWhen::Oblique | UsedWhen::OffAxis | UsedWhen::Twisted => None,
        UsedWhen::In(selector, names) => {
            // unused where the parameter that selects it is (dt under the rigid frame, mu-ss at
            // normal incidence), for that one's reason
            if let Some(r) = reason(&selector.used_when, params) {
                return Some(r);
            }
            let current = keys::value_text(selector.key, params)?;
            (!selects(selector, names, &current)).then(|| (format!("used only {}", own_words(selector, names)), true))
        }
    }
}

/// Which impacts use a parameter, in words (`for an oblique or spinning ball, with tangential =
/// bed or physical`); `always` for every impact. The help lines and the Python stubs say this.
pub fn words(when: &UsedWhen) -> String {
    match *when {
        UsedWhen::Always => "always".to_string(),
        UsedWhen::Oblique => "for an oblique or spinning ball".to_string(),
        UsedWhen::OffAxis => "off the long axis (r != 0)".to_string(),
        UsedWhen::Twisted => "off the long axis (r != 0) or for an oblique ball".to_string(),
        UsedWhen::In(selector, names) => {
            let own = own_words(selector, names);
            match selector.used_when {
                UsedWhen::Always => own,
                ref inner => match (words(inner), own.strip_prefix("with ")) {
                    (before, Some(rest)) if before.starts_with("with ") => format!("{before} and {rest}"),
                    (before, _) => format!("{before}, {own}"),
                },
            }
        }
    }
}

/// `with KEY = a or b`: the values of the choice `selector` that select any of `names`.
fn own_words(selector: &ParamSpec, names: &[&str]) -> String {
    let values: Vec<&str> = match selector.values {
        Values::Choice(choices) => choices.iter().map(|c| c.name).filter(|v| selects(selector, names, v)).collect(),
        _ => names.to_vec(),
    };
    let values = match values.as_slice() {
        [] => String::new(),
        [one] => one.to_string(),
        [init @ .., last] => format!("{} or {last}", init.join(", ")),
    };
    format!("with {} = {values}", selector.key)
}

/// Whether the value `current` of the choice `selector` selects one of `names`: it is one, or,
/// for the tangential law, it is a law with that mechanism (`physical` has every one).
fn selects(selector: &ParamSpec, names: &[&str], current: &str) -> bool {
    if names.contains(&current) {
        return true;
    }
    let law = |name: &str| TangentialLaw::parse_flag(keys::TANGENTIAL.key, name).ok();
    selector.key == keys::TANGENTIAL.key
        && law(current).is_some_and(|l| names.iter().filter_map(|n| law(n)).any(|m| l.has(m)))
}

/// Whether the tangential law `law` uses the parameter `spec`, by its declaration (`mu-ss`:
/// a law with a mechanism that names it); a parameter no law selects is used by every law.
pub(crate) fn law_uses(spec: &ParamSpec, law: TangentialLaw) -> bool {
    match spec.used_when {
        UsedWhen::In(selector, names) if selector.key == keys::TANGENTIAL.key => selects(selector, names, law.name()),
        _ => true,
    }
}

/// The first of `specs` that none of the impacts `params` uses, with why the first impact does
/// not use it (for the impacts of one command: a parameter is used if any of them uses it).
pub fn first_unused<'a>(specs: &[&'a ParamSpec], params: &[Params]) -> Option<(&'a ParamSpec, Unused)> {
    specs.iter().find_map(|&spec| {
        let first = unused(spec, params.first()?)?;
        params.iter().all(|p| unused(spec, p).is_some()).then_some((spec, first))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::keys::*;

    #[test]
    fn the_papers_impact_uses_its_own_parameters_and_not_the_variants() {
        let mut p = Params::default();
        p.impact.r = 0.0; // on the long axis, as the commands' default point
        for spec in [X, R, KS, EI, MASS, V1, SEGMENTS, LOAD, DT, SOLVER, FRAME, ANGLE_DEG] {
            assert_eq!(unused(&spec, &p), None, "{}", spec.key);
        }
        for spec in [MU, KT, HAND_DAMPING, STRING_STIFFENING, IX] {
            assert!(unused(&spec, &p).is_some(), "{}", spec.key);
        }
        let mut off_axis = p;
        off_axis.impact.r = 0.05;
        assert_eq!(unused(&IX, &off_axis), None);
        assert_eq!(unused(&HALF_WIDTH, &off_axis), None);
        let mut oblique = p;
        oblique.oblique.angle_deg = 30.0;
        assert_eq!(unused(&MU, &oblique), None);
        assert!(first_unused(&[&X, &MU], &[p, oblique]).is_none());
        assert_eq!(first_unused(&[&X, &MU], &[p]).map(|(s, _)| s.key), Some("mu"));
    }

    #[test]
    fn a_property_is_noted_and_a_methods_option_refused() {
        use crate::params::{Frame, SolverKind};
        let mut p = Params::default();
        p.impact.r = 0.0;
        // a method's option the chosen method cannot honour
        let hand = unused(&HAND_STIFFNESS, &p).unwrap();
        assert_eq!(hand, Unused { why: "used only with grip = hand".into(), refused: true });
        let mut modal = p;
        modal.numerics.solver = SolverKind::Modal;
        assert_eq!(unused(&DT, &modal).unwrap(), Unused { why: "used only with solver = fd".into(), refused: true });
        // the rigid frame: its options refused (through the solver it has none of), the
        // racket's stiffness noted, the segments and load rule used (its rigid-body masses and
        // load point are the segmented beam's)
        let mut rigid = p;
        rigid.variants.frame = Frame::Rigid;
        assert!(unused(&DT, &rigid).unwrap().refused && unused(&SOLVER, &rigid).unwrap().refused);
        assert_eq!(unused(&EI, &rigid).unwrap(), Unused { why: "used only with frame = beam".into(), refused: false });
        assert_eq!((unused(&SEGMENTS, &rigid), unused(&LOAD, &rigid)), (None, None));
        // at normal incidence even a method's option is only noted: no method was chosen
        // against it
        assert!(!unused(&TANGENTIAL, &p).unwrap().refused);
        let ball_ex = unused(&BALL_EX, &p).unwrap();
        assert!(ball_ex.why.contains("oblique or spinning ball") && !ball_ex.refused, "{ball_ex:?}");
        // a ball's or strings' property under a law without its mechanism: noted
        let mut oblique = p;
        oblique.oblique.angle_deg = 30.0;
        let mu_ss = unused(&MU_SS, &oblique).unwrap();
        assert_eq!(mu_ss, Unused { why: "used only with tangential = bed or physical".into(), refused: false });
        oblique.oblique.tangential = TangentialLaw::Physical;
        assert_eq!(
            (unused(&MU_SS, &oblique), unused(&BALL_EX, &oblique), unused(&BALL_KDYN, &oblique)),
            (None, None, None)
        );
    }

    #[test]
    fn the_words_compose_the_selectors_own() {
        assert_eq!(words(&X.used_when), "always");
        assert_eq!(words(&DT.used_when), "with frame = beam and solver = fd");
        assert_eq!(words(&MU_SS.used_when), "for an oblique or spinning ball, with tangential = bed or physical");
        assert_eq!(
            words(&BALL_KDYN.used_when),
            "for an oblique or spinning ball, with tangential = offset, radius or physical"
        );
        assert_eq!(words(&GRIP_LENGTH.used_when), "with grip = hand");
    }
}
