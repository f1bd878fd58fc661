//! How far the lanes kernel with FMA (`lanes::Avx::with_fma_unchecked`) moves results from
//! the scalar path's: `cargo run --release -p carry-core --example lanes_fma [SHOTS]
//! [avx512]` (default 1,000,000 shots a set; `avx512`: on the eight-lane AVX-512 packs, fused
//! and exact, rather than the four-lane AVX ones). Random launches (wedges to drivers, toppers, hooks and
//! slices) through random covered scenes (uniform winds, air, landing height, tee,
//! `tour2023`/`drives2026`), in chunks of 4,096 shots over 64 scenes: one set with the
//! default integrator, one with a random tolerance 1e-10..1e-2 a chunk (the property
//! test's spread). Prints, per set, the largest relative difference of each figure (against
//! `max(|scalar|, 1)`: 1 m, 1 s, 1 rad of scale, as `tests/tests/lanes.rs`), how many shots
//! differ by more than 1e-9, how many have other step counts (a step accepted on one path
//! and rejected on the other, or another step sequence), and how many results differ in
//! kind (error against flight). The exact AVX packs are checked bit for bit on the way.
//! Needs a CPU with AVX and FMA (docs/performance.md, "Lanes kernel").
use carry_core::aero::AeroModel;
use carry_core::lanes::{self, Avx, Shot};
use carry_core::units::{deg, rpm};
use carry_core::{
    Air, Ball, FlightOutcome, Integrator, Launch, PreparedScene, Result, Scene, Wind,
};
use nalgebra::Vector3;

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

const FIGURES: [&str; 7] = [
    "carry",
    "side",
    "apex",
    "apex time",
    "flight time",
    "landing angle",
    "landing speed",
];

fn figures(o: &FlightOutcome<f64>) -> [f64; 7] {
    [
        o.carry_m,
        o.side_m,
        o.apex_m,
        o.apex_time_s,
        o.flight_time_s,
        o.landing_angle_rad,
        o.landing_speed_mps,
    ]
}

fn scene(r: &mut Rng, ball: &Ball<f64>) -> Option<PreparedScene<f64>> {
    Scene {
        aero: if r.next() < 0.5 {
            AeroModel::default()
        } else {
            AeroModel::drives_2026()
        },
        wind: if r.next() < 0.2 {
            Wind::None
        } else {
            Wind::Uniform(Vector3::new(
                r.range(-20.0, 20.0),
                r.range(-2.0, 2.0),
                r.range(-20.0, 20.0),
            ))
        },
        air: Air::Density(r.range(0.9, 1.3)),
        landing_height_m: r.range(-5.0, 5.0),
        launch_position_m: Vector3::new(0.0, r.range(0.0, 0.05), 0.0),
        ..Scene::default()
    }
    .prepare(ball)
    .ok()
}

fn launch(r: &mut Rng) -> Option<carry_core::BallMotion<f64>> {
    let topped = r.next() < 0.1;
    Launch {
        ball_speed_mps: if topped {
            r.range(10.0, 50.0)
        } else {
            r.range(15.0, 95.0)
        },
        launch_angle_rad: deg(if topped {
            r.range(0.0, 4.0)
        } else {
            r.range(1.0, 55.0)
        }),
        launch_direction_rad: deg(r.range(-10.0, 10.0)),
        backspin_radps: rpm(if topped {
            r.range(0.0, 1500.0)
        } else {
            r.range(0.0, 11_000.0)
        }),
        sidespin_radps: rpm(r.range(-2500.0, 2500.0)),
    }
    .ball_motion()
    .ok()
}

fn fly(cpu: Avx, shots: &[Shot<'_, f64>], i: &Integrator<f64>) -> Vec<Result<FlightOutcome<f64>>> {
    let mut out: Vec<Option<Result<FlightOutcome<f64>>>> = vec![None; shots.len()];
    lanes::fly_each_on(Some(cpu), shots, i, |k, r| out[k] = Some(r));
    out.into_iter().flatten().collect()
}

fn main() {
    if !(is_x86_feature_detected!("avx") && is_x86_feature_detected!("fma")) {
        println!("this CPU lacks AVX or FMA");
        return;
    }
    #[allow(unsafe_code)]
    // SAFETY: AVX and FMA were just detected.
    let mut fma = unsafe { Avx::new_unchecked().with_fma_unchecked() };
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1_000_000);
    if std::env::args().nth(2).as_deref() == Some("avx512") {
        if !(is_x86_feature_detected!("avx512f") && is_x86_feature_detected!("avx512dq")) {
            println!("this CPU lacks AVX-512 F or DQ");
            return;
        }
        #[allow(unsafe_code)]
        {
            // SAFETY: AVX-512 F and DQ were just detected.
            fma = unsafe { fma.with_avx512_unchecked() };
        }
        println!("on the AVX-512 packs (eight lanes)");
    }
    let ball = Ball::standard();
    for (set, random_tolerance) in [
        ("default integrator", false),
        ("tolerance 1e-10..1e-2", true),
    ] {
        let mut r = Rng(if random_tolerance { 2 } else { 1 });
        let (mut flights, mut errors, mut over, mut restepped, mut kind) = (0, 0, 0, 0, 0);
        let mut worst = [0.0_f64; 7];
        let mut flown = 0;
        while flown < n {
            let scenes: Vec<PreparedScene<f64>> =
                (0..64).filter_map(|_| scene(&mut r, &ball)).collect();
            let shots: Vec<Shot<'_, f64>> = (0..4096.min(n - flown))
                .filter_map(|_| {
                    let s = &scenes[(r.next() * 64.0) as usize % scenes.len()];
                    launch(&mut r).map(|launch| Shot { scene: s, launch })
                })
                .collect();
            flown += 4096;
            let integrator = if random_tolerance {
                Integrator::dormand_prince(10f64.powf(r.range(-10.0, -2.0)))
            } else {
                Integrator::default()
            };
            let fused = fly(fma, &shots, &integrator);
            let exact = fly(fma.exact(), &shots, &integrator);
            for ((shot, f), e) in shots.iter().zip(&fused).zip(&exact) {
                let want = shot.scene.fly(&shot.launch, &integrator, None);
                assert_eq!(e, &want, "the exact AVX packs differ from the scalar path");
                match (f, &want) {
                    (Ok(a), Ok(b)) => {
                        flights += 1;
                        let mut beyond = false;
                        for (k, (x, y)) in figures(a).iter().zip(figures(b)).enumerate() {
                            let rel = (x - y).abs() / y.abs().max(1.0);
                            worst[k] = worst[k].max(rel);
                            beyond |= rel > 1e-9;
                        }
                        over += usize::from(beyond);
                        restepped += usize::from(a.stats != b.stats);
                    }
                    (Err(a), Err(b)) if a == b => errors += 1,
                    _ => {
                        kind += 1;
                        println!("differ in kind: {f:?} against {want:?}");
                    }
                }
            }
        }
        println!(
            "{set}: {flights} flights, {errors} errors alike, {kind} differ in kind, \
             {over} beyond 1e-9, {restepped} with other step counts"
        );
        for (name, w) in FIGURES.iter().zip(worst) {
            println!("  {name}: max relative difference {w:.2e}");
        }
    }
}
