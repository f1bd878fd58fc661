//! The rows of one call, computed in parallel (rayon, all cores) into columns.

use crate::args::{Request, check_value};
use carry_core::{PreparedScene, Real};
use carry_io::compute::{self, Mode, Precision};
use carry_io::error::InputError;
use carry_io::params::{Key, Params};
use carry_io::report::{csv_columns, csv_values};
use carry_io::scene::SCENE_KEYS;
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
/// precision `T`, flying through `scene` if given; returns the failed rows.
fn block<T: Real>(
    req: &Request,
    columns: &[&[f64]],
    scene: Option<&PreparedScene<T>>,
    first: usize,
    out: &mut [f64],
    width: usize,
) -> Vec<(usize, String)> {
    let mut failed = Vec::new();
    let mut row = Vec::with_capacity(width);
    for (k, slot) in out.chunks_exact_mut(width).enumerate() {
        let i = first + k;
        let result = params(req, columns, i)
            .and_then(|p| compute::run_in_scene::<T>(req.mode, &p, &req.numerics, scene, None));
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

/// Whether every row flies through the same scene with the same ball: then the scene is
/// prepared once for the call instead of once a row.
fn shared_scene(req: &Request) -> bool {
    req.mode != Mode::Impact
        && !req
            .keys
            .iter()
            .any(|k| SCENE_KEYS.contains(k) || matches!(k, Key::BallMass | Key::BallRadius))
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

fn run_in<T: Real>(req: &Request, columns: &[&[f64]], rows: usize) -> Output {
    let names = csv_columns(req.mode, req.ground);
    let width = names.len();
    // A scene that fails to prepare is left to each row, which reports it in order.
    let scene = shared_scene(req)
        .then(|| compute::prepared_scene::<T>(&req.base).ok())
        .flatten();
    let mut data = vec![0.0; rows * width];
    let failed = data
        .par_chunks_mut(BLOCK * width)
        .enumerate()
        .flat_map_iter(|(b, out)| block(req, columns, scene.as_ref(), b * BLOCK, out, width))
        .collect();
    Output {
        names,
        data,
        failed,
    }
}
