//! The ground plane's unit normal `n̂` as the run-out's arithmetic uses it: any unit vector
//! (`Vector3`), or level ground's `ŷ` exactly ([`Level`]), whose products with a vector are
//! that vector's components:
//!
//! ```text
//! n̂·v = v_y,   n̂ k = (0, k, 0),   v − (v·n̂)n̂ = (v_x, 0, v_z),   n̂ × v = (v_z, 0, −v_x)
//! ```
//!
//! The bounces, hops and skid are one chain of dependent steps (each waits on the last), and
//! a general dot product puts three multiplies and two additions on it; on level ground (the
//! usual case) the same results, bit for bit but for the sign of a zero, come without them
//! (the on-target suite compares a board that flies the general form, the micro:bit's, with
//! the host's level one).

use crate::real::{Real, at_least};
use nalgebra::Vector3;

/// A unit normal of the ground plane.
pub(crate) trait Normal<T: Real>: Copy {
    /// `n̂` as a vector.
    fn vector(self) -> Vector3<T>;
    /// `n̂·v`.
    fn dot(self, v: &Vector3<T>) -> T;
    /// `n̂ k`.
    fn scaled(self, k: T) -> Vector3<T>;
    /// `v − (v·n̂)n̂`: the part of `v` in the plane.
    fn in_plane(self, v: &Vector3<T>) -> Vector3<T>;
    /// `n̂ × v`.
    fn cross(self, v: &Vector3<T>) -> Vector3<T>;
    /// The square of a velocity's speed other than into the plane (the bounce's impact),
    /// `|v − (v·n̂)n̂|² + max(v·n̂, 0)²`: `|v|² − v_n²` with `v_n = max(−v·n̂, 0)`, without
    /// the cancellation. Bit for bit the same for `Level` and `ŷ` as a vector (sign of
    /// zero aside: the on-target suite compares the two).
    fn tangential_sq(self, v: &Vector3<T>) -> T;
    /// `|v|²` of a vector `v` in the plane (its normal component, zero or a rounding
    /// residue, left out where the normal is `ŷ`).
    fn norm_sq_in_plane(self, v: &Vector3<T>) -> T;
}

impl<T: Real> Normal<T> for Vector3<T> {
    #[inline(always)]
    fn vector(self) -> Vector3<T> {
        self
    }

    #[inline(always)]
    fn dot(self, v: &Vector3<T>) -> T {
        Vector3::dot(&self, v)
    }

    #[inline(always)]
    fn scaled(self, k: T) -> Vector3<T> {
        self * k
    }

    #[inline(always)]
    fn in_plane(self, v: &Vector3<T>) -> Vector3<T> {
        v - self * Vector3::dot(&self, v)
    }

    #[inline(always)]
    fn cross(self, v: &Vector3<T>) -> Vector3<T> {
        Vector3::cross(&self, v)
    }

    #[inline(always)]
    fn tangential_sq(self, v: &Vector3<T>) -> T {
        let away = at_least(Vector3::dot(&self, v), T::zero());
        Normal::in_plane(self, v).norm_squared() + away * away
    }

    #[inline(always)]
    fn norm_sq_in_plane(self, v: &Vector3<T>) -> T {
        v.norm_squared()
    }
}

/// Level ground: `n̂ = ŷ` (not on bare-metal targets without an FPU: see
/// `ground::run_out`).
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Level;

#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
impl<T: Real> Normal<T> for Level {
    #[inline(always)]
    fn vector(self) -> Vector3<T> {
        Vector3::y()
    }

    #[inline(always)]
    fn dot(self, v: &Vector3<T>) -> T {
        v.y
    }

    #[inline(always)]
    fn scaled(self, k: T) -> Vector3<T> {
        Vector3::new(T::zero(), k, T::zero())
    }

    #[inline(always)]
    fn in_plane(self, v: &Vector3<T>) -> Vector3<T> {
        Vector3::new(v.x, T::zero(), v.z)
    }

    #[inline(always)]
    fn cross(self, v: &Vector3<T>) -> Vector3<T> {
        Vector3::new(v.z, T::zero(), -v.x)
    }

    /// `v_x² + v_z²` (and `v_y²` when the ball is not moving into the ground, where
    /// `v_n = 0`): not waiting on `|v|²`.
    #[inline(always)]
    fn tangential_sq(self, v: &Vector3<T>) -> T {
        let away = at_least(v.y, T::zero());
        v.x * v.x + v.z * v.z + away * away
    }

    #[inline(always)]
    fn norm_sq_in_plane(self, v: &Vector3<T>) -> T {
        v.x * v.x + v.z * v.z
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `Level` against `ŷ` as a general normal: the same values (to the sign of a zero).
    #[test]
    fn level_is_the_vertical_normal() {
        let y = Vector3::<f64>::y();
        for v in [
            Vector3::new(3.5, -2.25, 0.75),
            Vector3::new(-1.0e3, 7.0e-3, 42.0),
            Vector3::new(0.0, 0.0, 0.0),
            Vector3::new(2.0, 5.0, -1.0),
        ] {
            assert_eq!(Normal::<f64>::vector(Level), y);
            assert_eq!(Level.dot(&v), Normal::dot(y, &v));
            assert_eq!(Level.scaled(v.x), Normal::scaled(y, v.x));
            assert_eq!(Level.in_plane(&v), Normal::in_plane(y, &v));
            assert_eq!(Level.cross(&v), Normal::cross(y, &v));
            assert_eq!(Level.tangential_sq(&v), Normal::tangential_sq(y, &v));
            let into = (-v.y).max(0.0);
            let bound = 4.0 * f64::EPSILON * v.norm_squared();
            assert!((Level.tangential_sq(&v) - (v.norm_squared() - into * into)).abs() <= bound);
            let flat = Level.in_plane(&v);
            assert_eq!(
                Level.norm_sq_in_plane(&flat),
                Normal::norm_sq_in_plane(y, &flat)
            );
        }
    }
}
