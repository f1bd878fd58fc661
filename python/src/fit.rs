//! `carry.fit`: lab's typed fit request ([`carry_lab::fit::request`]) on a CSV file the
//! Python layer writes; the JSON document comes back as a value, not text.

use carry_io::choice::Choice;
use carry_io::error::Failure;
use carry_io::units::Units;
use carry_lab::fit::request::{FitRequest, document};
use std::path::PathBuf;

/// The options of a fit, as Python passes them.
#[derive(Debug, Clone, Default)]
pub struct FitArgs {
    /// The CSV file of measured shots.
    pub input: PathBuf,
    /// More files fitted jointly (`carry fit --also`).
    pub also: Vec<PathBuf>,
    /// Weight of every table row when single drives are in the fit (`--table-weight`).
    pub table_weight: Option<f64>,
    /// Model family (`modern`, `quintavalla`, `compliant`).
    pub family: String,
    /// Evaluate this model instead of fitting.
    pub evaluate: Option<String>,
    /// Write the fitted model here (TOML).
    pub output: Option<PathBuf>,
    /// Run the leave-one-out cross-validation.
    pub cross_validation: bool,
    /// Input units (`si`, `imperial`).
    pub units: Option<String>,
    /// Air density of rows without conditions (kg/m³).
    pub air_density: Option<f64>,
    /// Temperature of rows without conditions.
    pub temperature: Option<f64>,
    /// Relative humidity of rows without conditions (%).
    pub humidity: Option<f64>,
    /// Station pressure of rows without conditions (Pa).
    pub pressure: Option<f64>,
    /// Altitude of rows without conditions.
    pub altitude: Option<f64>,
}

/// Why a fit failed: bad input (`ValueError`) or the fit itself (`RuntimeError`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum FitError {
    /// A bad argument or input value: the argument and why.
    Input(String),
    /// The fit could not run or a file could not be written.
    Failed(String),
}

/// Runs the fit; returns the document `carry fit --json` prints.
///
/// # Errors
/// A [`FitError`].
pub fn run(args: &FitArgs) -> Result<serde_json::Value, FitError> {
    let units = match &args.units {
        Some(t) => Units::parse(t).map_err(|r| FitError::Input(format!("units: {r}")))?,
        None => Units::Si,
    };
    let request = FitRequest {
        input: args.input.clone(),
        also: args.also.clone(),
        family: args.family.clone(),
        output: args.output.clone(),
        evaluate: args.evaluate.clone(),
        no_cross_validation: !args.cross_validation,
        units,
        json: true,
        no_progress: true,
        air_density: args.air_density,
        temperature: args.temperature,
        humidity: args.humidity,
        pressure: args.pressure,
        altitude: args.altitude,
        table_weight: args.table_weight,
        bound: Vec::new(),
    };
    document(&request).map_err(|e| match e {
        Failure::Input(e) => FitError::Input(e.as_column()),
        Failure::Io(e) => FitError::Failed(e.to_string()),
        Failure::Other(m) => FitError::Failed(m),
    })
}
