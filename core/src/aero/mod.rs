//! Aerodynamics: the models a scene can hold ([`AeroModel`]) and the flight's right-hand
//! side. Families: the seed's linear one ([`LinearAero`]; Quintavalla's coefficients are
//! the seed model) and the modern one ([`ModernAero`]; the calibrated default
//! `drives2026`, and `tour2023`). Every family has the structure of Quintavalla (2002), "A
//! generally applicable model for the aerodynamic behavior of golf balls", Science and Golf
//! IV, 341–348 (PHYSICS.md), shown here with the seed's coefficients:
//!
//! ```text
//! v_r = v − w,  V = |v_r|,  Sp = |ω|·R / V
//! C_D = 0.171 + 0.62 Sp     C_L = 0.083 + 0.885 Sp     C_M = 0.0125 Sp
//! q   = ½ ρ π R² V²
//! drag   = q C_D (−v_r/V)          lift = q C_L (ω̂ × v_r/V)       (0 when ω = 0)
//! torque = q C_M D (−ω̂)            dω/dt = torque / I_b            (the axis does not turn)
//! ```
//!
//! Written without dividing by `V` or `|ω|`, so every term is finite as `V → 0` (a ball
//! moving with the wind) and at `ω = 0`; with `A = ½ρπR²/m_b`, `s = |ω|`:
//!
//! ```text
//! a_drag = −A (0.171 V + 0.62 R s) v_r
//! a_lift =  A (0.083 V + 0.885 R s) (ω̂ × v_r)
//! ds/dt  = −(½ρπR² · 0.0125 · R · D / I_b) · V · s
//! ```
//!
//! Because the torque is anti-parallel to ω, the spin axis ω̂ is constant over a flight and
//! only the magnitude `s` is integrated: the state is position, velocity and `s`
//! (7 numbers), and the spin vector at any time is `s · ω̂`.

mod field;
mod linear;
pub(crate) mod model;
mod modern;
mod saturation;

pub use field::Effects;
pub(crate) use field::ForceField;
pub use linear::{
    CD_SP, CD0, CL_SP, CL0, CM_SP, LINEAR_NAMES, LinearAero, MAX_LINEAR_COEFFICIENT,
    drag_coefficient, lift_coefficient, moment_coefficient,
};
pub(crate) use model::PreparedAero;
pub use model::{AeroModel, BUILT_IN_MODELS};
pub use modern::{DRIVES_2026, MODERN_COEFFICIENTS, MODERN_NAMES, ModernAero, TOUR_2023};

use crate::real::{Real, lit};
use nalgebra::Vector3;

/// The integrated state: position (m) 0..3, velocity (m/s) 3..6, spin magnitude (rad/s) 6.
pub(crate) type State<T> = [T; 7];

/// Index of the height y in [`State`].
pub(crate) const Y: usize = 1;
/// Index of the vertical velocity in [`State`].
pub(crate) const VY: usize = 4;
/// Index of the spin magnitude in [`State`].
pub(crate) const S: usize = 6;

/// The right-hand side `dy/dt = f(y)` of a flight.
pub(crate) trait Rhs<T: Real> {
    /// Evaluates the derivative.
    fn eval(&self, y: &State<T>) -> State<T>;

    /// [`Rhs::eval`] inlined into its caller, for the adaptive integrator's stages where
    /// the precision is in hardware (hosts; `f32` on hard-float ARM): there a call costs
    /// ≈ 40 instructions per evaluation (the state through memory, the callee's saved
    /// registers), a third of the force model itself (docs/performance.md). Elsewhere
    /// (software floating point) the same as [`Rhs::eval`].
    #[inline(always)]
    fn eval_inlined(&self, y: &State<T>) -> State<T> {
        self.eval(y)
    }

    /// Whether a fixed step of `h` seconds from `y0` to `y1` grew no faster than the exact
    /// dynamics can. Drag only slows the ball in the air's frame and lift is normal to
    /// it, so the air speed `V = |v − w(y)|` grows by at most `d = g·h + |w(y₁) − w(y₀)|`
    /// over the step, and the spin only decays. Tested without a square root, on the
    /// squares, with `(V₀ + d)² ≤ 2V₀² + 4(g²h² + |Δw|²)` and a slack of 1/8 in speed:
    ///
    /// ```text
    /// V₁² ≤ (9/8)² · (2V₀² + 4(g²h² + |Δw|²)),     |s₁| ≤ (9/8)·s₀
    /// ```
    ///
    /// An explicit step past its stability limit (`h·k_d·V ≳ 2`) multiplies the air speed
    /// by `|1 − h·k_d·V|` or more, so it breaks this within a step or a few as the growth
    /// compounds (`k_d·V` grows with `V`); a stable step's truncation error is orders
    /// smaller than the slack. Without this test such a step can stay finite yet
    /// astronomically large (issue 20).
    fn step_is_bounded(&self, y0: &State<T>, y1: &State<T>, h: T) -> bool;
}

/// The flight dynamics of one shot: a prepared scene's force field and the (constant)
/// spin axis.
///
/// Disabled effects are skipped by branches on the scene's flags: they are constant for
/// the whole flight, so the branches are perfectly predicted (measured in docs/flight.md
/// against compile-time flags, [`Switches`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Dynamics<'a, T: Real> {
    pub(crate) field: &'a ForceField<T>,
    /// ω̂, or the zero vector when ω = 0 (no lift).
    pub(crate) axis: Vector3<T>,
}

/// One force evaluation and what it was made of: `a = g − k_d·v_r + k_l·(ω̂ × v_r)`,
/// `ds/dt = −λ·V·s`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ForceEvaluation<T: Real> {
    /// Acceleration (m/s², G, gravity included).
    pub(crate) acceleration: Vector3<T>,
    /// Rate of change of the spin magnitude (rad/s²).
    pub(crate) spin_rate: T,
    /// Air velocity `v_r` (m/s, G).
    relative_velocity: Vector3<T>,
    /// Air speed `V` (m/s) and its square.
    speed: T,
    speed_sq: T,
    /// Spin magnitude `s` (rad/s).
    spin: T,
    /// Drag and lift factors `k_d`, `k_l` (1/s; 0 when off).
    drag: T,
    lift: T,
    /// Spin decay factor `λ·V` (1/s; 0 without spin decay).
    decay: T,
}

impl<T: Real> ForceEvaluation<T> {
    /// `dy/dt` at the state `y` this evaluation was made at: its velocity, this
    /// acceleration and spin rate.
    #[inline(always)]
    #[must_use]
    pub(crate) fn derivative(&self, y: &State<T>) -> State<T> {
        let a = self.acceleration;
        [y[3], y[4], y[5], a.x, a.y, a.z, self.spin_rate]
    }
}

impl<T: Real> Dynamics<'_, T> {
    /// The forces with the effect switches given explicitly (constants fold away).
    #[inline(always)]
    fn forces_switched(
        &self,
        y: &State<T>,
        spin_sq: Option<T>,
        drag: bool,
        lift: bool,
        decay: bool,
        wind: bool,
    ) -> ForceEvaluation<T> {
        let p = self.field;
        let v = Vector3::new(y[3], y[4], y[5]);
        let s = y[S];
        let zero = T::zero();
        let mut f = ForceEvaluation {
            acceleration: Vector3::new(zero, -p.gravity, zero),
            spin_rate: zero,
            relative_velocity: v,
            speed: zero,
            speed_sq: zero,
            spin: s,
            drag: zero,
            lift: zero,
            decay: zero,
        };
        if drag || lift || decay {
            let vr = if wind { v - p.wind.at(y[Y]) } else { v };
            let speed_sq = vr.norm_squared();
            let speed = speed_sq.root();
            (f.relative_velocity, f.speed, f.speed_sq) = (vr, speed, speed_sq);
            if drag || lift {
                let (kd, kl) = p
                    .aero
                    .forces
                    .factors(speed, speed_sq, s, spin_sq, drag, lift);
                if drag {
                    f.acceleration -= vr * kd;
                    f.drag = kd;
                }
                if lift {
                    f.acceleration += self.axis.cross(&vr) * kl;
                    f.lift = kl;
                }
            }
            if decay {
                f.decay = p.aero.decay * speed;
                f.spin_rate = -f.decay * s;
            }
        }
        f
    }

    /// The derivative with the effect switches given explicitly (constants fold away).
    #[inline(always)]
    fn eval_switched(
        &self,
        y: &State<T>,
        drag: bool,
        lift: bool,
        decay: bool,
        wind: bool,
    ) -> State<T> {
        self.forces_switched(y, None, drag, lift, decay, wind)
            .derivative(y)
    }

    /// One force evaluation with what it was made of (the ground's hops). Inlined on hosts
    /// (the run-out is a chain of dependent steps; a call costs it time), out of line on
    /// bare-metal targets (size).
    #[cfg_attr(not(target_os = "none"), inline(always))]
    pub(crate) fn forces(&self, y: &State<T>) -> ForceEvaluation<T> {
        let e = &self.field.effects;
        self.forces_switched(y, None, e.drag, e.lift, e.spin_decay, self.field.has_wind())
    }

    /// [`Dynamics::forces`] given also the square of the spin `y[S]`, `spin_sq` (a hop's,
    /// from its spin vector): the spin laws take `(S/S_c)²` from it, not waiting on the
    /// square root that gives `y[S]` (the same force to rounding).
    #[cfg_attr(not(target_os = "none"), inline(always))]
    pub(crate) fn forces_given_spin_sq(&self, y: &State<T>, spin_sq: T) -> ForceEvaluation<T> {
        let e = &self.field.effects;
        let wind = self.field.has_wind();
        self.forces_switched(y, Some(spin_sq), e.drag, e.lift, e.spin_decay, wind)
    }

    /// The rates of change of the acceleration and of the spin rate over a short hop
    /// from `f`, with the speed changing by the drag alone: in still air or a uniform wind
    /// `dv_r/dt = a`, and
    ///
    /// ```text
    /// da/dt ≈ −k_d·a + k_l·(ω̂ × a) − k̇_d·v_r + k̇_l·(ω̂ × v_r),   k̇ = ∂k/∂V·V̇ + ∂k/∂s·ṡ
    /// V̇ = −k_d·V,   ṡ = −λV·s,   d²s/dt² = −λ(V̇s + Vṡ) = (V̇/V − λV)·ṡ
    /// ```
    ///
    /// Gravity's share of `V̇` is left out on purpose: the speed dips towards the apex of a
    /// hop and is back at its landing, so over the hop it averages out (what a secant
    /// through both ends sees); lift does no work. In a wind profile `v_r` also changes
    /// with height and this does not hold. `spin_sq`: the square of the spin `f` was
    /// evaluated at, when it was given it ([`Dynamics::forces_given_spin_sq`]).
    #[cfg_attr(not(target_os = "none"), inline(always))]
    pub(crate) fn rates_held(&self, f: &ForceEvaluation<T>, spin_sq: Option<T>) -> (Vector3<T>, T) {
        self.rates_along(f, -f.drag, spin_sq)
    }

    /// The same rates at the instant of `f` (a tangent, not a hop's secant): the speed
    /// changing at `V̇ = v_r·a/V` (gravity included; 0 at `V = 0`).
    pub(crate) fn rates_now(&self, f: &ForceEvaluation<T>) -> (Vector3<T>, T) {
        // (1/V² beside the dot product: only a multiply after it.)
        let relative = f.relative_velocity.dot(&f.acceleration) * (T::one() / f.speed_sq);
        let relative = if relative.is_finite() {
            relative
        } else {
            T::zero()
        };
        self.rates_along(f, relative, None)
    }

    /// The rates with the speed changing at the relative rate `V̇/V` (1/s).
    #[inline(always)]
    fn rates_along(
        &self,
        f: &ForceEvaluation<T>,
        relative_speed_rate: T,
        spin_sq: Option<T>,
    ) -> (Vector3<T>, T) {
        let e = &self.field.effects;
        let a = f.acceleration;
        let (dkd, dkl) = if e.drag || e.lift {
            self.field.aero.forces.factor_rates(
                f.speed,
                f.speed_sq,
                f.spin,
                spin_sq,
                relative_speed_rate,
                f.spin_rate,
                e.drag,
                e.lift,
            )
        } else {
            (T::zero(), T::zero())
        };
        let vr = f.relative_velocity;
        (
            self.axis.cross(&(a * f.lift + vr * dkl)) - (a * f.drag + vr * dkd),
            (relative_speed_rate - f.decay) * f.spin_rate,
        )
    }
}

impl<T: Real> Rhs<T> for Dynamics<'_, T> {
    // Inlined on hosts (speed); one out-of-line copy on bare-metal targets, where the
    // integrator's seven call sites would otherwise each carry the whole force model: the
    // flash saved is worth far more there than the call (docs/firmware.md measures both).
    #[cfg_attr(not(target_os = "none"), inline(always))]
    #[cfg_attr(target_os = "none", inline(never))]
    fn eval(&self, y: &State<T>) -> State<T> {
        let e = &self.field.effects;
        let wind = self.field.has_wind();
        self.eval_switched(y, e.drag, e.lift, e.spin_decay, wind)
    }

    #[inline(always)]
    fn eval_inlined(&self, y: &State<T>) -> State<T> {
        let e = &self.field.effects;
        let wind = self.field.has_wind();
        self.eval_switched(y, e.drag, e.lift, e.spin_decay, wind)
    }

    fn step_is_bounded(&self, y0: &State<T>, y1: &State<T>, h: T) -> bool {
        let wind = &self.field.wind;
        let (w0, w1) = (wind.at(y0[Y]), wind.at(y1[Y]));
        let air_sq =
            |y: &State<T>, w: &Vector3<T>| (Vector3::new(y[3], y[4], y[5]) - w).norm_squared();
        let gh = self.field.gravity * h;
        let growth_sq =
            lit::<T>(2.0) * air_sq(y0, &w0) + lit::<T>(4.0) * (gh * gh + (w1 - w0).norm_squared());
        air_sq(y1, &w1) <= lit::<T>(1.265_625) * growth_sq && y1[S].abs() <= y0[S] * lit(1.125)
    }
}

/// The same dynamics with the effects fixed at compile time (monomorphised): used only to
/// measure what runtime branches cost (benches/flight.rs, docs/flight.md).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Switches<
    'a,
    T: Real,
    const DRAG: bool,
    const LIFT: bool,
    const DECAY: bool,
    const WIND: u8,
>(pub(crate) Dynamics<'a, T>);

impl<T: Real, const DRAG: bool, const LIFT: bool, const DECAY: bool, const WIND: u8> Rhs<T>
    for Switches<'_, T, DRAG, LIFT, DECAY, WIND>
{
    #[inline(always)]
    fn eval(&self, y: &State<T>) -> State<T> {
        self.0.eval_switched(y, DRAG, LIFT, DECAY, WIND != 0)
    }

    fn step_is_bounded(&self, y0: &State<T>, y1: &State<T>, h: T) -> bool {
        self.0.step_is_bounded(y0, y1, h)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Ball;
    use crate::scene::Scene;
    use crate::wind::Wind;

    #[test]
    fn finite_when_moving_with_the_wind_and_without_spin() {
        let w = Vector3::new(5.0_f64, 0.0, -2.0);
        let scene = Scene {
            wind: Wind::Uniform(w),
            ..Scene::default()
        };
        let Ok(p) = scene.prepare(&Ball::standard()) else {
            panic!()
        };
        for axis in [Vector3::zeros(), Vector3::z()] {
            let d = Dynamics {
                field: &p.field,
                axis,
            };
            let f = d.eval(&[
                0.0,
                3.0,
                0.0,
                w.x,
                w.y,
                w.z,
                if axis.z > 0.0 { 300.0 } else { 0.0 },
            ]);
            assert!(f.iter().all(|x| x.is_finite()));
            assert!((f[4] + 9.80665).abs() < 1e-15 && f[3] == 0.0 && f[5] == 0.0 && f[6] == 0.0);
        }
    }

    #[test]
    fn matches_the_coefficient_form() {
        // Direct evaluation of q·C·direction against the divided-out hot-loop form, for
        // every family, including the modern one's drag crisis (low speed).
        let ball = Ball::<f64>::standard();
        for model in [AeroModel::quintavalla(), AeroModel::tour_2023()] {
            let scene = Scene {
                aero: model,
                ..Scene::default()
            };
            let Ok(p) = scene.prepare(&ball) else {
                panic!()
            };
            let mu = crate::air::STANDARD_VISCOSITY_PAS;
            let axis = Vector3::new(0.1, -0.2, 0.97).normalize();
            for (v, s) in [
                (Vector3::new(60.0, 9.0, -3.0), 250.0),
                (Vector3::new(15.0, -9.0, 3.0), 400.0),
                (Vector3::new(30.0, 1.0, 0.0), 0.0),
            ] {
                let d = Dynamics {
                    field: &p.field,
                    axis,
                };
                let f = d.eval(&[0.0, 0.0, 0.0, v.x, v.y, v.z, s]);
                let big_v = v.norm();
                let sp = s * ball.radius_m() / big_v;
                let re = 1.225 * big_v * ball.diameter_m() / mu;
                let (cd, cl, cm) = model.coefficients(sp, re);
                let q =
                    0.5 * 1.225 * core::f64::consts::PI * ball.radius_m().powi(2) * big_v * big_v;
                let force = -v / big_v * q * cd + axis.cross(&(v / big_v)) * q * cl;
                let a = force / ball.mass_kg() - Vector3::new(0.0, 9.80665, 0.0);
                assert!((Vector3::new(f[3], f[4], f[5]) - a).norm() < 1e-12);
                let torque = q * cm * ball.diameter_m();
                assert!((f[6] + torque / ball.inertia_kgm2()).abs() < 1e-10);
            }
        }
    }
}
