//! Which point of the face a delivery's face angle and dynamic loft describe.
//!
//! * [`DeliveryConvention::TrackMan`] — a launch monitor's: face angle and dynamic loft are
//!   the face's *at the contact point* (TrackMan measures the face normal where the ball
//!   touches it); club speed, attack angle and club path are the head's CG's. On a face with
//!   bulge and roll the normal at an off-centre contact already holds the curvature's tilt.
//! * [`DeliveryConvention::SeedCentre`] — the seed's (PHYSICS.md): face angle and dynamic
//!   loft orient the club itself, i.e. the normal at the *face centre*. What the golden files
//!   pin.
//!
//! The two agree for a centre strike and on a flat face. For an off-centre strike the club's
//! centre orientation is derived once, here: with `R_club(δ, φ) = Ry(−φ) Rz(δ − α) Rx(λ)`
//! (PHYSICS.md) and `n_E(ΔY, ΔZ)` the face normal at the contact point ([`crate::face`]),
//!
//! ```text
//! find (δ_c, φ_c):  R_club(δ_c, φ_c) Rz(α) n_E(ΔY, ΔZ) = R_club(δ, φ) Rz(α) x̂
//! ```
//!
//! i.e. the contact normal points where a centre strike's normal points for the given
//! angles (elevation δ and azimuth φ when λ = 0). Both sides have the form `Ry(−φ) Rz(θ) m`
//! with `m = Rx(λ) Rz(α) n_E`; `Rz` keeps `m_z` and `Ry` keeps the height, so with
//! `ρ = √(m_x² + m_y²)`, `β = atan2(m_y, m_x)` and the target `t`:
//!
//! ```text
//! θ = asin(t_y / ρ) − β          (the normal keeps pointing forward, θ + β ∈ [−π/2, π/2])
//! φ = atan2(t_z, t_x) − atan2(m_z, ρ cos(θ + β))
//! δ_c = θ + α
//! ```
//!
//! For λ = 0 this is `δ_c = δ − γ`, `φ_c = φ − β_E` with `tan γ = (a/b²)ΔY/s`,
//! `tan β_E = (a/c²)ΔZ/s` to first order (the issue's hand correction, loft minus
//! asin(ΔY/b) and face minus asin(ΔZ/c) on a sphere). The inverse
//! ([`at_contact_point`]) solves the same equation the other way round.

use crate::club::ClubHead;
use crate::delivery::{Delivery, FaceLocation, Strike};
use crate::error::{Error, Field, Reason, Result};
use crate::face::contact;
use crate::geometry::{rot_x, rot_y, rot_z};
use crate::real::Real;
use crate::validate::finite;
use nalgebra::Vector3;

/// Which point of the face a delivery's face angle and dynamic loft describe.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum DeliveryConvention {
    /// The seed's: the angles orient the club (the face centre's normal). The golden files.
    SeedCentre,
    /// TrackMan's: the angles are the face's at the contact point; speed, attack and path
    /// the head CG's. What a launch-monitor user gives (the CLI's and C API's default).
    TrackMan,
}

/// Face angle and dynamic loft (rad), the two angles the conventions read differently.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FaceAim<T> {
    /// Dynamic loft δ (rad).
    pub dynamic_loft_rad: T,
    /// Face angle φ (rad, + open).
    pub face_angle_rad: T,
}

/// The club's centre orientation (the seed's angles) that puts the face normal at the
/// contact point `location` where TrackMan's `aim` (at the contact point) says, for a club
/// with lie `lie_rad`. Exactly `aim` for a centre strike or a flat face.
///
/// # Errors
/// [`Error::InvalidInput`] naming a non-finite angle, location or lie;
/// [`Error::OffFace`] for a location off the face; `DynamicLoft`/`OutOfRange` when no
/// orientation reaches the asked normal (a loft within the normal's tilt of ±90°).
pub fn centre_aim<T: Real>(
    club: &ClubHead<T>,
    location: &FaceLocation<T>,
    lie_rad: T,
    aim: &FaceAim<T>,
) -> Result<FaceAim<T>> {
    let (aim, lie) = validated(location, lie_rad, aim)?;
    let Some(m) = contact_direction(club, location, lie)? else {
        return Ok(aim);
    };
    let m0 = centre_direction(club, lie);
    let t = rot_y(-aim.face_angle_rad) * rot_z(aim.dynamic_loft_rad - club.loft_rad()) * m0;
    let (theta, phi) = solve(&m, &t)?;
    Ok(FaceAim {
        dynamic_loft_rad: theta + club.loft_rad(),
        face_angle_rad: phi,
    })
}

/// The inverse of [`centre_aim`]: TrackMan's face angle and dynamic loft at the contact
/// point `location` of a club oriented by the seed's `centre` angles.
///
/// # Errors
/// As [`centre_aim`].
pub fn at_contact_point<T: Real>(
    club: &ClubHead<T>,
    location: &FaceLocation<T>,
    lie_rad: T,
    centre: &FaceAim<T>,
) -> Result<FaceAim<T>> {
    let (centre, lie) = validated(location, lie_rad, centre)?;
    let Some(m) = contact_direction(club, location, lie)? else {
        return Ok(centre);
    };
    let m0 = centre_direction(club, lie);
    let t = rot_y(-centre.face_angle_rad) * rot_z(centre.dynamic_loft_rad - club.loft_rad()) * m;
    let (theta, phi) = solve(&m0, &t)?;
    Ok(FaceAim {
        dynamic_loft_rad: theta + club.loft_rad(),
        face_angle_rad: phi,
    })
}

fn validated<T: Real>(
    location: &FaceLocation<T>,
    lie_rad: T,
    aim: &FaceAim<T>,
) -> Result<(FaceAim<T>, T)> {
    finite(location.height_m, Field::ImpactHeight)?;
    finite(location.toe_m, Field::ImpactToe)?;
    Ok((
        FaceAim {
            dynamic_loft_rad: finite(aim.dynamic_loft_rad, Field::DynamicLoft)?,
            face_angle_rad: finite(aim.face_angle_rad, Field::FaceAngle)?,
        },
        finite(lie_rad, Field::Lie)?,
    ))
}

/// `Rx(λ) Rz(α) x̂`: the centre normal before the loft and face turns.
fn centre_direction<T: Real>(club: &ClubHead<T>, lie: T) -> Vector3<T> {
    rot_x(lie) * club.face_rotation() * Vector3::x()
}

/// `Rx(λ) Rz(α) n_E` at `location`, or `None` when the normal there is the centre's
/// (`n_E = x̂` exactly: a centre strike, or a flat face).
fn contact_direction<T: Real>(
    club: &ClubHead<T>,
    location: &FaceLocation<T>,
    lie: T,
) -> Result<Option<Vector3<T>>> {
    let n = contact(club.face(), club.cg_to_face_m(), location)?.normal;
    if n == Vector3::x() {
        return Ok(None);
    }
    Ok(Some(rot_x(lie) * club.face_rotation() * n))
}

/// `(θ, φ)` with `Ry(−φ) Rz(θ) m = t` (unit vectors), the normal pointing forward.
fn solve<T: Real>(m: &Vector3<T>, t: &Vector3<T>) -> Result<(T, T)> {
    let rho = (m.x * m.x + m.y * m.y).root();
    let s = t.y / rho;
    if !(s.abs() <= T::one()) {
        return Err(Error::invalid(Field::DynamicLoft, Reason::OutOfRange));
    }
    let lift = s.asin();
    let theta = lift - m.y.atan2(m.x);
    // cos(asin s) = √(1 − s²) on the principal branch (libm's f32 `cos` runs in f64)
    let phi = t.z.atan2(t.x) - m.z.atan2(rho * (T::one() - s * s).root());
    if !(theta.is_finite() && phi.is_finite()) {
        return Err(Error::invalid(Field::DynamicLoft, Reason::OutOfRange));
    }
    Ok((theta, phi))
}

impl<T: Real> Delivery<T> {
    /// This delivery read in `convention`, as the seed's delivery (angles at the face
    /// centre) that strikes the same way: unchanged for [`DeliveryConvention::SeedCentre`].
    ///
    /// # Errors
    /// As [`centre_aim`].
    pub fn in_seed_convention(
        &self,
        club: &ClubHead<T>,
        convention: DeliveryConvention,
    ) -> Result<Self> {
        match convention {
            DeliveryConvention::SeedCentre => Ok(*self),
            DeliveryConvention::TrackMan => {
                let aim = FaceAim {
                    dynamic_loft_rad: self.dynamic_loft_rad,
                    face_angle_rad: self.face_angle_rad,
                };
                let c = centre_aim(club, &self.location, self.lie_rad, &aim)?;
                Ok(Self {
                    dynamic_loft_rad: c.dynamic_loft_rad,
                    face_angle_rad: c.face_angle_rad,
                    ..*self
                })
            }
        }
    }

    /// The strike of this delivery read in `convention` ([`Delivery::strike`] is the
    /// seed's reading).
    ///
    /// # Errors
    /// As [`centre_aim`] and [`Delivery::strike`].
    pub fn strike_in(
        &self,
        club: &ClubHead<T>,
        convention: DeliveryConvention,
    ) -> Result<Strike<T>> {
        self.in_seed_convention(club, convention)?.strike(club)
    }
}
