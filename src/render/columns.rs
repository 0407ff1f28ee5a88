//! The few column names of the commands' tables that no declaration holds (the speeds', a
//! map's, the modes' and a sweep's solver column).

/// The columns of the commands' tables that are neither a parameter's column
/// ([`crate::params::keys`]) nor a result field ([`crate::solve::outcome::FIELDS`]): each with
/// its unit in its name where it has one (or, for the speeds, the `unit` column beside it).
/// With the time series' [`super::impact::SERIES_COLUMNS`] they are the vocabulary
/// every CSV a command writes draws from (tests/vocabulary.rs).
pub const OTHER_COLUMNS: &[&str] = &[
    // speed
    "variant",
    "ball_speed_out",
    "change_pct",
    "unit",
    "launch_deg",
    "launch_spin_rpm",
    // map (a difference map's columns end in _a, _b and _b_minus_a)
    "power_pct",
    "ks_a_n_per_m",
    "ks_b_n_per_m",
    // modes
    "mode",
    "frequency_hz",
    // sweep: the solver that ran
    "solver",
];
