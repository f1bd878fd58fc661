//! `carry bench accuracy`: the accuracy–cost study (issue 6; report in docs/accuracy.md).
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

mod chart;
mod measure;
mod shots;

use measure::{
    Budget, FlightErrors, LaunchErrors, Method, Prec, Setting, ShotResult, SolverKind, Stat,
};
use serde::Serialize;
use shots::{Golden, Origin, Shot};
use std::fmt::Write as _;
use std::io::Write as _;
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
}

/// The "default fidelity" target: carry within 1 cm of the reference on every shot.
pub const CARRY_TARGET_M: f64 = 0.01;
/// Reference tolerance of the adaptive integrator.
const REFERENCE_TOLERANCE: f64 = 1e-12;

// ------------------------------------------------------------------ report types

/// One shot of the set, as reported.
#[derive(Debug, Clone, Serialize)]
struct ShotInfo {
    name: String,
    class: &'static str,
    origin: Origin,
    start: String,
    scene: String,
    /// The reference's results.
    reference: ReferenceShot,
}

#[derive(Debug, Clone, Copy, Serialize)]
struct ReferenceShot {
    carry_m: f64,
    side_m: f64,
    apex_m: f64,
    flight_time_s: f64,
    land_angle_deg: f64,
    force_evaluations: u32,
    /// Ball speed (m/s), launch angle (deg), spin (rpm), spin axis (deg): deliveries only.
    launch: Option<[f64; 4]>,
}

/// The reference against the golden files.
#[derive(Debug, Clone, Serialize)]
struct ReferenceCheck {
    description: &'static str,
    flight_cases: usize,
    /// Worst |reference − golden| over the golden flight cases.
    flight: Worst5,
    impact_cases: usize,
    /// Worst |reference − golden| over the golden impact cases.
    impact: Worst4,
    /// All within the bounds documented in docs/accuracy.md.
    passed: bool,
}

#[derive(Debug, Clone, Copy, Default, Serialize)]
struct Worst5 {
    carry_m: f64,
    side_m: f64,
    apex_m: f64,
    flight_time_s: f64,
    land_angle_deg: f64,
}

#[derive(Debug, Clone, Copy, Default, Serialize)]
struct Worst4 {
    ball_speed_mps: f64,
    launch_angle_deg: f64,
    spin_rpm: f64,
    spin_axis_deg: f64,
}

/// Impact accuracy and cost of a precision × solver.
#[derive(Debug, Clone, Serialize)]
struct ImpactRow {
    precision: Prec,
    solver: SolverKind,
    failures: usize,
    errors: LaunchErrors,
    /// Host time per impact (strike, solve, launch metrics), µs, median (noisy).
    us_per_impact: f64,
}

/// Accuracy and cost of one setting over the whole set.
#[derive(Debug, Clone, Serialize)]
struct Row {
    setting: Setting,
    label: String,
    /// Mean force evaluations per shot (exact).
    evals_mean: f64,
    /// Most force evaluations of any shot (exact).
    evals_max: u32,
    /// Host time per shot (µs), median of repeats (noisy).
    us_per_shot: f64,
    /// Shots that failed (e.g. a step that cannot meet the tolerance).
    failures: usize,
    errors: FlightErrors,
    /// The shot with the worst carry error.
    worst_carry_shot: String,
    /// Carry within 1 cm of the reference on every shot.
    within_1cm: bool,
    /// On its precision's Pareto front of worst carry error vs host time.
    pareto_time: bool,
    /// On its precision's Pareto front of worst carry error vs force evaluations
    /// (reduced-solver rows only: the solver does not change the evaluations).
    pareto_evals: bool,
}

/// Cost against flight time, for one launch.
#[derive(Debug, Clone, Serialize)]
struct FlightTimeRow {
    ball_speed_mps: f64,
    flight_time_s: f64,
    /// Per integrator (as `scaling_methods`): force evaluations.
    evals: Vec<u32>,
    /// Per integrator: host µs per flight.
    us: Vec<f64>,
}

#[derive(Debug, Clone, Serialize)]
struct Slope {
    integrator: String,
    /// d log(evaluations) / d log(flight time).
    evals_slope: f64,
    /// d log(time) / d log(flight time).
    time_slope: f64,
}

#[derive(Debug, Clone, Serialize)]
struct BatchRow {
    batch_size: usize,
    us_per_shot: f64,
}

#[derive(Debug, Clone, Serialize)]
struct Scaling {
    /// Integrators of the flight-time rows (f64).
    methods: Vec<String>,
    flight_time: Vec<FlightTimeRow>,
    slopes: Vec<Slope>,
    /// The default f64 full shot over the delivery shots, in batches of n (one core).
    batch: Vec<BatchRow>,
}

#[derive(Debug, Clone, Serialize)]
struct Study {
    quick: bool,
    timing: String,
    shots: Vec<ShotInfo>,
    reference: ReferenceCheck,
    impact: Vec<ImpactRow>,
    flight: Vec<Row>,
    scaling: Scaling,
    conclusions: Vec<String>,
}

// ------------------------------------------------------------------ running

/// Runs the accuracy study.
///
/// # Errors
/// A failing reference (a bug), or failing to write the SVG or standard output.
pub fn run(options: &StudyOptions) -> Result<(), String> {
    let study = build(options.quick)?;
    if let Some(path) = &options.svg {
        chart::draw(path, &chart_points(&study))
            .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    let text = if options.json {
        let mut s = serde_json::to_string_pretty(&study).map_err(|e| e.to_string())?;
        s.push('\n');
        s
    } else {
        let mut s = render(&study);
        if let Some(path) = &options.svg {
            let _ = writeln!(s, "\nwrote {}", path.display());
        }
        s
    };
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(e.to_string()),
        _ => Ok(()),
    }
}

fn build(quick: bool) -> Result<Study, String> {
    let shots = shots::shot_set(quick)?;
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

    // The reference: f64, full solver, DP45 at 1e-12.
    let reference_setting = Setting {
        precision: Prec::F64,
        solver: SolverKind::Full,
        integrator: Method::Dp45,
        param: REFERENCE_TOLERANCE,
        is_default: false,
    };
    let reference: Vec<ShotResult> = measure::results(&p64, &reference_setting)
        .into_iter()
        .zip(&shots)
        .map(|(r, s)| r.map_err(|e| format!("reference failed on {}: {e}", s.name)))
        .collect::<Result<_, _>>()?;
    let check = reference_check(&shots, &reference);

    // Impact: precision × solver (and pivoting) on the delivery shots.
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
                    measure::impact_launches(&p64, solver.solver()),
                    measure::time_impact(&p64, solver.solver(), budget),
                ),
                Prec::F32 => (
                    measure::impact_launches(&p32, solver.solver()),
                    measure::time_impact(&p32, solver.solver(), budget),
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

    // Flight and full shot: every setting over the whole set.
    let mut rows: Vec<Row> = measure::settings(quick)
        .into_iter()
        .map(|setting| {
            let (results, us) = match setting.precision {
                Prec::F64 => (
                    measure::results(&p64, &setting),
                    measure::time_setting(&p64, &setting, budget),
                ),
                Prec::F32 => (
                    measure::results(&p32, &setting),
                    measure::time_setting(&p32, &setting, budget),
                ),
            };
            let evals: Vec<u32> = results
                .iter()
                .filter_map(|r| r.as_ref().ok().map(|r| r.evals))
                .collect();
            let failures = results.len() - evals.len();
            let errors = measure::flight_errors(&results, &reference);
            let worst_carry_shot = results
                .iter()
                .zip(&reference)
                .zip(&shots)
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
        .collect();
    mark_pareto(&mut rows);

    let scaling = scaling(quick, &p64, budget)?;
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
    study.conclusions = conclusions(&study);
    Ok(study)
}

/// Bounds of the reference check: the golden files were computed by an independent f64
/// implementation (8th-order integrator at 1e-12); their apex is a sampled maximum.
const CHECK_POSITION_M: f64 = 1e-6;
const CHECK_APEX_M: f64 = 1e-4;
const CHECK_TIME_S: f64 = 1e-6;
const CHECK_ANGLE_DEG: f64 = 1e-6;
const CHECK_IMPACT_REL: f64 = 1e-9;

fn reference_check(shots: &[Shot], reference: &[ShotResult]) -> ReferenceCheck {
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

/// Marks each precision's Pareto fronts (rows that fail on any shot are excluded).
fn mark_pareto(rows: &mut [Row]) {
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

/// Least-squares slope of log y against log x.
fn loglog_slope(points: &[(f64, f64)]) -> f64 {
    let pts: Vec<(f64, f64)> = points
        .iter()
        .filter(|(x, y)| *x > 0.0 && *y > 0.0)
        .map(|(x, y)| (x.ln(), y.ln()))
        .collect();
    #[allow(clippy::cast_precision_loss)]
    let n = pts.len() as f64;
    let (mx, my) = (
        pts.iter().map(|p| p.0).sum::<f64>() / n,
        pts.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    sxy / sxx
}

fn scaling(quick: bool, p64: &[shots::Prepared<f64>], budget: Budget) -> Result<Scaling, String> {
    use carry_core::flight::Integrator;
    let methods: [(&str, Integrator<f64>); 3] = [
        ("euler h=1e-3", Integrator::Euler { step_s: 1e-3 }),
        ("rk4 h=0.02", Integrator::Rk4 { step_s: 0.02 }),
        ("dp45 default", Integrator::default()),
    ];
    let ball = carry_core::Ball::<f64>::standard();
    let scene = carry_core::Scene::<f64>::default();
    let mut flight_time = Vec::new();
    for launch in shots::scaling_launches(quick) {
        let motion = launch.ball_motion().map_err(|e| e.to_string())?;
        let mut evals = Vec::new();
        let mut us = Vec::new();
        let mut t = 0.0;
        for (_, integrator) in &methods {
            let out = carry_core::fly(&ball, &motion, &scene, integrator, None)
                .map_err(|e| format!("scaling flight: {e}"))?;
            t = out.flight_time_s;
            evals.push(out.stats.force_evaluations);
            us.push(measure::time_us(
                || {
                    let _ = std::hint::black_box(carry_core::fly(
                        &ball,
                        std::hint::black_box(&motion),
                        &scene,
                        integrator,
                        None,
                    ));
                },
                1,
                budget,
            ));
        }
        flight_time.push(FlightTimeRow {
            ball_speed_mps: launch.ball_speed_mps,
            flight_time_s: t,
            evals,
            us,
        });
    }
    let slopes = methods
        .iter()
        .enumerate()
        .map(|(i, (name, _))| Slope {
            integrator: (*name).to_owned(),
            evals_slope: loglog_slope(
                &flight_time
                    .iter()
                    .map(|r| (r.flight_time_s, f64::from(r.evals[i])))
                    .collect::<Vec<_>>(),
            ),
            time_slope: loglog_slope(
                &flight_time
                    .iter()
                    .map(|r| (r.flight_time_s, r.us[i]))
                    .collect::<Vec<_>>(),
            ),
        })
        .collect();

    // Batch size: the default f64 full shot over the delivery shots, n at a time.
    let deliveries: Vec<&shots::Prepared<f64>> = p64
        .iter()
        .filter(|p| matches!(p.start, shots::PreparedStart::Delivery { .. }))
        .collect();
    let integrator = Integrator::<f64>::default();
    let sizes: &[usize] = if quick {
        &[1, 100]
    } else {
        &[1, 10, 100, 1000, 10_000]
    };
    // Every batch size cycles through the same mix of deliveries (the cursor persists
    // across batches), so only the batch size differs.
    let mut cursor = 0_usize;
    let batch = sizes
        .iter()
        .map(|&n| BatchRow {
            batch_size: n,
            us_per_shot: measure::time_us(
                || {
                    for _ in 0..n {
                        let p = deliveries[cursor % deliveries.len()];
                        cursor = cursor.wrapping_add(1);
                        let _ = std::hint::black_box(measure::run_shot(
                            std::hint::black_box(p),
                            carry_core::Solver::Reduced,
                            &integrator,
                        ));
                    }
                },
                n,
                budget,
            ),
        })
        .collect();
    Ok(Scaling {
        methods: methods.iter().map(|(n, _)| (*n).to_owned()).collect(),
        flight_time,
        slopes,
        batch,
    })
}

// ------------------------------------------------------------------ conclusions

fn find(rows: &[Row], f: impl Fn(&Row) -> bool) -> Option<&Row> {
    rows.iter().find(|r| f(r))
}

fn cheapest(rows: &[Row], f: impl Fn(&Row) -> bool) -> Option<&Row> {
    rows.iter()
        .filter(|r| r.failures == 0 && f(r))
        .min_by(|a, b| a.us_per_shot.total_cmp(&b.us_per_shot))
}

fn conclusions(s: &Study) -> Vec<String> {
    let mut out = Vec::new();
    let rows = &s.flight;
    out.push(format!(
        "Reference check against the golden files: {} (flight: carry {} m, apex {} m; impact: \
         ball speed {} m/s, spin {} rpm).",
        if s.reference.passed {
            "passed"
        } else {
            "FAILED"
        },
        sci(s.reference.flight.carry_m),
        sci(s.reference.flight.apex_m),
        sci(s.reference.impact.ball_speed_mps),
        sci(s.reference.impact.spin_rpm),
    ));
    for prec in [Prec::F64, Prec::F32] {
        let p = |r: &Row| r.setting.precision == prec;
        if let Some(d) = find(rows, |r| p(r) && r.setting.is_default) {
            out.push(format!(
                "{} default ({}): worst carry error {} mm (median {} mm), {:.1} evaluations \
                 and {:.2} µs per shot; {} the 1 cm target on every shot{}.",
                prec.name(),
                d.label,
                sig(d.errors.carry_m.worst * 1e3),
                sig(d.errors.carry_m.median * 1e3),
                d.evals_mean,
                d.us_per_shot,
                if d.within_1cm { "meets" } else { "MISSES" },
                if d.pareto_time {
                    ", on the Pareto front"
                } else {
                    ""
                },
            ));
        }
        for (target, what) in [(CARRY_TARGET_M, "1 cm"), (1e-3, "1 mm")] {
            if let Some(c) = cheapest(rows, |r| p(r) && r.errors.carry_m.worst <= target) {
                out.push(format!(
                    "{}: cheapest setting within {what} on every shot: {} ({} mm, {:.1} \
                     evaluations, {:.2} µs).",
                    prec.name(),
                    c.label,
                    sig(c.errors.carry_m.worst * 1e3),
                    c.evals_mean,
                    c.us_per_shot
                ));
            }
        }
    }
    // The f32 noise floor: the best worst-case carry error f32 reaches, and the cheapest
    // setting within 1.5× of it.
    let f32_rows: Vec<&Row> = rows
        .iter()
        .filter(|r| r.setting.precision == Prec::F32 && r.failures == 0)
        .collect();
    if let Some(floor) = f32_rows
        .iter()
        .map(|r| r.errors.carry_m.worst)
        .min_by(f64::total_cmp)
        && let Some(c) = cheapest(rows, |r| {
            r.setting.precision == Prec::F32 && r.errors.carry_m.worst <= 1.5 * floor
        })
    {
        out.push(format!(
            "f32 noise floor: worst carry error {} mm at best; reached (within 1.5×) by {} at \
             {:.1} evaluations — tighter tolerances and smaller steps cost more and do not \
             improve it.",
            sig(floor * 1e3),
            c.label,
            c.evals_mean
        ));
    }
    if let (Some(r), Some(f)) = (
        find(rows, |r| {
            r.setting.precision == Prec::F64 && r.setting.is_default
        }),
        find(rows, |r| {
            r.setting.precision == Prec::F64
                && r.setting.solver == SolverKind::Full
                && r.setting.integrator == Method::Dp45
                && r.setting.param == measure::default_tolerance(Prec::F64)
        }),
    ) {
        out.push(format!(
            "Impact solver: the full 15×15 solve costs {:+.2} µs per shot over the reduced 3×3 \
             at the default integrator and changes the worst carry error by {} mm: both are \
             exact, so the reduced form is the default.",
            f.us_per_shot - r.us_per_shot,
            sig((f.errors.carry_m.worst - r.errors.carry_m.worst).abs() * 1e3),
        ));
    }
    if let (Some(e), Some(d)) = (
        find(rows, |r| {
            r.setting.precision == Prec::F64
                && r.setting.solver == SolverKind::Reduced
                && r.setting.integrator == Method::Euler
                && (r.setting.param - 2e-3).abs() < 1e-12
        }),
        find(rows, |r| {
            r.setting.precision == Prec::F64 && r.setting.is_default
        }),
    ) {
        out.push(format!(
            "Explicit Euler at 500 Hz (the peer's scheme): worst carry error {} mm with {:.0} \
             evaluations per shot, against {} mm with {:.0} for the default.",
            sig(e.errors.carry_m.worst * 1e3),
            e.evals_mean,
            sig(d.errors.carry_m.worst * 1e3),
            d.evals_mean
        ));
    }
    for sl in &s.scaling.slopes {
        out.push(format!(
            "Scaling with flight time, {}: evaluations ∝ T^{:.2}, host time ∝ T^{:.2}.",
            sl.integrator, sl.evals_slope, sl.time_slope
        ));
    }
    if let (Some(lo), Some(hi)) = (
        s.scaling
            .batch
            .iter()
            .map(|b| b.us_per_shot)
            .min_by(f64::total_cmp),
        s.scaling
            .batch
            .iter()
            .map(|b| b.us_per_shot)
            .max_by(f64::total_cmp),
    ) {
        out.push(format!(
            "Batch size 1 to {}: {:.2}–{:.2} µs per default f64 shot (flat).",
            s.scaling.batch.last().map_or(0, |b| b.batch_size),
            lo,
            hi
        ));
    }
    out
}

// ------------------------------------------------------------------ text output

/// A number with 3 significant digits, scientific when very small or large.
fn sig(x: f64) -> String {
    if !x.is_finite() {
        return if x.is_nan() {
            "—".into()
        } else {
            "∞".into()
        };
    }
    if x == 0.0 {
        return "0".into();
    }
    let a = x.abs();
    if (0.01..10_000.0).contains(&a) {
        // Digits after the point for 3 significant digits.
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let d = (2 - a.log10().floor() as i32).max(0) as usize;
        format!("{x:.d$}")
    } else {
        sci(x)
    }
}

fn sci(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else {
        format!("{x:.1e}")
    }
}

fn pair(s: &Stat, scale: f64) -> String {
    format!("{} ({})", sig(s.worst * scale), sig(s.median * scale))
}

fn render(s: &Study) -> String {
    let mut o = String::new();
    let n_launch = s
        .shots
        .iter()
        .filter(|x| x.origin == Origin::GoldenFlight)
        .count();
    let n_impact = s
        .shots
        .iter()
        .filter(|x| x.origin == Origin::GoldenImpact)
        .count();
    let n_own = s.shots.len() - n_launch - n_impact;
    let _ = writeln!(
        o,
        "carry accuracy–cost study{}: {} shots ({} golden launches, {} golden deliveries, {} \
         own full shots; see docs/accuracy.md)",
        if s.quick { " (--quick)" } else { "" },
        s.shots.len(),
        n_launch,
        n_impact,
        n_own
    );
    let r = &s.reference;
    let _ = writeln!(o, "Reference: {}.", r.description);
    let _ = writeln!(
        o,
        "  vs golden flight ({} cases): carry {} m, side {} m, apex {} m, flight time {} s, \
         landing angle {}°",
        r.flight_cases,
        sci(r.flight.carry_m),
        sci(r.flight.side_m),
        sci(r.flight.apex_m),
        sci(r.flight.flight_time_s),
        sci(r.flight.land_angle_deg)
    );
    let _ = writeln!(
        o,
        "  vs golden impact ({} cases): ball speed {} m/s, launch angle {}°, spin {} rpm, spin \
         axis {}° — {}",
        r.impact_cases,
        sci(r.impact.ball_speed_mps),
        sci(r.impact.launch_angle_deg),
        sci(r.impact.spin_rpm),
        sci(r.impact.spin_axis_deg),
        if r.passed { "passed" } else { "FAILED" }
    );
    let _ = writeln!(o, "Timing: {}.", s.timing);

    let _ = writeln!(
        o,
        "\nImpact — errors against the reference, worst (median) over the {} deliveries",
        s.shots
            .iter()
            .filter(|x| x.reference.launch.is_some())
            .count()
    );
    let _ = writeln!(
        o,
        "{:<4} {:<13} {:>22} {:>22} {:>22} {:>22} {:>9} {:>4}",
        "prec",
        "solver",
        "ball speed (m/s)",
        "launch angle (°)",
        "spin (rpm)",
        "spin axis (°)",
        "µs/impact",
        "fail"
    );
    for row in &s.impact {
        let e = &row.errors;
        let _ = writeln!(
            o,
            "{:<4} {:<13} {:>22} {:>22} {:>22} {:>22} {:>9.3} {:>4}",
            row.precision.name(),
            row.solver.name(),
            pair(&e.ball_speed_mps, 1.0),
            pair(&e.launch_angle_deg, 1.0),
            pair(&e.spin_rpm, 1.0),
            pair(&e.spin_axis_deg, 1.0),
            row.us_per_impact,
            row.failures
        );
    }

    let _ = writeln!(
        o,
        "\nFull shot (impact + flight; launches: flight only) — errors against the reference, \
         worst (median) over the set"
    );
    let _ = writeln!(
        o,
        "evals: mean force evaluations per shot (exact); µs: host time per shot (noisy). \
         Marks: * Pareto front (worst carry vs µs), e Pareto front (worst carry vs evals), \
         D default, ! a shot failed"
    );
    let _ = writeln!(
        o,
        "{:<4} {:<7} {:<5} {:<10} {:>8} {:>8} {:<3} {:>20} {:>20} {:>20} {:>18} {:>18}  worst carry shot",
        "prec",
        "solver",
        "integ",
        "param",
        "evals",
        "µs/shot",
        "",
        "carry (mm)",
        "side (mm)",
        "apex (mm)",
        "flight time (ms)",
        "land angle (°)",
    );
    let mut last = None;
    for row in &s.flight {
        let key = (row.setting.precision, row.setting.solver);
        if last.is_some_and(|k| k != key) {
            o.push('\n');
        }
        last = Some(key);
        let marks = format!(
            "{}{}{}{}",
            if row.pareto_time { "*" } else { "" },
            if row.pareto_evals { "e" } else { "" },
            if row.setting.is_default { "D" } else { "" },
            if row.failures > 0 { "!" } else { "" }
        );
        let e = &row.errors;
        let _ = writeln!(
            o,
            "{:<4} {:<7} {:<5} {:<10} {:>8.1} {:>8.2} {:<3} {:>20} {:>20} {:>20} {:>18} {:>18}  {}",
            row.setting.precision.name(),
            row.setting.solver.name(),
            row.setting.integrator.name(),
            row.setting.param_label(),
            row.evals_mean,
            row.us_per_shot,
            marks,
            pair(&e.carry_m, 1e3),
            pair(&e.side_m, 1e3),
            pair(&e.apex_m, 1e3),
            pair(&e.flight_time_s, 1e3),
            pair(&e.land_angle_deg, 1.0),
            row.worst_carry_shot,
        );
        if row.failures > 0 {
            let _ = writeln!(o, "     ({} shots failed)", row.failures);
        }
    }

    let sc = &s.scaling;
    let _ = writeln!(
        o,
        "\nScaling with flight time (f64, 30° launch, 3000 rpm, standard air): evaluations / µs \
         per flight"
    );
    let _ = write!(o, "{:>10} {:>14}", "speed m/s", "flight time s");
    for m in &sc.methods {
        let _ = write!(o, " {m:>22}");
    }
    o.push('\n');
    for r in &sc.flight_time {
        let _ = write!(o, "{:>10.0} {:>14.3}", r.ball_speed_mps, r.flight_time_s);
        for (e, u) in r.evals.iter().zip(&r.us) {
            let _ = write!(o, " {:>22}", format!("{e} / {u:.2}"));
        }
        o.push('\n');
    }
    let _ = write!(o, "{:>25}", "log-log slope");
    for sl in &sc.slopes {
        let _ = write!(
            o,
            " {:>22}",
            format!("{:.2} / {:.2}", sl.evals_slope, sl.time_slope)
        );
    }
    o.push('\n');
    let _ = writeln!(
        o,
        "\nBatch size (default f64 full shot, one core): {}",
        sc.batch
            .iter()
            .map(|b| format!("n={} {:.2} µs/shot", b.batch_size, b.us_per_shot))
            .collect::<Vec<_>>()
            .join(", ")
    );

    let _ = writeln!(o, "\nConclusions");
    for c in &s.conclusions {
        let _ = writeln!(o, "- {c}");
    }
    o
}

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
