//! Tests of the chart renderer: determinism, ranges, clipping, bad input.

use super::clip::Bounds;
use super::plan::{pad_linear, pad_log};
use super::*;

const PNG_SIGNATURE: [u8; 8] = [0x89, b'P', b'N', b'G', 0x0d, 0x0a, 0x1a, 0x0a];

fn scratch() -> tempfile::TempDir {
    tempfile::tempdir().expect("create temp dir")
}

fn render_bytes(chart: &Chart, dir: &Path, name: &str) -> Vec<u8> {
    let path = dir.join(name);
    render_png("test", chart, &path).expect("render");
    std::fs::read(&path).expect("read png")
}

fn files_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .expect("read dir")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

fn dual_axis_chart() -> Chart {
    let t: Vec<f64> = (0..200).map(|i| f64::from(i) * 0.05e-3).collect();
    let force: Vec<f64> = t.iter().map(|&s| (s / 10e-3 * std::f64::consts::PI).sin() * 1500.0).collect();
    let mut disp: Vec<f64> = t.iter().map(|&s| s * 1e3 * 2.0).collect();
    disp[50] = f64::NAN; // break in the line
    let mut chart = Chart::new("Impact force and displacement", "time (ms)", "force (N)");
    chart.y2_label = Some("displacement (mm)".to_string());
    let tms: Vec<f64> = t.iter().map(|s| s * 1e3).collect();
    chart.curves.push(Curve::new("force", tms.clone(), force));
    chart.curves.push(
        Curve::new("displacement", tms.clone(), disp).on_axis(Axis::Right).with_style(LineStyle::Dashed).with_color(1),
    );
    chart.curves.push(
        Curve::new("", tms.clone(), tms.iter().map(|v| v * 100.0).collect()).with_style(LineStyle::Faint).with_color(2),
    );
    chart.curves.push(
        Curve::new("measured", vec![1.0, 3.0, 5.0, 7.0], vec![400.0, 1100.0, 1450.0, 1200.0])
            .with_style(LineStyle::Points)
            .with_color(4),
    );
    chart.vlines.push(VLine::new(5.0, "ball leaves strings"));
    chart
}

fn log_chart() -> Chart {
    let ks: Vec<f64> = (0..40).map(|i| 10f64.powf(3.0 + f64::from(i) * 0.1)).collect();
    let e: Vec<f64> = ks.iter().map(|k| 0.9 - 0.3 / (1.0 + k / 1e5)).collect();
    let mut chart = Chart::new("COR vs string stiffness", "string stiffness ks (N/m)", "e");
    chart.x_log = true;
    chart.curves.push(Curve::new("rigid frame", ks.clone(), e.clone()).with_color(5));
    chart.curves.push(
        Curve::new("flexible frame", ks.clone(), e.iter().map(|v| v - 0.05).collect())
            .with_style(LineStyle::Dashed)
            .with_color(3),
    );
    chart.vlines.push(VLine::new(2e4, "typical strings"));
    chart.vlines.push(VLine::new(-5.0, "invisible on log axis"));
    chart
}

#[test]
fn renders_dual_axis_png_deterministically() {
    let dir = scratch();
    let chart = dual_axis_chart();
    let a = render_bytes(&chart, dir.path(), "dual.png");
    let b = render_bytes(&chart, dir.path(), "dual.png");
    assert_eq!(&a[..8], &PNG_SIGNATURE);
    assert!(a.len() > 10_000, "suspiciously small PNG: {} bytes", a.len());
    assert!(a == b, "rendering is not deterministic");
    assert_eq!(files_in(dir.path()), vec!["dual.png".to_string()]);
    if let Ok(keep) = std::env::var("RACKET_IMPACT_KEEP_TEST_PNG") {
        let _ = std::fs::copy(dir.path().join("dual.png"), Path::new(&keep).join("test_dual.png"));
    }
}

#[test]
fn renders_log_x_png() {
    let dir = scratch();
    let chart = log_chart();
    let a = render_bytes(&chart, dir.path(), "log.png");
    let b = render_bytes(&chart, dir.path(), "log2.png");
    assert_eq!(&a[..8], &PNG_SIGNATURE);
    assert!(a.len() > 10_000);
    assert!(a == b);
    if let Ok(keep) = std::env::var("RACKET_IMPACT_KEEP_TEST_PNG") {
        let _ = std::fs::copy(dir.path().join("log.png"), Path::new(&keep).join("test_log.png"));
    }
}

#[test]
fn log_x_with_right_axis_and_explicit_ranges() {
    let dir = scratch();
    let mut chart = log_chart();
    chart.y2_label = Some("ratio".to_string());
    chart.curves[1].axis = Axis::Right;
    chart.x_range = Some((1e3, 1e6));
    chart.y_range = Some((0.6, 0.8)); // narrower than the data: lines are clipped
    chart.y2_range = Some((0.0, 1.0));
    let a = render_bytes(&chart, dir.path(), "logdual.png");
    assert_eq!(&a[..8], &PNG_SIGNATURE);
}

#[test]
fn long_title_is_shrunk_to_fit() {
    assert!(fonts_registered());
    let mut buf = vec![0u8; (WIDTH * HEIGHT * 3) as usize];
    let root = BitMapBackend::with_buffer(&mut buf, (WIDTH, HEIGHT)).into_drawing_area();
    let short = title_font(&root, "Short").expect("font");
    let long_title = "A very long title that would not fit at thirty pixels in bold, \
                      so it has to be made smaller to fit the figure";
    let long = title_font(&root, long_title).expect("font");
    assert!(long.font.get_size() < short.font.get_size());
    let (w, _) = root.estimate_text_size(long_title, &long).expect("size");
    assert!(w <= WIDTH - 60);
}

#[test]
fn a_title_too_long_for_one_line_takes_two_before_it_shrinks() {
    assert!(fonts_registered());
    assert_eq!(title_layout("Short"), (vec!["Short".to_string()], TITLE_SIZE));
    let title = "Topspin forehand (racket 108 km/h, ball in 72 km/h, centre, 60 lb, mu 0.4): ball out at 184 km/h \
                 (0 deg path) to 150 km/h (40 deg)";
    let (lines, size) = title_layout(title);
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(size >= MIN_TITLE_SIZE, "{size}");
    // broken after the colon, each line fitting the width at that size
    assert!(lines[0].ends_with(':'), "{lines:?}");
    for l in &lines {
        let (w, _) = font(size, FontStyle::Bold).font.box_size(l).unwrap();
        assert!(w <= WIDTH - 60, "{l}: {w} px");
    }
    // and the figure draws
    let dir = scratch();
    let mut chart = log_chart();
    chart.title = title.to_string();
    assert_eq!(&render_bytes(&chart, dir.path(), "two.png")[..8], &PNG_SIGNATURE);
}

#[test]
fn different_charts_give_different_images() {
    let dir = scratch();
    let a = render_bytes(&log_chart(), dir.path(), "a.png");
    let mut other = log_chart();
    other.title = "Another title".to_string();
    let b = render_bytes(&other, dir.path(), "b.png");
    assert!(a != b);
}

#[test]
fn overwrites_existing_file() {
    let dir = scratch();
    let path = dir.path().join("fig.png");
    std::fs::write(&path, b"old").expect("write");
    render_png("t", &log_chart(), &path).expect("render");
    let bytes = std::fs::read(&path).expect("read");
    assert_eq!(&bytes[..8], &PNG_SIGNATURE);
}

#[test]
fn no_finite_points_is_an_error() {
    let dir = scratch();
    let path = dir.path().join("empty.png");
    let mut chart = Chart::new("t", "x", "y");
    chart.curves.push(Curve::new("nan", vec![f64::NAN, 1.0], vec![1.0, f64::INFINITY]));
    let err = render_png("fig0", &chart, &path).expect_err("must fail");
    assert!(matches!(err, Error::Plot { ref id, .. } if id == "fig0"), "{err}");
    assert!(files_in(dir.path()).is_empty());

    // No curves at all.
    let chart = Chart::new("t", "x", "y");
    assert!(render_png("fig0", &chart, &path).is_err());

    // Only non-positive x on a log axis.
    let mut chart = Chart::new("t", "x", "y");
    chart.x_log = true;
    chart.curves.push(Curve::new("c", vec![-1.0, 0.0], vec![1.0, 2.0]));
    assert!(render_png("fig0", &chart, &path).is_err());
    assert!(files_in(dir.path()).is_empty());
}

#[test]
fn bad_input_is_an_error_not_a_panic() {
    let dir = scratch();
    let path = dir.path().join("bad.png");
    let good = Curve::new("c", vec![1.0, 2.0], vec![1.0, 2.0]);

    let mut chart = Chart::new("t", "x", "y");
    chart.curves.push(Curve::new("c", vec![1.0, 2.0], vec![1.0]));
    let err = render_png("f", &chart, &path).expect_err("length mismatch");
    assert!(err.to_string().contains("x has 2 values but y has 1"), "{err}");

    for (xr, yr, log) in [
        (Some((2.0, 1.0)), None, false),
        (Some((1.0, 1.0)), None, false),
        (Some((f64::NAN, 1.0)), None, false),
        (Some((0.0, 10.0)), None, true),
        (None, Some((0.0, f64::INFINITY)), false),
    ] {
        let mut chart = Chart::new("t", "x", "y");
        chart.curves.push(good.clone());
        chart.x_range = xr;
        chart.y_range = yr;
        chart.x_log = log;
        assert!(render_png("f", &chart, &path).is_err(), "{xr:?} {yr:?} {log}");
    }

    // Missing directory.
    let mut chart = Chart::new("t", "x", "y");
    chart.curves.push(good);
    let missing = dir.path().join("nope").join("f.png");
    let err = render_png("f", &chart, &missing).expect_err("missing dir");
    assert!(matches!(err, Error::Plot { .. }));
    assert!(files_in(dir.path()).is_empty());
}

#[test]
fn degenerate_data_still_renders() {
    let dir = scratch();
    // One point, constant values, huge magnitudes.
    let mut chart = Chart::new("single", "x", "y");
    chart.curves.push(Curve::new("p", vec![3.0], vec![0.0]).with_style(LineStyle::Points));
    chart.curves.push(Curve::new("flat", vec![1.0, 2.0], vec![0.0, 0.0]).on_axis(Axis::Right));
    render_bytes(&chart, dir.path(), "single.png");

    let mut chart = Chart::new("huge", "x", "y");
    chart.curves.push(Curve::new("big", vec![0.0, 1e300], vec![-1e300, 1e300]));
    render_bytes(&chart, dir.path(), "huge.png");

    let mut chart = Chart::new("narrow log", "x", "y");
    chart.x_log = true;
    chart.curves.push(Curve::new("n", vec![2.0, 3.0, 8.0], vec![1.0, 2.0, 3.0]));
    render_bytes(&chart, dir.path(), "narrow.png");
}

#[test]
fn polylines_break_and_clip() {
    let b = Bounds::new((0.0, 10.0), (0.0, 10.0), false);
    // NaN in the middle splits the line.
    let xs = [1.0, 2.0, 3.0, 4.0, 5.0];
    let ys = [1.0, 2.0, f64::NAN, 4.0, 5.0];
    let p = b.polylines(&xs, &ys);
    assert_eq!(p, vec![vec![(1.0, 1.0), (2.0, 2.0)], vec![(4.0, 4.0), (5.0, 5.0)]]);
    // A segment leaving and re-entering the box is clipped into two pieces.
    let xs = [1.0, 5.0, 9.0];
    let ys = [5.0, 15.0, 5.0];
    let p = b.polylines(&xs, &ys);
    assert_eq!(p.len(), 2);
    assert_eq!(p[0][0], (1.0, 5.0));
    assert!((p[0][1].0 - 3.0).abs() < 1e-12 && (p[0][1].1 - 10.0).abs() < 1e-12);
    assert!((p[1][0].0 - 7.0).abs() < 1e-12 && (p[1][0].1 - 10.0).abs() < 1e-12);
    assert_eq!(p[1][1], (9.0, 5.0));
    // Fully outside: nothing.
    assert!(b.polylines(&[20.0, 30.0], &[1.0, 1.0]).is_empty());
    // Log axis: non-positive x breaks the line.
    let bl = Bounds::new((1.0, 1000.0), (0.0, 10.0), true);
    let p = bl.polylines(&[1.0, 10.0, 0.0, 100.0, 1000.0], &[1.0; 5]);
    assert_eq!(p, vec![vec![(1.0, 1.0), (10.0, 1.0)], vec![(100.0, 1.0), (1000.0, 1.0)]]);
    // Points outside are dropped.
    assert_eq!(b.points(&[1.0, 11.0, f64::NAN], &[1.0, 1.0, 1.0]), vec![(1.0, 1.0)]);
}

#[test]
fn tick_labels() {
    assert_eq!(tick_label(1400.0, (-75.0, 1575.0)), "1400");
    assert_eq!(tick_label(0.30000000000000004, (0.0, 1.0)), "0.3");
    assert_eq!(tick_label(1.1e-17, (-1.0, 1.0)), "0");
    assert_eq!(tick_label(-0.25, (-1.0, 1.0)), "-0.25");
    assert_eq!(tick_label(12345.62, (12345.5, 12345.7)), "12345.62");
    assert_eq!(tick_label(2e7, (0.0, 5e7)), "2e+07");
}

#[test]
fn ranges_from_data() {
    assert_eq!(pad_linear((0.0, 10.0)), (-0.5, 10.5));
    assert_eq!(pad_linear((0.0, 0.0)), (-1.0, 1.0));
    assert_eq!(pad_linear((5.0, 5.0)), (4.5, 5.5));
    let (a, b) = pad_log((10.0, 1000.0));
    assert!((a.log10() - 0.9).abs() < 1e-12 && (b.log10() - 3.1).abs() < 1e-12);
    // No power of ten inside: widened down to one.
    let (a, b) = pad_log((2.0, 8.0));
    assert_eq!(a, 1.0);
    assert!(b > 8.0 && b < 10.0);
    assert_eq!(tint(RGBColor(0, 0, 0), 0.6), RGBColor(153, 153, 153));
    assert_eq!(tint(RGBColor(255, 255, 255), 0.6), RGBColor(255, 255, 255));
}

#[test]
fn legend_goes_where_there_is_no_data() {
    let area = (100, 50, 1000, 650);
    let size = (300, 150);
    // nothing in the way: upper right
    assert_eq!(place_legend(area, size, &[]), (1000 - 12 - 300, 50 + 12));
    // data across the whole top (a curve near the upper edge): a lower corner
    let top: Vec<(i32, i32)> = (100..1000).map(|x| (x, 120)).collect();
    let (_, y) = place_legend(area, size, &top);
    assert_eq!(y, 650 - 12 - 150);
    // data in the upper right and across the bottom: upper left
    let mut pts: Vec<(i32, i32)> = (600..1000).flat_map(|x| [(x, 80), (x, 150)]).collect();
    pts.extend((100..1000).map(|x| (x, 600)));
    assert_eq!(place_legend(area, size, &pts), (100 + 12, 50 + 12));
    // whatever spot is chosen covers none of the points when one is free
    let (x, y) = place_legend(area, size, &pts);
    assert!(!pts.iter().any(|&(px, py)| px >= x && px <= x + 300 && py >= y && py <= y + 150));
}

#[test]
fn clipped_points_are_counted() {
    let mut chart = Chart::new("t", "x", "y");
    chart.curves.push(Curve::new("a", vec![0.0, 1.0, 2.0, 3.0], vec![0.5, -0.2, 0.5, f64::NAN]));
    assert_eq!(clipped_points(&chart), Ok(0), "ranges from the data hold every point");
    chart.y_range = Some((0.0, 1.0));
    assert_eq!(clipped_points(&chart), Ok(1), "-0.2 is below the axis");
    chart.x_range = Some((0.0, 1.5));
    assert_eq!(clipped_points(&chart), Ok(2), "x = 2 is beyond the x range");
    chart.y2_label = Some("right".into());
    chart.curves.push(Curve::new("b", vec![0.0, 1.0], vec![5.0, 50.0]).on_axis(Axis::Right));
    chart.y2_range = Some((0.0, 10.0));
    assert_eq!(clipped_points(&chart), Ok(3), "50 on the right axis");
    chart.y_range = Some((1.0, 0.0));
    assert!(clipped_points(&chart).is_err());
}

#[test]
fn paper_markers_and_bands_render_and_change_the_image() {
    let dir = scratch();
    let mut chart = dual_axis_chart();
    let plain = render_bytes(&chart, dir.path(), "plain.png");
    chart.bands.push(Band::new(0.0, 4.0, "string face"));
    let banded = render_bytes(&chart, dir.path(), "band.png");
    assert_ne!(plain, banded);
    chart.curves.push(Curve::new("paper: force", vec![5.0], vec![1500.0]).with_style(LineStyle::Paper));
    let with_paper = render_bytes(&chart, dir.path(), "paper.png");
    assert_ne!(banded, with_paper);
    assert_eq!(with_paper, render_bytes(&chart, dir.path(), "paper2.png"), "deterministic");
    // a band wholly outside the x range, and one reversed, draw without error
    chart.bands.push(Band::new(-50.0, -40.0, "outside"));
    chart.bands.push(Band::new(3.0, 1.0, "reversed"));
    render_bytes(&chart, dir.path(), "bands.png");
    // a chart that clips a curve still renders (with its note)
    chart.y_range = Some((0.0, 100.0));
    assert!(clipped_points(&chart).unwrap() > 0);
    render_bytes(&chart, dir.path(), "clipped.png");
}

#[test]
fn legend_fits_between_curves_when_no_corner_is_free() {
    let area = (100, 50, 1000, 650);
    // curves along the top and the bottom and a line down the middle: only a band between
    // y = 250 and 450 is free, at the right and the left
    let mut pts: Vec<(i32, i32)> = (100..1000).flat_map(|x| [(x, 240), (x, 460)]).collect();
    pts.extend((50..650).map(|y| (550, y)));
    let (x, y) = place_legend(area, (300, 150), &pts);
    assert!(!pts.iter().any(|&(px, py)| px >= x - 4 && px <= x + 304 && py >= y - 4 && py <= y + 154));
    assert_eq!(x, 1000 - 12 - 300, "the right side first");
}

/// WCAG contrast ratio of a colour against white.
fn contrast_on_white(c: RGBColor) -> f64 {
    let lin = |v: u8| {
        let s = f64::from(v) / 255.0;
        if s <= 0.04045 {
            s / 12.92
        } else {
            ((s + 0.055) / 1.055).powf(2.4)
        }
    };
    let l = 0.2126 * lin(c.0) + 0.7152 * lin(c.1) + 0.0722 * lin(c.2);
    1.05 / (l + 0.05)
}

#[test]
fn faint_curves_stay_readable_on_white() {
    // every palette colour that reads on white as a solid line (contrast >= 2) still does as a
    // faint one (>= 1.5; the old 60 % tint gave sky blue 1.37, the figures' near-invisible curves)
    for (i, _) in PALETTE.iter().enumerate() {
        let solid = palette(i);
        if contrast_on_white(solid) < 2.0 {
            continue;
        }
        let faint = tint(solid, super::draw::FAINT_TINT);
        assert!(contrast_on_white(faint) >= 1.5, "palette {i}: {}", contrast_on_white(faint));
    }
}

#[test]
fn named_ticks_replace_the_numbered_ones() {
    let dir = scratch();
    let mut chart = Chart::new("categories", "input", "index");
    chart.curves.push(Curve::new("total", vec![1.0, 2.0, 3.0], vec![0.2, 0.7, 0.1]).with_style(LineStyle::Points));
    chart.x_range = Some((0.5, 3.5));
    let numbered = render_bytes(&chart, dir.path(), "numbered.png");
    chart.x_ticks = vec![(1.0, "ks".into()), (2.0, "ei".into()), (3.0, "mass".into())];
    let named = render_bytes(&chart, dir.path(), "named.png");
    assert_ne!(numbered, named);
    assert_eq!(named, render_bytes(&chart, dir.path(), "named2.png"), "deterministic");
    // many long y names widen the label area; names outside the range are left out, no panic
    chart.y_ticks = (0..60).map(|k| (f64::from(k) / 60.0, format!("a_long_claim_identifier_{k}"))).collect();
    chart.y_ticks.push((5.0, "outside".into()));
    chart.y_ticks.push((f64::NAN, "nan".into()));
    assert_ne!(named, render_bytes(&chart, dir.path(), "both.png"));
}
