//! The files of a map: its CSV table, PNG heat map and JSON metadata, written together.

use crate::error::{Error, Result};
use crate::render::heatmap::HeatMap;

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
        let out =
            Outputs { csv: path.to_path_buf(), png: path.with_extension("png"), json: path.with_extension("json") };
        for p in [&out.csv, &out.png, &out.json] {
            if p.is_dir() {
                return Err(Error::invalid("out", path.display(), format!("{} is a directory", p.display())));
            }
        }
        Ok(out)
    }

    /// Write all three, all or nothing: each goes to a temporary file next to its target
    /// first, and only when all three are complete are they renamed over the targets.
    pub fn write(&self, csv: &str, map: &HeatMap, json: &str) -> Result<()> {
        let tmp_csv = crate::render::io::temp_sibling(&self.csv, "")?;
        let tmp_json = crate::render::io::temp_sibling(&self.json, "")?;
        let tmp_png = crate::render::io::temp_sibling(&self.png, ".png")?;
        let cleanup = || {
            for t in [&tmp_csv, &tmp_json, &tmp_png] {
                let _ = std::fs::remove_file(t);
            }
        };
        let written = (|| -> Result<()> {
            crate::render::io::write_synced(&tmp_csv, &self.csv, csv.as_bytes())?;
            crate::render::io::write_synced(&tmp_json, &self.json, json.as_bytes())?;
            crate::render::heatmap::draw_file(map, &tmp_png)
                .map_err(|message| Error::Plot { id: self.png.display().to_string(), message })
        })();
        if let Err(e) = written {
            cleanup();
            return Err(e);
        }
        for (tmp, path) in [(&tmp_csv, &self.csv), (&tmp_json, &self.json), (&tmp_png, &self.png)] {
            if let Err(e) = crate::render::io::commit_temp(tmp, path) {
                cleanup();
                return Err(e);
            }
        }
        Ok(())
    }
}
