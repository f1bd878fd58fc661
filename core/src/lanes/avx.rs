//! The lanes kernel on AVX (x86-64), for hosts that check the CPU at run time
//! ([`super::Avx`]): the kernel's packs as one 256-bit register, four `f64` lanes
//! (`__m256d`, [`F64x4`]) or eight `f32` lanes (`__m256`, [`F32x8`]), the whole kernel
//! compiled with `#[target_feature(enable = "avx")]`.
//!
//! Why not `wide` here: `wide::f64x4` picks its representation when the crate is compiled
//! (`cfg(target_feature = "avx")`), so on a baseline x86-64 build it is two SSE2 registers
//! whatever the calling function enables; inlined into an AVX function it becomes VEX-encoded
//! 128-bit code (measured: 9.3 k instructions a shot against 6.2 k for a whole
//! `-C target-cpu=x86-64-v3` build; docs/performance.md, "Lanes kernel"). This pack is the
//! AVX representation whatever the build's baseline.
//!
//! The arithmetic is IEEE 754's (`vaddpd`, `vmulpd`, `vdivpd`, `vsqrtpd` and their `…ps`
//! forms: correctly rounded, as the scalar `addsd`…`sqrtsd` and `addss`…`sqrtss`), so a
//! lane of [`F64x4<false>`] or [`F32x8`] is the scalar path's bit for bit, as with `wide`.
//! [`F64x4<true>`] (a token with FMA, [`Avx::fma`]) fuses the kernel's multiply–adds
//! (`vfmadd…pd`, one rounding) and takes a few shortcuts of its own (`Pack::FUSED`): its
//! results are within 1e-9 relative of the scalar path's (measured: 1.4e-13 at most over a
//! million launches at the default tolerance), not equal (docs/performance.md).
//!
//! Soundness: [`F64x4`] and [`F32x8`] are private; a value of them exists only inside
//! [`fly`], a `#[target_feature(enable = "avx")]` function, or (`F64x4<true>`) [`fly_fma`],
//! `#[target_feature(enable = "avx,fma")]`, which [`fly_each`] and [`fly_each_f32`] call
//! only with an [`Avx`] token, whose constructors require the caller to have checked the
//! CPU (AVX; FMA for a token with FMA). Every intrinsic below therefore runs on a CPU with
//! AVX, and the fused ones on a CPU with FMA.
#![allow(unsafe_code)]

use super::{Avx, Shot, fly_each_in, kernel::Pack};
use crate::error::Result;
use crate::flight::{FlightOutcome, Integrator};
use core::arch::x86_64::{
    __m256, __m256d, _CMP_LE_OQ, _CMP_LT_OQ, _CMP_NEQ_UQ, _mm256_add_pd, _mm256_add_ps,
    _mm256_and_pd, _mm256_and_ps, _mm256_andnot_pd, _mm256_andnot_ps, _mm256_blendv_pd,
    _mm256_blendv_ps, _mm256_cmp_pd, _mm256_cmp_ps, _mm256_div_pd, _mm256_div_ps, _mm256_fmadd_pd,
    _mm256_fmsub_pd, _mm256_fnmadd_pd, _mm256_movemask_pd, _mm256_movemask_ps, _mm256_mul_pd,
    _mm256_mul_ps, _mm256_or_pd, _mm256_or_ps, _mm256_set1_pd, _mm256_set1_ps, _mm256_sqrt_pd,
    _mm256_sqrt_ps, _mm256_sub_pd, _mm256_sub_ps, _mm256_xor_pd, _mm256_xor_ps,
};

/// Flies `shots` as [`super::fly_each`] does, on AVX packs.
pub(super) fn fly_each(
    cpu: Avx,
    shots: &[Shot<'_, f64>],
    integrator: &Integrator<f64>,
    sink: &mut dyn FnMut(usize, Result<FlightOutcome<f64>>),
) {
    if cpu.avx512() {
        return super::avx512::fly_each(cpu, shots, integrator, sink);
    }
    if cpu.fma() {
        // SAFETY: a token with FMA exists only where its creator checked that the CPU has
        // AVX and FMA (`Avx::new_unchecked`'s and `Avx::with_fma_unchecked`'s contracts),
        // which is what `fly_fma` requires.
        unsafe { fly_fma::<F64x4<true>, 4>(shots, integrator, sink) }
    } else {
        // SAFETY: the token exists only where its creator checked that the CPU has AVX
        // (`Avx::new_unchecked`'s contract), which is what `fly` requires.
        unsafe { fly::<F64x4<false>, 4>(shots, integrator, sink) }
    }
}

/// The kernel on the packs `P` of `N` lanes ([`F64x4`] or [`F32x8`]), compiled for AVX.
#[target_feature(enable = "avx")]
fn fly<P: Pack, const N: usize>(
    shots: &[Shot<'_, P::Scalar>],
    integrator: &Integrator<P::Scalar>,
    sink: &mut dyn FnMut(usize, Result<FlightOutcome<P::Scalar>>),
) {
    fly_each_in::<P, N>(shots, integrator, sink);
}

/// [`fly`] compiled for AVX and FMA (the pack [`F64x4<true>`], whose multiply–adds fuse).
#[target_feature(enable = "avx,fma")]
fn fly_fma<P: Pack, const N: usize>(
    shots: &[Shot<'_, P::Scalar>],
    integrator: &Integrator<P::Scalar>,
    sink: &mut dyn FnMut(usize, Result<FlightOutcome<P::Scalar>>),
) {
    fly_each_in::<P, N>(shots, integrator, sink);
}

/// Four `f64` lanes in one AVX register (only ever created inside [`fly`], or with `FMA`
/// inside [`fly_fma`]). `FMA`: [`Pack::mul_add`] and its kin are one fused instruction
/// (`vfmadd…pd`, one rounding) rather than a product and a sum.
#[derive(Clone, Copy)]
#[repr(transparent)]
struct F64x4<const FMA: bool>(__m256d);

/// Every method below runs one AVX intrinsic on values of [`F64x4`], which exist only
/// inside [`fly`] (AVX present: the module's soundness note).
macro_rules! avx {
    ($e:expr) => {
        // SAFETY: an `F64x4` exists only inside `fly`, which runs only on a CPU with AVX
        // (the module's soundness note); the intrinsic has no other precondition.
        unsafe { $e }
    };
}

x86_pack!(
    impl[const FMA: bool] F64x4<FMA>, f64, 4, avx, _mm256_set1_pd,
    [_mm256_add_pd, _mm256_sub_pd, _mm256_mul_pd, _mm256_div_pd, _mm256_and_pd, _mm256_or_pd, _mm256_xor_pd]
);

impl<const FMA: bool> F64x4<FMA> {
    /// The pack of an array.
    #[inline(always)]
    fn from_array(a: [f64; 4]) -> Self {
        // SAFETY: `__m256d` and `[f64; 4]` have the same size, and every bit pattern is
        // valid for both.
        Self(unsafe { core::mem::transmute::<[f64; 4], __m256d>(a) })
    }
}

impl<const FMA: bool> Pack for F64x4<FMA> {
    type Scalar = f64;
    const LANES: usize = 4;
    const FUSED: bool = FMA;
    #[inline(always)]
    fn mul_add(self, b: Self, c: Self) -> Self {
        if FMA {
            // SAFETY: an `F64x4<true>` exists only inside `fly_fma`, which runs only on a
            // CPU with AVX and FMA (the module's soundness note).
            Self(unsafe { _mm256_fmadd_pd(self.0, b.0, c.0) })
        } else {
            self * b + c
        }
    }
    #[inline(always)]
    fn mul_sub(self, b: Self, c: Self) -> Self {
        if FMA {
            // SAFETY: as in `mul_add`.
            Self(unsafe { _mm256_fmsub_pd(self.0, b.0, c.0) })
        } else {
            self * b - c
        }
    }
    #[inline(always)]
    fn neg_mul_add(self, b: Self, c: Self) -> Self {
        if FMA {
            // SAFETY: as in `mul_add`.
            Self(unsafe { _mm256_fnmadd_pd(self.0, b.0, c.0) })
        } else {
            c - self * b
        }
    }
    #[inline(always)]
    fn splat(x: f64) -> Self {
        Self(avx!(_mm256_set1_pd(x)))
    }
    #[inline(always)]
    fn get(&self, l: usize) -> f64 {
        self.lanes()[l % 4]
    }
    #[inline(always)]
    fn set(&mut self, l: usize, x: f64) {
        self.lanes_mut()[l % 4] = x;
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Self(avx!(_mm256_sqrt_pd(self.0)))
    }
    #[inline(always)]
    fn abs(self) -> Self {
        Self(avx!(_mm256_andnot_pd(_mm256_set1_pd(-0.0), self.0)))
    }
    #[inline(always)]
    fn lt(self, o: Self) -> Self {
        Self(avx!(_mm256_cmp_pd::<_CMP_LT_OQ>(self.0, o.0)))
    }
    #[inline(always)]
    fn le(self, o: Self) -> Self {
        Self(avx!(_mm256_cmp_pd::<_CMP_LE_OQ>(self.0, o.0)))
    }
    #[inline(always)]
    fn ne(self, o: Self) -> Self {
        // Unordered: true where either is NaN (IEEE `!=`, as SSE2's `cmpneqpd`).
        Self(avx!(_mm256_cmp_pd::<_CMP_NEQ_UQ>(self.0, o.0)))
    }
    #[inline(always)]
    fn blend(self, t: Self, f: Self) -> Self {
        Self(avx!(_mm256_blendv_pd(f.0, t.0, self.0)))
    }
    #[inline(always)]
    fn bits(self) -> u32 {
        avx!(_mm256_movemask_pd(self.0)).cast_unsigned()
    }
    #[inline(always)]
    fn mask(bits: u32) -> Self {
        // One load from a table of the 16 masks (built by shifts and compares, it was ≈ 15
        // integer instructions on AVX without AVX2).
        Self::from_array(MASKS[(bits & 15) as usize])
    }
}

/// The lane masks of the 4-bit patterns: lane `l` of `MASKS[b]` all ones where bit `l` of
/// `b` is set.
static MASKS: [[f64; 4]; 16] = {
    let mut m = [[0.0; 4]; 16];
    let mut b = 0;
    while b < 16 {
        let mut l = 0;
        while l < 4 {
            if b & (1 << l) != 0 {
                m[b][l] = f64::from_bits(!0);
            }
            l += 1;
        }
        b += 1;
    }
    m
};

/// Flies `f32` shots as [`super::fly_each`] does, on AVX packs of eight lanes.
pub(super) fn fly_each_f32(
    cpu: Avx,
    shots: &[Shot<'_, f32>],
    integrator: &Integrator<f32>,
    sink: &mut dyn FnMut(usize, Result<FlightOutcome<f32>>),
) {
    if cpu.avx512() {
        return super::avx512::fly_each_f32(cpu, shots, integrator, sink);
    }
    // SAFETY: as in `fly_each`: the token means the CPU has AVX, which `fly` requires.
    unsafe { fly::<F32x8, 8>(shots, integrator, sink) }
}

/// Eight `f32` lanes in one AVX register (only ever created inside [`fly`]; the same
/// soundness argument as [`F64x4`]'s, and the same IEEE 754 single-precision operations as
/// the scalar `addss`…`sqrtss`).
#[derive(Clone, Copy)]
#[repr(transparent)]
struct F32x8(__m256);

x86_pack!(
    impl[] F32x8, f32, 8, avx, _mm256_set1_ps,
    [_mm256_add_ps, _mm256_sub_ps, _mm256_mul_ps, _mm256_div_ps, _mm256_and_ps, _mm256_or_ps, _mm256_xor_ps]
);

impl Pack for F32x8 {
    type Scalar = f32;
    const LANES: usize = 8;
    #[inline(always)]
    fn splat(x: f32) -> Self {
        Self(avx!(_mm256_set1_ps(x)))
    }
    #[inline(always)]
    fn get(&self, l: usize) -> f32 {
        self.lanes()[l % 8]
    }
    #[inline(always)]
    fn set(&mut self, l: usize, x: f32) {
        self.lanes_mut()[l % 8] = x;
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Self(avx!(_mm256_sqrt_ps(self.0)))
    }
    #[inline(always)]
    fn abs(self) -> Self {
        Self(avx!(_mm256_andnot_ps(_mm256_set1_ps(-0.0), self.0)))
    }
    #[inline(always)]
    fn lt(self, o: Self) -> Self {
        Self(avx!(_mm256_cmp_ps::<_CMP_LT_OQ>(self.0, o.0)))
    }
    #[inline(always)]
    fn le(self, o: Self) -> Self {
        Self(avx!(_mm256_cmp_ps::<_CMP_LE_OQ>(self.0, o.0)))
    }
    #[inline(always)]
    fn ne(self, o: Self) -> Self {
        // Unordered, as `F64x4::ne`.
        Self(avx!(_mm256_cmp_ps::<_CMP_NEQ_UQ>(self.0, o.0)))
    }
    #[inline(always)]
    fn blend(self, t: Self, f: Self) -> Self {
        Self(avx!(_mm256_blendv_ps(f.0, t.0, self.0)))
    }
    #[inline(always)]
    fn bits(self) -> u32 {
        avx!(_mm256_movemask_ps(self.0)).cast_unsigned()
    }
    #[inline(always)]
    fn mask(bits: u32) -> Self {
        // Two loads from a table of the 16 four-lane masks.
        let (lo, hi) = (
            MASKS32[(bits & 15) as usize],
            MASKS32[((bits >> 4) & 15) as usize],
        );
        let a = [lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]];
        // SAFETY: `__m256` and `[f32; 8]` have the same size, and every bit pattern is
        // valid for both.
        Self(unsafe { core::mem::transmute::<[f32; 8], __m256>(a) })
    }
}

/// [`MASKS`] for `f32` lanes.
static MASKS32: [[f32; 4]; 16] = {
    let mut m = [[0.0; 4]; 16];
    let mut b = 0;
    while b < 16 {
        let mut l = 0;
        while l < 4 {
            if b & (1 << l) != 0 {
                m[b][l] = f32::from_bits(!0);
            }
            l += 1;
        }
        b += 1;
    }
    m
};
