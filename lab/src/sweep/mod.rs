//! `carry sweep`: where in the swing should the ball sit?
//!
//! Input: a club-head motion through impact sampled in time ([`Motion`], CSV). For each
//! ball position along the target line, find the instant the face reaches the ball
//! (contact), take the club state there (velocity, angular velocity, orientation →
//! [`carry_core::Strike::new`]), then the impact and the flight
//! ([`carry_core::shot`]'s solver and the setup's scene). Output: carry, side, launch and
//! spin against ball position, and the best position (longest carry).
//!
//! [`generate`] holds the example swing's model (a planar double pendulum).

mod contact;
pub mod generate;
pub mod motion;
mod plot;

pub use motion::{Motion, Sample};
pub use plot::draw;

use crate::error::{Error, Input, Result};
use crate::setup::{Setup, ShotSummary};
use carry_core::real::{lit, to_f64};
use carry_core::{BallMotion, ClubMotion, FaceLocation, Real, Strike, impact};
use contact::FaceTrack;
use nalgebra::{Matrix3, Vector3};
use serde::Serialize;

/// Most ball positions a sweep accepts.
pub const MAX_POSITIONS: usize = 1_000_000;

/// The ball positions `from, from + step, …, ≤ to` (m).
///
/// # Errors
/// [`Error::Invalid`] ([`Input::BallPositions`]): non-finite values, `from > to`, a step
/// that is not positive, or more than [`MAX_POSITIONS`] positions.
pub fn positions(from: f64, to: f64, step: f64) -> Result<Vec<f64>> {
    let bad = |why: &str| Error::invalid(Input::BallPositions, why);
    if !(from.is_finite() && to.is_finite() && step.is_finite()) {
        return Err(bad("from, to and step must be finite numbers"));
    }
    if from > to {
        return Err(bad("from is after to: give from,to,step with from ≤ to"));
    }
    if !(step > 0.0) {
        return Err(bad("the step must be positive"));
    }
    let count = ((to - from) / step + 1e-9).floor() + 1.0;
    if !(count <= MAX_POSITIONS as f64) {
        return Err(bad("too many positions (at most 1,000,000)"));
    }
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let count = count as usize;
    #[allow(clippy::cast_precision_loss)]
    Ok((0..count).map(|k| from + step * k as f64).collect())
}

/// The club at contact, in launch-monitor terms.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ClubAtContact {
    /// Time of contact in the swing file (s).
    pub impact_time_s: f64,
    /// Club head speed (m/s).
    pub club_speed_mps: f64,
    /// Attack angle (deg, + up).
    pub attack_angle_deg: f64,
    /// Club path (deg, + right).
    pub club_path_deg: f64,
    /// Face angle (deg, + open): the face normal's direction.
    pub face_angle_deg: f64,
    /// Dynamic loft (deg): the face normal's elevation.
    pub dynamic_loft_deg: f64,
    /// Impact height up the face (m).
    pub impact_height_m: f64,
    /// Impact offset toward the toe (m).
    pub impact_toe_m: f64,
}

/// One ball position's result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Row {
    /// Ball position along the target line (m).
    pub ball_position_m: f64,
    /// The club at contact.
    #[serde(flatten)]
    pub club: ClubAtContact,
    /// The shot, if the impact and flight succeed.
    #[serde(flatten)]
    pub shot: Option<ShotSummary>,
    /// Why the shot failed (e.g. the contact is off the face).
    pub error: Option<String>,
}

/// A sweep's result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sweep {
    /// One row per ball position, in order.
    pub rows: Vec<Row>,
    /// The index of the row with the longest carry.
    pub best: Option<usize>,
}

impl Sweep {
    /// The row with the longest carry.
    #[must_use]
    pub fn best_row(&self) -> Option<&Row> {
        self.best.and_then(|i| self.rows.get(i))
    }
}

fn club_at_contact(c: &contact::Contact) -> ClubAtContact {
    let v = c.state.velocity_mps;
    let speed = v.norm();
    let n = c.normal;
    ClubAtContact {
        impact_time_s: c.state.time_s,
        club_speed_mps: speed,
        attack_angle_deg: (v.y / speed).asin().to_degrees(),
        club_path_deg: v.z.atan2(v.x).to_degrees(),
        face_angle_deg: n.z.atan2(n.x).to_degrees(),
        dynamic_loft_deg: n.y.clamp(-1.0, 1.0).asin().to_degrees(),
        impact_height_m: c.height_m,
        impact_toe_m: c.toe_m,
    }
}

fn m3<T: Real>(m: &Matrix3<f64>) -> Matrix3<T> {
    m.map(lit)
}

fn v3<T: Real>(v: &Vector3<f64>) -> Vector3<T> {
    v.map(lit)
}

/// Sweeps `positions` (m along the target line) through `motion` with the setup's club,
/// ball, scene and numerics (its delivery is not used).
///
/// # Errors
/// [`Error::Invalid`] ([`Input::BallPositions`]) when the face never reaches a ball
/// position within the samples, or a ball is behind the face at the first sample.
pub fn sweep<T: Real>(setup: &Setup<T>, motion: &Motion, positions: &[f64]) -> Result<Sweep> {
    let face_rotation = setup.club.face_rotation().map(to_f64);
    let cg = setup.club.cg_to_face_m().map(to_f64);
    let track = FaceTrack::new(motion, face_rotation, cg, to_f64(setup.ball.radius_m()));
    let mut rows = Vec::with_capacity(positions.len());
    for &x in positions {
        let contact = track.contact(motion, x)?;
        let club = club_at_contact(&contact);
        let s = &contact.state;
        let strike = Strike::new(
            ClubMotion {
                velocity_mps: v3(&s.velocity_mps),
                spin_radps: v3(&s.spin_radps),
                orientation: m3(s.orientation.to_rotation_matrix().matrix()),
            },
            BallMotion::at_rest(),
            FaceLocation {
                height_m: lit(contact.height_m),
                toe_m: lit(contact.toe_m),
            },
        );
        let shot = strike
            .and_then(|strike| {
                let i = impact::solve(&setup.club, &setup.ball, &strike, setup.fidelity.solver)?;
                let f = setup.scene.fly(&i.ball, &setup.fidelity.integrator, None)?;
                Ok(ShotSummary::of(&carry_core::shot::ShotOutcome {
                    impact: i,
                    flight: f,
                }))
            })
            .map_err(|e| e.to_string());
        let (shot, error) = match shot {
            Ok(s) => (Some(s), None),
            Err(e) => (None, Some(e)),
        };
        rows.push(Row {
            ball_position_m: x,
            club,
            shot,
            error,
        });
    }
    let best = rows
        .iter()
        .enumerate()
        .filter_map(|(i, r)| r.shot.map(|s| (i, s.carry_m)))
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(i, _)| i);
    Ok(Sweep { rows, best })
}
