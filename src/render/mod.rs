//! Everything that turns numbers into files and text: result tables and their CSV, the one
//! look of every figure, heat maps of the string face, the text and CSV of one impact, the files
//! of a string-face map, and atomic file output.
//!
//! | module | job |
//! |---|---|
//! | [`table`] | named-column tables: CSV, column access, snapshot text |
//! | [`plot`] | line charts ([`plot::Chart`]) drawn to PNG |
//! | [`heatmap`] | heat maps with contours ([`heatmap::HeatMap`]) drawn to PNG |
//! | [`impact`] | one impact as text, CSV and a time-series file |
//! | [`columns`] | the column names of the commands' tables that no declaration holds |
//! | [`map_files`] | the three files of a string-face map, written together |
//! | [`io`] | atomic, deterministic file writes |
//! | [`temps`] | the temporary files staged, removed on an interrupt |
//! | [`json`] | every JSON output: pretty, unsigned zeros |
//! | [`place`] | where a label or legend goes, in charts and heat maps alike |
//!
//! Nothing here runs a solver: the layers above compute, and hand tables and charts down.

pub mod columns;
pub mod heatmap;
pub mod impact;
pub mod io;
pub mod json;
pub mod map_files;
pub mod place;
pub mod plot;
pub mod table;
pub mod temps;
