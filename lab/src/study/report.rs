//! The study's report: what `--json` serialises, and what the table, the conclusions and
//! the chart read.

use super::measure::{FlightErrors, LaunchErrors, Prec, Setting, SolverKind};
use super::shots::Origin;
use serde::Serialize;

/// One shot of the set, as reported.
#[derive(Debug, Clone, Serialize)]
pub struct ShotInfo {
    pub name: String,
    pub class: &'static str,
    pub origin: Origin,
    pub start: String,
    pub scene: String,
    /// The reference's results.
    pub reference: ReferenceShot,
}

#[derive(Debug, Clone, Copy, Serialize)]
pub struct ReferenceShot {
    pub carry_m: f64,
    pub side_m: f64,
    pub apex_m: f64,
    pub flight_time_s: f64,
    pub land_angle_deg: f64,
    pub force_evaluations: u32,
    /// Ball speed (m/s), launch angle (deg), spin (rpm), spin axis (deg): deliveries only.
    pub launch: Option<[f64; 4]>,
}

/// The reference against the golden files.
#[derive(Debug, Clone, Serialize)]
pub struct ReferenceCheck {
    pub description: &'static str,
    pub flight_cases: usize,
    /// Worst |reference − golden| over the golden flight cases.
    pub flight: Worst5,
    pub impact_cases: usize,
    /// Worst |reference − golden| over the golden impact cases.
    pub impact: Worst4,
    /// All within the bounds documented in docs/accuracy.md.
    pub passed: bool,
}

#[derive(Debug, Clone, Copy, Default, Serialize)]
pub struct Worst5 {
    pub carry_m: f64,
    pub side_m: f64,
    pub apex_m: f64,
    pub flight_time_s: f64,
    pub land_angle_deg: f64,
}

#[derive(Debug, Clone, Copy, Default, Serialize)]
pub struct Worst4 {
    pub ball_speed_mps: f64,
    pub launch_angle_deg: f64,
    pub spin_rpm: f64,
    pub spin_axis_deg: f64,
}

/// Impact accuracy and cost of a precision × solver.
#[derive(Debug, Clone, Serialize)]
pub struct ImpactRow {
    pub precision: Prec,
    pub solver: SolverKind,
    pub failures: usize,
    pub errors: LaunchErrors,
    /// Host time per impact (strike, solve, launch metrics), µs, median (noisy).
    pub us_per_impact: f64,
}

/// Accuracy and cost of one setting over the whole set.
#[derive(Debug, Clone, Serialize)]
pub struct Row {
    pub setting: Setting,
    pub label: String,
    /// Mean force evaluations per shot (exact).
    pub evals_mean: f64,
    /// Most force evaluations of any shot (exact).
    pub evals_max: u32,
    /// Host time per shot (µs), median of repeats (noisy).
    pub us_per_shot: f64,
    /// Shots that failed (e.g. a step that cannot meet the tolerance).
    pub failures: usize,
    pub errors: FlightErrors,
    /// The shot with the worst carry error.
    pub worst_carry_shot: String,
    /// Carry within 1 cm of the reference on every shot.
    pub within_1cm: bool,
    /// On its precision's Pareto front of worst carry error vs host time.
    pub pareto_time: bool,
    /// On its precision's Pareto front of worst carry error vs force evaluations
    /// (reduced-solver rows only: the solver does not change the evaluations).
    pub pareto_evals: bool,
}

/// Cost against flight time, for one launch.
#[derive(Debug, Clone, Serialize)]
pub struct FlightTimeRow {
    pub ball_speed_mps: f64,
    pub flight_time_s: f64,
    /// Per integrator (as `scaling_methods`): force evaluations.
    pub evals: Vec<u32>,
    /// Per integrator: host µs per flight.
    pub us: Vec<f64>,
}

#[derive(Debug, Clone, Serialize)]
pub struct Slope {
    pub integrator: String,
    /// d log(evaluations) / d log(flight time).
    pub evals_slope: f64,
    /// d log(time) / d log(flight time).
    pub time_slope: f64,
}

#[derive(Debug, Clone, Serialize)]
pub struct BatchRow {
    pub batch_size: usize,
    pub us_per_shot: f64,
}

#[derive(Debug, Clone, Serialize)]
pub struct Scaling {
    /// Integrators of the flight-time rows (f64).
    pub methods: Vec<String>,
    pub flight_time: Vec<FlightTimeRow>,
    pub slopes: Vec<Slope>,
    /// The default f64 full shot over the delivery shots, in batches of n (one core).
    pub batch: Vec<BatchRow>,
}

#[derive(Debug, Clone, Serialize)]
pub struct Study {
    pub quick: bool,
    pub timing: String,
    pub shots: Vec<ShotInfo>,
    pub reference: ReferenceCheck,
    pub impact: Vec<ImpactRow>,
    pub flight: Vec<Row>,
    pub scaling: Scaling,
    pub conclusions: Vec<String>,
}
