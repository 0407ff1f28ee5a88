//! How uncertain a parameter is: a distribution ([`Dist`]: uniform, normal or log-uniform) and
//! where it comes from ([`Uncertainty`]), declared beside the parameter in [`keys`](super::keys)
//! (the declaration, [`super::spec`], holds an [`Uncertainty`]; this file knows nothing of it).
//! The `uncertainty` command and the `robustness` experiment draw their inputs through
//! [`Dist::quantile`] (the inverse distribution function), so a low-discrepancy point in the
//! unit cube maps to the same values everywhere.

use crate::error::{Error, Result};

/// A distribution of one input.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Dist {
    /// Uniform on `[lo, hi]`.
    Uniform { lo: f64, hi: f64 },
    /// Normal with mean and standard deviation.
    Normal { mean: f64, sd: f64 },
    /// Uniform in the logarithm on `[lo, hi]` (`0 < lo`).
    LogUniform { lo: f64, hi: f64 },
}

/// The smallest probability a sample is drawn at (and one less it, the largest): the centre of
/// the first cell of a 23-bit low-discrepancy coordinate, so a normal input stays finite
/// (within 5.3 standard deviations of its mean).
pub const U_MIN: f64 = 0.5 / (1u64 << 23) as f64;

impl Dist {
    /// The value at probability `u` (0 < u < 1): the inverse distribution function.
    pub fn quantile(&self, u: f64) -> f64 {
        match *self {
            Dist::Uniform { lo, hi } => lo + u * (hi - lo),
            Dist::Normal { mean, sd } => mean + sd * normal_quantile(u),
            Dist::LogUniform { lo, hi } => (lo.ln() + u * (hi.ln() - lo.ln())).exp(),
        }
    }

    /// The smallest and largest value a sample can take ([`U_MIN`] and `1 - U_MIN` for a
    /// normal input).
    pub fn extent(&self) -> (f64, f64) {
        match *self {
            Dist::Uniform { lo, hi } | Dist::LogUniform { lo, hi } => (lo, hi),
            Dist::Normal { .. } => (self.quantile(U_MIN), self.quantile(1.0 - U_MIN)),
        }
    }

    /// The text form (`uniform:LO:HI`, `normal:MEAN:SD`, `loguniform:LO:HI`), numbers to six
    /// significant digits.
    pub fn text(&self) -> String {
        use crate::numfmt::sig;
        match *self {
            Dist::Uniform { lo, hi } => format!("uniform:{}:{}", sig(lo, 6), sig(hi, 6)),
            Dist::Normal { mean, sd } => format!("normal:{}:{}", sig(mean, 6), sig(sd, 6)),
            Dist::LogUniform { lo, hi } => format!("loguniform:{}:{}", sig(lo, 6), sig(hi, 6)),
        }
    }

    /// Parse `uniform:LO:HI`, `normal:MEAN:SD` or `loguniform:LO:HI` for parameter `field`:
    /// finite numbers, `LO < HI`, `SD > 0`, `LO > 0` for log-uniform; each violation a one-line
    /// error naming the field and what is allowed.
    pub fn parse(field: &'static str, text: &str) -> Result<Dist> {
        let shape = "a distribution is uniform:LO:HI, normal:MEAN:SD or loguniform:LO:HI";
        let parts: Vec<&str> = text.trim().split(':').collect();
        if parts.len() != 3 {
            return Err(Error::invalid(field, text, shape));
        }
        let number = |s: &str, what: &str| -> Result<f64> {
            // (as a flag's value: a number too small or too large for an f64 is refused as
            // written, not taken as 0 or inf)
            match crate::params::number::parse_number(s) {
                Ok(v) if v.is_finite() => Ok(v),
                Err(why) if s.trim().parse::<f64>().is_ok() => {
                    Err(Error::invalid(field, text, format!("{what} {why} ({shape})")))
                }
                _ => Err(Error::invalid(field, text, format!("{what} must be a finite number ({shape})"))),
            }
        };
        let dist = match parts[0] {
            "uniform" => Dist::Uniform { lo: number(parts[1], "LO")?, hi: number(parts[2], "HI")? },
            "loguniform" => Dist::LogUniform { lo: number(parts[1], "LO")?, hi: number(parts[2], "HI")? },
            "normal" => Dist::Normal { mean: number(parts[1], "MEAN")?, sd: number(parts[2], "SD")? },
            _ => return Err(Error::invalid(field, text, shape)),
        };
        match dist {
            Dist::Uniform { lo, hi } | Dist::LogUniform { lo, hi } if lo >= hi => {
                Err(Error::invalid(field, text, "the range needs LO < HI"))
            }
            Dist::LogUniform { lo, .. } if lo <= 0.0 => {
                Err(Error::invalid(field, text, "a log-uniform range needs 0 < LO < HI"))
            }
            Dist::Normal { sd, .. } if sd <= 0.0 => Err(Error::invalid(field, text, "a normal needs SD > 0")),
            d => Ok(d),
        }
    }
}

/// How many standard deviations either side of its mean a normal input's plausibility is judged
/// over ([`Dist::plausibility_range`]): 99.7 % of its draws (the draws themselves reach
/// [`U_MIN`], 5.3 standard deviations, so rarely that a warning for those would be for almost
/// no sample).
pub const NORMAL_REACH_SD: f64 = 3.0;

impl Dist {
    /// The values whose plausibility is judged: a uniform's or log-uniform's bounds; a normal's
    /// mean +- [`NORMAL_REACH_SD`] standard deviations. With the words saying which.
    pub fn plausibility_range(&self) -> ((f64, f64), String) {
        use crate::numfmt::sig;
        match *self {
            Dist::Uniform { lo, hi } | Dist::LogUniform { lo, hi } => ((lo, hi), "its bounds".to_string()),
            Dist::Normal { mean, sd } => (
                (mean - NORMAL_REACH_SD * sd, mean + NORMAL_REACH_SD * sd),
                format!("mean +- {} sd", sig(NORMAL_REACH_SD, 3)),
            ),
        }
    }
}

/// A parameter's declared uncertainty: its distribution and the source of it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Uncertainty {
    /// The distribution.
    pub dist: Dist,
    /// The paper's value the distribution is about. A claim computed at other values of this
    /// parameter (k_s at several tensions, v1 of Figs 7-8) takes the drawn value as a factor
    /// `drawn / nominal` on each of them.
    pub nominal: f64,
    /// Where it comes from: the paper's page and sentence, a row of `data/measured`, or
    /// "assumed" with the reason.
    pub source: &'static str,
}

/// The standard normal quantile (Acklam's rational approximation, relative error below
/// 1.2e-9 over 0 < u < 1).
pub fn normal_quantile(u: f64) -> f64 {
    const A: [f64; 6] = [
        -3.969683028665376e+01,
        2.209460984245205e+02,
        -2.759285104469687e+02,
        1.38357751867269e+02,
        -3.066479806614716e+01,
        2.506628277459239e+00,
    ];
    const B: [f64; 5] = [
        -5.447609879822406e+01,
        1.615858368580409e+02,
        -1.556989798598866e+02,
        6.680131188771972e+01,
        -1.328068155288572e+01,
    ];
    const C: [f64; 6] = [
        -7.784894002430293e-03,
        -3.223964580411365e-01,
        -2.400758277161838e+00,
        -2.549732539343734e+00,
        4.374664141464968e+00,
        2.938163982698783e+00,
    ];
    const D: [f64; 4] = [7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00, 3.754408661907416e+00];
    const LOW: f64 = 0.02425;
    let tail = |q: f64| {
        let t = (-2.0 * q.ln()).sqrt();
        (((((C[0] * t + C[1]) * t + C[2]) * t + C[3]) * t + C[4]) * t + C[5])
            / ((((D[0] * t + D[1]) * t + D[2]) * t + D[3]) * t + 1.0)
    };
    if u < LOW {
        tail(u)
    } else if u > 1.0 - LOW {
        -tail(1.0 - u)
    } else {
        let q = u - 0.5;
        let r = q * q;
        (((((A[0] * r + A[1]) * r + A[2]) * r + A[3]) * r + A[4]) * r + A[5]) * q
            / (((((B[0] * r + B[1]) * r + B[2]) * r + B[3]) * r + B[4]) * r + 1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_quantile_matches_tabulated_values() {
        // (u, z) from standard tables (10 digits)
        for (u, z) in
            [(0.5, 0.0), (0.975, 1.959963985), (0.05, -1.644853627), (0.001, -3.090232306), (0.9999, 3.719016485)]
        {
            assert!((normal_quantile(u) - z).abs() < 1e-8, "{u}: {}", normal_quantile(u));
        }
        assert!((normal_quantile(0.3) + normal_quantile(0.7)).abs() < 1e-12);
    }

    #[test]
    fn quantiles_of_each_shape() {
        let u = Dist::Uniform { lo: 2.0, hi: 4.0 };
        assert_eq!((u.quantile(0.25), u.extent()), (2.5, (2.0, 4.0)));
        let l = Dist::LogUniform { lo: 1e3, hi: 1e5 };
        assert!((l.quantile(0.5) - 1e4).abs() < 1e-8);
        let n = Dist::Normal { mean: 10.0, sd: 2.0 };
        assert!((n.quantile(0.975) - (10.0 + 2.0 * 1.959963985)).abs() < 1e-7);
        let (lo, hi) = n.extent();
        assert!(lo > 10.0 - 2.0 * 5.4 && lo < 10.0 - 2.0 * 5.2 && (lo + hi - 20.0).abs() < 1e-9, "{lo} {hi}");
    }

    #[test]
    fn specs_parse_or_name_what_is_wrong() {
        assert_eq!(Dist::parse("ks", "uniform:2e4:6e4").unwrap(), Dist::Uniform { lo: 2e4, hi: 6e4 });
        assert_eq!(Dist::parse("ks", "normal:4e4:1e3").unwrap(), Dist::Normal { mean: 4e4, sd: 1e3 });
        assert_eq!(Dist::parse("ks", "loguniform:2e4:6e4").unwrap(), Dist::LogUniform { lo: 2e4, hi: 6e4 });
        let msg = |t: &str| Dist::parse("ks", t).unwrap_err().to_string();
        assert_eq!(msg("uniform:6e4:2e4"), "invalid ks = uniform:6e4:2e4: the range needs LO < HI");
        assert_eq!(msg("normal:4e4:-1"), "invalid ks = normal:4e4:-1: a normal needs SD > 0");
        assert!(msg("loguniform:0:1").contains("0 < LO < HI"));
        assert!(msg("triangle:1:2").contains("uniform:LO:HI, normal:MEAN:SD or loguniform:LO:HI"));
        assert!(msg("uniform:1").contains("uniform:LO:HI"));
        assert!(msg("uniform:a:2").contains("LO must be a finite number"));
        assert!(msg("uniform:1:inf").contains("HI must be a finite number"));
        // as a flag's value: too small or too large for an f64 is refused as written
        assert!(msg("uniform:1e-400:1").contains("LO is too small to represent"), "{}", msg("uniform:1e-400:1"));
        assert!(msg("normal:1:1e400").contains("SD is too large to represent"));
    }
}
