//! A sheet: several charts on one page, in a grid, each with a note under it, text cells (a
//! small table in words), a title and a footnote, drawn into one PNG with the same fonts,
//! palette, mesh and legends as every other figure ([`super::Chart`]) and as deterministically.
//!
//! The page is [`CELL_WIDTH`] times the columns wide; its height follows from the rows and the
//! wrapped text (every grid row as tall as its tallest note), so no text is cut off.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::FontStyle;

use super::draw::draw_chart;
use super::plan::Plan;
use super::{font, fonts_registered, msg, Chart, AXIS_DESC_SIZE, TICK_SIZE};
use crate::error::{Error, Result};

/// Width of one cell, pixels.
pub const CELL_WIDTH: u32 = 800;
/// Height of one cell's chart, pixels.
pub const CHART_HEIGHT: u32 = 600;
/// Size of the notes' and the footnote's text, pixels.
pub const NOTE_SIZE: f64 = 17.0;
/// Line height of notes, footnotes and text cells, pixels.
const LINE: u32 = 23;
/// Margin around text, pixels.
const MARGIN: u32 = 24;
/// Height of the sheet's title band, pixels.
const TITLE_BAND: u32 = 64;

/// A cell of the sheet.
#[derive(Clone, Debug, PartialEq)]
pub enum Cell {
    /// A chart, with a note under it (paragraphs, wrapped to the cell).
    Chart {
        /// The chart (its own panel, if any, is not drawn).
        chart: Box<Chart>,
        /// The note's paragraphs.
        note: Vec<String>,
    },
    /// A small table in words: a bold title, rows of cells in aligned columns (the first row
    /// bold, a header), then a note.
    Text {
        /// The title.
        title: String,
        /// The rows.
        rows: Vec<Vec<String>>,
        /// The note's paragraphs.
        note: Vec<String>,
    },
}

/// A page of cells.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Sheet {
    /// The title, across the top.
    pub title: String,
    /// Cells per row.
    pub columns: usize,
    /// The cells, row by row.
    pub cells: Vec<Cell>,
    /// The footnote's paragraphs, across the bottom.
    pub footnote: Vec<String>,
}

/// `text` broken into lines no wider than `width` pixels in the note font (at spaces; a word
/// longer than the width stands on its own line).
pub fn wrap(text: &str, width: u32, size: f64) -> Vec<String> {
    fonts_registered();
    let style = font(size, FontStyle::Normal);
    let fits = |s: &str| style.font.box_size(s).is_ok_and(|(w, _)| w <= width);
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        let candidate = if line.is_empty() { word.to_string() } else { format!("{line} {word}") };
        if fits(&candidate) || line.is_empty() {
            line = candidate;
        } else {
            lines.push(std::mem::replace(&mut line, word.to_string()));
        }
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

impl Sheet {
    /// The page's width, pixels.
    pub fn width(&self) -> u32 {
        CELL_WIDTH * self.columns.max(1) as u32
    }

    /// The wrapped lines of each cell's note.
    fn note_lines(&self) -> Vec<Vec<String>> {
        let width = CELL_WIDTH - 2 * MARGIN;
        self.cells
            .iter()
            .map(|c| {
                let note = match c {
                    Cell::Chart { note, .. } | Cell::Text { note, .. } => note,
                };
                note.iter().flat_map(|p| wrap(p, width, NOTE_SIZE)).collect()
            })
            .collect()
    }

    /// The footnote's wrapped lines.
    fn footnote_lines(&self) -> Vec<String> {
        self.footnote.iter().flat_map(|p| wrap(p, self.width() - 2 * MARGIN, NOTE_SIZE)).collect()
    }

    /// Each grid row's height, pixels: the chart and its tallest note.
    fn row_heights(&self, notes: &[Vec<String>]) -> Vec<u32> {
        notes
            .chunks(self.columns.max(1))
            .map(|row| CHART_HEIGHT + LINE * row.iter().map(Vec::len).max().unwrap_or(0) as u32 + MARGIN / 2)
            .collect()
    }

    /// The page's height, pixels.
    pub fn height(&self) -> u32 {
        let rows: u32 = self.row_heights(&self.note_lines()).iter().sum();
        TITLE_BAND + rows + LINE * self.footnote_lines().len() as u32 + 2 * MARGIN
    }
}

/// Draw `sheet` as a PNG at `path`, staged in `staged` (published with the command's other
/// files); [`Error::Plot`] with `id` on any failure.
pub fn stage_sheet(
    staged: &mut crate::render::io::Staged,
    id: &str,
    sheet: &Sheet,
    path: &std::path::Path,
) -> Result<()> {
    let fail = |message: String| Error::Plot { id: id.to_string(), message };
    if !fonts_registered() {
        return Err(fail("could not load the bundled DejaVu Sans font".to_string()));
    }
    let plans = sheet
        .cells
        .iter()
        .map(|c| match c {
            Cell::Chart { chart, .. } => Plan::new(chart).map(Some),
            Cell::Text { .. } => Ok(None),
        })
        .collect::<std::result::Result<Vec<_>, _>>()
        .map_err(&fail)?;
    super::stage_drawn(staged, id, path, |tmp| draw(sheet, &plans, tmp))
}

/// Draw the whole sheet into the file `tmp`.
fn draw(sheet: &Sheet, plans: &[Option<Plan>], tmp: &std::path::Path) -> std::result::Result<(), String> {
    let (width, height) = (sheet.width(), sheet.height());
    let root = BitMapBackend::new(tmp, (width, height)).into_drawing_area();
    root.fill(&WHITE).map_err(msg)?;
    let title = font(30.0, FontStyle::Bold).pos(plotters::style::text_anchor::Pos::new(
        plotters::style::text_anchor::HPos::Center,
        plotters::style::text_anchor::VPos::Center,
    ));
    root.draw_text(&sheet.title, &title, (width as i32 / 2, TITLE_BAND as i32 / 2)).map_err(msg)?;
    let notes = sheet.note_lines();
    let heights = sheet.row_heights(&notes);
    let columns = sheet.columns.max(1);
    let mut top = TITLE_BAND;
    for (r, h) in heights.iter().enumerate() {
        for c in 0..columns {
            let k = r * columns + c;
            let Some(cell) = sheet.cells.get(k) else { continue };
            let left = c as u32 * CELL_WIDTH;
            let area = root.clone().shrink((left as i32, top as i32), (CELL_WIDTH, CHART_HEIGHT));
            match (cell, &plans[k]) {
                (Cell::Chart { chart, .. }, Some(plan)) => {
                    let (x0, x1) = plan.x;
                    if plan.x_log {
                        draw_chart(&area, chart, plan, (x0..x1).log_scale())?;
                    } else {
                        draw_chart(&area, chart, plan, x0..x1)?;
                    }
                }
                (Cell::Text { title, rows, .. }, _) => draw_text_cell(&area, title, rows)?,
                _ => {}
            }
            draw_lines(&root, &notes[k], (left + MARGIN, top + CHART_HEIGHT))?;
        }
        top += h;
    }
    let rule = RGBColor(0, 0, 0).mix(0.3);
    root.draw(&PathElement::new(
        vec![(MARGIN as i32, top as i32 + 4), ((width - MARGIN) as i32, top as i32 + 4)],
        rule,
    ))
    .map_err(msg)?;
    draw_lines(&root, &sheet.footnote_lines(), (MARGIN, top + MARGIN / 2))?;
    root.present().map_err(|e| format!("cannot write {}: {e}", tmp.display()))
}

/// Lines of note text from `(x, y)` down, one [`LINE`] apart.
fn draw_lines(
    root: &DrawingArea<BitMapBackend<'_>, Shift>,
    lines: &[String],
    (x, y): (u32, u32),
) -> std::result::Result<(), String> {
    let style = font(NOTE_SIZE, FontStyle::Normal).color(&RGBColor(40, 40, 40));
    for (i, line) in lines.iter().enumerate() {
        root.draw_text(line, &style, (x as i32, (y + LINE * i as u32) as i32)).map_err(msg)?;
    }
    Ok(())
}

/// A text cell: the title in bold, then the rows in columns as wide as their widest entry (the
/// first row bold); numbers are right-aligned in their column, words left-aligned.
fn draw_text_cell(
    area: &DrawingArea<BitMapBackend<'_>, Shift>,
    title: &str,
    rows: &[Vec<String>],
) -> std::result::Result<(), String> {
    let title_style = font(AXIS_DESC_SIZE + 2.0, FontStyle::Bold);
    area.draw_text(title, &title_style, (MARGIN as i32, MARGIN as i32)).map_err(msg)?;
    let normal = font(TICK_SIZE, FontStyle::Normal);
    let bold = font(TICK_SIZE, FontStyle::Bold);
    let n = rows.iter().map(Vec::len).max().unwrap_or(0);
    let mut widths = vec![0u32; n];
    for (i, row) in rows.iter().enumerate() {
        let style = if i == 0 { &bold } else { &normal };
        for (k, cell) in row.iter().enumerate() {
            widths[k] = widths[k].max(area.estimate_text_size(cell, style).map_err(msg)?.0);
        }
    }
    let gap = 18;
    let numeric = |s: &str| s.trim_start_matches(['+', '-']).chars().next().is_some_and(|c| c.is_ascii_digit());
    for (i, row) in rows.iter().enumerate() {
        let y = (MARGIN + 44 + (LINE + 3) * i as u32) as i32;
        let style = if i == 0 { &bold } else { &normal };
        let mut x = MARGIN as i32;
        for (k, cell) in row.iter().enumerate() {
            let w = area.estimate_text_size(cell, style).map_err(msg)?.0 as i32;
            let at = if i > 0 && k > 0 && numeric(cell) { x + widths[k] as i32 - w } else { x };
            area.draw_text(cell, style, (at, y)).map_err(msg)?;
            x += widths[k] as i32 + gap;
        }
        if i == 0 {
            let line_y = y + LINE as i32;
            let right = MARGIN as i32 + widths.iter().map(|w| *w as i32 + gap).sum::<i32>() - gap;
            area.draw(&PathElement::new(vec![(MARGIN as i32, line_y), (right, line_y)], RGBColor(0, 0, 0).mix(0.4)))
                .map_err(msg)?;
        }
    }
    Ok(())
}

/// The PNG bytes of `sheet` (drawn into a temporary file, then read), for a caller that keeps
/// the picture in memory.
pub fn sheet_png(id: &str, sheet: &Sheet) -> Result<Vec<u8>> {
    let dir = tempfile::tempdir().map_err(|e| Error::io(std::env::temp_dir(), e))?;
    let path = dir.path().join(format!("{id}.png"));
    let mut staged = crate::render::io::Staged::new();
    stage_sheet(&mut staged, id, sheet, &path)?;
    staged.commit()?;
    std::fs::read(&path).map_err(|e| Error::io(&path, e))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::plot::{Curve, LineStyle};

    fn sheet() -> Sheet {
        let chart = Chart {
            title: "A panel".into(),
            x_label: "x".into(),
            y_label: "y".into(),
            curves: vec![
                Curve::new("a line", vec![0.0, 1.0, 2.0], vec![1.0, 3.0, 2.0]),
                Curve {
                    label: "a guide".into(),
                    x: vec![0.0, 2.0],
                    y: vec![2.0, 2.0],
                    style: LineStyle::Guide,
                    ..Curve::default()
                },
            ],
            ..Chart::default()
        };
        Sheet {
            title: "A sheet".into(),
            columns: 2,
            cells: vec![
                Cell::Chart {
                    chart: Box::new(chart.clone()),
                    note: vec!["a note long enough to be wrapped ".repeat(8)],
                },
                Cell::Chart { chart: Box::new(chart), note: vec![] },
                Cell::Text {
                    title: "Words".into(),
                    rows: vec![vec!["what".into(), "value".into()], vec!["one".into(), "1.5".into()]],
                    note: vec![],
                },
            ],
            footnote: vec!["the footnote".into()],
        }
    }

    #[test]
    fn a_note_wraps_to_its_width_and_keeps_every_word() {
        let text = "the quick brown fox jumps over the lazy dog ".repeat(10);
        let lines = wrap(&text, 300, NOTE_SIZE);
        assert!(lines.len() > 3);
        assert_eq!(lines.join(" "), text.trim());
        fonts_registered();
        for l in &lines {
            assert!(font(NOTE_SIZE, FontStyle::Normal).font.box_size(l).unwrap().0 <= 300, "{l}");
        }
        assert_eq!(wrap("", 300, NOTE_SIZE), Vec::<String>::new());
    }

    #[test]
    fn the_same_sheet_draws_the_same_bytes_and_grows_with_its_notes() {
        let s = sheet();
        let (a, b) = (sheet_png("t", &s).unwrap(), sheet_png("t", &s).unwrap());
        assert!(a == b && a.starts_with(b"\x89PNG"));
        assert_eq!(s.width(), 2 * CELL_WIDTH);
        let mut longer = s.clone();
        longer.footnote.push("another line".into());
        assert_eq!(longer.height(), s.height() + LINE);
        // a chart that cannot be drawn is an error naming the figure, and no file
        let mut bad = s;
        bad.cells[0] = Cell::Chart { chart: Box::new(Chart::new("empty", "x", "y")), note: vec![] };
        let e = sheet_png("t", &bad).unwrap_err().to_string();
        assert!(e.contains("t") && e.contains("no curve"), "{e}");
    }
}
