//! Wind: none, a constant vector, or a power-law boundary-layer profile (PHYSICS.md).
//!
//! ```text
//! w(h) = w_ref · (h / h_ref)^k     for h > 0,      w(h) = 0 for h ≤ 0
//! ```
//!
//! `h` is the ball's height `y` above the ground plane of the tee (y = 0). The core takes the
//! wind as a vector in G; the CLI's "direction it blows towards, degrees from +X towards +Z"
//! convention is converted at the edge.

use crate::error::{Field, Result};
use crate::real::{Real, lit};
use crate::validate::{finite_vector, non_negative, positive};
use nalgebra::Vector3;

/// Default wind reference height (m): the 10 m of weather-station anemometers.
pub const DEFAULT_REFERENCE_HEIGHT_M: f64 = 10.0;
/// Default profile exponent k = 1/7 (open terrain).
pub const DEFAULT_EXPONENT: f64 = 1.0 / 7.0;

/// The wind a scene asks for.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Wind<T: Real> {
    /// Still air: the flight does no wind arithmetic at all.
    #[default]
    None,
    /// The same wind velocity everywhere (m/s, G).
    Uniform(Vector3<T>),
    /// A power-law profile `w(h) = w_ref · (h/h_ref)^k` above the ground, zero at and below it.
    Profile {
        /// Wind velocity at the reference height (m/s, G).
        reference_mps: Vector3<T>,
        /// Reference height h_ref (m), positive.
        reference_height_m: T,
        /// Exponent k, finite and not negative (0 = uniform above the ground).
        exponent: T,
    },
}

impl<T: Real> Wind<T> {
    /// A profile with the default reference height (10 m) and exponent (1/7).
    #[must_use]
    pub fn profile(reference_mps: Vector3<T>) -> Self {
        Self::Profile {
            reference_mps,
            reference_height_m: lit(DEFAULT_REFERENCE_HEIGHT_M),
            exponent: lit(DEFAULT_EXPONENT),
        }
    }

    /// Validates the wind into the form the flight loop evaluates.
    ///
    /// # Errors
    /// [`Field::Wind`] for a non-finite velocity, [`Field::WindReferenceHeight`] not
    /// finite and positive, [`Field::WindExponent`] not finite or negative.
    pub fn prepare(&self) -> Result<WindField<T>> {
        Ok(match *self {
            Self::None => WindField::None,
            Self::Uniform(w) => WindField::Uniform(finite_vector(&w, Field::Wind)?),
            Self::Profile {
                reference_mps,
                reference_height_m,
                exponent,
            } => WindField::Profile {
                reference_mps: finite_vector(&reference_mps, Field::Wind)?,
                inv_reference_height: T::one()
                    / positive(reference_height_m, Field::WindReferenceHeight)?,
                exponent: non_negative(exponent, Field::WindExponent)?,
            },
        })
    }
}

/// A validated wind, ready for evaluation in the flight loop.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum WindField<T: Real> {
    /// No wind.
    None,
    /// Constant wind (m/s).
    Uniform(Vector3<T>),
    /// Power-law profile, with `1/h_ref` precomputed.
    Profile {
        /// Wind at the reference height (m/s).
        reference_mps: Vector3<T>,
        /// 1 / h_ref (1/m).
        inv_reference_height: T,
        /// Exponent k.
        exponent: T,
    },
}

impl<T: Real> WindField<T> {
    /// Wind velocity at height `y` (m/s). The profile is `w_ref · exp(k · ln(y/h_ref))`
    /// for `y > 0`, exactly zero at and below the ground (never NaN: `ln` only sees
    /// positive arguments).
    #[inline(always)]
    #[must_use]
    pub fn at(&self, y: T) -> Vector3<T> {
        match *self {
            Self::None => Vector3::zeros(),
            Self::Uniform(w) => w,
            Self::Profile {
                reference_mps,
                inv_reference_height,
                exponent,
            } => {
                if y > T::zero() {
                    reference_mps * (exponent * (y * inv_reference_height).ln()).exp()
                } else {
                    Vector3::zeros()
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::{Error, Reason};

    #[test]
    fn profile_shape() {
        let Ok(w) = Wind::profile(Vector3::new(-8.0_f64, 0.0, 0.0)).prepare() else {
            panic!()
        };
        assert!((w.at(10.0).x + 8.0).abs() < 1e-12);
        assert!((w.at(20.0).x + 8.0 * 2.0_f64.powf(1.0 / 7.0)).abs() < 1e-12);
        assert_eq!(w.at(0.0), Vector3::zeros());
        assert_eq!(w.at(-3.0), Vector3::zeros());
        assert!(w.at(1e-300).x.is_finite());
    }

    #[test]
    fn rejects_bad_wind() {
        let bad = Wind::Profile {
            reference_mps: Vector3::new(1.0_f32, 0.0, 0.0),
            reference_height_m: 0.0,
            exponent: 0.1,
        };
        assert_eq!(
            bad.prepare(),
            Err(Error::invalid(
                Field::WindReferenceHeight,
                Reason::NotPositive
            ))
        );
        assert_eq!(
            Wind::Uniform(Vector3::new(f64::NAN, 0.0, 0.0)).prepare(),
            Err(Error::invalid(Field::Wind, Reason::NotFinite))
        );
    }
}
