//! Criterion benches of the lab's targets (issue 14): a sweep over 1,000 ball positions on
//! one core (≤ 10 ms), 100,000 dispersion shots on two threads (≤ 0.5 s), one optimizer
//! search. `cargo bench -p carry-lab --bench lab -- --warm-up-time 1 --measurement-time 3`.

use carry_core::PRESETS;
use carry_lab::Setup;
use carry_lab::dispersion::{Noise, simulate};
use carry_lab::optimize::{Options, Range, optimize};
use carry_lab::sweep::generate::SwingModel;
use carry_lab::sweep::{positions, sweep};
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;

fn setup() -> Setup<f64> {
    match Setup::standard(&PRESETS[0], 45.0) {
        Ok(s) => s,
        Err(e) => panic!("{e}"),
    }
}

fn sweep_1000(c: &mut Criterion) {
    let s = setup();
    let Ok(motion) = SwingModel::default().generate(
        s.club.face_rotation(),
        s.club.cg_to_face_m(),
        s.ball.radius_m(),
    ) else {
        panic!()
    };
    // 1,000 positions over ±0.1 m.
    let Ok(xs) = positions(-0.1, 0.0998, 0.0002) else {
        panic!()
    };
    assert_eq!(xs.len(), 1000);
    c.bench_function("sweep 1000 ball positions (1 core)", |b| {
        b.iter(|| sweep(black_box(&s), &motion, &xs))
    });
}

fn dispersion_100k(c: &mut Criterion) {
    let s = setup();
    let noise = Noise {
        face_angle_deg: 1.0,
        club_path_deg: 1.5,
        club_speed_mps: 1.0,
        impact_toe_m: 0.008,
        ..Noise::default()
    };
    let Ok(pool) = rayon::ThreadPoolBuilder::new().num_threads(2).build() else {
        panic!()
    };
    let mut g = c.benchmark_group("dispersion");
    g.sample_size(10);
    g.bench_function("100000 shots (2 threads)", |b| {
        b.iter(|| pool.install(|| simulate(black_box(&s), &noise, 100_000, 1, None)))
    });
    g.finish();
}

fn optimize_carry(c: &mut Criterion) {
    let s = setup().smooth();
    let options = Options::carry(Range { lo: 4.0, hi: 24.0 }, Range { lo: -5.0, hi: 5.0 });
    c.bench_function("optimize carry (1 start)", |b| {
        b.iter(|| optimize(black_box(&s), &options))
    });
}

criterion_group!(benches, sweep_1000, dispersion_100k, optimize_carry);
criterion_main!(benches);
