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
/// software `sqrtf` (the on-target suite checks every result against the host's), in a
/// leaf function of two instructions (docs/firmware.md).
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

/// The FPU's square root on hard-float ARM targets: a leaf function, `VSQRT.F32 s0, s0`
/// and a return. The hard-float ABI passes the argument and the result in `s0`, so a call
/// costs the call and the return (and the caller keeps its live values out of the
/// argument registers), where an inline `asm!` has to take the value through a general
/// register and save `s0` around the instruction on the stack (seven instructions a root):
/// Rust's `sreg` operand class needs the unstable `vfp2` target feature (docs/firmware.md,
/// *The FPU's square root*).
#[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
#[allow(unsafe_code)]
mod hardware {
    // The instruction by its encoding (`.inst.w`, Thumb-2 T1 of VSQRT.F32 with Sd = Sm = s0):
    // no `.fpu` directive, which would stay in force for any assembly after this block. Weak:
    // two copies of the crate in one image share one definition.
    core::arch::global_asm!(
        ".pushsection .text.carry_core_vsqrtf,\"ax\",%progbits",
        ".weak carry_core_vsqrtf",
        ".type carry_core_vsqrtf,%function",
        ".p2align 1",
        ".thumb_func",
        "carry_core_vsqrtf:",
        ".inst.w 0xeeb10ac0",
        "bx lr",
        ".size carry_core_vsqrtf, . - carry_core_vsqrtf",
        ".popsection",
    );

    unsafe extern "C" {
        /// `√x` by `VSQRT.F32` (defined above; it touches `s0` and nothing else).
        safe fn carry_core_vsqrtf(x: f32) -> f32;
    }

    /// `VSQRT.F32` on `x`.
    #[inline(always)]
    pub(super) fn sqrt(x: f32) -> f32 {
        carry_core_vsqrtf(x)
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

/// Whether this target computes in `f32` in hardware (hosts, hard-float ARM).
const HARDWARE_F32: bool = cfg!(any(not(target_os = "none"), target_abi = "eabihf"));
/// Whether this target computes in `f64` in hardware: hosts. Not on bare metal, where the
/// Cortex-M4F and M0 compute it in software (the M7's double-precision unit is not told
/// apart).
const HARDWARE_F64: bool = cfg!(not(target_os = "none"));

/// Whether every value is finite.
///
/// Where the precision's arithmetic is in hardware (hosts; `f32` on hard-float ARM, the
/// Cortex-M4F and M7) as `Σ xᵢ·0 = 0`: a finite value times zero is a zero (of either
/// sign) and a sum of zeros is zero; an infinity or a NaN times zero is NaN, and so is any
/// sum with it. One multiply–add per value where `is_finite` tests each value's exponent
/// bits in integer registers. In software floating point (`f64` on bare metal, `f32` on
/// the Cortex-M0) a multiply is a library call: `is_finite` there. The same answer either
/// way (unit test `real::tests::all_finite_is_every_value_finite`).
#[inline(always)]
#[must_use]
pub(crate) fn all_finite<T: Real>(values: &[T]) -> bool {
    let hardware = if core::mem::size_of::<T>() == 4 {
        HARDWARE_F32
    } else {
        HARDWARE_F64
    };
    if hardware {
        let zero = T::zero();
        values.iter().fold(zero, |sum, &x| sum + x * zero) == zero
    } else {
        values.iter().all(|x| x.is_finite())
    }
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

/// `larger(a, bound)` for a `bound` that is never NaN (a constant, or a value finite by
/// construction): one comparison, `a` unless it is below the bound or NaN. Equal to
/// [`larger`] for every `a` (zeros' signs included) whenever `bound` is not NaN; the
/// bounce's and the hops' clamps, a few instructions each on the Cortex-M4F.
#[inline(always)]
#[must_use]
pub(crate) fn at_least<T: Real>(a: T, bound: T) -> T {
    if a >= bound { a } else { bound }
}

/// `smaller(a, bound)` for a `bound` that is never NaN: one comparison (see [`at_least`]).
#[inline(always)]
#[must_use]
pub(crate) fn at_most<T: Real>(a: T, bound: T) -> T {
    if a <= bound { a } else { bound }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `all_finite` against `is_finite` on every pair of special and ordinary values, in
    /// both precisions (zeros of either sign, subnormals, the largest finite values).
    #[test]
    fn all_finite_is_every_value_finite() {
        fn check<T: Real + Copy + core::fmt::Debug>(values: &[T], finite: impl Fn(T) -> bool) {
            for &a in values {
                assert_eq!(all_finite(&[a]), finite(a), "{a:?}");
                for &b in values {
                    for set in [[a, b, T::zero()], [T::one(), a, b]] {
                        let expected = set.iter().all(|&x| finite(x));
                        assert_eq!(all_finite(&set), expected, "{set:?}");
                    }
                }
            }
            assert!(all_finite::<T>(&[]));
        }
        check(
            &[
                0.0,
                -0.0,
                1.0,
                -3.5,
                f64::MIN_POSITIVE / 4.0,
                f64::MAX,
                f64::MIN,
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::NAN,
            ],
            f64::is_finite,
        );
        check(
            &[
                0.0,
                -0.0,
                1.0,
                -3.5,
                f32::MIN_POSITIVE / 4.0,
                f32::MAX,
                f32::MIN,
                f32::INFINITY,
                f32::NEG_INFINITY,
                f32::NAN,
            ],
            f32::is_finite,
        );
    }

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

    /// The one-comparison clamps are `larger` and `smaller` bit for bit (zeros' signs and
    /// NaN `a` included) for every bound that is not NaN.
    #[test]
    fn at_least_and_at_most_are_larger_and_smaller_for_a_bound() {
        let values = [
            -f64::INFINITY,
            -2.5,
            -0.0,
            0.0,
            1e-300,
            3.0,
            f64::INFINITY,
            f64::NAN,
        ];
        for a in values {
            for b in values.into_iter().filter(|b| !b.is_nan()) {
                assert_eq!(at_least(a, b).to_bits(), larger(a, b).to_bits(), "{a} {b}");
                assert_eq!(at_most(a, b).to_bits(), smaller(a, b).to_bits(), "{a} {b}");
                let (a, b) = (a as f32, b as f32);
                assert_eq!(at_least(a, b).to_bits(), larger(a, b).to_bits(), "{a} {b}");
                assert_eq!(at_most(a, b).to_bits(), smaller(a, b).to_bits(), "{a} {b}");
            }
        }
    }
}
