//! The report of a build, kept where `RACKET_IMPACT_CACHE` names (opt-in): `report` computes
//! every claim, the claims under uncertainty at twice the samples and the spin calibration
//! (about 40 CPU-seconds), and what it prints and writes depends on nothing but the build (the
//! claims, the measurements and the presets are compiled in; `report` takes no parameter). So
//! the document is kept under a name made from a hash of the running executable's bytes: any
//! other build, however small the change, looks for another name, and a kept document is never
//! read by a build that did not write it. `make figures` sets the variable to `target/tmp/cache`
//! and the test suite's runs of the binary use the same folder, so the report `make figures`
//! computed is not computed again by the many tests that check what `report` does with its
//! options and output paths (tests/report.rs still computes it in the test's own process).
//!
//! A folder that cannot be read or written is no error: the report is computed as without the
//! variable. (Hand-written: a small file cache keyed by the executable is not what the caching
//! crates offer, which key by arguments within one process or need a service.)

use std::hash::Hasher;
use std::io::{Read, Write};
use std::path::PathBuf;

use racket_impact::Result;

/// The environment variable naming the folder.
pub const VARIABLE: &str = "RACKET_IMPACT_CACHE";

/// A hash of the running executable's bytes (`None` if it cannot be read).
fn build_id() -> Option<u64> {
    let mut file = std::fs::File::open(std::env::current_exe().ok()?).ok()?;
    // (`new` gives the same hasher in every process of a build: the same bytes, the same name)
    let mut hasher = std::hash::DefaultHasher::new();
    let mut buf = vec![0u8; 1 << 20];
    loop {
        let n = file.read(&mut buf).ok()?;
        if n == 0 {
            break;
        }
        hasher.write(&buf[..n]);
    }
    Some(hasher.finish())
}

/// `what` of this build: the kept text if there is one, else `compute()`, kept for the next run
/// (written to a temporary file in the folder and renamed, so a reader never sees half of it).
pub fn text(what: &str, compute: impl FnOnce() -> Result<String>) -> Result<String> {
    text_in(std::env::var_os(VARIABLE).filter(|v| !v.is_empty()).map(PathBuf::from), what, compute)
}

/// [`text`] with the folder given (`None`: nothing kept).
fn text_in(dir: Option<PathBuf>, what: &str, compute: impl FnOnce() -> Result<String>) -> Result<String> {
    let Some(path) = dir.zip(build_id()).map(|(dir, id)| dir.join(format!("{what}-{id:016x}.txt"))) else {
        return compute();
    };
    if let Ok(kept) = std::fs::read_to_string(&path) {
        return Ok(kept);
    }
    let text = compute()?;
    let keep = || -> std::io::Result<()> {
        let dir = path.parent().unwrap_or(std::path::Path::new("."));
        std::fs::create_dir_all(dir)?;
        let mut tmp = tempfile::NamedTempFile::new_in(dir)?;
        tmp.write_all(text.as_bytes())?;
        tmp.persist(&path).map_err(|e| e.error)?;
        Ok(())
    };
    // (a cache that cannot be written costs the next run its time, nothing else)
    let _ = keep();
    Ok(text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_kept_text_is_read_back_by_the_same_build_and_a_failing_folder_only_costs_time() {
        let dir = tempfile::tempdir().unwrap();
        let calls = std::cell::Cell::new(0);
        let compute = |t: &str| {
            calls.set(calls.get() + 1);
            Ok(t.to_string())
        };
        let kept = |what: &str, t: &str| text_in(Some(dir.path().to_path_buf()), what, || compute(t)).unwrap();
        assert_eq!(kept("report", "first"), "first");
        // the same build asks again: the kept text, not computed again
        assert_eq!(kept("report", "second"), "first");
        assert_eq!(calls.get(), 1);
        // another name is another text
        assert_eq!(kept("other", "third"), "third");
        assert_eq!(calls.get(), 2);
        // kept under the build's hash, nothing else left in the folder
        let id = build_id().unwrap();
        let mut names: Vec<String> =
            std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into()).collect();
        names.sort();
        assert_eq!(names, [format!("other-{id:016x}.txt"), format!("report-{id:016x}.txt")]);
        // another build (another hash) would not find it: the name holds the whole hash
        std::fs::write(dir.path().join(format!("report-{:016x}.txt", id ^ 1)), "stale").unwrap();
        assert_eq!(kept("report", "fourth"), "first");
        // no folder, or one that cannot be made: computed every time, no error
        assert_eq!(text_in(None, "report", || compute("fifth")).unwrap(), "fifth");
        let file = dir.path().join("a-file");
        std::fs::write(&file, "").unwrap();
        assert_eq!(text_in(Some(file.join("sub")), "report", || compute("sixth")).unwrap(), "sixth");
        assert_eq!(calls.get(), 4);
        // an error is passed on and nothing is kept
        let failed = text_in(Some(dir.path().join("e")), "report", || Err(racket_impact::Error::invalid("x", 1, "no")));
        assert!(failed.is_err() && !dir.path().join("e").exists());
    }
}
