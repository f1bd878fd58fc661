//! The figures of docs/estimate.md: the estimator (issue 23) on synthetic amateur drives.
//!
//! Deliveries are drawn like amateur TrackMan drives (club path sd 4.6°, attack sd 3.4°,
//! the spreads the issue's trivial rules imply; face-to-path sd 3°; dynamic loft, strike
//! location and club speed spread as in docs/estimate.md), launched with the default model
//! (driver preset, TrackMan's convention), measured with the default launch-monitor noise,
//! and estimated back from the ball data and the club speed. Prints the mean |error| per
//! datum against the issue's limits and trivial rules, the iterations used, and accuracy
//! against cost (tolerance, iteration budget, f32 against f64).
//!
//! ```sh
//! cargo run --release -p carry-lab --example estimate_report
//! ```

use carry_core::estimate::{BallData, ClubData, Posterior, Settings, Unknowns, estimate, predict};
use carry_core::real::{lit, to_f64};
use carry_core::{Ball, PRESETS, Real};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, Normal};
use rayon::prelude::*;

/// One synthetic shot: the truth and what the launch monitor saw.
struct Shot {
    truth: Unknowns<f64>,
    measured: BallData<f64>,
    club_speed_mps: f64,
}

fn shots(n: usize, seed: u64) -> Vec<Shot> {
    let p = &PRESETS[0];
    let club = p.spec::<f64>().validate().expect("driver");
    let ball = Ball::standard();
    let noise = Settings::<f64>::typical(&p.typical).noise;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let z = Normal::<f64>::new(0.0, 1.0).expect("normal");
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let mut g = || -> f64 { z.sample(&mut rng) };
        let path = 4.6 * g();
        let face = path + 3.0 * g();
        let truth = Unknowns {
            face_angle_rad: face.to_radians(),
            club_path_rad: path.to_radians(),
            dynamic_loft_rad: (13.5 + 3.0 * g()).to_radians(),
            attack_angle_rad: (-1.5 + 3.4 * g()).to_radians(),
            impact_toe_m: 0.012 * g(),
            impact_height_m: 0.003 + 0.008 * g(),
            club_speed_mps: 42.0 + 4.0 * g(),
        };
        let Ok(y) = predict(&club, &ball, &truth) else {
            continue;
        };
        let s = noise.ball.to_array();
        let y = y.to_array();
        let measured = BallData::from_array(core::array::from_fn(|i| y[i] + s[i] * g()));
        if measured.validated().is_err() {
            continue;
        }
        let club_speed_mps = truth.club_speed_mps + noise.club.club_speed_mps * g();
        out.push(Shot {
            truth,
            measured,
            club_speed_mps,
        });
    }
    out
}

/// Mean |error| (deg) of face, path, loft, attack; mean and max iterations; failures.
struct Score {
    /// Share of the shots that took at most k iterations, k = 1..=8.
    within: [f64; 8],
    mae: [f64; 4],
    strike_mm: [f64; 2],
    iterations: (f64, u8),
    failed: usize,
}

fn score<T: Real + Send + Sync>(shots: &[Shot], tolerance: f64, budget: u8) -> Score {
    score_with::<T>(shots, tolerance, budget, Posterior::Profile)
}

fn score_with<T: Real + Send + Sync>(
    shots: &[Shot],
    tolerance: f64,
    budget: u8,
    posterior: Posterior,
) -> Score {
    let p = &PRESETS[0];
    let club = p.spec::<T>().validate().expect("driver");
    let ball = Ball::<T>::standard();
    let mut settings = Settings::<T>::typical(&p.typical);
    settings.tolerance = lit(tolerance);
    settings.max_iterations = budget;
    settings.posterior = posterior;
    let results: Vec<_> = shots
        .par_iter()
        .map(|s| {
            let y = BallData::from_array(s.measured.to_array().map(lit::<T>));
            let c = ClubData {
                club_speed_mps: Some(lit(s.club_speed_mps)),
                ..ClubData::default()
            };
            estimate(&club, &ball, &y, &c, &settings).ok().map(|e| {
                let v = e.value;
                let t = &s.truth;
                (
                    [
                        (to_f64(v.face_angle_rad) - t.face_angle_rad)
                            .to_degrees()
                            .abs(),
                        (to_f64(v.club_path_rad) - t.club_path_rad)
                            .to_degrees()
                            .abs(),
                        (to_f64(v.dynamic_loft_rad) - t.dynamic_loft_rad)
                            .to_degrees()
                            .abs(),
                        (to_f64(v.attack_angle_rad) - t.attack_angle_rad)
                            .to_degrees()
                            .abs(),
                    ],
                    [
                        1e3 * (to_f64(v.impact_toe_m) - t.impact_toe_m).abs(),
                        1e3 * (to_f64(v.impact_height_m) - t.impact_height_m).abs(),
                    ],
                    e.iterations,
                )
            })
        })
        .collect();
    let ok: Vec<_> = results.iter().flatten().collect();
    let n = ok.len().max(1) as f64;
    let mut mae = [0.0; 4];
    let mut strike = [0.0; 2];
    let mut it_sum = 0.0;
    let mut it_max = 0;
    let mut within = [0.0; 8];
    for (e, s, it) in &ok {
        for (k, w) in within.iter_mut().enumerate() {
            if usize::from(*it) <= k + 1 {
                *w += 1.0 / results.len() as f64;
            }
        }
        for (m, v) in mae.iter_mut().zip(e) {
            *m += v / n;
        }
        for (m, v) in strike.iter_mut().zip(s) {
            *m += v / n;
        }
        it_sum += f64::from(*it) / n;
        it_max = it_max.max(*it);
    }
    Score {
        within,
        mae,
        strike_mm: strike,
        iterations: (it_sum, it_max),
        failed: results.len() - ok.len(),
    }
}

fn trivial(shots: &[Shot]) -> [f64; 4] {
    let n = shots.len() as f64;
    let mean_path = shots.iter().map(|s| s.truth.club_path_rad).sum::<f64>() / n;
    let mean_attack = shots.iter().map(|s| s.truth.attack_angle_rad).sum::<f64>() / n;
    let mut e = [0.0; 4];
    for s in shots {
        let t = &s.truth;
        let m = &s.measured;
        e[0] += (m.launch_direction_rad - t.face_angle_rad)
            .to_degrees()
            .abs()
            / n;
        e[1] += (mean_path - t.club_path_rad).to_degrees().abs() / n;
        e[2] += (m.launch_angle_rad.to_degrees() + 2.7 - t.dynamic_loft_rad.to_degrees()).abs() / n;
        e[3] += (mean_attack - t.attack_angle_rad).to_degrees().abs() / n;
    }
    e
}

fn main() {
    let n = 4000;
    let shots = shots(n, 23);
    println!("# synthetic amateur drives: {n} shots, seed 23\n");
    let t = trivial(&shots);
    let defaults = Settings::<f64>::typical(&PRESETS[0].typical);
    let s = score::<f64>(&shots, defaults.tolerance, defaults.max_iterations);
    let limits = [0.45, 1.6, 1.0, 2.0];
    let issue_trivial = [0.83, 3.65, 1.37, 2.75];
    let names = ["face angle", "club path", "dynamic loft", "attack angle"];
    println!(
        "| datum | estimate (f64) | issue limit | trivial rule here | trivial rule on TrackMan shots (issue) |"
    );
    println!("|---|---:|---:|---:|---:|");
    for i in 0..4 {
        println!(
            "| {} | {:.2}° | {:.2}° | {:.2}° | {:.2}° |",
            names[i], s.mae[i], limits[i], t[i], issue_trivial[i]
        );
    }
    println!(
        "\nstrike: toe {:.1} mm, height {:.1} mm mean |error|; iterations mean {:.2}, max {}; failures {}",
        s.strike_mm[0], s.strike_mm[1], s.iterations.0, s.iterations.1, s.failed
    );
    let f32s = score::<f32>(&shots, defaults.tolerance, defaults.max_iterations);
    println!("\nshare of shots done within k iterations (default settings):\n");
    println!("| k | 1 | 2 | 3 | 4 | 5 | 6 | 7 | 8 |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    for (label, sc) in [("f64", &s), ("f32", &f32s)] {
        let cells: Vec<String> = sc
            .within
            .iter()
            .map(|w| format!("{:.1} %", 100.0 * w))
            .collect();
        println!("| {label} | {} |", cells.join(" | "));
    }
    println!("\n## accuracy against cost\n");
    println!(
        "| precision | tolerance (σ) | budget | face | path | loft | attack | toe mm | height mm | mean it | max it | failed |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for (tol, budget) in [
        (1.0, 30),
        (0.3, 30),
        (0.1, 30),
        (0.03, 30),
        (0.1, 5),
        (0.1, 10),
    ] {
        for (label, sc) in [
            ("f64", score::<f64>(&shots, tol, budget)),
            ("f32", score::<f32>(&shots, tol, budget)),
            (
                "f64 Laplace (MAP)",
                score_with::<f64>(&shots, tol, budget, Posterior::Laplace),
            ),
        ] {
            println!(
                "| {label} | {tol} | {budget} | {:.3} | {:.3} | {:.3} | {:.3} | {:.2} | {:.2} | {:.2} | {} | {} |",
                sc.mae[0],
                sc.mae[1],
                sc.mae[2],
                sc.mae[3],
                sc.strike_mm[0],
                sc.strike_mm[1],
                sc.iterations.0,
                sc.iterations.1,
                sc.failed
            );
        }
    }
}
