//! One bounce on turf: Penner's model ("The run of a golf ball", Can. J. Phys. 80,
//! 931–940, 2002), written for any ground plane and any spin axis.
//!
//! In the plane of the ball's tangential motion (unit `t̂`, backspin axis `b̂ = t̂ × n̂`,
//! impact speed `v`, angle from the normal `φ`):
//!
//! ```text
//! crater tilt        θ_c = κ · 15.4° · (v / 18.6 m/s) · (φ / 44.4°) · min(1, v_n / v_f),
//!                    clamped to [0, φ] (CraterLaw::Penner), or with (v_n v_t / v)/9.298 m/s
//!                    for (v / 18.6 m/s)(φ / 44.4°) (CraterLaw::NormalTangential, issue 35)
//! tilted components  u = v_t cos θ_c − v_n sin θ_c,   v_n' = v_t sin θ_c + v_n cos θ_c
//! restitution        e = (e₀/0.510) · (0.510 − 0.0375 v_n' + 0.000903 v_n'²)  (v_n' ≤ 20 m/s)
//!                    e = (e₀/0.510) · 0.120                                     (v_n' > 20 m/s)
//! contact slip       s = u + R w                       (w: backspin about b̂)
//! rolls out if       |s| ≤ (7/2) μ (1 + e) v_n':   u' = (5u − 2Rw)/7,  w' = −u'/R
//! else it slides:    u' = u − sgn(s) μ (1+e) v_n',  w' = w − sgn(s) (5/2) μ (1+e) v_n' / R
//! rebound            v' = u' t̂' + e v_n' n̂'   (t̂', n̂' = t̂, n̂ tilted back by θ_c),
//!                    without any part into the ground plane (a fast backward exit)
//! ```
//!
//! The last factor of θ_c is ours: Penner fitted the crater law to landings (Haake's
//! measurements near 18.6 m/s, 44.4°) and it is unchanged for landings at a normal speed
//! of 6 m/s or more (a driver's, a wedge's). Extrapolated to the grazing impacts of a ball
//! already running out it would predict a crater for a rolling ball, which then skips
//! along in hops for tens of metres; a grazing ball barely dents the turf, so the tilt
//! fades with the normal speed below the turf's `v_f` ([`Turf::crater_fade_mps`];
//! [`CRATER_FADE_NORMAL_SPEED_MPS`] for the seed's surfaces; calibrated on shallow
//! landings, docs/ground.md).
//!
//! Penner's turf-crater law and e(v_n) were fitted to Haake's measurements on greens; the
//! roll/slide split is Daish's rigid-sphere impact with Coulomb friction, here with the
//! friction sign following the slip (Penner's form assumes forward slip). Spin about
//! `n̂` and `t̂` (the tilted part of a fade's or a draw's axis) is kept: the planar model
//! has no torque about those axes. The rebound never has more kinetic energy (translation
//! plus rotation) than the impact: `e ≤ e₀ ≤ 1`, the tilt is a rotation, and friction
//! stops at rolling.

use super::normal::Normal;
pub use super::surface::CRATER_FADE_NORMAL_SPEED_MPS;
use super::surface::{CraterLaw, PENNER_RESTITUTION_0, Turf};
use crate::real::{Real, at_least, at_most, length, lit};
use nalgebra::Vector3;

/// Penner's crater tilt at the reference impact (rad): 15.4°.
const CRATER_REFERENCE_RAD: f64 = 15.4 * core::f64::consts::PI / 180.0;
/// Reference impact speed of the crater law (m/s).
const CRATER_REFERENCE_SPEED_MPS: f64 = 18.6;
/// Reference impact angle from the normal of the crater law (rad): 44.4°.
const CRATER_REFERENCE_ANGLE_RAD: f64 = 44.4 * core::f64::consts::PI / 180.0;
/// `v_n v_t / v` at the crater law's reference impact (m/s):
/// `18.6 · sin 44.4° · cos 44.4°` = 9.298 m/s.
const CRATER_REFERENCE_NORMAL_TANGENTIAL_MPS: f64 = 9.297_960;
/// Normal speed above which Penner's restitution is constant (m/s).
const RESTITUTION_KNEE_MPS: f64 = 20.0;

/// Velocity and spin right after a bounce.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Rebound<T: Real> {
    /// Ball velocity after the bounce (m/s, G).
    pub velocity_mps: Vector3<T>,
    /// Ball spin after the bounce (rad/s, G).
    pub spin_radps: Vector3<T>,
    /// The rebound's speed away from the ground plane, `velocity_mps · n̂` (m/s, ≥ 0).
    pub normal_speed_mps: T,
    /// Whether the contact reached rolling (slip stopped) during the bounce.
    pub rolled: bool,
}

/// Penner's normal restitution `e(v_n)` scaled to the turf's `e₀` (module docs).
#[must_use]
pub fn restitution<T: Real>(normal_speed_mps: T, e0: T) -> T {
    let v = normal_speed_mps.abs();
    let penner = if v <= lit(RESTITUTION_KNEE_MPS) {
        lit::<T>(PENNER_RESTITUTION_0) - lit::<T>(0.0375) * v + lit::<T>(0.000903) * v * v
    } else {
        lit(0.120)
    };
    e0 / lit::<T>(PENNER_RESTITUTION_0) * penner
}

/// A unit vector in the plane of `n` (unit): the tangential direction of motion `vt` (of
/// length `len`) when there is one, else the direction a spin in the plane would kick the
/// ball, else downrange.
#[inline(always)]
fn tangent_direction<T: Real>(
    vt: &Vector3<T>,
    len: T,
    spin: &Vector3<T>,
    n: &Vector3<T>,
) -> Vector3<T> {
    if len > T::zero() {
        return vt / len;
    }
    let in_plane = spin - n * spin.dot(n);
    let s = length(&in_plane);
    if s > T::zero() {
        // Backspin axis b̂ = t̂ × n̂ ⇒ t̂ = n̂ × b̂.
        return n.cross(&(in_plane / s));
    }
    let x = Vector3::x() - n * n.x;
    let len = length(&x);
    if len > T::zero() {
        x / len
    } else {
        Vector3::z()
    }
}

/// One bounce of a ball of radius `radius_m` arriving with `velocity` and `spin` on a
/// plane of unit normal `n`, per the module docs. Finite inputs give finite outputs.
///
/// Written for a short dependency chain (each bounce waits on the last): the tangential
/// speed is the length of the tangential velocity (not a dot product after normalising),
/// the impact speed's square root runs beside it, and the crater law's constant factors
/// are one product.
pub(crate) fn rebound<T: Real, N: Normal<T>>(
    velocity: &Vector3<T>,
    spin: &Vector3<T>,
    n: N,
    turf: &Turf<T>,
    radius_m: T,
) -> Rebound<T> {
    let vn = at_least(-n.dot(velocity), T::zero());
    // The impact speed and the tangential speed from the squares, side by side (no
    // `hypot`: libm's single-precision one works in f64, software on a Cortex-M4F); with
    // them `u² + v_n'² = |v|²` below holds to rounding. The impact angle from the squares
    // too: its square root runs beside its polynomial.
    let speed_sq = velocity.norm_squared();
    let speed = speed_sq.root();
    let vt_sq = n.tangential_sq(velocity);
    let vt = vt_sq.root();
    // The direction of the tangential velocity (off the critical path: only `w` and the
    // rebound's direction need it). Its length is `v_t`: for a ball moving into the plane
    // `v + v_n n̂` is `v − (v·n̂)n̂` bit for bit, whose square `tangential_sq` sums alike.
    let vt_vec = velocity + n.scaled(vn);
    let t = tangent_direction(&vt_vec, vt, spin, &n.vector());
    // b̂ = t̂ × n̂ = −(n̂ × t̂)
    let b = -n.cross(&t);
    let w = spin.dot(&b);
    let phi = crate::geometry::atan2_first_quadrant_of_squares(vt_sq, vn * vn);
    // Faded out below the turf's fade speed (see the module docs).
    let fade = at_most(vn / turf.crater_fade_mps, T::one());
    let tilt = match turf.crater_law {
        // θ_c = κ·15.4°·(v/18.6)·(φ/44.4°)·min(1, v_n/v_f): everything but φ first.
        CraterLaw::Penner => {
            let per_speed_angle = lit::<T>(
                CRATER_REFERENCE_RAD / (CRATER_REFERENCE_SPEED_MPS * CRATER_REFERENCE_ANGLE_RAD),
            );
            turf.crater_scale * per_speed_angle * speed * fade * phi
        }
        // θ_c = κ·15.4°·(v_n v_t / v)/(18.6 · sin 44.4° cos 44.4°)·min(1, v_n/v_f).
        CraterLaw::NormalTangential => {
            let per_speed = lit::<T>(CRATER_REFERENCE_RAD / CRATER_REFERENCE_NORMAL_TANGENTIAL_MPS);
            turf.crater_scale * per_speed * (vt * vn) * fade / speed
        }
    };
    // (`φ` is finite for finite inputs, 0 for a standstill: one comparison a bound; a NaN
    // tilt, 0/0 for a standstill under the normal–tangential law, takes the bound.)
    let tilt = at_least(at_most(tilt, phi), T::zero());
    let (s, c) = crate::geometry::sin_cos_small(tilt);
    let u = vt * c - vn * s;
    let vn = at_least(vt * s + vn * c, T::zero());
    let e = restitution(vn, turf.restitution);
    let r = radius_m;
    let slip = u + r * w;
    // (μ·v_n' beside the restitution: one multiply after it.)
    let impulse = (T::one() + e) * (turf.friction * vn);
    let rolled = lit::<T>(3.5) * impulse >= slip.abs();
    let per_radius = T::one() / r;
    let (u1, w1) = if rolled {
        let u1 = lit::<T>(5.0 / 7.0) * u - lit::<T>(2.0 / 7.0) * r * w;
        (u1, -u1 * per_radius)
    } else {
        let sign = if slip > T::zero() {
            T::one()
        } else {
            -T::one()
        };
        (
            u - sign * impulse,
            w - sign * lit::<T>(2.5) * impulse * per_radius,
        )
    };
    let v1 = e * vn;
    let t1 = t * c + n.scaled(s);
    let n1 = n.scaled(c) - t * s;
    let mut out = t1 * u1 + n1 * v1;
    // The rebound's normal speed `out·n̂ = u'·sin θ_c + v'·cos θ_c` (t̂ ⊥ n̂), beside `out`
    // rather than a dot product after it. A fast backward exit out of the tilted crater
    // would point into the ground plane: the ground stops that part (the ball leaves
    // along it).
    let mut normal_speed = u1 * s + v1 * c;
    if normal_speed < T::zero() {
        out -= n.scaled(normal_speed);
        normal_speed = T::zero();
    }
    Rebound {
        velocity_mps: out,
        spin_radps: spin + b * (w1 - w),
        normal_speed_mps: normal_speed,
        rolled,
    }
}
