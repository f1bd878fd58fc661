//! The ball: a rigid solid sphere (PHYSICS.md: m_b = 0.04593 kg, R = 0.021336 m,
//! I_b = 0.4·m_b·R²), and its kinematic state.

use crate::error::{Field, Result};
use crate::real::{Real, lit};
use crate::validate::{finite_vector, positive};
use nalgebra::Vector3;

/// Ball parameters, validated: mass and radius are finite and positive.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Ball<T> {
    mass_kg: T,
    radius_m: T,
}

impl<T: Real> Ball<T> {
    /// Mass of the standard ball (kg): the Rules' maximum, 1.620 oz.
    pub const STANDARD_MASS_KG: f64 = 0.04593;
    /// Radius of the standard ball (m): the Rules' minimum diameter, 1.680 in.
    pub const STANDARD_RADIUS_M: f64 = 0.021336;

    /// A ball of the given mass (kg) and radius (m).
    ///
    /// # Errors
    /// [`Field::BallMass`] or [`Field::BallRadius`] when not finite and positive.
    pub fn new(mass_kg: T, radius_m: T) -> Result<Self> {
        Ok(Self {
            mass_kg: positive(mass_kg, Field::BallMass)?,
            radius_m: positive(radius_m, Field::BallRadius)?,
        })
    }

    /// The standard ball of PHYSICS.md.
    #[must_use]
    pub fn standard() -> Self {
        Self {
            mass_kg: lit(Self::STANDARD_MASS_KG),
            radius_m: lit(Self::STANDARD_RADIUS_M),
        }
    }

    /// Mass m_b (kg).
    #[must_use]
    pub fn mass_kg(&self) -> T {
        self.mass_kg
    }

    /// Radius R (m).
    #[must_use]
    pub fn radius_m(&self) -> T {
        self.radius_m
    }

    /// Diameter D = 2R (m).
    #[must_use]
    pub fn diameter_m(&self) -> T {
        self.radius_m + self.radius_m
    }

    /// Moment of inertia of a solid sphere about its centre, I_b = 0.4·m_b·R² (kg·m²).
    #[must_use]
    pub fn inertia_kgm2(&self) -> T {
        lit::<T>(0.4) * self.mass_kg * self.radius_m * self.radius_m
    }
}

/// Linear and angular velocity of the ball in the global frame G.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct BallMotion<T: Real> {
    /// Velocity of the centre (m/s, G).
    pub velocity_mps: Vector3<T>,
    /// Angular velocity (rad/s, G).
    pub spin_radps: Vector3<T>,
}

impl<T: Real> BallMotion<T> {
    /// A ball at rest (on the tee).
    #[must_use]
    pub fn at_rest() -> Self {
        Self {
            velocity_mps: Vector3::zeros(),
            spin_radps: Vector3::zeros(),
        }
    }

    /// Checks every component is finite.
    ///
    /// # Errors
    /// [`Field::BallVelocity`] or [`Field::BallSpin`] when a component is NaN or infinite.
    pub fn validated(&self) -> Result<Self> {
        finite_vector(&self.velocity_mps, Field::BallVelocity)?;
        finite_vector(&self.spin_radps, Field::BallSpin)?;
        Ok(*self)
    }
}

impl<T: Real> Default for BallMotion<T> {
    fn default() -> Self {
        Self::at_rest()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::{Error, Reason};

    #[test]
    fn rejects_bad_mass_and_radius() {
        assert_eq!(
            Ball::new(-1.0_f64, 0.02),
            Err(Error::invalid(Field::BallMass, Reason::NotPositive))
        );
        assert_eq!(
            Ball::new(0.04_f32, f32::NAN),
            Err(Error::invalid(Field::BallRadius, Reason::NotFinite))
        );
    }

    #[test]
    fn standard_inertia() {
        let b = Ball::<f64>::standard();
        assert!((b.inertia_kgm2() - 0.4 * 0.04593 * 0.021336 * 0.021336).abs() < 1e-18);
    }
}
