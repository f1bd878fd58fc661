//! `carry._carry`: the native half of the Python package `carry` (PyO3, rust-numpy).
//!
//! The Python layer (`carry/__init__.py`) checks and broadcasts the keyword arguments and
//! passes flat `float64` columns here; [`run`] resolves the options with carry-io's option
//! table, the CLI's own ([`args`]), computes every row in parallel with the GIL released
//! ([`rows`]) into one (rows × columns) array whose columns are the CLI batch CSV's.
//! [`fit_csv`] is lab's typed fit request and [`analysis`] lab's typed analysis requests
//! (`optimize`, `sweep`, `dispersion`, `normalize`); both return the document the CLI's
//! `--json` prints, as Python objects. This crate depends on carry-core, carry-io and
//! carry-lab only: no command-line grammar.

mod analyses;
mod args;
mod estimate;
mod fit;
mod launch_fit;
mod rows;

use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use std::path::PathBuf;

fn target_of(name: &str) -> PyResult<args::Target> {
    args::Target::of(name).ok_or_else(|| PyValueError::new_err(format!("mode: unknown '{name}'")))
}

/// The arguments of `mode` (`impact`, `flight`, `shot` or `estimate`) as (name, kind)
/// pairs: kind is `number`, `radius`, `vector`, `tensor`, `preset`, `contact`, `aero`,
/// `bool`, `ground` or `setting`.
#[pyfunction]
fn inputs(mode: &str) -> PyResult<Vec<(&'static str, &'static str)>> {
    Ok(args::inputs(target_of(mode)?))
}

/// Runs `mode` (`impact`, `flight`, `shot` or `estimate`) over the rows of `columns` (flat float64 arrays of one length, named by
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
    let target = target_of(mode)?;
    let req = args::request(target, &options, &names)
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
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
    let out = match target {
        args::Target::Run(_) => py.detach(|| rows::run(&req, &slices, rows)),
        args::Target::Estimate => py
            .detach(|| estimate::run(&req, &options, &slices, rows))
            .map_err(|e| PyRuntimeError::new_err(format!("{e:?}")))?,
    };
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

/// The output column names of `mode` (with the ground's when `ground`; the estimator's
/// have none).
#[pyfunction]
fn columns(mode: &str, ground: bool) -> PyResult<Vec<&'static str>> {
    Ok(match target_of(mode)? {
        args::Target::Run(mode) => carry_io::report::csv_columns(mode, ground),
        args::Target::Estimate => carry_lab::request::EstimateRecord::COLUMNS.to_vec(),
    })
}

/// A JSON value as Python objects: dict, list, float or int, str, bool, None.
fn to_py<'py>(py: Python<'py>, v: &serde_json::Value) -> PyResult<Bound<'py, PyAny>> {
    use pyo3::types::{PyDict, PyList};
    use serde_json::Value;
    Ok(match v {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => b.into_pyobject(py)?.to_owned().into_any(),
        Value::Number(n) => match (n.as_u64(), n.as_i64()) {
            (Some(u), _) => u.into_pyobject(py)?.into_any(),
            (None, Some(i)) => i.into_pyobject(py)?.into_any(),
            _ => n.as_f64().unwrap_or(f64::NAN).into_pyobject(py)?.into_any(),
        },
        Value::String(s) => s.into_pyobject(py)?.into_any(),
        Value::Array(a) => {
            let items = a
                .iter()
                .map(|x| to_py(py, x))
                .collect::<PyResult<Vec<_>>>()?;
            PyList::new(py, items)?.into_any()
        }
        Value::Object(m) => {
            let d = PyDict::new(py);
            for (k, x) in m {
                d.set_item(k, to_py(py, x)?)?;
            }
            d.into_any()
        }
    })
}

/// `carry fit --json` on the CSV file `input`; returns the document.
#[pyfunction]
#[pyo3(signature = (input, family, evaluate=None, output=None, cross_validation=true,
    units=None, air_density=None, temperature=None, humidity=None, pressure=None,
    altitude=None, also=Vec::new(), table_weight=None))]
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
    also: Vec<PathBuf>,
    table_weight: Option<f64>,
) -> PyResult<Py<PyAny>> {
    let a = fit::FitArgs {
        input,
        also,
        table_weight,
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
    let doc = py.detach(|| fit::run(&a)).map_err(|e| match e {
        fit::FitError::Input(m) => PyValueError::new_err(m),
        fit::FitError::Failed(m) => PyRuntimeError::new_err(m),
    })?;
    Ok(to_py(py, &doc)?.unbind())
}

/// One of lab's analyses (`optimize`, `sweep`, `dispersion`, `normalize`) with `options`
/// ((name, text) pairs, flags as `true`); returns (the document `carry <command> --json`
/// prints, the notes of options it replaced). Invalid input raises `ValueError` with the
/// CLI's one line (naming the option).
#[pyfunction]
fn analysis(
    py: Python<'_>,
    command: String,
    options: Vec<(String, String)>,
) -> PyResult<(Py<PyAny>, Vec<String>)> {
    let (doc, notes) = py
        .detach(|| analyses::run(&command, &options))
        .map_err(|e| match e {
            analyses::AnalysisError::Input(m) => PyValueError::new_err(m),
            analyses::AnalysisError::Failed(m) => PyRuntimeError::new_err(m),
        })?;
    Ok((to_py(py, &doc)?.unbind(), notes))
}

fn slice<'a>(name: &str, a: &'a Option<PyReadonlyArray1<'_, f64>>) -> PyResult<Option<&'a [f64]>> {
    a.as_ref()
        .map(|a| {
            a.as_slice()
                .map_err(|_| PyValueError::new_err(format!("{name}: not a contiguous array")))
        })
        .transpose()
}

/// The launch from the flight (issue 36) with `options` ((name, text) pairs: the summaries,
/// the measured launch, their `_sd`, the scene; flags as `true`) and the track arrays `t`
/// with `x`, `y`, `z` or with `radial_speed`; returns the record `carry estimate --from
/// flight --json` prints. Invalid input or a fit the data do not determine raises
/// `ValueError` with the CLI's one line (naming the option).
#[pyfunction]
#[pyo3(signature = (options, t=None, x=None, y=None, z=None, radial_speed=None))]
#[allow(clippy::needless_pass_by_value)]
fn launch_from_flight(
    py: Python<'_>,
    options: Vec<(String, String)>,
    t: Option<PyReadonlyArray1<'_, f64>>,
    x: Option<PyReadonlyArray1<'_, f64>>,
    y: Option<PyReadonlyArray1<'_, f64>>,
    z: Option<PyReadonlyArray1<'_, f64>>,
    radial_speed: Option<PyReadonlyArray1<'_, f64>>,
) -> PyResult<Py<PyAny>> {
    let xyz = match (slice("x", &x)?, slice("y", &y)?, slice("z", &z)?) {
        (Some(x), Some(y), Some(z)) => Some([x, y, z]),
        (None, None, None) => None,
        _ => {
            return Err(PyValueError::new_err(
                "--x, --y, --z: give all three or none",
            ));
        }
    };
    let arrays = launch_fit::Arrays {
        t: slice("t", &t)?,
        xyz,
        radial_speed: slice("radial_speed", &radial_speed)?,
    };
    let doc = py
        .detach(|| launch_fit::run(&options, &arrays))
        .map_err(|e| match e {
            analyses::AnalysisError::Input(m) => PyValueError::new_err(m),
            analyses::AnalysisError::Failed(m) => PyRuntimeError::new_err(m),
        })?;
    Ok(to_py(py, &doc)?.unbind())
}

/// The native module.
#[pymodule]
fn _carry(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(inputs, m)?)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(columns, m)?)?;
    m.add_function(wrap_pyfunction!(fit_csv, m)?)?;
    m.add_function(wrap_pyfunction!(analysis, m)?)?;
    m.add_function(wrap_pyfunction!(launch_from_flight, m)?)?;
    m.add("ARG_SETTINGS", args::SETTINGS.to_vec())?;
    Ok(())
}
