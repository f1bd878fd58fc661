//! Golden flight cases (tests/golden/flight.json) through the public API, in f64 and f32.

use carry_core::units::{to_deg, to_rpm};
use carry_core::{Ball, Error, FlightOutcome, Integrator, Real, fly};
use carry_tests::golden_flight::{FlightCase, load};

fn run<T: Real>(case: &FlightCase, integrator: &Integrator<T>) -> Result<FlightOutcome<T>, Error> {
    let launch = case.launch.to_launch::<T>().ball_motion()?;
    fly(
        &Ball::standard(),
        &launch,
        &case.scene.to_scene::<T>(),
        integrator,
        None,
    )
}

fn f<T: Real>(x: T) -> f64 {
    carry_core::real::to_f64(x)
}

/// Largest |error| of carry, side and apex (m) over the golden set, and the total force
/// evaluations.
fn worst<T: Real>(integrator: &Integrator<T>) -> (f64, u64) {
    worst_of(integrator, |_| true)
}

fn worst_of<T: Real>(integrator: &Integrator<T>, pick: impl Fn(&FlightCase) -> bool) -> (f64, u64) {
    let mut worst = 0.0_f64;
    let mut evals = 0_u64;
    for case in load().into_iter().filter(|c| pick(c)) {
        let out = run(&case, integrator).unwrap_or_else(|e| panic!("{}: {e}", case.name));
        let e = &case.expected;
        for d in [
            f(out.carry_m) - e.carry_m,
            f(out.side_m) - e.side_m,
            f(out.apex_m) - e.apex_m,
        ] {
            worst = worst.max(d.abs());
        }
        evals += u64::from(out.stats.force_evaluations);
    }
    (worst, evals)
}

/// Prints the accuracy/cost table behind the default choice (docs/flight.md):
/// `cargo test -p carry-tests --release --test flight_golden sweep -- --ignored --nocapture`.
#[test]
#[ignore = "prints the tuning table"]
fn sweep() {
    let n = load().len() as f64;
    let prof = |c: &FlightCase| c.scene.wind_profile.is_some();
    for (name, i64, i32) in [
        ("default", Integrator::default(), Integrator::default()),
        ("seed   ", Integrator::seed(), Integrator::seed()),
    ] {
        let (w64, e64) = worst::<f64>(&i64);
        let (w32, e32) = worst::<f32>(&i32);
        let (_, en) = worst_of::<f64>(&i64, |c| !prof(c));
        println!(
            "{name}: f64 worst {w64:.3e} m ({:.1} evals/shot, {:.1} without the profile)  f32 worst {w32:.3e} m ({:.1})",
            e64 as f64 / n,
            en as f64 / (n - 1.0),
            e32 as f64 / n,
        );
    }
    for tol in [
        1e-3, 7e-4, 5e-4, 4e-4, 3e-4, 2e-4, 1e-4, 7e-5, 5e-5, 4e-5, 3e-5, 1e-5, 1e-6, 1e-7,
    ] {
        let (w64, e64) = worst::<f64>(&Integrator::dormand_prince(tol));
        let (w32, e32) = worst::<f32>(&Integrator::dormand_prince(tol as f32));
        let (wp, ep) = worst_of::<f64>(&Integrator::dormand_prince(tol), prof);
        let (wn, en) = worst_of::<f64>(&Integrator::dormand_prince(tol), |c| !prof(c));
        println!(
            "DP45 tol {tol:>7.0e}: f64 worst {w64:.3e} m ({:.1} evals/shot)  f32 worst {w32:.3e} m ({:.1}) | profile {wp:.2e} ({ep}) others {wn:.2e} ({:.1})",
            e64 as f64 / n,
            e32 as f64 / n,
            en as f64 / (n - 1.0)
        );
    }
    for tol in [1e-7, 1e-8, 1e-10, 1e-12] {
        let (w64, e64) = worst::<f64>(&Integrator::dormand_prince(tol));
        println!(
            "DP45 tol {tol:>7.0e}: f64 worst {w64:.3e} m ({:.1} evals/shot)",
            e64 as f64 / n
        );
    }
    for h in [0.2, 0.1, 0.05, 0.02, 0.01] {
        let (w, e) = worst::<f64>(&Integrator::Rk4 { step_s: h });
        println!(
            "RK4 h {h}: f64 worst {w:.3e} m ({:.1} evals/shot)",
            e as f64 / n
        );
    }
    for h in [1e-3, 1e-4] {
        let (w, e) = worst::<f64>(&Integrator::Euler { step_s: h });
        println!(
            "Euler h {h}: f64 worst {w:.3e} m ({:.1} evals/shot)",
            e as f64 / n
        );
    }
}

/// Tolerances of one comparison, in the file's units (m, s, deg, rpm, m/s).
struct Tol {
    /// Carry, carry along X and side (m).
    distance: f64,
    /// Apex height (m).
    apex: f64,
    /// Flight time (s).
    time: f64,
    /// Apex time (s).
    apex_time: f64,
    /// Landing angle (deg).
    angle: f64,
    /// Landing spin (rpm).
    spin: f64,
    /// Landing speed (m/s).
    speed: f64,
}

/// The reference's apex is a sampled maximum, not the located one: against the tightest
/// setting our apex is higher on *every* case (by ≤ 2.0e-6 m) and the apex times differ
/// by up to ±0.83 ms either way — a maximum over samples ~1–2 ms apart, which undershoots
/// the true apex by ½·|a_y|·Δt² ≈ 2e-6 m. Our apex is the root of v_y on the interpolant
/// (checked against dense samples in flight_properties). So apex height is compared to
/// 3e-6 m and apex time to 1 ms where the rest is compared at the integrator's level.
const REFERENCE_APEX_M: f64 = 3.0e-6;
/// See [`REFERENCE_APEX_M`].
const REFERENCE_APEX_TIME_S: f64 = 1.0e-3;

/// f64 at the default fidelity: the 1 mm for carry, side and apex (the sweep
/// shows ≤ 0.50 mm at the default fidelity, 2× margin); the rest scaled from the
/// observed errors (flight time 3.1e-5 s, landing angle 8.0e-4°, spin 0.018 rpm) with a
/// 2–6× margin.
const F64_DEFAULT: Tol = Tol {
    distance: 1.0e-3,
    apex: 1.0e-3,
    time: 2.0e-4,
    apex_time: REFERENCE_APEX_TIME_S,
    angle: 5.0e-3,
    spin: 0.05,
    speed: LANDING_SPEED_F64_M_S,
};

/// Landing speed at the default fidelities: the error test bounds the state per step,
/// and the landing velocity (the fastest-changing part of the state, read from the
/// landing step) carries more of it than the position (observed 1.5e-3 m/s in f64,
/// 8.3e-3 m/s in f32, both on the wind-profile case, whose (y/h_ref)^k has an unbounded
/// derivative at the ground where the ball lands). 2× margin.
const LANDING_SPEED_F64_M_S: f64 = 3.0e-3;
/// See [`LANDING_SPEED_F64_M_S`].
const LANDING_SPEED_F32_M_S: f64 = 2.0e-2;

/// f64 at `Integrator::tight()` (DP45 at 1e-12 against the reference's 8th order at
/// 1e-12): the 1e-6 m for carry and side (observed ≤ 3e-9 m); apex limited by
/// the reference (see [`REFERENCE_APEX_M`]); the rest at the integrator's level.
const F64_TIGHT: Tol = Tol {
    distance: 1.0e-6,
    apex: REFERENCE_APEX_M,
    time: 1.0e-9,
    apex_time: REFERENCE_APEX_TIME_S,
    angle: 1.0e-8,
    spin: 1.0e-6,
    speed: 1.0e-8,
};

/// f32 at its default fidelity: the 1 cm (observed ≤ 4.1 mm); f32 itself
/// resolves ~2e-5 m at 250 m and the looser f32 tolerance sets the rest (observed: apex
/// 1.8 mm, flight time 2.5e-4 s, landing angle 5.6e-3°, spin 0.21 rpm).
const F32_DEFAULT: Tol = Tol {
    distance: 1.0e-2,
    apex: 1.0e-2,
    time: 1.0e-3,
    apex_time: REFERENCE_APEX_TIME_S * 2.0,
    angle: 2.0e-2,
    spin: 0.5,
    speed: LANDING_SPEED_F32_M_S,
};

fn check<T: Real>(integrator: &Integrator<T>, tol: &Tol) {
    for case in load() {
        let out = run(&case, integrator).unwrap_or_else(|e| panic!("{}: {e}", case.name));
        let e = &case.expected;
        let checks = [
            ("carry", f(out.carry_m), e.carry_m, tol.distance),
            ("carry_x", f(out.carry_x_m), e.carry_x_m, tol.distance),
            ("side", f(out.side_m), e.side_m, tol.distance),
            ("apex", f(out.apex_m), e.apex_m, tol.apex),
            (
                "flight time",
                f(out.flight_time_s),
                e.flight_time_s,
                tol.time,
            ),
            (
                "apex time",
                f(out.apex_time_s),
                e.apex_time_s,
                tol.apex_time,
            ),
            (
                "landing angle",
                f(to_deg(out.landing_angle_rad)),
                e.land_angle_deg,
                tol.angle,
            ),
            (
                "landing spin",
                f(to_rpm(out.landing_spin_radps)),
                e.land_spin_rpm,
                tol.spin,
            ),
            (
                "landing speed",
                f(out.landing_speed_mps),
                e.land_speed_mps,
                tol.speed,
            ),
            // Density: the formula in the working precision (relative 1e-6 covers f32).
            (
                "air density",
                f(out.air_density_kgm3),
                e.air_density_kgm3,
                1.0e-6,
            ),
        ];
        for (what, got, want, t) in checks {
            assert!(
                (got - want).abs() <= t,
                "{}: {what} {got} vs {want} (|Δ| {:.3e} > {t:e})",
                case.name,
                (got - want).abs()
            );
        }
    }
}

#[test]
fn golden_f64_default_fidelity() {
    check::<f64>(&Integrator::default(), &F64_DEFAULT);
}

#[test]
fn golden_f64_tight() {
    check::<f64>(&Integrator::tight(), &F64_TIGHT);
}

#[test]
fn golden_f32_default_fidelity() {
    check::<f32>(&Integrator::default(), &F32_DEFAULT);
}

#[test]
#[ignore = "prints per-case errors"]
fn per_case() {
    for tol in [1e-4, 1e-6] {
        for case in load() {
            let e = &case.expected;
            let o = run::<f64>(&case, &Integrator::dormand_prince(tol));
            let o32 = run::<f32>(&case, &Integrator::dormand_prince(tol as f32));
            match (o, o32) {
                (Ok(o), Ok(o32)) => println!(
                    "{tol:e} {:>32} carry {:+.2e} side {:+.2e} apex {:+.2e} t {:+.2e} evals {} rej {} | f32 carry {:+.2e} apex {:+.2e} evals {}",
                    case.name,
                    o.carry_m - e.carry_m,
                    o.side_m - e.side_m,
                    o.apex_m - e.apex_m,
                    o.flight_time_s - e.flight_time_s,
                    o.stats.force_evaluations,
                    o.stats.rejected_steps,
                    f(o32.carry_m) - e.carry_m,
                    f(o32.apex_m) - e.apex_m,
                    o32.stats.force_evaluations
                ),
                (a, b) => println!("{tol:e} {:>32} {:?} {:?}", case.name, a.err(), b.err()),
            }
        }
    }
}

#[test]
#[ignore = "profile experiments"]
fn profile_experiment() {
    let case = load()
        .into_iter()
        .find(|c| c.name.contains("profile"))
        .unwrap();
    for tol in [1e-4, 1e-5, 1e-6] {
        for h0 in [0.1, 1e-2, 1e-3, 1e-4, 1e-6] {
            let i = Integrator::DormandPrince {
                rtol: tol,
                atol: tol,
                initial_step_s: h0,
                max_step_s: 1.0,
            };
            let o = run::<f64>(&case, &i).unwrap();
            println!(
                "tol {tol:e} h0 {h0:e}: carry err {:+.3e} evals {} rej {}",
                o.carry_m - case.expected.carry_m,
                o.stats.force_evaluations,
                o.stats.rejected_steps
            );
        }
    }
    for h in [0.1, 0.05, 0.02, 0.01, 0.005] {
        let o = run::<f64>(&case, &Integrator::Rk4 { step_s: h }).unwrap();
        println!(
            "rk4 {h}: carry err {:+.3e} evals {}",
            o.carry_m - case.expected.carry_m,
            o.stats.force_evaluations
        );
    }
}

#[test]
#[ignore = "prints tight f64 errors"]
fn tight_per_case() {
    for case in load() {
        let e = &case.expected;
        let o = run::<f64>(&case, &Integrator::tight()).unwrap();
        println!(
            "{:>32} carry {:+.2e} side {:+.2e} apex {:+.2e} t {:+.2e} ta {:+.2e} ang {:+.2e} spin {:+.2e} v {:+.2e}",
            case.name,
            o.carry_m - e.carry_m,
            o.side_m - e.side_m,
            o.apex_m - e.apex_m,
            o.flight_time_s - e.flight_time_s,
            o.apex_time_s - e.apex_time_s,
            to_deg(o.landing_angle_rad) - e.land_angle_deg,
            to_rpm(o.landing_spin_radps) - e.land_spin_rpm,
            o.landing_speed_mps - e.land_speed_mps
        );
    }
}

/// Force evaluations of the benchmark's ladder shot (TrackMan tour driver, 1° right,
/// −300 rpm sidespin) on each rung, for docs/flight.md.
#[test]
#[ignore = "prints the ladder's evaluation counts"]
fn ladder_counts() {
    use carry_core::scene::effect_ladder;
    use carry_core::units::{deg, rpm};
    use carry_core::{Launch, Scene};
    let m = Launch {
        ball_speed_mps: 74.65568,
        launch_angle_rad: deg(10.9),
        launch_direction_rad: deg(1.0),
        backspin_radps: rpm(2686.0),
        sidespin_radps: rpm(-300.0),
    }
    .ball_motion()
    .unwrap();
    let ladder32 = effect_ladder::<f32>();
    for ((name, s), (_, s32)) in effect_ladder::<f64>().into_iter().zip(ladder32) {
        for (iname, i) in [
            ("rk4 0.05", Integrator::Rk4 { step_s: 0.05 }),
            ("default f64", Integrator::default()),
            ("tight", Integrator::tight()),
        ] {
            let o = fly(&Ball::standard(), &m, &s, &i, None).unwrap();
            print!(
                "{name} {iname}: {} evals ({} rej) carry {:.4} | ",
                o.stats.force_evaluations, o.stats.rejected_steps, o.carry_m
            );
        }
        let m32 = carry_core::BallMotion {
            velocity_mps: m.velocity_mps.cast::<f32>(),
            spin_radps: m.spin_radps.cast::<f32>(),
        };
        let o = fly(
            &Ball::<f32>::standard(),
            &m32,
            &s32,
            &Integrator::default(),
            None,
        )
        .unwrap();
        println!(
            "f32 default: {} evals carry {:.4}",
            o.stats.force_evaluations, o.carry_m
        );
    }
    for (name, i) in [
        ("euler 1e-3", Integrator::Euler { step_s: 1e-3 }),
        ("rk4 0.02", Integrator::Rk4 { step_s: 0.02 }),
    ] {
        let o = fly(&Ball::standard(), &m, &Scene::default(), &i, None).unwrap();
        println!(
            "{name}: {} evals carry {:.4}",
            o.stats.force_evaluations, o.carry_m
        );
    }
}

/// Largest deviation per quantity at the default fidelities (the figures behind the
/// tolerances above).
#[test]
#[ignore = "prints the largest deviations"]
fn max_deviations() {
    fn show<T: Real>(label: &str, integrator: &Integrator<T>) {
        let mut m = [0.0_f64; 6];
        for case in load() {
            let o = run(&case, integrator).unwrap();
            let e = &case.expected;
            let d = [
                (f(o.carry_m) - e.carry_m)
                    .abs()
                    .max((f(o.side_m) - e.side_m).abs()),
                (f(o.apex_m) - e.apex_m).abs(),
                (f(o.flight_time_s) - e.flight_time_s).abs(),
                (f(to_deg(o.landing_angle_rad)) - e.land_angle_deg).abs(),
                (f(to_rpm(o.landing_spin_radps)) - e.land_spin_rpm).abs(),
                (f(o.landing_speed_mps) - e.land_speed_mps).abs(),
            ];
            for (a, b) in m.iter_mut().zip(d) {
                *a = a.max(b);
            }
        }
        println!(
            "{label}: carry/side {:.2e} apex {:.2e} time {:.2e} angle {:.2e} spin {:.2e} speed {:.2e}",
            m[0], m[1], m[2], m[3], m[4], m[5]
        );
    }
    show::<f64>("f64 default", &Integrator::default());
    show::<f64>("f64 tight", &Integrator::tight());
    show::<f32>("f32 default", &Integrator::default());
}

/// Worst |error| over the golden set of each field the default-fidelity test checks
/// (carry, carry along X, side, apex, flight time, apex time, landing angle, spin, speed).
fn worst_fields<T: Real>(integrator: &Integrator<T>) -> ([f64; 9], u64) {
    let mut w = [0.0_f64; 9];
    let mut evals = 0_u64;
    for case in load() {
        let out = run(&case, integrator).unwrap_or_else(|e| panic!("{}: {e}", case.name));
        let e = &case.expected;
        let d = [
            f(out.carry_m) - e.carry_m,
            f(out.carry_x_m) - e.carry_x_m,
            f(out.side_m) - e.side_m,
            f(out.apex_m) - e.apex_m,
            f(out.flight_time_s) - e.flight_time_s,
            f(out.apex_time_s) - e.apex_time_s,
            f(to_deg(out.landing_angle_rad)) - e.land_angle_deg,
            f(to_rpm(out.landing_spin_radps)) - e.land_spin_rpm,
            f(out.landing_speed_mps) - e.land_speed_mps,
        ];
        for (w, d) in w.iter_mut().zip(d) {
            *w = w.max(d.abs());
        }
        evals += u64::from(out.stats.force_evaluations);
    }
    (w, evals)
}

/// The f64 default fidelity's tolerance against the golden set's checks, with the first
/// step by the default's rule `3.5 s·tol^(1/5)` (docs/flight.md, *Default integrator*):
/// `cargo test -p carry-tests --release --test flight_golden default_tolerance -- --ignored --nocapture`.
#[test]
#[ignore = "prints the default tolerance's table"]
fn default_tolerance() {
    let n = load().len() as f64;
    let limits = [
        F64_DEFAULT.distance,
        F64_DEFAULT.distance,
        F64_DEFAULT.distance,
        F64_DEFAULT.apex,
        F64_DEFAULT.time,
        F64_DEFAULT.apex_time,
        F64_DEFAULT.angle,
        F64_DEFAULT.spin,
        F64_DEFAULT.speed,
    ];
    println!(
        "tol      first  evals | carry    carry_x  side     apex     time     apex_t   angle    spin     speed  (worst / limit)"
    );
    let list = |k: &str, d: &str| -> Vec<f64> {
        std::env::var(k)
            .unwrap_or_else(|_| d.into())
            .split(',')
            .filter_map(|x| x.parse().ok())
            .collect()
    };
    for atol in list("ATOL", "0") {
        for tol in list("RTOL", "4e-5,5e-5,6e-5,7e-5,8e-5,9e-5,1e-4,1.2e-4,1.5e-4") {
            let atol = if atol > 0.0 { atol } else { tol };
            let first = (carry_core::integrator::INITIAL_STEP_SCALE_S * tol.powf(0.2) * 100.0)
                .round()
                / 100.0;
            print!("atol {atol:.1e} ");
            let i = Integrator::DormandPrince {
                rtol: tol,
                atol,
                initial_step_s: first,
                max_step_s: f64::MAX,
            };
            let (w, e) = worst_fields::<f64>(&i);
            let cells: Vec<String> = w
                .iter()
                .zip(limits)
                .map(|(w, l)| format!("{:.2}", w / l))
                .collect();
            println!(
                "{tol:.1e} {first:.2} s {:5.1} | {}",
                e as f64 / n,
                cells.join("     ")
            );
        }
    }
}
