//! The reference (f64, full 15×15 impact solver, Dormand–Prince at 1e-12) and its check
//! against the golden files.

use super::measure::{self, Method, Prec, Setting, ShotResult, SolverKind};
use super::report::{ReferenceCheck, Worst4, Worst5};
use super::shots::{Golden, Prepared, Shot};

/// Reference tolerance of the adaptive integrator.
const REFERENCE_TOLERANCE: f64 = 1e-12;

/// Every shot of the set with the reference setting.
///
/// # Errors
/// A shot the reference fails on (a bug).
pub fn results(shots: &[Shot], p64: &[Prepared<f64>]) -> Result<Vec<ShotResult>, String> {
    // The reference: f64, full solver, DP45 at 1e-12.
    let reference_setting = Setting {
        precision: Prec::F64,
        solver: SolverKind::Full,
        integrator: Method::Dp45,
        param: REFERENCE_TOLERANCE,
        is_default: false,
    };
    measure::results(p64, &reference_setting)
        .into_iter()
        .zip(shots)
        .map(|(r, s)| r.map_err(|e| format!("reference failed on {}: {e}", s.name)))
        .collect()
}

/// Bounds of the reference check: the golden files were computed by an independent f64
/// implementation (8th-order integrator at 1e-12); their apex is a sampled maximum.
const CHECK_POSITION_M: f64 = 1e-6;
const CHECK_APEX_M: f64 = 1e-4;
const CHECK_TIME_S: f64 = 1e-6;
const CHECK_ANGLE_DEG: f64 = 1e-6;
const CHECK_IMPACT_REL: f64 = 1e-9;

/// Worst |reference − golden| over the golden flight and impact cases, and whether all are
/// within the bounds above.
pub fn check(shots: &[Shot], reference: &[ShotResult]) -> ReferenceCheck {
    let mut flight = Worst5::default();
    let mut impact = Worst4::default();
    let (mut nf, mut ni) = (0, 0);
    let mut passed = true;
    for (s, r) in shots.iter().zip(reference) {
        match s.golden {
            Some(Golden::Flight {
                carry_m,
                side_m,
                apex_m,
                flight_time_s,
                land_angle_deg,
            }) => {
                nf += 1;
                flight.carry_m = flight.carry_m.max((r.carry_m - carry_m).abs());
                flight.side_m = flight.side_m.max((r.side_m - side_m).abs());
                flight.apex_m = flight.apex_m.max((r.apex_m - apex_m).abs());
                flight.flight_time_s = flight
                    .flight_time_s
                    .max((r.flight_time_s - flight_time_s).abs());
                flight.land_angle_deg = flight
                    .land_angle_deg
                    .max((r.land_angle_deg - land_angle_deg).abs());
            }
            Some(Golden::Impact {
                ball_speed_mps,
                launch_angle_deg,
                spin_rpm,
                spin_axis_deg,
            }) => {
                ni += 1;
                let Some([v, a, w, x]) = r.launch else {
                    passed = false;
                    continue;
                };
                impact.ball_speed_mps = impact.ball_speed_mps.max((v - ball_speed_mps).abs());
                impact.launch_angle_deg = impact.launch_angle_deg.max((a - launch_angle_deg).abs());
                impact.spin_rpm = impact.spin_rpm.max((w - spin_rpm).abs());
                impact.spin_axis_deg = impact.spin_axis_deg.max((x - spin_axis_deg).abs());
                passed &= (v - ball_speed_mps).abs() <= CHECK_IMPACT_REL * ball_speed_mps.abs()
                    && (w - spin_rpm).abs() <= CHECK_IMPACT_REL * spin_rpm.abs().max(1.0)
                    && (a - launch_angle_deg).abs() <= CHECK_IMPACT_REL * 90.0
                    && (x - spin_axis_deg).abs() <= CHECK_IMPACT_REL * 90.0;
            }
            None => {}
        }
    }
    passed &= flight.carry_m <= CHECK_POSITION_M
        && flight.side_m <= CHECK_POSITION_M
        && flight.apex_m <= CHECK_APEX_M
        && flight.flight_time_s <= CHECK_TIME_S
        && flight.land_angle_deg <= CHECK_ANGLE_DEG;
    ReferenceCheck {
        description: "f64, full 15×15 impact solver (equilibrated partial pivoting), \
                      Dormand–Prince 5(4) at rtol = atol = 1e-12",
        flight_cases: nf,
        flight,
        impact_cases: ni,
        impact,
        passed,
    }
}
