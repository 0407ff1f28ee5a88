//! The speed comparison's diagnostics: the notes about what no variant uses, the variants'
//! unusual parameters (those the stroke sets said in its own terms) and the largest twist.

use super::{SpeedComparison, SpeedRow, SPEED_SETS};
use crate::diagnostic::{Diagnostic, Kind};
use crate::intake::diagnose;
use crate::numfmt::sig;
use crate::params::keys;

impl SpeedComparison {
    /// The comparison's diagnostics, once each: the notes about what no variant uses, the
    /// variants' parameters but those the stroke sets (said in its own terms: the impact speed,
    /// the incoming spin, the incidence), the largest twist. Each variant's own are in its JSON
    /// row (with the notes, which hold for every variant).
    pub fn diagnostics(&self) -> Vec<Diagnostic> {
        self.diagnostics_of(&self.rows.iter().collect::<Vec<_>>())
    }

    pub(super) fn diagnostics_of(&self, rows: &[&SpeedRow]) -> Vec<Diagnostic> {
        let (req, u) = (&self.request, self.request.unit);
        let mut out = self.noted.clone();
        out.extend(diagnose::parameters(rows.iter().map(|r| &r.params), &SPEED_SETS.map(|(s, _)| s.key)));
        if let Some((lo, hi)) = keys::V1.usual {
            let v = (req.swing + req.incoming) * u.si;
            if !(lo..=hi).contains(&v) {
                out.push(Diagnostic::new(
                    Kind::Unusual,
                    keys::V1.key,
                    format!(
                        "swing + incoming = {} {} (the impact speed) is outside the usual {}..{} {} (computed anyway)",
                        sig(req.swing + req.incoming, 4),
                        u.label,
                        sig(lo / u.si, 3),
                        sig(hi / u.si, 3),
                        u.label
                    ),
                ));
            }
        }
        if let Some(line) = keys::SPIN_RPM.unusual(req.incoming_spin_rpm) {
            out.push(Diagnostic::new(
                Kind::Unusual,
                "incoming-spin-rpm",
                line.replacen(keys::SPIN_RPM.key, "incoming-spin-rpm", 1),
            ));
        }
        if let Some(angle) =
            rows.iter().map(|r| r.params.oblique.angle_deg).find(|&d| keys::ANGLE_DEG.unusual(d).is_some())
        {
            out.push(Diagnostic::new(
                Kind::Unusual,
                keys::ANGLE_DEG.key,
                format!(
                    "the swing path of {} deg meets the face at {} deg from its normal, beyond the usual incidences (computed anyway)",
                    req.path_deg,
                    sig(angle, 3)
                ),
            ));
        }
        let theta = rows.iter().map(|r| r.result.theta_end_deg).max_by(|a, b| a.abs().total_cmp(&b.abs()));
        out.extend(theta.and_then(diagnose::twist));
        out
    }
}
