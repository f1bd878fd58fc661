//! # carry-io
//!
//! The std library layer between the `no_std` physics core ([`carry_core`]) and every shell
//! (the `carry` CLI, the Python package, lab's analyses): what a shot's inputs and outputs
//! look like to a person or a file, defined once.
//!
//! * [`params`]: every input of a shot ([`params::Params`]) and the table of settable keys
//!   (`keys!`: command-line options, `--scene` files and batch CSV columns share it);
//! * [`units`]: SI or launch-monitor imperial at the edges;
//! * [`scene`]: the scene options (or a scene file) → a core [`carry_core::Scene`];
//! * [`ground`], [`contact`], [`aero_file`]: the ground, contact-law and aerodynamic model
//!   files, read and written;
//! * [`compute`]: the run ([`compute::Mode`], [`compute::Numerics`]): options → core → a
//!   [`report::Report`];
//! * [`report`]: the result records (the JSON contract) and the CSV columns;
//! * [`batch`]: many shots from a CSV file, in parallel;
//! * [`columns`]: many shots as columns of numbers over shared options (the Python
//!   package's calls), straight into a row-major array;
//! * [`error`]: [`error::InputError`], one line naming the option at fault;
//! * [`choice`]: the options that take one of a few names, parsed without clap.
//!
//! No command-line grammar lives here: the optional `clap` feature only derives
//! `clap::ValueEnum` on the option enums for the CLI. docs/architecture.md shows where this
//! crate sits.

pub mod aero_file;
pub mod batch;
pub mod choice;
pub mod columns;
pub mod compute;
pub mod contact;
pub mod error;
pub mod ground;
pub mod lanes;
pub mod mode;
pub mod params;
pub mod report;
pub mod scene;
pub mod units;

pub use compute::{Mode, Numerics};
pub use error::InputError;
pub use params::Params;
