//! The example swing: a planar double pendulum (arms and club) driven by a constant
//! shoulder torque with a natural wrist release, in an inclined swing plane.
//!
//! The model is Jorgensen's (T. P. Jorgensen, *The Physics of Golf*, 2nd ed., Springer
//! 1999, ch. 3–4; after Cochran & Stobbs, *The Search for the Perfect Swing*, 1968): a
//! fixed hub (between the shoulders), an arm rod (hub → hands) and a club rod (hands →
//! head), both rigid. With absolute angles θ (arm) and φ (club) measured in the plane
//! from the plane's downward direction towards the target, `β = φ − θ`,
//! `C = m₂ L₁ a₂`, `I_A = I₁ + m₂ L₁²`, `I_B = J₂ + m₂ a₂²` and the in-plane gravity
//! `g_p = g sin ε` (ε = plane angle from the horizontal), Lagrange's equations are
//!
//! ```text
//! I_A θ̈ + C cos β φ̈ = τ_s − τ_w + C sin β φ̇² − g_p (m₁a₁ + m₂L₁) sin θ
//! C cos β θ̈ + I_B φ̈ =       τ_w − C sin β θ̇² − g_p m₂a₂ sin φ
//! ```
//!
//! The wrists hold the club at the top's cock angle β₀ (a stop: the club cannot lag
//! further) for as long as holding it needs a torque in the uncocking sense; then they
//! release (τ_w = 0): Jorgensen's natural release. Integrated by classical RK4 at 10 µs.
//!
//! The plane contains the target line (+X) and the downward direction
//! `ŵ = (0, −sin ε, cos ε)` (the head hangs down and away from the golfer, towards +Z);
//! its normal is `k = ŵ × X̂ = (0, cos ε, sin ε)`. The head's CoM is
//! `hub + L₁ d(θ) + L₂ d(φ)`, `d(α) = cos α ŵ + sin α X̂`. The club head's orientation is
//! `R = Rot(k, φ − φ₀) · Rot(s, ψ)`: the swing in the plane (shaft lean changes the loft,
//! as hands ahead deloft the face), and the face's rotation about the shaft
//! `s = −ŵ` (+ closes), `ψ = κ (φ − φ₀)`, square at φ₀ = the club angle at the low point.
//! The frame's origin is the ball's centre for a ball struck at the face centre at the
//! low point; the samples span the low point ± [`SwingModel::half_window_s`].

use super::motion::{Motion, Sample};
use crate::error::{Error, Input, Result};
use nalgebra::{Matrix3, Rotation3, Unit, UnitQuaternion, Vector3};

/// The swing model's parameters (SI). Defaults: a driver swing of about 45 m/s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SwingModel {
    /// Arm length L₁, hub → hands (m).
    pub arm_length_m: f64,
    /// Arm mass m₁ (both arms, kg).
    pub arm_mass_kg: f64,
    /// Arm moment of inertia about the hub I₁ (kg·m²).
    pub arm_inertia_kgm2: f64,
    /// Club length L₂, hands → head CoM (m).
    pub club_length_m: f64,
    /// Club mass m₂ (kg).
    pub club_mass_kg: f64,
    /// Hands → club CoM a₂ (m).
    pub club_com_m: f64,
    /// Club moment of inertia about its CoM J₂ (kg·m²).
    pub club_inertia_kgm2: f64,
    /// Swing-plane angle from the horizontal ε (rad).
    pub plane_angle_rad: f64,
    /// Constant shoulder torque τ_s (N·m).
    pub shoulder_torque_nm: f64,
    /// Arm angle at the top θ₀ (rad, negative = back).
    pub top_arm_angle_rad: f64,
    /// Wrist cock at the top β₀ (rad, negative = the club lags).
    pub top_wrist_cock_rad: f64,
    /// Face rotation per radian of club swing κ (+ closes through impact).
    pub face_rotation_per_rad: f64,
    /// Half the sampled window around the low point (s).
    pub half_window_s: f64,
    /// Sample interval (s).
    pub sample_interval_s: f64,
}

impl Default for SwingModel {
    /// Arms 0.62 m, 7 kg, I₁ = m₁L₁²/3; a driver of 1.10 m to the head's CoM, 0.31 kg
    /// (0.2 kg head, 0.11 kg shaft and grip), CoM 0.905 m from the hands, J₂ = 0.0325
    /// kg·m²; plane 55°; top of the swing θ₀ = −150°, β₀ = −90°; 96 N·m; κ = 0.8;
    /// ±12 ms around the low point at 0.2 ms.
    fn default() -> Self {
        let (m1, l1) = (7.0, 0.62);
        Self {
            arm_length_m: l1,
            arm_mass_kg: m1,
            arm_inertia_kgm2: m1 * l1 * l1 / 3.0,
            club_length_m: 1.10,
            club_mass_kg: 0.31,
            club_com_m: 0.905,
            club_inertia_kgm2: 0.0325,
            plane_angle_rad: 55f64.to_radians(),
            shoulder_torque_nm: 96.0,
            top_arm_angle_rad: (-150f64).to_radians(),
            top_wrist_cock_rad: (-90f64).to_radians(),
            face_rotation_per_rad: 0.8,
            half_window_s: 0.012,
            sample_interval_s: 2.0e-4,
        }
    }
}

/// The example file's header comment (`lab/data/swing_driver.csv`).
pub const EXAMPLE_COMMENT: &str = "carry example swing: driver, planar double pendulum (lab/src/sweep/generate.rs, SwingModel::default()).
Club head CoM (m, G: x downrange, y up, z right; origin = ball centre at ball position 0), orientation C -> G as a unit quaternion.
Velocity and angular velocity are left out: carry sweep derives them by central differences.
Regenerate: carry sweep --generate lab/data/swing_driver.csv";

/// Integration step (s).
const STEP_S: f64 = 1.0e-5;
/// Longest downswing simulated (s).
const MAX_DOWNSWING_S: f64 = 2.0;

/// The pendulum's state: θ, φ, θ̇, φ̇, and whether the wrists still hold.
#[derive(Debug, Clone, Copy)]
struct State {
    theta: f64,
    phi: f64,
    theta_dot: f64,
    phi_dot: f64,
}

impl SwingModel {
    /// Angular accelerations; `locked` = the wrists hold β. Returns (θ̈, φ̈, τ_w).
    fn accelerations(&self, s: &State, locked: bool) -> (f64, f64, f64) {
        let (m1, l1, i1) = (self.arm_mass_kg, self.arm_length_m, self.arm_inertia_kgm2);
        let (m2, a2, j2) = (self.club_mass_kg, self.club_com_m, self.club_inertia_kgm2);
        let a1 = 0.5 * l1;
        let gp = carry_core::scene::STANDARD_GRAVITY_MPS2 * self.plane_angle_rad.sin();
        let c = m2 * l1 * a2;
        let (ia, ib) = (i1 + m2 * l1 * l1, j2 + m2 * a2 * a2);
        let beta = s.phi - s.theta;
        let (sb, cb) = beta.sin_cos();
        let r1 = self.shoulder_torque_nm + c * sb * s.phi_dot * s.phi_dot
            - gp * (m1 * a1 + m2 * l1) * s.theta.sin();
        let r2 = -c * sb * s.theta_dot * s.theta_dot - gp * m2 * a2 * s.phi.sin();
        if locked {
            // One rigid body: θ̈ = φ̈; add the rows (τ_w cancels), then τ_w from row 2.
            let acc = (r1 + r2) / (ia + 2.0 * c * cb + ib);
            let tau_w = c * cb * acc + ib * acc - r2;
            (acc, acc, tau_w)
        } else {
            let det = ia * ib - c * c * cb * cb;
            let theta_dd = (ib * r1 - c * cb * r2) / det;
            let phi_dd = (ia * r2 - c * cb * r1) / det;
            (theta_dd, phi_dd, 0.0)
        }
    }

    fn rk4(&self, s: &State, locked: bool, h: f64) -> State {
        let f = |s: &State| {
            let (a, b, _) = self.accelerations(s, locked);
            [s.theta_dot, s.phi_dot, a, b]
        };
        let add = |s: &State, k: [f64; 4], h: f64| State {
            theta: s.theta + h * k[0],
            phi: s.phi + h * k[1],
            theta_dot: s.theta_dot + h * k[2],
            phi_dot: s.phi_dot + h * k[3],
        };
        let k1 = f(s);
        let k2 = f(&add(s, k1, 0.5 * h));
        let k3 = f(&add(s, k2, 0.5 * h));
        let k4 = f(&add(s, k3, h));
        let mut k = [0.0; 4];
        for (i, ki) in k.iter_mut().enumerate() {
            *ki = (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]) / 6.0;
        }
        add(s, k, h)
    }

    fn plane(&self) -> (Vector3<f64>, Vector3<f64>) {
        let (se, ce) = self.plane_angle_rad.sin_cos();
        (Vector3::new(0.0, -se, ce), Vector3::new(0.0, ce, se))
    }

    fn dir(&self, angle: f64) -> Vector3<f64> {
        let (w, _) = self.plane();
        let (s, c) = angle.sin_cos();
        c * w + s * Vector3::x()
    }

    /// The downswing from the top to past the low point: (time, state) at every step.
    fn downswing(&self) -> Vec<(f64, State)> {
        let mut s = State {
            theta: self.top_arm_angle_rad,
            phi: self.top_arm_angle_rad + self.top_wrist_cock_rad,
            theta_dot: 0.0,
            phi_dot: 0.0,
        };
        let beta0 = self.top_wrist_cock_rad;
        let mut locked = true;
        let mut t = 0.0;
        let mut out = vec![(t, s)];
        while t < MAX_DOWNSWING_S && s.phi < 1.0 {
            if locked {
                let (_, _, tau_w) = self.accelerations(&s, true);
                // The stop can only push the club forward (τ_w ≥ 0): release when holding
                // would need a pull.
                if tau_w < 0.0 {
                    locked = false;
                }
            }
            s = self.rk4(&s, locked, STEP_S);
            if !locked && s.phi - s.theta < beta0 {
                // The club cannot lag beyond the stop.
                s.phi = s.theta + beta0;
                s.phi_dot = s.theta_dot;
                locked = true;
            }
            t += STEP_S;
            out.push((t, s));
        }
        out
    }

    /// Generates the swing samples for `club` (its static loft and CoM → face vector) and a
    /// ball of `ball_radius_m`.
    ///
    /// # Errors
    /// [`Error::Invalid`] ([`Input::Swing`]) if the pendulum never passes its low point
    /// (parameters that do not swing).
    pub fn generate(
        &self,
        face_rotation: &Matrix3<f64>,
        cg_to_face_m: &Vector3<f64>,
        ball_radius_m: f64,
    ) -> Result<Motion> {
        let path = self.downswing();
        let (l1, l2) = (self.arm_length_m, self.club_length_m);
        let head = |s: &State| l1 * self.dir(s.theta) + l2 * self.dir(s.phi);
        let head_velocity = |s: &State| {
            let d = |a: f64| {
                let (w, _) = self.plane();
                let (sn, c) = a.sin_cos();
                -sn * w + c * Vector3::x()
            };
            l1 * s.theta_dot * d(s.theta) + l2 * s.phi_dot * d(s.phi)
        };
        // The low point: the head's lowest height.
        let low = path
            .iter()
            .enumerate()
            .min_by(|a, b| head(&a.1.1).y.total_cmp(&head(&b.1.1).y))
            .map(|(i, _)| i)
            .filter(|&i| i > 0 && i + 1 < path.len())
            .ok_or_else(|| {
                Error::invalid(Input::Swing, "the swing model never passes its low point")
            })?;
        let (t_low, s_low) = path.get(low).copied().unwrap_or((0.0, path[0].1));
        let phi0 = s_low.phi;
        let (_, k) = self.plane();
        let shaft = Unit::new_normalize(-self.plane().0);
        let axis = Unit::new_normalize(k);
        let orientation = |s: &State| {
            let swing = Rotation3::from_axis_angle(&axis, s.phi - phi0);
            let face =
                Rotation3::from_axis_angle(&shaft, self.face_rotation_per_rad * (s.phi - phi0));
            UnitQuaternion::from_rotation_matrix(&(swing * face))
        };
        let spin = |s: &State| {
            let swing = Rotation3::from_axis_angle(&axis, s.phi - phi0);
            s.phi_dot * k + swing * (self.face_rotation_per_rad * s.phi_dot * shaft.into_inner())
        };
        // Origin: the ball's centre when the face centre strikes it at the low point.
        let q_low = orientation(&s_low).to_rotation_matrix().into_inner() * face_rotation;
        let origin = head(&s_low) + q_low * cg_to_face_m + ball_radius_m * (q_low * Vector3::x());
        let every = (self.sample_interval_s / STEP_S).round().max(1.0);
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let every = every as usize;
        let samples: Vec<Sample> = path
            .iter()
            .step_by(every)
            .filter(|(t, _)| (t - t_low).abs() <= self.half_window_s + 1e-12)
            .map(|(t, s)| Sample {
                time_s: t - t_low,
                position_m: head(s) - origin,
                orientation: orientation(s),
                velocity_mps: head_velocity(s),
                spin_radps: spin(s),
            })
            .collect();
        Motion::new(samples, false, false)
    }
}
