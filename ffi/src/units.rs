//! The CLI's units, converted exactly as the CLI converts them.

use carry_core::units::{deg, rpm};

/// Degrees → radians, rounded as the core and the CLI round it (single precision).
#[unsafe(no_mangle)]
pub extern "C" fn carry_deg_to_rad_f32(degrees: f32) -> f32 {
    deg(degrees)
}

/// Degrees → radians, rounded as the core and the CLI round it (double precision).
#[unsafe(no_mangle)]
pub extern "C" fn carry_deg_to_rad_f64(degrees: f64) -> f64 {
    deg(degrees)
}

/// rpm → rad/s, rounded as the core and the CLI round it (single precision).
#[unsafe(no_mangle)]
pub extern "C" fn carry_rpm_to_radps_f32(rev_per_min: f32) -> f32 {
    rpm(rev_per_min)
}

/// rpm → rad/s, rounded as the core and the CLI round it (double precision).
#[unsafe(no_mangle)]
pub extern "C" fn carry_rpm_to_radps_f64(rev_per_min: f64) -> f64 {
    rpm(rev_per_min)
}
