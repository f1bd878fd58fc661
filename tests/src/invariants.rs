//! Physical invariants of an impact (PHYSICS.md): linear momentum and angular momentum about
//! any fixed point are conserved; kinetic energy never increases for 0 ≤ e ≤ 1.

use carry_core::impact::ImpactOutcome;
use carry_core::{Ball, ClubHead, Real, Strike};
use nalgebra::Vector3;

/// Momenta and energy of the two bodies (f64 for the bookkeeping).
#[derive(Debug, Clone, Copy)]
pub struct Budget {
    /// Total linear momentum (kg·m/s).
    pub linear: Vector3<f64>,
    /// Total angular momentum about the chosen fixed point (kg·m²/s).
    pub angular: Vector3<f64>,
    /// Total kinetic energy (J).
    pub energy: f64,
}

fn f<T: Real>(v: &Vector3<T>) -> Vector3<f64> {
    v.map(carry_core::real::to_f64)
}

/// Momenta and energy before (`after = false`) or after the impact, about `point` (m, G).
/// The club's CoM is placed at the origin, the ball's centre at `r_imp − r_ball`.
#[must_use]
pub fn budget<T: Real>(
    club: &ClubHead<T>,
    ball: &Ball<T>,
    strike: &Strike<T>,
    out: &ImpactOutcome<T>,
    after: bool,
    point: Vector3<f64>,
) -> Budget {
    let to = carry_core::real::to_f64::<T>;
    let (mc, mb, ib) = (
        to(club.mass_kg()),
        to(ball.mass_kg()),
        to(ball.inertia_kgm2()),
    );
    let ic = out.contact.club_inertia_kgm2.map(to);
    let (vc, wc, vb, wb) = if after {
        (
            f(&out.club.velocity_mps),
            f(&out.club.spin_radps),
            f(&out.ball.velocity_mps),
            f(&out.ball.spin_radps),
        )
    } else {
        let c = strike.club();
        let b = strike.ball();
        (
            f(&c.velocity_mps),
            f(&c.spin_radps),
            f(&b.velocity_mps),
            f(&b.spin_radps),
        )
    };
    let xc = Vector3::zeros() - point;
    let xb = f(&out.contact.club_lever_m) - f(&out.contact.ball_lever_m) - point;
    Budget {
        linear: vc * mc + vb * mb,
        angular: xc.cross(&(vc * mc)) + ic * wc + xb.cross(&(vb * mb)) + wb * ib,
        energy: 0.5
            * (mc * vc.norm_squared()
                + wc.dot(&(ic * wc))
                + mb * vb.norm_squared()
                + ib * wb.norm_squared()),
    }
}
