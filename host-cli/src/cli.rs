//! The command-line grammar (clap derive): the top-level [`Cli`], its subcommands and the
//! commands' own structs. The option groups they share, with their value parsers and how
//! they apply to [`Params`], are in [`crate::args`].

pub use crate::args::{
    BallArgs, BatchArgs, ClubArgs, DeliveryArgs, IntegratorArgs, LaunchArgs, OutputArgs,
    PrecisionArgs, SceneArgs, SolverArgs, numerics,
};
use carry_io::compute::Numerics;
use carry_io::error::InputError;
use carry_io::params::Params;
use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

const AFTER_HELP: &str = "\
Units: SI by default (m/s, m, °C). With --units imperial, speeds are in mph, carry and \
side in yards, heights (apex, landing height, altitude, wind reference height) in feet, \
impact location in inches and temperature in °F. Angles are always degrees, launch spins \
rpm, club spin rad/s, club and ball parameters kg, kg·m² and m, pressure Pa. JSON and CSV \
output are always SI.

Frames: X downrange, Y up, Z right of the target line (seen from behind the ball). \
Positive: attack angle up, club path and face angle right (in-to-out, open), lie toe up, \
launch direction right, sidespin and spin axis curving right (fade/slice).

Bad input prints one line naming the option and exits with status 2.";

/// carry: golf impact and ball flight from the command line.
///
/// One command per question: `impact` (club delivery → launch), `flight` (launch → flight),
/// `shot` (both), `batch` (many shots from CSV), `plot` (trajectories to SVG), `clubs`
/// (the presets). Run `carry shot` for a driver shot with the built-in defaults.
#[derive(Debug, Parser)]
#[command(name = "carry", version, propagate_version = true, after_help = AFTER_HELP, max_term_width = 100)]
pub struct Cli {
    /// What to compute.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Club delivery → ball launch (ball speed, launch angle and direction, spins, smash).
    #[command(after_help = AFTER_HELP)]
    Impact(ImpactCmd),
    /// Launch (as a launch monitor reports it) → flight (carry, side, apex, landing).
    #[command(after_help = AFTER_HELP)]
    Flight(FlightCmd),
    /// Club delivery → impact → flight. With no options: a 45 m/s driver shot.
    #[command(after_help = AFTER_HELP)]
    Shot(ShotCmd),
    /// Many shots from a CSV file: one output row (CSV, or JSON lines with --json) per input row.
    #[command(subcommand)]
    Batch(BatchCmd),
    /// Side and top views of one or more trajectories, as SVG.
    #[command(subcommand)]
    Plot(PlotCmd),
    /// The club presets and their parameters.
    Clubs(ClubsCmd),
    /// Benchmarks and studies.
    #[command(subcommand)]
    Bench(BenchCmd),
    /// Fit a model family's coefficients to measured shots (CSV), with per-row residuals and
    /// leave-one-out errors; `--output` writes the model for `--aero FILE.toml`.
    #[command(after_help = crate::fit::AFTER_HELP)]
    Fit(crate::fit::FitCmd),
    /// The dynamic loft, attack angle (and impact height) that carry furthest; --chart for
    /// the optimizer chart (club speed × attack angle → best dynamic loft).
    #[command(after_help = AFTER_HELP)]
    Optimize(Box<crate::analyses::optimize::OptimizeCmd>),
    /// A club-head motion through impact (CSV) against ball positions along the target line.
    #[command(after_help = AFTER_HELP)]
    Sweep(Box<crate::analyses::sweep::SweepCmd>),
    /// Monte-Carlo over delivery noise: landing mean, covariance, 95 % ellipse, percentiles.
    #[command(after_help = AFTER_HELP)]
    Dispersion(Box<crate::analyses::dispersion::DispersionCmd>),
    /// A launch's carry in standard conditions (sea level, 21 °C, 50 % RH, no wind), and back.
    #[command(after_help = AFTER_HELP)]
    Normalize(Box<crate::analyses::normalize::NormalizeCmd>),
    /// Club data from ball data: face, path, dynamic loft, attack, strike location and club
    /// speed, each with its 1σ (the impact model run backwards; docs/estimate.md).
    #[command(after_help = AFTER_HELP)]
    Estimate(Box<crate::analyses::estimate::EstimateCmd>),
}

/// `carry impact`.
#[derive(Debug, Clone, Args)]
pub struct ImpactCmd {
    #[command(flatten)]
    pub delivery: DeliveryArgs,
    #[command(flatten)]
    pub club: ClubArgs,
    #[command(flatten)]
    pub precision: PrecisionArgs,
    #[command(flatten)]
    pub solver: SolverArgs,
    #[command(flatten)]
    pub output: OutputArgs,
}

/// `carry flight`.
#[derive(Debug, Clone, Args)]
pub struct FlightCmd {
    #[command(flatten)]
    pub launch: LaunchArgs,
    #[command(flatten)]
    pub ball: BallArgs,
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub precision: PrecisionArgs,
    #[command(flatten)]
    pub integrator: IntegratorArgs,
    #[command(flatten)]
    pub output: OutputArgs,
}

/// `carry shot`.
#[derive(Debug, Clone, Args)]
pub struct ShotCmd {
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
    #[command(flatten)]
    pub output: OutputArgs,
}

/// `carry batch`.
#[derive(Debug, Clone, Subcommand)]
#[allow(clippy::large_enum_variant)] // parsed once
pub enum BatchCmd {
    /// Many impacts: delivery columns → launch columns.
    #[command(after_help = AFTER_HELP)]
    Impact {
        #[command(flatten)]
        batch: BatchArgs,
        #[command(flatten)]
        cmd: ImpactCmd,
    },
    /// Many flights: launch columns → flight columns.
    #[command(after_help = AFTER_HELP)]
    Flight {
        #[command(flatten)]
        batch: BatchArgs,
        #[command(flatten)]
        cmd: FlightCmd,
    },
    /// Many shots: delivery columns → launch and flight columns.
    #[command(after_help = AFTER_HELP)]
    Shot {
        #[command(flatten)]
        batch: BatchArgs,
        #[command(flatten)]
        cmd: ShotCmd,
    },
    /// Many estimates of club data from ball data: launch columns (+ any measured club
    /// columns) → face_angle_deg, club_path_deg, dynamic_loft_deg, … each with *_sd.
    /// With `--from flight`: flight columns (apex_height, carry, side, flight_time,
    /// land_angle, … each with an optional *_sd; any measured launch columns) → spin_rpm,
    /// spin_axis_deg, … each with *_sd and *_source, the fitted flight and chi2.
    #[command(after_help = AFTER_HELP)]
    Estimate {
        #[command(flatten)]
        batch: BatchArgs,
        #[command(flatten)]
        cmd: Box<crate::analyses::estimate::EstimateCmd>,
    },
}

/// Plot options.
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Plot")]
pub struct PlotArgs {
    /// The SVG file to write.
    #[arg(long, short, value_name = "FILE.svg")]
    pub output: PathBuf,
    /// One trajectory per value of an option: NAME=V1,V2,… (snake_case or kebab-case name,
    /// values in the units of --units), e.g. `--vary impact_toe=-0.02,0,0.02`.
    #[arg(long, value_name = "NAME=VALUES", allow_hyphen_values = true)]
    pub vary: Option<String>,
    /// One trajectory per row of a CSV file (as `carry batch`); a `label` column names the curves.
    #[arg(long, short, value_name = "FILE.csv", conflicts_with = "vary")]
    pub input: Option<PathBuf>,
    /// Plot title.
    #[arg(long)]
    pub title: Option<String>,
}

/// `carry plot`.
#[derive(Debug, Clone, Subcommand)]
#[allow(clippy::large_enum_variant)] // parsed once
pub enum PlotCmd {
    /// Plot flights from launches.
    #[command(after_help = AFTER_HELP)]
    Flight {
        #[command(flatten)]
        plot: PlotArgs,
        #[command(flatten)]
        cmd: FlightCmd,
    },
    /// Plot shots from deliveries (e.g. the same delivery at several impact locations).
    #[command(after_help = AFTER_HELP)]
    Shot {
        #[command(flatten)]
        plot: PlotArgs,
        #[command(flatten)]
        cmd: ShotCmd,
    },
}

/// `carry clubs`.
#[derive(Debug, Clone, Args)]
pub struct ClubsCmd {
    /// Print JSON.
    #[arg(long)]
    pub json: bool,
}

/// `carry bench`.
#[derive(Debug, Clone, Subcommand)]
pub enum BenchCmd {
    /// Accuracy study: integrators and precisions against the reference.
    Accuracy {
        /// Print JSON.
        #[arg(long)]
        json: bool,
        /// Also write an SVG chart.
        #[arg(long, value_name = "FILE.svg")]
        svg: Option<PathBuf>,
        /// A quick, smaller study.
        #[arg(long)]
        quick: bool,
        /// Aerodynamic model of the study's shots (the golden flights keep the seed's):
        /// `drives2026` (default), `tour2023`, `quintavalla` or a model file.
        #[arg(long, value_name = "NAME|FILE.toml")]
        aero: Option<String>,
    },
}

impl ImpactCmd {
    /// The shot parameters and numerics these options describe.
    ///
    /// # Errors
    /// Invalid option combinations.
    pub fn resolve(&self) -> Result<(Params, Numerics), InputError> {
        let mut p = Params::default();
        let u = self.output.units;
        self.club.apply(&mut p, u);
        self.delivery.apply(&mut p, u);
        Ok((p, numerics(&self.precision, Some(&self.solver), None)?))
    }
}

impl FlightCmd {
    /// The shot parameters and numerics these options describe.
    ///
    /// # Errors
    /// A bad scene file or invalid option combinations.
    pub fn resolve(&self) -> Result<(Params, Numerics), InputError> {
        let mut p = Params::default();
        let u = self.output.units;
        self.ball.apply(&mut p, u);
        self.launch.apply(&mut p, u);
        self.scene.apply(&mut p, u)?;
        Ok((p, numerics(&self.precision, None, Some(&self.integrator))?))
    }
}

impl ShotCmd {
    /// The shot parameters and numerics these options describe.
    ///
    /// # Errors
    /// A bad scene file or invalid option combinations.
    pub fn resolve(&self) -> Result<(Params, Numerics), InputError> {
        let mut p = Params::default();
        let u = self.output.units;
        self.club.apply(&mut p, u);
        self.delivery.apply(&mut p, u);
        self.scene.apply(&mut p, u)?;
        Ok((
            p,
            numerics(&self.precision, Some(&self.solver), Some(&self.integrator))?,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn grammar_is_consistent() {
        Cli::command().debug_assert();
    }
}
