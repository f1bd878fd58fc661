//! The presets at their typical deliveries against TrackMan's 2023 PGA Tour averages
//! (`tests/data/trackman_tour_2023.csv`, a verbatim copy of `../shared/data/`): a driver,
//! woods, hybrid and irons a golfer would recognise. Dynamic lofts (except the driver's
//! published one) are the ones whose ball speed, launch and spin fit TrackMan's best together
//! (issue 11's cost, `carry_lab::bag::fitted_loft`, docs/impact.md §0.7), so all three are
//! checked, as means against issue 11's targets and row by row; the table prints with
//! `-- --nocapture`.

use carry_core::impact::{self, Solver};
use carry_core::presets::TYPICAL_CONVENTION;
use carry_core::units::{to_deg, to_mph, to_rpm};
use carry_core::{Ball, Preset};
use carry_tests::club_delivery::{Row, RowError};

/// Issue 11's targets on the mean |error| over the ten clubs: ball speed, launch (degrees),
/// spin.
const MEAN: (f64, f64, f64) = (0.02, 1.0, 0.10);
/// |launch − TrackMan| (degrees) of any club: the fitted lofts leave the woods and long irons
/// 0.9–1.4° high (the launch TrackMan's tour rows imply lies 0.7–0.9° below their measured
/// loft, docs/impact.md §0.7).
const LAUNCH_DEG: f64 = 1.5;
/// |ball speed / TrackMan − 1| of any club (PGA driver −3.3 %, irons up to +2.5 %).
const SPEED_REL: f64 = 0.035;
/// |spin / TrackMan − 1|: worst are the driver (+29 %) and the hybrid (−22 %, an estimated
/// head). Issue 11 held 25 %; the PGA 2023 driver average (2,545 rpm at 115 mph and 13.7° spin
/// loft) lies 26 % below TrackMan's own 2010 driver chart at the same speed and spin loft
/// (about 3,430 rpm between its 11.6° and 14.2° rows; the model: 3,281), and a strike high
/// enough to bring it within 25 % takes the chart's fast rows 10–15 % low
/// ([`the_driver_follows_trackmans_2010_driver_chart`], docs/impact.md §0.3).
const SPIN_REL: f64 = 0.30;
/// Mean |ball speed / chart − 1| on TrackMan's 2010 driver chart.
const CHART_SPEED_REL: f64 = 0.02;
/// Mean |launch − chart| (degrees).
const CHART_LAUNCH_DEG: f64 = 0.5;
/// Mean and worst |spin / chart − 1|.
const CHART_SPIN_REL: (f64, f64) = (0.06, 0.12);

#[test]
fn presets_reproduce_the_tour_averages() {
    let text = include_str!("../data/trackman_tour_2023.csv");
    let mut checked = 0;
    let mut mean = (0.0, 0.0, 0.0);
    for line in text.lines().skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        if f.first() != Some(&"PGA") {
            continue;
        }
        let Some(p) = f.get(1).and_then(|name| Preset::find(name)) else {
            continue; // 3-iron, 5-wood: no preset
        };
        let num = |i: usize| -> f64 { f[i].parse().unwrap_or(f64::NAN) };
        let (speed, launch, spin) = (num(4), num(6), num(7));
        let Ok(club) = p.spec::<f64>().validate() else {
            panic!("{}", p.name)
        };
        let t = p.typical;
        let d = t.delivery::<f64>();
        assert!(
            (to_mph(t.club_speed_mps) - num(2)).abs() < 1e-9,
            "{}",
            p.name
        );
        let Ok(o) = d
            .strike_in(&club, TYPICAL_CONVENTION)
            .and_then(|s| impact::solve(&club, &Ball::standard(), &s, Solver::Reduced))
        else {
            panic!("{}", p.name)
        };
        let l = o.launch;
        let (s, la, sp) = (
            to_mph(l.ball_speed_mps),
            to_deg(l.launch_angle_rad),
            to_rpm(l.spin_radps),
        );
        println!(
            "{:<7} ball {s:6.1}/{speed} mph  launch {la:5.1}/{launch}°  spin {sp:5.0}/{spin} rpm ({:+.0} %)",
            p.name,
            (sp / spin - 1.0) * 100.0
        );
        assert!((la - launch).abs() <= LAUNCH_DEG, "{}: launch {la}", p.name);
        assert!(
            (s / speed - 1.0).abs() <= SPEED_REL,
            "{}: ball speed {s}",
            p.name
        );
        assert!((sp / spin - 1.0).abs() <= SPIN_REL, "{}: spin {sp}", p.name);
        mean.0 += (s / speed - 1.0).abs() / 10.0;
        mean.1 += (la - launch).abs() / 10.0;
        mean.2 += (sp / spin - 1.0).abs() / 10.0;
        checked += 1;
    }
    assert_eq!(checked, 10, "driver, 3wood, hybrid, 4-9 iron, pw");
    println!(
        "mean |err|: ball speed {:.2} %, launch {:.2}°, spin {:.1} %",
        mean.0 * 100.0,
        mean.1,
        mean.2 * 100.0
    );
    assert!(
        mean.0 <= MEAN.0 && mean.1 <= MEAN.1 && mean.2 <= MEAN.2,
        "{mean:?}"
    );
}

/// The `driver` preset, struck where its typical delivery says, against TrackMan's 2010 driver
/// chart (`tests/data/trackman_driver_optimizer_2010.csv`, 30 deliveries at 75–120 mph and
/// attack −5°, 0°, +5°, with their dynamic lofts): TrackMan's own model of centred drives,
/// a check of the driver's spin over speed and spin loft. Not fitted to, but a bound of the
/// fit: the contact law's calibration keeps these bounds (docs/impact.md §0.6; the
/// unconstrained fit takes the slow, steep rows to +15 %). Prints the table with
/// `-- --nocapture`.
#[test]
fn the_driver_follows_trackmans_2010_driver_chart() {
    let text = include_str!("../data/trackman_driver_optimizer_2010.csv");
    let (mut speed, mut launch, mut spin, mut worst, mut n) = (0.0, 0.0, 0.0, 0.0_f64, 0.0);
    for line in text.lines().skip(1) {
        let f: Vec<f64> = line
            .split(',')
            .map(|x| x.parse().unwrap_or(f64::NAN))
            .collect();
        let row = Row {
            source: "TrackMan 2010 driver chart".into(),
            who: "chart".into(),
            club: "driver".into(),
            club_speed_mph: f[0],
            attack_deg: f[1],
            dynamic_loft_deg: f[7],
            ball_speed_mph: f[2],
            launch_deg: f[3],
            spin_rpm: f[4],
        };
        let Ok(p) = row.predict_with(&row.preset().spec()) else {
            panic!("{line}")
        };
        let e = RowError::of(&row, &p);
        println!(
            "{:>3} mph {:+} deg loft {:4.1}: ball {:+.1} %, launch {:+.2}, spin {:.0}/{} rpm ({:+.1} %)",
            f[0],
            f[1],
            f[7],
            e.speed_rel * 100.0,
            e.launch_deg,
            p.spin_rpm,
            f[4],
            e.spin_rel * 100.0
        );
        speed += e.speed_rel.abs();
        launch += e.launch_deg.abs();
        spin += e.spin_rel.abs();
        worst = worst.max(e.spin_rel.abs());
        n += 1.0;
    }
    let (speed, launch, spin) = (speed / n, launch / n, spin / n);
    println!(
        "mean |err|: ball speed {:.1} %, launch {launch:.2}°, spin {:.1} % (worst {:.1} %)",
        speed * 100.0,
        spin * 100.0,
        worst * 100.0
    );
    assert!(n > 29.0, "30 rows");
    assert!(speed <= CHART_SPEED_REL, "{speed}");
    assert!(launch <= CHART_LAUNCH_DEG, "{launch}");
    assert!(
        spin <= CHART_SPIN_REL.0 && worst <= CHART_SPIN_REL.1,
        "{spin} {worst}"
    );
}
