//! The launch from the flight on the single TrackMan drives (issue 36; docs/launch_fit.md,
//! section 4): spin and spin axis fitted by [`carry_core::launch_fit`] from TrackMan's
//! measured launch and its flight summaries, against TrackMan's measured spin and axis.
//!
//! * **Held-out aerodynamics.** The fit inverts the flight model, so an aerodynamic model
//!   fitted to the same shots would flatter it. [`DRIVES_2026_WITHOUT_SESSION`] holds
//!   `drives2026` refitted without each session block of 1,000 rows; [`held_out_model`]
//!   gives the model for a drive's own block, so each shot's spin comes from a model that
//!   never saw its session.
//! * **Rows.** [`Shot::of`]: a full launch, all five summaries (apex height, carry, side,
//!   flight time, landing angle), carry ≥ 20 m, launch ≥ 1°; the rows tracked outdoors
//!   also keep their last tracked point.
//! * **Noise.** [`Noise`]: the 1σ of the measured launch and of each summary.
//!   [`Noise::RADAR`] is the CLI's defaults; [`noise_from_residuals`] sets the summaries'
//!   σ from data: the robust scatter of TrackMan's summaries about the model's flight of
//!   TrackMan's own launch ([`summary_residuals`]) on the training sessions.
//! * **Errors.** [`SpinError`] per shot, [`SpinSummary`] per group (mean |err|, bias,
//!   median, axis, 1σ coverage), by the bands of [`crate::fit::single_shots`].
//! * **Weather** (the rows tracked outdoors): [`joint_weather`] fits one air density and one
//!   uniform wind to a group of shots jointly with each shot's launch (the core fits each
//!   shot with the weather fixed; a Gauss–Newton step on the weather uses the Schur
//!   complement of each shot's launch, so the spin's trade with the weather is accounted).

use crate::drives::Drive;
use crate::fit::single_shots::SessionWeather;
use carry_core::aero::{AeroModel, ModernAero};
use carry_core::launch_fit::{
    Datum, LaunchFit, LaunchValues, MeasuredLaunch, Observations, Settings, TrackPoint, Workspace,
    fit_launch,
};
use carry_core::units::{deg, rpm};
use carry_core::{Air, Ball, Integrator, Launch, Recorder, Sample, SampleSink, Scene, Wind};
use nalgebra::{SMatrix, SVector, Vector3};
use rayon::prelude::*;

/// `drives2026` refitted without session block `s` (row `s`), in the order of
/// [`ModernAero::to_array`], 4 significant digits: `cargo run --release -p carry-lab
/// --example spin_shape -- cv --sigma-data --carry-sigma=0.01 --spin-sigma=0.03` ("without
/// session s"; the refits' held-out carry: 1.50 % mean |err| on 3,668 rows, held-out spin
/// 5.92 %, docs/launch_fit.md §4).
pub const DRIVES_2026_WITHOUT_SESSION: [[f64; 9]; 5] = [
    [
        0.17, 0.3, 3.624e4, 0.2976, 1.5, 0.9475, 0.0119, 0.1387, 0.3013,
    ],
    [0.17, 0.3, 3.897e4, 0.2768, 1.5, 1.0, 0.0112, 0.1477, 0.3181],
    [
        0.17, 0.3, 5.51e4, 0.3023, 1.5, 0.8623, 0.011, 0.1294, 0.2777,
    ],
    [
        0.17, 0.3, 5.308e4, 0.3143, 1.5, 0.8373, 0.0101, 0.124, 0.2681,
    ],
    [
        0.17, 0.3, 4.061e4, 0.3021, 1.5, 0.8992, 0.0119, 0.1335, 0.2962,
    ],
];

/// The aerodynamics that never saw session block `session` ([`DRIVES_2026_WITHOUT_SESSION`]);
/// `drives2026` itself for a block it has no row for.
#[must_use]
pub fn held_out_model(session: usize) -> AeroModel<f64> {
    AeroModel::Modern(ModernAero::from_array(
        DRIVES_2026_WITHOUT_SESSION
            .get(session)
            .copied()
            .unwrap_or(carry_core::aero::DRIVES_2026),
    ))
}

/// The summaries, in the order of [`Shot::summaries`] and [`Noise::summaries`].
pub const SUMMARY_NAMES: [&str; 5] = [
    "apex height",
    "carry",
    "side",
    "flight time",
    "landing angle",
];

/// The 1σ of what a monitor measured and saw (SI; angles in radians).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Noise {
    /// Ball speed (m/s), launch angle (rad), launch direction (rad).
    pub launch: [f64; 3],
    /// Apex height (m), carry (m), side (m), flight time (s), landing angle (rad).
    pub summaries: [f64; 5],
    /// Each coordinate of a tracked point (m).
    pub track_m: f64,
}

impl Noise {
    /// The CLI's defaults (`carry_lab::launch_fit::LAUNCH_SD`, `SUMMARY_SD`: 0.2 m/s,
    /// 0.2°, 0.3°; apex 0.5 m, carry 1 m, side 0.5 m, flight time 0.05 s, landing 0.5°), a
    /// tracked point 0.5 m.
    pub const RADAR: Self = Self {
        launch: [0.2, 0.2 * DEG, 0.3 * DEG],
        summaries: [0.5, 1.0, 0.5, 0.05, 0.5 * DEG],
        track_m: 0.5,
    };
}

const DEG: f64 = std::f64::consts::PI / 180.0;

/// One drive as a launch-fit problem, with TrackMan's answer.
#[derive(Debug, Clone, PartialEq)]
pub struct Shot {
    /// Row in the file (0-based).
    pub index: usize,
    /// Its session block.
    pub session: usize,
    /// TrackMan's launch: ball speed (m/s), launch angle, direction (rad), spin (rad/s),
    /// axis (rad).
    pub launch: [f64; 5],
    /// Apex height (m), carry (m), side (m), flight time (s), landing angle (rad).
    pub summaries: [f64; 5],
    /// The last tracked point `(t s, [x, y, z] m)`, kept for the rows tracked outdoors.
    pub last_point: Option<(f64, [f64; 3])>,
}

impl Shot {
    /// The drive as a shot: a full launch, all five summaries, carry ≥ 20 m and launch
    /// ≥ 1°; the last tracked point when it was tracked outdoors.
    #[must_use]
    pub fn of(d: &Drive) -> Option<Self> {
        let [speed, launch, direction, spin, axis] = d.full_launch()?;
        let f = &d.flight;
        let summaries = [
            f.apex_m?,
            f.carry_m?,
            f.carry_side_m?,
            f.flight_time_s?,
            deg(f.land_angle_deg?),
        ];
        if summaries[1] < 20.0 || launch < 1.0 {
            return None;
        }
        let last_point = if d.tracked_outdoors() {
            Some((f.last_point_time_s?, f.last_point_m?))
        } else {
            None
        };
        Some(Self {
            index: d.index,
            session: d.session(),
            launch: [speed, deg(launch), deg(direction), rpm(spin), deg(axis)],
            summaries,
            last_point,
        })
    }

    /// TrackMan's spin (rpm).
    #[must_use]
    pub fn spin_rpm(&self) -> f64 {
        self.launch[3] * 60.0 / std::f64::consts::TAU
    }

    /// TrackMan's ball speed (mph).
    #[must_use]
    pub fn ball_speed_mph(&self) -> f64 {
        self.launch[0] / carry_core::units::MPS_PER_MPH
    }

    /// The fit's input: ball speed, launch angle and direction measured with `noise`'s σ,
    /// spin and axis free; the summaries `used` (in [`SUMMARY_NAMES`] order) and, with
    /// `track`, the last tracked point.
    #[must_use]
    pub fn problem(
        &self,
        noise: &Noise,
        used: [bool; 5],
        track: bool,
    ) -> (MeasuredLaunch<f64>, Observations<f64>) {
        let measured = LaunchValues {
            ball_speed_mps: Some(Datum::new(self.launch[0], noise.launch[0])),
            launch_angle_rad: Some(Datum::new(self.launch[1], noise.launch[1])),
            launch_direction_rad: Some(Datum::new(self.launch[2], noise.launch[2])),
            spin_radps: None,
            spin_axis_rad: None,
        };
        let s = |i: usize| used[i].then(|| Datum::new(self.summaries[i], noise.summaries[i]));
        let mut obs = Observations {
            apex_height_m: s(0),
            carry_m: s(1),
            side_m: s(2),
            flight_time_s: s(3),
            land_angle_rad: s(4),
            ..Observations::default()
        };
        if let (true, Some((t, p))) = (track, self.last_point) {
            // One point: the capacity (64) cannot be exceeded.
            let _ = obs.track.push(TrackPoint {
                time_s: t,
                position_m: Vector3::from(p),
                sd_m: noise.track_m,
            });
        }
        (measured, obs)
    }

    /// Fits spin and axis with `scene` and `settings` (see [`Shot::problem`]).
    ///
    /// # Errors
    /// The core's ([`fit_launch`]).
    pub fn fit(
        &self,
        scene: &Scene<f64>,
        settings: &Settings<f64>,
        noise: &Noise,
        used: [bool; 5],
        track: bool,
    ) -> Result<LaunchFit<f64>, carry_core::Error> {
        let (m, obs) = self.problem(noise, used, track);
        let mut ws = Box::new(Workspace::new());
        fit_launch(&Ball::standard(), scene, &m, &obs, settings, &mut ws)
    }
}

/// Every summary used.
pub const ALL: [bool; 5] = [true; 5];

/// One fitted shot against TrackMan.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpinError {
    /// `fitted / TrackMan − 1`.
    pub spin_rel: f64,
    /// Fitted − TrackMan axis (°).
    pub axis_deg: f64,
    /// TrackMan's spin within the fit's 1σ.
    pub spin_within: bool,
    /// TrackMan's axis within the fit's 1σ.
    pub axis_within: bool,
    /// `|fitted − TrackMan| / σ` of the spin (the fit's own 1σ).
    pub spin_z: f64,
    /// TrackMan's spin (rpm).
    pub spin_rpm: f64,
    /// TrackMan's ball speed (mph).
    pub ball_speed_mph: f64,
}

impl SpinError {
    /// The fit's errors against the shot's TrackMan figures.
    #[must_use]
    pub fn of(shot: &Shot, fit: &LaunchFit<f64>) -> Self {
        let ds = fit.value.spin_radps - shot.launch[3];
        let da = fit.value.spin_axis_rad - shot.launch[4];
        Self {
            spin_rel: ds / shot.launch[3],
            axis_deg: da.to_degrees(),
            spin_within: ds.abs() <= fit.sd.spin_radps,
            axis_within: da.abs() <= fit.sd.spin_axis_rad,
            spin_z: ds.abs() / fit.sd.spin_radps,
            spin_rpm: shot.spin_rpm(),
            ball_speed_mph: shot.ball_speed_mph(),
        }
    }
}

/// The errors of a group of shots.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SpinSummary {
    /// Shots.
    pub rows: usize,
    /// Spin mean |err| (%).
    pub mean_abs_pct: f64,
    /// Spin mean error (%): the bias.
    pub bias_pct: f64,
    /// Spin median error (%).
    pub median_pct: f64,
    /// Axis mean |err| (°).
    pub axis_mean_abs_deg: f64,
    /// Fraction of shots with TrackMan's spin within the fit's 1σ.
    pub spin_within: f64,
    /// Fraction with TrackMan's axis within the fit's 1σ.
    pub axis_within: f64,
}

impl SpinSummary {
    /// Summarises `errors`.
    #[must_use]
    pub fn of<'a>(errors: impl IntoIterator<Item = &'a SpinError>) -> Self {
        let e: Vec<&SpinError> = errors.into_iter().collect();
        if e.is_empty() {
            return Self::default();
        }
        #[allow(clippy::cast_precision_loss)]
        let n = e.len() as f64;
        let mean = |f: &dyn Fn(&SpinError) -> f64| e.iter().map(|x| f(x)).sum::<f64>() / n;
        let mut rel: Vec<f64> = e.iter().map(|x| x.spin_rel).collect();
        Self {
            rows: e.len(),
            mean_abs_pct: 100.0 * mean(&|x| x.spin_rel.abs()),
            bias_pct: 100.0 * mean(&|x| x.spin_rel),
            median_pct: 100.0 * median(&mut rel),
            axis_mean_abs_deg: mean(&|x| x.axis_deg.abs()),
            spin_within: mean(&|x| f64::from(u8::from(x.spin_within))),
            axis_within: mean(&|x| f64::from(u8::from(x.axis_within))),
        }
    }

    /// `errors` grouped by `key` into `bands` (`[lo, hi)`).
    #[must_use]
    pub fn by_band(
        errors: &[SpinError],
        key: impl Fn(&SpinError) -> f64,
        bands: &[(f64, f64)],
    ) -> Vec<Self> {
        bands
            .iter()
            .map(|&(lo, hi)| Self::of(errors.iter().filter(|e| (lo..hi).contains(&key(e)))))
            .collect()
    }
}

/// The factor `k` that puts 68.27 % of `|error| / σ` (`z`) within `k`: the 1σ scale that
/// calibrates a fit's σ on shots where the truth is known (NaN when empty).
#[must_use]
pub fn sigma_scale(z: &[f64]) -> f64 {
    if z.is_empty() {
        return f64::NAN;
    }
    let mut v = z.to_vec();
    v.sort_by(f64::total_cmp);
    #[allow(
        clippy::cast_precision_loss,
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss
    )]
    let i = ((0.6827 * v.len() as f64).ceil() as usize).clamp(1, v.len()) - 1;
    v[i]
}

/// The fraction of `z` within `k`.
#[must_use]
pub fn within(z: &[f64], k: f64) -> f64 {
    #[allow(clippy::cast_precision_loss)]
    let n = z.len() as f64;
    z.iter().filter(|&&x| x <= k).count() as f64 / n
}

/// The median (the mean of the middle two for an even count; NaN when empty).
#[must_use]
pub fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// A robust 1σ: 1.4826 × the median absolute deviation about the median (the σ of a
/// Gaussian, not pulled by the few rows TrackMan's summary misses wildly).
#[must_use]
pub fn robust_sd(values: &[f64]) -> f64 {
    let mut v = values.to_vec();
    let m = median(&mut v);
    let mut dev: Vec<f64> = values.iter().map(|x| (x - m).abs()).collect();
    1.4826 * median(&mut dev)
}

/// The flight of TrackMan's launch through `scene`: model − TrackMan for each summary
/// (in [`SUMMARY_NAMES`] order).
///
/// # Errors
/// The flight's.
pub fn summary_residuals(shot: &Shot, scene: &Scene<f64>) -> Result<[f64; 5], carry_core::Error> {
    let p = predict(shot, scene, &shot.launch, false)?;
    let mut r = [0.0; 5];
    for (i, x) in r.iter_mut().enumerate() {
        *x = p[i] - shot.summaries[i];
    }
    Ok(r)
}

/// `base` with the summaries' σ the robust scatter ([`robust_sd`]) of `residuals` (from
/// [`summary_residuals`]), each at least `base`'s.
#[must_use]
pub fn noise_from_residuals(residuals: &[[f64; 5]], base: Noise) -> Noise {
    let mut out = base;
    for (i, sd) in out.summaries.iter_mut().enumerate() {
        let col: Vec<f64> = residuals.iter().map(|r| r[i]).collect();
        *sd = sd.max(robust_sd(&col));
    }
    out
}

/// Keeps the sample at time `.0` (the recorder also hands over the landing sample).
struct At(f64, Option<Sample<f64>>);

impl SampleSink<f64> for At {
    fn clear(&mut self) {
        self.1 = None;
    }
    fn push(&mut self, s: Sample<f64>) -> bool {
        if s.time_s == self.0 {
            self.1 = Some(s);
        }
        true
    }
}

/// The five summaries of launch `x` (as [`Shot::launch`]) flown through `scene` (no
/// ground), followed, with `track` and a last tracked point, by the point's predicted
/// position (after the modelled landing: the landing state continued ballistically, as the
/// core does).
///
/// # Errors
/// The flight's.
pub fn predict(
    shot: &Shot,
    scene: &Scene<f64>,
    x: &[f64; 5],
    track: bool,
) -> Result<Vec<f64>, carry_core::Error> {
    let mut scene = *scene;
    scene.ground = None;
    let prepared = scene.prepare(&Ball::standard())?;
    let motion = Launch::from_spin_axis(x[0], x[1], x[2], x[3], x[4]).ball_motion()?;
    let point = shot.last_point.filter(|_| track);
    let times = [point.map_or(0.0, |p| p.0)];
    let mut sink = At(times[0], None);
    let o = if point.is_some() {
        let mut rec = Recorder::at_times(&times, &mut sink)?;
        prepared.fly(&motion, &Integrator::default(), Some(&mut rec))?
    } else {
        prepared.fly(&motion, &Integrator::default(), None)?
    };
    let mut out = vec![
        o.apex_m,
        o.carry_m,
        o.side_m,
        o.flight_time_s,
        o.landing_angle_rad,
    ];
    if point.is_some() {
        let p = match sink.1 {
            Some(s) => s.position_m,
            None => {
                let dt = times[0] - o.flight_time_s;
                let g = Vector3::new(0.0, -scene.gravity_mps2, 0.0);
                o.landing_position_m + o.landing_velocity_mps * dt + g * (0.5 * dt * dt)
            }
        };
        out.extend(p.iter());
    }
    Ok(out)
}

/// The share of each summary in the spin's information for `shot` at TrackMan's launch:
/// `(∂h_k/∂ω / σ_k)²` normalised to sum to 1 (the launch held; a forward difference of
/// 2 rad/s, the core's step).
///
/// # Errors
/// The flight's.
pub fn spin_information(
    shot: &Shot,
    scene: &Scene<f64>,
    noise: &Noise,
) -> Result<[f64; 5], carry_core::Error> {
    let base = predict(shot, scene, &shot.launch, false)?;
    let mut x = shot.launch;
    x[3] += 2.0;
    let moved = predict(shot, scene, &x, false)?;
    let mut info = [0.0; 5];
    for (i, v) in info.iter_mut().enumerate() {
        *v = ((moved[i] - base[i]) / 2.0 / noise.summaries[i]).powi(2);
    }
    let total: f64 = info.iter().sum();
    Ok(info.map(|v| v / total))
}

/// `scene` in `weather`: its air the weather's density, its wind the weather's uniform one.
#[must_use]
pub fn in_weather(scene: &Scene<f64>, weather: &SessionWeather) -> Scene<f64> {
    Scene {
        air: Air::Density(weather.density_kgm3),
        wind: Wind::Uniform(Vector3::new(
            weather.tail_wind_mps,
            0.0,
            weather.cross_wind_mps,
        )),
        ..*scene
    }
}

/// A group's weather fitted jointly with its shots' launches ([`joint_weather`]).
#[derive(Debug, Clone, PartialEq)]
pub struct JointWeather {
    /// The weather.
    pub weather: SessionWeather,
    /// Its posterior 1σ (density, tail wind, cross wind), Laplace.
    pub sd: [f64; 3],
    /// Gauss–Newton iterations.
    pub iterations: usize,
    /// Shots the core could fit at the final weather.
    pub fitted: usize,
    /// The profile cost at the end: Σ over the fitted shots of χ² + launch prior terms,
    /// plus the weather's prior.
    pub cost: f64,
}

const LAUNCH_STEPS: [f64; 5] = [0.05, 1e-3, 1e-3, 2.0, 2e-3];
const WEATHER_STEPS: [f64; 3] = [0.002, 0.05, 0.05];

type Mat5 = SMatrix<f64, 5, 5>;
type Mat53 = SMatrix<f64, 5, 3>;
type Mat3 = SMatrix<f64, 3, 3>;

/// One shot's contribution to the weather's normal equations, after its launch has been
/// eliminated (Schur complement), with its profile cost.
fn shot_terms(
    shot: &Shot,
    scene: &Scene<f64>,
    weather: &SessionWeather,
    noise: &Noise,
    settings: &Settings<f64>,
) -> Option<(Mat3, SVector<f64, 3>, f64)> {
    let here = in_weather(scene, weather);
    let fit = shot.fit(&here, settings, noise, ALL, true).ok()?;
    let x = fit.value.to_array();
    let (m, obs) = shot.problem(noise, ALL, true);
    let mut z = shot.summaries.to_vec();
    let mut sd = noise.summaries.to_vec();
    if let Some(p) = obs.track.first() {
        z.extend(p.position_m.iter());
        sd.extend([p.sd_m; 3]);
    }
    let h0 = predict(shot, &here, &x, true).ok()?;
    // At most eight rows (five summaries, a point's three coordinates); unused rows zero.
    let rows = z.len().min(8);
    let mut r = SVector::<f64, 8>::zeros();
    for k in 0..rows {
        r[k] = (h0[k] - z[k]) / sd[k];
    }
    let mut jx = SMatrix::<f64, 8, 5>::zeros();
    for j in 0..5 {
        let mut y = x;
        y[j] += LAUNCH_STEPS[j];
        let h = predict(shot, &here, &y, true).ok()?;
        for k in 0..rows {
            jx[(k, j)] = (h[k] - h0[k]) / LAUNCH_STEPS[j] / sd[k];
        }
    }
    let mut jw = SMatrix::<f64, 8, 3>::zeros();
    for j in 0..3 {
        let mut w = *weather;
        match j {
            0 => w.density_kgm3 += WEATHER_STEPS[0],
            1 => w.tail_wind_mps += WEATHER_STEPS[1],
            _ => w.cross_wind_mps += WEATHER_STEPS[2],
        }
        let h = predict(shot, &in_weather(scene, &w), &x, true).ok()?;
        for k in 0..rows {
            jw[(k, j)] = (h[k] - h0[k]) / WEATHER_STEPS[j] / sd[k];
        }
    }
    // The launch's prior: measured values, else the prior's mean and spread.
    let prior = &settings.prior;
    let (pm, ps) = (prior.mean.to_array(), prior.sd.to_array());
    let mut q = Mat5::zeros();
    let mut gx = SVector::<f64, 5>::zeros();
    let mut prior_cost = 0.0;
    for (i, d) in m.to_array().iter().enumerate() {
        let (mean, s) = d.map_or((pm[i], ps[i]), |d| (d.value, d.sd));
        q[(i, i)] = 1.0 / (s * s);
        gx[i] = (x[i] - mean) / (s * s);
        prior_cost += ((x[i] - mean) / s).powi(2);
    }
    let axx = Mat5::from_fn(|a, b| jx.column(a).dot(&jx.column(b))) + q;
    let axw = Mat53::from_fn(|a, b| jx.column(a).dot(&jw.column(b)));
    let aww = Mat3::from_fn(|a, b| jw.column(a).dot(&jw.column(b)));
    let gx = gx + SVector::<f64, 5>::from_fn(|a, _| jx.column(a).dot(&r));
    let gw = SVector::<f64, 3>::from_fn(|a, _| jw.column(a).dot(&r));
    let inv = axx.try_inverse()?;
    let s = aww - axw.transpose() * inv * axw;
    let b = gw - axw.transpose() * inv * gx;
    Some((s, b, r.norm_squared() + prior_cost))
}

fn weather_array(w: &SessionWeather) -> [f64; 3] {
    [w.density_kgm3, w.tail_wind_mps, w.cross_wind_mps]
}

fn weather_of(a: [f64; 3]) -> SessionWeather {
    SessionWeather {
        density_kgm3: a[0].clamp(0.8, 1.5),
        tail_wind_mps: a[1].clamp(-15.0, 15.0),
        cross_wind_mps: a[2].clamp(-15.0, 15.0),
    }
}

/// The terms summed over `shots`, with the weather's prior (mean `prior_mean`, the
/// core's spreads); `None` when no shot can be fitted.
fn totals(
    shots: &[&Shot],
    scene: &Scene<f64>,
    weather: &SessionWeather,
    prior_mean: &SessionWeather,
    noise: &Noise,
    settings: &Settings<f64>,
) -> Option<(Mat3, SVector<f64, 3>, f64, usize)> {
    let terms: Vec<_> = shots
        .par_iter()
        .filter_map(|s| shot_terms(s, scene, weather, noise, settings))
        .collect();
    if terms.is_empty() {
        return None;
    }
    let p = &settings.prior;
    let spread = [p.air_density_sd_kgm3, p.wind_sd_mps, p.wind_sd_mps];
    let (w, m) = (weather_array(weather), weather_array(prior_mean));
    let mut a = Mat3::zeros();
    let mut b = SVector::<f64, 3>::zeros();
    let mut cost = 0.0;
    for i in 0..3 {
        a[(i, i)] = 1.0 / spread[i].powi(2);
        b[i] = (w[i] - m[i]) / spread[i].powi(2);
        cost += ((w[i] - m[i]) / spread[i]).powi(2);
    }
    for (s, g, c) in &terms {
        a += s;
        b += g;
        cost += c;
    }
    Some((a, b, cost, terms.len()))
}

/// Fits one weather (air density, uniform tail and cross wind) to `shots` jointly with
/// each shot's launch: the profile cost `Σ_i min_x χ²_i(x, w) + prior` is minimised by
/// Gauss–Newton on `w`, each shot's launch refitted by the core at every `w` and its
/// sensitivities eliminated by the Schur complement (`S_i = A_ww − A_wx A_xx⁻¹ A_xw`), a
/// step halved up to four times while it does not lower the cost. The weather's prior is
/// the core's ([`carry_core::launch_fit::Prior::broad`] spreads) about `start`. Shots the core refuses at a
/// weather are left out of that weather's sums.
///
/// # Errors
/// No shot can be fitted, or the normal matrix is singular.
pub fn joint_weather(
    shots: &[&Shot],
    scene: &Scene<f64>,
    start: SessionWeather,
    noise: &Noise,
    settings: &Settings<f64>,
    max_iterations: usize,
) -> Result<JointWeather, String> {
    let mut w = start;
    let mut now =
        totals(shots, scene, &w, &start, noise, settings).ok_or("no shot could be fitted")?;
    let mut iterations = 0;
    while iterations < max_iterations {
        iterations += 1;
        let (a, b, cost, _) = now;
        let step = -(a
            .try_inverse()
            .ok_or("the weather's normal matrix is singular")?
            * b);
        let mut scale = 1.0;
        let mut accepted = false;
        for _ in 0..5 {
            let cand = weather_of(
                SVector::<f64, 3>::from(weather_array(&w))
                    .zip_map(&step, |x, d| x + scale * d)
                    .into(),
            );
            if let Some(t) = totals(shots, scene, &cand, &start, noise, settings)
                && t.2 <= cost
            {
                w = cand;
                now = t;
                accepted = true;
                break;
            }
            scale *= 0.5;
        }
        // Converged: the step is below a hundredth of the posterior σ, or no step helps.
        let inv = a.try_inverse().ok_or("singular")?;
        let small = (0..3).all(|i| step[i].abs() < 0.01 * inv[(i, i)].sqrt());
        if !accepted || small {
            break;
        }
    }
    let (a, _, cost, fitted) = now;
    let inv = a
        .try_inverse()
        .ok_or("the weather's normal matrix is singular")?;
    Ok(JointWeather {
        weather: w,
        sd: [inv[(0, 0)].sqrt(), inv[(1, 1)].sqrt(), inv[(2, 2)].sqrt()],
        iterations,
        fitted,
        cost,
    })
}

/// Rows tracked outdoors more than this many rows apart start a new outing
/// ([`outing_starts`]): the file has no dates, but its outdoor rows come in runs separated by
/// 77 and more rows hit indoors (at 40: three outings of the premium ball, rows
/// 1,031–1,278, 1,370–1,700 and 1,778–1,999).
pub const OUTING_GAP_ROWS: usize = 40;

/// The first row of each outing: a run of rows tracked outdoors
/// ([`Drive::tracked_outdoors`], any ball) with no gap over [`OUTING_GAP_ROWS`] rows.
#[must_use]
pub fn outing_starts(drives: &[Drive]) -> Vec<usize> {
    let mut starts = Vec::new();
    let mut last: Option<usize> = None;
    for d in drives.iter().filter(|d| d.tracked_outdoors()) {
        if last.is_none_or(|l| d.index > l + OUTING_GAP_ROWS) {
            starts.push(d.index);
        }
        last = Some(d.index);
    }
    starts
}

/// The outing of row `index` given [`outing_starts`]: the last start at or before it.
#[must_use]
pub fn outing_of(starts: &[usize], index: usize) -> usize {
    starts.partition_point(|&s| s <= index).saturating_sub(1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drives::{BallKind, ClubMeasured, FlightMeasured, LaunchMeasured};

    fn drive(index: usize, last_x_m: f64) -> Drive {
        Drive {
            index,
            ball: BallKind::Premium,
            club: ClubMeasured::default(),
            launch: LaunchMeasured::default(),
            flight: FlightMeasured {
                last_point_m: Some([last_x_m, 10.0, 0.0]),
                ..FlightMeasured::default()
            },
            strike_m: None,
        }
    }

    /// A shot whose summaries (and last point at 3 s) are the flight of `launch` in `scene`.
    fn synthetic(index: usize, launch: [f64; 5], scene: &Scene<f64>) -> Shot {
        let mut shot = Shot {
            index,
            session: 0,
            launch,
            summaries: [0.0; 5],
            last_point: Some((3.0, [0.0; 3])),
        };
        let p = predict(&shot, scene, &launch, true).unwrap();
        shot.summaries.copy_from_slice(&p[..5]);
        shot.last_point = Some((3.0, [p[5], p[6], p[7]]));
        shot
    }

    fn launch(speed: f64, angle_deg: f64, spin_rpm: f64, axis_deg: f64) -> [f64; 5] {
        [
            speed,
            deg(angle_deg),
            deg(1.0),
            rpm(spin_rpm),
            deg(axis_deg),
        ]
    }

    #[test]
    fn robust_statistics() {
        assert_eq!(median(&mut [3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&mut [4.0, 1.0, 2.0, 3.0]), 2.5);
        assert!(median(&mut []).is_nan());
        // MAD of 1..=5 about 3 is 1; one wild value does not move it.
        assert!((robust_sd(&[1.0, 2.0, 3.0, 4.0, 5.0]) - 1.4826).abs() < 1e-12);
        assert!((robust_sd(&[1.0, 2.0, 3.0, 4.0, 500.0]) - 1.4826).abs() < 1e-12);
        // 68.27 % of 1..=100 lies at or below 69.
        let z: Vec<f64> = (1..=100).map(f64::from).collect();
        assert_eq!(sigma_scale(&z), 69.0);
        assert!((within(&z, 69.0) - 0.69).abs() < 1e-12);
    }

    #[test]
    fn noise_from_residuals_takes_the_scatter_but_not_below_the_base() {
        let r: Vec<[f64; 5]> = (0..5)
            .map(|i| {
                let x = f64::from(i) - 2.0;
                [x, 10.0 * x, 0.0, 0.01 * x, 0.0]
            })
            .collect();
        let n = noise_from_residuals(&r, Noise::RADAR);
        assert!((n.summaries[0] - 1.4826).abs() < 1e-12);
        assert!((n.summaries[1] - 14.826).abs() < 1e-12);
        assert_eq!(n.summaries[2], Noise::RADAR.summaries[2]);
        assert_eq!(n.summaries[3], Noise::RADAR.summaries[3]);
        assert_eq!(n.launch, Noise::RADAR.launch);
    }

    #[test]
    fn outings_split_at_long_indoor_gaps() {
        let drives: Vec<Drive> = (0..300)
            .map(|i| {
                let outdoors = (10..50).contains(&i) || (120..130).contains(&i) || i == 160;
                drive(i, if outdoors { 150.0 } else { 5.0 })
            })
            .collect();
        let starts = outing_starts(&drives);
        // 50 → 120 is 70 rows apart (a new outing), 129 → 160 is 31 (the same).
        assert_eq!(starts, vec![10, 120]);
        assert_eq!(outing_of(&starts, 30), 0);
        assert_eq!(outing_of(&starts, 160), 1);
    }

    #[test]
    fn summaries_of_the_held_out_model_give_its_spin_back() {
        let scene = Scene {
            aero: held_out_model(2),
            ..Scene::default()
        };
        let truth = launch(65.0, 12.0, 2800.0, -4.0);
        let shot = synthetic(0, truth, &scene);
        let fit = shot
            .fit(&scene, &Settings::default(), &Noise::RADAR, ALL, false)
            .unwrap();
        let e = SpinError::of(&shot, &fit);
        assert!(e.spin_rel.abs() < 0.01, "{e:?}");
        assert!(e.axis_deg.abs() < 0.2, "{e:?}");
        assert!(e.spin_within && e.axis_within, "{e:?}");
        let info = spin_information(&shot, &scene, &Noise::RADAR).unwrap();
        assert!((info.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        assert!(info.iter().all(|&x| x >= 0.0));
        // The held-out models differ from drives2026 and from each other.
        assert_ne!(held_out_model(2), held_out_model(3));
        assert_eq!(
            held_out_model(9),
            AeroModel::Modern(ModernAero::from_array(carry_core::aero::DRIVES_2026))
        );
    }

    #[test]
    fn errors_summarise_by_band() {
        let e = |rel: f64, spin: f64| SpinError {
            spin_rel: rel,
            axis_deg: -1.0,
            spin_within: rel.abs() < 0.05,
            axis_within: true,
            spin_z: rel.abs() / 0.05,
            spin_rpm: spin,
            ball_speed_mph: 140.0,
        };
        let errors = [e(0.1, 2000.0), e(-0.02, 2100.0), e(0.04, 3000.0)];
        let s = SpinSummary::of(&errors);
        assert_eq!(s.rows, 3);
        assert!((s.mean_abs_pct - 16.0 / 3.0).abs() < 1e-9);
        assert!((s.bias_pct - 4.0).abs() < 1e-9);
        assert!((s.median_pct - 4.0).abs() < 1e-9);
        assert!((s.axis_mean_abs_deg - 1.0).abs() < 1e-12);
        assert!((s.spin_within - 2.0 / 3.0).abs() < 1e-12);
        let b = SpinSummary::by_band(&errors, |x| x.spin_rpm, &[(0.0, 2500.0), (2500.0, 1e9)]);
        assert_eq!((b[0].rows, b[1].rows), (2, 1));
    }

    #[test]
    fn the_joint_weather_is_found_again_with_the_spins() {
        let scene = Scene {
            aero: held_out_model(0),
            ..Scene::default()
        };
        let truth = SessionWeather {
            density_kgm3: 1.12,
            tail_wind_mps: 2.0,
            cross_wind_mps: -1.5,
        };
        let windy = in_weather(&scene, &truth);
        let shots: Vec<Shot> = [
            (70.0, 10.0, 2500.0, 3.0),
            (62.0, 13.0, 3200.0, -5.0),
            (55.0, 15.0, 4000.0, 0.0),
            (67.0, 11.0, 2200.0, 8.0),
            (48.0, 18.0, 5200.0, -2.0),
            (58.0, 14.0, 3600.0, 4.0),
        ]
        .into_iter()
        .enumerate()
        .map(|(i, (v, a, s, x))| synthetic(i, launch(v, a, s, x), &windy))
        .collect();
        let refs: Vec<&Shot> = shots.iter().collect();
        let start = SessionWeather {
            density_kgm3: 1.2,
            tail_wind_mps: 0.0,
            cross_wind_mps: 0.0,
        };
        let j = joint_weather(
            &refs,
            &scene,
            start,
            &Noise::RADAR,
            &Settings::default(),
            12,
        )
        .unwrap();
        assert_eq!(j.fitted, shots.len());
        let w = j.weather;
        assert!((w.density_kgm3 - truth.density_kgm3).abs() < 0.01, "{j:?}");
        assert!((w.tail_wind_mps - truth.tail_wind_mps).abs() < 0.2, "{j:?}");
        assert!(
            (w.cross_wind_mps - truth.cross_wind_mps).abs() < 0.2,
            "{j:?}"
        );
        // In the fitted weather every shot's spin comes back.
        let fitted = in_weather(&scene, &w);
        for s in &shots {
            let f = s
                .fit(&fitted, &Settings::default(), &Noise::RADAR, ALL, true)
                .unwrap();
            assert!(SpinError::of(s, &f).spin_rel.abs() < 0.02);
        }
    }
}
