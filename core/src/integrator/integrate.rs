//! The integrators: explicit Euler and classical RK4 with a fixed step, and the adaptive
//! embedded Dormand–Prince 5(4) pair (Dormand & Prince 1980, "A family of embedded
//! Runge–Kutta formulae", J. Comput. Appl. Math. 6, 19–26) with local extrapolation, FSAL,
//! a max-norm mixed error test `|eᵢ| ≤ atol + rtol·max(|y₀ᵢ|, |y₁ᵢ|)` and the standard
//! step controller `h ← h · clamp(0.9·err^(−3/16), 0.2, 5)` (no growth right after a
//! rejection; Hairer, Nørsett & Wanner, *Solving ODEs I*, §II.4).
//!
//! Every driver hands each accepted step to the [`Tracker`], which finds the apex and the
//! landing inside the step, and counts force evaluations (calls of the right-hand side).

use super::events::{Landing, Step, Tracker};
use crate::aero::{Rhs, State};
use crate::error::{Error, Result};
use crate::real::{Real, larger, lit, smaller};
use crate::trajectory::Stats;

/// `y + h Σ cⱼ kⱼ`, panic-free (iterators over fixed arrays).
#[inline(always)]
fn combine<T: Real, const K: usize>(
    y: &State<T>,
    h: T,
    c: [f64; K],
    k: [&State<T>; K],
) -> State<T> {
    let mut out = *y;
    for (cj, kj) in c.iter().zip(k.iter()) {
        let w = h * lit::<T>(*cj);
        for (o, x) in out.iter_mut().zip(kj.iter()) {
            *o += w * *x;
        }
    }
    out
}

fn all_finite<T: Real>(y: &State<T>) -> bool {
    y.iter().all(|x| x.is_finite())
}

/// The classic explicit methods with a fixed step `h` (the last step is cut to the time
/// limit). `rk4 = false`: Euler, `y₁ = y₀ + h f₀` (1 evaluation per step);
/// `rk4 = true`: classical Runge–Kutta (4 per step). `f₁ = f(y₁)` is reused as the next
/// step's `f₀`, so the Hermite interpolant costs nothing extra.
pub(crate) fn fixed<T: Real, R: Rhs<T>>(
    rhs: &R,
    y0: State<T>,
    h: T,
    rk4: bool,
    limit: T,
    tracker: &mut Tracker<'_, '_, T>,
    stats: &mut Stats,
) -> Result<Landing<T>> {
    let mut y = y0;
    let mut f0 = rhs.eval(&y);
    stats.force_evaluations = 1;
    let mut n: u32 = 0;
    loop {
        // t = n·h (not a running sum: no drift in f32 over thousands of steps).
        let t = lit::<T>(f64::from(n)) * h;
        let hh = smaller(h, limit - t);
        if !(hh > T::zero()) {
            return Err(Error::TimeLimit);
        }
        let y1 = if rk4 {
            let half = hh * lit(0.5);
            let k2 = rhs.eval(&combine(&y, half, [1.0], [&f0]));
            let k3 = rhs.eval(&combine(&y, half, [1.0], [&k2]));
            let k4 = rhs.eval(&combine(&y, hh, [1.0], [&k3]));
            stats.force_evaluations = stats.force_evaluations.saturating_add(3);
            combine(
                &y,
                hh / lit(6.0),
                [1.0, 2.0, 2.0, 1.0],
                [&f0, &k2, &k3, &k4],
            )
        } else {
            combine(&y, hh, [1.0], [&f0])
        };
        if !(all_finite(&y1) && rhs.step_is_bounded(&y, &y1, hh)) {
            return Err(Error::Unstable);
        }
        let f1 = rhs.eval(&y1);
        stats.force_evaluations = stats.force_evaluations.saturating_add(1);
        stats.steps = stats.steps.saturating_add(1);
        let step = Step {
            h: hh,
            y0: &y,
            y1: &y1,
            f0: &f0,
            f1: &f1,
            mid: None,
        };
        if let Some(th) = tracker.on_step(t, &step)? {
            return Ok(Landing::in_step(t, th, &step));
        }
        y = y1;
        f0 = f1;
        n = n.saturating_add(1);
    }
}

/// Tolerances and step bounds of the adaptive integrator (validated by the caller).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Adaptive<T> {
    pub(crate) rtol: T,
    pub(crate) atol: T,
    pub(crate) initial_step: T,
    pub(crate) max_step: T,
    /// Redo the landing step to end at the landing (once): for right-hand sides that are
    /// not smooth at the landing height.
    pub(crate) refine_landing: bool,
}

// Dormand–Prince 5(4) tableau (autonomous system: the nodes cᵢ are not needed).
const A2: [f64; 1] = [1.0 / 5.0];
const A3: [f64; 2] = [3.0 / 40.0, 9.0 / 40.0];
const A4: [f64; 3] = [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0];
const A5: [f64; 4] = [
    19372.0 / 6561.0,
    -25360.0 / 2187.0,
    64448.0 / 6561.0,
    -212.0 / 729.0,
];
const A6: [f64; 5] = [
    9017.0 / 3168.0,
    -355.0 / 33.0,
    46732.0 / 5247.0,
    49.0 / 176.0,
    -5103.0 / 18656.0,
];
/// 5th-order weights for k₁, k₃..k₆ (b₂ = b₇ = 0).
const B: [f64; 5] = [
    35.0 / 384.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
];
/// Error weights b − b̂ for k₁, k₃..k₇.
const E: [f64; 6] = [
    71.0 / 57600.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339_200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// One Dormand–Prince step's stages `k₃..k₆` (what the error estimate and the dense output
/// need; `k₂` is not) and its 5th-order result `y₁`.
pub(crate) struct Stages<T> {
    pub(crate) k3: State<T>,
    pub(crate) k4: State<T>,
    pub(crate) k5: State<T>,
    pub(crate) k6: State<T>,
    pub(crate) y1: State<T>,
}

/// The stages of one Dormand–Prince step of size `h` from `y` (with `k₁ = f(y)`): 5
/// evaluations.
#[inline(always)]
pub(crate) fn dormand_prince_stages<T: Real, R: Rhs<T>>(
    rhs: &R,
    y: &State<T>,
    k1: &State<T>,
    h: T,
) -> Stages<T> {
    let k2 = stage(rhs, &combine(y, h, A2, [k1]));
    let k3 = stage(rhs, &combine(y, h, A3, [k1, &k2]));
    let k4 = stage(rhs, &combine(y, h, A4, [k1, &k2, &k3]));
    let k5 = stage(rhs, &combine(y, h, A5, [k1, &k2, &k3, &k4]));
    let k6 = stage(rhs, &combine(y, h, A6, [k1, &k2, &k3, &k4, &k5]));
    let y1 = combine(y, h, B, [k1, &k3, &k4, &k5, &k6]);
    Stages { k3, k4, k5, k6, y1 }
}

/// The error test's weights `1/(atol + rtol·max(|y₀ᵢ|, |y₁ᵢ|))`.
#[inline(always)]
pub(crate) fn error_weights<T: Real>(y0: &State<T>, y1: &State<T>, cfg: &Adaptive<T>) -> State<T> {
    let mut weight = [T::zero(); 7];
    for ((w, a), b) in weight.iter_mut().zip(y0.iter()).zip(y1.iter()) {
        // `larger` by one comparison: `y₀` is an accepted (finite) state, and a NaN in
        // `y₁` leaves `|y₀ᵢ|`, as `larger` does (the step is then rejected anyway).
        let (a, b) = (a.abs(), b.abs());
        *w = T::one() / (cfg.atol + cfg.rtol * if b > a { b } else { a });
    }
    weight
}

/// The scaled max-norm of the embedded error estimate `e = h Σ (bᵢ − b̂ᵢ) kᵢ` over
/// `k₁, k₃..k₇` (≤ 1 passes; NaN gives NaN, a rejection).
#[inline(always)]
pub(crate) fn scaled_error<T: Real>(h: T, k: [&State<T>; 6], weight: &State<T>) -> T {
    // Started from the first term rather than from zeros (7 additions fewer; `0 + x`
    // differs from `x` only in the sign of a zero, which `|eᵢ|` drops).
    let [e1, rest @ ..] = E;
    let [k1, others @ ..] = k;
    let mut first = [T::zero(); 7];
    let w1 = h * lit::<T>(e1);
    for (o, x) in first.iter_mut().zip(k1.iter()) {
        *o = w1 * *x;
    }
    let e = combine(&first, h, rest, others);
    let mut err = T::zero();
    for (ei, w) in e.iter().zip(weight.iter()) {
        let r = ei.abs() * *w;
        // `!(r <= err)` also propagates NaN into a rejection.
        if !(r <= err) {
            err = r;
        }
    }
    err
}

/// The smaller of `a` and `b`, neither NaN: one comparison (`smaller` also handles NaN).
#[inline(always)]
fn below<T: Real>(a: T, b: T) -> T {
    if a > b { b } else { a }
}

/// The larger of `a` and `b`, neither NaN: one comparison (`larger` also handles NaN).
#[inline(always)]
fn above<T: Real>(a: T, b: T) -> T {
    if a < b { b } else { a }
}

/// `x^(−3/16)` by four square roots (`x^(1/8)·x^(1/16)`), for `x > 0`: the step
/// controller's exponent. 3/16 = 0.1875 sits between the elementary controller's 1/5 and
/// the PI controller's 0.2 − 0.75·β (Hairer & Wanner), and costs four hardware `sqrt`s
/// instead of a software `pow` (which dominated the per-step overhead on Cortex-M4F).
#[inline]
fn inv_root_3_16<T: Real>(x: T) -> T {
    let r8 = x.root().root().root();
    T::one() / (r8 * r8.root())
}

/// One Dormand–Prince stage's force evaluation: inlined where the precision is in hardware
/// (hosts, where `eval` is inlined anyway, and `f32` on hard-float ARM: ≈ 40 instructions a
/// call saved on the Cortex-M4F, docs/performance.md); called where it is in software (each
/// copy there is kilobytes of library calls).
#[inline(always)]
fn stage<T: Real, R: Rhs<T>>(rhs: &R, y: &State<T>) -> State<T> {
    if !cfg!(target_os = "none") || (cfg!(target_abi = "eabihf") && core::mem::size_of::<T>() == 4)
    {
        rhs.eval_inlined(y)
    } else {
        rhs.eval(y)
    }
}

/// Adaptive Dormand–Prince 5(4) to the landing.
pub(crate) fn dormand_prince<T: Real, R: Rhs<T>>(
    rhs: &R,
    y0: State<T>,
    cfg: Adaptive<T>,
    limit: T,
    tracker: &mut Tracker<'_, '_, T>,
    stats: &mut Stats,
) -> Result<Landing<T>> {
    let mut cfg = cfg;
    let mut y = y0;
    // (Called, not inlined: once a flight, and a seventh inlined copy cost the M4F's
    // flight 156 instructions in register shuffling.)
    let mut k1 = rhs.eval(&y);
    stats.force_evaluations = 1;
    let mut t = T::zero();
    let mut h = smaller(cfg.initial_step, cfg.max_step);
    let mut rejected_last = false;
    let mut refined = false;
    let (safety, grow, shrink) = (lit::<T>(0.9), lit::<T>(5.0), lit::<T>(0.2));
    let eps16 = T::default_epsilon() * lit(16.0);
    loop {
        if stats.steps.saturating_add(stats.rejected_steps) >= super::MAX_ADAPTIVE_STEPS {
            return Err(Error::StepLimit);
        }
        let remaining = limit - t;
        if !(remaining > T::zero()) {
            return Err(Error::TimeLimit);
        }
        // (Neither is NaN: `h` is finite and positive, `remaining` positive.)
        h = below(h, remaining);
        // The stages written out (as `dormand_prince_stages`): through the shared function
        // the compiler keeps the stages in memory, which costs the flight (docs/flight.md).
        let k2 = stage(rhs, &combine(&y, h, A2, [&k1]));
        let k3 = stage(rhs, &combine(&y, h, A3, [&k1, &k2]));
        let k4 = stage(rhs, &combine(&y, h, A4, [&k1, &k2, &k3]));
        let k5 = stage(rhs, &combine(&y, h, A5, [&k1, &k2, &k3, &k4]));
        let k6 = stage(rhs, &combine(&y, h, A6, [&k1, &k2, &k3, &k4, &k5]));
        let y1 = combine(&y, h, B, [&k1, &k3, &k4, &k5, &k6]);
        // The error test's weights need only y₀ and y₁: their divisions run beside the
        // last evaluation instead of after it.
        let weight = error_weights(&y, &y1, &cfg);
        let k7 = stage(rhs, &y1);
        stats.force_evaluations = stats.force_evaluations.saturating_add(6);
        let err = scaled_error(h, [&k1, &k3, &k4, &k5, &k6, &k7], &weight);
        if err <= T::one() && crate::real::all_finite(&y1) {
            let step = Step {
                h,
                y0: &y,
                y1: &y1,
                f0: &k1,
                f1: &k7,
                mid: Some([&k3, &k4, &k5, &k6]),
            };
            // Once: redo the step to end at the landing, so the landing state comes from a
            // Runge–Kutta step rather than from the interpolant across a non-smooth point
            // (the wind profile at the ground).
            // And at a grazing landing (see `super::GRAZING_LANDING_RAD`).
            let refine = if cfg.refine_landing {
                tracker.landing_in(&step)
            } else if !refined && tracker.ends_below(&step) {
                tracker.grazing_landing(&step)
            } else {
                None
            };
            if let Some(th) = refine {
                cfg.refine_landing = false;
                refined = true;
                if th < T::one() && th > T::zero() {
                    // The discarded step counts as rejected (its evaluations are spent).
                    stats.rejected_steps = stats.rejected_steps.saturating_add(1);
                    h *= th;
                    continue;
                }
            }
            stats.steps = stats.steps.saturating_add(1);
            // (On hosts, a step without events makes no call: `Tracker::quiet`.)
            if (cfg!(target_os = "none") || !tracker.quiet(&step))
                && let Some(th) = tracker.on_step(t, &step)?
            {
                return Ok(Landing::in_step(t, th, &step));
            }
            t += h;
            y = y1;
            k1 = k7;
            // (`err ∈ [0, 1]`, `h` finite and positive: no NaN here, so plain comparisons
            // rather than `smaller`/`larger`, which also handle NaN.)
            let mut factor = if err > T::zero() {
                below(safety * inv_root_3_16(err), grow)
            } else {
                grow
            };
            if rejected_last {
                factor = below(factor, T::one());
            }
            h = below(h * above(factor, shrink), cfg.max_step);
            rejected_last = false;
        } else {
            stats.rejected_steps = stats.rejected_steps.saturating_add(1);
            let factor = if err.is_finite() {
                larger(safety * inv_root_3_16(err), shrink)
            } else {
                shrink
            };
            h *= smaller(factor, safety);
            rejected_last = true;
            if !(h > eps16 * larger(t, T::one())) {
                return Err(Error::StepSizeUnderflow);
            }
        }
    }
}
