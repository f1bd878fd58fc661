//! The presets at their typical deliveries against TrackMan's 2023 PGA Tour averages
//! (`tests/data/trackman_tour_2023.csv`, a verbatim copy of `../shared/data/`): a driver,
//! woods, hybrid and irons a golfer would recognise. Dynamic lofts (except the driver's
//! published one) were chosen so that launch matches, so the informative checks are ball
//! speed and spin; the table prints with `-- --nocapture`.

use carry_core::impact::{self, Solver};
use carry_core::presets::TYPICAL_CONVENTION;
use carry_core::units::{to_deg, to_mph, to_rpm};
use carry_core::{Ball, Preset};

/// |launch − TrackMan| (degrees): the driver's published dynamic loft is not tuned to it.
const LAUNCH_DEG: f64 = 0.6;
/// |ball speed / TrackMan − 1|: the iron COR estimates run high by up to 4 %.
const SPEED_REL: f64 = 0.045;
/// |spin / TrackMan − 1|: worst are the driver (+28 %: the strike height serves the amateur
/// rows of `club_delivery.csv` too, docs/impact.md) and the hybrid (−23 %, an estimated head).
const SPIN_REL: f64 = 0.30;

#[test]
fn presets_reproduce_the_tour_averages() {
    let text = include_str!("../data/trackman_tour_2023.csv");
    let mut checked = 0;
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
        checked += 1;
    }
    assert_eq!(checked, 10, "driver, 3wood, hybrid, 4-9 iron, pw");
}
