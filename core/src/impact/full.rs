//! The full system: 15 unknowns `x = [V_c, Ω_c, V_b, Ω_b, P]` and 15 linear equations,
//! assembled on a fixed-size `SMatrix<T, 15, 15>` and solved by Gaussian elimination.
//!
//! ```text
//! rows 0–2   m_c V_c + P             = m_c v_c
//! rows 3–5   I_c Ω_c + [r_imp]× P    = I_c ω_c
//! rows 6–8   m_b V_b − P             = m_b v_b
//! rows 9–11  I_b Ω_b − [r_ball]× P   = I_b ω_b
//! row  12    nᵀ u                    = −e n·u⁰
//! rows 13–14 t_iᵀ u                  = 0
//! u = V_b − [r_ball]× Ω_b − V_c + [r_imp]× Ω_c
//! ```
//!
//! Seed contact only ([`super::ContactLaw::Rolling`]): the compliant law is piecewise (friction
//! cone, energy bound), and its branch is decided from the collision matrix `K` of the
//! reduced form; a 15×15 version would re-solve that decision, not check it independently.
//! Asking for it ([`super::solve`]) is a typed error.

use super::{PostImpact, Problem};
use crate::error::Result;
use crate::geometry::{cross_matrix, tangents};
use crate::linalg::{Pivoting, solve_gauss};
use crate::real::Real;
use nalgebra::{Matrix3, SMatrix, SVector, Vector3};

/// Size of the full system.
pub const N: usize = 15;

/// The 15×15 matrix and right-hand side of `problem`, with the tangents of
/// [`tangents`] completing the contact frame.
#[must_use]
pub fn assemble<T: Real>(problem: &Problem<T>) -> (SMatrix<T, N, N>, SVector<T, N>) {
    let (t1, t2) = tangents(&problem.contact.normal);
    assemble_in_frame(problem, &t1, &t2)
}

/// The 15×15 system with a caller-chosen tangent pair `t1, t2` (unit, orthogonal to each
/// other and to n). The solution does not depend on the choice.
#[must_use]
pub fn assemble_in_frame<T: Real>(
    problem: &Problem<T>,
    t1: &Vector3<T>,
    t2: &Vector3<T>,
) -> (SMatrix<T, N, N>, SVector<T, N>) {
    let c = &problem.contact;
    let (mc, mb, ib) = (
        problem.club_mass_kg,
        problem.ball_mass_kg,
        problem.ball_inertia_kgm2,
    );
    let eye = Matrix3::<T>::identity();
    let rc = cross_matrix(&c.club_lever_m);
    let rb = cross_matrix(&c.ball_lever_m);
    let mut a = SMatrix::<T, N, N>::zeros();
    let mut b = SVector::<T, N>::zeros();
    // linear and angular impulse–momentum of club and ball
    a.fixed_view_mut::<3, 3>(0, 0).copy_from(&(eye * mc));
    a.fixed_view_mut::<3, 3>(0, 12).copy_from(&eye);
    a.fixed_view_mut::<3, 3>(3, 3)
        .copy_from(&c.club_inertia_kgm2);
    a.fixed_view_mut::<3, 3>(3, 12).copy_from(&rc);
    a.fixed_view_mut::<3, 3>(6, 6).copy_from(&(eye * mb));
    a.fixed_view_mut::<3, 3>(6, 12).copy_from(&(-eye));
    a.fixed_view_mut::<3, 3>(9, 9).copy_from(&(eye * ib));
    a.fixed_view_mut::<3, 3>(9, 12).copy_from(&(-rb));
    b.fixed_rows_mut::<3>(0)
        .copy_from(&(problem.club.velocity_mps * mc));
    b.fixed_rows_mut::<3>(3)
        .copy_from(&(c.club_inertia_kgm2 * problem.club.spin_radps));
    b.fixed_rows_mut::<3>(6)
        .copy_from(&(problem.ball.velocity_mps * mb));
    b.fixed_rows_mut::<3>(9)
        .copy_from(&(problem.ball.spin_radps * ib));
    // contact conditions along n, t1, t2: rows Dᵀ u with D = [n t1 t2], written as one
    // constant-offset block (no runtime row index: no bounds check at any opt-level)
    let d = Matrix3::from_rows(&[c.normal.transpose(), t1.transpose(), t2.transpose()]);
    let target = problem.target_velocity_mps();
    a.fixed_view_mut::<3, 3>(12, 0).copy_from(&(-d));
    a.fixed_view_mut::<3, 3>(12, 3).copy_from(&(d * rc));
    a.fixed_view_mut::<3, 3>(12, 6).copy_from(&d);
    a.fixed_view_mut::<3, 3>(12, 9).copy_from(&(-(d * rb)));
    b.fixed_rows_mut::<3>(12)
        .copy_from(&Vector3::new(c.normal.dot(&target), T::zero(), T::zero()));
    (a, b)
}

/// Solves the full system with `pivoting`.
///
/// # Errors
/// [`crate::Error::Singular`] when a pivot falls below the scale-aware threshold.
// Out of line on soft-float MCUs: the 15×15 system's frame is then not reserved by every
// `impact::solve` (the spin-axis share's path holds two of those on the micro:bit's 16 KiB
// stack). Inlined elsewhere: out of line it costs the M4F's reduced solve 150 instructions.
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), inline(never))]
pub fn solve<T: Real>(problem: &Problem<T>, pivoting: Pivoting) -> Result<PostImpact<T>> {
    let (a, b) = assemble(problem);
    solve_system(a, &b, pivoting)
}

/// Solves an assembled system (e.g. from [`assemble_in_frame`]).
///
/// # Errors
/// [`crate::Error::Singular`] when a pivot falls below the scale-aware threshold.
pub fn solve_system<T: Real>(
    mut a: SMatrix<T, N, N>,
    b: &SVector<T, N>,
    pivoting: Pivoting,
) -> Result<PostImpact<T>> {
    let x = solve_gauss(&mut a, b, pivoting)?;
    let v = |i: usize| Vector3::new(x[i], x[i + 1], x[i + 2]);
    Ok(PostImpact {
        club_velocity_mps: v(0),
        club_spin_radps: v(3),
        ball_velocity_mps: v(6),
        ball_spin_radps: v(9),
        impulse_ns: v(12),
    })
}
