//! The launch from the flight (`carry_core::launch_fit`, issue 36): noise-free round trips
//! from summaries, a radar track and a Doppler trace (to 1e-3 posterior σ), the 1σ's
//! calibration on noisy synthetic shots, the typed errors, f32 beside f64.

use carry_core::Real;
use carry_core::launch_fit::{
    Datum, DopplerSample, LaunchValues, MeasuredLaunch, Observations, Settings, Source, TrackPoint,
    Workspace, fit_launch,
};
use carry_core::real::lit;
use carry_core::units::{deg, rpm};
use carry_core::{Ball, Error, Field, Integrator, Launch, Recorder, Sample, Scene};
use nalgebra::Vector3;

/// A driver: 70 m/s, 12°, 1° right, 2,700 rpm, axis 6° (a fade).
fn truth<T: Real>() -> LaunchValues<T> {
    LaunchValues {
        ball_speed_mps: lit(70.0),
        launch_angle_rad: deg(lit(12.0)),
        launch_direction_rad: deg(lit(1.0)),
        spin_radps: rpm(lit(2700.0)),
        spin_axis_rad: deg(lit(6.0)),
    }
}

fn launch_of<T: Real>(v: &LaunchValues<T>) -> Launch<T> {
    Launch::from_spin_axis(
        v.ball_speed_mps,
        v.launch_angle_rad,
        v.launch_direction_rad,
        v.spin_radps,
        v.spin_axis_rad,
    )
}

/// The measured launch without spin and axis: speed 0.2 m/s, angles 0.2°.
fn measured<T: Real>(v: &LaunchValues<T>) -> MeasuredLaunch<T> {
    LaunchValues {
        ball_speed_mps: Some(Datum::new(v.ball_speed_mps, lit(0.2))),
        launch_angle_rad: Some(Datum::new(v.launch_angle_rad, deg(lit(0.2)))),
        launch_direction_rad: Some(Datum::new(v.launch_direction_rad, deg(lit(0.2)))),
        spin_radps: None,
        spin_axis_rad: None,
    }
}

struct Samples<T: Real>(Vec<Sample<T>>);

impl<T: Real> carry_core::SampleSink<T> for Samples<T> {
    fn clear(&mut self) {
        self.0.clear();
    }
    fn push(&mut self, s: Sample<T>) -> bool {
        self.0.push(s);
        true
    }
}

/// The true flight: its outcome and its samples at `times`.
fn fly_truth<T: Real>(
    v: &LaunchValues<T>,
    integrator: &Integrator<T>,
    times: &[T],
) -> (carry_core::FlightOutcome<T>, Vec<Sample<T>>) {
    let scene = Scene::<T>::default().prepare(&Ball::standard()).unwrap();
    let motion = launch_of(v).ball_motion().unwrap();
    let mut sink = Samples(Vec::new());
    let outcome = {
        let mut rec = Recorder::at_times(times, &mut sink).unwrap();
        scene.fly(&motion, integrator, Some(&mut rec)).unwrap()
    };
    (outcome, sink.0)
}

/// Summaries with their 1σ: apex 0.5 m, carry 1 m, side 0.5 m, flight time 0.05 s,
/// landing angle 0.5°.
fn summaries<T: Real>(o: &carry_core::FlightOutcome<T>) -> Observations<T> {
    Observations {
        apex_height_m: Some(Datum::new(o.apex_m, lit(0.5))),
        carry_m: Some(Datum::new(o.carry_m, lit(1.0))),
        side_m: Some(Datum::new(o.side_m, lit(0.5))),
        flight_time_s: Some(Datum::new(o.flight_time_s, lit(0.05))),
        land_angle_rad: Some(Datum::new(o.landing_angle_rad, deg(lit(0.5)))),
        ..Observations::default()
    }
}

/// A tight integrator and tolerance, and priors 1,000 times broader than the defaults:
/// without noise, the MAP is the truth up to the prior's pull, `(σ_post/s)²·(μ − x)`.
fn settings<T: Real>(integrator: Integrator<T>) -> Settings<T> {
    let mut s = Settings {
        integrator,
        tolerance: lit(1e-5),
        ..Settings::default()
    };
    let k = lit::<T>(1000.0);
    s.prior.sd = LaunchValues::from_array(s.prior.sd.to_array().map(|v| v * k));
    s.prior.wind_sd_mps *= k;
    s
}

fn assert_round_trip(
    fit: &carry_core::launch_fit::LaunchFit<f64>,
    v: &LaunchValues<f64>,
    tol_sigma: f64,
) {
    let got = fit.value.to_array();
    let sd = fit.sd.to_array();
    for (i, (g, t)) in got.iter().zip(v.to_array()).enumerate() {
        assert!(
            (g - t).abs() <= tol_sigma * sd[i],
            "unknown {i}: {g} vs {t} (σ {})",
            sd[i]
        );
    }
}

#[test]
fn summaries_round_trip_to_a_thousandth_of_a_sigma() {
    let v = truth::<f64>();
    let tight = Integrator::tight();
    let (o, _) = fly_truth(&v, &tight, &[]);
    let obs = summaries(&o);
    let mut ws = Workspace::new();
    let fit = fit_launch(
        &Ball::standard(),
        &Scene::default(),
        &measured(&v),
        &obs,
        &settings(tight),
        &mut ws,
    )
    .unwrap();
    assert_round_trip(&fit, &v, 1e-3);
    assert_eq!(fit.source.spin_radps, Source::Fitted);
    assert_eq!(fit.source.ball_speed_mps, Source::Measured);
    // The spin is pinned to a few per cent by these summaries.
    assert!(
        fit.sd.spin_radps < 0.1 * v.spin_radps,
        "{}",
        fit.sd.spin_radps
    );
    assert!(fit.chi2 < 1e-4, "{}", fit.chi2);
    assert!(fit.flights < 60, "{}", fit.flights);
}

#[test]
fn a_radar_track_round_trips_and_fits_wind() {
    let v = truth::<f64>();
    let tight = Integrator::tight();
    // 32 points over the first 2 s, 5 cm each.
    let times: Vec<f64> = (1..=32).map(|k| f64::from(k) * 2.0 / 32.0).collect();
    let scene = Scene {
        wind: carry_core::Wind::Uniform(Vector3::new(-3.0, 0.0, 2.0)),
        ..Scene::default()
    };
    let prepared = scene.prepare(&Ball::standard()).unwrap();
    let motion = launch_of(&v).ball_motion().unwrap();
    let mut sink = Samples(Vec::new());
    {
        let mut rec = Recorder::at_times(&times, &mut sink).unwrap();
        prepared.fly(&motion, &tight, Some(&mut rec)).unwrap();
    }
    let mut obs = Observations::default();
    for s in sink.0.iter().take(times.len()) {
        obs.track
            .push(TrackPoint {
                time_s: s.time_s,
                position_m: s.position_m,
                sd_m: 0.05,
            })
            .unwrap();
    }
    assert_eq!(obs.track.len(), 32);
    let mut ws = Workspace::new();
    let settings = Settings {
        fit_wind: true,
        ..settings(tight)
    };
    let fit = fit_launch(
        &Ball::standard(),
        &Scene::default(),
        &measured(&v),
        &obs,
        &settings,
        &mut ws,
    )
    .unwrap();
    assert_round_trip(&fit, &v, 1e-3);
    let wind = fit.wind_mps.unwrap();
    assert!((wind[0].value + 3.0).abs() <= 1e-3 * wind[0].sd, "{wind:?}");
    assert!((wind[1].value - 2.0).abs() <= 1e-3 * wind[1].sd, "{wind:?}");
}

#[test]
fn a_doppler_trace_round_trips() {
    let v = truth::<f64>();
    let tight = Integrator::tight();
    // One second at 100 Hz, radar 2.5 m behind the tee, 0.3 m up.
    let times: Vec<f64> = (1..=100).map(|k| f64::from(k) * 0.01).collect();
    let (_, samples) = fly_truth(&v, &tight, &times);
    let mut obs = Observations::default();
    let radar = obs.radar_position_m;
    for s in samples.iter().take(times.len()) {
        let line = s.position_m - radar;
        obs.doppler
            .push(DopplerSample {
                time_s: s.time_s,
                radial_speed_mps: s.velocity_mps.dot(&line) / line.norm(),
                sd_mps: 0.1,
            })
            .unwrap();
    }
    let mut ws = Workspace::new();
    // Spin only: a trace from straight behind barely sees the axis, so it is measured.
    let mut m = measured(&v);
    m.spin_axis_rad = Some(Datum::new(v.spin_axis_rad, deg(1.5)));
    let fit = fit_launch(
        &Ball::standard(),
        &Scene::default(),
        &m,
        &obs,
        &settings(tight),
        &mut ws,
    )
    .unwrap();
    assert_round_trip(&fit, &v, 1e-3);
    assert!(
        fit.sd.spin_radps < 0.05 * v.spin_radps,
        "{}",
        fit.sd.spin_radps
    );
}

/// A deterministic normal deviate stream (Box–Muller over a 64-bit LCG).
struct Normal(u64);

impl Normal {
    fn uniform(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    fn next(&mut self) -> f64 {
        let (u, w) = (self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (2.0 * std::f64::consts::PI * w).cos()
    }
}

#[test]
fn the_one_sigma_is_calibrated_on_noisy_shots() {
    let mut n = Normal(36);
    let integrator = Integrator::default();
    let (mut within_spin, mut within_axis, mut shots) = (0, 0, 0);
    for k in 0..120 {
        let v = LaunchValues {
            ball_speed_mps: 55.0 + 20.0 * n.uniform(),
            launch_angle_rad: deg(8.0 + 10.0 * n.uniform()),
            launch_direction_rad: deg(-3.0 + 6.0 * n.uniform()),
            spin_radps: rpm(2000.0 + 4000.0 * n.uniform()),
            spin_axis_rad: deg(-15.0 + 30.0 * n.uniform()),
        };
        let (o, _) = fly_truth(&v, &integrator, &[]);
        let mut obs = summaries(&o);
        for d in [
            &mut obs.apex_height_m,
            &mut obs.carry_m,
            &mut obs.side_m,
            &mut obs.flight_time_s,
            &mut obs.land_angle_rad,
        ]
        .into_iter()
        .flatten()
        {
            d.value += d.sd * n.next();
        }
        let mut m = measured(&v);
        for d in [
            &mut m.ball_speed_mps,
            &mut m.launch_angle_rad,
            &mut m.launch_direction_rad,
        ]
        .into_iter()
        .flatten()
        {
            d.value += d.sd * n.next();
        }
        let mut ws = Workspace::new();
        let fit = fit_launch(
            &Ball::standard(),
            &Scene::default(),
            &m,
            &obs,
            &Settings::default(),
            &mut ws,
        )
        .unwrap_or_else(|e| panic!("shot {k}: {e}"));
        shots += 1;
        within_spin +=
            usize::from((fit.value.spin_radps - v.spin_radps).abs() <= fit.sd.spin_radps);
        within_axis +=
            usize::from((fit.value.spin_axis_rad - v.spin_axis_rad).abs() <= fit.sd.spin_axis_rad);
    }
    let (fs, fa) = (
        within_spin as f64 / shots as f64,
        within_axis as f64 / shots as f64,
    );
    println!("within 1σ: spin {fs:.2}, axis {fa:.2} over {shots} shots");
    // 68 % expected; ±0.12 covers the binomial spread of 120 shots (σ ≈ 0.043) nearly 3×.
    assert!((0.56..=0.80).contains(&fs), "spin {fs}");
    assert!((0.56..=0.80).contains(&fa), "axis {fa}");
}

#[test]
fn too_few_or_uninformative_observations_are_typed_errors() {
    let v = truth::<f64>();
    let (o, _) = fly_truth(&v, &Integrator::default(), &[]);
    let ball = Ball::standard();
    let scene = Scene::default();
    let s = Settings::default();
    let mut ws = Workspace::new();
    // Carry alone for spin and axis.
    let only_carry = Observations {
        carry_m: Some(Datum::new(o.carry_m, 1.0)),
        ..Observations::default()
    };
    assert_eq!(
        fit_launch(&ball, &scene, &measured(&v), &only_carry, &s, &mut ws).unwrap_err(),
        Error::TooFewObservations
    );
    // Nothing at all, everything measured.
    let all: MeasuredLaunch<f64> =
        LaunchValues::from_array(v.to_array().map(|x| Some(Datum::new(x, 0.1))));
    assert_eq!(
        fit_launch(&ball, &scene, &all, &Observations::default(), &s, &mut ws).unwrap_err(),
        Error::TooFewObservations
    );
    // Apex, carry and flight time say nothing of the axis's sign: a square shot's axis.
    let square = LaunchValues {
        spin_axis_rad: 0.0,
        launch_direction_rad: 0.0,
        ..v
    };
    let (o, _) = fly_truth(&square, &Integrator::default(), &[]);
    let no_side = Observations {
        apex_height_m: Some(Datum::new(o.apex_m, 0.5)),
        carry_m: Some(Datum::new(o.carry_m, 1.0)),
        flight_time_s: Some(Datum::new(o.flight_time_s, 0.05)),
        ..Observations::default()
    };
    assert_eq!(
        fit_launch(&ball, &scene, &measured(&square), &no_side, &s, &mut ws).unwrap_err(),
        Error::Unidentifiable(Field::SpinAxis)
    );
}

#[test]
fn bad_observations_name_their_field() {
    let v = truth::<f64>();
    let ball = Ball::standard();
    let scene = Scene::default();
    let s = Settings::default();
    let mut ws = Workspace::new();
    let mut obs = Observations {
        carry_m: Some(Datum::new(f64::NAN, 1.0)),
        side_m: Some(Datum::new(0.0, 1.0)),
        ..Observations::default()
    };
    let e = fit_launch(&ball, &scene, &measured(&v), &obs, &s, &mut ws).unwrap_err();
    assert!(
        matches!(
            e,
            Error::InvalidInput {
                field: Field::Observation,
                ..
            }
        ),
        "{e:?}"
    );
    obs.carry_m = Some(Datum::new(200.0, 0.0));
    let e = fit_launch(&ball, &scene, &measured(&v), &obs, &s, &mut ws).unwrap_err();
    assert!(
        matches!(
            e,
            Error::InvalidInput {
                field: Field::MeasurementNoise,
                ..
            }
        ),
        "{e:?}"
    );
    // A track out of time order.
    let mut obs = Observations::default();
    for t in [0.5, 0.2] {
        obs.track
            .push(TrackPoint {
                time_s: t,
                position_m: Vector3::new(t * 60.0, t * 10.0, 0.0),
                sd_m: 0.1,
            })
            .unwrap();
    }
    let e = fit_launch(&ball, &scene, &measured(&v), &obs, &s, &mut ws).unwrap_err();
    assert!(
        matches!(
            e,
            Error::InvalidInput {
                field: Field::Observation,
                ..
            }
        ),
        "{e:?}"
    );
    // A prior that is no prior.
    let mut bad = Settings::default();
    bad.prior.sd.spin_radps = -1.0;
    let e = fit_launch(
        &ball,
        &scene,
        &measured(&v),
        &summaries(&fly_truth(&v, &Integrator::default(), &[]).0),
        &bad,
        &mut ws,
    )
    .unwrap_err();
    assert!(
        matches!(
            e,
            Error::InvalidInput {
                field: Field::PriorSpread,
                ..
            }
        ),
        "{e:?}"
    );
}

#[test]
fn f32_agrees_with_f64_within_its_noise() {
    let v64 = truth::<f64>();
    let (o, _) = fly_truth(&v64, &Integrator::default(), &[]);
    let mut ws = Workspace::new();
    let fit64 = fit_launch(
        &Ball::standard(),
        &Scene::default(),
        &measured(&v64),
        &summaries(&o),
        &Settings::default(),
        &mut ws,
    )
    .unwrap();
    let v32 = truth::<f32>();
    let o32 = carry_core::FlightOutcome::<f32> {
        carry_m: o.carry_m as f32,
        side_m: o.side_m as f32,
        apex_m: o.apex_m as f32,
        flight_time_s: o.flight_time_s as f32,
        landing_angle_rad: o.landing_angle_rad as f32,
        ..fly_truth(&v32, &Integrator::default(), &[]).0
    };
    let mut ws32 = Workspace::<f32>::new();
    let fit32 = fit_launch(
        &Ball::standard(),
        &Scene::default(),
        &measured(&v32),
        &summaries(&o32),
        &Settings::default(),
        &mut ws32,
    )
    .unwrap();
    // Within a tenth of the posterior σ: the precision is not what limits the answer.
    let d_spin = (f64::from(fit32.value.spin_radps) - fit64.value.spin_radps).abs();
    let d_axis = (f64::from(fit32.value.spin_axis_rad) - fit64.value.spin_axis_rad).abs();
    assert!(
        d_spin < 0.1 * fit64.sd.spin_radps,
        "{d_spin} vs σ {}",
        fit64.sd.spin_radps
    );
    assert!(
        d_axis < 0.1 * fit64.sd.spin_axis_rad,
        "{d_axis} vs σ {}",
        fit64.sd.spin_axis_rad
    );
}

#[test]
fn given_times_read_the_same_dense_output_as_an_interval() {
    // Samples at k·Δ given explicitly are bit for bit the interval recorder's.
    let v = truth::<f64>();
    let scene = Scene::<f64>::default().prepare(&Ball::standard()).unwrap();
    let motion = launch_of(&v).ball_motion().unwrap();
    let integrator = Integrator::default();
    let mut every: heapless::Vec<Sample<f64>, 128> = heapless::Vec::new();
    let a = {
        let mut rec = Recorder::new(0.1, &mut every).unwrap();
        scene.fly(&motion, &integrator, Some(&mut rec)).unwrap()
    };
    let times: Vec<f64> = (0..every.len() - 1).map(|k| k as f64 * 0.1).collect();
    let mut given = Samples(Vec::new());
    let b = {
        let mut rec = Recorder::at_times(&times, &mut given).unwrap();
        scene.fly(&motion, &integrator, Some(&mut rec)).unwrap()
    };
    assert_eq!(a, b);
    assert_eq!(every.as_slice(), given.0.as_slice());
    // Times out of order or negative are refused.
    let mut sink = Samples(Vec::new());
    assert!(Recorder::at_times(&[0.2, 0.1], &mut sink).is_err());
    assert!(Recorder::at_times(&[-0.1], &mut sink).is_err());
    assert!(Recorder::at_times(&[f64::NAN], &mut sink).is_err());
}
