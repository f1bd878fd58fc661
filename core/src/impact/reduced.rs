//! The exact reduced form: the 3×3 collision matrix (Petersen & McPhee; Brach, "Mechanical
//! Impact Dynamics", 1991):
//!
//! ```text
//! K = (1/m_c + 1/m_b)·I − [r_imp]× I_c⁻¹ [r_imp]× − [r_ball]× I_b⁻¹ [r_ball]×
//! K P = −u⁰ − e (n·u⁰) n
//! ```
//! `K` maps an impulse on the ball to the change of the contact-point relative velocity;
//! it is symmetric positive definite for positive masses and inertias, so LDLᵀ solves it.
//! The right-hand side above is the seed's rolling contact; the compliant law
//! ([`super::contact_law`]) computes its impulse from the same `K`.

use super::contact_law::CompliantContact;
use super::{PostImpact, Problem};
use crate::error::Result;
use crate::geometry::cross_matrix;
use crate::linalg::solve_spd3;
use crate::real::Real;
use nalgebra::Matrix3;

/// The collision matrix `K` of `problem`.
#[must_use]
#[inline(always)]
pub fn collision_matrix<T: Real>(problem: &Problem<T>) -> Matrix3<T> {
    let c = &problem.contact;
    let rc = cross_matrix(&c.club_lever_m);
    let rb = cross_matrix(&c.ball_lever_m);
    let inv_mass = T::one() / problem.club_mass_kg + T::one() / problem.ball_mass_kg;
    let k = Matrix3::from_diagonal_element(inv_mass)
        - rc * c.club_inverse_inertia * rc
        - rb * rb / problem.ball_inertia_kgm2;
    // symmetric by construction; symmetrise the rounding
    (k + k.transpose()) * nalgebra::convert::<f64, T>(0.5)
}

/// Solves the reduced form with the seed's rolling contact.
///
/// # Errors
/// [`crate::Error::Singular`] when `K` is not numerically positive definite.
pub fn solve<T: Real>(problem: &Problem<T>) -> Result<PostImpact<T>> {
    let k = collision_matrix(problem);
    let rhs = problem.target_velocity_mps() - problem.approach_mps;
    let p = solve_spd3(&k, &rhs)?;
    Ok(problem.apply_impulse(&p))
}

/// Solves the reduced form with the compliant contact `law` (its impulse from the same `K`).
///
/// # Errors
/// [`crate::Error::Singular`] when `K` is not numerically positive definite.
pub fn solve_compliant<T: Real>(
    problem: &Problem<T>,
    law: &CompliantContact<T>,
) -> Result<PostImpact<T>> {
    let k = collision_matrix(problem);
    let (p, _) = law.impulse(
        &k,
        &problem.approach_mps,
        &problem.contact.normal,
        problem.restitution,
    )?;
    Ok(problem.apply_impulse(&p))
}
