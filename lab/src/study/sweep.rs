//! The sweep: every precision × impact solver on the deliveries, and every setting of the
//! study over the whole set, each measured against the reference.

use super::CARRY_TARGET_M;
use super::measure::{self, Budget, Prec, ShotResult, SolverKind};
use super::report::{ImpactRow, Row};
use super::shots::{Prepared, Shot};

/// Impact: precision × solver (and pivoting) on the delivery shots.
pub fn impact(
    p64: &[Prepared<f64>],
    p32: &[Prepared<f32>],
    reference: &[ShotResult],
    budget: Budget,
) -> Vec<ImpactRow> {
    let ref_launches: Vec<[f64; 4]> = reference.iter().filter_map(|r| r.launch).collect();
    let mut impact = Vec::new();
    for precision in [Prec::F64, Prec::F32] {
        for solver in [
            SolverKind::Reduced,
            SolverKind::Full,
            SolverKind::FullPartial,
            SolverKind::FullNoPivoting,
        ] {
            let (launches, us) = match precision {
                Prec::F64 => (
                    measure::impact_launches(p64, solver.solver()),
                    measure::time_impact(p64, solver.solver(), budget),
                ),
                Prec::F32 => (
                    measure::impact_launches(p32, solver.solver()),
                    measure::time_impact(p32, solver.solver(), budget),
                ),
            };
            let (ok, reference): (Vec<[f64; 4]>, Vec<[f64; 4]>) = launches
                .iter()
                .zip(&ref_launches)
                .filter_map(|(l, r)| l.as_ref().ok().map(|l| (*l, *r)))
                .unzip();
            impact.push(ImpactRow {
                precision,
                solver,
                failures: launches.len() - ok.len(),
                errors: measure::launch_errors(&ok, &reference),
                us_per_impact: us,
            });
        }
    }
    impact
}

/// Flight and full shot: every setting over the whole set (Pareto marks not yet set).
pub fn flight(
    quick: bool,
    shots: &[Shot],
    p64: &[Prepared<f64>],
    p32: &[Prepared<f32>],
    reference: &[ShotResult],
    budget: Budget,
) -> Vec<Row> {
    measure::settings(quick)
        .into_iter()
        .map(|setting| {
            let (results, us) = match setting.precision {
                Prec::F64 => (
                    measure::results(p64, &setting),
                    measure::time_setting(p64, &setting, budget),
                ),
                Prec::F32 => (
                    measure::results(p32, &setting),
                    measure::time_setting(p32, &setting, budget),
                ),
            };
            let evals: Vec<u32> = results
                .iter()
                .filter_map(|r| r.as_ref().ok().map(|r| r.evals))
                .collect();
            let failures = results.len() - evals.len();
            let errors = measure::flight_errors(&results, reference);
            let worst_carry_shot = results
                .iter()
                .zip(reference)
                .zip(shots)
                .filter_map(|((r, x), s)| {
                    r.as_ref()
                        .ok()
                        .map(|r| ((r.carry_m - x.carry_m).abs(), &s.name))
                })
                .max_by(|a, b| a.0.total_cmp(&b.0))
                .map(|(_, n)| n.clone())
                .unwrap_or_default();
            #[allow(clippy::cast_precision_loss)]
            let evals_mean =
                evals.iter().map(|&e| f64::from(e)).sum::<f64>() / evals.len().max(1) as f64;
            Row {
                label: setting.label(),
                setting,
                evals_mean,
                evals_max: evals.iter().copied().max().unwrap_or(0),
                us_per_shot: us,
                failures,
                within_1cm: failures == 0 && errors.carry_m.worst <= CARRY_TARGET_M,
                errors,
                worst_carry_shot,
                pareto_time: false,
                pareto_evals: false,
            }
        })
        .collect()
}
