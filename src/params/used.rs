//! Which parameters an impact actually uses: a value given for a parameter the selected model
//! does not read (friction at normal incidence, a hand's stiffness with a free grip, a time step
//! for the modal solver) is refused where it is a flag and named as unused where it comes from a
//! shared config file, never silently ignored.

use super::{Frame, Grip, Params, SolverKind, StringLaw, TangentialLaw};

/// Whether a value given for a parameter the impact does not use is accepted with a note or
/// refused (issue 32): a *property* of the racket, ball or strings that this impact does not
/// exercise (friction at normal incidence, `ix` on the long axis) is accepted with one note, so
/// that a script describing one racket and ball can loop over impact points and angles; an
/// *option of a method* the chosen method cannot honour (`dt` with the modal solver, a hand's
/// stiffness with the free grip, `mu-ss` without the sliding bed) is refused.
pub fn is_refused(key: &str, params: &Params) -> bool {
    let impact_only = params.oblique.is_normal() || params.impact.r == 0.0;
    match key {
        // unused only because of where and how the ball arrives: the impact
        "azimuth-deg" | "mu" | "kt" | "ball-radius" | "ball-inertia-factor" | "tangential" | "string"
            if params.oblique.is_normal() =>
        {
            false
        }
        k if params.oblique.is_normal() && TangentialLaw::readers(k).next().is_some() => false,
        "half-width" | "ix" if impact_only => false,
        _ => true,
    }
}

/// Why a parameter of the tangential contact is not used at normal incidence.
const OBLIQUE_ONLY: &str =
    "used only for an oblique or spinning ball (at normal incidence without spin no tangential force acts)";

/// Why the impact `params` does not use parameter `key`, or `None` if it does.
pub fn unused_reason(key: &str, params: &Params) -> Option<&'static str> {
    let v = &params.variants;
    match key {
        "azimuth-deg" | "mu" | "kt" | "ball-radius" | "ball-inertia-factor" | "tangential" | "string"
            if params.oblique.is_normal() =>
        {
            Some(OBLIQUE_ONLY)
        }
        // a parameter of a mechanism (the keys of the registry, `tangential_mechanisms!`)
        k if params.oblique.is_normal() && TangentialLaw::readers(k).next().is_some() => Some(OBLIQUE_ONLY),
        k if TangentialLaw::readers(k).next().is_some() && !params.oblique.tangential.reads(k) => {
            Some(mechanism_only(k))
        }
        "hand-stiffness" | "hand-damping" | "grip-length" if v.grip != Grip::Hand => Some("used only with grip = hand"),
        "string-stiffening" | "stiffening-deflection" if v.strings != StringLaw::Stiffening => {
            Some("used only with strings = stiffening")
        }
        "half-width" if params.impact.r == 0.0 && params.oblique.is_normal() => {
            Some("used only as the bound of |r| off the long axis (the impact is at r = 0)")
        }
        "ix" if params.impact.r == 0.0 && params.oblique.is_normal() => {
            Some("used only off the long axis (r != 0) or for an oblique ball: nothing twists the frame at r = 0")
        }
        "ei" | "solver" if v.frame == Frame::Rigid => Some("not used by the rigid frame (a closed form)"),
        "dt" if v.frame == Frame::Rigid || params.numerics.solver == SolverKind::Modal => {
            Some("used only by the fd solver (the modal solver and the rigid frame take no time step)")
        }
        _ => None,
    }
}

/// Why a parameter that only some tangential laws read is not used: the laws that read it
/// (from the registry of mechanisms, `tangential_mechanisms!`).
fn mechanism_only(key: &str) -> &'static str {
    static REASONS: std::sync::OnceLock<Vec<(&'static str, String)>> = std::sync::OnceLock::new();
    let reasons = REASONS.get_or_init(|| {
        let read = super::keys::ALL.iter().map(|s| s.key).filter(|&k| TangentialLaw::readers(k).next().is_some());
        read.into_iter()
            .map(|k| {
                let laws: Vec<&str> = TangentialLaw::readers(k).map(|l| l.name()).collect();
                let (last, rest) = laws.split_last().expect("a key some law reads");
                (k, format!("used only by the tangential laws {} and {last}", rest.join(", ")))
            })
            .collect()
    });
    reasons.iter().find(|(k, _)| *k == key).map_or("not used by this tangential law", |(_, why)| why.as_str())
}

/// The first of `keys` that none of the impacts `params` uses, with the reason (for the
/// impacts of one command: a key is used if any of them uses it).
pub fn first_unused<'a>(keys: &[&'a str], params: &[Params]) -> Option<(&'a str, &'static str)> {
    keys.iter().find_map(|&k| {
        let reasons: Vec<Option<&'static str>> = params.iter().map(|p| unused_reason(k, p)).collect();
        match reasons.first() {
            Some(Some(why)) if reasons.iter().all(Option::is_some) => Some((k, *why)),
            _ => None,
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_papers_impact_uses_its_own_parameters_and_not_the_variants() {
        let mut p = Params::default();
        p.impact.r = 0.0; // on the long axis, as the commands' default point
        for key in ["x", "r", "ks", "ei", "mass", "v1", "segments", "load", "dt", "solver", "frame", "angle-deg"] {
            assert_eq!(unused_reason(key, &p), None, "{key}");
        }
        for key in ["mu", "kt", "hand-damping", "string-stiffening", "ix"] {
            assert!(unused_reason(key, &p).is_some(), "{key}");
        }
        let mut off_axis = p;
        off_axis.impact.r = 0.05;
        assert_eq!(unused_reason("ix", &off_axis), None);
        assert_eq!(unused_reason("half-width", &off_axis), None);
        let mut oblique = p;
        oblique.oblique.angle_deg = 30.0;
        assert_eq!(unused_reason("mu", &oblique), None);
        assert_eq!(first_unused(&["x", "mu"], &[p, oblique]), None);
        assert_eq!(first_unused(&["x", "mu"], &[p]).map(|(k, _)| k), Some("mu"));
    }
}
