//! The result of a fit: coefficients, per-row residuals, summaries.

use super::problem::Problem;
use super::solve::Solved;
use serde::Serialize;

/// One fitted parameter.
#[derive(Debug, Clone, Serialize)]
pub struct Parameter {
    /// Its name (as in the model file).
    pub name: &'static str,
    /// The fitted value.
    pub value: f64,
    /// Where the fit started.
    pub initial: f64,
    /// The physical bounds.
    pub lower: f64,
    /// The physical bounds.
    pub upper: f64,
}

/// One row: what was observed and what the fitted model (and, with leave-one-out, the
/// model fitted without this row) predicts, per quantity.
#[derive(Debug, Clone, Serialize)]
pub struct RowResult {
    /// 1-based row number of the input.
    pub row: usize,
    /// The row's label.
    pub label: String,
    /// Observed values (`null`: not measured).
    pub observed: Vec<Option<f64>>,
    /// The fitted model's predictions.
    pub predicted: Vec<f64>,
    /// The leave-one-out predictions.
    pub loo_predicted: Option<Vec<f64>>,
}

/// Error statistics of one quantity over the rows that observed it.
#[derive(Debug, Clone, Copy, Default, Serialize)]
pub struct QuantitySummary {
    /// Rows with an observation.
    pub rows: usize,
    /// Mean |predicted − observed|.
    pub mean_abs: f64,
    /// Max |predicted − observed|.
    pub max_abs: f64,
    /// Mean |predicted − observed| / |observed| (%).
    pub mean_abs_pct: f64,
    /// Max |predicted − observed| / |observed| (%).
    pub max_abs_pct: f64,
    /// Mean predicted − observed (the bias).
    pub mean: f64,
}

impl QuantitySummary {
    fn of(pairs: impl Iterator<Item = (f64, f64)>) -> Self {
        let mut s = Self::default();
        for (pred, obs) in pairs {
            let e = pred - obs;
            let pct = 100.0 * e.abs() / obs.abs();
            s.rows += 1;
            s.mean_abs += e.abs();
            s.mean += e;
            s.max_abs = s.max_abs.max(e.abs());
            s.mean_abs_pct += pct;
            s.max_abs_pct = s.max_abs_pct.max(pct);
        }
        if s.rows > 0 {
            #[allow(clippy::cast_precision_loss)]
            let n = s.rows as f64;
            s.mean_abs /= n;
            s.mean /= n;
            s.mean_abs_pct /= n;
        }
        s
    }
}

/// A finished fit.
#[derive(Debug, Clone, Serialize)]
pub struct Fit {
    /// The fitted parameters.
    pub parameters: Vec<Parameter>,
    /// Names of the quantities in the row tables and summaries.
    pub quantities: Vec<&'static str>,
    /// Every row.
    pub rows: Vec<RowResult>,
    /// Per quantity, the fitted model's errors.
    pub summary: Vec<QuantitySummary>,
    /// Per quantity, the leave-one-out errors.
    pub loo_summary: Option<Vec<QuantitySummary>>,
    /// `½·Σ r²` of the weighted, scaled residuals at the optimum.
    pub cost: f64,
    /// Model row evaluations of the main fit.
    pub row_evaluations: usize,
    /// Why the optimiser stopped.
    pub termination: String,
    /// Whether it converged.
    pub converged: bool,
}

impl Fit {
    /// The fitted values, in parameter order.
    #[must_use]
    pub fn values(&self) -> Vec<f64> {
        self.parameters.iter().map(|p| p.value).collect()
    }

    /// The summary of quantity `name` (`None` if the family has no such quantity).
    #[must_use]
    pub fn summary_of(&self, name: &str) -> Option<&QuantitySummary> {
        let i = self.quantities.iter().position(|q| *q == name)?;
        self.summary.get(i)
    }

    /// The summaries of the rows `keep` selects, per quantity: fitted, and held out when
    /// the fit was cross-validated.
    #[must_use]
    pub fn summaries_of_rows(
        &self,
        keep: impl Fn(&RowResult) -> bool,
    ) -> (Vec<QuantitySummary>, Option<Vec<QuantitySummary>>) {
        let rows: Vec<&RowResult> = self.rows.iter().filter(|r| keep(r)).collect();
        let of = |i: usize, loo: bool| {
            QuantitySummary::of(rows.iter().filter_map(|r| {
                let obs = r.observed.get(i).copied().flatten()?;
                let pred = if loo {
                    r.loo_predicted.as_ref()?.get(i).copied()?
                } else {
                    r.predicted.get(i).copied()?
                };
                Some((pred, obs))
            }))
        };
        let n = self.quantities.len();
        (
            (0..n).map(|i| of(i, false)).collect(),
            self.loo_summary
                .as_ref()
                .map(|_| (0..n).map(|i| of(i, true)).collect()),
        )
    }

    /// The leave-one-out summary of quantity `name`.
    #[must_use]
    pub fn loo_summary_of(&self, name: &str) -> Option<&QuantitySummary> {
        let i = self.quantities.iter().position(|q| *q == name)?;
        self.loo_summary.as_ref()?.get(i)
    }
}

pub(super) fn tabulate<P: Problem>(
    problem: &P,
    rows: &[P::Row],
    solved: &Solved,
    predicted: Vec<Vec<f64>>,
    loo: Option<Vec<Vec<f64>>>,
) -> Fit {
    let bounds = problem.bounds();
    let parameters = problem
        .parameter_names()
        .into_iter()
        .zip(problem.initial())
        .zip(bounds)
        .zip(&solved.parameters)
        .map(|(((name, initial), (lower, upper)), &value)| Parameter {
            name,
            value,
            initial,
            lower,
            upper,
        })
        .collect();
    let quantities = problem.quantity_names();
    let mut loo = loo.map(IntoIterator::into_iter);
    let table: Vec<RowResult> = rows
        .iter()
        .zip(predicted)
        .enumerate()
        .map(|(i, (row, predicted))| RowResult {
            row: i + 1,
            label: problem.label(row),
            observed: problem.observed(row),
            predicted,
            loo_predicted: loo.as_mut().and_then(Iterator::next),
        })
        .collect();
    let summarise = |pick: &dyn Fn(&RowResult) -> Option<&Vec<f64>>| -> Vec<QuantitySummary> {
        (0..quantities.len())
            .map(|q| {
                QuantitySummary::of(table.iter().filter_map(|r| {
                    let obs = r.observed.get(q).copied().flatten()?;
                    Some((*pick(r)?.get(q)?, obs))
                }))
            })
            .collect()
    };
    let summary = summarise(&|r| Some(&r.predicted));
    let loo_summary = table
        .first()
        .is_some_and(|r| r.loo_predicted.is_some())
        .then(|| summarise(&|r| r.loo_predicted.as_ref()));
    Fit {
        parameters,
        quantities,
        rows: table,
        summary,
        loo_summary,
        cost: solved.cost,
        row_evaluations: solved.row_evaluations,
        termination: solved.termination.clone(),
        converged: solved.converged,
    }
}
