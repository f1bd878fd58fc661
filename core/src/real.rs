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

/// The larger of `a` and `b`, or the one that is not NaN: C's `fmax`, written as a
/// comparison so that it inlines. `RealField::max` calls libm's `fmaxf`/`fmax` out of line,
/// a call in every step of the integrator on the Cortex-M4F (docs/firmware.md). Same
/// result as `a.max(b)`, sign of equal zeros aside.
#[inline(always)]
#[must_use]
pub fn larger<T: Real>(a: T, b: T) -> T {
    if a < b {
        b
    } else if a >= b || b.partial_cmp(&b).is_none() {
        a
    } else {
        b // a is NaN
    }
}

/// The smaller of `a` and `b`, or the one that is not NaN: C's `fmin` inlined (see
/// [`larger`]).
#[inline(always)]
#[must_use]
pub fn smaller<T: Real>(a: T, b: T) -> T {
    if a > b {
        b
    } else if a <= b || b.partial_cmp(&b).is_none() {
        a
    } else {
        b // a is NaN
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn larger_and_smaller_are_fmax_and_fmin() {
        let values = [
            -f64::INFINITY,
            -2.5,
            -0.0,
            1e-300,
            3.0,
            f64::INFINITY,
            f64::NAN,
        ];
        for a in values {
            for b in values {
                let (mx, mn) = (larger(a, b), smaller(a, b));
                assert!(mx.to_bits() == a.max(b).to_bits() || (mx == 0.0 && a.max(b) == 0.0));
                assert!(mn.to_bits() == a.min(b).to_bits() || (mn == 0.0 && a.min(b) == 0.0));
                let (mx32, mn32) = (larger(a as f32, b as f32), smaller(a as f32, b as f32));
                assert!(mx32.to_bits() == (a as f32).max(b as f32).to_bits() || mx32 == 0.0);
                assert!(mn32.to_bits() == (a as f32).min(b as f32).to_bits() || mn32 == 0.0);
            }
        }
    }
}
