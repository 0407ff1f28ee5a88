//! Warnings as data. A run that is valid but doubtful (a value outside its usual range, a result
//! beyond the model's range, a value the data does not give, a property given but not used)
//! returns a [`Diagnostic`] with its result instead of printing it: a library caller, a test or
//! the report sees what the command line prints (one `warning:` line each on stderr, silenced by
//! `--quiet`) and what its JSON output carries under the key `diagnostics`.

use serde::Serialize;

/// What kind of doubt a [`Diagnostic`] raises.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum Kind {
    /// A valid value outside the range usual for it (a typo or a unit slip?), computed anyway.
    Unusual,
    /// A result beyond the range the model is meant for (a large twist, a ball squashed past
    /// its radius, a re-contact), computed anyway.
    BeyondModel,
    /// A value the data does not give, taken from elsewhere (a string without friction data).
    MissingData,
    /// A property or key given that this run does not use ("noted, not used").
    NotUsed,
}

/// One doubt about a run: its kind, the field it is about and the sentence that says it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Diagnostic {
    /// What kind of doubt.
    pub kind: Kind,
    /// The parameter key or result field it is about (`ks`, `theta_end_deg`; `f1`, `density`
    /// or `string` for the frame frequency, the racket's mass density and the named string).
    pub field: String,
    /// One line, as the command line prints it after `warning: `.
    pub sentence: String,
}

impl Diagnostic {
    /// A diagnostic of `kind` about `field`.
    pub fn new(kind: Kind, field: impl Into<String>, sentence: impl Into<String>) -> Self {
        Diagnostic { kind, field: field.into(), sentence: sentence.into() }
    }
}

impl std::fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.sentence)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_diagnostic_is_its_sentence_and_serialises_with_its_kind_and_field() {
        let d = Diagnostic::new(Kind::BeyondModel, "theta_end_deg", "twist theta_end = 20 deg is beyond ...");
        assert_eq!(d.to_string(), "twist theta_end = 20 deg is beyond ...");
        let v = serde_json::to_value(&d).unwrap();
        assert_eq!(v["kind"], "beyond_model");
        assert_eq!(v["field"], "theta_end_deg");
    }
}
