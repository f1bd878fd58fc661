//! The rows of one call, computed in parallel (rayon, all cores) into columns.

use crate::args::{Request, check_value};
use carry_cli::compute;
use carry_cli::error::InputError;
use carry_cli::params::Params;
use carry_cli::report::{csv_columns, csv_values};
use rayon::prelude::*;

/// Rows per parallel work item.
const BLOCK: usize = 256;

/// The results: one vector per output column, and each row's error (if any).
#[derive(Debug, Clone)]
pub struct Output {
    /// Column names (the CLI's batch CSV columns).
    pub names: Vec<&'static str>,
    /// Column values, `names[j]` in `columns[j]`; NaN in failed rows.
    pub columns: Vec<Vec<f64>>,
    /// The message of each failed row (`club_speed: must be positive`), else `None`.
    pub errors: Vec<Option<String>>,
}

/// The parameters of row `i`: the shared options with the row's numbers.
fn params(req: &Request, columns: &[&[f64]], i: usize) -> Result<Params, InputError> {
    let mut p = req.base;
    for (key, column) in req.keys.iter().zip(columns) {
        let value = check_value(*key, column[i])?;
        key.set(&mut p, req.units, value);
    }
    Ok(p)
}

/// Computes rows `range` into a row-major block of `width` values per row.
fn block(
    req: &Request,
    columns: &[&[f64]],
    range: std::ops::Range<usize>,
    width: usize,
) -> (Vec<f64>, Vec<Option<String>>) {
    let mut values = Vec::with_capacity(range.len() * width);
    let mut errors = Vec::with_capacity(range.len());
    for i in range {
        let result =
            params(req, columns, i).and_then(|p| compute::run(req.mode, &p, &req.numerics));
        match result {
            Ok(r) => {
                csv_values(&mut values, req.mode, req.ground, &r);
                errors.push(None);
            }
            Err(e) => {
                values.resize(values.len() + width, f64::NAN);
                errors.push(Some(e.as_column()));
            }
        }
    }
    (values, errors)
}

/// Runs `req` over `rows` rows; `columns[j]` holds the values of `req.keys[j]`, each of
/// length `rows`.
#[must_use]
pub fn run(req: &Request, columns: &[&[f64]], rows: usize) -> Output {
    let names = csv_columns(req.mode, req.ground);
    let width = names.len();
    let blocks: Vec<(Vec<f64>, Vec<Option<String>>)> = (0..rows.div_ceil(BLOCK))
        .into_par_iter()
        .map(|b| block(req, columns, b * BLOCK..rows.min((b + 1) * BLOCK), width))
        .collect();
    let mut out: Vec<Vec<f64>> = (0..width).map(|_| Vec::with_capacity(rows)).collect();
    let mut errors = Vec::with_capacity(rows);
    for (values, errs) in blocks {
        for row in values.chunks_exact(width) {
            for (column, x) in out.iter_mut().zip(row) {
                column.push(*x);
            }
        }
        errors.extend(errs);
    }
    Output {
        names,
        columns: out,
        errors,
    }
}
