//! The colour maps of the heat maps (sequential viridis, diverging RdBu) and the colour range
//! of a field.

use plotters::style::RGBColor;

/// Viridis (matplotlib's perceptually uniform colour map) at t = 0, 0.1, ..., 1.
const VIRIDIS: [(u8, u8, u8); 11] = [
    (68, 1, 84),
    (72, 36, 117),
    (65, 68, 135),
    (53, 95, 141),
    (42, 120, 142),
    (33, 145, 140),
    (34, 168, 132),
    (68, 191, 112),
    (122, 209, 81),
    (189, 223, 38),
    (253, 231, 37),
];

/// ColorBrewer RdBu (11 classes), blue (negative) to red (positive), white in the middle.
const RDBU: [(u8, u8, u8); 11] = [
    (5, 48, 97),
    (33, 102, 172),
    (67, 147, 195),
    (146, 197, 222),
    (209, 229, 240),
    (247, 247, 247),
    (253, 219, 199),
    (244, 165, 130),
    (214, 96, 77),
    (178, 24, 43),
    (103, 0, 31),
];

/// Linear interpolation in an 11-stop colour table; `t` is clamped to [0, 1] (NaN gives 0).
fn lerp_table(table: &[(u8, u8, u8); 11], t: f64) -> RGBColor {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let f = t * 10.0;
    // (`f >= 0`: truncation is its floor)
    let i = (f as usize).min(9);
    let w = f - i as f64;
    let (a, b) = (table[i], table[i + 1]);
    // (rounded half away from zero by its whole part and the rest, as `f64::round` does for
    // these values in [0, 255], without the library call a baseline x86-64 build makes for it)
    let mix = |u: u8, v: u8| {
        let x = (f64::from(u) + w * (f64::from(v) - f64::from(u))).clamp(0.0, 255.0);
        let whole = x as u8;
        if x - f64::from(whole) >= 0.5 {
            whole + 1
        } else {
            whole
        }
    };
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The sequential colour map: dark purple (0) through teal to yellow (1).
pub fn viridis(t: f64) -> RGBColor {
    lerp_table(&VIRIDIS, t)
}

/// The diverging colour map: blue (0) through white (0.5) to red (1).
pub fn diverging(t: f64) -> RGBColor {
    lerp_table(&RDBU, t)
}

/// How values map to colours.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ColorScale {
    /// [`viridis`] from the smallest to the largest value.
    #[default]
    Sequential,
    /// [`diverging`] over `[-m, m]`, `m` the largest |value|: zero is white.
    Diverging,
}

impl ColorScale {
    /// The scale for these values: [`ColorScale::Diverging`] only when the finite values have
    /// both signs (some below zero and some above), else [`ColorScale::Sequential`] (a field
    /// all of one sign, e.g. a difference that is negative everywhere, gets the whole colour
    /// map for its own range rather than half of a scale centred on a zero it never reaches).
    pub fn for_values(z: &[f64]) -> ColorScale {
        let finite = || z.iter().copied().filter(|v| v.is_finite());
        if finite().any(|v| v < 0.0) && finite().any(|v| v > 0.0) {
            ColorScale::Diverging
        } else {
            ColorScale::Sequential
        }
    }
}

/// The colour range of the finite values: (lo, hi) with lo < hi, and the data extent (if any).
pub fn color_range(z: &[f64], scale: ColorScale) -> ((f64, f64), Option<(f64, f64)>) {
    let data = z.iter().copied().filter(|v| v.is_finite()).fold(None, |acc: Option<(f64, f64)>, v| match acc {
        None => Some((v, v)),
        Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
    });
    let range = match (scale, data) {
        (_, None) => match scale {
            ColorScale::Sequential => (0.0, 1.0),
            ColorScale::Diverging => (-1.0, 1.0),
        },
        (ColorScale::Sequential, Some((lo, hi))) => {
            if hi > lo {
                (lo, hi)
            } else {
                let d = if lo == 0.0 { 1.0 } else { 0.05 * lo.abs() };
                (lo - d, hi + d)
            }
        }
        (ColorScale::Diverging, Some((lo, hi))) => {
            let m = lo.abs().max(hi.abs());
            let m = if m > 0.0 { m } else { 1.0 };
            (-m, m)
        }
    };
    (range, data)
}
