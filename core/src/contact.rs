//! Contact geometry in the global frame G (PHYSICS.md):
//!
//! ```text
//! Q      = R_club · Rz(α)                      (E → G)
//! n      = Q n_E
//! r_imp  = Q (cg_to_face − (a,0,0) + p_E)      club CoM → contact point
//! r_ball = −R n                                ball centre → contact point
//! I_c,G  = R_club · I_c · R_clubᵀ
//! ```

use crate::ball::Ball;
use crate::club::ClubHead;
use crate::delivery::Strike;
use crate::error::Result;
use crate::face::contact;
use crate::real::Real;
use nalgebra::{Matrix3, Vector3};

/// Where and how the two bodies touch, in G.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Contact<T: Real> {
    /// Unit contact normal n, out of the face (towards the ball).
    pub normal: Vector3<T>,
    /// Club CoM → contact point r_imp (m).
    pub club_lever_m: Vector3<T>,
    /// Ball centre → contact point r_ball = −R n (m).
    pub ball_lever_m: Vector3<T>,
    /// Club inertia in G, I_c,G = R I_c Rᵀ (kg·m²).
    pub club_inertia_kgm2: Matrix3<T>,
    /// Inverse club inertia in G, R I_c⁻¹ Rᵀ (1/(kg·m²)).
    pub club_inverse_inertia: Matrix3<T>,
}

impl<T: Real> Contact<T> {
    /// The contact geometry of `strike` between `club` and `ball`.
    ///
    /// # Errors
    /// [`crate::Error::OffFace`] when the impact location is off the face.
    pub fn new(club: &ClubHead<T>, ball: &Ball<T>, strike: &Strike<T>) -> Result<Self> {
        let on_face = contact(club.face(), club.cg_to_face_m(), strike.location())?;
        let r = &strike.club().orientation;
        let q = r * club.face_rotation();
        let normal = q * on_face.normal;
        let rt = r.transpose();
        Ok(Self {
            normal,
            club_lever_m: q * on_face.point_from_cg_m,
            ball_lever_m: normal * -ball.radius_m(),
            club_inertia_kgm2: r * club.inertia_kgm2() * rt,
            club_inverse_inertia: r * club.inverse_inertia() * rt,
        })
    }
}
