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
        "mu-ss" | "ball-ex" | "ball-kdyn" if params.oblique.is_normal() => false,
        "half-width" | "ix" if impact_only => false,
        _ => true,
    }
}

/// Why the impact `params` does not use parameter `key`, or `None` if it does.
pub fn unused_reason(key: &str, params: &Params) -> Option<&'static str> {
    let v = &params.variants;
    match key {
        "azimuth-deg" | "mu" | "kt" | "ball-radius" | "ball-inertia-factor" | "tangential" | "string" | "mu-ss"
        | "ball-ex" | "ball-kdyn"
            if params.oblique.is_normal() =>
        {
            Some(
                "used only for an oblique or spinning ball (at normal incidence without spin no tangential force acts)",
            )
        }
        "mu-ss" if !params.oblique.tangential.has(TangentialLaw::Bed) => {
            Some("used only by the tangential laws bed and physical (strings sliding over each other)")
        }
        "ball-ex" if !params.oblique.tangential.has(TangentialLaw::Loss) => {
            Some("used only by the tangential laws loss and physical (the damper on the ball's tangential spring)")
        }
        "ball-kdyn" if !params.oblique.tangential.has(TangentialLaw::Radius)
            && !params.oblique.tangential.has(TangentialLaw::Offset) =>
        {
            Some("used only by the tangential laws radius, offset and physical (the ball's compression under the normal force)")
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
