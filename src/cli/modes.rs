//! `modes`: the eigenfrequencies of the free racket and the nodes of its fundamental mode.

use clap::Args;
use racket_impact::command::modes::Modes;
use racket_impact::command::{execute, Control};
use racket_impact::numfmt::sig;
use racket_impact::Result;

use super::common::{out, print_diagnostics, Common, Format};
use super::options::{ModesOptions, Options};
use super::overrides::ModesKeys;

#[derive(Args, Debug)]
pub struct ModesArgs {
    #[command(flatten)]
    pub common: Common<ModesKeys>,
    #[command(flatten)]
    pub options: Options<ModesOptions>,
}

/// The free racket's eigenfrequencies and mode-1 nodes.
pub fn run(a: ModesArgs) -> Result<()> {
    let modes = execute(Modes::new(&a.common.sources(), &a.options.0)?, &Control::new())?;
    let params = &modes.params;
    let text = match a.common.format {
        Format::Json => racket_impact::render::json::pretty(&modes.json()?)?,
        Format::Csv => {
            let mut s = String::from("mode,frequency_hz\n");
            for (k, f) in modes.frequencies_hz.iter().enumerate() {
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
                params.numerics.segments
            );
            for (k, f) in modes.frequencies_hz.iter().enumerate() {
                s.push_str(&format!("mode {}: {:9.2} Hz\n", k + 1, f));
            }
            let list: Vec<String> = modes.mode1_nodes_m.iter().map(|x| format!("{:.2} cm", 100.0 * x)).collect();
            s.push_str(&format!("mode-1 nodes from the tip: {}\n", list.join(", ")));
            s
        }
    };
    out!("{text}");
    print_diagnostics(&modes.diagnostics);
    Ok(())
}
