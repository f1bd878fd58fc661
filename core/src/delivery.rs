//! Club delivery in launch-monitor terms → club state at impact (PHYSICS.md).
//!
//! ```text
//! v_c    = v · (cos θa cos φp,  sin θa,  cos θa sin φp)
//! R_club = Ry(−φf) · Rz(δ − α) · Rx(λ)              (C → G)
//! ```

use crate::ball::BallMotion;
use crate::club::ClubHead;
use crate::error::{Error, Field, Reason, Result};
use crate::geometry::{rot_x, rot_y, rot_z, rotation_defect, sin_cos};
use crate::real::{Real, length};
use crate::validate::{finite, finite_matrix, finite_vector, non_negative};
use nalgebra::{Matrix3, Vector3};

/// How the club arrives at the ball, as a launch monitor reports it. SI: m/s, rad, m.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Delivery<T: Real> {
    /// Club head (CoM) speed v (m/s).
    pub club_speed_mps: T,
    /// Attack angle θa (rad, + up).
    pub attack_angle_rad: T,
    /// Club path φp (rad, + right of target: in-to-out for a right-hander).
    pub club_path_rad: T,
    /// Face angle φf (rad, + open, pointing right).
    pub face_angle_rad: T,
    /// Dynamic loft δ (rad).
    pub dynamic_loft_rad: T,
    /// Lie / face tilt λ (rad, + rotates +Y towards +Z about X: toe up).
    pub lie_rad: T,
    /// Club angular velocity ω_c before impact (rad/s, G).
    pub club_spin_radps: Vector3<T>,
    /// Where on the face the ball is struck.
    pub location: FaceLocation<T>,
}

/// Impact location on the face, in the face frame E, from the face centre (m).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FaceLocation<T> {
    /// ΔY: up the face (m).
    pub height_m: T,
    /// ΔZ: toward the toe (m).
    pub toe_m: T,
}

/// Club motion and orientation just before impact, in the global frame G — what a sensor
/// fusion gives directly.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ClubMotion<T: Real> {
    /// CoM velocity v_c (m/s, G).
    pub velocity_mps: Vector3<T>,
    /// Angular velocity ω_c (rad/s, G).
    pub spin_radps: Vector3<T>,
    /// Orientation R_club (rotation C → G).
    pub orientation: Matrix3<T>,
}

/// Everything the impact needs besides the two bodies' parameters: club motion, ball
/// motion (at rest on a tee unless given) and the impact location. Validated.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Strike<T: Real> {
    club: ClubMotion<T>,
    ball: BallMotion<T>,
    location: FaceLocation<T>,
}

impl<T: Real> FaceLocation<T> {
    /// This location, checked: both coordinates finite (whether it is on the face is the
    /// club's to say, in the impact).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the non-finite coordinate.
    pub(crate) fn validated(&self) -> Result<()> {
        finite(self.height_m, Field::ImpactHeight)?;
        finite(self.toe_m, Field::ImpactToe)?;
        Ok(())
    }

    /// The face centre.
    #[must_use]
    pub fn centre() -> Self {
        Self {
            height_m: T::zero(),
            toe_m: T::zero(),
        }
    }
}

impl<T: Real> Default for FaceLocation<T> {
    fn default() -> Self {
        Self::centre()
    }
}

impl<T: Real> Delivery<T> {
    /// A square, centred delivery at `club_speed_mps` with the club's static loft.
    #[must_use]
    pub fn square(club_speed_mps: T, club: &ClubHead<T>) -> Self {
        Self {
            club_speed_mps,
            attack_angle_rad: T::zero(),
            club_path_rad: T::zero(),
            face_angle_rad: T::zero(),
            dynamic_loft_rad: club.loft_rad(),
            lie_rad: T::zero(),
            club_spin_radps: Vector3::zeros(),
            location: FaceLocation::default(),
        }
    }

    /// Club velocity direction and orientation from launch-monitor terms; the ball at rest.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming a non-finite input or a negative club speed.
    pub fn strike(&self, club: &ClubHead<T>) -> Result<Strike<T>> {
        let v = non_negative(self.club_speed_mps, Field::ClubSpeed)?;
        let attack = finite(self.attack_angle_rad, Field::AttackAngle)?;
        let path = finite(self.club_path_rad, Field::ClubPath)?;
        let face = finite(self.face_angle_rad, Field::FaceAngle)?;
        let loft = finite(self.dynamic_loft_rad, Field::DynamicLoft)?;
        let lie = finite(self.lie_rad, Field::Lie)?;
        let spin = finite_vector(&self.club_spin_radps, Field::ClubSpin)?;
        let (sa, ca) = sin_cos(attack);
        let (sp, cp) = sin_cos(path);
        let velocity = Vector3::new(ca * cp, sa, ca * sp) * v;
        let orientation = rot_y(-face) * rot_z(loft - club.loft_rad()) * rot_x(lie);
        // Not through `Strike::new`: its checks of the club's motion cannot fail here (the
        // velocity is a unit vector times a finite speed, the orientation a product of three
        // rotations built from finite angles, a rotation to a few ulps), and the rotation test
        // (`R Rᵀ − I`, `det R`) cost ≈ 200 instructions of a 10k-instruction shot on a
        // Cortex-M4F (docs/performance.md). The ball at rest needs no check; the location does.
        self.location.validated()?;
        Ok(Strike {
            club: ClubMotion {
                velocity_mps: velocity,
                spin_radps: spin,
                orientation,
            },
            ball: BallMotion::at_rest(),
            location: self.location,
        })
    }
}

impl<T: Real> Strike<T> {
    /// A strike from club and ball motion given directly.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for non-finite components or an orientation that is not a
    /// proper rotation (to √ε of the precision).
    pub fn new(
        club: ClubMotion<T>,
        ball: BallMotion<T>,
        location: FaceLocation<T>,
    ) -> Result<Self> {
        finite_vector(&club.velocity_mps, Field::ClubVelocity)?;
        finite_vector(&club.spin_radps, Field::ClubSpin)?;
        finite_matrix(&club.orientation, Field::ClubOrientation)?;
        let (defect, det) = rotation_defect(&club.orientation);
        let tol = T::default_epsilon().root();
        if !(defect <= tol && (det - T::one()).abs() <= tol) {
            return Err(Error::invalid(Field::ClubOrientation, Reason::NotRotation));
        }
        ball.validated()?;
        location.validated()?;
        Ok(Self {
            club,
            ball,
            location,
        })
    }

    /// Club motion before impact.
    #[must_use]
    pub fn club(&self) -> &ClubMotion<T> {
        &self.club
    }
    /// Ball motion before impact.
    #[must_use]
    pub fn ball(&self) -> &BallMotion<T> {
        &self.ball
    }
    /// Impact location on the face.
    #[must_use]
    pub fn location(&self) -> &FaceLocation<T> {
        &self.location
    }
    /// Club head speed |v_c| (m/s): the denominator of the smash factor.
    #[must_use]
    pub fn club_speed_mps(&self) -> T {
        length(&self.club.velocity_mps)
    }
}
