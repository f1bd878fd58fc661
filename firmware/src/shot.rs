//! A full shot as a launch monitor runs it: the measured club delivery → strike →
//! impact → launch → flight → carry. The reference shot is the golden driver
//! (`driver_centre_45` in tests/golden/impact.json: 45 m/s, 10.5° loft, centre strike),
//! whose launch the flight golden file flies as `reference_driver_impact`.

use carry_core::flight::{self, FlightOutcome, Integrator};
use carry_core::impact::{self, ContactLaw, ImpactOutcome, Solver};
use carry_core::presets::FITTED_CONTACT;
use carry_core::real::{Real, lit};
use carry_core::scene::Scene;
use carry_core::units::deg;
use carry_core::{Ball, ClubSpec, Delivery, FaceLocation, Result};
use nalgebra::{Matrix3, Vector3};

/// The f64 reference carry of the reference driver shot (m) with the seed's aerodynamics:
/// `reference_driver_impact` in tests/golden/flight.json.
pub const REFERENCE_CARRY_M: f64 = 199.682_864_687_470_04;
/// The f64 carry of the reference driver shot with the calibrated default aerodynamics
/// (`drives2026`; 206.392459010803 m with `tour2023`, 205.5546080869668 m with issue 35's
/// first `drives2026`) and the seed's contact, at a tolerance of 1e-12 on the host:
/// `carry shot --contact rolling --integrator dp45 --tolerance 1e-12 --json`.
pub const CALIBRATED_CARRY_M: f64 = 203.632_033_543_055_66;

/// The precision of the size-probe and example binaries (`--features f64` for f64).
#[cfg(not(feature = "f64"))]
pub type R = f32;
/// The precision of the size-probe and example binaries (`--features f64` for f64).
#[cfg(feature = "f64")]
pub type R = f64;

/// The reference driver head (the golden `driver_centre_45` club).
#[must_use]
pub fn driver<T: Real>() -> ClubSpec<T> {
    ClubSpec {
        mass_kg: lit(0.2),
        inertia_kgm2: Matrix3::from_diagonal(&Vector3::new(lit(3.0e-4), lit(4.2e-4), lit(2.2e-4))),
        loft_rad: deg(lit(10.5)),
        roll_radius_m: lit(0.3),
        bulge_radius_m: lit(0.3),
        face_depth_radius_m: Some(lit(0.3)),
        cg_to_face_m: Vector3::new(lit(0.04), T::zero(), T::zero()),
        restitution: lit(0.83),
        contact: ContactLaw::Rolling,
        spin_axis_share: T::one(),
    }
}

/// The same head with the presets' calibrated compliant contact.
#[must_use]
pub fn driver_compliant<T: Real>() -> ClubSpec<T> {
    ClubSpec {
        contact: FITTED_CONTACT.cast(),
        ..driver()
    }
}

/// The measured delivery of the reference shot: 45 m/s, square, centred.
#[must_use]
pub fn delivery<T: Real>() -> Delivery<T> {
    Delivery {
        club_speed_mps: lit(45.0),
        attack_angle_rad: T::zero(),
        club_path_rad: T::zero(),
        face_angle_rad: T::zero(),
        dynamic_loft_rad: deg(lit(10.5)),
        lie_rad: T::zero(),
        club_spin_radps: Vector3::zeros(),
        location: FaceLocation {
            height_m: T::zero(),
            toe_m: T::zero(),
        },
    }
}

/// The impact of one shot: validate the club, build the strike, solve.
///
/// # Errors
/// The core's error.
#[inline(always)]
pub fn impact<T: Real>(
    club: &ClubSpec<T>,
    delivery: &Delivery<T>,
    solver: Solver,
) -> Result<ImpactOutcome<T>> {
    let club = club.validate()?;
    let strike = delivery.strike(&club)?;
    impact::solve(&club, &Ball::standard(), &strike, solver)
}

/// The flight of the ball the impact launched, through `scene`.
///
/// # Errors
/// The core's error.
#[inline(never)]
pub fn flight<T: Real>(
    hit: &ImpactOutcome<T>,
    scene: &Scene<T>,
    integrator: &Integrator<T>,
) -> Result<FlightOutcome<T>> {
    flight::fly(&Ball::standard(), &hit.ball, scene, integrator, None)
}

/// A full shot: validate the club, prepare the scene, then what the core's
/// [`carry_core::shot::play`] does (strike → impact → flight). Inlined into its caller,
/// so that a constant `solver` leaves only that solver in the caller's code.
///
/// # Errors
/// The core's error.
#[inline(always)]
pub fn full<T: Real>(
    club: &ClubSpec<T>,
    delivery: &Delivery<T>,
    solver: Solver,
    scene: &Scene<T>,
    integrator: &Integrator<T>,
) -> Result<(ImpactOutcome<T>, FlightOutcome<T>)> {
    let club = club.validate()?;
    let ball = Ball::standard();
    let scene = scene.prepare(&ball)?;
    // The same steps as `carry_core::shot::play`, spelled out so that a constant solver
    // is visible to the optimiser: `play` takes it at run time and links both solvers.
    let strike = delivery.strike(&club)?;
    let hit = impact::solve(&club, &ball, &strike, solver)?;
    let flight = scene.fly(&hit.ball, integrator, None)?;
    Ok((hit, flight))
}
