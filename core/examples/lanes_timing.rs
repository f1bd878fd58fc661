//! Quick timing of the lanes kernel against the scalar path (medians of repeated runs over
//! 1,024 launches, one thread): `cargo run --release -p carry-core --example lanes_timing`,
//! optionally with one path's name (`scalar`, `avx`, `fma` (AVX and FMA), `avx512`,
//! `avx512fma` (eight lanes a register, exact and fused), `lanes`, or in `f32`: `scalar32`,
//! `avx32`, `avx512_32` (sixteen lanes a register), `lanes32`) and
//! a number of passes. The criterion bench (`--bench lanes`) is the reference; this is for
//! profiling.
use carry_core::lanes::{self, Shot};
use carry_core::units::{deg, rpm};
use carry_core::{Ball, Integrator, Launch, Scene};
use std::time::Instant;

fn main() {
    let Ok(scene) = Scene::<f64>::default().prepare(&Ball::standard()) else {
        return;
    };
    let mut state: u64 = 0x2545_F491_4F6C_DD1D;
    let mut next = |lo: f64, hi: f64| {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        lo + (hi - lo) * ((state >> 11) as f64 / (1u64 << 53) as f64)
    };
    let shots: Vec<Shot<'_, f64>> = (0..1024)
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
            .map(|launch| Shot {
                scene: &scene,
                launch,
            })
        })
        .collect();
    let integrator = Integrator::default();
    let (mut evals, mut steps, mut n) = (0u64, 0u64, 0u64);
    for s in &shots {
        if let Ok(o) = s.scene.fly(&s.launch, &integrator, None) {
            evals += u64::from(o.stats.force_evaluations);
            steps += u64::from(o.stats.steps + o.stats.rejected_steps);
            n += 1;
        }
    }
    println!(
        "mean per flight: {:.1} force evaluations, {:.1} steps",
        evals as f64 / n as f64,
        steps as f64 / n as f64
    );
    let only = std::env::args().nth(1);
    // Passes (15 unless a second argument says; many passes make the process's CPU time,
    // `/usr/bin/time -f %U`, a measure that a loaded machine's waits do not inflate).
    let runs = std::env::args()
        .nth(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(15);
    let time = |name: &str, f: &dyn Fn() -> f64| {
        if only.as_deref().is_some_and(|o| o != name) {
            return;
        }
        let mut t: Vec<f64> = (0..runs)
            .map(|_| {
                let s = Instant::now();
                std::hint::black_box(f());
                s.elapsed().as_secs_f64() / shots.len() as f64 * 1e6
            })
            .collect();
        t.sort_by(f64::total_cmp);
        println!(
            "{name}: median {:.3} us/shot (fastest pass {:.3})",
            t[runs / 2],
            t[0]
        );
    };
    time("scalar", &|| {
        shots
            .iter()
            .filter_map(|s| s.scene.fly(&s.launch, &integrator, None).ok())
            .map(|o| o.carry_m)
            .sum()
    });
    // The host's check (as `carry_io::lanes`): AVX packs where the CPU has them.
    #[allow(unsafe_code)]
    // SAFETY: `Avx::new_unchecked` requires AVX, which was just detected.
    let cpu = is_x86_feature_detected!("avx").then(|| unsafe { lanes::Avx::new_unchecked() });
    time("avx", &|| {
        let mut c = 0.0;
        lanes::fly_each_on(cpu, &shots, &integrator, |_, r| {
            c += r.map_or(0.0, |o| o.carry_m)
        });
        c
    });
    // AVX with FMA where the CPU has it (`carry_io::lanes::cpu`'s choice).
    #[allow(unsafe_code)]
    // SAFETY: `with_fma_unchecked` requires FMA, which was just detected.
    let fma = cpu
        .filter(|_| is_x86_feature_detected!("fma"))
        .map(|c| unsafe { c.with_fma_unchecked() });
    time("fma", &|| {
        let mut c = 0.0;
        lanes::fly_each_on(fma, &shots, &integrator, |_, r| {
            c += r.map_or(0.0, |o| o.carry_m)
        });
        c
    });
    // AVX-512 (eight `f64` lanes a register), exact and fused, where the CPU has it.
    #[allow(unsafe_code)]
    // SAFETY: `with_avx512_unchecked` requires AVX-512 F and DQ, which were just detected.
    let avx512 = cpu
        .filter(|_| is_x86_feature_detected!("avx512f") && is_x86_feature_detected!("avx512dq"))
        .map(|c| unsafe { c.with_avx512_unchecked() });
    #[allow(unsafe_code)]
    // SAFETY: FMA was detected (and AVX-512 F has the fused multiply–adds).
    let avx512_fma = avx512
        .filter(|_| fma.is_some())
        .map(|c| unsafe { c.with_fma_unchecked() });
    for (name, cpu) in [("avx512", avx512), ("avx512fma", avx512_fma)] {
        let Some(cpu) = cpu else { continue };
        time(name, &|| {
            let mut c = 0.0;
            lanes::fly_each_on(Some(cpu), &shots, &integrator, |_, r| {
                c += r.map_or(0.0, |o| o.carry_m)
            });
            c
        });
    }
    time("lanes", &|| {
        let mut c = 0.0;
        lanes::fly_each(&shots, &integrator, |_, r| {
            c += r.map_or(0.0, |o| o.carry_m)
        });
        c
    });
    // The same launches in `f32` (AVX: eight lanes a register).
    let Ok(scene32) = Scene::<f32>::default().prepare(&Ball::standard()) else {
        return;
    };
    let shots32: Vec<Shot<'_, f32>> = shots
        .iter()
        .filter_map(|s| {
            let m = s.launch;
            carry_core::BallMotion::<f32> {
                velocity_mps: m.velocity_mps.map(|x| x as f32),
                spin_radps: m.spin_radps.map(|x| x as f32),
            }
            .validated()
            .ok()
            .map(|launch| Shot {
                scene: &scene32,
                launch,
            })
        })
        .collect();
    let integrator32 = Integrator::<f32>::default();
    time("scalar32", &|| {
        shots32
            .iter()
            .filter_map(|s| s.scene.fly(&s.launch, &integrator32, None).ok())
            .map(|o| f64::from(o.carry_m))
            .sum()
    });
    time("avx32", &|| {
        let mut c = 0.0;
        lanes::fly_each_on(cpu, &shots32, &integrator32, |_, r| {
            c += r.map_or(0.0, |o| f64::from(o.carry_m))
        });
        c
    });
    time("avx512_32", &|| {
        let mut c = 0.0;
        lanes::fly_each_on(avx512, &shots32, &integrator32, |_, r| {
            c += r.map_or(0.0, |o| f64::from(o.carry_m))
        });
        c
    });
    time("lanes32", &|| {
        let mut c = 0.0;
        lanes::fly_each(&shots32, &integrator32, |_, r| {
            c += r.map_or(0.0, |o| f64::from(o.carry_m))
        });
        c
    });
}
