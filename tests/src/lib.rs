//! Shared helpers of the public-API test suite: golden-file loading, random scenarios
//! and physical invariants.
pub mod club_delivery;
pub mod golden;
pub mod golden_flight;
pub mod invariants;
pub mod scenario;
