//! The files of a map: its CSV table, PNG heat map and JSON metadata, written together.

use crate::error::{Error, Result};
use crate::render::heatmap::HeatMap;
use crate::render::io::{resolve, Staged};

/// The three output files of a map: the CSV as given, the PNG and the JSON next to it (same
/// stem).
#[derive(Debug, Clone, PartialEq)]
pub struct Outputs {
    /// The table.
    pub csv: std::path::PathBuf,
    /// The heat map.
    pub png: std::path::PathBuf,
    /// The metadata.
    pub json: std::path::PathBuf,
}

impl Outputs {
    /// The files for `--out path` (the PNG and JSON replace its extension); the directory must
    /// exist and the path must not itself end in `.png` or `.json`.
    pub fn for_csv(path: &std::path::Path) -> Result<Outputs> {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
        if ext == "png" || ext == "json" || path.file_name().is_none() {
            return Err(Error::invalid(
                "out",
                path.display(),
                "the CSV file of the map (the PNG and JSON go next to it with the same stem), e.g. map.csv",
            ));
        }
        crate::render::io::check_output_dir("out", path)?;
        if resolve(path)?.is_through() {
            return Err(Error::invalid(
                "out",
                path.display(),
                "a map is three files (CSV, PNG and JSON with the same stem): give a file path, not a device or pipe (--format csv prints the table)",
            ));
        }
        let out =
            Outputs { csv: path.to_path_buf(), png: path.with_extension("png"), json: path.with_extension("json") };
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
