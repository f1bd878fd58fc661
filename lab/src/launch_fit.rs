//! The launch from the flight as a typed request (`carry estimate --from flight`, issue 36;
//! the physics is [`carry_core::launch_fit`], docs/launch_fit.md): what a launch monitor
//! measured at launch and saw of the flight, in SI with degrees and rpm as the shells give
//! them, run in either precision; a track file reader; the serialisable record.

use std::path::Path;

use carry_core::Real;
use carry_core::launch_fit::{
    self as lf, Datum, DopplerSample, LaunchValues, MeasuredLaunch, Observations, Settings, Source,
    TrackPoint, Workspace,
};
use carry_core::real::{lit, to_f64};
use carry_core::units::rpm;
use carry_io::compute::{self, Numerics, Precision};
use carry_io::error::{Failure, InputError};
use carry_io::params::Params;
use nalgebra::Vector3;
use serde::Serialize;

/// A value and its 1σ, as the shells give them (the unit of the field that holds it).
pub type Given = Option<(f64, f64)>;

/// Default 1σ of the measured launch (m/s, °, °, rpm, °): a radar monitor's.
pub const LAUNCH_SD: [f64; 5] = [0.2, 0.2, 0.3, 150.0, 2.0];
/// Default 1σ of the summaries: apex height 0.5 m, apex time 0.1 s, carry 1 m, side 0.5 m,
/// flight time 0.05 s, landing angle 0.5°.
pub const SUMMARY_SD: [f64; 6] = [0.5, 0.1, 1.0, 0.5, 0.05, 0.5];
/// Default 1σ of a track point (m) and of a radial speed (m/s).
pub const TRACK_SD_M: f64 = 0.1;
/// See [`TRACK_SD_M`].
pub const DOPPLER_SD_MPS: f64 = 0.1;

/// A track read from a file: timed positions, or timed radial speeds.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Track {
    /// `(t s, [x, y, z] m)`.
    pub positions: Vec<(f64, [f64; 3])>,
    /// `(t s, radial speed m/s)`.
    pub radial_speeds: Vec<(f64, f64)>,
}

/// Reads a track CSV: a header `t,x,y,z` (positions, m, in the shot's frame G) or
/// `t,radial_speed` (m/s along the radar's line of sight), then one row per observation,
/// in time order.
///
/// # Errors
/// `track` naming the line and why.
pub fn read_track(path: &Path) -> Result<Track, InputError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| InputError::new("track", format!("{}: {e}", path.display())))?;
    parse_track(&text)
}

/// Parses a track CSV's text (see [`read_track`]).
///
/// # Errors
/// As [`read_track`].
pub fn parse_track(text: &str) -> Result<Track, InputError> {
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    let (_, header) = lines
        .next()
        .ok_or_else(|| InputError::new("track", "the file is empty"))?;
    let names: Vec<&str> = header.split(',').map(str::trim).collect();
    let doppler = match names.as_slice() {
        ["t", "x", "y", "z"] => false,
        ["t", "radial_speed"] => true,
        _ => {
            return Err(InputError::new(
                "track",
                format!("header '{header}' is neither 't,x,y,z' nor 't,radial_speed'"),
            ));
        }
    };
    let mut track = Track::default();
    let capacity = if doppler {
        lf::MAX_DOPPLER_SAMPLES
    } else {
        lf::MAX_TRACK_POINTS
    };
    for (i, line) in lines {
        let cells: Result<Vec<f64>, _> = line.split(',').map(|c| c.trim().parse::<f64>()).collect();
        let bad = |why: &str| InputError::new("track", format!("line {}: {why}", i + 1));
        let cells = cells.map_err(|_| bad("not a number"))?;
        if cells.len() != names.len() {
            return Err(bad(&format!(
                "{} values, expected {}",
                cells.len(),
                names.len()
            )));
        }
        if cells.iter().any(|v| !v.is_finite()) {
            return Err(bad("not a finite number"));
        }
        let t = cells.first().copied().unwrap_or(f64::NAN);
        let last = if doppler {
            track.radial_speeds.last().map(|p| p.0)
        } else {
            track.positions.last().map(|p| p.0)
        };
        if t < 0.0 || last.is_some_and(|l| t < l) {
            return Err(bad("times must be non-negative and in order"));
        }
        let n = if doppler {
            track.radial_speeds.len()
        } else {
            track.positions.len()
        };
        if n >= capacity {
            return Err(bad(&format!("more than {capacity} observations")));
        }
        match cells.as_slice() {
            [t, x, y, z] => track.positions.push((*t, [*x, *y, *z])),
            [t, v] => track.radial_speeds.push((*t, *v)),
            _ => return Err(bad("malformed row")),
        }
    }
    Ok(track)
}

/// What the monitor measured and saw; each `Given` is `(value, 1σ)`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FlightRequest {
    /// Ball speed (m/s).
    pub ball_speed_mps: Given,
    /// Launch angle (°).
    pub launch_angle_deg: Given,
    /// Launch direction (°, + right).
    pub launch_direction_deg: Given,
    /// Total spin (rpm).
    pub spin_rpm: Given,
    /// Spin axis (°, + right).
    pub spin_axis_deg: Given,
    /// Apex height (m).
    pub apex_height_m: Given,
    /// Apex time (s).
    pub apex_time_s: Given,
    /// Carry (m).
    pub carry_m: Given,
    /// Side (m, + right).
    pub side_m: Given,
    /// Flight time (s).
    pub flight_time_s: Given,
    /// Landing angle (°).
    pub land_angle_deg: Given,
    /// The track, with its 1σ (m for positions, m/s for radial speeds).
    pub track: Track,
    /// 1σ of each track point (m).
    pub track_sd_m: f64,
    /// 1σ of each radial speed (m/s).
    pub doppler_sd_mps: f64,
    /// The radar's position (m, G) for radial speeds.
    pub radar_position_m: [f64; 3],
    /// Fit a uniform wind.
    pub fit_wind: bool,
    /// Fit the air density.
    pub fit_air_density: bool,
}

/// One fitted launch figure: value, 1σ and where it came from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Figure {
    /// Value (the unit in the key's name).
    pub value: f64,
    /// 1σ.
    pub sd: f64,
    /// `measured` or `fitted to the flight`.
    pub source: &'static str,
}

/// The launch figures' keys, in [`FlightRecord::launch`] order.
pub const LAUNCH_KEYS: [&str; 5] = [
    "ball_speed_mps",
    "launch_angle_deg",
    "launch_direction_deg",
    "spin_rpm",
    "spin_axis_deg",
];

/// The launch figures flat: `spin_rpm`, `spin_rpm_sd`, `spin_rpm_source`, ….
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LaunchFigures(pub [Figure; 5]);

impl Serialize for LaunchFigures {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = s.serialize_map(Some(15))?;
        for (key, f) in LAUNCH_KEYS.iter().zip(&self.0) {
            m.serialize_entry(*key, &f.value)?;
            m.serialize_entry(&format!("{key}_sd"), &f.sd)?;
            m.serialize_entry(&format!("{key}_source"), f.source)?;
        }
        m.end()
    }
}

/// The launch from the flight, SI with degrees and rpm (serialisable: the JSON contract of
/// `carry estimate --from flight --json`: the launch figures flat, each with `_sd` and
/// `_source`, then the wind and air density when fitted, the fitted launch's flight and
/// the fit's statistics).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FlightRecord {
    /// Ball speed (m/s), launch angle (°), launch direction (°), spin (rpm), spin axis (°).
    #[serde(flatten)]
    pub launch: LaunchFigures,
    /// Fitted uniform wind `(x downrange, z right)` (m/s) and 1σ, when asked for.
    pub wind_mps: Option<[(f64, f64); 2]>,
    /// Fitted air density (kg/m³) and 1σ, when asked for.
    pub air_density_kgm3: Option<(f64, f64)>,
    /// The fitted launch's flight: carry (m).
    pub carry_m: f64,
    /// Side (m).
    pub side_m: f64,
    /// Apex (m).
    pub apex_m: f64,
    /// Flight time (s).
    pub flight_time_s: f64,
    /// Landing angle (°).
    pub land_angle_deg: f64,
    /// Total (tee to rest, m) of the fitted launch on the scene's ground, when it names one
    /// (`--ground`, a `ground` column): the launch flown once more through io's run.
    pub total_m: Option<f64>,
    /// Roll (first landing to rest, m), with `total_m`.
    pub roll_m: Option<f64>,
    /// χ² of the flight observations at the fit, and their number.
    pub chi2: f64,
    /// Flight observations used.
    pub observations: u16,
    /// The observation the fit misses most (`carry`, `track point 3 y`, …) and by how many σ.
    pub worst_observation: String,
    /// See `worst_observation`.
    pub worst_residual_sigma: f64,
    /// Iterations and flights flown.
    pub iterations: u16,
    /// See `iterations`.
    pub flights: u16,
}

fn observed_name(o: lf::Observed) -> String {
    match o {
        lf::Observed::Track { index, axis } => {
            format!(
                "track point {index} {}",
                ["x", "y", "z"].get(usize::from(axis)).unwrap_or(&"?")
            )
        }
        lf::Observed::Doppler(i) => format!("radial speed {i}"),
        lf::Observed::ApexHeight => "apex_height".into(),
        lf::Observed::ApexTime => "apex_time".into(),
        lf::Observed::Carry => "carry".into(),
        lf::Observed::Side => "side".into(),
        lf::Observed::FlightTime => "flight_time".into(),
        lf::Observed::LandAngle => "land_angle".into(),
        _ => "observation".into(),
    }
}

/// A `Given` checked: finite value, positive finite 1σ, else an error naming `key`.
fn datum<T: Real>(
    g: Given,
    key: &'static str,
    si: impl Fn(f64) -> f64,
) -> Result<Option<Datum<T>>, InputError> {
    let Some((v, sd)) = g else { return Ok(None) };
    if !v.is_finite() {
        return Err(InputError::new(key, "is not a finite number"));
    }
    if !(sd > 0.0 && sd.is_finite()) {
        return Err(InputError::new(key, "its 1σ must be positive"));
    }
    Ok(Some(Datum::new(lit(si(v)), lit(si(sd)))))
}

fn figure<T: Real>(value: T, sd: T, source: Source, to: impl Fn(f64) -> f64) -> Figure {
    Figure {
        value: to(to_f64(value)),
        sd: to(to_f64(sd)),
        source: source.name(),
    }
}

/// Fits the launch to the flight in `p`'s scene (its ground ignored), ball and precision.
///
/// # Errors
/// An option naming what is wrong (status 2): a bad value or 1σ, too few observations
/// (`apex_height, carry, side, flight_time, land_angle, track`), an unknown the
/// observations do not determine (its option), no convergence, a flight that fails.
pub fn fit(p: &Params, n: &Numerics, r: &FlightRequest) -> Result<FlightRecord, Failure> {
    match n.precision {
        Precision::F32 => fit_in::<f32>(p, n, r),
        Precision::F64 => fit_in::<f64>(p, n, r),
    }
}

/// The measured launch figures checked against the estimator's ranges
/// ([`carry_core::estimate::BallData::validated`]: launch angle and direction within ±90°,
/// spin in 0–19,099 rpm, spin axis within ±180°), each error naming its own option (issue 34:
/// a launch angle of 95° was reported as a spin out of range, a launch direction of 120° as
/// a spin the observations do not determine). A figure not given, not finite (its own
/// error follows) or the ball speed (the flight's own check words its bound) is checked at a
/// neutral value that passes.
fn launch_in_range(r: &FlightRequest) -> Result<(), InputError> {
    let v = |g: Given, neutral: f64| match g {
        Some((x, _)) if x.is_finite() => x,
        _ => neutral,
    };
    carry_core::estimate::BallData::<f64> {
        ball_speed_mps: 50.0,
        launch_angle_rad: v(r.launch_angle_deg, 0.0).to_radians(),
        launch_direction_rad: v(r.launch_direction_deg, 0.0).to_radians(),
        // the upper bound is the flight's own (it words it)
        spin_radps: rpm(v(r.spin_rpm, 0.0)).min(1000.0),
        spin_axis_rad: v(r.spin_axis_deg, 0.0).to_radians(),
    }
    .validated()
    .map(|_| ())
    .map_err(InputError::from)
}

fn fit_in<T: Real>(p: &Params, n: &Numerics, r: &FlightRequest) -> Result<FlightRecord, Failure> {
    launch_in_range(r)?;
    let ball = compute::ball::<T>(p)?;
    let scene = carry_io::scene::build::<T>(&p.scene)?;
    let measured: MeasuredLaunch<T> = LaunchValues {
        ball_speed_mps: datum(r.ball_speed_mps, "ball_speed", |v| v)?,
        launch_angle_rad: datum(r.launch_angle_deg, "launch_angle", f64::to_radians)?,
        launch_direction_rad: datum(r.launch_direction_deg, "launch_direction", f64::to_radians)?,
        spin_radps: datum(r.spin_rpm, "spin", rpm)?,
        spin_axis_rad: datum(r.spin_axis_deg, "spin_axis", f64::to_radians)?,
    };
    let mut obs = Observations::<T> {
        apex_height_m: datum(r.apex_height_m, "apex_height", |v| v)?,
        apex_time_s: datum(r.apex_time_s, "apex_time", |v| v)?,
        carry_m: datum(r.carry_m, "carry", |v| v)?,
        side_m: datum(r.side_m, "side", |v| v)?,
        flight_time_s: datum(r.flight_time_s, "flight_time", |v| v)?,
        land_angle_rad: datum(r.land_angle_deg, "land_angle", f64::to_radians)?,
        radar_position_m: Vector3::from(r.radar_position_m.map(lit::<T>)),
        ..Observations::default()
    };
    let sd = |v: f64, key| {
        if v > 0.0 && v.is_finite() {
            Ok(lit::<T>(v))
        } else {
            Err(InputError::new(key, "its 1σ must be positive"))
        }
    };
    let track_sd = sd(r.track_sd_m, "track_sd")?;
    let doppler_sd = sd(r.doppler_sd_mps, "track_sd")?;
    for (t, [x, y, z]) in &r.track.positions {
        obs.track
            .push(TrackPoint {
                time_s: lit(*t),
                position_m: Vector3::new(lit(*x), lit(*y), lit(*z)),
                sd_m: track_sd,
            })
            .map_err(|_| {
                InputError::new(
                    "track",
                    format!("more than {} points", lf::MAX_TRACK_POINTS),
                )
            })?;
    }
    for (t, v) in &r.track.radial_speeds {
        obs.doppler
            .push(DopplerSample {
                time_s: lit(*t),
                radial_speed_mps: lit(*v),
                sd_mps: doppler_sd,
            })
            .map_err(|_| {
                InputError::new(
                    "track",
                    format!("more than {} samples", lf::MAX_DOPPLER_SAMPLES),
                )
            })?;
    }
    let settings = Settings {
        integrator: n.integrator::<T>(),
        fit_wind: r.fit_wind,
        fit_air_density: r.fit_air_density,
        ..Settings::default()
    };
    let mut ws = Box::new(Workspace::<T>::new());
    let f =
        lf::fit_launch(&ball, &scene, &measured, &obs, &settings, &mut ws).map_err(fit_error)?;
    let degrees = f64::to_degrees;
    let to_rpm = |v: f64| v * 60.0 / std::f64::consts::TAU;
    let same = |v: f64| v;
    let ground = if p.scene.ground.is_empty() {
        None
    } else {
        on_the_ground(p, n, &f)?
    };
    Ok(FlightRecord {
        launch: LaunchFigures([
            figure(
                f.value.ball_speed_mps,
                f.sd.ball_speed_mps,
                f.source.ball_speed_mps,
                same,
            ),
            figure(
                f.value.launch_angle_rad,
                f.sd.launch_angle_rad,
                f.source.launch_angle_rad,
                degrees,
            ),
            figure(
                f.value.launch_direction_rad,
                f.sd.launch_direction_rad,
                f.source.launch_direction_rad,
                degrees,
            ),
            figure(
                f.value.spin_radps,
                f.sd.spin_radps,
                f.source.spin_radps,
                to_rpm,
            ),
            figure(
                f.value.spin_axis_rad,
                f.sd.spin_axis_rad,
                f.source.spin_axis_rad,
                degrees,
            ),
        ]),
        wind_mps: f
            .wind_mps
            .map(|w| w.map(|d| (to_f64(d.value), to_f64(d.sd)))),
        air_density_kgm3: f.air_density_kgm3.map(|d| (to_f64(d.value), to_f64(d.sd))),
        carry_m: to_f64(f.flight.carry_m),
        side_m: to_f64(f.flight.side_m),
        apex_m: to_f64(f.flight.apex_m),
        flight_time_s: to_f64(f.flight.flight_time_s),
        land_angle_deg: degrees(to_f64(f.flight.landing_angle_rad)),
        total_m: ground.map(|g| g.total_m),
        roll_m: ground.map(|g| g.roll_m),
        chi2: to_f64(f.chi2),
        observations: f.observations,
        worst_observation: observed_name(f.worst_observation),
        worst_residual_sigma: to_f64(f.worst_residual_sigma),
        iterations: f.iterations,
        flights: f.flights,
    })
}

/// The fitted launch flown once more through io's run in `p`'s scene with its ground (the
/// fitted wind and air density in place of the scene's when they were fitted): its rest.
fn on_the_ground<T: Real>(
    p: &Params,
    n: &Numerics,
    f: &lf::LaunchFit<T>,
) -> Result<Option<carry_io::report::GroundReport>, Failure> {
    let mut q = *p;
    let v = &f.value;
    q.launch.ball_speed_mps = to_f64(v.ball_speed_mps);
    q.launch.launch_angle_deg = to_f64(v.launch_angle_rad).to_degrees();
    q.launch.launch_direction_deg = to_f64(v.launch_direction_rad).to_degrees();
    q.launch.spin_rpm = Some(to_f64(v.spin_radps) * 60.0 / std::f64::consts::TAU);
    q.launch.spin_axis_deg = Some(to_f64(v.spin_axis_rad).to_degrees());
    q.launch.backspin_rpm = None;
    q.launch.sidespin_rpm = None;
    if let Some([x, z]) = f.wind_mps {
        q.scene.wind_mps = Some([to_f64(x.value), 0.0, to_f64(z.value)]);
        q.scene.wind_speed_mps = None;
        q.scene.wind_direction_deg = None;
        q.scene.wind_reference_height_m = None;
        q.scene.wind_exponent = None;
    }
    if let Some(rho) = f.air_density_kgm3 {
        q.scene.air_density_kgm3 = Some(to_f64(rho.value));
    }
    let r = compute::run(compute::Mode::Flight, &q, n)?;
    Ok(r.flight.and_then(|g| g.ground))
}

impl FlightRecord {
    /// The CSV columns of `carry batch estimate --from flight` (after `line` and `label`,
    /// before `error`), in the order of [`Self::cells`]: each launch figure with `_sd` and
    /// `_source`, the fitted wind and air density (empty unless fitted), the fitted launch's
    /// flight (`total_m`, `roll_m` empty without a ground), the fit's statistics.
    pub const COLUMNS: [&'static str; 34] = [
        "ball_speed_mps",
        "ball_speed_mps_sd",
        "ball_speed_mps_source",
        "launch_angle_deg",
        "launch_angle_deg_sd",
        "launch_angle_deg_source",
        "launch_direction_deg",
        "launch_direction_deg_sd",
        "launch_direction_deg_source",
        "spin_rpm",
        "spin_rpm_sd",
        "spin_rpm_source",
        "spin_axis_deg",
        "spin_axis_deg_sd",
        "spin_axis_deg_source",
        "wind_x_mps",
        "wind_x_mps_sd",
        "wind_z_mps",
        "wind_z_mps_sd",
        "air_density_kgm3",
        "air_density_kgm3_sd",
        "carry_m",
        "side_m",
        "apex_m",
        "flight_time_s",
        "land_angle_deg",
        "total_m",
        "roll_m",
        "chi2",
        "observations",
        "worst_observation",
        "worst_residual_sigma",
        "iterations",
        "flights",
    ];

    /// The record as CSV cells (unquoted text) in the order of [`Self::COLUMNS`]: numbers
    /// in their shortest round-trip form, absent values empty.
    #[must_use]
    pub fn cells(&self) -> Vec<String> {
        let num = |v: f64| {
            if v.is_finite() {
                format!("{v}")
            } else {
                String::new()
            }
        };
        let opt = |v: Option<f64>| v.map_or(String::new(), num);
        let mut c = Vec::with_capacity(Self::COLUMNS.len());
        for f in &self.launch.0 {
            c.push(num(f.value));
            c.push(num(f.sd));
            c.push(f.source.to_owned());
        }
        let [wx, wz] = self.wind_mps.map_or([None; 2], |w| w.map(Some));
        for w in [wx, wz] {
            c.push(opt(w.map(|w| w.0)));
            c.push(opt(w.map(|w| w.1)));
        }
        c.push(opt(self.air_density_kgm3.map(|d| d.0)));
        c.push(opt(self.air_density_kgm3.map(|d| d.1)));
        for v in [
            self.carry_m,
            self.side_m,
            self.apex_m,
            self.flight_time_s,
            self.land_angle_deg,
        ] {
            c.push(num(v));
        }
        c.push(opt(self.total_m));
        c.push(opt(self.roll_m));
        c.push(num(self.chi2));
        c.push(self.observations.to_string());
        c.push(self.worst_observation.clone());
        c.push(num(self.worst_residual_sigma));
        c.push(self.iterations.to_string());
        c.push(self.flights.to_string());
        c
    }
}

/// [`fit`] over many rows in parallel on `threads` workers (`None`: all cores), each row
/// the parameters (scene, ball) and the request of one shot, or the error its input had;
/// the results in row order (`carry batch estimate --from flight`, Python's
/// `carry.launch_from_flight` over arrays).
///
/// # Errors
/// The thread pool cannot start.
pub fn fit_rows(
    rows: &[Result<(Params, FlightRequest), InputError>],
    n: &Numerics,
    threads: Option<usize>,
) -> Result<Vec<Result<FlightRecord, InputError>>, Failure> {
    crate::rows::par_rows(rows, threads, "launch_fit", |p, r| fit(p, n, r))
}

/// The core's errors of the fit, naming the option that can fix them.
fn fit_error(e: carry_core::Error) -> Failure {
    use carry_core::{Error, Field};
    let input = match e {
        Error::TooFewObservations => InputError::new(
            "apex_height, carry, side, flight_time, land_angle, track",
            "too few flight observations for the launch quantities not measured",
        ),
        Error::Unidentifiable(field) => {
            let key = match field {
                Field::BallSpeed => "ball_speed",
                Field::LaunchAngle => "launch_angle",
                Field::LaunchDirection => "launch_direction",
                Field::BallSpin => "spin",
                Field::SpinAxis => "spin_axis",
                Field::Wind => "fit_wind",
                Field::AirDensity => "fit_air_density",
                _ => "track",
            };
            InputError::new(
                key,
                format!(
                    "the flight observations do not determine the {field}: measure it or observe more of the flight"
                ),
            )
        }
        Error::NoConvergence => InputError::new(
            "apex_height, carry, side, flight_time, land_angle, track",
            "the launch fit did not converge: the observations may contradict each other",
        ),
        Error::IllPosed => InputError::new(
            "apex_height, carry, side, flight_time, land_angle, track",
            "the observations and priors do not determine the launch in this precision",
        ),
        other => InputError::from(other),
    };
    Failure::Input(input)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_both_track_kinds_and_names_bad_lines() {
        let t = parse_track("t,x,y,z\n0.1,6,1,0\n0.2,12,2,0.1\n").unwrap();
        assert_eq!(
            t.positions,
            vec![(0.1, [6.0, 1.0, 0.0]), (0.2, [12.0, 2.0, 0.1])]
        );
        let d = parse_track("t, radial_speed\n0.01,70\n0.02,69.9\n").unwrap();
        assert_eq!(d.radial_speeds.len(), 2);
        let e = parse_track("t,x,y,z\n0.2,1,1,1\n0.1,2,2,2\n").unwrap_err();
        assert_eq!(
            e.to_string(),
            "--track: line 3: times must be non-negative and in order"
        );
        let e = parse_track("a,b\n1,2\n").unwrap_err();
        assert!(e.to_string().starts_with("--track: header 'a,b'"), "{e}");
        let e = parse_track("t,x,y,z\n0.1,1,x,1\n").unwrap_err();
        assert_eq!(e.to_string(), "--track: line 2: not a number");
    }

    #[test]
    fn fits_spin_from_summaries_and_names_missing_data() {
        // The flight of a known launch, observed by its summaries.
        let p = Params::default();
        let n = Numerics::default();
        let launch = carry_core::Launch::from_spin_axis(
            70.0,
            12f64.to_radians(),
            0.0,
            rpm(2800.0),
            4f64.to_radians(),
        );
        let scene = carry_io::scene::build::<f64>(&p.scene)
            .unwrap()
            .prepare(&carry_core::Ball::standard())
            .unwrap();
        let o = scene
            .fly(&launch.ball_motion().unwrap(), &n.integrator(), None)
            .unwrap();
        let mut r = FlightRequest {
            ball_speed_mps: Some((70.0, 0.2)),
            launch_angle_deg: Some((12.0, 0.2)),
            launch_direction_deg: Some((0.0, 0.3)),
            apex_height_m: Some((o.apex_m, 0.5)),
            carry_m: Some((o.carry_m, 1.0)),
            side_m: Some((o.side_m, 0.5)),
            flight_time_s: Some((o.flight_time_s, 0.05)),
            land_angle_deg: Some((o.landing_angle_rad.to_degrees(), 0.5)),
            track_sd_m: TRACK_SD_M,
            doppler_sd_mps: DOPPLER_SD_MPS,
            ..FlightRequest::default()
        };
        let rec = fit(&p, &n, &r).unwrap();
        let [speed, _, _, spin, _] = rec.launch.0;
        assert!((spin.value - 2800.0).abs() < 2.0 * spin.sd, "{rec:?}");
        assert_eq!(spin.source, "fitted to the flight");
        assert_eq!(speed.source, "measured");
        let json = serde_json::to_value(&rec).unwrap();
        assert_eq!(json["spin_rpm"], spin.value);
        assert_eq!(json["spin_rpm_sd"], spin.sd);
        assert_eq!(json["spin_axis_deg_source"], "fitted to the flight");
        let f32s = Numerics {
            precision: Precision::F32,
            ..n
        };
        let rec32 = fit(&p, &f32s, &r).unwrap();
        assert!((rec32.launch.0[3].value - spin.value).abs() < 0.2 * spin.sd);
        r.side_m = None;
        r.land_angle_deg = None;
        r.flight_time_s = None;
        r.apex_height_m = None;
        let e = fit(&p, &n, &r).unwrap_err();
        let Failure::Input(e) = e else {
            panic!("{e:?}")
        };
        assert_eq!(
            e.key,
            "apex_height, carry, side, flight_time, land_angle, track"
        );
        r.carry_m = Some((200.0, -1.0));
        let Failure::Input(e) = fit(&p, &n, &r).unwrap_err() else {
            panic!()
        };
        assert_eq!(e.to_string(), "--carry: its 1σ must be positive");
    }
}
