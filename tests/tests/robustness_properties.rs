//! Issue 7 property tests beyond `impact_properties.rs`: f32 agrees with f64 within
//! documented bounds; every output is finite (or a named error) over an extended domain
//! that reaches the hard corners; flight outputs are finite and carry is continuous in
//! the launch (no jumps between nearby launches). Regressions are committed under
//! `tests/proptest-regressions/`.

use carry_core::impact::{self, Solver};
use carry_core::real::{lit, to_f64};
use carry_core::scene::Scene;
use carry_core::units::{deg, rpm};
use carry_core::{Ball, ContactLaw, Error, Integrator, Launch, Real, Wind, fly};
use carry_tests::scenario::{Scenario, scenario};
use nalgebra::Vector3;
use proptest::prelude::*;
use proptest::test_runner::FileFailurePersistence;

/// Failing seeds go to `tests/proptest-regressions/robustness_properties.txt` (committed;
/// the path is relative to the package directory, where `cargo test` runs).
fn persistence() -> Option<Box<dyn proptest::test_runner::FailurePersistence>> {
    Some(Box::new(FileFailurePersistence::Direct(
        "proptest-regressions/robustness_properties.txt",
    )))
}

/// f32 vs f64 ball velocity, relative: the f32 run sees f32-rounded inputs (ε/2 each) and
/// solves in ~30 ε (robustness_conditioning.rs: ≤ 4.3e-7 from the solve alone); the
/// problem's condition in its inputs is O(10), so 2e-5 bounds the sum with margin.
const F32_VELOCITY_REL: f64 = 2e-5;
/// f32 vs f64 ball spin, relative to the spin scale |v_c|/R (spin can be near zero): the
/// spin comes from a lever-arm cross product and loses ~10× more (conditioning study:
/// ≤ 7e-6 from the solve), so 1e-4.
const F32_SPIN_REL: f64 = 1e-4;
/// f32 vs f64 carry with the default integrators (m): the f32 default is documented to 1 cm
/// of the reference on the golden set (docs/flight.md); with 30 m/s winds and 12,000 rpm
/// the local error per step (tolerance 1e-6 × |y| ≈ 2e-4 m, and f32 rounding of ~200 m
/// positions, 1.5e-5 m) accumulates over more steps. With the calibrated aerodynamics (the
/// drag crisis and the saturating lift, crossed many times by a ball riding a 30 m/s
/// tailwind) the measured worst over 2,000 cases was 14 cm on a 440 m carry (a proptest
/// find: 15.5 cm; later a helper's run 27 cm, over the 0.25 m bound then). Over 200,000
/// cases of this generator (2026-11-28): 147 beyond 0.1 m, one beyond 0.25 m, worst 0.29 m
/// (a 290 m carry launched at 59° into a 10 m/s wind); bound 0.35 m.
const F32_CARRY_M: f64 = 0.35;

fn f32_matches_f64(s: &Scenario, solver: Solver) -> Result<(), TestCaseError> {
    let (Ok((c64, b64, s64)), Ok((c32, b32, s32))) = (s.build::<f64>(), s.build::<f32>()) else {
        return Err(TestCaseError::reject("invalid"));
    };
    let (Ok(a), Ok(b)) = (
        impact::solve(&c64, &b64, &s64, solver),
        impact::solve(&c32, &b32, &s32, solver),
    ) else {
        return Err(TestCaseError::reject("no impact"));
    };
    let v = a.ball.velocity_mps;
    let dv = (b.ball.velocity_mps.map(f64::from) - v).norm() / v.norm().max(1e-9);
    prop_assert!(dv <= F32_VELOCITY_REL, "velocity {dv:e}");
    let w_scale = s64.club_speed_mps() / b64.radius_m();
    let dw = (b.ball.spin_radps.map(f64::from) - a.ball.spin_radps).norm() / w_scale;
    prop_assert!(dw <= F32_SPIN_REL, "spin {dw:e}");
    Ok(())
}

/// The golfer domain pushed to the catalogue's corners: club speed 1e-3…150 m/s, club mass
/// and inertia ×1e-3…×1e6, face and path to ±80°, e anywhere in [0, 1], impact anywhere
/// (including off the face).
fn extended() -> impl Strategy<Value = Scenario> {
    (
        scenario(),
        -3.0..6.0_f64,
        -3.0..2.18_f64,
        -80.0..80.0_f64,
        -80.0..80.0_f64,
        0.0..=1.0_f64,
        -0.3..0.3_f64,
        -0.3..0.3_f64,
    )
        .prop_map(|(mut s, mass_exp, speed_exp, face, path, e, h, t)| {
            let k = 10f64.powf(mass_exp);
            s.club_mass_kg *= k;
            s.inertia_diag = s.inertia_diag.map(|x| x * k);
            s.club_speed_mps = 10f64.powf(speed_exp);
            s.club_spin_radps = s.club_spin_radps.map(|w| w * s.club_speed_mps / 45.0);
            s.face_deg = face;
            s.path_deg = path;
            s.restitution = e;
            s.height_m = h;
            s.toe_m = t;
            s
        })
}

fn finite_or_named<T: Real>(s: &Scenario) -> Result<(), TestCaseError> {
    let Ok((club, ball, strike)) = s.build::<T>() else {
        return Ok(());
    };
    for solver in [Solver::Reduced, Solver::FULL] {
        match impact::solve(&club, &ball, &strike, solver) {
            Ok(o) => {
                let v = [
                    o.ball.velocity_mps,
                    o.ball.spin_radps,
                    o.club.velocity_mps,
                    o.club.spin_radps,
                    o.impulse_ns,
                ];
                prop_assert!(v.iter().all(|x| x.iter().all(|c| c.is_finite())));
                let l = o.launch;
                prop_assert!(
                    [
                        l.ball_speed_mps,
                        l.launch_angle_rad,
                        l.launch_direction_rad,
                        l.spin_radps,
                        l.spin_axis_rad,
                        l.smash_factor
                    ]
                    .iter()
                    .all(|x| x.is_finite())
                );
                // Energy never increases (relative to the precision) — checked where the
                // impact point is within a golfer's ±2 cm × ±3 cm of the face centre. Far out
                // at the face edge the large lever arm couples the normal and tangential
                // impulses, and Newton's (kinematic) restitution with full sticking can then
                // *gain* up to ~2 % energy: a known limitation of the model (Kane's paradox;
                // Stronge 1991), not of the numerics. Regression: `energy_gain_at_the_edge`.
                if s.height_m.abs() > 0.02 || s.toe_m.abs() > 0.03 {
                    continue;
                }
                let before = carry_tests::invariants::budget(
                    &club,
                    &ball,
                    &strike,
                    &o,
                    false,
                    Vector3::zeros(),
                )
                .energy;
                let after = carry_tests::invariants::budget(
                    &club,
                    &ball,
                    &strike,
                    &o,
                    true,
                    Vector3::zeros(),
                )
                .energy;
                let tol = if T::default_epsilon() > lit(1e-10) {
                    1e-5
                } else {
                    1e-12
                };
                prop_assert!(after <= before * (1.0 + tol), "energy {before} → {after}");
            }
            Err(Error::OffFace | Error::NoApproach) => {}
            // f32 only, full 15×15 only: a 1e-3× club struck ~0.2 m off-centre (I_c ≪ m_c r²)
            // drives a pivot of the equilibrated elimination below 15 ε; the reduced solver
            // still solves it. A clean named error (docs/robustness.md, open finding).
            Err(Error::Singular)
                if solver != Solver::Reduced && T::default_epsilon() > lit(1e-10) => {}
            Err(e) => prop_assert!(false, "{solver:?}: {e}"),
        }
    }
    Ok(())
}

/// A launch anywhere a golf ball goes: 5–90 m/s, −10…80° (from a 1 m tee when
/// below the horizontal), ±45° direction, 0–12,000 rpm about any axis tilt, winds ≤ 30 m/s.
#[derive(Debug, Clone, Copy)]
struct Shot {
    speed: f64,
    angle_deg: f64,
    direction_deg: f64,
    spin_rpm: f64,
    axis_deg: f64,
    wind: [f64; 3],
}

fn shot() -> impl Strategy<Value = Shot> {
    (
        5.0..90.0_f64,
        -10.0..80.0_f64,
        -45.0..45.0_f64,
        0.0..12_000.0_f64,
        -60.0..60.0_f64,
        [-30.0..30.0_f64, -3.0..3.0_f64, -30.0..30.0_f64],
    )
        .prop_map(
            |(speed, angle_deg, direction_deg, spin_rpm, axis_deg, wind)| Shot {
                speed,
                angle_deg,
                direction_deg,
                spin_rpm,
                axis_deg,
                wind,
            },
        )
}

impl Shot {
    /// Launched below the horizontal (from the 1 m tee): the ball may skim the landing
    /// plane and lift off again, and carry — the *first* downward crossing — is then
    /// genuinely discontinuous (and arbitrarily sensitive near the tangency). Such shots
    /// are checked for finiteness only.
    fn grazing(&self) -> bool {
        self.angle_deg < 2.0
    }

    fn fly<T: Real>(&self, dspeed: f64) -> carry_core::Result<carry_core::FlightOutcome<T>> {
        let l = Launch::<T>::from_spin_axis(
            lit(self.speed + dspeed),
            deg(lit(self.angle_deg)),
            deg(lit(self.direction_deg)),
            rpm(lit(self.spin_rpm)),
            deg(lit(self.axis_deg)),
        );
        let w = Vector3::new(lit(self.wind[0]), lit(self.wind[1]), lit(self.wind[2]));
        let scene = Scene::<T> {
            wind: Wind::profile(w),
            launch_position_m: Vector3::new(
                T::zero(),
                lit(if self.angle_deg < 0.0 { 1.0 } else { 0.0 }),
                T::zero(),
            ),
            ..Scene::default()
        };
        fly(
            &Ball::standard(),
            &l.ball_motion()?,
            &scene,
            &Integrator::default(),
            None,
        )
    }
}

fn flight_finite<T: Real>(s: &Shot) -> Result<f64, TestCaseError> {
    match s.fly::<T>(0.0) {
        Ok(o) => {
            let v = [
                o.carry_m,
                o.side_m,
                o.apex_m,
                o.flight_time_s,
                o.landing_angle_rad,
                o.landing_speed_mps,
                o.landing_spin_radps,
            ];
            prop_assert!(v.iter().all(|x| x.is_finite()), "{o:?}");
            prop_assert!(o.carry_m >= T::zero() && o.landing_spin_radps >= T::zero());
            Ok(to_f64(o.carry_m))
        }
        // a ball launched downwards into a strong updraft, say: documented outcomes only
        Err(Error::NoLanding | Error::TimeLimit) => Err(TestCaseError::reject("no landing")),
        Err(e) => Err(TestCaseError::fail(format!("{e}"))),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, max_global_rejects: 100_000, failure_persistence: persistence(), ..ProptestConfig::default() })]

    #[test]
    fn impact_f32_matches_f64_reduced(s in scenario()) { f32_matches_f64(&s, Solver::Reduced)?; }

    #[test]
    fn impact_f32_matches_f64_full(s in scenario()) { f32_matches_f64(&s, Solver::FULL)?; }

    #[test]
    fn impact_finite_or_named_error_f64(s in extended()) { finite_or_named::<f64>(&s)?; }

    #[test]
    fn impact_finite_or_named_error_f32(s in extended()) { finite_or_named::<f32>(&s)?; }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, max_global_rejects: 10_000, failure_persistence: persistence(), ..ProptestConfig::default() })]

    #[test]
    fn flight_finite_and_f32_matches_f64(s in shot()) {
        let c64 = flight_finite::<f64>(&s)?;
        let c32 = flight_finite::<f32>(&s)?;
        prop_assume!(!s.grazing());
        prop_assert!((c64 - c32).abs() <= F32_CARRY_M, "carry f64 {c64} vs f32 {c32}");
    }

    /// Carry is continuous in the launch: a 1 mm/s change of ball speed moves carry by at
    /// most ∂carry/∂v·Δv (≤ 10 m per m/s for any golf shot) plus twice the integrator's
    /// documented error (1 mm in f64, 1 cm in f32) — the adaptive step sequence may change
    /// between the two launches, the landing interpolation must not jump.
    #[test]
    fn carry_is_continuous_in_the_launch(s in shot()) {
        prop_assume!(!s.grazing());
        let dv = 1e-3;
        for (tol, a, b) in [
            (2e-3, s.fly::<f64>(0.0).map(|o| o.carry_m), s.fly::<f64>(dv).map(|o| o.carry_m)),
            (2e-2, s.fly::<f32>(0.0).map(|o| f64::from(o.carry_m)), s.fly::<f32>(dv).map(|o| f64::from(o.carry_m))),
        ] {
            match (a, b) {
                (Ok(a), Ok(b)) => prop_assert!((a - b).abs() <= 10.0 * dv + tol, "carry jumps {a} → {b}"),
                (Err(_), Err(_)) => {}
                (a, b) => prop_assert!(false, "outcome changes kind: {a:?} vs {b:?}"),
            }
        }
    }
}

/// The model's known energy gain far off-centre (see `finite_or_named`): documented, and
/// bounded so that a numerical regression on top of it would still show.
#[test]
fn energy_gain_at_the_edge() {
    let s = Scenario {
        club_mass_kg: 0.15,
        inertia_diag: [5e-5; 3],
        products_frac: [0.0; 3],
        loft_deg: 0.0,
        roll_radius_m: f64::INFINITY,
        bulge_radius_m: 0.328_745_280_897_156_7,
        cg_to_face_m: [0.0; 3],
        restitution: 0.817_438_374_048_688_9,
        club_speed_mps: 1.0,
        attack_deg: 0.0,
        path_deg: -11.378_692_914_561_409,
        face_deg: 15.166_481_963_448_21,
        dynamic_loft_offset_deg: 0.0,
        lie_deg: 0.0,
        club_spin_radps: [0.0; 3],
        height_m: 0.0,
        toe_m: -0.298_679_923_601_070_8,
        contact: ContactLaw::Rolling,
    };
    let Ok((club, ball, strike)) = s.build::<f64>() else {
        panic!("scenario")
    };
    for solver in [Solver::Reduced, Solver::FULL] {
        let Ok(o) = impact::solve(&club, &ball, &strike, solver) else {
            panic!("{solver:?}")
        };
        let e0 =
            carry_tests::invariants::budget(&club, &ball, &strike, &o, false, Vector3::zeros())
                .energy;
        let e1 = carry_tests::invariants::budget(&club, &ball, &strike, &o, true, Vector3::zeros())
            .energy;
        // compressive impulse, yet 0.94 % more kinetic energy: the model, not the solver
        assert!(o.contact.normal.dot(&o.impulse_ns) > 0.0);
        assert!(e1 > e0 && e1 < e0 * 1.02, "{e0} → {e1}");
    }
}
