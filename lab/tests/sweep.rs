//! The swing sweep: the example swing model, derived rates, contact search and errors.

use carry_core::presets::REFERENCE_DRIVER;
use carry_lab::sweep::generate::SwingModel;
use carry_lab::sweep::{Motion, positions, sweep};
use carry_lab::{Error, Input, Setup};

/// Central differences at 0.2 ms against the model's exact velocity (m/s): the error is
/// O(h²·|jerk|) ≈ 1e-3 m/s for a head at 45 m/s on a ~1.7 m radius.
const VELOCITY_TOLERANCE_MPS: f64 = 0.02;
/// The same for the angular velocity (rad/s).
const SPIN_TOLERANCE_RADPS: f64 = 0.05;

fn setup() -> Setup<f64> {
    // the club `carry sweep` uses when none is named (the shipped example is generated for it)
    match Setup::standard(&REFERENCE_DRIVER, 45.0) {
        Ok(s) => s,
        Err(e) => panic!("{e}"),
    }
}

fn example(s: &Setup<f64>) -> Motion {
    let m = SwingModel::default();
    match m.generate(
        &s.club.face_rotation().clone(),
        s.club.cg_to_face_m(),
        s.ball.radius_m(),
    ) {
        Ok(m) => m,
        Err(e) => panic!("{e}"),
    }
}

#[test]
fn derived_rates_match_the_model() {
    let s = setup();
    let exact = example(&s);
    let csv = exact.to_csv(false, "test");
    let Ok(derived) = Motion::from_csv(csv.as_bytes(), s.club.loft_rad()) else {
        panic!()
    };
    assert_eq!(derived.samples().len(), exact.samples().len());
    // Interior samples (the ends are one-sided).
    let n = exact.samples().len();
    for (a, b) in exact.samples()[1..n - 1]
        .iter()
        .zip(&derived.samples()[1..n - 1])
    {
        assert!(
            (a.velocity_mps - b.velocity_mps).norm() < VELOCITY_TOLERANCE_MPS,
            "{} vs {}",
            a.velocity_mps,
            b.velocity_mps
        );
        assert!(
            (a.spin_radps - b.spin_radps).norm() < SPIN_TOLERANCE_RADPS,
            "{} vs {}",
            a.spin_radps,
            b.spin_radps
        );
    }
    let speed = exact.samples()[n / 2].velocity_mps.norm();
    println!("head speed at the low point {speed:.2} m/s");
    assert!((35.0..55.0).contains(&speed), "{speed}");
}

#[test]
fn sweep_finds_contacts_and_a_best_position() {
    let s = setup();
    let motion = example(&s);
    let Ok(xs) = positions(-0.1, 0.1, 0.01) else {
        panic!()
    };
    let Ok(result) = sweep(&s, &motion, &xs) else {
        panic!()
    };
    assert_eq!(result.rows.len(), 21);
    // Contact times increase with the ball position; the attack angle rises through the
    // low point (descending before it, ascending after).
    for w in result.rows.windows(2) {
        assert!(w[1].club.impact_time_s > w[0].club.impact_time_s);
        assert!(w[1].club.attack_angle_deg > w[0].club.attack_angle_deg);
    }
    let first = &result.rows[0].club;
    let last = &result.rows[20].club;
    assert!(first.attack_angle_deg < 0.0 && last.attack_angle_deg > 0.0);
    // Before the low point the path is in-to-out (+), after it out-to-in (−).
    assert!(first.club_path_deg > 0.0 && last.club_path_deg < 0.0);
    let Some(best) = result.best_row() else {
        panic!()
    };
    for r in &result.rows {
        if let Some(shot) = r.shot {
            assert!(shot.carry_m <= best.shot.map_or(0.0, |b| b.carry_m));
        }
    }
    // At position 0 the face centre meets the ball (the generator's origin).
    let mid = &result.rows[10].club;
    assert!(
        mid.impact_height_m.abs() < 2e-3 && mid.impact_toe_m.abs() < 2e-3,
        "{mid:?}"
    );
    for r in &result.rows {
        println!(
            "{:+.2} attack {:+.2} path {:+.2} face {:+.2} loft {:.2} h {:+.4} toe {:+.4} carry {:?}",
            r.ball_position_m,
            r.club.attack_angle_deg,
            r.club.club_path_deg,
            r.club.face_angle_deg,
            r.club.dynamic_loft_deg,
            r.club.impact_height_m,
            r.club.impact_toe_m,
            r.shot.map(|s| (s.carry_m, s.side_m))
        );
    }
}

#[test]
fn bad_swings_are_typed_errors() {
    let s = setup();
    let loft = s.club.loft_rad();
    let header = "t_s,x_m,y_m,z_m,qw,qx,qy,qz\n";
    // Non-monotonic time.
    let csv = format!("{header}0,0,0,0,1,0,0,0\n0.001,0.04,0,0,1,0,0,0\n0.0005,0.08,0,0,1,0,0,0\n");
    assert!(matches!(
        Motion::from_csv(csv.as_bytes(), loft),
        Err(Error::Invalid(Input::Swing, _))
    ));
    // Not a unit quaternion.
    let csv =
        format!("{header}0,0,0,0,1,0,0,0\n0.001,0.04,0,0,0.9,0,0,0\n0.002,0.08,0,0,1,0,0,0\n");
    let Err(Error::Invalid(Input::Swing, why)) = Motion::from_csv(csv.as_bytes(), loft) else {
        panic!()
    };
    assert!(
        why.contains("line 3") && why.contains("unit quaternion"),
        "{why}"
    );
    // A face that stops short of the ball.
    let csv =
        format!("{header}0,-0.5,0,0,1,0,0,0\n0.001,-0.45,0,0,1,0,0,0\n0.002,-0.4,0,0,1,0,0,0\n");
    let Ok(m) = Motion::from_csv(csv.as_bytes(), loft) else {
        panic!()
    };
    assert!(matches!(
        sweep(&s, &m, &[0.0]),
        Err(Error::Invalid(Input::BallPositions, _))
    ));
    assert!(positions(0.1, -0.1, 0.01).is_err());
    assert!(positions(0.0, 0.1, 0.0).is_err());
}

/// The shipped example swing is the generator's output (regenerate with
/// `CARRY_REGENERATE=1 cargo test -p carry-lab --test sweep` or `carry sweep --generate`).
#[test]
fn shipped_example_is_the_generators_output() {
    let s = setup();
    let text = example(&s).to_csv(false, carry_lab::sweep::generate::EXAMPLE_COMMENT);
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/swing_driver.csv");
    if std::env::var_os("CARRY_REGENERATE").is_some() {
        let _ = std::fs::write(path, &text);
    }
    let shipped = std::fs::read_to_string(path).unwrap_or_default();
    assert!(shipped == text, "{path} is stale: regenerate it");
}

mod properties {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// Ball positions: ordered, evenly stepped, inside [from, to], and the count the
        /// step implies.
        #[test]
        fn positions_are_a_grid(from in -1.0..1.0f64, width in 0.0..1.0f64, step in 1e-3..0.5f64) {
            let Ok(xs) = positions(from, from + width, step) else {
                return Err(TestCaseError::fail("rejected"));
            };
            prop_assert!(!xs.is_empty());
            prop_assert_eq!(xs[0], from);
            prop_assert!(xs.iter().all(|&x| x <= from + width + 1e-9 * (1.0 + width)));
            prop_assert!(xs.windows(2).all(|w| ((w[1] - w[0]) - step).abs() < 1e-9));
            prop_assert!(xs.last().is_some_and(|&x| x + step > from + width - 1e-9));
        }
    }
}
