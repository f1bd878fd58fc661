//! Precision: every numerical routine is generic over [`Real`] (`f32` or `f64`).

use nalgebra::{Dim, RealField, Vector, storage::Storage};

/// A floating-point scalar the core can compute in: `f32` or `f64` (a [`RealField`] that
/// is `Copy` and has a [`Root`]). Precision is chosen only at the edges.
pub trait Real: RealField + Copy + Root {}

impl<T: RealField + Copy + Root> Real for T {}

/// The correctly rounded square root (IEEE 754), the one the core takes.
///
/// For `f64`, and for `f32` without a hardware FPU, it is libm's (nalgebra's
/// `ComplexField::sqrt` with `libm-force`). For `f32` on an ARM target with a hardware
/// floating-point unit (`target_abi = "eabihf"`: the Cortex-M4F and M7), it is the FPU's
/// `VSQRT.F32`, which IEEE 754 also requires to be correctly rounded: the same bits as libm's
/// software `sqrtf` (the on-target suite checks every result against the host's), in about
/// a tenth of the instructions (docs/firmware.md).
pub trait Root: Sized {
    /// `√self`, correctly rounded.
    #[must_use]
    fn root(self) -> Self;
}

impl Root for f64 {
    #[inline(always)]
    fn root(self) -> f64 {
        nalgebra::ComplexField::sqrt(self)
    }
}

impl Root for f32 {
    #[cfg(not(all(target_arch = "arm", target_abi = "eabihf")))]
    #[inline(always)]
    fn root(self) -> f32 {
        nalgebra::ComplexField::sqrt(self)
    }

    #[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
    #[inline(always)]
    fn root(self) -> f32 {
        hardware::sqrt(self)
    }
}

/// The FPU's square root on hard-float ARM targets.
#[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
mod hardware {
    /// `VSQRT.F32` on `x`. The value goes in and out through general registers (Rust's
    /// `sreg` operand class needs the unstable `vfp2` target feature); `s0` is saved and
    /// restored around the instruction on the stack.
    #[allow(unsafe_code)]
    #[inline(always)]
    pub(super) fn sqrt(x: f32) -> f32 {
        let bits: u32;
        // SAFETY: the instructions touch only `s0` (pushed first, popped last), the two
        // general registers named as operands and the stack below the stack pointer;
        // VSQRT reads and writes no memory and sets no condition flags (only FPSCR's
        // cumulative exception bits, as any floating-point operation does).
        unsafe {
            core::arch::asm!(
                "vpush {{s0}}",
                "vmov s0, {x}",
                "vsqrt.f32 s0, s0",
                "vmov {r}, s0",
                "vpop {{s0}}",
                x = in(reg) x.to_bits(),
                r = lateout(reg) bits,
                options(pure, readonly, preserves_flags)
            );
        }
        f32::from_bits(bits)
    }
}

/// The Euclidean length `√(v·v)` of a vector: nalgebra's `norm`, with [`Root::root`].
#[inline(always)]
#[must_use]
pub fn length<T: Real, D: Dim, S: Storage<T, D>>(v: &Vector<T, D, S>) -> T {
    v.norm_squared().root()
}

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
