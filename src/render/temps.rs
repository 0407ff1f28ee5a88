//! The temporary files a run has staged (outputs not yet published, and the replaced files
//! kept until a set of outputs is published), so that an interrupt can remove them: the
//! command line's SIGINT/SIGTERM handler calls [`remove_staged`] and exits. Every temporary
//! file of [`crate::render::io`] is a `Temp`, known here from its creation until it is
//! renamed into place or dropped (which removes it).

use std::path::{Path, PathBuf};
use std::sync::Mutex;

use tempfile::NamedTempFile;

/// The paths of the temporary files now staged.
static STAGED: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Held while a set of outputs is renamed into place (or rolled back), so that an interrupt
/// waits for the set to be whole, old or new, before it removes what is left.
pub(crate) static PUBLISHING: Mutex<()> = Mutex::new(());

fn staged() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    STAGED.lock().unwrap_or_else(|e| e.into_inner())
}

/// Set once an interrupt's clean-up has begun ([`remove_staged`]): the run is ending with the
/// signal's status, and an error the clean-up causes in the run (a directory removed under it)
/// is not reported ([`interrupted`]).
static INTERRUPTED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Whether an interrupt is being handled: the command line then waits for the handler to exit
/// with the signal's status instead of reporting an error of its own.
pub fn interrupted() -> bool {
    INTERRUPTED.load(std::sync::atomic::Ordering::SeqCst)
}

/// The directories a run has created for its outputs (`figures --out new/dir`), outermost first:
/// an interrupted or failed run removes those it leaves empty.
static CREATED_DIRS: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// The directories this run created: held while a directory is created and recorded, so that an
/// interrupt sees every directory that exists.
pub(crate) fn created_dirs() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    CREATED_DIRS.lock().unwrap_or_else(|e| e.into_inner())
}

/// Remove the directories this run created (for its outputs) that are empty, innermost first
/// (one that holds a file, published or not, is kept); for a run that failed. Returns how many
/// were removed.
pub fn remove_created_dirs() -> usize {
    remove_dirs(&mut created_dirs())
}

fn remove_dirs(dirs: &mut Vec<PathBuf>) -> usize {
    let removed = dirs.iter().rev().filter(|d| std::fs::remove_dir(d).is_ok()).count();
    dirs.clear();
    removed
}

/// No longer staged (renamed into place, or removed).
pub(crate) fn unregister(path: &Path) {
    let mut staged = staged();
    if let Some(i) = staged.iter().position(|p| p == path) {
        staged.swap_remove(i);
    }
}

/// Remove every staged temporary file and then every directory the run created that is left
/// empty (for an interrupted run, which then exits: no directory is created after this), after
/// any set of outputs being renamed into place is whole. Returns how many files were removed.
pub fn remove_staged() -> usize {
    INTERRUPTED.store(true, std::sync::atomic::Ordering::SeqCst);
    let _whole = PUBLISHING.lock().unwrap_or_else(|e| e.into_inner());
    let mut staged = staged();
    let removed = staged.iter().filter(|p| std::fs::remove_file(p).is_ok()).count();
    staged.clear();
    // the directories last; the run exits next, so both registers stay locked: no temporary
    // file or directory is created after them (one being created now is finished first, and seen)
    let mut dirs = created_dirs();
    remove_dirs(&mut dirs);
    std::mem::forget(dirs);
    std::mem::forget(staged);
    removed
}

/// A staged temporary file: removed when dropped (by [`tempfile`]), and known to
/// [`remove_staged`] until then or until [`Temp::persist`] renames it into place.
pub(crate) struct Temp(Option<NamedTempFile>);

impl Temp {
    /// Create a temporary file with `create` and stage it, holding the register meanwhile: an
    /// interrupt then sees every temporary file that exists, and none is created after it
    /// ([`remove_staged`] keeps the register until the run exits).
    pub(crate) fn create(create: impl FnOnce() -> std::io::Result<NamedTempFile>) -> std::io::Result<Temp> {
        let mut staged = staged();
        let file = create()?;
        staged.push(file.path().to_path_buf());
        Ok(Temp(Some(file)))
    }

    fn file(&self) -> &NamedTempFile {
        self.0.as_ref().expect("a Temp holds its file until persisted")
    }

    /// Its path.
    pub(crate) fn path(&self) -> &Path {
        self.file().path()
    }

    /// The open file.
    pub(crate) fn as_file(&self) -> &std::fs::File {
        self.file().as_file()
    }

    /// Rename it over `target` (see [`NamedTempFile::persist`]); no longer staged.
    pub(crate) fn persist(mut self, target: &Path) -> std::io::Result<()> {
        let file = self.0.take().expect("a Temp holds its file until persisted");
        let path = file.path().to_path_buf();
        match file.persist(target) {
            Ok(_) => {
                unregister(&path);
                Ok(())
            }
            Err(e) => {
                // (dropping the returned file removes it)
                unregister(&path);
                Err(e.error)
            }
        }
    }
}

impl Drop for Temp {
    fn drop(&mut self) {
        if let Some(file) = self.0.take() {
            let path = file.path().to_path_buf();
            drop(file);
            unregister(&path);
        }
    }
}

impl std::io::Write for Temp {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0.as_mut().expect("a Temp holds its file until persisted").write(buf)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.0.as_mut().expect("a Temp holds its file until persisted").flush()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_staged_file_is_known_until_persisted_or_dropped() {
        // (remove_staged is not called here: it would take the files of tests running beside
        // this one; tests/traps.rs interrupts a real run)
        let dir = tempfile::tempdir().unwrap();
        let a = Temp::create(|| NamedTempFile::new_in(dir.path())).unwrap();
        let b = Temp::create(|| NamedTempFile::new_in(dir.path())).unwrap();
        let (pa, pb) = (a.path().to_path_buf(), b.path().to_path_buf());
        assert!(staged().contains(&pa) && staged().contains(&pb));
        a.persist(&dir.path().join("out.csv")).unwrap();
        drop(b);
        assert!(!staged().contains(&pa) && !staged().contains(&pb));
        assert!(!pb.exists() && dir.path().join("out.csv").exists());
    }
}
