//! The core's lanes kernel ([`carry_core::lanes`], issue 37) on the fastest packs this CPU
//! has: the host's runtime dispatch. The core is `no_std` and cannot ask the CPU; here
//! `std` checks it once (`is_x86_feature_detected!`, cached by `std`) and hands the core an
//! [`Avx`] token where the CPU has AVX, so batches (`f64` and `f32`) fly on 256-bit packs
//! compiled for AVX even in a baseline x86-64 build (which has SSE2 only); where it has FMA
//! too, the token says so and the `f64` kernel fuses its multiply–adds; where it has
//! AVX-512 (F and DQ), the kernel runs on 512-bit packs (eight `f64` or sixteen `f32`
//! lanes). The results are the
//! scalar path's bit for bit without FMA (and in `f32`), within 1e-9 relative with it
//! (docs/performance.md, "Lanes kernel"; [`cpu_exact`] picks the exact packs). `carry batch`, the Python
//! package and the Dask example reach the kernel through [`crate::compute::run_rows`],
//! which calls [`fly_each`].

use carry_core::lanes::{self, Avx, LaneReal, Shot};
use carry_core::{FlightOutcome, Integrator, Result};

/// The AVX token where the CPU running this program has AVX (x86-64), with FMA where it
/// has FMA too and AVX-512 (eight `f64` lanes a register) where it has AVX-512 F and DQ,
/// else `None`.
#[must_use]
pub fn cpu() -> Option<Avx> {
    let avx = cpu_exact()?;
    #[cfg(target_arch = "x86_64")]
    if std::is_x86_feature_detected!("fma") {
        // SAFETY: `with_fma_unchecked` requires a CPU with FMA, which
        // `is_x86_feature_detected!("fma")` has just confirmed.
        #[allow(unsafe_code)]
        return Some(unsafe { avx.with_fma_unchecked() });
    }
    Some(avx)
}

/// The AVX token without FMA (the packs whose results are the scalar path's bit for bit)
/// where the CPU running this program has AVX, else `None`; with AVX-512 (eight `f64`
/// lanes a register, bit for bit too) where it has AVX-512 F and DQ.
#[must_use]
pub fn cpu_exact() -> Option<Avx> {
    #[cfg(target_arch = "x86_64")]
    if std::is_x86_feature_detected!("avx") {
        // SAFETY: `Avx::new_unchecked` requires a CPU (and OS) with AVX, which
        // `is_x86_feature_detected!("avx")` has just confirmed.
        #[allow(unsafe_code)]
        let avx = unsafe { Avx::new_unchecked() };
        if std::is_x86_feature_detected!("avx512f") && std::is_x86_feature_detected!("avx512dq") {
            // SAFETY: `with_avx512_unchecked` requires a CPU (and OS) with AVX-512 F and
            // DQ, which `is_x86_feature_detected!` has just confirmed.
            #[allow(unsafe_code)]
            return Some(unsafe { avx.with_avx512_unchecked() });
        }
        return Some(avx);
    }
    None
}

/// [`carry_core::lanes::fly_each`] on the fastest packs of this CPU ([`cpu`]); the same
/// results (within 1e-9 relative with FMA), each handed to `sink` with its shot's index.
pub fn fly_each<T: LaneReal>(
    shots: &[Shot<'_, T>],
    integrator: &Integrator<T>,
    sink: impl FnMut(usize, Result<FlightOutcome<T>>),
) {
    lanes::fly_each_on(cpu(), shots, integrator, sink);
}

#[cfg(test)]
mod tests {
    use super::{cpu, cpu_exact};

    /// The tokens say what the CPU has: AVX-512 exactly where it has AVX-512 F and DQ (the
    /// packs `cpu()` then prefers), FMA in `cpu()` only, `cpu_exact()` the same token without
    /// FMA.
    #[test]
    fn tokens_follow_the_cpu() {
        assert_eq!(cpu_exact(), cpu().map(|c| c.exact()));
        assert!(cpu_exact().is_none_or(|c| !c.fma()));
        #[cfg(target_arch = "x86_64")]
        {
            let avx = std::is_x86_feature_detected!("avx");
            let avx512 = avx
                && std::is_x86_feature_detected!("avx512f")
                && std::is_x86_feature_detected!("avx512dq");
            assert_eq!(cpu().is_some(), avx);
            assert_eq!(cpu().is_some_and(|c| c.avx512()), avx512);
            assert_eq!(
                cpu().is_some_and(|c| c.fma()),
                avx && std::is_x86_feature_detected!("fma")
            );
            if !avx512 {
                println!("note: no AVX-512 on this CPU; the 8-lane f64 packs are not used");
            }
        }
    }
}
