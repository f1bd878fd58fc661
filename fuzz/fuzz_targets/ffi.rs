//! Fuzz the C API (carry-ffi) through its C entry points, in f32 and f64: arbitrary
//! struct contents (NaN, ±∞, extremes, out-of-range selectors), NULL pointers, no / tiny /
//! ample trajectory buffers. Every call must return one of the `carry_error_t` codes; a
//! success (or a full buffer) must leave finite results and a sample count within the
//! capacity. The estimator (club data from ball data) too: arbitrary ball data, club data,
//! noise, prior, budget and posterior selector; a success must leave finite estimates and
//! non-negative 1σ. The launch from the flight too (issue 36): arbitrary measured launch,
//! summaries, track and Doppler arrays (NULL or not, past capacity), priors, budget; a
//! success must leave a finite fit and positive 1σ, `CARRY_ERR_UNIDENTIFIABLE` a named
//! unknown.
//!
//! Work bounds as the flight target's (docs/robustness.md): fixed or maximum steps below
//! `time limit / 2e5`, updrafts that grow without bound and absurd drag scales are legal
//! but slow, and skipped.
#![no_main]
#![allow(
    unsafe_code,
    clippy::neg_cmp_op_on_partial_ord,
    clippy::field_reassign_with_default
)]

use carry_core::real::{Real, lit, to_f64};
use carry_ffi::error::ALL;
use carry_ffi::estimate::{
    CarryBallData, CarryDeliveryData, CarryEstimateInput, CarryEstimateResult,
};
use carry_ffi::launch_fit::{
    CarryDopplerSample, CarryLaunchFromFlightInput, CarryLaunchFromFlightResult,
    CarryLaunchFromFlightWorkspace, CarryTrackPoint,
};
use carry_ffi::scene::*;
use carry_ffi::settings::*;
use carry_ffi::*;
use carry_fuzz::Bytes;
use core::ptr::{null, null_mut};
use libfuzzer_sys::fuzz_target;

const MAX_STEPS: f64 = 2e5;

/// A selector: mostly one of its `count` values, sometimes any `u32`.
fn selector(b: &mut Bytes<'_>, count: u32) -> u32 {
    match b.byte() {
        0..=239 => u32::from(b.byte()) % count,
        _ => u32::from_le_bytes([b.byte(), b.byte(), b.byte(), b.byte()]),
    }
}

fn f<T: Real>(b: &mut Bytes<'_>, lo: f64, hi: f64) -> T {
    lit(b.param(lo, hi))
}

fn a3<T: Real>(b: &mut Bytes<'_>, lo: f64, hi: f64) -> [T; 3] {
    b.vec3(lo, hi).map(lit)
}

fn mutate_club<T: Real>(b: &mut Bytes<'_>, c: &mut CarryClub<T>) {
    if b.flag() {
        c.mass_kg = f(b, 0.05, 1.0);
        c.inertia_kgm2 = [0; 9].map(|_| f(b, -2e-4, 1e-3));
        c.loft_rad = f(b, -0.5, 1.2);
        c.roll_radius_m = f(b, 0.05, 2.0);
        c.bulge_radius_m = f(b, 0.05, 2.0);
        c.face_depth_radius_m = f(b, 0.0, 2.0);
        c.cg_to_face_m = a3(b, -0.05, 0.06);
        c.restitution = f(b, 0.0, 1.0);
        c.friction = f(b, -0.1, 2.0);
        c.tangential_restitution = f(b, -1.1, 1.1);
        c.tangential_restitution_slope = f(b, -5.0, 5.0);
        c.restitution_speed_slope_spm = f(b, -0.01, 0.05);
        c.tangential_restitution_max = f(b, -0.1, 1.1);
        c.spin_axis_share = f(b, -0.1, 1.1);
    }
    c.contact = selector(b, 2);
}

fn mutate_delivery<T: Real>(b: &mut Bytes<'_>, d: &mut CarryDelivery<T>) {
    if b.flag() {
        d.club_speed_mps = f(b, 0.0, 80.0);
        d.attack_angle_rad = f(b, -0.5, 0.5);
        d.club_path_rad = f(b, -0.5, 0.5);
        d.face_angle_rad = f(b, -0.5, 0.5);
        d.dynamic_loft_rad = f(b, -0.5, 1.2);
        d.lie_rad = f(b, -0.5, 0.5);
        d.club_spin_radps = a3(b, -100.0, 100.0);
        d.impact_height_m = f(b, -0.04, 0.04);
        d.impact_toe_m = f(b, -0.05, 0.05);
    }
}

/// The scene and settings; `false` when the flight would take unbounded work.
fn mutate_scene<T: Real>(
    b: &mut Bytes<'_>,
    s: &mut CarryScene<T>,
    n: &mut CarrySettings<T>,
) -> bool {
    if b.flag() {
        s.drag = u32::from(b.byte());
        s.lift = u32::from(b.flag());
        s.spin_decay = u32::from(b.flag());
        s.air_density_kgm3 = f(b, 0.0, 2.0);
        s.temperature_c = f(b, -40.0, 50.0);
        s.relative_humidity = f(b, 0.0, 1.0);
        s.pressure_pa = f(b, 5e4, 1.1e5);
        s.altitude_m = f(b, -500.0, 5000.0);
        s.wind_mps = a3(b, -30.0, 30.0);
        s.wind_reference_height_m = f(b, 0.5, 50.0);
        s.wind_exponent = f(b, 0.0, 0.5);
        s.landing_height_m = f(b, -20.0, 40.0);
        s.time_limit_s = f(b, 0.1, 60.0);
        s.gravity_mps2 = f(b, 0.0, 20.0);
        s.launch_position_m = a3(b, -5.0, 5.0);
        s.stimp_m = f(b, 1.0, 5.0);
        s.ground_normal = a3(b, -0.3, 1.0);
    }
    s.aero = selector(b, 2);
    s.air = selector(b, 3);
    s.wind = selector(b, 3);
    s.ground = selector(b, 6);
    n.solver = selector(b, 2);
    n.integrator = selector(b, 3);
    if b.flag() {
        n.step_s = f(b, 1e-4, 0.1);
        n.rtol = f(b, 1e-12, 1e-2);
        n.atol = f(b, 1e-12, 1e-2);
        n.initial_step_s = f(b, 1e-4, 1.0);
        n.max_step_s = f(b, 1e-3, 10.0);
    }
    let limit = to_f64(s.time_limit_s);
    let step = match n.integrator {
        CARRY_INTEGRATOR_DP45 => to_f64(n.max_step_s),
        _ => to_f64(n.step_s),
    };
    let w = s.wind_mps.map(to_f64);
    let calm = match s.wind {
        CARRY_WIND_PROFILE => to_f64(s.wind_exponent) <= 0.5 && w[1].abs() <= 5.0,
        CARRY_WIND_UNIFORM => w[1].abs() <= 50.0,
        _ => true,
    };
    let air = to_f64(s.air_density_kgm3);
    limit.is_finite() && !(step < limit / MAX_STEPS) && calm && !(air > 10.0)
}

fn finite<T: Real>(xs: &[T]) -> bool {
    xs.iter().all(|x| x.is_finite())
}

fn check_flight<T: Real>(r: &CarryFlightResult<T>) {
    let mut xs = vec![
        r.carry_m,
        r.carry_x_m,
        r.side_m,
        r.apex_m,
        r.apex_time_s,
        r.flight_time_s,
        r.landing_angle_rad,
        r.landing_speed_mps,
        r.landing_spin_radps,
        r.air_density_kgm3,
    ];
    xs.extend(
        r.landing_position_m
            .iter()
            .chain(&r.landing_velocity_mps)
            .chain(&r.landing_spin_vector_radps),
    );
    if r.has_ground != 0 {
        xs.extend([r.total_m, r.roll_m, r.time_to_rest_s]);
        xs.extend(r.rest_position_m);
    }
    assert!(finite(&xs), "non-finite flight result {r:?}");
}

fn check_impact<T: Real>(r: &CarryImpactResult<T>) {
    let mut xs: Vec<T> = [
        r.ball_velocity_mps,
        r.ball_spin_radps,
        r.club_velocity_mps,
        r.club_spin_radps,
        r.impulse_ns,
    ]
    .concat();
    xs.extend([
        r.ball_speed_mps,
        r.launch_angle_rad,
        r.launch_direction_rad,
        r.spin_radps,
        r.backspin_radps,
        r.sidespin_radps,
        r.spin_axis_rad,
        r.smash_factor,
    ]);
    assert!(finite(&xs), "non-finite impact result {r:?}");
}

/// The C API of one precision.
trait Api: Real + Default {
    unsafe fn impact(
        i: *const CarryImpactInput<Self>,
        o: *mut CarryImpactResult<Self>,
    ) -> CarryError;
    unsafe fn flight(
        i: *const CarryFlightInput<Self>,
        s: *mut CarrySample<Self>,
        c: usize,
        n: *mut usize,
        o: *mut CarryFlightResult<Self>,
    ) -> CarryError;
    unsafe fn shot(
        i: *const CarryShotInput<Self>,
        s: *mut CarrySample<Self>,
        c: usize,
        n: *mut usize,
        o: *mut CarryShotResult<Self>,
    ) -> CarryError;
    unsafe fn estimate_default(
        name: *const core::ffi::c_char,
        o: *mut CarryEstimateInput<Self>,
    ) -> CarryError;
    unsafe fn estimate(
        i: *const CarryEstimateInput<Self>,
        o: *mut CarryEstimateResult<Self>,
    ) -> CarryError;
    unsafe fn strike_height(
        name: *const core::ffi::c_char,
        loft: Self,
        radius: Self,
        o: *mut Self,
    ) -> CarryError;
    unsafe fn launch_default(o: *mut CarryLaunchFromFlightInput<Self>) -> CarryError;
    unsafe fn launch_from_flight(
        i: *const CarryLaunchFromFlightInput<Self>,
        w: *mut CarryLaunchFromFlightWorkspace<Self>,
        o: *mut CarryLaunchFromFlightResult<Self>,
    ) -> CarryError;
}

macro_rules! api {
    ($t:ty, $i:ident, $f:ident, $s:ident, $ed:ident, $e:ident, $h:ident, $ld:ident, $l:ident) => {
        impl Api for $t {
            unsafe fn impact(
                i: *const CarryImpactInput<Self>,
                o: *mut CarryImpactResult<Self>,
            ) -> CarryError {
                unsafe { $i(i, o) }
            }
            unsafe fn flight(
                i: *const CarryFlightInput<Self>,
                s: *mut CarrySample<Self>,
                c: usize,
                n: *mut usize,
                o: *mut CarryFlightResult<Self>,
            ) -> CarryError {
                unsafe { $f(i, s, c, n, o) }
            }
            unsafe fn shot(
                i: *const CarryShotInput<Self>,
                s: *mut CarrySample<Self>,
                c: usize,
                n: *mut usize,
                o: *mut CarryShotResult<Self>,
            ) -> CarryError {
                unsafe { $s(i, s, c, n, o) }
            }
            unsafe fn estimate_default(
                name: *const core::ffi::c_char,
                o: *mut CarryEstimateInput<Self>,
            ) -> CarryError {
                unsafe { $ed(name, o) }
            }
            unsafe fn estimate(
                i: *const CarryEstimateInput<Self>,
                o: *mut CarryEstimateResult<Self>,
            ) -> CarryError {
                unsafe { $e(i, o) }
            }
            unsafe fn strike_height(
                name: *const core::ffi::c_char,
                loft: Self,
                radius: Self,
                o: *mut Self,
            ) -> CarryError {
                unsafe { $h(name, loft, radius, o) }
            }
            unsafe fn launch_default(o: *mut CarryLaunchFromFlightInput<Self>) -> CarryError {
                unsafe { $ld(o) }
            }
            unsafe fn launch_from_flight(
                i: *const CarryLaunchFromFlightInput<Self>,
                w: *mut CarryLaunchFromFlightWorkspace<Self>,
                o: *mut CarryLaunchFromFlightResult<Self>,
            ) -> CarryError {
                unsafe { $l(i, w, o) }
            }
        }
    };
}
api!(
    f32,
    carry_impact_f32,
    carry_flight_f32,
    carry_shot_f32,
    carry_estimate_input_default_f32,
    carry_estimate_f32,
    carry_strike_height_f32,
    carry_launch_from_flight_input_default_f32,
    carry_launch_from_flight_f32
);
api!(
    f64,
    carry_impact_f64,
    carry_flight_f64,
    carry_shot_f64,
    carry_estimate_input_default_f64,
    carry_estimate_f64,
    carry_strike_height_f64,
    carry_launch_from_flight_input_default_f64,
    carry_launch_from_flight_f64
);

/// NULL (rarely) or the address of `x`.
fn ptr_or_null<P>(b: &mut Bytes<'_>, x: *mut P) -> *mut P {
    if b.byte() < 8 { null_mut() } else { x }
}

fn delivery_data<T: Real>(b: &mut Bytes<'_>, d: &mut CarryDeliveryData<T>, scale: f64) {
    d.face_angle_rad = f(b, -0.6 * scale, 0.6 * scale);
    d.club_path_rad = f(b, -0.6 * scale, 0.6 * scale);
    d.dynamic_loft_rad = f(b, -0.3 * scale, 1.2 * scale);
    d.attack_angle_rad = f(b, -0.5 * scale, 0.5 * scale);
    d.impact_toe_m = f(b, -0.05 * scale, 0.05 * scale);
    d.impact_height_m = f(b, -0.05 * scale, 0.05 * scale);
    d.club_speed_mps = f(b, -5.0, 80.0 * scale);
}

/// The named-club rule's strike height for an arbitrary name, loft and ball radius: a
/// finite height or a typed error, the output untouched on error.
fn strike_height_op<T: Api>(b: &mut Bytes<'_>) -> CarryError {
    let names = [c"driver", c"3wood", c"7iron", c"lw", c"putter"];
    let name = names[usize::from(b.byte()) % names.len()];
    let name = if b.byte() < 8 { null() } else { name.as_ptr() };
    let (loft, radius) = (f::<T>(b, -4.0, 4.0), f::<T>(b, -0.01, 0.1));
    let mut h = T::zero();
    let hp = ptr_or_null(b, &mut h);
    // SAFETY: NULL or a NUL-terminated name; NULL or a live value.
    let code = unsafe { T::strike_height(name, loft, radius, hp) };
    if code == CarryError::CARRY_OK {
        assert!(h.is_finite(), "non-finite strike height {h:?}");
    } else {
        assert!(h == T::zero(), "written on error: {h:?}");
    }
    code
}

/// One estimate from a preset's defaults with arbitrary measurements and settings.
fn estimate_op<T: Api>(b: &mut Bytes<'_>) -> CarryError {
    let names = [c"driver", c"7iron", c"pw", c"putter"];
    let name = names[usize::from(b.byte()) % names.len()];
    let mut i = core::mem::MaybeUninit::<CarryEstimateInput<T>>::uninit();
    // SAFETY: a NUL-terminated name and a writable struct.
    let code = unsafe { T::estimate_default(name.as_ptr(), i.as_mut_ptr()) };
    if code != CarryError::CARRY_OK {
        return code;
    }
    // SAFETY: written on CARRY_OK.
    let mut i = unsafe { i.assume_init() };
    mutate_club(b, &mut i.club);
    let m = &mut i.measured_ball;
    m.ball_speed_mps = f(b, -1.0, 160.0);
    m.launch_angle_rad = f(b, -1.7, 1.7);
    m.launch_direction_rad = f(b, -1.7, 1.7);
    m.spin_radps = f(b, -10.0, 2100.0);
    m.spin_axis_rad = f(b, -3.3, 3.3);
    i.measured = selector(b, 32);
    delivery_data(b, &mut i.measured_club, 1.0);
    if b.flag() {
        let n = &mut i.ball_noise;
        n.ball_speed_mps = f(b, -0.1, 5.0);
        n.launch_angle_rad = f(b, -0.01, 0.1);
        n.spin_radps = f(b, -1.0, 100.0);
        delivery_data(b, &mut i.club_noise, 0.1);
        delivery_data(b, &mut i.prior_sd, 0.2);
    }
    if b.flag() {
        delivery_data(b, &mut i.prior_mean, 1.0);
    }
    i.max_iterations = selector(b, 40);
    i.tolerance = f(b, -0.1, 1.2);
    i.posterior = selector(b, 2);
    let mut o = CarryEstimateResult::<T>::default();
    let ip = if b.byte() < 8 { null() } else { &i as *const _ };
    let op = ptr_or_null(b, &mut o);
    // SAFETY: NULL or live values.
    let code = unsafe { T::estimate(ip, op) };
    if code == CarryError::CARRY_OK {
        let v = &o.value;
        let sd = &o.sd;
        let values = [
            v.face_angle_rad,
            v.club_path_rad,
            v.dynamic_loft_rad,
            v.attack_angle_rad,
            v.impact_toe_m,
            v.impact_height_m,
            v.club_speed_mps,
            v.smash_factor,
        ];
        let sds = [
            sd.face_angle_rad,
            sd.club_path_rad,
            sd.dynamic_loft_rad,
            sd.attack_angle_rad,
            sd.impact_toe_m,
            sd.impact_height_m,
            sd.club_speed_mps,
        ];
        assert!(finite(&values), "non-finite estimate: {o:?}");
        assert!(
            sds.iter()
                .all(|s| to_f64(*s) >= 0.0 && to_f64(*s).is_finite()),
            "bad 1σ: {o:?}"
        );
    }
    code
}

fn launch_values<T: Real>(b: &mut Bytes<'_>, v: &mut CarryBallData<T>, scale: f64) {
    v.ball_speed_mps = f(b, -5.0 * scale, 90.0 * scale);
    v.launch_angle_rad = f(b, -0.5 * scale, 1.0 * scale);
    v.launch_direction_rad = f(b, -0.3 * scale, 0.3 * scale);
    v.spin_radps = f(b, -100.0 * scale, 1200.0 * scale);
    v.spin_axis_rad = f(b, -0.8 * scale, 0.8 * scale);
}

/// One launch fit from the defaults with arbitrary measurements, observations and arrays.
fn launch_from_flight_op<T: Api>(b: &mut Bytes<'_>) -> CarryError {
    let mut i = core::mem::MaybeUninit::uninit();
    // SAFETY: a writable struct.
    let code = unsafe { T::launch_default(i.as_mut_ptr()) };
    assert_eq!(code, CarryError::CARRY_OK);
    // SAFETY: written on CARRY_OK.
    let mut i: CarryLaunchFromFlightInput<T> = unsafe { i.assume_init() };
    i.measured = u32::from(b.byte());
    launch_values(b, &mut i.measured_launch, 1.0);
    if b.flag() {
        launch_values(b, &mut i.measured_sd, 0.01);
    }
    i.observed = u32::from(b.byte());
    let s = &mut i.summaries;
    s.apex_height_m = f(b, -5.0, 60.0);
    s.apex_time_s = f(b, -1.0, 6.0);
    s.carry_m = f(b, -10.0, 320.0);
    s.side_m = f(b, -60.0, 60.0);
    s.flight_time_s = f(b, -1.0, 12.0);
    s.land_angle_rad = f(b, -0.5, 1.6);
    if b.flag() {
        let sd = &mut i.summaries_sd;
        sd.apex_height_m = f(b, -0.1, 5.0);
        sd.carry_m = f(b, -0.1, 5.0);
        sd.side_m = f(b, -0.1, 5.0);
        sd.flight_time_s = f(b, -0.1, 1.0);
        sd.land_angle_rad = f(b, -0.01, 0.1);
    }
    // a track along a straight climb with noise, a Doppler trace; lengths past capacity
    // and NULL arrays with lengths sometimes
    let n_track = usize::from(b.byte() % 72);
    let dt: f64 = b.param(0.001, 0.2);
    let track: Vec<CarryTrackPoint<T>> = (0..n_track)
        .map(|k| {
            let t = dt * (k as f64 + 1.0);
            CarryTrackPoint {
                time_s: lit(t),
                position_m: [lit(60.0 * t), lit(15.0 * t - 4.9 * t * t), lit(0.0)]
                    .map(|x: T| x + f(b, -0.3, 0.3)),
                sd_m: f(b, 0.0, 0.5),
            }
        })
        .collect();
    let n_doppler = usize::from(b.byte()) + if b.flag() { 8 } else { 0 };
    let n_doppler = if b.flag() { n_doppler } else { 0 };
    let doppler: Vec<CarryDopplerSample<T>> = (0..n_doppler)
        .map(|k| CarryDopplerSample {
            time_s: lit(0.01 * (k as f64 + 1.0)),
            radial_speed_mps: lit(70.0 - 5.0 * 0.01 * k as f64),
            sd_mps: lit(0.1),
        })
        .collect();
    i.track = if b.byte() < 8 { null() } else { track.as_ptr() };
    i.track_len = track.len();
    i.doppler = if b.byte() < 8 {
        null()
    } else {
        doppler.as_ptr()
    };
    i.doppler_len = doppler.len();
    i.radar_position_m = a3(b, -5.0, 5.0);
    if b.flag() {
        launch_values(b, &mut i.prior_mean, 1.0);
        launch_values(b, &mut i.prior_sd, 0.1);
        i.wind_prior_sd_mps = f(b, -1.0, 10.0);
        i.air_density_prior_sd_kgm3 = f(b, -0.01, 0.2);
    }
    i.fit_wind = u32::from(b.flag());
    i.fit_air_density = u32::from(b.flag());
    i.max_iterations = u32::from(b.byte() % 40);
    i.scene.aero = selector(b, 2);
    i.settings.integrator = selector(b, 3);
    if i.settings.integrator != CARRY_INTEGRATOR_DP45 {
        // fixed steps of 5 ms or coarser: bounded work. `param` also draws special values
        // and raw bits: a positive step below 5 ms is legal but slow (a subnormal step
        // never reaches the 60 s limit: an explorer's timeout, 2026-11-28), so it is raised
        // to 5 ms; zero, negative and non-finite steps stay (they are refused at once).
        let step: T = f(b, 5e-3, 0.05);
        i.settings.step_s = if step > T::zero() && step < lit(5e-3) {
            lit(5e-3)
        } else {
            step
        };
    }
    let mut w = Box::new(CarryLaunchFromFlightWorkspace {
        scratch: [T::zero(); carry_ffi::launch_fit::CARRY_LAUNCH_FIT_WORKSPACE_LEN],
    });
    let mut o = CarryLaunchFromFlightResult::<T>::refused(0);
    let ip = if b.byte() < 4 { null() } else { &i as *const _ };
    let wp = ptr_or_null(b, &mut *w);
    let op = ptr_or_null(b, &mut o);
    // SAFETY: NULL or live values; the arrays hold their lengths' elements or are NULL.
    let code = unsafe { T::launch_from_flight(ip, wp, op) };
    if code == CarryError::CARRY_OK {
        let v = [
            o.value.ball_speed_mps,
            o.value.launch_angle_rad,
            o.value.launch_direction_rad,
            o.value.spin_radps,
            o.value.spin_axis_rad,
            o.chi2,
            o.flight.carry_m,
        ];
        assert!(finite(&v), "non-finite launch fit: {o:?}");
        let sd = [
            o.sd.ball_speed_mps,
            o.sd.launch_angle_rad,
            o.sd.launch_direction_rad,
            o.sd.spin_radps,
            o.sd.spin_axis_rad,
        ];
        assert!(
            sd.iter()
                .all(|s| to_f64(*s) > 0.0 && to_f64(*s).is_finite()),
            "bad 1σ: {o:?}"
        );
        assert_eq!(o.unidentified, carry_ffi::launch_fit::CARRY_DATUM_NONE);
    }
    if code == CarryError::CARRY_ERR_UNIDENTIFIABLE {
        assert_ne!(
            o.unidentified,
            carry_ffi::launch_fit::CARRY_DATUM_NONE,
            "{o:?}"
        );
    }
    code
}

fn run<T: Api>(b: &mut Bytes<'_>) {
    let mut samples = vec![CarrySample::<T>::default(); 16];
    let capacity = usize::from(b.byte() % 17);
    let with_buffer = b.flag();
    let sp = if with_buffer {
        samples.as_mut_ptr()
    } else {
        null_mut()
    };
    let mut count = usize::MAX;
    let np = ptr_or_null(b, &mut count);
    // 252..=255 (which chose the three others before the estimator was added) estimate,
    // 248..=251 the named-club strike height, 244..=247 the launch from the flight
    let op = b.byte();
    let code = match if op >= 252 {
        3
    } else if op >= 248 {
        4
    } else if op >= 244 {
        5
    } else {
        op % 3
    } {
        3 => estimate_op::<T>(b),
        4 => strike_height_op::<T>(b),
        5 => launch_from_flight_op::<T>(b),
        0 => {
            let mut i = CarryImpactInput::<T>::default();
            mutate_club(b, &mut i.club);
            mutate_delivery(b, &mut i.delivery);
            i.ball.mass_kg = f(b, 0.01, 0.1);
            i.settings.solver = selector(b, 2);
            let mut o = CarryImpactResult::<T>::default();
            let ip = if b.byte() < 8 { null() } else { &i as *const _ };
            let op = ptr_or_null(b, &mut o);
            // SAFETY: NULL or live values.
            let code = unsafe { T::impact(ip, op) };
            if code == CarryError::CARRY_OK {
                check_impact(&o);
            }
            code
        }
        1 => {
            let mut i = CarryFlightInput::<T>::default();
            i.launch = CarryLaunch {
                ball_speed_mps: f(b, 0.0, 150.0),
                launch_angle_rad: f(b, -1.6, 1.6),
                launch_direction_rad: f(b, -3.2, 3.2),
                backspin_radps: f(b, -2200.0, 2200.0),
                sidespin_radps: f(b, -2200.0, 2200.0),
            };
            i.record_interval_s = f(b, 1e-3, 1.0);
            if !mutate_scene(b, &mut i.scene, &mut i.settings) {
                return;
            }
            let mut o = CarryFlightResult::<T>::default();
            let op = ptr_or_null(b, &mut o);
            // SAFETY: NULL or live values; `sp` holds 16 ≥ `capacity` samples.
            let code = unsafe { T::flight(&i, sp, capacity, np, op) };
            if matches!(
                code,
                CarryError::CARRY_OK | CarryError::CARRY_ERR_BUFFER_TOO_SMALL
            ) {
                check_flight(&o);
            }
            code
        }
        _ => {
            let mut i = CarryShotInput::<T>::default();
            mutate_club(b, &mut i.club);
            mutate_delivery(b, &mut i.delivery);
            i.record_interval_s = f(b, 1e-3, 1.0);
            if !mutate_scene(b, &mut i.scene, &mut i.settings) {
                return;
            }
            let mut o = CarryShotResult::<T>::default();
            let op = ptr_or_null(b, &mut o);
            // SAFETY: NULL or live values; `sp` holds 16 ≥ `capacity` samples.
            let code = unsafe { T::shot(&i, sp, capacity, np, op) };
            if matches!(
                code,
                CarryError::CARRY_OK | CarryError::CARRY_ERR_BUFFER_TOO_SMALL
            ) {
                check_impact(&o.impact);
                check_flight(&o.flight);
            }
            code
        }
    };
    assert!(ALL.contains(&code), "not a carry_error_t: {}", code as u32);
    if code == CarryError::CARRY_ERR_BUFFER_TOO_SMALL {
        assert!(with_buffer, "a full buffer without a buffer");
    }
    if with_buffer && !np.is_null() && count != usize::MAX {
        assert!(
            count <= capacity,
            "{count} samples in a buffer of {capacity}"
        );
        for s in &samples[..count] {
            assert!(
                s.time_s.is_finite() && finite(&s.position_m) && finite(&s.velocity_mps),
                "non-finite sample after {code:?}: {s:?}"
            );
        }
    }
}

fuzz_target!(|data: &[u8]| {
    let mut b = Bytes::new(data);
    if b.flag() {
        run::<f32>(&mut b);
    } else {
        run::<f64>(&mut b);
    }
});
