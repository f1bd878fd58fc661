//! Levenberg–Marquardt on the launch fit's MAP problem (Nocedal & Wright, "Numerical
//! Optimization", 2nd ed., §10.3; Marquardt 1963's diagonal scaling):
//!
//! ```text
//! r(x) = (h(x) − z)/σ                         (flight observations, normalised)
//! A    = Jᵀ J + Q,   g = Jᵀ r + Q (x − m)      (Q = diag(q): measured launch and priors)
//! (A + λ diag A) δ = −g,   x ← x + δ  if  |r|² + (x − m)ᵀ Q (x − m)  falls
//! ```
//!
//! `J` is the forward difference of `r` with fixed steps ([`STEP`]: large against the
//! adaptive integrator's error, so its step-size choices do not show in the slopes), one
//! flight per free unknown, computed once per iteration. The iteration stops when the
//! Newton step (λ = 0) is below `tolerance` posterior σ (`√(−gᵀδ)`), when the cost's
//! predicted fall `−gᵀδ` is below the cost's rounding floor ([`rounding_floor`]: in f32 the
//! last iterations would chase rounding), or when no damping makes the cost fall
//! (stationary to the precision); the posterior covariance is `A⁻¹` at that point.

use super::model::{Schedule, observed, predict, row_kind, shared_scene};
use super::{
    Datum, IDENTIFIED_RATIO, LaunchFit, LaunchValues, MAX_ROWS, MeasuredLaunch, Observations,
    Settings, Source, UNKNOWNS, Workspace,
};
use crate::ball::Ball;
use crate::error::{Error, Field, Reason, Result};
use crate::estimate::spd::Cholesky;
use crate::flight::FlightOutcome;
use crate::real::{Real, lit};
use crate::scene::{PreparedScene, Scene};
use nalgebra::{SMatrix, SVector};

type V<T> = SVector<T, UNKNOWNS>;
type M<T> = SMatrix<T, UNKNOWNS, UNKNOWNS>;

/// Forward-difference steps of the unknowns (m/s, rad, rad, rad/s, rad, m/s, m/s, kg/m³).
const STEP: [f64; UNKNOWNS] = [0.05, 1e-3, 1e-3, 2.0, 2e-3, 0.05, 0.05, 2e-3];

/// The field each unknown is named by in an error.
const FIELD: [Field; UNKNOWNS] = [
    Field::BallSpeed,
    Field::LaunchAngle,
    Field::LaunchDirection,
    Field::BallSpin,
    Field::SpinAxis,
    Field::Wind,
    Field::Wind,
    Field::AirDensity,
];

const LAMBDA_START: f64 = 1e-3;
const LAMBDA_MIN: f64 = 1e-9;
const LAMBDA_GROWTH: f64 = 10.0;
const MAX_REJECTS: usize = 8;

fn get<T: Real>(v: &[T], i: usize) -> T {
    v.get(i).copied().unwrap_or_else(T::zero)
}

/// The problem: observations in normalised form, the quadratic terms, and the scratch.
struct Problem<'a, T: Real> {
    ball: &'a Ball<T>,
    scene: &'a Scene<T>,
    obs: &'a Observations<T>,
    settings: &'a Settings<T>,
    schedule: Schedule<T>,
    /// The scene all flights share when it is not fitted.
    shared: Option<PreparedScene<T>>,
    rows: usize,
    active: [bool; UNKNOWNS],
    q: V<T>,
    m: V<T>,
    flights: u16,
}

impl<T: Real> Problem<'_, T> {
    /// Flies `x`, writes the normalised residuals into `out`; the outcome.
    fn residuals(
        &mut self,
        x: &V<T>,
        z: &[T; MAX_ROWS],
        sd: &[T; MAX_ROWS],
        out: &mut [T; MAX_ROWS],
    ) -> Result<FlightOutcome<T>> {
        self.flights = self.flights.saturating_add(1);
        let xa: [T; UNKNOWNS] = core::array::from_fn(|i| get(x.as_slice(), i));
        let outcome = predict(
            self.ball,
            self.scene,
            self.shared.as_ref(),
            &xa,
            self.obs,
            &self.schedule,
            self.settings,
            out,
        )?;
        for ((r, z), s) in out.iter_mut().zip(z).zip(sd).take(self.rows) {
            *r = (*r - *z) / *s;
        }
        Ok(outcome)
    }

    fn chi2(&self, r: &[T; MAX_ROWS]) -> T {
        r.iter().take(self.rows).fold(T::zero(), |a, v| a + *v * *v)
    }

    fn cost(&self, r: &[T; MAX_ROWS], x: &V<T>) -> T {
        let dx = x - self.m;
        self.chi2(r) + dx.component_mul(&dx).dot(&self.q)
    }
}

pub(super) fn run<T: Real>(
    ball: &Ball<T>,
    scene: &Scene<T>,
    measured: &MeasuredLaunch<T>,
    obs: &Observations<T>,
    settings: &Settings<T>,
    ws: &mut Workspace<T>,
) -> Result<LaunchFit<T>> {
    let rows = obs.rows();
    let measured_arr = measured.to_array();
    let mut active = [true; UNKNOWNS];
    if let Some(a) = active.get_mut(5..7) {
        a.fill(settings.fit_wind);
    }
    if let Some(a) = active.get_mut(7) {
        *a = settings.fit_air_density;
    }
    // The free unknowns: the launch quantities not measured, the wind, the density.
    let free = measured_arr.iter().filter(|m| m.is_none()).count()
        + active.iter().skip(5).filter(|a| **a).count();
    if rows == 0 || rows < free {
        return Err(Error::TooFewObservations);
    }
    let density = scene.air.density_kgm3()?;
    let prior = &settings.prior;
    let prior_mean = prior.mean.to_array();
    let prior_sd = prior.sd.to_array();
    let mut m = V::<T>::zeros();
    let mut q = V::<T>::zeros();
    let mut spread = [T::one(); UNKNOWNS];
    for i in 0..UNKNOWNS {
        let (mean, sd) = if i < 5 {
            match measured_arr.get(i).copied().flatten() {
                Some(d) => (d.value, d.sd),
                None => (get(&prior_mean, i), get(&prior_sd, i)),
            }
        } else if i < 7 {
            (T::zero(), prior.wind_sd_mps)
        } else {
            (density, prior.air_density_sd_kgm3)
        };
        if let (Some(mi), Some(qi), Some(s)) = (m.get_mut(i), q.get_mut(i), spread.get_mut(i)) {
            *mi = mean;
            *qi = if active.get(i) == Some(&true) {
                T::one() / (sd * sd)
            } else {
                T::zero()
            };
            *s = sd;
        }
    }
    let mut p = Problem {
        ball,
        scene,
        obs,
        settings,
        schedule: Schedule::of(obs),
        shared: shared_scene(ball, scene, settings)?,
        rows,
        active,
        q,
        m,
        flights: 0,
    };
    // Observed values and 1σ in row order.
    observed(obs, &mut ws.observed, &mut ws.sd);
    let (z, sd) = (&ws.observed, &ws.sd);

    let mut x = m;
    let mut outcome = p.residuals(&x, z, sd, &mut ws.residual)?;
    let mut cost = p.cost(&ws.residual, &x);
    if !cost.is_finite() {
        // Observations (or 1σ) this precision cannot square: a typed error, not a NaN.
        return Err(Error::invalid(Field::Observation, Reason::OutOfRange));
    }
    let mut lambda = lit::<T>(LAMBDA_START);
    let tolerance = settings.tolerance;
    let mut iterations: u16 = 0;
    // Both exits (converged, or stationary to the precision) leave with the factor of A.
    let chol = loop {
        // Jacobian columns of the active unknowns.
        for i in 0..UNKNOWNS {
            if !p.active.get(i).copied().unwrap_or(false) {
                continue;
            }
            let h = lit::<T>(STEP.get(i).copied().unwrap_or(1e-3));
            let mut xp = x;
            if let Some(v) = xp.get_mut(i) {
                *v += h;
            }
            let Some(col) = ws.columns.get_mut(i) else {
                continue;
            };
            p.residuals(&xp, z, sd, col)?;
            for (c, r) in col.iter_mut().zip(ws.residual.iter()).take(rows) {
                *c = (*c - *r) / h;
            }
        }
        // Normal equations.
        let mut a = M::<T>::zeros();
        let mut g = V::<T>::zeros();
        for i in 0..UNKNOWNS {
            let active_i = p.active.get(i).copied().unwrap_or(false);
            if !active_i {
                if let Some(v) = a.get_mut((i, i)) {
                    *v = T::one();
                }
                continue;
            }
            let ci = ws.columns.get(i);
            let gi = ci.map_or(T::zero(), |c| {
                c.iter()
                    .zip(ws.residual.iter())
                    .take(rows)
                    .fold(T::zero(), |s, (c, r)| s + *c * *r)
            });
            if let Some(v) = g.get_mut(i) {
                *v = gi + get(p.q.as_slice(), i) * (get(x.as_slice(), i) - get(p.m.as_slice(), i));
            }
            for j in 0..=i {
                if !p.active.get(j).copied().unwrap_or(false) {
                    continue;
                }
                let cj = ws.columns.get(j);
                let aij = match (ci, cj) {
                    (Some(ci), Some(cj)) => ci
                        .iter()
                        .zip(cj.iter())
                        .take(rows)
                        .fold(T::zero(), |s, (a, b)| s + *a * *b),
                    _ => T::zero(),
                };
                if let Some(v) = a.get_mut((i, j)) {
                    *v = aij;
                }
                if let Some(v) = a.get_mut((j, i)) {
                    *v = aij;
                }
            }
            if let Some(v) = a.get_mut((i, i)) {
                *v += get(p.q.as_slice(), i);
            }
        }
        // The Newton step's decrement (the cost's predicted fall): converged when it is
        // below the tolerance, or below what rounding alone moves the cost by.
        let chol = Cholesky::<T, UNKNOWNS>::factor(&a).map_err(|_| Error::IllPosed)?;
        let newton = chol.solve(&(-g)).map_err(|_| Error::IllPosed)?;
        let decrement = -g.dot(&newton);
        if !(decrement > tolerance * tolerance
            && decrement > rounding_floor(&p, &ws.residual, z, sd, &x))
        {
            break chol;
        }
        if iterations >= settings.max_iterations {
            return Err(Error::NoConvergence);
        }
        iterations = iterations.saturating_add(1);
        // Damped steps until the cost falls.
        let mut accepted = false;
        for _ in 0..MAX_REJECTS {
            let mut damped = a;
            for i in 0..UNKNOWNS {
                if p.active.get(i).copied().unwrap_or(false)
                    && let Some(v) = damped.get_mut((i, i))
                {
                    *v *= T::one() + lambda;
                }
            }
            let step = Cholesky::<T, UNKNOWNS>::factor(&damped)
                .and_then(|c| c.solve(&(-g)))
                .map_err(|_| Error::IllPosed)?;
            let trial_x = x + step;
            let spin_ok = trial_x.get(3).is_some_and(|s| *s >= T::zero());
            let trial = if spin_ok {
                p.residuals(&trial_x, z, sd, &mut ws.trial).ok()
            } else {
                None
            };
            if let Some(trial_outcome) = trial {
                let trial_cost = p.cost(&ws.trial, &trial_x);
                if trial_cost < cost {
                    x = trial_x;
                    cost = trial_cost;
                    outcome = trial_outcome;
                    // Only the rows in use: swapping the whole buffers (2 × 454 numbers)
                    // cost ≈ 1.4k instructions per accepted step on a Cortex-M4F.
                    if let (Some(r), Some(t)) = (ws.residual.get_mut(..rows), ws.trial.get(..rows))
                    {
                        r.copy_from_slice(t);
                    }
                    let shrunk = lambda / lit(LAMBDA_GROWTH);
                    lambda = if shrunk > lit(LAMBDA_MIN) {
                        shrunk
                    } else {
                        lit(LAMBDA_MIN)
                    };
                    accepted = true;
                    break;
                }
            }
            lambda *= lit(LAMBDA_GROWTH);
        }
        if !accepted {
            // No damping makes the cost fall: stationary to the precision.
            break chol;
        }
    };
    let cov = chol.inverse().map_err(|_| Error::IllPosed)?;
    mirror_check(&mut p, &x, &cov, cost, measured, z, sd, &mut ws.trial)?;
    finish(
        &p,
        &x,
        &cov,
        &spread,
        measured,
        outcome,
        &ws.residual,
        iterations,
    )
}

/// The cost's rounding floor: how much the cost moves when every prediction `hᵢ` and
/// every unknown `xⱼ` moves by one relative ε of the precision,
///
/// ```text
/// floor = 2ε ( Σᵢ |rᵢ| |hᵢ|/σᵢ + Σⱼ qⱼ |xⱼ − mⱼ| |xⱼ| ),   hᵢ/σᵢ = rᵢ + zᵢ/σᵢ
/// ```
///
/// (the first-order change of `Σ rᵢ² + Σ qⱼ (xⱼ − mⱼ)²`). A Newton step that promises less
/// than this cannot be told from rounding: the step's acceptance test compares costs with
/// that much noise, and a flight carries more than one rounding of its predictions. In f64
/// the floor is ~1e-12 and the tolerance stops the iteration; in f32 it is ~1e-4 for a
/// launch monitor's summaries, ~1e-2 for a Doppler trace, and stops the iterations that
/// would chase rounding (docs/launch_fit.md, "Stopping").
fn rounding_floor<T: Real>(
    p: &Problem<'_, T>,
    r: &[T; MAX_ROWS],
    z: &[T; MAX_ROWS],
    sd: &[T; MAX_ROWS],
    x: &V<T>,
) -> T {
    let rows = r
        .iter()
        .zip(z)
        .zip(sd)
        .take(p.rows)
        .fold(T::zero(), |a, ((r, z), s)| a + (*r * (*r + *z / *s)).abs());
    let prior = x
        .iter()
        .zip(p.m.iter())
        .zip(p.q.iter())
        .fold(T::zero(), |a, ((x, m), q)| a + (*q * (*x - *m) * *x).abs());
    lit::<T>(2.0) * T::default_epsilon() * (rows + prior)
}

/// The spin axis's sign must be seen: observations blind to left and right (no side, no
/// lateral track, a trace from straight behind) fit a tilted axis by the carry it costs
/// (`cos(axis)` of the backspin) equally well either way. When the axis was fitted, is
/// more than two of its σ off zero, and its mirror image (−axis, all else held) explains
/// the data within one unit of cost, the fit refuses with [`Error::Unidentifiable`]`(`[`Field::SpinAxis`]`)`.
#[allow(clippy::too_many_arguments)]
fn mirror_check<T: Real>(
    p: &mut Problem<'_, T>,
    x: &V<T>,
    cov: &M<T>,
    cost: T,
    measured: &MeasuredLaunch<T>,
    z: &[T; MAX_ROWS],
    sd: &[T; MAX_ROWS],
    scratch: &mut [T; MAX_ROWS],
) -> Result<()> {
    if measured.spin_axis_rad.is_some() {
        return Ok(());
    }
    let axis = get(x.as_slice(), 4);
    // Within two of its σ of zero the sign is not claimed anyway.
    let var = cov.get((4, 4)).copied().unwrap_or_else(T::zero);
    let two_sd = lit::<T>(2.0)
        * if var > T::zero() {
            var.root()
        } else {
            T::zero()
        };
    if !(axis.abs() > lit::<T>(1e-3) && axis.abs() > two_sd) {
        return Ok(());
    }
    let mut mirror = *x;
    if let Some(a) = mirror.get_mut(4) {
        *a = -axis;
    }
    // A mirror that does not fly is no rival.
    if p.residuals(&mirror, z, sd, scratch).is_err() {
        return Ok(());
    }
    if (p.cost(scratch, &mirror) - cost).abs() < T::one() {
        return Err(Error::Unidentifiable(Field::SpinAxis));
    }
    Ok(())
}

#[allow(clippy::too_many_arguments)]
fn finish<T: Real>(
    p: &Problem<'_, T>,
    x: &V<T>,
    cov: &M<T>,
    spread: &[T; UNKNOWNS],
    measured: &MeasuredLaunch<T>,
    flight: FlightOutcome<T>,
    residual: &[T; MAX_ROWS],
    iterations: u16,
) -> Result<LaunchFit<T>> {
    let sd: [T; UNKNOWNS] = core::array::from_fn(|i| {
        let v = cov.get((i, i)).copied().unwrap_or_else(T::zero);
        if v > T::zero() { v.root() } else { T::zero() }
    });
    let chi2 = p.chi2(residual);
    let finite =
        chi2.is_finite() && sd.iter().all(|v| v.is_finite()) && x.iter().all(|v| v.is_finite());
    if !finite {
        return Err(Error::invalid(Field::Observation, Reason::OutOfRange));
    }
    let measured_arr = measured.to_array();
    // Every free unknown must be pinned down by the observations.
    let ratio = lit::<T>(IDENTIFIED_RATIO);
    for i in 0..UNKNOWNS {
        let free = p.active.get(i).copied().unwrap_or(false)
            && (i >= 5 || measured_arr.get(i).copied().flatten().is_none());
        if free && !(get(&sd, i) < ratio * get(spread, i)) {
            return Err(Error::Unidentifiable(
                FIELD.get(i).copied().unwrap_or(Field::Observation),
            ));
        }
    }
    let xs = x.as_slice();
    let source = LaunchValues::from_array(core::array::from_fn(|i| {
        if measured_arr.get(i).copied().flatten().is_some() {
            Source::Measured
        } else {
            Source::Fitted
        }
    }));
    let datum = |i: usize| Datum::new(get(xs, i), get(&sd, i));
    let (worst_row, worst) =
        residual
            .iter()
            .take(p.rows)
            .enumerate()
            .fold((0, T::zero()), |(k, w), (i, r)| {
                if r.abs() > w.abs() { (i, *r) } else { (k, w) }
            });
    Ok(LaunchFit {
        value: LaunchValues::from_array(core::array::from_fn(|i| get(xs, i))),
        sd: LaunchValues::from_array(core::array::from_fn(|i| get(&sd, i))),
        source,
        wind_mps: p.settings.fit_wind.then(|| [datum(5), datum(6)]),
        air_density_kgm3: p.settings.fit_air_density.then(|| datum(7)),
        flight,
        chi2,
        worst_observation: row_kind(p.obs, worst_row),
        worst_residual_sigma: worst,
        observations: u16::try_from(p.rows).unwrap_or(u16::MAX),
        iterations,
        flights: p.flights,
    })
}
