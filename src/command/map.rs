//! `map`: a quantity over the string face, one impact per grid point (the front end writes its
//! files or hands the grid to Python).

use super::{Control, Given, Kind, Many, Opt, Request, Unit, Work, LONG};
use crate::diagnostic::Diagnostic;
use crate::error::Result;
use crate::intake::Sources;
use crate::params::Params;
use crate::study::map::{MapOutcome, MapRequest, Quantity, MAP_SETS, MAX_GRID, MIN_GRID};

/// The command.
pub const NAME: &str = "map";

/// Its options.
pub const OPTIONS: &[Opt] = &[
    Opt::new(
        "quantity",
        Kind::Choice(&["e_a", "tau", "theta", "f_vib", "power", "spin", "rebound_angle"]),
        Some("power"),
        "The quantity shown in the heat map (the table has every one): e_a, tau (impact duration, ms), theta \
         (twist at the end of the impact, deg), f_vib (vibration energy, fraction of the ball's incident KE), \
         power (100 e_A, %), spin (outgoing spin, rpm) or rebound_angle (deg; these two of an oblique or spinning \
         ball)",
    ),
    Opt::new(
        "nx",
        Kind::Count { lo: MIN_GRID as u64, hi: MAX_GRID as u64 },
        Some("41"),
        "Grid points along the racket, from the tip to the end of the face",
    ),
    Opt::new(
        "nr",
        Kind::Count { lo: MIN_GRID as u64, hi: MAX_GRID as u64 },
        Some("21"),
        "Grid points across the face, from -half-width to +half-width",
    ),
    Opt::new(
        "compare-racket",
        Kind::Text,
        None,
        "Difference map against this racket (file or preset): B - A with A = the racket",
    ),
    Opt::new(
        "compare-tension-lb",
        Kind::Number,
        None,
        "Difference map between string tensions, lb: T (A = the configuration as given, B = at T) or T1,T2 (A at \
         T1, B at T2); k_s = 4e4 N/m * T / 60 lb",
    )
    .many(Many::List),
    LONG,
];

/// A map, checked and ready to run: its configurations read and validated.
#[derive(Debug, Clone)]
pub struct Map {
    /// The map's request (the study's).
    pub request: MapRequest,
    /// Its configurations, `(label, params)`: one, or two to compare.
    pub configs: Vec<(String, Params)>,
    /// Its impacts.
    pub total: usize,
    /// The notes made before it runs.
    noted: Vec<Diagnostic>,
    long: bool,
}

/// A map, run.
#[derive(Debug, Clone)]
pub struct Mapped {
    /// The table, heat map, metadata, summary and grid.
    pub map: MapOutcome,
    /// The notes made before the run, then the map's own diagnostics.
    pub diagnostics: Vec<Diagnostic>,
}

impl Map {
    /// The map `sources` and the options `given` describe: the grid counts and the comparison
    /// checked, the configurations read and validated, a flag none of its impacts can honour
    /// refused (what the grid sets, [`MAP_SETS`], is not a flag of the map), one none exercises
    /// noted.
    pub fn new(sources: &Sources, given: &Given) -> Result<Map> {
        let mut sources = sources.clone();
        // (the command has no flag for what the grid sets: a config file's values are noted)
        sources.not_taken = MAP_SETS.iter().map(|(s, _)| s.key).collect();
        let compare_tension_lb = given.numbers("compare-tension-lb")?;
        if compare_tension_lb.len() >= 2 {
            sources.set_by_options.extend(crate::intake::compare::TENSION_SETS);
        }
        let quantity: Quantity = given.choice("quantity")?.unwrap_or("power").parse()?;
        let count = |name| given.count(name).map(|n| n.unwrap_or_default() as usize);
        let request = MapRequest {
            sources,
            quantity,
            nx: count("nx")?,
            nr: count("nr")?,
            compare_racket: given.text("compare-racket"),
            compare_tension_lb,
        };
        request.check()?;
        let (configs, total) = request.configurations()?;
        let noted = request.check_used(&configs)?;
        Ok(Map { request, configs, total, noted, long: given.switch("long")? })
    }
}

impl Request for Map {
    const NAME: &'static str = NAME;
    const OPTIONS: &'static [Opt] = OPTIONS;
    type Output = Mapped;

    fn work(&self, threads: usize) -> Option<Work> {
        Some(Work {
            estimate: MapRequest::estimate(&self.configs, self.request.nx, self.request.nr, self.total, threads),
            asked: format!("a {} x {} grid ({} impacts)", self.request.nx, self.request.nr, self.total),
            fewer: "a coarser grid (--nx, --nr)",
            long: self.long,
        })
    }

    fn run(self, ctl: &Control) -> Result<Mapped> {
        ctl.begin(self.total as u64, Unit::Impacts);
        let map = self.request.run(&self.configs, &mut |done| ctl.set_done(done))?;
        let diagnostics = self.noted.into_iter().chain(map.diagnostics(self.configs.iter().map(|(_, p)| p))).collect();
        Ok(Mapped { map, diagnostics })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_quantities_are_the_maps() {
        let Kind::Choice(names) = OPTIONS[0].kind else { panic!("quantity is a choice") };
        assert_eq!(names.to_vec(), Quantity::every().map(Quantity::name).collect::<Vec<_>>());
    }
}
