//! The modern family's spin laws in the flight loop's form: the lift's two saturating
//! components and the spin drag tied to the main one, as one piecewise polynomial.
//!
//! Each component `a·sat(S/S_c)·V`, `sat(u) = 1 − (1 − min(u, 1))⁴`, is, with `u = S/S_c =
//! κ/V` (`κ = (R/S_c)·s`) and below its saturation,
//!
//! ```text
//! sat(u)·V = 4u·V − 6u²·V + 4u³·V − u⁴·V = κ·(4 + 4u²) + V·(−6u² − u⁴)
//! ```
//!
//! With `y = S/S_first` for the component that saturates first and `ρ = S_first/S_c ≤ 1`
//! (`u = ρ·y`), the sum of the components on each piece is again `κ·(α₁ + α₃u²) + V·(α₀ +
//! u²·(α₂ + α₄u²))`, with coefficients fixed when the scene is prepared:
//!
//! * `y < 1`, both rising: `u = y`, `α₁ = Σ 4aρ`, `α₃ = Σ 4aρ³`, `α₂ = −Σ 6aρ²`,
//!   `α₄ = −Σ aρ⁴`, `α₀ = 0`;
//! * `y ≥ 1 > x`, the first saturated: `u = x = ρ_second·y`, the second's quartic and
//!   `α₀ = a_first`;
//! * both saturated: `α₀ = Σ a`, the rest 0.
//!
//! So the two components cost one polynomial, as one did: `u² = κ²/V²` needs one division,
//! by `V²`, beside the square root, and `V` joins in one multiply–add after it.

use crate::real::{Real, lit};

/// `κ·(α₁ + α₃u²) + V·(α₀ + u²·(α₂ + α₄u²))`: coefficients `[α₀, α₁, α₂, α₃, α₄]`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(crate) struct Poly<T>(pub(crate) [T; 5]);

impl<T: Real> Poly<T> {
    /// `(P, Q)` with the law `= P + Q·V`, at `κ` and `u²`.
    #[inline(always)]
    fn at(&self, kappa: T, u_sq: T) -> (T, T) {
        let [a0, a1, a2, a3, a4] = self.0;
        (kappa * (a1 + a3 * u_sq), a0 + u_sq * (a2 + a4 * u_sq))
    }

    /// `V·∂(law)/∂V = −2κα₃u² + V·(α₀ − α₂u² − 3α₄u⁴)` (from `∂(u²)/∂V·V = −2u²`).
    #[inline(always)]
    fn speed_derivative(&self, kappa: T, u_sq: T, speed: T) -> T {
        let [a0, _, a2, a3, a4] = self.0;
        let two = lit::<T>(2.0);
        -(two * kappa * a3 * u_sq) + speed * (a0 - u_sq * (a2 + lit::<T>(3.0) * a4 * u_sq))
    }
}

/// One piece of the spin laws: the lift's and the spin drag's polynomials.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(crate) struct Piece<T> {
    pub(crate) lift: Poly<T>,
    pub(crate) drag: Poly<T>,
}

/// The spin laws `A·C_L(S)·V` and `A·C_D,spin(S)·V` (1/s) of the modern family, piecewise.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(crate) struct SpinLaws<T> {
    /// `R/S_first` (m): `κ = per_spin·s`, `y = κ/V`.
    pub(crate) per_spin: T,
    /// `ρ_second = S_first/S_second` and its square.
    pub(crate) second: T,
    pub(crate) second_sq: T,
    /// Both rising (`y < 1`).
    pub(crate) rising: Piece<T>,
    /// The first saturated (`y ≥ 1 > x`), in `x = ρ_second·y` and `κ·ρ_second`.
    pub(crate) second_rising: Piece<T>,
    /// Both saturated: `α₀` of the lift and of the drag.
    pub(crate) lift_saturated: T,
    pub(crate) drag_saturated: T,
}

/// A component `(lift amplitude, drag amplitude, S_c)`: `a_L·sat(S/S_c)`, `a_D·sat(S/S_c)`.
type Component<T> = (T, T, T);

/// The quartic's coefficients `[α₀..α₄]` of one component with `u = ρ·y`, times `a`.
fn quartic<T: Real>(a: T, rho: T) -> [T; 5] {
    let rho_sq = rho * rho;
    let four = lit::<T>(4.0);
    [
        T::zero(),
        four * a * rho,
        -(lit::<T>(6.0) * a * rho_sq),
        four * a * rho * rho_sq,
        -(a * rho_sq * rho_sq),
    ]
}

fn add<T: Real>(x: [T; 5], y: [T; 5]) -> [T; 5] {
    core::array::from_fn(|i| x[i] + y[i])
}

impl<T: Real> SpinLaws<T> {
    /// The laws of two components (per unit mass, `A` folded into the amplitudes) on a ball
    /// of radius `radius` (m). Saturation spins must be positive (validated by the model).
    pub(crate) fn new(radius: T, one: Component<T>, other: Component<T>) -> Self {
        let (first, second) = if one.2 <= other.2 {
            (one, other)
        } else {
            (other, one)
        };
        let rho = first.2 / second.2;
        let both = |pick: fn(&Component<T>) -> T| {
            add(quartic(pick(&first), T::one()), quartic(pick(&second), rho))
        };
        let mut second_lift = quartic(second.0, T::one());
        second_lift[0] = first.0;
        let mut second_drag = quartic(second.1, T::one());
        second_drag[0] = first.1;
        Self {
            per_spin: radius / first.2,
            second: rho,
            second_sq: rho * rho,
            rising: Piece {
                lift: Poly(both(|c| c.0)),
                drag: Poly(both(|c| c.1)),
            },
            second_rising: Piece {
                lift: Poly(second_lift),
                drag: Poly(second_drag),
            },
            lift_saturated: first.0 + second.0,
            drag_saturated: first.1 + second.1,
        }
    }

    /// The piece, `κ` and `u²` at spin `s` and `V² = speed_sq`; `None` past both
    /// saturations (also at `V = 0`, where `y² = ∞` or NaN). With the spin's square
    /// `spin_sq` given (a hop's, from the spin vector), `κ² = (R/S_first)²·s²` from it: the
    /// division does not wait on the square root that gives `s`.
    #[inline(always)]
    fn piece(&self, spin: T, spin_sq: Option<T>, speed_sq: T) -> Option<(&Piece<T>, T, T)> {
        let kappa = self.per_spin * spin;
        let kappa_sq = match spin_sq {
            Some(q) => (self.per_spin * self.per_spin) * q,
            None => kappa * kappa,
        };
        let y_sq = kappa_sq / speed_sq;
        if y_sq < T::one() {
            Some((&self.rising, kappa, y_sq))
        } else {
            let x_sq = self.second_sq * y_sq;
            (x_sq < T::one()).then_some((&self.second_rising, self.second * kappa, x_sq))
        }
    }

    /// `((P_L, Q_L), (P_D, Q_D))`: `A·C_L·V = P_L + Q_L·V` and `A·C_D,spin·V = P_D + Q_D·V`
    /// at spin `s` (its square `spin_sq`, if known: [`SpinLaws::piece`]) and `V² = speed_sq`,
    /// from `V²` alone.
    #[inline(always)]
    pub(crate) fn at(&self, spin: T, spin_sq: Option<T>, speed_sq: T) -> ((T, T), (T, T)) {
        match self.piece(spin, spin_sq, speed_sq) {
            Some((p, kappa, u_sq)) => (p.lift.at(kappa, u_sq), p.drag.at(kappa, u_sq)),
            None => (
                (T::zero(), self.lift_saturated),
                (T::zero(), self.drag_saturated),
            ),
        }
    }

    /// `(V·∂(A·C_L·V)/∂V, V·∂(A·C_D,spin·V)/∂V)` at spin `s` (its square `spin_sq`, if
    /// known), speed `V` and `V² = speed_sq`.
    pub(crate) fn speed_derivatives(
        &self,
        spin: T,
        spin_sq: Option<T>,
        speed: T,
        speed_sq: T,
    ) -> (T, T) {
        match self.piece(spin, spin_sq, speed_sq) {
            Some((p, kappa, u_sq)) => (
                p.lift.speed_derivative(kappa, u_sq, speed),
                p.drag.speed_derivative(kappa, u_sq, speed),
            ),
            None => (self.lift_saturated * speed, self.drag_saturated * speed),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The piecewise polynomial against the components summed directly, on every piece and
    /// with either component saturating first.
    #[test]
    fn is_the_sum_of_the_saturating_components() {
        let sat = |u: f64| 1.0 - (1.0 - u.min(1.0)).powi(4);
        let r = 0.021_335;
        for (one, other) in [
            ((0.3, 0.2, 1.0), (0.1, 0.0, 0.2)),
            ((0.1, 0.0, 0.2), (0.3, 0.2, 1.0)),
            ((0.3, 0.15, 0.5), (0.2, 0.05, 0.5)),
        ] {
            let laws = SpinLaws::new(r, one, other);
            for (v, s) in [(60.0, 200.0), (30.0, 500.0), (20.0, 900.0), (5.0, 900.0)] {
                let big_s = r * s / v;
                let direct = |i: usize| {
                    let pick = |c: (f64, f64, f64)| if i == 0 { c.0 } else { c.1 };
                    (pick(one) * sat(big_s / one.2) + pick(other) * sat(big_s / other.2)) * v
                };
                let ((pl, ql), (pd, qd)) = laws.at(s, None, v * v);
                assert!((pl + ql * v - direct(0)).abs() < 1e-12, "{v} {s}");
                assert!((pd + qd * v - direct(1)).abs() < 1e-12, "{v} {s}");
                // The speed derivative against a central difference.
                let h = 1e-6 * v;
                let law = |v: f64| {
                    let ((pl, ql), (pd, qd)) = laws.at(s, None, v * v);
                    (pl + ql * v, pd + qd * v)
                };
                let ((l1, d1), (l0, d0)) = (law(v + h), law(v - h));
                let (dl, dd) = laws.speed_derivatives(s, None, v, v * v);
                assert!((dl - v * (l1 - l0) / (2.0 * h)).abs() < 1e-6, "{v} {s}");
                assert!((dd - v * (d1 - d0) / (2.0 * h)).abs() < 1e-6, "{v} {s}");
            }
        }
    }
}
