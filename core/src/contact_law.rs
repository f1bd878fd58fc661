//! The face–ball contact *law*: which impulse the contact transmits (the geometry is
//! [`crate::contact`]). A property of the face–ball pair, held by the club like its COR.
//!
//! * [`ContactLaw::Rolling`] — the seed's (Petersen & McPhee): the ball leaves the face
//!   rolling without slipping, `t·u = 0`, with Newton's restitution `n·u = −e n·u⁰`. Solved
//!   as `K P = −u⁰ − e (n·u⁰) n`; bit for bit the seed's model.
//! * [`ContactLaw::Compliant`] — a Coulomb-limited contact with tangential compliance and
//!   speed-dependent restitution, solved algebraically in the same impulse–momentum frame
//!   (Brach's friction-ratio treatment, R. M. Brach, "Mechanical Impact Dynamics", Wiley
//!   1991, ch. 7–8, with Stronge's energetic bound, W. J. Stronge, "Impact Mechanics", CUP
//!   2000, §3.4):
//!
//! ```text
//! v_n = −n·u⁰ > 0,   u⁰_t = u⁰ + v_n n,   tan ψ = |u⁰_t| / v_n          (obliquity ψ)
//! e(v_n) = clamp(e_c − k_e (v_n − 48.77 m/s), 0, 1)                      (Penner 2001)
//! e_t(ψ) = clamp(e_t0 + s_t tan ψ, 0, e_t,max)                            (Cross 2002/2005)
//! grip:   u* = e v_n n − e_t u⁰_t,   P = λ K⁻¹u* − K⁻¹u⁰,
//!         λ = min(1, ‖u⁰‖/‖u*‖) in the energy norm ‖x‖² = xᵀK⁻¹x
//! slide, when |P_t| > μ P_n (outside the friction cone):
//!         d = −u⁰_t/|u⁰_t|,  q = n + μ d,  P = P_n q,
//!         P_n = min((1+e) v_n / (nᵀK q),  −2 q·u⁰ / (qᵀK q))
//! ```
//!
//! **Energy never increases** (proof). With `u = u⁰ + K P` the work of an impulse is
//! `ΔT = ½ P·(u⁰ + u) = ½ (‖u‖² − ‖u⁰‖²)` in the energy norm (K symmetric positive
//! definite). Gripping, `u = λ u*` and `λ‖u*‖ ≤ ‖u⁰‖`. Sliding, `ΔT(P_n) = P_n q·u⁰ +
//! ½ P_n² qᵀKq ≤ 0` for `0 ≤ P_n ≤ −2 q·u⁰ / qᵀKq`, and `q·u⁰ = −v_n − μ|u⁰_t| < 0`.
//! The bound λ is active only when the restitution operator, anisotropic in a frame where
//! K couples normal and tangential directions, would return more energy than the impact
//! stores (the seed's +0.94 % at the face edge); it then scales both restitutions alike.
//!
//! Assumptions: one instantaneous impulse (no slip reversal inside the impact); the slip
//! direction is the initial one (Brach; the grip branch covers the cases where slip would
//! stop); tangential restitution acts only when the ball grips (Cross's grip–slip picture:
//! the ball's tangential elastic deformation springs back and the ball leaves with more
//! spin than rolling); friction is isotropic. Sources: R. Cross, "Grip-slip behavior of a
//! bouncing ball", Am. J. Phys. 70 (2002) 1093, and "Bounce of a spinning ball near normal
//! incidence", Am. J. Phys. 73 (2005) 914 (tangential COR up to ~0.3–0.5 where the ball
//! grips, falling with obliquity as it slides); Arakawa et al., oblique impacts of golf
//! balls (spin above the rolling value); Caldwell & McPhee, Sports Eng. 27:16 (2024)
//! (μ ≈ 0.36 driver, ≈ 0.5 7-iron); D. Penner, "The physics of golf: the optimum loft of a
//! driver", Am. J. Phys. 69 (2001) 563 (e ≈ 0.86 − 0.0029 v_n).

use crate::error::{Error, Field, Reason, Result};
use crate::linalg::Ldl3;
use crate::real::{Real, length, lit};
use crate::validate::{finite, in_range, non_negative};
use nalgebra::{Matrix3, Vector3};

/// Normal relative speed of the USGA/R&A face COR test (160 ft/s), at which a club's
/// rated COR `e_c` applies (m/s).
pub const COR_TEST_SPEED_MPS: f64 = 48.768;

/// How the face and the ball interact tangentially.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum ContactLaw<T> {
    /// The seed's rigid contact: rolling without slipping, constant restitution.
    #[default]
    Rolling,
    /// Friction-limited, tangentially compliant contact with speed-dependent restitution.
    Compliant(CompliantContact<T>),
}

/// Parameters of [`ContactLaw::Compliant`] (dimensionless unless stated).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct CompliantContact<T> {
    /// Coulomb friction coefficient μ ≥ 0; `+∞` never slides.
    pub friction: T,
    /// Tangential restitution law's value at normal incidence e_t0, in [−1, 1]; the law
    /// `e_t0 + s_t tan ψ` is clamped into [0, 1] (0: the ball leaves rolling), so a negative
    /// e_t0 with a positive slope is an overshoot that starts at obliquity tan ψ = −e_t0/s_t.
    pub tangential_restitution: T,
    /// Change of e_t per unit tan ψ (obliquity ψ from the normal); finite, any sign.
    pub tangential_restitution_slope: T,
    /// Ceiling e_t,max of the tangential restitution, in [0, 1] (1: the line alone). The
    /// line rises with obliquity while the ball grips; the elastic energy its tangential
    /// spring can return is bounded (Cross 2002 measures e_t up to 0.3–0.5 where a ball
    /// grips, falling once it slides: Maw, Barber & Fawcett 1976), so the law holds the
    /// plateau of that hump rather than extrapolating the line to steep wedges.
    pub tangential_restitution_max: T,
    /// Fall of the normal restitution per m/s of normal speed above
    /// [`COR_TEST_SPEED_MPS`], k_e ≥ 0 (s/m).
    pub restitution_speed_slope_spm: T,
}

/// Which branch of the compliant law produced the impulse.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Regime {
    /// The ball grips (inside the friction cone), restitution as asked.
    Grip,
    /// The ball grips; both restitutions scaled down by the energy bound λ < 1.
    GripEnergyBound,
    /// The ball slides on the cone, normal impulse from restitution.
    Slide,
    /// The ball slides; the normal impulse limited by the energy bound.
    SlideEnergyBound,
}

impl<T: Real> ContactLaw<T> {
    /// Checks the parameters (once, when the club is validated).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the first bad parameter: μ NaN or negative, e_t
    /// e_t0
    /// outside [−1, 1], a non-finite slope, e_t,max outside [0, 1], a negative speed slope.
    pub fn validate(&self) -> Result<Self> {
        match self {
            Self::Rolling => Ok(Self::Rolling),
            Self::Compliant(c) => c.validate().map(Self::Compliant),
        }
    }
}

impl<T: Real> CompliantContact<T> {
    /// Checks the parameters.
    ///
    /// # Errors
    /// As [`ContactLaw::validate`].
    pub fn validate(&self) -> Result<Self> {
        let mu = self.friction;
        #[allow(clippy::eq_op)]
        if mu != mu {
            return Err(Error::invalid(Field::Friction, Reason::NotFinite));
        }
        if mu < T::zero() {
            return Err(Error::invalid(Field::Friction, Reason::Negative));
        }
        Ok(Self {
            friction: mu,
            tangential_restitution: in_range(
                self.tangential_restitution,
                -T::one(),
                T::one(),
                Field::TangentialRestitution,
            )?,
            tangential_restitution_slope: finite(
                self.tangential_restitution_slope,
                Field::TangentialRestitutionSlope,
            )?,
            tangential_restitution_max: in_range(
                self.tangential_restitution_max,
                T::zero(),
                T::one(),
                Field::TangentialRestitutionMax,
            )?,
            restitution_speed_slope_spm: non_negative(
                self.restitution_speed_slope_spm,
                Field::RestitutionSpeedSlope,
            )?,
        })
    }

    /// Normal restitution at normal speed `v_n` for a club rated `e_c`:
    /// `clamp(e_c − k_e (v_n − 48.77), 0, 1)`.
    #[must_use]
    pub fn normal_restitution(&self, rated: T, normal_speed_mps: T) -> T {
        let e =
            rated - self.restitution_speed_slope_spm * (normal_speed_mps - lit(COR_TEST_SPEED_MPS));
        clamp01(e)
    }

    /// Tangential restitution at obliquity `tan ψ`: `clamp(e_t0 + s_t tan ψ, 0, e_t,max)`.
    #[must_use]
    pub fn tangential_restitution_at(&self, tan_obliquity: T) -> T {
        let line = self.tangential_restitution + self.tangential_restitution_slope * tan_obliquity;
        line.max(T::zero()).min(self.tangential_restitution_max)
    }

    /// The impulse on the ball for collision matrix `k`, approach velocity `u0` (contact
    /// point of the ball relative to the club's) and unit normal `n` (out of the face), for
    /// a club rated `e_c`. See the module docs for the equations.
    ///
    /// # Errors
    /// [`Error::Singular`] when `k` is not numerically positive definite or a result is not
    /// finite; [`Error::NoApproach`] when `n·u0 ≥ 0`.
    pub fn impulse(
        &self,
        k: &Matrix3<T>,
        u0: &Vector3<T>,
        n: &Vector3<T>,
        rated_restitution: T,
    ) -> Result<(Vector3<T>, Regime)> {
        let zero = T::zero();
        let v_n = -n.dot(u0);
        if !(v_n > zero) {
            return Err(Error::NoApproach);
        }
        let ldl = Ldl3::factor(k)?;
        let e = self.normal_restitution(rated_restitution, v_n);
        let u0_t = u0 + n * v_n;
        let slip = length(&u0_t);
        let e_t = self.tangential_restitution_at(slip / v_n);
        // grip: target u* = e v_n n − e_t u⁰_t + (1 − g) c P_n, scaled into the energy bound
        let target = n * (e * v_n) - u0_t * e_t;
        let a = ldl.solve(&target)?;
        let b = ldl.solve(u0)?;
        let (a, target) = self.with_gear_slip(k, &ldl, n, a, &b, target, e_t)?;
        let (target_energy, approach_energy) = (target.dot(&a), u0.dot(&b));
        let (lambda, bound) = if target_energy > approach_energy {
            ((approach_energy / target_energy).root(), true)
        } else {
            (T::one(), false)
        };
        let grip = a * lambda - b;
        let p_n = n.dot(&grip);
        let p_t = grip - n * p_n;
        let p_t_norm = length(&p_t);
        let mu = self.friction;
        // NaN-safe towards gripping: μ = ∞ (∞·0 = NaN) always grips
        let grips = !mu.is_finite() || !(p_t_norm > mu * p_n);
        if grips {
            let regime = if bound {
                Regime::GripEnergyBound
            } else {
                Regime::Grip
            };
            return finite_impulse(grip, regime);
        }
        // slide: impulse on the cone, opposing the initial slip
        let d = if slip > zero {
            u0_t / -slip
        } else if p_t_norm > zero {
            p_t / p_t_norm
        } else {
            Vector3::zeros()
        };
        let q = n + d * mu;
        let kq = k * q;
        let qkq = q.dot(&kq);
        let nkq = n.dot(&kq);
        let bound_n = lit::<T>(-2.0) * q.dot(u0) / qkq;
        let (p_n, regime) = if nkq > zero {
            let from_restitution = (T::one() + e) * v_n / nkq;
            if from_restitution <= bound_n {
                (from_restitution, Regime::Slide)
            } else {
                (bound_n, Regime::SlideEnergyBound)
            }
        } else {
            (bound_n, Regime::SlideEnergyBound)
        };
        finite_impulse(q * p_n.max(zero), regime)
    }
}

impl<T: Real> CompliantContact<T> {
    /// The grip target with the part of the gear effect the ball's tangential spring does
    /// not pass on. `c = (I − n nᵀ) K n` is the tangential velocity of the club's contact
    /// point relative to the ball's per unit normal impulse (the head turning about its
    /// CG); the ball keeps the fraction `1 − g(e_t)` of `c P_n` as slip at separation:
    ///
    /// ```text
    /// u* = e v_n n − e_t u⁰_t + (1 − g) c P_n,   P = K⁻¹u* − K⁻¹u⁰,   P_n = n·P
    /// ⇒ P_n = n·(a − b) / (1 − (1 − g) n·K⁻¹c)     (a = K⁻¹(e v_n n − e_t u⁰_t), b = K⁻¹u⁰)
    /// ```
    /// with `n·K⁻¹c = 1 − (nᵀKn)(nᵀK⁻¹n) ≤ 0` (Cauchy–Schwarz), so the denominator is ≥ 1.
    /// Returns `(K⁻¹u*, u*)`.
    #[allow(clippy::too_many_arguments)]
    fn with_gear_slip(
        &self,
        k: &Matrix3<T>,
        ldl: &Ldl3<T>,
        n: &Vector3<T>,
        a: Vector3<T>,
        b: &Vector3<T>,
        target: Vector3<T>,
        e_t: T,
    ) -> Result<(Vector3<T>, Vector3<T>)> {
        let keep = T::one() - gear_transmission(e_t);
        if !(keep > T::zero()) {
            return Ok((a, target));
        }
        let kn = k * n;
        let c = kn - n * n.dot(&kn);
        let d = ldl.solve(&c)?;
        let p_n = n.dot(&(a - b)) / (T::one() - keep * n.dot(&d));
        let slip = keep * p_n;
        Ok((a + d * slip, target + c * slip))
    }
}

/// The fraction `g` of the rigid gear effect a ball with tangential restitution `e_t`
/// takes (`e_t` in [0, 1]; 1 at `e_t = 1`, 1/3 at `e_t = 0`).
///
/// A linear tangential spring at the contact (Cross, Am. J. Phys. 70 (2002) 1093;
/// Maw, Barber & Fawcett, Wear 38 (1976) 101), natural frequency `ω_t`, under a half-sine
/// normal force of frequency `ω_n = π/τ`, `r = ω_t/ω_n`. An initial slip `w₀` leaves as
/// `w₀ cos πr`, so `e_t = −cos πr`; a slip forced by the head's rotation, `c J_n(t)`,
/// leaves as `c P_n (1 + cos πr) / (2(1 − r²))`, the ball taking the rest:
///
/// ```text
/// g = 1 − (1 + cos πr) / (2 (1 − r²)),   r = 1 − x,   x = acos(e_t)/π ∈ [0, ½]
///   = 1 − (1 − e_t) / (2 x (2 − x))
/// ```
/// (the soft branch r ≤ 1; `r → ∞` is the rigid ball, g = 1; `r → 0` no gear effect).
#[must_use]
pub fn gear_transmission<T: Real>(e_t: T) -> T {
    let e_t = clamp01(e_t);
    let x = e_t.acos() / T::pi();
    if !(x > lit(1e-4)) {
        // 1 − e_t ≈ π²x²/2: g ≈ 1 − π²x/8
        return T::one() - T::pi() * T::pi() * x * lit(0.125);
    }
    T::one() - (T::one() - e_t) / (lit::<T>(2.0) * x * (lit::<T>(2.0) - x))
}

/// A finite impulse, or [`Error::Singular`]: a matrix that is not a collision matrix
/// (not symmetric positive definite) can make the energy scaling `√(u⁰ᵀK⁻¹u⁰ / u*ᵀK⁻¹u*)`
/// or the cone projection non-finite.
fn finite_impulse<T: Real>(p: Vector3<T>, regime: Regime) -> Result<(Vector3<T>, Regime)> {
    if p.iter().all(|x| x.is_finite()) {
        Ok((p, regime))
    } else {
        Err(Error::Singular)
    }
}

impl ContactLaw<f64> {
    /// This law in precision `T` (each parameter rounded to nearest).
    #[must_use]
    pub fn cast<T: Real>(&self) -> ContactLaw<T> {
        match self {
            Self::Rolling => ContactLaw::Rolling,
            Self::Compliant(c) => ContactLaw::Compliant(c.cast()),
        }
    }
}

impl CompliantContact<f64> {
    /// These parameters in precision `T` (each rounded to nearest).
    #[must_use]
    pub fn cast<T: Real>(&self) -> CompliantContact<T> {
        CompliantContact {
            friction: lit(self.friction),
            tangential_restitution: lit(self.tangential_restitution),
            tangential_restitution_slope: lit(self.tangential_restitution_slope),
            tangential_restitution_max: lit(self.tangential_restitution_max),
            restitution_speed_slope_spm: lit(self.restitution_speed_slope_spm),
        }
    }
}

fn clamp01<T: Real>(x: T) -> T {
    x.max(T::zero()).min(T::one())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn law(mu: f64, et: f64) -> CompliantContact<f64> {
        CompliantContact {
            friction: mu,
            tangential_restitution: et,
            tangential_restitution_slope: 0.0,
            tangential_restitution_max: 1.0,
            restitution_speed_slope_spm: 0.0,
        }
    }

    /// A ball (m, I = 0.4 m R²) against a rigid wall: K = diag(1/m, 3.5/m, 3.5/m) in the
    /// contact frame (n = x).
    fn wall() -> Matrix3<f64> {
        let m = 0.04593;
        Matrix3::from_diagonal(&Vector3::new(1.0 / m, 3.5 / m, 3.5 / m))
    }

    #[test]
    fn grip_reverses_tangential_velocity_by_e_t() {
        let (k, n) = (wall(), Vector3::x());
        let u0 = Vector3::new(-40.0, 10.0, 0.0);
        let Ok((p, r)) = law(f64::INFINITY, 0.3).impulse(&k, &u0, &n, 0.8) else {
            panic!()
        };
        assert_eq!(r, Regime::Grip);
        let u = u0 + k * p;
        assert!((u.x - 0.8 * 40.0).abs() < 1e-12);
        assert!((u.y + 0.3 * 10.0).abs() < 1e-12);
    }

    #[test]
    fn slides_on_the_cone_when_friction_is_low() {
        let (k, n) = (wall(), Vector3::x());
        let u0 = Vector3::new(-10.0, 30.0, 0.0);
        for mu in [0.0, 0.1] {
            let Ok((p, r)) = law(mu, 0.3).impulse(&k, &u0, &n, 0.8) else {
                panic!()
            };
            assert_eq!(r, Regime::Slide);
            assert!((p.y + mu * p.x).abs() < 1e-12, "{p:?}");
            let u = u0 + k * p;
            assert!((u.x - 8.0).abs() < 1e-12);
        }
    }

    /// The law is the line clamped into [0, e_t,max].
    #[test]
    fn tangential_restitution_is_the_capped_line() {
        let c = CompliantContact {
            tangential_restitution: -0.4,
            tangential_restitution_slope: 1.3,
            tangential_restitution_max: 0.25,
            ..law(0.4, 0.0)
        };
        assert_eq!(c.tangential_restitution_at(0.2), 0.0);
        assert!((c.tangential_restitution_at(0.4) - 0.12).abs() < 1e-12);
        assert_eq!(c.tangential_restitution_at(0.9), 0.25);
        assert_eq!(law(0.4, 0.7).tangential_restitution_at(5.0), 0.7);
    }

    #[test]
    fn rejects_bad_parameters() {
        let bad = [
            (law(f64::NAN, 0.1), Field::Friction),
            (law(-0.1, 0.1), Field::Friction),
            (law(0.4, 1.1), Field::TangentialRestitution),
            (law(0.4, -1.5), Field::TangentialRestitution),
            (
                CompliantContact {
                    tangential_restitution_max: 1.5,
                    ..law(0.4, 0.1)
                },
                Field::TangentialRestitutionMax,
            ),
            (
                CompliantContact {
                    tangential_restitution_max: f64::NAN,
                    ..law(0.4, 0.1)
                },
                Field::TangentialRestitutionMax,
            ),
        ];
        for (c, field) in bad {
            assert!(
                matches!(c.validate(), Err(Error::InvalidInput { field: f, .. }) if f == field)
            );
        }
        assert!(law(f64::INFINITY, 0.0).validate().is_ok());
    }
}
