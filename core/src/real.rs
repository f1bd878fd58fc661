//! Precision: every numerical routine is generic over [`Real`] (`f32` or `f64`).

use nalgebra::RealField;

/// A floating-point scalar the core can compute in: `f32` or `f64` (any
/// [`RealField`] that is `Copy`). Precision is chosen only at the edges.
pub trait Real: RealField + Copy {}

impl<T: RealField + Copy> Real for T {}

/// Converts an `f64` constant into the working precision (rounding to nearest).
#[inline(always)]
#[must_use]
pub fn lit<T: Real>(x: f64) -> T {
    nalgebra::convert(x)
}

/// Converts a working-precision value to `f64` (exact for `f32` and `f64`).
#[inline(always)]
#[must_use]
pub fn to_f64<T: Real>(x: T) -> f64 {
    nalgebra::try_convert(x).unwrap_or(f64::NAN)
}
