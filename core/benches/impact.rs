//! Impact solver costs: reduced 3×3 vs full 15×15 (each pivoting), the reduced form with
//! the compliant contact, f32 vs f64.
//! `cargo bench -p carry-core --bench impact`
use carry_core::impact::{self, Solver};
use carry_core::linalg::Pivoting;
use carry_core::real::lit;
use carry_core::{Ball, ClubSpec, Delivery, FaceLocation, Real};
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;

fn bench_precision<T: Real>(c: &mut Criterion, label: &str) {
    let Ok(club) = ClubSpec::<T>::driver().validate() else {
        return;
    };
    let ball = Ball::<T>::standard();
    let mut delivery = Delivery::square(lit(45.0), &club);
    delivery.location = FaceLocation {
        height_m: lit(0.005),
        toe_m: lit(0.01),
    };
    let Ok(strike) = delivery.strike(&club) else {
        return;
    };
    let mut group = c.benchmark_group(format!("impact/{label}"));
    let solvers = [
        ("reduced", Solver::Reduced),
        ("full_equilibrated", Solver::Full(Pivoting::Equilibrated)),
        ("full_partial", Solver::Full(Pivoting::Partial)),
    ];
    for (name, solver) in solvers {
        group.bench_function(name, |b| {
            b.iter(|| {
                impact::solve(
                    black_box(&club),
                    black_box(&ball),
                    black_box(&strike),
                    solver,
                )
            })
        });
    }
    // the same strike with the presets' calibrated compliant contact
    let compliant = ClubSpec::<T> {
        contact: carry_core::presets::FITTED_CONTACT.cast(),
        ..ClubSpec::<T>::driver()
    };
    if let Ok(compliant) = compliant.validate() {
        group.bench_function("reduced_compliant", |b| {
            b.iter(|| {
                impact::solve(
                    black_box(&compliant),
                    black_box(&ball),
                    black_box(&strike),
                    Solver::Reduced,
                )
            })
        });
    }
    group.bench_function("delivery_to_strike", |b| {
        b.iter(|| black_box(&delivery).strike(black_box(&club)))
    });
    group.finish();
}

fn impact_benches(c: &mut Criterion) {
    bench_precision::<f64>(c, "f64");
    bench_precision::<f32>(c, "f32");
}

criterion_group!(benches, impact_benches);
criterion_main!(benches);
