//! The no-panic link check of the C API (issue 13): its entry points (carry-ffi) on
//! opaque inputs — every initialiser, the presets, impact, flight and shot in both
//! precisions, with a trajectory buffer, a too-small one, NULL pointers — and the error
//! messages, built `--release` with carry-ffi's `panic-undefined` handler: the image
//! links only if no panic path is reachable from any of them.
#![no_std]
#![no_main]

use carry_ffi::*;
use core::hint::black_box;
use core::ptr::{null, null_mut};

/// An opaque value, its address hidden from the optimiser.
fn opaque<T>(v: T) -> T {
    black_box(v)
}

/// Sums the codes (and one number of each result) so nothing is dead.
fn paths() -> u32 {
    let mut acc = 0_u32;
    let mut add = |c: CarryError| acc = acc.wrapping_add(c as u32);
    let mut shot32: CarryShotInputF32 = opaque(CarryShotInputF32::default());
    let mut shot64: CarryShotInputF64 = opaque(CarryShotInputF64::default());
    let mut flight32: CarryFlightInputF32 = opaque(CarryFlightInputF32::default());
    let mut flight64: CarryFlightInputF64 = opaque(CarryFlightInputF64::default());
    let mut impact32: CarryImpactInputF32 = opaque(CarryImpactInputF32::default());
    let mut impact64: CarryImpactInputF64 = opaque(CarryImpactInputF64::default());
    let mut samples32 = [CarrySample::<f32>::default(); 8];
    let mut samples64 = [CarrySample::<f64>::default(); 8];
    let mut count = 0_usize;
    let mut r_shot32 = opaque(CarryShotResultF32::default());
    let mut r_shot64 = opaque(CarryShotResultF64::default());
    let mut r_flight32 = opaque(CarryFlightResultF32::default());
    let mut r_flight64 = opaque(CarryFlightResultF64::default());
    let mut r_impact32 = opaque(CarryImpactResultF32::default());
    let mut r_impact64 = opaque(CarryImpactResultF64::default());
    let name = opaque(c"7iron".as_ptr());
    let index = opaque(3_u32);
    let cap = opaque(8_usize);
    // SAFETY: every pointer is NULL or points to a live value of its type; the sample
    // buffers hold `cap` (≤ 8) samples.
    unsafe {
        add(carry_shot_input_default_f32(opaque(&mut shot32)));
        add(carry_shot_input_default_f64(opaque(&mut shot64)));
        add(carry_flight_input_default_f32(opaque(&mut flight32)));
        add(carry_flight_input_default_f64(opaque(&mut flight64)));
        add(carry_impact_input_default_f32(opaque(&mut impact32)));
        add(carry_impact_input_default_f64(opaque(&mut impact64)));
        add(carry_club_default_f32(opaque(&mut shot32.club)));
        add(carry_club_default_f64(opaque(&mut shot64.club)));
        add(carry_ball_default_f32(opaque(&mut shot32.ball)));
        add(carry_ball_default_f64(opaque(&mut shot64.ball)));
        add(carry_delivery_default_f32(opaque(&mut shot32.delivery)));
        add(carry_delivery_default_f64(opaque(&mut shot64.delivery)));
        add(carry_launch_default_f32(opaque(&mut flight32.launch)));
        add(carry_launch_default_f64(opaque(&mut flight64.launch)));
        add(carry_scene_default_f32(opaque(&mut shot32.scene)));
        add(carry_scene_default_f64(opaque(&mut shot64.scene)));
        add(carry_settings_default_f32(opaque(&mut shot32.settings)));
        add(carry_settings_default_f64(opaque(&mut shot64.settings)));
        add(carry_club_preset_f32(name, opaque(&mut shot32.club)));
        add(carry_club_preset_f64(name, opaque(&mut shot64.club)));
        add(carry_club_preset_index_f32(
            index,
            opaque(&mut impact32.club),
        ));
        add(carry_club_preset_index_f64(
            index,
            opaque(&mut impact64.club),
        ));
        add(carry_delivery_typical_f32(
            name,
            opaque(&mut shot32.delivery),
        ));
        add(carry_delivery_typical_f64(
            name,
            opaque(&mut shot64.delivery),
        ));
        let (mut h32, mut h64) = (opaque(0.0_f32), opaque(0.0_f64));
        add(carry_strike_height_f32(
            name,
            opaque(0.35_f32),
            opaque(0.021_336_f32),
            opaque(&mut h32),
        ));
        add(carry_strike_height_f64(
            name,
            opaque(0.35_f64),
            opaque(0.021_336_f64),
            opaque(&mut h64),
        ));
        shot32.delivery.impact_height_m = h32;
        shot64.delivery.impact_height_m = h64;
        add(carry_impact_f32(opaque(&impact32), opaque(&mut r_impact32)));
        add(carry_impact_f64(opaque(&impact64), opaque(&mut r_impact64)));
        add(carry_flight_f32(
            opaque(&flight32),
            opaque(samples32.as_mut_ptr()),
            cap,
            opaque(&mut count),
            opaque(&mut r_flight32),
        ));
        add(carry_flight_f64(
            opaque(&flight64),
            opaque(samples64.as_mut_ptr()),
            cap,
            opaque(&mut count),
            opaque(&mut r_flight64),
        ));
        add(carry_shot_f32(
            opaque(&shot32),
            opaque(samples32.as_mut_ptr()),
            cap,
            opaque(&mut count),
            opaque(&mut r_shot32),
        ));
        add(carry_shot_f64(
            opaque(&shot64),
            opaque(samples64.as_mut_ptr()),
            cap,
            opaque(&mut count),
            opaque(&mut r_shot64),
        ));
        add(carry_shot_f32(
            opaque(null()),
            opaque(null_mut()),
            0,
            opaque(null_mut()),
            opaque(null_mut()),
        ));
        add(carry_flight_f64(
            opaque(&flight64),
            opaque(null_mut()),
            0,
            opaque(null_mut()),
            opaque(&mut r_flight64),
        ));
    }
    // the estimator (issue 23)
    let mut est32 = core::mem::MaybeUninit::<CarryEstimateInputF32>::zeroed();
    let mut est64 = core::mem::MaybeUninit::<CarryEstimateInputF64>::zeroed();
    let mut r_est32 = opaque(carry_ffi::estimate::CarryEstimateResult::<f32>::default());
    let mut r_est64 = opaque(carry_ffi::estimate::CarryEstimateResult::<f64>::default());
    // SAFETY: every pointer is NULL or points to a live value of its type; the zeroed
    // inputs are plain numbers (any bit pattern is a valid input).
    unsafe {
        add(carry_estimate_input_default_f32(
            name,
            opaque(est32.as_mut_ptr()),
        ));
        add(carry_estimate_input_default_f64(
            name,
            opaque(est64.as_mut_ptr()),
        ));
        add(carry_estimate_f32(
            opaque(est32.as_ptr()),
            opaque(&mut r_est32),
        ));
        add(carry_estimate_f64(
            opaque(est64.as_ptr()),
            opaque(&mut r_est64),
        ));
    }
    black_box((r_est32, r_est64));
    // the launch from the flight (issue 36)
    let mut lf32 = core::mem::MaybeUninit::<CarryLaunchFromFlightInputF32>::zeroed();
    let mut lf64 = core::mem::MaybeUninit::<CarryLaunchFromFlightInputF64>::zeroed();
    let mut ws32 = core::mem::MaybeUninit::<CarryLaunchFromFlightWorkspaceF32>::zeroed();
    let mut ws64 = core::mem::MaybeUninit::<CarryLaunchFromFlightWorkspaceF64>::zeroed();
    let mut r_lf32 = opaque(CarryLaunchFromFlightResultF32::refused(0));
    let mut r_lf64 = opaque(CarryLaunchFromFlightResultF64::refused(0));
    // SAFETY: every pointer is NULL or points to a live value of its type; the zeroed
    // inputs are plain numbers and NULL arrays (any bit pattern of a number is valid).
    unsafe {
        add(carry_launch_from_flight_input_default_f32(opaque(
            lf32.as_mut_ptr(),
        )));
        add(carry_launch_from_flight_input_default_f64(opaque(
            lf64.as_mut_ptr(),
        )));
        add(carry_launch_from_flight_f32(
            opaque(lf32.as_ptr()),
            opaque(ws32.as_mut_ptr()),
            opaque(&mut r_lf32),
        ));
        add(carry_launch_from_flight_f64(
            opaque(lf64.as_ptr()),
            opaque(ws64.as_mut_ptr()),
            opaque(&mut r_lf64),
        ));
    }
    black_box((r_lf32, r_lf64));
    acc = acc.wrapping_add(carry_club_preset_count());
    acc = acc.wrapping_add(opaque(carry_club_preset_name(index)) as usize as u32);
    acc = acc.wrapping_add(opaque(carry_error_message(opaque(index))) as usize as u32);
    acc = acc.wrapping_add(carry_deg_to_rad_f32(opaque(1.0)).to_bits());
    acc = acc.wrapping_add(carry_rpm_to_radps_f64(opaque(1.0)).to_bits() as u32);
    black_box((
        r_shot32, r_shot64, r_flight32, r_flight64, r_impact32, r_impact64, samples32, samples64,
    ));
    acc.wrapping_add(count as u32)
}

#[cortex_m_rt::entry]
fn main() -> ! {
    // The negative control (`--features canary`), as in `src/main.rs`.
    #[cfg(feature = "canary")]
    black_box([1_u8; 4][black_box(7_usize) % black_box(8_usize)]);
    loop {
        black_box(paths());
    }
}
