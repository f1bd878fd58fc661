//! The flight golden cases (`tests/golden/flight.json`, computed in f64 by an independent
//! reference implementation: adaptive 8th-order integrator at 1e-12, exact landing event;
//! read by `carry-golden`, the one golden-file reader, which also turns launches and scenes
//! into the core's types). Launches are in launch-monitor units (deg, rpm); the expected
//! values are SI except angles (deg) and spin (rpm).

pub use carry_golden::{FlightCase, FlightExpected};

/// All flight cases.
///
/// # Panics
/// When the golden file does not match its schema (a broken checkout).
#[must_use]
pub fn load() -> Vec<FlightCase> {
    carry_golden::flight_cases().unwrap_or_else(|e| panic!("{e}"))
}
