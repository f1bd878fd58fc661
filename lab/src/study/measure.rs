//! Running one setting over the shot set: results, errors against the reference, force
//! evaluations (exact) and host time (noisy, a median of repeated in-process timings).

use super::shots::{Prepared, PreparedStart, Shot};
use carry_core::flight::{DEFAULT_TOLERANCE_F32, DEFAULT_TOLERANCE_F64, Integrator};
use carry_core::impact::{self, Solver};
use carry_core::linalg::Pivoting;
use carry_core::real::{lit, to_f64};
use carry_core::shot::{self, Fidelity};
use carry_core::units::{to_deg, to_rpm};
use carry_core::{FlightOutcome, LaunchMetrics, Real};
use serde::Serialize;
use std::hint::black_box;
use std::time::Instant;

/// Floating-point precision.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Prec {
    F64,
    F32,
}

impl Prec {
    pub fn name(self) -> &'static str {
        match self {
            Self::F64 => "f64",
            Self::F32 => "f32",
        }
    }
}

/// Impact solver (with the full solver's pivoting variants for the impact table).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SolverKind {
    /// The exact 3×3 collision-matrix form (the default).
    Reduced,
    /// Full 15×15, row-equilibrated partial pivoting (`Solver::FULL`).
    Full,
    /// Full 15×15, plain partial pivoting.
    FullPartial,
    /// Full 15×15, no pivoting.
    FullNoPivoting,
}

impl SolverKind {
    pub fn solver(self) -> Solver {
        match self {
            Self::Reduced => Solver::Reduced,
            Self::Full => Solver::FULL,
            Self::FullPartial => Solver::Full(Pivoting::Partial),
            Self::FullNoPivoting => Solver::Full(Pivoting::None),
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Self::Reduced => "reduced",
            Self::Full => "full",
            Self::FullPartial => "full/partial",
            Self::FullNoPivoting => "full/none",
        }
    }
}

/// Flight integrator family.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    Euler,
    Rk4,
    Dp45,
}

impl Method {
    pub fn name(self) -> &'static str {
        match self {
            Self::Euler => "euler",
            Self::Rk4 => "rk4",
            Self::Dp45 => "dp45",
        }
    }
}

/// One point of the study: precision × solver × integrator × step or tolerance.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Setting {
    pub precision: Prec,
    pub solver: SolverKind,
    pub integrator: Method,
    /// Fixed step (s) for Euler and RK4, `rtol = atol` for DP45.
    pub param: f64,
    /// The library default for this precision (reduced solver, `Integrator::default()`).
    pub is_default: bool,
}

impl Setting {
    pub fn integrator<T: Real>(&self) -> Integrator<T> {
        match self.integrator {
            Method::Euler => Integrator::Euler {
                step_s: lit(self.param),
            },
            Method::Rk4 => Integrator::Rk4 {
                step_s: lit(self.param),
            },
            Method::Dp45 if self.is_default => Integrator::default(),
            Method::Dp45 => Integrator::dormand_prince(lit(self.param)),
        }
    }

    /// "h=2e-3 s" or "tol=4e-5".
    pub fn param_label(&self) -> String {
        match self.integrator {
            Method::Euler | Method::Rk4 => format!("h={}", short(self.param)),
            Method::Dp45 => format!("tol={}", short(self.param)),
        }
    }

    pub fn label(&self) -> String {
        format!(
            "{} {} {} {}",
            self.precision.name(),
            self.solver.name(),
            self.integrator.name(),
            self.param_label()
        )
    }
}

/// `2e-3`, `0.05`, `4e-5`: the shortest exact rendering.
pub fn short(x: f64) -> String {
    if x >= 0.01 {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// The default DP45 tolerance of a precision.
pub fn default_tolerance(p: Prec) -> f64 {
    match p {
        Prec::F64 => DEFAULT_TOLERANCE_F64,
        Prec::F32 => DEFAULT_TOLERANCE_F32,
    }
}

/// The settings of the study.
pub fn settings(quick: bool) -> Vec<Setting> {
    let euler: &[f64] = if quick {
        &[1e-2, 2e-3]
    } else {
        &[1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4]
    };
    let rk4: &[f64] = if quick {
        &[0.1, 0.02]
    } else {
        &[0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.002]
    };
    let dp64: &[f64] = if quick {
        &[1e-3, 1e-6]
    } else {
        &[1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-10]
    };
    let dp32: &[f64] = if quick {
        &[1e-3, 1e-6]
    } else {
        &[1e-2, 3e-3, 1e-3, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6]
    };
    let mut out = Vec::new();
    for precision in [Prec::F64, Prec::F32] {
        for solver in [SolverKind::Reduced, SolverKind::Full] {
            let mut push = |integrator, param, is_default| {
                out.push(Setting {
                    precision,
                    solver,
                    integrator,
                    param,
                    is_default: is_default && solver == SolverKind::Reduced,
                });
            };
            for &h in euler {
                push(Method::Euler, h, false);
            }
            for &h in rk4 {
                push(Method::Rk4, h, false);
            }
            let default = default_tolerance(precision);
            let mut tols: Vec<f64> = if precision == Prec::F64 { dp64 } else { dp32 }.to_vec();
            tols.retain(|t| *t != default);
            let at = tols.iter().position(|t| *t < default).unwrap_or(tols.len());
            tols.insert(at, default);
            for tol in tols {
                push(Method::Dp45, tol, tol == default);
            }
        }
    }
    out
}

// ------------------------------------------------------------------ one shot

/// What one shot produced, in `f64` display units.
#[derive(Debug, Clone, Copy, Default)]
pub struct ShotResult {
    /// Ball speed (m/s), launch angle (deg), spin (rpm), spin axis (deg) — for deliveries.
    pub launch: Option<[f64; 4]>,
    pub carry_m: f64,
    pub side_m: f64,
    pub apex_m: f64,
    pub flight_time_s: f64,
    pub land_angle_deg: f64,
    pub evals: u32,
}

/// A delivery: strike → impact → launch metrics → flight (`carry_core::shot::play`); a
/// launch: launch → ball motion → flight.
#[inline]
pub fn run_shot<T: Real>(
    p: &Prepared<T>,
    solver: Solver,
    integrator: &Integrator<T>,
) -> carry_core::Result<(Option<LaunchMetrics<T>>, FlightOutcome<T>)> {
    match &p.start {
        PreparedStart::Launch(l) => Ok((None, p.scene.fly(&l.ball_motion()?, integrator, None)?)),
        PreparedStart::Delivery { head, delivery } => {
            let fidelity = Fidelity {
                solver,
                integrator: *integrator,
            };
            let out = shot::play(head, &p.ball, delivery, &p.scene, &fidelity, None)?;
            Ok((Some(out.impact.launch), out.flight))
        }
    }
}

/// Launch metrics in display units.
pub fn launch_values<T: Real>(m: &LaunchMetrics<T>) -> [f64; 4] {
    [
        to_f64(m.ball_speed_mps),
        to_f64(to_deg(m.launch_angle_rad)),
        to_f64(to_rpm(m.spin_radps)),
        to_f64(to_deg(m.spin_axis_rad)),
    ]
}

/// Runs every shot once at `setting`; `Err` entries are failures.
pub fn results<T: Real>(
    prepared: &[Prepared<T>],
    setting: &Setting,
) -> Vec<Result<ShotResult, carry_core::Error>> {
    let integrator = setting.integrator::<T>();
    let solver = setting.solver.solver();
    prepared
        .iter()
        .map(|p| {
            run_shot(p, solver, &integrator).map(|(m, f)| ShotResult {
                launch: m.as_ref().map(launch_values),
                carry_m: to_f64(f.carry_m),
                side_m: to_f64(f.side_m),
                apex_m: to_f64(f.apex_m),
                flight_time_s: to_f64(f.flight_time_s),
                land_angle_deg: to_f64(to_deg(f.landing_angle_rad)),
                evals: f.stats.force_evaluations,
            })
        })
        .collect()
}

// ------------------------------------------------------------------ statistics

/// Worst and median of absolute errors over the set.
#[derive(Debug, Clone, Copy, Default, Serialize)]
pub struct Stat {
    pub worst: f64,
    pub median: f64,
}

pub fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

pub fn stat(mut errors: Vec<f64>) -> Stat {
    if errors.is_empty() {
        return Stat {
            worst: f64::NAN,
            median: f64::NAN,
        };
    }
    let worst = errors.iter().copied().fold(0.0, f64::max);
    Stat {
        worst,
        median: median(&mut errors),
    }
}

/// Flight errors of a setting against the reference.
#[derive(Debug, Clone, Copy, Default, Serialize)]
pub struct FlightErrors {
    /// |Δcarry| (m).
    pub carry_m: Stat,
    /// |Δside| (m).
    pub side_m: Stat,
    /// |Δapex| (m).
    pub apex_m: Stat,
    /// |Δflight time| (s).
    pub flight_time_s: Stat,
    /// |Δlanding angle| (deg).
    pub land_angle_deg: Stat,
}

/// Launch errors of a precision × solver against the reference.
#[derive(Debug, Clone, Copy, Default, Serialize)]
pub struct LaunchErrors {
    /// |Δball speed| (m/s).
    pub ball_speed_mps: Stat,
    /// |Δlaunch angle| (deg).
    pub launch_angle_deg: Stat,
    /// |Δspin| (rpm).
    pub spin_rpm: Stat,
    /// |Δspin axis| (deg).
    pub spin_axis_deg: Stat,
}

/// Flight errors over the shots that succeeded.
pub fn flight_errors(
    results: &[Result<ShotResult, carry_core::Error>],
    reference: &[ShotResult],
) -> FlightErrors {
    let ok: Vec<(&ShotResult, &ShotResult)> = results
        .iter()
        .zip(reference)
        .filter_map(|(r, x)| r.as_ref().ok().map(|r| (r, x)))
        .collect();
    let e = |f: fn(&ShotResult) -> f64| stat(ok.iter().map(|(r, x)| (f(r) - f(x)).abs()).collect());
    FlightErrors {
        carry_m: e(|r| r.carry_m),
        side_m: e(|r| r.side_m),
        apex_m: e(|r| r.apex_m),
        flight_time_s: e(|r| r.flight_time_s),
        land_angle_deg: e(|r| r.land_angle_deg),
    }
}

/// Launch errors over the delivery shots.
pub fn launch_errors(launches: &[[f64; 4]], reference: &[[f64; 4]]) -> LaunchErrors {
    let e = |i: usize| {
        stat(
            launches
                .iter()
                .zip(reference)
                .map(|(a, b)| (a[i] - b[i]).abs())
                .collect(),
        )
    };
    LaunchErrors {
        ball_speed_mps: e(0),
        launch_angle_deg: e(1),
        spin_rpm: e(2),
        spin_axis_deg: e(3),
    }
}

// ------------------------------------------------------------------ timing

/// How long to time.
#[derive(Debug, Clone, Copy)]
pub struct Budget {
    /// Repeats; the median is reported.
    pub samples: usize,
    /// Target length of one repeat (s); at least one pass over the set.
    pub sample_s: f64,
}

/// Median time per item (µs) of `pass`, which processes `items` items per call.
pub fn time_us(mut pass: impl FnMut(), items: usize, budget: Budget) -> f64 {
    let t0 = Instant::now();
    pass();
    let one = t0.elapsed().as_secs_f64().max(1e-9);
    // Truncation is fine: a repeat count.
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let k = ((budget.sample_s / one).ceil() as usize).clamp(1, 10_000_000);
    // Slow settings (one pass ≫ a repeat) are timed fewer times: their noise is relatively
    // small and the study must stay short.
    let repeats = if one > 10.0 * budget.sample_s {
        budget.samples.min(5)
    } else {
        budget.samples
    };
    let mut samples: Vec<f64> = (0..repeats.max(1))
        .map(|_| {
            let t = Instant::now();
            for _ in 0..k {
                pass();
            }
            #[allow(clippy::cast_precision_loss)]
            let per = t.elapsed().as_secs_f64() / (k * items.max(1)) as f64;
            per
        })
        .collect();
    median(&mut samples) * 1e6
}

/// Median host time per shot (µs) of `setting` over `prepared`.
pub fn time_setting<T: Real>(prepared: &[Prepared<T>], setting: &Setting, budget: Budget) -> f64 {
    let integrator = setting.integrator::<T>();
    let solver = setting.solver.solver();
    time_us(
        || {
            for p in prepared {
                let _ = black_box(run_shot(black_box(p), solver, &integrator));
            }
        },
        prepared.len(),
        budget,
    )
}

/// Median host time per impact (µs): strike → solve → launch metrics.
pub fn time_impact<T: Real>(prepared: &[Prepared<T>], solver: Solver, budget: Budget) -> f64 {
    let n = prepared
        .iter()
        .filter(|p| matches!(p.start, PreparedStart::Delivery { .. }))
        .count();
    time_us(
        || {
            for p in prepared {
                if let PreparedStart::Delivery { head, delivery } = &p.start {
                    let _ = black_box(
                        delivery
                            .strike(black_box(head))
                            .and_then(|s| impact::solve(head, &p.ball, &s, solver)),
                    );
                }
            }
        },
        n,
        budget,
    )
}

/// Impact launch metrics of the delivery shots.
pub fn impact_launches<T: Real>(
    prepared: &[Prepared<T>],
    solver: Solver,
) -> Vec<Result<[f64; 4], carry_core::Error>> {
    prepared
        .iter()
        .filter_map(|p| match &p.start {
            PreparedStart::Delivery { head, delivery } => Some(
                delivery
                    .strike(head)
                    .and_then(|s| impact::solve(head, &p.ball, &s, solver))
                    .map(|o| launch_values(&o.launch)),
            ),
            PreparedStart::Launch(_) => None,
        })
        .collect()
}

/// Prepares every shot in precision `T`.
///
/// # Errors
/// An invalid shot (a bug in the set).
pub fn prepare_all<T: Real>(shots: &[Shot]) -> Result<Vec<Prepared<T>>, String> {
    shots.iter().map(Shot::prepare::<T>).collect()
}
