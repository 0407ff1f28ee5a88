//! The parameter intake: where a command's parameters come from ([`Sources`]: the paper
//! defaults < a racket file or preset < a config file < the flags), what a value given for a
//! parameter the command's impacts do not use is told ([`unused`]: a property not exercised is
//! noted, a method's option not honoured refused, flags and config keys alike), the comparison
//! options of `speed` and `map` ([`compare`]), and the physics-validity checks of what was taken
//! in and what came out ([`diagnose`]). The studies ([`crate::study`]) and the command line
//! start from here; nothing here runs an impact.

pub mod compare;
pub mod diagnose;
pub mod unused;

use std::path::{Path, PathBuf};

use crate::diagnostic::Diagnostic;
use crate::error::Result;
use crate::params::{keys, Overrides, Params};
use crate::racket::Fitted;

pub use unused::unused_config_note;
pub(crate) use unused::unused_flag;

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
    /// `--compare-tension-lb` tensions, [`compare::TENSION_SETS`]): a config file's values for them
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
    /// notes ([`Kind::NotUsed`](crate::diagnostic::Kind::NotUsed)): one for each flag of a property none of them exercises (field:
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

/// The overrides of a `--config` file, or none.
pub fn config_file(path: Option<&Path>) -> Result<Overrides> {
    path.map_or_else(|| Ok(Overrides::default()), Overrides::from_toml_file)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnostic::Kind;

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
