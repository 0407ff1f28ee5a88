//! The fit: the model's [`Racket`] whose discrete beam reproduces a spec's mass, balance,
//! swingweight and free-free frequency (density by the maximum-entropy tilt of the uniform
//! beam, EI by rescaling),
//! and the impact parameters of a command from a spec and overrides.

use nalgebra::{Matrix2, Vector2};

use super::convert::{Resolved, Shape, Stiffness};
use super::report::FitReport;
use super::spec::{RacketSpec, SWING_AXIS_FROM_BUTT_M};
use crate::error::{Error, Result};
use crate::model::beam::Beam;
use crate::numfmt::fmt_sig;
use crate::params::{self, Ball, Profile, Racket, Strings, TILT_MAX};

/// The model's parameters fitted to a [`RacketSpec`], with the report of the fit.
#[derive(Debug, Clone, PartialEq)]
pub struct Fitted {
    /// The racket (SI units).
    pub racket: Racket,
    /// The string bed.
    pub strings: Strings,
    /// The ball.
    pub ball: Ball,
    /// The friction of a ball on these strings, if the file gives it.
    pub mu: Option<f64>,
    /// The string the file names (`string`), if any.
    pub string: params::StringName,
    /// Targets beside what the discrete model has.
    pub report: FitReport,
}

impl Fitted {
    /// Full impact parameters: this racket, strings and ball with the given impact and
    /// numerics (use the same `segments` as the fit for an exact match of the targets).
    pub fn params(&self, impact: params::Impact, numerics: params::Numerics) -> params::Params {
        let mut oblique = params::Oblique::default();
        if let Some(mu) = self.mu {
            oblique.mu = mu;
        }
        oblique.string = self.string;
        // (the file's own mu beside a string that sets it was refused when it was read)
        let _ = params::strings::apply(&mut oblique, false, false);
        params::Params {
            ball: self.ball,
            strings: self.strings,
            racket: self.racket,
            impact,
            numerics,
            variants: Default::default(),
            oblique,
        }
    }
}

impl RacketSpec {
    /// Fit the model's racket to this spec for a beam of `segments` segments: the discrete
    /// beam reproduces the mass, balance, swingweight and free-free frequency exactly (to
    /// rounding). Errors name the key that cannot be met.
    pub fn to_racket(&self, segments: usize) -> Result<Fitted> {
        params::check_segments(segments)?;
        let r = self.resolve()?;
        let (half_width, head_length) = match r.head {
            Some((l, hw)) => (hw, Some(l)),
            None => (Racket::default().half_width, None),
        };
        let uniform = r.shape.is_none() && r.ratio == [1.0; 4];
        let profile =
            (!uniform).then_some(Profile { knots: r.knots, density: [1.0; 4], stiffness: r.ratio, tilt: [0.0; 2] });
        let mut racket = Racket { length: r.length, mass: r.mass, ei: 1.0, ix: r.ix, half_width, head_length, profile };
        if let Some(shape) = &r.shape {
            let tilt = fit_tilt(&r, shape, &racket, segments)?;
            if let Some(p) = racket.profile.as_mut() {
                p.tilt = tilt;
            }
        }
        racket.ei = match r.stiffness {
            Stiffness::Ei(ei) => ei,
            Stiffness::Frequency(f) => fit_ei(&racket, f, segments)?,
        };
        racket.validate()?;
        let strings = Strings { ks: r.ks };
        strings.validate()?;
        r.ball.validate()?;
        if let Some(mu) = self.mu {
            params::keys::MU.check(mu)?;
        }
        let string = match &self.string {
            Some(text) => params::strings::parse(text)?,
            None => params::StringName::None,
        };
        let mut probe = params::Oblique { string, ..Default::default() };
        params::strings::apply(&mut probe, self.mu.is_some(), false)?;
        let report = self.report(&r, &racket, segments);
        Ok(Fitted { racket, strings, ball: r.ball, mu: self.mu, string, report })
    }
}

/// The mass distribution of the discrete beam of `racket` (with `profile`) on `segments`
/// segments: node positions (m from the tip) and masses normalised to sum to one.
fn node_weights(racket: &Racket, segments: usize) -> (Vec<f64>, Vec<f64>) {
    let beam = Beam::new(racket, segments);
    let total = beam.total_mass;
    (beam.x, beam.mass.iter().map(|m| m / total).collect())
}

/// The tilt `[t1, t2]` of the uniform density (`lambda(f) ~ exp(t1 f + t2 f^2)`, `f` the
/// fraction of the length from the tip) whose discrete beam has the spec's balance and
/// swingweight (its mass is the racket's by construction). Of all densities with that mass,
/// balance and swingweight it is the one closest to the paper's uniform beam in relative
/// entropy. Any mass on the racket has `M d^2 < SW < M (d^2 + b (L - b))` with `d` the balance's
/// distance from the swingweight axis and `b` its distance from the butt (all the mass at the
/// two ends is the upper limit); the family, with its tilt bounded by |t| <= 100, covers the
/// interior of that range, not the last few per cent next to either limit (nor, on very coarse
/// beams of 4-6 segments, all of it), and says so when it falls short. Newton's
/// method on the two moments, whose Jacobian is the covariance of the moments with `(f, f^2)`
/// under the node masses (exact for masses `~ exp(t1 f_i + t2 f_i^2)`, close for the lumped
/// ones), with the step halved until the residual falls.
fn fit_tilt(r: &Resolved, shape: &Shape, racket: &Racket, segments: usize) -> Result<[f64; 2]> {
    let (length, mass) = (r.length, r.mass);
    let x_axis = length - SWING_AXIS_FROM_BUTT_M;
    let d = x_axis - shape.x_cm;
    let (sw_lo, sw_hi) = (mass * d * d, mass * (d * d + shape.x_cm * (length - shape.x_cm)));
    let unreachable = |physical: bool| {
        let at = match shape.balance_key {
            "balance_cm" => format!("balance_cm = {}", shape.balance_given),
            key => format!("{key} = {} ({} cm from the butt)", shape.balance_given, fmt_sig(shape.balance_cm, 6)),
        };
        Error::invalid(
            "swingweight_kg_cm2",
            shape.sw_given,
            format!(
                "{}; at {at} and mass_g = {} a swingweight must satisfy {} < swingweight_kg_cm2 < {} kg cm^2 \
                 (all the mass at the balance point, and all of it at the two ends)",
                if physical {
                    "no mass distribution on the racket has this balance and swingweight"
                } else {
                    "the fitted density family (the uniform beam tilted by exp(t1 f + t2 f^2), |t| <= 100) does not \
                     reach this swingweight, though some mass distribution could: its limits are those of the family, \
                     within the physical range"
                },
                fmt_sig(mass * 1000.0, 6),
                fmt_sig(round_sig(true, sw_lo * 1.0e4, 4).max(super::spec::ranges::SWINGWEIGHT.0), 4),
                fmt_sig(round_sig(false, sw_hi * 1.0e4, 4).min(super::spec::ranges::SWINGWEIGHT.1), 4)
            ),
        )
    };
    // a balance and mass whose whole physical range lies outside the keys' allowed swingweights
    // are what is wrong, not the swingweight: no allowed value could be suggested
    let (sw_min, sw_max) = super::spec::ranges::SWINGWEIGHT;
    if sw_lo * 1.0e4 >= sw_max || sw_hi * 1.0e4 <= sw_min {
        return Err(Error::invalid(
            shape.balance_key,
            shape.balance_given,
            format!(
                "at mass_g = {} every possible swingweight of this balance lies in {}..{} kg cm^2, outside the \
                 allowed swingweight_kg_cm2 {sw_min}..{sw_max}: check the balance and the mass",
                fmt_sig(mass * 1000.0, 6),
                fmt_sig(round_sig(true, sw_lo * 1.0e4, 4), 4),
                fmt_sig(round_sig(false, sw_hi * 1.0e4, 4), 4)
            ),
        ));
    }
    if !(shape.swingweight > sw_lo && shape.swingweight < sw_hi) {
        return Err(unreachable(true));
    }
    let moments = |tilt: [f64; 2]| {
        let mut trial = *racket;
        if let Some(p) = trial.profile.as_mut() {
            p.tilt = tilt;
        }
        let (x, w) = node_weights(&trial, segments);
        let u: Vec<f64> = x.iter().map(|x| x / length).collect();
        let mean = |g: &dyn Fn(usize) -> f64| w.iter().enumerate().map(|(i, w)| w * g(i)).sum::<f64>();
        let m1 = mean(&|i| x[i]);
        let m2 = mean(&|i| (x_axis - x[i]).powi(2));
        let residual = [(m1 - shape.x_cm) / length, (mass * m2 - shape.swingweight) / shape.swingweight];
        let cov = |f: &dyn Fn(usize) -> f64, g: &dyn Fn(usize) -> f64| mean(&|i| f(i) * g(i)) - mean(f) * mean(g);
        let first = |i: usize| x[i] / length;
        let second = |i: usize| mass * (x_axis - x[i]).powi(2) / shape.swingweight;
        let jacobian = Matrix2::new(
            cov(&first, &|i| u[i]),
            cov(&first, &|i| u[i] * u[i]),
            cov(&second, &|i| u[i]),
            cov(&second, &|i| u[i] * u[i]),
        );
        (Vector2::new(residual[0], residual[1]), jacobian)
    };
    let mut tilt = [0.0, 0.0];
    let (mut res, mut jac) = moments(tilt);
    for _ in 0..100 {
        if res.amax() < 1.0e-14 {
            return Ok(tilt);
        }
        let Some(step) = jac.lu().solve(&res) else { break };
        let mut scale = 1.0;
        let mut improved = false;
        for _ in 0..40 {
            let trial = [tilt[0] - scale * step[0], tilt[1] - scale * step[1]];
            if trial.iter().all(|t| t.is_finite() && t.abs() <= TILT_MAX) {
                let (r2, j2) = moments(trial);
                if r2.norm() < res.norm() {
                    (tilt, res, jac, improved) = (trial, r2, j2, true);
                    break;
                }
            }
            scale *= 0.5;
        }
        if !improved {
            break;
        }
    }
    // the residual cannot fall further: the rounding floor, or a combination so near the
    // limits that the tilt runs out of range
    if res.amax() < 1.0e-11 {
        Ok(tilt)
    } else {
        Err(unreachable(false))
    }
}

/// The `ei` whose discrete beam has the first free-free frequency `f_hz`: `omega^2` is
/// proportional to `ei` at fixed masses, so one solve and a rescale suffice; a second pass
/// removes any rounding.
fn fit_ei(racket: &Racket, f_hz: f64, segments: usize) -> Result<f64> {
    let mut trial = Racket { ei: 100.0, ..*racket };
    for _ in 0..2 {
        let f = Beam::new(&trial, segments).modes().frequency_hz(1);
        if !(f.is_finite() && f > 0.0) {
            return Err(Error::invalid(
                "frequency_hz",
                f_hz,
                "the discrete beam has no finite fundamental frequency for this mass and length",
            ));
        }
        trial.ei *= (f_hz / f).powi(2);
    }
    let (lo, hi) = const { params::keys::EI.range() };
    if trial.ei.is_finite() && (lo..=hi).contains(&trial.ei) {
        Ok(trial.ei)
    } else {
        Err(Error::invalid(
            "frequency_hz",
            f_hz,
            format!(
                "this frequency needs EI = {} N m^2 for this mass and length, outside the model's {}..={} N m^2",
                fmt_sig(trial.ei, 4),
                crate::numfmt::readable(lo),
                crate::numfmt::readable(hi)
            ),
        ))
    }
}

/// Impact parameters for a command: the defaults (the paper's racket, ball and strings with the
/// `hat` load), replaced by the racket description when one is given (fitted at the segment
/// count the overrides ask for, else the default 39), hit by default at the centre of the string
/// face on the long axis ([`keys::face_centre_impact`](params::keys::face_centre_impact): the
/// head outline's centre, or 16 cm from the tip on a racket without one) unless `x` and `r` say
/// otherwise, then the config-file and flag overrides (`overrides` = flags already merged over
/// the config). Validated. Returns the fit too.
pub fn resolve(spec: Option<&RacketSpec>, overrides: &params::Overrides) -> Result<(params::Params, Option<Fitted>)> {
    let mut p = params::Params::default();
    let fitted = match spec {
        Some(spec) => {
            let f = spec.to_racket(overrides.segments.unwrap_or(p.numerics.segments))?;
            p.racket = f.racket;
            p.strings = f.strings;
            p.ball = f.ball;
            if let Some(mu) = f.mu {
                p.oblique.mu = mu;
            }
            p.oblique.string = f.string;
            Some(f)
        }
        None => None,
    };
    params::keys::face_centre_impact(&mut p);
    // a racket file's head outline is the string face: its width is the file's to say (an
    // override would move the face's edge away from the racket described, and let an impact
    // land outside its head)
    if let (Some(hw), Some(_)) = (overrides.half_width, p.racket.head_length) {
        if hw != p.racket.half_width {
            return Err(crate::error::Error::invalid(
                "half-width",
                hw,
                format!(
                    "the racket file's head outline sets the string face (half-width {} m): change head_width_cm (or head_size_sq_in) in the file",
                    crate::numfmt::sig(p.racket.half_width, 4)
                ),
            ));
        }
    }
    overrides.apply(&mut p);
    let file_mu = fitted.as_ref().is_some_and(|f| f.mu.is_some());
    params::strings::apply(&mut p.oblique, overrides.mu.is_some() || file_mu, overrides.mu_ss.is_some())?;
    p.validate()?;
    Ok((p, fitted))
}

/// `x` rounded up (or down) to `digits` significant digits.
fn round_sig(up: bool, x: f64, digits: usize) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let e = 10f64.powi(x.abs().log10().floor() as i32 - digits as i32 + 1);
    let r = if up { (x / e).ceil() * e } else { (x / e).floor() * e };
    // undo representation error of the product (e.g. 273.90000000000003)
    let snapped: f64 = fmt_sig(r, digits).parse().unwrap_or(r);
    snapped
}
