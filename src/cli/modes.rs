//! `modes`: the eigenfrequencies of the free racket and the nodes of its fundamental mode.

use clap::Args;
use racket_impact::model::beam::Beam;
use racket_impact::numfmt::sig;
use racket_impact::{Error, Result};

use super::common::{diagnostics_json, out, print_diagnostics, Common, Format};
use super::overrides::ModesKeys;

#[derive(Args, Debug)]
pub struct ModesArgs {
    #[command(flatten)]
    pub common: Common<ModesKeys>,
    /// Number of flexible modes to list (1..=20, at most N-1)
    #[arg(long, default_value_t = 4, allow_hyphen_values = true)]
    pub count: usize,
}

/// The free racket's eigenfrequencies and mode-1 nodes.
pub fn run(a: ModesArgs) -> Result<()> {
    let params = a.common.sources().params()?;
    let noted = a.common.check_used([&params])?;
    let n = params.numerics.segments;
    if a.count == 0 || a.count > 20 || a.count > n - 1 {
        return Err(Error::invalid("count", a.count, format!("must satisfy 1 <= count <= min(20, N-1 = {})", n - 1)));
    }
    let beam = Beam::new(&params.racket, n);
    let modes = beam.modes();
    let freqs: Vec<f64> = (1..=a.count).map(|k| modes.frequency_hz(k)).collect();
    let nodes = modes.node_positions(1, &beam.x);
    let diagnostics: Vec<_> =
        noted.into_iter().chain(racket_impact::intake::diagnose::parameters([&params], &[])).collect();
    let text = match a.common.format {
        Format::Json => {
            let v = serde_json::json!({
                "frequencies_hz": freqs,
                "mode1_nodes_m": nodes,
                "segments": n,
                "params": params.racket,
                "diagnostics": diagnostics_json(&diagnostics)?,
            });
            racket_impact::render::json::pretty(&v)?
        }
        Format::Csv => {
            let mut s = String::from("mode,frequency_hz\n");
            for (k, f) in freqs.iter().enumerate() {
                s.push_str(&format!("{},{}\n", k + 1, f));
            }
            s
        }
        Format::Text => {
            let mut s = format!(
                "free-free racket: L = {} m, M = {} kg, EI = {} N m^2, N = {}\n",
                sig(params.racket.length, 6),
                sig(params.racket.mass, 6),
                sig(params.racket.ei, 6),
                n
            );
            for (k, f) in freqs.iter().enumerate() {
                s.push_str(&format!("mode {}: {:9.2} Hz\n", k + 1, f));
            }
            let list: Vec<String> = nodes.iter().map(|x| format!("{:.2} cm", 100.0 * x)).collect();
            s.push_str(&format!("mode-1 nodes from the tip: {}\n", list.join(", ")));
            s
        }
    };
    out!("{text}");
    print_diagnostics(&diagnostics);
    Ok(())
}
