//! The one reader of carry's golden files.
//!
//! `tests/golden/impact.json` and `tests/golden/flight.json` are verbatim copies of
//! `../shared/golden/`, computed by an independent f64 reference implementation. This crate
//! reads them into plain `f64` cases in the files' own units (degrees, rpm, SI otherwise) and
//! names, and turns them into the core's types (`to_core`: the seed's models, named); every
//! consumer (the public-API tests, the C API's tests, the firmware's build script, the CLI's
//! tests and the lab's accuracy study) starts from here. The files are
//! embedded at compile time ([`IMPACT_JSON`], [`FLIGHT_JSON`]), so a consumer rebuilds when they
//! change and a binary that embeds the study needs no file at run time.
//!
//! The reference writes Python's JSON: bare `NaN`, `Infinity` and `-Infinity` tokens (in the
//! error cases). They are read as the IEEE values.

mod flight;
mod impact;
mod json;
mod to_core;

pub use flight::{Effects, FlightCase, FlightExpected, Launch, Scene, Weather, WindProfile};
pub use impact::{Ball, Club, Delivery, ImpactCase, ImpactExpected};
pub use json::Error;

/// The impact golden file, as committed.
pub const IMPACT_JSON: &str = include_str!("../impact.json");

/// The flight golden file, as committed.
pub const FLIGHT_JSON: &str = include_str!("../flight.json");

/// The directory holding the golden files (`tests/golden`).
#[must_use]
pub fn dir() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

/// Every case of the impact golden file.
///
/// # Errors
/// When the embedded file does not match the schema (a broken checkout).
pub fn impact_cases() -> Result<Vec<ImpactCase>, Error> {
    impact::parse(IMPACT_JSON)
}

/// Every case of the flight golden file.
///
/// # Errors
/// When the embedded file does not match the schema (a broken checkout).
pub fn flight_cases() -> Result<Vec<FlightCase>, Error> {
    flight::parse(FLIGHT_JSON)
}
