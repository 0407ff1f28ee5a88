//! Atomic, deterministic file output.
//!
//! Every file the crate produces (CSV tables, JSON, PNG figures) is first written to a hidden
//! temporary file next to its target and then renamed over it, so a reader never sees a
//! half-written file and an interrupted run never leaves a truncated one behind.

use std::fs::{self, File};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use crate::error::{Error, Result};

/// Distinguishes temporary files made by different threads of the same process.
static TEMP_COUNTER: AtomicU64 = AtomicU64::new(0);

/// The directory a file at `path` lives in (`.` for a bare file name).
fn parent_dir(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// A fresh temporary path next to `path`: `.<file>.tmp.<pid>.<n>` followed by `suffix`.
///
/// Checks that `path` names a file and that its directory exists; creates nothing.
pub(crate) fn temp_sibling(path: &Path, suffix: &str) -> Result<PathBuf> {
    let name = path.file_name().ok_or_else(|| Error::io(path, "not a file path (no file name)"))?;
    let dir = parent_dir(path);
    if !dir.is_dir() {
        return Err(Error::io(path, format!("directory {} does not exist", dir.display())));
    }
    let n = TEMP_COUNTER.fetch_add(1, Ordering::Relaxed);
    let tmp_name = format!(".{}.tmp.{}.{}{}", name.to_string_lossy(), std::process::id(), n, suffix);
    Ok(dir.join(tmp_name))
}

/// Move the finished temporary file `tmp` over `path`; on failure remove `tmp`.
pub(crate) fn commit_temp(tmp: &Path, path: &Path) -> Result<()> {
    fs::rename(tmp, path).map_err(|e| {
        let _ = fs::remove_file(tmp);
        Error::io(path, e)
    })
}

/// Write `bytes` to `path` atomically.
///
/// The bytes go to a temporary file in the same directory (`.<file>.tmp.<pid>.<n>`), which is
/// flushed and synced and then renamed over `path`. On any error the temporary file is removed
/// and an [`Error::Io`] naming `path` is returned; `path` itself is then untouched.
///
/// The directory of `path` must already exist; this function never creates directories (see
/// [`ensure_dir`]).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    let tmp = temp_sibling(path, "")?;
    if let Err(e) = write_synced(&tmp, path, bytes) {
        let _ = fs::remove_file(&tmp);
        return Err(e);
    }
    commit_temp(&tmp, path)
}

/// Write `bytes` to the temporary file `tmp` and sync it (errors name the eventual `target`);
/// the caller removes `tmp` on error and renames it over `target` on success.
pub(crate) fn write_synced(tmp: &Path, target: &Path, bytes: &[u8]) -> Result<()> {
    let written = (|| -> std::io::Result<()> {
        let mut file = File::create(tmp)?;
        file.write_all(bytes)?;
        file.flush()?;
        file.sync_all()
    })();
    written.map_err(|e| Error::io(target, e))
}

/// Refuse an output `path` whose directory does not exist, as an invalid value of the option
/// `field` (checked before any work, so nothing is computed for an output that cannot be
/// written).
pub fn check_output_dir(field: &'static str, path: &Path) -> Result<()> {
    let dir = parent_dir(path);
    if !dir.is_dir() {
        return Err(Error::invalid(field, path.display(), format!("directory {} does not exist", dir.display())));
    }
    Ok(())
}

/// A file written in pieces and published atomically: the bytes go to a hidden temporary file
/// next to the target; [`AtomicFile::commit`] syncs it and renames it over the target. Dropped
/// without a commit (an error, a panic), the temporary file is removed and the target is
/// untouched. Used for streamed outputs such as `sweep`, whose size is not known in advance.
pub struct AtomicFile {
    tmp: PathBuf,
    path: PathBuf,
    out: Option<std::io::BufWriter<File>>,
}

impl AtomicFile {
    /// Start writing `path` (its directory must exist).
    pub fn create(path: &Path) -> Result<Self> {
        let tmp = temp_sibling(path, "")?;
        let file = File::create(&tmp).map_err(|e| Error::io(path, e))?;
        Ok(AtomicFile { tmp, path: path.to_path_buf(), out: Some(std::io::BufWriter::new(file)) })
    }

    /// Append bytes.
    pub fn write(&mut self, bytes: &[u8]) -> Result<()> {
        match self.out.as_mut() {
            Some(w) => w.write_all(bytes).map_err(|e| Error::io(&self.path, e)),
            None => Err(Error::io(&self.path, "already committed")),
        }
    }

    /// Flush, sync and rename over the target.
    pub fn commit(mut self) -> Result<()> {
        let w = self.out.take().ok_or_else(|| Error::io(&self.path, "already committed"))?;
        let file = w.into_inner().map_err(|e| Error::io(&self.path, e.error()))?;
        file.sync_all().map_err(|e| Error::io(&self.path, e))?;
        drop(file);
        commit_temp(&self.tmp, &self.path)
    }
}

impl Drop for AtomicFile {
    fn drop(&mut self) {
        if self.out.take().is_some() {
            let _ = fs::remove_file(&self.tmp);
        }
    }
}

/// Create `dir` and any missing parents (like `mkdir -p`).
///
/// Succeeds if the directory already exists; fails with an [`Error::Io`] naming `dir` if it
/// cannot be created (for example because a regular file is in the way).
pub fn ensure_dir(dir: &Path) -> Result<()> {
    fs::create_dir_all(dir).map_err(|e| Error::io(dir, format!("cannot create directory: {e}")))?;
    if dir.is_dir() {
        Ok(())
    } else {
        Err(Error::io(dir, "exists but is not a directory"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch() -> tempfile::TempDir {
        tempfile::tempdir().expect("create temp dir")
    }

    fn entries(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(dir)
            .expect("read dir")
            .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn writes_content() {
        let dir = scratch();
        let path = dir.path().join("out.csv");
        write_atomic(&path, b"a,b\n1,2\n").expect("write");
        assert_eq!(fs::read(&path).expect("read"), b"a,b\n1,2\n");
    }

    #[test]
    fn overwrites_existing_file() {
        let dir = scratch();
        let path = dir.path().join("out.txt");
        write_atomic(&path, b"a much longer first version").expect("write 1");
        write_atomic(&path, b"short").expect("write 2");
        assert_eq!(fs::read(&path).expect("read"), b"short");
    }

    #[test]
    fn leaves_no_temp_file() {
        let dir = scratch();
        let path = dir.path().join("x.json");
        write_atomic(&path, b"{}").expect("write");
        write_atomic(&path, b"[]").expect("write again");
        assert_eq!(entries(dir.path()), vec!["x.json".to_string()]);
    }

    #[test]
    fn empty_content() {
        let dir = scratch();
        let path = dir.path().join("empty");
        write_atomic(&path, b"").expect("write");
        assert_eq!(fs::read(&path).expect("read").len(), 0);
    }

    #[test]
    fn missing_directory_is_an_error_and_creates_nothing() {
        let dir = scratch();
        let missing = dir.path().join("no_such_dir");
        let path = missing.join("out.csv");
        let err = write_atomic(&path, b"data").expect_err("must fail");
        let msg = err.to_string();
        assert!(msg.contains("out.csv"), "{msg}");
        assert!(msg.contains("does not exist"), "{msg}");
        assert!(!missing.exists());
        assert!(entries(dir.path()).is_empty());
    }

    #[test]
    fn directory_as_target_is_an_error_and_cleans_up() {
        let dir = scratch();
        let target = dir.path().join("sub");
        fs::create_dir(&target).expect("mkdir");
        fs::write(target.join("keep"), b"k").expect("write keep");
        assert!(write_atomic(&target, b"data").is_err());
        // Only the (non-empty) directory remains; the temporary file is gone.
        assert_eq!(entries(dir.path()), vec!["sub".to_string()]);
    }

    #[test]
    fn ensure_dir_creates_nested_and_is_idempotent() {
        let dir = scratch();
        let nested = dir.path().join("a").join("b").join("c");
        ensure_dir(&nested).expect("create");
        assert!(nested.is_dir());
        ensure_dir(&nested).expect("again");
    }

    #[test]
    fn ensure_dir_fails_on_file() {
        let dir = scratch();
        let file = dir.path().join("f");
        fs::write(&file, b"x").expect("write");
        let err = ensure_dir(&file).expect_err("must fail");
        assert!(err.to_string().contains('f'));
    }
}
