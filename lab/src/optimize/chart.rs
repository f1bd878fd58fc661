//! The optimizer chart (after TrackMan's): for each club speed × attack angle, the
//! dynamic loft that maximises carry (or, with a ground in the scene, the total), and the
//! launch, carry and total it gives.
//!
//! Each cell is a bounded one-dimensional maximisation over dynamic loft by argmin's Brent
//! method (Brent 1973, *Algorithms for Minimization without Derivatives*, ch. 5: golden
//! section with parabolic interpolation); the cells run in parallel (rayon).

use super::{Range, require_ground};
use crate::error::{Error, Input, Result};
use crate::setup::{Setup, ShotSummary};
use argmin::core::{CostFunction, Executor, State as _};
use argmin::solver::brent::BrentOpt;
use carry_core::Real;
use carry_core::real::{lit, to_f64};
use carry_core::units::deg;
use rayon::prelude::*;
use serde::Serialize;

/// Brent's absolute tolerance on the dynamic loft (deg).
const LOFT_TOLERANCE_DEG: f64 = 1.0e-3;

/// The chart's grid and the loft bounds.
#[derive(Debug, Clone, PartialEq)]
pub struct ChartOptions {
    /// Club speeds (m/s), the rows.
    pub club_speeds_mps: Vec<f64>,
    /// Attack angles (deg), the columns.
    pub attack_angles_deg: Vec<f64>,
    /// Dynamic loft bounds (deg).
    pub dynamic_loft_deg: Range,
    /// What each cell maximises.
    pub objective: ChartObjective,
}

/// What the chart's cells maximise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ChartObjective {
    /// Carry (TrackMan's optimizer chart).
    #[default]
    Carry,
    /// Total, carry plus bounce and roll: needs a ground in the scene.
    Total,
}

/// One cell: the best dynamic loft at a club speed and attack angle.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ChartCell {
    /// Club speed (m/s).
    pub club_speed_mps: f64,
    /// Attack angle (deg).
    pub attack_angle_deg: f64,
    /// Best dynamic loft (deg).
    pub dynamic_loft_deg: f64,
    /// The shot there.
    #[serde(flatten)]
    pub shot: ShotSummary,
}

/// The chart: cells row by row (speed-major), in the order of the options.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Chart {
    /// Club speeds (m/s).
    pub club_speeds_mps: Vec<f64>,
    /// Attack angles (deg).
    pub attack_angles_deg: Vec<f64>,
    /// The cells, speed-major.
    pub cells: Vec<ChartCell>,
}

struct LoftCost<'a, T: Real> {
    setup: &'a Setup<T>,
    objective: ChartObjective,
}

impl<T: Real> CostFunction for LoftCost<'_, T> {
    type Param = f64;
    type Output = f64;
    fn cost(&self, loft_deg: &f64) -> std::result::Result<f64, argmin::core::Error> {
        let mut d = self.setup.delivery;
        d.dynamic_loft_rad = deg(lit(*loft_deg));
        let gain = self
            .setup
            .play(&d)
            .ok()
            .and_then(|out| match self.objective {
                ChartObjective::Carry => Some(out.flight.carry_m),
                ChartObjective::Total => out.flight.ground.map(|g| g.total_m),
            });
        Ok(gain.map_or(f64::MAX, |m| -to_f64(m)))
    }
}

fn cell<T: Real>(
    base: &Setup<T>,
    speed: f64,
    attack: f64,
    loft: Range,
    objective: ChartObjective,
) -> Result<ChartCell> {
    let mut setup = *base;
    setup.delivery.club_speed_mps = lit(speed);
    setup.delivery.attack_angle_rad = deg(lit(attack));
    let solver = BrentOpt::new(loft.lo, loft.hi).set_tolerance(1e-10, LOFT_TOLERANCE_DEG);
    let cost = LoftCost {
        setup: &setup,
        objective,
    };
    let result = Executor::new(cost, solver)
        .configure(|s| s.param(0.5 * (loft.lo + loft.hi)).max_iters(200))
        .run()
        .map_err(|e| Error::Library(e.to_string()))?;
    let best = result
        .state()
        .get_best_param()
        .copied()
        .unwrap_or(0.5 * (loft.lo + loft.hi));
    setup.delivery.dynamic_loft_rad = deg(lit(best));
    let out = setup.play_base()?;
    Ok(ChartCell {
        club_speed_mps: speed,
        attack_angle_deg: attack,
        dynamic_loft_deg: best,
        shot: ShotSummary::of(&out),
    })
}

/// Computes the optimizer chart.
///
/// # Errors
/// [`Error::Invalid`] for an empty grid, a non-finite or negative speed, or the total
/// without a ground in the scene; the core's errors when the best shot of a cell fails.
pub fn chart<T: Real>(setup: &Setup<T>, options: &ChartOptions) -> Result<Chart> {
    if options.club_speeds_mps.is_empty()
        || options
            .club_speeds_mps
            .iter()
            .any(|v| !(v.is_finite() && *v > 0.0))
    {
        return Err(Error::invalid(
            Input::ChartSpeeds,
            "need one or more positive club speeds",
        ));
    }
    if options.attack_angles_deg.is_empty()
        || options.attack_angles_deg.iter().any(|a| !a.is_finite())
    {
        return Err(Error::invalid(
            Input::ChartAttackAngles,
            "need one or more finite attack angles",
        ));
    }
    if options.objective == ChartObjective::Total {
        require_ground(setup)?;
    }
    let grid: Vec<(f64, f64)> = options
        .club_speeds_mps
        .iter()
        .flat_map(|&v| options.attack_angles_deg.iter().map(move |&a| (v, a)))
        .collect();
    let cells = grid
        .par_iter()
        .map(|&(v, a)| cell(setup, v, a, options.dynamic_loft_deg, options.objective))
        .collect::<Result<Vec<_>>>()?;
    Ok(Chart {
        club_speeds_mps: options.club_speeds_mps.clone(),
        attack_angles_deg: options.attack_angles_deg.clone(),
        cells,
    })
}
