//! Impact invariants as property tests over random valid deliveries (proptest), plus the
//! closed-form limits. Regressions proptest finds are committed under
//! `tests/proptest-regressions/`.

use carry_core::impact::{self, Problem, Solver, full};
use carry_core::linalg::Pivoting;
use carry_core::real::{lit, to_f64};
use carry_core::{Ball, ClubSpec, Delivery, Error, FaceLocation, Real};
use carry_tests::invariants::budget;
use carry_tests::scenario::{Scenario, preset_scenario, scenario};
use nalgebra::Vector3;
use proptest::prelude::*;

/// Relative tolerance of conservation laws in f64 (the issue asks for 1e-12).
const CONSERVE_F64: f64 = 1e-12;
/// Relative tolerance of conservation laws in f32 (the issue asks for 1e-5).
const CONSERVE_F32: f64 = 1e-5;

fn rel(a: Vector3<f64>, b: Vector3<f64>, scale: f64) -> f64 {
    (a - b).norm() / scale.max(1e-300)
}

fn check_invariants<T: Real>(s: &Scenario, solver: Solver, tol: f64) -> Result<(), TestCaseError> {
    let Ok((club, ball, strike)) = s.build::<T>() else {
        return Err(TestCaseError::reject("invalid"));
    };
    let out = match impact::solve(&club, &ball, &strike, solver) {
        Ok(o) => o,
        Err(Error::NoApproach) => return Err(TestCaseError::reject("no approach")),
        Err(e) => return Err(TestCaseError::fail(format!("{e}"))),
    };
    let point = Vector3::new(0.3, -0.2, 0.7); // an arbitrary fixed point (m)
    let before = budget(&club, &ball, &strike, &out, false, point);
    let after = budget(&club, &ball, &strike, &out, true, point);
    // scale: momentum of the club, and its angular momentum about the point
    let p_scale = before.linear.norm() + to_f64(club.mass_kg()) * 1.0;
    let l_scale = before.angular.norm() + p_scale * point.norm();
    prop_assert!(
        rel(before.linear, after.linear, p_scale) <= tol,
        "linear momentum {:?} → {:?}",
        before.linear,
        after.linear
    );
    prop_assert!(
        rel(before.angular, after.angular, l_scale) <= tol,
        "angular momentum {:?} → {:?}",
        before.angular,
        after.angular
    );
    // no tangential slip; normal separation −e n·u⁰
    let c = &out.contact;
    let u_after = (out.ball.velocity_mps + out.ball.spin_radps.cross(&c.ball_lever_m))
        - (out.club.velocity_mps + out.club.spin_radps.cross(&c.club_lever_m));
    let Ok(problem) = Problem::new(&club, &ball, &strike) else {
        return Err(TestCaseError::fail("problem"));
    };
    // Work–energy identity of an impulse: ΔT = ½ P·(u⁰ + u). (Energy need not fall: see
    // `check_energy` and the note there.)
    let work = 0.5 * to_f64(out.impulse_ns.dot(&(problem.approach_mps + u_after)));
    let d_energy = after.energy - before.energy;
    prop_assert!(
        (d_energy - work).abs() <= 8.0 * tol * before.energy,
        "ΔT {d_energy} vs ½P·(u⁰+u) {work}"
    );
    let target = problem.target_velocity_mps();
    let u_scale = to_f64(problem.approach_mps.norm());
    let du = (u_after - target).map(to_f64).norm();
    prop_assert!(
        du <= 16.0 * tol * u_scale.max(1e-9),
        "contact velocity off target by {du}"
    );
    prop_assert!(
        out.ball
            .velocity_mps
            .iter()
            .chain(out.ball.spin_radps.iter())
            .all(|x| x.is_finite())
    );
    Ok(())
}

/// Kinetic energy never increases for the realistic clubs (presets, e up to the preset's).
///
/// Not over the whole domain: Newton's restitution with sticking lets the tangential
/// impulse do positive work, ½P_t·u⁰_t > 0, when the collision matrix couples normal and
/// tangential directions strongly (a light, low-inertia head struck high or far off-centre
/// with e ≈ 1). proptest found ΔT/T = +1.0e-4 (regression file), confirmed independently
/// with numpy from PHYSICS.md's equations; the robustness suite pins a +0.94 % case at the
/// face edge. PHYSICS.md's "never increases" holds for every golden case and for the preset
/// clubs over a golfer's delivery range (toe ±30 mm, height ±20 mm, face and path ±10°),
/// which this property checks; the identity ΔT = ½P·(u⁰+u) holds everywhere.
fn check_energy<T: Real>(s: &Scenario, tol: f64) -> Result<(), TestCaseError> {
    let Ok((club, ball, strike)) = s.build::<T>() else {
        return Err(TestCaseError::reject("invalid"));
    };
    let Ok(out) = impact::solve(&club, &ball, &strike, Solver::Reduced) else {
        return Err(TestCaseError::reject("no impact"));
    };
    let p = Vector3::zeros();
    let before = budget(&club, &ball, &strike, &out, false, p);
    let after = budget(&club, &ball, &strike, &out, true, p);
    prop_assert!(
        after.energy <= before.energy * (1.0 + tol),
        "energy {} → {}",
        before.energy,
        after.energy
    );
    Ok(())
}

fn check_solvers_agree<T: Real>(s: &Scenario, tol: f64) -> Result<(), TestCaseError> {
    let Ok((club, ball, strike)) = s.build::<T>() else {
        return Err(TestCaseError::reject("invalid"));
    };
    let (Ok(r), Ok(f)) = (
        impact::solve(&club, &ball, &strike, Solver::Reduced),
        impact::solve(&club, &ball, &strike, Solver::FULL),
    ) else {
        return Err(TestCaseError::reject("no impact"));
    };
    let scale = to_f64(strike.club_speed_mps()) * 2.0;
    let d = (r.ball.velocity_mps - f.ball.velocity_mps)
        .map(to_f64)
        .norm();
    prop_assert!(d <= tol * scale, "ball velocity differs by {d}");
    let w_scale = scale / to_f64(ball.radius_m());
    let dw = (r.ball.spin_radps - f.ball.spin_radps).map(to_f64).norm();
    prop_assert!(dw <= tol * w_scale, "ball spin differs by {dw}");
    Ok(())
}

/// The empirical spin-axis share (issue 34, `ClubSpec::spin_axis_share`) changes only the
/// spin axis: the same ball velocity bit for bit, the same spin magnitude, the axis'
/// tangent scaled by `k` (and never larger), whatever the club and delivery.
fn check_axis_share<T: Real>(s: &Scenario, k: f64, tol: f64) -> Result<(), TestCaseError> {
    let spec = s.club_spec::<T>();
    let shared = ClubSpec {
        spin_axis_share: lit(k),
        ..spec
    };
    let (Ok(physics), Ok(club)) = (spec.validate(), shared.validate()) else {
        return Err(TestCaseError::reject("invalid"));
    };
    let Ok(strike) = s.delivery::<T>().strike(&physics) else {
        return Err(TestCaseError::reject("no strike"));
    };
    let ball = Ball::standard();
    let (Ok(a), Ok(b)) = (
        impact::solve(&physics, &ball, &strike, Solver::Reduced),
        impact::solve(&club, &ball, &strike, Solver::Reduced),
    ) else {
        return Err(TestCaseError::reject("no impact"));
    };
    prop_assert_eq!(a.ball.velocity_mps, b.ball.velocity_mps);
    prop_assert_eq!(a.launch.ball_speed_mps, b.launch.ball_speed_mps);
    let (la, lb) = (a.launch, b.launch);
    let spin = to_f64(la.spin_radps);
    prop_assert!((to_f64(lb.spin_radps) - spin).abs() <= tol * (1.0 + spin));
    let (ta, tb) = (
        to_f64(la.spin_axis_rad).tan(),
        to_f64(lb.spin_axis_rad).tan(),
    );
    if to_f64(la.backspin_radps) > 1.0 && ta.abs() < 50.0 {
        prop_assert!(
            (tb - k * ta).abs() <= tol * 100.0 * (1.0 + ta.abs()),
            "tan axis {tb} against k·{ta}"
        );
        prop_assert!(to_f64(lb.spin_axis_rad).abs() <= to_f64(la.spin_axis_rad).abs() + tol);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, max_global_rejects: 100_000, ..ProptestConfig::default() })]

    #[test]
    fn invariants_hold_f64_reduced(s in scenario()) { check_invariants::<f64>(&s, Solver::Reduced, CONSERVE_F64)?; }

    #[test]
    fn invariants_hold_f64_full(s in scenario()) { check_invariants::<f64>(&s, Solver::FULL, CONSERVE_F64)?; }

    #[test]
    fn invariants_hold_f32_reduced(s in scenario()) { check_invariants::<f32>(&s, Solver::Reduced, CONSERVE_F32)?; }

    #[test]
    fn invariants_hold_f32_full(s in scenario()) { check_invariants::<f32>(&s, Solver::FULL, CONSERVE_F32)?; }

    #[test]
    fn energy_never_increases_with_preset_clubs(s in preset_scenario()) {
        check_energy::<f64>(&s, CONSERVE_F64)?;
        check_energy::<f32>(&s, CONSERVE_F32)?;
    }

    #[test]
    fn spin_axis_share_changes_only_the_axis(s in preset_scenario(), k in 0.05..=1.0_f64) {
        check_axis_share::<f64>(&s, k, 1e-12)?;
        check_axis_share::<f32>(&s, k, 2e-5)?;
    }

    #[test]
    fn full_and_reduced_agree(s in scenario()) {
        check_solvers_agree::<f64>(&s, 1e-12)?;
        check_solvers_agree::<f32>(&s, 2e-5)?;
    }

    #[test]
    fn toe_heel_mirror_flips_side_quantities(s in scenario()) {
        let (Ok((c1, b1, s1)), Ok((c2, b2, s2))) = (s.build::<f64>(), s.mirrored().build::<f64>()) else {
            return Err(TestCaseError::reject("invalid"));
        };
        let (Ok(a), Ok(m)) = (impact::solve(&c1, &b1, &s1, Solver::Reduced), impact::solve(&c2, &b2, &s2, Solver::Reduced)) else {
            return Err(TestCaseError::reject("no impact"));
        };
        let (la, lm) = (a.launch, m.launch);
        let tol = 1e-9;
        prop_assert!((la.sidespin_radps + lm.sidespin_radps).abs() <= tol * (1.0 + la.spin_radps));
        prop_assert!((la.launch_direction_rad + lm.launch_direction_rad).abs() <= tol);
        prop_assert!((la.backspin_radps - lm.backspin_radps).abs() <= tol * (1.0 + la.spin_radps));
        prop_assert!((la.ball_speed_mps - lm.ball_speed_mps).abs() <= tol * la.ball_speed_mps);
        prop_assert!((la.launch_angle_rad - lm.launch_angle_rad).abs() <= tol);
    }

    #[test]
    fn result_does_not_depend_on_tangents(s in scenario(), theta in 0.0..std::f64::consts::TAU) {
        let Ok((club, ball, strike)) = s.build::<f64>() else { return Err(TestCaseError::reject("invalid")) };
        let Ok(problem) = Problem::new(&club, &ball, &strike) else { return Err(TestCaseError::reject("no impact")) };
        let (t1, t2) = carry_core::geometry::tangents(&problem.contact.normal);
        let (sn, cs) = theta.sin_cos();
        let (u1, u2) = (t1 * cs + t2 * sn, t2 * cs - t1 * sn);
        let (a0, b0) = full::assemble_in_frame(&problem, &t1, &t2);
        let (a1, b1) = full::assemble_in_frame(&problem, &u1, &u2);
        let (Ok(x0), Ok(x1)) = (full::solve_system(a0, &b0, Pivoting::Equilibrated), full::solve_system(a1, &b1, Pivoting::Equilibrated)) else {
            return Err(TestCaseError::fail("singular"));
        };
        let scale = strike.club_speed_mps();
        prop_assert!((x0.ball_velocity_mps - x1.ball_velocity_mps).norm() <= 1e-12 * scale);
        prop_assert!((x0.ball_spin_radps - x1.ball_spin_radps).norm() <= 1e-12 * scale / ball.radius_m());
    }
}

/// Zero loft, normal through the CoM, club moving along the normal, no rotation:
/// `V_b = (1+e)·m_c·v/(m_c+m_b)` along the normal, and no spin.
fn head_on<T: Real>(e: f64, tol: f64) {
    let mut spec = ClubSpec::<T>::driver();
    spec.loft_rad = T::zero();
    spec.restitution = lit(e);
    let Ok(club) = spec.validate() else {
        panic!("club")
    };
    let ball = Ball::<T>::standard();
    let v = 45.0;
    let mut d = Delivery::square(lit(v), &club);
    d.dynamic_loft_rad = T::zero();
    for solver in [Solver::Reduced, Solver::FULL] {
        let Ok(strike) = d.strike(&club) else {
            panic!("strike")
        };
        let Ok(out) = impact::solve(&club, &ball, &strike, solver) else {
            panic!("solve")
        };
        let (mc, mb) = (0.2, 0.04593);
        let want = (1.0 + e) * mc * v / (mc + mb);
        let got = out.ball.velocity_mps.map(to_f64);
        assert!(
            (got.x - want).abs() <= tol * want,
            "{solver:?}: {} vs {want}",
            got.x
        );
        assert!(got.y.abs() <= tol * want && got.z.abs() <= tol * want);
        assert!(out.ball.spin_radps.map(to_f64).norm() <= tol * want / 0.021336);
    }
}

#[test]
fn head_on_hit_matches_closed_form() {
    for e in [0.0, 0.5, 0.83, 1.0] {
        head_on::<f64>(e, 1e-14);
        head_on::<f32>(e, 1e-6);
    }
}

/// As club mass and inertia grow without bound, the ball leaves as from a rigid wall
/// moving at the club's velocity: `V_b = (1+e)(v·n)n + (2/7)v_t`,
/// `Ω_b = (5/(7R)) n̂ × …` with magnitude `5|v_t|/(7R)` (rolling on the wall, I = 0.4mR²).
#[test]
fn heavy_club_is_a_rigid_wall() {
    let ball = Ball::<f64>::standard();
    let r = ball.radius_m();
    for scale in [1e3, 1e6, 1e9] {
        let mut spec = ClubSpec::<f64>::driver();
        spec.mass_kg *= scale;
        spec.inertia_kgm2 *= scale;
        let Ok(club) = spec.validate() else {
            panic!("club")
        };
        let mut d = Delivery::square(45.0, &club);
        d.location = FaceLocation {
            height_m: 0.004,
            toe_m: -0.007,
        };
        d.face_angle_rad = 0.05;
        let Ok(strike) = d.strike(&club) else {
            panic!("strike")
        };
        for solver in [Solver::Reduced, Solver::FULL] {
            let Ok(out) = impact::solve(&club, &ball, &strike, solver) else {
                panic!("{solver:?} at {scale}")
            };
            let n = out.contact.normal;
            let v = strike.club().velocity_mps;
            let vn = v.dot(&n);
            let vt = v - n * vn;
            let e = club.restitution();
            let want_v = n * ((1.0 + e) * vn) + vt * (2.0 / 7.0);
            let want_w = (-n).cross(&vt) * (5.0 / (7.0 * r));
            let tol = 10.0 / scale; // O(m_b/m_c) from the finite mass
            assert!(
                (out.ball.velocity_mps - want_v).norm() <= tol * v.norm(),
                "{solver:?} {scale}"
            );
            assert!(
                (out.ball.spin_radps - want_w).norm() <= tol * v.norm() / r,
                "{solver:?} {scale}"
            );
        }
    }
}

/// A spin-axis share outside (0, 1] (or NaN) is an invalid input naming it, in both
/// precisions; the presets and the defaults hold the physics' 1.
#[test]
fn spin_axis_share_outside_its_range_is_rejected() {
    fn check<T: Real>() {
        let spec = ClubSpec::<T>::driver();
        assert_eq!(spec.spin_axis_share, T::one());
        for k in [0.0, -0.5, 1.0 + 1e-3, f64::NAN, f64::INFINITY] {
            let bad = ClubSpec {
                spin_axis_share: lit(k),
                ..spec
            };
            match bad.validate() {
                Err(Error::InvalidInput { field, .. }) => {
                    assert_eq!(field, carry_core::Field::SpinAxisShare, "{k}");
                }
                other => panic!("{k}: {other:?}"),
            }
        }
        assert!(
            ClubSpec {
                spin_axis_share: lit(1e-3),
                ..spec
            }
            .validate()
            .is_ok()
        );
    }
    check::<f64>();
    check::<f32>();
    for p in carry_core::PRESETS {
        assert_eq!(p.spec::<f64>().spin_axis_share, 1.0, "{}", p.name);
    }
}
