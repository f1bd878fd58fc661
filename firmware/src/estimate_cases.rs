//! Club data from ball data (issue 23): estimates from launch-monitor ball data, with and
//! without club data, for a driver and an iron.
//!
//! Like `cases.rs`, compiled into the firmware and `#[path]`-included by `build.rs`,
//! which runs the same code on the host so that the on-target tests can demand bit
//! identity. It uses only `core`, `carry-core` and `nalgebra`.
#![allow(dead_code)]

use carry_core::estimate::{BallData, ClubData, Settings, estimate};
use carry_core::real::{Real, lit};
use carry_core::units::{deg, rpm};
use carry_core::{Ball, Error, Preset};

/// One estimate: club preset, ball data (deg, rpm, m/s) and what was measured of the club.
#[derive(Debug, Clone, Copy)]
pub struct EstimateCase {
    pub name: &'static str,
    /// Club preset name (`carry_core::PRESETS`).
    pub club: &'static str,
    pub ball_speed_mps: f64,
    pub launch_angle_deg: f64,
    pub launch_direction_deg: f64,
    pub spin_rpm: f64,
    pub spin_axis_deg: f64,
    /// Measured club speed (m/s), if any.
    pub club_speed_mps: Option<f64>,
    /// Measured club path (deg), if any.
    pub club_path_deg: Option<f64>,
}

/// The on-target estimates.
pub const ESTIMATE_CASES: [EstimateCase; 4] = [
    EstimateCase {
        name: "driver_fade_club_speed",
        club: "driver",
        ball_speed_mps: 66.0,
        launch_angle_deg: 13.2,
        launch_direction_deg: 1.1,
        spin_rpm: 2750.0,
        spin_axis_deg: 6.5,
        club_speed_mps: Some(45.5),
        club_path_deg: None,
    },
    EstimateCase {
        name: "driver_draw_ball_only",
        club: "driver",
        ball_speed_mps: 70.0,
        launch_angle_deg: 11.0,
        launch_direction_deg: -2.0,
        spin_rpm: 2300.0,
        spin_axis_deg: -8.0,
        club_speed_mps: None,
        club_path_deg: None,
    },
    EstimateCase {
        name: "driver_path_measured",
        club: "driver",
        ball_speed_mps: 63.0,
        launch_angle_deg: 15.0,
        launch_direction_deg: 3.0,
        spin_rpm: 3300.0,
        spin_axis_deg: 12.0,
        club_speed_mps: Some(44.0),
        club_path_deg: Some(-3.0),
    },
    EstimateCase {
        name: "7iron_club_speed",
        club: "7iron",
        ball_speed_mps: 53.0,
        launch_angle_deg: 17.0,
        launch_direction_deg: 0.5,
        spin_rpm: 6800.0,
        spin_axis_deg: 2.0,
        club_speed_mps: Some(39.0),
        club_path_deg: None,
    },
];

/// Estimate outputs, in this order: the ten values of `ClubEstimate` (face, path,
/// face-to-path, dynamic loft, attack, spin loft, toe, height, club speed, smash), their
/// ten 1σ, the five residuals and the iterations.
pub const ESTIMATE_OUTPUTS: usize = 26;
/// Names of the estimate outputs (for messages).
pub const ESTIMATE_NAMES: [&str; ESTIMATE_OUTPUTS] = [
    "face",
    "path",
    "face_to_path",
    "dynamic_loft",
    "attack",
    "spin_loft",
    "toe",
    "height",
    "club_speed",
    "smash",
    "face_sd",
    "path_sd",
    "face_to_path_sd",
    "dynamic_loft_sd",
    "attack_sd",
    "spin_loft_sd",
    "toe_sd",
    "height_sd",
    "club_speed_sd",
    "smash_sd",
    "res_ball_speed",
    "res_launch_angle",
    "res_launch_direction",
    "res_spin",
    "res_spin_axis",
    "iterations",
];

impl EstimateCase {
    /// The estimate with the preset's default settings, flattened (see
    /// [`ESTIMATE_OUTPUTS`]).
    ///
    /// # Errors
    /// The core's error ([`Error::InvalidInput`] for an unknown preset).
    pub fn outputs<T: Real>(&self) -> Result<[T; ESTIMATE_OUTPUTS], Error> {
        let preset = Preset::find(self.club).ok_or(Error::invalid(
            carry_core::Field::Loft,
            carry_core::Reason::OutOfRange,
        ))?;
        let club = preset.spec::<T>().validate()?;
        let measured = BallData {
            ball_speed_mps: lit(self.ball_speed_mps),
            launch_angle_rad: deg(lit(self.launch_angle_deg)),
            launch_direction_rad: deg(lit(self.launch_direction_deg)),
            spin_radps: rpm(lit(self.spin_rpm)),
            spin_axis_rad: deg(lit(self.spin_axis_deg)),
        };
        let club_data = ClubData {
            club_speed_mps: self.club_speed_mps.map(lit),
            club_path_rad: self.club_path_deg.map(|p| deg(lit(p))),
            ..ClubData::default()
        };
        let settings = Settings::typical(&preset.typical);
        let e = estimate(&club, &Ball::standard(), &measured, &club_data, &settings)?;
        let mut out = [T::zero(); ESTIMATE_OUTPUTS];
        let all = e
            .value
            .to_array()
            .into_iter()
            .chain(e.sd.to_array())
            .chain(e.residual.to_array())
            .chain([lit(f64::from(e.iterations))]);
        for (o, v) in out.iter_mut().zip(all) {
            *o = v;
        }
        Ok(out)
    }
}
