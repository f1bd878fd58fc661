//! `carry optimize`: the delivery that maximises carry (or minimises dispersion) within
//! the user's bounds.
//!
//! **Variables**: dynamic loft and attack angle (degrees), optionally the impact height up
//! the face (m); every other delivery field stays as given. A variable whose range is one
//! value (`lo == hi`, [`Range::fixed`]) is held there: it is not a dimension of the search
//! and has no flatness entry. **Method**: argmin's
//! Nelder–Mead simplex (Nelder & Mead 1965, *Comput. J.* 7, 308–313; the default
//! coefficients α = 1, γ = 2, ρ = ½, σ = ½) on the box mapped to the unit cube `u ∈ [0,1]ⁿ`;
//! the bounds are kept by evaluating the shot at the clamped point and adding a quadratic
//! penalty `P·|u − clamp(u)|²` outside (so an optimum on a bound, e.g. the highest attack
//! angle allowed, is found exactly). Each start runs the simplex to convergence, then once
//! more from a fresh small simplex around its best vertex (the usual restart against a
//! collapsed simplex). The first start is the box centre, the others uniform in the box
//! from a seeded ChaCha8 generator; the best optimum wins and every start is reported.
//!
//! The objective must be smooth for the simplex to converge to 0.1°: use a tight flight
//! tolerance (the CLI uses Dormand–Prince at 1e-9 in f64 unless told otherwise); the
//! default 4e-5 makes the carry step by ~0.1 mm as the step sequence changes.
//!
//! **Flatness**: the objective lost at ±1° of each angle and ±1 mm of impact height.

mod chart;
mod heatmap;
mod problem;

pub use chart::{Chart, ChartCell, ChartObjective, ChartOptions, chart};
pub use heatmap::draw as draw_chart;

use crate::dispersion::Noise;
use crate::error::{Error, Input, Result};
use crate::setup::{Setup, ShotSummary};
use carry_core::Real;
use problem::{Problem, Space};
use rand::{RngExt as _, SeedableRng as _};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;

/// A closed interval `[lo, hi]`, validated: finite and `lo ≤ hi`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Range {
    /// Lower bound.
    pub lo: f64,
    /// Upper bound.
    pub hi: f64,
}

impl Range {
    /// A validated range for `input`.
    ///
    /// # Errors
    /// [`Error::Invalid`] for non-finite or inverted bounds.
    pub fn new(lo: f64, hi: f64, input: Input) -> Result<Self> {
        if !(lo.is_finite() && hi.is_finite()) {
            return Err(Error::invalid(input, "bounds must be finite numbers"));
        }
        if lo > hi {
            return Err(Error::invalid(
                input,
                format!("the bounds are inverted ({lo} > {hi}): give low,high"),
            ));
        }
        Ok(Self { lo, hi })
    }

    /// The one-value range that holds a variable at `x` (not searched).
    ///
    /// # Errors
    /// [`Error::Invalid`] for a non-finite `x`.
    pub fn fixed(x: f64, input: Input) -> Result<Self> {
        Self::new(x, x, input)
    }

    /// Whether the range holds its variable at one value.
    #[must_use]
    pub fn is_fixed(&self) -> bool {
        self.lo == self.hi
    }

    fn at(&self, u: f64) -> f64 {
        self.lo + (self.hi - self.lo) * u
    }
}

/// What the optimizer seeks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Objective {
    /// Maximise carry.
    Carry,
    /// Maximise total distance (carry + bounce and roll): needs a scene with a ground
    /// (`--ground`); [`optimize`] rejects it otherwise.
    Total,
    /// Minimise the side spread (standard deviation of side, m) under a delivery noise
    /// model: a Monte-Carlo of `shots` shots with common random numbers (`seed`), so the
    /// objective is a deterministic, smooth function of the variables.
    Dispersion {
        /// The noise standard deviations.
        noise: Noise,
        /// Shots per evaluation.
        shots: usize,
        /// Seed of the noise.
        seed: u64,
    },
}

impl Objective {
    /// The objective's name in reports.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Self::Carry => "carry",
            Self::Total => "total",
            Self::Dispersion { .. } => "dispersion",
        }
    }
}

/// The search: bounds, objective, starts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Dynamic loft bounds (deg).
    pub dynamic_loft_deg: Range,
    /// Attack angle bounds (deg).
    pub attack_angle_deg: Range,
    /// Impact height bounds (m); `None` keeps the base delivery's impact height.
    pub impact_height_m: Option<Range>,
    /// The objective.
    pub objective: Objective,
    /// Number of starts (≥ 1): the box centre, then random points.
    pub starts: usize,
    /// Seed of the random starts.
    pub seed: u64,
    /// Most simplex iterations per run.
    pub max_iterations: u64,
}

impl Options {
    /// Carry, one start, the given bounds; 400 iterations per run.
    #[must_use]
    pub fn carry(dynamic_loft_deg: Range, attack_angle_deg: Range) -> Self {
        Self {
            dynamic_loft_deg,
            attack_angle_deg,
            impact_height_m: None,
            objective: Objective::Carry,
            starts: 1,
            seed: 0,
            max_iterations: 400,
        }
    }
}

/// A point of the search space in user units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Point {
    /// Dynamic loft (deg).
    pub dynamic_loft_deg: f64,
    /// Attack angle (deg).
    pub attack_angle_deg: f64,
    /// Impact height (m).
    pub impact_height_m: f64,
}

/// One start of the search and where it ended.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Start {
    /// Where it started.
    pub from: Point,
    /// Where it converged.
    pub to: Point,
    /// The objective there (carry or total m, or side spread m).
    pub objective_value: f64,
    /// Objective evaluations used.
    pub evaluations: u64,
}

/// How much the objective worsens a step away from the optimum in one variable.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Flatness {
    /// `dynamic_loft_deg`, `attack_angle_deg` or `impact_height_m`.
    pub variable: &'static str,
    /// The step (1° or 0.001 m).
    pub step: f64,
    /// Objective lost at −step (m; carry lost, or side spread gained); `None` if that shot fails.
    pub loss_minus_m: Option<f64>,
    /// Objective lost at +step (m).
    pub loss_plus_m: Option<f64>,
}

/// The optimum and how it was found.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Optimum {
    /// `carry`, `total` or `dispersion`.
    pub objective: &'static str,
    /// The optimal delivery variables.
    #[serde(flatten)]
    pub point: Point,
    /// The objective there (carry or total m, or side spread m).
    pub objective_value: f64,
    /// The shot at the optimum (launch and landing).
    pub shot: ShotSummary,
    /// Objective evaluations over all starts.
    pub evaluations: u64,
    /// Wall time of the search (s).
    pub elapsed_s: f64,
    /// Loss at ±1 step of each variable.
    pub flatness: Vec<Flatness>,
    /// Every start.
    pub starts: Vec<Start>,
}

/// The total objective's requirement (the optimum's and the chart's): a ground in the
/// scene to bounce and roll on.
fn require_ground<T: Real>(setup: &Setup<T>) -> Result<()> {
    if setup.scene.ground().is_none() {
        return Err(Error::invalid(
            Input::Objective,
            "total distance needs a ground (e.g. --ground fairway) to bounce and roll on",
        ));
    }
    Ok(())
}

/// Finds the best delivery within `options`' bounds.
///
/// # Errors
/// [`Error::Invalid`] for no starts, the `total` objective without a ground in the scene, or a
/// dispersion objective without noise or shots; [`Error::Core`] when the base delivery at
/// the box centre is not a valid shot; [`Error::Library`] if argmin fails.
pub fn optimize<T: Real>(setup: &Setup<T>, options: &Options) -> Result<Optimum> {
    let clock = std::time::Instant::now();
    if options.starts == 0 {
        return Err(Error::invalid(Input::Count, "need at least one start"));
    }
    let problem = Problem::new(setup, options)?;
    let space = problem.space();
    if space.dimension() == 0 {
        return Err(Error::invalid(
            Input::DynamicLoftRange,
            "every variable is held at one value: nothing to optimise",
        ));
    }
    let centre = vec![0.5; space.dimension()];
    // The centre must be a valid shot: otherwise the bounds (or the rest of the delivery)
    // are wrong, and the user should hear why rather than get a penalised nonsense point.
    problem.shot(&centre)?;
    let mut rng = ChaCha8Rng::seed_from_u64(options.seed);
    let mut starts = Vec::with_capacity(options.starts);
    for k in 0..options.starts {
        let u0: Vec<f64> = if k == 0 {
            centre.clone()
        } else {
            (0..space.dimension())
                .map(|_| rng.random::<f64>())
                .collect()
        };
        let before = problem.evaluations();
        let best = problem.minimise(&u0, options.max_iterations)?;
        starts.push((u0, best, problem.evaluations() - before));
    }
    let best = starts
        .iter()
        .min_by(|a, b| a.1.1.total_cmp(&b.1.1))
        .map(|s| s.1.0.clone())
        .unwrap_or(centre);
    let out = problem.shot(&best)?;
    let value = problem.value(&best)?;
    let flatness = problem.flatness(&best, value);
    Ok(Optimum {
        objective: options.objective.name(),
        point: space.point(&best),
        objective_value: value,
        shot: ShotSummary::of(&out),
        evaluations: problem.evaluations(),
        elapsed_s: clock.elapsed().as_secs_f64(),
        flatness,
        starts: starts
            .iter()
            .map(|(u0, (u, cost), evaluations)| Start {
                from: space.point(u0),
                to: space.point(u),
                objective_value: -problem.sense() * cost,
                evaluations: *evaluations,
            })
            .collect(),
    })
}

impl Space {
    fn point(&self, u: &[f64]) -> Point {
        let x = self.at(u);
        Point {
            dynamic_loft_deg: x[0],
            attack_angle_deg: x[1],
            impact_height_m: x[2],
        }
    }
}
