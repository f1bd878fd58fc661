//! Fitting model coefficients to measurements (`carry fit`): weighted nonlinear least
//! squares within physical bounds, a per-row residual table, and leave-one-out
//! cross-validation.
//!
//! A family implements [`Problem`]; [`fit`] solves it with Levenberg–Marquardt
//! ([`solve`]), tabulates every row, and refits once per left-out row
//! ([`FitOptions::leave_one_out`]) to measure how the model predicts data it was not
//! fitted to. [`flight`] holds the aerodynamic families, [`impact`] the compliant contact.

mod bounded;
pub mod command;
pub mod flight;
pub mod impact;
pub mod joint_contact;
mod problem;
mod report;
pub mod request;
pub mod request_contact;
pub mod single_drives;
pub mod single_shots;
mod solve;
pub mod spin_target;
pub mod table_average;

pub use bounded::{to_bounded, to_unbounded};
pub use problem::Problem;
pub use report::{Fit, Parameter, QuantitySummary, RowResult};
pub use solve::{Solved, residuals, solve};

use rayon::prelude::*;

/// Options of [`fit`].
#[derive(Debug, Clone, Copy)]
pub struct FitOptions {
    /// Also refit once per row with that row left out (once per group for rows of a
    /// group, [`Problem::group`]).
    pub leave_one_out: bool,
}

impl Default for FitOptions {
    fn default() -> Self {
        Self {
            leave_one_out: true,
        }
    }
}

/// Tabulates `problem`'s errors on `rows` at fixed parameters `p` (no fitting): how a given
/// model does on the data.
///
/// # Errors
/// A row the model cannot predict.
pub fn evaluate<P: Problem>(problem: &P, rows: &[P::Row], p: &[f64]) -> Result<Fit, String> {
    let predicted: Vec<Vec<f64>> = rows
        .par_iter()
        .map(|r| problem.predict(p, r))
        .collect::<Result<_, _>>()?;
    let cost = residuals(problem, rows, p)?
        .iter()
        .map(|x| 0.5 * x * x)
        .sum();
    let solved = Solved {
        parameters: p.to_vec(),
        cost,
        row_evaluations: rows.len(),
        termination: "evaluated (not fitted)".into(),
        converged: true,
    };
    Ok(report::tabulate(problem, rows, &solved, predicted, None))
}

/// Fits `problem` to `rows` and reports the residuals (and the cross-validated errors:
/// each row predicted by a refit without it, or without its whole group, [`Problem::group`],
/// e.g. a session of single drives). `progress` is called once per finished solve (1 + one
/// per group and per row without a group).
///
/// # Errors
/// The errors of [`solve`]; a leave-one-out solve or prediction that fails.
pub fn fit<P: Problem>(
    problem: &P,
    rows: &[P::Row],
    options: FitOptions,
    progress: &(dyn Fn() + Sync),
) -> Result<Fit, String> {
    let solved = solve(problem, rows, &problem.initial())?;
    progress();
    let predicted: Vec<Vec<f64>> = rows
        .par_iter()
        .map(|r| problem.predict(&solved.parameters, r))
        .collect::<Result<_, _>>()?;
    let loo: Option<Vec<Vec<f64>>> = if options.leave_one_out && rows.len() > 1 {
        // What is held out together: a row's group (a session of single shots), or the row
        // alone.
        let key = |i: usize| problem.group(&rows[i]).ok_or(i);
        let mut units: Vec<Result<usize, usize>> = (0..rows.len()).map(key).collect();
        units.sort_unstable();
        units.dedup();
        let held: Vec<Vec<(usize, Vec<f64>)>> = units
            .into_par_iter()
            .map(|unit| {
                let rest: Vec<P::Row> = rows
                    .iter()
                    .enumerate()
                    .filter(|&(j, _)| key(j) != unit)
                    .map(|(_, r)| r.clone())
                    .collect();
                let what = match unit {
                    Ok(g) => format!("group {g}"),
                    Err(i) => format!("row {}", i + 1),
                };
                let s = solve(problem, &rest, &solved.parameters)
                    .map_err(|e| format!("cross-validation without {what}: {e}"))?;
                progress();
                let out = (0..rows.len())
                    .filter(|&j| key(j) == unit)
                    .map(|j| Ok((j, problem.predict(&s.parameters, &rows[j])?)))
                    .collect::<Result<Vec<_>, String>>()?;
                Ok(out)
            })
            .collect::<Result<_, String>>()?;
        let mut out = vec![Vec::new(); rows.len()];
        for (j, p) in held.into_iter().flatten() {
            out[j] = p;
        }
        Some(out)
    } else {
        None
    };
    Ok(report::tabulate(problem, rows, &solved, predicted, loo))
}
