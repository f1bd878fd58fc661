//! `carry_*_default_*`: fill an input struct with the CLI's defaults.

use crate::error::{CarryError, code};
use crate::ptr::{non_null, write};

/// Writes `value` to `out`.
///
/// # Safety
/// `out` is NULL or writable.
unsafe fn init<T>(out: *mut T, value: impl FnOnce() -> T) -> CarryError {
    code(non_null(out).map(|out| {
        // SAFETY: not NULL; writable by the caller's contract.
        unsafe { write(out, value()) }
    }))
}

/// Fills `*out` with a club head: the `driver` preset with its calibrated compliant contact (the CLI's default club); single precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_club_default_f32(out: *mut crate::CarryClubF32) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::club::default_club) }
}

/// Fills `*out` with a club head: the `driver` preset with its calibrated compliant contact (the CLI's default club); double precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_club_default_f64(out: *mut crate::CarryClubF64) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::club::default_club) }
}

/// Fills `*out` with the standard ball (45.93 g, 42.672 mm); single precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_ball_default_f32(out: *mut crate::CarryBallF32) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::CarryBall::standard) }
}

/// Fills `*out` with the standard ball (45.93 g, 42.672 mm); double precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_ball_default_f64(out: *mut crate::CarryBallF64) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::CarryBall::standard) }
}

/// Fills `*out` with a delivery: 45 m/s, square, centred, the default club's static loft; single precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_delivery_default_f32(
    out: *mut crate::CarryDeliveryF32,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe {
        init(out, || {
            crate::CarryDelivery::square(&crate::club::default_club())
        })
    }
}

/// Fills `*out` with a delivery: 45 m/s, square, centred, the default club's static loft; double precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_delivery_default_f64(
    out: *mut crate::CarryDeliveryF64,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe {
        init(out, || {
            crate::CarryDelivery::square(&crate::club::default_club())
        })
    }
}

/// Fills `*out` with a launch: 167 mph, 10.9°, 2686 rpm backspin (the CLI's `carry flight`); single precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_launch_default_f32(out: *mut crate::CarryLaunchF32) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::CarryLaunch::default) }
}

/// Fills `*out` with a launch: 167 mph, 10.9°, 2686 rpm backspin (the CLI's `carry flight`); double precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_launch_default_f64(out: *mut crate::CarryLaunchF64) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::CarryLaunch::default) }
}

/// Fills `*out` with a scene: all effects, `drives2026`, 1.225 kg/m³, no wind, landing at 0 m, no ground; single precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_scene_default_f32(out: *mut crate::CarrySceneF32) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::CarryScene::default) }
}

/// Fills `*out` with a scene: all effects, `drives2026`, 1.225 kg/m³, no wind, landing at 0 m, no ground; double precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_scene_default_f64(out: *mut crate::CarrySceneF64) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::CarryScene::default) }
}

/// Fills `*out` with numerical settings: reduced solver, Dormand–Prince at the precision's default tolerance; single precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_settings_default_f32(
    out: *mut crate::CarrySettingsF32,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::CarrySettings::default) }
}

/// Fills `*out` with numerical settings: reduced solver, Dormand–Prince at the precision's default tolerance; double precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_settings_default_f64(
    out: *mut crate::CarrySettingsF64,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::CarrySettings::default) }
}

/// Fills `*out` with an impact input (the CLI's `carry impact` defaults); single precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_impact_input_default_f32(
    out: *mut crate::CarryImpactInputF32,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::CarryImpactInput::default) }
}

/// Fills `*out` with an impact input (the CLI's `carry impact` defaults); double precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_impact_input_default_f64(
    out: *mut crate::CarryImpactInputF64,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::CarryImpactInput::default) }
}

/// Fills `*out` with a flight input (the CLI's `carry flight` defaults, 0.1 s samples); single precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_flight_input_default_f32(
    out: *mut crate::CarryFlightInputF32,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::CarryFlightInput::default) }
}

/// Fills `*out` with a flight input (the CLI's `carry flight` defaults, 0.1 s samples); double precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_flight_input_default_f64(
    out: *mut crate::CarryFlightInputF64,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::CarryFlightInput::default) }
}

/// Fills `*out` with a shot input (the CLI's `carry shot` defaults, 0.1 s samples); single precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_shot_input_default_f32(
    out: *mut crate::CarryShotInputF32,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::CarryShotInput::default) }
}

/// Fills `*out` with a shot input (the CLI's `carry shot` defaults, 0.1 s samples); double precision.
///
/// # Safety
/// `out` is NULL or points to a writable struct.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_shot_input_default_f64(
    out: *mut crate::CarryShotInputF64,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { init(out, crate::CarryShotInput::default) }
}
