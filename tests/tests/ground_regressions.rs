//! Regressions found by fuzzing the ground (issue 20), through the public API.

use carry_core::ground::{Ground, Surface};
use carry_core::wind::Wind;
use carry_core::{Ball, BallMotion, Error, Field, Integrator, Reason, Scene, fly};
use nalgebra::Vector3;

/// A fuzzed ground scene in f32, as the ground fuzz target builds it: a wind profile with
/// reference wind `wind` (m/s), the landing plane `landing_height_m` above the launch, the
/// firm fairway tilted to `normal` (not normalised).
fn fairway_in_wind(wind: [f32; 3], landing_height_m: f32, normal: [f32; 3]) -> Scene<f32> {
    Scene {
        wind: Wind::profile(Vector3::from(wind)),
        landing_height_m,
        ground: Some(Ground {
            surface: Surface::FairwayFirm,
            normal: Vector3::from(normal),
        }),
        ..Scene::default()
    }
}

/// Issue 20: an f32 flight at 1.3·10⁵ m/s and 2.3·10⁶ rad/s with a 30 ms RK4 step landed
/// with an astronomically large (finite) velocity, and the roll on a 40° slope came back
/// `Ok` with `total_m = ∞`. (The fuzz input is fuzz/corpus/ground/issue-20-nonfinite-rollout.)
#[test]
fn issue_20_f32_rollout_is_finite_or_an_error() {
    let motion = BallMotion::<f32> {
        velocity_mps: Vector3::new(75686.54, 108983.45, -11210.602),
        spin_radps: Vector3::new(189.79669, -2261634.5, 1281.3812),
    };
    let scene = fairway_in_wind(
        [11.981918, -7.352941, -7.3538566],
        -7.401999,
        [0.01808194, 1.1679256, 0.99334705],
    );
    let out = fly(
        &Ball::standard(),
        &motion,
        &scene,
        &Integrator::Rk4 {
            step_s: 0.030171435,
        },
        None,
    );
    // Far outside the model's validity (Mach 390): rejected up front, naming the launch.
    assert_eq!(
        out,
        Err(Error::invalid(Field::BallVelocity, Reason::OutOfRange))
    );
    // The same scene from the fastest accepted launch, with the same 30 ms RK4 step, and
    // with steps far past RK4's stability limit: finite figures or a typed error, never
    // an astronomical rollout.
    let speed = carry_core::flight::MAX_BALL_SPEED_MPS as f32 * 0.999;
    let fast = BallMotion::<f32> {
        velocity_mps: motion.velocity_mps.normalize() * speed,
        spin_radps: motion.spin_radps.normalize()
            * (carry_core::flight::MAX_SPIN_RADPS as f32 * 0.999),
    };
    for step_s in [0.030171435_f32, 0.5, 5.0, 60.0] {
        let out = fly(
            &Ball::standard(),
            &fast,
            &scene,
            &Integrator::Rk4 { step_s },
            None,
        );
        match out {
            Ok(out) => {
                let g = out.ground.expect("a ground gives a rollout");
                let figures = [g.total_m, g.roll_m, g.time_to_rest_s, out.landing_speed_mps];
                assert!(figures.iter().all(|x| x.is_finite()), "{g:?}");
                // Nothing faster than the launch plus what the fall and the roll can add.
                assert!(out.landing_speed_mps < 2.0 * speed, "{out:?}");
                assert!(g.total_m < 1.0e5, "{g:?}");
            }
            Err(e) => assert!(
                matches!(e, Error::Unstable | Error::NoLanding | Error::TimeLimit),
                "step {step_s}: {e:?}"
            ),
        }
    }
}

/// A fixed step far past the explicit method's stability limit is `Unstable`, not a
/// finite but astronomical landing (issue 20's second fault): 100 m/s with Euler at 10 s
/// (`h·k_d·V ≈ 4`, past Euler's limit of 2) and RK4 at 30 s (≈ 14, past 2.8).
#[test]
fn unstable_fixed_steps_are_errors() {
    let motion = carry_core::Launch::<f64> {
        ball_speed_mps: 100.0,
        launch_angle_rad: 0.2,
        launch_direction_rad: 0.0,
        backspin_radps: 300.0,
        sidespin_radps: 0.0,
    }
    .ball_motion()
    .expect("valid launch");
    for integrator in [
        Integrator::Euler { step_s: 10.0 },
        Integrator::Rk4 { step_s: 30.0 },
    ] {
        let out = fly(
            &Ball::standard(),
            &motion,
            &Scene::default(),
            &integrator,
            None,
        );
        assert_eq!(out, Err(Error::Unstable), "{integrator:?}");
    }
}

/// Issue 21's fuzzing: a ball barely moving with 1,200 rad/s of backspin on a nearly
/// frictionless, resistance-free turf skidded for the whole time cap, gripped, and rolled
/// on; the level roll's closed form `ln cos(θ₀ − kτ) − ln cos θ₀` cancelled
/// catastrophically for a resistance of 1e-300 and put the ball at −9·10²⁹¹ m. (The fuzz
/// input is fuzz/corpus/ground/issue21-frictionless-skid.)
#[test]
fn issue_21_frictionless_skid_stays_finite() {
    let motion = BallMotion::<f64> {
        velocity_mps: Vector3::new(1e-300, 0.0, 0.0),
        spin_radps: Vector3::new(-1.2e-297, -0.5676, 1204.54),
    };
    let turf = carry_core::Turf {
        restitution: 0.45,
        friction: 1e-300,
        rolling_resistance: 1e-300,
        crater_scale: 1e-300,
        crater_fade_mps: carry_core::ground::bounce::CRATER_FADE_NORMAL_SPEED_MPS,
        grass_drag_s2pm2: carry_core::ground::surface::GRASS_DRAG_S2PM2,
        crater_law: carry_core::ground::CraterLaw::Penner,
        grass_height_m: carry_core::ground::STOP_HEIGHT_M,
    };
    let scene = Scene::<f64> {
        landing_height_m: -8.4e-308,
        ground: Some(Ground {
            surface: Surface::Custom(turf),
            normal: Vector3::new(1e-300, 1.0, 1e-300),
        }),
        ..Scene::default()
    };
    let out = fly(
        &Ball::standard(),
        &motion,
        &scene,
        &Integrator::default(),
        None,
    );
    let Ok(out) = out else { panic!("{out:?}") };
    let g = out.ground.expect("a rollout");
    assert!(g.total_m.is_finite() && g.rest_position_m.iter().all(|x| x.is_finite()));
    // At most the gripped speed (2/7 of a 25.7 m/s slip) for the minute's cap.
    assert!(g.total_m < 7.5 * 60.0, "{g:?}");
    assert!(g.time_to_rest_s <= 60.0 + 1e-9, "{g:?}");
}

/// CI's fixed-seed fuzz run of the ground (2026-11-26): an f32 topped start 4.9 m under its
/// landing plane on an 18° slope, fast (47 m/s) with 460 rad/s of spin, bounced into a hop
/// the lift nearly held up (10 s long); the closed-form low hop extrapolated its short-time
/// force model over it and the ball "hopped" 25,000 km. Such hops are now integrated
/// (`ground::LOW_HOP_MIN_PULL`). (The fuzz input is fuzz/corpus/ground/slope-topped-astronomical.)
#[test]
fn a_hop_the_lift_holds_up_is_integrated_not_extrapolated() {
    let motion = BallMotion::<f32> {
        velocity_mps: Vector3::new(43.503838, -14.086464, -13.457313),
        spin_radps: Vector3::new(136.68153, 17.254902, 441.85425),
    };
    let scene = fairway_in_wind(
        [0.05882353, -1.0, 11.777752],
        4.922103,
        [0.4745098, 1.4745098, 0.003921569],
    );
    let out = fly(
        &Ball::standard(),
        &motion,
        &scene,
        &Integrator::Rk4 { step_s: 0.03817647 },
        None,
    );
    let Ok(out) = out else { panic!("{out:?}") };
    let g = out.ground.expect("a ground gives a rollout");
    // Down an 18° slope for a minute: finite and terrestrial (the roll's terminal speed
    // under the grass drag is tens of m/s), never thousands of kilometres.
    assert!(g.total_m.is_finite() && g.total_m < 5.0e3, "{g:?}");
    assert!(g.rest_position_m.iter().all(|x| x.abs() < 5.0e3), "{g:?}");
}
