//! What a parameter declaration is: [`ParamSpec`] (key, help, unit, range, ...), the kinds of
//! value a key takes ([`FlagValue`]), the range checks whose messages every validation uses, and
//! the `declare_params!` macro that turns the one table in [`keys`](super::keys) into the
//! specs, the [`Overrides`](super::Overrides) struct and its key list, setter, merge and apply.

use crate::error::{Error, Result};

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
        Err(Error::invalid(field, v, format!("{what} must satisfy {lo:e} <= {field} <= {hi:e} {unit}")))
    }
}

/// A value a parameter key takes, parsed from its text as a flag would be.
pub trait FlagValue: Sized {
    /// The kind of value, for the declaration.
    const VALUES: Values;
    /// Parse `text` (surrounding spaces ignored) for the parameter `key`.
    fn parse_flag(key: &'static str, text: &str) -> Result<Self>;
}

impl FlagValue for f64 {
    const VALUES: Values = Values::Number;
    fn parse_flag(key: &'static str, text: &str) -> Result<Self> {
        text.trim().parse::<f64>().map_err(|_| Error::invalid(key, text, "must be a number"))
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
/// where `check` is `within(lo, hi)`, `rule` or `choice`.
macro_rules! declare_params {
    ($(
        #[doc = $doc:literal]
        $konst:ident $field:ident: $ty:ty = $key:literal at $($place:ident).+,
        what $what:literal, unit $unit:literal, column $column:literal, $check:ident $(($lo:expr, $hi:expr))?;
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
            };
        )*

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
}

pub(crate) use declare_params;
