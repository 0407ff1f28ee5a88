//! The parameter flags on the command line: one clap argument per declared parameter
//! ([`keys::ALL`]), read into [`Overrides`] with the same setter the sweeps use.

use clap::builder::{PossibleValue, PossibleValuesParser};
use clap::{value_parser, Arg, ArgAction, ArgMatches, Command, FromArgMatches};
use racket_impact::params::keys;
use racket_impact::params::spec::{ParamSpec, Values};
use racket_impact::params::Overrides;

/// The parameter flags (`--x`, `--ks`, ...), in the order of their declaration.
#[derive(Debug, Clone, Default)]
pub struct OverrideArgs(pub Overrides);

/// The clap argument of one parameter: `--KEY <KEY>` with its help; numbers may be negative
/// (the validation names the range), choices list their names.
fn arg(spec: &ParamSpec) -> Arg {
    let arg = Arg::new(spec.key)
        .long(spec.key)
        .value_name(spec.key.to_uppercase().replace('-', "_"))
        .action(ArgAction::Set)
        .help(spec.help());
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

impl clap::Args for OverrideArgs {
    fn augment_args(cmd: Command) -> Command {
        keys::ALL.iter().fold(cmd, |cmd, spec| cmd.arg(arg(spec)))
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
