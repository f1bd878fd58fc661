//! Impact: club delivery → ball launch.

use crate::club::{CarryBall, CarryClub};
use crate::error::{CARRY_ERR_UNKNOWN_OPTION, Result};
use crate::settings::CarrySettings;
use carry_core::impact::{self, ImpactOutcome};
use carry_core::presets::Preset;
use carry_core::real::{Real, lit};
use carry_core::{Delivery, DeliveryConvention, FaceLocation, Strike};
use nalgebra::Vector3;

/// `CarryDelivery::convention`: face angle and dynamic loft at the face centre (the seed's,
/// PHYSICS.md; what the golden files pin). Zero, so a zeroed struct reads angles as before.
pub const CARRY_CONVENTION_SEED_CENTRE: u32 = 0;

/// `CarryDelivery::convention`: face angle and dynamic loft at the contact point, club
/// speed, attack and path at the head's CG (TrackMan's; the defaults' and the CLI's).
pub const CARRY_CONVENTION_TRACKMAN: u32 = 1;

/// How the club arrives at the ball, in launch-monitor terms (m/s, rad, rad/s, m).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarryDelivery<T> {
    /// Club head speed (m/s).
    pub club_speed_mps: T,
    /// Attack angle (rad, + up).
    pub attack_angle_rad: T,
    /// Club path (rad, + right of target).
    pub club_path_rad: T,
    /// Face angle (rad, + open).
    pub face_angle_rad: T,
    /// Dynamic loft (rad).
    pub dynamic_loft_rad: T,
    /// Lie / face tilt (rad, + toe up).
    pub lie_rad: T,
    /// Club angular velocity before impact (rad/s, global frame).
    pub club_spin_radps: [T; 3],
    /// Impact location up the face from its centre (m).
    pub impact_height_m: T,
    /// Impact location toward the toe (m).
    pub impact_toe_m: T,
    /// Where face angle and dynamic loft are read: `CARRY_CONVENTION_TRACKMAN` (at the
    /// contact point; the defaults) or `CARRY_CONVENTION_SEED_CENTRE` (at the face centre).
    pub convention: u32,
}

/// What an impact needs. Start from `carry_impact_input_default_*`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarryImpactInput<T> {
    /// The club head.
    pub club: CarryClub<T>,
    /// The ball.
    pub ball: CarryBall<T>,
    /// The delivery.
    pub delivery: CarryDelivery<T>,
    /// The solver (only `solver` is used).
    pub settings: CarrySettings<T>,
}

/// The result of an impact (global frame: x downrange, y up, z right).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CarryImpactResult<T> {
    /// Ball velocity after impact (m/s).
    pub ball_velocity_mps: [T; 3],
    /// Ball spin after impact (rad/s).
    pub ball_spin_radps: [T; 3],
    /// Club velocity after impact (m/s).
    pub club_velocity_mps: [T; 3],
    /// Club spin after impact (rad/s).
    pub club_spin_radps: [T; 3],
    /// Impulse on the ball (N·s).
    pub impulse_ns: [T; 3],
    /// Ball speed (m/s).
    pub ball_speed_mps: T,
    /// Launch angle above the horizontal (rad).
    pub launch_angle_rad: T,
    /// Launch direction, + right (rad).
    pub launch_direction_rad: T,
    /// Total spin (rad/s).
    pub spin_radps: T,
    /// Backspin (rad/s).
    pub backspin_radps: T,
    /// Sidespin, + curves right (rad/s).
    pub sidespin_radps: T,
    /// Spin axis tilt, + right (rad).
    pub spin_axis_rad: T,
    /// Smash factor: ball speed / club speed.
    pub smash_factor: T,
}

impl<T: Real> CarryDelivery<T> {
    /// The core delivery.
    #[must_use]
    pub fn delivery(&self) -> Delivery<T> {
        Delivery {
            club_speed_mps: self.club_speed_mps,
            attack_angle_rad: self.attack_angle_rad,
            club_path_rad: self.club_path_rad,
            face_angle_rad: self.face_angle_rad,
            dynamic_loft_rad: self.dynamic_loft_rad,
            lie_rad: self.lie_rad,
            club_spin_radps: Vector3::from(self.club_spin_radps),
            location: FaceLocation {
                height_m: self.impact_height_m,
                toe_m: self.impact_toe_m,
            },
        }
    }

    /// The delivery convention.
    ///
    /// # Errors
    /// `CARRY_ERR_UNKNOWN_OPTION` for an unknown `convention`.
    pub fn convention(&self) -> Result<DeliveryConvention> {
        match self.convention {
            CARRY_CONVENTION_SEED_CENTRE => Ok(DeliveryConvention::SeedCentre),
            CARRY_CONVENTION_TRACKMAN => Ok(DeliveryConvention::TrackMan),
            _ => Err(CARRY_ERR_UNKNOWN_OPTION),
        }
    }

    /// The core strike of this delivery on `club`, read in its convention.
    ///
    /// # Errors
    /// `CARRY_ERR_UNKNOWN_OPTION`, or the core's errors.
    pub fn strike(&self, club: &carry_core::ClubHead<T>) -> Result<Strike<T>> {
        Ok(self.delivery().strike_in(club, self.convention()?)?)
    }

    /// The CLI's default delivery for `club`: 45 m/s, square, centred, dynamic loft =
    /// static loft, TrackMan's convention.
    #[must_use]
    pub fn square(club: &CarryClub<T>) -> Self {
        Self {
            club_speed_mps: lit(45.0),
            attack_angle_rad: T::zero(),
            club_path_rad: T::zero(),
            face_angle_rad: T::zero(),
            dynamic_loft_rad: club.loft_rad,
            lie_rad: T::zero(),
            club_spin_radps: [T::zero(); 3],
            impact_height_m: T::zero(),
            impact_toe_m: T::zero(),
            convention: CARRY_CONVENTION_TRACKMAN,
        }
    }

    /// The typical tour delivery of `preset`, as the CLI's `--club NAME` fills it in
    /// (the core's [`carry_core::presets::TypicalDelivery::delivery`], TrackMan's
    /// convention).
    #[must_use]
    pub fn typical(preset: &Preset) -> Self {
        Self::from_delivery(
            &preset.typical.delivery::<T>(),
            carry_core::presets::TYPICAL_CONVENTION,
        )
    }

    /// The C form of a core delivery read in `convention`.
    #[must_use]
    pub fn from_delivery(d: &Delivery<T>, convention: DeliveryConvention) -> Self {
        Self {
            club_speed_mps: d.club_speed_mps,
            attack_angle_rad: d.attack_angle_rad,
            club_path_rad: d.club_path_rad,
            face_angle_rad: d.face_angle_rad,
            dynamic_loft_rad: d.dynamic_loft_rad,
            lie_rad: d.lie_rad,
            club_spin_radps: d.club_spin_radps.into(),
            impact_height_m: d.location.height_m,
            impact_toe_m: d.location.toe_m,
            convention: match convention {
                DeliveryConvention::SeedCentre => CARRY_CONVENTION_SEED_CENTRE,
                DeliveryConvention::TrackMan => CARRY_CONVENTION_TRACKMAN,
            },
        }
    }
}

impl<T: Real> CarryImpactResult<T> {
    /// The C form of a core impact outcome.
    #[must_use]
    pub fn from_outcome(o: &ImpactOutcome<T>) -> Self {
        let l = &o.launch;
        Self {
            ball_velocity_mps: o.ball.velocity_mps.into(),
            ball_spin_radps: o.ball.spin_radps.into(),
            club_velocity_mps: o.club.velocity_mps.into(),
            club_spin_radps: o.club.spin_radps.into(),
            impulse_ns: o.impulse_ns.into(),
            ball_speed_mps: l.ball_speed_mps,
            launch_angle_rad: l.launch_angle_rad,
            launch_direction_rad: l.launch_direction_rad,
            spin_radps: l.spin_radps,
            backspin_radps: l.backspin_radps,
            sidespin_radps: l.sidespin_radps,
            spin_axis_rad: l.spin_axis_rad,
            smash_factor: l.smash_factor,
        }
    }
}

impl<T: Real> Default for CarryImpactInput<T> {
    /// The CLI's `carry impact` defaults (TrackMan's convention).
    fn default() -> Self {
        let club = crate::club::default_club();
        Self {
            club,
            ball: CarryBall::standard(),
            delivery: CarryDelivery::square(&club),
            settings: CarrySettings::default(),
        }
    }
}

/// The impact of `input`: validate the club and ball, build the strike, solve.
///
/// # Errors
/// The core's errors; `CARRY_ERR_UNKNOWN_OPTION` for an unknown contact or solver.
pub fn run<T: Real>(input: &CarryImpactInput<T>) -> Result<CarryImpactResult<T>> {
    let club = input.club.spec()?.validate();
    let club = club.as_ref().map_err(|e| *e)?;
    let ball = input.ball.ball()?;
    let solver = input.settings.solver()?;
    let strike = input.delivery.strike(club)?;
    let out = impact::solve(club, &ball, &strike, solver)?;
    Ok(CarryImpactResult::from_outcome(&out))
}
