//! The crate's one error type.
//!
//! Every message is a single line that names the offending field (with the name used by the
//! command-line flags and config files), the value given and the allowed range, so the CLI can
//! print it as is and exit with code 2.

use std::path::PathBuf;

/// Everything that can go wrong in the library.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A parameter is outside its physical or numerical range.
    #[error("invalid {field} = {value}: {allowed}")]
    InvalidParameter {
        /// Flag / config key of the parameter (`ks`, `x`, `dt`, ...).
        field: &'static str,
        /// The value as given.
        value: String,
        /// The allowed range, in words with units.
        allowed: String,
    },
    /// A racket file could not be read or parsed.
    #[error("racket file {path}: {message}")]
    RacketFile {
        /// The file.
        path: PathBuf,
        /// What is wrong with it (one line).
        message: String,
    },
    /// A config file could not be read or parsed.
    #[error("config file {path}: {message}")]
    Config {
        /// The file.
        path: PathBuf,
        /// What is wrong with it (one line).
        message: String,
    },
    /// The impact did not finish within the simulated-time limit.
    #[error(
        "impact did not end within {limit_s:.4e} s of simulated time (the ball never left the \
         strings); check ks, k1 and the racket parameters"
    )]
    ImpactDidNotEnd {
        /// The limit that was reached, s.
        limit_s: f64,
    },
    /// The integration lost energy conservation beyond the guard (a step too close to the
    /// stability limit, or parameters far outside the model's range).
    #[error(
        "energy not conserved: relative error {error:.3e} exceeds {limit:.0e}; use a smaller dt \
         (the default is converged) or check the parameters"
    )]
    EnergyDrift {
        /// The largest relative energy error seen.
        error: f64,
        /// The guard.
        limit: f64,
    },
    /// The vibrating frame met the ball again after separation, which the model does not
    /// follow; an experiment refuses to fold such an impact into its numbers.
    #[error(
        "re-contact after separation at x = {x} m, r = {r} m, ks = {ks} N/m: the vibrating frame \
         catches the ball again, which the model does not follow"
    )]
    Recontact {
        /// Impact position, m.
        x: f64,
        /// Off-axis distance, m.
        r: f64,
        /// String stiffness, N/m.
        ks: f64,
    },
    /// Explicit time stepping would take too long for these parameters.
    #[error(
        "these parameters need about {steps:.2e} time steps of {dt_s:.3e} s on {nodes} nodes (limit \
         {limit:.0e} node-steps): the frame is too stiff, too light or too finely divided, or the \
         contact too soft, for explicit time stepping; check ei, mass, length, segments, ks, k1, mb, ix"
    )]
    TooManySteps {
        /// Estimated steps for the contact limit plus the post-impact window.
        steps: f64,
        /// The time step, s.
        dt_s: f64,
        /// Beam nodes.
        nodes: usize,
        /// The limit on steps x nodes.
        limit: f64,
    },
    /// The modal solver's closed-form free vibration would take too long to search for its
    /// peak: too many samples of too many modes over two fundamental periods.
    #[error(
        "these parameters need about {work:.2e} mode-samples (limit {limit:.0e}) to follow the free \
         vibration of {modes} modes over two fundamental periods (f1 = {f1_hz:.3e} Hz) at the fastest \
         kept mode: the frame is too flexible, or the contact too stiff, for the modal solver; check \
         ei, mass, length, segments, ks, k1"
    )]
    TooManySamples {
        /// Estimated mode-samples.
        work: f64,
        /// Retained flexible modes.
        modes: usize,
        /// First frame frequency, Hz.
        f1_hz: f64,
        /// The limit on mode-samples.
        limit: f64,
    },
    /// The tangential contact of an oblique or spinning ball would take too many steps.
    #[error(
        "the tangential contact needs up to {steps:.2e} steps over the longest contact allowed \
         (limit {limit:.0e}): the ball's spin or the tangential spring is too fast for it; check kt, mb, \
         ball-radius, ball-inertia-factor, ix"
    )]
    TooManyTangentialSteps {
        /// The steps at most.
        steps: f64,
        /// The limit.
        limit: f64,
    },
    /// A result came out non-finite (guard; parameter ranges are meant to prevent it).
    #[error("the impact produced a non-finite {field}; the parameters are outside the model's range")]
    NonFinite {
        /// The offending result field.
        field: &'static str,
    },
    /// The expansion-law root solve (Eq 10) failed; should not happen for valid inputs.
    #[error("expansion-law solve (Eq 10) did not converge for Y_T/Y0 = {z}")]
    ContactSolve {
        /// The normalised total compression at which it failed.
        z: f64,
    },
    /// Reading or writing a file failed.
    #[error("{path}: {message}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The operating-system message.
        message: String,
    },
    /// One point of a sweep failed: the error, after the point's swept values.
    #[error("at {point}: {source}")]
    AtPoint {
        /// The swept values, `x = 0.1, segments = 4`.
        point: String,
        /// What failed there.
        source: Box<Error>,
    },
    /// Several problems found together (a racket description checks every key before it says
    /// what is wrong), as one line: `N problems: first; second; ...`. Its reader names the file
    /// ([`crate::racket::RacketSpec::from_toml_bytes`]).
    #[error("{} problems: {}", .0.len(), one_line(.0))]
    Several(Vec<Error>),
    /// An unknown experiment id was requested (quoted: [`crate::numfmt::quoted`]).
    #[error("unknown experiment id '{0}' (see `racket-impact figures --list`)")]
    UnknownExperiment(String),
    /// The run was stopped (Ctrl-C in Python, [`crate::control::Control::cancel`]) before it ended.
    #[error("the run was interrupted before it ended")]
    Cancelled,
    /// A run estimated above the ten minutes a run may take, not asked for as long
    /// ([`crate::command`]): what the user asked for, then the estimate.
    #[error(
        "{asked}: the run is estimated at {estimate}, above the {limit} a run may take unless --long is \
         given: give --long to run it anyway, or {fewer}"
    )]
    TooLong {
        /// What was asked for, in the user's terms (`the default 256 samples (768 impacts)`).
        asked: String,
        /// The estimate in words.
        estimate: String,
        /// The limit in words (`10 min`).
        limit: String,
        /// What would make it shorter (`fewer samples`).
        fewer: String,
    },
    /// Plot rendering failed.
    #[error("plot {id}: {message}")]
    Plot {
        /// The experiment id.
        id: String,
        /// The backend's message.
        message: String,
    },
}

/// The errors `errors` on one line, `first; second; ...`.
fn one_line(errors: &[Error]) -> String {
    errors.iter().map(ToString::to_string).collect::<Vec<_>>().join("; ")
}

/// Shorthand for `Result<T, racket_impact::Error>`.
pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// Build an [`Error::InvalidParameter`].
    /// A value that is a number is shown readably: to [`MESSAGE_DIGITS`] significant digits,
    /// with an exponent where it is very large or small (`1e30`, not 31 digits;
    /// `2.1`, not `2.0999999999999996`); any other text as it is.
    ///
    /// [`MESSAGE_DIGITS`]: crate::numfmt::MESSAGE_DIGITS
    pub fn invalid(field: &'static str, value: impl std::fmt::Display, allowed: impl Into<String>) -> Self {
        Error::InvalidParameter { field, value: crate::numfmt::shown(&value.to_string()), allowed: allowed.into() }
    }

    /// A row of a compiled-in CSV table (`what`: which table, `text` its contents) that does not
    /// read: the file and line ([`csv_line`]), the column by its header name and what was wrong
    /// with it.
    pub fn csv_row(what: &'static str, file: &str, text: &str, headers: &csv::StringRecord, err: &csv::Error) -> Self {
        let line = err.position().map_or(0, |p| csv_line(text, p));
        let reason = match err.kind() {
            csv::ErrorKind::Deserialize { err, .. } => {
                let column = err.field().and_then(|i| headers.get(i as usize)).unwrap_or("?");
                // (the cell may be quoted in the reason: `unknown variant ...`)
                format!(
                    "column {}: {}",
                    crate::numfmt::quoted(column),
                    crate::numfmt::quoted_up_to(&err.kind().to_string(), 300)
                )
            }
            csv::ErrorKind::UnequalLengths { expected_len, len, .. } => {
                format!("{len} fields where the header has {expected_len}")
            }
            _ => err.to_string(),
        };
        Error::invalid(what, format!("{file}:{line}"), reason)
    }

    /// Whether the error is a cancelled run's, or carries one (a sweep's point, several).
    pub fn is_cancelled(&self) -> bool {
        match self {
            Error::Cancelled => true,
            Error::AtPoint { source, .. } => source.is_cancelled(),
            Error::Several(all) => all.iter().any(Error::is_cancelled),
            _ => false,
        }
    }

    /// Build an [`Error::Io`] from a path and an `std::io::Error`.
    pub fn io(path: impl Into<PathBuf>, err: impl std::fmt::Display) -> Self {
        Error::Io { path: path.into(), message: err.to_string() }
    }
}

/// The 1-based line of `text` on which the record that csv reports at `at` starts. csv places a
/// record that follows blank lines at the first of them (its `Position::line` too), so they are
/// skipped here.
pub fn csv_line(text: &str, at: &csv::Position) -> u64 {
    let from = usize::try_from(at.byte()).unwrap_or(text.len()).min(text.len());
    let rest = &text[from..];
    let start = from + rest.len() - rest.trim_start_matches(['\r', '\n']).len();
    1 + text[..start].matches('\n').count() as u64
}
