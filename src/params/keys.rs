//! The impact parameters, each declared once: its flag and config key, help, unit, range (or
//! the rule that checks it), sweep column, place in [`Params`], help heading, role (a property or
//! a method's option) and which impacts use it. The specs ([`ALL`], one constant each),
//! [`Overrides`] with its key list, setter, merge and apply, the validation messages, the
//! command line's flags and their help, and the notes and refusals of a value an impact does not
//! use ([`super::used`]) all come from this table. A new parameter is one row here plus its
//! physics (its field in the struct that holds it, its check there, and the model that reads
//! it).

use serde::{Deserialize, Serialize};

use super::spec::{declare_params, Check, FlagValue, ParamSpec};
use super::uncertainty::Dist;
use super::{Frame, Grip, LoadRule, Params, SolverKind, StringLaw, StringName, TangentialLaw};
use crate::error::{Error, Result};

/// The rules' largest and smallest coefficient of restitution of a ball dropped 100 in on
/// concrete, `0.745 +- 0.017` (paper p. 3): the ends of the declared range of `p` (Eq 12).
pub const E_MAX: f64 = 0.745 + 0.017;
/// See [`E_MAX`].
pub const E_MIN: f64 = 0.745 - 0.017;

/// How the racket's, its strings' and its ball's defaults are chosen: a racket file (or preset)
/// replaces the paper's ([`crate::racket::resolve`]).
const RACKET_FILE: &str = "the paper's; with --racket, the racket file's";

declare_params! {
    /// Impact distance from the tip, m (0 <= x <= length)
    X x: f64 = "x" at impact.x,
        what "impact point", unit "m", column "x_m", rule "0 <= x <= length",
        under Impact, Property, used Always, default "the centre of the string face; with --racket, the centre of its head";
    /// Impact distance from the long axis, m (|r| <= half-width)
    R r: f64 = "r" at impact.r,
        what "off-axis distance", unit "m", column "r_m", rule "|r| <= half-width",
        under Impact, Property, used Always, default "on the long axis";
    /// String-plane stiffness, N/m (1 ..= 1e12)
    KS ks: f64 = "ks" at strings.ks,
        what "string-plane stiffness", unit "N/m", column "ks_n_per_m", within(1.0, 1.0e12),
        under Strings, Property, used Always, default RACKET_FILE, usual(5.0e3, 2.0e5),
        uncertain(Dist::Uniform { lo: 3.6e4, hi: 4.4e4 }, 4.0e4, "assumed +-10 %: the paper states no calibration of tension to k_s (60 lb = 4e4 N/m is ours, inferred from its 60 -> 50 lb arithmetic; SPEC.md section 3) and says only (p. 3, String parameters) that k_s is 'typically about 10 %' larger at large deflection, a one-sided stiffening taken here as the order of the uncertainty; a claim takes it as one factor on every k_s it uses");
    /// Frame bending stiffness EI, N m^2 (1e-2 ..= 1e9)
    EI ei: f64 = "ei" at racket.ei,
        what "bending stiffness EI", unit "N m^2", column "ei_n_m2", within(1.0e-2, 1.0e9),
        under Racket, Property, used In(&FRAME, &["beam"]), default RACKET_FILE,
        uncertain(Dist::Uniform { lo: 150.0 * 0.9 * 0.9, hi: 150.0 * 1.1 * 1.1 }, 150.0, "p. 4, Racket parameters: the fundamental is 'typically about 125 Hz'; f1 within +-10 % (112.5-137.5 Hz, assumed for 'about') is EI = 150 (f1/125)^2 N m^2");
    /// Racket mass, kg (1e-3 ..= 1e6)
    MASS mass: f64 = "mass" at racket.mass,
        what "racket mass", unit "kg", column "mass_kg", within(1.0e-3, 1.0e6),
        under Racket, Property, used Always, default RACKET_FILE, usual(0.15, 1.0),
        uncertain(Dist::Uniform { lo: 0.32, hi: 0.36 }, 0.34, "assumed: the paper's 340 g racket (p. 4) +-20 g, the spread of plausible rackets of its length");
    /// Racket length, m (0.05 ..= 5)
    LENGTH length: f64 = "length" at racket.length,
        what "racket length", unit "m", column "length_m", within(0.05, 5.0),
        under Racket, Property, used Always, default RACKET_FILE, usual(0.4, 1.0),
        uncertain(Dist::Uniform { lo: 0.686, hi: 0.737 }, 0.71, "assumed: 27 in (standard) to 29 in (the rules' maximum), about the paper's 71 cm (p. 4)");
    /// Moment of inertia about the long axis, kg m^2 (1e-7 ..= 1e4)
    IX ix: f64 = "ix" at racket.ix,
        what "moment of inertia about the long axis", unit "kg m^2", column "ix_kg_m2", within(1.0e-7, 1.0e4),
        under Racket, Property, used Twisted, default RACKET_FILE, usual(3.0e-4, 6.0e-3),
        uncertain(Dist::Uniform { lo: 0.0012, hi: 0.0018 }, 0.0015, "p. 4: I_x = 0.0015 kg m^2, 'typical for such a racket (Brody 1985)'; assumed +-20 %");
    /// Half-width of the string face, m (1e-3 ..= 1): the largest |r|
    HALF_WIDTH half_width: f64 = "half-width" at racket.half_width,
        what "string-face half-width", unit "m", column "half_width_m", within(1.0e-3, 1.0),
        under Racket, Property, used OffAxis, default RACKET_FILE, usual(0.05, 0.2);
    /// Ball mass, kg (1e-4 ..= 10)
    MB mb: f64 = "mb" at ball.mass,
        what "ball mass", unit "kg", column "mb_kg", within(1.0e-4, 10.0),
        under Ball, Property, used Always, default RACKET_FILE, usual(0.02, 0.2),
        uncertain(Dist::Uniform { lo: 0.0558, hi: 0.0576 }, 0.057, "p. 3, Ball parameters: the rules' 'mass of 56.7 +- 0.9 g' (every legal ball; the paper computes with 57 g)");
    /// Ball compression stiffness k1, N/m (1 ..= 1e9)
    K1 k1: f64 = "k1" at ball.k1,
        what "ball compression stiffness", unit "N/m", column "k1_n_per_m", within(1.0, 1.0e9),
        under Ball, Property, used Always, default RACKET_FILE, usual(5.0e3, 2.0e5),
        uncertain(Dist::Uniform { lo: 2.4e4, hi: 3.6e4 }, 3.0e4, "assumed: the paper gives no range (p. 3, 'it is assumed that k1 = 3e4 N/m'); +-20 %");
    /// Ball hysteresis exponent p (1 < p <= 10)
    P p: f64 = "p" at ball.p,
        what "hysteresis exponent", unit "", column "p", rule "1 < p <= 10",
        under Ball, Property, used Always, default RACKET_FILE, usual(1.2, 5.0),
        uncertain(Dist::Uniform { lo: 2.0 / (E_MAX * E_MAX) - 1.0, hi: 2.0 / (E_MIN * E_MIN) - 1.0 }, 2.55, "p. 3, Ball parameters: the rules' 'e = 0.745 +- 0.017' for a 100-inch drop on concrete through Eq 12, p = 2/e^2 - 1 (2.444 at e 0.762, 2.774 at e 0.728), uniform in p");
    /// Incident ball speed, m/s (1e-3 ..= 1e3)
    V1 v1: f64 = "v1" at impact.v1,
        what "incident ball speed", unit "m/s", column "v1_m_per_s", within(1.0e-3, 1.0e3),
        under Impact, Property, used Always, usual(1.0, 70.0),
        uncertain(Dist::Uniform { lo: 27.0, hi: 33.0 }, 30.0, "assumed: the 30 m/s relative speed of Figs 7-8 (p. 6) +-10 %; the model is linear in v1, so only absolute rotations and forces depend on it");
    /// Number of beam segments N (4..=400)
    SEGMENTS segments: usize = "segments" at numerics.segments,
        what "number of beam segments", unit "", column "segments", rule "4 <= segments <= 400",
        under Numerics, MethodOption, used Always;
    /// Load rule: node (the paper's) or hat
    LOAD load: LoadRule = "load" at numerics.load,
        what "load rule", unit "", column "load", choice,
        under Numerics, MethodOption, used Always;
    /// Time step, s (must be below the stability limit)
    DT dt: f64 = "dt" at numerics.dt,
        what "time step", unit "s", column "dt_s", rule "0 < dt, below the stability limit of the beam",
        under Numerics, MethodOption, used In(&SOLVER, &["fd"]), default "the converged automatic step";
    /// Solver: fd (explicit time stepping, the reference) or modal (modal superposition)
    SOLVER solver: SolverKind = "solver" at numerics.solver,
        what "solver", unit "", column "solver", choice,
        under Numerics, MethodOption, used In(&FRAME, &["beam"]);
    /// Frame model: beam (the paper's flexible beam) or rigid (closed-form rigid racket)
    FRAME frame: Frame = "frame" at variants.frame,
        what "frame model", unit "", column "frame", choice,
        under Racket, MethodOption, used Always;
    /// Grip: free (the paper's) or hand (springs and dampers over the grip length)
    GRIP grip: Grip = "grip" at variants.grip,
        what "grip", unit "", column "grip", choice,
        under Racket, MethodOption, used Always;
    /// String law: linear (the paper's) or stiffening
    STRINGS strings: StringLaw = "strings" at variants.strings,
        what "string law", unit "", column "strings", choice,
        under Strings, MethodOption, used Always;
    /// Stiffening fraction s at the stiffening deflection (0 ..= 10)
    STRING_STIFFENING string_stiffening: f64 = "string-stiffening" at variants.string_stiffening,
        what "string stiffening fraction", unit "", column "string_stiffening", within(0.0, 10.0),
        under Strings, MethodOption, used In(&STRINGS, &["stiffening"]);
    /// Deflection at which the strings are stiffer by s, m (1e-4 ..= 1)
    STIFFENING_DEFLECTION stiffening_deflection: f64 = "stiffening-deflection" at variants.stiffening_deflection,
        what "stiffening deflection", unit "m", column "stiffening_deflection_m", within(1.0e-4, 1.0),
        under Strings, MethodOption, used In(&STRINGS, &["stiffening"]);
    /// Total hand stiffness, N/m (0 ..= 1e7)
    HAND_STIFFNESS hand_stiffness: f64 = "hand-stiffness" at variants.hand_stiffness,
        what "hand stiffness", unit "N/m", column "hand_stiffness_n_per_m", within(0.0, 1.0e7),
        under Racket, MethodOption, used In(&GRIP, &["hand"]);
    /// Total hand damping, N s/m (0 ..= 1e4)
    HAND_DAMPING hand_damping: f64 = "hand-damping" at variants.hand_damping,
        what "hand damping", unit "N s/m", column "hand_damping_n_s_per_m", within(0.0, 1.0e4),
        under Racket, MethodOption, used In(&GRIP, &["hand"]);
    /// Grip length from the butt, m (up to half the racket)
    GRIP_LENGTH grip_length: f64 = "grip-length" at variants.grip_length,
        what "grip length", unit "m", column "grip_length_m", rule "1e-3 <= grip-length <= length / 2",
        under Racket, MethodOption, used In(&GRIP, &["hand"]);
    /// Incidence angle from the string-plane normal, degrees (0 ..= 85)
    ANGLE_DEG angle_deg: f64 = "angle-deg" at oblique.angle_deg,
        what "incidence angle", unit "deg", column "angle_deg", within(0.0, 85.0),
        under Oblique, Property, used Always, usual(0.0, 80.0);
    /// In-plane direction of the incoming ball, degrees from the long axis towards the handle; 90 = across the face to +r (-360 ..= 360)
    AZIMUTH_DEG azimuth_deg: f64 = "azimuth-deg" at oblique.azimuth_deg,
        what "azimuth", unit "deg", column "azimuth_deg", within(-360.0, 360.0),
        under Oblique, Property, used Oblique;
    /// Incoming spin, rpm; > 0 topspin relative to the ball's motion along the strings (-2e4 ..= 2e4)
    SPIN_RPM spin_rpm: f64 = "spin-rpm" at oblique.spin_rpm,
        what "incoming spin", unit "rpm", column "spin_rpm", within(-2.0e4, 2.0e4),
        under Oblique, Property, used Always, usual(-6.0e3, 6.0e3);
    /// Friction coefficient of ball on strings (0 ..= 2)
    MU mu: f64 = "mu" at oblique.mu,
        what "friction coefficient", unit "", column "mu", within(0.0, 2.0),
        under Oblique, Property, used Oblique, usual(0.0, 1.0);
    /// Ratio of the ball's sliding friction on the strings during an impact to the coefficient in use (mu, or the string's TWU database COF) (0.05 ..= 3)
    MU_SCALE mu_scale: f64 = "mu-scale" at oblique.mu_scale,
        what "impact-to-tabulated friction ratio", unit "", column "mu_scale", within(0.05, 3.0),
        under Oblique, Property, used Oblique, usual(0.3, 1.5);
    /// Tangential stiffness of ball and string bed in series, N/m (1 ..= 1e9)
    KT kt: f64 = "kt" at oblique.kt,
        what "tangential stiffness", unit "N/m", column "kt_n_per_m", within(1.0, 1.0e9),
        under Oblique, Property, used Oblique, usual(5.0e3, 1.0e6);
    /// Tangential contact law: the elastic law, one mechanism on top of it, or physical (every mechanism)
    TANGENTIAL tangential: TangentialLaw = "tangential" at oblique.tangential,
        what "tangential contact law", unit "", column "tangential", choice,
        under Oblique, MethodOption, used Oblique;
    /// String-to-string friction coefficient (0 ..= 2)
    MU_SS mu_ss: f64 = "mu-ss" at oblique.mu_ss,
        what "string-to-string friction coefficient", unit "", column "mu_ss", within(0.0, 2.0),
        under Strings, Property, used In(&TANGENTIAL, &["bed"]), usual(0.0, 0.5);
    /// The string, from data/strings: sets mu and mu-ss (its TWU database values)
    STRING string: StringName = "string" at oblique.string,
        what "string", unit "", column "string", choice,
        under Strings, Property, used Oblique;
    /// Ball radius, m (1e-3 ..= 1)
    BALL_RADIUS ball_radius: f64 = "ball-radius" at oblique.ball_radius,
        what "ball radius", unit "m", column "ball_radius_m", within(1.0e-3, 1.0),
        under Ball, Property, used Oblique, usual(0.015, 0.05);
    /// Ball moment of inertia over m_b R^2 (0.1 ..= 2/3: thin shell 2/3, solid sphere 0.4, tennis ball about 0.55)
    BALL_INERTIA_FACTOR ball_inertia_factor: f64 = "ball-inertia-factor" at oblique.ball_inertia_factor,
        what "ball inertia factor", unit "", column "ball_inertia_factor", rule "0.1 <= ball-inertia-factor <= 2/3",
        under Ball, Property, used Oblique, usual(0.4, 2.0 / 3.0);
    /// The ball's tangential restitution in a gripping bounce e_x (0.01 ..= 0.99)
    BALL_EX ball_ex: f64 = "ball-ex" at oblique.ball_ex,
        what "ball tangential restitution", unit "", column "ball_ex", within(0.01, 0.99),
        under Ball, Property, used In(&TANGENTIAL, &["loss"]), usual(0.05, 0.5),
        uncertain(Dist::Uniform { lo: 0.10, hi: 0.17 }, 0.135, "data/measured M079-M080: 'e_x 0.10-0.17 for gripping tennis-ball bounces' (Cross 2002, Am. J. Phys. 70, Table III, as quoted in public code), uniform over the range");
    /// The ball's dynamic compression stiffness for the contact geometry, N/m (1e3 ..= 1e9)
    BALL_KDYN ball_kdyn: f64 = "ball-kdyn" at oblique.ball_kdyn,
        what "ball dynamic compression stiffness", unit "N/m", column "ball_kdyn_n_per_m", within(1.0e3, 1.0e9),
        under Ball, Property, used In(&TANGENTIAL, &["radius", "offset"]), usual(1.0e4, 3.0e5),
        uncertain(Dist::Uniform { lo: super::drop_test::kdyn_from_drop(0.057, 0.007), hi: super::drop_test::kdyn_from_drop(0.057, 0.005) }, super::drop_test::BALL_KDYN, "data/measured M081: a 100-inch drop on concrete compresses the ball 'about 6 mm' (Cross's tennis pages, as summarised in public notes); 5-7 mm (assumed for 'about') through k = m_b 2 g h / d^2 with the paper's 57 g");
}

/// The impact point a new user expects when none is given: the centre of the string face on
/// the long axis ([`Racket::face_centre`](super::Racket::face_centre), `r = 0`).
pub fn face_centre_impact(params: &mut Params) {
    params.impact.x = params.racket.face_centre();
    params.impact.r = 0.0;
}

/// The parameters the free racket's modes depend on (the `modes` command takes only these): its
/// length, mass and stiffness, and the segments of the beam.
pub const FREE_RACKET: [ParamSpec; 4] = [LENGTH, MASS, EI, SEGMENTS];

/// Usual range of the frame's first free-free bending frequency, Hz (wooden frames about
/// 100 Hz, stiff composite ones up to about 200 Hz; the paper's 125 Hz).
pub const USUAL_F1_HZ: (f64, f64) = (60.0, 300.0);

/// Largest twist at the end of the impact the small-angle model (Eq 7) is meant for, degrees.
pub const SMALL_TWIST_DEG: f64 = 15.0;

/// The parameters with a declared uncertainty, in the order of the flags.
pub fn uncertain() -> impl Iterator<Item = &'static ParamSpec> {
    ALL.iter().filter(|s| s.uncertainty.is_some())
}

/// The declaration of `key`, if it is a parameter.
pub fn find(key: &str) -> Option<&'static ParamSpec> {
    ALL.iter().find(|s| s.key == key)
}

/// The other spellings of a parameter a config file may use: the key with underscores (as in
/// the JSON, `angle_deg`) and its CSV column with the unit (`ks_n_per_m`), so that names read
/// off any output can be given back.
pub fn aliases(spec: &ParamSpec) -> [String; 2] {
    [spec.key.replace('-', "_"), spec.column.to_string()]
}

/// The declaration a name denotes: a key, or one of its [`aliases`].
pub fn find_any(name: &str) -> Option<&'static ParamSpec> {
    find(name).or_else(|| ALL.iter().find(|s| aliases(s).iter().any(|a| a == name)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::spec::Values;

    #[test]
    fn every_declared_key_is_a_config_key_with_its_flags_value() {
        for spec in &ALL {
            let (flag, toml_value) = match spec.values {
                Values::Number => ("0.5".to_string(), "0.5".to_string()),
                Values::Count => ("10".to_string(), "10".to_string()),
                Values::Choice(choices) => (choices[1].name.to_string(), format!("\"{}\"", choices[1].name)),
            };
            let mut from_flag = Overrides::default();
            from_flag.set(spec.key, &flag).unwrap();
            let from_config: Overrides = toml::from_str(&format!("{} = {toml_value}", spec.key)).unwrap();
            assert_eq!(from_flag, from_config, "{}", spec.key);
            assert_ne!(from_flag, Overrides::default(), "{}", spec.key);
            assert_eq!(find(spec.key), Some(spec));
        }
        assert_eq!(Overrides::KEYS.to_vec(), ALL.iter().map(|s| s.key).collect::<Vec<_>>());
    }

    #[test]
    fn declared_uncertainties_are_about_the_paper_values_and_valid() {
        let paper = Params::paper();
        let keys: Vec<&str> = uncertain().map(|s| s.key).collect();
        assert_eq!(keys, ["ks", "ei", "mass", "length", "ix", "mb", "k1", "p", "v1", "ball-ex", "ball-kdyn"]);
        for spec in uncertain() {
            let u = spec.uncertainty.unwrap();
            let (lo, hi) = u.dist.extent();
            assert!(lo < u.nominal && u.nominal < hi, "{}: {lo} {} {hi}", spec.key, u.nominal);
            assert!(!u.source.is_empty());
            if spec.key != V1.key {
                assert_eq!(Some(u.nominal), value_number(spec.key, &paper), "{}", spec.key);
            }
            for v in [lo, hi] {
                let mut p = paper;
                let mut o = Overrides::default();
                o.set(spec.key, &v.to_string()).unwrap();
                o.apply(&mut p);
                p.validate().unwrap();
            }
        }
        // p through Eq 12 at the rules' e: e = sqrt(2/(p+1))
        let Some(Dist::Uniform { lo, hi }) = P.uncertainty.map(|u| u.dist) else { panic!() };
        assert!(((2.0 / (lo + 1.0)).sqrt() - 0.762).abs() < 1e-12 && ((2.0 / (hi + 1.0)).sqrt() - 0.728).abs() < 1e-12);
    }

    #[test]
    fn every_row_names_itself_and_its_selectors_consistently() {
        use crate::params::spec::{Heading, UsedWhen};
        for spec in &ALL {
            // the name a program spells it by is the key with underscores, and an alias of it
            assert_eq!(spec.name, spec.key.replace('-', "_"), "{}", spec.key);
            assert_eq!(find_any(spec.name), Some(spec));
            // a parameter of the ball is listed under Ball (ball-ex and ball-kdyn were under
            // Numerics)
            if spec.key.starts_with("ball-") {
                assert_eq!(spec.heading, Heading::Ball, "{}", spec.key);
            }
            // a condition names a choice parameter and some of its values
            if let UsedWhen::In(selector, names) = spec.used_when {
                let Values::Choice(choices) = selector.values else {
                    panic!("{}: {} is no choice", spec.key, selector.key)
                };
                for name in names {
                    assert!(
                        choices.iter().any(|c| c.name == *name),
                        "{}: {} has no value {name}",
                        spec.key,
                        selector.key
                    );
                }
                assert_eq!(find(selector.key), Some(selector));
            }
        }
        // every heading holds a parameter
        for heading in Heading::ALL {
            assert!(ALL.iter().any(|s| s.heading == heading), "{heading:?}");
        }
    }

    #[test]
    fn every_declared_range_is_checked_by_the_validation() {
        // a row's range holds only if the struct holding the value checks it: a value beyond it
        // is refused, naming the key
        for spec in ALL.iter().filter(|s| matches!(s.check, Check::Within(..))) {
            let (_, hi) = spec.range();
            let mut o = Overrides::default();
            o.set(spec.key, &(hi + hi.abs() + 1.0).to_string()).unwrap();
            let mut p = Params::default();
            o.apply(&mut p);
            let e = p.validate().map_err(|e| e.to_string());
            assert!(
                e.as_ref().is_err_and(|e| e.starts_with(&format!("invalid {} =", spec.key))),
                "{}: {e:?}",
                spec.key
            );
        }
    }

    #[test]
    fn the_range_in_words_is_the_validations() {
        assert_eq!(KS.range_text(), "1 <= ks <= 1e12 N/m");
        assert_eq!(BALL_EX.range_text(), "0.01 <= ball-ex <= 0.99");
        assert_eq!(X.range_text(), "0 <= x <= length");
        assert_eq!(LOAD.range_text(), "one of: node, hat");
        // a number's range is the one its help line states
        for spec in ALL.iter().filter(|s| matches!(s.check, Check::Within(..))) {
            let (lo, hi) = spec.range();
            let stated = spec.doc.rsplit_once('(').and_then(|(_, r)| r.split_once(" ..= ")).map(|(a, b)| {
                let b = b.split([')', ':']).next().unwrap_or_default();
                (a.trim().parse::<f64>().ok(), b.trim().parse::<f64>().ok())
            });
            assert_eq!(stated, Some((Some(lo), Some(hi))), "{}: {}", spec.key, spec.doc);
        }
    }

    #[test]
    fn range_messages_name_the_key_the_range_and_the_unit() {
        let msg = KS.check(0.5).unwrap_err().to_string();
        assert_eq!(msg, "invalid ks = 0.5: string-plane stiffness must satisfy 1 <= ks <= 1e12 N/m");
        assert_eq!(EI.range(), (1.0e-2, 1.0e9));
        assert!(X.check(1e9).is_ok(), "x is checked by the impact's own rule");
    }
}
