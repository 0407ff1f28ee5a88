//! The input files this run has read (config and racket files, a measurements CSV), kept so that no output of the
//! same run replaces one of them (`sweep --config c.toml --out c.toml`): an output path is
//! compared with them by identity (device and inode, after following links), not spelling, so
//! `./c.toml`, an absolute path, a hard link and a symbolic link to it are all the same file.
//!
//! Every input is read through `super::read_file` or [`read_text`], which record it here; the output side
//! ([`crate::render::io`]) asks [`same_as_input`] before any work and again when it stages a
//! file. Hand-written rather than the `same-file` crate: its handles open the file, which
//! blocks on a FIFO output (`--out /dev/stdout` into a pipe) and changes nothing for a path
//! compared by its metadata.

use std::path::{Path, PathBuf};
use std::sync::Mutex;

use crate::error::{Error, Result};

/// What identifies a file on this system.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Identity(#[cfg(unix)] (u64, u64), #[cfg(not(unix))] PathBuf);

/// The identity of the file at `path` (links followed), if there is one.
fn identity(path: &Path) -> Option<Identity> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        std::fs::metadata(path).ok().map(|m| Identity((m.dev(), m.ino())))
    }
    #[cfg(not(unix))]
    {
        std::fs::canonicalize(path).ok().map(Identity)
    }
}

/// The inputs read so far: the path as given, and the file's identity.
static READ: Mutex<Vec<(PathBuf, Identity)>> = Mutex::new(Vec::new());

/// Record that the file at `path` is an input of this run.
pub(crate) fn record(path: &Path) {
    if let Some(id) = identity(path) {
        let mut read = READ.lock().unwrap_or_else(|e| e.into_inner());
        if !read.iter().any(|(_, i)| *i == id) {
            read.push((path.to_path_buf(), id));
        }
    }
}

/// Read the input file at `path` whole, as text, and record it as an input of this run: the
/// measurements CSV of `calibrate` (config and racket files go through `super::read_file`, which
/// records them too), so that no output of the run replaces it (`--plot` onto the CSV, an
/// `--out` that is a link to it). A file larger than `max_bytes` (`/dev/zero`, or a CSV of
/// gigabytes) is refused instead of read; `what` names the file in that message.
pub fn read_text(path: &Path, what: &str, max_bytes: u64) -> Result<String> {
    use std::io::Read;
    let mut bytes = Vec::new();
    let file = std::fs::File::open(path).map_err(|e| Error::io(path, e))?;
    file.take(max_bytes + 1).read_to_end(&mut bytes).map_err(|e| Error::io(path, e))?;
    if bytes.len() as u64 > max_bytes {
        return Err(Error::io(path, format!("is larger than {} MiB, the most {what} may be", max_bytes >> 20)));
    }
    let text = String::from_utf8(bytes).map_err(|_| Error::io(path, "is not a UTF-8 text file"))?;
    record(path);
    Ok(text)
}

/// The input (as it was named) that the file at `output` is, if any; `None` for an output
/// that does not exist yet.
pub fn same_as_input(output: &Path) -> Option<PathBuf> {
    let id = identity(output)?;
    let read = READ.lock().unwrap_or_else(|e| e.into_inner());
    read.iter().find(|(_, i)| *i == id).map(|(p, _)| p.clone())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_input_is_found_by_identity_whatever_the_spelling() {
        let dir = tempfile::tempdir().unwrap();
        let input = dir.path().join("c.toml");
        std::fs::write(&input, "ks = 4e4\n").unwrap();
        let other = dir.path().join("other.csv");
        std::fs::write(&other, "").unwrap();
        assert_eq!(same_as_input(&input), None);
        record(&input);
        assert_eq!(same_as_input(&dir.path().join(".").join("c.toml")), Some(input.clone()));
        assert_eq!(same_as_input(&other), None);
        assert_eq!(same_as_input(&dir.path().join("missing.csv")), None);
        #[cfg(unix)]
        {
            let link = dir.path().join("link.csv");
            std::os::unix::fs::symlink("c.toml", &link).unwrap();
            assert_eq!(same_as_input(&link), Some(input.clone()));
            let hard = dir.path().join("hard.csv");
            std::fs::hard_link(&input, &hard).unwrap();
            assert_eq!(same_as_input(&hard), Some(input));
        }
    }
}
