//! What a flight returns.

use crate::ground::Rollout;
use crate::real::Real;
use crate::trajectory::Stats;
use nalgebra::Vector3;

/// Where and how the ball lands.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FlightOutcome<T: Real> {
    /// Carry: horizontal distance from the tee to the landing point (m).
    pub carry_m: T,
    /// Carry along the target line, landing X − tee X (m).
    pub carry_x_m: T,
    /// Side: landing Z − tee Z, + right (m).
    pub side_m: T,
    /// Apex: the highest Y of the flight (m, G; the tee's ground is Y = 0), located on the
    /// interpolant where `v_y = 0`. The launch height if the ball never rises.
    pub apex_m: T,
    /// Time of the apex (s).
    pub apex_time_s: T,
    /// Flight time, launch to landing (s).
    pub flight_time_s: T,
    /// Landing angle below the horizontal (rad), ground frame: `atan2(−v_y, |v_xz|)`.
    pub landing_angle_rad: T,
    /// Landing speed |v|, ground frame (m/s).
    pub landing_speed_mps: T,
    /// Spin at landing |ω| (rad/s).
    pub landing_spin_radps: T,
    /// Landing position (m, G).
    pub landing_position_m: Vector3<T>,
    /// Landing velocity, ground frame (m/s, G).
    pub landing_velocity_mps: Vector3<T>,
    /// Spin vector at landing (rad/s, G).
    pub landing_spin_vector_radps: Vector3<T>,
    /// The air density flown through (kg/m³).
    pub air_density_kgm3: T,
    /// Work done: force evaluations, accepted and rejected steps.
    pub stats: Stats,
    /// The recorder's buffer filled up and samples were dropped.
    pub recording_full: bool,
    /// Bounce and roll to rest, when the scene has a ground (`None` otherwise).
    pub ground: Option<Rollout<T>>,
}
