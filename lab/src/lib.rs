//! # carry-lab
//!
//! Analyses on top of the `no_std` physics core ([`carry_core`]), for a PC (std, rayon):
//!
//! * [`study`]: the accuracy–cost study (`carry bench accuracy`, docs/accuracy.md):
//!   precisions, impact solvers and integrators measured against each other.
//!
//! The command line (`carry-cli`) is a thin shell over this crate: it parses, calls, and
//! formats; every analysis returns data (and renders tables or charts on request) rather
//! than printing.

pub mod study;
