//! Levenberg–Marquardt on the estimator's MAP problem (Nocedal & Wright, "Numerical
//! Optimization", 2nd ed., §10.3; Marquardt 1963's diagonal scaling):
//!
//! ```text
//! r(x) = (f(x) − y) / σ                       (5 normalised ball residuals)
//! A    = Jᵀ J + Q,  g = Jᵀ r + Q (x − m)       (Q = diag(q), the prior and club data)
//! (A + λ diag A) δ = −g,  x ← x + δ  if the cost  |r|² + (x − m)ᵀ Q (x − m)  falls
//! ```
//!
//! The prior `N(μ, s²)` and a measured club datum `N(c, σ_c²)` on the same unknown combine
//! into one quadratic term, `q = 1/s² + 1/σ_c²`, `m = (μ/s² + c/σ_c²)/q`. `J` is the forward
//! difference of the normalised residuals with steps `√ε · unit`. Two additions to plain
//! Levenberg–Marquardt, both for the prior-dominated directions where the residuals' own
//! curvature matters: a secant estimate `S` of that curvature (Dennis, Gay & Welsch's
//! NL2SOL update) added to `A` while the Newton step stays a descent direction, and a
//! one-point line search along each accepted step. The iteration stops when the Newton
//! step is below `tolerance` posterior σ (`√(−gᵀδ)`) or when no damping makes the cost fall
//! (stationary to the precision); it fails with [`Error::NoConvergence`] after the budget.
//! The 7×7 systems are solved by a scaled Cholesky factorisation ([`super::spd`]).
//!
//! The posterior ([`Posterior`]): the Laplace covariance `C = A⁻¹` (Gauss–Newton, at the
//! last Jacobian; one inverse), each 1σ `√(cᵀ C c)` for the datum's gradient `c`; by
//! default, along the strike height's valley the profile posterior replaces it (the
//! cost minimised with the height held, probed either side of the MAP, summarised as a
//! split normal: [`valley`]), and the value is the posterior mean (docs/estimate.md §1).
//!
//! Stack: on soft-float MCUs (the micro:bit's Cortex-M0: 16 KiB of RAM in all) the loop,
//! the posterior and the valley keep their matrix algebra in out-of-line steps, so that
//! the frames under each forward evaluation hold only the state (`cfg_attr(…,
//! inline(never))` below; the f64 estimate's peak is 12.8 KiB there, measured by the
//! on-target suite). Hardware-float targets and hosts inline as the compiler chooses: the
//! same operations in the same order, so the results are bit for bit the same.

use super::model::{Model, SPEED, Unknowns};
use super::spd::Cholesky;
use super::{
    BallData, Check, ClubData, ClubEstimate, Consistency, Datum, Estimate, Posterior, Settings,
    chi2_quantile,
};
use crate::error::{Error, Result};
use crate::real::{Real, lit};
use core::f64::consts::PI;
use nalgebra::{SMatrix, SVector};

type V7<T> = SVector<T, 7>;
type M7<T> = SMatrix<T, 7, 7>;
type Jacobian<T> = SMatrix<T, 5, 7>;

/// Scale of each unknown (rad ×4, m ×2, m/s): finite-difference steps and the stopping
/// test are `√ε` of these.
const UNIT: [f64; 7] = [0.5, 0.5, 0.5, 0.5, 0.05, 0.05, 50.0];

/// Damping: start, floor, growth on a rejected step, rejected steps per iteration.
const LAMBDA_START: f64 = 1e-3;
const LAMBDA_MIN: f64 = 1e-9;
const LAMBDA_GROWTH: f64 = 10.0;
const MAX_REJECTS: usize = 8;

/// Line search along an accepted step: tried only for a predicted stretch above the
/// minimum or below its inverse, capped at the maximum.
const MIN_STRETCH: f64 = 1.2;
const MAX_STRETCH: f64 = 8.0;

/// The problem's data in the solver's normalised form.
struct Problem<'a, T: Real> {
    model: &'a Model<'a, T>,
    y: [T; 5],
    sigma: [T; 5],
    /// Precision of the quadratic term on each unknown.
    q: V7<T>,
    /// Its centre.
    m: V7<T>,
}

impl<T: Real> Problem<'_, T> {
    /// Normalised residuals of a prediction.
    fn residual(&self, f: &BallData<T>) -> SVector<T, 5> {
        let d = difference(f, &self.y);
        SVector::<T, 5>::from_fn(|i, _| {
            let (Some(d), Some(s)) = (d.get(i), self.sigma.get(i)) else {
                return T::zero();
            };
            *d / *s
        })
    }

    fn cost(&self, r: &SVector<T, 5>, x: &V7<T>) -> T {
        let dx = x - self.m;
        r.norm_squared() + dx.component_mul(&dx).dot(&self.q)
    }

    fn predict(&self, x: &V7<T>) -> Result<BallData<T>> {
        self.model.predict(&unknowns(x))
    }
}

/// `f − y` per ball number, the spin axis wrapped into (−π, π].
fn difference<T: Real>(f: &BallData<T>, y: &[T; 5]) -> [T; 5] {
    let f = f.to_array();
    let mut d = [T::zero(); 5];
    for ((d, f), y) in d.iter_mut().zip(f).zip(y) {
        *d = f - *y;
    }
    let pi = lit::<T>(PI);
    if let Some(axis) = d.last_mut() {
        if *axis > pi {
            *axis -= pi + pi;
        } else if *axis < -pi {
            *axis += pi + pi;
        }
    }
    d
}

fn unknowns<T: Real>(x: &V7<T>) -> Unknowns<T> {
    Unknowns::from_array(core::array::from_fn(|i| {
        x.get(i).copied().unwrap_or_else(T::zero)
    }))
}

fn units<T: Real>() -> V7<T> {
    let eps = T::default_epsilon().root();
    V7::from(UNIT.map(|u| lit::<T>(u) * eps))
}

pub(super) fn run<T: Real>(
    model: &Model<'_, T>,
    measured: &BallData<T>,
    club_data: &ClubData<T>,
    settings: &Settings<T>,
) -> Result<Estimate<T>> {
    let Settings {
        noise,
        prior,
        max_iterations,
        tolerance,
        posterior: summary,
        check,
        sd_scale,
    } = *settings;
    let measured_club = [
        club_data.face_angle_rad,
        club_data.club_path_rad,
        club_data.dynamic_loft_rad,
        club_data.attack_angle_rad,
        None,
        None,
        club_data.club_speed_mps,
    ];
    let mut q = [T::zero(); 7];
    let mut m = [T::zero(); 7];
    for ((((q, m), mu), s), (c, sc)) in q
        .iter_mut()
        .zip(m.iter_mut())
        .zip(prior.mean.to_array())
        .zip(prior.sd.to_array())
        .zip(measured_club.iter().zip(noise.club.to_array()))
    {
        let mut precision = T::one() / (s * s);
        let mut weighted = mu * precision;
        if let Some(c) = c {
            let pc = T::one() / (sc * sc);
            precision += pc;
            weighted += *c * pc;
        }
        *q = precision;
        *m = weighted / precision;
    }
    // the spin axis of a slowly spinning ball is poorly defined: its noise grows by the
    // spin's noise over the spin, σ_axis² + (σ_spin / spin)²
    let mut sigma = noise.ball;
    let spin = crate::real::larger(measured.spin_radps, sigma.spin_radps);
    let wobble = sigma.spin_radps / spin;
    sigma.spin_axis_rad = (sigma.spin_axis_rad * sigma.spin_axis_rad + wobble * wobble).root();
    let problem = Problem {
        model,
        y: measured.to_array(),
        sigma: sigma.to_array(),
        q: V7::from(q),
        m: V7::from(m),
    };
    let start = start(&problem, measured, &measured_club)?;
    let solution = iterate(&problem, start, max_iterations, tolerance)?;
    let mut e = posterior(&problem, &solution, club_data, summary, &sd_scale)?;
    e.consistency = consistency(
        &problem.residual(&solution.f),
        &solution.x,
        &measured_club,
        settings,
        &check,
    );
    Ok(e)
}

/// The order of the measured club data in the unknowns (face, path, loft, attack, –, –,
/// speed).
const CLUB_DATA: [Option<Datum>; 7] = [
    Some(Datum::FaceAngle),
    Some(Datum::ClubPath),
    Some(Datum::DynamicLoft),
    Some(Datum::AttackAngle),
    None,
    None,
    Some(Datum::ClubSpeed),
];

/// The consistency check at the most probable delivery `x` ([`Consistency`]): the cost's
/// terms `z` of the ball data (the normalised residuals `r`), of the measured club data and
/// of the prior, their sum of squares against the χ² bound of as many degrees of freedom
/// as data, and the largest measured `|z|` against `max_shift_sd`.
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), inline(never))]
fn consistency<T: Real>(
    r: &SVector<T, 5>,
    x: &V7<T>,
    measured_club: &[Option<T>; 7],
    settings: &Settings<T>,
    check: &Check<T>,
) -> Consistency<T> {
    let mut chi2 = T::zero();
    let mut dof: u8 = 5;
    let mut worst = (Datum::Club, -T::one());
    let mut worst_measured = T::zero();
    for (z, datum) in r.iter().zip(Datum::BALL) {
        chi2 += *z * *z;
        let a = z.abs();
        worst_measured = crate::real::larger(worst_measured, a);
        if a > worst.1 {
            worst = (datum, a);
        }
    }
    let prior_mean = settings.prior.mean.to_array();
    let prior_sd = settings.prior.sd.to_array();
    let club_sd = settings.noise.club.to_array();
    for (i, xi) in x.iter().enumerate() {
        let (Some(mu), Some(s)) = (prior_mean.get(i), prior_sd.get(i)) else {
            continue;
        };
        let z = (*xi - *mu) / *s;
        chi2 += z * z;
        if z.abs() > worst.1 {
            worst = (Datum::Club, z.abs());
        }
        if let (Some(Some(c)), Some(sc), Some(Some(datum))) =
            (measured_club.get(i), club_sd.get(i), CLUB_DATA.get(i))
        {
            let z = (*xi - *c) / *sc;
            chi2 += z * z;
            dof += 1;
            let a = z.abs();
            worst_measured = crate::real::larger(worst_measured, a);
            if a > worst.1 {
                worst = (*datum, a);
            }
        }
    }
    let bound = chi2_quantile(dof, check.tail_probability);
    Consistency {
        chi2,
        dof,
        bound,
        worst: worst.0,
        worst_sd: crate::real::larger(worst.1, T::zero()),
        // NaN-proof: consistent only when both tests pass on finite numbers
        consistent: chi2 <= bound && worst_measured <= check.max_shift_sd,
    }
}

/// A good start: the centre `m`, moved so that its launch matches the measured one to
/// first order (face by the launch direction, loft by the launch angle, speed by the ball
/// speed) where the device did not measure that datum. One forward evaluation.
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), inline(never))]
fn start<T: Real>(
    problem: &Problem<'_, T>,
    measured: &BallData<T>,
    measured_club: &[Option<T>; 7],
) -> Result<V7<T>> {
    let mut x = problem.m;
    let f = problem.predict(&x)?;
    let [face, _, loft, _, _, _, speed] = measured_club;
    if face.is_none()
        && let Some(v) = x.get_mut(0)
    {
        *v += measured.launch_direction_rad - f.launch_direction_rad;
    }
    if loft.is_none()
        && let Some(v) = x.get_mut(2)
    {
        *v += measured.launch_angle_rad - f.launch_angle_rad;
    }
    if speed.is_none()
        && f.ball_speed_mps > T::zero()
        && let Some(v) = x.get_mut(SPEED)
    {
        *v *= measured.ball_speed_mps / f.ball_speed_mps;
    }
    Ok(x)
}

/// Where the iteration stopped.
struct Solution<T: Real> {
    /// The unknowns.
    x: V7<T>,
    /// The normal matrix `Jᵀ J + Q` of the last Jacobian (the posterior precision).
    a: M7<T>,
    /// The last Jacobian of the normalised residuals.
    jac: Jacobian<T>,
    /// The prediction at `x`.
    f: BallData<T>,
    /// Iterations (Jacobians) used.
    iterations: u8,
}

/// The Levenberg–Marquardt loop: the solution, its normal matrix `A`, the Jacobian of the
/// normalised residuals and the prediction at the solution.
///
/// Its matrix algebra runs in small out-of-line steps ([`normal_equations`],
/// [`damped_step`], [`broyden_update`], ...): this frame, which sits under every forward
/// evaluation, holds only the iteration's state (the micro:bit's f64 estimate has 16 KiB
/// of stack for all of it; docs/firmware.md).
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), inline(never))]
fn iterate<T: Real>(
    problem: &Problem<'_, T>,
    start: V7<T>,
    max_iterations: u8,
    tolerance: T,
) -> Result<Solution<T>> {
    let unit = units::<T>();
    let mut x = start;
    let mut f = problem.predict(&x)?;
    let mut r = problem.residual(&f);
    let mut cost = problem.cost(&r, &x);
    let mut lambda = lit::<T>(LAMBDA_START);
    // the secant estimate S of the residuals' own curvature Σ r_k ∇²r_k, and the previous
    // iteration's Jacobian, gradient and step it is updated from
    let mut secant = M7::<T>::zeros();
    let mut previous: Option<(Jacobian<T>, V7<T>, V7<T>)> = None;
    // the last Jacobian with Broyden's rank-one update along the last step: good enough to
    // tell that the iteration has converged (and for the covariance), saving the seven
    // forward evaluations of a fresh Jacobian at the end
    let mut broyden: Option<Jacobian<T>> = None;
    for iteration in 1..=max_iterations {
        if let Some(jac) = broyden.take() {
            let (a, g) = normal_equations(problem, &jac, &r, &x);
            let (_, newton) = newton_step(&a, &mut secant, &g)?;
            if -g.dot(&newton) <= tolerance * tolerance {
                return Ok(Solution {
                    x,
                    a,
                    jac,
                    f,
                    iterations: iteration,
                });
            }
        }
        let jac = jacobian(problem, &x, &r, &unit, None)?;
        let (a, g) = normal_equations(problem, &jac, &r, &x);
        if let Some((jp, gp, s)) = &previous {
            update_secant(&mut secant, s, &(g - gp), &jac, jp, &r);
        }
        let (model, newton) = newton_step(&a, &mut secant, &g)?;
        // converged when the Newton step is below `tolerance` posterior σ: its Mahalanobis
        // length² is the Newton decrement −gᵀδ
        if -g.dot(&newton) <= tolerance * tolerance {
            return Ok(Solution {
                x,
                a,
                jac,
                f,
                iterations: iteration,
            });
        }
        let Some(Trial {
            step,
            mut next,
            f: mut fn_,
            r: mut rn,
            cost: mut cn,
        }) = damped_step(problem, &model, &a, &g, &x, cost, &mut lambda)
        else {
            // no damping lowers the cost: stationary to the precision
            return Ok(Solution {
                x,
                a,
                jac,
                f,
                iterations: iteration,
            });
        };
        // Along the step the cost is c(t) ≈ c₀ + 2(gᵀδ) t + κ t²; fitted through c(1) its
        // minimum t* = −gᵀδ / κ lies away from 1 where the Gauss–Newton model misjudges the
        // curvature (the prior-dominated directions, where the residuals' own curvature
        // counts): try it once.
        let slope = (g + g).dot(&step); // the cost's gradient is 2g
        let kappa = cn - cost - slope;
        if slope < T::zero() && kappa > T::zero() {
            let t = crate::real::smaller(-slope / (kappa + kappa), lit(MAX_STRETCH));
            if t > lit(MIN_STRETCH) || t < lit(1.0 / MIN_STRETCH) {
                let longer = step * t;
                let far = x + longer;
                if let Ok(ff) = problem.predict(&far) {
                    let rf = problem.residual(&ff);
                    let cf = problem.cost(&rf, &far);
                    if cf < cn {
                        (next, fn_, rn, cn) = (far, ff, rf, cf);
                    }
                }
            }
        }
        let step = next - x;
        broyden = broyden_update(&jac, &r, &rn, &step);
        previous = Some((jac, g, step));
        x = next;
        f = fn_;
        r = rn;
        cost = cn;
    }
    Err(Error::NoConvergence)
}

/// The normal equations of the normalised residuals `r` with Jacobian `J` at `x`: `A =
/// JᵀJ + Q` and the (half) gradient `g = Jᵀr + Q(x − m)`.
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), inline(never))]
fn normal_equations<T: Real>(
    problem: &Problem<'_, T>,
    jac: &Jacobian<T>,
    r: &SVector<T, 5>,
    x: &V7<T>,
) -> (M7<T>, V7<T>) {
    let jt = jac.transpose();
    let a = jt * jac + M7::from_diagonal(&problem.q);
    let g = jt * r + problem.q.component_mul(&(x - problem.m));
    (a, g)
}

/// An accepted Levenberg–Marquardt step: the step, the new point, its prediction,
/// residuals and cost.
struct Trial<T: Real> {
    step: V7<T>,
    next: V7<T>,
    f: BallData<T>,
    r: SVector<T, 5>,
    cost: T,
}

/// The first of up to `MAX_REJECTS` damped steps `(M + λ diag A) δ = −g` from `x` that
/// lowers `cost` (λ grown tenfold per rejection, shrunk tenfold on acceptance), or `None`.
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), inline(never))]
fn damped_step<T: Real>(
    problem: &Problem<'_, T>,
    model: &M7<T>,
    a: &M7<T>,
    g: &V7<T>,
    x: &V7<T>,
    cost: T,
    lambda: &mut T,
) -> Option<Trial<T>> {
    for _ in 0..MAX_REJECTS {
        let damped = model + M7::from_diagonal(&(a.diagonal() * *lambda));
        let Ok(step) = solve_spd(&damped, &(-g)) else {
            *lambda *= lit(LAMBDA_GROWTH);
            continue;
        };
        let next = x + step;
        if let Ok(f) = problem.predict(&next) {
            let r = problem.residual(&f);
            let cn = problem.cost(&r, &next);
            if cn <= cost {
                *lambda = crate::real::larger(*lambda / lit(LAMBDA_GROWTH), lit(LAMBDA_MIN));
                return Some(Trial {
                    step,
                    next,
                    f,
                    r,
                    cost: cn,
                });
            }
        }
        *lambda *= lit(LAMBDA_GROWTH);
    }
    None
}

/// Broyden's rank-one update of the Jacobian `J` along the step `s` (residuals `r` → `rₙ`),
/// in the unknowns' scaled norm: `J + (rₙ − r − J s) (W s)ᵀ / (sᵀ W s)`, `W = diag(1/u²)`;
/// `None` for a zero step or a non-finite update.
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), inline(never))]
fn broyden_update<T: Real>(
    jac: &Jacobian<T>,
    r: &SVector<T, 5>,
    rn: &SVector<T, 5>,
    step: &V7<T>,
) -> Option<Jacobian<T>> {
    let weight = V7::from(UNIT.map(|u| T::one() / lit::<T>(u * u)));
    let scaled = step.component_mul(&weight);
    let norm = step.dot(&scaled);
    if !(norm > T::zero()) {
        return None;
    }
    let update = (rn - r - jac * step) * (scaled.transpose() / norm);
    update.iter().all(|v| v.is_finite()).then(|| jac + update)
}

/// The Newton step of the model Hessian: Gauss–Newton's `a` plus the secant term where
/// that keeps the step a descent direction (else the secant term is dropped).
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), inline(never))]
fn newton_step<T: Real>(a: &M7<T>, secant: &mut M7<T>, g: &V7<T>) -> Result<(M7<T>, V7<T>)> {
    let model = a + *secant;
    match solve_spd(&model, &(-g)) {
        Ok(d) if g.dot(&d) < T::zero() => Ok((model, d)),
        _ => {
            *secant = M7::zeros();
            let d = solve_spd(a, &(-g)).map_err(|_| Error::IllPosed)?;
            Ok((*a, d))
        }
    }
}

/// The Dennis–Gay–Welsch secant update of `S ≈ Σ r_k ∇²r_k` (NL2SOL: Dennis, Gay &
/// Welsch, ACM TOMS 7, 1981), with its sizing: for the step `s`, the change `y` of the
/// (half) gradient and `y# = (J₊ − J)ᵀ r₊`, `S ← τS` with `τ = min(1, |sᵀy#| / |sᵀSs|)`,
/// then `S₊ = S + (w yᵀ + y wᵀ)/yᵀs − (wᵀs) y yᵀ/(yᵀs)²`, `w = y# − S s`.
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), inline(never))]
fn update_secant<T: Real>(
    secant: &mut M7<T>,
    s: &V7<T>,
    y: &V7<T>,
    jac: &Jacobian<T>,
    previous_jac: &Jacobian<T>,
    r: &SVector<T, 5>,
) {
    let ysharp = &((jac - previous_jac).transpose() * r);
    let sss = s.dot(&(*secant * s));
    let ssy = s.dot(ysharp).abs();
    if sss.abs() > ssy {
        *secant *= ssy / sss.abs();
    }
    let ys = y.dot(s);
    if !(ys > T::zero()) {
        return;
    }
    let w = ysharp - *secant * s;
    let update =
        (w * y.transpose() + y * w.transpose()) / ys - (y * y.transpose()) * (w.dot(s) / (ys * ys));
    if update.iter().all(|v| v.is_finite()) {
        *secant += update;
    }
}

/// Forward differences of the normalised residuals (a backward difference where the
/// forward point is outside the model's domain).
fn jacobian<T: Real>(
    problem: &Problem<'_, T>,
    x: &V7<T>,
    r: &SVector<T, 5>,
    unit: &V7<T>,
    skip: Option<usize>,
) -> Result<Jacobian<T>> {
    let mut jac = Jacobian::<T>::zeros();
    for (i, (mut column, h)) in jac.column_iter_mut().zip(unit.iter()).enumerate() {
        if skip == Some(i) {
            continue;
        }
        let h = *h;
        let mut xp = *x;
        if let Some(v) = xp.get_mut(i) {
            *v += h;
        }
        let (rp, h) = match problem.predict(&xp) {
            Ok(fp) => (problem.residual(&fp), h),
            Err(_) => {
                if let Some(v) = xp.get_mut(i) {
                    *v -= h + h;
                }
                (problem.residual(&problem.predict(&xp)?), -h)
            }
        };
        column.copy_from(&((rp - r) / h));
    }
    Ok(jac)
}

/// The profile posterior along the strike height: the first probe on either side (in
/// Laplace σ of the height; a side found wider than this is probed again at twice its
/// width), the farthest probe (also the floor of a width, `t/FAR`), the Gauss–Newton
/// relaxations per probe (one relaxation, or Broyden/chord Jacobians instead of fresh
/// ones, lost the calibration: docs/estimate.md §4), and the ramp over which the second
/// probe's width is blended in, as a fraction of the first probe: from `PROBE` to
/// `PROBE·(1 + BLEND)` (a switch at `PROBE` made f32 and f64 differ by up to 1.3σ;
/// docs/estimate.md §4).
const PROBE: f64 = 1.5;
const FAR: f64 = 10.0;
const RELAX: usize = 2;
const BLEND: f64 = 0.2;
/// Index of the strike height in the unknowns.
const HEIGHT: usize = 5;

/// The posterior's covariance `A⁻¹` of the symmetric positive definite normal matrix.
///
/// # Errors
/// [`Error::IllPosed`] when `A` is not positive definite in the precision.
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), inline(never))]
fn inverse<T: Real>(a: &M7<T>) -> Result<M7<T>> {
    Cholesky::factor(a)
        .and_then(|c| c.inverse())
        .map_err(|_| Error::IllPosed)
}

/// `A⁻¹ b` for a symmetric `A` (an error unless it is positive definite).
fn solve_spd<T: Real>(a: &M7<T>, b: &V7<T>) -> Result<V7<T>> {
    Cholesky::factor(a)?.solve(b)
}

/// The profile cost: the cost minimised over every unknown but the strike height, from
/// `x0` (its height held), by `RELAX` Gauss–Newton steps on fresh forward-difference
/// Jacobians (six columns: the height's is not needed), each step kept only if it lowers
/// the cost. The point and its cost.
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), inline(never))]
fn relax<T: Real>(problem: &Problem<'_, T>, x0: V7<T>) -> Option<(V7<T>, T)> {
    let unit = units::<T>();
    let mut x = x0;
    let mut r = problem.residual(&problem.predict(&x).ok()?);
    let mut cost = problem.cost(&r, &x);
    for _ in 0..RELAX {
        let jac = jacobian(problem, &x, &r, &unit, Some(HEIGHT)).ok()?;
        let (mut a, mut g) = normal_equations(problem, &jac, &r, &x);
        // the height held: its row and column of the normal equations replaced by δh = 0
        a.row_mut(HEIGHT).fill(T::zero());
        a.column_mut(HEIGHT).fill(T::zero());
        if let Some(v) = a.get_mut((HEIGHT, HEIGHT)) {
            *v = T::one();
        }
        if let Some(v) = g.get_mut(HEIGHT) {
            *v = T::zero();
        }
        let Ok(step) = solve_spd(&a, &(-g)) else {
            break;
        };
        let next = x + step;
        let Ok(f) = problem.predict(&next) else {
            break;
        };
        let rn = problem.residual(&f);
        let cn = problem.cost(&rn, &next);
        if !(cn < cost) {
            break;
        }
        (x, r, cost) = (next, rn, cn);
    }
    Some((x, cost))
}

/// The posterior along the valley of the strike height: mean shift and covariance of the
/// delivery, from the profile cost (the cost minimised with the height held) probed on
/// either side of the MAP.
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), inline(never))]
fn valley<T: Real>(
    problem: &Problem<'_, T>,
    x: &V7<T>,
    r: &SVector<T, 5>,
    cov: &M7<T>,
) -> Option<(V7<T>, M7<T>)> {
    let chh = cov.get((HEIGHT, HEIGHT)).copied()?;
    if !(chh > T::zero()) {
        return None;
    }
    // the height's conditional direction, one Laplace σ long (sᵀ A s = 1)
    let s: V7<T> = cov.column(HEIGHT) / chh.root();
    let c0 = problem.cost(r, x);
    let probe = lit::<T>(PROBE);
    let far = lit::<T>(FAR);
    // per side: the profile's Gaussian width σ± (in Laplace σ) and the valley's direction
    // d± (the delivery per unit t)
    let mut sides = [(T::one(), s), (T::one(), s)];
    for ((width, dir), sign) in sides.iter_mut().zip([T::one(), -T::one()]) {
        let mut t = probe;
        let mut start = s;
        // the first probe's width and direction, once it asks for a second
        let mut near: Option<(T, V7<T>)> = None;
        // one call site of `relax` (its frame is large: the micro:bit's stack holds one)
        for _ in 0..2 {
            let Some((xp, cp)) = relax(problem, x + start * (sign * t)) else {
                break;
            };
            let dc = crate::real::larger(cp - c0, t * t / (far * far));
            let (w, d) = (t / dc.root(), (xp - x) / (sign * t));
            if let Some((w_near, d_near)) = near {
                // a side wider than the probe is probed again at twice its width, farther
                // along the valley, and that estimate blended in as the first width grows
                // from `PROBE` to `PROBE·(1 + BLEND)`: the summary stays continuous in the data
                let blend = crate::real::smaller((w_near - probe) / (probe * lit(BLEND)), T::one());
                *width = w_near + (w - w_near) * blend;
                *dir = d_near + (d - d_near) * blend;
                break;
            }
            (*width, *dir) = (w, d);
            if !(w > probe) {
                break;
            }
            near = Some((w, d));
            t = crate::real::smaller(w + w, far);
            start = d;
        }
    }
    Some(split_normal(sides, &s, cov))
}

/// The valley's posterior from its two sides' widths σ± and directions d± (per Laplace σ
/// along the height's conditional direction `s`) and the Laplace covariance: mean shift
/// and covariance, with the covariance along `s` replaced by the split normal's.
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), inline(never))]
fn split_normal<T: Real>(sides: [(T, V7<T>); 2], s: &V7<T>, cov: &M7<T>) -> (V7<T>, M7<T>) {
    let [(up, du), (down, dd)] = sides;
    // split normal: p(t) ∝ exp(−t²/2σ±²) for t ≷ 0, a = √(2/π)/(σ₊ + σ₋);
    // E[t; t>0] = a σ₊², E[t; t<0] = −a σ₋², E[t²; t≷0] = σ±³/(σ₊ + σ₋)
    let sum = up + down;
    let a = lit::<T>(core::f64::consts::FRAC_2_PI).root() / sum;
    let mean = du * (a * up * up) - dd * (a * down * down);
    let second = du * du.transpose() * (up * up * up / sum)
        + dd * dd.transpose() * (down * down * down / sum);
    let perp = cov - s * s.transpose();
    (mean, perp + second - mean * mean.transpose())
}

/// The posterior: value and 1σ of every datum, the mean and `√(cᵀ Σ c)` for its gradient
/// `c`, with `Σ` the Laplace covariance `A⁻¹` in every direction but the strike height's
/// valley, where the profile posterior replaces it; reported as `D Σ D`, `D =
/// diag(sd_scale)` (the posterior σ calibration, [`Settings::sd_scale`]).
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), inline(never))]
fn posterior<T: Real>(
    problem: &Problem<'_, T>,
    solution: &Solution<T>,
    club_data: &ClubData<T>,
    summary: Posterior,
    sd_scale: &Unknowns<T>,
) -> Result<Estimate<T>> {
    let Solution { x, a, f, .. } = solution;
    let mut cov = inverse(a)?;
    let mut mean = *x;
    let profile = match summary {
        Posterior::Laplace => None,
        Posterior::Profile => valley(problem, x, &problem.residual(f), &cov),
    };
    if let Some((shift, c)) = profile {
        mean += shift;
        cov = c;
    }
    summarise(problem, solution, club_data, &mean, &cov, sd_scale)
}

/// The estimate from the posterior's `mean` and covariance `cov` (before the σ
/// calibration `sd_scale`), with the smash factor and the residuals of the most probable
/// delivery (`solution`). Out of line: [`posterior`]'s frame sits under the valley's
/// forward evaluations.
#[cfg_attr(all(target_os = "none", not(target_abi = "eabihf")), inline(never))]
fn summarise<T: Real>(
    problem: &Problem<'_, T>,
    solution: &Solution<T>,
    club_data: &ClubData<T>,
    mean: &V7<T>,
    cov: &M7<T>,
    sd_scale: &Unknowns<T>,
) -> Result<Estimate<T>> {
    let Solution {
        x,
        jac,
        f,
        iterations,
        ..
    } = solution;
    let map_speed = x.get(SPEED).copied().unwrap_or_else(T::zero);
    let d = V7::<T>::from(sd_scale.to_array());
    let cov = cov.component_mul(&(d * d.transpose()));
    let sd = |c: V7<T>| -> Result<T> {
        let var = c.dot(&(cov * c));
        Ok(if var > T::zero() {
            var.root()
        } else {
            T::zero()
        })
    };
    let e = |i: usize| V7::<T>::from_fn(|k, _| if k == i { T::one() } else { T::zero() });
    let u = unknowns(mean);
    // the smash factor and the residuals are those of the most probable delivery
    let speed = map_speed;
    let ball_speed = f.ball_speed_mps;
    let smash = if speed > T::zero() {
        ball_speed / speed
    } else {
        T::zero()
    };
    // d smash / dx = (d ball speed / dx) / v − (ball speed / v²) e_v
    let sigma_speed = problem.sigma.first().copied().unwrap_or_else(T::one);
    let mut smash_gradient: V7<T> = jac.row(0).transpose() * sigma_speed;
    if speed > T::zero() {
        smash_gradient /= speed;
        if let Some(g) = smash_gradient.get_mut(SPEED) {
            *g -= smash / speed;
        }
    }
    let value = ClubEstimate {
        face_angle_rad: u.face_angle_rad,
        club_path_rad: u.club_path_rad,
        face_to_path_rad: u.face_angle_rad - u.club_path_rad,
        dynamic_loft_rad: u.dynamic_loft_rad,
        attack_angle_rad: u.attack_angle_rad,
        spin_loft_rad: u.dynamic_loft_rad - u.attack_angle_rad,
        impact_toe_m: u.impact_toe_m,
        impact_height_m: u.impact_height_m,
        club_speed_mps: u.club_speed_mps,
        smash_factor: smash,
    };
    let sd = ClubEstimate {
        face_angle_rad: sd(e(0))?,
        club_path_rad: sd(e(1))?,
        face_to_path_rad: sd(e(0) - e(1))?,
        dynamic_loft_rad: sd(e(2))?,
        attack_angle_rad: sd(e(3))?,
        spin_loft_rad: sd(e(2) - e(3))?,
        impact_toe_m: sd(e(4))?,
        impact_height_m: sd(e(5))?,
        club_speed_mps: sd(e(SPEED))?,
        smash_factor: sd(smash_gradient)?,
    };
    let all_finite = value
        .to_array()
        .iter()
        .chain(sd.to_array().iter())
        .all(|v| v.is_finite());
    if !all_finite {
        return Err(Error::IllPosed);
    }
    Ok(Estimate {
        value,
        sd,
        residual: BallData::from_array(difference(f, &problem.y)),
        iterations: *iterations,
        club_speed_estimated: club_data.club_speed_mps.is_none(),
        // filled in by `run`
        consistency: Consistency {
            chi2: T::zero(),
            dof: 5,
            bound: T::zero(),
            worst: Datum::Club,
            worst_sd: T::zero(),
            consistent: true,
        },
    })
}
