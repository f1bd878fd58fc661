//! The C API's launch from the flight (issue 36) through its `extern "C"` entry points: the
//! core's fit bit for bit, a known launch's spin and axis recovered within 1σ from its
//! summaries and from a track array, each figure's source, and the error codes.

use carry_core::launch_fit::{Datum, LaunchValues, Observations, Settings, Workspace, fit_launch};
use carry_core::units::{deg, rpm};
use carry_core::{Ball, FlightOutcome, Integrator, Launch, Recorder, Sample, SampleSink, Scene};
use carry_ffi::error::CarryError::*;
use carry_ffi::launch_fit::*;
use carry_ffi::*;
use core::ptr::{null, null_mut};

fn input<T: carry_core::Real>(
    default: unsafe extern "C" fn(*mut CarryLaunchFromFlightInput<T>) -> error::CarryError,
) -> CarryLaunchFromFlightInput<T> {
    let mut input = core::mem::MaybeUninit::uninit();
    // SAFETY: a writable struct.
    let rc = unsafe { default(input.as_mut_ptr()) };
    assert_eq!(rc, CARRY_OK);
    // SAFETY: written on CARRY_OK.
    unsafe { input.assume_init() }
}

fn workspace<T: carry_core::Real>() -> Box<CarryLaunchFromFlightWorkspace<T>> {
    Box::new(CarryLaunchFromFlightWorkspace {
        scratch: [T::zero(); CARRY_LAUNCH_FIT_WORKSPACE_LEN],
    })
}

/// 70 m/s, 12°, 0°, 2,800 rpm, axis 5°.
fn truth() -> Launch<f64> {
    Launch::from_spin_axis(70.0, deg(12.0), 0.0, rpm(2800.0), deg(5.0))
}

fn fly(launch: &Launch<f64>) -> FlightOutcome<f64> {
    Scene::default()
        .prepare(&Ball::standard())
        .unwrap()
        .fly(&launch.ball_motion().unwrap(), &Integrator::default(), None)
        .unwrap()
}

/// The input of the summaries of `o`, ball speed, launch angle and direction measured.
fn summaries_input(o: &FlightOutcome<f64>) -> CarryLaunchFromFlightInputF64 {
    let mut i = input::<f64>(carry_launch_from_flight_input_default_f64);
    i.measured =
        CARRY_MEASURED_BALL_SPEED | CARRY_MEASURED_LAUNCH_ANGLE | CARRY_MEASURED_LAUNCH_DIRECTION;
    i.measured_launch.ball_speed_mps = 70.0;
    i.measured_launch.launch_angle_rad = deg(12.0);
    i.measured_launch.launch_direction_rad = 0.0;
    i.observed = CARRY_OBSERVED_APEX_HEIGHT
        | CARRY_OBSERVED_CARRY
        | CARRY_OBSERVED_SIDE
        | CARRY_OBSERVED_FLIGHT_TIME
        | CARRY_OBSERVED_LAND_ANGLE;
    i.summaries.apex_height_m = o.apex_m;
    i.summaries.carry_m = o.carry_m;
    i.summaries.side_m = o.side_m;
    i.summaries.flight_time_s = o.flight_time_s;
    i.summaries.land_angle_rad = o.landing_angle_rad;
    i
}

#[test]
fn f64_is_the_core_s_fit_and_recovers_spin_and_axis() {
    let o = fly(&truth());
    let i = summaries_input(&o);
    let mut ws = workspace::<f64>();
    let mut out = CarryLaunchFromFlightResultF64::refused(0);
    // SAFETY: valid pointers; no arrays.
    let rc = unsafe { carry_launch_from_flight_f64(&i, &mut *ws, &mut out) };
    assert_eq!(rc, CARRY_OK);
    assert!(
        (out.value.spin_radps - rpm(2800.0)).abs() < out.sd.spin_radps,
        "{out:?}"
    );
    assert!(
        (out.value.spin_axis_rad - deg(5.0)).abs() < out.sd.spin_axis_rad,
        "{out:?}"
    );
    assert_eq!(out.source.spin, CARRY_SOURCE_FITTED);
    assert_eq!(out.source.spin_axis, CARRY_SOURCE_FITTED);
    assert_eq!(out.source.ball_speed, CARRY_SOURCE_MEASURED);
    assert_eq!(out.observations, 5);
    assert_eq!(out.unidentified, CARRY_DATUM_NONE);
    assert_eq!(out.wind_fitted, 0);
    // the core's fit, bit for bit
    let d = |v, sd| Some(Datum::new(v, sd));
    let measured = LaunchValues {
        ball_speed_mps: d(70.0, 0.2),
        launch_angle_rad: d(deg(12.0), deg(0.2)),
        launch_direction_rad: d(0.0, deg(0.3)),
        spin_radps: None,
        spin_axis_rad: None,
    };
    let obs = Observations {
        apex_height_m: d(o.apex_m, 0.5),
        carry_m: d(o.carry_m, 1.0),
        side_m: d(o.side_m, 0.5),
        flight_time_s: d(o.flight_time_s, 0.05),
        land_angle_rad: d(o.landing_angle_rad, deg(0.5)),
        ..Observations::default()
    };
    let mut core_ws = Box::new(Workspace::new());
    let f = fit_launch(
        &Ball::standard(),
        &Scene::default(),
        &measured,
        &obs,
        &Settings::default(),
        &mut core_ws,
    )
    .unwrap();
    assert_eq!(out.value.spin_radps, f.value.spin_radps);
    assert_eq!(out.sd.spin_axis_rad, f.sd.spin_axis_rad);
    assert_eq!(out.chi2, f.chi2);
    assert_eq!(out.flight.carry_m, f.flight.carry_m);
    assert_eq!(out.flights, u32::from(f.flights));
    // single precision: the same fit to its precision
    let mut i32 = input::<f32>(carry_launch_from_flight_input_default_f32);
    i32.measured = i.measured;
    i32.observed = i.observed;
    i32.measured_launch.ball_speed_mps = 70.0;
    i32.measured_launch.launch_angle_rad = deg(12.0f32);
    i32.summaries.apex_height_m = o.apex_m as f32;
    i32.summaries.carry_m = o.carry_m as f32;
    i32.summaries.side_m = o.side_m as f32;
    i32.summaries.flight_time_s = o.flight_time_s as f32;
    i32.summaries.land_angle_rad = o.landing_angle_rad as f32;
    let mut ws32 = workspace::<f32>();
    let mut out32 = CarryLaunchFromFlightResultF32::refused(0);
    // SAFETY: valid pointers.
    let rc = unsafe { carry_launch_from_flight_f32(&i32, &mut *ws32, &mut out32) };
    assert_eq!(rc, CARRY_OK);
    let spin = f64::from(out32.value.spin_radps);
    assert!(
        (spin - out.value.spin_radps).abs() < 0.2 * out.sd.spin_radps,
        "{out32:?}"
    );
}

struct Samples(Vec<Sample<f64>>);

impl SampleSink<f64> for Samples {
    fn clear(&mut self) {
        self.0.clear();
    }
    fn push(&mut self, s: Sample<f64>) -> bool {
        self.0.push(s);
        true
    }
}

/// 20 radar points over the first second, passed as a C array.
fn track_points() -> Vec<CarryTrackPointF64> {
    let times: Vec<f64> = (1..=20).map(|k| f64::from(k) * 0.05).collect();
    let scene = Scene::<f64>::default().prepare(&Ball::standard()).unwrap();
    let mut sink = Samples(Vec::new());
    {
        let mut rec = Recorder::at_times(&times, &mut sink).unwrap();
        scene
            .fly(
                &truth().ball_motion().unwrap(),
                &Integrator::default(),
                Some(&mut rec),
            )
            .unwrap();
    }
    sink.0
        .iter()
        .take(times.len())
        .map(|s| CarryTrackPoint {
            time_s: s.time_s,
            position_m: [s.position_m.x, s.position_m.y, s.position_m.z],
            sd_m: 0.05,
        })
        .collect()
}

#[test]
fn a_track_array_gives_spin_and_axis() {
    let track = track_points();
    let mut i = input::<f64>(carry_launch_from_flight_input_default_f64);
    i.measured =
        CARRY_MEASURED_BALL_SPEED | CARRY_MEASURED_LAUNCH_ANGLE | CARRY_MEASURED_LAUNCH_DIRECTION;
    i.measured_launch.ball_speed_mps = 70.0;
    i.measured_launch.launch_angle_rad = deg(12.0);
    i.track = track.as_ptr();
    i.track_len = track.len();
    let mut ws = workspace::<f64>();
    let mut out = CarryLaunchFromFlightResultF64::refused(0);
    // SAFETY: valid pointers; `track` outlives the call.
    let rc = unsafe { carry_launch_from_flight_f64(&i, &mut *ws, &mut out) };
    assert_eq!(rc, CARRY_OK);
    assert_eq!(out.observations, 60);
    assert!(
        (out.value.spin_radps - rpm(2800.0)).abs() < 2.0 * out.sd.spin_radps,
        "{out:?}"
    );
    assert!(
        (out.value.spin_axis_rad - deg(5.0)).abs() < 2.0 * out.sd.spin_axis_rad,
        "{out:?}"
    );
    if out.worst_observation == CARRY_OBSERVED_TRACK {
        assert!(out.worst_index < 20 && out.worst_axis < 3, "{out:?}");
    }
}

#[test]
fn errors_have_their_codes() {
    let o = fly(&truth());
    let base = summaries_input(&o);
    let mut ws = workspace::<f64>();
    let mut out = CarryLaunchFromFlightResultF64::refused(0);
    let call = |i: &CarryLaunchFromFlightInputF64,
                ws: &mut CarryLaunchFromFlightWorkspaceF64,
                out: &mut CarryLaunchFromFlightResultF64| {
        // SAFETY: valid pointers (the arrays as each case sets them).
        unsafe { carry_launch_from_flight_f64(i, ws, out) }
    };
    // one summary for two unknowns
    let mut i = base;
    i.observed = CARRY_OBSERVED_CARRY;
    assert_eq!(call(&i, &mut ws, &mut out), CARRY_ERR_TOO_FEW_OBSERVATIONS);
    // no side: the axis's sign is not determined
    let mut i = base;
    i.observed &= !(CARRY_OBSERVED_SIDE | CARRY_OBSERVED_LAND_ANGLE);
    i.summaries.apex_height_m = 31.9;
    i.summaries.carry_m = 222.4;
    i.summaries.flight_time_s = 6.7;
    assert_eq!(call(&i, &mut ws, &mut out), CARRY_ERR_UNIDENTIFIABLE);
    assert_eq!(out.unidentified, CARRY_DATUM_SPIN_AXIS_CODE);
    // a 1σ not positive, a value not finite
    let mut i = base;
    i.summaries_sd.carry_m = 0.0;
    assert_eq!(call(&i, &mut ws, &mut out), CARRY_ERR_INVALID_INPUT);
    let mut i = base;
    i.summaries.side_m = f64::NAN;
    assert_eq!(call(&i, &mut ws, &mut out), CARRY_ERR_INVALID_INPUT);
    // arrays: NULL with a length, too long
    let mut i = base;
    i.track_len = 3;
    assert_eq!(call(&i, &mut ws, &mut out), CARRY_ERR_NULL_POINTER);
    let many = vec![CarryDopplerSampleF64::default(); CARRY_LAUNCH_FIT_MAX_DOPPLER_SAMPLES + 1];
    let mut i = base;
    i.doppler = many.as_ptr();
    i.doppler_len = many.len();
    assert_eq!(call(&i, &mut ws, &mut out), CARRY_ERR_TOO_MANY_OBSERVATIONS);
    // an unknown selector
    let mut i = base;
    i.scene.aero = 99;
    assert_eq!(call(&i, &mut ws, &mut out), CARRY_ERR_UNKNOWN_OPTION);
    // NULL arguments
    // SAFETY: NULL or valid pointers only.
    unsafe {
        assert_eq!(
            carry_launch_from_flight_f64(null(), &mut *ws, &mut out),
            CARRY_ERR_NULL_POINTER
        );
        assert_eq!(
            carry_launch_from_flight_f64(&base, null_mut(), &mut out),
            CARRY_ERR_NULL_POINTER
        );
        assert_eq!(
            carry_launch_from_flight_f64(&base, &mut *ws, null_mut()),
            CARRY_ERR_NULL_POINTER
        );
        assert_eq!(
            carry_launch_from_flight_input_default_f32(null_mut()),
            CARRY_ERR_NULL_POINTER
        );
    }
}

const CARRY_DATUM_SPIN_AXIS_CODE: u32 = estimate::CARRY_DATUM_SPIN_AXIS;
