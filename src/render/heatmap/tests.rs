//! Tests of the heat maps: contours, levels, sampling, colour maps, degenerate and bad input.

use super::draw::{level_label, plot_geometry};
use super::*;

fn grid(nx: usize, ny: usize, f: impl Fn(f64, f64) -> f64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let xs: Vec<f64> = (0..nx).map(|i| i as f64).collect();
    let ys: Vec<f64> = (0..ny).map(|j| j as f64).collect();
    let z = xs.iter().flat_map(|&x| ys.iter().map(move |&y| (x, y))).map(|(x, y)| f(x, y)).collect();
    (xs, ys, z)
}

#[test]
fn linear_field_gives_straight_contours_at_the_level() {
    // z = x: the contour z = 1.5 is the vertical line x = 1.5
    let (xs, ys, z) = grid(4, 5, |x, _| x);
    let segs = contour_segments(&xs, &ys, &z, 1.5);
    assert_eq!(segs.len(), 4, "one segment per cell row");
    for s in &segs {
        assert_eq!((s[0].0, s[1].0), (1.5, 1.5));
        assert_eq!((s[0].1 - s[1].1).abs(), 1.0);
    }
    // z = 2x + y: the contour z = 3 is the line y = 3 - 2x; every segment lies on it
    let (xs, ys, z) = grid(5, 5, |x, y| 2.0 * x + y);
    let segs = contour_segments(&xs, &ys, &z, 3.0);
    assert!(!segs.is_empty());
    for s in &segs {
        for p in s {
            assert!((p.1 - (3.0 - 2.0 * p.0)).abs() < 1e-12, "{p:?}");
        }
    }
    // total length: the line from (0, 3) to (1.5, 0) inside the grid
    let len: f64 = segs.iter().map(|s| ((s[1].0 - s[0].0).powi(2) + (s[1].1 - s[0].1).powi(2)).sqrt()).sum();
    assert!((len - (1.5f64.powi(2) + 9.0).sqrt()).abs() < 1e-12, "{len}");
}

#[test]
fn contours_skip_missing_cells_and_constant_fields() {
    let (xs, ys, mut z) = grid(3, 3, |x, _| x);
    z[4] = f64::NAN; // the centre point: every cell touches it
    assert!(contour_segments(&xs, &ys, &z, 0.5).is_empty());
    let (xs, ys, z) = grid(3, 3, |_, _| 2.0);
    assert!(contour_segments(&xs, &ys, &z, 2.0).is_empty());
    assert!(contour_segments(&[0.0], &[0.0], &[1.0], 0.5).is_empty());
}

#[test]
fn saddles_give_two_segments() {
    // corners 1 0 / 0 1 around a cell
    let xs = [0.0, 1.0];
    let ys = [0.0, 1.0];
    let z = [1.0, 0.0, 0.0, 1.0]; // (0,0)=1, (0,1)=0, (1,0)=0, (1,1)=1
    assert_eq!(contour_segments(&xs, &ys, &z, 0.5).len(), 2);
}

#[test]
fn levels_are_round_and_inside() {
    let (l, step) = contour_levels(0.112, 0.418, 8);
    assert_eq!(step, 0.05);
    assert_eq!(l.len(), 6);
    assert!((l[0] - 0.15).abs() < 1e-12 && (l[5] - 0.4).abs() < 1e-12);
    let (l, _) = contour_levels(-2.3, 1.1, 8);
    assert!(l.contains(&0.0));
    assert!(contour_levels(1.0, 1.0, 8).0.is_empty());
    assert!(contour_levels(f64::NAN, 1.0, 8).0.is_empty());
    assert_eq!(level_label(0.15000000000000002, 0.05), "0.15");
    assert_eq!(level_label(-0.0, 0.25), "0.00");
    assert_eq!(level_label(40.0, 5.0), "40");
}

#[test]
fn sampling_is_bilinear_inside_and_nearest_at_the_edge() {
    let (xs, ys, mut z) = grid(3, 3, |x, y| x + 10.0 * y);
    assert!((sample(&xs, &ys, &z, 0.5, 0.25).unwrap() - 3.0).abs() < 1e-12);
    assert_eq!(sample(&xs, &ys, &z, 2.0, 2.0), Some(22.0));
    assert_eq!(sample(&xs, &ys, &z, -0.1, 0.0), None);
    z[0] = f64::NAN;
    // cell (0,0) now has three corners: the nearest one
    assert_eq!(sample(&xs, &ys, &z, 0.2, 0.9), Some(10.0));
    assert_eq!(sample(&xs, &ys, &z, 0.9, 0.1), Some(1.0));
}

#[test]
fn colour_maps_run_from_end_to_end() {
    assert_eq!(viridis(0.0), RGBColor(68, 1, 84));
    assert_eq!(viridis(1.0), RGBColor(253, 231, 37));
    assert_eq!(viridis(2.0), viridis(1.0));
    assert_eq!(diverging(0.5), RGBColor(247, 247, 247));
    let ((lo, hi), _) = color_range(&[-1.0, 3.0, f64::NAN], ColorScale::Diverging);
    assert_eq!((lo, hi), (-3.0, 3.0));
    let ((lo, hi), d) = color_range(&[f64::NAN], ColorScale::Sequential);
    assert_eq!(((lo, hi), d), ((0.0, 1.0), None));
    let ((lo, hi), _) = color_range(&[5.0, 5.0], ColorScale::Sequential);
    assert!(lo < 5.0 && hi > 5.0);
}

fn face_map(nx: usize, ny: usize, f: impl Fn(f64, f64) -> f64) -> HeatMap {
    let e = Ellipse { x0: 0.0, x1: 32.0, half_height: 12.5 };
    let xs: Vec<f64> = (0..nx).map(|i| 32.0 * i as f64 / (nx - 1).max(1) as f64).collect();
    let ys: Vec<f64> = (0..ny).map(|j| -12.5 + 25.0 * j as f64 / (ny - 1).max(1) as f64).collect();
    let z = xs
        .iter()
        .flat_map(|&x| ys.iter().map(move |&y| (x, y)))
        .map(|(x, y)| if e.contains(x, y) { f(x, y) } else { f64::NAN })
        .collect();
    HeatMap {
        title: "test map".into(),
        subtitle: "a subtitle".into(),
        x_label: "x (cm)".into(),
        y_label: "r (cm)".into(),
        bar_label: "e_A".into(),
        xs,
        ys,
        z,
        clip: vec![e],
        outlines: vec![e],
        segments: vec![Segment { from: (16.0, -12.5), to: (16.0, 12.5), label: "node".into() }],
        markers: vec![Marker { at: (30.0, 0.0), label: "max".into() }],
        ..HeatMap::default()
    }
}

#[test]
fn degenerate_maps_render_without_panic_and_deterministically() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        face_map(25, 13, |x, y| 0.3 + 0.01 * x - 0.001 * y * y),
        face_map(25, 13, |_, _| f64::NAN),
        face_map(25, 13, |_, _| 0.4),
        face_map(2, 2, |x, _| x),
        face_map(1, 1, |x, _| x),
        HeatMap::default(),
    ];
    for (k, m) in cases.iter().enumerate() {
        let a = dir.path().join(format!("m{k}.png"));
        let b = dir.path().join(format!("m{k}b.png"));
        render_png("t", m, &a).unwrap_or_else(|e| panic!("case {k}: {e}"));
        render_png("t", m, &b).unwrap();
        let (a, b) = (std::fs::read(a).unwrap(), std::fs::read(b).unwrap());
        assert_eq!(&a[1..4], b"PNG");
        assert!(a == b, "case {k} not deterministic");
    }
    let mut diff = face_map(9, 7, |x, y| x - 16.0 + y);
    diff.scale = ColorScale::Diverging;
    render_png("t", &diff, &dir.path().join("d.png")).unwrap();
    if let Ok(keep) = std::env::var("RACKET_IMPACT_KEEP_TEST_PNG") {
        for f in ["m0.png", "m1.png", "m2.png", "m3.png", "d.png"] {
            let _ = std::fs::copy(dir.path().join(f), Path::new(&keep).join(format!("heatmap_{f}")));
        }
    }
}

#[test]
fn bad_grids_are_errors() {
    let dir = tempfile::tempdir().unwrap();
    let mut m = face_map(5, 5, |x, _| x);
    m.z.pop();
    assert!(render_png("t", &m, &dir.path().join("a.png")).is_err());
    let mut m = face_map(5, 5, |x, _| x);
    m.xs[2] = m.xs[1];
    assert!(render_png("t", &m, &dir.path().join("a.png")).is_err());
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn sampling_colours_only_the_half_cell_around_a_computed_point() {
    let (xs, ys, mut z) = grid(3, 3, |x, y| x + y);
    for (k, v) in z.iter_mut().enumerate() {
        if k != 0 {
            *v = f64::NAN; // only (0, 0) computed
        }
    }
    assert_eq!(sample(&xs, &ys, &z, 0.4, 0.4), Some(0.0));
    assert_eq!(sample(&xs, &ys, &z, 0.6, 0.4), None, "nearer a point that was not computed");
    assert_eq!(sample(&xs, &ys, &z, 0.4, 0.6), None);
    assert_eq!(sample(&xs, &ys, &z, 1.5, 1.5), None);
}

#[test]
fn diverging_scale_only_for_data_of_both_signs() {
    assert_eq!(ColorScale::for_values(&[-2.5, -0.7, f64::NAN]), ColorScale::Sequential);
    assert_eq!(ColorScale::for_values(&[0.1, 0.4]), ColorScale::Sequential);
    assert_eq!(ColorScale::for_values(&[-0.2, 0.0, 0.0]), ColorScale::Sequential);
    assert_eq!(ColorScale::for_values(&[-0.2, 0.3]), ColorScale::Diverging);
    assert_eq!(ColorScale::for_values(&[f64::NAN]), ColorScale::Sequential);
    // an all-negative field then spans the whole colour map, not half of one centred on 0
    let ((lo, hi), _) = color_range(&[-2.5, -0.7], ColorScale::for_values(&[-2.5, -0.7]));
    assert_eq!((lo, hi), (-2.5, -0.7));
}

/// The pixels of a drawn map, row-major RGB.
fn draw_to_buffer(map: &HeatMap) -> Vec<u8> {
    assert!(plot::fonts_registered());
    let mut buf = vec![0u8; (WIDTH * HEIGHT * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (WIDTH, HEIGHT)).into_drawing_area();
        root.fill(&WHITE).unwrap();
        super::draw::draw(&root, map).unwrap();
        root.present().unwrap();
    }
    buf
}

#[test]
fn map_pixels_away_from_computed_points_stay_background() {
    // an 11 x 11 grid over 0..10 with only the columns x = 0 and 1 computed
    let (xs, ys, mut z) = grid(11, 11, |x, y| x + 0.1 * y);
    for (k, v) in z.iter_mut().enumerate() {
        if k / 11 > 1 {
            *v = f64::NAN;
        }
    }
    let map = HeatMap { title: "partial".into(), xs, ys, z, ..HeatMap::default() };
    let buf = draw_to_buffer(&map);
    let ((l, t, r, b), ((x0, x1), (y0, y1))) = plot_geometry(&map);
    let px = |x: f64| l + ((x - x0) / (x1 - x0) * f64::from(r - l)).round() as i32;
    let py = |y: f64| b - ((y - y0) / (y1 - y0) * f64::from(b - t)).round() as i32;
    let rgb = |x: i32, y: i32| {
        let k = ((y as u32 * WIDTH + x as u32) * 3) as usize;
        (buf[k], buf[k + 1], buf[k + 2])
    };
    let white = (255, 255, 255);
    // right of x = 1.5 (half a step beyond the last computed column): nothing coloured
    let mut coloured = 0;
    for y in py(9.5)..=py(0.5) {
        for x in px(1.5) + 3..=px(9.5) {
            coloured += usize::from(rgb(x, y) != white);
        }
    }
    assert_eq!(coloured, 0, "pixels coloured where no point was computed");
    // and the computed strip is coloured
    assert_ne!(rgb(px(0.7), py(5.0)), white);
}

#[test]
fn the_rim_is_filled_from_the_data_and_the_data_kept() {
    // 5 x 5 with only the centre computed: one ring gets it, the corners need a second ring
    let mut z = vec![f64::NAN; 25];
    z[2 * 5 + 2] = 3.0;
    let one = fill_rim(5, 5, &z, 1);
    assert_eq!(one[2 * 5 + 2], 3.0);
    for k in [5 + 2, 3 * 5 + 2, 2 * 5 + 1, 2 * 5 + 3] {
        assert_eq!(one[k], 3.0, "{k}");
    }
    assert!(one[5 + 1].is_nan() && one[0].is_nan());
    let two = fill_rim(5, 5, &z, 2);
    assert_eq!(two[5 + 1], 3.0);
    assert!(two[0].is_nan(), "three steps away");
    // a missing point between two values takes their mean; computed points never change
    let (_, _, mut lin) = grid(3, 1, |x, _| x);
    lin[1] = f64::NAN;
    let filled = fill_rim(3, 1, &lin, 1);
    assert_eq!(filled, vec![0.0, 1.0, 2.0]);
}

/// Pixel colour of a drawn map at (x, y) in data units.
fn pixel(map: &HeatMap, buf: &[u8], (x, y): (f64, f64)) -> (u8, u8, u8) {
    let ((l, t, r, b), ((x0, x1), (y0, y1))) = plot_geometry(map);
    let px = l + ((x - x0) / (x1 - x0) * f64::from(r - l)).round() as i32;
    let py = b - ((y - y0) / (y1 - y0) * f64::from(b - t)).round() as i32;
    let k = ((py as u32 * WIDTH + px as u32) * 3) as usize;
    (buf[k], buf[k + 1], buf[k + 2])
}

#[test]
fn clipped_maps_are_shaded_up_to_their_outline() {
    // the face sampled inside its outline only, as the string-face maps are
    let map = face_map(41, 21, |x, y| x + 0.3 * y);
    let buf = draw_to_buffer(&map);
    let e = map.clip[0];
    let (c, a) = (0.5 * (e.x0 + e.x1), 0.5 * (e.x1 - e.x0));
    let mut white = Vec::new();
    for k in 0..360 {
        let t = f64::from(k).to_radians();
        // 96 % of the way out: inside the outline, beyond the last computed points of many cells
        let p = (c + 0.96 * a * t.cos(), 0.96 * e.half_height * t.sin());
        if pixel(&map, &buf, p) == (255, 255, 255) {
            white.push(k);
        }
    }
    assert!(white.is_empty(), "unshaded just inside the outline at angles {white:?}");
}

#[test]
fn values_below_the_floor_are_grey_and_the_colour_scale_starts_at_it() {
    let mut map = face_map(41, 21, |x, _| x - 8.0);
    map.floor = Some(0.0);
    let buf = draw_to_buffer(&map);
    let grey = BELOW_FLOOR;
    assert_eq!(pixel(&map, &buf, (4.0, 0.0)), grey, "below the floor");
    assert_ne!(pixel(&map, &buf, (20.0, 0.0)), grey);
    // just above the floor the colour is the bottom of the colour map
    let v = viridis(0.0);
    let (r, g, b) = pixel(&map, &buf, (8.3, 0.0));
    assert!((i32::from(r) - i32::from(v.0)).abs() < 30 && (i32::from(b) - i32::from(v.2)).abs() < 30, "{r} {g} {b}");
    // without a floor the same map has no grey
    map.floor = None;
    let buf = draw_to_buffer(&map);
    assert_ne!(pixel(&map, &buf, (4.0, 0.0)), grey);
}

#[test]
fn points_the_mask_greys_are_grey_whatever_their_value_and_left_out_of_the_scale() {
    // a value that grows towards the tip (as a rebound angle does), greyed where x < 8
    let mut map = face_map(41, 21, |x, _| 100.0 - x);
    map.grey_below_zero = map.xs.iter().flat_map(|&x| map.ys.iter().map(move |_| x - 8.0)).collect();
    let buf = draw_to_buffer(&map);
    assert_eq!(pixel(&map, &buf, (4.0, 0.0)), BELOW_FLOOR, "masked");
    assert_ne!(pixel(&map, &buf, (20.0, 0.0)), BELOW_FLOOR);
    // the scale ends at the largest value shown (92 at x = 8): just right of the mask, the top
    let v = viridis(1.0);
    let (r, g, b) = pixel(&map, &buf, (8.5, 0.0));
    assert!((i32::from(r) - i32::from(v.0)).abs() < 30 && (i32::from(g) - i32::from(v.1)).abs() < 30, "{r} {g} {b}");
    assert!(map.shown_values().iter().zip(&map.grey_below_zero).all(|(v, g)| *g >= 0.0 || v.is_nan()));
    map.grey_below_zero.clear();
    let buf = draw_to_buffer(&map);
    assert_ne!(pixel(&map, &buf, (4.0, 0.0)), BELOW_FLOOR, "no mask, no grey");
}
