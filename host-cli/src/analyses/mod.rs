//! The lab's commands (`optimize`, `sweep`, `dispersion`, `normalize`): clap options → the
//! typed requests of [`carry_lab::request`] (which Python calls too) → table, JSON, CSV or
//! SVG. All logic lives in carry-lab; this is parsing and formatting.

pub mod dispersion;
pub mod estimate;
pub mod from_flight;
pub mod normalize;
pub mod optimize;
mod output;
pub mod sweep;

use crate::args::{ClubArgs, DeliveryArgs, IntegratorArgs, PrecisionArgs, SceneArgs, SolverArgs};
use carry_io::compute::Numerics;
use carry_io::error::{Failure, InputError};
use carry_io::params::Params;
use carry_io::units::Units;
pub use carry_lab::request::{failure, setup, with_setup};

/// Everything of a shot the lab commands share: delivery, club, scene, numerics.
#[derive(Debug, Clone, clap::Args)]
pub struct ShotArgs {
    #[command(flatten)]
    pub delivery: DeliveryArgs,
    #[command(flatten)]
    pub club: ClubArgs,
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub precision: PrecisionArgs,
    #[command(flatten)]
    pub solver: SolverArgs,
    #[command(flatten)]
    pub integrator: IntegratorArgs,
}

impl ShotArgs {
    /// The parameters and numerics, in `units`.
    ///
    /// # Errors
    /// A bad scene file or option combination.
    pub fn resolve(&self, units: Units) -> Result<(Params, Numerics), InputError> {
        let mut p = Params::default();
        self.club.apply(&mut p, units);
        self.delivery.apply(&mut p, units);
        self.scene.apply(&mut p, units)?;
        let n = crate::args::numerics(&self.precision, Some(&self.solver), Some(&self.integrator))?;
        Ok((p, n))
    }
}

/// Prints the notes of options an analysis replaced, one line each on stderr.
pub fn print_notes(notes: &[String]) {
    use std::io::Write as _;
    let mut err = std::io::stderr().lock();
    for n in notes {
        let _ = writeln!(err, "carry: {n}");
    }
}

pub use carry_io::params::{parse_pair, parse_triple};

/// A chart writer of the lab.
type Draw<T> = fn(&std::path::Path, &T) -> Result<(), Box<dyn std::error::Error>>;

/// Writes an SVG with `draw`, mapping a failure to status 1.
///
/// # Errors
/// Failing to draw or write.
pub fn write_svg<T>(path: &std::path::Path, data: &T, draw: Draw<T>) -> Result<(), Failure> {
    draw(path, data).map_err(|e| Failure::Other(format!("cannot write {}: {e}", path.display())))
}
