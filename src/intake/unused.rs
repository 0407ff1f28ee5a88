//! What a value given for a parameter that none of a command's impacts uses is told, from a
//! flag and from a config file alike ([`crate::params::used`] says which impacts use a
//! parameter and whether an unused value is noted or refused).

use std::path::Path;

use crate::diagnostic::{Diagnostic, Kind};
use crate::error::{Error, Result};
use crate::params::spec::ParamSpec;
use crate::params::{keys, used, Overrides, Params};

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
