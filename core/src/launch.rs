//! Launch conditions in launch-monitor terms, both ways (PHYSICS.md):
//!
//! ```text
//! ball speed        |V|
//! launch angle      asin(V_y / |V|)             (+ up)
//! launch direction  ψ = atan2(V_z, V_x)         (+ right)
//! backspin          Ω · (−sin ψ, 0, cos ψ)
//! sidespin          −Ω_y                        (+ curves right: fade/slice)
//! spin axis         atan2(sidespin, backspin)   (+ tilted right)
//! smash factor      |V| / v_club
//! Ω = backspin·(−sin ψ, 0, cos ψ) + (0, −sidespin, 0)
//! ```

use crate::ball::BallMotion;
use crate::error::{Field, Result};
use crate::geometry::sin_cos;
use crate::real::{Real, length};
use crate::validate::{finite, non_negative};
use nalgebra::Vector3;

/// Launch metrics as a launch monitor reports them (SI: m/s, rad, rad/s).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LaunchMetrics<T> {
    /// Ball speed |V_b| (m/s).
    pub ball_speed_mps: T,
    /// Launch angle above the horizontal (rad).
    pub launch_angle_rad: T,
    /// Launch direction ψ, + right of the target line (rad).
    pub launch_direction_rad: T,
    /// Total spin |Ω_b| (rad/s).
    pub spin_radps: T,
    /// Backspin: spin about the horizontal axis square to the launch direction (rad/s).
    pub backspin_radps: T,
    /// Sidespin −Ω_y, + curves right (rad/s).
    pub sidespin_radps: T,
    /// Spin axis tilt atan2(sidespin, backspin), + tilted right (rad).
    pub spin_axis_rad: T,
    /// Smash factor |V_b| / club speed (zero when the club speed is zero).
    pub smash_factor: T,
}

impl<T: Real> LaunchMetrics<T> {
    /// Metrics of a ball leaving with `motion`, struck by a club at `club_speed_mps`.
    #[must_use]
    pub fn from_motion(motion: &BallMotion<T>, club_speed_mps: T) -> Self {
        let v = &motion.velocity_mps;
        let w = &motion.spin_radps;
        let speed = length(v);
        // sin ψ, cos ψ from the components: no trigonometry (f32 sin/cos run in soft f64 on
        // a Cortex-M4F), and exact where atan2 then sin_cos would round twice.
        let horizontal = (v.x * v.x + v.z * v.z).root();
        let direction = v.z.atan2(v.x);
        let (sin_psi, cos_psi) = if horizontal > T::zero() {
            (v.z / horizontal, v.x / horizontal)
        } else {
            (T::zero(), T::one())
        };
        let backspin = -w.x * sin_psi + w.z * cos_psi;
        let sidespin = -w.y;
        Self {
            ball_speed_mps: speed,
            launch_angle_rad: v.y.atan2(horizontal),
            launch_direction_rad: direction,
            spin_radps: length(w),
            backspin_radps: backspin,
            sidespin_radps: sidespin,
            spin_axis_rad: sidespin.atan2(backspin),
            smash_factor: if club_speed_mps > T::zero() {
                speed / club_speed_mps
            } else {
                T::zero()
            },
        }
    }
}

/// A launch as a launch monitor measures it: the input of a flight.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Launch<T> {
    /// Ball speed (m/s).
    pub ball_speed_mps: T,
    /// Launch angle, + up (rad).
    pub launch_angle_rad: T,
    /// Launch direction ψ, + right (rad).
    pub launch_direction_rad: T,
    /// Backspin (rad/s).
    pub backspin_radps: T,
    /// Sidespin, + curves right (rad/s).
    pub sidespin_radps: T,
}

impl<T: Real> Launch<T> {
    /// A launch from total spin and spin axis (+ tilted right) instead of back/sidespin:
    /// backspin = spin·cos(axis), sidespin = spin·sin(axis).
    #[must_use]
    pub fn from_spin_axis(
        ball_speed_mps: T,
        launch_angle_rad: T,
        launch_direction_rad: T,
        spin_radps: T,
        spin_axis_rad: T,
    ) -> Self {
        let (s, c) = sin_cos(spin_axis_rad);
        Self {
            ball_speed_mps,
            launch_angle_rad,
            launch_direction_rad,
            backspin_radps: spin_radps * c,
            sidespin_radps: spin_radps * s,
        }
    }

    /// The launch a ball in `motion` has (inverse of [`Launch::ball_motion`]).
    #[must_use]
    pub fn from_motion(motion: &BallMotion<T>) -> Self {
        let m = LaunchMetrics::from_motion(motion, T::zero());
        Self {
            ball_speed_mps: m.ball_speed_mps,
            launch_angle_rad: m.launch_angle_rad,
            launch_direction_rad: m.launch_direction_rad,
            backspin_radps: m.backspin_radps,
            sidespin_radps: m.sidespin_radps,
        }
    }

    /// Ball velocity and spin in G:
    /// `V = speed·(cos θ cos ψ, sin θ, cos θ sin ψ)`,
    /// `Ω = backspin·(−sin ψ, 0, cos ψ) + (0, −sidespin, 0)`.
    ///
    /// # Errors
    /// [`crate::Error::InvalidInput`] for a non-finite value or a negative ball speed.
    pub fn ball_motion(&self) -> Result<BallMotion<T>> {
        let speed = non_negative(self.ball_speed_mps, Field::BallSpeed)?;
        let (st, ct) = sin_cos(finite(self.launch_angle_rad, Field::LaunchAngle)?);
        let (sp, cp) = sin_cos(finite(self.launch_direction_rad, Field::LaunchDirection)?);
        let back = finite(self.backspin_radps, Field::Backspin)?;
        let side = finite(self.sidespin_radps, Field::Sidespin)?;
        Ok(BallMotion {
            velocity_mps: Vector3::new(ct * cp, st, ct * sp) * speed,
            spin_radps: Vector3::new(-sp * back, -side, cp * back),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn launch_round_trips_through_ball_motion() {
        let l = Launch {
            ball_speed_mps: 70.0_f64,
            launch_angle_rad: 0.2,
            launch_direction_rad: -0.05,
            backspin_radps: 260.0,
            sidespin_radps: -40.0,
        };
        let Ok(m) = l.ball_motion() else { panic!() };
        let back = Launch::from_motion(&m);
        assert!((back.ball_speed_mps - 70.0).abs() < 1e-12);
        assert!((back.launch_angle_rad - 0.2).abs() < 1e-14);
        assert!((back.launch_direction_rad + 0.05).abs() < 1e-14);
        assert!((back.backspin_radps - 260.0).abs() < 1e-12);
        assert!((back.sidespin_radps + 40.0).abs() < 1e-12);
    }

    #[test]
    fn spin_axis_signs() {
        let l = Launch::from_spin_axis(70.0_f64, 0.2, 0.0, 300.0, 0.3);
        let m = LaunchMetrics::from_motion(&l.ball_motion().unwrap_or_default(), 45.0);
        assert!(m.spin_axis_rad > 0.0 && m.sidespin_radps > 0.0);
        assert!((m.spin_axis_rad - 0.3).abs() < 1e-14);
    }
}
