//! The parameter flags on the command line: one clap argument per declared parameter
//! ([`keys::ALL`]), read into [`Overrides`] with the same setter the sweeps use.

use clap::builder::{PossibleValue, PossibleValuesParser};
use clap::{value_parser, Arg, ArgAction, ArgMatches, Command, FromArgMatches};
use racket_impact::params::spec::{Heading, ParamSpec, UsedWhen, Values};
use racket_impact::params::{keys, used};
use racket_impact::params::{Overrides, Params};

/// The parameter keys a command takes: it has a flag for each, and reads each from a config
/// file; the others it sets itself or does not use (its help does not list them, the command
/// line refuses them, a config file's values for them are named as unused).
pub trait KeySet: std::fmt::Debug + Clone + Send + Sync + 'static {
    /// The command.
    const COMMAND: &'static str;
    /// Whether the command takes the parameter `key`.
    fn takes(key: &str) -> bool;
    /// Whether the command runs impacts (the help then says which impacts use a parameter);
    /// `modes` runs none.
    const RUNS_IMPACTS: bool = true;
    /// The declared keys it does not take.
    fn not_taken() -> Vec<&'static str> {
        keys::ALL.iter().map(|s| s.key).filter(|k| !Self::takes(k)).collect()
    }
}

/// Declares a [`KeySet`]: `name = "command": |key| takes`, or `name = "command" (false): ...`
/// for a command that runs no impacts.
macro_rules! key_set {
    ($($(#[doc = $doc:literal])* $name:ident = $command:literal $(($impacts:literal))?: |$key:ident| $takes:expr;)+) => {$(
        $(#[doc = $doc])*
        #[derive(Debug, Clone, Copy, Default)]
        pub struct $name;
        impl KeySet for $name {
            const COMMAND: &'static str = $command;
            $(const RUNS_IMPACTS: bool = $impacts;)?
            fn takes($key: &str) -> bool {
                $takes
            }
        }
    )+};
}

key_set! {
    /// `simulate`: every parameter.
    SimulateKeys = "simulate": |_key| true;
    /// `modes`: the free racket's modes depend only on its length, mass, stiffness and segments.
    ModesKeys = "modes" (false): |key| racket_impact::command::modes::not_taken(key).is_none();
    /// `speed`: every parameter but the impact speed, incidence and spin, which the swing sets.
    SpeedKeys = "speed": |key| racket_impact::study::speed::set_by_speed(key).is_none();
    /// `map`: every parameter but the impact point (the grid sets it) and the solver and its
    /// step (a map runs the modal solver wherever the variants allow it, else fd with its
    /// automatic step).
    MapKeys = "map": |key| racket_impact::study::map::set_by_map(key).is_none();
    /// `uncertainty`: every parameter, as `simulate` (its solver default is the modal one).
    UncertaintyKeys = "uncertainty": |_key| true;
    /// `card`: every parameter but the impact points, ball speeds, incidence and k_s, which the
    /// card sets itself (from its strokes and tensions).
    CardKeys = "card": |key| racket_impact::study::card::set_by_card(key).is_none();
    /// `calibrate`: every parameter but the shot's speed, incidence, incoming spin and grip,
    /// which each measured row sets.
    CalibrateKeys = "calibrate": |key| !racket_impact::study::calibrate::shot::ROW_SETS.contains(&key);
}

/// The parameter flags (`--x`, `--ks`, ...) a command takes ([`KeySet`]), in the order of
/// their declaration.
#[derive(Debug, Clone)]
pub struct OverrideArgs<K: KeySet>(pub Overrides, std::marker::PhantomData<K>);

impl<K: KeySet> Default for OverrideArgs<K> {
    fn default() -> Self {
        OverrideArgs(Overrides::default(), std::marker::PhantomData)
    }
}

/// The clap argument of one parameter: `--KEY <KEY>` with its help under its declared heading
/// ([`ParamSpec::heading`]); numbers may be negative (the validation names the range), choices
/// list their names.
fn arg(spec: &ParamSpec, defaults: &Params, command: &str, runs_impacts: bool) -> Arg {
    let arg = Arg::new(spec.key)
        .long(spec.key)
        .help_heading(spec.heading.title())
        .value_name(spec.key.to_uppercase().replace('-', "_"))
        .action(ArgAction::Set)
        .help(help(spec, defaults, command, runs_impacts));
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
/// start from (the paper's racket hit at its face centre), how the default is chosen where the
/// declaration says, and which impacts use the parameter where not every one does.
fn help(spec: &ParamSpec, defaults: &Params, command: &str, runs_impacts: bool) -> String {
    let used = match spec.used_when {
        _ if !runs_impacts => String::new(),
        UsedWhen::Always => String::new(),
        ref when => format!(" [used only {}]", used::words(when)),
    };
    if spec.key == keys::SOLVER.key && command == UncertaintyKeys::COMMAND {
        // its runs default to the fast solver, as a sweep's do (study::sweep::default_solver)
        return format!("{} [default: modal; fd where a hand grip or stiffening strings need it]{used}", spec.help());
    }
    let value = keys::value_text(spec.key, defaults).unwrap_or_default();
    let unit = if spec.unit.is_empty() || value.parse::<f64>().is_err() || matches!(spec.values, Values::Choice(_)) {
        String::new()
    } else {
        format!(" {}", spec.unit)
    };
    let how = spec.default_words.map_or(String::new(), |words| format!(", {words}"));
    format!("{} [default: {value}{unit}{how}]{used}", spec.help())
}

impl<K: KeySet> clap::Args for OverrideArgs<K> {
    fn augment_args(cmd: Command) -> Command {
        let defaults = match racket_impact::racket::resolve(None, &Overrides::default()) {
            Ok((p, _)) => p,
            Err(_) => Params::default(),
        };
        // grouped by heading, in the order of Heading::ALL, each group in the declarations' order
        let mut specs: Vec<&ParamSpec> = keys::ALL.iter().filter(|s| K::takes(s.key)).collect();
        specs.sort_by_key(|s| Heading::ALL.iter().position(|h| *h == s.heading));
        specs.into_iter().fold(cmd, |cmd, spec| cmd.arg(arg(spec, &defaults, K::COMMAND, K::RUNS_IMPACTS)))
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}

impl<K: KeySet> FromArgMatches for OverrideArgs<K> {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        let mut args = OverrideArgs::default();
        args.update_from_arg_matches(matches)?;
        Ok(args)
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        for spec in keys::ALL.iter().filter(|s| K::takes(s.key)) {
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
