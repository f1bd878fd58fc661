//! # carry-lab
//!
//! Analyses on top of the `no_std` physics core ([`carry_core`]), for a PC (std, rayon):
//!
//! * [`study`]: the accuracy–cost study (`carry bench accuracy`, docs/accuracy.md):
//!   precisions, impact solvers and integrators measured against each other.
//! * [`fit`]: fitting model coefficients to measured data (`carry fit`), with
//!   leave-one-out cross-validation; [`aero_file`] reads and writes fitted models.
//! * [`optimize`]: the delivery (dynamic loft, attack angle, impact height) that maximises
//!   carry within bounds (argmin), and the TrackMan-style optimizer chart.
//! * [`sweep`]: a club-head motion through impact (sampled in time) against a range of ball
//!   positions; the example swing's generator (a planar double pendulum).
//! * [`dispersion`]: Monte-Carlo over delivery noise, landing statistics and ellipse.
//! * [`normalize`]: the carry of a launch in standard conditions, and back.
//! * [`bag`]: the bag from delivery alone against TrackMan's 2023 tour averages.
//! * [`launch_fit`]: the launch from the flight as a typed request (`carry estimate --from
//!   flight`), and the track file reader.
//! * [`launch_drives`]: the launch fit on the single drives against TrackMan's spin (held-out
//!   aerodynamics, data-set observation noise, one weather per group of outdoor shots).
//! * [`drives`]: single TrackMan drives (`../shared/data/trackman_amateur_drives.csv`), read
//!   where they lie, with session blocks for cross-validation.
//!
//! The command line (`carry-cli`) is a thin shell over this crate: it parses, calls, and
//! formats; every analysis returns data (and renders tables or charts on request) rather
//! than printing. docs/optimize.md has the measured figures.

/// The aerodynamic model files, now in [`carry_io`] (re-exported for existing paths).
pub use carry_io::aero_file;
pub mod bag;
pub mod columns;
pub mod dispersion;
pub mod drives;
pub mod error;
pub mod fit;
pub mod ground_drives;
pub mod ground_fit;
pub mod ground_joint;
pub mod launch_drives;
pub mod launch_fit;
pub mod normalize;
pub mod optimize;
pub mod request;
pub mod rows;
pub mod setup;
pub mod study;
pub mod sweep;

pub use error::{Error, Input, Result};
pub use setup::{Setup, ShotSummary};
