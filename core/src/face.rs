//! Contact geometry on the face ellipsoid, in the face frame E (PHYSICS.md).
//!
//! ```text
//! s²  = 1 − ΔY²/b² − ΔZ²/c²
//! p_E = (a·s, ΔY, ΔZ)                 n_E = normalise(s/a, ΔY/b², ΔZ/c²)
//! ```
//! Written without the `a·s − a` cancellation: the contact point relative to the club's
//! CoM is `cg_to_face + (a(s−1), ΔY, ΔZ)` with `a(s−1) = −(ΔY²·a/b² + ΔZ²·a/c²)/(1+s)`,
//! and the normal is scaled by `a`: `n_E ∝ (s, ΔY·a/b², ΔZ·a/c²)`. Both stay exact for
//! flat faces (b, c → ∞, including `+∞`).

use crate::club::FaceShape;
use crate::delivery::FaceLocation;
use crate::error::{Error, Result};
use crate::real::{Real, length, lit};
use nalgebra::Vector3;

/// The contact point and outward face normal, in E.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FaceContact<T: Real> {
    /// Club CoM → contact point (m, E).
    pub point_from_cg_m: Vector3<T>,
    /// Unit outward normal (E).
    pub normal: Vector3<T>,
}

/// Smallest `s²` accepted, in units of the precision's ε: below it the rounding of
/// `ΔY²/b² + ΔZ²/c²` (about ε) moves the normal by more than about 1e-3 rad.
const MIN_S_SQ_IN_EPS: f64 = 1024.0;

/// Contact point and normal for an impact at `location`.
///
/// # Errors
/// [`Error::OffFace`] when `s² ≤ 1024 ε` (the point is off the face or so near its
/// edge that the normal is unreliable in this precision).
pub fn contact<T: Real>(
    face: &FaceShape<T>,
    cg_to_face_m: &Vector3<T>,
    location: &FaceLocation<T>,
) -> Result<FaceContact<T>> {
    let (dy, dz) = (location.height_m, location.toe_m);
    let q = dy * dy * face.inv_roll_sq + dz * dz * face.inv_bulge_sq;
    let s_sq = T::one() - q;
    if !(s_sq > lit::<T>(MIN_S_SQ_IN_EPS) * T::default_epsilon()) {
        return Err(Error::OffFace);
    }
    let s = s_sq.root();
    let ky = dy * face.depth_over_roll_sq;
    let kz = dz * face.depth_over_bulge_sq;
    let depth = -(dy * ky + dz * kz) / (T::one() + s);
    let point = cg_to_face_m + Vector3::new(depth, dy, dz);
    let normal = Vector3::new(s, ky, kz);
    let len = length(&normal);
    if !(len.is_finite() && len > T::zero() && point.iter().all(|x| x.is_finite())) {
        return Err(Error::OffFace);
    }
    Ok(FaceContact {
        point_from_cg_m: point,
        normal: normal / len,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::club::ClubSpec;

    #[test]
    fn centre_is_the_face_centre_with_normal_x() {
        let club = ClubSpec::<f64>::driver().validate();
        let Ok(club) = club else { panic!("driver") };
        let c = contact(club.face(), club.cg_to_face_m(), &FaceLocation::default());
        let Ok(c) = c else { panic!("centre hit") };
        assert_eq!(c.normal, Vector3::x());
        assert_eq!(c.point_from_cg_m, Vector3::new(0.04, 0.0, 0.0));
    }

    #[test]
    fn matches_the_textbook_form_and_seed_angles() {
        let (a, b, c, dy, dz) = (0.28_f64, 0.305, 0.254, -0.008, 0.018);
        let mut spec = ClubSpec::<f64>::driver();
        spec.roll_radius_m = b;
        spec.bulge_radius_m = c;
        spec.face_depth_radius_m = Some(a);
        let Ok(club) = spec.validate() else {
            panic!("club")
        };
        let loc = FaceLocation {
            height_m: dy,
            toe_m: dz,
        };
        let Ok(got) = contact(club.face(), club.cg_to_face_m(), &loc) else {
            panic!()
        };
        let s = (1.0 - dy * dy / (b * b) - dz * dz / (c * c)).sqrt();
        let p = Vector3::new(0.04 - a + a * s, dy, dz);
        let n = Vector3::new(s / a, dy / (b * b), dz / (c * c)).normalize();
        assert!((got.point_from_cg_m - p).norm() < 1e-15);
        assert!((got.normal - n).norm() < 1e-15);
        // seed angles: tan γ = a·ΔY/(b²·s), tan β = a·ΔZ/(c²·s)
        assert!((got.normal.y / got.normal.x - a * dy / (b * b * s)).abs() < 1e-14);
        assert!((got.normal.z / got.normal.x - a * dz / (c * c * s)).abs() < 1e-14);
    }

    #[test]
    fn off_the_edge_is_an_error() {
        let Ok(club) = ClubSpec::<f32>::driver().validate() else {
            panic!()
        };
        let loc = FaceLocation {
            height_m: 0.0,
            toe_m: 0.31,
        };
        assert_eq!(
            contact(club.face(), club.cg_to_face_m(), &loc),
            Err(Error::OffFace)
        );
        let loc = FaceLocation {
            height_m: 0.0,
            toe_m: 0.3,
        };
        assert_eq!(
            contact(club.face(), club.cg_to_face_m(), &loc),
            Err(Error::OffFace)
        );
    }
}
