//! Full-shot costs (issue 6): club delivery → strike → impact → launch metrics → flight,
//! per precision, impact solver and integrator; cost per shot against batch size; cost
//! against flight time per integrator.
//!
//! `cargo bench -p carry-core --bench shot` (short runs: 1 s warm-up, 2 s measurement);
//! figures in docs/accuracy.md.
use carry_core::impact::Solver;
use carry_core::real::lit;
use carry_core::shot::{Fidelity, ShotOutcome, play};
use carry_core::units::{deg, rpm};
use carry_core::{
    Ball, ClubHead, ClubSpec, Delivery, FaceLocation, Integrator, Launch, PreparedScene, Real,
    Scene, fly,
};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

/// The default shot of `carry shot`: a 45 m/s driver, slightly off-centre (5 mm up, 10 mm
/// toe) so the gear effect gives a little sidespin.
fn driver_shot<T: Real>() -> Option<(ClubHead<T>, Delivery<T>)> {
    let club = ClubSpec::<T>::driver().validate().ok()?;
    let mut delivery = Delivery::square(lit(45.0), &club);
    delivery.location = FaceLocation {
        height_m: lit(0.005),
        toe_m: lit(0.01),
    };
    Some((club, delivery))
}

/// One full shot: everything a launch monitor computes per swing — strike, impact, launch
/// metrics, flight (`shot::play`; the club head, ball and scene are session constants,
/// validated and prepared once, as in the firmware's cost figures).
#[inline]
fn shot<T: Real>(
    club: &ClubHead<T>,
    ball: &Ball<T>,
    delivery: &Delivery<T>,
    scene: &PreparedScene<T>,
    solver: Solver,
    integrator: &Integrator<T>,
) -> carry_core::Result<ShotOutcome<T>> {
    let fidelity = Fidelity {
        solver,
        integrator: *integrator,
    };
    play(club, ball, delivery, scene, &fidelity, None)
}

fn full_shot<T: Real>(c: &mut Criterion, label: &str) {
    let Some((club, delivery)) = driver_shot::<T>() else {
        return;
    };
    let ball = Ball::<T>::standard();
    let Ok(scene) = Scene::<T>::default().prepare(&ball) else {
        return;
    };
    let mut group = c.benchmark_group(format!("shot/{label}"));
    let cases: [(&str, Solver, Integrator<T>); 6] = [
        ("default", Solver::Reduced, Integrator::default()),
        ("full_solver", Solver::FULL, Integrator::default()),
        (
            "dp45_1e-3",
            Solver::Reduced,
            Integrator::dormand_prince(lit(1e-3)),
        ),
        ("tight", Solver::Reduced, Integrator::tight()),
        (
            "rk4_0.02",
            Solver::Reduced,
            Integrator::Rk4 { step_s: lit(0.02) },
        ),
        (
            "euler_500hz",
            Solver::Reduced,
            Integrator::Euler { step_s: lit(0.002) },
        ),
    ];
    for (name, solver, integrator) in cases {
        group.bench_function(name, |b| {
            b.iter(|| {
                shot(
                    black_box(&club),
                    black_box(&ball),
                    black_box(&delivery),
                    black_box(&scene),
                    solver,
                    black_box(&integrator),
                )
            })
        });
    }
    // The default fidelity with the seed's aerodynamics (the default scene flies the
    // calibrated model): what the model choice costs.
    let seed = Scene::<T> {
        aero: carry_core::aero::AeroModel::quintavalla(),
        ..Scene::default()
    };
    if let Ok(seed) = seed.prepare(&ball) {
        group.bench_function("default_seed_aero", |b| {
            b.iter(|| {
                shot(
                    black_box(&club),
                    black_box(&ball),
                    black_box(&delivery),
                    black_box(&seed),
                    Solver::Reduced,
                    black_box(&Integrator::default()),
                )
            })
        });
    }
    group.finish();
}

/// Cost per shot against batch size: n different deliveries (speed, face location and
/// path varied) per iteration, reported as throughput per shot.
fn batch_size(c: &mut Criterion) {
    let Some((club, base)) = driver_shot::<f64>() else {
        return;
    };
    let ball = Ball::<f64>::standard();
    let Ok(scene) = Scene::<f64>::default().prepare(&ball) else {
        return;
    };
    let integrator = Integrator::<f64>::default();
    let mut group = c.benchmark_group("shot_batch/f64_default");
    for n in [1_usize, 16, 256, 4096] {
        let deliveries: Vec<Delivery<f64>> = (0..n)
            .map(|i| {
                #[allow(clippy::cast_precision_loss)]
                let x = (i % 64) as f64 / 64.0;
                Delivery {
                    club_speed_mps: 38.0 + 12.0 * x,
                    club_path_rad: deg(4.0 * x - 2.0),
                    location: FaceLocation {
                        height_m: 0.01 * x - 0.005,
                        toe_m: 0.02 - 0.04 * x,
                    },
                    ..base
                }
            })
            .collect();
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::from_parameter(n), &deliveries, |b, ds| {
            b.iter(|| {
                for d in ds {
                    let _ = black_box(shot(
                        &club,
                        &ball,
                        black_box(d),
                        &scene,
                        Solver::Reduced,
                        &integrator,
                    ));
                }
            })
        });
    }
    group.finish();
}

/// Cost of a flight against its flight time (30° launch, 3000 rpm, 10–80 m/s): fixed-step
/// integrators grow linearly, the adaptive one sub-linearly.
fn flight_time(c: &mut Criterion) {
    let ball = Ball::<f64>::standard();
    let scene = Scene::<f64>::default();
    let methods: [(&str, Integrator<f64>); 3] = [
        ("euler_1e-3", Integrator::Euler { step_s: 1e-3 }),
        ("rk4_0.02", Integrator::Rk4 { step_s: 0.02 }),
        ("dp45_default", Integrator::default()),
    ];
    for (name, integrator) in methods {
        let mut group = c.benchmark_group(format!("flight_time/{name}"));
        for speed in [10.0, 25.0, 45.0, 80.0] {
            let Ok(motion) = (Launch {
                ball_speed_mps: speed,
                launch_angle_rad: deg(30.0),
                launch_direction_rad: 0.0,
                backspin_radps: rpm(3000.0),
                sidespin_radps: 0.0,
            })
            .ball_motion() else {
                continue;
            };
            let t = fly(&ball, &motion, &scene, &integrator, None).map_or(0.0, |o| o.flight_time_s);
            group.bench_function(BenchmarkId::from_parameter(format!("{t:.2}s")), |b| {
                b.iter(|| fly(&ball, black_box(&motion), &scene, &integrator, None))
            });
        }
        group.finish();
    }
}

/// The launches of `bench/peer_opengolfcoach.py` (keep in sync): ball speed (m/s), launch
/// angle (deg), spin (rpm); straight, standard air. One iteration flies all 12.
const PEER_LAUNCHES: [(f64, f64, f64); 12] = [
    (65.87976772775029, 8.744649330360067, 2257.99909553281),
    (74.65568, 10.9, 2686.0),
    (90.0, 12.0, 2200.0),
    (63.0, 13.0, 3000.0),
    (70.0, 9.2, 3655.0),
    (53.6448, 16.3, 7097.0),
    (59.0, 12.1, 5361.0),
    (45.59808, 24.2, 9304.0),
    (21.75, 36.6, 6447.0),
    (12.0, 30.0, 4000.0),
    (60.0, 14.0, 0.0),
    (40.0, 80.0, 9000.0),
];

/// Flights of the peer comparison's launches at the default fidelity (f64): the
/// compute-only figure `bench/peer_opengolfcoach.py` divides by 12.
fn peer_launches(c: &mut Criterion) {
    let ball = Ball::<f64>::standard();
    let scene = Scene::<f64>::default();
    let integrator = Integrator::<f64>::default();
    let motions: Vec<_> = PEER_LAUNCHES
        .iter()
        .filter_map(|&(v, a, s)| {
            Launch {
                ball_speed_mps: v,
                launch_angle_rad: deg(a),
                launch_direction_rad: 0.0,
                backspin_radps: rpm(s),
                sidespin_radps: 0.0,
            }
            .ball_motion()
            .ok()
        })
        .collect();
    let mut group = c.benchmark_group("peer_launches");
    group.throughput(Throughput::Elements(motions.len() as u64));
    group.bench_function("f64_default", |b| {
        b.iter(|| {
            for m in &motions {
                let _ = black_box(fly(&ball, black_box(m), &scene, &integrator, None));
            }
        })
    });
    group.finish();
}

/// The ground effect's cost (issue 12): the default shot with no ground, then bouncing and
/// rolling to rest on each surface (docs/ground.md). Target: ≤ 1.5× the shot without.
fn ground<T: Real>(c: &mut Criterion, label: &str) {
    use carry_core::ground::{Ground, Surface};
    let Some((club, delivery)) = driver_shot::<T>() else {
        return;
    };
    let ball = Ball::<T>::standard();
    let mut group = c.benchmark_group(format!("shot_ground/{label}"));
    let cases: [(&str, Option<Surface<T>>); 4] = [
        ("none", None),
        ("fairway", Some(Surface::FairwayFirm)),
        ("green", Some(Surface::green())),
        ("rough", Some(Surface::Rough)),
    ];
    for (name, surface) in cases {
        let scene = Scene::<T> {
            ground: surface.map(Ground::level),
            ..Scene::default()
        };
        let Ok(scene) = scene.prepare(&ball) else {
            return;
        };
        group.bench_function(name, |b| {
            b.iter(|| {
                shot(
                    black_box(&club),
                    black_box(&ball),
                    black_box(&delivery),
                    black_box(&scene),
                    Solver::Reduced,
                    &Integrator::default(),
                )
            })
        });
    }
    group.finish();
}

/// The bounce's latency (docs/ground.md "Cost"): a chain of 64 bounces, each fed the last
/// one's rebound turned back down (a run-out's bounces wait on each other the same way).
fn bounce_chain(c: &mut Criterion) {
    use carry_core::ground::{Ground, Surface};
    use nalgebra::Vector3;
    let Ok(ground) = Ground::level(Surface::<f64>::FairwayFirm).prepare(0.021_336) else {
        return;
    };
    c.bench_function("shot_ground/bounce_chain_64", |b| {
        b.iter(|| {
            let mut v = black_box(Vector3::new(6.2, -0.75, -0.3));
            let mut w = black_box(Vector3::new(0.0, 0.0, -290.0));
            for _ in 0..64 {
                let Ok(r) = ground.bounce(&v, &w) else {
                    break;
                };
                // Back down at the same normal speed, the rebound's tangential velocity.
                v = Vector3::new(r.velocity_mps.x, -0.75, r.velocity_mps.z);
                w = r.spin_radps;
            }
            (v, w)
        })
    });
}

fn shot_benches(c: &mut Criterion) {
    bounce_chain(c);
    ground::<f64>(c, "f64");
    ground::<f32>(c, "f32");
    full_shot::<f64>(c, "f64");
    full_shot::<f32>(c, "f32");
    batch_size(c);
    flight_time(c);
    peer_launches(c);
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(2))
        .sample_size(30);
    targets = shot_benches
}
criterion_main!(benches);
