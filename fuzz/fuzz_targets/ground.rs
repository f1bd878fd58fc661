//! Fuzz the ground after the landing (issue 12): any surface (presets, any stimp, custom
//! turf with any values, NaN and absurd ones included), any slope, wind and integrator,
//! after a golf-like flight; and single bounces with any velocity and spin. A success
//! must be finite and physical: the run ends at rest or at the roll time cap, after the
//! landing, within the bounce budget, and a bounce never adds energy. Launches below the
//! horizon (topped shots, issue 21) run out from the launch point.
#![no_main]
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use carry_core::flight::{Integrator, Recorder, Sample};
use carry_core::ground::{CraterLaw, Ground, MAX_BOUNCES, Surface, Turf};
use carry_core::real::{lit, to_f64};
use carry_core::scene::Scene;
use carry_core::wind::Wind;
use carry_core::{Ball, Error, Launch, Real, Result};
use carry_fuzz::Bytes;
use libfuzzer_sys::fuzz_target;
use nalgebra::Vector3;

fn v<T: Real>(a: [f64; 3]) -> Vector3<T> {
    Vector3::new(lit(a[0]), lit(a[1]), lit(a[2]))
}

/// A number from the input: usually in range, sometimes anything (NaN, ∞, huge, negative).
fn wild(b: &mut Bytes<'_>, lo: f64, hi: f64) -> f64 {
    match b.byte() % 8 {
        0 => f64::NAN,
        1 => -b.param(0.0, 1e6),
        2 => b.param(hi, 1e30),
        3 => f64::INFINITY,
        _ => b.param(lo, hi),
    }
}

/// A surface from one byte (and the custom turf's): the issue-35 fits share tag 5, the
/// byte's high half picking the joint fairway, so that the committed corpus decodes every
/// other surface and every later field as before.
fn surface<T: Real>(b: &mut Bytes<'_>) -> Surface<T> {
    let tag = b.byte();
    match tag % 6 {
        0 => Surface::FairwayFirm,
        1 => Surface::FairwaySoft,
        5 if tag >= 128 => Surface::FairwayJoint,
        5 => Surface::FairwayTrackman,
        2 => Surface::Rough,
        3 => Surface::Green {
            stimp_m: lit(wild(b, 0.3, 9.0)),
        },
        _ => Surface::Custom(Turf {
            restitution: lit(wild(b, 0.0, 1.0)),
            friction: lit(wild(b, 0.0, 2.0)),
            rolling_resistance: lit(wild(b, 0.0, 1.0)),
            crater_scale: lit(wild(b, 0.0, 3.0)),
            crater_fade_mps: lit(wild(b, 0.0, 120.0)),
            grass_drag_s2pm2: lit(wild(b, 0.0, 1.0)),
            crater_law: if b.byte() % 2 == 0 {
                CraterLaw::Penner
            } else {
                CraterLaw::NormalTangential
            },
            // (Fixed: a byte more here would shift the committed corpus's decoding.)
            grass_height_m: lit(carry_core::ground::surface::FAIRWAY_GRASS_HEIGHT_M),
        }),
    }
}

fn run<T: Real>(b: &mut Bytes<'_>) -> Result<()> {
    let ball = Ball::<T>::standard();
    let ground = Ground {
        surface: surface::<T>(b),
        normal: if b.flag() {
            Vector3::y()
        } else {
            v(b.vec3(-1.0, 1.0)) + Vector3::y()
        },
    };
    if b.flag() {
        // One bounce through the public entry point.
        let g = ground.prepare(ball.radius_m())?;
        let vel: Vector3<T> = v(b.vec3(-80.0, 80.0));
        let spin: Vector3<T> = v(b.vec3(-1500.0, 1500.0));
        let r = g.bounce(&vel, &spin)?;
        assert!(
            r.velocity_mps
                .iter()
                .chain(r.spin_radps.iter())
                .all(|x| x.is_finite()),
            "a bounce from finite motion gave a non-finite one: {r:?}"
        );
        // √(2 × kinetic energy) = √(m v² + I ω²) by `hypot`, so that motion near the precision's
        // largest value does not overflow the check itself (found by the fixed-seed run:
        // ω² of a 1e155 rad/s spin is ∞ in f64, I ω² is not)
        let norm = |v: &Vector3<T>| to_f64(v.x).hypot(to_f64(v.y)).hypot(to_f64(v.z));
        let root_energy = |v: &Vector3<T>, w: &Vector3<T>| {
            (to_f64(ball.mass_kg()).sqrt() * norm(v))
                .hypot(to_f64(ball.inertia_kgm2()).sqrt() * norm(w))
        };
        if to_f64(vel.dot(&g.normal())) < 0.0 {
            let (e0, e1) = (
                root_energy(&vel, &spin),
                root_energy(&r.velocity_mps, &r.spin_radps),
            );
            assert!(
                e1 <= e0 * (1.0 + 5e-5) + 1e-9,
                "bounce adds energy: √(2E) {e0} → {e1}"
            );
        }
        return Ok(());
    }
    let launch = Launch::<T> {
        ball_speed_mps: lit(b.param(5.0, 90.0)),
        // Below the horizon too: from at or below the landing height a topped shot meets
        // the ground at once and runs out from the launch (issue 21).
        launch_angle_rad: lit(b.param(-0.3, 1.4)),
        launch_direction_rad: lit(b.param(-0.3, 0.3)),
        backspin_radps: lit(b.param(-300.0, 1300.0)),
        sidespin_radps: lit(b.param(-400.0, 400.0)),
    };
    let wind = match b.byte() % 3 {
        0 => Wind::None,
        1 => Wind::Uniform(v(b.vec3(-15.0, 15.0))),
        _ => Wind::profile(v(b.vec3(-15.0, 15.0))),
    };
    let scene = Scene::<T> {
        wind,
        landing_height_m: lit(b.param(-10.0, 10.0)),
        ground: Some(ground),
        ..Scene::default()
    };
    // Work bound (as in the flight target): steps of at least 5 ms, tolerances of at least
    // 1e-6, so an input costs milliseconds, not seconds.
    let integrator = match b.byte() % 3 {
        0 => Integrator::Rk4 {
            step_s: lit(b.param(5e-3, 0.05)),
        },
        1 => Integrator::dormand_prince(lit(b.param(1e-6, 1e-2))),
        _ => Integrator::default(),
    };
    // `param` also yields special values (tiny, huge, raw bits): keep only inputs whose
    // work is bounded, as the flight target does (a 1e-308 s step is legitimately slow).
    let step_ok = match integrator {
        Integrator::Rk4 { step_s } => to_f64(step_s) >= 5e-3,
        Integrator::DormandPrince { rtol, atol, .. } => {
            to_f64(rtol) >= 1e-6 && to_f64(atol) >= 1e-6
        }
        Integrator::Euler { .. } => false,
    };
    let calm = match wind {
        Wind::None => true,
        Wind::Uniform(w)
        | Wind::Profile {
            reference_mps: w, ..
        } => w.iter().all(|x| to_f64(*x).abs() <= 30.0),
    };
    if !(step_ok && calm) {
        return Ok(());
    }
    let motion = launch.ball_motion()?;
    if std::env::var_os("CARRY_FUZZ_DEBUG").is_some() {
        eprintln!("{motion:?}\n{scene:?}\n{integrator:?}");
    }
    let mut buffer: heapless::Vec<Sample<T>, 64> = heapless::Vec::new();
    let mut recorder = if b.flag() {
        Recorder::new(lit(b.param(1e-3, 0.5)), &mut buffer).ok()
    } else {
        None
    };
    if std::env::var_os("CARRY_FUZZ_DEBUG").is_some() {
        eprintln!("{recorder:?} f32={}", core::mem::size_of::<T>() == 4);
    }
    let out = match scene
        .prepare(&ball)?
        .fly(&motion, &integrator, recorder.as_mut())
    {
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
    let g = out.ground.expect("a ground gives a rollout");
    assert!(
        [g.total_m, g.roll_m, g.time_to_rest_s]
            .iter()
            .chain(g.rest_position_m.iter())
            .all(|x| x.is_finite()),
        "non-finite rollout {g:?}"
    );
    assert!(g.time_to_rest_s >= out.flight_time_s, "{g:?}");
    // Nothing astronomical (issue 20): launches are at most MAX_BALL_SPEED_MPS, and a
    // minute of rolling down the steepest accepted slope adds under 10 km.
    assert!(to_f64(g.total_m) < 1.0e5, "astronomical rollout {g:?}");
    assert!(g.total_m >= T::zero() && g.bounces <= MAX_BOUNCES);
    if let Some(r) = recorder {
        assert!(
            r.samples().windows(2).all(|w| w[1].time_s >= w[0].time_s),
            "samples out of time order: {:?}",
            r.samples().iter().map(|s| s.time_s).collect::<Vec<_>>()
        );
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

fuzz_target!(|data: &[u8]| {
    let mut b = Bytes::new(data);
    let _ = if b.flag() {
        run::<f32>(&mut b)
    } else {
        run::<f64>(&mut b)
    };
});
