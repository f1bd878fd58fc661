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
/// Hops lower than this (m) fly in closed form with the scene's forces at their two ends
/// (two force evaluations, the acceleration linear in time; see `low_hop`); flying them
/// with the integrator costs 7 force evaluations or more and an event search. Higher hops
/// are integrated. docs/ground.md measures what this changes (millimetres).
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
#[derive(Debug, Clone, Copy)]
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

    /// The acceleration (m/s², G, gravity included) and the rate of change of the spin
    /// magnitude (rad/s²) of a ball at `position` with `velocity`, spinning at `spin`
    /// (rad/s) about the unit `axis` (zero without spin): one force evaluation.
    fn forces(
        &self,
        position: &Vector3<T>,
        velocity: &Vector3<T>,
        spin: T,
        axis: &Vector3<T>,
        stats: &mut Stats,
    ) -> (Vector3<T>, T);

    /// Whether the forces see a wind that changes with height (a profile).
    fn wind_varies(&self) -> bool;
}

/// A low hop in closed form with the scene's forces at its ends: the acceleration and the
/// spin's rate of change are taken linear in time between their values at the bounce and
/// at the landing predicted with the initial force (two force evaluations):
///
/// ```text
/// p(τ) = p₀ + v₀τ + a₀τ²/2 + jτ³/6,   v(τ) = v₀ + a₀τ + jτ²/2,   j = (a₁ − a₀)/τ₁
/// ```
///
/// landing where `n̂·(p − p₀) = 0`, a quadratic in `τ` (solved exactly). In a wind profile
/// (zero wind at the ground, where both ends are) a third evaluation in the middle of the
/// hop makes the acceleration quadratic in time. `None` when the force does not pull the
/// ball back to the plane.
pub(crate) fn low_hop<T: Real, H: Hopper<T>>(
    from: &Contact<T>,
    n: &Vector3<T>,
    hopper: &H,
    wind_varies: bool,
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
    let (a0, s0) = hopper.forces(&from.position, &from.velocity, spin0, &axis, stats);
    let vn = from.velocity.dot(n);
    let two = lit::<T>(2.0);
    // First guess: the parabola of the initial force.
    let an = a0.dot(n);
    if !(an < T::zero()) {
        return None;
    }
    // τ₁ and 1/τ₁ side by side (two divisions, neither waiting on the other).
    let t1 = -two * vn / an;
    let per_t1 = -an / (two * vn);
    let half = lit::<T>(0.5);
    let sixth = lit::<T>(1.0 / 6.0);
    // The spin magnitude, its rate linear in time between the ends (never below zero).
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
    let zero = Vector3::zeros();
    let (p1, v1) = state(t1, &zero);
    let (a1, s1) = hopper.forces(&p1, &v1, spin_at(t1, s0, T::zero()), &axis, stats);
    let (j, spin_jerk) = ((a1 - a0) * per_t1, (s1 - s0) * per_t1);
    // n̂·(p − p₀)/τ = vn + an τ/2 + jn τ²/6 = 0: the quadratic's root that continues the
    // parabola's (stable form 2c/(−b + √(b² − 4ac)), a = jn/6, b = an/2 < 0, c = vn > 0).
    // jn = j·n from the normal accelerations (one dot product after a₁, not two steps).
    let jn = (a1.dot(n) - an) * per_t1;
    let b = an * half;
    let disc = b * b - jn * (lit::<T>(2.0 / 3.0) * vn);
    if !(disc >= T::zero()) {
        return None;
    }
    let tau = two * vn / (disc.sqrt() - b);
    if !(tau > T::zero() && tau.is_finite()) {
        return None;
    }
    // In a wind profile both ends are on the ground, where its wind is zero: a third
    // evaluation in the middle of the hop, and the acceleration quadratic in time through
    // the three, `j = (4a_m − 3a₀ − a₁)/τ₁`, `q = 2(a₀ + a₁ − 2a_m)/τ₁²`; the landing by
    // Newton's method from the two-end root on `vn + a_nτ/2 + j_nτ²/6 + q_nτ³/12 = 0`.
    let (j, q, tau) = if wind_varies {
        let tm = t1 * half;
        let (pm, vm) = state(tm, &j);
        let (am, _) = hopper.forces(&pm, &vm, spin_at(tm, s0, spin_jerk), &axis, stats);
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
        (j, Some(q), tau)
    } else {
        (j, None, tau)
    };
    if let Some(r) = recorder {
        let dt = r.interval();
        let k = crate::real::to_f64(from.time / dt);
        let mut k = if k.is_finite() && k > 0.0 {
            k as u32
        } else {
            0
        };
        // Every pass pushes a sample; a full recorder stops it.
        while !r.is_full() {
            k = k.saturating_add(1);
            let t = lit::<T>(f64::from(k)) * dt - from.time;
            if !(t > T::zero() && t < tau) {
                break;
            }
            let (p, v) = state_q(t, &j, q.as_ref());
            r.push(crate::flight::Sample {
                time_s: from.time + t,
                position_m: p,
                velocity_mps: v,
                spin_radps: axis * spin_at(t, s0, spin_jerk),
            });
        }
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
    let wind_varies = hopper.wind_varies();
    let mut at = *first;
    let mut bounces = 0_u32;
    let roll_velocity = loop {
        let r = bounce::rebound(&at.velocity, &at.spin, &n, &ground.turf, ground.radius);
        let vn = r.velocity_mps.dot(&n);
        if !(vn > T::zero() && vn * vn >= hop_speed_sq) || bounces >= MAX_BOUNCES {
            break r.velocity_mps - n * vn;
        }
        bounces += 1;
        let from = Contact {
            velocity: r.velocity_mps,
            spin: r.spin_radps,
            ..at
        };
        let low = if vn * vn < low_hop_speed_sq {
            low_hop(
                &from,
                &n,
                hopper,
                wind_varies,
                &mut stats,
                recorder.as_deref_mut(),
            )
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
    if !roll_velocity.iter().all(|x| x.is_finite()) {
        return Err(Error::Unstable);
    }
    let end = roll::Roll {
        normal: n,
        gravity: g_vec,
        resistance: ground.turf.rolling_resistance,
        radius: ground.radius,
        start_time: at.time,
        recorder,
    }
    .run(at.position, roll_velocity);
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
