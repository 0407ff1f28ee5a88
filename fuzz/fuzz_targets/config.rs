//! Fuzz the `--config` parser: any bytes either parse and validate or give an error; nothing
//! panics, and a config that validates also builds a model (eigen-decomposition, time step).
#![no_main]

use libfuzzer_sys::fuzz_target;
use racket_impact::params::{Overrides, Params};
use racket_impact::solve::FdModel;

fuzz_target!(|data: &[u8]| {
    let path = std::path::Path::new("fuzz.toml");
    if let Ok(o) = Overrides::from_toml_bytes(path, data) {
        let mut p = Params::default();
        o.apply(&mut p);
        if p.validate().is_ok() && p.numerics.segments <= 60 {
            let _ = FdModel::new(&p);
        }
    }
});
