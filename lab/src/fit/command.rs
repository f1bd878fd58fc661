//! The typed `carry fit` request and what a family's fit produces: shared by the
//! aerodynamic families' request module and the contact family's, so that neither imports
//! the other.

use super::Fit;
use carry_io::error::InputError;
use carry_io::units::Units;
use std::path::PathBuf;

/// A fit of measured shots (`carry fit`, `carry.fit`): the files, the family and the
/// conditions of rows without their own.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FitRequest {
    /// Measured shots (CSV; `-` for standard input). The columns: this module's doc.
    pub input: PathBuf,
    /// More measured shots, fitted jointly with --input (repeatable; the same columns
    /// rules, each file its own header). With `--family compliant`: more delivery tables, a
    /// driver chart (no `club` column) or single-drive TrackMan exports (issue 34).
    pub also: Vec<PathBuf>,
    /// Model family to fit: `modern` (drag crisis, a lift of two saturating components,
    /// Smits & Smith spin decay; 9 coefficients) or `quintavalla` (the seed's linear family, 5 coefficients);
    /// `compliant`: the face–ball contact law on delivery → launch rows (club,
    /// club_speed_mph, attack_deg, dynamic_loft_deg, ball_speed_mph, launch_deg, spin_rpm,
    /// as ../shared/data/club_delivery.csv; writes a `--contact` file).
    pub family: String,
    /// Write the fitted model here (TOML; use it with `--aero FILE.toml`).
    pub output: Option<PathBuf>,
    /// Do not fit: report how this model (`drives2026`, `tour2023`, `quintavalla` or a model
    /// file) does on the input (its family replaces --family).
    pub evaluate: Option<String>,
    /// Skip the leave-one-out cross-validation (one refit per row).
    pub no_cross_validation: bool,
    /// Input and display units (JSON stays SI).
    pub units: Units,
    /// The JSON document (SI) rather than the table.
    pub json: bool,
    /// No progress bar.
    pub no_progress: bool,
    /// Air density of rows without conditions (kg/m³) (default 1.225). Excludes weather.
    pub air_density: Option<f64>,
    /// Temperature of rows without conditions (°C | °F) (weather; default 15 °C).
    pub temperature: Option<f64>,
    /// Relative humidity of rows without conditions (%) (weather; default 0).
    pub humidity: Option<f64>,
    /// Station pressure of rows without conditions (Pa) (weather). Excludes --altitude.
    pub pressure: Option<f64>,
    /// Altitude of rows without conditions (m | ft) (weather).
    pub altitude: Option<f64>,
    /// Weight of every row that is not a single drive (the tables), when single drives are
    /// in the fit (default 1; docs/aero.md, issue 35, uses 20).
    pub table_weight: Option<f64>,
    /// Replaced parameter bounds, `INDEX:LO:HI` or `NAME:LO:HI` (repeatable; the index in
    /// the family's parameter order, from 0; e.g. `8:0.01:0.4`, the modern family's
    /// `cl_low_saturation_spin` as with single drives in the fit). The start is moved
    /// into them.
    pub bound: Vec<String>,
}

/// What a fit produces: text (the table, or the JSON document as text) or the JSON
/// document as a value.
pub(super) enum Produced {
    /// The table, or the pretty JSON text.
    Text(String),
    /// The JSON document.
    Value(serde_json::Value),
}

impl FitRequest {
    /// Checks the options that exclude each other (the CLI's grammar says the same with
    /// its usage errors): the air density or the weather, the pressure or the altitude,
    /// `output` or `evaluate`.
    ///
    /// # Errors
    /// An [`InputError`] naming the first option at fault.
    pub fn check(&self) -> Result<(), InputError> {
        if self.air_density.is_some()
            && (self.temperature.is_some()
                || self.humidity.is_some()
                || self.pressure.is_some()
                || self.altitude.is_some())
        {
            return Err(InputError::new(
                "air_density",
                "give either the air density or the weather, not both",
            ));
        }
        if self.pressure.is_some() && self.altitude.is_some() {
            return Err(InputError::new(
                "pressure",
                "give either the pressure or the altitude, not both",
            ));
        }
        if self.output.is_some() && self.evaluate.is_some() {
            return Err(InputError::new("output", "cannot be used with evaluate"));
        }
        Ok(())
    }
}

/// How a fit ended, for the report's first line.
pub(super) fn status(f: &Fit, evaluated: bool) -> &'static str {
    if evaluated {
        "evaluated, not fitted"
    } else if f.converged {
        "converged"
    } else {
        "NOT converged"
    }
}
