//! `card`: what string tension does to one racket, in one picture and one table
//! ([`crate::study::card`]), as a request of the command layer: its options declared once, its
//! work estimated before it starts, its impacts counted and stopped through one [`Control`].

use super::{Control, Given, Kind, Opt, Request, Unit, Work, LONG};
use crate::error::Result;
use crate::intake::Sources;
use crate::study::card::{Card, CardRequest, Prepared, Strokes, KMH};

/// The command.
pub const NAME: &str = "card";

/// Its options (the parameters are its flags as for `simulate`, but for what it sets itself,
/// [`crate::study::card::CARD_SETS`]). The defaults are the study's ([`CardRequest::default`]):
/// a test holds them equal.
pub const OPTIONS: &[Opt] = &[
    Opt::new(
        "tensions-lb",
        Kind::Text,
        Some(crate::study::card::DEFAULT_TENSIONS),
        "The tensions, lb: lo:hi:count (both ends included) or a list T1,T2,...; k_s = 4e4 N/m * T / 60 lb",
    ),
    Opt::new(
        "reference-lb",
        Kind::Number,
        None,
        "The tension the power changes count from, lb (default: the racket's own, from its k_s; added to the \
         tensions if it is not one of them)",
    ),
    Opt::new(
        "compare",
        Kind::Text,
        None,
        "A second racket (file or preset) drawn beside the first, dashed (e.g. paper-widebody-200hz)",
    ),
    Opt::new(
        "serve-kmh",
        Kind::Number,
        Some("151.2"),
        "Racket speed at the impact point on the serve, km/h (ball at rest)",
    ),
    Opt::new(
        "forehand-kmh",
        Kind::Number,
        Some("90"),
        "Racket speed at the impact point on the forehand, and the incoming ball's, km/h",
    ),
    Opt::new(
        "swing-rad-per-s",
        Kind::Number,
        Some("30"),
        "The racket's angular speed for the swing angle during the contact, rad/s",
    ),
    Opt::new(
        "sweet-within",
        Kind::Number,
        Some("0.1"),
        "The sweet spot: the face area where e_A is within this fraction of its best (0 < f < 1)",
    ),
    Opt::new("nx", Kind::Count { lo: 2, hi: 401 }, Some("81"), "Map grid points along the face, from the tip"),
    Opt::new("nr", Kind::Count { lo: 2, hi: 401 }, Some("41"), "Map grid points across the face"),
    LONG,
];

/// A card, checked and ready to run.
#[derive(Debug, Clone)]
pub struct CardCommand {
    /// The card's rackets, tensions and impacts.
    pub prepared: Prepared,
    long: bool,
}

impl CardCommand {
    /// The card of the racket `sources` describe, with the options `given`: every option and
    /// every impact's parameters checked, the flags it does not take refused, a config file's
    /// values for them named, before anything runs.
    pub fn new(sources: &Sources, given: &Given) -> Result<CardCommand> {
        let number = |name: &str| given.number(name).map(|v| v.unwrap_or(f64::NAN));
        let count = |name: &str| given.count(name).map(|v| v.unwrap_or_default() as usize);
        let request = CardRequest {
            sources: Sources { command: NAME, not_taken: crate::study::card::not_taken(), ..sources.clone() },
            tensions_lb: given.text("tensions-lb").unwrap_or_default(),
            reference_lb: given.number("reference-lb")?,
            compare: given.text("compare"),
            strokes: Strokes {
                serve_m_per_s: number("serve-kmh")? / KMH,
                forehand_m_per_s: number("forehand-kmh")? / KMH,
                swing_rad_per_s: number("swing-rad-per-s")?,
            },
            sweet_within: number("sweet-within")?,
            grid: (count("nx")?, count("nr")?),
        };
        Ok(CardCommand { prepared: request.prepare()?, long: given.switch("long")? })
    }
}

impl Request for CardCommand {
    const NAME: &'static str = NAME;
    const OPTIONS: &'static [Opt] = OPTIONS;
    type Output = Card;

    fn work(&self, threads: usize) -> Option<Work> {
        let p = &self.prepared;
        let (nx, nr) = p.request.grid;
        Some(Work {
            estimate: p.estimate(threads).ok()?,
            asked: format!("a card of {} tensions with an {nx} x {nr} map each", p.tensions_lb.len()),
            fewer: "fewer tensions or a coarser grid (--nx, --nr)",
            long: self.long,
        })
    }

    fn run(self, ctl: &Control) -> Result<Card> {
        ctl.begin(self.prepared.impacts()?, Unit::Impacts);
        self.prepared.run()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_declared_defaults_are_the_study_s() {
        let request = CardCommand::new(&Sources::default(), &Given::new(OPTIONS)).unwrap().prepared.request;
        let study = CardRequest::default();
        assert_eq!(request.tensions_lb, study.tensions_lb);
        assert_eq!(request.grid, study.grid);
        assert_eq!(request.sweet_within, study.sweet_within);
        let (a, b) = (request.strokes, study.strokes);
        for (x, y) in [(a.serve_m_per_s, b.serve_m_per_s), (a.forehand_m_per_s, b.forehand_m_per_s)] {
            assert!((x - y).abs() <= 1e-12 * y, "{x} against {y}");
        }
        assert_eq!(a.swing_rad_per_s, b.swing_rad_per_s);
    }

    #[test]
    fn a_cancelled_card_stops_with_nothing() {
        let mut given = Given::new(OPTIONS);
        given.set("tensions-lb", "50,60").unwrap();
        let request = CardCommand::new(&Sources::default(), &given).unwrap();
        let ctl = Control::new();
        ctl.cancel();
        assert!(super::super::execute(request, &ctl).is_err_and(|e| e.is_cancelled()));
    }

    #[test]
    fn the_impacts_count_themselves_to_the_card_s_total() {
        let mut given = Given::new(OPTIONS);
        for (k, v) in [("tensions-lb", "50,60"), ("nx", "11"), ("nr", "7")] {
            given.set(k, v).unwrap();
        }
        let request = CardCommand::new(&Sources::default(), &given).unwrap();
        let total = request.prepared.impacts().unwrap();
        let ctl = Control::new();
        super::super::execute(request, &ctl).unwrap();
        let s = ctl.status();
        assert_eq!((s.total, s.position), (total, total as f64));
    }
}
