//! Estimator cost (issue 23): one estimate of club data from ball data and club speed with
//! the driver preset's default settings, f64 and f32; an everyday shot, and a cycle over
//! 64 deliveries spread like the default prior (the typical mix of iteration counts).
//! `cargo bench -p carry-core --bench estimate`
use carry_core::estimate::{BallData, ClubData, Posterior, Settings, Unknowns, estimate, predict};
use carry_core::real::lit;
use carry_core::units::deg;
use carry_core::{Ball, PRESETS, Real};
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;

/// A fixed spread of deliveries: each unknown at mean + sd·z with z from a fixed
/// low-discrepancy sequence in [−1.5, 1.5].
fn deliveries<T: Real>(settings: &Settings<T>, n: usize) -> Vec<Unknowns<T>> {
    let (m, s) = (settings.prior.mean.to_array(), settings.prior.sd.to_array());
    (0..n)
        .map(|k| {
            Unknowns::from_array(core::array::from_fn(|i| {
                let u = ((k as f64 + 0.5) * (0.618_034 + 0.137 * i as f64)).fract();
                m[i] + s[i] * lit::<T>(3.0 * u - 1.5)
            }))
        })
        .collect()
}

fn bench_precision<T: Real>(c: &mut Criterion, label: &str) {
    let preset = &PRESETS[0];
    let Ok(club) = preset.spec::<T>().validate() else {
        return;
    };
    let ball = Ball::<T>::standard();
    let settings = Settings::<T>::typical(&preset.typical);
    let everyday = Unknowns {
        face_angle_rad: deg(lit(1.2)),
        club_path_rad: deg(lit(2.5)),
        dynamic_loft_rad: deg(lit(12.0)),
        attack_angle_rad: deg(lit(-1.5)),
        impact_toe_m: lit(0.008),
        impact_height_m: lit(0.004),
        club_speed_mps: lit(45.0),
    };
    let case = |u: &Unknowns<T>| -> Option<(BallData<T>, ClubData<T>)> {
        let y = predict(&club, &ball, u).ok()?;
        let c = ClubData {
            club_speed_mps: Some(u.club_speed_mps),
            ..ClubData::default()
        };
        Some((y, c))
    };
    let mut group = c.benchmark_group(format!("estimate/{label}"));
    if let Some((y, cd)) = case(&everyday) {
        group.bench_function("everyday_club_speed", |b| {
            b.iter(|| {
                estimate(
                    black_box(&club),
                    &ball,
                    black_box(&y),
                    black_box(&cd),
                    &settings,
                )
            })
        });
    }
    let laplace = Settings {
        posterior: Posterior::Laplace,
        ..settings
    };
    if let Some((y, cd)) = case(&everyday) {
        group.bench_function("everyday_club_speed_laplace", |b| {
            b.iter(|| {
                estimate(
                    black_box(&club),
                    &ball,
                    black_box(&y),
                    black_box(&cd),
                    &laplace,
                )
            })
        });
    }
    let cases: Vec<_> = deliveries(&settings, 64).iter().filter_map(case).collect();
    let mut k = 0;
    group.bench_function("prior_spread_club_speed", |b| {
        b.iter(|| {
            k = (k + 1) % cases.len().max(1);
            cases
                .get(k)
                .map(|(y, cd)| estimate(&club, &ball, black_box(y), black_box(cd), &settings))
        })
    });
    group.bench_function("prior_spread_club_speed_laplace", |b| {
        b.iter(|| {
            k = (k + 1) % cases.len().max(1);
            cases
                .get(k)
                .map(|(y, cd)| estimate(&club, &ball, black_box(y), black_box(cd), &laplace))
        })
    });
    group.bench_function("predict", |b| {
        b.iter(|| predict(black_box(&club), &ball, black_box(&everyday)))
    });
    group.finish();
}

fn all(c: &mut Criterion) {
    bench_precision::<f64>(c, "f64");
    bench_precision::<f32>(c, "f32");
}

criterion_group!(benches, all);
criterion_main!(benches);
