//! The lanes kernel (issue 37) beside the scalar path: the same 256 launches (wedges to
//! drivers, hooks and slices, in still air and in a uniform wind) flown one by one with
//! `PreparedScene::fly`, through `lanes::fly_each` (4 lanes on the build's baseline packs:
//! SSE2 on x86-64) and, where the CPU has AVX, through `lanes::fly_each_on` with the AVX
//! token, exact (`lanes-avx`) and with FMA where the CPU has it (`lanes-fma`), and where
//! it has AVX-512 on eight lanes a register, exact (`lanes-avx512`) and fused
//! (`lanes-avx512-fma`: what `carry batch` and the Python package run there;
//! `carry_io::lanes`), one thread.
//! Throughput is per shot.
//!
//! `cargo bench -p carry-core --bench lanes`; figures in docs/performance.md ("Lanes kernel").
use carry_core::lanes::{self, Shot};
use carry_core::units::{deg, rpm};
use carry_core::{Ball, Integrator, Launch, PreparedScene, Scene, Wind};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use nalgebra::Vector3;
use std::hint::black_box;
use std::time::Duration;

const SHOTS: usize = 256;

/// A fixed spread of launches (a linear congruential stream, so every run flies the same).
fn launches(scene: &PreparedScene<f64>) -> Vec<Shot<'_, f64>> {
    let mut state: u64 = 0x2545_F491_4F6C_DD1D;
    let mut next = |lo: f64, hi: f64| {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        lo + (hi - lo) * ((state >> 11) as f64 / (1u64 << 53) as f64)
    };
    (0..SHOTS)
        .filter_map(|_| {
            Launch {
                ball_speed_mps: next(40.0, 80.0),
                launch_angle_rad: deg(next(9.0, 30.0)),
                launch_direction_rad: deg(next(-4.0, 4.0)),
                backspin_radps: rpm(next(2000.0, 9500.0)),
                sidespin_radps: rpm(next(-1200.0, 1200.0)),
            }
            .ball_motion()
            .ok()
            .map(|launch| Shot { scene, launch })
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let ball = Ball::standard();
    let integrator = Integrator::<f64>::default();
    for (name, wind) in [
        ("still", Wind::None),
        ("wind", Wind::Uniform(Vector3::new(-5.0, 0.0, 3.0))),
    ] {
        let Ok(scene) = Scene::<f64> {
            wind,
            ..Scene::default()
        }
        .prepare(&ball) else {
            return;
        };
        let shots = launches(&scene);
        let mut g = c.benchmark_group(format!("lanes/{name}"));
        g.sample_size(30)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(3))
            .throughput(Throughput::Elements(shots.len() as u64));
        g.bench_function("scalar", |b| {
            b.iter(|| {
                let mut carry = 0.0;
                for s in black_box(&shots) {
                    if let Ok(o) = s.scene.fly(&s.launch, &integrator, None) {
                        carry += o.carry_m;
                    }
                }
                carry
            })
        });
        g.bench_function("lanes", |b| {
            b.iter(|| {
                let mut carry = 0.0;
                lanes::fly_each(black_box(&shots), &integrator, |_, r| {
                    if let Ok(o) = r {
                        carry += o.carry_m;
                    }
                });
                carry
            })
        });
        let fma = avx().filter(|_| is_x86_feature_detected!("fma"));
        #[allow(unsafe_code)]
        // SAFETY: `with_fma_unchecked` requires FMA, which was just detected.
        let fma = fma.map(|c| unsafe { c.with_fma_unchecked() });
        // AVX-512 (eight `f64` lanes a register) where the CPU has AVX-512 F and DQ.
        let avx512 = avx().filter(|_| {
            is_x86_feature_detected!("avx512f") && is_x86_feature_detected!("avx512dq")
        });
        #[allow(unsafe_code)]
        // SAFETY: `with_avx512_unchecked` requires AVX-512 F and DQ, just detected.
        let avx512 = avx512.map(|c| unsafe { c.with_avx512_unchecked() });
        #[allow(unsafe_code)]
        // SAFETY: AVX-512 F has the fused multiply–adds (and FMA was detected).
        let avx512_fma = avx512
            .zip(fma)
            .map(|(c, _)| unsafe { c.with_fma_unchecked() });
        for (name, cpu) in [
            ("lanes-avx", avx()),
            ("lanes-fma", fma),
            ("lanes-avx512", avx512),
            ("lanes-avx512-fma", avx512_fma),
        ] {
            let Some(cpu) = cpu else { continue };
            g.bench_function(name, |b| {
                b.iter(|| {
                    let mut carry = 0.0;
                    lanes::fly_each_on(Some(cpu), black_box(&shots), &integrator, |_, r| {
                        if let Ok(o) = r {
                            carry += o.carry_m;
                        }
                    });
                    carry
                })
            });
        }
        g.finish();
    }
}

/// The AVX token where the CPU has AVX (the host's check, as `carry_io::lanes::cpu`).
#[allow(unsafe_code)]
fn avx() -> Option<lanes::Avx> {
    // SAFETY: `Avx::new_unchecked` requires AVX, which was just detected.
    is_x86_feature_detected!("avx").then(|| unsafe { lanes::Avx::new_unchecked() })
}

criterion_group!(benches, bench);
criterion_main!(benches);
