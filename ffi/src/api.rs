//! The C entry points that compute: presets, impact, flight, shot. Each is a thin wrapper
//! over a generic function of the precision; see `defaults` for the initialisers.

use crate::club::{PRESET_NAMES, preset_at, preset_named};
use crate::error::{CarryError, Result, code};
use crate::flight::{self, CarrySample};
use crate::ptr::{non_null, with, write};
use crate::{CarryClub, CarryDelivery, impact, shot};
use crate::{
    CarryClubF32, CarryClubF64, CarryDeliveryF32, CarryDeliveryF64, CarryFlightInputF32,
    CarryFlightInputF64, CarryFlightResultF32, CarryFlightResultF64, CarryImpactInputF32,
    CarryImpactInputF64, CarryImpactResultF32, CarryImpactResultF64, CarrySampleF32,
    CarrySampleF64, CarryShotInputF32, CarryShotInputF64, CarryShotResultF32, CarryShotResultF64,
};
use carry_core::presets::Preset;
use carry_core::real::{Real, lit};
use carry_core::{Ball, Error, Field, Reason};
use core::ffi::c_char;

pub use crate::defaults::*;

/// Number of club presets (`carry clubs`).
#[unsafe(no_mangle)]
pub extern "C" fn carry_club_preset_count() -> u32 {
    PRESET_NAMES.len() as u32
}

/// The name of preset `index` (static, NUL-terminated), or NULL past the last.
#[unsafe(no_mangle)]
pub extern "C" fn carry_club_preset_name(index: u32) -> *const c_char {
    match PRESET_NAMES.get(index as usize) {
        Some(name) => name.as_ptr(),
        None => core::ptr::null(),
    }
}

fn preset_club<T: Real>(preset: Result<&'static Preset>, out: *mut CarryClub<T>) -> CarryError {
    code((|| {
        let out = non_null(out)?;
        let club = CarryClub::from_spec(&preset?.spec());
        // SAFETY: not NULL; writable by the caller's contract.
        unsafe { write(out, club) };
        Ok(())
    })())
}

fn preset_delivery<T: Real>(
    preset: Result<&'static Preset>,
    out: *mut CarryDelivery<T>,
) -> CarryError {
    code((|| {
        let out = non_null(out)?;
        let delivery = CarryDelivery::typical(preset?);
        // SAFETY: not NULL; writable by the caller's contract.
        unsafe { write(out, delivery) };
        Ok(())
    })())
}

/// The club preset named `name` (as the CLI's `--club`: `driver`, `3wood`, `hybrid`,
/// `4iron`…`9iron`, `pw`, `gw`, `sw`, `lw`), single precision.
///
/// # Safety
/// `name` is NULL or NUL-terminated; `out` is NULL or points to a writable club.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_club_preset_f32(
    name: *const c_char,
    out: *mut CarryClubF32,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    preset_club(unsafe { preset_named(name) }, out)
}

/// The club preset named `name`, double precision (see `carry_club_preset_f32`).
///
/// # Safety
/// As `carry_club_preset_f32`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_club_preset_f64(
    name: *const c_char,
    out: *mut CarryClubF64,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    preset_club(unsafe { preset_named(name) }, out)
}

/// Club preset number `index` (0 = driver … `carry_club_preset_count() − 1`), single
/// precision.
///
/// # Safety
/// `out` is NULL or points to a writable club.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_club_preset_index_f32(
    index: u32,
    out: *mut CarryClubF32,
) -> CarryError {
    preset_club(preset_at(index), out)
}

/// Club preset number `index`, double precision.
///
/// # Safety
/// `out` is NULL or points to a writable club.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_club_preset_index_f64(
    index: u32,
    out: *mut CarryClubF64,
) -> CarryError {
    preset_club(preset_at(index), out)
}

/// The typical tour delivery of the preset named `name` (club speed, attack angle,
/// dynamic loft, strike height), as the CLI fills it in for `--club NAME`; single
/// precision.
///
/// # Safety
/// `name` is NULL or NUL-terminated; `out` is NULL or points to a writable delivery.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_delivery_typical_f32(
    name: *const c_char,
    out: *mut CarryDeliveryF32,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    preset_delivery(unsafe { preset_named(name) }, out)
}

/// The typical tour delivery of the preset named `name`, double precision.
///
/// # Safety
/// As `carry_delivery_typical_f32`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_delivery_typical_f64(
    name: *const c_char,
    out: *mut CarryDeliveryF64,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    preset_delivery(unsafe { preset_named(name) }, out)
}

/// The named-club rule's strike height (`carry_core::Preset::completed`): a flat face at
/// the turf height of `loft`, a curved face its typical strike.
fn strike_height<T: Real>(
    preset: Result<&'static Preset>,
    dynamic_loft_rad: T,
    ball_radius_m: T,
    out: *mut T,
) -> CarryError {
    code((|| {
        let out = non_null(out)?;
        let preset = preset?;
        let ball = Ball::new(lit(Ball::<f64>::STANDARD_MASS_KG), ball_radius_m)?;
        if !dynamic_loft_rad.is_finite() {
            return Err(Error::invalid(Field::DynamicLoft, Reason::NotFinite).into());
        }
        let height = preset.strike_height_m(dynamic_loft_rad, ball.radius_m());
        if !height.is_finite() {
            // a radius near the precision's largest value overflows R (1 − sin δ)
            return Err(Error::invalid(Field::BallRadius, Reason::OutOfRange).into());
        }
        // SAFETY: not NULL; writable by the caller's contract.
        unsafe { write(out, height) };
        Ok(())
    })())
}

/// Where the preset named `name` strikes at dynamic loft `dynamic_loft_rad` when no strike
/// location is known (m up the face from its centre), as the CLI's `--club NAME
/// --dynamic-loft …` without `--impact-height`: a flat face (irons, wedges) where a ball of
/// radius `ball_radius_m` on firm turf meets it at that loft, a curved face its typical
/// strike. Set a delivery's `impact_height_m` from it after changing the typical loft;
/// single precision.
///
/// # Safety
/// `name` is NULL or NUL-terminated; `out` is NULL or points to a writable float.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_strike_height_f32(
    name: *const c_char,
    dynamic_loft_rad: f32,
    ball_radius_m: f32,
    out: *mut f32,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    strike_height(
        unsafe { preset_named(name) },
        dynamic_loft_rad,
        ball_radius_m,
        out,
    )
}

/// As `carry_strike_height_f32`, double precision.
///
/// # Safety
/// As `carry_strike_height_f32`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_strike_height_f64(
    name: *const c_char,
    dynamic_loft_rad: f64,
    ball_radius_m: f64,
    out: *mut f64,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    strike_height(
        unsafe { preset_named(name) },
        dynamic_loft_rad,
        ball_radius_m,
        out,
    )
}

/// # Safety
/// `input` is NULL or readable; `out` is NULL or writable.
unsafe fn impact_entry<T: Real>(
    input: *const impact::CarryImpactInput<T>,
    out: *mut impact::CarryImpactResult<T>,
) -> CarryError {
    code((|| {
        let out = non_null(out)?;
        // SAFETY: NULL or readable by the caller's contract.
        let result = unsafe { with(input, impact::run) }?;
        // SAFETY: not NULL; writable by the caller's contract.
        unsafe { write(out, result) };
        Ok(())
    })())
}

/// # Safety
/// `input` is NULL or readable; `samples` NULL or `capacity` writable samples; `count`
/// and `out` NULL or writable.
unsafe fn flight_entry<T: Real>(
    input: *const flight::CarryFlightInput<T>,
    samples: *mut CarrySample<T>,
    capacity: usize,
    count: *mut usize,
    out: *mut flight::CarryFlightResult<T>,
) -> CarryError {
    code((|| {
        let out = non_null(out)?;
        // SAFETY: the caller's contract on `samples`, `capacity` and `count`.
        let mut buffer = unsafe { flight::buffer(samples, capacity, count) }?;
        // SAFETY: NULL or readable by the caller's contract.
        let full = unsafe {
            with(input, |i| {
                let result = flight::run(i, buffer.as_mut())?;
                // SAFETY: not NULL; writable by the caller's contract.
                write(out, result);
                Ok(result.recording_full)
            })
        };
        // SAFETY: `count` NULL or writable.
        unsafe { flight::finish(buffer.as_ref(), count, full.is_ok()) };
        flight::full(buffer.as_ref(), full?)
    })())
}

/// # Safety
/// As `flight_entry`.
unsafe fn shot_entry<T: Real>(
    input: *const shot::CarryShotInput<T>,
    samples: *mut CarrySample<T>,
    capacity: usize,
    count: *mut usize,
    out: *mut shot::CarryShotResult<T>,
) -> CarryError {
    code((|| {
        let out = non_null(out)?;
        // SAFETY: the caller's contract on `samples`, `capacity` and `count`.
        let mut buffer = unsafe { flight::buffer(samples, capacity, count) }?;
        // SAFETY: NULL or readable by the caller's contract.
        let full = unsafe {
            with(input, |i| {
                shot::run_with(i, buffer.as_mut(), |result| {
                    // SAFETY: not NULL; writable by the caller's contract.
                    write(out, result());
                })
            })
        };
        // SAFETY: `count` NULL or writable.
        unsafe { flight::finish(buffer.as_ref(), count, full.is_ok()) };
        flight::full(buffer.as_ref(), u32::from(full?))
    })())
}

/// Impact: club delivery → ball launch, single precision. Writes `*out` on `CARRY_OK`
/// only.
///
/// # Safety
/// `input` is NULL or points to a readable input, `out` NULL or to a writable result.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_impact_f32(
    input: *const CarryImpactInputF32,
    out: *mut CarryImpactResultF32,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { impact_entry(input, out) }
}

/// Impact, double precision (see `carry_impact_f32`).
///
/// # Safety
/// As `carry_impact_f32`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_impact_f64(
    input: *const CarryImpactInputF64,
    out: *mut CarryImpactResultF64,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { impact_entry(input, out) }
}

/// Flight: launch → landing (→ rest on a ground), single precision. `samples` may be
/// NULL (no trajectory); otherwise it holds `capacity` samples, `count` (not NULL)
/// receives how many were written, one every `record_interval_s` and then the landing
/// (0 on an error). A full buffer returns `CARRY_ERR_BUFFER_TOO_SMALL` with `*out`
/// complete. `*out` is written on `CARRY_OK` and `CARRY_ERR_BUFFER_TOO_SMALL` only.
///
/// # Safety
/// `input` NULL or readable; `samples` NULL or `capacity` writable samples; `count` and
/// `out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_flight_f32(
    input: *const CarryFlightInputF32,
    samples: *mut CarrySampleF32,
    capacity: usize,
    count: *mut usize,
    out: *mut CarryFlightResultF32,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { flight_entry(input, samples, capacity, count, out) }
}

/// Flight, double precision (see `carry_flight_f32`).
///
/// # Safety
/// As `carry_flight_f32`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_flight_f64(
    input: *const CarryFlightInputF64,
    samples: *mut CarrySampleF64,
    capacity: usize,
    count: *mut usize,
    out: *mut CarryFlightResultF64,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { flight_entry(input, samples, capacity, count, out) }
}

/// Shot: delivery → impact → flight, single precision; the trajectory as in
/// `carry_flight_f32`.
///
/// # Safety
/// As `carry_flight_f32`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_shot_f32(
    input: *const CarryShotInputF32,
    samples: *mut CarrySampleF32,
    capacity: usize,
    count: *mut usize,
    out: *mut CarryShotResultF32,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { shot_entry(input, samples, capacity, count, out) }
}

/// Shot, double precision (see `carry_shot_f32`).
///
/// # Safety
/// As `carry_flight_f32`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_shot_f64(
    input: *const CarryShotInputF64,
    samples: *mut CarrySampleF64,
    capacity: usize,
    count: *mut usize,
    out: *mut CarryShotResultF64,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { shot_entry(input, samples, capacity, count, out) }
}

/// # Safety
/// `input` is NULL or readable; `out` is NULL or writable.
unsafe fn estimate_entry<T: Real>(
    input: *const crate::estimate::CarryEstimateInput<T>,
    out: *mut crate::estimate::CarryEstimateResult<T>,
) -> CarryError {
    code((|| {
        let out = non_null(out)?;
        // SAFETY: NULL or readable by the caller's contract.
        let result = unsafe { with(input, crate::estimate::run) }?;
        let consistent = result.consistent != 0;
        // SAFETY: not NULL; writable by the caller's contract.
        unsafe { write(out, result) };
        if consistent {
            Ok(())
        } else {
            Err(crate::error::CARRY_ERR_INCONSISTENT)
        }
    })())
}

fn estimate_default<T: Real>(
    preset: Result<&'static Preset>,
    out: *mut crate::estimate::CarryEstimateInput<T>,
) -> CarryError {
    code((|| {
        let out = non_null(out)?;
        let input = crate::estimate::CarryEstimateInput::typical(preset?);
        // SAFETY: not NULL; writable by the caller's contract.
        unsafe { write(out, input) };
        Ok(())
    })())
}

/// The default estimate input for the preset named `name` (issue 23): its club, the
/// standard ball, the default launch-monitor noise and the preset's typical prior, nothing
/// measured; fill in `measured_ball` (and `measured`/`measured_club`). Single precision.
///
/// # Safety
/// `name` is NULL or NUL-terminated; `out` is NULL or points to a writable input.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_estimate_input_default_f32(
    name: *const c_char,
    out: *mut crate::CarryEstimateInputF32,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    estimate_default(unsafe { preset_named(name) }, out)
}

/// The default estimate input, double precision (see `carry_estimate_input_default_f32`).
///
/// # Safety
/// As `carry_estimate_input_default_f32`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_estimate_input_default_f64(
    name: *const c_char,
    out: *mut crate::CarryEstimateInputF64,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    estimate_default(unsafe { preset_named(name) }, out)
}

/// Club data from ball data (issue 23, docs/estimate.md): the delivery that explains the
/// measured ball data, each datum with its 1σ; single precision. Writes `*out` on
/// `CARRY_OK` and on `CARRY_ERR_INCONSISTENT` (the data disagree with each other or with
/// the club: `out->worst` names the worst datum, issue 34) only.
///
/// # Safety
/// `input` is NULL or points to a readable input, `out` NULL or to a writable result.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_estimate_f32(
    input: *const crate::CarryEstimateInputF32,
    out: *mut crate::CarryEstimateResultF32,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { estimate_entry(input, out) }
}

/// Club data from ball data, double precision (see `carry_estimate_f32`).
///
/// # Safety
/// As `carry_estimate_f32`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_estimate_f64(
    input: *const crate::CarryEstimateInputF64,
    out: *mut crate::CarryEstimateResultF64,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { estimate_entry(input, out) }
}

/// # Safety
/// `input` NULL or readable (its arrays as documented); `workspace` and `out` NULL or
/// writable.
unsafe fn launch_from_flight_entry<T: Real>(
    input: *const crate::launch_fit::CarryLaunchFromFlightInput<T>,
    workspace: *mut crate::launch_fit::CarryLaunchFromFlightWorkspace<T>,
    out: *mut crate::launch_fit::CarryLaunchFromFlightResult<T>,
) -> CarryError {
    code((|| {
        let out = non_null(out)?;
        let workspace = non_null(workspace)?;
        if !workspace.is_aligned() {
            return Err(crate::error::CARRY_ERR_INVALID_INPUT);
        }
        // SAFETY: not NULL, aligned, writable and not aliased during the call (the
        // caller's contract).
        let ws = crate::launch_fit::workspace(unsafe { &mut *workspace });
        // SAFETY: NULL or readable by the caller's contract, its arrays forwarded.
        let result = unsafe { with(input, |i| Ok(crate::launch_fit::run(i, ws))) }?;
        match result {
            Ok(r) => {
                // SAFETY: not NULL; writable by the caller's contract.
                unsafe { write(out, r) };
                Ok(())
            }
            Err((e, unidentified)) => {
                if e == crate::error::CARRY_ERR_UNIDENTIFIABLE {
                    let r = crate::launch_fit::CarryLaunchFromFlightResult::refused(unidentified);
                    // SAFETY: as above.
                    unsafe { write(out, r) };
                }
                Err(e)
            }
        }
    })())
}

fn launch_from_flight_default<T: Real>(
    out: *mut crate::launch_fit::CarryLaunchFromFlightInput<T>,
) -> CarryError {
    code((|| {
        let out = non_null(out)?;
        // SAFETY: not NULL; writable by the caller's contract.
        unsafe {
            write(
                out,
                crate::launch_fit::CarryLaunchFromFlightInput::typical(),
            )
        };
        Ok(())
    })())
}

/// The default launch-from-flight input (issue 36): the standard ball, the default scene
/// and integrator, nothing measured or observed (the 1σ fields hold the CLI's defaults),
/// no track, the radar 2.5 m behind the tee at 0.3 m, broad priors, launch only. Single
/// precision.
///
/// # Safety
/// `out` is NULL or points to a writable input.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_launch_from_flight_input_default_f32(
    out: *mut crate::CarryLaunchFromFlightInputF32,
) -> CarryError {
    launch_from_flight_default(out)
}

/// The default launch-from-flight input, double precision (see
/// `carry_launch_from_flight_input_default_f32`).
///
/// # Safety
/// As `carry_launch_from_flight_input_default_f32`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_launch_from_flight_input_default_f64(
    out: *mut crate::CarryLaunchFromFlightInputF64,
) -> CarryError {
    launch_from_flight_default(out)
}

/// The launch from the flight (issue 36, docs/launch_fit.md): the launch quantities not
/// measured (`input->measured`), fitted to the observed summaries, track points and
/// Doppler samples, each with its 1σ and source; single precision. `workspace` is the
/// solver's scratch (caller-owned, uninitialised is fine). Writes `*out` on `CARRY_OK`,
/// and on `CARRY_ERR_UNIDENTIFIABLE` (zeros, `out->unidentified` naming the quantity the
/// observations do not determine) only. Errors: `CARRY_ERR_TOO_FEW_OBSERVATIONS`,
/// `CARRY_ERR_UNIDENTIFIABLE`, `CARRY_ERR_TOO_MANY_OBSERVATIONS`,
/// `CARRY_ERR_NO_CONVERGENCE`, `CARRY_ERR_ILL_POSED`, `CARRY_ERR_INVALID_INPUT` (a bad
/// value or 1σ, times out of order, a misaligned workspace), `CARRY_ERR_NULL_POINTER` (also
/// a NULL array with a length), `CARRY_ERR_UNKNOWN_OPTION`, a flight's.
///
/// # Safety
/// `input` is NULL or points to a readable input whose `track` and `doppler` are NULL or
/// point to `track_len` and `doppler_len` readable elements; `workspace` and `out` are
/// NULL or point to a writable workspace and result.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_launch_from_flight_f32(
    input: *const crate::CarryLaunchFromFlightInputF32,
    workspace: *mut crate::CarryLaunchFromFlightWorkspaceF32,
    out: *mut crate::CarryLaunchFromFlightResultF32,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { launch_from_flight_entry(input, workspace, out) }
}

/// The launch from the flight, double precision (see `carry_launch_from_flight_f32`).
///
/// # Safety
/// As `carry_launch_from_flight_f32`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn carry_launch_from_flight_f64(
    input: *const crate::CarryLaunchFromFlightInputF64,
    workspace: *mut crate::CarryLaunchFromFlightWorkspaceF64,
    out: *mut crate::CarryLaunchFromFlightResultF64,
) -> CarryError {
    // SAFETY: the caller's contract, forwarded.
    unsafe { launch_from_flight_entry(input, workspace, out) }
}
