//! `speed`: the outgoing ball speed for a swing and an incoming ball, compared across string
//! tensions or rackets.

use super::{Control, Given, Kind, Many, Opt, Request, Unit, Work};
use crate::error::{Error, Result};
use crate::intake::Sources;
use crate::study::speed::{SpeedComparison, SpeedRequest, SpeedUnit, SPEED_SETS};

/// The command.
pub const NAME: &str = "speed";

/// The units of the speeds, each with its other spellings: (name, its unit).
const UNITS: [(&str, SpeedUnit); 7] = [
    ("kmh", SpeedUnit::KMH),
    ("mph", SpeedUnit::MPH),
    ("ms", SpeedUnit::MS),
    ("kph", SpeedUnit::KMH),
    ("km/h", SpeedUnit::KMH),
    ("m/s", SpeedUnit::MS),
    ("mps", SpeedUnit::MS),
];

/// Its options.
pub const OPTIONS: &[Opt] = &[
    Opt::new("swing", Kind::Number, None, "Racket speed at the impact point, towards the ball (in --unit)").required(),
    Opt::new("incoming", Kind::Number, Some("0"), "Incoming ball speed, towards the racket (in --unit); 0 for a serve"),
    Opt::new(
        "unit",
        Kind::Choice(&["kmh", "mph", "ms", "kph", "km/h", "m/s", "mps"]),
        Some("kmh"),
        "Unit of the speeds: kilometres per hour (kmh, also kph, km/h), miles per hour (mph), metres per second \
         (ms, also m/s, mps)",
    ),
    Opt::new(
        "compare-tension-lb",
        Kind::Number,
        None,
        "Compare string tensions, lb: T (A = the configuration as given, against A at T) or T1,T2,... (A at T1, \
         against A at each other tension); k_s = 4e4 N/m * T / 60 lb",
    )
    .many(Many::List),
    Opt::new(
        "compare-racket",
        Kind::Text,
        None,
        "Compare against these rackets (files or presets, e.g. light,players): each against A = the racket (or \
         the paper's), which is the first row",
    )
    .many(Many::List),
    Opt::new(
        "swing-path-deg",
        Kind::Number,
        Some("0"),
        "Swing path angle above the horizontal, degrees (-80..=80): > 0 brushes up the back of the ball for \
         topspin; the face stands vertical and the ball comes in horizontally",
    ),
    Opt::new(
        "incoming-spin-rpm",
        Kind::Number,
        Some("0"),
        "Spin of the incoming ball in its own flight, rpm (court frame: > 0 topspin, its top moving forward)",
    ),
];

/// A comparison of outgoing speeds, ready to run (its speeds and variants are checked as it
/// runs, before any impact).
#[derive(Debug, Clone)]
pub struct Speed {
    /// The study's request.
    pub request: SpeedRequest,
}

impl Speed {
    /// The comparison `sources` and the options `given` describe; what the swing sets (the
    /// impact speed, incidence and spin, [`SPEED_SETS`]) is not a flag of `speed`.
    pub fn new(sources: &Sources, given: &Given) -> Result<Speed> {
        let mut sources = sources.clone();
        sources.not_taken = SPEED_SETS.iter().map(|(s, _)| s.key).collect();
        if let Some((spec, why)) = SPEED_SETS.iter().find(|(s, _)| sources.flags.given().contains(&s.key)) {
            let mut values = crate::params::Params::default();
            sources.flags.apply(&mut values);
            let value = crate::params::keys::value_text(spec.key, &values).unwrap_or_default();
            return Err(Error::invalid(spec.key, value, format!("speed does not take it: {why}")));
        }
        let compare_tension_lb = given.numbers("compare-tension-lb")?;
        if compare_tension_lb.len() >= 2 {
            sources.set_by_options.extend(crate::intake::compare::TENSION_SETS);
        }
        let unit = given.choice("unit")?.unwrap_or("kmh");
        let unit = UNITS.iter().find(|(n, _)| *n == unit).map_or(SpeedUnit::KMH, |(_, u)| *u);
        let number = |name| given.number(name).map(Option::unwrap_or_default);
        let request = SpeedRequest {
            sources,
            swing: given.required_number("swing")?,
            incoming: number("incoming")?,
            unit,
            compare_tension_lb,
            compare_racket: given.texts("compare-racket"),
            path_deg: number("swing-path-deg")?,
            incoming_spin_rpm: number("incoming-spin-rpm")?,
        };
        Ok(Speed { request })
    }
}

impl Request for Speed {
    const NAME: &'static str = NAME;
    const OPTIONS: &'static [Opt] = OPTIONS;
    type Output = SpeedComparison;

    fn work(&self, _threads: usize) -> Option<Work> {
        // (one impact per variant, a handful: a moment)
        None
    }

    fn run(self, ctl: &Control) -> Result<SpeedComparison> {
        let variants = 1 + self.request.compare_racket.len().max(self.request.compare_tension_lb.len().max(1) - 1);
        ctl.begin(variants as u64, Unit::Impacts);
        self.request.run()
    }
}
