//! The launch from the flight (issue 36): `carry_core::launch_fit` on synthetic
//! observations of known launches — summaries (apex, carry, side, flight time, landing
//! angle) with the launch measured, a radar track, a Doppler trace.
//!
//! Like `cases.rs`, compiled into the firmware and `#[path]`-included by `build.rs`, which
//! runs the same code on the host so that the on-target tests can demand bit identity. The
//! observations are made here, in the precision of the fit: the true launch is flown with
//! the default model and integrator, read at the observation times
//! ([`carry_core::Recorder::at_times`]), and given a deterministic pseudo-noise (an LCG
//! summed Irwin–Hall to an approximately normal deviate, in f64 arithmetic only, so the
//! host and the target draw the same numbers). Noise model as `launch_fit_report`
//! (docs/launch_fit.md §3): positions σ = 0.05 m + 0.002 × range, radial speeds 0.1 m/s,
//! summaries as the CLI's defaults, the measured launch 0.2 m/s, 0.2°, 0.3° (axis 3°).
//! It uses only `core`, `carry-core` and `nalgebra`.
#![allow(dead_code)]

use carry_core::launch_fit::{
    Datum, DopplerSample, LaunchValues, MeasuredLaunch, Observations, Settings, TrackPoint,
    Workspace, fit_launch,
};
use carry_core::real::{Real, lit, to_f64};
use carry_core::units::{deg, rpm};
use carry_core::{Ball, Error, Integrator, Launch, Recorder, Sample, SampleSink, Scene};
use nalgebra::Vector3;

/// What a case observes of the flight.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Seen {
    /// Apex height, carry, flight time, landing angle, and the side when `side`.
    Summaries {
        /// Whether the side at the landing is observed.
        side: bool,
    },
    /// `points` radar positions, evenly spaced over `duration_s` (the first at
    /// `duration_s / points`).
    Track {
        /// Points (≤ 64).
        points: u16,
        /// Duration (s).
        duration_s: f64,
    },
    /// `samples` radial speeds from 2.5 m behind the tee, 0.3 m up, evenly spaced over
    /// `duration_s`.
    Doppler {
        /// Samples (≤ 256).
        samples: u16,
        /// Duration (s).
        duration_s: f64,
    },
}

/// One launch fit: the true launch, what is observed and what is measured at launch.
#[derive(Debug, Clone, Copy)]
pub struct LaunchFitCase {
    pub name: &'static str,
    /// Ball speed (m/s), launch angle (°), launch direction (°), spin (rpm), axis (°).
    pub truth: [f64; 5],
    pub seen: Seen,
    /// Ball speed, launch angle and direction measured (else fitted too).
    pub launch_measured: bool,
    /// The spin axis measured (3°) too (a Doppler trace from behind barely sees it).
    pub axis_measured: bool,
    /// Seed of the pseudo-noise.
    pub seed: u64,
}

/// The on-target launch fits.
pub const LAUNCH_FIT_CASES: [LaunchFitCase; 5] = [
    // (a) launch measured + apex, carry, side, flight time, landing angle → spin and axis
    LaunchFitCase {
        name: "driver_summaries",
        truth: [70.0, 12.0, 1.0, 2700.0, 6.0],
        seen: Seen::Summaries { side: true },
        launch_measured: true,
        axis_measured: false,
        seed: 1,
    },
    LaunchFitCase {
        name: "7iron_summaries",
        truth: [53.0, 17.0, -0.5, 6800.0, -4.0],
        seen: Seen::Summaries { side: true },
        launch_measured: true,
        axis_measured: false,
        seed: 2,
    },
    // no side: the axis's sign is not seen, a typed error (Unidentifiable(SpinAxis))
    LaunchFitCase {
        name: "driver_summaries_without_side",
        truth: [70.0, 12.0, 1.0, 2700.0, 6.0],
        seen: Seen::Summaries { side: false },
        launch_measured: true,
        axis_measured: false,
        seed: 1,
    },
    // (b) 32 radar positions over 1.5 s → the full launch (nothing measured)
    LaunchFitCase {
        name: "driver_track32_full_launch",
        truth: [70.0, 12.0, 1.0, 2700.0, 6.0],
        seen: Seen::Track {
            points: 32,
            duration_s: 1.5,
        },
        launch_measured: false,
        axis_measured: false,
        seed: 3,
    },
    // (c) one second of Doppler at 100 Hz, launch and axis measured → spin
    LaunchFitCase {
        name: "driver_doppler100",
        truth: [70.0, 12.0, 1.0, 2700.0, 6.0],
        seen: Seen::Doppler {
            samples: 100,
            duration_s: 1.0,
        },
        launch_measured: true,
        axis_measured: true,
        seed: 4,
    },
];

/// The fits the cost harness counts (`src/bin/cost.rs`) beside [`LAUNCH_FIT_CASES`]: the
/// observation sets of docs/launch_fit.md §3 (positions at 20 Hz, Doppler at 100 Hz, over
/// 0.25, 0.5, 1 and 2 s, the launch measured; the axis too with Doppler) on the driver.
pub const COST_CASES: [LaunchFitCase; 8] = {
    const fn track(name: &'static str, points: u16, duration_s: f64) -> LaunchFitCase {
        LaunchFitCase {
            name,
            truth: [70.0, 12.0, 1.0, 2700.0, 6.0],
            seen: Seen::Track { points, duration_s },
            launch_measured: true,
            axis_measured: false,
            seed: 5,
        }
    }
    const fn doppler(name: &'static str, samples: u16, duration_s: f64) -> LaunchFitCase {
        LaunchFitCase {
            name,
            truth: [70.0, 12.0, 1.0, 2700.0, 6.0],
            seen: Seen::Doppler {
                samples,
                duration_s,
            },
            launch_measured: true,
            axis_measured: true,
            seed: 6,
        }
    }
    [
        track("launch fit: positions 0.25 s (5 at 20 Hz) [f32]", 5, 0.25),
        track("launch fit: positions 0.5 s (10 at 20 Hz) [f32]", 10, 0.5),
        track("launch fit: positions 1 s (20 at 20 Hz) [f32]", 20, 1.0),
        track("launch fit: positions 2 s (40 at 20 Hz) [f32]", 40, 2.0),
        doppler("launch fit: Doppler 0.25 s (25 at 100 Hz) [f32]", 25, 0.25),
        doppler("launch fit: Doppler 0.5 s (50 at 100 Hz) [f32]", 50, 0.5),
        doppler("launch fit: Doppler 1 s (100 at 100 Hz) [f32]", 100, 1.0),
        doppler("launch fit: Doppler 2 s (200 at 100 Hz) [f32]", 200, 2.0),
    ]
};

/// Launch-fit outputs, in this order: the five launch values (SI), their five 1σ, χ², the
/// worst residual (σ), iterations, flights, and the fitted launch's carry (m).
pub const LAUNCH_FIT_OUTPUTS: usize = 15;
/// Names of the launch-fit outputs (for messages).
pub const LAUNCH_FIT_NAMES: [&str; LAUNCH_FIT_OUTPUTS] = [
    "ball_speed",
    "launch_angle",
    "launch_direction",
    "spin",
    "spin_axis",
    "ball_speed_sd",
    "launch_angle_sd",
    "launch_direction_sd",
    "spin_sd",
    "spin_axis_sd",
    "chi2",
    "worst_residual_sigma",
    "iterations",
    "flights",
    "carry",
];

/// A deterministic, approximately normal deviate stream: Knuth's MMIX LCG, twelve 24-bit
/// uniforms summed minus 6 (Irwin–Hall; variance 1). Integer and f64 `+ − ×` only, so the
/// host and every target draw the same numbers.
pub struct Noise(u64);

impl Noise {
    /// A stream from `seed`.
    #[must_use]
    pub const fn new(seed: u64) -> Self {
        Self(seed)
    }

    fn uniform(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        // 24 high bits: exact in f64, in [0, 1).
        (self.0 >> 40) as f64 * (1.0 / 16_777_216.0)
    }

    /// The next deviate.
    pub fn next(&mut self) -> f64 {
        let mut s = 0.0;
        for _ in 0..12 {
            s += self.uniform();
        }
        s - 6.0
    }
}

/// The first `N` samples of a flight.
struct Samples<T: Real, const N: usize> {
    samples: [Option<Sample<T>>; N],
    len: usize,
}

impl<T: Real, const N: usize> SampleSink<T> for Samples<T, N> {
    fn clear(&mut self) {
        self.len = 0;
    }
    fn push(&mut self, s: Sample<T>) -> bool {
        if let Some(slot) = self.samples.get_mut(self.len) {
            *slot = Some(s);
            self.len += 1;
            true
        } else {
            false
        }
    }
}

/// The largest number of timed observations of a case.
const MAX_TIMES: usize = 256;

impl LaunchFitCase {
    /// The true launch (SI).
    #[must_use]
    pub fn truth<T: Real>(&self) -> LaunchValues<T> {
        let [speed, angle, direction, spin, axis] = self.truth;
        LaunchValues {
            ball_speed_mps: lit(speed),
            launch_angle_rad: deg(lit(angle)),
            launch_direction_rad: deg(lit(direction)),
            spin_radps: rpm(lit(spin)),
            spin_axis_rad: deg(lit(axis)),
        }
    }

    /// The fit's inputs: what was measured at launch and the observations, noisy.
    ///
    /// # Errors
    /// The true flight's error (none for these cases).
    pub fn inputs<T: Real>(&self) -> Result<(MeasuredLaunch<T>, Observations<T>), Error> {
        let truth = self.truth::<T>();
        let mut noise = Noise::new(self.seed);
        let (n, duration_s) = match self.seen {
            Seen::Summaries { .. } => (0, 0.0),
            Seen::Track { points, duration_s } => (usize::from(points), duration_s),
            Seen::Doppler {
                samples,
                duration_s,
            } => (usize::from(samples), duration_s),
        };
        let n = n.min(MAX_TIMES);
        let mut times = [T::zero(); MAX_TIMES];
        for (k, t) in times.iter_mut().enumerate().take(n) {
            *t = lit(duration_s * (k + 1) as f64 / n as f64);
        }
        let scene = Scene::<T>::default().prepare(&Ball::standard())?;
        let motion = Launch::from_spin_axis(
            truth.ball_speed_mps,
            truth.launch_angle_rad,
            truth.launch_direction_rad,
            truth.spin_radps,
            truth.spin_axis_rad,
        )
        .ball_motion()?;
        let mut sink = Samples::<T, MAX_TIMES> {
            samples: [None; MAX_TIMES],
            len: 0,
        };
        let outcome = {
            let mut rec = Recorder::at_times(times.get(..n).unwrap_or(&[]), &mut sink)?;
            scene.fly(&motion, &Integrator::default(), Some(&mut rec))?
        };
        let mut obs = Observations::<T>::default();
        let scheduled = sink.samples.iter().take(sink.len.min(n)).flatten();
        match self.seen {
            Seen::Summaries { side } => {
                let mut datum = |v: T, sd: T| Some(Datum::new(v + sd * lit(noise.next()), sd));
                obs.apex_height_m = datum(outcome.apex_m, lit(0.5));
                obs.carry_m = datum(outcome.carry_m, lit(1.0));
                let s = datum(outcome.side_m, lit(0.5));
                if side {
                    obs.side_m = s;
                }
                obs.flight_time_s = datum(outcome.flight_time_s, lit(0.05));
                obs.land_angle_rad = datum(outcome.landing_angle_rad, deg(lit(0.5)));
            }
            Seen::Track { .. } => {
                for s in scheduled {
                    let range = s.position_m.norm();
                    let sd = lit::<T>(0.05) + lit::<T>(0.002) * range;
                    let e = Vector3::new(lit(noise.next()), lit(noise.next()), lit(noise.next()));
                    // capacity: at most 64 points by construction of the cases
                    let _ = obs.track.push(TrackPoint {
                        time_s: s.time_s,
                        position_m: s.position_m + e * sd,
                        sd_m: sd,
                    });
                }
            }
            Seen::Doppler { .. } => {
                let radar = obs.radar_position_m;
                for s in scheduled {
                    let line = s.position_m - radar;
                    let radial = s.velocity_mps.dot(&line) / line.norm();
                    let sd = lit::<T>(0.1);
                    let _ = obs.doppler.push(DopplerSample {
                        time_s: s.time_s,
                        radial_speed_mps: radial + sd * lit(noise.next()),
                        sd_mps: sd,
                    });
                }
            }
        }
        let mut measured = MeasuredLaunch::<T>::default();
        let mut measure = |v: T, sd: T| Some(Datum::new(v + sd * lit(noise.next()), sd));
        if self.launch_measured {
            measured.ball_speed_mps = measure(truth.ball_speed_mps, lit(0.2));
            measured.launch_angle_rad = measure(truth.launch_angle_rad, deg(lit(0.2)));
            measured.launch_direction_rad = measure(truth.launch_direction_rad, deg(lit(0.3)));
        }
        if self.axis_measured {
            measured.spin_axis_rad = measure(truth.spin_axis_rad, deg(lit(3.0)));
        }
        Ok((measured, obs))
    }

    /// The fit with the default settings, flattened (see [`LAUNCH_FIT_OUTPUTS`]).
    ///
    /// # Errors
    /// The core's error (`Unidentifiable(SpinAxis)` for the case without side).
    pub fn outputs<T: Real>(
        &self,
        workspace: &mut Workspace<T>,
    ) -> Result<[T; LAUNCH_FIT_OUTPUTS], Error> {
        let (measured, obs) = self.inputs::<T>()?;
        let fit = fit_launch(
            &Ball::standard(),
            &Scene::default(),
            &measured,
            &obs,
            &Settings::default(),
            workspace,
        )?;
        let mut out = [T::zero(); LAUNCH_FIT_OUTPUTS];
        let all = fit
            .value
            .to_array()
            .into_iter()
            .chain(fit.sd.to_array())
            .chain([
                fit.chi2,
                fit.worst_residual_sigma,
                lit(f64::from(fit.iterations)),
                lit(f64::from(fit.flights)),
                fit.flight.carry_m,
            ]);
        for (o, v) in out.iter_mut().zip(all) {
            *o = v;
        }
        Ok(out)
    }
}

/// How far a fitted launch value is from the truth, in its fitted σ (for the on-target
/// sanity check: the fit must land near the launch that made the data).
#[must_use]
pub fn sigmas_off<T: Real>(case: &LaunchFitCase, out: &[T; LAUNCH_FIT_OUTPUTS]) -> [f64; 5] {
    let truth = case.truth::<T>().to_array();
    core::array::from_fn(|i| {
        let v = out.get(i).copied().map_or(f64::NAN, to_f64);
        let sd = out.get(i + 5).copied().map_or(f64::NAN, to_f64);
        let t = truth.get(i).copied().map_or(f64::NAN, to_f64);
        (v - t) / sd
    })
}
