//! The compliant contact law (`impact::contact_law`): energy never increases (the exact work
//! identity and ΔT ≤ 0 over 10⁵ random deliveries and laws), momentum is conserved, its
//! limits reproduce the seed's rolling contact and frictionless impact, hard cases stay
//! finite or give a named error in f32 and f64, and the full solver refuses it by name.

use carry_core::impact::contact_law::gear_transmission;
use carry_core::impact::{self, CompliantContact, ContactLaw, Problem, Regime, Solver, reduced};
use carry_core::real::to_f64;
use carry_core::{Ball, ClubSpec, Delivery, Error, FaceLocation, Field, Real, Reason};
use carry_tests::invariants::budget;
use carry_tests::scenario::{Scenario, compliant_scenario};
use nalgebra::Vector3;
use proptest::prelude::*;

/// Relative tolerance of the work identity and of ΔT ≤ 0 in f64: a few roundings of the
/// energy (the largest term, ½ m_c v², carries ε relative).
const ENERGY_F64: f64 = 1e-12;
/// The same in f32 (ε = 1.19e-7; ~40 roundings in the solve and in the bookkeeping).
const ENERGY_F32: f64 = 5e-6;
/// Relative tolerance of momentum conservation (as `impact_properties.rs`).
const MOMENTUM_F64: f64 = 1e-12;
const MOMENTUM_F32: f64 = 1e-5;

fn check_energy<T: Real>(s: &Scenario, tol: f64, momentum_tol: f64) -> Result<(), TestCaseError> {
    let Ok((club, ball, strike)) = s.build::<T>() else {
        return Err(TestCaseError::reject("invalid"));
    };
    let out = match impact::solve(&club, &ball, &strike, Solver::Reduced) {
        Ok(o) => o,
        Err(Error::NoApproach) => return Err(TestCaseError::reject("no approach")),
        Err(e) => return Err(TestCaseError::fail(format!("{e}"))),
    };
    let Ok(problem) = Problem::new(&club, &ball, &strike) else {
        return Err(TestCaseError::fail("problem"));
    };
    let origin = Vector3::zeros();
    let before = budget(&club, &ball, &strike, &out, false, origin);
    let after = budget(&club, &ball, &strike, &out, true, origin);
    let c = &out.contact;
    let u = (out.ball.velocity_mps + out.ball.spin_radps.cross(&c.ball_lever_m))
        - (out.club.velocity_mps + out.club.spin_radps.cross(&c.club_lever_m));
    let work = 0.5 * to_f64(out.impulse_ns.dot(&(problem.approach_mps + u)));
    let d_energy = after.energy - before.energy;
    prop_assert!(
        (d_energy - work).abs() <= tol * before.energy,
        "ΔT {d_energy} vs ½P·(u⁰+u) {work}"
    );
    prop_assert!(
        d_energy <= tol * before.energy,
        "energy rises: {} → {} ({:e} relative)",
        before.energy,
        after.energy,
        d_energy / before.energy
    );
    let p_scale = before.linear.norm() + to_f64(club.mass_kg());
    prop_assert!((after.linear - before.linear).norm() <= momentum_tol * p_scale);
    Ok(())
}

/// A deterministic sampler over the domain of `scenario::scenario()` and
/// `scenario::compliant_law()` (SplitMix64; proptest's own generation costs ~20× the solve
/// in a debug build, and 10⁵ cases must stay fast). proptest covers the same domain with
/// shrinking in `compliant_energy_proptest` below.
struct Sampler(u64);

impl Sampler {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        #[allow(clippy::cast_precision_loss)]
        let u = (z >> 11) as f64 / (1u64 << 53) as f64;
        u
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
    /// One of `special` a quarter of the time, else uniform in [lo, hi).
    fn weighted(&mut self, special: &[f64], lo: f64, hi: f64) -> f64 {
        if self.next() < 0.25 {
            #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
            let i = (self.next() * special.len() as f64) as usize;
            special.get(i).copied().unwrap_or(lo)
        } else {
            self.range(lo, hi)
        }
    }
    fn radius(&mut self) -> f64 {
        if self.next() < 0.5 {
            f64::INFINITY
        } else {
            self.range(0.2, 0.5)
        }
    }
    fn scenario(&mut self) -> Scenario {
        let law = CompliantContact {
            friction: self.weighted(&[0.0, f64::INFINITY], 0.0, 2.0),
            tangential_restitution: self.weighted(&[-1.0, 0.0, 1.0], -1.0, 1.0),
            tangential_restitution_slope: self.weighted(&[0.0], -3.0, 3.0),
            tangential_restitution_max: self.weighted(&[1.0, 0.0], 0.0, 1.0),
            restitution_speed_slope_spm: self.weighted(&[0.0], 0.0, 0.03),
        };
        Scenario {
            club_mass_kg: self.range(0.15, 0.35),
            inertia_diag: [(); 3].map(|()| self.range(5e-5, 6e-4)),
            products_frac: [(); 3].map(|()| self.range(-0.2, 0.2)),
            loft_deg: self.range(0.0, 60.0),
            roll_radius_m: self.radius(),
            bulge_radius_m: self.radius(),
            cg_to_face_m: [
                self.range(0.0, 0.045),
                self.range(-0.005, 0.005),
                self.range(-0.005, 0.005),
            ],
            restitution: self.weighted(&[0.0, 1.0], 0.0, 1.0),
            club_speed_mps: self.range(2.0, 60.0),
            attack_deg: self.range(-8.0, 8.0),
            path_deg: self.range(-10.0, 10.0),
            face_deg: self.range(-10.0, 10.0),
            dynamic_loft_offset_deg: self.range(-6.0, 6.0),
            lie_deg: self.range(-8.0, 8.0),
            club_spin_radps: [(); 3].map(|()| self.range(-30.0, 30.0)),
            height_m: self.range(-0.02, 0.02),
            toe_m: self.range(-0.03, 0.03),
            contact: ContactLaw::Compliant(law),
        }
    }
}

/// 10⁵ random clubs, deliveries and compliant laws (μ from 0 to ∞, e and e_t from 0 to 1,
/// the limits weighted in), in f64 and f32: the work identity ΔT = ½P·(u⁰+u) holds and
/// energy never increases. Counts the deliveries that reached an impact.
#[test]
fn energy_never_increases_over_1e5_random_deliveries() {
    let mut sampler = Sampler(0x5EED_CAFE);
    let (mut checked, mut attempts) = (0_u32, 0_u32);
    while checked < 100_000 {
        attempts += 1;
        let s = sampler.scenario();
        let r64 = check_energy::<f64>(&s, ENERGY_F64, MOMENTUM_F64);
        let r32 = check_energy::<f32>(&s, ENERGY_F32, MOMENTUM_F32);
        match (r64, r32) {
            (Ok(()), Ok(())) => checked += 1,
            (Err(TestCaseError::Fail(m)), _) | (_, Err(TestCaseError::Fail(m))) => {
                panic!("{m}: {s:?}")
            }
            _ => {}
        }
        assert!(attempts < 400_000, "too many rejected samples");
    }
    println!("{checked} deliveries checked in {attempts} samples");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2_000, max_global_rejects: 100_000, ..ProptestConfig::default() })]

    /// The same property with proptest's shrinking (regressions are committed).
    #[test]
    fn compliant_energy_proptest(s in compliant_scenario()) {
        check_energy::<f64>(&s, ENERGY_F64, MOMENTUM_F64)?;
        check_energy::<f32>(&s, ENERGY_F32, MOMENTUM_F32)?;
    }
}

fn seed_like() -> CompliantContact<f64> {
    CompliantContact {
        friction: f64::INFINITY,
        tangential_restitution: 0.0,
        tangential_restitution_slope: 0.0,
        tangential_restitution_max: 1.0,
        restitution_speed_slope_spm: 0.0,
    }
}

fn driver_with(law: ContactLaw<f64>) -> ClubSpec<f64> {
    ClubSpec {
        contact: law,
        ..ClubSpec::driver()
    }
}

/// μ = ∞, e_t = 0 and a constant COR is the seed's rolling contact (to rounding) where the
/// normal line passes through the CG (no gear effect), and keeps about a third of the seed's
/// gear effect elsewhere (the ball's tangential spring, `gear_transmission(0) = 1/3`).
#[test]
fn infinite_friction_without_overshoot_is_the_seed_but_for_the_gear_effect() {
    assert!((gear_transmission(0.0_f64) - 1.0 / 3.0).abs() < 1e-15);
    assert!((gear_transmission(1.0_f64) - 1.0).abs() < 1e-15);
    assert!((gear_transmission(1.0_f32 - 1e-6) - 1.0).abs() < 1e-3);
    let run = |law, toe: f64, height: f64, face: f64| {
        let Ok(club) = driver_with(law).validate() else {
            panic!("club")
        };
        let mut d = Delivery::square(45.0, &club);
        d.location = FaceLocation {
            height_m: height,
            toe_m: toe,
        };
        d.face_angle_rad = face;
        let Ok(strike) = d.strike(&club) else {
            panic!("strike")
        };
        let Ok(o) = impact::solve(&club, &Ball::standard(), &strike, Solver::Reduced) else {
            panic!("solve")
        };
        o
    };
    let compliant = ContactLaw::Compliant(seed_like());
    let (a, b) = (
        run(ContactLaw::Rolling, 0.0, 0.0, 0.0),
        run(compliant, 0.0, 0.0, 0.0),
    );
    assert!((a.ball.velocity_mps - b.ball.velocity_mps).norm() <= 1e-12 * 70.0);
    assert!((a.ball.spin_radps - b.ball.spin_radps).norm() <= 1e-12 * 3000.0);
    // off the CG's normal line: the gear effect's change of the spin vector (against a flat
    // face's centre hit with the same normal) is a third of the seed's, within the coupling
    for (toe, height) in [(0.02, 0.0), (0.0, 0.012), (-0.015, -0.01)] {
        let seed = run(ContactLaw::Rolling, toe, height, 0.0);
        let soft = run(compliant, toe, height, 0.0);
        let centre = run(ContactLaw::Rolling, 0.0, 0.0, 0.0);
        // the spin a centre hit with this contact normal would have: remove the geometry by
        // comparing the two laws' spins with each other and with the centre's
        let gear_seed = (seed.ball.spin_radps - centre.ball.spin_radps).norm();
        let gear_soft = (soft.ball.spin_radps - centre.ball.spin_radps).norm();
        assert!(gear_soft < gear_seed, "{toe} {height}");
    }
    // on a flat face the change of spin off the CG's line is the gear effect alone: the
    // compliant law keeps about g = 1/3 of the seed's (the coupling through K moves it a
    // little)
    let flat = |law| {
        let mut spec = driver_with(law);
        spec.roll_radius_m = f64::INFINITY;
        spec.bulge_radius_m = f64::INFINITY;
        let Ok(club) = spec.validate() else {
            panic!("club")
        };
        let spin = |toe: f64| {
            let mut d = Delivery::square(45.0, &club);
            d.location.toe_m = toe;
            let Ok(o) = d
                .strike(&club)
                .and_then(|s| impact::solve(&club, &Ball::standard(), &s, Solver::Reduced))
            else {
                panic!("solve")
            };
            o.launch.sidespin_radps
        };
        spin(0.02) - spin(0.0)
    };
    let ratio = flat(compliant) / flat(ContactLaw::Rolling);
    assert!((ratio - 1.0 / 3.0).abs() < 0.05, "{ratio}");
}

/// μ = 0: the impulse is along the normal (no spin from the face), whatever e_t asks.
#[test]
fn frictionless_impulse_is_normal() {
    let law = CompliantContact {
        friction: 0.0,
        tangential_restitution: 0.5,
        ..seed_like()
    };
    for loft in [10.5_f64, 34.0, 58.0] {
        let mut spec = driver_with(ContactLaw::Compliant(law));
        spec.loft_rad = loft.to_radians();
        let Ok(club) = spec.validate() else {
            panic!("club")
        };
        let Ok(strike) = Delivery::square(40.0, &club).strike(&club) else {
            panic!("strike")
        };
        let Ok(o) = impact::solve(&club, &Ball::standard(), &strike, Solver::Reduced) else {
            panic!("solve")
        };
        let n = o.contact.normal;
        let p = o.impulse_ns;
        assert!((p - n * n.dot(&p)).norm() <= 1e-12 * p.norm(), "{loft}");
        assert!(o.ball.spin_radps.norm() <= 1e-9, "{loft}");
    }
}

/// Spin overshoot: with e_t > 0 the ball leaves with more backspin and a lower launch than
/// rolling (Cross's grip–slip picture); a low friction coefficient caps it.
#[test]
fn overshoot_adds_spin_and_friction_caps_it() {
    let run = |law: ContactLaw<f64>| {
        let mut spec = driver_with(law);
        spec.loft_rad = 34f64.to_radians();
        let Ok(club) = spec.validate() else {
            panic!("club")
        };
        let Ok(strike) = Delivery::square(40.0, &club).strike(&club) else {
            panic!("strike")
        };
        let Ok(o) = impact::solve(&club, &Ball::standard(), &strike, Solver::Reduced) else {
            panic!("solve")
        };
        o.launch
    };
    let rolling = run(ContactLaw::Rolling);
    let grip = run(ContactLaw::Compliant(CompliantContact {
        tangential_restitution: 0.3,
        ..seed_like()
    }));
    let slide = run(ContactLaw::Compliant(CompliantContact {
        friction: 0.05,
        tangential_restitution: 0.3,
        ..seed_like()
    }));
    assert!(grip.backspin_radps > 1.2 * rolling.backspin_radps);
    assert!(grip.launch_angle_rad < rolling.launch_angle_rad);
    assert!(slide.backspin_radps < 0.6 * rolling.backspin_radps);
}

/// The seed's known energy gain at the face edge (`robustness_properties.rs`,
/// `energy_gain_at_the_edge`): the compliant law's energy bound removes it.
#[test]
fn energy_bound_removes_the_seeds_gain_at_the_edge() {
    let mut s = Scenario {
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
    let gain = |s: &Scenario| {
        let Ok((club, ball, strike)) = s.build::<f64>() else {
            panic!("scenario")
        };
        let Ok(o) = impact::solve(&club, &ball, &strike, Solver::Reduced) else {
            panic!("solve")
        };
        let z = Vector3::zeros();
        let b = budget(&club, &ball, &strike, &o, false, z).energy;
        (budget(&club, &ball, &strike, &o, true, z).energy - b) / b
    };
    assert!(gain(&s) > 5e-3, "the seed gains energy here");
    s.contact = ContactLaw::Compliant(seed_like());
    assert!(gain(&s) <= 1e-12, "{}", gain(&s));
    // and it is the grip branch's bound that acted
    let Ok((club, ball, strike)) = s.build::<f64>() else {
        panic!("scenario")
    };
    let Ok(problem) = Problem::new(&club, &ball, &strike) else {
        panic!("problem")
    };
    let k = reduced::collision_matrix(&problem);
    let r = seed_like().impulse(
        &k,
        &problem.approach_mps,
        &problem.contact.normal,
        problem.restitution,
    );
    // the ball grips; with the gear slip (a third of the rigid gear effect at e_t = 0) the
    // impact may already store enough that the bound need not act
    assert!(
        matches!(
            r.map(|(_, regime)| regime),
            Ok(Regime::GripEnergyBound | Regime::Grip)
        ),
        "{r:?}"
    );
}

/// The full 15×15 solver supports only the seed's contact: a named error, not a wrong answer.
#[test]
fn full_solver_names_the_unsupported_contact() {
    let Ok(club) = driver_with(ContactLaw::Compliant(seed_like())).validate() else {
        panic!("club")
    };
    let Ok(strike) = Delivery::square(45.0, &club).strike(&club) else {
        panic!("strike")
    };
    assert_eq!(
        impact::solve(&club, &Ball::standard(), &strike, Solver::FULL).map(|_| ()),
        Err(Error::invalid(
            Field::ContactLaw,
            Reason::UnsupportedBySolver
        ))
    );
}

/// Hard cases, f32 and f64: face edge, flat faces, e = 0 and 1, glancing blows, μ = 0 and
/// μ → ∞, e_t at both clamps: a finite launch or a named error, never NaN or a panic.
fn hard_cases<T: Real>() -> usize {
    let mut finite = 0;
    let laws = [0.0, 0.4, 1e6, f64::INFINITY].into_iter().flat_map(|mu| {
        [-1.0, 0.0, 1.0].map(|e_t| CompliantContact {
            friction: mu,
            tangential_restitution: e_t,
            tangential_restitution_slope: 2.0,
            tangential_restitution_max: 1.0,
            restitution_speed_slope_spm: 0.01,
        })
    });
    for law in laws {
        for e in [0.0, 1.0] {
            for flat in [false, true] {
                for (height, toe) in [(0.0, 0.0), (0.0, 0.2999), (0.2999, 0.0), (0.0, 0.35)] {
                    for (loft, attack) in [(10.5_f64, 0.0_f64), (85.0, 0.0), (0.0, 80.0)] {
                        let mut spec = ClubSpec::<T>::driver();
                        spec.contact = ContactLaw::Compliant(law).cast();
                        spec.restitution = carry_core::real::lit(e);
                        spec.loft_rad = carry_core::real::lit(loft.to_radians());
                        if flat {
                            spec.roll_radius_m = carry_core::real::lit(f64::INFINITY);
                            spec.bulge_radius_m = carry_core::real::lit(f64::INFINITY);
                        }
                        let Ok(club) = spec.validate() else {
                            panic!("club")
                        };
                        let mut d = Delivery::square(carry_core::real::lit(45.0), &club);
                        d.attack_angle_rad = carry_core::real::lit(attack.to_radians());
                        d.location = FaceLocation {
                            height_m: carry_core::real::lit(height),
                            toe_m: carry_core::real::lit(toe),
                        };
                        let r = d.strike(&club).and_then(|s| {
                            impact::solve(&club, &Ball::standard(), &s, Solver::Reduced)
                        });
                        match r {
                            Ok(o) => {
                                let l = o.launch;
                                assert!(
                                    l.ball_speed_mps.is_finite()
                                        && l.spin_radps.is_finite()
                                        && l.launch_angle_rad.is_finite(),
                                    "{law:?} e {e} flat {flat} at ({height},{toe}) loft {loft}"
                                );
                                finite += 1;
                            }
                            Err(Error::OffFace | Error::NoApproach | Error::Singular) => {}
                            Err(other) => panic!("unexpected {other}"),
                        }
                    }
                }
            }
        }
    }
    finite
}

#[test]
fn hard_cases_are_finite_or_named_f32_and_f64() {
    let (a, b) = (hard_cases::<f64>(), hard_cases::<f32>());
    assert!(a > 300 && b > 300, "{a} {b}");
}

/// Validation names the bad parameter when the club is validated.
#[test]
fn club_validation_checks_the_law() {
    let bad = CompliantContact {
        friction: -1.0,
        ..seed_like()
    };
    assert_eq!(
        driver_with(ContactLaw::Compliant(bad))
            .validate()
            .map(|_| ()),
        Err(Error::invalid(Field::Friction, Reason::Negative))
    );
    let bad = CompliantContact {
        restitution_speed_slope_spm: f64::NAN,
        ..seed_like()
    };
    assert_eq!(
        driver_with(ContactLaw::Compliant(bad))
            .validate()
            .map(|_| ()),
        Err(Error::invalid(
            Field::RestitutionSpeedSlope,
            Reason::NotFinite
        ))
    );
}
