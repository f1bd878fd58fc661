//! Unit conversions for the edges, and the constants several layers share. Inside, the
//! core is SI: m, s, kg, rad, rad/s.
//!
//! Launch monitors speak degrees, rpm, mph and yards; convert with these at the boundary.
//! The accepted input ranges below are the ones the core validates against (the modules
//! that validate re-export them); shells quote them in their messages instead of copying
//! the numbers.

use crate::real::{Real, lit};

/// m/s per mph (exact: 1 mph = 0.44704 m/s).
pub const MPS_PER_MPH: f64 = 0.44704;
/// Metres per yard (exact).
pub const M_PER_YARD: f64 = 0.9144;
/// Metres per foot (exact).
pub const M_PER_FOOT: f64 = 0.3048;
/// rad/s per rpm (2π/60).
pub const RADPS_PER_RPM: f64 = core::f64::consts::PI / 30.0;
/// Standard gravity (m/s²; exact by definition, CGPM 1901).
pub const STANDARD_GRAVITY_MPS2: f64 = 9.80665;

/// Accepted stimp readings (m): 1 ft to 30 ft ([`crate::ground::Surface::Green`]).
pub const STIMP_RANGE_M: (f64, f64) = (M_PER_FOOT, 30.0 * M_PER_FOOT);
/// Steepest accepted ground (rad): 45° ([`crate::ground::Ground`]).
pub const MAX_SLOPE_RAD: f64 = core::f64::consts::FRAC_PI_4;
/// Accepted air temperatures (°C) ([`crate::air::Weather`]).
pub const TEMPERATURE_RANGE_C: (f64, f64) = (-100.0, 100.0);
/// Accepted altitudes (m): the standard atmosphere's troposphere and below
/// ([`crate::air::Pressure::Altitude`]).
pub const ALTITUDE_RANGE_M: (f64, f64) = (-5_000.0, 11_000.0);

/// Degrees → radians.
#[inline]
#[must_use]
pub fn deg<T: Real>(degrees: T) -> T {
    degrees * (T::pi() / lit(180.0))
}

/// Radians → degrees.
#[inline]
#[must_use]
pub fn to_deg<T: Real>(radians: T) -> T {
    radians * (lit::<T>(180.0) / T::pi())
}

/// rpm → rad/s.
#[inline]
#[must_use]
pub fn rpm<T: Real>(rev_per_min: T) -> T {
    rev_per_min * (T::pi() / lit(30.0))
}

/// rad/s → rpm.
#[inline]
#[must_use]
pub fn to_rpm<T: Real>(radps: T) -> T {
    radps * (lit::<T>(30.0) / T::pi())
}

/// mph → m/s.
#[inline]
#[must_use]
pub fn mph<T: Real>(miles_per_hour: T) -> T {
    miles_per_hour * lit(MPS_PER_MPH)
}

/// m/s → mph.
#[inline]
#[must_use]
pub fn to_mph<T: Real>(mps: T) -> T {
    mps / lit(MPS_PER_MPH)
}

/// Yards → metres.
#[inline]
#[must_use]
pub fn yards<T: Real>(yd: T) -> T {
    yd * lit(M_PER_YARD)
}

/// Metres → yards.
#[inline]
#[must_use]
pub fn to_yards<T: Real>(m: T) -> T {
    m / lit(M_PER_YARD)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trips() {
        assert!((to_deg(deg(10.5_f64)) - 10.5).abs() < 1e-13);
        assert!((to_rpm(rpm(2686.0_f64)) - 2686.0).abs() < 1e-10);
        assert!((mph(167.0_f64) - 74.65568).abs() < 1e-12);
        assert!((to_yards(yards(275.0_f64)) - 275.0).abs() < 1e-12);
    }
}
