//! The whole shot, end to end: club delivery → impact → launch → flight → outcome.
//!
//! A thin composition of [`crate::impact::solve`] and [`PreparedScene::fly`]: the ball
//! leaves the face with the impact's velocity and spin and flies through the scene.

use crate::ball::Ball;
use crate::club::ClubHead;
use crate::delivery::Delivery;
use crate::error::Result;
use crate::flight::{FlightOutcome, Integrator, Recorder};
use crate::impact::{self, ImpactOutcome, Solver};
use crate::real::Real;
use crate::scene::PreparedScene;

/// Numerical settings of a shot: impact solver and flight integrator.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Fidelity<T> {
    /// How the impact is solved.
    pub solver: Solver,
    /// How the flight is integrated.
    pub integrator: Integrator<T>,
}

impl<T: Real> Default for Fidelity<T> {
    /// The documented defaults: reduced impact solver, default-fidelity flight
    /// ([`Integrator::default`]: carry within 1 mm in f64, 1 cm in f32).
    fn default() -> Self {
        Self {
            solver: Solver::Reduced,
            integrator: Integrator::default(),
        }
    }
}

/// Impact and flight of one shot.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ShotOutcome<T: Real> {
    /// The impact: ball and club after impact, impulse, launch metrics.
    pub impact: ImpactOutcome<T>,
    /// The flight of the launched ball.
    pub flight: FlightOutcome<T>,
}

/// Plays `delivery` with `club` on `ball` through the prepared `scene`.
///
/// # Errors
/// Any error of [`Delivery::strike`], [`impact::solve`] or [`PreparedScene::fly`].
pub fn play<T: Real>(
    club: &ClubHead<T>,
    ball: &Ball<T>,
    delivery: &Delivery<T>,
    scene: &PreparedScene<T>,
    fidelity: &Fidelity<T>,
    recorder: Option<&mut Recorder<'_, T>>,
) -> Result<ShotOutcome<T>> {
    // The strike and the impact are read where they were returned (a `?` moves them out
    // of their `Result`: two copies of the impact's few hundred bytes, ≈ 650 instructions
    // of `memcpy` on a Cortex-M4F, docs/performance.md); the impact is copied once, into
    // the outcome.
    let strike = delivery.strike(club);
    let strike = match &strike {
        Ok(s) => s,
        Err(e) => return Err(*e),
    };
    let impact = impact::solve(club, ball, strike, fidelity.solver);
    let hit = match &impact {
        Ok(i) => i,
        Err(e) => return Err(*e),
    };
    let flight = scene.fly(&hit.ball, &fidelity.integrator, recorder)?;
    Ok(ShotOutcome {
        impact: *hit,
        flight,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::club::ClubSpec;
    use crate::scene::Scene;

    /// PHYSICS.md's reference: the default driver at 45 m/s carries 199.683 m with the
    /// seed's aerodynamics.
    #[test]
    fn reference_driver_shot() {
        let Ok(club) = ClubSpec::<f64>::driver().validate() else {
            panic!()
        };
        let ball = Ball::standard();
        let seed = Scene {
            aero: crate::aero::AeroModel::quintavalla(),
            ..Scene::default()
        };
        let Ok(scene) = seed.prepare(&ball) else {
            panic!()
        };
        let d = Delivery::square(45.0, &club);
        let Ok(out) = play(&club, &ball, &d, &scene, &Fidelity::default(), None) else {
            panic!()
        };
        assert!(
            (out.flight.carry_m - 199.683).abs() < 1e-3,
            "{}",
            out.flight.carry_m
        );
        assert!((out.impact.launch.ball_speed_mps - 65.880).abs() < 1e-3);
    }
}
