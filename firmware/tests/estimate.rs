//! On-target estimates of club data from ball data (issue 23), run on QEMU by `cargo test
//! --release`: every case of `carry_firmware::estimate_cases`, in f32 and f64, bit for
//! bit against the host's result (computed by `build.rs` from the same source), with the
//! peak stack of each estimate (painted) within a bound the micro:bit's RAM holds.
//!
//! Its own image, apart from `golden.rs`: the micro:bit's 256 KiB of flash hold the
//! estimator in software f32 and f64, or the rest of the suite, not both.
#![no_std]
#![no_main]

use carry_firmware as _;

use carry_firmware::compare::{Precision, identical};
use carry_firmware::estimate_cases::{ESTIMATE_CASES, ESTIMATE_NAMES};
use carry_firmware::golden::{ESTIMATE, Host};

/// Estimates of club data from ball data (issue 23), bit for bit against the host.
fn estimate_bit_identity<T: Precision>(
    host: impl Fn(&carry_firmware::golden::EstimateHost) -> &Host<T::Bits, 26>,
) {
    let mut differ = 0u32;
    for (case, h) in ESTIMATE_CASES.iter().zip(ESTIMATE) {
        defmt::assert_eq!(case.name, h.name);
        let (target, stack) = carry_firmware::stack::measure(|| case.outputs::<T>());
        defmt::info!(
            "estimate {=str} {=str}: peak stack {=usize} B",
            T::NAME,
            case.name,
            stack
        );
        // The micro:bit has 16 KiB of RAM for everything: f32 6.8 KiB, f64 12.8 KiB at
        // this commit (docs/firmware.md). A guard against a regression that would
        // overflow it, which faults (a lockup on QEMU) rather than failing a test.
        defmt::assert!(stack < 1800 * core::mem::size_of::<T>());
        if !identical(case.name, "default", &ESTIMATE_NAMES, &target, host(h)) {
            differ += 1;
        }
    }
    defmt::info!(
        "estimate {=str}: {=usize} cases, {=u32} differ from the host",
        T::NAME,
        ESTIMATE_CASES.len(),
        differ
    );
    defmt::assert_eq!(differ, 0);
}

#[defmt_test::tests]
mod tests {
    use super::estimate_bit_identity;

    #[test]
    fn estimate_f32_bit_identical_to_host() {
        estimate_bit_identity::<f32>(|c| &c.host_f32);
    }

    #[test]
    fn estimate_f64_bit_identical_to_host() {
        estimate_bit_identity::<f64>(|c| &c.host_f64);
    }
}
