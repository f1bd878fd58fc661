//! The rows of one call, computed in parallel (rayon, all cores) into columns.

use crate::args::{Request, check_value};
use carry_core::lanes::LaneReal;
use carry_io::compute::{self, Precision};
use carry_io::error::InputError;
use carry_io::params::Params;
use carry_io::report::{csv_columns, csv_values};
use rayon::prelude::*;

/// Rows per parallel work item.
const BLOCK: usize = 256;

/// The results of one call.
#[derive(Debug, Clone)]
pub struct Output {
    /// Column names (the CLI's batch CSV columns).
    pub names: Vec<&'static str>,
    /// The values, row-major: row `i`, column `j` at `i * names.len() + j`; NaN in failed
    /// rows.
    pub data: Vec<f64>,
    /// The failed rows: index and message (`club_speed: must be positive`).
    pub failed: Vec<(usize, String)>,
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

/// Computes the rows from `first` into `out` (row-major, `width` values a row) in
/// precision `T`; returns the failed rows.
fn block<T: LaneReal>(
    req: &Request,
    columns: &[&[f64]],
    first: usize,
    out: &mut [f64],
    width: usize,
) -> Vec<(usize, String)> {
    let mut failed = Vec::new();
    let mut row = Vec::with_capacity(width);
    let rows = out.len() / width.max(1);
    // The block's rows together: the flights in the core's lanes kernel where it covers
    // them (issue 37); a row whose scene cannot be shared is prepared on its own.
    let parsed: Vec<Result<Params, InputError>> = (first..first + rows)
        .map(|i| params(req, columns, i))
        .collect();
    let good: Vec<Params> = parsed
        .iter()
        .filter_map(|p| p.as_ref().ok().copied())
        .collect();
    let mut reports = compute::run_rows_in::<T>(req.mode, &good, &req.numerics).into_iter();
    for (k, (slot, p)) in out.chunks_exact_mut(width).zip(parsed).enumerate() {
        let i = first + k;
        let result = p.and_then(|_| {
            reports
                .next()
                .unwrap_or_else(|| Err(InputError::new("input", "row not computed")))
        });
        match result {
            Ok(r) => {
                row.clear();
                csv_values(&mut row, req.mode, req.ground, &r);
                slot.copy_from_slice(&row);
            }
            Err(e) => {
                slot.fill(f64::NAN);
                failed.push((i, e.as_column()));
            }
        }
    }
    failed
}

/// Runs `req` over `rows` rows; `columns[j]` holds the values of `req.keys[j]`, each of
/// length `rows`. Blocks of rows run in parallel, each writing its part of the output.
#[must_use]
pub fn run(req: &Request, columns: &[&[f64]], rows: usize) -> Output {
    match req.numerics.precision {
        Precision::F32 => run_in::<f32>(req, columns, rows),
        Precision::F64 => run_in::<f64>(req, columns, rows),
    }
}

fn run_in<T: LaneReal>(req: &Request, columns: &[&[f64]], rows: usize) -> Output {
    let names = csv_columns(req.mode, req.ground);
    let width = names.len();
    let mut data = vec![0.0; rows * width];
    let failed = data
        .par_chunks_mut(BLOCK * width)
        .enumerate()
        .flat_map_iter(|(b, out)| block::<T>(req, columns, b * BLOCK, out, width))
        .collect();
    Output {
        names,
        data,
        failed,
    }
}
