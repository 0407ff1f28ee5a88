//! The speed comparison written out: its table (CSV), its JSON and its text.

use super::{SpeedComparison, SpeedRow};
use crate::error::Result;
use crate::render::table::{Table, Value};
use crate::solve::swing::gain_pct;

/// The sign conventions of the spins a stroke's JSON prints.
pub const SPEED_SPIN_CONVENTION: &str =
    "spin_rpm (the ball's spin as it leaves) and incoming_spin_rpm: > 0 topspin in the \
     court's frame (the ball's top moving forward in its flight); params.oblique.spin_rpm and result.spin_out_rpm: the \
     racket's frame, > 0 topspin relative to the ball's incoming motion along the strings";

impl SpeedComparison {
    /// The reference's outgoing speed, m/s.
    fn v_ref(&self) -> f64 {
        self.rows[0].v_out
    }

    /// The comparison as a table (speeds in the request's unit).
    pub fn table(&self) -> Result<Table> {
        let unit = self.request.unit;
        let mut cols = vec![
            "variant",
            "x_m",
            "r_m",
            "ks_n_per_m",
            "e_a",
            "tau_s",
            "theta_end_deg",
            "ball_speed_out",
            "change_pct",
            "unit",
        ];
        if self.request.is_stroke() {
            cols.extend(["launch_deg", "launch_spin_rpm"]);
        }
        let mut t = Table::new("speed", &cols);
        for SpeedRow { label, params: p, result: r, v_out, launch } in &self.rows {
            let mut row = vec![
                Value::Text(label.clone()),
                p.impact.x.into(),
                p.impact.r.into(),
                p.strings.ks.into(),
                r.e_a.into(),
                r.tau_s.into(),
                r.theta_end_deg.into(),
                (v_out / unit.si).into(),
                gain_pct(self.v_ref(), *v_out).into(),
                Value::Text(unit.label.into()),
            ];
            if let Some((launch_deg, spin_rpm)) = launch {
                row.extend([Value::from(*launch_deg), Value::from(*spin_rpm)]);
            }
            t.push(row)?;
        }
        Ok(t)
    }

    /// The comparison as pretty JSON (one object per variant) with a final newline.
    pub fn json(&self) -> Result<String> {
        let unit = self.request.unit;
        let v: Vec<serde_json::Value> = self
            .rows
            .iter()
            .map(|row| {
                let SpeedRow { label, params: p, result: r, v_out, launch } = row;
                let mut v = serde_json::json!({
                    "variant": label, "params": p, "result": crate::render::impact::result_json(p, r),
                    "ball_speed_out": v_out / unit.si, "change_pct": gain_pct(self.v_ref(), *v_out), "unit": unit.label,
                    "diagnostics": self.diagnostics_of(&[row]),
                });
                if let (Some((launch_deg, spin_rpm)), Some(o)) = (launch, v.as_object_mut()) {
                    o.insert("launch_deg".into(), (*launch_deg).into());
                    o.insert("spin_rpm".into(), (*spin_rpm).into());
                    o.insert("incoming_spin_rpm".into(), self.request.incoming_spin_rpm.into());
                    o.insert("spin_convention".into(), SPEED_SPIN_CONVENTION.into());
                }
                v
            })
            .collect();
        crate::render::json::pretty(&v)
    }

    /// The comparison as text: the swing, then one line per variant.
    pub fn text(&self) -> String {
        if self.request.is_stroke() {
            return self.stroke_text();
        }
        let (req, unit) = (&self.request, self.request.unit);
        let mut s = format!(
            "swing {} {u} at the impact point, incoming ball {} {u}: v_out = e_A v_in + (1 + e_A) v_racket\n",
            req.swing,
            req.incoming,
            u = unit.label
        );
        s.push_str(&format!(
            "{:<22} {:>7} {:>6} {:>9} {:>8} {:>8} {:>9} {:>12} {:>9}\n",
            "variant", "x cm", "r cm", "ks N/m", "e_A", "tau ms", "theta deg", "ball out", "change"
        ));
        for SpeedRow { label, params: p, result: r, v_out, .. } in &self.rows {
            s.push_str(&format!(
                "{:<22} {:>7.1} {:>6.1} {:>9.0} {:>8.4} {:>8.3} {:>9.2} {:>7.1} {:<4} {:>+8.2} %\n",
                label,
                100.0 * p.impact.x,
                100.0 * p.impact.r,
                p.strings.ks,
                r.e_a,
                1e3 * r.tau_s,
                r.theta_end_deg,
                v_out / unit.si,
                unit.label,
                gain_pct(self.v_ref(), *v_out)
            ));
        }
        s
    }

    /// The text of a stroke along a tilted path or with a spinning ball: speed, launch angle and
    /// spin in the court's frame.
    fn stroke_text(&self) -> String {
        let (req, unit) = (&self.request, self.request.unit);
        let mut s = format!(
            "swing {} {u} along a path {} deg above the horizontal, incoming ball {} {u} with {} rpm of topspin \
             (court frame; the impact computed in the racket's frame)\n",
            req.swing,
            req.path_deg,
            req.incoming,
            req.incoming_spin_rpm,
            u = unit.label
        );
        s.push_str(
            "spin: > 0 is topspin in the court's frame (the ball's top moving forward in its flight), \
             for the incoming ball and the spin column alike\n",
        );
        // a tangential law other than the default one is named (it changes every spin)
        if let Some(p) = self.rows.first().map(|r| &r.params) {
            if p.oblique.tangential != crate::params::TangentialLaw::default() {
                s.push_str(&format!("tangential contact law: {}\n", p.oblique.tangential.name()));
            }
        }
        s.push_str(&format!(
            "{:<22} {:>7} {:>9} {:>8} {:>10} {:>12} {:>9} {:>10} {:>9}\n",
            "variant", "x cm", "ks N/m", "e_A", "incidence", "ball out", "change", "launch", "spin rpm"
        ));
        for SpeedRow { label, params: p, result: r, v_out, launch } in &self.rows {
            let (launch_deg, spin_rpm) = launch.unwrap_or((0.0, 0.0));
            s.push_str(&format!(
                "{:<22} {:>7.1} {:>9.0} {:>8.4} {:>6.1} deg {:>7.1} {:<4} {:>+8.2} % {:>6.1} deg {:>9.0}\n",
                label,
                100.0 * p.impact.x,
                p.strings.ks,
                r.e_a,
                p.oblique.angle_deg,
                v_out / unit.si,
                unit.label,
                gain_pct(self.v_ref(), *v_out),
                launch_deg,
                spin_rpm
            ));
        }
        s
    }
}
