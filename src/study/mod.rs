//! Studies built from many impacts, the library logic behind the commands that run them:
//! [`sweep`] (the cartesian product of any parameters, streamed), [`map`] (one impact per
//! point of the string face) and [`speed`] (outgoing ball speeds for a swing, compared across
//! tensions or rackets), [`sensitivity`] (Sobol'/Saltelli uncertainty propagation and global
//! sensitivity for any model), [`impact`] (one impact as `simulate` runs it). [`Sources`] resolves a command's parameters from a racket, a config
//! file and the flags.

pub mod calibrate;
pub mod diagnose;
pub mod impact;
pub mod map;
pub mod measured;
pub mod sensitivity;
pub mod speed;
pub mod stats;
pub mod sweep;
pub mod uncertainty;

use std::path::{Path, PathBuf};

use crate::diagnostic::{Diagnostic, Kind};
use crate::error::{Error, Result};
use crate::params::spec::ParamSpec;
use crate::params::{keys, used, Overrides, Params};
use crate::racket::Fitted;

/// The columns of the commands' tables that are neither a parameter's column
/// ([`crate::params::keys`]) nor a result field ([`crate::solve::outcome::FIELDS`]): each with
/// its unit in its name where it has one (or, for the speeds, the `unit` column beside it).
/// With the time series' [`crate::render::impact::SERIES_COLUMNS`] they are the vocabulary
/// every CSV a command writes draws from (tests/vocabulary.rs).
pub const OTHER_COLUMNS: &[&str] = &[
    // speed
    "variant",
    "ball_speed_out",
    "change_pct",
    "unit",
    "launch_deg",
    "launch_spin_rpm",
    // map (a difference map's columns end in _a, _b and _b_minus_a)
    "power_pct",
    "ks_a_n_per_m",
    "ks_b_n_per_m",
    // modes
    "mode",
    "frequency_hz",
    // sweep: the solver that ran
    "solver",
];

/// Where a command's parameters come from: the paper defaults (with the user default `hat`
/// load) < a racket file or preset < a config file < the flags.
#[derive(Debug, Clone, Default)]
pub struct Sources {
    /// Racket description file (TOML, player units) or preset name.
    pub racket: Option<String>,
    /// TOML file with any parameter key.
    pub config: Option<PathBuf>,
    /// The parameter flags.
    pub flags: Overrides,
    /// The command these parameters are for (named in the notes about unused config keys).
    pub command: &'static str,
    /// The parameter keys the command does not take (it sets them itself or does not use
    /// them): it has no flag for them, and a config file's values for them are dropped
    /// ([`Sources::config`]) and named as unused ([`Sources::check_used`]).
    pub not_taken: Vec<&'static str>,
    /// The parameter keys this run sets from the command's own options (k_s from two or more
    /// `--compare-tension-lb` tensions, [`TENSION_SETS`]): a config file's values for them
    /// are named as set on the command line ([`Sources::check_used`]).
    pub set_by_options: Vec<&'static str>,
}

impl Sources {
    /// The parameters, validated.
    pub fn params(&self) -> Result<Params> {
        self.resolve(self.racket.as_deref()).map(|(p, _)| p)
    }

    /// The parameters with the racket `racket` instead of [`Sources::racket`], validated, and
    /// the racket's fit.
    pub fn resolve(&self, racket: Option<&str>) -> Result<(Params, Option<Fitted>)> {
        let (config, _) = self.config()?;
        let spec = racket.map(crate::racket::load).transpose()?;
        crate::racket::resolve(spec.as_ref(), &self.flags.clone().or(config))
    }

    /// The config file's overrides without the keys the command does not take, and those keys.
    pub fn config(&self) -> Result<(Overrides, Vec<&'static str>)> {
        let mut config = config_file(self.config.as_deref())?;
        let dropped: Vec<&'static str> = config.given().into_iter().filter(|k| self.not_taken.contains(k)).collect();
        for k in &dropped {
            config.clear(k);
        }
        Ok((config, dropped))
    }

    /// Refuse a value for a method's option that none of the command's impacts `params` can
    /// honour, from a flag or from the config file alike ([`crate::params::used`]); return the
    /// notes ([`Kind::NotUsed`]): one for each flag of a property none of them exercises (field:
    /// its key), and one naming the config file's keys that the command does not take, that are
    /// set on the command line, or that are properties none of its impacts exercises (a config
    /// file may be shared between commands, so a key a command does not take is not refused;
    /// field `config`).
    pub fn check_used(&self, params: &[Params]) -> Result<Vec<Diagnostic>> {
        let mut noted = Vec::new();
        let first = params.first().copied().unwrap_or_default();
        for spec in self.flags.given().into_iter().filter_map(keys::find) {
            let value = keys::value_text(spec.key, &first).unwrap_or_default();
            noted.extend(unused_flag(spec, &value, params, "this impact")?);
        }
        let (config, dropped) = self.config()?;
        let path = self.config.as_deref().unwrap_or(Path::new(""));
        let overridden: Vec<&str> = self.flags.given().into_iter().chain(self.set_by_options.iter().copied()).collect();
        noted.extend(unused_config_note(path, &config, &overridden, &dropped, self.command, params)?);
        Ok(noted)
    }
}

/// The note ([`Kind::NotUsed`]) for the flag of `spec` (its value written `value`) that none
/// of the impacts `params` uses, or its refusal if it is a method's option none of them can
/// honour ([`crate::params::used`]: a property an impact does not exercise is noted, a method's
/// option it cannot honour refused); `None` if one of them uses it. `these`: the words for the
/// impacts.
pub(crate) fn unused_flag(spec: &ParamSpec, value: &str, params: &[Params], these: &str) -> Result<Option<Diagnostic>> {
    let Some((spec, unused)) = used::first_unused(&[spec], params) else {
        return Ok(None);
    };
    let (field, why) = (spec.key, unused.why);
    if unused.refused {
        return Err(Error::invalid(field, value, why));
    }
    Ok(Some(Diagnostic::new(Kind::NotUsed, field, format!("--{field} {value} is not exercised by {these} ({why})"))))
}

/// One note ([`Kind::NotUsed`], field `config`) naming the keys of the config file at `path`
/// (values `config`) that are not used: those the command does not take (`dropped`), those set
/// otherwise (`overridden`: by a flag, or swept), and the properties none of its impacts
/// `params` exercises ([`crate::params::used`]); `None` when every key is used. A method's
/// option none of the impacts can honour is refused, as its flag is.
pub fn unused_config_note(
    path: &Path,
    config: &Overrides,
    overridden: &[&str],
    dropped: &[&str],
    command: &str,
    params: &[Params],
) -> Result<Option<Diagnostic>> {
    let mut notes: Vec<String> = Vec::new();
    if !dropped.is_empty() {
        notes.push(format!("{} (not used by {command})", dropped.join(", ")));
    }
    let set: Vec<&str> = config.given().into_iter().filter(|k| overridden.contains(k)).collect();
    if !set.is_empty() {
        notes.push(format!("{} (set on the command line)", set.join(", ")));
    }
    for spec in config.given().into_iter().filter(|k| !overridden.contains(k)).filter_map(keys::find) {
        let Some((spec, unused)) = used::first_unused(&[spec], params) else { continue };
        if unused.refused {
            let mut values = Params::default();
            config.apply(&mut values);
            let value = keys::value_text(spec.key, &values).unwrap_or_default();
            return Err(Error::invalid(spec.key, value, format!("{} (config file {})", unused.why, path.display())));
        }
        notes.push(format!("{} ({})", spec.key, unused.why));
    }
    Ok((!notes.is_empty()).then(|| {
        let sentence = format!("config file {}: not used here: {}", path.display(), notes.join("; "));
        Diagnostic::new(Kind::NotUsed, "config", sentence)
    }))
}

/// The overrides of a `--config` file, or none.
pub fn config_file(path: Option<&Path>) -> Result<Overrides> {
    path.map_or_else(|| Ok(Overrides::default()), Overrides::from_toml_file)
}

/// A racket argument as a short name: the paper's racket, a preset as is, a file by the
/// `name` it gives (else its file stem).
pub fn racket_label(arg: Option<&str>) -> String {
    match arg {
        None => "paper racket".to_string(),
        Some(a) if crate::racket::preset_names().contains(&a) => a.to_string(),
        Some(a) => crate::racket::load(a)
            .ok()
            .and_then(|spec| spec.name)
            .unwrap_or_else(|| Path::new(a).file_stem().and_then(|s| s.to_str()).unwrap_or(a).to_string()),
    }
}

/// The parameter keys a compared tension sets in each configuration it names (k_s =
/// [`crate::params::ks_from_tension_lb`]).
pub const TENSION_SETS: [&str; 1] = ["ks"];

/// The comparison options of `speed` and `map`: tensions or rackets, not both; each tension in
/// range and named once; and, when every compared configuration is at a given tension (two or
/// more tensions), no flag for what the tensions set ([`TENSION_SETS`]): no row would use it.
pub fn check_comparison(tensions_lb: &[f64], rackets_given: bool, flags: &Overrides) -> Result<()> {
    if !tensions_lb.is_empty() && rackets_given {
        return Err(Error::invalid(
            "compare-tension-lb",
            "(with --compare-racket)",
            "compare either tensions or rackets, not both",
        ));
    }
    if let Some(t) = tensions_lb.iter().find(|t| !(t.is_finite() && **t > 0.0 && **t <= 200.0)) {
        return Err(Error::invalid("compare-tension-lb", t, "tension must satisfy 0 < T <= 200 lb"));
    }
    if let Some((i, t)) = tensions_lb.iter().enumerate().find(|(i, t)| tensions_lb[..*i].contains(t)) {
        let list = tensions_lb.iter().map(f64::to_string).collect::<Vec<_>>().join(",");
        return Err(Error::invalid(
            "compare-tension-lb",
            list,
            format!("the tension {t} lb is given twice (item {}): a configuration compared with itself differs nowhere; give different tensions", i + 1),
        ));
    }
    if tensions_lb.len() >= 2 {
        let given = flags.given();
        if let Some(key) = TENSION_SETS.iter().find(|k| given.contains(k)) {
            let mut p = Params::default();
            flags.apply(&mut p);
            let value = crate::params::keys::value_text(key, &p).unwrap_or_default();
            return Err(Error::invalid(
                key,
                value,
                "not used with two or more --compare-tension-lb tensions: every compared configuration takes its k_s \
                 from its tension (4e4 N/m * T / 60 lb); give one tension T to compare this k_s against T",
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sources(flags: &[(&str, &str)]) -> (Sources, Params) {
        let mut o = Overrides::default();
        for (key, value) in flags {
            o.set(key, value).unwrap();
        }
        let mut p = Params::default();
        o.apply(&mut p);
        (Sources { flags: o, command: "simulate", ..Sources::default() }, p)
    }

    #[test]
    fn a_property_the_impact_does_not_exercise_is_a_note_an_option_it_cannot_honour_refused() {
        // friction at normal incidence: accepted, returned as a note about its key
        let (s, p) = sources(&[("mu", "0.4"), ("ks", "3e4")]);
        let notes = s.check_used(&[p]).unwrap();
        assert_eq!(notes.len(), 1, "{notes:?}");
        assert_eq!((notes[0].kind, notes[0].field.as_str()), (Kind::NotUsed, "mu"));
        assert!(notes[0].sentence.starts_with("--mu 0.4 is not exercised by this impact ("), "{}", notes[0]);
        // everything used: nothing to say
        let (s, p) = sources(&[("ks", "3e4")]);
        assert_eq!(s.check_used(&[p]).unwrap(), vec![]);
        // a step size the modal solver cannot honour: refused
        let (s, p) = sources(&[("solver", "modal"), ("dt", "1e-6")]);
        assert!(s.check_used(&[p]).unwrap_err().to_string().starts_with("invalid dt"));
    }
}
