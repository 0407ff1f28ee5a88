//! Studies built from many impacts, the library logic behind the commands that run them:
//! [`sweep`] (the cartesian product of any parameters, streamed), [`map`] (one impact per
//! point of the string face) and [`speed`] (outgoing ball speeds for a swing, compared across
//! tensions or rackets), [`sensitivity`] (Sobol'/Saltelli uncertainty propagation and global
//! sensitivity for any model). [`Sources`] resolves a command's parameters from a racket, a config
//! file and the flags.

pub mod map;
pub mod sensitivity;
pub mod speed;
pub mod sweep;
pub mod uncertainty;

use std::path::{Path, PathBuf};

use crate::error::{Error, Result};
use crate::params::{Overrides, Params};
use crate::racket::Fitted;

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
}

impl Sources {
    /// The parameters, validated.
    pub fn params(&self) -> Result<Params> {
        self.resolve(self.racket.as_deref()).map(|(p, _)| p)
    }

    /// The parameters with the racket `racket` instead of [`Sources::racket`], validated, and
    /// the racket's fit.
    pub fn resolve(&self, racket: Option<&str>) -> Result<(Params, Option<Fitted>)> {
        let config = config_file(self.config.as_deref())?;
        let spec = racket.map(crate::racket::load).transpose()?;
        crate::racket::resolve(spec.as_ref(), &self.flags.clone().or(config))
    }
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

/// The comparison options of `speed` and `map`: tensions or rackets, not both; each tension in
/// range.
pub fn check_comparison(tensions_lb: &[f64], rackets_given: bool) -> Result<()> {
    if !tensions_lb.is_empty() && rackets_given {
        return Err(Error::invalid(
            "compare-tension-lb",
            "(with --compare-racket)",
            "compare either tensions or rackets, not both",
        ));
    }
    match tensions_lb.iter().find(|t| !(t.is_finite() && **t > 0.0 && **t <= 200.0)) {
        Some(t) => Err(Error::invalid("compare-tension-lb", t, "tension must satisfy 0 < T <= 200 lb")),
        None => Ok(()),
    }
}
