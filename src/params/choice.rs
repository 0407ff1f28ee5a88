//! A parameter that takes one of a list of names (a frame, a grip, a law, a solver), declared
//! from one list by `choice_enum!`: its variants with their names and help lines, its
//! default, and from that its list of values, its names for the help, its flag parsing and its
//! serde form (the name as a string). Every count and list of a choice's values is read from
//! that list ([`Choice`](super::spec::Choice), `ALL`), never typed.

/// Declares a choice enum from one list: each variant with its config name and what it means
/// (its doc and its help line), the default; and from that its `ALL`, `CHOICES`, `name`, flag
/// parsing and serde form (the name, as a string; an unknown name is serde's "unknown variant",
/// with the names expected).
///
/// A name is a string literal, or a parenthesised expression that is one at compile time
/// (`(stringify!(bed))`, for a list that names a file by its choice).
macro_rules! choice_enum {
    ($(#[doc = $doc:literal])+ $name:ident (default $default:ident) { $($variant:ident = $key:tt: $help:literal,)+ }) => {
        $(#[doc = $doc])+
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum $name {
            $(#[doc = $help] $variant,)+
        }

        impl Default for $name {
            fn default() -> Self {
                $name::$default
            }
        }

        impl $name {
            /// Every value, in the order of [`Self::CHOICES`].
            pub const ALL: [$name; [$($key),+].len()] = [$($name::$variant),+];
            /// The names on the command line and in configs, with what they mean.
            pub const CHOICES: &'static [$crate::params::spec::Choice] =
                &[$($crate::params::spec::Choice { name: $key, help: Some($help) }),+];
            /// The names alone, in the same order.
            const NAMES: &'static [&'static str] = &[$($key),+];

            /// The name used on the command line and in configs.
            pub fn name(self) -> &'static str {
                Self::CHOICES[self as usize].name
            }
        }

        impl $crate::params::spec::FlagValue for $name {
            const VALUES: $crate::params::spec::Values = $crate::params::spec::Values::Choice($name::CHOICES);
            fn parse_flag(key: &'static str, text: &str) -> $crate::error::Result<Self> {
                let names: Vec<($name, &str)> = $name::ALL.into_iter().map(|v| (v, v.name())).collect();
                $crate::params::spec::one_of(key, text, &names)
            }
        }

        impl ::serde::Serialize for $name {
            fn serialize<S: ::serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
                s.serialize_str(self.name())
            }
        }

        impl<'de> ::serde::Deserialize<'de> for $name {
            fn deserialize<D: ::serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
                struct Names;
                impl ::serde::de::Visitor<'_> for Names {
                    type Value = $name;
                    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                        write!(f, "one of {}", $name::NAMES.join(", "))
                    }
                    fn visit_str<E: ::serde::de::Error>(self, v: &str) -> std::result::Result<$name, E> {
                        $name::ALL.into_iter().find(|c| c.name() == v).ok_or_else(|| E::unknown_variant(v, $name::NAMES))
                    }
                }
                d.deserialize_str(Names)
            }
        }
    };
}
pub(crate) use choice_enum;
