//! # carry-ffi
//!
//! A small, stable C API over `carry-core`: impact, flight and shot in `f32` and `f64`,
//! club presets and custom clubs, scenes, numerical settings. The header
//! `include/carry.h` is generated from this crate by cbindgen (`ffi/cbindgen.toml`).
//!
//! Rules of the API (docs/ffi.md):
//! - every input and output is a plain `#[repr(C)]` struct of floats and unsigned
//!   integers; selectors are `uint32_t` fields holding `CARRY_*` constants, so any bit
//!   pattern a C caller leaves in a struct is defined (an unknown selector is
//!   `CARRY_ERR_UNKNOWN_OPTION`);
//! - SI units throughout, angles in radians and spins in rad/s (the core's units; the
//!   CLI's degrees and rpm convert with `carry_deg_to_rad_*`/`carry_rpm_to_radps_*`);
//! - the caller owns all memory: inputs are read, results written through pointers,
//!   trajectory samples go into a caller buffer (pointer + capacity in, count out);
//!   nothing is allocated, nothing panics, every pointer is checked for NULL;
//! - every function returns a `carry_error_t` (`CARRY_OK` = 0); `carry_error_message`
//!   gives a static message for each.
#![no_std]
#![allow(unsafe_code)]

// Hosted builds (the cdylib, the tests) need std's panic runtime; the library uses none of std.
#[cfg(not(target_os = "none"))]
extern crate std;

pub mod club;
pub mod error;
pub mod estimate;
pub mod flight;
pub mod impact;
pub mod launch_fit;
mod ptr;
pub mod scene;
pub mod settings;
pub mod shot;
pub mod units;

pub use club::{CarryBall, CarryClub};
pub use error::{CarryError, carry_error_message};
pub use flight::{CarryFlightInput, CarryFlightResult, CarryLaunch, CarrySample};
pub use impact::{CarryDelivery, CarryImpactInput, CarryImpactResult};
pub use scene::CarryScene;
pub use settings::CarrySettings;
pub use shot::{CarryShotInput, CarryShotResult};

/// A club head in single precision.
pub type CarryClubF32 = CarryClub<f32>;
/// A club head in double precision.
pub type CarryClubF64 = CarryClub<f64>;
/// A ball in single precision.
pub type CarryBallF32 = CarryBall<f32>;
/// A ball in double precision.
pub type CarryBallF64 = CarryBall<f64>;
/// A club delivery in single precision.
pub type CarryDeliveryF32 = CarryDelivery<f32>;
/// A club delivery in double precision.
pub type CarryDeliveryF64 = CarryDelivery<f64>;
/// A launch in single precision.
pub type CarryLaunchF32 = CarryLaunch<f32>;
/// A launch in double precision.
pub type CarryLaunchF64 = CarryLaunch<f64>;
/// A scene in single precision.
pub type CarrySceneF32 = CarryScene<f32>;
/// A scene in double precision.
pub type CarrySceneF64 = CarryScene<f64>;
/// Numerical settings in single precision.
pub type CarrySettingsF32 = CarrySettings<f32>;
/// Numerical settings in double precision.
pub type CarrySettingsF64 = CarrySettings<f64>;
/// Impact input in single precision.
pub type CarryImpactInputF32 = CarryImpactInput<f32>;
/// Impact input in double precision.
pub type CarryImpactInputF64 = CarryImpactInput<f64>;
/// Impact result in single precision.
pub type CarryImpactResultF32 = CarryImpactResult<f32>;
/// Impact result in double precision.
pub type CarryImpactResultF64 = CarryImpactResult<f64>;
/// Flight input in single precision.
pub type CarryFlightInputF32 = CarryFlightInput<f32>;
/// Flight input in double precision.
pub type CarryFlightInputF64 = CarryFlightInput<f64>;
/// Flight result in single precision.
pub type CarryFlightResultF32 = CarryFlightResult<f32>;
/// Flight result in double precision.
pub type CarryFlightResultF64 = CarryFlightResult<f64>;
/// A trajectory sample in single precision.
pub type CarrySampleF32 = CarrySample<f32>;
/// A trajectory sample in double precision.
pub type CarrySampleF64 = CarrySample<f64>;
/// Shot input in single precision.
pub type CarryShotInputF32 = CarryShotInput<f32>;
/// Shot input in double precision.
pub type CarryShotInputF64 = CarryShotInput<f64>;
/// Shot result in single precision.
pub type CarryShotResultF32 = CarryShotResult<f32>;
/// Shot result in double precision.
pub type CarryShotResultF64 = CarryShotResult<f64>;

/// Estimate input in single precision.
pub type CarryEstimateInputF32 = estimate::CarryEstimateInput<f32>;
/// Estimate input in double precision.
pub type CarryEstimateInputF64 = estimate::CarryEstimateInput<f64>;
/// Estimate result in single precision.
pub type CarryEstimateResultF32 = estimate::CarryEstimateResult<f32>;
/// Estimate result in double precision.
pub type CarryEstimateResultF64 = estimate::CarryEstimateResult<f64>;

/// Launch-from-flight input in single precision.
pub type CarryLaunchFromFlightInputF32 = launch_fit::CarryLaunchFromFlightInput<f32>;
/// Launch-from-flight input in double precision.
pub type CarryLaunchFromFlightInputF64 = launch_fit::CarryLaunchFromFlightInput<f64>;
/// Launch-from-flight result in single precision.
pub type CarryLaunchFromFlightResultF32 = launch_fit::CarryLaunchFromFlightResult<f32>;
/// Launch-from-flight result in double precision.
pub type CarryLaunchFromFlightResultF64 = launch_fit::CarryLaunchFromFlightResult<f64>;
/// The launch fit's scratch space in single precision.
pub type CarryLaunchFromFlightWorkspaceF32 = launch_fit::CarryLaunchFromFlightWorkspace<f32>;
/// The launch fit's scratch space in double precision.
pub type CarryLaunchFromFlightWorkspaceF64 = launch_fit::CarryLaunchFromFlightWorkspace<f64>;
/// A track point in single precision.
pub type CarryTrackPointF32 = launch_fit::CarryTrackPoint<f32>;
/// A track point in double precision.
pub type CarryTrackPointF64 = launch_fit::CarryTrackPoint<f64>;
/// A Doppler sample in single precision.
pub type CarryDopplerSampleF32 = launch_fit::CarryDopplerSample<f32>;
/// A Doppler sample in double precision.
pub type CarryDopplerSampleF64 = launch_fit::CarryDopplerSample<f64>;

mod api;
mod defaults;
pub use api::*;
pub use units::*;

/// The staticlib's panic handler on bare metal. Never reached: `nopanic/` proves the C
/// entry points link without any panic path.
#[cfg(all(
    target_os = "none",
    feature = "panic-handler",
    not(feature = "panic-undefined")
))]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo<'_>) -> ! {
    loop {
        core::hint::spin_loop();
    }
}

/// The no-panic proof's handler (`nopanic/src/bin/ffi.rs`): calls a function that does
/// not exist, so an image that can still reach a panic does not link.
#[cfg(all(target_os = "none", feature = "panic-undefined"))]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo<'_>) -> ! {
    unsafe extern "C" {
        /// Never defined: referencing it fails the link.
        fn carry_core_reached_a_panic_path() -> !;
    }
    // SAFETY: never runs; the symbol does not exist, so an image that still calls the
    // panic handler does not link.
    unsafe { carry_core_reached_a_panic_path() }
}
