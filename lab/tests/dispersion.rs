//! Dispersion: zero noise is the single shot, side spread is linear in small face-angle
//! noise with the slope of a two-shot derivative, results do not depend on threads.

use carry_core::PRESETS;
use carry_core::units::deg;
use carry_lab::dispersion::{Noise, simulate};
use carry_lab::{Error, Input, Setup};
use proptest::prelude::*;

/// Linearity: side SD at 2σ over side SD at σ (same draws) equals 2 to this.
const LINEARITY_TOLERANCE: f64 = 2.0e-3;
/// Slope against the central-difference derivative: the sample SD of N standard normals
/// differs from 1 by ~1/√(2N) (0.7 % at N = 10 000); 3 % leaves room for that.
const SLOPE_TOLERANCE: f64 = 0.03;
/// Face-angle step of the derivative (deg).
const DERIVATIVE_STEP_DEG: f64 = 0.01;

fn setup<T: carry_core::Real>() -> Setup<T> {
    match Setup::standard(&PRESETS[0], 45.0) {
        Ok(s) => s,
        Err(e) => panic!("{e}"),
    }
}

fn check_zero_noise<T: carry_core::Real>() {
    let s = setup::<T>();
    let Ok(base) = s.play_base() else { panic!() };
    let Ok(d) = simulate(&s, &Noise::default(), 64, 7, None) else {
        panic!()
    };
    let carry = carry_core::real::to_f64(base.flight.carry_m);
    let side = carry_core::real::to_f64(base.flight.side_m);
    assert_eq!(d.carry_mean_m, carry);
    assert_eq!(d.side_mean_m, side);
    assert_eq!(d.carry_sd_m, 0.0);
    assert_eq!(d.covariance_m2, [[0.0, 0.0], [0.0, 0.0]]);
    assert_eq!(d.carry_percentiles_m.p5, carry);
    assert_eq!(d.failed_shots, 0);
}

#[test]
fn zero_noise_reproduces_the_single_shot_exactly() {
    check_zero_noise::<f64>();
    check_zero_noise::<f32>();
}

#[test]
fn side_spread_is_linear_in_small_face_noise() {
    let s = setup::<f64>();
    let sigma = 0.1;
    let noise = |sd: f64| Noise {
        face_angle_deg: sd,
        ..Noise::default()
    };
    let (Ok(a), Ok(b)) = (
        simulate(&s, &noise(sigma), 10_000, 3, None),
        simulate(&s, &noise(2.0 * sigma), 10_000, 3, None),
    ) else {
        panic!()
    };
    let ratio = b.side_sd_m / a.side_sd_m;
    assert!((ratio - 2.0).abs() < LINEARITY_TOLERANCE, "ratio {ratio}");
    // ∂side/∂face from two shots.
    let side_at = |face_deg: f64| {
        let mut d = s.delivery;
        d.face_angle_rad = deg(face_deg);
        match s.play(&d) {
            Ok(o) => o.flight.side_m,
            Err(e) => panic!("{e}"),
        }
    };
    let slope = (side_at(DERIVATIVE_STEP_DEG) - side_at(-DERIVATIVE_STEP_DEG))
        / (2.0 * DERIVATIVE_STEP_DEG);
    let measured = a.side_sd_m / sigma;
    assert!(
        (measured / slope.abs() - 1.0).abs() < SLOPE_TOLERANCE,
        "side SD per degree {measured} vs |∂side/∂face| {}",
        slope.abs()
    );
}

#[test]
fn thread_count_does_not_change_the_result() {
    let s = setup::<f64>();
    let noise = Noise {
        face_angle_deg: 1.0,
        club_speed_mps: 1.0,
        impact_toe_m: 0.005,
        ..Noise::default()
    };
    let run = |threads: usize| {
        let Ok(pool) = rayon::ThreadPoolBuilder::new().num_threads(threads).build() else {
            panic!()
        };
        match pool.install(|| simulate(&s, &noise, 3000, 11, None)) {
            Ok(d) => d,
            Err(e) => panic!("{e}"),
        }
    };
    assert_eq!(run(1), run(2));
}

#[test]
fn bad_noise_and_counts_are_typed_errors() {
    let s = setup::<f64>();
    let bad = Noise {
        club_path_deg: -1.0,
        ..Noise::default()
    };
    assert!(matches!(
        simulate(&s, &bad, 10, 1, None),
        Err(Error::Invalid(Input::NoiseSd(1), _))
    ));
    assert!(matches!(
        simulate(&s, &Noise::default(), 1, 1, None),
        Err(Error::Invalid(Input::Count, _))
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Any noise: the statistics are finite and consistent (ellipse axes ordered, the
    /// percentiles ordered, SDs match the covariance's diagonal).
    #[test]
    fn statistics_are_consistent(
        face in 0.0..3.0f64, path in 0.0..3.0f64, speed in 0.0..3.0f64,
        toe in 0.0..0.01f64, seed in any::<u64>(),
    ) {
        let s = setup::<f64>();
        let noise = Noise { face_angle_deg: face, club_path_deg: path, club_speed_mps: speed,
            impact_toe_m: toe, ..Noise::default() };
        let Ok(d) = simulate(&s, &noise, 200, seed, None) else { return Err(TestCaseError::fail("failed")); };
        let e = d.ellipse_95;
        prop_assert!(e.semi_major_m >= e.semi_minor_m && e.semi_minor_m >= 0.0);
        let p = d.side_percentiles_m;
        prop_assert!(p.min <= p.p5 && p.p5 <= p.p25 && p.p25 <= p.p50 && p.p50 <= p.p75
            && p.p75 <= p.p95 && p.p95 <= p.max);
        prop_assert!((d.side_sd_m * d.side_sd_m - d.covariance_m2[1][1]).abs()
            <= 1e-9 * (1.0 + d.covariance_m2[1][1]));
        prop_assert!(d.covariance_m2[0][1] == d.covariance_m2[1][0]);
    }
}
