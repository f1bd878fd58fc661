//! The forward model of the estimator: a delivery in TrackMan's convention → the five ball
//! numbers a launch monitor measures, through the same impact the CLI runs
//! ([`crate::Delivery::strike_in`] with [`DeliveryConvention::TrackMan`], then
//! [`crate::impact::solve`] with the reduced solver and the club's contact law).

use crate::ball::Ball;
use crate::club::ClubHead;
use crate::convention::DeliveryConvention;
use crate::delivery::{Delivery, FaceLocation};
use crate::error::Result;
use crate::impact::{self, Solver};
use crate::real::Real;
use nalgebra::Vector3;

use super::BallData;

/// The estimator's unknowns (TrackMan's convention; SI). Also the shape of the prior's mean
/// and spread and of the club measurements' noise.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Unknowns<T> {
    /// Face angle at the contact point, + open (rad).
    pub face_angle_rad: T,
    /// Club path, + in-to-out (rad).
    pub club_path_rad: T,
    /// Dynamic loft at the contact point (rad).
    pub dynamic_loft_rad: T,
    /// Attack angle, + up (rad).
    pub attack_angle_rad: T,
    /// Strike toward the toe from the face centre (m).
    pub impact_toe_m: T,
    /// Strike up the face from the face centre (m).
    pub impact_height_m: T,
    /// Club head speed (m/s).
    pub club_speed_mps: T,
}

/// Index of the club speed in [`Unknowns::to_array`].
pub(super) const SPEED: usize = 6;

impl<T: Real> Unknowns<T> {
    /// As an array in the order of the fields.
    #[must_use]
    pub fn to_array(&self) -> [T; 7] {
        [
            self.face_angle_rad,
            self.club_path_rad,
            self.dynamic_loft_rad,
            self.attack_angle_rad,
            self.impact_toe_m,
            self.impact_height_m,
            self.club_speed_mps,
        ]
    }

    /// From an array in the order of the fields.
    #[must_use]
    pub fn from_array(a: [T; 7]) -> Self {
        let [face, path, loft, attack, toe, height, speed] = a;
        Self {
            face_angle_rad: face,
            club_path_rad: path,
            dynamic_loft_rad: loft,
            attack_angle_rad: attack,
            impact_toe_m: toe,
            impact_height_m: height,
            club_speed_mps: speed,
        }
    }

    /// The core delivery (TrackMan's convention; no lie, no club spin).
    #[must_use]
    pub fn delivery(&self) -> Delivery<T> {
        Delivery {
            club_speed_mps: self.club_speed_mps,
            attack_angle_rad: self.attack_angle_rad,
            club_path_rad: self.club_path_rad,
            face_angle_rad: self.face_angle_rad,
            dynamic_loft_rad: self.dynamic_loft_rad,
            lie_rad: T::zero(),
            club_spin_radps: Vector3::zeros(),
            location: FaceLocation {
                height_m: self.impact_height_m,
                toe_m: self.impact_toe_m,
            },
        }
    }
}

/// The bodies of the forward model.
pub(super) struct Model<'a, T: Real> {
    pub club: &'a ClubHead<T>,
    pub ball: &'a Ball<T>,
}

impl<T: Real> Model<'_, T> {
    /// The ball numbers of delivery `x` ([`predict`]).
    pub fn predict(&self, x: &Unknowns<T>) -> Result<BallData<T>> {
        predict(self.club, self.ball, x)
    }
}

/// The ball numbers `club` gives `ball` with delivery `x` (TrackMan's convention; reduced
/// solver; the club's contact law): the estimator's forward model `f(x)`.
///
/// # Errors
/// As [`Delivery::strike_in`] and [`impact::solve`].
pub fn predict<T: Real>(
    club: &ClubHead<T>,
    ball: &Ball<T>,
    x: &Unknowns<T>,
) -> Result<BallData<T>> {
    let strike = x.delivery().strike_in(club, DeliveryConvention::TrackMan)?;
    let out = impact::solve(club, ball, &strike, Solver::Reduced)?;
    Ok(BallData::from_metrics(&out.launch))
}
