//! The launch from the flight (issue 36): spin, and whatever else of the launch a monitor
//! did not measure, fitted to what it saw of the ball's flight.
//!
//! A radar tracks the ball for one to six seconds, a Doppler unit sees its speed along the
//! line of sight, many monitors report the apex and the landing. The flight model run
//! backwards against those observations gives the launch quantities that were not measured
//! (by default spin rate and spin axis), and on request a uniform wind and the air density,
//! as the maximum a posteriori point of a Gaussian model:
//!
//! ```text
//! x̂ = argmin Σ_k ((h_k(x) − z_k)/σ_k)²  +  Σ_i q_i (x_i − m_i)²
//!              flight observations          measured launch (m = value, q = 1/σ²)
//!                                           and priors (m = mean, q = 1/s²)
//! ```
//!
//! with `x = (ball speed, launch angle, launch direction, spin, spin axis, wind x, wind z,
//! air density)`, `h` the flight ([`crate::PreparedScene::fly`]) read at the observation
//! times from the integrator's dense output ([`crate::Recorder::at_times`]: one flight per
//! evaluation, however many observations), and `z` the observations ([`Observations`]):
//! timed 3-D positions, timed radial speeds seen by a radar at a given position (Doppler),
//! apex height and time, carry, side, flight time and landing angle, each with its 1σ.
//! Levenberg–Marquardt ([`solve`]) on the normal equations with a forward-difference
//! Jacobian (one flight per free unknown per iteration, the sensitivities computed once per
//! iteration), a scaled Cholesky factorisation, and a bounded number of iterations. The 1σ
//! of every unknown is the Laplace posterior's, `√diag (JᵀJ + Q)⁻¹` at the solution.
//!
//! What the data must do, else a typed error, never a silent guess:
//! - at least as many observations as free unknowns ([`Error::TooFewObservations`]);
//! - shrink each free unknown's spread below [`IDENTIFIED_RATIO`] of its prior's
//!   ([`Error::Unidentifiable`] naming the unknown);
//! - converge within the iteration budget ([`Error::NoConvergence`]).
//!
//! Capacity is fixed: [`MAX_TRACK_POINTS`] positions and [`MAX_DOPPLER_SAMPLES`] radial
//! speeds; the caller owns the [`Workspace`] (the Jacobian's columns), so nothing is
//! allocated and the stack stays small on a microcontroller. docs/launch_fit.md has what
//! each observation identifies and the accuracy against cost.

mod model;
mod solve;

pub use model::Observed;

use crate::ball::Ball;
use crate::error::{Error, Field, Reason, Result};
use crate::flight::FlightOutcome;
use crate::integrator::Integrator;
use crate::launch::Launch;
use crate::real::{Real, lit};
use crate::scene::Scene;
use crate::units::{deg, rpm};
use nalgebra::Vector3;

/// Track points (timed 3-D positions) an observation set can hold.
pub const MAX_TRACK_POINTS: usize = 64;
/// Doppler samples (timed radial speeds) an observation set can hold.
pub const MAX_DOPPLER_SAMPLES: usize = 256;
/// Summary observations: apex height, apex time, carry, side, flight time, landing angle.
pub const SUMMARIES: usize = 6;
/// Residual rows at most: three per track point, one per Doppler sample, the summaries.
pub const MAX_ROWS: usize = 3 * MAX_TRACK_POINTS + MAX_DOPPLER_SAMPLES + SUMMARIES;
/// Unknowns: ball speed, launch angle, launch direction, spin, spin axis, wind x, wind z,
/// air density.
pub const UNKNOWNS: usize = 8;
/// A free unknown counts as identified when the data shrink its 1σ below this fraction of
/// its prior's (docs/launch_fit.md: 0.8, i.e. the observations carry at least 36 % of the
/// information about it).
pub const IDENTIFIED_RATIO: f64 = 0.8;

/// One observed or measured number and its 1σ (same unit).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Datum<T> {
    /// The value.
    pub value: T,
    /// Its 1σ noise, positive.
    pub sd: T,
}

impl<T> Datum<T> {
    /// A value with 1σ `sd`.
    pub const fn new(value: T, sd: T) -> Self {
        Self { value, sd }
    }
}

/// A timed position of the ball (a radar's or a camera's track point).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct TrackPoint<T: Real> {
    /// Time since launch (s).
    pub time_s: T,
    /// Position (m, G: x downrange, y up, z right; the tee at the origin).
    pub position_m: Vector3<T>,
    /// 1σ of each coordinate (m), positive.
    pub sd_m: T,
}

/// A timed speed along the line of sight of the radar (Doppler): `v · (p − r)/|p − r|`,
/// positive when the ball moves away from the radar at `r`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct DopplerSample<T> {
    /// Time since launch (s).
    pub time_s: T,
    /// Radial speed (m/s), + away from the radar.
    pub radial_speed_mps: T,
    /// Its 1σ (m/s), positive.
    pub sd_mps: T,
}

/// What a monitor saw of the flight: any subset, each with its 1σ.
#[derive(Debug, Clone, PartialEq)]
pub struct Observations<T: Real> {
    /// Timed positions, in time order.
    pub track: heapless::Vec<TrackPoint<T>, MAX_TRACK_POINTS>,
    /// Timed radial speeds, in time order.
    pub doppler: heapless::Vec<DopplerSample<T>, MAX_DOPPLER_SAMPLES>,
    /// Where the Doppler radar is (m, G), e.g. 2.5 m behind the tee at 0.3 m height.
    pub radar_position_m: Vector3<T>,
    /// Apex height above the tee's ground (m).
    pub apex_height_m: Option<Datum<T>>,
    /// Time of the apex (s).
    pub apex_time_s: Option<Datum<T>>,
    /// Carry: horizontal distance from the tee to the landing (m).
    pub carry_m: Option<Datum<T>>,
    /// Side at the landing, + right (m).
    pub side_m: Option<Datum<T>>,
    /// Flight time (s).
    pub flight_time_s: Option<Datum<T>>,
    /// Landing angle below the horizontal (rad).
    pub land_angle_rad: Option<Datum<T>>,
}

impl<T: Real> Default for Observations<T> {
    /// Nothing observed; the radar 2.5 m behind the tee, 0.3 m up.
    fn default() -> Self {
        Self {
            track: heapless::Vec::new(),
            doppler: heapless::Vec::new(),
            radar_position_m: Vector3::new(lit(-2.5), lit(0.3), T::zero()),
            apex_height_m: None,
            apex_time_s: None,
            carry_m: None,
            side_m: None,
            flight_time_s: None,
            land_angle_rad: None,
        }
    }
}

impl<T: Real> Observations<T> {
    /// The summaries in [`Observed`] order (apex height, apex time, carry, side, flight
    /// time, landing angle).
    #[must_use]
    pub fn summaries(&self) -> [Option<Datum<T>>; SUMMARIES] {
        [
            self.apex_height_m,
            self.apex_time_s,
            self.carry_m,
            self.side_m,
            self.flight_time_s,
            self.land_angle_rad,
        ]
    }

    /// The number of residual rows: three per track point, one per Doppler sample and
    /// summary.
    #[must_use]
    pub fn rows(&self) -> usize {
        3 * self.track.len()
            + self.doppler.len()
            + self.summaries().iter().filter(|s| s.is_some()).count()
    }

    /// Checks every observation: finite, 1σ positive, times not negative and in order
    /// within the track and within the Doppler trace, the radar position finite.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] with [`Field::Observation`] (a value or time) or
    /// [`Field::MeasurementNoise`] (a 1σ).
    pub fn validate(&self) -> Result<()> {
        let bad = |f| Err(Error::invalid(f, Reason::OutOfRange));
        let mut last = T::zero();
        for p in &self.track {
            if !(p.time_s.is_finite()
                && p.time_s >= last
                && crate::real::all_finite(p.position_m.as_slice()))
            {
                return bad(Field::Observation);
            }
            if !(p.sd_m > T::zero() && p.sd_m.is_finite()) {
                return bad(Field::MeasurementNoise);
            }
            last = p.time_s;
        }
        last = T::zero();
        for d in &self.doppler {
            if !(d.time_s.is_finite() && d.time_s >= last && d.radial_speed_mps.is_finite()) {
                return bad(Field::Observation);
            }
            if !(d.sd_mps > T::zero() && d.sd_mps.is_finite()) {
                return bad(Field::MeasurementNoise);
            }
            last = d.time_s;
        }
        if !self.doppler.is_empty() && !crate::real::all_finite(self.radar_position_m.as_slice()) {
            return bad(Field::Observation);
        }
        for s in self.summaries().iter().flatten() {
            if !s.value.is_finite() {
                return bad(Field::Observation);
            }
            if !(s.sd > T::zero() && s.sd.is_finite()) {
                return bad(Field::MeasurementNoise);
            }
        }
        Ok(())
    }
}

/// The launch quantities, SI: the unknowns' first five entries. Also their measurements
/// (each `Option`), priors and 1σ.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LaunchValues<T> {
    /// Ball speed (m/s).
    pub ball_speed_mps: T,
    /// Launch angle, + up (rad).
    pub launch_angle_rad: T,
    /// Launch direction, + right (rad).
    pub launch_direction_rad: T,
    /// Total spin (rad/s).
    pub spin_radps: T,
    /// Spin axis, + tilted right (rad).
    pub spin_axis_rad: T,
}

impl<T: Copy> LaunchValues<T> {
    /// In unknown order.
    pub fn to_array(&self) -> [T; 5] {
        [
            self.ball_speed_mps,
            self.launch_angle_rad,
            self.launch_direction_rad,
            self.spin_radps,
            self.spin_axis_rad,
        ]
    }

    /// From unknown order.
    pub fn from_array(a: [T; 5]) -> Self {
        let [
            ball_speed_mps,
            launch_angle_rad,
            launch_direction_rad,
            spin_radps,
            spin_axis_rad,
        ] = a;
        Self {
            ball_speed_mps,
            launch_angle_rad,
            launch_direction_rad,
            spin_radps,
            spin_axis_rad,
        }
    }
}

/// The launch quantities a monitor measured, each with its 1σ (`None`: not measured, to
/// be fitted to the flight).
pub type MeasuredLaunch<T> = LaunchValues<Option<Datum<T>>>;

impl<T> Default for LaunchValues<Option<Datum<T>>> {
    /// Nothing measured.
    fn default() -> Self {
        Self {
            ball_speed_mps: None,
            launch_angle_rad: None,
            launch_direction_rad: None,
            spin_radps: None,
            spin_axis_rad: None,
        }
    }
}

/// Where a launch figure came from, as commercial monitors report it (Garmin's spin
/// calculation type, TrackMan's reduced-accuracy list).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Source {
    /// Measured at launch (and refined by the flight within its 1σ).
    Measured,
    /// Not measured: fitted to the flight.
    Fitted,
}

impl Source {
    /// `measured` or `fitted to the flight`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Measured => "measured",
            Self::Fitted => "fitted to the flight",
        }
    }
}

/// The prior of every unknown: a Gaussian mean and 1σ (SI), used where nothing measured
/// it. Engineering defaults spanning golf shots (docs/launch_fit.md), overridable.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Prior<T> {
    /// Means of the launch quantities.
    pub mean: LaunchValues<T>,
    /// Their 1σ.
    pub sd: LaunchValues<T>,
    /// 1σ of each horizontal wind component (m/s; mean: no wind), when fitted.
    pub wind_sd_mps: T,
    /// Mean and 1σ of the air density (kg/m³), when fitted (the mean: the scene's).
    pub air_density_sd_kgm3: T,
}

impl<T: Real> Prior<T> {
    /// Broad defaults over golf shots: ball speed 55 ± 25 m/s, launch 14 ± 10°, direction
    /// 0 ± 10°, spin 4,000 ± 3,000 rpm, axis 0 ± 20°; wind 5 m/s per component; air density
    /// ± 0.08 kg/m³ (sea level to about 1,000 m, hot to cold).
    #[must_use]
    pub fn broad() -> Self {
        Self {
            mean: LaunchValues {
                ball_speed_mps: lit(55.0),
                launch_angle_rad: deg(lit(14.0)),
                launch_direction_rad: T::zero(),
                spin_radps: rpm(lit(4000.0)),
                spin_axis_rad: T::zero(),
            },
            sd: LaunchValues {
                ball_speed_mps: lit(25.0),
                launch_angle_rad: deg(lit(10.0)),
                launch_direction_rad: deg(lit(10.0)),
                spin_radps: rpm(lit(3000.0)),
                spin_axis_rad: deg(lit(20.0)),
            },
            wind_sd_mps: lit(5.0),
            air_density_sd_kgm3: lit(0.08),
        }
    }
}

/// How to fit.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Settings<T> {
    /// The priors.
    pub prior: Prior<T>,
    /// Fit a uniform horizontal wind (x, z) instead of the scene's wind.
    pub fit_wind: bool,
    /// Fit the air density instead of the scene's.
    pub fit_air_density: bool,
    /// The flights' integrator.
    pub integrator: Integrator<T>,
    /// Iteration budget.
    pub max_iterations: u16,
    /// Stop when the Newton step is below this many posterior σ (or when the cost's
    /// predicted fall is below its rounding floor, which in f32 comes first: the fit stops
    /// where further iterations would chase rounding).
    pub tolerance: T,
}

impl<T: Real> Default for Settings<T> {
    /// Broad priors, launch only (no wind, no air density), the default integrator,
    /// 30 iterations, steps below 1e-3 σ.
    fn default() -> Self {
        Self {
            prior: Prior::broad(),
            fit_wind: false,
            fit_air_density: false,
            integrator: Integrator::default(),
            max_iterations: 30,
            tolerance: lit(1e-3),
        }
    }
}

/// The fitted launch.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LaunchFit<T: Real> {
    /// The launch quantities (posterior mode).
    pub value: LaunchValues<T>,
    /// Their 1σ.
    pub sd: LaunchValues<T>,
    /// Where each came from.
    pub source: LaunchValues<Source>,
    /// The fitted uniform wind (x, z; m/s, G), when asked for.
    pub wind_mps: Option<[Datum<T>; 2]>,
    /// The fitted air density (kg/m³), when asked for.
    pub air_density_kgm3: Option<Datum<T>>,
    /// The flight of the fitted launch through the fitted scene (no ground).
    pub flight: FlightOutcome<T>,
    /// `Σ ((h_k − z_k)/σ_k)²` over the flight observations at the solution.
    pub chi2: T,
    /// The observation the fit misses most, and by how many of its σ (signed: model −
    /// observed).
    pub worst_observation: Observed,
    /// See [`LaunchFit::worst_observation`].
    pub worst_residual_sigma: T,
    /// Flight observations (residual rows) used.
    pub observations: u16,
    /// Levenberg–Marquardt iterations.
    pub iterations: u16,
    /// Flights flown (the cost: one per evaluation).
    pub flights: u16,
}

impl<T: Real> LaunchFit<T> {
    /// The fitted launch as a flight input.
    #[must_use]
    pub fn launch(&self) -> Launch<T> {
        Launch::from_spin_axis(
            self.value.ball_speed_mps,
            self.value.launch_angle_rad,
            self.value.launch_direction_rad,
            self.value.spin_radps,
            self.value.spin_axis_rad,
        )
    }
}

/// The solver's scratch space: the Jacobian's columns and the residuals (caller-owned, so
/// a microcontroller can place it in static memory: `(UNKNOWNS + 4)·MAX_ROWS` numbers,
/// 21 KiB in `f32`). `repr(C)`: nothing but `T` arrays, so it is laid out as
/// `[T; (UNKNOWNS + 4) · MAX_ROWS]` and the C API can hand over caller memory of that shape.
#[derive(Debug, Clone)]
#[repr(C)]
pub struct Workspace<T> {
    pub(crate) columns: [[T; MAX_ROWS]; UNKNOWNS],
    pub(crate) residual: [T; MAX_ROWS],
    pub(crate) trial: [T; MAX_ROWS],
    pub(crate) observed: [T; MAX_ROWS],
    pub(crate) sd: [T; MAX_ROWS],
}

impl<T: Real> Workspace<T> {
    /// A zeroed workspace.
    #[must_use]
    pub fn new() -> Self {
        Self {
            columns: [[T::zero(); MAX_ROWS]; UNKNOWNS],
            residual: [T::zero(); MAX_ROWS],
            trial: [T::zero(); MAX_ROWS],
            observed: [T::zero(); MAX_ROWS],
            sd: [T::one(); MAX_ROWS],
        }
    }
}

impl<T: Real> Default for Workspace<T> {
    fn default() -> Self {
        Self::new()
    }
}

/// Fits the launch to the flight observations (see the module docs).
///
/// `scene` is the flight's scene (aerodynamic model, air, wind, landing height; its ground
/// is ignored: the observations are of the flight); with `fit_wind` its wind is replaced
/// by a fitted uniform one, with `fit_air_density` its air by a fitted density.
///
/// # Errors
/// [`Error::InvalidInput`] for an invalid observation, measurement, prior or setting
/// (naming it) or scene; [`Error::TooFewObservations`] when the observations are fewer than
/// the free unknowns; [`Error::Unidentifiable`] naming an unknown the observations do not
/// pin down; [`Error::NoConvergence`]; [`Error::IllPosed`] when the normal matrix is
/// singular in the precision; a flight's error at the starting point.
pub fn fit_launch<T: Real>(
    ball: &Ball<T>,
    scene: &Scene<T>,
    measured: &MeasuredLaunch<T>,
    observations: &Observations<T>,
    settings: &Settings<T>,
    workspace: &mut Workspace<T>,
) -> Result<LaunchFit<T>> {
    observations.validate()?;
    validate_settings(measured, settings)?;
    solve::run(ball, scene, measured, observations, settings, workspace)
}

fn validate_settings<T: Real>(measured: &MeasuredLaunch<T>, settings: &Settings<T>) -> Result<()> {
    for m in measured.to_array().iter().flatten() {
        if !m.value.is_finite() {
            return Err(Error::invalid(Field::Observation, Reason::NotFinite));
        }
        if !(m.sd > T::zero() && m.sd.is_finite()) {
            return Err(Error::invalid(Field::MeasurementNoise, Reason::NotPositive));
        }
    }
    let p = &settings.prior;
    let spreads = p.sd.to_array();
    for (mean, sd) in p.mean.to_array().iter().zip(spreads) {
        if !mean.is_finite() {
            return Err(Error::invalid(Field::PriorMean, Reason::NotFinite));
        }
        if !(sd > T::zero() && sd.is_finite()) {
            return Err(Error::invalid(Field::PriorSpread, Reason::NotPositive));
        }
    }
    for sd in [p.wind_sd_mps, p.air_density_sd_kgm3] {
        if !(sd > T::zero() && sd.is_finite()) {
            return Err(Error::invalid(Field::PriorSpread, Reason::NotPositive));
        }
    }
    if settings.max_iterations == 0 {
        return Err(Error::invalid(Field::Iterations, Reason::NotPositive));
    }
    if !(settings.tolerance > T::zero() && settings.tolerance.is_finite()) {
        return Err(Error::invalid(Field::Tolerance, Reason::NotPositive));
    }
    settings.integrator.method().map(|_| ())
}
