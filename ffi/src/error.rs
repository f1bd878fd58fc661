//! The error codes of the C API and their messages.

use carry_core::Error;
use core::ffi::{CStr, c_char};

/// What a `carry_*` function returns: `CARRY_OK`, or why it failed. One code per kind of
/// core error, plus the C API's own (null pointer, buffer too small, unknown name or
/// option).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[allow(non_camel_case_types)]
pub enum CarryError {
    /// Success.
    CARRY_OK = 0,
    /// An input is NaN, infinite or outside its range (the core's `InvalidInput`).
    CARRY_ERR_INVALID_INPUT = 1,
    /// The impact point is off the club face.
    CARRY_ERR_OFF_FACE = 2,
    /// The club is not approaching the ball: no impact.
    CARRY_ERR_NO_APPROACH = 3,
    /// The impact system is numerically singular in this precision.
    CARRY_ERR_SINGULAR = 4,
    /// The ball never comes down through the landing height.
    CARRY_ERR_NO_LANDING = 5,
    /// The flight time limit was reached before landing.
    CARRY_ERR_TIME_LIMIT = 6,
    /// The adaptive integrator cannot meet the tolerance in this precision.
    CARRY_ERR_STEP_SIZE_UNDERFLOW = 7,
    /// The fixed-step integrator diverged: the step is too large.
    CARRY_ERR_UNSTABLE = 8,
    /// The adaptive integrator used up its step budget before landing.
    CARRY_ERR_STEP_LIMIT = 9,
    /// A required pointer argument is NULL.
    CARRY_ERR_NULL_POINTER = 10,
    /// The trajectory buffer filled up: the results are complete, later samples dropped.
    CARRY_ERR_BUFFER_TOO_SMALL = 11,
    /// No club preset has this name or index.
    CARRY_ERR_UNKNOWN_NAME = 12,
    /// A selector field (contact, aero, air, wind, ground, solver, integrator) holds a
    /// value that is none of its `CARRY_*` constants.
    CARRY_ERR_UNKNOWN_OPTION = 13,
    /// A core error this version of the C API does not know.
    CARRY_ERR_OTHER = 14,
    /// The estimator did not converge within its iteration budget.
    CARRY_ERR_NO_CONVERGENCE = 15,
    /// The estimator's normal matrix is singular in this precision.
    CARRY_ERR_ILL_POSED = 16,
    /// The estimator's data disagree with each other or with the club: `*out` is written
    /// (the best compromise) and its `worst` names the worst datum (`CARRY_DATUM_*`).
    CARRY_ERR_INCONSISTENT = 17,
    /// The launch fit has fewer flight observations than launch quantities to fit.
    CARRY_ERR_TOO_FEW_OBSERVATIONS = 18,
    /// The flight observations do not determine a fitted quantity: `out->unidentified`
    /// names it (`CARRY_DATUM_*`); measure it or observe more of the flight.
    CARRY_ERR_UNIDENTIFIABLE = 19,
    /// More track points or Doppler samples than the launch fit holds
    /// (`CARRY_LAUNCH_FIT_MAX_TRACK_POINTS`, `CARRY_LAUNCH_FIT_MAX_DOPPLER_SAMPLES`).
    CARRY_ERR_TOO_MANY_OBSERVATIONS = 20,
}

pub use CarryError::*;

/// Result of the C API's Rust side.
pub type Result<T> = core::result::Result<T, CarryError>;

impl From<Error> for CarryError {
    fn from(e: Error) -> Self {
        match e {
            Error::InvalidInput { .. } => CARRY_ERR_INVALID_INPUT,
            Error::OffFace => CARRY_ERR_OFF_FACE,
            Error::NoApproach => CARRY_ERR_NO_APPROACH,
            Error::Singular => CARRY_ERR_SINGULAR,
            Error::NoLanding => CARRY_ERR_NO_LANDING,
            Error::TimeLimit => CARRY_ERR_TIME_LIMIT,
            Error::StepSizeUnderflow => CARRY_ERR_STEP_SIZE_UNDERFLOW,
            Error::Unstable => CARRY_ERR_UNSTABLE,
            Error::StepLimit => CARRY_ERR_STEP_LIMIT,
            Error::NoConvergence => CARRY_ERR_NO_CONVERGENCE,
            Error::IllPosed => CARRY_ERR_ILL_POSED,
            Error::Inconsistent { .. } => CARRY_ERR_INCONSISTENT,
            Error::TooFewObservations => CARRY_ERR_TOO_FEW_OBSERVATIONS,
            Error::Unidentifiable(_) => CARRY_ERR_UNIDENTIFIABLE,
            _ => CARRY_ERR_OTHER,
        }
    }
}

/// Every code, in order (for tests and tables).
pub const ALL: [CarryError; 21] = [
    CARRY_OK,
    CARRY_ERR_INVALID_INPUT,
    CARRY_ERR_OFF_FACE,
    CARRY_ERR_NO_APPROACH,
    CARRY_ERR_SINGULAR,
    CARRY_ERR_NO_LANDING,
    CARRY_ERR_TIME_LIMIT,
    CARRY_ERR_STEP_SIZE_UNDERFLOW,
    CARRY_ERR_UNSTABLE,
    CARRY_ERR_STEP_LIMIT,
    CARRY_ERR_NULL_POINTER,
    CARRY_ERR_BUFFER_TOO_SMALL,
    CARRY_ERR_UNKNOWN_NAME,
    CARRY_ERR_UNKNOWN_OPTION,
    CARRY_ERR_OTHER,
    CARRY_ERR_NO_CONVERGENCE,
    CARRY_ERR_ILL_POSED,
    CARRY_ERR_INCONSISTENT,
    CARRY_ERR_TOO_FEW_OBSERVATIONS,
    CARRY_ERR_UNIDENTIFIABLE,
    CARRY_ERR_TOO_MANY_OBSERVATIONS,
];

/// The message of the code with number `code` (any number: unknown ones have one too).
#[must_use]
pub fn message(code: u32) -> &'static CStr {
    match code {
        0 => c"ok",
        1 => c"invalid input: a value is NaN, infinite or out of its range",
        2 => c"the impact point is off the club face",
        3 => c"the club is not approaching the ball: no impact",
        4 => c"the impact system is numerically singular",
        5 => c"the ball never comes down through the landing height",
        6 => c"the time limit was reached before the ball landed or while it bounced",
        7 => c"the integrator cannot meet the tolerance in this precision",
        8 => c"the fixed-step integrator diverged: the step is too large",
        9 => c"the adaptive integrator used up its step budget before landing",
        10 => c"a required pointer argument is NULL",
        11 => c"the trajectory buffer is too small: later samples were dropped",
        12 => c"no club preset has this name or index",
        13 => c"a selector field holds none of its CARRY_* values",
        14 => c"an error this version of the C API does not know",
        15 => c"the estimate did not converge within its iteration budget",
        16 => c"the estimate is ill-posed in this precision",
        17 => c"the estimate's data disagree with each other or with the club",
        18 => c"too few flight observations for the launch quantities not measured",
        19 => c"the flight observations do not determine a fitted quantity: measure it or observe more of the flight",
        20 => c"more track points or Doppler samples than the launch fit holds",
        _ => c"unknown error code",
    }
}

/// A static, NUL-terminated English message for an error code. Takes the code as an
/// integer (pass a `carry_error_t`), so that any value a C caller passes is defined:
/// unknown codes give "unknown error code". Never NULL.
#[unsafe(no_mangle)]
pub extern "C" fn carry_error_message(code: u32) -> *const c_char {
    message(code).as_ptr()
}

/// `CARRY_OK` or the error.
pub(crate) fn code(r: Result<()>) -> CarryError {
    match r {
        Ok(()) => CARRY_OK,
        Err(e) => e,
    }
}
