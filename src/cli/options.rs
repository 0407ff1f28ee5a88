//! A command's own options on the command line: one clap argument per option its request
//! declares ([`racket_impact::command::Opt`]), read as the texts given into
//! [`Given`], which the request checks (as the parameter flags are built from their
//! declarations in [`super::overrides`]).

use clap::{Arg, ArgAction, ArgMatches, Command, FromArgMatches};
use racket_impact::command::{self, Given, Kind, Many, Opt};

/// The options of one command, as its request declares them.
pub trait Declared: std::fmt::Debug + Clone + Send + Sync + 'static {
    /// The declarations.
    const OPTIONS: &'static [Opt];
}

/// Declares a [`Declared`] for each command: `name = the options`.
macro_rules! declared {
    ($($(#[doc = $doc:literal])* $name:ident = $options:expr;)+) => {$(
        $(#[doc = $doc])*
        #[derive(Debug, Clone, Copy, Default)]
        pub struct $name;
        impl Declared for $name {
            const OPTIONS: &'static [Opt] = $options;
        }
    )+};
}

declared! {
    /// `simulate`'s options.
    SimulateOptions = command::simulate::OPTIONS;
    /// `sweep`'s options.
    SweepOptions = command::sweep::OPTIONS;
    /// `card`'s options.
    CardOptions = command::card::OPTIONS;
    /// `map`'s options.
    MapOptions = command::map::OPTIONS;
    /// `uncertainty`'s options.
    UncertaintyOptions = command::uncertainty::OPTIONS;
    /// `speed`'s options.
    SpeedOptions = command::speed::OPTIONS;
    /// `modes`'s options.
    ModesOptions = command::modes::OPTIONS;
    /// `calibrate`'s options.
    CalibrateOptions = command::calibrate::OPTIONS;
}

/// The options of a command, as given on its command line.
#[derive(Debug, Clone)]
pub struct Options<D: Declared>(pub Given, std::marker::PhantomData<D>);

impl<D: Declared> Default for Options<D> {
    fn default() -> Self {
        Options(Given::new(D::OPTIONS), std::marker::PhantomData)
    }
}

/// The clap argument's id of an option: its name with underscores (as clap's derive names a
/// field).
pub fn id(opt: &Opt) -> String {
    opt.keyword()
}

/// The clap argument of one option: `--NAME` with its help, its default and its choices; the
/// texts are taken as given (the request reads and checks them, with one message for both
/// front ends).
fn arg(opt: &Opt) -> Arg {
    let mut help = opt.help.to_string();
    if let Kind::Choice(names) = opt.kind {
        help += &format!(" [possible values: {}]", names.join(", "));
    }
    if let Some(d) = opt.default {
        help += &format!(" [default: {d}]");
    }
    let arg = Arg::new(id(opt)).long(opt.name).help(help).required(opt.required);
    let arg = match opt.heading {
        Some(h) => arg.help_heading(h),
        None => arg,
    };
    if opt.kind == Kind::Switch {
        return arg.action(ArgAction::SetTrue);
    }
    let arg = arg.value_name(opt.name.to_uppercase().replace('-', "_")).allow_hyphen_values(true);
    match opt.many {
        Many::One => arg.action(ArgAction::Set),
        Many::List => arg.action(ArgAction::Append).value_delimiter(','),
        Many::Repeated => arg.action(ArgAction::Append),
    }
}

impl<D: Declared> clap::Args for Options<D> {
    fn augment_args(cmd: Command) -> Command {
        D::OPTIONS.iter().filter(|o| o.cli).fold(cmd, |cmd, opt| cmd.arg(arg(opt)))
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}

impl<D: Declared> FromArgMatches for Options<D> {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        let mut options = Options::default();
        options.update_from_arg_matches(matches)?;
        Ok(options)
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        let bad = |e: racket_impact::Error| clap::Error::raw(clap::error::ErrorKind::ValueValidation, e.to_string());
        for opt in D::OPTIONS.iter().filter(|o| o.cli) {
            let id = id(opt);
            if opt.kind == Kind::Switch {
                if matches.get_flag(&id) {
                    self.0.set(opt.name, "true").map_err(bad)?;
                }
                continue;
            }
            for text in matches.get_raw(&id).into_iter().flatten() {
                self.0.set(opt.name, text.to_string_lossy()).map_err(bad)?;
            }
        }
        Ok(())
    }
}
