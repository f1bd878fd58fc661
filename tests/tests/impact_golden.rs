//! Golden impact cases (`golden/impact.json`, independent f64 reference) through both
//! solvers, in f64 and f32, with named tolerances per precision.

use carry_core::impact::{self, ImpactOutcome, Solver};
use carry_core::linalg::Pivoting;
use carry_core::real::to_f64;
use carry_core::units::{to_deg, to_rpm};
use carry_core::{Real, Result};
use carry_tests::golden::{ImpactCase, ImpactExpected, error_name, impact_cases};
use nalgebra::Vector3;

/// Tolerances of one precision.
#[derive(Debug, Clone, Copy)]
struct Tolerances {
    /// Relative error of vectors (velocities, spins, impulse), |Δv| / |v|.
    vector_rel: f64,
    /// Relative error of ball speed and smash factor.
    speed_rel: f64,
    /// Absolute error of angles (degrees).
    angle_deg: f64,
    /// Absolute error of spin rates (rpm).
    spin_rpm: f64,
}

/// f64: the contract (1e-9 relative, 1e-6°, 1e-3 rpm).
const F64: Tolerances = Tolerances {
    vector_rel: 1e-9,
    speed_rel: 1e-9,
    angle_deg: 1e-6,
    spin_rpm: 1e-3,
};

/// f32 (ε = 1.19e-7). The solve chains ~10 roundings of O(1) relative condition
/// (K's entries are well scaled; the 15×15 system is row-equilibrated), so results carry
/// a few ε relative: we allow 6e-6 relative on vectors and speed (≈ 50 ε; worst seen
/// 3.6e-6 on a club spin through the full solver, 1.3e-6 on speeds). Angles come from
/// atan2 of components accurate to that, so 4e-6 rad ≈ 2.5e-4°; we allow 1e-3°. Spins of
/// up to ~3000 rpm carry ~4e-6 relative ≈ 0.012 rpm, and back/sidespin are projections
/// that add cancellation on the smaller component: we allow 0.05 rpm — 1e-5 of a driver's
/// backspin and far below any launch monitor's resolution (~1 rpm). Measured worst errors
/// are printed by `cargo test -p carry-tests --test impact_golden -- --nocapture`.
const F32: Tolerances = Tolerances {
    vector_rel: 6e-6,
    speed_rel: 6e-6,
    angle_deg: 1e-3,
    spin_rpm: 0.05,
};

/// The shipping solvers: reduced 3×3 and full 15×15 with its default (row-equilibrated)
/// pivoting. Plain partial pivoting is compared in the conditioning study
/// (`robustness_conditioning.rs`): in f32 it loses ~3× more on the ball spin.
const SOLVERS: [Solver; 2] = [Solver::Reduced, Solver::Full(Pivoting::Equilibrated)];

fn run<T: Real>(case: &ImpactCase, solver: Solver) -> Result<ImpactOutcome<T>> {
    let club = case.club_spec::<T>().validate()?;
    let ball = case.ball.to_ball::<T>()?;
    let strike = case.delivery.to_delivery::<T>().strike(&club)?;
    impact::solve(&club, &ball, &strike, solver)
}

fn v64<T: Real>(v: &Vector3<T>) -> [f64; 3] {
    [to_f64(v.x), to_f64(v.y), to_f64(v.z)]
}

fn rel_vec(got: [f64; 3], want: [f64; 3]) -> f64 {
    let d = ((got[0] - want[0]).powi(2) + (got[1] - want[1]).powi(2) + (got[2] - want[2]).powi(2))
        .sqrt();
    let n = (want[0].powi(2) + want[1].powi(2) + want[2].powi(2)).sqrt();
    d / n.max(1e-12)
}

/// Worst error per quantity over the set, with the case that produced it.
#[derive(Default, Debug)]
struct Worst {
    vector_rel: (f64, String),
    speed_rel: (f64, String),
    angle_deg: (f64, String),
    spin_rpm: (f64, String),
}

fn keep(slot: &mut (f64, String), err: f64, what: &str) {
    if err > slot.0 || err.is_nan() {
        *slot = (err, what.to_owned());
    }
}

fn compare<T: Real>(
    out: &ImpactOutcome<T>,
    e: &ImpactExpected,
    tol: Tolerances,
    name: &str,
    worst: &mut Worst,
) {
    let l = &out.launch;
    let vectors = [
        (
            "ball_velocity",
            v64(&out.ball.velocity_mps),
            e.ball_velocity_mps,
        ),
        ("ball_spin", v64(&out.ball.spin_radps), e.ball_spin_radps),
        (
            "club_velocity",
            v64(&out.club.velocity_mps),
            e.club_velocity_mps,
        ),
        ("club_spin", v64(&out.club.spin_radps), e.club_spin_radps),
        ("impulse", v64(&out.impulse_ns), e.impulse_ns),
    ];
    for (q, got, want) in vectors {
        let err = rel_vec(got, want);
        keep(&mut worst.vector_rel, err, &format!("{name}.{q}"));
        assert!(
            err <= tol.vector_rel,
            "{name}: {q} {got:?} vs {want:?} (rel {err:e})"
        );
    }
    let speeds = [
        ("ball_speed", to_f64(l.ball_speed_mps), e.ball_speed_mps),
        ("smash", to_f64(l.smash_factor), e.smash_factor),
    ];
    for (q, got, want) in speeds {
        let err = ((got - want) / want).abs();
        keep(&mut worst.speed_rel, err, &format!("{name}.{q}"));
        assert!(
            err <= tol.speed_rel,
            "{name}: {q} {got} vs {want} (rel {err:e})"
        );
    }
    let angles = [
        (
            "launch_angle",
            to_f64(to_deg(l.launch_angle_rad)),
            e.launch_angle_deg,
        ),
        (
            "launch_direction",
            to_f64(to_deg(l.launch_direction_rad)),
            e.launch_direction_deg,
        ),
        (
            "spin_axis",
            to_f64(to_deg(l.spin_axis_rad)),
            e.spin_axis_deg,
        ),
    ];
    for (q, got, want) in angles {
        let err = (got - want).abs();
        keep(&mut worst.angle_deg, err, &format!("{name}.{q}"));
        assert!(
            err <= tol.angle_deg,
            "{name}: {q} {got}° vs {want}° (err {err:e})"
        );
    }
    let spins = [
        ("spin", to_f64(to_rpm(l.spin_radps)), e.spin_rpm),
        ("backspin", to_f64(to_rpm(l.backspin_radps)), e.backspin_rpm),
        ("sidespin", to_f64(to_rpm(l.sidespin_radps)), e.sidespin_rpm),
    ];
    for (q, got, want) in spins {
        let err = (got - want).abs();
        keep(&mut worst.spin_rpm, err, &format!("{name}.{q}"));
        assert!(
            err <= tol.spin_rpm,
            "{name}: {q} {got} rpm vs {want} rpm (err {err:e})"
        );
    }
}

fn golden_set<T: Real>(tol: Tolerances, label: &str) {
    let cases = impact_cases();
    assert!(cases.len() >= 20, "golden set has {} cases", cases.len());
    for solver in SOLVERS {
        let mut worst = Worst::default();
        let mut checked = 0;
        for case in &cases {
            let got = run::<T>(case, solver);
            match (case.expected, case.expected_error.as_deref()) {
                (Some(e), _) => {
                    let out = got.unwrap_or_else(|err| panic!("{}: {err}", case.name));
                    compare(&out, &e, tol, &case.name, &mut worst);
                    checked += 1;
                }
                (None, Some(want)) => {
                    let err = got.expect_err(&case.name);
                    assert_eq!(error_name(&err), want, "{}: got {err}", case.name);
                }
                (None, None) => panic!("{}: neither expected nor expected_error", case.name),
            }
        }
        assert!(checked >= 19);
        println!("{label} {solver:?}: worst errors over {checked} cases: {worst:#?}");
    }
}

#[test]
fn golden_impact_f64_both_solvers() {
    golden_set::<f64>(F64, "f64");
}

#[test]
fn golden_impact_f32_both_solvers() {
    golden_set::<f32>(F32, "f32");
}
