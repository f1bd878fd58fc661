//! # carry-lab
//!
//! Analyses on top of the `no_std` physics core ([`carry_core`]), for a PC (std, rayon):
//!
//! * [`study`]: the accuracy–cost study (`carry bench accuracy`, docs/accuracy.md):
//!   precisions, impact solvers and integrators measured against each other.
//! * [`fit`]: fitting model coefficients to measured data (`carry fit`), with
//!   leave-one-out cross-validation; [`aero_file`] reads and writes fitted models.
//!
//! The command line (`carry-cli`) is a thin shell over this crate: it parses, calls, and
//! formats; every analysis returns data (and renders tables or charts on request) rather
//! than printing.

pub mod aero_file;
pub mod fit;
pub mod study;
