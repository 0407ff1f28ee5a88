//! What a parameter declaration is: [`ParamSpec`] (key, help, unit, range, ...), the kinds of
//! value a key takes ([`FlagValue`]), the range checks whose messages every validation uses, and
//! the `declare_params!` macro that turns the one table in [`keys`](super::keys) into the
//! specs, the [`Overrides`](super::Overrides) struct and its key list, setter, merge and apply.

use crate::error::{Error, Result};
use crate::numfmt::{readable, sig};

/// One impact parameter as the command line, the config files and the validation see it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParamSpec {
    /// The flag and config key (`half-width`).
    pub key: &'static str,
    /// The flag's help line, as the doc comment of its [`Overrides`](super::Overrides) field.
    pub doc: &'static str,
    /// What it is, in words, for the validation messages (`string-plane stiffness`).
    pub what: &'static str,
    /// Its unit (empty for a pure number).
    pub unit: &'static str,
    /// Its column in a sweep's CSV, with the SI unit (`ks_n_per_m`).
    pub column: &'static str,
    /// The kind of value it takes.
    pub values: Values,
    /// How a value is checked.
    pub check: Check,
    /// The range real rackets, balls and shots lie in, `(lo, hi)` in the parameter's unit:
    /// a value outside it is valid (it runs) but earns a warning ([`ParamSpec::unusual`]).
    pub usual: Option<(f64, f64)>,
    /// How uncertain the paper's value is, with the source of that (the inputs of the
    /// `robustness` experiment); `None` for a parameter the paper fixes by choice.
    pub uncertainty: Option<super::uncertainty::Uncertainty>,
}

/// The kind of value a parameter takes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Values {
    /// A real number.
    Number,
    /// A whole number.
    Count,
    /// One of these names.
    Choice(&'static [Choice]),
}

/// One name a choice parameter takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Choice {
    /// The name on the command line and in configs.
    pub name: &'static str,
    /// What it means, shown with the flag's help (`None` for a choice listed by name only).
    pub help: Option<&'static str>,
}

/// How a parameter's value is checked.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Check {
    /// A physical range, `lo <= v <= hi` ([`ParamSpec::check`]).
    Within(f64, f64),
    /// A rule of its own, in the `validate` of the struct that holds it (the impact point
    /// against the face, `1 < p`, the segment count, the grip against the racket's length).
    Rule,
    /// One of its names, checked when the text is parsed.
    Choice,
}

impl ParamSpec {
    /// The help line without the doc comment's leading space.
    pub fn help(&self) -> &'static str {
        self.doc.trim()
    }

    /// The allowed range of a [`Check::Within`] parameter (a compile error in a `const` for
    /// any other).
    pub const fn range(&self) -> (f64, f64) {
        match self.check {
            Check::Within(lo, hi) => (lo, hi),
            Check::Rule | Check::Choice => panic!("the parameter has no fixed range"),
        }
    }

    /// Check `v` against the range of a [`Check::Within`] parameter (others have their rules in
    /// their struct's `validate` and pass here).
    pub fn check(&self, v: f64) -> Result<()> {
        match self.check {
            Check::Within(lo, hi) => within(self.key, v, self.what, self.unit, (lo, hi)),
            Check::Rule | Check::Choice => Ok(()),
        }
    }

    /// For a value outside the [`usual`](ParamSpec::usual) range: one line naming the value
    /// and that range (`ks = 40 N/m is outside the usual 5e3..2e5 N/m of string-plane
    /// stiffness`); `None` inside it or for a parameter without one.
    pub fn unusual(&self, v: f64) -> Option<String> {
        let (lo, hi) = self.usual?;
        if (lo..=hi).contains(&v) {
            return None;
        }
        let unit = if self.unit.is_empty() { String::new() } else { format!(" {}", self.unit) };
        Some(format!(
            "{} = {}{unit} is outside the usual {}..{}{unit} of {} (computed anyway)",
            self.key,
            sig(v, 6),
            sig(lo, 3),
            sig(hi, 3),
            self.what
        ))
    }

    /// "must be a finite number (m)", naming the key.
    pub fn finite(&self, v: f64) -> Result<()> {
        if v.is_finite() {
            Ok(())
        } else {
            Err(Error::invalid(self.key, v, format!("must be a finite number ({})", self.unit)))
        }
    }

    /// "... must be a finite number > 0 s", naming the key.
    pub fn positive(&self, v: f64) -> Result<()> {
        positive(self.key, v, self.what, self.unit)
    }
}

/// "`what` must be a finite number > 0 `unit`", naming `field`.
pub(crate) fn positive(field: &'static str, v: f64, what: &str, unit: &str) -> Result<()> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(Error::invalid(field, v, format!("{what} must be a finite number > 0 {unit}")))
    }
}

/// A physical range check: `lo <= v <= hi`. The ranges are wide (far beyond any racket sport)
/// but keep every energy and frequency representable, so a result is never NaN.
pub(crate) fn within(field: &'static str, v: f64, what: &str, unit: &str, (lo, hi): (f64, f64)) -> Result<()> {
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(())
    } else {
        let (lo, hi) = (readable(lo), readable(hi));
        Err(Error::invalid(field, v, format!("{what} must satisfy {lo} <= {field} <= {hi} {unit}").trim_end()))
    }
}

/// A value a parameter key takes, parsed from its text as a flag would be.
pub trait FlagValue: Sized {
    /// The kind of value, for the declaration.
    const VALUES: Values;
    /// Parse `text` (surrounding spaces ignored) for the parameter `key`.
    fn parse_flag(key: &'static str, text: &str) -> Result<Self>;
}

/// A parameter's value in [`Params`](super::Params) as the flag would spell it (for the
/// defaults in `--help`), and as a number where it is one (for the plausibility warnings).
pub trait ShowValue {
    /// The value as text (`0.16`, `hat`, `auto` for an unset time step).
    fn show(&self) -> String;
    /// The value as a number, if it is one.
    fn number(&self) -> Option<f64> {
        None
    }
}

impl ShowValue for f64 {
    fn show(&self) -> String {
        sig(*self, 6)
    }
    fn number(&self) -> Option<f64> {
        Some(*self)
    }
}

impl ShowValue for usize {
    fn show(&self) -> String {
        self.to_string()
    }
    fn number(&self) -> Option<f64> {
        Some(*self as f64)
    }
}

/// The choice parameters show their name.
macro_rules! show_by_name {
    ($($t:ty),*) => {$(
        impl ShowValue for $t {
            fn show(&self) -> String {
                self.name().to_string()
            }
        }
    )*};
}
show_by_name!(
    super::LoadRule,
    super::SolverKind,
    super::Frame,
    super::Grip,
    super::StringLaw,
    super::TangentialLaw,
    super::StringName
);

impl ShowValue for Option<f64> {
    fn show(&self) -> String {
        self.map_or_else(|| "auto".to_string(), |v| v.show())
    }
    fn number(&self) -> Option<f64> {
        *self
    }
}

/// A number as written on the command line or in a file: refused (with the reason) where it
/// is not a number, or where it does not fit an f64 (`1e-400`, `1e400`: named as written, not
/// as the 0 or inf it rounds to). Every number option reads through this.
pub fn parse_number(text: &str) -> std::result::Result<f64, &'static str> {
    let t = text.trim();
    let v = t.parse::<f64>().map_err(|_| "must be a number")?;
    let mantissa = t.trim_start_matches(['+', '-']).split(['e', 'E']).next().unwrap_or("");
    let written_finite = mantissa.chars().all(|c| c.is_ascii_digit() || c == '.');
    if v == 0.0 && written_finite && mantissa.chars().any(|c| ('1'..='9').contains(&c)) {
        return Err("is too small to represent as a number (below about 1e-308)");
    }
    if v.is_infinite() && written_finite {
        return Err("is too large to represent as a number (above about 1.8e308)");
    }
    Ok(v)
}

impl FlagValue for f64 {
    const VALUES: Values = Values::Number;
    fn parse_flag(key: &'static str, text: &str) -> Result<Self> {
        parse_number(text).map_err(|why| Error::invalid(key, text, why))
    }
}

/// Largest allowed number of segments.
pub const MAX_SEGMENTS: usize = 400;
/// Smallest allowed number of segments (a free-free beam needs interior curvature points).
pub const MIN_SEGMENTS: usize = 4;

impl FlagValue for usize {
    const VALUES: Values = Values::Count;
    fn parse_flag(key: &'static str, text: &str) -> Result<Self> {
        // the one whole-number parameter is the segment count
        text.trim().parse().map_err(|_| {
            Error::invalid(key, text, format!("must be a whole number of {key}, {MIN_SEGMENTS} <= N <= {MAX_SEGMENTS}"))
        })
    }
}

/// Find `text` (trimmed) among `choices`; else "must be one of: a, b", naming `key`.
pub(crate) fn one_of<T: Copy>(key: &'static str, text: &str, choices: &[(T, &str)]) -> Result<T> {
    let name = text.trim();
    choices.iter().find(|(_, n)| *n == name).map(|(v, _)| *v).ok_or_else(|| {
        let names: Vec<&str> = choices.iter().map(|(_, n)| *n).collect();
        Error::invalid(key, text, format!("must be one of: {}", names.join(", ")))
    })
}

/// Declare the impact parameters, each once: the per-parameter [`ParamSpec`] constants, their
/// list `ALL`, and [`Overrides`](super::Overrides) (one optional field per key, the same struct
/// read from a config file) with `KEYS`, `set`, `or` and `apply`.
///
/// Each entry: the doc line (the flag's help), then
/// `CONST field: Type = "key" at place.in.params, what "...", unit "...", column "...", check;`
/// where `check` is `within(lo, hi)`, `rule` or `choice`, optionally followed by
/// `, usual(lo, hi)`: the range real equipment and shots lie in (outside it: a warning), and
/// optionally by `, uncertain(dist, nominal, "source")`: the paper value's uncertainty
/// ([`Uncertainty`](super::uncertainty::Uncertainty)).
macro_rules! declare_params {
    ($(
        #[doc = $doc:literal]
        $konst:ident $field:ident: $ty:ty = $key:literal at $($place:ident).+,
        what $what:literal, unit $unit:literal, column $column:literal, $check:ident $(($lo:expr, $hi:expr))?
        $(, usual($ulo:expr, $uhi:expr))?
        $(, uncertain($dist:expr, $nominal:expr, $source:literal))?;
    )*) => {
        $(
            #[doc = concat!("The `", $key, "` parameter:", $doc)]
            pub const $konst: ParamSpec = ParamSpec {
                key: $key,
                doc: $doc,
                what: $what,
                unit: $unit,
                column: $column,
                values: <$ty as FlagValue>::VALUES,
                check: declare_params!(@check $check $(($lo, $hi))?),
                usual: declare_params!(@usual $(($ulo, $uhi))?),
                uncertainty: declare_params!(@uncertain $(($dist, $nominal, $source))?),
            };
        )*

        /// The value of parameter `key` in `params`, as the flag would spell it (`None` for a
        /// key that is not a parameter).
        pub fn value_text(key: &str, params: &Params) -> Option<String> {
            use super::spec::ShowValue;
            match key {
                $($key => Some(params.$($place).+.show()),)*
                _ => None,
            }
        }

        /// The value of parameter `key` in `params` as a number, where it is one.
        pub fn value_number(key: &str, params: &Params) -> Option<f64> {
            use super::spec::ShowValue;
            match key {
                $($key => params.$($place).+.number(),)*
                _ => None,
            }
        }

        /// Every parameter, in the order of the flags.
        pub const ALL: [ParamSpec; [$($key),*].len()] = [$($konst),*];

        /// Overrides of [`Params`], one optional field per command-line flag. The same struct is the
        /// `--config` TOML file (keys spelled as the flags, unknown keys rejected), so a config and
        /// the flags can never drift apart. Precedence: paper defaults < config file < flags.
        #[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
        #[serde(deny_unknown_fields, rename_all = "kebab-case")]
        pub struct Overrides {
            $(
                #[doc = $doc]
                pub $field: Option<$ty>,
            )*
        }

        impl Overrides {
            /// The keys, spelled as the flags and config keys.
            pub const KEYS: [&'static str; [$($key),*].len()] = [$($key),*];

            /// Set one field from its text, as a flag would (used by `sweep`, which varies any key).
            pub fn set(&mut self, key: &str, value: &str) -> Result<()> {
                match key {
                    $($key => self.$field = Some(<$ty as FlagValue>::parse_flag($key, value)?),)*
                    _ => {
                        return Err(Error::Config {
                            path: "<sweep>".into(),
                            message: format!("unknown parameter '{key}' (known: {})", Self::KEYS.join(", ")),
                        })
                    }
                }
                Ok(())
            }

            /// The keys set, in the order of their declaration.
            pub fn given(&self) -> Vec<&'static str> {
                let mut keys = Vec::new();
                $(
                    if self.$field.is_some() {
                        keys.push($key);
                    }
                )*
                keys
            }

            /// Unset `key` (nothing if it is not a key).
            pub fn clear(&mut self, key: &str) {
                match key {
                    $($key => self.$field = None,)*
                    _ => {}
                }
            }

            /// Field-wise `self` where set, else `base`.
            pub fn or(self, base: Overrides) -> Overrides {
                Overrides { $($field: self.$field.or(base.$field),)* }
            }

            /// Apply the set fields to `params` (no validation: call [`Params::validate`] after).
            pub fn apply(&self, params: &mut Params) {
                $(
                    if let Some(v) = self.$field {
                        params.$($place).+ = v.into();
                    }
                )*
            }
        }
    };
    (@check within ($lo:expr, $hi:expr)) => { Check::Within($lo, $hi) };
    (@check rule) => { Check::Rule };
    (@check choice) => { Check::Choice };
    (@usual ($lo:expr, $hi:expr)) => { Some(($lo, $hi)) };
    (@usual) => { None };
    (@uncertain ($dist:expr, $nominal:expr, $source:literal)) => {
        Some(super::uncertainty::Uncertainty { dist: $dist, nominal: $nominal, source: $source })
    };
    (@uncertain) => { None };
}

pub(crate) use declare_params;
