//! Full shots with a ground (issue 12): club preset and delivery → impact → flight →
//! bounces and roll to rest, on each surface, level and sloped; and topped shots
//! (issue 21), launched at or below the horizon, which meet the turf at once and run out.
//!
//! Like `cases.rs`, compiled into the firmware and `#[path]`-included by `build.rs`,
//! which runs the same code on the host so that the on-target tests can demand bit
//! identity. It uses only `core`, `carry-core` and `nalgebra`.
#![allow(dead_code)]

use carry_core::ground::{Ground, RunEnd, Surface};
use carry_core::real::{Real, lit};
use carry_core::scene::Scene;
use carry_core::shot::{Fidelity, play};
use carry_core::units::{deg, rpm};
use carry_core::{Ball, Delivery, Error, FaceLocation, Launch, Preset};

/// One full shot with a ground.
#[derive(Debug, Clone, Copy)]
pub struct GroundCase {
    pub name: &'static str,
    /// Club preset name (`carry_core::PRESETS`).
    pub club: &'static str,
    pub club_speed_mps: f64,
    /// 0 firm fairway, 1 soft fairway, 2 rough, 3 green, 4 the joint fairway (issue 35).
    pub surface: u8,
    /// Green speed (ft), greens only.
    pub stimp_ft: f64,
    pub slope_deg: f64,
    pub slope_direction_deg: f64,
    /// A launch given directly instead of the club's (ball speed m/s, launch angle deg,
    /// backspin rpm): a topped shot, launched from the turf at or below the horizon.
    pub launch: Option<[f64; 3]>,
}

/// The on-target ground shots.
pub const GROUND_CASES: [GroundCase; 9] = [
    GroundCase {
        name: "driver_fairway",
        club: "driver",
        club_speed_mps: 45.0,
        surface: 0,
        stimp_ft: 0.0,
        slope_deg: 0.0,
        slope_direction_deg: 0.0,
        launch: None,
    },
    GroundCase {
        name: "driver_soft_uphill",
        club: "driver",
        club_speed_mps: 50.0,
        surface: 1,
        stimp_ft: 0.0,
        slope_deg: 3.0,
        slope_direction_deg: 20.0,
        launch: None,
    },
    GroundCase {
        name: "7iron_rough",
        club: "7iron",
        club_speed_mps: 40.0,
        surface: 2,
        stimp_ft: 0.0,
        slope_deg: 0.0,
        slope_direction_deg: 0.0,
        launch: None,
    },
    GroundCase {
        name: "pw_green",
        club: "pw",
        club_speed_mps: 38.0,
        surface: 3,
        stimp_ft: 11.0,
        slope_deg: 0.0,
        slope_direction_deg: 0.0,
        launch: None,
    },
    GroundCase {
        name: "pw_green_sidehill",
        club: "pw",
        club_speed_mps: 38.0,
        surface: 3,
        stimp_ft: 10.0,
        slope_deg: 2.0,
        slope_direction_deg: 90.0,
        launch: None,
    },
    GroundCase {
        name: "lw_steep_green_rolls_on",
        club: "lw58",
        club_speed_mps: 32.0,
        surface: 3,
        stimp_ft: 13.0,
        slope_deg: 8.0,
        slope_direction_deg: -120.0,
        launch: None,
    },
    // A topped drive (100 mph ball, 2° below the horizon, 1,800 rpm) on the firm fairway.
    GroundCase {
        name: "topped_driver_fairway",
        club: "driver",
        club_speed_mps: 0.0,
        surface: 0,
        stimp_ft: 0.0,
        slope_deg: 0.0,
        slope_direction_deg: 0.0,
        launch: Some([44.7, -2.0, 1800.0]),
    },
    // A thinned iron launched level into the rough, downhill.
    GroundCase {
        name: "thin_iron_at_horizon_rough",
        club: "7iron",
        club_speed_mps: 0.0,
        surface: 2,
        stimp_ft: 0.0,
        slope_deg: 2.0,
        slope_direction_deg: 180.0,
        launch: Some([38.0, 0.0, 900.0]),
    },
    // The driver on the joint fairway (issue 35: TrackMan's drives and chart), slightly
    // downhill: the normal–tangential crater and the turf's own fade and grass drag.
    GroundCase {
        name: "driver_fairway_joint",
        club: "driver",
        club_speed_mps: 45.0,
        surface: 4,
        stimp_ft: 0.0,
        slope_deg: 1.5,
        slope_direction_deg: 170.0,
        launch: None,
    },
];

/// Ground outputs, in this order: carry, total, roll, rest x, y, z, time to rest,
/// bounces, hop force evaluations, still rolling (1) or at rest (0).
pub const GROUND_OUTPUTS: usize = 10;
/// Names of the ground outputs (for messages).
pub const GROUND_NAMES: [&str; GROUND_OUTPUTS] = [
    "carry",
    "total",
    "roll",
    "rest_x",
    "rest_y",
    "rest_z",
    "time_to_rest",
    "bounces",
    "evaluations",
    "still_rolling",
];

impl GroundCase {
    /// The scene: defaults plus this ground.
    #[must_use]
    pub fn scene<T: Real>(&self) -> Scene<T> {
        let surface = match self.surface {
            0 => Surface::FairwayFirm,
            1 => Surface::FairwaySoft,
            2 => Surface::Rough,
            4 => Surface::FairwayJoint,
            _ => Surface::Green {
                stimp_m: lit(self.stimp_ft * carry_core::ground::surface::FOOT_M),
            },
        };
        Scene {
            ground: Some(Ground::sloped(
                surface,
                deg(lit(self.slope_deg)),
                deg(lit(self.slope_direction_deg)),
            )),
            ..Scene::default()
        }
    }

    /// The full shot, flattened (see [`GROUND_OUTPUTS`]).
    ///
    /// # Errors
    /// The core's error ([`Error::InvalidInput`] for an unknown preset).
    pub fn outputs<T: Real>(&self) -> Result<[T; GROUND_OUTPUTS], Error> {
        let ball = Ball::standard();
        let scene = self.scene::<T>().prepare(&ball)?;
        let fidelity = Fidelity::default();
        let f = if let Some([speed_mps, angle_deg, backspin_rpm]) = self.launch {
            let launch = Launch {
                ball_speed_mps: lit(speed_mps),
                launch_angle_rad: deg(lit(angle_deg)),
                launch_direction_rad: T::zero(),
                backspin_radps: rpm(lit(backspin_rpm)),
                sidespin_radps: T::zero(),
            };
            scene.fly(&launch.ball_motion()?, &fidelity.integrator, None)?
        } else {
            let preset = Preset::find(self.club).ok_or(Error::invalid(
                carry_core::Field::Loft,
                carry_core::Reason::OutOfRange,
            ))?;
            let club = preset.spec::<T>().validate()?;
            let mut delivery = Delivery::square(lit(self.club_speed_mps), &club);
            delivery.location = FaceLocation {
                height_m: lit(0.003),
                toe_m: lit(0.005),
            };
            play(&club, &ball, &delivery, &scene, &fidelity, None)?.flight
        };
        let g = f.ground.ok_or(Error::NoLanding)?;
        let n = |x: u32| -> T { lit(f64::from(x)) };
        Ok([
            f.carry_m,
            g.total_m,
            g.roll_m,
            g.rest_position_m.x,
            g.rest_position_m.y,
            g.rest_position_m.z,
            g.time_to_rest_s,
            n(g.bounces),
            n(g.stats.force_evaluations),
            if g.end == RunEnd::StillRolling {
                T::one()
            } else {
                T::zero()
            },
        ])
    }
}
