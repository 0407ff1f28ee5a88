//! Figures a reader can read (issue 24, class 8), and figures that say what they show (class
//! 5): the oblique and swing figures' axes fit their data, the tension figure's eight curves
//! need four legend entries and sit apart, the swing figure speaks the `speed` command's km/h,
//! oblique figures name their incidence, azimuth, spin and friction, and a figure made for
//! another racket names it and leaves out the paper's values.

use racket_impact::experiments::{self, fit_range, Context};
use racket_impact::render::plot::{clipped_points, Axis, Chart, LineStyle};

fn chart(id: &str, ctx: &Context) -> (Chart, racket_impact::render::table::Table) {
    let exp = experiments::find(id).unwrap();
    let table = (exp.run)(ctx).unwrap();
    ((exp.chart)(ctx, &table), table)
}

/// Smallest and largest y of the curves on one axis.
fn extent(c: &Chart, right: bool) -> (f64, f64) {
    c.curves
        .iter()
        .filter(|k| (c.y2_label.is_some() && k.axis == Axis::Right) == right)
        .flat_map(|k| k.y.iter().copied())
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| (l.min(v), h.max(v)))
}

#[test]
fn oblique_and_swing_axes_fit_their_data() {
    let ctx = Context::paper();
    for id in ["oblique_angle", "topspin_forehand"] {
        let (c, _) = chart(id, &ctx);
        assert_eq!(clipped_points(&c).unwrap(), 0, "{id} cuts a curve off");
        for (right, range) in [(false, c.y_range), (true, c.y2_range)] {
            let (lo, hi) = extent(&c, right);
            let (a, b) = range.unwrap_or_else(|| panic!("{id}: ranges are fitted, not left to padding"));
            // from zero (all these quantities start there) to at most a round step past the data
            assert!(a <= lo && b >= hi, "{id} right {right}: {a}..{b} for {lo}..{hi}");
            assert!(b - a <= 1.35 * (hi - a.max(0.0).min(lo)), "{id} right {right}: {a}..{b} for {lo}..{hi}");
        }
    }
    // oblique_angle's left axis no longer runs to 150 for data under 80
    let (c, _) = chart("oblique_angle", &ctx);
    assert!(c.y_range.unwrap().1 <= 100.0, "{:?}", c.y_range);
}

/// The spin table's figure (issue 36, item 8): its y axis starts near its lowest point, not at
/// -1000 rpm under data that starts above 1000, and its points keep to the lower part of the
/// axis, the upper part left to the legend, which then covers none of them.
#[test]
fn the_spin_table_figure_fits_its_points_under_its_legend() {
    let (c, _) = chart("validation_spin", &Context::paper());
    assert_eq!(clipped_points(&c).unwrap(), 0);
    // the points (the dashed line model = measured is a reference, not data)
    let mut points = c.clone();
    points.curves.retain(|k| k.style != LineStyle::Dashed);
    let (lo, hi) = extent(&points, false);
    let (a, b) = c.y_range.unwrap();
    assert!(a >= 0.0 && a <= lo && lo - a <= 0.1 * (hi - lo), "{a}..{b} for {lo}..{hi}");
    assert!(hi <= a + 0.56 * (b - a), "points reach {hi} of {a}..{b}: the legend's part");
}

#[test]
fn the_tension_figure_stacks_its_curves_under_four_legend_entries() {
    let (c, _) = chart("oblique_tension", &Context::paper());
    assert_eq!(clipped_points(&c).unwrap(), 0);
    let legend: Vec<&str> = c.curves.iter().map(|k| k.label.as_str()).filter(|l| !l.is_empty()).collect();
    assert_eq!(legend.len(), 4, "{legend:?}");
    // spin in the upper half of its axis, rebound angle in the lower half of its own
    let ((s0, s1), (a0, a1)) = (c.y_range.unwrap(), c.y2_range.unwrap());
    let (slo, shi) = extent(&c, false);
    let (alo, ahi) = extent(&c, true);
    assert!(slo > 0.5 * (s0 + s1) && shi <= s1, "spin {slo}..{shi} on {s0}..{s1}");
    assert!(ahi < 0.5 * (a0 + a1) && alo >= a0, "angle {alo}..{ahi} on {a0}..{a1}");
    // neither axis runs far past its curves: each set fills at least 35 % of its axis
    assert!((shi - slo) / (s1 - s0) > 0.35 * 0.5 && (ahi - alo) / (a1 - a0) > 0.35 * 0.5);
}

#[test]
fn oblique_figures_name_their_incidence_spin_and_friction() {
    let ctx = Context::paper();
    let (c, _) = chart("oblique_angle", &ctx);
    for needle in ["azimuth 90 deg", "no incoming spin", "mu 0.4", "30 m/s"] {
        assert!(c.title.contains(needle), "{}", c.title);
    }
    let (c, _) = chart("oblique_tension", &ctx);
    for needle in ["azimuth 90 deg", "no spin in", "30 m/s"] {
        assert!(c.title.contains(needle), "{}", c.title);
    }
    // the two friction laws (solid and dashed) are named in the title (issue 40: the legend
    // names each curve's quantity and angle instead)
    assert!(c.title.contains("solid mu 0.4") && c.title.contains("dashed mu 0.4 T / 60 lb"), "{}", c.title);
    // the tangential stiffness the impacts ran with (the default, calibrated)
    let kt = racket_impact::numfmt::sig(racket_impact::params::Oblique::default().kt, 3);
    assert!(c.x_label.contains(&format!("kt {kt} N/m")), "{}", c.x_label);
    let (c, _) = chart("topspin_forehand", &ctx);
    assert!(c.title.contains("mu 0.4") && c.y2_label.as_deref().unwrap().contains("court"), "{c:?}");
}

#[test]
fn the_swing_figure_speaks_the_speed_commands_km_per_h() {
    // the angles have their own axis; the ball speed, in km/h, is told in the title (its ends)
    let (c, t) = chart("topspin_forehand", &Context::paper());
    assert!(c.title.contains("108 km/h") && !c.y_label.contains("km/h"), "{c:?}");
    let speeds = t.column("ball_speed_m_per_s").unwrap();
    for si in [speeds[0], speeds[speeds.len() - 1]] {
        assert!(c.title.contains(&format!("{:.0} km/h", 3.6 * si)), "{}", c.title);
    }
}

#[test]
fn figures_for_another_racket_name_it_and_leave_out_the_papers_values() {
    let paper = Context::paper();
    let fitted = racketfit("tweener");
    let ctx = Context::with_racket(fitted.racket, fitted.ball).named("tweener");
    let mut checked = 0;
    for exp in experiments::registry() {
        if !matches!(exp.id, "fig4_energy" | "fig7_off_axis_x10" | "speeds" | "fig6_string_stiffness") {
            continue;
        }
        let table = (exp.run)(&paper).unwrap();
        let on_paper = paper.adapt((exp.chart)(&paper, &table));
        assert!(on_paper.curves.iter().any(|c| c.style == LineStyle::Paper || c.label.starts_with("paper")));
        let own = ctx.adapt((exp.chart)(&ctx, &(exp.run)(&ctx).unwrap()));
        assert!(
            own.curves.iter().all(|c| c.style != LineStyle::Paper && !c.label.starts_with("paper")),
            "{}: {:?}",
            exp.id,
            own.curves.iter().map(|c| &c.label).collect::<Vec<_>>()
        );
        assert!(own.title.contains("racket: tweener"), "{}", own.title);
        checked += 1;
    }
    assert_eq!(checked, 4);
}

fn racketfit(name: &str) -> racket_impact::racket::Fitted {
    racket_impact::racket::load(name).unwrap().to_racket(39).unwrap()
}

#[test]
fn fitted_ranges_hold_their_data_within_a_round_step() {
    assert_eq!(fit_range([0.0, 78.0], true), Some((0.0, 100.0)));
    assert_eq!(fit_range([3200.0, 5600.0], false), Some((3000.0, 6000.0)));
    assert_eq!(fit_range([f64::NAN], true), None);
    let (a, b) = fit_range([-10.5, 47.9], true).unwrap();
    assert!((-25.0..=-10.5).contains(&a) && (47.9..=60.0).contains(&b), "{a} {b}");
}
