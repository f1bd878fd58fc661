//! The accuracy–cost study behind `carry bench accuracy` (report in docs/accuracy.md).
//!
//! * **Reference**: every shot in `f64` with the full 15×15 impact solver and
//!   Dormand–Prince at a tolerance of 1e-12, checked against the golden files.
//! * **Axes**: precision (f64, f32) × impact solver (reduced 3×3, full 15×15) × integrator
//!   (Euler, RK4, DP45) × step or tolerance (6–10 values each).
//! * **Shots**: the fixed set of [`shots`] (golden launches, golden deliveries and our own).
//! * **Errors**: carry, side, apex, flight time, landing angle (worst and median over the
//!   set); for the impact, ball speed, launch angle, spin and spin axis.
//! * **Cost**: force evaluations per shot (exact, deterministic) and host time per shot
//!   (a median of repeated in-process timings on one core: noisy). MCU instruction counts
//!   come from the firmware harness (docs/firmware.md).
//!
//! Prints a table (or `--json`), optionally an SVG of error against cost with the Pareto
//! front of each precision (`--svg`). `--quick` runs a reduced sweep on 8 shots.

mod assemble;
mod chart;
mod conclusions;
mod measure;
mod numbers;
mod pareto;
mod reference;
mod report;
mod scaling;
mod shots;
mod sweep;
mod table;

use measure::{Prec, SolverKind};
use report::Study;
use std::fmt::Write as _;
use std::path::PathBuf;

/// Options of the accuracy study.
#[derive(Debug, Clone, Default)]
pub struct StudyOptions {
    /// Print JSON instead of a table.
    pub json: bool,
    /// Also write an SVG chart here.
    pub svg: Option<PathBuf>,
    /// A quick, smaller study.
    pub quick: bool,
    /// The aerodynamic model of every shot but the golden flights (which keep the seed's).
    pub aero: carry_core::aero::AeroModel<f64>,
}

/// The "default fidelity" target: carry within 1 cm of the reference on every shot.
pub const CARRY_TARGET_M: f64 = 0.01;

/// Runs the accuracy study and renders it: a table, or JSON with `options.json`; writes
/// the SVG chart when asked. The caller prints the returned text.
///
/// # Errors
/// A failing reference (a bug), or failing to write the SVG.
pub fn run(options: &StudyOptions) -> Result<String, String> {
    let study = assemble::build(options.quick, &options.aero)?;
    if let Some(path) = &options.svg {
        chart::draw(path, &chart_points(&study))
            .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    Ok(if options.json {
        let mut s = serde_json::to_string_pretty(&study).map_err(|e| e.to_string())?;
        s.push('\n');
        s
    } else {
        let mut s = table::render(&study);
        if let Some(path) = &options.svg {
            let _ = writeln!(s, "\nwrote {}", path.display());
        }
        s
    })
}

/// The chart's points: every setting that succeeded on every shot.
fn chart_points(s: &Study) -> Vec<chart::Point> {
    s.flight
        .iter()
        .filter(|r| r.failures == 0)
        .map(|r| chart::Point {
            f32: r.setting.precision == Prec::F32,
            method: r.setting.integrator,
            full_solver: r.setting.solver != SolverKind::Reduced,
            is_default: r.setting.is_default,
            us: r.us_per_shot,
            evals: r.evals_mean,
            error_m: r.errors.carry_m.worst,
            pareto_time: r.pareto_time,
            pareto_evals: r.pareto_evals,
        })
        .collect()
}
