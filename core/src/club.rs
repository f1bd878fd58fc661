//! The club head: rigid body parameters and the face ellipsoid, validated once.
//!
//! Frames (PHYSICS.md): the club frame C sits at the head's centre of mass; the face frame
//! E is C rotated by the static loft α about +z_C (`R_CE = Rz(α)`), x_E out of the face.

pub use crate::contact_law::ContactLaw;
use crate::error::{Error, Field, Reason, Result};
use crate::real::{Real, lit};
use crate::validate::{
    finite, finite_matrix, finite_vector, in_range, positive, positive_or_infinite,
};
use nalgebra::{Matrix3, Vector3};

/// Club head parameters as a user gives them (SI units, angles in radians). Turn into a
/// validated [`ClubHead`] with [`ClubSpec::validate`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ClubSpec<T: Real> {
    /// Head mass m_c (kg).
    pub mass_kg: T,
    /// Inertia tensor about the CoM, in the club frame C (kg·m²). Symmetric positive definite.
    pub inertia_kgm2: Matrix3<T>,
    /// Static loft α (rad).
    pub loft_rad: T,
    /// Roll radius b: curvature up the face (m); `+∞` for a flat face.
    pub roll_radius_m: T,
    /// Bulge radius c: curvature across the face (m); `+∞` for a flat face.
    pub bulge_radius_m: T,
    /// Ellipsoid x radius a (m). `None`: equal to the bulge radius c when that is finite,
    /// else to the roll radius b, else flat.
    pub face_depth_radius_m: Option<T>,
    /// Vector from the CoM to the face centre, in the face frame E (m).
    pub cg_to_face_m: Vector3<T>,
    /// Normal coefficient of restitution e, in [0, 1] (the face's rating, at the COR test's
    /// 48.77 m/s for a speed-dependent contact law).
    pub restitution: T,
    /// The face–ball contact law ([`ContactLaw::Rolling`] is the seed's).
    pub contact: ContactLaw<T>,
    /// The empirical D-plane share k of the launch's spin axis, in (0, 1]
    /// ([`crate::impact::axis_share`]; docs/impact.md §0.8): `tan a' = k·tan a`. A named
    /// empirical option beside the physics; 1 (every preset's, [`ClubSpec::PHYSICS_AXIS`])
    /// is the impact's own axis, bit for bit.
    pub spin_axis_share: T,
}

impl<T: Real> ClubSpec<T> {
    /// The [`ClubSpec::spin_axis_share`] that leaves the impact's own spin axis (1).
    pub const PHYSICS_AXIS: f64 = 1.0;

    /// Validates every parameter and precomputes what the solvers need.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the first bad parameter: non-finite values,
    /// non-positive mass or radii, an inertia tensor that is not symmetric positive
    /// definite, `e` outside [0, 1], an infinite depth radius with a curved face, a spin-axis
    /// share outside (0, 1].
    pub fn validate(&self) -> Result<ClubHead<T>> {
        let mass_kg = positive(self.mass_kg, Field::ClubMass)?;
        let inertia = validate_inertia(&self.inertia_kgm2)?;
        let inverse_inertia = inertia
            .try_inverse()
            .filter(|m| m.iter().all(|x| x.is_finite()))
            .ok_or(Error::invalid(
                Field::ClubInertia,
                Reason::NotPositiveDefinite,
            ))?;
        let loft_rad = in_range(self.loft_rad, -T::frac_pi_2(), T::frac_pi_2(), Field::Loft)?;
        let b = positive_or_infinite(self.roll_radius_m, Field::RollRadius)?;
        let c = positive_or_infinite(self.bulge_radius_m, Field::BulgeRadius)?;
        // The depth radius and the input it comes from (named when a/r² overflows).
        let (a, a_field) = match self.face_depth_radius_m {
            Some(a) => (
                positive_or_infinite(a, Field::FaceDepthRadius)?,
                Field::FaceDepthRadius,
            ),
            None if c.is_finite() => (c, Field::BulgeRadius),
            None => (b, Field::RollRadius),
        };
        let face = FaceShape::new(a, b, c, a_field)?;
        let cg_to_face_m = finite_vector(&self.cg_to_face_m, Field::CgToFace)?;
        let restitution = in_range(self.restitution, T::zero(), T::one(), Field::Restitution)?;
        finite(restitution, Field::Restitution)?;
        let contact = self.contact.validate()?;
        let spin_axis_share = self.spin_axis_share;
        if !(spin_axis_share > T::zero() && spin_axis_share <= T::one()) {
            let reason = if spin_axis_share.is_finite() {
                Reason::OutOfRange
            } else {
                Reason::NotFinite
            };
            return Err(Error::invalid(Field::SpinAxisShare, reason));
        }
        Ok(ClubHead {
            mass_kg,
            inertia_kgm2: inertia,
            inverse_inertia,
            loft_rad,
            face_rotation: crate::geometry::rot_z(loft_rad),
            face,
            cg_to_face_m,
            restitution,
            contact,
            spin_axis_share,
        })
    }
}

/// Symmetric (to rounding) and positive definite (Cholesky succeeds).
fn validate_inertia<T: Real>(m: &Matrix3<T>) -> Result<Matrix3<T>> {
    let m = finite_matrix(m, Field::ClubInertia)?;
    let scale = m.amax();
    let asym = (m - m.transpose()).amax();
    if asym > lit::<T>(64.0) * T::default_epsilon() * scale {
        return Err(Error::invalid(Field::ClubInertia, Reason::NotSymmetric));
    }
    let sym = (m + m.transpose()) * lit::<T>(0.5);
    // Cholesky by hand: every leading minor positive.
    let d0 = sym[(0, 0)];
    let minor2 = sym[(0, 0)] * sym[(1, 1)] - sym[(0, 1)] * sym[(1, 0)];
    let det = sym.determinant();
    if !(d0 > T::zero() && minor2 > T::zero() && det > T::zero()) {
        return Err(Error::invalid(
            Field::ClubInertia,
            Reason::NotPositiveDefinite,
        ));
    }
    Ok(sym)
}

/// The face ellipsoid `x²/a² + y²/b² + z²/c² = 1` in the face frame E, stored as the
/// curvature terms the contact geometry needs, so that flat faces (b, c → ∞) lose no
/// precision: `1/b²`, `1/c²` (zero when flat) and `a/b²`, `a/c²`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FaceShape<T> {
    /// Depth radius a (m), possibly `+∞` for a flat face.
    pub depth_radius_m: T,
    /// 1/b² (1/m²).
    pub inv_roll_sq: T,
    /// 1/c² (1/m²).
    pub inv_bulge_sq: T,
    /// a/b² (1/m).
    pub depth_over_roll_sq: T,
    /// a/c² (1/m).
    pub depth_over_bulge_sq: T,
}

impl<T: Real> FaceShape<T> {
    fn new(a: T, b: T, c: T, a_field: Field) -> Result<Self> {
        let inv_sq = |r: T| {
            if r.is_finite() {
                T::one() / (r * r)
            } else {
                T::zero()
            }
        };
        // a/r²: zero for a flat direction; undefined (rejected) for a curved direction
        // with an infinite depth radius.
        let ratio = |r: T| {
            if !r.is_finite() {
                Ok(T::zero())
            } else if a.is_finite() {
                Ok(a / (r * r))
            } else {
                Err(Error::invalid(Field::FaceDepthRadius, Reason::OutOfRange))
            }
        };
        let shape = Self {
            depth_radius_m: a,
            inv_roll_sq: inv_sq(b),
            inv_bulge_sq: inv_sq(c),
            depth_over_roll_sq: ratio(b)?,
            depth_over_bulge_sq: ratio(c)?,
        };
        // Tiny radii overflow 1/r² to ∞, a huge depth radius overflows a/r²: reject rather
        // than compute with it, naming the input at fault (issue 7: a bulge radius near the
        // precision's maximum, the default depth radius, used to be blamed on the roll).
        if !shape.inv_roll_sq.is_finite() {
            return Err(Error::invalid(Field::RollRadius, Reason::OutOfRange));
        }
        if !shape.inv_bulge_sq.is_finite() {
            return Err(Error::invalid(Field::BulgeRadius, Reason::OutOfRange));
        }
        if !(shape.depth_over_roll_sq.is_finite() && shape.depth_over_bulge_sq.is_finite()) {
            return Err(Error::invalid(a_field, Reason::OutOfRange));
        }
        Ok(shape)
    }
}

/// A validated club head. Build it with [`ClubSpec::validate`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ClubHead<T: Real> {
    mass_kg: T,
    inertia_kgm2: Matrix3<T>,
    inverse_inertia: Matrix3<T>,
    loft_rad: T,
    /// `R_CE = Rz(α)`, computed once (no trigonometry in the impact solve).
    face_rotation: Matrix3<T>,
    face: FaceShape<T>,
    cg_to_face_m: Vector3<T>,
    restitution: T,
    contact: ContactLaw<T>,
    spin_axis_share: T,
}

impl<T: Real> ClubHead<T> {
    /// Mass m_c (kg).
    #[must_use]
    pub fn mass_kg(&self) -> T {
        self.mass_kg
    }
    /// Inertia about the CoM in C (kg·m²), symmetrised.
    #[must_use]
    pub fn inertia_kgm2(&self) -> &Matrix3<T> {
        &self.inertia_kgm2
    }
    /// Inverse inertia in C (1/(kg·m²)).
    #[must_use]
    pub fn inverse_inertia(&self) -> &Matrix3<T> {
        &self.inverse_inertia
    }
    /// Static loft α (rad).
    #[must_use]
    pub fn loft_rad(&self) -> T {
        self.loft_rad
    }
    /// Face frame → club frame, `R_CE = Rz(α)`.
    #[must_use]
    pub fn face_rotation(&self) -> &Matrix3<T> {
        &self.face_rotation
    }
    /// The face ellipsoid.
    #[must_use]
    pub fn face(&self) -> &FaceShape<T> {
        &self.face
    }
    /// CoM → face centre in E (m).
    #[must_use]
    pub fn cg_to_face_m(&self) -> &Vector3<T> {
        &self.cg_to_face_m
    }
    /// Coefficient of restitution e.
    #[must_use]
    pub fn restitution(&self) -> T {
        self.restitution
    }
    /// The face–ball contact law.
    #[must_use]
    pub fn contact_law(&self) -> &ContactLaw<T> {
        &self.contact
    }
    /// The empirical D-plane share of the spin axis, in (0, 1] (1: the physics).
    #[must_use]
    pub fn spin_axis_share(&self) -> T {
        self.spin_axis_share
    }
    /// The same club with the physics' spin axis (share 1).
    #[must_use]
    pub(crate) fn with_physics_axis(&self) -> Self {
        Self {
            spin_axis_share: T::one(),
            ..*self
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets::{PRESETS, Preset};

    #[test]
    fn presets_validate_in_both_precisions() {
        for p in PRESETS {
            assert!(p.spec::<f64>().validate().is_ok(), "{}", p.name);
            assert!(p.spec::<f32>().validate().is_ok(), "{}", p.name);
        }
    }

    #[test]
    fn names_the_bad_parameter() {
        let mut s = ClubSpec::<f64>::driver();
        s.restitution = 1.2;
        assert_eq!(
            s.validate(),
            Err(Error::invalid(Field::Restitution, Reason::OutOfRange))
        );
        let mut s = ClubSpec::<f64>::driver();
        s.inertia_kgm2[(0, 1)] = 1e-4;
        assert_eq!(
            s.validate(),
            Err(Error::invalid(Field::ClubInertia, Reason::NotSymmetric))
        );
        let mut s = ClubSpec::<f64>::driver();
        s.inertia_kgm2[(2, 2)] = -1e-4;
        assert_eq!(
            s.validate(),
            Err(Error::invalid(
                Field::ClubInertia,
                Reason::NotPositiveDefinite
            ))
        );
        let mut s = ClubSpec::<f64>::driver();
        s.bulge_radius_m = f64::NAN;
        assert_eq!(
            s.validate(),
            Err(Error::invalid(Field::BulgeRadius, Reason::NotFinite))
        );
    }

    #[test]
    fn flat_face_has_zero_curvature() {
        let h = Preset::find("7iron").map(|p| p.spec::<f32>().validate());
        let Some(Ok(h)) = h else {
            panic!("7iron preset")
        };
        assert_eq!(h.face().inv_roll_sq, 0.0);
        assert_eq!(h.face().depth_over_bulge_sq, 0.0);
    }
}
