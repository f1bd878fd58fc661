//! Normalisation: round trips, the standard scene, and the direction of the change.

use carry_core::air::{Pressure, Weather};
use carry_core::flight::Integrator;
use carry_core::units::{deg, rpm};
use carry_core::{Air, Ball, Launch, Scene, Wind};
use carry_lab::normalize::{Direction, normalize, standard_scene};
use nalgebra::Vector3;
use proptest::prelude::*;

fn driver_launch() -> carry_core::BallMotion<f64> {
    let l = Launch {
        ball_speed_mps: 74.66,
        launch_angle_rad: deg(10.9),
        launch_direction_rad: 0.0,
        backspin_radps: rpm(2686.0),
        sidespin_radps: 0.0,
    };
    match l.ball_motion() {
        Ok(m) => m,
        Err(e) => panic!("{e}"),
    }
}

fn weather(t: f64, rh: f64, altitude: f64) -> Scene<f64> {
    Scene {
        air: Air::Weather(Weather {
            temperature_c: t,
            relative_humidity: rh,
            pressure: Pressure::Altitude(altitude),
        }),
        ..Scene::default()
    }
}

#[test]
fn standard_conditions_are_neutral_and_thin_air_carries_further() {
    let ball = Ball::standard();
    let m = driver_launch();
    let i = Integrator::default();
    // Already standard: no change.
    let std = standard_scene(&Scene::<f64>::default());
    let Ok(r) = normalize(&ball, &m, &std, &i, Direction::ToStandard) else {
        panic!()
    };
    assert_eq!(r.carry_change_m, 0.0);
    assert!((r.from.air_density_kgm3 - 1.194).abs() < 2e-3);
    // Denver: thinner air → the measured carry is longer, normalised shorter.
    let Ok(r) = normalize(
        &ball,
        &m,
        &weather(21.0, 0.5, 1600.0),
        &i,
        Direction::ToStandard,
    ) else {
        panic!()
    };
    assert!(r.from.carry_m > r.to.carry_m && r.carry_change_m < 0.0);
    // And back: the mirror image.
    let Ok(back) = normalize(
        &ball,
        &m,
        &weather(21.0, 0.5, 1600.0),
        &i,
        Direction::ToConditions,
    ) else {
        panic!()
    };
    assert_eq!(back.from, r.to);
    assert_eq!(back.to, r.from);
    // Wind is removed in standard conditions.
    let windy = Scene {
        wind: Wind::Uniform(Vector3::new(5.0, 0.0, 0.0)),
        ..weather(21.0, 0.5, 0.0)
    };
    let Ok(r) = normalize(&ball, &m, &windy, &i, Direction::ToStandard) else {
        panic!()
    };
    assert!(r.carry_change_m < 0.0);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// Any weather: to-standard then the reverse direction give the same two flights, and
    /// standard always has the same density.
    #[test]
    fn directions_are_mirror_images(t in -10.0..40.0f64, rh in 0.0..1.0f64, h in -100.0..3000.0f64) {
        let ball = Ball::standard();
        let m = driver_launch();
        let i = Integrator::default();
        let scene = weather(t, rh, h);
        let (Ok(a), Ok(b)) = (
            normalize(&ball, &m, &scene, &i, Direction::ToStandard),
            normalize(&ball, &m, &scene, &i, Direction::ToConditions),
        ) else { return Err(TestCaseError::fail("failed")); };
        prop_assert_eq!(a.from, b.to);
        prop_assert_eq!(a.to, b.from);
        prop_assert!((a.to.air_density_kgm3 - 1.1942).abs() < 1e-3);
        prop_assert!(a.carry_m.is_finite());
    }
}
