//! What string tension does to one racket, in one picture (the `card` command): for a racket
//! (a preset, a spec-sheet file or flags), a string (data/strings) and a range of tensions, five
//! panels against the tension, each the same library call as the command that computes it on
//! its own, so the card never disagrees with `simulate`, `map` or `speed`:
//!
//! | panel | quantity | computed as |
//! |---|---|---|
//! | power | serve and forehand ball speed at the centre and at [`OFF_CENTRE`], change from the reference tension, % | `speed` ([`SpeedRow::head_on`](crate::study::speed::SpeedRow::head_on): `e_A` at the relative speed, `v = e_A v_in + (1 + e_A) v_racket`) |
//! | sweet spot | face area where `e_A >= (1 - f) max e_A`, and where the maximum lies | `map` ([`FaceMap::compute`](crate::study::map::FaceMap::compute): one impact per grid point, the map's solver) |
//! | control | twist at `r = 4 cm`, 30 m/s (Fig 8); the swing angle `omega tau` during the contact | `simulate` |
//! | comfort | vibration energy left in the frame after an impact near the tip and near the throat; the impact duration | `simulate` |
//! | spin | outgoing spin of a topspin forehand, with what its law was validated on ([`spin`]) | `speed`'s stroke ([`Swing::hit`](crate::solve::swing::Swing::hit)) |
//!
//! With `compare` a second racket is drawn beside the first on every panel. On the paper's own
//! racket the card also sets the paper's conclusions beside the model's ([`paper`]).
//!
//! The card sets the impact points, the ball speeds, the incidence and `k_s` (from each
//! tension, [`ks_from_tension_lb`](crate::params::ks_from_tension_lb)) itself ([`CARD_SETS`]);
//! every other parameter comes from the racket, the config file and the flags, as for
//! `simulate`. Its solver and load rule are the
//! configuration's (the maps run the map's solver, as `map` does).
//!
//! Files: [`compute`] runs the impacts and maps into rows, [`table`] writes them as the card's
//! table with its header block, [`figure`] draws the table, [`spin`] reads the spin law's
//! validation status, [`paper`] the paper's conclusions.

pub mod compute;
pub mod figure;
pub mod paper;
pub mod spin;
pub mod table;

use crate::diagnostic::{Diagnostic, Kind};
use crate::error::{Error, Result};
use crate::intake::compare::racket_label;
use crate::intake::Sources;
use crate::params::spec::ParamSpec;
use crate::params::{keys, tension_lb_from_ks, Params};
use crate::solve::swing::Swing;

pub use compute::{Card, Points, Row};

/// The tensions of a card unless given: 45 to 65 lb in nine steps of 2.5 lb (the range players
/// string in; it holds the paper's 50 and 60 lb).
pub const DEFAULT_TENSIONS: &str = "45:65:9";
/// Fewest and most tensions on a card.
pub const TENSION_COUNT: (usize, usize) = (2, 41);
/// The largest tension accepted, lb (as `--compare-tension-lb`).
pub const MAX_TENSION_LB: f64 = 200.0;

/// The racket speed at the impact point of the card's serve, m/s, against a ball at rest (the
/// paper's serve frame, p. 5): the speed at which the paper's racket at 60 lb (e_A 0.42 at the
/// centre) sends off the paper's fast serve, a ball 'accelerated from 0 to 60 m/s' (p. 3):
/// 60 / 1.42 = 42 m/s (the `speeds` experiment's serve).
pub const SERVE_M_PER_S: f64 = 42.0;
/// The racket speed at the impact point of the card's forehand, m/s, and the incoming ball's
/// (the paper's forehand frame, p. 5-6: the racket as fast as the ball, `(1 + 2 e_A) v`): 25 m/s,
/// 90 km/h each, a hard rally forehand (an assumption; the % changes do not depend on it, the
/// model being linear in the speed).
pub const FOREHAND_M_PER_S: f64 = 25.0;
/// The card's off-centre point: (towards the tip from the centre, across the face), m. The
/// paper's Fig 4 impact (x = 10 cm, r = 5 cm) on its racket, whose centre is 15.8 cm from the
/// tip: 5.8 cm towards the tip and 5 cm off the long axis.
pub const OFF_CENTRE: (f64, f64) = (0.058, 0.05);
/// The twist case (Figs 7-8): the ball `r` = 4 cm off the long axis at 30 m/s, at the centre.
pub const TWIST_R: f64 = 0.04;
/// The ball speed of the twist case and of the comfort impacts, m/s (Figs 7-8).
pub const TWIST_V1: f64 = 30.0;
/// The racket's angular speed for the swing angle during the contact, rad/s: the paper's 'as
/// high as 30 rad/s' (p. 1, Introduction; p. 7, Discussion).
pub const SWING_RAD_PER_S: f64 = 30.0;
/// How far from either end of the string face the comfort impacts are, m: 6 cm, the paper's
/// 'near the tip' of Figs 6 and 9 (x = 6 cm); near the throat the same distance from the face's
/// other end.
pub const NEAR_END: f64 = 0.06;
/// The sweet spot: where e_A is within this fraction of its best over the face.
pub const SWEET_WITHIN: f64 = 0.1;
/// The card's map grid unless given (points along the face and across it): twice as fine as
/// `map`'s default in each direction, so that a grid cell is 0.8 x 0.6 cm on the paper's face.
pub const GRID: (usize, usize) = (81, 41);
/// The spin panel's shot: the tour forehand of the spin validation (`validation_spin`'s
/// `forehand_spin_rpm` at a 20 deg swing path, M052-M054): a 30 m/s racket brushing up along a
/// path 20 deg above the horizontal against a 20 m/s ball without spin, at the centre.
pub const SPIN_SHOT: Swing = Swing { racket_speed: 30.0, path_deg: 20.0, incoming: 20.0, incoming_spin_rpm: 0.0 };
/// The preset of the paper's 200 Hz frame (Fig 9), set beside the paper's racket near the tip.
pub const WIDEBODY_PRESET: &str = "paper-widebody-200hz";

/// The parameters the card sets itself, each with why.
pub const CARD_SETS: [(ParamSpec, &str); 7] = {
    use crate::params::keys::{ANGLE_DEG, AZIMUTH_DEG, KS, R, SPIN_RPM, V1, X};
    const POINTS: &str = "the card sets the impact points (centre, off-centre, near the tip and the throat)";
    const SPEEDS: &str = "the card sets the ball speeds (--serve-kmh, --forehand-kmh; 30 m/s for control and comfort)";
    const SHOT: &str = "the card's spin shot is a topspin forehand at normal incidence to the strings' motion";
    [
        (X, POINTS),
        (R, POINTS),
        (V1, SPEEDS),
        (ANGLE_DEG, SHOT),
        (AZIMUTH_DEG, SHOT),
        (SPIN_RPM, SHOT),
        (KS, "the card sets k_s from each tension (--tensions-lb; 4e4 N/m * T / 60 lb): give --reference-lb for your own"),
    ]
};

/// Why the card does not take the parameter `key`, if it sets it itself ([`CARD_SETS`]).
pub fn set_by_card(key: &str) -> Option<&'static str> {
    CARD_SETS.iter().find(|(s, _)| s.key == key).map(|(_, why)| *why)
}

/// The speeds and rates of the strokes a card assumes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Strokes {
    /// Racket speed at the impact point on the serve, m/s (ball at rest).
    pub serve_m_per_s: f64,
    /// Racket speed at the impact point on the forehand, and the incoming ball's, m/s.
    pub forehand_m_per_s: f64,
    /// The racket's angular speed for the swing angle during the contact, rad/s.
    pub swing_rad_per_s: f64,
}

impl Default for Strokes {
    fn default() -> Self {
        Strokes { serve_m_per_s: SERVE_M_PER_S, forehand_m_per_s: FOREHAND_M_PER_S, swing_rad_per_s: SWING_RAD_PER_S }
    }
}

/// km/h per m/s: the card speaks in the `speed` command's default unit.
pub const KMH: f64 = 3.6;

impl Strokes {
    /// Check each speed: finite and in range (in the unit its option is given in).
    pub fn validate(&self) -> Result<()> {
        for (field, v, lo, hi, what) in [
            ("serve-kmh", self.serve_m_per_s * KMH, 1.0, 400.0, "racket speed at the impact point (km/h)"),
            ("forehand-kmh", self.forehand_m_per_s * KMH, 1.0, 400.0, "racket and ball speed (km/h)"),
            ("swing-rad-per-s", self.swing_rad_per_s, 0.0, 200.0, "the racket's angular speed (rad/s)"),
        ] {
            if !(v.is_finite() && (lo..=hi).contains(&v)) {
                return Err(Error::invalid(
                    field,
                    crate::numfmt::sig(v, 6),
                    format!("{what} must satisfy {lo} <= {field} <= {hi}"),
                ));
            }
        }
        Ok(())
    }
}

/// A card: the racket (in [`CardRequest::sources`]), the tensions and what each panel assumes.
#[derive(Debug, Clone)]
pub struct CardRequest {
    /// The racket, config file and flags (the string is the flag `string`).
    pub sources: Sources,
    /// The tensions, as text: `lo:hi:count` (both ends included) or a list `45,50,55`, lb.
    pub tensions_lb: String,
    /// The tension the changes are counted from, lb; `None`: the configuration's own (its k_s
    /// as a tension), which is added to the tensions if it is not one of them.
    pub reference_lb: Option<f64>,
    /// A second racket (file or preset), drawn beside the first.
    pub compare: Option<String>,
    /// The strokes' speeds.
    pub strokes: Strokes,
    /// The sweet spot: e_A within this fraction of its best (0 < f < 1).
    pub sweet_within: f64,
    /// The map grid: points along the face and across it.
    pub grid: (usize, usize),
}

impl Default for CardRequest {
    fn default() -> Self {
        CardRequest {
            sources: Sources { command: "card", not_taken: not_taken(), ..Sources::default() },
            tensions_lb: DEFAULT_TENSIONS.to_string(),
            reference_lb: None,
            compare: None,
            strokes: Strokes::default(),
            sweet_within: SWEET_WITHIN,
            grid: GRID,
        }
    }
}

/// The declared keys the card does not take ([`CARD_SETS`]): a config file's values for them
/// are dropped and named.
pub fn not_taken() -> Vec<&'static str> {
    CARD_SETS.iter().map(|(s, _)| s.key).collect()
}

/// One racket of a card: its label, its configuration (at its own tension, the impact at the
/// centre) and its impact points.
#[derive(Debug, Clone, PartialEq)]
pub struct Variant {
    /// The racket's short name.
    pub label: String,
    /// Its configuration as resolved.
    pub params: Params,
    /// Where the card hits it.
    pub points: Points,
}

/// A card checked and ready to run: its rackets, tensions and reference, and the work it will do.
#[derive(Debug, Clone)]
pub struct Prepared {
    /// What was asked.
    pub request: CardRequest,
    /// The racket (A) and the compared one (B).
    pub variants: Vec<Variant>,
    /// The tensions, ascending, the reference among them, lb.
    pub tensions_lb: Vec<f64>,
    /// The reference tension, lb.
    pub reference_lb: f64,
    /// The paper's 200 Hz frame with A's flags, where A is the paper's racket (its conclusions
    /// are then set beside the model's).
    pub widebody: Option<Params>,
    /// The notes about flags and config keys the card does not use.
    pub noted: Vec<Diagnostic>,
}

/// Parse the tensions: `lo:hi:count` (both ends included, count >= 2) or a list `45,50,55`;
/// each in `0 < T <= 200` lb, none twice; returned ascending.
pub fn parse_tensions(spec: &str) -> Result<Vec<f64>> {
    let bad = |why: String| Error::invalid("tensions-lb", spec, why);
    let number = |text: &str, what: &str| {
        crate::params::number::parse_number(text.trim()).map_err(|why| bad(format!("{what} {why}")))
    };
    let mut values: Vec<f64> = if spec.contains(':') {
        let parts: Vec<&str> = spec.split(':').collect();
        let [lo, hi, count] = parts[..] else {
            return Err(bad("a range is lo:hi:count (both ends included), e.g. 45:65:9".into()));
        };
        let (lo, hi, count) = (number(lo, "lo")?, number(hi, "hi")?, number(count, "count")?);
        let (least, most) = TENSION_COUNT;
        if !(count.fract() == 0.0 && (least as f64..=most as f64).contains(&count)) {
            return Err(bad(format!("the count must be a whole number, {least} <= count <= {most}")));
        }
        if lo.partial_cmp(&hi) != Some(std::cmp::Ordering::Less) {
            return Err(bad("the range must rise: lo < hi".into()));
        }
        let n = count as usize;
        (0..n).map(|i| if i + 1 == n { hi } else { lo + (hi - lo) * i as f64 / (n - 1) as f64 }).collect()
    } else {
        spec.split(',').map(|t| number(t, "tension")).collect::<Result<_>>()?
    };
    if let Some(t) = values.iter().find(|t| !(t.is_finite() && **t > 0.0 && **t <= MAX_TENSION_LB)) {
        return Err(bad(format!(
            "tension {} lb: each must satisfy 0 < T <= {MAX_TENSION_LB} lb",
            crate::numfmt::sig(*t, 6)
        )));
    }
    values.sort_by(f64::total_cmp);
    if values.windows(2).any(|w| w[0] == w[1]) {
        return Err(bad("a tension is given twice: give each once".into()));
    }
    let (least, most) = TENSION_COUNT;
    if !(least..=most).contains(&values.len()) {
        return Err(bad(format!("give {least} to {most} tensions (a card is drawn against the tension)")));
    }
    Ok(values)
}

impl CardRequest {
    /// Check every option and resolve the rackets, before any impact runs: the tensions and the
    /// reference, the strokes, the grid, the impact points on each face, and the flags the card
    /// does not take or none of its impacts uses.
    pub fn prepare(&self) -> Result<Prepared> {
        let mut tensions = parse_tensions(&self.tensions_lb)?;
        self.strokes.validate()?;
        if !(self.sweet_within.is_finite() && self.sweet_within > 0.0 && self.sweet_within < 1.0) {
            return Err(Error::invalid(
                "sweet-within",
                self.sweet_within,
                "the sweet spot's fraction of the best e_A must satisfy 0 < sweet-within < 1",
            ));
        }
        crate::study::map::check_count("nx", self.grid.0)?;
        crate::study::map::check_count("nr", self.grid.1)?;
        let mut variants = vec![self.variant(self.sources.racket.as_deref())?];
        if let Some(b) = &self.compare {
            if self.sources.racket.as_deref() == Some(b.as_str()) {
                return Err(Error::invalid(
                    "compare",
                    b,
                    "is the card's own racket: a racket compared with itself differs nowhere",
                ));
            }
            // (a racket the card cannot read is named by the option that gave it)
            variants.push(self.variant(Some(b)).map_err(|e| match e {
                Error::InvalidParameter { field: "racket", value, allowed } => {
                    Error::InvalidParameter { field: "compare", value, allowed }
                }
                other => other,
            })?);
        }
        let reference = match self.reference_lb {
            Some(t) if !(t.is_finite() && t > 0.0 && t <= MAX_TENSION_LB) => {
                return Err(Error::invalid(
                    "reference-lb",
                    t,
                    format!("tension must satisfy 0 < T <= {MAX_TENSION_LB} lb"),
                ))
            }
            Some(t) => t,
            None => tension_lb_from_ks(variants[0].params.strings.ks),
        };
        // a reference within rounding of a tension of the list is that tension
        let reference = tensions.iter().copied().find(|t| (t - reference).abs() <= 1e-9 * t).unwrap_or(reference);
        if !tensions.contains(&reference) {
            tensions.push(reference);
            tensions.sort_by(f64::total_cmp);
        }
        let paper = is_paper(&variants[0].params);
        let widebody = if paper { Some(self.sources.resolve(Some(WIDEBODY_PRESET))?.0) } else { None };
        // every configuration at every tension is valid before any impact runs
        for v in &variants {
            for &t in &tensions {
                compute::at_tension(&v.params, t).validate()?;
            }
        }
        let prepared = Prepared {
            request: self.clone(),
            variants,
            tensions_lb: tensions,
            reference_lb: reference,
            widebody,
            noted: Vec::new(),
        };
        // every impact's parameters valid before any runs (the spin shot's incidence too)
        let jobs = prepared.jobs();
        for j in jobs.iter().filter(|j| j.runs()) {
            j.params.validate()?;
        }
        let mut noted =
            self.sources.check_used(&jobs.iter().filter(|j| j.runs()).map(|j| j.params).collect::<Vec<_>>())?;
        if jobs.iter().any(|j| !j.runs()) {
            noted.push(Diagnostic::new(
                Kind::NotUsed,
                keys::FRAME.key,
                "the rigid frame takes no oblique impact: the card has no spin (its panel says so)",
            ));
        }
        Ok(Prepared { noted, ..prepared })
    }

    /// The racket `racket` (`None`: the paper's) with the card's sources: a flag for what the
    /// card sets refused, the config file's values for them dropped.
    fn variant(&self, racket: Option<&str>) -> Result<Variant> {
        let flags = &self.sources.flags;
        if let Some((spec, why)) = CARD_SETS.iter().find(|(s, _)| flags.given().contains(&s.key)) {
            let mut values = Params::default();
            flags.apply(&mut values);
            let value = keys::value_text(spec.key, &values).unwrap_or_default();
            return Err(Error::invalid(spec.key, value, format!("card does not take it: {why}")));
        }
        let (params, _) = self.sources.resolve(racket)?;
        let points = Points::of(&params.racket).map_err(|why| {
            Error::invalid(
                "racket",
                racket_label(racket),
                format!("the card's impact points do not fit its face: {why}"),
            )
        })?;
        Ok(Variant { label: racket_label(racket), params, points })
    }
}

/// Whether `p` is the paper's racket and ball under the paper's model (a free flexible beam,
/// linear strings): its conclusions are then set beside the model's.
pub fn is_paper(p: &Params) -> bool {
    p.racket == crate::params::Racket::default()
        && p.ball == crate::params::Ball::default()
        && p.variants == crate::params::Variants::default()
}
