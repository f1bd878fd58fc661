//! Issue 7, flight hard cases: each asserts finite results or the named error — never NaN,
//! never a panic — and the closed form or limit where one exists, in f64 and f32.

use carry_core::real::{lit, to_f64};
use carry_core::scene::{Effects, Scene};
use carry_core::units::rpm;
use carry_core::{
    Ball, BallMotion, Error, FlightOutcome, Integrator, Launch, Real, Result, Wind, fly,
};
use nalgebra::Vector3;

fn is_f32<T: Real>() -> bool {
    T::default_epsilon() > lit(1e-10)
}

/// A driver launch (PHYSICS.md reference: 65.88 m/s, 8.745°, 2258 rpm).
fn driver_launch<T: Real>() -> Launch<T> {
    Launch {
        ball_speed_mps: lit(65.880),
        launch_angle_rad: lit(8.745_f64.to_radians()),
        launch_direction_rad: T::zero(),
        backspin_radps: rpm(lit(2258.0)),
        sidespin_radps: T::zero(),
    }
}

fn finite<T: Real>(o: &FlightOutcome<T>) -> bool {
    let s = [
        o.carry_m,
        o.carry_x_m,
        o.side_m,
        o.apex_m,
        o.apex_time_s,
        o.flight_time_s,
        o.landing_angle_rad,
        o.landing_speed_mps,
        o.landing_spin_radps,
        o.air_density_kgm3,
    ];
    s.iter().all(|x| x.is_finite())
        && [
            o.landing_position_m,
            o.landing_velocity_mps,
            o.landing_spin_vector_radps,
        ]
        .iter()
        .all(|v| v.iter().all(|x| x.is_finite()))
}

/// Flies and asserts a success is finite and physical (carry ≥ 0, time within the limit).
fn fly_checked<T: Real>(
    motion: &BallMotion<T>,
    scene: &Scene<T>,
    integrator: &Integrator<T>,
) -> Result<FlightOutcome<T>> {
    let out = fly(&Ball::standard(), motion, scene, integrator, None)?;
    assert!(finite(&out), "non-finite flight {out:?}");
    assert!(
        out.carry_m >= T::zero()
            && out.flight_time_s > T::zero()
            && out.flight_time_s <= scene.time_limit_s
    );
    Ok(out)
}

fn motion<T: Real>(l: &Launch<T>) -> BallMotion<T> {
    l.ball_motion().unwrap_or_else(|e| panic!("launch: {e}"))
}

/// Relative tolerance of a closed form against the adaptive default integrator: its
/// documented accuracy is 1 mm on ~200 m in f64 (5e-6 relative) and 1 cm in f32; the
/// vacuum cases below are polynomial in t, which DP5 integrates nearly exactly, so 1e-8
/// (f64) and 2e-5 (f32, ~100 ε of accumulated rounding over the steps).
fn closed_tol<T: Real>() -> f64 {
    if is_f32::<T>() { 2e-5 } else { 1e-8 }
}

fn spin_cases<T: Real>() {
    let scene = Scene::<T>::default();
    let dp = Integrator::default();
    // zero spin: no lift (its direction is undefined) — identical to lift switched off
    let mut l = driver_launch::<T>();
    l.backspin_radps = T::zero();
    let Ok(zero) = fly_checked(&motion(&l), &scene, &dp) else {
        panic!("zero spin")
    };
    let no_lift = Scene {
        effects: Effects {
            lift: false,
            ..Effects::ALL
        },
        ..scene
    };
    let Ok(reference) = fly_checked(&motion(&l), &no_lift, &dp) else {
        panic!()
    };
    assert_eq!(zero.carry_m, reference.carry_m);
    assert_eq!(zero.side_m, T::zero());
    // pure rifle spin (axis along the velocity): finite; the spin axis never turns
    let m0 = motion(&driver_launch::<T>());
    let rifle = BallMotion {
        velocity_mps: m0.velocity_mps,
        spin_radps: m0.velocity_mps.normalize() * rpm(lit::<T>(3000.0)),
    };
    let Ok(out) = fly_checked(&rifle, &scene, &dp) else {
        panic!("rifle")
    };
    let axis = rifle.spin_radps.normalize();
    let landed = out.landing_spin_vector_radps;
    assert!(
        to_f64((landed - axis * landed.dot(&axis)).norm())
            <= 16.0 * closed_tol::<T>() * to_f64(landed.norm())
    );
    // 20,000 rpm: finite, decays, still lands
    let mut l = driver_launch::<T>();
    l.backspin_radps = rpm(lit(20_000.0));
    let Ok(out) = fly_checked(&motion(&l), &scene, &dp) else {
        panic!("20k rpm")
    };
    assert!(out.landing_spin_radps < l.backspin_radps && out.apex_m > zero.apex_m);
}

#[test]
fn zero_rifle_and_huge_spin() {
    spin_cases::<f64>();
    spin_cases::<f32>();
}

fn with_the_wind<T: Real>() {
    // Launched horizontally from 2 m at exactly the wind's velocity: V = 0 at t = 0. No
    // spin, so the horizontal air speed stays exactly 0 and carry_x = w · t exactly.
    let w = Vector3::new(lit::<T>(20.0), T::zero(), T::zero());
    let scene = Scene {
        wind: Wind::Uniform(w),
        launch_position_m: Vector3::new(T::zero(), lit(2.0), T::zero()),
        ..Scene::default()
    };
    let m = BallMotion {
        velocity_mps: w,
        spin_radps: Vector3::zeros(),
    };
    let Ok(out) = fly_checked(&m, &scene, &Integrator::default()) else {
        panic!("with the wind")
    };
    let t = to_f64(out.flight_time_s);
    let t_vacuum = (2.0 * 2.0 / 9.80665_f64).sqrt();
    assert!(
        t >= t_vacuum && t <= t_vacuum * 1.01,
        "t = {t} vs vacuum {t_vacuum}"
    );
    assert!((to_f64(out.carry_x_m) - 20.0 * t).abs() <= closed_tol::<T>() * 20.0 * t);
    assert_eq!(out.side_m, T::zero());
}

#[test]
fn ball_moving_with_the_wind() {
    with_the_wind::<f64>();
    with_the_wind::<f32>();
}

fn vertical<T: Real>() {
    // vacuum: apex v²/2g at t = v/g, flight 2v/g, carry 0
    let v = 30.0;
    let g = 9.80665;
    let l = Launch {
        ball_speed_mps: lit::<T>(v),
        launch_angle_rad: T::frac_pi_2(),
        launch_direction_rad: T::zero(),
        backspin_radps: T::zero(),
        sidespin_radps: T::zero(),
    };
    let vacuum = Scene {
        effects: Effects::GRAVITY_ONLY,
        ..Scene::default()
    };
    let Ok(out) = fly_checked(&motion(&l), &vacuum, &Integrator::default()) else {
        panic!("vertical")
    };
    let tol = closed_tol::<T>();
    assert!((to_f64(out.apex_m) - v * v / (2.0 * g)).abs() <= tol * v * v / (2.0 * g));
    assert!((to_f64(out.apex_time_s) - v / g).abs() <= tol * v / g);
    assert!((to_f64(out.flight_time_s) - 2.0 * v / g).abs() <= tol * 2.0 * v / g);
    assert!(
        to_f64(out.carry_m) <= 1e-6 * v,
        "carry {}",
        to_f64(out.carry_m)
    );
    // with air, with and without spin: finite
    for spin in [0.0, 3000.0] {
        let mut l = l;
        l.backspin_radps = rpm(lit(spin));
        let Ok(_) = fly_checked(&motion(&l), &Scene::default(), &Integrator::default()) else {
            panic!("vertical spin {spin}")
        };
    }
}

#[test]
fn vertical_launch() {
    vertical::<f64>();
    vertical::<f32>();
}

fn below_horizontal_and_high_landing<T: Real>() {
    let mut l = driver_launch::<T>();
    l.launch_angle_rad = lit(-10_f64.to_radians());
    // from the ground: it never comes down *through* the landing height
    let r = fly_checked(&motion(&l), &Scene::default(), &Integrator::default());
    assert_eq!(r.err(), Some(Error::NoLanding));
    // from 1.5 m: lands; the apex is the launch height at t = 0
    let high = Scene {
        launch_position_m: Vector3::new(T::zero(), lit(1.5), T::zero()),
        ..Scene::default()
    };
    let Ok(out) = fly_checked(&motion(&l), &high, &Integrator::default()) else {
        panic!("below horizontal")
    };
    assert_eq!(out.apex_m, lit(1.5));
    assert_eq!(out.apex_time_s, T::zero());
    // a landing height above the apex (the driver's apex is ~16 m)
    let above = Scene {
        landing_height_m: lit(40.0),
        ..Scene::default()
    };
    let r = fly_checked(
        &motion(&driver_launch::<T>()),
        &above,
        &Integrator::default(),
    );
    assert_eq!(r.err(), Some(Error::NoLanding));
    // the time limit reached before landing (flight ~5.1 s)
    let short = Scene {
        time_limit_s: lit(2.0),
        ..Scene::default()
    };
    for integ in [
        Integrator::default(),
        Integrator::Rk4 { step_s: lit(0.01) },
        Integrator::Euler { step_s: lit(0.001) },
    ] {
        let r = fly_checked(&motion(&driver_launch::<T>()), &short, &integ);
        assert_eq!(r.err(), Some(Error::TimeLimit), "{integ:?}");
    }
}

#[test]
fn launch_below_horizontal_landing_above_apex_time_limit() {
    below_horizontal_and_high_landing::<f64>();
    below_horizontal_and_high_landing::<f32>();
}

/// Fixed steps from 1e-6 s to 5 s on a short pitch (flight ≈ 1.6 s, so 1e-6 s is 1.6e6
/// steps): small steps converge to the adaptive reference; large ones are finite or a clean
/// [`Error::Unstable`]; never NaN.
fn fixed_steps<T: Real>() -> Vec<(String, f64)> {
    let l = Launch {
        ball_speed_mps: lit::<T>(12.0),
        launch_angle_rad: lit(0.6),
        launch_direction_rad: T::zero(),
        backspin_radps: rpm(lit(4000.0)),
        sidespin_radps: rpm(lit(300.0)),
    };
    let m = motion(&l);
    let scene = Scene::default();
    let Ok(reference) = fly_checked(
        &motion(&Launch {
            ball_speed_mps: 12.0,
            launch_angle_rad: 0.6,
            launch_direction_rad: 0.0,
            backspin_radps: rpm(4000.0),
            sidespin_radps: rpm(300.0),
        }),
        &Scene::default(),
        &Integrator::<f64>::tight(),
    ) else {
        panic!()
    };
    let want = reference.carry_m;
    let mut rows = Vec::new();
    for h in [1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.1, 0.5, 1.0, 5.0] {
        for (name, integ) in [
            (
                "euler",
                Integrator::Euler {
                    step_s: lit::<T>(h),
                },
            ),
            (
                "rk4",
                Integrator::Rk4 {
                    step_s: lit::<T>(h),
                },
            ),
        ] {
            if name == "euler" && h < 1e-5 && !cfg!(not(debug_assertions)) {
                continue; // 1.6e6 unoptimised Euler steps: only in --release runs
            }
            match fly_checked(&m, &scene, &integ) {
                Ok(out) => {
                    let err = (to_f64(out.carry_m) - want).abs();
                    rows.push((format!("{name} h={h:e}"), err));
                    // Convergence where the method is accurate: Euler O(h) (~1.5 m/s of
                    // h-error per m), RK4 O(h⁴); in f32 the sum of ~1e6 rounded increments
                    // floors the error at ~n·ε·|y| (documented best effort).
                    // (n = 1.6 s / h steps, each rounding a ~15 m coordinate by ≤ ε)
                    let floor = if is_f32::<T>() {
                        2e-3 + 1.2e-7 * 15.0 * 1.6 / h
                    } else {
                        1e-6
                    };
                    let bound = match name {
                        "euler" => 20.0 * h + floor,
                        _ => 2e3 * h.powi(4) + floor,
                    };
                    if h <= 1e-2 {
                        assert!(
                            err <= bound,
                            "{name} h = {h}: carry error {err:e} > {bound:e}"
                        );
                    }
                }
                Err(Error::Unstable) => rows.push((format!("{name} h={h:e}: unstable"), f64::NAN)),
                Err(e) => panic!("{name} h = {h}: {e}"),
            }
        }
    }
    rows
}

#[test]
fn fixed_steps_from_a_microsecond_to_five_seconds() {
    for (name, err) in fixed_steps::<f64>() {
        println!("f64 {name}: |Δcarry| = {err:.3e} m");
    }
    for (name, err) in fixed_steps::<f32>() {
        println!("f32 {name}: |Δcarry| = {err:.3e} m");
    }
}

/// An adaptive tolerance below what the precision can resolve: a clean
/// [`Error::StepSizeUnderflow`] or a finite best effort close to the f64 result.
fn unreachable_tolerance<T: Real>() -> Result<f64> {
    let m = motion(&driver_launch::<T>());
    let Ok(reference) = fly_checked(
        &motion(&driver_launch::<f64>()),
        &Scene::default(),
        &Integrator::<f64>::tight(),
    ) else {
        panic!()
    };
    let out = fly_checked(
        &m,
        &Scene::default(),
        &Integrator::dormand_prince(lit(1e-14)),
    )?;
    let err = (to_f64(out.carry_m) - reference.carry_m).abs();
    assert!(err <= 0.05, "best effort off by {err}");
    Ok(err)
}

#[test]
fn adaptive_tolerance_out_of_reach() {
    // f64 reaches 1e-14 (the error test mixes rtol·|y| and atol); f32 (ε = 1.2e-7) cannot.
    let r64 = unreachable_tolerance::<f64>();
    let r32 = unreachable_tolerance::<f32>();
    println!("tolerance 1e-14: f64 {r64:?}, f32 {r32:?}");
    assert!(r64.is_ok());
    assert!(
        matches!(r32, Ok(_) | Err(Error::StepSizeUnderflow)),
        "{r32:?}"
    );
    // and a tolerance f32 cannot even represent relative to the state: 1e-30
    let m = motion(&driver_launch::<f32>());
    let r = fly_checked(&m, &Scene::default(), &Integrator::dormand_prince(1e-30));
    assert_eq!(r.err(), Some(Error::StepSizeUnderflow));
}

fn wind_from_everywhere<T: Real>() {
    let m = motion(&driver_launch::<T>());
    let calm = fly_checked(&m, &Scene::default(), &Integrator::default())
        .unwrap_or_else(|e| panic!("{e}"));
    let mut results = Vec::new();
    for k in 0..24 {
        let dir = f64::from(k) * 15.0_f64.to_radians();
        // "towards" direction, degrees from +X towards +Z (the CLI convention)
        let w = Vector3::new(
            lit::<T>(30.0 * dir.cos()),
            T::zero(),
            lit::<T>(30.0 * dir.sin()),
        );
        for wind in [Wind::Uniform(w), Wind::profile(w)] {
            let scene = Scene {
                wind,
                ..Scene::default()
            };
            match fly_checked(&m, &scene, &Integrator::default()) {
                Ok(out) => results.push((k, out)),
                Err(e) => panic!("wind towards {}°: {e}", k * 15),
            }
        }
    }
    // a crosswind blowing towards +Z (90°) drifts the ball right, towards −Z (270°) left;
    // (a 30 m/s tail- or headwind is not monotone in carry: it also changes the lift)
    let side = |k: usize, i: usize| to_f64(results[2 * k + i].1.side_m);
    for (i, (_, tail)) in results.iter().take(2).enumerate() {
        assert!(side(6, i) > 1.0 && side(18, i) < -1.0, "crosswind drift");
        assert!(to_f64(tail.carry_x_m) != to_f64(calm.carry_x_m));
    }
    // mirror symmetry: wind towards +θ and −θ give mirrored side, equal carry_x
    for k in 1..12 {
        for i in 0..2 {
            let (a, b) = (&results[2 * k + i].1, &results[2 * (24 - k) + i].1);
            let tol = 1e3 * closed_tol::<T>() * to_f64(a.carry_m);
            assert!(
                (to_f64(a.side_m) + to_f64(b.side_m)).abs() <= tol,
                "side at ±{}°",
                k * 15
            );
            assert!(
                (to_f64(a.carry_x_m) - to_f64(b.carry_x_m)).abs() <= tol,
                "carry at ±{}°",
                k * 15
            );
        }
    }
}

#[test]
fn thirty_metre_per_second_wind_from_every_direction() {
    wind_from_everywhere::<f64>();
    wind_from_everywhere::<f32>();
}

/// Bad flight inputs: NaN, ±∞ and out-of-range values name their field; huge finite
/// scene values are rejected rather than overflowing (found by fuzzing).
#[test]
fn bad_flight_inputs_name_their_field() {
    use carry_core::{Field, Reason};
    let m = motion(&driver_launch::<f64>());
    let dp = Integrator::default();
    let cases: [(Scene<f64>, Field); 5] = [
        (
            Scene {
                gravity_mps2: 1e300,
                ..Scene::default()
            },
            Field::Gravity,
        ),
        (
            Scene {
                landing_height_m: 1e300,
                ..Scene::default()
            },
            Field::LandingHeight,
        ),
        (
            Scene {
                launch_position_m: Vector3::new(0.0, 1e300, 0.0),
                ..Scene::default()
            },
            Field::LaunchPosition,
        ),
        (
            Scene {
                time_limit_s: f64::NAN,
                ..Scene::default()
            },
            Field::TimeLimit,
        ),
        (
            Scene {
                wind: Wind::Uniform(Vector3::new(f64::INFINITY, 0.0, 0.0)),
                ..Scene::default()
            },
            Field::Wind,
        ),
    ];
    for (scene, field) in cases {
        match fly_checked(&m, &scene, &dp) {
            Err(Error::InvalidInput { field: got, .. }) => assert_eq!(got, field),
            other => panic!("{field:?}: {other:?}"),
        }
    }
    for bad in [f64::NAN, f64::INFINITY, -1.0, 0.0] {
        for integ in [
            Integrator::Euler { step_s: bad },
            Integrator::Rk4 { step_s: bad },
            Integrator::dormand_prince(bad),
        ] {
            let r = fly_checked(&m, &Scene::default(), &integ);
            assert!(
                matches!(
                    r,
                    Err(Error::InvalidInput {
                        field: Field::Step | Field::Tolerance,
                        ..
                    })
                ),
                "{integ:?}: {r:?}"
            );
        }
    }
    let nan = BallMotion {
        velocity_mps: Vector3::new(f64::NAN, 0.0, 0.0),
        spin_radps: Vector3::zeros(),
    };
    assert_eq!(
        fly_checked(&nan, &Scene::default(), &dp).err(),
        Some(Error::invalid(Field::BallVelocity, Reason::NotFinite))
    );
}

/// Finding of the flight fuzzer (docs/robustness.md): Dormand–Prince with an absolute
/// tolerance of 3.4e38 on a lift-only ball circling about a vertical spin axis did not
/// terminate (every step passed the error test). Fixed: tolerances above
/// `flight::MAX_TOLERANCE` are rejected, and the adaptive loop has a step budget
/// (`flight::MAX_ADAPTIVE_STEPS` → `Error::StepLimit`), so the loosest accepted tolerance
/// terminates too.
#[test]
fn absurd_tolerance_terminates() {
    use carry_core::Air;
    use carry_core::{Field, Reason};
    let ball = Ball::new(0.059_362_325_474_937_07, 0.043_791_409_170_672_16)
        .unwrap_or_else(|e| panic!("{e}"));
    let m = BallMotion {
        velocity_mps: Vector3::new(
            33.902_638_659_229_29,
            97.723_498_050_281_22,
            52.800_231_334_067_604,
        ),
        spin_radps: Vector3::new(
            -8.414_709_848_078_965e-301,
            -191.851_682_307_164_08,
            5.403_023_058_681_397_5e-301,
        ),
    };
    let scene = Scene {
        effects: Effects {
            drag: false,
            lift: true,
            spin_decay: false,
        },
        air: Air::Density(1.0),
        landing_height_m: 26.463_721_675_440_603,
        time_limit_s: 46.610_588_235_294_12,
        gravity_mps2: 1.0,
        launch_position_m: Vector3::new(
            2.759_670_405_127_031_3,
            -2.755_703_059_433_890_3,
            1.617_074_845_502_402_9,
        ),
        ..Scene::default()
    };
    let integrator = Integrator::DormandPrince {
        rtol: 0.007_754_940_108_563_562,
        atol: 3.4e38,
        initial_step_s: 0.065_615_687_800_411_99,
        max_step_s: f64::INFINITY,
    };
    assert_eq!(
        fly(&ball, &m, &scene, &integrator, None).err(),
        Some(Error::invalid(Field::Tolerance, Reason::OutOfRange))
    );
    let loosest = Integrator::DormandPrince {
        rtol: 1.0,
        atol: carry_core::flight::MAX_TOLERANCE,
        initial_step_s: 0.065_615_687_800_411_99,
        max_step_s: f64::INFINITY,
    };
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(fly(&ball, &m, &scene, &loosest, None));
    });
    let r = rx.recv_timeout(std::time::Duration::from_secs(20));
    let Ok(r) = r else {
        panic!("the flight did not terminate within 20 s")
    };
    assert!(
        matches!(r, Err(Error::TimeLimit | Error::StepLimit) | Ok(_)),
        "{r:?}"
    );
}
