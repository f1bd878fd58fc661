//! Runs the whole study and assembles its report.

use super::measure::{self, Budget};
use super::report::{ReferenceShot, ShotInfo, Study};
use super::{conclusions, pareto, reference, scaling, shots, sweep};
use carry_core::aero::AeroModel;

/// Runs the study: the reference and its check, the sweep, the scaling, the conclusions.
///
/// # Errors
/// A failing reference (a bug) or scaling launch.
pub fn build(quick: bool, aero: &AeroModel<f64>) -> Result<Study, String> {
    let shots = shots::shot_set(quick, aero)?;
    let p64 = measure::prepare_all::<f64>(&shots)?;
    let p32 = measure::prepare_all::<f32>(&shots)?;
    let budget = if quick {
        Budget {
            samples: 1,
            sample_s: 2e-4,
        }
    } else {
        // Short repeats, many of them: on a loaded machine most short repeats run
        // uninterrupted, and the median ignores the ones that did not.
        Budget {
            samples: 21,
            sample_s: 5e-4,
        }
    };
    let reference = reference::results(&shots, &p64)?;
    let check = reference::check(&shots, &reference);
    let impact = sweep::impact(&p64, &p32, &reference, budget);
    let mut rows = sweep::flight(quick, &shots, &p64, &p32, &reference, budget);
    pareto::mark(&mut rows);

    let scaling = scaling::measure(quick, &p64, budget, aero)?;
    let mut study = Study {
        quick,
        timing: format!(
            "host µs: median of {} in-process repeats of ≥{} ms on one core (5 for settings \
             slower than 10× that; noisy on a shared machine); force evaluations: exact",
            budget.samples,
            budget.sample_s * 1e3
        ),
        shots: shots
            .iter()
            .zip(&reference)
            .map(|(s, r)| ShotInfo {
                name: s.name.clone(),
                class: s.class,
                origin: s.origin,
                start: s.describe_start(),
                scene: s.scene.describe(),
                reference: ReferenceShot {
                    carry_m: r.carry_m,
                    side_m: r.side_m,
                    apex_m: r.apex_m,
                    flight_time_s: r.flight_time_s,
                    land_angle_deg: r.land_angle_deg,
                    force_evaluations: r.evals,
                    launch: r.launch,
                },
            })
            .collect(),
        reference: check,
        impact,
        flight: rows,
        scaling,
        conclusions: Vec::new(),
    };
    study.conclusions = conclusions::derive(&study);
    Ok(study)
}
