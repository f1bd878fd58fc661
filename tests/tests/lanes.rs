//! The lanes kernel (`carry_core::lanes`, issue 37) against the scalar path
//! (`PreparedScene::fly`), through the public API: a few hundred random launches in lanes
//! that finish at different times, invalid shots among them, scenes the kernel does not
//! cover mixed in, in `f64` and `f32`, and a property test.

use carry_core::lanes::{self, Avx, LaneReal, Shot};
use carry_core::units::{deg, rpm};
use carry_core::{
    Air, Ball, BallMotion, Effects, Error, FlightOutcome, Ground, Integrator, Launch,
    PreparedScene, Real, Result, Scene, Surface, Wind, aero::AeroModel, real::lit, real::to_f64,
};
use nalgebra::Vector3;
use proptest::prelude::*;

/// SplitMix64: a deterministic stream in [0, 1).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}

fn launch<T: Real>(speed: f64, angle: f64, dir: f64, back: f64, side: f64) -> BallMotion<T> {
    Launch {
        ball_speed_mps: lit(speed),
        launch_angle_rad: deg(lit(angle)),
        launch_direction_rad: deg(lit(dir)),
        backspin_radps: rpm(lit(back)),
        sidespin_radps: rpm(lit(side)),
    }
    .ball_motion()
    .unwrap_or_default()
}

/// A random golf launch: wedges to drivers, toppers to sky balls, hooks and slices.
fn random_launch<T: Real>(r: &mut Rng) -> BallMotion<T> {
    launch(
        r.range(15.0, 95.0),
        r.range(1.0, 55.0),
        r.range(-10.0, 10.0),
        r.range(0.0, 11_000.0),
        r.range(-2500.0, 2500.0),
    )
}

/// The scenes the kernel covers (the default model in still air, uniform winds, other
/// air, a raised tee, a lower green, drives2026) and two it does not (the seed's model, a
/// ground), prepared.
fn scenes<T: Real>() -> Vec<PreparedScene<T>> {
    let ball = Ball::<T>::standard();
    let w = |x: f64, z: f64| Wind::Uniform(Vector3::new(lit(x), lit(0.0), lit(z)));
    let list = [
        Scene::default(),
        Scene {
            wind: w(-6.0, 3.0),
            ..Scene::default()
        },
        Scene {
            wind: w(9.0, -4.0),
            air: Air::Density(lit(1.0)),
            landing_height_m: lit(-4.0),
            ..Scene::default()
        },
        Scene {
            aero: AeroModel::drives_2026(),
            launch_position_m: Vector3::new(lit(0.0), lit(0.04), lit(0.0)),
            landing_height_m: lit(2.5),
            ..Scene::default()
        },
        Scene {
            aero: AeroModel::quintavalla(),
            ..Scene::default()
        },
        Scene {
            ground: Some(Ground::level(Surface::green())),
            ..Scene::default()
        },
        Scene {
            effects: Effects {
                spin_decay: false,
                ..Effects::ALL
            },
            ..Scene::default()
        },
    ];
    list.iter()
        .map(|s| s.prepare(&ball).unwrap_or_else(|e| panic!("{e:?}")))
        .collect()
}

/// Every shot's result through `lanes::fly_each_on` with `cpu`, in input order.
fn fly_lanes_on<T: LaneReal>(
    cpu: Option<Avx>,
    shots: &[Shot<'_, T>],
    integrator: &Integrator<T>,
) -> Vec<Result<FlightOutcome<T>>> {
    let mut out: Vec<Option<Result<FlightOutcome<T>>>> = vec![None; shots.len()];
    lanes::fly_each_on(cpu, shots, integrator, |i, r| {
        assert!(out[i].is_none(), "shot {i} reported twice");
        out[i] = Some(r);
    });
    out.into_iter()
        .enumerate()
        .map(|(i, r)| r.unwrap_or_else(|| panic!("shot {i} not reported")))
        .collect()
}

/// Every shot's result through `lanes::fly_each` (the build's baseline packs), in input
/// order; where the CPU has AVX, also through the exact AVX packs (`Avx::exact`), which
/// must give the very same results, and where it has FMA too, through the fused packs
/// (`carry_io::lanes::cpu`'s choice), whose results must be within 1e-9 of them
/// ([`close`]); both on four lanes (`Avx::avx256`) and, where the CPU has AVX-512, on
/// eight.
fn fly_lanes<T: LaneReal>(
    shots: &[Shot<'_, T>],
    integrator: &Integrator<T>,
) -> Vec<Result<FlightOutcome<T>>> {
    let base = fly_lanes_on(None, shots, integrator);
    if let Some(cpu) = carry_io::lanes::cpu() {
        // The 256-bit packs, and where the CPU has AVX-512 the 512-bit ones (eight `f64`
        // lanes; `cpu()` prefers them): exact ones bit for bit, fused ones within 1e-9.
        let mut tokens = vec![cpu.avx256()];
        if cpu.avx512() {
            tokens.push(cpu);
        } else {
            note_no_avx512();
        }
        // (A lane's operations do not depend on the pack's width: the fused 8-lane packs
        // give the fused 4-lane ones' results bit for bit.)
        let mut fused_4 = None;
        for cpu in tokens {
            let avx = fly_lanes_on(Some(cpu.exact()), shots, integrator);
            for (i, (a, b)) in avx.iter().zip(&base).enumerate() {
                assert_eq!(
                    a, b,
                    "shot {i}: AVX packs ({cpu:?}) against the baseline ones"
                );
            }
            if cpu.fma() {
                let fused = fly_lanes_on(Some(cpu), shots, integrator);
                for (i, (a, b)) in fused.iter().zip(&base).enumerate() {
                    close(a, b, 1e-9, &format!("shot {i}: fused packs ({cpu:?})"));
                }
                if let Some(four) = &fused_4 {
                    assert_eq!(&fused, four, "fused packs: eight lanes against four");
                }
                fused_4 = Some(fused);
            }
        }
    }
    let mut plain: Vec<Option<Result<FlightOutcome<T>>>> = vec![None; shots.len()];
    lanes::fly_each(shots, integrator, |i, r| plain[i] = Some(r));
    for (i, (a, b)) in plain.iter().zip(&base).enumerate() {
        assert_eq!(
            a.as_ref(),
            Some(b),
            "shot {i}: fly_each against fly_each_on(None)"
        );
    }
    base
}

/// Says once that this CPU has no AVX-512, so its packs are not checked here.
fn note_no_avx512() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| println!("note: no AVX-512 on this CPU; its packs not checked"));
}

/// Flights that fail in the air, lane by lane: a time limit shorter than most flights (the
/// lanes' packed time check), beside scenes without one, and a tolerance so fine that
/// steps underflow or hit the step limit.
#[test]
fn lanes_fail_in_the_air_as_the_scalar_path_does() {
    let ball = Ball::<f64>::standard();
    let short = Scene::<f64> {
        time_limit_s: 3.0,
        ..Scene::default()
    }
    .prepare(&ball)
    .unwrap_or_else(|e| panic!("{e:?}"));
    let mut scenes = vec![short];
    scenes.extend(self::scenes::<f64>().into_iter().take(2));
    let shots = shots(&scenes, 200, 91);
    let integrator = Integrator::default();
    let out = fly_lanes::<f64>(&shots, &integrator);
    compare(&shots, &integrator, &out, 0.0);
    let timed_out = out
        .iter()
        .filter(|r| matches!(r, Err(Error::TimeLimit)))
        .count();
    let landed = out.iter().filter(|r| r.is_ok()).count();
    assert!(
        timed_out > 10 && landed > 50,
        "{timed_out} timed out, {landed} landed"
    );
    // A tolerance too fine for `f64`: the scalar path's own failures, lane by lane.
    let fine = Integrator::dormand_prince(1e-300);
    let few = &shots[..12];
    let out = fly_lanes::<f64>(few, &fine);
    compare(few, &fine, &out, 0.0);
    let underflows = out
        .iter()
        .filter(|r| matches!(r, Err(Error::StepSizeUnderflow)))
        .count();
    assert!(underflows >= 10, "{underflows} step-size underflows");
}

/// The same error, or the figures within `rel` (relative, at least 1 m or 1 s or 1 rad of
/// scale); whether the outcomes are equal bit for bit.
fn close<T: Real>(
    got: &Result<FlightOutcome<T>>,
    want: &Result<FlightOutcome<T>>,
    rel: f64,
    what: &str,
) -> bool {
    match (got, want) {
        (Ok(g), Ok(w)) => {
            let figures = |o: &FlightOutcome<T>| {
                [
                    o.carry_m,
                    o.side_m,
                    o.apex_m,
                    o.apex_time_s,
                    o.flight_time_s,
                    o.landing_angle_rad,
                    o.landing_speed_mps,
                ]
                .map(to_f64)
            };
            for (k, (a, b)) in figures(g).iter().zip(figures(w)).enumerate() {
                assert!(
                    (a - b).abs() <= rel * b.abs().max(1.0),
                    "{what}: figure {k}: {a} against {b}"
                );
            }
            g == w
        }
        (Err(a), Err(b)) => {
            assert_eq!(a, b, "{what}");
            false
        }
        _ => panic!("{what}: {got:?} against {want:?}"),
    }
}

/// Compares each lanes result with the scalar one ([`close`]); returns how many outcomes
/// are the scalar ones bit for bit.
fn compare<T: Real>(
    shots: &[Shot<'_, T>],
    integrator: &Integrator<T>,
    lanes: &[Result<FlightOutcome<T>>],
    rel: f64,
) -> usize {
    let mut identical = 0;
    for (i, (shot, got)) in shots.iter().zip(lanes).enumerate() {
        let want = shot.scene.fly(&shot.launch, integrator, None);
        identical += usize::from(close(got, &want, rel, &format!("shot {i}: lanes, scalar")));
    }
    identical
}

/// The shots: `n` random launches spread over the scenes, with invalid ones every so
/// often (NaN, too fast, spinning too fast, launched into the ground).
fn shots<'a, T: Real>(scenes: &'a [PreparedScene<T>], n: usize, seed: u64) -> Vec<Shot<'a, T>> {
    let mut r = Rng(seed);
    (0..n)
        .map(|i| {
            let scene = &scenes[(r.next() * scenes.len() as f64) as usize % scenes.len()];
            let mut launch = random_launch::<T>(&mut r);
            match i % 37 {
                5 => launch.velocity_mps.x = lit(f64::NAN),
                11 => launch.velocity_mps *= lit::<T>(3.0),
                17 => launch.spin_radps *= lit::<T>(1.0e3),
                23 => launch.velocity_mps.y = lit(-3.0),
                _ => {}
            }
            Shot { scene, launch }
        })
        .collect()
}

#[test]
fn lanes_equal_the_scalar_path_in_f64() {
    let scenes = scenes::<f64>();
    let shots = shots(&scenes, 600, 37);
    for integrator in [
        Integrator::default(),
        Integrator::seed(),
        Integrator::dormand_prince(1e-9),
    ] {
        let out = fly_lanes::<f64>(&shots, &integrator);
        let identical = compare(&shots, &integrator, &out, 1e-9);
        let ok = out.iter().filter(|r| r.is_ok()).count();
        let errors = out.len() - ok;
        println!("{integrator:?}: {ok} flights, {identical} bit-identical, {errors} errors");
        // At least the NaN and the over-spun shots fail (the others may fly).
        assert!(errors >= 2 * (600 / 37), "the invalid shots fail: {errors}");
        // At this commit every lane runs the scalar operations: all bit-identical.
        assert_eq!(identical, ok, "bit-identical outcomes");
    }
}

/// More shots than lanes, fewer than lanes, and none.
#[test]
fn any_number_of_shots() {
    let scenes = scenes::<f64>();
    let integrator = Integrator::default();
    for n in [0, 1, 2, 3, 4, 5, 9, 64] {
        let shots = shots(&scenes[..4], n, 8 + n as u64);
        let out = fly_lanes::<f64>(&shots, &integrator);
        compare(&shots, &integrator, &out, 0.0);
    }
}

#[test]
fn lanes_equal_the_scalar_path_in_f32() {
    let scenes = scenes::<f32>();
    let shots = shots(&scenes, 300, 32);
    let integrator = Integrator::default();
    let out = fly_lanes::<f32>(&shots, &integrator);
    let identical = compare(&shots, &integrator, &out, 0.0);
    assert_eq!(identical, out.iter().filter(|r| r.is_ok()).count());
}

/// Lanes finish at different times: a wedge, a driver and a sky ball beside a topped shot
/// and a bad one, in one group of four and beyond; the fixed-step integrators fall back.
#[test]
fn lanes_that_finish_apart_and_fallbacks() {
    let scenes = scenes::<f64>();
    let s = &scenes[0];
    let launches = [
        launch::<f64>(40.0, 30.0, 0.0, 9000.0, 500.0),
        launch(75.0, 11.0, 2.0, 2600.0, -300.0),
        launch(60.0, 3.0, 0.0, 1500.0, 0.0),
        BallMotion {
            velocity_mps: Vector3::new(f64::NAN, 5.0, 0.0),
            ..launch(50.0, 10.0, 0.0, 2000.0, 0.0)
        },
        launch(30.0, 60.0, 0.0, 7000.0, 0.0),
        launch(70.0, 14.0, -3.0, 3000.0, 800.0),
    ];
    let shots: Vec<Shot<'_, f64>> = launches
        .iter()
        .map(|&launch| Shot { scene: s, launch })
        .collect();
    for integrator in [Integrator::default(), Integrator::Rk4 { step_s: 1e-3 }] {
        let out = fly_lanes::<f64>(&shots, &integrator);
        compare(&shots, &integrator, &out, 0.0);
        assert!(matches!(out[3], Err(Error::InvalidInput { .. })));
        let times: Vec<f64> = out.iter().flatten().map(|o| o.flight_time_s).collect();
        let (lo, hi) = times
            .iter()
            .fold((f64::MAX, 0.0_f64), |(a, b), t| (a.min(*t), b.max(*t)));
        assert!(hi > 2.0 * lo, "flight times {times:?}");
    }
    assert!(lanes::covers(s, &Integrator::default()));
    assert!(!lanes::covers(s, &Integrator::Rk4 { step_s: 1e-3 }));
    assert!(!lanes::covers(&scenes[4], &Integrator::default()));
    assert!(!lanes::covers(&scenes[5], &Integrator::default()));
    // An invalid integrator: every shot gets the scalar path's error.
    let bad = Integrator::dormand_prince(-1.0);
    let out = fly_lanes::<f64>(&shots, &bad);
    compare(&shots, &bad, &out, 0.0);
    assert!(out.iter().all(Result::is_err));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// Any launches, valid or not, through a covered scene with any uniform wind: never a
    /// panic, and each result the scalar path's.
    #[test]
    fn lanes_match_scalar_for_any_launch(
        launches in prop::collection::vec(
            (-10.0..160.0f64, -30.0..90.0f64, -45.0..45.0f64, -5000.0..40_000.0f64, -9000.0..9000.0f64),
            1..11,
        ),
        wind in (-20.0..20.0f64, -20.0..20.0f64),
        tolerance in 1e-10..1e-2f64,
    ) {
        let scene = Scene::<f64> {
            wind: Wind::Uniform(Vector3::new(wind.0, 0.0, wind.1)),
            ..Scene::default()
        }
        .prepare(&Ball::standard())
        .unwrap_or_else(|e| panic!("{e:?}"));
        let shots: Vec<Shot<'_, f64>> = launches
            .iter()
            .map(|&(v, a, d, b, s)| Shot {
                scene: &scene,
                launch: Launch {
                    ball_speed_mps: v,
                    launch_angle_rad: deg(a),
                    launch_direction_rad: deg(d),
                    backspin_radps: rpm(b),
                    sidespin_radps: rpm(s),
                }
                .ball_motion()
                .unwrap_or_default(),
            })
            .collect();
        let integrator = Integrator::dormand_prince(tolerance);
        let out = fly_lanes::<f64>(&shots, &integrator);
        compare(&shots, &integrator, &out, 1e-9);
    }
}
