//! Fuzz the launch from the flight (issue 36): any measured subset of the launch, any
//! summaries, track points and Doppler samples (valid or not: NaN, negative 1σ, times out
//! of order), priors, wind and air-density fitting, iteration budget and tolerance, in f32
//! and f64. A success must be finite with non-negative 1σ; anything else a typed error.
#![no_main]

use carry_core::launch_fit::{
    Datum, DopplerSample, LaunchValues, MeasuredLaunch, Observations, Settings, TrackPoint,
    Workspace, fit_launch,
};
use carry_core::real::lit;
use carry_core::{Ball, Real, Result, Scene};
use carry_fuzz::Bytes;
use libfuzzer_sys::fuzz_target;
use nalgebra::Vector3;

fn datum<T: Real>(b: &mut Bytes<'_>, lo: f64, hi: f64) -> Option<Datum<T>> {
    if b.flag() {
        Some(Datum::new(lit(b.param(lo, hi)), lit(b.param(-0.1, 5.0))))
    } else {
        None
    }
}

fn run<T: Real>(b: &mut Bytes<'_>) -> Result<()> {
    let measured: MeasuredLaunch<T> = LaunchValues {
        ball_speed_mps: datum(b, 0.0, 100.0),
        launch_angle_rad: datum(b, -0.6, 1.2),
        launch_direction_rad: datum(b, -0.5, 0.5),
        spin_radps: datum(b, 0.0, 1500.0),
        spin_axis_rad: datum(b, -1.6, 1.6),
    };
    let mut obs = Observations::<T> {
        apex_height_m: datum(b, -5.0, 60.0),
        apex_time_s: datum(b, 0.0, 5.0),
        carry_m: datum(b, 0.0, 300.0),
        side_m: datum(b, -50.0, 50.0),
        flight_time_s: datum(b, 0.0, 10.0),
        land_angle_rad: datum(b, -0.5, 1.5),
        ..Observations::default()
    };
    let points = b.byte() % 12;
    for _ in 0..points {
        let t = b.param(0.0, 3.0);
        let p = b.vec3(-10.0, 150.0);
        let sd = b.param(-0.1, 2.0);
        let _ = obs.track.push(TrackPoint {
            time_s: lit(t),
            position_m: Vector3::from(p.map(lit)),
            sd_m: lit(sd),
        });
    }
    let samples = b.byte() % 24;
    for _ in 0..samples {
        let t = b.param(0.0, 2.0);
        let _ = obs.doppler.push(DopplerSample {
            time_s: lit(t),
            radial_speed_mps: lit(b.param(-10.0, 90.0)),
            sd_mps: lit(b.param(-0.1, 2.0)),
        });
    }
    if b.flag() {
        obs.radar_position_m = Vector3::from(b.vec3(-5.0, 5.0).map(lit));
    }
    let mut settings = Settings::<T> {
        fit_wind: b.flag(),
        fit_air_density: b.flag(),
        ..Settings::default()
    };
    if b.flag() {
        settings.max_iterations = u16::from(b.byte());
        settings.tolerance = lit(b.param(0.0, 1.0));
        settings.prior.sd.spin_radps = lit(b.param(-10.0, 1000.0));
        settings.prior.mean.spin_axis_rad = lit(b.param(-2.0, 2.0));
    }
    let mut ws = Box::new(Workspace::<T>::new());
    let f = fit_launch(
        &Ball::standard(),
        &Scene::default(),
        &measured,
        &obs,
        &settings,
        &mut ws,
    )?;
    for v in f.value.to_array().into_iter().chain(f.sd.to_array()) {
        assert!(v.is_finite(), "non-finite fit {f:?}");
    }
    assert!(
        f.sd.to_array().iter().all(|s| *s >= T::zero()),
        "negative 1σ {f:?}"
    );
    assert!(f.chi2.is_finite() && f.chi2 >= T::zero());
    assert!(f.iterations <= settings.max_iterations);
    Ok(())
}

fuzz_target!(|data: &[u8]| {
    let mut b = Bytes::new(data);
    let _ = if b.flag() {
        run::<f32>(&mut b)
    } else {
        run::<f64>(&mut b)
    };
});
