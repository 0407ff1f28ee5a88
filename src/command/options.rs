//! A command's own options (not the impact parameters, which `params::keys` declares), each
//! declared once ([`Opt`]): the command line builds its flags from the declaration and the
//! Python package its keywords, and both hand the texts as given to [`Given`], from which the
//! request reads each one with the declared checks, so that a bad value gets one message
//! whichever front end gave it.

use crate::error::{Error, Result};
use crate::params::number::parse_number;

/// What values an option takes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kind {
    /// On or off: `--long` on the command line, `long=True` in Python.
    Switch,
    /// A whole number in `lo..=hi`.
    Count {
        /// The least allowed.
        lo: u64,
        /// The most allowed.
        hi: u64,
    },
    /// A real number (its range is the request's to check: it often depends on others).
    Number,
    /// A text: a name, a file, a `KEY=DIST`.
    Text,
    /// One of these names.
    Choice(&'static [&'static str]),
}

/// How many values an option takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Many {
    /// One.
    One,
    /// A list: comma-separated on the command line (`--compare-tension-lb 50,60`), a sequence
    /// in Python.
    List,
    /// Repeatable (`--vary A --vary B`), a sequence in Python.
    Repeated,
}

/// One option of a command, declared once.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Opt {
    /// Its flag without the dashes (`compare-tension-lb`); the Python keyword is the same with
    /// underscores.
    pub name: &'static str,
    /// What values it takes.
    pub kind: Kind,
    /// How many.
    pub many: Many,
    /// The default, as the flag would be given it (`41`); `None`: none, or one that depends on
    /// other options (the help says which).
    pub default: Option<&'static str>,
    /// What it does, one line (with its unit and range where the kind does not say them).
    pub help: &'static str,
    /// Whether the command line has this flag: `false` for an option the command line sets
    /// from an output option of its own (`simulate --series FILE` asks for the time series).
    pub cli: bool,
    /// The heading the command line's help lists it under (`None`: the command's own options).
    pub heading: Option<&'static str>,
    /// Whether it must be given (it then has no default).
    pub required: bool,
}

impl Opt {
    /// An option with one value, on both front ends.
    pub const fn new(name: &'static str, kind: Kind, default: Option<&'static str>, help: &'static str) -> Opt {
        Opt { name, kind, many: Many::One, default, help, cli: true, heading: None, required: false }
    }

    /// The option, which must be given.
    pub const fn required(self) -> Opt {
        Opt { required: true, ..self }
    }

    /// The option listed under `heading` in the command line's help.
    pub const fn heading(self, heading: &'static str) -> Opt {
        Opt { heading: Some(heading), ..self }
    }

    /// The option taking a list (`Many::List`) or repeated (`Many::Repeated`).
    pub const fn many(self, many: Many) -> Opt {
        Opt { many, ..self }
    }

    /// The option the command line sets from an output option of its own.
    pub const fn not_on_cli(self) -> Opt {
        Opt { cli: false, ..self }
    }

    /// The Python keyword: the name with underscores.
    pub fn keyword(&self) -> String {
        self.name.replace('-', "_")
    }

    /// The allowed values in words, for a message: `a whole number, 2 <= nx <= 401`.
    pub fn allowed(&self) -> String {
        match self.kind {
            Kind::Switch => "must be true or false".into(),
            Kind::Count { lo, hi } => format!("must be a whole number, {lo} <= {} <= {hi}", self.name),
            Kind::Number => "must be a finite number".into(),
            Kind::Text => "must be a text".into(),
            Kind::Choice(names) => format!("must be one of {}", names.join(", ")),
        }
    }
}

/// `--long`: the ten-minute rule of every command whose work is estimated
/// ([`crate::command::execute`]).
pub const LONG: Opt = Opt::new(
    "long",
    Kind::Switch,
    None,
    "Run even when the work is estimated above ten minutes, which is refused without it (a run estimated \
     above a minute says so before it starts)",
);

/// The texts given for a command's options, as the front end read them.
#[derive(Debug, Clone)]
pub struct Given {
    opts: &'static [Opt],
    values: Vec<(&'static str, Vec<String>)>,
}

impl Given {
    /// Nothing given yet, of the options `opts`.
    pub fn new(opts: &'static [Opt]) -> Given {
        Given { opts, values: Vec::new() }
    }

    /// The declaration of the option `name` (its flag or its Python keyword).
    pub fn find(opts: &'static [Opt], name: &str) -> Option<&'static Opt> {
        opts.iter().find(|o| o.name == name || o.keyword() == name)
    }

    fn opt(&self, name: &str) -> &'static Opt {
        // (a request reads only the options it declares: a wrong name is a bug, caught by its tests)
        Given::find(self.opts, name).unwrap_or_else(|| panic!("option {name} is not declared"))
    }

    /// `text` given for the option `name` (its flag or its Python keyword): one more value of a
    /// list or a repeated option, the value of any other (given twice: refused).
    pub fn set(&mut self, name: &str, text: impl Into<String>) -> Result<()> {
        let opt = Given::find(self.opts, name).ok_or_else(|| {
            let known: Vec<&str> = self.opts.iter().map(|o| o.name).collect();
            Error::invalid("option", name, format!("unknown option (known: {})", known.join(", ")))
        })?;
        let text = text.into();
        match self.values.iter_mut().find(|(n, _)| *n == opt.name) {
            Some((_, texts)) if opt.many != Many::One => texts.push(text),
            Some(_) => return Err(Error::invalid(opt.name, text, "is given twice")),
            None => self.values.push((opt.name, vec![text])),
        }
        Ok(())
    }

    /// Whether the option was given.
    pub fn is_given(&self, name: &str) -> bool {
        let opt = self.opt(name);
        self.values.iter().any(|(n, _)| *n == opt.name)
    }

    /// The texts given, else the default's (one), else none.
    fn texts_or_default(&self, name: &str) -> (&'static Opt, Vec<String>) {
        let opt = self.opt(name);
        let given = self.values.iter().find(|(n, _)| *n == opt.name).map(|(_, t)| t.clone());
        (opt, given.unwrap_or_else(|| opt.default.map(|d| vec![d.to_string()]).unwrap_or_default()))
    }

    /// The one text of the option, or its default.
    fn one(&self, name: &str) -> (&'static Opt, Option<String>) {
        let (opt, texts) = self.texts_or_default(name);
        (opt, texts.into_iter().next())
    }

    /// A switch: given (`true`), not given or `false`.
    pub fn switch(&self, name: &str) -> Result<bool> {
        match self.one(name) {
            (_, None) => Ok(false),
            (opt, Some(t)) => match t.trim() {
                "true" | "" => Ok(true),
                "false" => Ok(false),
                other => Err(Error::invalid(opt.name, other, opt.allowed())),
            },
        }
    }

    /// A whole number within the declared range: given, else the default, else `None`.
    pub fn count(&self, name: &str) -> Result<Option<u64>> {
        let (opt, text) = self.one(name);
        text.map(|t| count(opt, &t)).transpose()
    }

    /// The whole numbers given (a list), each within the declared range.
    pub fn counts(&self, name: &str) -> Result<Vec<u64>> {
        let (opt, texts) = self.texts_or_default(name);
        texts.iter().map(|t| count(opt, t)).collect()
    }

    /// A finite number that must be given (a required option: [`Opt::required`]).
    pub fn required_number(&self, name: &str) -> Result<f64> {
        let opt = self.opt(name);
        self.number(name)?.ok_or_else(|| Error::invalid(opt.name, "(not given)", format!("is required: {}", opt.help)))
    }

    /// A finite number: given, else the default, else `None`.
    pub fn number(&self, name: &str) -> Result<Option<f64>> {
        let (opt, text) = self.one(name);
        text.map(|t| number(opt, &t)).transpose()
    }

    /// The finite numbers given (a list).
    pub fn numbers(&self, name: &str) -> Result<Vec<f64>> {
        let (opt, texts) = self.texts_or_default(name);
        texts.iter().map(|t| number(opt, t)).collect()
    }

    /// A text: given, else the default, else `None`.
    pub fn text(&self, name: &str) -> Option<String> {
        self.one(name).1
    }

    /// The texts given (a list or a repeated option), else the default's.
    pub fn texts(&self, name: &str) -> Vec<String> {
        self.texts_or_default(name).1
    }

    /// One of the declared names: given, else the default, else `None`.
    pub fn choice(&self, name: &str) -> Result<Option<&'static str>> {
        let (opt, text) = self.one(name);
        let Kind::Choice(names) = opt.kind else { return Ok(text.map(|_| "")) };
        text.map(|t| {
            names.iter().copied().find(|n| *n == t.trim()).ok_or_else(|| Error::invalid(opt.name, t, opt.allowed()))
        })
        .transpose()
    }

    /// What the user asked for with a count, in words opening a message: `1024 samples` as
    /// given, `the default 256 samples` when not.
    pub fn asked(&self, name: &str, value: u64, unit: &str) -> String {
        if self.is_given(name) {
            format!("{value} {unit}")
        } else {
            format!("the default {value} {unit}")
        }
    }
}

/// `text` as a whole number within `opt`'s range.
fn count(opt: &Opt, text: &str) -> Result<u64> {
    let (lo, hi) = match opt.kind {
        Kind::Count { lo, hi } => (lo, hi),
        _ => (0, u64::MAX),
    };
    // (the value as given, digits and all: `18446744073709551616`, not rounded as a number)
    let bad = || Error::InvalidParameter { field: opt.name, value: text.to_string(), allowed: opt.allowed() };
    let t = text.trim();
    // (digits only: no sign, no point, no exponent; a number beyond u64 is out of range too)
    if t.is_empty() || !t.bytes().all(|b| b.is_ascii_digit()) {
        return Err(bad());
    }
    match t.parse::<u64>() {
        Ok(v) if (lo..=hi).contains(&v) => Ok(v),
        _ => Err(bad()),
    }
}

/// `text` as a finite number.
fn number(opt: &Opt, text: &str) -> Result<f64> {
    match parse_number(text) {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(Error::invalid(opt.name, text, opt.allowed())),
        Err(why) => Err(Error::invalid(opt.name, text, why)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const OPTS: &[Opt] = &[
        Opt::new("nx", Kind::Count { lo: 2, hi: 401 }, Some("41"), "grid points"),
        Opt::new("compare-tension-lb", Kind::Number, None, "tensions").many(Many::List),
        Opt::new("quantity", Kind::Choice(&["power", "tau"]), Some("power"), "what"),
        LONG,
    ];

    #[test]
    fn each_value_is_read_with_its_declared_check_and_one_message() {
        let mut g = Given::new(OPTS);
        assert_eq!(g.count("nx").unwrap(), Some(41));
        assert_eq!(g.asked("nx", 41, "points"), "the default 41 points");
        assert!(!g.switch("long").unwrap());
        g.set("nx", "7").unwrap();
        g.set("compare_tension_lb", "50").unwrap();
        g.set("compare-tension-lb", "60").unwrap();
        g.set("long", "true").unwrap();
        assert_eq!(g.count("nx").unwrap(), Some(7));
        assert_eq!(g.asked("nx", 7, "points"), "7 points");
        assert_eq!(g.numbers("compare-tension-lb").unwrap(), vec![50.0, 60.0]);
        assert!(g.switch("long").unwrap());
        assert_eq!(g.choice("quantity").unwrap(), Some("power"));
        assert_eq!(g.set("nx", "8").unwrap_err().to_string(), "invalid nx = 8: is given twice");
        for bad in ["2.5", "-1", "1", "402", "18446744073709551616", "1e2", ""] {
            // (shown as given)
            let mut g = Given::new(OPTS);
            g.set("nx", bad).unwrap();
            let msg = g.count("nx").unwrap_err().to_string();
            assert_eq!(msg, format!("invalid nx = {bad}: must be a whole number, 2 <= nx <= 401"));
        }
        let mut g = Given::new(OPTS);
        g.set("compare-tension-lb", "NaN").unwrap();
        assert_eq!(
            g.numbers("compare-tension-lb").unwrap_err().to_string(),
            "invalid compare-tension-lb = NaN: must be a finite number"
        );
        assert!(g.set("nz", "1").unwrap_err().to_string().contains("unknown option (known: nx, "));
    }
}
