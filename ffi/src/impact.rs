//! Impact: club delivery → ball launch.

use crate::club::{CarryBall, CarryClub};
use crate::error::Result;
use crate::settings::CarrySettings;
use carry_core::impact::{self, ImpactOutcome};
use carry_core::presets::{Preset, roll_tilt_rad};
use carry_core::real::{Real, lit};
use carry_core::units::deg;
use carry_core::{Delivery, FaceLocation};
use nalgebra::Vector3;

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

    /// The CLI's default delivery for `club`: 45 m/s, square, centred, dynamic loft =
    /// static loft.
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
        }
    }

    /// The typical tour delivery of `preset`, as the CLI's `--club NAME` fills it in:
    /// club speed, attack angle, strike height, and the club's turn for TrackMan's
    /// dynamic loft at the contact point.
    #[must_use]
    pub fn typical(preset: &Preset) -> Self {
        let t = &preset.typical;
        let height = lit::<T>(t.impact_height_m);
        let tilt = match preset.spec::<T>().validate() {
            Ok(head) => roll_tilt_rad(head.face(), height),
            Err(_) => T::zero(),
        };
        Self {
            club_speed_mps: lit(t.club_speed_mps),
            attack_angle_rad: deg(lit(t.attack_angle_deg)),
            dynamic_loft_rad: deg(lit::<T>(t.dynamic_loft_deg)) - tilt,
            impact_height_m: height,
            ..Self::square(&CarryClub::from_spec(&preset.spec()))
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
    /// The CLI's `carry impact` defaults.
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
    let strike = input.delivery.delivery().strike(club)?;
    let out = impact::solve(club, &ball, &strike, solver)?;
    Ok(CarryImpactResult::from_outcome(&out))
}
