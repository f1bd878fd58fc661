//! The C API's estimator (issue 23) through its `extern "C"` entry points: the core's
//! result bit for bit, the ball data of a known delivery estimated back within 2σ, and the
//! error codes.

use carry_core::Ball;
use carry_core::estimate::{ClubData, Posterior, Settings, Unknowns, estimate, predict};
use carry_core::presets::Preset;
use carry_core::units::deg;
use carry_ffi::error::CarryError::*;
use carry_ffi::estimate::{
    CARRY_MEASURED_CLUB_SPEED, CARRY_POSTERIOR_LAPLACE, CARRY_POSTERIOR_PROFILE,
    CarryEstimateResult,
};
use carry_ffi::*;
use core::ptr::{null, null_mut};

fn driver_input<T: carry_core::Real>(
    default: unsafe extern "C" fn(
        *const core::ffi::c_char,
        *mut estimate::CarryEstimateInput<T>,
    ) -> error::CarryError,
) -> estimate::CarryEstimateInput<T> {
    let mut input = core::mem::MaybeUninit::uninit();
    // SAFETY: a NUL-terminated name and a writable struct.
    let rc = unsafe { default(c"driver".as_ptr(), input.as_mut_ptr()) };
    assert_eq!(rc, CARRY_OK);
    // SAFETY: written on CARRY_OK.
    unsafe { input.assume_init() }
}

#[test]
fn estimate_f64_is_the_core_s_and_recovers_a_delivery() {
    let truth = Unknowns {
        face_angle_rad: deg(1.5),
        club_path_rad: deg(-2.0),
        dynamic_loft_rad: deg(13.0),
        attack_angle_rad: deg(1.0),
        impact_toe_m: 0.004,
        impact_height_m: 0.006,
        club_speed_mps: 44.0,
    };
    let preset = Preset::find("driver").expect("driver");
    let club = preset.spec::<f64>().validate().expect("club");
    let y = predict(&club, &Ball::standard(), &truth).expect("launch");
    let mut input = driver_input::<f64>(carry_estimate_input_default_f64);
    input.measured_ball.ball_speed_mps = y.ball_speed_mps;
    input.measured_ball.launch_angle_rad = y.launch_angle_rad;
    input.measured_ball.launch_direction_rad = y.launch_direction_rad;
    input.measured_ball.spin_radps = y.spin_radps;
    input.measured_ball.spin_axis_rad = y.spin_axis_rad;
    input.measured = CARRY_MEASURED_CLUB_SPEED;
    input.measured_club.club_speed_mps = 44.0;
    let mut out = CarryEstimateResult::<f64>::default();
    // SAFETY: valid pointers.
    let rc = unsafe { carry_estimate_f64(&input, &mut out) };
    assert_eq!(rc, CARRY_OK);
    let core = estimate(
        &club,
        &Ball::standard(),
        &y,
        &ClubData {
            club_speed_mps: Some(44.0),
            ..ClubData::default()
        },
        &Settings::for_preset(preset),
    )
    .expect("estimate");
    assert_eq!(
        out.value.face_angle_rad.to_bits(),
        core.value.face_angle_rad.to_bits()
    );
    assert_eq!(
        out.sd.impact_height_m.to_bits(),
        core.sd.impact_height_m.to_bits()
    );
    assert_eq!(out.iterations, u32::from(core.iterations));
    assert_eq!(out.club_speed_estimated, 0);
    assert!((out.value.face_angle_rad - truth.face_angle_rad).abs() < 2.0 * out.sd.face_angle_rad);
    assert!(
        (out.value.dynamic_loft_rad - truth.dynamic_loft_rad).abs() < 2.0 * out.sd.dynamic_loft_rad
    );
}

#[test]
fn estimate_f32_runs_and_errors_are_typed() {
    let mut input = driver_input::<f32>(carry_estimate_input_default_f32);
    input.measured_ball.ball_speed_mps = 66.0;
    input.measured_ball.launch_angle_rad = 0.23;
    input.measured_ball.launch_direction_rad = 0.02;
    input.measured_ball.spin_radps = 288.0;
    input.measured_ball.spin_axis_rad = 0.11;
    let mut out = CarryEstimateResult::<f32>::default();
    // SAFETY: valid pointers.
    let rc = unsafe { carry_estimate_f32(&input, &mut out) };
    assert_eq!(rc, CARRY_OK);
    assert!(out.value.club_path_rad.is_finite() && out.sd.club_path_rad > 0.0);
    assert_eq!(out.club_speed_estimated, 1);
    // SAFETY: NULL pointers are refused.
    let rc = unsafe { carry_estimate_f32(null(), &mut out) };
    assert_eq!(rc, CARRY_ERR_NULL_POINTER);
    // SAFETY: as above.
    let rc = unsafe { carry_estimate_f32(&input, null_mut()) };
    assert_eq!(rc, CARRY_ERR_NULL_POINTER);
    let mut bad = input;
    bad.max_iterations = 0;
    // SAFETY: valid pointers.
    let rc = unsafe { carry_estimate_f32(&bad, &mut out) };
    assert_eq!(rc, CARRY_ERR_INVALID_INPUT);
    bad = input;
    bad.measured_ball.spin_radps = f32::NAN;
    // SAFETY: valid pointers.
    let rc = unsafe { carry_estimate_f32(&bad, &mut out) };
    assert_eq!(rc, CARRY_ERR_INVALID_INPUT);
    bad = input;
    bad.posterior = 2;
    // SAFETY: valid pointers.
    let rc = unsafe { carry_estimate_f32(&bad, &mut out) };
    assert_eq!(rc, CARRY_ERR_UNKNOWN_OPTION);
    let mut unknown = core::mem::MaybeUninit::<CarryEstimateInputF32>::uninit();
    // SAFETY: a NUL-terminated name and a writable struct.
    let rc = unsafe { carry_estimate_input_default_f32(c"putter".as_ptr(), unknown.as_mut_ptr()) };
    assert_eq!(rc, CARRY_ERR_UNKNOWN_NAME);
}

/// `posterior`: the default is the calibrated profile summary; `CARRY_POSTERIOR_LAPLACE` is
/// the core's `Posterior::Laplace`, bit for bit.
#[test]
fn estimate_takes_the_posterior_summary() {
    let preset = Preset::find("driver").expect("driver");
    let club = preset.spec::<f64>().validate().expect("club");
    let truth = Unknowns {
        face_angle_rad: deg(-1.0),
        club_path_rad: deg(2.0),
        dynamic_loft_rad: deg(12.0),
        attack_angle_rad: deg(-1.5),
        impact_toe_m: 0.006,
        impact_height_m: 0.004,
        club_speed_mps: 45.0,
    };
    let y = predict(&club, &Ball::standard(), &truth).expect("launch");
    let mut input = driver_input::<f64>(carry_estimate_input_default_f64);
    assert_eq!(input.posterior, CARRY_POSTERIOR_PROFILE);
    input.measured_ball.ball_speed_mps = y.ball_speed_mps;
    input.measured_ball.launch_angle_rad = y.launch_angle_rad;
    input.measured_ball.launch_direction_rad = y.launch_direction_rad;
    input.measured_ball.spin_radps = y.spin_radps;
    input.measured_ball.spin_axis_rad = y.spin_axis_rad;
    input.posterior = CARRY_POSTERIOR_LAPLACE;
    let mut out = CarryEstimateResult::<f64>::default();
    // SAFETY: valid pointers.
    let rc = unsafe { carry_estimate_f64(&input, &mut out) };
    assert_eq!(rc, CARRY_OK);
    let settings = Settings {
        posterior: Posterior::Laplace,
        ..Settings::for_preset(preset)
    };
    let core = estimate(
        &club,
        &Ball::standard(),
        &y,
        &ClubData::default(),
        &settings,
    )
    .expect("estimate");
    assert_eq!(
        out.value.impact_height_m.to_bits(),
        core.value.impact_height_m.to_bits()
    );
    assert_eq!(
        out.sd.attack_angle_rad.to_bits(),
        core.sd.attack_angle_rad.to_bits()
    );
}

/// Issue 34: ball data and a club speed that disagree return `CARRY_ERR_INCONSISTENT` with
/// the result written, its verdict naming the worst datum (the ball or the club speed);
/// the same ball data with a fitting club speed are `CARRY_OK` and consistent.
#[test]
fn estimate_reports_inconsistent_data() {
    use carry_ffi::estimate::{CARRY_DATUM_BALL_SPEED, CARRY_DATUM_CLUB_SPEED};
    let mut input = driver_input::<f64>(carry_estimate_input_default_f64);
    input.measured_ball.ball_speed_mps = 70.0;
    input.measured_ball.launch_angle_rad = deg(12.0);
    input.measured_ball.spin_radps = 2800.0 * core::f64::consts::PI / 30.0;
    input.measured = CARRY_MEASURED_CLUB_SPEED;
    input.measured_club.club_speed_mps = 5.0;
    let mut out = CarryEstimateResult::<f64>::default();
    // SAFETY: valid pointers.
    let rc = unsafe { carry_estimate_f64(&input, &mut out) };
    assert_eq!(rc, CARRY_ERR_INCONSISTENT);
    assert_eq!(out.consistent, 0);
    assert!(out.chi2 > out.chi2_bound && out.chi2_bound > 0.0, "{out:?}");
    assert!(
        [CARRY_DATUM_BALL_SPEED, CARRY_DATUM_CLUB_SPEED].contains(&out.worst),
        "{out:?}"
    );
    assert!(
        out.worst_sd > 4.0 && out.value.club_speed_mps > 5.0,
        "{out:?}"
    );
    input.measured_club.club_speed_mps = 47.0;
    // SAFETY: valid pointers.
    let rc = unsafe { carry_estimate_f64(&input, &mut out) };
    assert_eq!(rc, CARRY_OK);
    assert_eq!(out.consistent, 1);
    // a check bound out of range is invalid input
    input.check_tail_probability = 0.0;
    // SAFETY: valid pointers.
    let rc = unsafe { carry_estimate_f64(&input, &mut out) };
    assert_eq!(rc, CARRY_ERR_INVALID_INPUT);
}
