//! `carry._carry`: the native half of the Python package `carry` (PyO3, rust-numpy).
//!
//! The Python layer (`carry/__init__.py`) checks and broadcasts the keyword arguments and
//! passes flat `float64` columns here; [`run`] resolves the options with the CLI's own
//! option table ([`args`]), computes every row in parallel with the GIL released
//! ([`rows`]) into one (rows × columns) array whose columns are the CLI batch CSV's.
//! [`fit_csv`] is `carry fit --json`; [`analysis`] runs `carry optimize`, `sweep`,
//! `dispersion` and `normalize` with `--json`.

mod args;
mod fit;
mod rows;

use carry_cli::compute::Mode;
use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use std::path::PathBuf;

fn mode_of(name: &str) -> PyResult<Mode> {
    match name {
        "impact" => Ok(Mode::Impact),
        "flight" => Ok(Mode::Flight),
        "shot" => Ok(Mode::Shot),
        _ => Err(PyValueError::new_err(format!("mode: unknown '{name}'"))),
    }
}

/// The arguments of `mode` as (name, kind) pairs: kind is `number`, `radius`, `vector`,
/// `tensor`, `preset`, `contact`, `aero`, `bool`, `ground` or `setting`.
#[pyfunction]
fn inputs(mode: &str) -> PyResult<Vec<(&'static str, &'static str)>> {
    Ok(args::inputs(mode_of(mode)?))
}

/// Runs `mode` over the rows of `columns` (flat float64 arrays of one length, named by
/// `names`) with the shared `options` ((name, text) pairs). Returns (column names, a
/// float64 array of shape (rows, columns), list of (row index, message) of failed rows).
#[pyfunction]
#[pyo3(signature = (mode, names, columns, options, rows))]
fn run<'py>(
    py: Python<'py>,
    mode: &str,
    names: Vec<String>,
    columns: Vec<PyReadonlyArray1<'py, f64>>,
    options: Vec<(String, String)>,
    rows: usize,
) -> PyResult<Output<'py>> {
    let mode = mode_of(mode)?;
    let req =
        args::request(mode, &options, &names).map_err(|e| PyValueError::new_err(e.to_string()))?;
    let slices = columns
        .iter()
        .zip(&names)
        .map(|(c, name)| {
            let s = c
                .as_slice()
                .map_err(|_| PyValueError::new_err(format!("{name}: not a contiguous array")))?;
            if s.len() == rows {
                Ok(s)
            } else {
                Err(PyValueError::new_err(format!(
                    "{name}: {} values for {rows} rows",
                    s.len()
                )))
            }
        })
        .collect::<PyResult<Vec<&[f64]>>>()?;
    let out = py.detach(|| rows::run(&req, &slices, rows));
    let width = out.names.len();
    let data = PyArray1::from_vec(py, out.data).reshape([rows, width])?;
    Ok((out.names, data, out.failed))
}

/// What [`run`] returns: names, values (rows × columns), failed rows.
type Output<'py> = (
    Vec<&'static str>,
    Bound<'py, PyArray2<f64>>,
    Vec<(usize, String)>,
);

/// The output column names of `mode` (with the ground's when `ground`).
#[pyfunction]
fn columns(mode: &str, ground: bool) -> PyResult<Vec<&'static str>> {
    Ok(carry_cli::report::csv_columns(mode_of(mode)?, ground))
}

/// `carry fit --json` on the CSV file `input`; returns the JSON text.
#[pyfunction]
#[pyo3(signature = (input, family, evaluate=None, output=None, cross_validation=true,
    units=None, air_density=None, temperature=None, humidity=None, pressure=None,
    altitude=None))]
#[allow(clippy::too_many_arguments)]
fn fit_csv(
    py: Python<'_>,
    input: PathBuf,
    family: String,
    evaluate: Option<String>,
    output: Option<PathBuf>,
    cross_validation: bool,
    units: Option<String>,
    air_density: Option<f64>,
    temperature: Option<f64>,
    humidity: Option<f64>,
    pressure: Option<f64>,
    altitude: Option<f64>,
) -> PyResult<String> {
    let a = fit::FitArgs {
        input,
        family,
        evaluate,
        output,
        cross_validation,
        units,
        air_density,
        temperature,
        humidity,
        pressure,
        altitude,
    };
    py.detach(|| fit::run(&a)).map_err(|e| match e {
        fit::FitError::Input(m) => PyValueError::new_err(m),
        fit::FitError::Failed(m) => PyRuntimeError::new_err(m),
    })
}

/// One of the CLI's analyses (`optimize`, `sweep`, `dispersion`, `normalize`) from its
/// argument vector (program name first); returns what the command prints. Invalid input
/// raises `ValueError` with the CLI's one line (naming the option).
#[pyfunction]
fn analysis(py: Python<'_>, argv: Vec<String>) -> PyResult<String> {
    py.detach(|| carry_cli::analysis(argv))
        .map_err(|e| match e {
            carry_cli::AnalysisFailure::Input(m) => PyValueError::new_err(m),
            carry_cli::AnalysisFailure::Failed(m) => PyRuntimeError::new_err(m),
        })
}

/// The native module.
#[pymodule]
fn _carry(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(inputs, m)?)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(columns, m)?)?;
    m.add_function(wrap_pyfunction!(fit_csv, m)?)?;
    m.add_function(wrap_pyfunction!(analysis, m)?)?;
    m.add("ARG_SETTINGS", args::SETTINGS.to_vec())?;
    Ok(())
}
