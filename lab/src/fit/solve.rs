//! Weighted nonlinear least squares with the Levenberg–Marquardt implementation of the
//! `levenberg-marquardt` crate (a port of MINPACK's `lmder`), in the bounded
//! parametrisation of [`super::bounded`], with a central-difference Jacobian computed in
//! parallel.

use super::bounded::{to_bounded, to_unbounded};
use super::problem::Problem;
use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt};
use nalgebra034::storage::Owned;
use nalgebra034::{DMatrix, DVector, Dyn};
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Central-difference step in the unbounded parameter `θ` (dimensionless, `θ = O(1)`).
const JACOBIAN_STEP: f64 = 1e-5;

/// The outcome of one least-squares solve.
#[derive(Debug, Clone)]
pub struct Solved {
    /// The fitted parameters (inside the bounds).
    pub parameters: Vec<f64>,
    /// `½·Σ r²` at the optimum (weighted, scaled residuals).
    pub cost: f64,
    /// Model evaluations (rows × trial points, including the Jacobian's).
    pub row_evaluations: usize,
    /// Why the optimiser stopped.
    pub termination: String,
    /// Whether it stopped at a minimum (not on an iteration limit or a failure).
    pub converged: bool,
}

/// The weighted, scaled residual vector of `rows` at parameters `p`.
///
/// # Errors
/// The first row the model cannot predict.
pub fn residuals<P: Problem>(problem: &P, rows: &[P::Row], p: &[f64]) -> Result<Vec<f64>, String> {
    let per_row: Vec<Vec<f64>> = rows
        .par_iter()
        .map(|row| {
            let predicted = problem.predict(p, row)?;
            let sqrt_w = problem.weight(row).sqrt();
            Ok(problem
                .observed(row)
                .into_iter()
                .zip(problem.sigma(row))
                .zip(predicted)
                .filter_map(|((obs, sigma), pred)| obs.map(|o| sqrt_w * (pred - o) / sigma))
                .collect())
        })
        .collect::<Result<_, String>>()?;
    Ok(per_row.concat())
}

struct Adapter<'a, P: Problem> {
    problem: &'a P,
    rows: &'a [P::Row],
    bounds: Vec<(f64, f64)>,
    theta: DVector<f64>,
    evaluations: AtomicUsize,
}

impl<P: Problem> Adapter<'_, P> {
    fn physical(&self, theta: &DVector<f64>) -> Vec<f64> {
        theta
            .iter()
            .zip(&self.bounds)
            .map(|(&t, &b)| to_bounded(t, b))
            .collect()
    }

    fn eval(&self, theta: &DVector<f64>) -> Option<Vec<f64>> {
        self.evaluations
            .fetch_add(self.rows.len(), Ordering::Relaxed);
        residuals(self.problem, self.rows, &self.physical(theta)).ok()
    }
}

impl<P: Problem> LeastSquaresProblem<f64, Dyn, Dyn> for Adapter<'_, P> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Dyn>;
    type ParameterStorage = Owned<f64, Dyn>;

    fn set_params(&mut self, x: &DVector<f64>) {
        self.theta.copy_from(x);
    }

    fn params(&self) -> DVector<f64> {
        self.theta.clone()
    }

    fn residuals(&self) -> Option<DVector<f64>> {
        self.eval(&self.theta).map(DVector::from_vec)
    }

    fn jacobian(&self) -> Option<DMatrix<f64>> {
        let columns: Vec<Vec<f64>> = (0..self.theta.len())
            .into_par_iter()
            .map(|j| {
                let (mut plus, mut minus) = (self.theta.clone(), self.theta.clone());
                plus[j] += JACOBIAN_STEP;
                minus[j] -= JACOBIAN_STEP;
                let (rp, rm) = (self.eval(&plus)?, self.eval(&minus)?);
                Some(
                    rp.iter()
                        .zip(&rm)
                        .map(|(a, b)| (a - b) / (2.0 * JACOBIAN_STEP))
                        .collect(),
                )
            })
            .collect::<Option<_>>()?;
        let m = columns.first().map_or(0, Vec::len);
        Some(DMatrix::from_fn(m, columns.len(), |i, j| columns[j][i]))
    }
}

/// Fits `problem` to `rows` from the starting point `start` (physical parameters).
///
/// # Errors
/// No rows, a model that cannot predict a row at the starting point, or an optimiser
/// failure before any step.
pub fn solve<P: Problem>(problem: &P, rows: &[P::Row], start: &[f64]) -> Result<Solved, String> {
    if rows.is_empty() {
        return Err("no rows to fit".into());
    }
    let bounds = problem.bounds();
    // Fail early, with the model's own message, if the start cannot be evaluated.
    let r0 = residuals(problem, rows, start)?;
    if r0.len() < start.len() {
        return Err(format!(
            "{} observations cannot determine {} parameters",
            r0.len(),
            start.len()
        ));
    }
    let theta = DVector::from_iterator(
        start.len(),
        start.iter().zip(&bounds).map(|(&p, &b)| to_unbounded(p, b)),
    );
    let adapter = Adapter {
        problem,
        rows,
        bounds,
        theta,
        evaluations: AtomicUsize::new(0),
    };
    let (adapter, report) = LevenbergMarquardt::new()
        .with_patience(200)
        .minimize(adapter);
    let parameters = adapter.physical(&adapter.theta);
    let cost = residuals(problem, rows, &parameters)
        .map(|r| 0.5 * r.iter().map(|x| x * x).sum::<f64>())
        .unwrap_or(f64::NAN);
    Ok(Solved {
        parameters,
        cost,
        row_evaluations: adapter.evaluations.load(Ordering::Relaxed),
        termination: format!("{:?}", report.termination),
        converged: report.termination.was_successful(),
    })
}
