//! Fuzz the flight entry points: launch → ball motion, scene preparation (density, weather,
//! wind, aerodynamic model and coefficients), and every integrator, in f32 and f64. A success must be finite and physical.
//! On a flag the same shot also flies through the lanes kernel (`carry_io::lanes`, the
//! batch path): on the build's baseline packs and the exact AVX packs it must agree with the
//! scalar path bit for bit, on the fused (FMA) packs to 1e-9 relative.
//!
//! The only inputs bounded beyond validation are the *work* a flight may take: a fixed
//! step or a maximum adaptive step below `time limit / 2e5` would take more than 2e5 steps
//! (legitimately slow, not a bug), so the harness skips those; see docs/robustness.md.
#![no_main]
// `!(a < b)` is the NaN-aware test on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use carry_core::aero::{AeroModel, LinearAero, ModernAero};
use carry_core::air::{Air, Pressure, Weather};
use carry_core::ball::BallMotion;
use carry_core::flight::{Integrator, Recorder, Sample};
use carry_core::lanes::{self, LaneReal, Shot};
use carry_core::real::{lit, to_f64};
use carry_core::scene::{Effects, PreparedScene, Scene};
use carry_core::wind::Wind;
use carry_core::{Ball, Error, FlightOutcome, Launch, Real, Result};
use carry_fuzz::Bytes;
use libfuzzer_sys::fuzz_target;
use nalgebra::Vector3;

fn v<T: Real>(a: [f64; 3]) -> Vector3<T> {
    Vector3::new(lit(a[0]), lit(a[1]), lit(a[2]))
}

const MAX_STEPS: f64 = 2e5;

fn run<T: LaneReal>(b: &mut Bytes<'_>) -> Result<()> {
    let ball = Ball::<T>::new(lit(b.param(0.01, 0.1)), lit(b.param(0.01, 0.05)))?;
    let launch = Launch::<T> {
        ball_speed_mps: lit(b.param(0.0, 150.0)),
        launch_angle_rad: lit(b.param(-1.6, 1.6)),
        launch_direction_rad: lit(b.param(-3.2, 3.2)),
        backspin_radps: lit(b.param(-2200.0, 2200.0)),
        sidespin_radps: lit(b.param(-2200.0, 2200.0)),
    };
    let air = match b.byte() % 3 {
        0 => Air::Density(lit(b.param(0.0, 2.0))),
        1 => Air::Weather(Weather {
            temperature_c: lit(b.param(-40.0, 50.0)),
            relative_humidity: lit(b.param(0.0, 1.0)),
            pressure: Pressure::Pa(lit(b.param(5e4, 1.1e5))),
        }),
        _ => Air::Weather(Weather {
            temperature_c: lit(b.param(-40.0, 50.0)),
            relative_humidity: lit(b.param(0.0, 1.0)),
            pressure: Pressure::Altitude(lit(b.param(-500.0, 5000.0))),
        }),
    };
    let wind = match b.byte() % 3 {
        0 => Wind::None,
        1 => Wind::Uniform(v(b.vec3(-30.0, 30.0))),
        _ => Wind::Profile {
            reference_mps: v(b.vec3(-30.0, 30.0)),
            reference_height_m: lit(b.param(0.5, 50.0)),
            exponent: lit(b.param(0.0, 0.5)),
        },
    };
    let time_limit = b.param(0.1, 60.0);
    let mut scene = Scene::<T> {
        effects: Effects {
            drag: b.flag(),
            lift: b.flag(),
            spin_decay: b.flag(),
        },
        air,
        wind,
        landing_height_m: lit(b.param(-20.0, 40.0)),
        time_limit_s: lit(time_limit),
        gravity_mps2: lit(b.param(0.0, 20.0)),
        launch_position_m: v(b.vec3(-5.0, 5.0)),
        ground: None,
        aero: AeroModel::default(),
    };
    let min_step = time_limit / MAX_STEPS;
    let integrator = match b.byte() % 3 {
        0 => Integrator::Euler {
            step_s: lit(b.param(1e-4, 0.1)),
        },
        1 => Integrator::Rk4 {
            step_s: lit(b.param(1e-4, 5.0)),
        },
        _ => Integrator::DormandPrince {
            rtol: lit(b.param(1e-12, 1e-2)),
            atol: lit(b.param(1e-12, 1e-2)),
            initial_step_s: lit(b.param(1e-4, 1.0)),
            max_step_s: lit(b.param(1e-3, 10.0)),
        },
    };
    let bounded = match integrator {
        Integrator::Euler { step_s } | Integrator::Rk4 { step_s } => !(to_f64(step_s) < min_step),
        Integrator::DormandPrince { max_step_s, .. } => !(to_f64(max_step_s) < min_step),
    };
    // Work bound 3: an updraft that grows without bound with height (a profile exponent
    // near 1 with a vertical component) lifts the ball exponentially for the whole time
    // limit; with a tight tolerance that is millions of correct, tiny steps.
    let calm_enough = match wind {
        Wind::Profile {
            reference_mps,
            exponent,
            ..
        } => to_f64(exponent) <= 0.5 && to_f64(reference_mps.y).abs() <= 5.0,
        Wind::Uniform(w) => to_f64(w.y).abs() <= 50.0,
        Wind::None => true,
    };
    // Any tolerance goes: the core rejects tolerances above 1 (an atol of 3.4e38 once
    // accepted every step and never terminated), and the adaptive step budget
    // (`flight::MAX_ADAPTIVE_STEPS`) bounds the work of tight ones.
    if !bounded || !calm_enough || !time_limit.is_finite() {
        return Ok(());
    }
    let motion = launch.ball_motion()?;
    let mut buffer: heapless::Vec<Sample<T>, 32> = heapless::Vec::new();
    let interval = b.param(1e-3, 1.0);
    let mut recorder = if b.flag() {
        Recorder::new(lit(interval), &mut buffer).ok()
    } else {
        None
    };
    // The aerodynamic model: the two built-in ones, or arbitrary coefficients of either
    // family (absurd ones must be named errors from `prepare`).
    scene.aero = match b.byte() % 4 {
        0 => AeroModel::quintavalla(),
        1 => AeroModel::tour_2023(),
        2 => AeroModel::Linear(LinearAero::from_array(
            [0; 5].map(|_| lit(b.param(-0.5, 12.0))),
        )),
        _ => AeroModel::Modern(ModernAero {
            cd_supercritical: lit(b.param(-0.1, 2.5)),
            cd_subcritical: lit(b.param(-0.1, 2.5)),
            reynolds_critical: lit(b.param(0.0, 2e7)),
            cl_max: lit(b.param(-0.1, 2.5)),
            cl_saturation_spin: lit(b.param(-0.1, 12.0)),
            cd_lift: lit(b.param(-0.5, 2.5)),
            cm_spin: lit(b.param(-0.01, 1.5)),
            cl_low: lit(b.param(-0.1, 2.5)),
            cl_low_saturation_spin: lit(b.param(-0.1, 12.0)),
        }),
    };
    let prepared = scene.prepare(&ball)?;
    // Work bound 2: the drag scale ρR²/m (golf: 0.012 /m). Far above it (a 1e300 kg/m³
    // air, a 1e-300 kg ball) the flight is stiff and the explicit integrators need
    // ~1/(ρR²/m·V) steps: correct but unbounded work (the core has no step-count cap; see
    // docs/robustness.md, "remaining").
    let r = to_f64(ball.radius_m());
    let drag_scale = to_f64(prepared.air_density_kgm3()) * r * r / to_f64(ball.mass_kg());
    if !(drag_scale <= 1.0) {
        return Ok(());
    }
    if std::env::var_os("CARRY_FUZZ_DEBUG").is_some() {
        eprintln!("{ball:?}\n{motion:?}\n{scene:?}\n{integrator:?}");
    }
    if b.flag() {
        lanes_agree(&prepared, &motion, &integrator);
    }
    let out = match prepared.fly(&motion, &integrator, recorder.as_mut()) {
        Ok(out) => out,
        Err(
            Error::InvalidInput { .. }
            | Error::NoLanding
            | Error::TimeLimit
            | Error::StepSizeUnderflow
            | Error::StepLimit
            | Error::Unstable,
        ) => return Ok(()),
        Err(e) => panic!("flight returned an impact error: {e:?}"),
    };
    let scalars = [
        out.carry_m,
        out.carry_x_m,
        out.side_m,
        out.apex_m,
        out.apex_time_s,
        out.flight_time_s,
        out.landing_angle_rad,
        out.landing_speed_mps,
        out.landing_spin_radps,
        out.air_density_kgm3,
    ];
    assert!(
        scalars.iter().all(|x| x.is_finite()),
        "non-finite outcome {out:?}"
    );
    for vec in [
        out.landing_position_m,
        out.landing_velocity_mps,
        out.landing_spin_vector_radps,
    ] {
        assert!(
            vec.iter().all(|x| x.is_finite()),
            "non-finite outcome {out:?}"
        );
    }
    assert!(out.carry_m >= T::zero());
    assert!(
        out.flight_time_s >= T::zero() && out.flight_time_s <= lit::<T>(time_limit) * lit(1.0001)
    );
    // (No sign check on the landing spin: an explicit step much larger than the spin-decay
    // time scale overshoots the magnitude through zero — inaccurate, but finite, and the
    // documented price of a too-large fixed step.)
    if let Some(r) = recorder {
        for s in r.samples() {
            assert!(
                s.position_m
                    .iter()
                    .chain(s.velocity_mps.iter())
                    .all(|x| x.is_finite())
            );
        }
    }
    Ok(())
}

/// The lanes kernel (issue 37) gives every shot of a batch the scalar path's result, error
/// or not: bit for bit on the build's baseline packs and on the exact AVX packs (four lanes,
/// and eight where the CPU has AVX-512); on the fused packs (AVX and FMA, or AVX-512: what
/// `carry batch` flies where the CPU has them) the same error, or the figures within 1e-9
/// relative (at least 1 m, 1 s, 1 rad of scale).
fn lanes_agree<T: LaneReal>(
    scene: &PreparedScene<T>,
    motion: &BallMotion<T>,
    integrator: &Integrator<T>,
) {
    let scalar = scene.fly(motion, integrator, None);
    let shot = Shot {
        scene,
        launch: *motion,
    };
    let shots = [shot; 3];
    let cpu = carry_io::lanes::cpu();
    let mut packs = vec![(None, true)];
    // The 256-bit packs (four `f64` lanes) and, where the CPU has AVX-512, the 512-bit
    // ones (eight lanes): exact bit for bit, fused within 1e-9.
    let tokens = cpu.map(|c| [Some(c.avx256()), c.avx512().then_some(c)]);
    for c in tokens.into_iter().flatten().flatten() {
        packs.push((Some(c.exact()), true));
        if c.fma() {
            packs.push((Some(c), false));
        }
    }
    for (cpu, exact) in packs {
        let mut flown = 0;
        lanes::fly_each_on(cpu, &shots, integrator, |i, lane| {
            flown += 1;
            if exact {
                assert!(
                    lane == scalar,
                    "lane {i} ({cpu:?}) differs from the scalar path: {lane:?} against {scalar:?}"
                );
            } else {
                close(&lane, &scalar, 1e-9);
            }
        });
        assert_eq!(flown, shots.len());
    }
}

/// The same error, or every figure within `rel` relative (at least 1 m, 1 s, 1 rad of
/// scale).
fn close<T: Real>(got: &Result<FlightOutcome<T>>, want: &Result<FlightOutcome<T>>, rel: f64) {
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
    match (got, want) {
        (Ok(g), Ok(w)) => {
            for (a, b) in figures(g).iter().zip(figures(w)) {
                assert!(
                    (a - b).abs() <= rel * b.abs().max(1.0),
                    "fused lanes {g:?} against the scalar path {w:?}"
                );
            }
        }
        (Err(a), Err(b)) => assert_eq!(a, b),
        _ => panic!("fused lanes {got:?} against the scalar path {want:?}"),
    }
}

fuzz_target!(|data: &[u8]| {
    let mut b = Bytes::new(data);
    let _ = if b.flag() {
        run::<f32>(&mut b)
    } else {
        run::<f64>(&mut b)
    };
});
