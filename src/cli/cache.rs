//! What a command computes from nothing but its build, kept where `RACKET_IMPACT_CACHE` names
//! (opt-in). `report` computes every claim, the claims under uncertainty at twice the samples and
//! the spin calibration (about 40 CPU-seconds), and `uncertainty --claims` every claim at every
//! draw (about 20 CPU-seconds at its default 128 samples); what they print and write depends on
//! nothing but the build and, for `--claims`, its sample count and seed (the claims, the
//! measurements and the presets are compiled in; `report` takes no parameter, `--claims` refuses
//! every other). So a text is kept under a name made from what it is and a hash of the running
//! executable's bytes: any other build, however small the change, looks for another name, and a
//! kept text is never read by a build that did not write it. `make figures` sets the variable to
//! `target/tmp/cache` and the test suite's runs of the binary use the same folder, so the report
//! `make figures` computed is not computed again by the many tests that check what `report` does
//! with its options and output paths, and the claims' study at a sample count is computed once
//! for the tests that read its three formats.
//!
//! A folder that cannot be read or written is no error: the text is computed as without the
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
    texts(&[what], 0, || Ok(vec![compute()?]))
}

/// `whats[which]` of this build, where one computation gives a text for each of `whats` (a
/// result in every output format): the kept text if there is one, else every text of
/// `compute()`, each kept for the next run.
pub fn texts(whats: &[&str], which: usize, compute: impl FnOnce() -> Result<Vec<String>>) -> Result<String> {
    texts_in(std::env::var_os(VARIABLE).filter(|v| !v.is_empty()).map(PathBuf::from), whats, which, compute)
}

/// [`texts`] with the folder given (`None`: nothing kept).
fn texts_in(
    dir: Option<PathBuf>,
    whats: &[&str],
    which: usize,
    compute: impl FnOnce() -> Result<Vec<String>>,
) -> Result<String> {
    if which >= whats.len() {
        return Err(racket_impact::Error::invalid("cache", which, format!("one of {} texts expected", whats.len())));
    }
    let computed = || -> Result<Vec<String>> {
        let all = compute()?;
        if all.len() != whats.len() || which >= all.len() {
            return Err(racket_impact::Error::invalid("cache", all.len(), format!("{} texts expected", whats.len())));
        }
        Ok(all)
    };
    let Some((dir, id)) = dir.zip(build_id()) else {
        return Ok(computed()?.swap_remove(which));
    };
    let path = |what: &str| dir.join(format!("{what}-{id:016x}.txt"));
    let kept = || std::fs::read_to_string(path(whats[which])).ok();
    if let Some(text) = kept() {
        return Ok(text);
    }
    // One run computes, the others of this build that ask meanwhile wait for its texts (the
    // test suite starts several at once): a lock on a file beside them, released when this run
    // ends however it ends. A lock that cannot be had costs only the time of computing here too.
    let _lock = lock(&dir, &path(whats[0]).with_extension("lock"));
    if let Some(text) = kept() {
        return Ok(text);
    }
    let mut all = computed()?;
    let keep = |what: &str, text: &str| -> std::io::Result<()> {
        std::fs::create_dir_all(&dir)?;
        let mut tmp = tempfile::NamedTempFile::new_in(&dir)?;
        tmp.write_all(text.as_bytes())?;
        tmp.persist(path(what)).map_err(|e| e.error)?;
        Ok(())
    };
    for (what, text) in whats.iter().zip(&all) {
        // (a cache that cannot be written costs the next run its time, nothing else)
        let _ = keep(what, text);
    }
    Ok(all.swap_remove(which))
}

/// An exclusive lock on the file `path` in `dir` (made if missing), held until the file returned
/// is dropped; `None` where it cannot be had (then nothing waits).
#[cfg(unix)]
fn lock(dir: &std::path::Path, path: &std::path::Path) -> Option<std::fs::File> {
    std::fs::create_dir_all(dir).ok()?;
    let file = std::fs::OpenOptions::new().create(true).truncate(false).write(true).open(path).ok()?;
    rustix::fs::flock(&file, rustix::fs::FlockOperation::LockExclusive).ok()?;
    Some(file)
}

/// (No lock here: runs asking at once each compute the text.)
#[cfg(not(unix))]
fn lock(_dir: &std::path::Path, _path: &std::path::Path) -> Option<std::fs::File> {
    None
}

/// [`text`] with the folder given (`None`: nothing kept).
#[cfg(test)]
fn text_in(dir: Option<PathBuf>, what: &str, compute: impl FnOnce() -> Result<String>) -> Result<String> {
    texts_in(dir, &[what], 0, || Ok(vec![compute()?]))
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
        assert_eq!(
            names,
            ["other-{id:016x}.lock", "other-{id:016x}.txt", "report-{id:016x}.lock", "report-{id:016x}.txt"]
                .map(|n| n.replace("{id:016x}", &format!("{id:016x}")))
        );
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
        assert!(failed.is_err() && !dir.path().join("e").join(format!("report-{id:016x}.txt")).exists());
    }

    #[test]
    #[cfg(unix)]
    fn runs_asking_at_once_compute_once() {
        let dir = tempfile::tempdir().unwrap();
        let calls = std::sync::atomic::AtomicUsize::new(0);
        let texts: Vec<String> = std::thread::scope(|scope| {
            let asks: Vec<_> = (0..3)
                .map(|which| {
                    let (dir, calls) = (dir.path().to_path_buf(), &calls);
                    scope.spawn(move || {
                        texts_in(Some(dir), &["a", "b", "c"], which, || {
                            calls.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
                            std::thread::sleep(std::time::Duration::from_millis(200));
                            Ok(vec!["ta".into(), "tb".into(), "tc".into()])
                        })
                        .unwrap()
                    })
                })
                .collect();
            asks.into_iter().map(|h| h.join().unwrap()).collect()
        });
        assert_eq!(texts, ["ta", "tb", "tc"]);
        assert_eq!(calls.load(std::sync::atomic::Ordering::SeqCst), 1);
    }

    #[test]
    fn the_texts_of_one_computation_are_kept_together_and_each_read_back() {
        let dir = tempfile::tempdir().unwrap();
        let calls = std::cell::Cell::new(0);
        let formats = ["claims-2-0-text", "claims-2-0-csv", "claims-2-0-json"];
        let kept = |which: usize| {
            texts_in(Some(dir.path().to_path_buf()), &formats, which, || {
                calls.set(calls.get() + 1);
                Ok(vec!["t".into(), "c".into(), "j".into()])
            })
            .unwrap()
        };
        assert_eq!(kept(1), "c");
        // the other formats of the same computation: kept by the first, not computed again
        assert_eq!((kept(2), kept(0), kept(1)), ("j".into(), "t".into(), "c".into()));
        assert_eq!(calls.get(), 1);
        // without a folder: computed, the one asked for given
        assert_eq!(texts_in(None, &formats, 2, || Ok(vec!["a".into(), "b".into(), "c".into()])).unwrap(), "c");
        // a computation that does not give one text per name is an error, not a wrong text
        let short = texts_in(Some(dir.path().join("x")), &formats, 2, || Ok(vec!["a".into()]));
        let id = build_id().unwrap();
        assert!(short.is_err() && !dir.path().join("x").join(format!("claims-2-0-json-{id:016x}.txt")).exists());
    }
}
