//! Many shots given as columns of numbers over shared options (the Python package's calls,
//! issue 13; made cheap for issue 37): each column sets one key, every row shares the rest
//! (a base [`Params`]). The rows' results are written straight into a row-major array in
//! [`csv_columns`](crate::report::csv_columns) order, the values of the run row by row
//! ([`crate::compute::run`]) bit for bit (`io/tests/columns.rs` checks it).
//!
//! What a call does not vary costs nothing per row:
//! * rows whose columns are launch keys only ([`Key::is_launch`]) in a flight never build
//!   a [`Params`]: each row is the base's launch with its numbers, the ball and the scene
//!   are checked and prepared once for the block, and each flight's values go from the
//!   lanes kernel's callback into the output row;
//! * other rows build their [`Params`] once and run through
//!   [`compute::run_rows_sharing`], which compares no scenes when no column is a scene or
//!   ball key ([`Key::is_scene`]).
//!
//! This module uses [`crate::compute`] and [`crate::report`]; neither uses it.

use crate::compute::{self, Mode, Numerics};
use crate::error::InputError;
use crate::params::{Key, Params};
use crate::report::{Report, write_values};
use crate::units::{Quantity, Units};
use carry_core::lanes::{LaneReal, Shot};

/// Rows as columns over shared options.
#[derive(Debug, Clone, Copy)]
pub struct Columns<'a> {
    /// The options every row shares, in SI.
    pub base: &'a Params,
    /// The units of the columns' numbers.
    pub units: Units,
    /// The key each column sets (numbers: [`crate::params::Kind::Number`] or
    /// [`crate::params::Kind::Radius`]), in column order.
    pub keys: &'a [Key],
    /// The columns, one per key, each at least as long as the rows asked for.
    pub values: &'a [&'a [f64]],
}

impl Columns<'_> {
    /// The key of each column with its quantity (for units).
    fn keyed(&self) -> Vec<(Key, Quantity, &[f64])> {
        self.keys
            .iter()
            .zip(self.values)
            .map(|(k, v)| (*k, k.quantity(), *v))
            .collect()
    }

    /// The parameters of row `i`: the base with the row's numbers, checked as the text
    /// parser would ([`Key::check_number`]) and set as [`Key::set`] sets them.
    ///
    /// # Errors
    /// The first column (in order) whose number is not valid.
    pub fn params(&self, i: usize) -> Result<Params, InputError> {
        let mut p = *self.base;
        for (key, column) in self.keys.iter().zip(self.values) {
            let x = key.check_number(column[i])?;
            key.set(&mut p, self.units, crate::params::Value::Number(x));
        }
        Ok(p)
    }
}

/// Runs `mode` on rows `first..first + out.len() / width` of `cols` in precision `T`,
/// writing each row's values ([`write_values`], `width` of them: `csv_columns(mode,
/// ground)`) into `out` (row-major) and NaN into a failed row's; returns the failed rows
/// (index, error) in row order.
pub fn run_block<T: LaneReal>(
    mode: Mode,
    cols: &Columns<'_>,
    n: &Numerics,
    ground: bool,
    first: usize,
    out: &mut [f64],
    width: usize,
) -> Vec<(usize, InputError)> {
    if width == 0 {
        return Vec::new();
    }
    if mode == Mode::Flight
        && cols.keys.iter().all(|k| k.is_launch())
        && let Some(failed) = launches::<T>(cols, n, ground, first, out, width)
    {
        return failed;
    }
    rows::<T>(mode, cols, n, ground, first, out, width)
}

/// Flights whose rows vary the launch only; `None` when the base's ball or scene is
/// invalid (then [`rows`] reports each row's first error as the run would).
fn launches<T: LaneReal>(
    cols: &Columns<'_>,
    n: &Numerics,
    ground: bool,
    first: usize,
    out: &mut [f64],
    width: usize,
) -> Option<Vec<(usize, InputError)>> {
    let base = cols.base;
    compute::ball::<T>(base).ok()?;
    let scene = compute::prepared_scene::<T>(base).ok()?;
    let keyed = cols.keyed();
    let count = out.len() / width;
    let mut failed = Vec::new();
    let mut shots = Vec::with_capacity(count);
    let mut reports = Vec::with_capacity(count);
    let mut index = Vec::with_capacity(count);
    for k in 0..count {
        let i = first + k;
        let mut l = base.launch;
        let start = (|| {
            for (key, q, column) in &keyed {
                let x = key.check_number(column[i])?;
                key.set_launch(&mut l, cols.units.to_si(*q, x));
            }
            compute::launch_motion_of::<T>(&l)
        })();
        match start {
            Ok((motion, launch)) => {
                shots.push(Shot {
                    scene: &scene,
                    launch: motion,
                });
                reports.push(launch);
                index.push(k);
            }
            Err(e) => {
                out[k * width..(k + 1) * width].fill(f64::NAN);
                failed.push((i, e));
            }
        }
    }
    let integrator = n.integrator::<T>();
    let mut late = false;
    crate::lanes::fly_each(&shots, &integrator, |j, outcome| {
        let k = index[j];
        let slot = &mut out[k * width..(k + 1) * width];
        match outcome {
            Ok(o) => write_values(
                slot,
                Mode::Flight,
                ground,
                &Report {
                    launch: reports[j],
                    club_after: None,
                    impulse_ns: None,
                    flight: Some(compute::flight_report(&o)),
                },
            ),
            Err(e) => {
                slot.fill(f64::NAN);
                failed.push((
                    first + k,
                    compute::into_the_ground(e, &shots[j].launch, &scene),
                ));
                late = true;
            }
        }
    });
    if late {
        failed.sort_by_key(|(i, _)| *i);
    }
    Some(failed)
}

/// Any rows: each row's [`Params`] once, run by [`compute::run_rows_sharing`].
fn rows<T: LaneReal>(
    mode: Mode,
    cols: &Columns<'_>,
    n: &Numerics,
    ground: bool,
    first: usize,
    out: &mut [f64],
    width: usize,
) -> Vec<(usize, InputError)> {
    let count = out.len() / width;
    let mut failed = Vec::new();
    let mut good = Vec::with_capacity(count);
    let mut index = Vec::with_capacity(count);
    for k in 0..count {
        match cols.params(first + k) {
            Ok(p) => {
                good.push(p);
                index.push(k);
            }
            Err(e) => {
                out[k * width..(k + 1) * width].fill(f64::NAN);
                failed.push((first + k, e));
            }
        }
    }
    let one_scene = !cols.keys.iter().any(|k| k.is_scene());
    let reports = compute::run_rows_sharing::<T>(mode, &good, n, one_scene);
    let mut late = false;
    for (k, result) in index.into_iter().zip(reports) {
        let slot = &mut out[k * width..(k + 1) * width];
        match result {
            Ok(r) => write_values(slot, mode, ground, &r),
            Err(e) => {
                slot.fill(f64::NAN);
                failed.push((first + k, e));
                late = true;
            }
        }
    }
    if late {
        failed.sort_by_key(|(i, _)| *i);
    }
    failed
}
