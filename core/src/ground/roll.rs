//! Rolling on the ground plane until the ball rests (or a time cap).
//!
//! A rolling solid sphere (`I = (2/5) m R²`) on a plane of unit normal `n̂` under gravity
//! `g⃗` and a rolling resistance `ρ` (Penner 2002, "The physics of putting"):
//!
//! ```text
//! a = (5/7) · (g⃗_t − ρ g_n v̂),     g⃗_t = g⃗ − (g⃗·n̂) n̂ (along the plane),  g_n = −g⃗·n̂
//! ```
//!
//! On level ground (`g⃗_t = 0`) this is a constant deceleration along a straight line:
//! closed form, `t = v/a`, `d = v²/(2a)`. On a slope the path curves and has no
//! elementary closed form: it is integrated with the explicit midpoint rule at a fixed
//! step [`ROLL_STEP_S`], and the stop is located inside the last step. The ball rests
//! where the slope's pull is below the resistance, `|g⃗_t| ≤ ρ g_n`; on a steeper slope it
//! rolls on until [`ROLL_TIME_CAP_S`].

use crate::flight::{Recorder, Sample};
use crate::real::{Real, lit, smaller, to_f64};
use nalgebra::Vector3;

/// The longest roll simulated (s): a ball still rolling then ends as
/// [`super::RunEnd::StillRolling`].
pub const ROLL_TIME_CAP_S: f64 = 60.0;
/// Step of the roll integration on a slope (s).
pub const ROLL_STEP_S: f64 = 1.0 / 128.0;

/// Where and when a roll ends.
pub(crate) struct RollEnd<T: Real> {
    pub(crate) position: Vector3<T>,
    /// Duration of the roll (s).
    pub(crate) duration: T,
    /// The time cap ended the roll, not the ball resting.
    pub(crate) still_rolling: bool,
}

/// What a roll needs to know.
pub(crate) struct Roll<'r, 'b, T: Real> {
    pub(crate) normal: Vector3<T>,
    pub(crate) gravity: Vector3<T>,
    pub(crate) resistance: T,
    pub(crate) radius: T,
    /// Time since launch at the start of the roll (s), for the recording.
    pub(crate) start_time: T,
    pub(crate) recorder: Option<&'r mut Recorder<'b, T>>,
}

impl<T: Real> Roll<'_, '_, T> {
    fn record(&mut self, time_since_start: T, position: Vector3<T>, velocity: Vector3<T>) {
        let spin = self.normal.cross(&velocity) / self.radius;
        if let Some(r) = self.recorder.as_deref_mut() {
            r.push(Sample {
                time_s: self.start_time + time_since_start,
                position_m: position,
                velocity_mps: velocity,
                spin_radps: spin,
            });
        }
    }

    /// The first recording time after `t` (time since the start of the roll), if the
    /// recorder has room: `k·Δ − t_start` for the smallest such `k`.
    fn next_sample_after(&self, t: T) -> Option<T> {
        let r = self.recorder.as_deref()?;
        if r.is_full() {
            return None;
        }
        let dt = r.interval();
        let k = to_f64((self.start_time + t) / dt);
        let k = if k.is_finite() && k > 0.0 {
            k as u32
        } else {
            0
        };
        let ts = lit::<T>(f64::from(k.saturating_add(1))) * dt - self.start_time;
        (ts > t).then_some(ts)
    }

    /// Records the samples in `(from, to]` with `state(τ) = (position, velocity)`.
    fn record_span(&mut self, from: T, to: T, state: impl Fn(T) -> (Vector3<T>, Vector3<T>)) {
        let mut last = from;
        // Every pass pushes a sample or stops; a full recorder stops it.
        while let Some(ts) = self.next_sample_after(last) {
            if ts > to {
                break;
            }
            let (p, v) = state(ts);
            self.record(ts, p, v);
            last = ts;
        }
    }

    /// Rolls from `p0` with the in-plane velocity `v0`.
    pub(crate) fn run(mut self, p0: Vector3<T>, v0: Vector3<T>) -> RollEnd<T> {
        let n = self.normal;
        let g_n = -self.gravity.dot(&n);
        let g_t = self.gravity + n * g_n;
        let five_sevenths = lit::<T>(5.0 / 7.0);
        let resist = five_sevenths * self.resistance * g_n;
        let cap = lit::<T>(ROLL_TIME_CAP_S);
        if g_t.norm_squared() == T::zero() {
            return self.level(p0, v0, resist, cap);
        }
        let pull = g_t * five_sevenths;
        let holds = g_t.norm() <= self.resistance * g_n;
        let h = lit::<T>(ROLL_STEP_S);
        let accel = |v: &Vector3<T>| {
            let s = v.norm();
            if s > T::zero() {
                pull - v * (resist / s)
            } else {
                pull
            }
        };
        let (mut p, mut v) = (p0, v0);
        let mut t = T::zero();
        let steps = (ROLL_TIME_CAP_S / ROLL_STEP_S) as u32;
        for _ in 0..steps {
            let s = v.norm();
            if s <= resist * h && holds {
                // Stops within this step: decelerate along the current direction.
                let denom = if s > T::zero() {
                    resist - pull.dot(&v) / s
                } else {
                    resist
                };
                let ts = if denom > T::zero() {
                    smaller(s / denom, h)
                } else {
                    h
                };
                let p1 = p + v * (ts * lit(0.5));
                t += ts;
                self.record(t, p1, Vector3::zeros());
                return RollEnd {
                    position: p1,
                    duration: t,
                    still_rolling: false,
                };
            }
            let vm = v + accel(&v) * (h * lit(0.5));
            let v1 = v + accel(&vm) * h;
            let p1 = p + vm * h;
            let (p0s, v0s, t0) = (p, v, t);
            self.record_span(t0, t0 + h, |ts| {
                let f = (ts - t0) / h;
                (p0s + (p1 - p0s) * f, v0s + (v1 - v0s) * f)
            });
            p = p1;
            v = v1;
            t += h;
            if !(p.iter().all(|x| x.is_finite()) && v.iter().all(|x| x.is_finite())) {
                break;
            }
        }
        self.record(t, p, v);
        RollEnd {
            position: p,
            duration: t,
            still_rolling: true,
        }
    }

    /// Level ground: `x(τ) = p₀ + v̂ (u τ − a τ²/2)` until `τ = u/a`.
    fn level(mut self, p0: Vector3<T>, v0: Vector3<T>, resist: T, cap: T) -> RollEnd<T> {
        let u = v0.norm();
        if !(u > T::zero()) {
            self.record(T::zero(), p0, Vector3::zeros());
            return RollEnd {
                position: p0,
                duration: T::zero(),
                still_rolling: false,
            };
        }
        let dir = v0 / u;
        let stop = if resist > T::zero() { u / resist } else { cap };
        let (end, still_rolling) = if stop <= cap {
            (stop, false)
        } else {
            (cap, true)
        };
        let at = |tau: T| dir * (u * tau - resist * tau * tau * lit(0.5));
        self.record_span(T::zero(), end, |ts| (p0 + at(ts), dir * (u - resist * ts)));
        let position = p0 + at(end);
        self.record(
            end,
            position,
            if still_rolling {
                dir * (u - resist * end)
            } else {
                Vector3::zeros()
            },
        );
        RollEnd {
            position,
            duration: end,
            still_rolling,
        }
    }
}
