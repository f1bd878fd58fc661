//! The adaptive integrator's first trial step over a spread of shots (docs/flight.md):
//! accepted and rejected steps, force evaluations, and the carry's and total's distance
//! from a tight f64 reference, in f32 and f64 at their default tolerances.
//!
//! `cargo run --release -p carry-core --example initial_step [STEP_S ...]`
use carry_core::ground::{Ground, Surface};
use carry_core::impact::{self, Solver};
use carry_core::units::{deg, rpm};
use carry_core::{
    Ball, BallMotion, ClubSpec, ContactLaw, Delivery, FaceLocation, Integrator, Launch, Real,
    Scene, Wind, fly,
};
use nalgebra::{Matrix3, Vector3};

/// A shot: name, ball speed (mph), launch angle (°), backspin (rpm), sidespin (rpm),
/// wind (m/s, G), with a firm fairway.
type Shot = (&'static str, f64, f64, f64, f64, [f64; 3], bool);

const SHOTS: [Shot; 19] = [
    ("M4F reference shot", 0.0, 0.0, 0.0, 0.0, [0.0; 3], false),
    ("M4F everyday shot", 0.0, 0.0, 0.0, 0.0, [0.0; 3], false),
    (
        "M4F reference + fairway",
        0.0,
        0.0,
        0.0,
        0.0,
        [0.0; 3],
        true,
    ),
    ("driver 171mph", 171.0, 10.4, 2545.0, 0.0, [0.0; 3], false),
    (
        "driver 45m/s default",
        147.4,
        8.7,
        2258.0,
        0.0,
        [0.0; 3],
        false,
    ),
    ("driver low spin", 160.0, 12.0, 1400.0, 0.0, [0.0; 3], false),
    ("driver slice", 140.0, 11.0, 3000.0, 900.0, [0.0; 3], false),
    (
        "amateur driver",
        120.0,
        14.0,
        3200.0,
        -400.0,
        [0.0; 3],
        false,
    ),
    ("3-wood", 158.0, 9.3, 3663.0, 0.0, [0.0; 3], false),
    ("7-iron", 123.0, 16.1, 7124.0, 0.0, [0.0; 3], false),
    ("pitching wedge", 104.0, 23.7, 9316.0, 0.0, [0.0; 3], false),
    ("lob wedge 60 yd", 60.0, 32.0, 7000.0, 0.0, [0.0; 3], false),
    (
        "driver headwind",
        150.0,
        11.0,
        2600.0,
        0.0,
        [-8.0, 0.0, 0.0],
        false,
    ),
    (
        "driver tailwind",
        150.0,
        11.0,
        2600.0,
        0.0,
        [6.0, 0.0, 0.0],
        false,
    ),
    (
        "7-iron crosswind",
        123.0,
        16.1,
        7124.0,
        0.0,
        [0.0, 0.0, 7.0],
        false,
    ),
    ("driver + fairway", 147.4, 8.7, 2258.0, 0.0, [0.0; 3], true),
    ("7-iron + fairway", 123.0, 16.1, 7124.0, 0.0, [0.0; 3], true),
    (
        "topped 0.5° + fairway",
        110.0,
        0.5,
        2500.0,
        0.0,
        [0.0; 3],
        true,
    ),
    (
        "topped 3° + fairway",
        120.0,
        3.0,
        3500.0,
        0.0,
        [0.0; 3],
        true,
    ),
];

struct Run {
    carry: f64,
    total: f64,
    steps: u32,
    rejected: u32,
    evals: u32,
}

/// The firmware's cost-table driver shots (firmware/src/shot.rs, src/bin/cost.rs): the
/// reference delivery (45 m/s, square, centred) or the everyday one, launched by the
/// reduced impact solver in the precision `T`, as on the M4F.
fn firmware_launch<T: Real>(everyday: bool) -> BallMotion<T> {
    let c = |x: f64| carry_core::real::lit::<T>(x);
    let spec = ClubSpec {
        mass_kg: c(0.2),
        inertia_kgm2: Matrix3::from_diagonal(&Vector3::new(c(3.0e-4), c(4.2e-4), c(2.2e-4))),
        loft_rad: deg(c(10.5)),
        roll_radius_m: c(0.3),
        bulge_radius_m: c(0.3),
        face_depth_radius_m: Some(c(0.3)),
        cg_to_face_m: Vector3::new(c(0.04), T::zero(), T::zero()),
        restitution: c(0.83),
        contact: ContactLaw::Rolling,
        spin_axis_share: T::one(),
    };
    let mut d = Delivery {
        club_speed_mps: c(45.0),
        attack_angle_rad: T::zero(),
        club_path_rad: T::zero(),
        face_angle_rad: T::zero(),
        dynamic_loft_rad: deg(c(10.5)),
        lie_rad: T::zero(),
        club_spin_radps: Vector3::zeros(),
        location: FaceLocation {
            height_m: T::zero(),
            toe_m: T::zero(),
        },
    };
    if everyday {
        d.attack_angle_rad = deg(c(-1.5));
        d.club_path_rad = deg(c(2.5));
        d.face_angle_rad = deg(c(1.2));
        d.dynamic_loft_rad = deg(c(12.0));
        d.lie_rad = deg(c(-0.8));
        d.location.toe_m = c(0.008);
        d.location.height_m = c(0.004);
    }
    let club = spec.validate().expect("club");
    let strike = d.strike(&club).expect("strike");
    impact::solve(&club, &Ball::standard(), &strike, Solver::Reduced)
        .expect("impact")
        .ball
}

fn run<T: Real>(s: &Shot, integrator: &Integrator<T>) -> Run {
    let (name, v, l, back, side, w, ground) = *s;
    let c = |x: f64| carry_core::real::lit::<T>(x);
    let m = match name {
        "M4F reference shot" | "M4F reference + fairway" => firmware_launch(false),
        "M4F everyday shot" => firmware_launch(true),
        _ => Launch {
            ball_speed_mps: c(v * 0.44704),
            launch_angle_rad: deg(c(l)),
            launch_direction_rad: T::zero(),
            backspin_radps: rpm(c(back)),
            sidespin_radps: rpm(c(side)),
        }
        .ball_motion()
        .expect("launch"),
    };
    let scene = Scene {
        wind: if w == [0.0; 3] {
            Wind::None
        } else {
            Wind::Uniform(Vector3::new(c(w[0]), c(w[1]), c(w[2])))
        },
        ground: ground.then(|| Ground::level(Surface::FairwayFirm)),
        ..Scene::default()
    };
    let o = fly(&Ball::<T>::standard(), &m, &scene, integrator, None).expect("flight");
    let f = carry_core::real::to_f64::<T>;
    Run {
        carry: f(o.carry_m),
        total: o.ground.map_or(f64::NAN, |g| f(g.total_m)),
        steps: o.stats.steps,
        rejected: o.stats.rejected_steps,
        evals: o.stats.force_evaluations,
    }
}

/// The default integrator (or DP5(4) at `TOL`) with the first step `h` (s), or, for a
/// negative `h`, `-h · tol^(1/5)` (s).
fn with_first_step<T: Real>(h: f64) -> Integrator<T> {
    let base = std::env::var("TOL")
        .ok()
        .and_then(|t| t.parse::<f64>().ok())
        .map_or_else(Integrator::<T>::default, |t| {
            Integrator::dormand_prince(carry_core::real::lit(t))
        });
    match base {
        Integrator::DormandPrince {
            rtol,
            atol,
            max_step_s,
            ..
        } => Integrator::DormandPrince {
            rtol,
            atol,
            initial_step_s: if h < 0.0 {
                carry_core::real::lit::<T>(-h) * rtol.powf(carry_core::real::lit(0.2))
            } else {
                carry_core::real::lit(h)
            },
            max_step_s,
        },
        other => other,
    }
}

/// A grid of launches (ball speed 60–180 mph, launch 1–40°, backspin 1,500–10,000 rpm)
/// in still air and in a head-, tail- and crosswind, without a ground.
fn grid() -> Vec<Shot> {
    let mut g = Vec::new();
    for v in [60.0, 80.0, 100.0, 120.0, 140.0, 160.0, 180.0] {
        for l in [1.0, 4.0, 8.0, 12.0, 16.0, 20.0, 25.0, 30.0, 40.0] {
            for w in [1500.0, 2500.0, 4000.0, 6000.0, 8000.0, 10000.0] {
                for wind in [[0.0; 3], [-8.0, 0.0, 0.0], [6.0, 0.0, 0.0], [0.0, 0.0, 7.0]] {
                    g.push(("grid", v, l, w, 300.0, wind, false));
                }
            }
        }
    }
    g
}

fn summary(h: f64, shots: &[Shot], reference: &[Run]) {
    let (mut e64, mut e32, mut r64, mut r32) = (0_u64, 0_u64, 0_u64, 0_u64);
    let (mut w64, mut w32) = (0.0_f64, 0.0_f64);
    for (s, r) in shots.iter().zip(reference) {
        let a = run::<f64>(s, &with_first_step(h));
        let b = if std::env::var("TOL").is_ok_and(|t| t.parse().is_ok_and(|t: f64| t < 1e-6)) {
            Run {
                carry: r.carry,
                total: 0.0,
                steps: 0,
                rejected: 0,
                evals: 0,
            }
        } else {
            run::<f32>(s, &with_first_step(h))
        };
        e64 += u64::from(a.evals);
        e32 += u64::from(b.evals);
        r64 += u64::from(a.rejected);
        r32 += u64::from(b.rejected);
        w64 = w64.max((a.carry - r.carry).abs());
        w32 = w32.max((b.carry - r.carry).abs());
    }
    let n = shots.len() as f64;
    println!(
        "grid first step {h:5} s: f64 {:.2} evals/shot, {:.3} rejected, worst carry {w64:.2e} m | f32 {:.2} evals/shot, {:.3} rejected, worst carry {w32:.2e} m",
        e64 as f64 / n,
        r64 as f64 / n,
        e32 as f64 / n,
        r32 as f64 / n
    );
}

fn main() {
    let steps: Vec<f64> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let steps = if steps.is_empty() {
        vec![0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.4]
    } else {
        steps
    };
    if std::env::var_os("GRID").is_some() {
        let g = grid();
        let reference: Vec<Run> = g
            .iter()
            .map(|s| run::<f64>(s, &Integrator::dormand_prince(1e-13)))
            .collect();
        for &h in &steps {
            summary(h, &g, &reference);
        }
        return;
    }
    let reference: Vec<Run> = SHOTS
        .iter()
        .map(|s| run::<f64>(s, &Integrator::dormand_prince(1e-13)))
        .collect();
    for h in steps {
        println!("first step {h} s");
        let (mut e64, mut e32, mut w64, mut w32) = (0, 0, 0.0_f64, 0.0_f64);
        for (s, r) in SHOTS.iter().zip(&reference) {
            let a = run::<f64>(s, &with_first_step(h));
            let b = run::<f32>(s, &with_first_step(h));
            let (da, db) = ((a.carry - r.carry).abs(), (b.carry - r.carry).abs());
            let (ta, tb) = ((a.total - r.total).abs(), (b.total - r.total).abs());
            e64 += a.evals;
            e32 += b.evals;
            w64 = w64.max(da).max(if ta.is_nan() { 0.0 } else { ta });
            w32 = w32.max(db).max(if tb.is_nan() { 0.0 } else { tb });
            println!(
                "  {:24} f64 {:2}+{} steps {:3} evals carry {:+.2e} total {:+.2e} | f32 {:2}+{} steps {:3} evals carry {:+.2e} total {:+.2e}",
                s.0,
                a.steps,
                a.rejected,
                a.evals,
                a.carry - r.carry,
                a.total - r.total,
                b.steps,
                b.rejected,
                b.evals,
                b.carry - r.carry,
                b.total - r.total,
            );
        }
        println!(
            "  sum evals f64 {e64} f32 {e32}; worst |carry|,|total| error f64 {w64:.2e} m, f32 {w32:.2e} m"
        );
    }
}
