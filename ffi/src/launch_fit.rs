//! The launch from the flight (issue 36): the core's launch fit
//! (`carry_core::launch_fit`, docs/launch_fit.md) behind the C ABI. The launch quantities
//! a monitor did not measure (by default spin and spin axis), each with its 1σ and its
//! source, fitted to what it saw of the flight: summaries, a track of timed positions,
//! timed radial speeds of a Doppler radar. The caller owns the solver's scratch space
//! ([`CarryLaunchFromFlightWorkspace`], 21 KiB in `f32`, 43 KiB in `f64`).

use crate::club::CarryBall;
use crate::error::{
    CARRY_ERR_NULL_POINTER, CARRY_ERR_TOO_MANY_OBSERVATIONS, CARRY_ERR_UNIDENTIFIABLE, CarryError,
    Result,
};
use crate::estimate::{
    CARRY_DATUM_BALL_SPEED, CARRY_DATUM_LAUNCH_ANGLE, CARRY_DATUM_LAUNCH_DIRECTION,
    CARRY_DATUM_SPIN, CARRY_DATUM_SPIN_AXIS, CarryBallData,
};
use crate::scene::CarryScene;
use crate::settings::CarrySettings;
use carry_core::launch_fit::{
    self as lf, Datum, DopplerSample, LaunchValues, MeasuredLaunch, Observations, Observed, Prior,
    Settings, Source, TrackPoint, Workspace,
};
use carry_core::real::Real;
use carry_core::{Error, Field};
use nalgebra::Vector3;

/// Track points an input can hold (`carry_core::launch_fit::MAX_TRACK_POINTS`); more are
/// `CARRY_ERR_TOO_MANY_OBSERVATIONS`.
pub const CARRY_LAUNCH_FIT_MAX_TRACK_POINTS: usize = 64;
/// Doppler samples an input can hold (`MAX_DOPPLER_SAMPLES`).
pub const CARRY_LAUNCH_FIT_MAX_DOPPLER_SAMPLES: usize = 256;
/// Numbers in the solver's scratch space: `(UNKNOWNS + 4) · MAX_ROWS` = 12 · 454.
pub const CARRY_LAUNCH_FIT_WORKSPACE_LEN: usize = 5448;

const _: () = {
    assert!(CARRY_LAUNCH_FIT_MAX_TRACK_POINTS == lf::MAX_TRACK_POINTS);
    assert!(CARRY_LAUNCH_FIT_MAX_DOPPLER_SAMPLES == lf::MAX_DOPPLER_SAMPLES);
    assert!(CARRY_LAUNCH_FIT_WORKSPACE_LEN == (lf::UNKNOWNS + 4) * lf::MAX_ROWS);
    // The core's workspace is `repr(C)` and holds only `T` arrays: the same layout.
    assert!(
        core::mem::size_of::<Workspace<f32>>()
            == core::mem::size_of::<CarryLaunchFromFlightWorkspace<f32>>()
    );
    assert!(
        core::mem::size_of::<Workspace<f64>>()
            == core::mem::size_of::<CarryLaunchFromFlightWorkspace<f64>>()
    );
    assert!(
        core::mem::align_of::<Workspace<f64>>()
            == core::mem::align_of::<CarryLaunchFromFlightWorkspace<f64>>()
    );
};

/// `CarryLaunchFromFlightInput::measured` bit: the ball speed was measured.
pub const CARRY_MEASURED_BALL_SPEED: u32 = 1;
/// `CarryLaunchFromFlightInput::measured` bit: the launch angle was measured.
pub const CARRY_MEASURED_LAUNCH_ANGLE: u32 = 2;
/// `CarryLaunchFromFlightInput::measured` bit: the launch direction was measured.
pub const CARRY_MEASURED_LAUNCH_DIRECTION: u32 = 4;
/// `CarryLaunchFromFlightInput::measured` bit: the spin rate was measured.
pub const CARRY_MEASURED_SPIN: u32 = 8;
/// `CarryLaunchFromFlightInput::measured` bit: the spin axis was measured.
pub const CARRY_MEASURED_SPIN_AXIS: u32 = 16;

/// `CarryLaunchFromFlightInput::observed` bit (and `worst_observation` code): apex height.
pub const CARRY_OBSERVED_APEX_HEIGHT: u32 = 1;
/// `observed` bit: time of the apex.
pub const CARRY_OBSERVED_APEX_TIME: u32 = 2;
/// `observed` bit: carry.
pub const CARRY_OBSERVED_CARRY: u32 = 4;
/// `observed` bit: side at the landing.
pub const CARRY_OBSERVED_SIDE: u32 = 8;
/// `observed` bit: flight time.
pub const CARRY_OBSERVED_FLIGHT_TIME: u32 = 16;
/// `observed` bit: landing angle.
pub const CARRY_OBSERVED_LAND_ANGLE: u32 = 32;
/// `CarryLaunchFromFlightResult::worst_observation`: a coordinate (`worst_axis`: 0 x, 1 y,
/// 2 z) of track point `worst_index`.
pub const CARRY_OBSERVED_TRACK: u32 = 64;
/// `worst_observation`: Doppler sample `worst_index`.
pub const CARRY_OBSERVED_DOPPLER: u32 = 128;

/// `CarryLaunchSources` field: measured at launch (refined by the flight within its 1σ).
pub const CARRY_SOURCE_MEASURED: u32 = 0;
/// `CarryLaunchSources` field: not measured, fitted to the flight.
pub const CARRY_SOURCE_FITTED: u32 = 1;

/// `CarryLaunchFromFlightResult::unidentified` (with `CARRY_ERR_UNIDENTIFIABLE`): the
/// fitted uniform wind. (The launch quantities use `CARRY_DATUM_BALL_SPEED` …
/// `CARRY_DATUM_SPIN_AXIS`.)
pub const CARRY_DATUM_WIND: u32 = 11;
/// `unidentified`: the fitted air density.
pub const CARRY_DATUM_AIR_DENSITY: u32 = 12;
/// `unidentified`: none (the call did not return `CARRY_ERR_UNIDENTIFIABLE`).
pub const CARRY_DATUM_NONE: u32 = 255;

/// The flight summaries a monitor reports (m, s, rad), or their 1σ.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CarryFlightSummaries<T> {
    /// Apex height above the tee's ground (m).
    pub apex_height_m: T,
    /// Time of the apex (s).
    pub apex_time_s: T,
    /// Carry: horizontal distance from the tee to the landing (m).
    pub carry_m: T,
    /// Side at the landing, + right (m).
    pub side_m: T,
    /// Flight time (s).
    pub flight_time_s: T,
    /// Landing angle below the horizontal (rad).
    pub land_angle_rad: T,
}

/// A timed position of the ball (a radar's or a camera's track point).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CarryTrackPoint<T> {
    /// Time since launch (s), not before the previous point's.
    pub time_s: T,
    /// Position (m, global frame: x downrange, y up, z right; the tee at the origin).
    pub position_m: [T; 3],
    /// 1σ of each coordinate (m), positive.
    pub sd_m: T,
}

/// A timed speed along the radar's line of sight, + away from the radar.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CarryDopplerSample<T> {
    /// Time since launch (s), not before the previous sample's.
    pub time_s: T,
    /// Radial speed (m/s).
    pub radial_speed_mps: T,
    /// Its 1σ (m/s), positive.
    pub sd_mps: T,
}

/// What `carry_launch_from_flight_*` needs. Start from
/// `carry_launch_from_flight_input_default_*`, set the `measured` launch and the `observed`
/// summaries (each with its 1σ), and point `track`/`doppler` at the caller's arrays.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarryLaunchFromFlightInput<T> {
    /// The ball.
    pub ball: CarryBall<T>,
    /// The flight's scene (aerodynamic model, air, wind, landing height; its ground is not
    /// used: the observations are of the flight).
    pub scene: CarryScene<T>,
    /// The flights' integrator (`solver` is not used).
    pub settings: CarrySettings<T>,
    /// Which launch quantities were measured: an OR of `CARRY_MEASURED_BALL_SPEED` …
    /// `CARRY_MEASURED_SPIN_AXIS`; the others are fitted.
    pub measured: u32,
    /// The measured launch (only the fields `measured` names are read).
    pub measured_launch: CarryBallData<T>,
    /// Their 1σ (positive).
    pub measured_sd: CarryBallData<T>,
    /// Which summaries were observed: an OR of `CARRY_OBSERVED_APEX_HEIGHT` …
    /// `CARRY_OBSERVED_LAND_ANGLE`.
    pub observed: u32,
    /// The observed summaries (only the fields `observed` names are read).
    pub summaries: CarryFlightSummaries<T>,
    /// Their 1σ (positive).
    pub summaries_sd: CarryFlightSummaries<T>,
    /// `track_len` timed positions in time order (may be NULL when `track_len` is 0).
    pub track: *const CarryTrackPoint<T>,
    /// Number of track points, at most `CARRY_LAUNCH_FIT_MAX_TRACK_POINTS`.
    pub track_len: usize,
    /// `doppler_len` timed radial speeds in time order (may be NULL when `doppler_len` is 0).
    pub doppler: *const CarryDopplerSample<T>,
    /// Number of Doppler samples, at most `CARRY_LAUNCH_FIT_MAX_DOPPLER_SAMPLES`.
    pub doppler_len: usize,
    /// Where the Doppler radar is (m, global frame; default 2.5 m behind the tee, 0.3 m up).
    pub radar_position_m: [T; 3],
    /// Prior mean of each launch quantity (used where not measured).
    pub prior_mean: CarryBallData<T>,
    /// Prior spread (1σ) of each launch quantity.
    pub prior_sd: CarryBallData<T>,
    /// Prior 1σ of each horizontal wind component when fitted (m/s).
    pub wind_prior_sd_mps: T,
    /// Prior 1σ of the air density when fitted (kg/m³; its mean: the scene's).
    pub air_density_prior_sd_kgm3: T,
    /// Non-zero: also fit a uniform horizontal wind (x, z) instead of the scene's.
    pub fit_wind: u32,
    /// Non-zero: also fit the air density instead of the scene's.
    pub fit_air_density: u32,
    /// Iteration budget, 1..=65535.
    pub max_iterations: u32,
    /// Stop when the Newton step is below this many posterior σ (positive).
    pub tolerance: T,
}

/// The solver's scratch space, owned by the caller (e.g. a `static` on a microcontroller):
/// `CARRY_LAUNCH_FIT_WORKSPACE_LEN` numbers. Its contents need no initialisation and mean
/// nothing after the call.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct CarryLaunchFromFlightWorkspace<T> {
    /// Scratch.
    pub scratch: [T; CARRY_LAUNCH_FIT_WORKSPACE_LEN],
}

/// Where each launch figure came from: `CARRY_SOURCE_MEASURED` or `CARRY_SOURCE_FITTED`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct CarryLaunchSources {
    /// Ball speed.
    pub ball_speed: u32,
    /// Launch angle.
    pub launch_angle: u32,
    /// Launch direction.
    pub launch_direction: u32,
    /// Spin rate.
    pub spin: u32,
    /// Spin axis.
    pub spin_axis: u32,
}

/// The fitted launch.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CarryLaunchFromFlightResult<T> {
    /// The launch quantities (posterior mode; m/s, rad, rad/s).
    pub value: CarryBallData<T>,
    /// Their 1σ.
    pub sd: CarryBallData<T>,
    /// Where each came from.
    pub source: CarryLaunchSources,
    /// 1 when the wind was fitted (then `wind_mps`, `wind_sd_mps` hold it), else 0.
    pub wind_fitted: u32,
    /// The fitted uniform wind (x downrange, z right; m/s).
    pub wind_mps: [T; 2],
    /// Its 1σ.
    pub wind_sd_mps: [T; 2],
    /// 1 when the air density was fitted, else 0.
    pub air_density_fitted: u32,
    /// The fitted air density (kg/m³).
    pub air_density_kgm3: T,
    /// Its 1σ.
    pub air_density_sd_kgm3: T,
    /// The fitted launch's flight through the (fitted) scene, no ground: apex height, apex
    /// time, carry, side, flight time, landing angle.
    pub flight: CarryFlightSummaries<T>,
    /// `Σ ((model − observed)/σ)²` over the flight observations at the fit.
    pub chi2: T,
    /// Flight observations (residual rows) used.
    pub observations: u32,
    /// The observation the fit misses most: a `CARRY_OBSERVED_*` code.
    pub worst_observation: u32,
    /// Its track point or Doppler sample index (`CARRY_OBSERVED_TRACK`, `_DOPPLER`).
    pub worst_index: u32,
    /// Its coordinate (0 x, 1 y, 2 z) for `CARRY_OBSERVED_TRACK`.
    pub worst_axis: u32,
    /// By how many of its σ (signed: model − observed).
    pub worst_residual_sd: T,
    /// Levenberg–Marquardt iterations.
    pub iterations: u32,
    /// Flights flown (the cost).
    pub flights: u32,
    /// With `CARRY_ERR_UNIDENTIFIABLE`: the unknown the observations do not determine
    /// (`CARRY_DATUM_BALL_SPEED` … `CARRY_DATUM_SPIN_AXIS`, `CARRY_DATUM_WIND`,
    /// `CARRY_DATUM_AIR_DENSITY`); otherwise `CARRY_DATUM_NONE`.
    pub unidentified: u32,
}

fn values_c<T: Copy>(v: &LaunchValues<T>) -> CarryBallData<T> {
    CarryBallData {
        ball_speed_mps: v.ball_speed_mps,
        launch_angle_rad: v.launch_angle_rad,
        launch_direction_rad: v.launch_direction_rad,
        spin_radps: v.spin_radps,
        spin_axis_rad: v.spin_axis_rad,
    }
}

fn values_core<T: Copy>(b: &CarryBallData<T>) -> LaunchValues<T> {
    LaunchValues {
        ball_speed_mps: b.ball_speed_mps,
        launch_angle_rad: b.launch_angle_rad,
        launch_direction_rad: b.launch_direction_rad,
        spin_radps: b.spin_radps,
        spin_axis_rad: b.spin_axis_rad,
    }
}

fn source_code(s: Source) -> u32 {
    match s {
        Source::Measured => CARRY_SOURCE_MEASURED,
        Source::Fitted => CARRY_SOURCE_FITTED,
    }
}

/// The `CARRY_DATUM_*` code of an unknown the core names.
fn unknown_code(f: Field) -> u32 {
    match f {
        Field::BallSpeed => CARRY_DATUM_BALL_SPEED,
        Field::LaunchAngle => CARRY_DATUM_LAUNCH_ANGLE,
        Field::LaunchDirection => CARRY_DATUM_LAUNCH_DIRECTION,
        Field::BallSpin => CARRY_DATUM_SPIN,
        Field::SpinAxis => CARRY_DATUM_SPIN_AXIS,
        Field::Wind => CARRY_DATUM_WIND,
        Field::AirDensity => CARRY_DATUM_AIR_DENSITY,
        _ => CARRY_DATUM_NONE,
    }
}

/// The `CARRY_OBSERVED_*` code, index and axis of an observation.
fn observed_code(o: Observed) -> (u32, u32, u32) {
    match o {
        Observed::Track { index, axis } => {
            (CARRY_OBSERVED_TRACK, u32::from(index), u32::from(axis))
        }
        Observed::Doppler(i) => (CARRY_OBSERVED_DOPPLER, u32::from(i), 0),
        Observed::ApexHeight => (CARRY_OBSERVED_APEX_HEIGHT, 0, 0),
        Observed::ApexTime => (CARRY_OBSERVED_APEX_TIME, 0, 0),
        Observed::Carry => (CARRY_OBSERVED_CARRY, 0, 0),
        Observed::Side => (CARRY_OBSERVED_SIDE, 0, 0),
        Observed::FlightTime => (CARRY_OBSERVED_FLIGHT_TIME, 0, 0),
        Observed::LandAngle => (CARRY_OBSERVED_LAND_ANGLE, 0, 0),
        _ => (0, 0, 0),
    }
}

impl<T: Real> CarryLaunchFromFlightInput<T> {
    /// The defaults: the standard ball, the default scene and integrator, nothing measured
    /// or observed (zero values, 1σ the CLI's defaults: 0.2 m/s, 0.2°, 0.3°, 150 rpm, 2°;
    /// apex 0.5 m, apex time 0.1 s, carry 1 m, side 0.5 m, flight time 0.05 s, landing
    /// 0.5°), no track, the radar 2.5 m behind the tee at 0.3 m, the core's broad priors,
    /// launch only, 30 iterations, tolerance 1e-3.
    #[must_use]
    pub fn typical() -> Self {
        use carry_core::real::lit;
        use carry_core::units::{deg, rpm};
        let s = Settings::<T>::default();
        let o = Observations::<T>::default();
        let r = o.radar_position_m;
        Self {
            ball: CarryBall::standard(),
            scene: CarryScene::default(),
            settings: CarrySettings::default(),
            measured: 0,
            measured_launch: values_c(&LaunchValues::from_array([T::zero(); 5])),
            measured_sd: CarryBallData {
                ball_speed_mps: lit(0.2),
                launch_angle_rad: deg(lit(0.2)),
                launch_direction_rad: deg(lit(0.3)),
                spin_radps: rpm(lit(150.0)),
                spin_axis_rad: deg(lit(2.0)),
            },
            observed: 0,
            summaries: CarryFlightSummaries::default_zero(),
            summaries_sd: CarryFlightSummaries {
                apex_height_m: lit(0.5),
                apex_time_s: lit(0.1),
                carry_m: lit(1.0),
                side_m: lit(0.5),
                flight_time_s: lit(0.05),
                land_angle_rad: deg(lit(0.5)),
            },
            track: core::ptr::null(),
            track_len: 0,
            doppler: core::ptr::null(),
            doppler_len: 0,
            radar_position_m: [r.x, r.y, r.z],
            prior_mean: values_c(&s.prior.mean),
            prior_sd: values_c(&s.prior.sd),
            wind_prior_sd_mps: s.prior.wind_sd_mps,
            air_density_prior_sd_kgm3: s.prior.air_density_sd_kgm3,
            fit_wind: 0,
            fit_air_density: 0,
            max_iterations: u32::from(s.max_iterations),
            tolerance: s.tolerance,
        }
    }
}

impl<T: Real> CarryLaunchFromFlightResult<T> {
    /// All zeros, naming the unknown the observations do not determine.
    #[must_use]
    pub fn refused(unidentified: u32) -> Self {
        let zero = values_c(&LaunchValues::from_array([T::zero(); 5]));
        Self {
            value: zero,
            sd: zero,
            source: CarryLaunchSources::default(),
            wind_fitted: 0,
            wind_mps: [T::zero(); 2],
            wind_sd_mps: [T::zero(); 2],
            air_density_fitted: 0,
            air_density_kgm3: T::zero(),
            air_density_sd_kgm3: T::zero(),
            flight: CarryFlightSummaries::default_zero(),
            chi2: T::zero(),
            observations: 0,
            worst_observation: 0,
            worst_index: 0,
            worst_axis: 0,
            worst_residual_sd: T::zero(),
            iterations: 0,
            flights: 0,
            unidentified,
        }
    }
}

impl<T: Real> CarryFlightSummaries<T> {
    fn default_zero() -> Self {
        Self {
            apex_height_m: T::zero(),
            apex_time_s: T::zero(),
            carry_m: T::zero(),
            side_m: T::zero(),
            flight_time_s: T::zero(),
            land_angle_rad: T::zero(),
        }
    }
}

/// Hands `push` each of `len` elements of a caller array (unaligned reads allowed), at most
/// `max`.
///
/// # Safety
/// `p` is NULL (then `len` must be 0) or points to `len` readable elements.
unsafe fn read_array<E: Copy>(
    p: *const E,
    len: usize,
    max: usize,
    mut push: impl FnMut(E) -> bool,
) -> Result<()> {
    if len == 0 {
        return Ok(());
    }
    if p.is_null() {
        return Err(CARRY_ERR_NULL_POINTER);
    }
    if len > max {
        return Err(CARRY_ERR_TOO_MANY_OBSERVATIONS);
    }
    for k in 0..len {
        // SAFETY: `k < len` elements are readable (the caller's contract); unaligned reads
        // are allowed; every bit pattern is a valid plain-float element.
        let e = unsafe { p.add(k).read_unaligned() };
        if !push(e) {
            return Err(CARRY_ERR_TOO_MANY_OBSERVATIONS);
        }
    }
    Ok(())
}

/// The fit of `input`, or the error with the unknown the observations do not determine
/// (for `CARRY_ERR_UNIDENTIFIABLE`).
///
/// # Errors
/// `CARRY_ERR_NULL_POINTER` for a NULL array with a length, `CARRY_ERR_TOO_MANY_OBSERVATIONS`,
/// `CARRY_ERR_UNKNOWN_OPTION` for an unknown scene or integrator selector, and the core's
/// (`CARRY_ERR_INVALID_INPUT`, `CARRY_ERR_TOO_FEW_OBSERVATIONS`, `CARRY_ERR_UNIDENTIFIABLE`,
/// `CARRY_ERR_NO_CONVERGENCE`, `CARRY_ERR_ILL_POSED`, a flight's).
///
/// # Safety
/// `input.track` and `input.doppler` are NULL or point to their lengths' elements.
pub unsafe fn run<T: Real>(
    input: &CarryLaunchFromFlightInput<T>,
    workspace: &mut Workspace<T>,
) -> core::result::Result<CarryLaunchFromFlightResult<T>, (CarryError, u32)> {
    let plain = |e: CarryError| (e, CARRY_DATUM_NONE);
    let ball = input.ball.ball().map_err(plain)?;
    let scene = input.scene.scene().map_err(plain)?;
    let integrator = input.settings.integrator().map_err(plain)?;
    let has = |bits: u32, bit: u32| bits & bit != 0;
    let m = &input.measured_launch;
    let msd = &input.measured_sd;
    let pick = |bit: u32, v: T, sd: T| has(input.measured, bit).then(|| Datum::new(v, sd));
    let measured: MeasuredLaunch<T> = LaunchValues {
        ball_speed_mps: pick(
            CARRY_MEASURED_BALL_SPEED,
            m.ball_speed_mps,
            msd.ball_speed_mps,
        ),
        launch_angle_rad: pick(
            CARRY_MEASURED_LAUNCH_ANGLE,
            m.launch_angle_rad,
            msd.launch_angle_rad,
        ),
        launch_direction_rad: pick(
            CARRY_MEASURED_LAUNCH_DIRECTION,
            m.launch_direction_rad,
            msd.launch_direction_rad,
        ),
        spin_radps: pick(CARRY_MEASURED_SPIN, m.spin_radps, msd.spin_radps),
        spin_axis_rad: pick(CARRY_MEASURED_SPIN_AXIS, m.spin_axis_rad, msd.spin_axis_rad),
    };
    let s = &input.summaries;
    let ssd = &input.summaries_sd;
    let seen = |bit: u32, v: T, sd: T| has(input.observed, bit).then(|| Datum::new(v, sd));
    let mut obs = Observations {
        radar_position_m: Vector3::from(input.radar_position_m),
        apex_height_m: seen(
            CARRY_OBSERVED_APEX_HEIGHT,
            s.apex_height_m,
            ssd.apex_height_m,
        ),
        apex_time_s: seen(CARRY_OBSERVED_APEX_TIME, s.apex_time_s, ssd.apex_time_s),
        carry_m: seen(CARRY_OBSERVED_CARRY, s.carry_m, ssd.carry_m),
        side_m: seen(CARRY_OBSERVED_SIDE, s.side_m, ssd.side_m),
        flight_time_s: seen(
            CARRY_OBSERVED_FLIGHT_TIME,
            s.flight_time_s,
            ssd.flight_time_s,
        ),
        land_angle_rad: seen(
            CARRY_OBSERVED_LAND_ANGLE,
            s.land_angle_rad,
            ssd.land_angle_rad,
        ),
        ..Observations::default()
    };
    // SAFETY: the caller's contract on the arrays, forwarded.
    unsafe {
        read_array(input.track, input.track_len, lf::MAX_TRACK_POINTS, |p| {
            let point = TrackPoint {
                time_s: p.time_s,
                position_m: Vector3::from(p.position_m),
                sd_m: p.sd_m,
            };
            obs.track.push(point).is_ok()
        })
        .map_err(plain)?;
        read_array(
            input.doppler,
            input.doppler_len,
            lf::MAX_DOPPLER_SAMPLES,
            |d| {
                let sample = DopplerSample {
                    time_s: d.time_s,
                    radial_speed_mps: d.radial_speed_mps,
                    sd_mps: d.sd_mps,
                };
                obs.doppler.push(sample).is_ok()
            },
        )
        .map_err(plain)?;
    }
    let settings = Settings {
        prior: Prior {
            mean: values_core(&input.prior_mean),
            sd: values_core(&input.prior_sd),
            wind_sd_mps: input.wind_prior_sd_mps,
            air_density_sd_kgm3: input.air_density_prior_sd_kgm3,
        },
        fit_wind: input.fit_wind != 0,
        fit_air_density: input.fit_air_density != 0,
        integrator,
        // past u16: 0, the core's Iterations error
        max_iterations: u16::try_from(input.max_iterations).unwrap_or(0),
        tolerance: input.tolerance,
    };
    let f =
        lf::fit_launch(&ball, &scene, &measured, &obs, &settings, workspace).map_err(
            |e| match e {
                Error::Unidentifiable(field) => (CARRY_ERR_UNIDENTIFIABLE, unknown_code(field)),
                other => plain(other.into()),
            },
        )?;
    let (worst_observation, worst_index, worst_axis) = observed_code(f.worst_observation);
    let zero = Datum::new(T::zero(), T::zero());
    let [wx, wz] = f.wind_mps.unwrap_or([zero; 2]);
    let rho = f.air_density_kgm3.unwrap_or(zero);
    let g = &f.flight;
    Ok(CarryLaunchFromFlightResult {
        value: values_c(&f.value),
        sd: values_c(&f.sd),
        source: CarryLaunchSources {
            ball_speed: source_code(f.source.ball_speed_mps),
            launch_angle: source_code(f.source.launch_angle_rad),
            launch_direction: source_code(f.source.launch_direction_rad),
            spin: source_code(f.source.spin_radps),
            spin_axis: source_code(f.source.spin_axis_rad),
        },
        wind_fitted: u32::from(f.wind_mps.is_some()),
        wind_mps: [wx.value, wz.value],
        wind_sd_mps: [wx.sd, wz.sd],
        air_density_fitted: u32::from(f.air_density_kgm3.is_some()),
        air_density_kgm3: rho.value,
        air_density_sd_kgm3: rho.sd,
        flight: CarryFlightSummaries {
            apex_height_m: g.apex_m,
            apex_time_s: g.apex_time_s,
            carry_m: g.carry_m,
            side_m: g.side_m,
            flight_time_s: g.flight_time_s,
            land_angle_rad: g.landing_angle_rad,
        },
        chi2: f.chi2,
        observations: u32::from(f.observations),
        worst_observation,
        worst_index,
        worst_axis,
        worst_residual_sd: f.worst_residual_sigma,
        iterations: u32::from(f.iterations),
        flights: u32::from(f.flights),
        unidentified: CARRY_DATUM_NONE,
    })
}

/// The core's workspace over the caller's scratch.
pub(crate) fn workspace<T: Real>(w: &mut CarryLaunchFromFlightWorkspace<T>) -> &mut Workspace<T> {
    let p = core::ptr::from_mut(w).cast::<Workspace<T>>();
    // SAFETY: both types are `repr(C)` and nothing but `T` arrays of the same total length
    // (the size and alignment are asserted above), so the one is the other's layout; every
    // bit pattern of a float is a valid `T`; the borrow is `w`'s.
    unsafe { &mut *p }
}
