//! The forward model of the launch fit: one flight of the unknowns' launch through their
//! scene, read at every observation time from the integrator's dense output
//! ([`crate::Recorder::at_times`] into a sink that writes the predicted observations), then
//! the summaries from the flight's outcome.

use super::{MAX_DOPPLER_SAMPLES, MAX_TRACK_POINTS, Observations, Settings, UNKNOWNS};
use crate::air::Air;
use crate::ball::Ball;
use crate::error::Result;
use crate::flight::FlightOutcome;
use crate::launch::Launch;
use crate::real::{Real, length, lit};
use crate::scene::{PreparedScene, Scene};
use crate::trajectory::{Recorder, Sample, SampleSink};
use crate::wind::Wind;
use nalgebra::Vector3;

/// Which flight observation a residual row holds (rows are in this order: the track's
/// coordinates point by point, the Doppler samples, then the summaries present).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum Observed {
    /// Coordinate `axis` (0 x, 1 y, 2 z) of track point `index`.
    Track {
        /// The point's index.
        index: u16,
        /// 0 x, 1 y, 2 z.
        axis: u8,
    },
    /// Doppler sample `index`.
    Doppler(u16),
    /// Apex height.
    ApexHeight,
    /// Apex time.
    ApexTime,
    /// Carry.
    Carry,
    /// Side.
    Side,
    /// Flight time.
    FlightTime,
    /// Landing angle.
    LandAngle,
}

const SCHEDULED: usize = MAX_TRACK_POINTS + MAX_DOPPLER_SAMPLES;

/// The observation times of track and Doppler merged in time order, and where each came
/// from (`< MAX_TRACK_POINTS`: a track point; else a Doppler sample, offset by it).
pub(super) struct Schedule<T> {
    pub(super) times: [T; SCHEDULED],
    origin: [u16; SCHEDULED],
    pub(super) len: usize,
}

impl<T: Real> Schedule<T> {
    pub(super) fn of(obs: &Observations<T>) -> Self {
        let mut s = Self {
            times: [T::zero(); SCHEDULED],
            origin: [0; SCHEDULED],
            len: 0,
        };
        let (mut i, mut j) = (0usize, 0usize);
        let doppler_origin = |j: usize| u16::try_from(MAX_TRACK_POINTS + j).unwrap_or(u16::MAX);
        loop {
            let p = obs.track.get(i).map(|p| p.time_s);
            let d = obs.doppler.get(j).map(|d| d.time_s);
            let (time, origin) = match (p, d) {
                (Some(tp), Some(td)) if tp <= td => {
                    i += 1;
                    (tp, u16::try_from(i - 1).unwrap_or(u16::MAX))
                }
                (Some(tp), None) => {
                    i += 1;
                    (tp, u16::try_from(i - 1).unwrap_or(u16::MAX))
                }
                (_, Some(td)) => {
                    j += 1;
                    (td, doppler_origin(j - 1))
                }
                (None, None) => break,
            };
            if let (Some(t), Some(o)) = (s.times.get_mut(s.len), s.origin.get_mut(s.len)) {
                *t = time;
                *o = origin;
                s.len += 1;
            } else {
                break;
            }
        }
        s
    }

    fn times(&self) -> &[T] {
        self.times.get(..self.len).unwrap_or(&[])
    }
}

/// Writes the predicted track positions and radial speeds into their rows as the flight
/// hands it the scheduled samples.
struct Sink<'a, T: Real> {
    obs: &'a Observations<T>,
    schedule: &'a Schedule<T>,
    rows: &'a mut [T],
    next: usize,
}

impl<T: Real> Sink<'_, T> {
    #[inline(always)]
    fn write(&mut self, k: usize, position: &Vector3<T>, velocity: &Vector3<T>) {
        let Some(&origin) = self.schedule.origin.get(k) else {
            return;
        };
        let origin = usize::from(origin);
        let n_track = self.obs.track.len();
        if origin < MAX_TRACK_POINTS {
            for (a, v) in position.iter().enumerate() {
                if let Some(r) = self.rows.get_mut(3 * origin + a) {
                    *r = *v;
                }
            }
        } else {
            let j = origin - MAX_TRACK_POINTS;
            let line = position - self.obs.radar_position_m;
            let distance = length(&line);
            let radial = if distance > T::zero() {
                velocity.dot(&line) / distance
            } else {
                length(velocity)
            };
            if let Some(r) = self.rows.get_mut(3 * n_track + j) {
                *r = radial;
            }
        }
    }
}

impl<T: Real> SampleSink<T> for Sink<'_, T> {
    fn clear(&mut self) {
        self.next = 0;
    }

    fn push(&mut self, sample: Sample<T>) -> bool {
        // The scheduled samples come first, at exactly their times; the landing sample
        // after them (or before the times past the landing) is not one of them.
        let scheduled = self.schedule.times.get(self.next).copied();
        if self.next < self.schedule.len && scheduled == Some(sample.time_s) {
            self.write(self.next, &sample.position_m, &sample.velocity_mps);
            self.next += 1;
        }
        true
    }
}

/// The scene the unknowns `x` fly through: the given one, its wind replaced by a uniform
/// `(x₅, 0, x₆)` when fitted, its air by the density `x₇` when fitted; no ground.
pub(super) fn scene_of<T: Real>(
    base: &Scene<T>,
    x: &[T; UNKNOWNS],
    settings: &Settings<T>,
) -> Scene<T> {
    let mut scene = *base;
    scene.ground = None;
    let at = |i: usize| x.get(i).copied().unwrap_or_else(T::zero);
    if settings.fit_wind {
        scene.wind = Wind::Uniform(Vector3::new(at(5), T::zero(), at(6)));
    }
    if settings.fit_air_density {
        scene.air = Air::Density(at(7));
    }
    scene
}

/// The prepared scene every flight of a fit shares when neither wind nor air density is
/// fitted (`None` otherwise: each flight then prepares its own, [`scene_of`]). Preparing
/// is deterministic, so sharing it changes no bit; it saves a scene copy and preparation
/// per flight (≈ 4k of ≈ 18k instructions on a Cortex-M4F, docs/firmware.md).
///
/// # Errors
/// The scene's errors.
pub(super) fn shared_scene<T: Real>(
    ball: &Ball<T>,
    base: &Scene<T>,
    settings: &Settings<T>,
) -> Result<Option<PreparedScene<T>>> {
    if settings.fit_wind || settings.fit_air_density {
        return Ok(None);
    }
    scene_of(base, &[T::zero(); UNKNOWNS], settings)
        .prepare(ball)
        .map(Some)
}

/// Flies the unknowns `x` and writes every predicted flight observation into `rows` (in
/// [`Observed`] order). Observation times after the modelled landing continue the landing
/// state ballistically (a smooth continuation for the solver; at a fit that matches, no
/// observation is after the landing). `shared`: the scene from [`shared_scene`].
///
/// # Errors
/// The flight's (and the scene's) errors.
#[allow(clippy::too_many_arguments)]
pub(super) fn predict<T: Real>(
    ball: &Ball<T>,
    base: &Scene<T>,
    shared: Option<&PreparedScene<T>>,
    x: &[T; UNKNOWNS],
    obs: &Observations<T>,
    schedule: &Schedule<T>,
    settings: &Settings<T>,
    rows: &mut [T],
) -> Result<FlightOutcome<T>> {
    let at = |i: usize| x.get(i).copied().unwrap_or_else(T::zero);
    let launch = Launch::from_spin_axis(at(0), at(1), at(2), at(3), at(4)).ball_motion()?;
    let own;
    let scene = match shared {
        Some(s) => s,
        None => {
            own = scene_of(base, x, settings).prepare(ball)?;
            &own
        }
    };
    let mut sink = Sink {
        obs,
        schedule,
        rows,
        next: 0,
    };
    let outcome = {
        let mut recorder = Recorder::at_times(schedule.times(), &mut sink)?;
        scene.fly(&launch, &settings.integrator, Some(&mut recorder))?
    };
    // Times past the landing: the landing state continued under gravity alone.
    let g = Vector3::new(T::zero(), -base.gravity_mps2, T::zero());
    let half = lit::<T>(0.5);
    for k in sink.next..schedule.len {
        let t = schedule.times.get(k).copied().unwrap_or_else(T::zero);
        let dt = t - outcome.flight_time_s;
        let p =
            outcome.landing_position_m + outcome.landing_velocity_mps * dt + g * (half * dt * dt);
        let v = outcome.landing_velocity_mps + g * dt;
        sink.write(k, &p, &v);
    }
    let start = 3 * obs.track.len() + obs.doppler.len();
    let predicted = [
        outcome.apex_m,
        outcome.apex_time_s,
        outcome.carry_m,
        outcome.side_m,
        outcome.flight_time_s,
        outcome.landing_angle_rad,
    ];
    let mut row = start;
    for (s, p) in obs.summaries().iter().zip(predicted) {
        if s.is_some() {
            if let Some(r) = sink.rows.get_mut(row) {
                *r = p;
            }
            row += 1;
        }
    }
    Ok(outcome)
}

/// The observed values and their 1σ in row order (the same layout as [`predict`]).
pub(super) fn observed<T: Real>(obs: &Observations<T>, value: &mut [T], sd: &mut [T]) {
    let mut row = 0;
    let mut put = |v: T, s: T| {
        if let (Some(a), Some(b)) = (value.get_mut(row), sd.get_mut(row)) {
            *a = v;
            *b = s;
        }
        row += 1;
    };
    for p in &obs.track {
        for v in p.position_m.iter() {
            put(*v, p.sd_m);
        }
    }
    for d in &obs.doppler {
        put(d.radial_speed_mps, d.sd_mps);
    }
    for s in obs.summaries().iter().flatten() {
        put(s.value, s.sd);
    }
}

/// What row `row` holds.
#[must_use]
pub(super) fn row_kind<T: Real>(obs: &Observations<T>, row: usize) -> Observed {
    let n_track = obs.track.len();
    let n_doppler = obs.doppler.len();
    if row < 3 * n_track {
        return Observed::Track {
            index: u16::try_from(row / 3).unwrap_or(u16::MAX),
            axis: u8::try_from(row % 3).unwrap_or(0),
        };
    }
    if row < 3 * n_track + n_doppler {
        return Observed::Doppler(u16::try_from(row - 3 * n_track).unwrap_or(u16::MAX));
    }
    let kinds = [
        Observed::ApexHeight,
        Observed::ApexTime,
        Observed::Carry,
        Observed::Side,
        Observed::FlightTime,
        Observed::LandAngle,
    ];
    let mut k = 3 * n_track + n_doppler;
    for (s, kind) in obs.summaries().iter().zip(kinds) {
        if s.is_some() {
            if k == row {
                return kind;
            }
            k += 1;
        }
    }
    Observed::LandAngle
}
