//! What a parameter declaration is: [`ParamSpec`] (key, help, unit, range, help heading, role
//! and when an impact uses it, ...), the kinds of value a key takes ([`FlagValue`]), the range
//! checks whose messages every validation uses, and the `declare_params!` macro that turns the
//! one table in [`keys`](super::keys) into the specs, the [`Overrides`](super::Overrides) struct
//! and its key list, setter, merge and apply.
//!
//! A declaration is what every surface of a parameter is derived from: the command line's flag
//! (its help line, default and heading), the config key and its aliases, the validation
//! messages, the notes and refusals of a value an impact does not use
//! ([`used`](super::used)), the sweep column and the uncertainty. A library caller (the Python
//! bindings) reads the same: [`ParamSpec::key`], [`ParamSpec::name`], [`ParamSpec::unit`],
//! [`ParamSpec::range_text`], [`ParamSpec::help`], [`ParamSpec::heading`],
//! [`ParamSpec::used_when`] and, for the default, [`keys::value_text`](super::keys::value_text)
//! of the parameters a command starts from.

use super::number::parse_number;
use crate::error::{Error, Result};
use crate::numfmt::{readable, sig};

/// One impact parameter as the command line, the config files and the validation see it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParamSpec {
    /// The flag and config key (`half-width`).
    pub key: &'static str,
    /// The key as an identifier: its field in [`Overrides`](super::Overrides), and the name a
    /// program (a Python keyword, a JSON member) spells it by: the key with underscores
    /// (`half_width`).
    pub name: &'static str,
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
    /// What it describes: the heading its flag is listed under in the help.
    pub heading: Heading,
    /// Whether it is a property (of the racket, ball, strings or shot) or a method's option:
    /// what a value given for it is told where an impact does not use it.
    pub role: Role,
    /// Which impacts use it.
    pub used_when: UsedWhen,
    /// How its default is chosen, where the value alone does not say (`on the long axis`).
    pub default_words: Option<&'static str>,
}

/// What a parameter describes, the heading its flag is listed under in the help, in the order
/// the help shows them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Heading {
    /// Where and how fast the ball arrives.
    Impact,
    /// The racket: its frame, how it is held.
    Racket,
    /// The ball.
    Ball,
    /// The string bed and the strings.
    Strings,
    /// An oblique or spinning ball: incidence, spin, friction, the tangential law.
    Oblique,
    /// The discretisation and the solver.
    Numerics,
}

impl Heading {
    /// Every heading, in the order the help shows them.
    pub const ALL: [Heading; 6] =
        [Heading::Impact, Heading::Racket, Heading::Ball, Heading::Strings, Heading::Oblique, Heading::Numerics];

    /// The heading as the help prints it.
    pub const fn title(self) -> &'static str {
        match self {
            Heading::Impact => "Impact",
            Heading::Racket => "Racket",
            Heading::Ball => "Ball",
            Heading::Strings => "Strings",
            Heading::Oblique => "Oblique impact",
            Heading::Numerics => "Numerics",
        }
    }
}

/// What a parameter is, which decides what a value given for it is told where an impact does not
/// use it (the brief, issue 32): a *property* of the racket, ball, strings or shot that the
/// impact does not exercise is accepted with one note, so that a script describing one racket
/// and ball can loop over impact points, angles and models; an *option of a method* the chosen
/// method cannot honour is refused. (An option unused only because of where and how the ball
/// arrives, a tangential law at normal incidence, is noted: no method was chosen against it.)
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    /// Describes the racket, the ball, the strings or the shot.
    Property,
    /// Chooses or sets up a model or a solver (a frame, a grip, a law, a step).
    MethodOption,
}

/// Which impacts use a parameter ([`super::used`] says why one does not, and whether a value
/// given for it is then noted or refused).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum UsedWhen {
    /// Every impact.
    Always,
    /// An oblique or spinning ball only: at normal incidence without spin no tangential force
    /// acts.
    Oblique,
    /// An impact off the long axis (`r != 0`) only.
    OffAxis,
    /// An impact off the long axis or an oblique ball only: nothing else twists the frame.
    Twisted,
    /// Only where the choice parameter `.0` is used and takes one of the values named `.1` (for
    /// the tangential law: a law with that mechanism, so `physical` too).
    In(&'static ParamSpec, &'static [&'static str]),
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
    /// against the face, `1 < p`, the segment count, the grip against the racket's length),
    /// in words (`0 <= x <= length`).
    Rule(&'static str),
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
            Check::Rule(_) | Check::Choice => panic!("the parameter has no fixed range"),
        }
    }

    /// Check `v` against the range of a [`Check::Within`] parameter (others have their rules in
    /// their struct's `validate` and pass here).
    pub fn check(&self, v: f64) -> Result<()> {
        match self.check {
            Check::Within(lo, hi) => within(self.key, v, self.what, self.unit, (lo, hi)),
            Check::Rule(_) | Check::Choice => Ok(()),
        }
    }

    /// The values it accepts, in words: `1 <= ks <= 1e12 N/m` (as its validation message says
    /// them), its rule (`0 <= x <= length`), or its choices (`one of: node, hat`).
    pub fn range_text(&self) -> String {
        match (self.check, self.values) {
            (Check::Within(lo, hi), _) => {
                format!("{} <= {} <= {} {}", readable(lo), self.key, readable(hi), self.unit).trim_end().to_string()
            }
            (Check::Rule(words), _) => words.to_string(),
            (Check::Choice, Values::Choice(choices)) => {
                format!("one of: {}", choices.iter().map(|c| c.name).collect::<Vec<_>>().join(", "))
            }
            (Check::Choice, _) => String::new(),
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
            crate::numfmt::given(v, 6),
            sig(lo, 3),
            sig(hi, 3),
            self.what
        ))
    }

    /// One warning line when the draws of `dist` for this parameter reach outside its usual
    /// range (the range `simulate` warns with); `None` inside it or for a parameter without one.
    pub fn unusual_draws(&self, dist: &super::uncertainty::Dist) -> Option<String> {
        let (ulo, uhi) = self.usual?;
        let ((lo, hi), which) = dist.plausibility_range();
        if lo >= ulo && hi <= uhi {
            return None;
        }
        let unit = if self.unit.is_empty() { String::new() } else { format!(" {}", self.unit) };
        Some(format!(
            "{} = {} reaches {}..{}{unit} ({which}), outside the usual {}..{}{unit} of {} (drawn anyway)",
            self.key,
            dist.text(),
            sig(lo, 6),
            sig(hi, 6),
            sig(ulo, 3),
            sig(uhi, 3),
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
/// `CONST field: Type = "key" at place.in.params, what "...", unit "...", column "...", check,`
/// where `check` is `within(lo, hi)`, `rule "words"` or `choice`; then
/// `under Heading, Role, used UsedWhen` ([`Heading`], [`Role`], [`UsedWhen`], by variant name),
/// optionally followed by `, default WORDS`: how its default is chosen; by
/// `, usual(lo, hi)`: the range real equipment and shots lie in (outside it: a warning); and by
/// `, uncertain(dist, nominal, "source")`: the paper value's uncertainty
/// ([`Uncertainty`](super::uncertainty::Uncertainty)).
macro_rules! declare_params {
    ($(
        #[doc = $doc:literal]
        $konst:ident $field:ident: $ty:ty = $key:literal at $($place:ident).+,
        what $what:literal, unit $unit:literal, column $column:literal, $check:ident $(($lo:expr, $hi:expr))? $($words:literal)?,
        under $heading:ident, $role:ident, used $used:ident $(($($when:tt)*))?
        $(, default $default:expr)?
        $(, usual($ulo:expr, $uhi:expr))?
        $(, uncertain($dist:expr, $nominal:expr, $source:literal))?;
    )*) => {
        $(
            #[doc = concat!("The `", $key, "` parameter:", $doc)]
            pub const $konst: ParamSpec = ParamSpec {
                key: $key,
                name: stringify!($field),
                doc: $doc,
                what: $what,
                unit: $unit,
                column: $column,
                values: <$ty as FlagValue>::VALUES,
                check: declare_params!(@check $check $(($lo, $hi))? $($words)?),
                usual: declare_params!(@usual $(($ulo, $uhi))?),
                uncertainty: declare_params!(@uncertain $(($dist, $nominal, $source))?),
                heading: super::spec::Heading::$heading,
                role: super::spec::Role::$role,
                used_when: super::spec::UsedWhen::$used $(($($when)*))?,
                default_words: declare_params!(@default $($default)?),
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
                            message: format!("unknown parameter '{}' (known: {})", crate::numfmt::quoted(key), Self::KEYS.join(", ")),
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
    (@check rule $words:literal) => { Check::Rule($words) };
    (@check choice) => { Check::Choice };
    (@usual ($lo:expr, $hi:expr)) => { Some(($lo, $hi)) };
    (@usual) => { None };
    (@uncertain ($dist:expr, $nominal:expr, $source:literal)) => {
        Some(super::uncertainty::Uncertainty { dist: $dist, nominal: $nominal, source: $source })
    };
    (@uncertain) => { None };
    (@default $words:expr) => { Some($words) };
    (@default) => { None };
}

pub(crate) use declare_params;
