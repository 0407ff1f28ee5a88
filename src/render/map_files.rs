//! The files of a map: its CSV table, PNG heat map and JSON metadata, written together.

use crate::error::{Error, Result};
use crate::render::heatmap::HeatMap;
use crate::render::io::{resolve, Resolved, Staged};

/// The three output files of a map: the CSV as given, the PNG and the JSON next to it (same
/// stem).
///
/// Where the CSV path is a symbolic link, its target is written and the link kept (as for every
/// output, see [`crate::render::io`]), and the PNG and JSON go beside that target with its stem:
/// the three files of a map always sit together, so a link `latest.csv -> run7/map.csv` updates
/// `run7/map.{csv,png,json}` and never leaves a new `run7/map.csv` beside an old `run7/map.png`
/// with the new picture at `latest.png`.
#[derive(Debug, Clone, PartialEq)]
pub struct Outputs {
    /// The table, as given.
    pub csv: std::path::PathBuf,
    /// The file the table really is, where [`Outputs::csv`] is a symbolic link (the siblings
    /// are named from it).
    pub csv_target: Option<std::path::PathBuf>,
    /// The heat map.
    pub png: std::path::PathBuf,
    /// The metadata.
    pub json: std::path::PathBuf,
}

impl Outputs {
    /// The files for `--out path` (the PNG and JSON replace its extension, or its link
    /// target's); the directory must exist and neither the path nor what it links to may end
    /// in `.png` or `.json` (the CSV would be overwritten by a sibling).
    pub fn for_csv(path: &std::path::Path) -> Result<Outputs> {
        Outputs::for_csv_of(
            path,
            "the CSV file of the map (the PNG and JSON go next to it with the same stem), e.g. map.csv",
            "a map is three files (CSV, PNG and JSON with the same stem): give a file path, not a device or pipe (--format csv prints the table)",
        )
    }

    /// [`Outputs::for_csv`] for another command's files, with its own words for a path that
    /// names a sibling (`sibling`) and for a device or pipe (`through`).
    pub fn for_csv_of(path: &std::path::Path, sibling: &str, through: &str) -> Result<Outputs> {
        let sibling_named = |p: &std::path::Path| {
            let ext = p.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
            ext == "png" || ext == "json" || p.file_name().is_none()
        };
        let refuse = || Error::invalid("out", path.display(), sibling);
        if sibling_named(path) {
            return Err(refuse());
        }
        crate::render::io::check_output_dir("out", path)?;
        let target = match resolve(path)? {
            Resolved::Through(_) => return Err(Error::invalid("out", path.display(), through)),
            Resolved::File(target) if sibling_named(&target) => return Err(refuse()),
            Resolved::File(target) => target,
        };
        let is_link = std::fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_symlink());
        let csv_target = if is_link {
            // the target's directory exists (resolve checked it): named without `dir/../`
            let dir = target.parent().unwrap_or(std::path::Path::new("."));
            let dir = if dir.as_os_str().is_empty() { std::path::Path::new(".") } else { dir };
            let dir = std::fs::canonicalize(dir).map_err(|e| Error::io(path, e))?;
            Some(dir.join(target.file_name().unwrap_or_default()))
        } else {
            None
        };
        let stem = csv_target.as_deref().unwrap_or(path);
        let out = Outputs {
            csv: path.to_path_buf(),
            png: stem.with_extension("png"),
            json: stem.with_extension("json"),
            csv_target: csv_target.clone(),
        };
        for p in [&out.png, &out.json] {
            crate::render::io::check_output_dir("out", p)?;
        }
        Ok(out)
    }

    /// Stage all three (see [`crate::render::io::Staged`]): each is complete in a temporary
    /// file, and the caller publishes them together around the printed summary
    /// ([`Staged::publish`]); dropped instead, nothing is written.
    pub fn stage(&self, csv: &str, map: &HeatMap, json: &str) -> Result<Staged> {
        let mut staged = Staged::new();
        staged.bytes(&self.csv, csv.as_bytes())?;
        staged.bytes(&self.json, json.as_bytes())?;
        staged.with(&self.png, ".png", |tmp| {
            crate::render::heatmap::draw_file(map, tmp)
                .map_err(|message| Error::Plot { id: self.png.display().to_string(), message })
        })?;
        Ok(staged)
    }
}
