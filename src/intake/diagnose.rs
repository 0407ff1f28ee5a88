//! The physics-validity checks of a run, returned as [`Diagnostic`]s with its result (the
//! command line prints them; a library caller reads them): parameters outside their usual
//! ranges (declared with the parameters), a first frame frequency no racket has, a racket
//! density no frame has, a named string without friction data, a twist beyond the small-angle
//! model, a ball squashed past its radius and a re-contact after separation.

use crate::diagnostic::{Diagnostic, Kind};
use crate::numfmt::sig;
use crate::params::{keys, Params, TangentialLaw};
use crate::solve::ImpactResult;

/// The diagnostics of one impact `r` of `params`, in the order the command line prints them:
/// the parameters, the twist, the ball's compression, a re-contact.
pub fn impact(params: &Params, r: &ImpactResult) -> Vec<Diagnostic> {
    let mut out = parameters([params], &[]);
    out.extend(twist(r.theta_end_deg));
    out.extend(squash(params, r.y0_m));
    if r.recontact {
        out.push(Diagnostic::new(
            Kind::BeyondModel,
            "recontact",
            "the vibrating frame met the ball again after separation (re-contact not modelled)",
        ));
    }
    if r.tangential_chatter {
        out.push(Diagnostic::new(
            Kind::BeyondModel,
            keys::TANGENTIAL.key,
            "the ball sat on the edge between gripping at the friction limit and sliding, and the switch chattered until \
             it was cut short: the spin and slip fraction hang on the solver's step there (fd, the reference, and modal \
             can part by about 1e-3; SPEC.md section 6, Known limit)",
        ));
    }
    out
}

/// One diagnostic for each parameter of `params` outside its usual range (the first unusual
/// value it takes), a first frame frequency no racket has, a racket density no frame has and a
/// named string without friction data, once each; none for the parameters `skip`, which a
/// command sets from its own options and checks in their terms.
pub fn parameters<'a>(params: impl IntoIterator<Item = &'a Params>, skip: &[&str]) -> Vec<Diagnostic> {
    let mut out: Vec<Diagnostic> = Vec::new();
    for p in params {
        let f1 = crate::model::basis::Basis::of(&p.racket, p.numerics.segments).omega[0] / (2.0 * std::f64::consts::PI);
        let (lo, hi) = keys::USUAL_F1_HZ;
        let frequency = (!(lo..=hi).contains(&f1)).then(|| {
            Diagnostic::new(
                Kind::Unusual,
                "f1",
                format!(
                    "first frame frequency f1 = {} Hz is outside the usual {lo}..{hi} Hz of rackets (from EI, mass and length; computed anyway)",
                    sig(f1, 4)
                ),
            )
        });
        let unusual = keys::ALL.iter().filter_map(|spec| {
            let line = spec.unusual(keys::value_number(spec.key, p)?)?;
            Some(Diagnostic::new(Kind::Unusual, spec.key, line))
        });
        let density = crate::racket::density_warning(&p.racket).map(|s| Diagnostic::new(Kind::Unusual, "density", s));
        let string = crate::params::strings::missing_data_note(&p.oblique)
            .map(|s| Diagnostic::new(Kind::MissingData, keys::STRING.key, s));
        for d in unusual.chain(frequency).chain(density).chain(string) {
            if !skip.contains(&d.field.as_str()) && !out.iter().any(|o| o.field == d.field) {
                out.push(d);
            }
        }
    }
    out
}

/// The diagnostics the impact commands give for a fitted racket (unusual values, frequency,
/// density), at the face centre with the default numerics on the fit's `segments` segments.
pub fn racket(fitted: &crate::racket::Fitted, segments: usize) -> Vec<Diagnostic> {
    let numerics = crate::params::Numerics { segments, ..Default::default() };
    let mut p = fitted.params(crate::params::Impact::default(), numerics);
    keys::face_centre_impact(&mut p);
    parameters([&p], &[])
}

/// A twist at the end of an impact beyond the small-angle model (Eq 7).
pub fn twist(theta_end_deg: f64) -> Option<Diagnostic> {
    (theta_end_deg.abs() > keys::SMALL_TWIST_DEG).then(|| {
        Diagnostic::new(
            Kind::BeyondModel,
            "theta_end_deg",
            format!(
                "twist theta_end = {} deg is beyond the small-angle model's usual |theta| <= {} deg (computed anyway; check ks, ix and r)",
                sig(theta_end_deg, 3),
                keys::SMALL_TWIST_DEG
            ),
        )
    })
}

/// The ball's largest compression `y0_m` beyond its radius: the paper's linear ball (F = k1 y)
/// is then outside its range, and the radius law's friction lever `R - delta` is clamped at
/// zero.
pub fn squash(params: &Params, y0_m: f64) -> Option<Diagnostic> {
    let radius = params.oblique.ball_radius;
    (y0_m > radius).then(|| {
        let lever = if !params.oblique.is_normal() && params.oblique.tangential.has(TangentialLaw::Radius) {
            "; the radius law's friction lever R - delta is clamped at 0, so the spin results rest on that clamp"
        } else {
            ""
        };
        Diagnostic::new(
            Kind::BeyondModel,
            "y0_m",
            format!(
                "ball compression y0 = {} mm exceeds the ball's radius {} mm: the paper's linear ball (F = k1 y) is \
                 outside its range (computed anyway; check v1 and k1){lever}",
                sig(1e3 * y0_m, 3),
                sig(1e3 * radius, 3)
            ),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_paper_impact_raises_no_doubt_and_a_typo_one() {
        let p = Params::default();
        assert_eq!(impact(&p, &crate::simulate(&p).unwrap()), vec![]);
        let mut q = p;
        q.strings.ks = 40.0; // N/m for kN/m: valid, unusual
        let d = parameters([&q, &q], &[]);
        assert_eq!(d.len(), 1, "once per parameter: {d:?}");
        assert_eq!((d[0].kind, d[0].field.as_str()), (Kind::Unusual, "ks"));
        assert!(d[0].sentence.starts_with("ks = 40 N/m is outside the usual"), "{}", d[0].sentence);
        assert!(parameters([&q], &["ks"]).is_empty(), "a skipped key is not checked");
    }

    #[test]
    fn twist_and_squash_beyond_the_model() {
        assert!(twist(keys::SMALL_TWIST_DEG).is_none());
        assert_eq!(twist(-20.0).unwrap().field, "theta_end_deg");
        let p = Params::default();
        assert!(squash(&p, 0.5 * p.oblique.ball_radius).is_none());
        assert_eq!(squash(&p, 2.0 * p.oblique.ball_radius).unwrap().kind, Kind::BeyondModel);
    }
}
