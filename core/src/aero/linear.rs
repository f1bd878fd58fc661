//! The seed's linear family (Quintavalla 2002, PHYSICS.md): coefficients linear in the
//! spin parameter `Sp = |ω|·R/V`, independent of the Reynolds number,
//!
//! ```text
//! C_D = c_d0 + c_d,sp·Sp      C_L = c_l0 + c_l,sp·Sp      C_M = c_m,sp·Sp
//! ```
//!
//! [`LinearAero::quintavalla`] holds Quintavalla's values (0.171, 0.62, 0.083, 0.885,
//! 0.0125), which the golden files pin bit for bit; `carry fit --family quintavalla`
//! refits all five.

use crate::error::{Error, Field, Reason, Result};
use crate::real::{Real, lit};

/// Quintavalla's drag coefficient at zero spin.
pub const CD0: f64 = 0.171;
/// Quintavalla's drag coefficient slope in the spin parameter.
pub const CD_SP: f64 = 0.62;
/// Quintavalla's lift coefficient at zero spin (for ω ≠ 0).
pub const CL0: f64 = 0.083;
/// Quintavalla's lift coefficient slope in the spin parameter.
pub const CL_SP: f64 = 0.885;
/// Quintavalla's spin-decay (moment) coefficient slope in the spin parameter.
pub const CM_SP: f64 = 0.0125;
/// Largest accepted coefficient of the linear family: far above any golf ball's, and far
/// inside f32's range (a guard against absurd input, not a physical bound).
pub const MAX_LINEAR_COEFFICIENT: f64 = 10.0;

/// Coefficients of the linear family. Validate with [`LinearAero::validate`] (done by
/// [`crate::Scene::prepare`]).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LinearAero<T> {
    /// Drag coefficient at zero spin, `c_d0`.
    pub cd0: T,
    /// Drag slope in the spin parameter, `c_d,sp`.
    pub cd_spin: T,
    /// Lift coefficient at zero spin parameter (for ω ≠ 0), `c_l0`.
    pub cl0: T,
    /// Lift slope in the spin parameter, `c_l,sp`.
    pub cl_spin: T,
    /// Moment (spin-decay) slope in the spin parameter, `c_m,sp`.
    pub cm_spin: T,
}

/// Names of the linear family's coefficients, in the order of [`LinearAero::to_array`]
/// (the keys of an aerodynamic model file).
pub const LINEAR_NAMES: [&str; 5] = ["cd0", "cd_spin", "cl0", "cl_spin", "cm_spin"];

impl<T: Real> LinearAero<T> {
    /// Quintavalla's coefficients: the seed model.
    #[must_use]
    pub fn quintavalla() -> Self {
        Self {
            cd0: lit(CD0),
            cd_spin: lit(CD_SP),
            cl0: lit(CL0),
            cl_spin: lit(CL_SP),
            cm_spin: lit(CM_SP),
        }
    }

    /// The coefficients in order `[cd0, cd_spin, cl0, cl_spin, cm_spin]` (the fitting
    /// order of `carry fit --family quintavalla`).
    #[must_use]
    pub fn to_array(&self) -> [T; 5] {
        [self.cd0, self.cd_spin, self.cl0, self.cl_spin, self.cm_spin]
    }

    /// The inverse of [`LinearAero::to_array`].
    #[must_use]
    pub fn from_array(c: [T; 5]) -> Self {
        Self {
            cd0: c[0],
            cd_spin: c[1],
            cl0: c[2],
            cl_spin: c[3],
            cm_spin: c[4],
        }
    }

    /// Checks every coefficient is finite and in `0..=10`.
    ///
    /// # Errors
    /// [`Field::DragCoefficient`], [`Field::LiftCoefficient`] or
    /// [`Field::SpinDecayCoefficient`] with [`Reason::NotFinite`] or [`Reason::OutOfRange`].
    pub fn validate(&self) -> Result<Self> {
        let fields = [
            Field::DragCoefficient,
            Field::DragCoefficient,
            Field::LiftCoefficient,
            Field::LiftCoefficient,
            Field::SpinDecayCoefficient,
        ];
        for (c, field) in self.to_array().into_iter().zip(fields) {
            coefficient(c, lit(MAX_LINEAR_COEFFICIENT), field)?;
        }
        Ok(*self)
    }

    /// `C_D = c_d0 + c_d,sp·Sp`.
    #[must_use]
    pub fn drag_coefficient(&self, spin_parameter: T) -> T {
        self.cd0 + self.cd_spin * spin_parameter
    }

    /// `C_L = c_l0 + c_l,sp·Sp` (the lift itself is zero when ω = 0).
    #[must_use]
    pub fn lift_coefficient(&self, spin_parameter: T) -> T {
        self.cl0 + self.cl_spin * spin_parameter
    }

    /// `C_M = c_m,sp·Sp`.
    #[must_use]
    pub fn moment_coefficient(&self, spin_parameter: T) -> T {
        self.cm_spin * spin_parameter
    }
}

/// A coefficient must be finite and in `0..=max`.
pub(crate) fn coefficient<T: Real>(c: T, max: T, field: Field) -> Result<T> {
    if !c.is_finite() {
        return Err(Error::invalid(field, Reason::NotFinite));
    }
    if !(c >= T::zero() && c <= max) {
        return Err(Error::invalid(field, Reason::OutOfRange));
    }
    Ok(c)
}

/// Quintavalla's drag coefficient `C_D = 0.171 + 0.62 Sp`.
#[must_use]
pub fn drag_coefficient<T: Real>(spin_parameter: T) -> T {
    LinearAero::quintavalla().drag_coefficient(spin_parameter)
}

/// Quintavalla's lift coefficient `C_L = 0.083 + 0.885 Sp` (zero lift when ω = 0).
#[must_use]
pub fn lift_coefficient<T: Real>(spin_parameter: T) -> T {
    LinearAero::quintavalla().lift_coefficient(spin_parameter)
}

/// Quintavalla's moment coefficient of the spin-decay torque `C_M = 0.0125 Sp`.
#[must_use]
pub fn moment_coefficient<T: Real>(spin_parameter: T) -> T {
    LinearAero::quintavalla().moment_coefficient(spin_parameter)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quintavalla_is_the_published_formula() {
        for sp in [0.0, 0.05, 0.1, 0.2, 0.35, 0.6_f64] {
            assert_eq!(drag_coefficient(sp), 0.171 + 0.62 * sp);
            assert_eq!(lift_coefficient(sp), 0.083 + 0.885 * sp);
            assert_eq!(moment_coefficient(sp), 0.0125 * sp);
        }
    }

    #[test]
    fn rejects_absurd_coefficients() {
        let q = LinearAero::<f64>::quintavalla();
        assert_eq!(q.validate(), Ok(q));
        let bad = LinearAero { cd0: -0.1, ..q };
        assert_eq!(
            bad.validate(),
            Err(Error::invalid(Field::DragCoefficient, Reason::OutOfRange))
        );
        let bad = LinearAero {
            cm_spin: f64::NAN,
            ..q
        };
        assert_eq!(
            bad.validate(),
            Err(Error::invalid(
                Field::SpinDecayCoefficient,
                Reason::NotFinite
            ))
        );
        assert_eq!(LinearAero::from_array(q.to_array()), q);
    }
}
