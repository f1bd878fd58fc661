//! The lanes kernel on AVX-512 (x86-64), for hosts whose CPU has AVX-512 F and DQ
//! ([`super::Avx::with_avx512_unchecked`]): the kernel's packs as one 512-bit register,
//! eight `f64` lanes (`__m512d`, [`F64x8`]) or sixteen `f32` lanes (`__m512`, [`F32x16`]),
//! the whole kernel compiled with `#[target_feature(enable = "avx512f,avx512dq")]`.
//!
//! The arithmetic is IEEE 754's (`vaddpd`, `vmulpd`, `vdivpd`, `vsqrtpd` on `zmm`
//! registers, the default rounding, no embedded rounding or reciprocal approximations), so
//! a lane of [`F64x8<false>`] is the scalar path's bit for bit, as [`super::avx`]'s
//! `F64x4<false>`. [`F64x8<true>`] (a token with FMA) fuses the kernel's multiply–adds
//! (`vfmadd…pd`, which AVX-512 F has for `zmm`) and takes the fused packs' shortcuts
//! (`Pack::FUSED`): within 1e-9 relative of the scalar path, as `F64x4<true>`.
//!
//! Masks: the kernel's `Pack` trait has a mask be a pack (all ones or all zeros a lane).
//! Here a compare gives AVX-512's `__mmask8` (`vcmppd k`), widened to a pack by
//! `vpmovm2q`; a blend narrows it back (`vpmovq2m`) for `vblendmpd`. LLVM folds the pairs
//! (a widened mask's sign bits are the mask), so masks stay in `k` registers.
//!
//! Soundness: [`F64x8`] and [`F32x16`] are private; a value of them exists only inside
//! [`fly`], a `#[target_feature(enable = "avx512f,avx512dq")]` function, which [`fly_each`]
//! and [`fly_each_f32`] call only
//! with an [`Avx`] token with AVX-512, whose constructor requires the caller to have
//! checked the CPU (AVX-512 F and DQ). Every intrinsic below therefore runs on such a CPU
//! (AVX-512 F includes the 512-bit fused multiply–adds).
#![allow(unsafe_code)]

use super::{Avx, Shot, fly_each_in, kernel::Pack};
use crate::error::Result;
use crate::flight::{FlightOutcome, Integrator};
use core::arch::x86_64::{
    __m512, __m512d, _CMP_LE_OQ, _CMP_LT_OQ, _CMP_NEQ_UQ, _mm512_abs_pd, _mm512_abs_ps,
    _mm512_add_pd, _mm512_add_ps, _mm512_and_pd, _mm512_and_ps, _mm512_castpd_si512,
    _mm512_castps_si512, _mm512_castsi512_pd, _mm512_castsi512_ps, _mm512_cmp_pd_mask,
    _mm512_cmp_ps_mask, _mm512_div_pd, _mm512_div_ps, _mm512_fmadd_pd, _mm512_fmsub_pd,
    _mm512_fnmadd_pd, _mm512_mask_blend_pd, _mm512_mask_blend_ps, _mm512_movepi32_mask,
    _mm512_movepi64_mask, _mm512_movm_epi32, _mm512_movm_epi64, _mm512_mul_pd, _mm512_mul_ps,
    _mm512_or_pd, _mm512_or_ps, _mm512_set1_pd, _mm512_set1_ps, _mm512_sqrt_pd, _mm512_sqrt_ps,
    _mm512_sub_pd, _mm512_sub_ps, _mm512_xor_pd, _mm512_xor_ps,
};

/// Flies `shots` as [`super::fly_each`] does, on AVX-512 packs of eight `f64` lanes.
pub(super) fn fly_each(
    cpu: Avx,
    shots: &[Shot<'_, f64>],
    integrator: &Integrator<f64>,
    sink: &mut dyn FnMut(usize, Result<FlightOutcome<f64>>),
) {
    if cpu.fma() {
        // SAFETY: a token with AVX-512 exists only where its creator checked that the CPU
        // has AVX-512 F and DQ (`Avx::with_avx512_unchecked`'s contract), which is what
        // `fly` requires; AVX-512 F has the fused multiply–adds `F64x8<true>` uses.
        unsafe { fly::<F64x8<true>, 8>(shots, integrator, sink) }
    } else {
        // SAFETY: as above.
        unsafe { fly::<F64x8<false>, 8>(shots, integrator, sink) }
    }
}

/// The kernel on the packs `P` of `N` lanes ([`F64x8`]), compiled for AVX-512.
#[target_feature(enable = "avx512f,avx512dq")]
fn fly<P: Pack, const N: usize>(
    shots: &[Shot<'_, P::Scalar>],
    integrator: &Integrator<P::Scalar>,
    sink: &mut dyn FnMut(usize, Result<FlightOutcome<P::Scalar>>),
) {
    fly_each_in::<P, N>(shots, integrator, sink);
}

/// Eight `f64` lanes in one AVX-512 register (only ever created inside [`fly`]). `FMA`:
/// [`Pack::mul_add`] and its kin are one fused instruction (`vfmadd…pd`, one rounding)
/// rather than a product and a sum.
#[derive(Clone, Copy)]
#[repr(transparent)]
struct F64x8<const FMA: bool>(__m512d);

/// Every method below runs AVX-512 F/DQ intrinsics on values of [`F64x8`], which exist
/// only inside [`fly`] (AVX-512 F and DQ present: the module's soundness note).
macro_rules! avx512 {
    ($e:expr) => {
        // SAFETY: an `F64x8` exists only inside `fly`, which runs only on a CPU with
        // AVX-512 F and DQ (the module's soundness note); the intrinsic has no other
        // precondition.
        unsafe { $e }
    };
}

/// The [`Pack`] methods both AVX-512 packs write the same way, each one intrinsic on the
/// register: broadcast, lane access, square root, absolute value, the compares (a
/// `__mmask` widened to a pack), the blend (the mask narrowed back, `$k`) and the mask of
/// lane bits (`$movm` widens a `__mmask`; bits past the pack's lanes are not lanes).
macro_rules! avx512_pack_methods {
    (
        $scalar:ty, $n:literal, $bits:ty, $set1:ident, $sqrt:ident, $abs:ident,
        $cmp:ident, $blend:ident, $movm:ident, $from_int:ident
    ) => {
        #[inline(always)]
        fn splat(x: $scalar) -> Self {
            Self(avx512!($set1(x)))
        }
        #[inline(always)]
        fn get(&self, l: usize) -> $scalar {
            self.lanes()[l % $n]
        }
        #[inline(always)]
        fn set(&mut self, l: usize, x: $scalar) {
            self.lanes_mut()[l % $n] = x;
        }
        #[inline(always)]
        fn sqrt(self) -> Self {
            Self(avx512!($sqrt(self.0)))
        }
        #[inline(always)]
        fn abs(self) -> Self {
            Self(avx512!($abs(self.0)))
        }
        #[inline(always)]
        fn lt(self, o: Self) -> Self {
            Self::mask(avx512!($cmp::<_CMP_LT_OQ>(self.0, o.0)).into())
        }
        #[inline(always)]
        fn le(self, o: Self) -> Self {
            Self::mask(avx512!($cmp::<_CMP_LE_OQ>(self.0, o.0)).into())
        }
        #[inline(always)]
        fn ne(self, o: Self) -> Self {
            // Unordered: true where either is NaN (IEEE `!=`, as the AVX packs' `ne`).
            Self::mask(avx512!($cmp::<_CMP_NEQ_UQ>(self.0, o.0)).into())
        }
        #[inline(always)]
        fn blend(self, t: Self, f: Self) -> Self {
            // `_mm512_mask_blend_*(k, a, b)` takes `b` where `k` is set.
            Self(avx512!($blend(self.k(), f.0, t.0)))
        }
        #[inline(always)]
        fn bits(self) -> u32 {
            u32::from(self.k())
        }
        #[inline(always)]
        fn mask(bits: u32) -> Self {
            // All ones in the lanes whose bit is set (`vpmovm2q`/`vpmovm2d`); the bits past
            // the pack's lanes are dropped.
            #[allow(clippy::cast_possible_truncation)]
            let k = bits as $bits;
            Self(avx512!($from_int($movm(k))))
        }
    };
}

x86_pack!(
    impl[const FMA: bool] F64x8<FMA>, f64, 8, avx512, _mm512_set1_pd,
    [_mm512_add_pd, _mm512_sub_pd, _mm512_mul_pd, _mm512_div_pd, _mm512_and_pd, _mm512_or_pd, _mm512_xor_pd]
);

impl<const FMA: bool> F64x8<FMA> {
    /// The mask's lanes as AVX-512's `__mmask8` (the sign bit of each lane).
    #[inline(always)]
    fn k(self) -> u8 {
        avx512!(_mm512_movepi64_mask(_mm512_castpd_si512(self.0)))
    }
}

impl<const FMA: bool> Pack for F64x8<FMA> {
    type Scalar = f64;
    const LANES: usize = 8;
    const FUSED: bool = FMA;
    #[inline(always)]
    fn mul_add(self, b: Self, c: Self) -> Self {
        if FMA {
            Self(avx512!(_mm512_fmadd_pd(self.0, b.0, c.0)))
        } else {
            self * b + c
        }
    }
    #[inline(always)]
    fn mul_sub(self, b: Self, c: Self) -> Self {
        if FMA {
            Self(avx512!(_mm512_fmsub_pd(self.0, b.0, c.0)))
        } else {
            self * b - c
        }
    }
    #[inline(always)]
    fn neg_mul_add(self, b: Self, c: Self) -> Self {
        if FMA {
            Self(avx512!(_mm512_fnmadd_pd(self.0, b.0, c.0)))
        } else {
            c - self * b
        }
    }
    avx512_pack_methods!(
        f64,
        8,
        u8,
        _mm512_set1_pd,
        _mm512_sqrt_pd,
        _mm512_abs_pd,
        _mm512_cmp_pd_mask,
        _mm512_mask_blend_pd,
        _mm512_movm_epi64,
        _mm512_castsi512_pd
    );
}

/// Flies `f32` shots as [`super::fly_each`] does, on AVX-512 packs of sixteen lanes.
pub(super) fn fly_each_f32(
    _cpu: Avx,
    shots: &[Shot<'_, f32>],
    integrator: &Integrator<f32>,
    sink: &mut dyn FnMut(usize, Result<FlightOutcome<f32>>),
) {
    // SAFETY: as in `fly_each`: a token with AVX-512 means the CPU has AVX-512 F and DQ,
    // which `fly` requires.
    unsafe { fly::<F32x16, 16>(shots, integrator, sink) }
}

/// Sixteen `f32` lanes in one AVX-512 register (only ever created inside [`fly`]; the same
/// soundness argument as [`F64x8`]'s, and the same IEEE 754 single-precision operations as
/// the scalar `addss`…`sqrtss`: bit for bit the scalar `f32` path, as `avx::F32x8`).
#[derive(Clone, Copy)]
#[repr(transparent)]
struct F32x16(__m512);

x86_pack!(
    impl[] F32x16, f32, 16, avx512, _mm512_set1_ps,
    [_mm512_add_ps, _mm512_sub_ps, _mm512_mul_ps, _mm512_div_ps, _mm512_and_ps, _mm512_or_ps, _mm512_xor_ps]
);

impl F32x16 {
    /// The mask's lanes as AVX-512's `__mmask16` (the sign bit of each lane).
    #[inline(always)]
    fn k(self) -> u16 {
        avx512!(_mm512_movepi32_mask(_mm512_castps_si512(self.0)))
    }
}

impl Pack for F32x16 {
    type Scalar = f32;
    const LANES: usize = 16;
    avx512_pack_methods!(
        f32,
        16,
        u16,
        _mm512_set1_ps,
        _mm512_sqrt_ps,
        _mm512_abs_ps,
        _mm512_cmp_ps_mask,
        _mm512_mask_blend_ps,
        _mm512_movm_epi32,
        _mm512_castsi512_ps
    );
}
