//! A racket description in the units of a spec sheet, fitted to the model's [`Racket`](crate::params::Racket).
//!
//! A [`RacketSpec`] is a TOML file (or a built-in preset, [`preset_names`]) whose keys carry
//! their unit in the name. [`RacketSpec::to_racket`] turns it into the model's parameters for a
//! beam of `N` segments and reports how well the discrete model reproduces each stated number
//! ([`FitReport`]).
//!
//! ```toml
//! name = "my frame"
//! length_in = 27                 # or length_cm
//! mass_g = 305                   # strung
//! balance_cm = 33.0              # from the butt; or balance_pts_hl = 4
//! swingweight_kg_cm2 = 305       # about the axis 10 cm from the butt
//! twistweight_kg_cm2 = 14.5      # about the long axis
//! frequency_hz = 150             # free-free first bending; or ei_n_m2 = 150
//! stiffness_ratio = [1.0, 1.4, 1.4, 1.2]    # optional EI shape at tip, head end, handle start, butt
//! head_size_sq_in = 100          # or head_length_cm + head_width_cm
//! head_aspect = 1.30             # optional; default DEFAULT_HEAD_ASPECT = 1.35
//! handle_length_cm = 19          # optional
//! tension_lb = 55                # or tension_kg, string_bed_n_per_m, dt_kp_cm; default 4e4 N/m
//! [ball]                         # optional; defaults are the paper's ball
//! mass_g = 57
//! k1_n_per_m = 3e4
//! p = 2.55
//! ```
//!
//! ## Conversions and the assumptions behind them
//! ```text
//! length      L = length_cm / 100 m,  or  L = 0.0254 length_in m
//! mass        M = mass_g / 1000 kg, the STRUNG mass: the model's strings are massless
//!             (Eq 2), so the strings, grip and bumper are lumped into the frame's density
//! balance     b = balance_cm (from the butt),  or  b = L/2 - balance_pts_hl * 1/8 in
//!             (1 point = 3.175 mm head-light; negative = head-heavy); x_cm = L - b from the tip
//! swingweight SW = sum_i m_i (x_a - x_i)^2 on the discrete beam, x_a = L - 10 cm (the usual
//!             swingweight machine axis); kg cm^2 / 1e4 = kg m^2
//! twistweight I_x = twistweight_kg_cm2 / 1e4 kg m^2 (Eq 7's rigid twist about the long axis)
//! stiffness   EI(x) = ei * stiffness_ratio(x/L); with frequency_hz, ei is scaled so that the
//!             discrete beam's first free-free bending frequency equals it at N (omega^2 is
//!             proportional to ei at fixed masses; exact to the eigen solver's rounding, about
//!             1e-9 relative at N = 160); with ei_n_m2, ei is taken as is
//! head        string face = ellipse from the tip, length l along and width w across the
//!             racket; from head_size_sq_in = A and head_aspect = a = l/w (absent: 1.35, the
//!             proportion of the largest legal string face, ITF Rules of Tennis App. I):
//!             A = pi/4 l w  =>  w = sqrt(4 A / (pi a)), l = a w   (1 sq in = 6.4516 cm^2).
//!             The quoted head size is the strung area; its ellipse is placed at the tip,
//!             ignoring the frame's thickness there. No head keys: the paper's strip over the
//!             whole length with half-width 0.125 m.
//! strings     k_s = 4e4 N/m * T / 60 lb (SPEC.md section 3: k_s proportional to tension);
//!             tension_kg is kilograms-force, T = tension_kg / 0.45359237 lb;
//!             string_bed_n_per_m is k_s directly; dt_kp_cm (a stringing-shop "dynamic
//!             tension" meter, 1 kp/cm = 980.665 N/m) is TAKEN AS k_s DIRECTLY. That is an
//!             assumption: DT is measured on a clamped frame with the meter's own load, not the
//!             model's string-plane constant; typical DT values of 30-40 kp/cm (2.9-3.9e4 N/m)
//!             are at least of the paper's order (4e4 N/m at 60 lb).
//!             None of them: the paper's k_s = 4e4 N/m.
//! frame flex  RA ratings (a clamped-handle static deflection index) have no published
//!             conversion to EI, so they are not accepted: give frequency_hz (measure it by
//!             tapping a loosely hung racket) or ei_n_m2.
//! ```
//!
//! ## Mass distribution
//! Without balance and swingweight the racket is the paper's uniform beam (no profile). With
//! them the linear density is the uniform beam's tilted by an exponential of a quadratic,
//! `lambda(f) ~ exp(t1 f + t2 f^2)` at the fraction `f` of the length from the tip, with `t1` and
//! `t2` solved (Newton's method) so that the DISCRETE beam's balance and swingweight equal the
//! targets; its mass is the target by construction. Of all densities with that mass, balance and
//! swingweight it is the one of least relative entropy to the uniform beam (the maximum-entropy
//! distribution with given first and second moments), so it adds no structure the three numbers
//! do not ask for: mass pulled towards both ends (a heavy head loop and handle, a light throat)
//! when the swingweight is above the uniform beam's, towards the middle when below. Any mass on
//! the racket has `M d^2 < SW < M (d^2 + b (L - b))` with `d` the balance's distance from the
//! swingweight axis and `b` from the butt; outside that the error gives the range. The family
//! (tilt bounded by |t| <= 100) fits the interior of that range, every published spec sheet we
//! tried among them, but not the last few per cent next to either limit, where the error says
//! the family, not physics, is the limit. (Before this family the density was piecewise linear over the knots
//! with a constant handle, which could not hold the head-loop mass of real frames: a 300 g,
//! 32.5 cm, 315 kg cm^2 frame was refused.)
//!
//! Physically sensible: the fit reports the density at the knots and its extremes; where the
//! density leaves [`PLAUSIBLE_DENSITY`] = 0.25..4 times the mean `M / L`, every command warns
//! (the fit still runs). Real spec sheets fit well inside it: see the fixture
//! `tests/data/spec_sheets/` and the test `published_spec_sheets_fit` (its densities run
//! from about 0.6 to 2.5 times the mean). The knots `[0, head end, handle start, L]` (head end =
//! the head length, or 48 % of L without head keys; handle start = L - handle_length_cm, default
//! [`DEFAULT_HANDLE_LENGTH_CM`]) still carry the stiffness profile.
//!
//! The fit is for the `N` it is given: the same racket on another `N` reproduces the targets
//! only to the discretisation error (O(N^-2)).
//!
//! ## Sources of the presets' typical values
//! The modern presets (`light`, `tweener`, `players`) are round typical numbers, not any
//! frame's data, chosen inside commonly quoted ranges: strung mass about 255-340 g, lighter
//! frames balanced head-heavy and heavier ones head-light, 1 balance point = 1/8 in (retailers'
//! guides, e.g. Tennis Warehouse University, C. Lindsey, "Weight, balance and swingweight";
//! Tennis Express, "Racquet information"); swingweights of about 300-340 kg cm^2 for adult
//! frames and twistweights of about 13-16 kg cm^2 (racket guides; H. Brody, "A new twist on the
//! twistweight", Tennis Industry, 2005, explains the quantity); head sizes of 95-110 sq in on
//! 27 in frames; free-free frequencies of composite frames above the < 120 Hz of wooden ones
//! (L. Taraborrelli et al., "Materials have driven the historical development of the tennis
//! racket", Appl. Sci. 9 (2019) 4352), taken here as 135-160 Hz. Each preset file states its values.
//!
//! ## Files
//! | file | job |
//! |---|---|
//! | [`spec`] | the racket file: keys in player units, their ranges, parsing |
//! | [`convert`] | a spec checked and converted to SI units (every validation message) |
//! | [`fit`] | the fit to the discrete beam (density profile, EI) and command parameters |
//! | [`report`] | how well the fitted model reproduces each stated number |
//! | [`presets`] | the built-in presets and loading a racket by name or path |

pub mod convert;
pub mod fit;
pub mod presets;
pub mod report;
pub mod spec;

#[cfg(test)]
mod tests;

pub use fit::{resolve, Fitted};
pub use presets::{load, preset, preset_names, presets_table};
pub use report::{density_extremes, density_warning, Check, FitReport};
pub use spec::{
    ranges, BallSpec, RacketSpec, BALANCE_POINT_CM, DEFAULT_HANDLE_LENGTH_CM, DEFAULT_HEAD_ASPECT,
    DEFAULT_HEAD_END_FRACTION, KP_PER_CM, LB_KG, PLAUSIBLE_DENSITY, SQ_IN_CM2, SWING_AXIS_FROM_BUTT_M,
};
