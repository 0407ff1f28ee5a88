//! Atomic, deterministic file output that never replaces what is not a file.
//!
//! Every file the crate produces (CSV tables, JSON, PNG figures) is first written to a hidden
//! temporary file ([`tempfile`], removed if dropped) next to the file it will become and then
//! renamed over it, so a reader never sees a half-written file and an interrupted run never
//! leaves a truncated one behind. The new file takes the replaced file's permissions; being a
//! new file, it is no longer the one other hard links to the old file name (they keep the old
//! content), as with any atomic replace.
//!
//! What is at the output path decides how it is written ([`resolve`]):
//! - nothing or a regular file: temporary file + rename;
//! - a symbolic link: its target is written (atomically, as above, where the target is a
//!   regular file or missing); the link stays;
//! - a device, FIFO or socket (`/dev/null`, `/dev/stdout`, a named pipe): written through,
//!   never replaced;
//! - a directory: refused.
//!
//! A command that writes several files and prints stages them in one [`Staged`] and publishes
//! them all or none ([`Staged::publish`]): every destination checked again, devices and FIFOs
//! written first (the writes that can fail and cannot be taken back), then the files renamed
//! into place, each keeping the file it replaces until the end, then the printing (which may
//! say "wrote ..."). A failing rename or a failing standard output (`> /dev/full`) puts back
//! every file already replaced, so any error leaves the old outputs (a device already written
//! cannot be taken back). The temporary files are known to [`crate::render::temps`], which an
//! interrupt (SIGINT, SIGTERM) uses to remove them.
//!
//! An output is never one of the command's inputs ([`not_an_input`]): a path that is the same
//! file as a config or racket file the command read (compared by identity, so a link or another
//! spelling is caught too), or any path ending in `.toml` (the input format: no command writes
//! one), is refused before any work and again when the file is staged.
//!
//! Why not `tempfile::NamedTempFile::persist` or `atomic-write-file` alone: both rename onto
//! the path they are given, which replaces a symlink or a device by a regular file. They are
//! right for a regular file; [`tempfile`] is used for that part.

use std::fs::{self, File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};

use crate::error::{Error, Result};
use crate::render::temps::{Temp, PUBLISHING};

/// The directory a file at `path` lives in (`.` for a bare file name).
fn parent_dir(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// Whether `path` as written can only name a directory: it ends in a separator (`sub/`) or in
/// `.` or `..` (`sub/.`), which `Path::file_name` reads past (`sub/` has the file name `sub`).
fn names_a_directory(path: &Path) -> bool {
    let text = path.as_os_str().to_string_lossy();
    let last = text.rsplit(std::path::is_separator).next().unwrap_or_default();
    text.ends_with(std::path::is_separator) || last == "." || last == ".."
}

/// Whether the outputs `a` and `b` of one command are the same file: the same target once
/// symbolic links are followed, its directory compared by identity (`./x.csv` and `x.csv`, a
/// link to the other). A path that does not resolve is compared as written.
pub fn same_output(a: &Path, b: &Path) -> bool {
    let target = |p: &Path| -> PathBuf {
        let at = match resolve(p) {
            Ok(Resolved::File(f)) | Ok(Resolved::Through(f)) => f,
            Err(_) => p.to_path_buf(),
        };
        match (fs::canonicalize(parent_dir(&at)), at.file_name()) {
            (Ok(dir), Some(name)) => dir.join(name),
            _ => at,
        }
    };
    target(a) == target(b)
}

/// How an output path is written, once its symbolic links are followed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Resolved {
    /// A regular file or nothing (at the end of any symlinks): temporary file + rename.
    File(PathBuf),
    /// A device, FIFO or socket: written through, never replaced.
    Through(PathBuf),
}

impl Resolved {
    /// Whether the output is written through (a device or FIFO), not replaced.
    pub fn is_through(&self) -> bool {
        matches!(self, Resolved::Through(_))
    }
}

/// Follow the symbolic links at `path` (a dangling link names the file to create) and say how
/// the output is written; a directory (or a link to one), a link loop or a missing directory
/// is an error naming `path`.
pub fn resolve(path: &Path) -> Result<Resolved> {
    if path.file_name().is_none() || names_a_directory(path) {
        return Err(Error::io(path, "names a directory (it ends in a path separator): give a file name"));
    }
    // What the system's own link following ends at: a device, FIFO or socket is written
    // through the path as given, whose links may pass through names that are not paths
    // (`/dev/stdout -> /proc/self/fd/1 -> pipe:[N]`, opened by the kernel, not by name).
    if let Ok(meta) = fs::metadata(path) {
        let kind = meta.file_type();
        if !kind.is_file() && !kind.is_dir() {
            return Ok(Resolved::Through(path.to_path_buf()));
        }
    }
    let mut at = path.to_path_buf();
    for _ in 0..40 {
        let meta = match fs::symlink_metadata(&at) {
            Ok(m) => m,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                let dir = parent_dir(&at);
                if !dir.is_dir() {
                    return Err(Error::io(path, format!("directory {} does not exist", dir.display())));
                }
                return Ok(Resolved::File(at));
            }
            Err(e) => return Err(Error::io(path, e)),
        };
        let kind = meta.file_type();
        if kind.is_symlink() {
            let link = fs::read_link(&at).map_err(|e| Error::io(path, e))?;
            at = if link.is_absolute() { link } else { parent_dir(&at).join(link) };
            continue;
        }
        if kind.is_dir() {
            return Err(Error::io(path, "is a directory"));
        }
        return Ok(if kind.is_file() { Resolved::File(at) } else { Resolved::Through(at) });
    }
    Err(Error::io(path, "too many levels of symbolic links"))
}

/// Refuse an output `path` that would replace an input of this run: the same file as a config
/// or racket file read ([`crate::params::inputs`]), or a `.toml` path (the format of those
/// inputs, which no command writes). The reason, in words, for the caller's error.
pub fn not_an_input(path: &Path) -> std::result::Result<(), String> {
    if let Some(input) = crate::params::inputs::same_as_input(path) {
        return Err(format!(
            "is the same file as {}, an input of this command: write the output to another file",
            input.display()
        ));
    }
    if path.extension().is_some_and(|e| e.eq_ignore_ascii_case("toml")) {
        return Err("ends in .toml, the format of config and racket files, which no command writes:                     name the output for what it is (.csv, .json, .md)"
            .to_string());
    }
    Ok(())
}

/// A new empty temporary file for the output `shown`, resolved to `target`: beside a file
/// target (so the rename stays on one file system), in the system's temporary directory for
/// a device. Created readable by all (subject to the umask), as a plain file would be.
fn temp_for(target: &Resolved, shown: &Path, suffix: &str) -> Result<Temp> {
    let (dir, name) = match target {
        Resolved::File(p) => (parent_dir(p).to_path_buf(), p.file_name()),
        Resolved::Through(p) => (std::env::temp_dir(), p.file_name()),
    };
    let prefix = format!(".{}.tmp.", name.map(|n| n.to_string_lossy()).unwrap_or_default());
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(suffix);
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(fs::Permissions::from_mode(0o666));
    }
    Temp::create(|| builder.tempfile_in(&dir)).map_err(|e| Error::io(shown, cannot_create(&dir, &e)))
}

/// Why no file can be created in `dir`, in a few words (`directory d is not writable: permission
/// denied`).
fn cannot_create(dir: &Path, e: &std::io::Error) -> String {
    format!("cannot create a file in directory {}: {}", dir.display(), std::io::Error::from(e.kind()))
}

/// Copy the finished temporary file `tmp` through the device or FIFO `target`.
fn write_through(tmp: &Path, target: &Path, shown: &Path) -> Result<()> {
    let copied = (|| -> std::io::Result<()> {
        let mut from = File::open(tmp)?;
        let mut to = OpenOptions::new().write(true).open(target)?;
        std::io::copy(&mut from, &mut to)?;
        to.flush()
    })();
    copied.map_err(|e| Error::io(shown, e))
}

/// Rename the finished temporary file `tmp` over the regular file (or nothing) `target`,
/// giving it first the permissions of the file it replaces (a `chmod 600` output stays 600;
/// a new file keeps the temporary file's, readable by all subject to the umask).
fn replace(tmp: Temp, target: &Path, shown: &Path) -> Result<()> {
    if let Ok(meta) = fs::metadata(target) {
        tmp.as_file().set_permissions(meta.permissions()).map_err(|e| Error::io(shown, e))?;
    }
    tmp.persist(target).map_err(|e| Error::io(shown, format!("cannot replace it with the new output: {e}")))
}

/// One staged output: its temporary file, where it goes and the path the user gave.
struct Pending {
    tmp: Temp,
    target: Resolved,
    shown: PathBuf,
}

/// A file renamed into place, and how to take it back: the file it replaced, kept under a
/// hidden name beside it (a hard link, or a copy where links are not possible), or nothing
/// where there was none.
struct Replaced {
    target: PathBuf,
    old: Option<Temp>,
}

impl Replaced {
    /// Rename the staged `p` over its target `target`, keeping the file it replaces.
    fn swap_in(p: Pending, target: &Path) -> Result<Replaced> {
        let old = match fs::symlink_metadata(target) {
            Ok(m) if m.file_type().is_file() => {
                let keep = temp_for(&p.target, &p.shown, ".old")?;
                let kept = fs::remove_file(keep.path())
                    .and_then(|()| fs::hard_link(target, keep.path()))
                    .or_else(|_| fs::copy(target, keep.path()).map(|_| ()));
                kept.map_err(|e| Error::io(&p.shown, format!("cannot keep the file it replaces: {e}")))?;
                Some(keep)
            }
            _ => None,
        };
        replace(p.tmp, target, &p.shown)?;
        Ok(Replaced { target: target.to_path_buf(), old })
    }

    /// Put back what was there before (best effort: this runs after another error).
    fn undo(self) {
        match self.old {
            Some(old) => {
                let _ = old.persist(&self.target);
            }
            None => {
                let _ = fs::remove_file(&self.target);
            }
        }
    }
}

/// Output files staged together and published together, all or none ([`Staged::publish`]);
/// dropped without a commit (an error, a failed print), every temporary file is removed and no
/// output is touched.
#[derive(Default)]
pub struct Staged {
    files: Vec<Pending>,
}

impl Staged {
    /// Nothing staged yet.
    pub fn new() -> Self {
        Staged::default()
    }

    /// Stage `bytes` as the content of `path`.
    pub fn bytes(&mut self, path: &Path, bytes: &[u8]) -> Result<()> {
        self.with(path, "", |tmp| {
            let written = (|| -> std::io::Result<()> {
                let mut file = OpenOptions::new().write(true).truncate(true).open(tmp)?;
                file.write_all(bytes)?;
                file.sync_all()
            })();
            written.map_err(|e| Error::io(path, e))
        })
    }

    /// Stage the file that `write` writes at the temporary path it is given (which ends in
    /// `suffix`, for writers that choose the format by extension) as the content of `path`.
    pub fn with(&mut self, path: &Path, suffix: &str, write: impl FnOnce(&Path) -> Result<()>) -> Result<()> {
        not_an_input(path).map_err(|why| Error::io(path, why))?;
        let target = resolve(path)?;
        let tmp = temp_for(&target, path, suffix)?;
        write(tmp.path())?;
        self.files.push(Pending { tmp, target, shown: path.to_path_buf() });
        Ok(())
    }

    /// Move everything staged in `other` into this set (published with it).
    pub fn append(&mut self, other: Staged) {
        self.files.extend(other.files);
    }

    /// Publish every staged file (see [`Staged::publish`]).
    pub fn commit(self) -> Result<()> {
        self.publish(|| Ok(()))
    }

    /// Publish every staged file, all or none, then run `print` (the command's standard
    /// output, which may say what was written).
    ///
    /// Every destination is checked again first (a directory or a missing folder that appeared
    /// since the files were staged fails the command before anything is replaced). Devices and
    /// FIFOs are then written through (they cannot be taken back, so they go first: a full
    /// device fails the command before any file is replaced). Then the files are renamed into
    /// place, each keeping the file it replaces; if a rename fails, or `print` fails after them
    /// (`> /dev/full`), every file already renamed is put back as it was. Only when all is done
    /// are the kept files removed.
    pub fn publish(mut self, print: impl FnOnce() -> Result<()>) -> Result<()> {
        let files = std::mem::take(&mut self.files);
        for p in &files {
            not_an_input(&p.shown).map_err(|why| Error::io(&p.shown, why))?;
            if resolve(&p.shown)? != p.target {
                return Err(Error::io(&p.shown, "changed while the output was being prepared"));
            }
        }
        let (through, renamed): (Vec<Pending>, Vec<Pending>) = files.into_iter().partition(|p| p.target.is_through());
        for p in &through {
            if let Resolved::Through(target) = &p.target {
                write_through(p.tmp.path(), target, &p.shown)?;
            }
        }
        let undo_all = |done: Vec<Replaced>| {
            let _whole = PUBLISHING.lock().unwrap_or_else(|e| e.into_inner());
            done.into_iter().rev().for_each(Replaced::undo);
        };
        let mut done = Vec::new();
        {
            let _whole = PUBLISHING.lock().unwrap_or_else(|e| e.into_inner());
            for p in renamed {
                let Resolved::File(target) = p.target.clone() else { continue };
                match Replaced::swap_in(p, &target) {
                    Ok(r) => done.push(r),
                    Err(e) => {
                        drop(_whole);
                        undo_all(done);
                        return Err(e);
                    }
                }
            }
        }
        if let Err(e) = print() {
            undo_all(done);
            return Err(e);
        }
        // (dropping the kept files removes them)
        drop(done);
        Ok(())
    }
}

/// Write `bytes` to `path` atomically (see the module docs for links and devices).
///
/// On any error no temporary file is left and an [`Error::Io`] naming `path` is returned;
/// `path` itself is then untouched. The directory of `path` must already exist; this function
/// never creates directories (see [`ensure_dir`]).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    let mut staged = Staged::new();
    staged.bytes(path, bytes)?;
    staged.commit()
}

/// Write the file that `write` writes at a temporary path ending in `suffix` to `path`
/// atomically, as [`write_atomic`].
pub fn write_with(path: &Path, suffix: &str, write: impl FnOnce(&Path) -> Result<()>) -> Result<()> {
    let mut staged = Staged::new();
    staged.with(path, suffix, write)?;
    staged.commit()
}

/// Refuse an output `path` that cannot be written, as an invalid value of the option `field`:
/// its directory does not exist, it is a directory, or no file can be created beside it (a
/// read-only directory). Checked before any work, so nothing is computed for an output that
/// cannot be written; creates nothing.
pub fn check_output_dir(field: &'static str, path: &Path) -> Result<()> {
    let refuse = |why: String| Error::invalid(field, path.display(), why);
    not_an_input(path).map_err(refuse)?;
    let dir = parent_dir(path);
    if !dir.is_dir() {
        return Err(refuse(format!("directory {} does not exist", dir.display())));
    }
    let message = |e: Error| match e {
        Error::Io { message, .. } => message,
        other => other.to_string(),
    };
    let target = resolve(path).map_err(|e| refuse(message(e)))?;
    match &target {
        // a probe of the same kind as the real temporary file, removed at once
        Resolved::File(file) => {
            temp_for(&target, path, "").map_err(|e| refuse(message(e)))?;
            if let Some(why) = cannot_replace(file) {
                return Err(refuse(why));
            }
        }
        Resolved::Through(device) => probe_device(device).map_err(|e| refuse(format!("cannot be written: {e}")))?,
    }
    Ok(())
}

/// Why the existing regular file `file` cannot be replaced by a rename, where it is marked
/// immutable or append-only (`chattr +i`, `+a`): opening it for writing (which writes nothing)
/// then fails with "Operation not permitted", where a file that is merely read-only fails with
/// "Permission denied" and is replaced all the same. `None` for any other file.
fn cannot_replace(file: &Path) -> Option<String> {
    if !fs::symlink_metadata(file).is_ok_and(|m| m.is_file()) {
        return None;
    }
    match OpenOptions::new().write(true).open(file) {
        Err(e) if e.kind() == std::io::ErrorKind::PermissionDenied && e.raw_os_error() == Some(1) => Some(format!(
            "the existing file cannot be replaced ({e}: it is marked immutable or append-only, see lsattr)"
        )),
        _ => None,
    }
}

/// Whether a character device can be written, without writing to it: opened for writing and
/// given an empty write, which writes nothing and fails where every write would (`/dev/full`:
/// no space left; a read-only device). A FIFO is not probed (opening it would block until a
/// reader comes, and closing it would end that reader's input), nor a socket.
fn probe_device(device: &Path) -> std::io::Result<()> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if !fs::metadata(device)?.file_type().is_char_device() {
            return Ok(());
        }
        let mut file = OpenOptions::new().write(true).open(device)?;
        // (`write`, not `write_all`: an empty `write_all` never calls the system)
        file.write(&[]).map(|_| ())
    }
    #[cfg(not(unix))]
    {
        let _ = device;
        Ok(())
    }
}

/// A file written in pieces and published atomically: the bytes go to a hidden temporary file
/// next to the target (or straight through a device or FIFO); [`AtomicFile::commit`] syncs it
/// and renames it over the target. Dropped without a commit (an error, a panic), the temporary
/// file is removed and the target is untouched. Used for streamed outputs such as `sweep`,
/// whose size is not known in advance.
pub struct AtomicFile {
    path: PathBuf,
    out: Option<Stream>,
}

/// Where an [`AtomicFile`]'s bytes go.
enum Stream {
    Temp(std::io::BufWriter<Temp>, PathBuf),
    Through(std::io::BufWriter<File>),
}

impl AtomicFile {
    /// Start writing `path` (its directory must exist).
    pub fn create(path: &Path) -> Result<Self> {
        not_an_input(path).map_err(|why| Error::io(path, why))?;
        let out = match resolve(path)? {
            Resolved::Through(target) => {
                let file = OpenOptions::new().write(true).open(&target).map_err(|e| Error::io(path, e))?;
                Stream::Through(std::io::BufWriter::new(file))
            }
            file @ Resolved::File(_) => {
                let tmp = temp_for(&file, path, "")?;
                let Resolved::File(target) = file else { unreachable!("matched as a file") };
                Stream::Temp(std::io::BufWriter::new(tmp), target)
            }
        };
        Ok(AtomicFile { path: path.to_path_buf(), out: Some(out) })
    }

    /// Append bytes.
    pub fn write(&mut self, bytes: &[u8]) -> Result<()> {
        let written = match self.out.as_mut() {
            Some(Stream::Temp(w, _)) => w.write_all(bytes),
            Some(Stream::Through(w)) => w.write_all(bytes),
            None => return Err(Error::io(&self.path, "already committed")),
        };
        written.map_err(|e| Error::io(&self.path, e))
    }

    /// Flush, sync and rename over the target (or flush through the device).
    pub fn commit(mut self) -> Result<()> {
        let fail = |e: std::io::Error| Error::io(&self.path, e);
        match self.out.take() {
            Some(Stream::Temp(w, target)) => {
                let tmp = w.into_inner().map_err(|e| fail(e.into_error()))?;
                tmp.as_file().sync_all().map_err(fail)?;
                replace(tmp, &target, &self.path)
            }
            Some(Stream::Through(mut w)) => w.flush().map_err(fail),
            None => Err(Error::io(&self.path, "already committed")),
        }
    }
}

/// Refuse a directory path `dir`, the value of the option `field`, that cannot become a
/// directory: it, or the nearest of its ancestors that exists, is not a directory (a regular
/// file in the way). Checked before any work; creates nothing.
pub fn check_dir_path(field: &'static str, dir: &Path) -> Result<()> {
    let existing = dir.ancestors().find(|a| !a.as_os_str().is_empty() && fs::metadata(a).is_ok());
    match existing {
        Some(a) if !a.is_dir() => {
            let why = if a == dir {
                "is a file, not a directory (the option names the directory the files go in)".to_string()
            } else {
                format!("{} is a file, not a directory", a.display())
            };
            Err(Error::invalid(field, dir.display(), why))
        }
        _ => Ok(()),
    }
}

/// Create `dir` and any missing parents (like `mkdir -p`).
///
/// Succeeds if the directory already exists; fails with an [`Error::Io`] naming `dir` if it
/// cannot be created (for example because a regular file is in the way).
pub fn ensure_dir(dir: &Path) -> Result<()> {
    // the directories this creates, outermost first, are removed again if the run fails or is
    // interrupted while they are empty (`render::temps::remove_created_dirs`)
    let mut created = super::temps::created_dirs();
    let missing: Vec<&Path> =
        dir.ancestors().take_while(|a| !a.as_os_str().is_empty() && fs::symlink_metadata(a).is_err()).collect();
    let made = fs::create_dir_all(dir);
    created.extend(missing.iter().rev().map(|d| d.to_path_buf()));
    drop(created);
    made.map_err(|e| Error::io(dir, format!("cannot create directory: {e}")))?;
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

    /// A folder with an old `a.csv`, and a set staging new contents for `a.csv` and a new `b.png`.
    fn old_a_staged_with_new_b() -> (tempfile::TempDir, PathBuf, PathBuf, Staged) {
        let dir = scratch();
        let (a, b) = (dir.path().join("a.csv"), dir.path().join("b.png"));
        fs::write(&a, b"old a").unwrap();
        let mut staged = Staged::new();
        staged.bytes(&a, b"new a").unwrap();
        staged.bytes(&b, b"new b").unwrap();
        (dir, a, b, staged)
    }

    /// A device that fails every write (`/dev/full`) is refused by the check every command
    /// makes before its work; one that takes writes (`/dev/null`) passes, and is not written.
    #[cfg(target_os = "linux")]
    #[test]
    fn a_full_device_is_refused_before_any_work() {
        let msg = check_output_dir("out", Path::new("/dev/full")).unwrap_err().to_string();
        assert!(msg.starts_with("invalid out = /dev/full: cannot be written: No space left"), "{msg}");
        assert!(check_output_dir("out", Path::new("/dev/null")).is_ok());
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

    #[cfg(unix)]
    #[test]
    fn links_are_followed_to_what_they_name_and_loops_and_directories_refused() {
        let dir = scratch();
        let (a, b, c) = (dir.path().join("a"), dir.path().join("b"), dir.path().join("c.csv"));
        std::os::unix::fs::symlink("b", &a).unwrap();
        std::os::unix::fs::symlink("c.csv", &b).unwrap();
        assert_eq!(resolve(&a).unwrap(), Resolved::File(dir.path().join("c.csv")), "dangling at the end: created");
        write_atomic(&a, b"x").unwrap();
        assert_eq!(fs::read(&c).unwrap(), b"x");
        assert!(fs::symlink_metadata(&a).unwrap().file_type().is_symlink());
        let (l1, l2) = (dir.path().join("l1"), dir.path().join("l2"));
        std::os::unix::fs::symlink("l2", &l1).unwrap();
        std::os::unix::fs::symlink("l1", &l2).unwrap();
        assert!(resolve(&l1).unwrap_err().to_string().contains("symbolic links"));
        let d = dir.path().join("d");
        fs::create_dir(&d).unwrap();
        std::os::unix::fs::symlink("d", dir.path().join("ld")).unwrap();
        assert!(resolve(&dir.path().join("ld")).unwrap_err().to_string().contains("is a directory"));
        assert!(resolve(Path::new("/dev/null")).unwrap().is_through());
    }

    #[test]
    fn a_staged_file_dropped_uncommitted_leaves_nothing() {
        let dir = scratch();
        let path = dir.path().join("out.csv");
        fs::write(&path, b"old").unwrap();
        let mut staged = Staged::new();
        staged.bytes(&path, b"new").unwrap();
        staged.bytes(&dir.path().join("other.json"), b"{}").unwrap();
        drop(staged);
        assert_eq!(fs::read(&path).unwrap(), b"old");
        assert_eq!(entries(dir.path()), vec!["out.csv".to_string()]);
    }

    #[test]
    fn a_failed_print_puts_back_every_replaced_file() {
        let (dir, a, b, staged) = old_a_staged_with_new_b();
        let e = staged.publish(|| Err(Error::io("<stdout>", "No space left on device"))).unwrap_err();
        assert!(e.to_string().contains("No space left"), "{e}");
        assert_eq!(fs::read(&a).unwrap(), b"old a", "replaced file put back");
        assert!(!b.exists(), "new file removed");
        assert_eq!(entries(dir.path()), vec!["a.csv".to_string()], "no temporary or kept file left");
        // and published, the kept files are removed
        let mut staged = Staged::new();
        staged.bytes(&a, b"new a").unwrap();
        staged.bytes(&b, b"new b").unwrap();
        staged.commit().unwrap();
        assert_eq!((fs::read(&a).unwrap(), fs::read(&b).unwrap()), (b"new a".to_vec(), b"new b".to_vec()));
        assert_eq!(entries(dir.path()), vec!["a.csv".to_string(), "b.png".to_string()]);
    }

    #[test]
    fn a_destination_that_changed_fails_before_any_rename() {
        let (dir, a, b, staged) = old_a_staged_with_new_b();
        fs::create_dir(&b).unwrap();
        let mut printed = false;
        let e = staged
            .publish(|| {
                printed = true;
                Ok(())
            })
            .unwrap_err();
        assert!(e.to_string().contains("is a directory"), "{e}");
        assert!(!printed, "nothing said written");
        assert_eq!(fs::read(&a).unwrap(), b"old a");
        assert_eq!(entries(dir.path()), vec!["a.csv".to_string(), "b.png".to_string()]);
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
