//! Closed forms, symmetries, convergence orders and error paths of the flight, through the
//! public API.

use carry_core::air::{Air, Pressure, Weather};
use carry_core::flight::{Recorder, Sample};
use carry_core::units::{deg, rpm};
use carry_core::{
    Ball, BallMotion, Effects, Error, Field, FlightOutcome, Integrator, Launch, Reason, Scene,
    Wind, fly,
};
use nalgebra::Vector3;

fn launch(
    speed: f64,
    angle_deg: f64,
    dir_deg: f64,
    back_rpm: f64,
    side_rpm: f64,
) -> BallMotion<f64> {
    Launch {
        ball_speed_mps: speed,
        launch_angle_rad: deg(angle_deg),
        launch_direction_rad: deg(dir_deg),
        backspin_radps: rpm(back_rpm),
        sidespin_radps: rpm(side_rpm),
    }
    .ball_motion()
    .expect("valid launch")
}

fn driver() -> BallMotion<f64> {
    launch(
        65.879_767_727_750_29,
        8.744_649_330_360_067,
        0.0,
        2_257.999_095_532_81,
        0.0,
    )
}

fn go(m: &BallMotion<f64>, scene: &Scene<f64>, integrator: &Integrator<f64>) -> FlightOutcome<f64> {
    fly(&Ball::standard(), m, scene, integrator, None).expect("flight lands")
}

/// Reference carry of `driver()` in still standard air (tests/golden/flight.json,
/// reference_driver_impact).
const DRIVER_CARRY_M: f64 = 199.682_864_687_470_04;

#[test]
fn vacuum_is_the_parabola() {
    // y(t) is quadratic: DP5 and its dense output reproduce it to rounding.
    let (v, th, psi) = (50.0_f64, deg(30.0_f64), deg(5.0_f64));
    let m = launch(50.0, 30.0, 5.0, 3000.0, 300.0);
    let g = 9.806_65;
    let scene = Scene {
        effects: Effects::GRAVITY_ONLY,
        ..Scene::default()
    };
    for integrator in [Integrator::default(), Integrator::Rk4 { step_s: 0.37 }] {
        let out = go(&m, &scene, &integrator);
        let t = 2.0 * v * th.sin() / g;
        // Tolerances: a few ulps of the 220 m / 5 s magnitudes.
        assert!(
            (out.flight_time_s - t).abs() < 1e-12,
            "{}",
            out.flight_time_s - t
        );
        assert!((out.carry_m - v * th.cos() * t).abs() < 1e-10);
        assert!((out.side_m - v * th.cos() * psi.sin() * t).abs() < 1e-10);
        assert!((out.apex_m - (v * th.sin()).powi(2) / (2.0 * g)).abs() < 1e-11);
        assert!((out.apex_time_s - t / 2.0).abs() < 1e-12);
        assert!((out.landing_angle_rad - th).abs() < 1e-12);
        assert!(
            (out.landing_spin_radps - m.spin_radps.norm()).abs() < 1e-12,
            "no decay switched on"
        );
    }
}

#[test]
fn zero_spin_gives_zero_lift() {
    let m = launch(60.0, 14.0, 0.0, 0.0, 0.0);
    let with_lift = go(&m, &Scene::default(), &Integrator::default());
    let without = go(
        &m,
        &Scene {
            effects: Effects {
                lift: false,
                ..Effects::ALL
            },
            ..Scene::default()
        },
        &Integrator::default(),
    );
    // Identical arithmetic apart from adding exact zeros: bit-for-bit.
    assert_eq!(with_lift.carry_m, without.carry_m);
    assert_eq!(with_lift.apex_m, without.apex_m);
    assert_eq!(with_lift.side_m, 0.0);
}

#[test]
fn rifle_spin_does_not_curve() {
    // Spin parallel to the velocity: ω̂ × v_r = 0. Gravity would bend v away from the fixed
    // spin axis (and then lift acts), so this is checked without gravity: from an elevated
    // tee, launched down and to the right, the ball flies a straight line.
    let p0 = Vector3::new(0.0, 10.0, 0.0);
    let v0 = Vector3::new(40.0, -15.0, 6.0);
    let m = BallMotion {
        velocity_mps: v0,
        spin_radps: v0.normalize() * 300.0,
    };
    let scene = Scene {
        gravity_mps2: 0.0,
        launch_position_m: p0,
        ..Scene::default()
    };
    let out = go(&m, &scene, &Integrator::default());
    let d = out.landing_position_m - p0;
    // Off-line distance of the landing from the launch line: rounding only.
    assert!(
        d.cross(&v0.normalize()).norm() < 1e-12,
        "{}",
        d.cross(&v0.normalize()).norm()
    );
    let no_lift = go(
        &m,
        &Scene {
            effects: Effects {
                lift: false,
                ..Effects::ALL
            },
            ..scene
        },
        &Integrator::default(),
    );
    assert!((no_lift.landing_position_m - out.landing_position_m).norm() < 1e-12);
}

#[test]
fn mirror_symmetry() {
    for (m, wind) in [
        (launch(70.0, 12.0, 2.0, 2443.2, 889.25), Wind::None),
        (
            launch(62.0, 13.0, -4.0, 3100.0, -500.0),
            Wind::Uniform(Vector3::new(-3.0, 0.0, 4.0)),
        ),
    ] {
        let mirror = |v: Vector3<f64>| Vector3::new(v.x, v.y, -v.z);
        // Spin is a pseudovector: mirroring z → −z maps ω to (−ωx, −ωy, ωz).
        let mm = BallMotion {
            velocity_mps: mirror(m.velocity_mps),
            spin_radps: Vector3::new(-m.spin_radps.x, -m.spin_radps.y, m.spin_radps.z),
        };
        let mw = match wind {
            Wind::Uniform(w) => Wind::Uniform(mirror(w)),
            w => w,
        };
        let a = go(
            &m,
            &Scene {
                wind,
                ..Scene::default()
            },
            &Integrator::default(),
        );
        let b = go(
            &mm,
            &Scene {
                wind: mw,
                ..Scene::default()
            },
            &Integrator::default(),
        );
        assert!(a.side_m.abs() > 1.0);
        // The same operations on mirrored operands (sign flips are exact): to rounding.
        assert!((a.side_m + b.side_m).abs() < 1e-9);
        assert!((a.carry_m - b.carry_m).abs() < 1e-9);
        assert!((a.apex_m - b.apex_m).abs() < 1e-9);
        assert_eq!(a.stats, b.stats);
    }
}

fn carry_error(integrator: &Integrator<f64>) -> f64 {
    // DRIVER_CARRY_M is the seed model's reference carry.
    let seed = Scene {
        aero: carry_core::aero::AeroModel::quintavalla(),
        ..Scene::default()
    };
    (go(&driver(), &seed, integrator).carry_m - DRIVER_CARRY_M).abs()
}

#[test]
fn rk4_converges_at_fourth_order() {
    // Halving h divides the error by 2⁴ = 16 asymptotically; [12, 20] allows for the
    // higher-order terms at these step sizes.
    let ratio = carry_error(&Integrator::Rk4 { step_s: 0.1 })
        / carry_error(&Integrator::Rk4 { step_s: 0.05 });
    assert!((12.0..20.0).contains(&ratio), "RK4 ratio {ratio}");
}

#[test]
fn euler_converges_at_first_order() {
    let ratio = carry_error(&Integrator::Euler { step_s: 0.002 })
        / carry_error(&Integrator::Euler { step_s: 0.001 });
    assert!((1.9..2.1).contains(&ratio), "Euler ratio {ratio}");
}

#[test]
fn force_evaluations_are_counted() {
    let m = driver();
    let s = Scene::default();
    let e = go(&m, &s, &Integrator::Euler { step_s: 0.01 }).stats;
    assert_eq!(e.force_evaluations, e.steps + 1);
    let r = go(&m, &s, &Integrator::Rk4 { step_s: 0.05 }).stats;
    assert_eq!(r.force_evaluations, 4 * r.steps + 1);
    let d = go(&m, &s, &Integrator::default()).stats;
    assert_eq!(d.force_evaluations, 6 * (d.steps + d.rejected_steps) + 1);
    assert_eq!(d, go(&m, &s, &Integrator::default()).stats, "deterministic");
}

#[test]
fn apex_is_the_true_maximum() {
    let mut buf = heapless::Vec::<Sample<f64>, 8192>::new();
    let mut rec = Recorder::new(1e-3, &mut buf).expect("interval");
    let out = fly(
        &Ball::standard(),
        &driver(),
        &Scene::default(),
        &Integrator::tight(),
        Some(&mut rec),
    )
    .expect("lands");
    assert!(!out.recording_full);
    let top = rec
        .samples()
        .iter()
        .map(|s| s.position_m.y)
        .fold(f64::MIN, f64::max);
    // Never below a sample; above the best 1 ms sample by at most ½·g·(0.5 ms)² ≈ 1.3e-6 m.
    assert!(
        out.apex_m >= top && out.apex_m - top < 1.5e-6,
        "{} {top}",
        out.apex_m
    );
}

#[test]
fn recording_samples_and_full_buffer() {
    let mut buf = heapless::Vec::<Sample<f64>, 1024>::new();
    let mut rec = Recorder::new(0.01, &mut buf).expect("interval");
    let out = fly(
        &Ball::standard(),
        &driver(),
        &Scene::default(),
        &Integrator::default(),
        Some(&mut rec),
    )
    .expect("lands");
    let s = rec.samples();
    assert!(!out.recording_full && !rec.is_full());
    assert_eq!(
        s.len(),
        (out.flight_time_s / 0.01).ceil() as usize + 1,
        "every 10 ms, then the landing"
    );
    assert!(
        s.iter()
            .zip(s.iter().skip(1))
            .all(|(a, b)| b.time_s > a.time_s)
    );
    assert!(
        s.iter()
            .take(s.len() - 1)
            .enumerate()
            .all(|(k, x)| (x.time_s - k as f64 * 0.01).abs() < 1e-12)
    );
    let last = s[s.len() - 1];
    assert_eq!(last.position_m, out.landing_position_m);
    assert_eq!(s[0].position_m, Vector3::zeros());

    let mut small = heapless::Vec::<Sample<f64>, 16>::new();
    let mut rec = Recorder::new(0.01, &mut small).expect("interval");
    let full = fly(
        &Ball::standard(),
        &driver(),
        &Scene::default(),
        &Integrator::default(),
        Some(&mut rec),
    )
    .expect("a full buffer is not an error");
    assert!(full.recording_full && rec.samples().len() == 16);
    assert_eq!(
        full.carry_m, out.carry_m,
        "recording does not change the flight"
    );
}

#[test]
fn moving_with_the_wind_is_finite() {
    let w = Vector3::new(12.0, 6.0, -2.0);
    let m = BallMotion {
        velocity_mps: w,
        spin_radps: Vector3::zeros(),
    };
    let out = go(
        &m,
        &Scene {
            wind: Wind::Uniform(w),
            ..Scene::default()
        },
        &Integrator::default(),
    );
    assert!(out.carry_m.is_finite() && out.apex_m > 0.0);
    let m = BallMotion {
        velocity_mps: w,
        spin_radps: Vector3::new(0.0, 0.0, 200.0),
    };
    let out = go(
        &m,
        &Scene {
            wind: Wind::Uniform(w),
            ..Scene::default()
        },
        &Integrator::Rk4 { step_s: 0.01 },
    );
    assert!(out.carry_m.is_finite());
}

#[test]
fn f32_follows_f64() {
    let l = Launch {
        ball_speed_mps: 70.0_f32,
        launch_angle_rad: deg(12.0),
        launch_direction_rad: deg(2.0),
        backspin_radps: rpm(2443.2),
        sidespin_radps: rpm(889.25),
    };
    let m32 = l.ball_motion().expect("valid");
    let o32 = fly(
        &Ball::standard(),
        &m32,
        &Scene::default(),
        &Integrator::default(),
        None,
    )
    .expect("lands");
    let o64 = go(
        &launch(70.0, 12.0, 2.0, 2443.2, 889.25),
        &Scene::default(),
        &Integrator::tight(),
    );
    // The f32 default fidelity's 1 cm contract.
    assert!((f64::from(o32.carry_m) - o64.carry_m).abs() < 1e-2);
    assert!((f64::from(o32.side_m) - o64.side_m).abs() < 1e-2);
}

#[test]
fn errors_are_typed() {
    let ball = Ball::standard();
    let ok = driver();
    let d = Integrator::default();
    let bad = BallMotion {
        velocity_mps: Vector3::new(f64::NAN, 1.0, 0.0),
        ..ok
    };
    assert_eq!(
        fly(&ball, &bad, &Scene::default(), &d, None),
        Err(Error::invalid(Field::BallVelocity, Reason::NotFinite))
    );
    let humid = Scene {
        air: Air::Weather(Weather {
            temperature_c: 20.0,
            relative_humidity: 1.2,
            pressure: Pressure::Altitude(0.0),
        }),
        ..Scene::default()
    };
    assert_eq!(
        fly(&ball, &ok, &humid, &d, None),
        Err(Error::invalid(Field::Humidity, Reason::OutOfRange))
    );
    let vacuum_negative = Scene {
        air: Air::Density(-0.1),
        ..Scene::default()
    };
    assert_eq!(
        fly(&ball, &ok, &vacuum_negative, &d, None),
        Err(Error::invalid(Field::AirDensity, Reason::Negative))
    );
    let nan_height = Scene {
        landing_height_m: f64::NAN,
        ..Scene::default()
    };
    assert_eq!(
        fly(&ball, &ok, &nan_height, &d, None),
        Err(Error::invalid(Field::LandingHeight, Reason::NotFinite))
    );
    assert_eq!(
        fly(
            &ball,
            &ok,
            &Scene::default(),
            &Integrator::Rk4 { step_s: 0.0 },
            None
        ),
        Err(Error::invalid(Field::Step, Reason::NotPositive))
    );
    assert_eq!(
        fly(
            &ball,
            &ok,
            &Scene::default(),
            &Integrator::dormand_prince(-1e-6),
            None
        ),
        Err(Error::invalid(Field::Tolerance, Reason::NotPositive))
    );
    // A target a metre above the apex.
    let Ok(flat) = fly(&ball, &ok, &Scene::default(), &d, None) else {
        panic!("flat landing")
    };
    let high = Scene {
        landing_height_m: flat.apex_m + 1.0,
        ..Scene::default()
    };
    assert_eq!(fly(&ball, &ok, &high, &d, None), Err(Error::NoLanding));
    // Launched into the ground.
    assert_eq!(
        fly(
            &ball,
            &launch(30.0, -5.0, 0.0, 0.0, 0.0),
            &Scene::default(),
            &d,
            None
        ),
        Err(Error::NoLanding)
    );
    let short = Scene {
        time_limit_s: 2.0,
        ..Scene::default()
    };
    assert_eq!(fly(&ball, &ok, &short, &d, None), Err(Error::TimeLimit));
    assert_eq!(
        fly(
            &ball,
            &ok,
            &short,
            &Integrator::Euler { step_s: 0.01 },
            None
        ),
        Err(Error::TimeLimit)
    );
    // 1e-20 is far below f64 rounding: the step shrinks until it underflows.
    assert_eq!(
        fly(
            &ball,
            &ok,
            &Scene::default(),
            &Integrator::dormand_prince(1e-20),
            None
        ),
        Err(Error::StepSizeUnderflow)
    );
    let mut buf = heapless::Vec::<Sample<f64>, 4>::new();
    assert_eq!(
        Recorder::new(0.0, &mut buf).err(),
        Some(Error::invalid(Field::RecordInterval, Reason::NotPositive))
    );
}

#[test]
fn uphill_and_downhill_landing() {
    let m = launch(55.0, 18.0, 0.0, 6000.0, 0.0);
    let flat = go(&m, &Scene::default(), &Integrator::default());
    let up = go(
        &m,
        &Scene {
            landing_height_m: 12.0,
            ..Scene::default()
        },
        &Integrator::default(),
    );
    let down = go(
        &m,
        &Scene {
            landing_height_m: -25.0,
            ..Scene::default()
        },
        &Integrator::default(),
    );
    assert!(up.carry_m < flat.carry_m && flat.carry_m < down.carry_m);
    assert!(
        (up.landing_position_m.y - 12.0).abs() < 1e-9
            && (down.landing_position_m.y + 25.0).abs() < 1e-9
    );
}
