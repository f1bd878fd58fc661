//! Flight costs: the per-effect ladder (gravity only, then adding drag, lift, spin
//! decay, a wind profile and weather), the integrators, and the effect-switch mechanism
//! (runtime branches vs compile-time monomorphised switches).
//!
//! `cargo bench -p carry-core --bench flight`; figures in docs/flight.md.
use carry_core::flight::bench::{WIND_FIELD, WIND_NONE, fly_switched};
use carry_core::real::lit;
use carry_core::scene::effect_ladder;
use carry_core::units::{deg, rpm};
use carry_core::{Ball, BallMotion, Integrator, Launch, Real, Scene, fly};
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

/// TrackMan's PGA Tour driver average launch (PHYSICS.md): 167 mph, 10.9°, 2686 rpm.
fn driver<T: Real>() -> BallMotion<T> {
    Launch {
        ball_speed_mps: lit(74.65568),
        launch_angle_rad: deg(lit(10.9)),
        launch_direction_rad: deg(lit(1.0)),
        backspin_radps: rpm(lit(2686.0)),
        sidespin_radps: rpm(lit(-300.0)),
    }
    .ball_motion()
    .unwrap_or_default()
}

fn effects<T: Real>(c: &mut Criterion, label: &str) {
    let ball = Ball::<T>::standard();
    let launch = driver::<T>();
    // A fixed step makes the evaluation count (almost) the same on every rung, so the
    // differences are the per-evaluation cost of each effect; the default adaptive
    // integrator shows what a user pays (its step count depends on the effects too).
    for (name, integrator) in [
        ("rk4_h0.05", Integrator::Rk4 { step_s: lit(0.05) }),
        ("default", Integrator::default()),
    ] {
        let mut group = configure_group(c, &format!("flight/effects/{label}/{name}"));
        for (rung, scene) in effect_ladder::<T>() {
            group.bench_function(rung, |b| {
                b.iter(|| {
                    fly(
                        black_box(&ball),
                        black_box(&launch),
                        black_box(&scene),
                        &integrator,
                        None,
                    )
                })
            });
        }
        group.finish();
    }
}

fn configure_group<'a>(
    c: &'a mut Criterion,
    name: &str,
) -> criterion::BenchmarkGroup<'a, criterion::measurement::WallTime> {
    let mut g = c.benchmark_group(name);
    g.sample_size(40)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    g
}

fn integrators<T: Real>(c: &mut Criterion, label: &str) {
    let ball = Ball::<T>::standard();
    let launch = driver::<T>();
    let scene = Scene::<T>::default();
    let mut group = configure_group(c, &format!("flight/integrator/{label}"));
    let list = [
        ("euler_h1e-3", Integrator::Euler { step_s: lit(1e-3) }),
        ("rk4_h0.05", Integrator::Rk4 { step_s: lit(0.05) }),
        ("rk4_h0.02", Integrator::Rk4 { step_s: lit(0.02) }),
        ("dp45_default", Integrator::default()),
        ("dp45_tight", Integrator::tight()),
    ];
    for (name, integrator) in list {
        group.bench_function(name, |b| {
            b.iter(|| {
                fly(
                    black_box(&ball),
                    black_box(&launch),
                    black_box(&scene),
                    &integrator,
                    None,
                )
            })
        });
    }
    group.finish();
}

/// Runtime branches on the scene's flags (the production path) against the same flight
/// with the switches as const generics (one monomorphised copy per combination).
fn mechanism(c: &mut Criterion) {
    let ball = Ball::<f64>::standard();
    let launch = driver::<f64>();
    let integrator = Integrator::<f64>::default();
    let [(_, gravity), _, _, (_, full), (_, profile), _] = effect_ladder::<f64>();
    let (Ok(gravity), Ok(full), Ok(profile)) = (
        gravity.prepare(&ball),
        full.prepare(&ball),
        profile.prepare(&ball),
    ) else {
        return;
    };
    let mut group = configure_group(c, "flight/mechanism/f64");
    group.bench_function("gravity_runtime", |b| {
        b.iter(|| black_box(&gravity).fly(black_box(&launch), &integrator, None))
    });
    group.bench_function("gravity_const", |b| {
        b.iter(|| {
            fly_switched::<f64, false, false, false, WIND_NONE>(
                black_box(&gravity),
                black_box(&launch),
                &integrator,
            )
        })
    });
    group.bench_function("full_runtime", |b| {
        b.iter(|| black_box(&full).fly(black_box(&launch), &integrator, None))
    });
    group.bench_function("full_const", |b| {
        b.iter(|| {
            fly_switched::<f64, true, true, true, WIND_NONE>(
                black_box(&full),
                black_box(&launch),
                &integrator,
            )
        })
    });
    group.bench_function("profile_runtime", |b| {
        b.iter(|| black_box(&profile).fly(black_box(&launch), &integrator, None))
    });
    group.bench_function("profile_const", |b| {
        b.iter(|| {
            fly_switched::<f64, true, true, true, WIND_FIELD>(
                black_box(&profile),
                black_box(&launch),
                &integrator,
            )
        })
    });
    group.finish();
}

fn flight_benches(c: &mut Criterion) {
    effects::<f64>(c, "f64");
    effects::<f32>(c, "f32");
    integrators::<f64>(c, "f64");
    integrators::<f32>(c, "f32");
    mechanism(c);
}

criterion_group!(benches, flight_benches);
criterion_main!(benches);
