//! Fitting model coefficients to measurements (`carry fit`): weighted nonlinear least
//! squares within physical bounds, a per-row residual table, and leave-one-out
//! cross-validation.
//!
//! A family implements [`Problem`]; [`fit`] solves it with Levenberg–Marquardt
//! ([`solve`]), tabulates every row, and refits once per left-out row
//! ([`FitOptions::leave_one_out`]) to measure how the model predicts data it was not
//! fitted to. [`flight`] holds the aerodynamic families, [`impact`] the compliant contact.

mod bounded;
pub mod flight;
pub mod impact;
mod problem;
mod report;
pub mod request;
pub mod request_contact;
pub mod single_drives;
mod solve;

pub use bounded::{to_bounded, to_unbounded};
pub use problem::Problem;
pub use report::{Fit, Parameter, QuantitySummary, RowResult};
pub use solve::{Solved, residuals, solve};

use rayon::prelude::*;

/// Options of [`fit`].
#[derive(Debug, Clone, Copy)]
pub struct FitOptions {
    /// Also refit once per row with that row left out.
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

/// Fits `problem` to `rows` and reports the residuals (and the leave-one-out errors).
/// `progress` is called once per finished solve (1 + the number of rows with
/// leave-one-out).
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
        Some(
            (0..rows.len())
                .into_par_iter()
                .map(|i| {
                    let rest: Vec<P::Row> = rows
                        .iter()
                        .enumerate()
                        .filter(|&(j, _)| j != i)
                        .map(|(_, r)| r.clone())
                        .collect();
                    let s = solve(problem, &rest, &solved.parameters)
                        .map_err(|e| format!("leave-one-out without row {}: {e}", i + 1))?;
                    progress();
                    problem.predict(&s.parameters, &rows[i])
                })
                .collect::<Result<_, String>>()?,
        )
    } else {
        None
    };
    Ok(report::tabulate(problem, rows, &solved, predicted, loo))
}
