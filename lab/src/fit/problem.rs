//! What a fit needs to know about a model family and its measurements.

/// A model family to fit to measured rows: its parameters with physical bounds, the
/// measured quantities of a row, and the model's prediction of them.
///
/// The fit minimises `Σ_rows w_row · Σ_q ((predicted_q − observed_q)/σ_q)²` over the
/// quantities a row has observed; rows with no observation of a quantity skip it.
pub trait Problem: Sync {
    /// One measured row.
    type Row: Sync + Clone;
    /// Parameter names, in order (snake_case, as in the model file).
    fn parameter_names(&self) -> Vec<&'static str>;
    /// Physical bounds `(lower, upper)` per parameter, `lower < upper`: the fit never
    /// leaves them.
    fn bounds(&self) -> Vec<(f64, f64)>;
    /// The starting point, inside the bounds.
    fn initial(&self) -> Vec<f64>;
    /// Names of the predicted quantities (e.g. `carry`, `apex`, `land_angle`).
    fn quantity_names(&self) -> Vec<&'static str>;
    /// The observed value of each quantity in `row` (`None`: not measured).
    fn observed(&self, row: &Self::Row) -> Vec<Option<f64>>;
    /// The residual scale σ of each quantity in `row` (same units as the quantity).
    fn sigma(&self, row: &Self::Row) -> Vec<f64>;
    /// A short label for the row in reports (e.g. `PGA 7iron`).
    fn label(&self, _row: &Self::Row) -> String {
        String::new()
    }
    /// The row's cross-validation group: rows of a group are held out together (a session
    /// of single shots); `None`: the row is held out alone.
    fn group(&self, _row: &Self::Row) -> Option<usize> {
        None
    }
    /// The row's weight (1 unless the input says otherwise), positive.
    fn weight(&self, _row: &Self::Row) -> f64 {
        1.0
    }
    /// The model's prediction of every quantity for `row` with parameters `p`.
    ///
    /// # Errors
    /// A message when the model cannot produce the row (e.g. the ball never lands).
    fn predict(&self, p: &[f64], row: &Self::Row) -> Result<Vec<f64>, String>;
}
