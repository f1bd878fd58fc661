//! On-target launch fits (issue 36), run on QEMU by `cargo test --release`: every case of
//! `carry_firmware::launch_fit_cases` (launch + summaries → spin and axis, a 32-point track
//! → the full launch, a Doppler trace → spin, and a typed refusal), in f32 and f64, bit for
//! bit against the host's result (computed by `build.rs` from the same source), each fitted
//! value within 3σ of the launch that made the data, and the fit's peak stack.
//!
//! Its own image. Not on the micro:bit: the caller-owned `Workspace<f32>` alone is
//! 21,792 B, more than its 16 KiB of RAM (the image there only checks that this is still so).
#![no_std]
#![no_main]

use carry_firmware as _;

#[cfg(not(carry_m0))]
mod fits {
    use carry_core::launch_fit::{Observations, Settings, Workspace, fit_launch};
    use carry_core::{Ball, Scene};
    use carry_firmware::compare::{Precision, identical};
    use carry_firmware::golden::{Host, LAUNCH_FIT, LaunchFitHost};
    use carry_firmware::launch_fit_cases::{
        LAUNCH_FIT_CASES, LAUNCH_FIT_NAMES, LAUNCH_FIT_OUTPUTS, sigmas_off,
    };

    /// Every launch fit, bit for bit against the host, and near the truth.
    pub fn bit_identity<T: Precision>(
        host: impl Fn(&LaunchFitHost) -> &Host<T::Bits, LAUNCH_FIT_OUTPUTS>,
    ) {
        let mut ws = Workspace::<T>::new();
        let mut differ = 0u32;
        for (case, h) in LAUNCH_FIT_CASES.iter().zip(LAUNCH_FIT) {
            defmt::assert_eq!(case.name, h.name);
            let target = case.outputs::<T>(&mut ws);
            if !identical(case.name, "default", &LAUNCH_FIT_NAMES, &target, host(h)) {
                differ += 1;
            }
            match &target {
                Ok(out) => {
                    let off = sigmas_off(case, out);
                    defmt::info!(
                        "launch_fit {=str} {=str}: {=f64} iterations, {=f64} flights, (fit - truth)/sd = {}",
                        T::NAME,
                        case.name,
                        carry_core::real::to_f64(out[12]),
                        carry_core::real::to_f64(out[13]),
                        off
                    );
                    for s in off {
                        defmt::assert!(s.abs() < 3.0, "{=str}: {=f64} sigma off", case.name, s);
                    }
                }
                Err(e) => defmt::info!("launch_fit {=str} {=str}: {}", T::NAME, case.name, e),
            }
        }
        defmt::info!(
            "launch_fit {=str}: {=usize} cases, {=u32} differ from the host",
            T::NAME,
            LAUNCH_FIT_CASES.len(),
            differ
        );
        defmt::assert_eq!(differ, 0);
    }

    /// The sizes of the caller's data and the fit's own peak stack (painted), per case.
    pub fn memory<T: Precision>() {
        let mut ws = Workspace::<T>::new();
        defmt::info!(
            "launch_fit {=str}: Workspace {=usize} B, Observations {=usize} B",
            T::NAME,
            core::mem::size_of::<Workspace<T>>(),
            core::mem::size_of::<Observations<T>>()
        );
        for case in &LAUNCH_FIT_CASES {
            let Ok((measured, obs)) = case.inputs::<T>() else {
                defmt::panic!("{=str}: no observations", case.name);
            };
            let (ball, scene, settings) = (Ball::standard(), Scene::default(), Settings::default());
            let (_, stack) = carry_firmware::stack::measure(|| {
                fit_launch(&ball, &scene, &measured, &obs, &settings, &mut ws).is_ok()
            });
            defmt::info!(
                "launch_fit {=str} {=str}: peak stack of fit_launch {=usize} B (workspace and observations not included)",
                T::NAME,
                case.name,
                stack
            );
            // f32 8.8 KiB, f64 17 KiB at this commit: a guard against a large regression
            defmt::assert!(stack < 3 * 1024 * core::mem::size_of::<T>());
        }
    }
}

#[defmt_test::tests]
mod tests {
    #[cfg(not(carry_m0))]
    #[test]
    fn launch_fit_f32_bit_identical_to_host() {
        super::fits::bit_identity::<f32>(|c| &c.host_f32);
    }

    #[cfg(not(carry_m0))]
    #[test]
    fn launch_fit_f64_bit_identical_to_host() {
        super::fits::bit_identity::<f64>(|c| &c.host_f64);
    }

    #[cfg(not(carry_m0))]
    #[test]
    fn launch_fit_memory() {
        super::fits::memory::<f32>();
        super::fits::memory::<f64>();
    }

    /// The micro:bit (16 KiB of RAM) cannot hold the fit's workspace.
    #[cfg(carry_m0)]
    #[test]
    fn launch_fit_workspace_exceeds_the_m0_ram() {
        let bytes = core::mem::size_of::<carry_core::launch_fit::Workspace<f32>>();
        defmt::info!(
            "launch_fit not run on the M0: Workspace<f32> is {=usize} B, RAM 16384 B",
            bytes
        );
        defmt::assert!(bytes > 16 * 1024);
    }
}
