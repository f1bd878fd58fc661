//! The optimizer's problem: the unit cube ↔ delivery variables, the penalised cost that
//! argmin's Nelder–Mead minimises, and the evaluation counter.

use super::{Flatness, Objective, Options, Range, require_ground};
use crate::dispersion::{self, Noise};
use crate::error::{Error, Input, Result};
use crate::setup::Setup;
use argmin::core::{CostFunction, Executor, State as _};
use argmin::solver::neldermead::NelderMead;
use carry_core::real::{lit, to_f64};
use carry_core::shot::ShotOutcome;
use carry_core::units::deg;
use carry_core::{Delivery, Real};
use std::sync::atomic::{AtomicU64, Ordering};

/// Penalty weight outside the box (objective units per unit-cube distance²).
const PENALTY: f64 = 1.0e3;
/// Cost of a point whose shot fails (a finite wall the simplex retreats from).
const FAILED_COST: f64 = 1.0e6;
/// Edge of the initial simplex in the unit cube.
const SIMPLEX_EDGE: f64 = 0.15;
/// Edge of the restart simplex around the first run's best vertex.
const RESTART_EDGE: f64 = 0.02;
/// Convergence: standard deviation of the simplex's costs (m).
const SD_TOLERANCE: f64 = 1.0e-10;

/// The variables' bounds: dynamic loft (deg), attack angle (deg), impact height (m). A
/// variable whose range is a single value (`lo == hi`) is fixed there and is not a
/// dimension of the search.
pub(super) struct Space {
    ranges: [Range; 3],
    /// The free variables (indices into `ranges`), in order: the unit cube's axes.
    free: Vec<usize>,
}

impl Space {
    fn new(ranges: [Range; 3]) -> Self {
        let free = (0..3).filter(|&i| ranges[i].lo < ranges[i].hi).collect();
        Self { ranges, free }
    }

    pub(super) fn dimension(&self) -> usize {
        self.free.len()
    }

    /// User units at `u` (clamped into the box): `[loft_deg, attack_deg, height_m]`.
    pub(super) fn at(&self, u: &[f64]) -> [f64; 3] {
        let mut x = self.ranges.map(|r| r.lo);
        for (&i, &ui) in self.free.iter().zip(u) {
            x[i] = self.ranges[i].at(ui.clamp(0.0, 1.0));
        }
        x
    }
}

/// The optimization problem for one setup.
pub(super) struct Problem<'a, T: Real> {
    setup: &'a Setup<T>,
    space: Space,
    objective: Objective,
    evaluations: AtomicU64,
}

impl<'a, T: Real> Problem<'a, T> {
    pub(super) fn new(setup: &'a Setup<T>, o: &Options) -> Result<Self> {
        match o.objective {
            Objective::Carry => {}
            Objective::Total => require_ground(setup)?,
            Objective::Dispersion { noise, shots, .. } => {
                noise.validate()?;
                if noise == Noise::default() {
                    return Err(Error::invalid(
                        Input::Objective,
                        "dispersion needs some delivery noise (give at least one of the -sd options)",
                    ));
                }
                if shots < 2 {
                    return Err(Error::invalid(Input::Count, "need at least 2 shots"));
                }
            }
        }
        let height = o.impact_height_m.unwrap_or(Range {
            lo: to_f64(setup.delivery.location.height_m),
            hi: to_f64(setup.delivery.location.height_m),
        });
        Ok(Self {
            setup,
            space: Space::new([o.dynamic_loft_deg, o.attack_angle_deg, height]),
            objective: o.objective,
            evaluations: AtomicU64::new(0),
        })
    }

    pub(super) fn space(&self) -> &Space {
        &self.space
    }

    pub(super) fn evaluations(&self) -> u64 {
        self.evaluations.load(Ordering::Relaxed)
    }

    /// +1 when the objective is maximised, −1 when minimised: cost = −sense·value.
    pub(super) fn sense(&self) -> f64 {
        match self.objective {
            Objective::Dispersion { .. } => -1.0,
            _ => 1.0,
        }
    }

    fn delivery_at(&self, x: [f64; 3]) -> Delivery<T> {
        let mut d = self.setup.delivery;
        d.dynamic_loft_rad = deg(lit(x[0]));
        d.attack_angle_rad = deg(lit(x[1]));
        d.location.height_m = lit(x[2]);
        d
    }

    /// The shot at `u` (clamped).
    pub(super) fn shot(&self, u: &[f64]) -> Result<ShotOutcome<T>> {
        Ok(self.setup.play(&self.delivery_at(self.space.at(u)))?)
    }

    /// The objective at the point `x` in user units (carry, or side spread; m).
    fn score(&self, x: [f64; 3]) -> Result<f64> {
        self.evaluations.fetch_add(1, Ordering::Relaxed);
        let delivery = self.delivery_at(x);
        match self.objective {
            Objective::Carry => {
                let out = self.setup.play(&delivery)?;
                Ok(to_f64(out.flight.carry_m))
            }
            Objective::Total => {
                let out = self.setup.play(&delivery)?;
                // `new` checked the scene has a ground, so every landing has a rollout.
                Ok(out.flight.ground.map_or(f64::NAN, |g| to_f64(g.total_m)))
            }
            Objective::Dispersion { noise, shots, seed } => {
                let setup = Setup {
                    delivery,
                    ..*self.setup
                };
                let d = dispersion::simulate(&setup, &noise, shots, seed, None)?;
                Ok(d.side_sd_m)
            }
        }
    }

    /// The objective at `u` (clamped).
    pub(super) fn value(&self, u: &[f64]) -> Result<f64> {
        self.score(self.space.at(u))
    }

    /// The penalised cost argmin minimises.
    fn penalised(&self, u: &[f64]) -> f64 {
        let excess: f64 = u
            .iter()
            .map(|&ui| {
                let e = ui - ui.clamp(0.0, 1.0);
                e * e
            })
            .sum();
        let base = match self.value(u) {
            Ok(v) if v.is_finite() => -self.sense() * v,
            _ => FAILED_COST,
        };
        base + PENALTY * excess
    }

    fn simplex(&self, u0: &[f64], edge: f64) -> Vec<Vec<f64>> {
        let mut vertices = vec![u0.to_vec()];
        for i in 0..u0.len() {
            let mut v = u0.to_vec();
            if let Some(vi) = v.get_mut(i) {
                *vi = if *vi + edge <= 1.0 {
                    *vi + edge
                } else {
                    *vi - edge
                };
            }
            vertices.push(v);
        }
        vertices
    }

    fn run(&self, u0: &[f64], edge: f64, max_iterations: u64) -> Result<(Vec<f64>, f64)> {
        let solver = NelderMead::new(self.simplex(u0, edge))
            .with_sd_tolerance(SD_TOLERANCE)
            .map_err(|e| Error::Library(e.to_string()))?;
        let result = Executor::new(Cost(self), solver)
            .configure(|state| state.max_iters(max_iterations))
            .run()
            .map_err(|e| Error::Library(e.to_string()))?;
        let state = result.state();
        let best = state
            .get_best_param()
            .cloned()
            .unwrap_or_else(|| u0.to_vec());
        Ok((best, state.get_best_cost()))
    }

    /// Minimises from `u0`: a run, then a restart from a small simplex around its best.
    /// Returns the best point (clamped into the box) and its cost.
    pub(super) fn minimise(&self, u0: &[f64], max_iterations: u64) -> Result<(Vec<f64>, f64)> {
        let (first, _) = self.run(u0, SIMPLEX_EDGE, max_iterations)?;
        let (best, cost) = self.run(&first, RESTART_EDGE, max_iterations)?;
        Ok((best.iter().map(|u| u.clamp(0.0, 1.0)).collect(), cost))
    }

    /// The objective lost a step away from `u` in each variable (not clamped: the
    /// function's own shape, bounds aside).
    pub(super) fn flatness(&self, u: &[f64], value: f64) -> Vec<Flatness> {
        const NAMES: [&str; 3] = ["dynamic_loft_deg", "attack_angle_deg", "impact_height_m"];
        const STEPS: [f64; 3] = [1.0, 1.0, 0.001];
        let x = self.space.at(u);
        self.space
            .free
            .iter()
            .filter_map(|&i| {
                let (name, step) = (NAMES.get(i)?, STEPS.get(i)?);
                let loss = |sign: f64| {
                    let mut y = x;
                    if let Some(yi) = y.get_mut(i) {
                        *yi += sign * step;
                    }
                    self.score(y).ok().map(|v| self.sense() * (value - v))
                };
                Some(Flatness {
                    variable: name,
                    step: *step,
                    loss_minus_m: loss(-1.0),
                    loss_plus_m: loss(1.0),
                })
            })
            .collect()
    }
}

/// argmin's view of the problem.
struct Cost<'p, 'a, T: Real>(&'p Problem<'a, T>);

impl<T: Real> CostFunction for Cost<'_, '_, T> {
    type Param = Vec<f64>;
    type Output = f64;

    fn cost(&self, u: &Self::Param) -> std::result::Result<f64, argmin::core::Error> {
        Ok(self.0.penalised(u))
    }
}
