//! After the landing: bounces and roll to rest, on the ground a [`Scene`](crate::Scene)
//! names (`Scene::ground`). See docs/ground.md for the model, its sources and its checks.
//!
//! The run starts at the flight's first landing (carry keeps its meaning) on a ground
//! plane through that point, level or sloped ([`Ground::normal`]):
//!
//! 1. **Bounce** ([`bounce`]): Penner's (2002) turf impact — a crater tilt growing with
//!    impact speed and angle, a normal restitution falling with normal speed, Coulomb
//!    friction that may reverse the spin (a wedge checks or spins back).
//! 2. **Hop**: between bounces the ball flies with the scene's own aerodynamics and wind
//!    (the flight's integrator and force model) until it comes back down through the plane.
//! 3. **Roll** ([`roll`]): once a rebound would rise less than [`STOP_HEIGHT_M`] (Penner's
//!    criterion) the ball rolls against the surface's rolling resistance, in closed form on
//!    level ground.
//!
//! Nothing of this runs, or costs anything, when the scene has no ground.

pub mod bounce;
pub mod roll;
pub mod surface;

use crate::aero::ForceEvaluation;
use crate::error::{Error, Field, Reason, Result};
use crate::flight::{Recorder, Stats};
use crate::real::{Real, larger, lit};
use crate::validate::finite_vector;
use nalgebra::Vector3;
pub use surface::{Surface, Turf};

/// A rebound lower than this (m) ends the bouncing: the ball rolls (Penner 2002: 5 mm).
pub const STOP_HEIGHT_M: f64 = 0.005;
/// At most this many hops; the ball then rolls (a bound on the run time, never reached by
/// a golf shot: they stop within about ten).
pub const MAX_BOUNCES: u32 = 64;
/// Hops lower than this (m) fly in closed form (one force evaluation and its rate over the
/// hop, three in a wind profile; see `low_hop`); flying them with the integrator costs 7
/// force evaluations and a landing search. Higher hops are integrated. docs/ground.md
/// measures what this changes (centimetres over a run-out).
pub const LOW_HOP_HEIGHT_M: f64 = 1.0;
/// Steepest accepted ground (rad): 45°.
pub const MAX_SLOPE_RAD: f64 = core::f64::consts::FRAC_PI_4;

/// The ground after the landing: a surface and the plane's orientation.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Ground<T: Real> {
    /// What the ball lands on.
    pub surface: Surface<T>,
    /// Normal of the ground plane (G, pointing up; need not be unit length). The plane
    /// passes through the first landing point. At most [`MAX_SLOPE_RAD`] from vertical.
    pub normal: Vector3<T>,
}

impl<T: Real> Ground<T> {
    /// Level ground of `surface`.
    #[must_use]
    pub fn level(surface: Surface<T>) -> Self {
        Self {
            surface,
            normal: Vector3::y(),
        }
    }

    /// Ground rising at `slope_rad` towards `direction_rad` (from downrange towards the
    /// right, as a wind direction: 0 = uphill towards the target, 180° = downhill):
    /// `n = (−sin α cos ψ, cos α, −sin α sin ψ)`.
    #[must_use]
    pub fn sloped(surface: Surface<T>, slope_rad: T, direction_rad: T) -> Self {
        let (sa, ca) = slope_rad.sin_cos();
        let (sp, cp) = direction_rad.sin_cos();
        Self {
            surface,
            normal: Vector3::new(-sa * cp, ca, -sa * sp),
        }
    }

    /// Validates the ground for a ball of radius `radius_m`.
    ///
    /// # Errors
    /// The surface's errors ([`Surface::turf`]); [`Field::GroundNormal`] not finite, zero,
    /// or steeper than [`MAX_SLOPE_RAD`].
    pub fn prepare(&self, radius_m: T) -> Result<PreparedGround<T>> {
        let turf = self.surface.turf()?;
        let n = finite_vector(&self.normal, Field::GroundNormal)?;
        let len = n.norm();
        if !(len > T::zero() && len.is_finite()) {
            return Err(Error::invalid(Field::GroundNormal, Reason::NotPositive));
        }
        let n = n / len;
        if !(n.y >= lit::<T>(MAX_SLOPE_RAD).cos()) {
            return Err(Error::invalid(Field::GroundNormal, Reason::OutOfRange));
        }
        Ok(PreparedGround {
            turf,
            normal: n,
            radius: radius_m,
        })
    }
}

/// A validated ground.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct PreparedGround<T: Real> {
    pub(crate) turf: Turf<T>,
    pub(crate) normal: Vector3<T>,
    pub(crate) radius: T,
}

impl<T: Real> PreparedGround<T> {
    /// The validated turf.
    #[must_use]
    pub fn turf(&self) -> Turf<T> {
        self.turf
    }

    /// The unit normal of the ground plane.
    #[must_use]
    pub fn normal(&self) -> Vector3<T> {
        self.normal
    }

    /// One bounce on this ground ([`bounce`]): velocity and spin just after the impact.
    ///
    /// # Errors
    /// [`Field::BallVelocity`] or [`Field::BallSpin`] not finite (or so large that the
    /// rebound overflows).
    pub fn bounce(
        &self,
        velocity_mps: &Vector3<T>,
        spin_radps: &Vector3<T>,
    ) -> Result<bounce::Rebound<T>> {
        let v = finite_vector(velocity_mps, Field::BallVelocity)?;
        let w = finite_vector(spin_radps, Field::BallSpin)?;
        let r = bounce::rebound(&v, &w, &self.normal, &self.turf, self.radius);
        finite_vector(&r.velocity_mps, Field::BallVelocity)?;
        finite_vector(&r.spin_radps, Field::BallSpin)?;
        Ok(r)
    }
}

/// How a run after the landing ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum RunEnd {
    /// The ball came to rest.
    Rest,
    /// The ball was still rolling at the roll time cap ([`roll::ROLL_TIME_CAP_S`]): the
    /// slope is steeper than the surface's rolling resistance (or there is none). The
    /// "rest" figures are where it was then.
    StillRolling,
}

/// Bounce and roll after the first landing.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Rollout<T: Real> {
    /// Total: horizontal distance from the tee to the rest point (m).
    pub total_m: T,
    /// Roll: distance along the ground from the first landing to rest (m), negative when
    /// the ball ends behind the landing (it spun back).
    pub roll_m: T,
    /// Number of hops (bounces the ball left the ground from).
    pub bounces: u32,
    /// Rest position (m, G).
    pub rest_position_m: Vector3<T>,
    /// Time from launch to rest (s).
    pub time_to_rest_s: T,
    /// Rest, or still rolling at the time cap.
    pub end: RunEnd,
    /// Work done by the hops (force evaluations and steps).
    pub stats: Stats,
}

/// The state at a ground contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Contact<T: Real> {
    pub(crate) time: T,
    pub(crate) position: Vector3<T>,
    pub(crate) velocity: Vector3<T>,
    pub(crate) spin: Vector3<T>,
}

/// Flies a hop from a contact: returns the next contact (through the flight's integrator
/// and force model; see `flight::hop`).
pub(crate) trait Hopper<T: Real> {
    fn hop(
        &self,
        from: &Contact<T>,
        plane: crate::flight::Plane<T>,
        recorder: Option<&mut Recorder<'_, T>>,
        stats: &mut Stats,
    ) -> Result<Contact<T>>;

    /// The acceleration (m/s², G, gravity included), the rate of change of the spin
    /// magnitude (rad/s²) and the coefficients behind them, of a ball at `position` with
    /// `velocity`, spinning at `spin` (rad/s) about the unit `axis` (zero without spin):
    /// one force evaluation.
    fn forces(
        &self,
        position: &Vector3<T>,
        velocity: &Vector3<T>,
        spin: T,
        axis: &Vector3<T>,
        stats: &mut Stats,
    ) -> ForceEvaluation<T>;

    /// The rates of change of the acceleration and of the spin rate over a short hop from
    /// the evaluation `forces` of a ball spinning about `axis` (`aero::Dynamics::rates_held`).
    fn rates_held(&self, forces: &ForceEvaluation<T>, axis: &Vector3<T>) -> (Vector3<T>, T);

    /// Whether the forces see a wind that changes with height (a profile).
    fn wind_varies(&self) -> bool;
}

/// How a low hop's closed form takes the scene's forces (see [`low_hop`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum HopForces {
    /// Still air or a uniform wind: one evaluation at the bounce and its rate over the hop.
    Held,
    /// A wind profile: three evaluations, at the bounce, at the predicted landing and in
    /// the middle of the hop.
    ThreePoints,
}

impl HopForces {
    /// The form for a scene whose wind does (a profile) or does not vary with height.
    pub(crate) fn for_wind(varies_with_height: bool) -> Self {
        if varies_with_height {
            Self::ThreePoints
        } else {
            Self::Held
        }
    }
}

/// A low hop in closed form: the acceleration and the spin's rate of change linear (or
/// quadratic) in time,
///
/// ```text
/// p(τ) = p₀ + v₀τ + a₀τ²/2 + jτ³/6,   v(τ) = v₀ + a₀τ + jτ²/2
/// ```
///
/// landing where `n̂·(p − p₀) = 0`, a quadratic in `τ` (solved exactly). The rate `j`
/// ([`HopForces`]):
/// - `Held`: from the one evaluation at the bounce (`aero::Dynamics::rates_held`): the
///   force's change with the velocity, and its factors' change as the drag slows the ball
///   and the spin decays. Gravity's share of the speed's change is left out: the speed
///   dips towards the apex and is back at the landing. Against the same hops integrated
///   it is as close as a second evaluation at the landing (unit test
///   `flight::tests::closed_form_hop_matches_the_integrated_hop`; docs/ground.md);
/// - `ThreePoints`: in a wind profile the air velocity changes with height (zero at the
///   ground, where both ends are), so the forces are evaluated at the bounce, at the
///   landing predicted with `a₀` (`j = (a₁ − a₀)/τ₁`) and in the middle of that hop, and
///   the acceleration is quadratic in time through the three.
///
/// `None` when the force does not pull the ball back to the plane.
pub(crate) fn low_hop<T: Real, H: Hopper<T>>(
    from: &Contact<T>,
    n: &Vector3<T>,
    hopper: &H,
    form: HopForces,
    stats: &mut Stats,
    recorder: Option<&mut Recorder<'_, T>>,
) -> Option<Contact<T>> {
    // The spin axis is fixed in flight: its magnitude and direction once (each `norm` is a
    // software square root on a Cortex-M4F).
    let spin0 = from.spin.norm();
    let axis = if spin0 > T::zero() {
        from.spin / spin0
    } else {
        Vector3::zeros()
    };
    let f0 = hopper.forces(&from.position, &from.velocity, spin0, &axis, stats);
    let (a0, s0) = (f0.acceleration, f0.spin_rate);
    let vn = from.velocity.dot(n);
    let two = lit::<T>(2.0);
    // First guess: the parabola of the initial force.
    let an = a0.dot(n);
    if !(an < T::zero()) {
        return None;
    }
    let half = lit::<T>(0.5);
    let sixth = lit::<T>(1.0 / 6.0);
    // The spin magnitude, its rate linear in time (never below zero).
    let spin_at = |tau: T, rate0: T, jerk: T| {
        larger(spin0 + rate0 * tau + jerk * tau * tau * half, T::zero())
    };
    let state = |tau: T, j: &Vector3<T>| {
        (
            from.position
                + from.velocity * tau
                + a0 * (half * tau * tau)
                + j * (sixth * tau * tau * tau),
            from.velocity + a0 * tau + j * (half * tau * tau),
        )
    };
    // With `a(τ) = a₀ + jτ + qτ²` (q only in a wind profile, see below).
    let state_q = |tau: T, j: &Vector3<T>, q: Option<&Vector3<T>>| {
        let (p, v) = state(tau, j);
        match q {
            Some(q) => {
                let tau2 = tau * tau;
                (
                    p + q * (lit::<T>(1.0 / 12.0) * tau2 * tau2),
                    v + q * (lit::<T>(1.0 / 3.0) * tau2 * tau),
                )
            }
            None => (p, v),
        }
    };
    let (j, spin_jerk, q, tau) = if form == HopForces::Held {
        let (j, spin_jerk) = hopper.rates_held(&f0, &axis);
        (j, spin_jerk, None, hop_landing(vn, an, j.dot(n))?)
    } else {
        // τ₁ and 1/τ₁ side by side (two divisions, neither waiting on the other).
        let t1 = -two * vn / an;
        let per_t1 = -an / (two * vn);
        let zero = Vector3::zeros();
        let (p1, v1) = state(t1, &zero);
        let f1 = hopper.forces(&p1, &v1, spin_at(t1, s0, T::zero()), &axis, stats);
        let a1 = f1.acceleration;
        let (j, spin_jerk) = ((a1 - a0) * per_t1, (f1.spin_rate - s0) * per_t1);
        // jn = j·n from the normal accelerations (one dot product after a₁, not two steps).
        let tau = hop_landing(vn, an, (a1.dot(n) - an) * per_t1)?;
        // Through the three, `j = (4a_m − 3a₀ − a₁)/τ₁`, `q = 2(a₀ + a₁ − 2a_m)/τ₁²`; the
        // landing by Newton's method from the two-end root on
        // `vn + a_nτ/2 + j_nτ²/6 + q_nτ³/12 = 0`.
        let tm = t1 * half;
        let (pm, vm) = state(tm, &j);
        let am = hopper
            .forces(&pm, &vm, spin_at(tm, s0, spin_jerk), &axis, stats)
            .acceleration;
        let j = (am * lit::<T>(4.0) - a0 * lit::<T>(3.0) - a1) * per_t1;
        let q = (a0 + a1 - am * two) * (two * per_t1 * per_t1);
        let (jn, qn) = (j.dot(n), q.dot(n));
        let mut tau = tau;
        for _ in 0..3 {
            let g = vn + tau * (an * half + tau * (jn * sixth + tau * qn * lit(1.0 / 12.0)));
            let dg = an * half + tau * (jn * lit(1.0 / 3.0) + tau * qn * lit(0.25));
            if dg < T::zero() {
                tau -= g / dg;
            }
        }
        if !(tau > T::zero() && tau.is_finite()) {
            return None;
        }
        (j, spin_jerk, Some(q), tau)
    };
    if let Some(r) = recorder {
        r.record_hop(from.time, tau, &axis, |t| {
            let (p, v) = state_q(t, &j, q.as_ref());
            (p, v, spin_at(t, s0, spin_jerk))
        });
    }
    // (The plain closure when there is no q: the `Option` in the landing's state cost ~25
    // instructions a shot on the M4F.)
    let (position, velocity) = match q {
        Some(q) => state_q(tau, &j, Some(&q)),
        None => state(tau, &j),
    };
    Some(Contact {
        time: from.time + tau,
        position,
        velocity,
        spin: axis * spin_at(tau, s0, spin_jerk),
    })
}

/// The landing time `τ > 0` of a hop leaving the plane at normal speed `vn > 0` with normal
/// acceleration `an < 0` and normal jerk `jn`: the root of `vn + an τ/2 + jn τ²/6 = 0` that
/// continues the parabola's `τ₀ = −2vn/an`; `None` when there is none.
///
/// With `τ = τ₀·y` and `x = −jn·τ₀/(3an)`, `y = 1 + x y²`, so `y = Σ Cₖ xᵏ` (Catalan
/// numbers 1, 1, 2, 5, 14, 42, …). For `|x| ≤ 1/32` (a low hop's `x` is about 0.01) the
/// series to `x⁵` (truncation `132x⁶ < 1.3·10⁻⁷` relative): `τ₀` and the scale of `x` need
/// only `an` and run beside the jerk's computation, and after `jn` it is a few
/// multiply–adds where the closed form `2vn/(√(an²/4 − 2jn·vn/3) − an/2)` (used otherwise)
/// waits on a square root and a division.
#[inline]
pub(crate) fn hop_landing<T: Real>(vn: T, an: T, jn: T) -> Option<T> {
    let two = lit::<T>(2.0);
    let per_an = T::one() / an;
    let tau0 = -two * vn * per_an;
    let x = jn * (tau0 * per_an * lit::<T>(-1.0 / 3.0));
    if x.abs() <= lit::<T>(1.0 / 32.0) && tau0 > T::zero() && tau0.is_finite() {
        let x2 = x * x;
        let low = T::one() + x + x2 * (two + lit::<T>(5.0) * x);
        let high = lit::<T>(14.0) + lit::<T>(42.0) * x;
        return Some(tau0 * (low + (x2 * x2) * high));
    }
    // The stable form 2c/(−b + √(b² − 4ac)), a = jn/6, b = an/2 < 0, c = vn > 0.
    let b = an * lit::<T>(0.5);
    let disc = b * b - jn * (lit::<T>(2.0 / 3.0) * vn);
    if !(disc >= T::zero()) {
        return None;
    }
    let tau = two * vn / (disc.sqrt() - b);
    (tau > T::zero() && tau.is_finite()).then_some(tau)
}

/// Bounces and rolls from the first landing `first` to rest.
pub(crate) fn run_out<T: Real, H: Hopper<T>>(
    ground: &PreparedGround<T>,
    gravity: T,
    launch_position: &Vector3<T>,
    first: &Contact<T>,
    hopper: &H,
    recorder: Option<&mut Recorder<'_, T>>,
) -> Result<Rollout<T>> {
    let mut recorder = recorder;
    let n = ground.normal;
    let plane = crate::flight::Plane {
        normal: n,
        offset: n.dot(&first.position),
    };
    let g_vec = Vector3::new(T::zero(), -gravity, T::zero());
    let g_n = gravity * n.y;
    // A rebound rises v²/(2 g_n) above the plane: it hops if v² ≥ 2 g_n h_stop.
    let hop_speed_sq = lit::<T>(2.0 * STOP_HEIGHT_M) * g_n;
    let low_hop_speed_sq = lit::<T>(2.0 * LOW_HOP_HEIGHT_M) * g_n;
    let mut stats = Stats::default();
    let form = HopForces::for_wind(hopper.wind_varies());
    let mut at = *first;
    let mut bounces = 0_u32;
    let (roll_velocity, roll_spin) = loop {
        let r = bounce::rebound(&at.velocity, &at.spin, &n, &ground.turf, ground.radius);
        let vn = r.normal_speed_mps;
        if !(vn > T::zero() && vn * vn >= hop_speed_sq) || bounces >= MAX_BOUNCES {
            break (r.velocity_mps - n * vn, r.spin_radps);
        }
        bounces += 1;
        let from = Contact {
            velocity: r.velocity_mps,
            spin: r.spin_radps,
            ..at
        };
        let low = if vn * vn < low_hop_speed_sq {
            low_hop(&from, &n, hopper, form, &mut stats, recorder.as_deref_mut())
        } else {
            None
        };
        at = match low {
            Some(c) => c,
            None => hopper.hop(&from, plane, recorder.as_deref_mut(), &mut stats)?,
        };
        // Back onto the plane (the landing is on it to the root finder's accuracy).
        at.position -= n * (n.dot(&at.position) - plane.offset);
    };
    if !(roll_velocity.iter().all(|x| x.is_finite()) && roll_spin.iter().all(|x| x.is_finite())) {
        return Err(Error::Unstable);
    }
    let end = roll::Roll {
        normal: n,
        gravity: g_vec,
        resistance: ground.turf.rolling_resistance,
        grass_drag: lit(surface::GRASS_DRAG_S2PM2),
        friction: ground.turf.friction,
        radius: ground.radius,
        start_time: at.time,
        recorder,
    }
    .run(at.position, roll_velocity, &roll_spin);
    let rest = end.position;
    if !(rest.iter().all(|x| x.is_finite()) && end.duration.is_finite()) {
        return Err(Error::Unstable);
    }
    let along = rest - first.position;
    let forward = Vector3::new(first.velocity.x, T::zero(), first.velocity.z);
    let roll = along.norm();
    // (No `hypot`: the distances are metres, far from overflow; libm's is out of line.)
    let (dx, dz) = (rest.x - launch_position.x, rest.z - launch_position.z);
    let total = (dx * dx + dz * dz).sqrt();
    Ok(Rollout {
        total_m: total,
        roll_m: if along.dot(&forward) < T::zero() {
            -roll
        } else {
            roll
        },
        bounces,
        rest_position_m: rest,
        time_to_rest_s: at.time + end.duration,
        end: if end.still_rolling {
            RunEnd::StillRolling
        } else {
            RunEnd::Rest
        },
        stats,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    fn green() -> PreparedGround<f64> {
        match Ground::level(Surface::green()).prepare(0.021336) {
            Ok(g) => g,
            Err(e) => panic!("{e}"),
        }
    }

    /// The series landing against the quadratic's closed-form root, across and beyond the
    /// series' range (a low hop's x ≈ 0.01), and no root where there is none.
    #[test]
    fn hop_landing_is_the_quadratics_root() {
        for vn in [0.05, 0.7, 2.6, 4.4] {
            for an in [-14.0, -9.8, -6.0] {
                for jn in [-40.0, -3.0, -0.5, 0.0, 0.2, 1.0, 6.0] {
                    let exact = {
                        let b = 0.5 * an;
                        let disc: f64 = b * b - jn * (2.0 / 3.0) * vn;
                        (disc >= 0.0).then(|| 2.0 * vn / (disc.sqrt() - b))
                    };
                    let tau = hop_landing(vn, an, jn);
                    match (tau, exact) {
                        (Some(t), Some(e)) => {
                            assert!((t - e).abs() <= 2e-7 * e, "{vn} {an} {jn}: {t} {e}");
                            let g = vn + an * t / 2.0 + jn * t * t / 6.0;
                            assert!(g.abs() <= 1e-6 * vn, "{vn} {an} {jn}: residual {g}");
                        }
                        (None, None) => {}
                        other => panic!("{vn} {an} {jn}: {other:?}"),
                    }
                }
            }
        }
    }

    #[test]
    fn restitution_stays_in_range() {
        for v in [0.0, 5.0, 13.0, 20.0, 20.001, 50.0, 1e6] {
            let e = bounce::restitution(v, 0.51_f64);
            assert!((0.119..=0.51).contains(&e), "{v}: {e}");
        }
    }

    #[test]
    fn vertical_drop_without_spin_goes_straight_up() {
        let Ok(r) = green().bounce(&Vector3::new(0.0, -5.0, 0.0), &Vector3::zeros()) else {
            panic!()
        };
        assert_eq!((r.velocity_mps.x, r.velocity_mps.z), (0.0, 0.0));
        assert!(r.velocity_mps.y > 0.0 && r.velocity_mps.y < 5.0);
    }

    #[test]
    fn absurd_surfaces_are_named() {
        let custom = |restitution, friction| {
            Ground::level(Surface::Custom(Turf {
                restitution,
                friction,
                rolling_resistance: 0.1,
                crater_scale: 1.0,
            }))
            .prepare(0.021_f64)
        };
        let err = |f, r| Err(Error::invalid(f, r));
        assert_eq!(
            custom(1.2, 0.4),
            err(Field::GroundRestitution, Reason::OutOfRange)
        );
        assert_eq!(
            custom(0.5, -0.1),
            err(Field::GroundFriction, Reason::Negative)
        );
        assert_eq!(
            custom(f64::NAN, 0.4),
            err(Field::GroundRestitution, Reason::NotFinite)
        );
        let steep = Ground::sloped(Surface::<f64>::Rough, 1.0, 0.0).prepare(0.021);
        assert_eq!(steep, err(Field::GroundNormal, Reason::OutOfRange));
        let slow = Ground::level(Surface::Green { stimp_m: 0.0 }).prepare(0.021_f64);
        assert_eq!(slow, err(Field::Stimp, Reason::NotPositive));
    }
}
