//! The Pareto fronts of worst carry error against cost, per precision.

use super::measure::SolverKind;
use super::report::Row;

/// Marks each precision's Pareto fronts (rows that fail on any shot are excluded).
pub fn mark(rows: &mut [Row]) {
    let n = rows.len();
    for i in 0..n {
        let a = &rows[i];
        if a.failures > 0 {
            continue;
        }
        let dominated = |cost: &dyn Fn(&Row) -> f64, eligible: &dyn Fn(&Row) -> bool| {
            rows.iter().any(|b| {
                b.setting.precision == a.setting.precision
                    && b.failures == 0
                    && eligible(b)
                    && cost(b) <= cost(a)
                    && b.errors.carry_m.worst <= a.errors.carry_m.worst
                    && (cost(b) < cost(a) || b.errors.carry_m.worst < a.errors.carry_m.worst)
            })
        };
        let on_time = !dominated(&|r| r.us_per_shot, &|_| true);
        let reduced = |r: &Row| r.setting.solver == SolverKind::Reduced;
        let on_evals = reduced(a) && !dominated(&|r| r.evals_mean, &reduced);
        rows[i].pareto_time = on_time;
        rows[i].pareto_evals = on_evals;
    }
}
