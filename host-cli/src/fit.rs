//! `carry fit`: the grammar of a fit request ([`carry_lab::fit::request`], which reads the
//! files, fits, and formats the report).

use carry_io::error::Failure;
use carry_io::units::Units;
use carry_lab::fit::request::{self, FitRequest};
use clap::Args;
use std::path::PathBuf;

/// `carry fit`.
#[derive(Debug, Clone, Args)]
pub struct FitCmd {
    /// Measured shots (CSV; `-` for standard input). See `carry fit --help` for columns.
    #[arg(long, value_name = "FILE.csv")]
    pub input: PathBuf,
    /// More measured shots, fitted jointly with --input (repeatable; the same columns
    /// rules, each file its own header). With `--family compliant`: more delivery tables, a
    /// driver chart (no `club` column) or single-drive TrackMan exports (issue 34).
    #[arg(long = "also", value_name = "FILE.csv")]
    pub also: Vec<PathBuf>,
    /// Model family to fit: `modern` (drag crisis, a lift of two saturating components,
    /// Smits & Smith spin decay; 9 coefficients) or `quintavalla` (the seed's linear family, 5 coefficients);
    /// `compliant`: the face–ball contact law on delivery → launch rows (club,
    /// club_speed_mph, attack_deg, dynamic_loft_deg, ball_speed_mph, launch_deg, spin_rpm,
    /// as ../shared/data/club_delivery.csv; writes a `--contact` file).
    #[arg(long, default_value = "modern", value_name = "FAMILY")]
    pub family: String,
    /// Write the fitted model here (TOML; use it with `--aero FILE.toml`).
    #[arg(long, value_name = "MODEL.toml")]
    pub output: Option<PathBuf>,
    /// Do not fit: report how this model (`drives2026`, `tour2023`, `quintavalla` or a model
    /// file) does on the input (its family replaces --family).
    #[arg(long, value_name = "NAME|FILE.toml", conflicts_with = "output")]
    pub evaluate: Option<String>,
    /// Skip the leave-one-out cross-validation (one refit per row).
    #[arg(long)]
    pub no_cross_validation: bool,
    /// Input and display units (JSON stays SI).
    #[arg(long, value_enum, default_value_t = Units::Si)]
    pub units: Units,
    /// Print JSON (SI).
    #[arg(long)]
    pub json: bool,
    /// No progress bar.
    #[arg(long)]
    pub no_progress: bool,
    /// Air density of rows without conditions [kg/m³] (default 1.225). Excludes weather.
    #[arg(long, value_name = "KG/M3", conflicts_with_all = ["temperature", "humidity", "pressure", "altitude"])]
    pub air_density: Option<f64>,
    /// Temperature of rows without conditions [°C | °F] (weather; default 15 °C).
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub temperature: Option<f64>,
    /// Relative humidity of rows without conditions [%] (weather; default 0).
    #[arg(long, value_name = "PCT")]
    pub humidity: Option<f64>,
    /// Station pressure of rows without conditions [Pa] (weather). Excludes --altitude.
    #[arg(long, value_name = "PA", conflicts_with = "altitude")]
    pub pressure: Option<f64>,
    /// Altitude of rows without conditions [m | ft] (weather).
    #[arg(long, value_name = "H", allow_hyphen_values = true)]
    pub altitude: Option<f64>,
    /// With single drives in the fit: the weight of every table row (default 1; issue 35's
    /// fit used 20 against ~3,700 drives).
    #[arg(long, value_name = "W")]
    pub table_weight: Option<f64>,
    /// Replace a parameter's bounds: `INDEX:LO:HI` or `NAME:LO:HI` (repeatable; INDEX in
    /// the family's order from 0, e.g. `8:0.01:0.4` for the modern `cl_low_saturation_spin`,
    /// the bound single drives in the fit already get). The start is moved into them.
    #[arg(long, value_name = "INDEX:LO:HI")]
    pub bound: Vec<String>,
}

/// Help text after the options.
pub const AFTER_HELP: &str = "\
Input columns: ball_speed, launch_angle, launch_direction, backspin+sidespin or spin+spin_axis; \
carry (required), apex, land_angle, flight_time, side; optional temperature, humidity, \
pressure|altitude, air_density, label, weight. A unit suffix (_mph _mps _yd _ft _m _deg _rpm _s \
_c _f _pa _pct) overrides --units, so TrackMan exports read as they are:
  carry fit --input ../shared/data/trackman_tour_2023.csv --temperature 21.1 --humidity 50 \
--pressure 101325 --output tour.toml
A single-drive TrackMan export (header `Ball,Club Speed,...,Carry Flat - Length,...` and a units line, as ../shared/data/trackman_amateur_drives.csv) is recognised by its header, as --input or --also: its premium-ball indoor rows are fitted on carry, apex, landing angle and flight time (rows the default model misses by > 15 % left out, and listed), and cross-validated by session (blocks of 1,000 consecutive rows held out together; table rows one by one):
  carry fit --input ../shared/data/trackman_tour_2023.csv --also ../shared/data/trackman_driver_optimizer_2010.csv --also ../shared/data/trackman_amateur_drives.csv --table-weight 20 --temperature 21.1 --humidity 50 --pressure 101325 --output drives.toml
The contact law (--family compliant) fits delivery → launch rows (club_delivery.csv's columns); with --also, more tables, a driver chart (no club column: TrackMan's 2010 optimizer, struck by the driver preset) and single-drive exports, jointly (the drives 1/--table-weight times the tables in total, k_e within Penner's measured 0.0020-0.0040 s/m, drives held out by session):
  carry fit --family compliant --input ../shared/data/club_delivery.csv --also ../shared/data/trackman_driver_optimizer_2010.csv --also ../shared/data/trackman_amateur_drives.csv --output contact.toml";

impl FitCmd {
    /// The typed request of these options.
    #[must_use]
    pub fn request(&self) -> FitRequest {
        FitRequest {
            input: self.input.clone(),
            also: self.also.clone(),
            family: self.family.clone(),
            output: self.output.clone(),
            evaluate: self.evaluate.clone(),
            no_cross_validation: self.no_cross_validation,
            units: self.units,
            json: self.json,
            no_progress: self.no_progress,
            air_density: self.air_density,
            temperature: self.temperature,
            humidity: self.humidity,
            pressure: self.pressure,
            altitude: self.altitude,
            table_weight: self.table_weight,
            bound: self.bound.clone(),
        }
    }
}

/// Runs `carry fit`.
///
/// # Errors
/// As [`request::report`], or stdout cannot be written.
pub fn run(cmd: &FitCmd) -> Result<(), Failure> {
    crate::write_stdout(request::report(&cmd.request())?.as_bytes())
}
