//! The parameter flags on the command line: one clap argument per declared parameter
//! ([`keys::ALL`]), read into [`Overrides`] with the same setter the sweeps use.

use clap::builder::{PossibleValue, PossibleValuesParser};
use clap::{value_parser, Arg, ArgAction, ArgMatches, Command, FromArgMatches};
use racket_impact::params::keys;
use racket_impact::params::spec::{ParamSpec, Values};
use racket_impact::params::{Overrides, Params};

/// The parameter flags (`--x`, `--ks`, ...), in the order of their declaration.
#[derive(Debug, Clone, Default)]
pub struct OverrideArgs(pub Overrides);

/// The clap argument of one parameter: `--KEY <KEY>` with its help; numbers may be negative
/// (the validation names the range), choices list their names.
fn arg(spec: &ParamSpec, defaults: &Params) -> Arg {
    let arg = Arg::new(spec.key)
        .long(spec.key)
        .value_name(spec.key.to_uppercase().replace('-', "_"))
        .action(ArgAction::Set)
        .help(help(spec, defaults));
    match spec.values {
        Values::Number => arg.value_parser(value_parser!(f64)).allow_hyphen_values(true),
        Values::Count => arg.value_parser(value_parser!(usize)).allow_hyphen_values(true),
        Values::Choice(choices) => arg.value_parser(PossibleValuesParser::new(choices.iter().map(|c| {
            let value = PossibleValue::new(c.name);
            match c.help {
                Some(help) => value.help(help),
                None => value,
            }
        }))),
    }
}

/// The help line with the default the commands use, read from the parameters the commands
/// start from (the paper's racket hit at its face centre).
fn help(spec: &ParamSpec, defaults: &Params) -> String {
    let value = keys::value_text(spec.key, defaults).unwrap_or_default();
    let unit = if spec.unit.is_empty() || value.parse::<f64>().is_err() || matches!(spec.values, Values::Choice(_)) {
        String::new()
    } else {
        format!(" {}", spec.unit)
    };
    let note = match spec.key {
        "x" => ", the centre of the string face; with --racket, the centre of its head",
        "r" => ", on the long axis",
        "dt" => ", the converged automatic step",
        "ks" | "mass" | "length" | "ei" | "ix" | "half-width" | "mb" | "k1" | "p" => {
            ", the paper's; with --racket, the racket file's"
        }
        _ => "",
    };
    format!("{} [default: {value}{unit}{note}]", spec.help())
}

impl clap::Args for OverrideArgs {
    fn augment_args(cmd: Command) -> Command {
        let defaults = match racket_impact::racket::resolve(None, &Overrides::default()) {
            Ok((p, _)) => p,
            Err(_) => Params::default(),
        };
        keys::ALL.iter().fold(cmd, |cmd, spec| cmd.arg(arg(spec, &defaults)))
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}

impl FromArgMatches for OverrideArgs {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        let mut args = OverrideArgs::default();
        args.update_from_arg_matches(matches)?;
        Ok(args)
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        for spec in &keys::ALL {
            // clap has parsed the text already; the setter reads it into its typed field
            let text = matches.get_raw(spec.key).and_then(|mut raw| raw.next()).and_then(|t| t.to_str());
            if let Some(text) = text {
                self.0
                    .set(spec.key, text)
                    .map_err(|e| clap::Error::raw(clap::error::ErrorKind::ValueValidation, e.to_string()))?;
            }
        }
        Ok(())
    }
}
