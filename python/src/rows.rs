//! The rows of one call, computed in parallel (rayon, all cores) into columns.

use crate::args::Request;
use carry_core::lanes::LaneReal;
use carry_io::columns::{Columns, run_block};
use carry_io::compute::Precision;
use carry_io::report::csv_columns;
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

/// Computes the rows from `first` into `out` (row-major, `width` values a row) in
/// precision `T` (carry-io's [`run_block`]: the flights in the core's lanes kernel
/// where it covers them, issue 37); returns the failed rows.
fn block<T: LaneReal>(
    req: &Request,
    columns: &[&[f64]],
    first: usize,
    out: &mut [f64],
    width: usize,
) -> Vec<(usize, String)> {
    let cols = Columns {
        base: &req.base,
        units: req.units,
        keys: &req.keys,
        values: columns,
    };
    run_block::<T>(
        req.mode,
        &cols,
        &req.numerics,
        req.ground,
        first,
        out,
        width,
    )
    .into_iter()
    .map(|(i, e)| (i, e.as_column()))
    .collect()
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
