//! A [`RacketSpec`] checked and converted to SI units: every range check and every rule for
//! groups of alternative keys, with the messages that name the key.

use super::spec::{ranges, RacketSpec, BALANCE_POINT_CM, DEFAULT_HANDLE_LENGTH_CM, DEFAULT_HEAD_END_FRACTION};
use super::spec::{DEFAULT_HEAD_ASPECT, KP_PER_CM, LB_KG, SQ_IN_CM2};
use crate::error::{Error, Result};
use crate::numfmt::fmt_sig;
use crate::params::{self, Ball, Strings};

/// How the frame stiffness is given.
#[derive(Debug, Clone, Copy)]
pub(super) enum Stiffness {
    Frequency(f64),
    Ei(f64),
}

/// Balance (from the tip, m), swingweight (kg m^2) and the key the balance was given as.
#[derive(Debug, Clone, Copy)]
pub(super) struct Shape {
    pub(super) x_cm: f64,
    pub(super) swingweight: f64,
    /// The swingweight as given, kg cm^2.
    pub(super) sw_given: f64,
    pub(super) balance_key: &'static str,
    /// The balance as given, in its key's unit.
    pub(super) balance_given: f64,
    /// The balance from the butt, cm.
    pub(super) balance_cm: f64,
}

/// A checked spec in SI units.
#[derive(Debug, Clone, Copy)]
pub(super) struct Resolved {
    pub(super) length: f64,
    pub(super) mass: f64,
    pub(super) shape: Option<Shape>,
    pub(super) ix: f64,
    pub(super) stiffness: Stiffness,
    pub(super) ratio: [f64; 4],
    pub(super) head: Option<(f64, f64)>,
    pub(super) knots: [f64; 4],
    pub(super) ks: f64,
    pub(super) ball: Ball,
}

/// `v` within `lo..=hi`, else an error naming the key, the allowed range and the unit.
fn check(key: &'static str, v: f64, what: &str, unit: &str, (lo, hi): (f64, f64)) -> Result<f64> {
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(Error::invalid(key, v, format!("{what} must satisfy {lo} <= {key} <= {hi} {unit}")))
    }
}

/// At most one of a group of alternative keys; `label` names the group in errors.
fn one_of<T: Copy>(label: &'static str, keys: &[(&'static str, Option<T>)]) -> Result<Option<(&'static str, T)>> {
    let given: Vec<_> = keys.iter().filter_map(|(k, v)| v.map(|v| (*k, v))).collect();
    match given.as_slice() {
        [] => Ok(None),
        [one] => Ok(Some(*one)),
        _ => {
            let names: Vec<&str> = keys.iter().map(|(k, _)| *k).collect();
            Err(Error::invalid(label, "(several given)", format!("give only one of {}", names.join(", "))))
        }
    }
}

/// Exactly one of a group of alternative keys.
fn required<T: Copy>(label: &'static str, keys: &[(&'static str, Option<T>)]) -> Result<(&'static str, T)> {
    one_of(label, keys)?.ok_or_else(|| {
        let names: Vec<&str> = keys.iter().map(|(k, _)| *k).collect();
        Error::invalid(label, "(missing)", format!("give exactly one of {}", names.join(", ")))
    })
}

/// The value, or `None` with the problem kept.
fn keep<T>(errors: &mut Vec<Error>, r: Result<T>) -> Option<T> {
    r.map_err(|e| errors.push(e)).ok()
}

/// One problem as it is; several as [`Error::Several`] (one line, `N problems: first; ...`).
fn combine(mut errors: Vec<Error>) -> Error {
    if errors.len() == 1 {
        return errors.remove(0);
    }
    Error::Several(errors)
}

impl RacketSpec {
    /// The spec checked and in SI units; every problem is reported (several as one line).
    pub(super) fn resolve(&self) -> Result<Resolved> {
        use ranges::*;
        // every independent key is checked, and all the problems reported at once
        let mut errors: Vec<Error> = Vec::new();
        let length_cm = keep(
            &mut errors,
            match required("length_in/length_cm", &[("length_in", self.length_in), ("length_cm", self.length_cm)]) {
                Ok(("length_in", v)) => check("length_in", v, "racket length", "in", LENGTH_IN).map(|v| v * 2.54),
                Ok((_, v)) => check("length_cm", v, "racket length", "cm", LENGTH_CM),
                Err(e) => Err(e),
            },
        );
        let mass = keep(
            &mut errors,
            self.mass_g
                .ok_or_else(|| Error::invalid("mass_g", "(missing)", "give the strung mass in g"))
                .and_then(|g| check("mass_g", g, "strung mass", "g", MASS_G))
                .map(|g| g / 1000.0),
        );
        let shape = length_cm.and_then(|l| keep(&mut errors, self.shape(l, l / 100.0)));
        let ix = keep(
            &mut errors,
            self.twistweight_kg_cm2
                .ok_or_else(|| {
                    Error::invalid(
                        "twistweight_kg_cm2",
                        "(missing)",
                        "give the twistweight (moment about the long axis)",
                    )
                })
                .and_then(|tw| check("twistweight_kg_cm2", tw, "twistweight", "kg cm^2", TWISTWEIGHT))
                .map(|tw| tw / 1.0e4),
        );
        let stiffness = keep(&mut errors, self.stiffness());
        let head = length_cm.and_then(|l| keep(&mut errors, self.head(l)));
        let knots = match (length_cm, head) {
            (Some(l), Some(head)) => keep(&mut errors, self.knots(l, head)),
            _ => None,
        };
        let ks = keep(&mut errors, self.ks());
        let ball = keep(&mut errors, self.ball());
        match (length_cm, mass, shape, ix, stiffness, head, knots, ks, ball) {
            (
                Some(l),
                Some(mass),
                Some(shape),
                Some(ix),
                Some((stiffness, ratio)),
                Some(head),
                Some(knots),
                Some(ks),
                Some(ball),
            ) if errors.is_empty() => {
                Ok(Resolved { length: l / 100.0, mass, shape, ix, stiffness, ratio, head, knots, ks, ball })
            }
            _ => Err(combine(errors)),
        }
    }

    /// Balance and swingweight, both or neither.
    fn shape(&self, length_cm: f64, length: f64) -> Result<Option<Shape>> {
        use ranges::*;
        let balance = one_of(
            "balance_cm/balance_pts_hl",
            &[("balance_cm", self.balance_cm), ("balance_pts_hl", self.balance_pts_hl)],
        )?;
        Ok(match (balance, self.swingweight_kg_cm2) {
            (None, None) => None,
            (Some((key, _)), None) => {
                return Err(Error::invalid(
                    "swingweight_kg_cm2",
                    "(missing)",
                    format!("{key} needs swingweight_kg_cm2 (give both, or neither for the paper's uniform beam)"),
                ))
            }
            (None, Some(_)) => {
                return Err(Error::invalid(
                    "balance_cm/balance_pts_hl",
                    "(missing)",
                    "swingweight_kg_cm2 needs a balance (give both, or neither for the paper's uniform beam)",
                ))
            }
            (Some((key, b)), Some(sw)) => {
                let (balance_key, balance_cm) = if key == "balance_cm" {
                    ("balance_cm", b)
                } else {
                    let pts = check("balance_pts_hl", b, "balance", "points head-light", BALANCE_PTS)?;
                    ("balance_pts_hl", 0.5 * length_cm - pts * BALANCE_POINT_CM)
                };
                if !(balance_cm.is_finite() && balance_cm > 0.0 && balance_cm < length_cm) {
                    return Err(Error::invalid(
                        balance_key,
                        b,
                        format!("the balance point must lie on the racket, 0 < balance < {length_cm} cm from the butt"),
                    ));
                }
                let sw = check("swingweight_kg_cm2", sw, "swingweight", "kg cm^2", SWINGWEIGHT)?;
                Some(Shape {
                    x_cm: length - balance_cm / 100.0,
                    swingweight: sw / 1.0e4,
                    sw_given: sw,
                    balance_key,
                    balance_given: b,
                    balance_cm,
                })
            }
        })
    }

    /// The frame stiffness (frequency or EI) and its relative profile.
    fn stiffness(&self) -> Result<(Stiffness, [f64; 4])> {
        use ranges::*;
        let stiffness = match required(
            "frequency_hz/ei_n_m2",
            &[("frequency_hz", self.frequency_hz), ("ei_n_m2", self.ei_n_m2)],
        )? {
            ("frequency_hz", f) => {
                Stiffness::Frequency(check("frequency_hz", f, "free-free frequency", "Hz", FREQUENCY_HZ)?)
            }
            (_, ei) => Stiffness::Ei(check("ei_n_m2", ei, "bending stiffness", "N m^2", EI)?),
        };
        let ratio = self.stiffness_ratio.unwrap_or([1.0; 4]);
        for &r in &ratio {
            check("stiffness_ratio", r, "relative stiffness at each knot", "", STIFFNESS_RATIO)?;
        }
        Ok((stiffness, ratio))
    }

    /// The knots of the profiles, fractions of the length: tip, head end, handle start, butt.
    fn knots(&self, length_cm: f64, head: Option<(f64, f64)>) -> Result<[f64; 4]> {
        use ranges::*;
        let head_end = head.map_or(DEFAULT_HEAD_END_FRACTION * length_cm, |(l, _)| l * 100.0);
        let handle_cm = match self.handle_length_cm {
            Some(h) => check("handle_length_cm", h, "handle length", "cm", HANDLE_CM)?,
            None => DEFAULT_HANDLE_LENGTH_CM,
        };
        if head_end + handle_cm >= length_cm {
            return Err(Error::invalid(
                "handle_length_cm",
                handle_cm,
                format!(
                    "the head end ({} cm from the tip{}) and the handle must leave a throat: head + handle < length = {} cm",
                    fmt_sig(head_end, 4),
                    if head.is_some() { "" } else { ", by default 48 % of the length" },
                    fmt_sig(length_cm, 4)
                ),
            ));
        }
        Ok([0.0, head_end / length_cm, 1.0 - handle_cm / length_cm, 1.0])
    }

    /// The string-plane stiffness `k_s`, N/m, from whichever tension key is given.
    fn ks(&self) -> Result<f64> {
        use ranges::*;
        let tension = one_of(
            "tension_lb/tension_kg/string_bed_n_per_m/dt_kp_cm",
            &[
                ("tension_lb", self.tension_lb),
                ("tension_kg", self.tension_kg),
                ("string_bed_n_per_m", self.string_bed_n_per_m),
                ("dt_kp_cm", self.dt_kp_cm),
            ],
        )?;
        let ks = match tension {
            None => Strings::default().ks,
            Some(("tension_lb", t)) => params::ks_from_tension_lb(check("tension_lb", t, "tension", "lb", TENSION_LB)?),
            Some(("tension_kg", t)) => {
                params::ks_from_tension_lb(check("tension_kg", t, "tension", "kg", TENSION_KG)? / LB_KG)
            }
            Some(("string_bed_n_per_m", k)) => {
                check("string_bed_n_per_m", k, "string-bed stiffness", "N/m", STRING_BED)?
            }
            Some((_, dt)) => check("dt_kp_cm", dt, "dynamic tension", "kp/cm", DT_KP_CM)? * KP_PER_CM,
        };
        Ok(ks)
    }

    /// The ball: the paper's, with any keys given replaced.
    fn ball(&self) -> Result<Ball> {
        use ranges::*;
        let mut ball = Ball::default();
        if let Some(b) = &self.ball {
            if let Some(m) = b.mass_g {
                ball.mass = check("ball.mass_g", m, "ball mass", "g", BALL_MASS_G)? / 1000.0;
            }
            if let Some(k1) = b.k1_n_per_m {
                ball.k1 = check("ball.k1_n_per_m", k1, "ball compression stiffness", "N/m", BALL_K1)?;
            }
            if let Some(p) = b.p {
                if !(p.is_finite() && p > 1.0 && p <= 10.0) {
                    return Err(Error::invalid("ball.p", p, "hysteresis exponent must satisfy 1 < p <= 10"));
                }
                ball.p = p;
            }
        }
        Ok(ball)
    }

    /// The string face as (length, half-width) in m, if any head keys are given.
    fn head(&self, length_cm: f64) -> Result<Option<(f64, f64)>> {
        use ranges::*;
        let by_size = self.head_length_cm.is_some() || self.head_width_cm.is_some();
        let by_area = self.head_size_sq_in.is_some() || self.head_aspect.is_some();
        let (l_cm, w_cm) = match (by_size, by_area) {
            (false, false) => return Ok(None),
            (true, true) => return Err(Error::invalid(
                "head_length_cm/head_size_sq_in",
                "(several given)",
                "give either head_length_cm with head_width_cm, or head_size_sq_in (with head_aspect, or its default)",
            )),
            (true, false) => {
                let (Some(l), Some(w)) = (self.head_length_cm, self.head_width_cm) else {
                    let missing = if self.head_length_cm.is_none() { "head_length_cm" } else { "head_width_cm" };
                    return Err(Error::invalid(missing, "(missing)", "head_length_cm and head_width_cm go together"));
                };
                (
                    check("head_length_cm", l, "head length", "cm", HEAD_CM)?,
                    check("head_width_cm", w, "head width", "cm", HEAD_CM)?,
                )
            }
            (false, true) => {
                let Some(a) = self.head_size_sq_in else {
                    return Err(Error::invalid(
                        "head_size_sq_in",
                        "(missing)",
                        "head_aspect needs head_size_sq_in (the aspect alone gives no size)",
                    ));
                };
                let r = self.head_aspect.unwrap_or(DEFAULT_HEAD_ASPECT);
                let area = check("head_size_sq_in", a, "head size", "sq in", HEAD_SQ_IN)? * SQ_IN_CM2;
                let aspect = check("head_aspect", r, "head length / width", "", HEAD_ASPECT)?;
                let w = (4.0 * area / (std::f64::consts::PI * aspect)).sqrt();
                (aspect * w, w)
            }
        };
        if l_cm >= length_cm {
            let (key, given) = match (self.head_length_cm, self.head_size_sq_in) {
                (Some(l), _) => ("head_length_cm", l),
                (_, a) => ("head_size_sq_in", a.unwrap_or(f64::NAN)),
            };
            return Err(Error::invalid(
                key,
                given,
                format!("the head ({} cm long) must be shorter than the racket ({length_cm} cm)", fmt_sig(l_cm, 4)),
            ));
        }
        Ok(Some((l_cm / 100.0, 0.5 * w_cm / 100.0)))
    }
}
