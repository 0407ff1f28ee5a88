//! The fit: the model's [`Racket`] whose discrete beam reproduces a spec's mass, balance,
//! swingweight and free-free frequency (density profile by a 3x3 linear solve, EI by rescaling),
//! and the impact parameters of a command from a spec and overrides.

use nalgebra::{Matrix2, Matrix3, Vector2, Vector3};

use super::convert::{Resolved, Shape, Stiffness};
use super::report::FitReport;
use super::spec::{RacketSpec, SWING_AXIS_FROM_BUTT_M};
use crate::error::{Error, Result};
use crate::model::beam::Beam;
use crate::params::{self, Ball, Profile, Racket, Strings};
use crate::render::table::fmt_sig;

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
        let mut density = [1.0; 4];
        if let Some(shape) = &r.shape {
            let d = fit_density(&r, shape, segments)?;
            density = [d[0], d[1], d[2], d[2]];
        }
        let uniform = r.shape.is_none() && r.ratio == [1.0; 4];
        let profile = (!uniform).then_some(Profile { knots: r.knots, density, stiffness: r.ratio });
        let mut racket = Racket { length: r.length, mass: r.mass, ei: 1.0, ix: r.ix, half_width, head_length, profile };
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

/// Node masses of the three basis densities (tip, head end, handle) on the discrete beam, in
/// the units of a density of 1 kg per unit of relative length: `m = L * sum_k d_k B_k` for a
/// density `d_k` (kg/m) at the knots. `Beam::new` scales its lumped masses to the racket's mass;
/// the hat functions sum to one, so the unscaled masses sum to the basis function's integral,
/// which is known exactly and undoes the scaling.
fn basis_masses(knots: [f64; 4], length: f64, segments: usize) -> ([Vec<f64>; 3], Vec<f64>) {
    let [_, k1, k2, _] = knots;
    let bases = [
        ([1.0, 0.0, 0.0, 0.0], 0.5 * k1),
        ([0.0, 1.0, 0.0, 0.0], 0.5 * k2),
        ([0.0, 0.0, 1.0, 1.0], 0.5 * (k2 - k1) + (1.0 - k2)),
    ];
    let mut x = Vec::new();
    let masses = bases.map(|(density, integral)| {
        let profile = Profile { knots, density, stiffness: [1.0; 4] };
        let racket = Racket { length, mass: 1.0, profile: Some(profile), ..Racket::default() };
        let beam = Beam::new(&racket, segments);
        x = beam.x;
        beam.mass.iter().map(|m| m * integral).collect()
    });
    (masses, x)
}

/// Knot densities (tip, head end, handle; arbitrary common scale) whose discrete beam has the
/// spec's mass, balance and swingweight; an error names balance or swingweight when no
/// positive density does.
fn fit_density(r: &Resolved, shape: &Shape, segments: usize) -> Result<[f64; 3]> {
    let (basis, x) = basis_masses(r.knots, r.length, segments);
    let x_axis = r.length - SWING_AXIS_FROM_BUTT_M;
    // moments of each basis: mass, first moment about the tip, second moment about the axis
    let moments = basis.clone().map(|m| {
        let m0: f64 = m.iter().sum();
        let m1: f64 = m.iter().zip(&x).map(|(m, x)| m * x).sum();
        let m2: f64 = m.iter().zip(&x).map(|(m, x)| m * (x_axis - x).powi(2)).sum();
        [m0, m1, m2]
    });
    let a = Matrix3::from_fn(|i, k| moments[k][i]);
    let b = Vector3::new(r.mass, r.mass * shape.x_cm, shape.swingweight);
    let d = a.lu().solve(&b);
    if let Some(d) = d.filter(|d| d.iter().all(|v| v.is_finite() && *v > 0.0)) {
        return Ok([d[0], d[1], d[2]]);
    }
    // Diagnose. With positive densities the centre of mass is a weighted mean of the bases'
    // centroids, so it must lie between them.
    let centroids = moments.map(|m| m[1] / m[0]);
    let (lo, hi) = centroids.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &c| (l.min(c), h.max(c)));
    // the stated ranges are rounded inwards, so every value they admit is accepted
    let to_butt = |x: f64, up: bool| fmt_sig(round_sig(up, (r.length - x) * 100.0, 4), 4);
    if !(shape.x_cm > lo && shape.x_cm < hi) {
        return Err(Error::invalid(
            shape.balance_key,
            shape.balance_given,
            format!(
                "no positive density (linear over head and throat, constant handle) balances there; \
                 this racket's profile reaches {} < balance < {} cm from the butt",
                to_butt(hi, true),
                to_butt(lo, false)
            ),
        ));
    }
    // At this balance the positive densities form a segment whose ends have one density 0;
    // the swingweight is linear along it, so its range is spanned by the ends.
    let mut sw_ends = Vec::new();
    for zero in 0..3 {
        let [i, j] = match zero {
            0 => [1, 2],
            1 => [0, 2],
            _ => [0, 1],
        };
        let m = Matrix2::new(moments[i][0], moments[j][0], moments[i][1], moments[j][1]);
        if let Some(c) = m.lu().solve(&Vector2::new(r.mass, r.mass * shape.x_cm)) {
            if c.iter().all(|v| v.is_finite() && *v >= 0.0) {
                sw_ends.push(c[0] * moments[i][2] + c[1] * moments[j][2]);
            }
        }
    }
    let (sw_lo, sw_hi) = sw_ends.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &s| (l.min(s), h.max(s)));
    let range = if sw_lo.is_finite() && sw_hi.is_finite() {
        let at = match shape.balance_key {
            "balance_cm" => format!("balance_cm = {}", shape.balance_given),
            key => format!("{key} = {} ({} cm from the butt)", shape.balance_given, fmt_sig(shape.balance_cm, 6)),
        };
        format!(
            "; at {at} this profile realises {} < swingweight_kg_cm2 < {} kg cm^2",
            fmt_sig(round_sig(true, sw_lo * 1.0e4, 4), 4),
            fmt_sig(round_sig(false, sw_hi * 1.0e4, 4), 4)
        )
    } else {
        String::new()
    };
    Err(Error::invalid(
        "swingweight_kg_cm2",
        shape.sw_given,
        format!(
            "this balance and swingweight cannot be realised by a positive density (linear over head and \
             throat, constant handle){range}"
        ),
    ))
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
                "this frequency needs EI = {} N m^2 for this mass and length, outside the model's {lo:e}..={hi:e} N m^2",
                fmt_sig(trial.ei, 4)
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
