//! `speed`: the outgoing ball speed for a swing and an incoming ball, compared across string
//! tensions or rackets.

use clap::{Args, ValueEnum};
use racket_impact::study::speed::{SpeedRequest, SpeedUnit};
use racket_impact::Result;

use super::common::{out, print_diagnostics, Common, Format};
use super::overrides::SpeedKeys;

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum UnitArg {
    /// kilometres per hour (also kph, km/h)
    #[value(alias = "kph", alias = "km/h")]
    Kmh,
    /// miles per hour
    Mph,
    /// metres per second (also m/s, mps)
    #[value(alias = "m/s", alias = "mps")]
    Ms,
}

impl UnitArg {
    /// The unit it names.
    fn unit(self) -> SpeedUnit {
        match self {
            UnitArg::Kmh => SpeedUnit::KMH,
            UnitArg::Mph => SpeedUnit::MPH,
            UnitArg::Ms => SpeedUnit::MS,
        }
    }
}

#[derive(Args, Debug)]
pub struct SpeedArgs {
    #[command(flatten)]
    pub common: Common<SpeedKeys>,
    /// Racket speed at the impact point, towards the ball (in --unit)
    #[arg(long, value_parser = super::common::number, allow_hyphen_values = true)]
    pub swing: f64,
    /// Incoming ball speed, towards the racket (in --unit); 0 for a serve
    #[arg(long, value_parser = super::common::number, default_value_t = 0.0, allow_hyphen_values = true)]
    pub incoming: f64,
    /// Unit of the speeds
    #[arg(long, value_enum, default_value_t = UnitArg::Kmh)]
    pub unit: UnitArg,
    /// Compare string tensions, lb: T (A = the configuration as given, against A at T) or
    /// T1,T2,... (A at T1, against A at each other tension); k_s = 4e4 N/m * T / 60 lb
    #[arg(long, value_parser = super::common::number, value_delimiter = ',', allow_hyphen_values = true)]
    pub compare_tension_lb: Vec<f64>,
    /// Compare against these rackets (files or presets, e.g. light,players): each against A =
    /// --racket (or the paper's), which is the first row
    #[arg(long, value_delimiter = ',')]
    pub compare_racket: Vec<String>,
    /// Swing path angle above the horizontal, degrees (-80..=80): > 0 brushes up the back of
    /// the ball for topspin; the face stands vertical and the ball comes in horizontally
    #[arg(long, value_parser = super::common::number, default_value_t = 0.0, allow_hyphen_values = true)]
    pub swing_path_deg: f64,
    /// Spin of the incoming ball in its own flight, rpm (court frame: > 0 topspin, its top moving forward)
    #[arg(long, value_parser = super::common::number, default_value_t = 0.0, allow_hyphen_values = true)]
    pub incoming_spin_rpm: f64,
}

/// Run the comparison and print it in the chosen format.
pub fn run(a: SpeedArgs) -> Result<()> {
    let mut sources = a.common.sources();
    if a.compare_tension_lb.len() >= 2 {
        sources.set_by_options.extend(racket_impact::intake::compare::TENSION_SETS);
    }
    let request = SpeedRequest {
        sources: sources.clone(),
        swing: a.swing,
        incoming: a.incoming,
        unit: a.unit.unit(),
        compare_tension_lb: a.compare_tension_lb,
        compare_racket: a.compare_racket,
        path_deg: a.swing_path_deg,
        incoming_spin_rpm: a.incoming_spin_rpm,
    };
    let comparison = request.run()?;
    let text = match a.common.format {
        Format::Csv => comparison.table()?.to_csv(),
        Format::Json => comparison.json()?,
        Format::Text => comparison.text(),
    };
    out!("{text}");
    // (the impact speed, incidence and spin come from this command's options: said in them)
    print_diagnostics(&comparison.diagnostics());
    Ok(())
}
