//! What an impact reports: [`ImpactResult`], declared once with the table of its fields
//! ([`FIELDS`]) that every reader of a result (the finiteness check, the text output, the sweep
//! columns, the map quantities) takes names, units and values from; and the time series.

use serde::Serialize;

use crate::error::{Error, Result};

/// How a field's value is read from a result.
#[derive(Debug, Clone, Copy)]
pub enum Get {
    /// A number.
    Number(fn(&ImpactResult) -> f64),
    /// A yes/no flag.
    Flag(fn(&ImpactResult) -> bool),
}

/// How the plain-text output shows a field: `label value unit`, the value times `scale`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Text {
    /// The label (the key without its unit suffix).
    pub label: &'static str,
    /// The value is shown times this (1e3 for ms and mm).
    pub scale: f64,
    /// The unit or remark after the value (empty for none).
    pub unit: &'static str,
    /// The unit or remark instead for an oblique or spinning ball, where it differs: the
    /// energy fractions of the normal motion are then of the normal incoming KE
    /// `m_b (v1 cos angle)^2 / 2` only, while the tangential ones are of the whole.
    pub oblique_unit: Option<&'static str>,
    /// Shown only for a racket held in a hand (`--grip hand`).
    pub hand_only: bool,
    /// Shown only for an oblique or spinning ball (`--angle-deg`, `--spin-rpm`).
    pub oblique_only: bool,
    /// Shown only under a tangential law with named loss mechanisms (`--tangential` other than
    /// `elastic`; NaN, and left out, under the elastic law).
    pub law_only: bool,
}

/// One field of [`ImpactResult`].
#[derive(Debug, Clone, Copy)]
pub struct Field {
    /// Its JSON and CSV key (the struct field's name, or the name declared with `as`).
    pub key: &'static str,
    /// Its SI unit (empty for a pure number or a fraction of the incident energy).
    pub unit: &'static str,
    /// What it is (the struct field's doc).
    pub doc: &'static str,
    /// Its value.
    pub get: Get,
    /// Checked to be finite before a result is returned ([`ImpactResult::check_finite`]).
    pub checked: bool,
    /// A column of every sweep row.
    pub sweep: bool,
    /// Its line in the text output, if it has one.
    pub text: Option<Text>,
}

impl Field {
    /// Whether the field is one of an oblique or spinning ball (NaN at normal incidence).
    pub fn is_oblique(&self) -> bool {
        self.text.is_some_and(|t| t.oblique_only)
    }

    /// Whether the field is a loss of a named tangential mechanism (NaN under the elastic law).
    pub fn is_law_only(&self) -> bool {
        self.text.is_some_and(|t| t.law_only)
    }

    /// The value as a number (a flag as 0 or 1).
    pub fn number(&self, r: &ImpactResult) -> f64 {
        match self.get {
            Get::Number(g) => g(r),
            Get::Flag(g) => f64::from(u8::from(g(r))),
        }
    }
}

/// The field of a key, at compile time where the key is a constant (an unknown key is then a
/// compile error).
pub const fn field(key: &str) -> &'static Field {
    let mut i = 0;
    while i < FIELDS.len() {
        if same(FIELDS[i].key, key) {
            return &FIELDS[i];
        }
        i += 1;
    }
    panic!("no such impact result field")
}

/// String equality in a `const fn`.
const fn same(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// A text line with the value as it is.
const fn text(label: &'static str, unit: &'static str) -> Option<Text> {
    Some(Text { label, scale: 1.0, unit, hand_only: false, oblique_only: false, law_only: false, oblique_unit: None })
}

/// A text line of an energy fraction of the normal motion: its base named for an oblique or
/// spinning ball, the normal incoming KE.
const fn text_normal(label: &'static str, unit: &'static str, oblique_unit: &'static str) -> Option<Text> {
    Some(Text {
        label,
        scale: 1.0,
        unit,
        hand_only: false,
        oblique_only: false,
        law_only: false,
        oblique_unit: Some(oblique_unit),
    })
}

/// A text line with the value times 1000 (ms, mm).
const fn text_milli(label: &'static str, unit: &'static str) -> Option<Text> {
    Some(Text { label, scale: 1e3, unit, hand_only: false, oblique_only: false, law_only: false, oblique_unit: None })
}

/// A text line shown only for an oblique or spinning ball.
const fn text_oblique(label: &'static str, unit: &'static str) -> Option<Text> {
    Some(Text { label, scale: 1.0, unit, hand_only: false, oblique_only: true, law_only: false, oblique_unit: None })
}

/// A text line shown only for an oblique or spinning ball under a tangential law with named
/// loss mechanisms.
const fn text_law(label: &'static str, unit: &'static str) -> Option<Text> {
    Some(Text { label, scale: 1.0, unit, hand_only: false, oblique_only: true, law_only: true, oblique_unit: None })
}

/// A field value that is left out of the JSON: NaN, which marks a quantity that does not apply
/// (the oblique fields of a normal impact).
trait Absent {
    /// Left out of the JSON.
    fn absent(&self) -> bool;
    /// Equal, or both absent.
    fn same(&self, other: &Self) -> bool;
}

impl Absent for f64 {
    fn absent(&self) -> bool {
        self.is_nan()
    }
    fn same(&self, other: &Self) -> bool {
        self == other || (self.is_nan() && other.is_nan())
    }
}

impl Absent for bool {
    fn absent(&self) -> bool {
        false
    }
    fn same(&self, other: &Self) -> bool {
        self == other
    }
}

/// Declares [`ImpactResult`] and [`FIELDS`] from one list: each field's doc, name (`as
/// "name"` where the JSON and CSV name differs from the Rust one: every non-SI or dimensioned
/// name carries its unit), type, unit, whether it is checked and swept, and its text line.
macro_rules! impact_result {
    (@get f64, $key:ident) => { Get::Number(|r: &ImpactResult| r.$key) };
    (@get bool, $key:ident) => { Get::Flag(|r: &ImpactResult| r.$key) };
    (@zero f64) => { 0.0 };
    (@zero bool) => { false };
    (@lerp f64, $a:expr, $b:expr, $w:expr) => { (1.0 - $w) * $a + $w * $b };
    (@lerp bool, $a:expr, $b:expr, $w:expr) => { $a || $b };
    (@name $key:ident $name:literal) => { $name };
    (@name $key:ident) => { stringify!($key) };
    ($($(#[doc = $doc:literal])+ $key:ident $(as $name:literal)?: $ty:tt [$unit:literal] checked: $checked:literal, sweep: $sweep:literal, text: $text:expr;)+) => {
        /// What one impact reports (SPEC.md section 2). Energies are fractions of `m_b v1^2 / 2`.
        #[derive(Debug, Clone, Copy, Serialize)]
        pub struct ImpactResult {
            $($(#[doc = $doc])+ #[serde(skip_serializing_if = "Absent::absent")] $(#[serde(rename = $name)])? pub $key: $ty,)+
        }

        /// Equal field by field, a NaN (a quantity that does not apply) equal to a NaN, so a
        /// result equals itself.
        impl PartialEq for ImpactResult {
            fn eq(&self, other: &Self) -> bool {
                $(Absent::same(&self.$key, &other.$key))&&+
            }
        }

        impl ImpactResult {
            /// Every field zero (or false): the base a solver fills in, so that the fields it
            /// does not set (the oblique ones, set afterwards) need not be listed again.
            pub(crate) const ZERO: ImpactResult = ImpactResult { $($key: impact_result!(@zero $ty),)+ };

            /// `a` and `b` read on the straight line between them at `w` (0 gives `a`, 1 gives `b`):
            /// every number interpolated, a flag set if either sets it. How a reader reads a curve
            /// drawn through two computed impacts between them.
            pub fn lerp(a: &ImpactResult, b: &ImpactResult, w: f64) -> ImpactResult {
                ImpactResult { $($key: impact_result!(@lerp $ty, a.$key, b.$key, w),)+ }
            }
        }

        /// Every field of [`ImpactResult`], in declaration (and JSON) order.
        pub const FIELDS: &[Field] = &[$(Field {
            key: impact_result!(@name $key $($name)?),
            unit: $unit,
            doc: concat!($($doc),+),
            get: impact_result!(@get $ty, $key),
            checked: $checked,
            sweep: $sweep,
            text: $text,
        },)+];
    };
}

impact_result! {
    /// Apparent coefficient of restitution `v2 / v1` (racket initially at rest).
    e_a: f64 [""] checked: true, sweep: true, text: text("e_a", "");
    /// Impact duration, s.
    tau_s: f64 ["s"] checked: true, sweep: true, text: text_milli("tau", "ms");
    /// Rotation about the long axis at the end of the impact, degrees.
    theta_end_deg: f64 ["deg"] checked: true, sweep: true, text: text("theta_end", "deg");
    /// Energy dissipated in the ball (Eq 11).
    f_ball: f64 [""] checked: true, sweep: true, text: text_normal("f_ball", "lost in the ball (Eq 11)", "lost in the ball (Eq 11; of the normal incoming KE)");
    /// Racket vibration energy after impact: racket energy minus its rigid-body energy.
    f_vib: f64 [""] checked: true, sweep: true, text: text_normal("f_vib", "racket vibration", "racket vibration (of the normal incoming KE)");
    /// The paper's vibration measure: peak bending PE during two fundamental periods after impact.
    f_vib_peak_pe: f64 [""] checked: true, sweep: true,
        text: text_normal("f_vib_peak_pe", "peak bending PE after impact (paper)", "peak bending PE after impact (paper; of the normal incoming KE)");
    /// Kinetic energy of twist about the long axis.
    f_spin: f64 [""] checked: true, sweep: true, text: text_normal("f_spin", "twist about the long axis", "twist about the long axis (of the normal incoming KE)");
    /// Energy taken by the hand (`--grip hand`: its springs' energy plus what its dampers
    /// dissipated) at separation; 0 for the paper's free racket.
    f_hand: f64 [""] checked: true, sweep: false,
        text: Some(Text { label: "f_hand", scale: 1.0, unit: "taken by the hand (springs + damping)", hand_only: true, oblique_only: false, law_only: false, oblique_unit: Some("taken by the hand (springs + damping; of the normal incoming KE)") });
    /// Rigid-body kinetic energy of the racket (translation + rotation about the centre of mass).
    f_rigid: f64 [""] checked: true, sweep: true, text: text_normal("f_rigid", "racket rigid-body KE", "racket rigid-body KE (of the normal incoming KE)");
    /// Rebound kinetic energy of the ball (= e_a^2), as a fraction of the incoming kinetic
    /// energy; for an oblique or spinning ball that of the normal motion, `(v2_n / v1_n)^2`, a
    /// fraction of the normal incoming KE `m_b (v1 cos angle)^2 / 2` only.
    f_ke_ball: f64 [""] checked: true, sweep: true, text: text_normal("f_ke_ball", "of initial ball KE", "ball rebound KE (v2_n / v1_n)^2, of the normal incoming KE");
    /// Maximum contact force, N.
    peak_force_n: f64 ["N"] checked: true, sweep: true, text: text("peak_force", "N");
    /// Largest relative deviation of the total energy from its initial value, over the run.
    energy_error: f64 [""] checked: true, sweep: true, text: text("energy_error", "relative");
    /// Largest relative deviation of the total linear momentum from `m_b v1`, over the run.
    momentum_error: f64 [""] checked: true, sweep: false, text: text("momentum_error", "relative");
    /// Where the force really acted, m from the tip.
    x_load_m: f64 ["m"] checked: false, sweep: true, text: None;
    /// Time of maximum total compression `Y_T`, s.
    t_max_compression_s: f64 ["s"] checked: false, sweep: false, text: text_milli("t_max_compression", "ms");
    /// Maximum ball compression `Y0`, m.
    y0_m: f64 ["m"] checked: false, sweep: false, text: text_milli("y0", "mm ball compression");
    /// True if the vibrating frame caught the ball again within the post-impact window.
    recontact: bool [""] checked: false, sweep: true, text: None;
    /// Time step used, s.
    dt_s: f64 ["s"] checked: false, sweep: false, text: text("dt", "s");
    /// Rebound velocity along the outward normal of the string plane, m/s (racket initially at
    /// rest; `e_a` times the incoming normal speed): > 0 the ball rebounds away from the strings,
    /// < 0 (where `e_a` < 0, near the tip) it moves on in its incoming direction, slower than
    /// the recoiling frame it leaves. This and the fields below are those of an
    /// oblique or spinning ball: NaN, and left out of the JSON, at normal incidence without spin.
    v2_n as "v2_n_m_per_s": f64 ["m/s"] checked: false, sweep: true, text: text_oblique("v2_n", "m/s along the strings' outward normal (racket at rest before)");
    /// Rebound velocity in the string plane along `t`, the in-plane direction the ball came
    /// in along, m/s (negative: back the way it came).
    v2_t as "v2_t_m_per_s": f64 ["m/s"] checked: false, sweep: true, text: text_oblique("v2_t", "m/s in the string plane (> 0: on along the incoming in-plane direction)");
    /// Outgoing spin, rpm, with the sign convention of `--spin-rpm`: positive is topspin
    /// relative to the ball's incoming motion along the strings (the spin of a ball rolling
    /// along the strings in the in-plane direction it came in along), not the court's topspin
    /// (`speed` converts to the court's frame).
    spin_out_rpm: f64 ["rpm"] checked: false, sweep: true, text: text_oblique("spin_out", "rpm (> 0: topspin relative to the ball's incoming motion along the strings)");
    /// Direction of the outgoing velocity from the outward normal of the string plane, degrees,
    /// `atan2(v2_t, v2_n)` (positive: on along `t`). Over 90 degrees exactly when `v2_n` < 0:
    /// the ball does not rebound but moves on in its incoming direction, leaving the strings
    /// only because the frame recoils faster; the angle is then still the direction it moves
    /// in, and the text output says so.
    rebound_angle_deg: f64 ["deg"] checked: false, sweep: true, text: text_oblique("rebound_angle", "deg, outgoing velocity from the outward normal");
    /// Tangential coefficient of restitution of the contact point, `-(w_out - u_out) / w_in`
    /// (`w` the slip velocity of the ball's contact point, `u_out` the frame's there); NaN
    /// (undefined: null in the JSON of an oblique or spinning impact, an empty CSV field,
    /// `undefined` in the text) when the contact point arrives with a slip below
    /// [`crate::solve::oblique::E_T_MIN_SLIP_FRACTION`] of the incident speed.
    e_t: f64 [""] checked: false, sweep: true, text: text_oblique("e_t", "tangential COR of the contact point");
    /// Share of the contact time in which the ball slid on the strings.
    slip_fraction: f64 [""] checked: false, sweep: true, text: text_oblique("slip_fraction", "of the contact time sliding");
    /// Energy dissipated by friction, as a fraction of the ball's whole incoming kinetic energy
    /// (translation at `v1` and spin; the normal fractions above are of the normal part
    /// `m_b (v1 cos angle)^2 / 2`, as at normal incidence at that speed).
    f_friction: f64 [""] checked: false, sweep: true, text: text_oblique("f_friction", "lost to friction (of the whole incoming KE)");
    /// Spin kinetic energy of the ball after impact (fraction of the whole incoming kinetic energy).
    f_ball_spin: f64 [""] checked: false, sweep: true, text: text_oblique("f_ball_spin", "ball spin KE after (of the whole incoming KE)");
    /// In-plane kinetic energy of the racket after impact (translation in and rotation about
    /// the normal of the string plane; fraction of the whole incoming kinetic energy).
    f_racket_inplane: f64 [""] checked: false, sweep: true,
        text: text_oblique("f_racket_inplane", "racket in-plane KE (of the whole incoming KE)");
    /// Energy dissipated in the ball's tangential damper (mechanism `loss`; fraction of the
    /// whole incoming kinetic energy). NaN (left out) under the elastic law.
    f_tangential_damping: f64 [""] checked: false, sweep: true,
        text: text_law("f_tangential_damping", "lost in the ball's tangential damper (of the whole incoming KE)");
    /// Energy dissipated by the strings sliding over each other (mechanism `bed`; fraction of
    /// the whole incoming kinetic energy). NaN (left out) under the elastic law.
    f_string_sliding: f64 [""] checked: false, sweep: true,
        text: text_law("f_string_sliding", "lost by the strings sliding (of the whole incoming KE)");
    /// Energy dissipated by the offset torque against the spin (mechanism `offset`; fraction
    /// of the whole incoming kinetic energy). NaN (left out) under the elastic law.
    f_rolling: f64 [""] checked: false, sweep: true,
        text: text_law("f_rolling", "lost to the offset torque against the spin (of the whole incoming KE)");
    /// True if the tangential contact's switch between the ball gripping at the friction limit
    /// and sliding chattered until a force piece reached its cap of switches (SPEC.md section
    /// 6, "Known limit"; `bed` and `physical` only): the outcome then hangs on the solver's
    /// piece length, and fd's is the reference.
    tangential_chatter: bool [""] checked: false, sweep: false, text: None;
}

/// The text output's lines, in its order.
pub const TEXT_ORDER: [&Field; 28] = [
    field("e_a"),
    field("tau_s"),
    field("theta_end_deg"),
    field("peak_force_n"),
    field("f_ke_ball"),
    field("f_ball"),
    field("f_rigid"),
    field("f_vib"),
    field("f_vib_peak_pe"),
    field("f_spin"),
    field("f_hand"),
    field("t_max_compression_s"),
    field("y0_m"),
    field("energy_error"),
    field("momentum_error"),
    field("dt_s"),
    field("v2_n_m_per_s"),
    field("v2_t_m_per_s"),
    field("rebound_angle_deg"),
    field("spin_out_rpm"),
    field("e_t"),
    field("slip_fraction"),
    field("f_friction"),
    field("f_ball_spin"),
    field("f_racket_inplane"),
    field("f_tangential_damping"),
    field("f_string_sliding"),
    field("f_rolling"),
];

/// An impact whose relative energy error exceeds this is an error, never a result.
pub const ENERGY_ERROR_LIMIT: f64 = 1.0e-4;

impl ImpactResult {
    /// An impact whose energy error (the normal ledger's, and the tangential one's joined to
    /// it) exceeds [`ENERGY_ERROR_LIMIT`] is an error, never a result: the same check for every
    /// solver and for the tangential part (SPEC.md section 2).
    pub(crate) fn check_energy(&self) -> Result<()> {
        if self.energy_error <= ENERGY_ERROR_LIMIT {
            Ok(())
        } else {
            Err(Error::EnergyDrift { error: self.energy_error, limit: ENERGY_ERROR_LIMIT })
        }
    }

    /// Every checked field finite, or an error naming the first that is not (`f64::max` would
    /// hide a NaN in the running error maxima, so the check is on the final numbers).
    pub fn check_finite(&self) -> Result<()> {
        match FIELDS.iter().find(|f| f.checked && !f.number(self).is_finite()) {
            Some(f) => Err(Error::NonFinite { field: f.key }),
            None => Ok(()),
        }
    }
}

/// One sample of the time series.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SeriesRow {
    /// Time, s.
    pub t_s: f64,
    /// Contact force, N.
    pub force_n: f64,
    /// Ball displacement `y_b`, m.
    pub y_ball_m: f64,
    /// Total compression `Y_T` (ball + strings), m; negative after separation.
    pub y_total_m: f64,
    /// Rotation about the long axis, rad.
    pub theta_rad: f64,
    /// Ball kinetic energy (fraction of the initial).
    pub ke_ball: f64,
    /// Ball elastic energy plus the energy it has dissipated.
    pub pe_ball: f64,
    /// String elastic energy.
    pub pe_string: f64,
    /// Kinetic energy of all beam nodes (translation, rotation and vibration).
    pub ke_racket: f64,
    /// Bending potential energy of the beam.
    pub pe_racket: f64,
    /// Kinetic energy of twist about the long axis.
    pub ke_spin: f64,
    /// Energy in the hand's springs plus what its dampers dissipated (`--grip hand`).
    pub hand: f64,
    /// Sum of the above (1 up to the integration error).
    pub total: f64,
}

/// Options for recording the time series.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeriesOptions {
    /// Spacing of the samples, s (rounded to a whole number of steps).
    pub sample_dt: f64,
    /// Record (and step) at least until this time, s.
    pub t_end: f64,
}

impl Default for SeriesOptions {
    fn default() -> Self {
        SeriesOptions { sample_dt: 2.0e-5, t_end: 0.0 }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_field_table_reads_every_field_under_its_json_key_in_json_order() {
        let r = ImpactResult {
            e_a: 1.0,
            tau_s: 2.0,
            theta_end_deg: 3.0,
            f_ball: 4.0,
            f_vib: 5.0,
            f_vib_peak_pe: 6.0,
            f_spin: 7.0,
            f_hand: 8.0,
            f_rigid: 9.0,
            f_ke_ball: 10.0,
            peak_force_n: 11.0,
            energy_error: 12.0,
            momentum_error: 13.0,
            x_load_m: 14.0,
            t_max_compression_s: 15.0,
            y0_m: 16.0,
            recontact: true,
            dt_s: 18.0,
            v2_n: 19.0,
            v2_t: 20.0,
            spin_out_rpm: 21.0,
            rebound_angle_deg: 22.0,
            e_t: 23.0,
            slip_fraction: 24.0,
            f_friction: 25.0,
            f_ball_spin: 26.0,
            f_racket_inplane: 27.0,
            f_tangential_damping: 28.0,
            f_string_sliding: 29.0,
            f_rolling: 30.0,
            tangential_chatter: true,
        };
        let text = serde_json::to_string(&r).unwrap();
        let json = serde_json::to_value(r).unwrap();
        let json = json.as_object().unwrap();
        assert_eq!(json.len(), FIELDS.len());
        let mut at = 0;
        for f in FIELDS {
            let value = match f.get {
                Get::Number(_) => json[f.key].as_f64().unwrap(),
                Get::Flag(_) => f64::from(u8::from(json[f.key].as_bool().unwrap())),
            };
            assert_eq!(f.number(&r), value, "{}", f.key);
            let pos = text.find(&format!("\"{}\":", f.key)).unwrap();
            assert!(pos >= at, "{} out of order", f.key);
            at = pos;
        }
    }

    #[test]
    fn the_first_non_finite_checked_field_is_named() {
        let mut r = crate::solve::simulate(&crate::params::Params::paper()).unwrap();
        r.momentum_error = f64::NAN;
        r.f_vib = f64::INFINITY;
        assert!(matches!(r.check_finite(), Err(Error::NonFinite { field: "f_vib" })));
        r.f_vib = 0.0;
        assert!(matches!(r.check_finite(), Err(Error::NonFinite { field: "momentum_error" })));
        r.momentum_error = 0.0;
        r.dt_s = f64::NAN;
        assert!(r.check_finite().is_ok());
    }
}
