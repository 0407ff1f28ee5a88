//! Clipping curves to the plotting area: polylines broken at unusable points and cut at the
//! edges (Liang-Barsky), in axis space (log10 x on a log axis).

/// A data point (x, y).
pub(super) type Pt = (f64, f64);

/// The visible rectangle in axis space (log10 x on a log axis).
#[derive(Clone, Copy)]
pub(super) struct Bounds {
    log: bool,
    u0: f64,
    u1: f64,
    v0: f64,
    v1: f64,
}

impl Bounds {
    pub(super) fn new(x: (f64, f64), y: (f64, f64), log: bool) -> Self {
        let (u0, u1) = if log { (x.0.log10(), x.1.log10()) } else { x };
        Bounds { log, u0, u1, v0: y.0, v1: y.1 }
    }

    /// Axis-space u coordinate of data x.
    pub(super) fn u(&self, x: f64) -> f64 {
        if self.log {
            x.log10()
        } else {
            x
        }
    }

    /// Data x of axis-space u.
    pub(super) fn x(&self, u: f64) -> f64 {
        if self.log {
            10f64.powf(u)
        } else {
            u
        }
    }

    /// The x range in data units.
    pub(super) fn x_range(&self) -> (f64, f64) {
        (self.x(self.u0), self.x(self.u1))
    }

    /// The y range.
    pub(super) fn y_range(&self) -> (f64, f64) {
        (self.v0, self.v1)
    }

    /// Where `(x, y)` lies across the bounds: (0, 0) at the lower-left corner, (1, 1) at the
    /// upper-right one.
    pub(super) fn frac(&self, x: f64, y: f64) -> (f64, f64) {
        ((self.u(x) - self.u0) / (self.u1 - self.u0), (y - self.v0) / (self.v1 - self.v0))
    }

    /// A point that can be placed on the axes at all.
    pub(super) fn usable(&self, x: f64, y: f64) -> bool {
        x.is_finite() && y.is_finite() && (!self.log || x > 0.0)
    }

    pub(super) fn contains(&self, x: f64, y: f64) -> bool {
        if !self.usable(x, y) {
            return false;
        }
        let u = self.u(x);
        u >= self.u0 && u <= self.u1 && y >= self.v0 && y <= self.v1
    }

    /// Liang–Barsky clip of segment a-b; returns the visible part and whether each end moved.
    pub(super) fn clip(&self, a: Pt, b: Pt) -> Option<(Pt, Pt, bool, bool)> {
        let (ua, ub) = (self.u(a.0), self.u(b.0));
        let (du, dv) = (ub - ua, b.1 - a.1);
        let mut t0 = 0.0_f64;
        let mut t1 = 1.0_f64;
        for (p, q) in [(-du, ua - self.u0), (du, self.u1 - ua), (-dv, a.1 - self.v0), (dv, self.v1 - a.1)] {
            if p == 0.0 {
                if q < 0.0 {
                    return None;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    if r > t1 {
                        return None;
                    }
                    t0 = t0.max(r);
                } else {
                    if r < t0 {
                        return None;
                    }
                    t1 = t1.min(r);
                }
            }
        }
        if !(t0.is_finite() && t1.is_finite()) || t0 > t1 {
            return None;
        }
        let at = |t: f64| (self.x(ua + t * du), a.1 + t * dv);
        let start = if t0 > 0.0 { at(t0) } else { a };
        let end = if t1 < 1.0 { at(t1) } else { b };
        Some((start, end, t0 > 0.0, t1 < 1.0))
    }

    /// The visible pieces of the polyline through (xs, ys): broken at unusable points and
    /// clipped to the bounds.
    pub(super) fn polylines(&self, xs: &[f64], ys: &[f64]) -> Vec<Vec<(f64, f64)>> {
        let mut out = Vec::new();
        let mut current: Vec<(f64, f64)> = Vec::new();
        let mut continues = false; // `current` ends at the unclipped previous point
        for (wx, wy) in xs.windows(2).zip(ys.windows(2)) {
            let a = (wx[0], wy[0]);
            let b = (wx[1], wy[1]);
            if !(self.usable(a.0, a.1) && self.usable(b.0, b.1)) {
                continues = false;
                continue;
            }
            match self.clip(a, b) {
                None => continues = false,
                Some((s, e, s_moved, e_moved)) => {
                    if !continues || s_moved {
                        if current.len() >= 2 {
                            out.push(std::mem::take(&mut current));
                        }
                        current.clear();
                        current.push(s);
                    }
                    current.push(e);
                    continues = !e_moved;
                }
            }
        }
        if current.len() >= 2 {
            out.push(current);
        }
        out
    }

    /// The visible points of (xs, ys).
    pub(super) fn points(&self, xs: &[f64], ys: &[f64]) -> Vec<(f64, f64)> {
        xs.iter().zip(ys).map(|(&x, &y)| (x, y)).filter(|&(x, y)| self.contains(x, y)).collect()
    }
}
