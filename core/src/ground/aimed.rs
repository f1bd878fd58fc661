//! A hop in one aimed Dormand–Prince step: the step ends where the parabola of the hop's
//! initial force comes back to the ground plane, and the landing is found by a short
//! Taylor expansion about the step's end instead of a root search on the interpolant.
//!
//! With the step's end state `(p₁, v₁, s₁)`, its force `a₁` (the step's last, FSAL,
//! evaluation) and that force's instantaneous rate `j₁` (`aero::Dynamics::rates_now`), the
//! landing is `Δ` after the end, the root near 0 of the plane's height to second order,
//!
//! ```text
//! δ + v_n Δ + a_n Δ²/2 = 0,   Δ = 2δ / (√(v_n² − 2 a_n δ) − v_n)      (δ = n̂·p₁ − c, v_n < 0)
//! p = p₁ + v₁Δ + a₁Δ²/2 + j₁Δ³/6,   v = v₁ + a₁Δ + j₁Δ²/2,   s = s₁ + ṡ₁Δ + s̈₁Δ²/2
//! ```
//!
//! The parabola misses the landing by a few per cent of the hop (`|Δ|` a few tens of
//! milliseconds for a driver's first hop; about 0.1 s of 1.6 s), where the dropped terms
//! (`d²a/dt²`, the factors' spin term) move a driver's first hop by about a millimetre a
//! second (unit test `ground::hop::tests::aimed_hop_matches_the_integrated_hop`). The step keeps the integrator's error test; a step that
//! fails it, or a correction longer than [`AIMED_MAX_CORRECTION`] of the step, returns
//! `None` and the caller integrates the hop with the event search instead.

use crate::aero::{Dynamics, S, State};
use crate::integrator::events::Step;
use crate::integrator::integrate::{
    Adaptive, Stages, dormand_prince_stages, error_weights, scaled_error,
};
use crate::real::{Real, all_finite, at_least, lit};
use crate::trajectory::{Contact, Plane, Recorder, Stats};
use nalgebra::Vector3;

/// Largest landing correction `|Δ|` past or before the aimed step's end, as a fraction of
/// the step.
pub const AIMED_MAX_CORRECTION: f64 = 0.25;

/// The hop from `from` (its state `y0`, the square `spin_sq` of its spin `y0[S]`, spin
/// magnitude and unit axis as in `dynamics`) to
/// its landing on `plane`, in one aimed step at the hop tolerances `cfg` within `limit`
/// seconds; `None` when the step is rejected or the landing is too far from its end (see
/// the module docs). Evaluations and the step count into `stats` either way.
#[allow(clippy::too_many_arguments)]
pub(crate) fn aimed_hop<T: Real>(
    dynamics: &Dynamics<'_, T>,
    from_time: T,
    y0: &State<T>,
    spin_sq: T,
    plane: &Plane<T>,
    cfg: &Adaptive<T>,
    limit: T,
    recorder: Option<&mut Recorder<'_, T>>,
    stats: &mut Stats,
) -> Option<Contact<T>> {
    let n = plane.normal;
    // (The spin laws from the spin's square: not waiting on its square root.)
    let f0 = dynamics.forces_given_spin_sq(y0, spin_sq);
    stats.force_evaluations = stats.force_evaluations.saturating_add(1);
    let k1 = f0.derivative(y0);
    let vn0 = n.dot(&Vector3::new(y0[3], y0[4], y0[5]));
    let h = lit::<T>(-2.0) * vn0 / f0.acceleration.dot(&n);
    if !(h > T::zero() && h <= limit && h <= cfg.max_step) {
        return None;
    }
    let Stages { k3, k4, k5, k6, y1 } = dormand_prince_stages(dynamics, y0, &k1, h);
    let weight = error_weights(y0, &y1, cfg);
    let f1 = dynamics.forces(&y1);
    let k7 = f1.derivative(&y1);
    stats.force_evaluations = stats.force_evaluations.saturating_add(6);
    let err = scaled_error(h, [&k1, &k3, &k4, &k5, &k6, &k7], &weight);
    let landing = (err <= T::one() && all_finite(&y1))
        .then(|| {
            let p1 = Vector3::new(y1[0], y1[1], y1[2]);
            let v1 = Vector3::new(y1[3], y1[4], y1[5]);
            let delta = n.dot(&p1) - plane.offset;
            let vn = v1.dot(&n);
            let disc = vn * vn - lit::<T>(2.0) * f1.acceleration.dot(&n) * delta;
            let dt = lit::<T>(2.0) * delta / (disc.root() - vn);
            let within = dt.abs() <= lit::<T>(AIMED_MAX_CORRECTION) * h;
            (vn < T::zero() && within).then_some((p1, v1, dt))
        })
        .flatten();
    let Some((p1, v1, dt)) = landing else {
        stats.rejected_steps = stats.rejected_steps.saturating_add(1);
        return None;
    };
    stats.steps = stats.steps.saturating_add(1);
    let a1 = f1.acceleration;
    let (j1, spin_jerk) = dynamics.rates_now(&f1);
    let half = lit::<T>(0.5);
    let after_end = |d: T| {
        (
            p1 + v1 * d + a1 * (half * d * d) + j1 * (lit::<T>(1.0 / 6.0) * d * d * d),
            v1 + a1 * d + j1 * (half * d * d),
            at_least(
                y1[S] + f1.spin_rate * d + spin_jerk * (half * d * d),
                T::zero(),
            ),
        )
    };
    let duration = h + dt;
    if let Some(r) = recorder {
        let step = Step {
            h,
            y0,
            y1: &y1,
            f0: &k1,
            f1: &k7,
            mid: Some([&k3, &k4, &k5, &k6]),
        };
        r.record_hop(from_time, duration, &dynamics.axis, |t| {
            if t <= h {
                let y = step.state_at(t / h);
                (
                    Vector3::new(y[0], y[1], y[2]),
                    Vector3::new(y[3], y[4], y[5]),
                    y[S],
                )
            } else {
                after_end(t - h)
            }
        });
    }
    let (position, velocity, spin) = after_end(dt);
    Some(Contact {
        time: from_time + duration,
        position,
        velocity,
        spin: dynamics.axis * spin,
    })
}
