//! Skidding and rolling on the ground plane until the ball rests (or a time cap).
//!
//! **Skid.** The bouncing can end with the contact still slipping (a shallow landing
//! leaves the ground with backspin or overspin). The contact point's slip
//! `s = v + ω × (−R n̂)` then closes under Coulomb friction `μ g_n` (the turf's bounce
//! friction) at `(7/2)μ g_n − g⃗_t·ŝ` (a solid sphere: the friction slows the centre and
//! turns the spin), during which the ball moves with `a = g⃗_t − μ g_n ŝ`. It leaves at
//! the rolling speed `(5v − 2Rω_b)/7` on level ground (Daish; Penner 2002), having lost
//! energy to friction.
//!
//! **Roll.** A rolling solid sphere (`I = (2/5) m R²`) on a plane of unit normal `n̂`
//! under gravity `g⃗` and a rolling resistance that grows with speed, the grass drag:
//!
//! ```text
//! a = (5/7) · (g⃗_t − ρ(v) g_n v̂),   ρ(v) = ρ₀ (1 + c v²),
//! g⃗_t = g⃗ − (g⃗·n̂) n̂ (along the plane),  g_n = −g⃗·n̂
//! ```
//!
//! (Penner 2002, "The physics of putting", as quoted in patents citing it:
//! `ρ = (0.7028/S)(1 + 0.0065 v²)`, S in ft, v in ft/s; c = 0.070 s²/m²,
//! [`super::surface::GRASS_DRAG_S2PM2`]). On level ground this is a straight line in
//! closed form (`Roll::level`). On a slope the path curves and has no elementary closed
//! form: a fixed step [`ROLL_STEP_S`], the slope's pull as two half kicks around the
//! resistance's exact-in-direction update `s' = max(s − A h, 0)/(1 + B s h)` (Strang
//! splitting; `A = (5/7)ρ₀g_n`, `B = A c`), which never gains speed or reverses the ball
//! at any speed. The stop is located inside the last step. The ball rests where the
//! slope's pull is below the resistance at rest, `|g⃗_t| ≤ ρ₀ g_n`; on a steeper slope it
//! rolls on until [`ROLL_TIME_CAP_S`].

use super::normal::Normal;
use crate::real::{Real, at_least, at_most, length, lit, to_f64};
use crate::trajectory::{Recorder, Sample};
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
pub(crate) struct Roll<'r, 'b, T: Real, N: Normal<T>> {
    /// The ground plane's unit normal.
    pub(crate) normal: N,
    pub(crate) gravity: Vector3<T>,
    pub(crate) resistance: T,
    /// The grass drag's growth with speed `c` (s²/m²): the resistance is `ρ₀(1 + c v²)`.
    pub(crate) grass_drag: T,
    /// Ball–turf friction while the ball skids.
    pub(crate) friction: T,
    pub(crate) radius: T,
    /// Time since launch at the start of the roll (s), for the recording.
    pub(crate) start_time: T,
    pub(crate) recorder: Option<&'r mut Recorder<'b, T>>,
}

impl<T: Real, N: Normal<T>> Roll<'_, '_, T, N> {
    fn record(&mut self, time_since_start: T, position: Vector3<T>, velocity: Vector3<T>) {
        let spin = self.normal.cross(&velocity) / self.radius;
        self.record_spinning(time_since_start, position, velocity, spin);
    }

    fn record_spinning(
        &mut self,
        time_since_start: T,
        position: Vector3<T>,
        velocity: Vector3<T>,
        spin: Vector3<T>,
    ) {
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
        if let Some(given) = r.given_after(self.start_time + t) {
            return given.map(|ts| ts - self.start_time);
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

    /// Skids from `p0` with the in-plane velocity `v0` and the spin `spin` until the
    /// contact stops slipping (module docs): the position, velocity and duration at the
    /// start of the pure roll.
    ///
    /// Fixed steps of [`ROLL_STEP_S`]: Coulomb friction `μ g_n` against the slip (on the
    /// centre and, as a torque, on the spin) and the slope's pull for the step, then the
    /// grass drag on the speed, `s' = max(s − A h, 0)/(1 + B s h)` with `A = ρ₀ g_n`,
    /// `B = A c` (as the roll's, on the centre alone: a sliding ball need not turn).
    /// Friction stops within the step where the slip would reverse; the last of the slip
    /// goes in one gripping impulse `Δv = −(2/7)s`. Each part only takes energy (and the
    /// pull gives what gravity gives).
    fn skid(
        &mut self,
        p0: Vector3<T>,
        v0: Vector3<T>,
        spin: &Vector3<T>,
    ) -> (Vector3<T>, Vector3<T>, T) {
        let n = self.normal;
        let g_n = -n.dot(&self.gravity);
        let g_t = self.gravity + n.scaled(g_n);
        let r = self.radius;
        let in_plane = |x: Vector3<T>| n.in_plane(&x);
        // The spin's share of the slip, `(ω × n̂)·R` in the plane (the slip is `v − that`).
        let spin_slip = |w: &Vector3<T>| in_plane(n.cross(w) * (-r));
        let grip = self.friction * g_n;
        let (mut p, mut v, mut w) = (p0, v0, *spin);
        let mut slip = in_plane(v - spin_slip(&w));
        let h = lit::<T>(ROLL_STEP_S);
        let resist = self.resistance * g_n;
        let drag = resist * self.grass_drag;
        let spin_per_grip = lit::<T>(2.5) / r;
        let mut t = T::zero();
        let steps = (ROLL_TIME_CAP_S / ROLL_STEP_S) as u32;
        for _ in 0..steps {
            let size = n.norm_sq_in_plane(&slip).root();
            if !(size > T::zero() && grip > T::zero()) {
                break;
            }
            let dir = slip * (T::one() / size);
            // The slip closes at (7/2)μg_n less the slope's pull along it.
            let closing = lit::<T>(3.5) * grip - g_t.dot(&dir);
            if !(closing > T::zero()) {
                break;
            }
            // Friction for at most the step, stopping where the slip would reverse (the
            // test by a product: the division only for the last, shorter step).
            let dt = if size >= closing * h {
                h
            } else {
                size / closing
            };
            // (The pull's share first: after `dir`, one multiply and one subtraction.)
            let v1 = (v + g_t * dt) - dir * (grip * dt);
            let w1 = w + n.cross(&dir) * (spin_per_grip * grip * dt);
            // The grass drag on the speed (never a gain, never a reversal):
            // `s' = max(s − A dt, 0)/(1 + B s dt)`, as the factor `s'/s` in one division.
            let speed_sq = n.norm_sq_in_plane(&v1);
            let speed = speed_sq.root();
            let scale = at_least(speed - resist * dt, T::zero()) / (speed + drag * dt * speed_sq);
            let (v1, v1_in_plane) = if speed > T::zero() {
                (v1 * scale, in_plane(v1) * scale)
            } else {
                (v1, in_plane(v1))
            };
            let p1 = p + (v + v1) * (dt * lit(0.5));
            let (pa, va, wa, ta) = (p, v, w, t);
            if self.recorder.is_some() {
                let mut last = t;
                while let Some(ts) = self.next_sample_after(last) {
                    if ts > t + dt {
                        break;
                    }
                    let f = (ts - ta) / dt;
                    self.record_spinning(
                        ts,
                        pa + (p1 - pa) * f,
                        va + (v1 - va) * f,
                        wa + (w1 - wa) * f,
                    );
                    last = ts;
                }
            }
            p = p1;
            v = v1_in_plane;
            w = w1;
            t += dt;
            slip = v - spin_slip(&w);
            if dt < h {
                break;
            }
        }
        // What is left of the slip goes in one gripping impulse (none if it closed).
        let v = v - slip * lit::<T>(2.0 / 7.0);
        (p, v, t)
    }

    /// Skids (while the contact slips) and rolls from `p0` with the in-plane velocity `v0`
    /// and the spin `spin`.
    pub(crate) fn run(mut self, p0: Vector3<T>, v0: Vector3<T>, spin: &Vector3<T>) -> RollEnd<T> {
        let (p0, v0, skid) = self.skid(p0, v0, spin);
        self.start_time += skid;
        let mut end = self.roll(p0, v0, lit::<T>(ROLL_TIME_CAP_S) - skid);
        end.duration += skid;
        end
    }

    /// Rolls from `p0` with the in-plane velocity `v0`.
    fn roll(mut self, p0: Vector3<T>, v0: Vector3<T>, cap: T) -> RollEnd<T> {
        let n = self.normal.vector();
        let g_n = -self.gravity.dot(&n);
        let g_t = self.gravity + n * g_n;
        let five_sevenths = lit::<T>(5.0 / 7.0);
        // a(v) = A + B v² along −v̂: A = (5/7)ρ₀g_n, B = A·c.
        let resist = five_sevenths * self.resistance * g_n;
        let drag = resist * self.grass_drag;
        let cap = at_least(cap, T::zero());
        if g_t.norm_squared() == T::zero() {
            return self.level(p0, v0, resist, cap);
        }
        let pull = g_t * five_sevenths;
        let holds = length(&g_t) <= self.resistance * g_n;
        let h = lit::<T>(ROLL_STEP_S);
        let half_h = h * lit(0.5);
        let (mut p, mut v) = (p0, v0);
        let mut t = T::zero();
        // At most the time cap's steps (what the skid left of it, rounded up).
        let steps = (to_f64(cap / h).min(ROLL_TIME_CAP_S / ROLL_STEP_S) + 0.999) as u32;
        for _ in 0..steps {
            // Half a kick of the slope's pull, the resistance over the whole step, half a
            // kick (Strang splitting). The resistance on the speed alone,
            // `s' = max(s − A h, 0)/(1 + B s h)`: second order in h, never a gain and
            // never a reversal at any speed (an explicit step of `B v²` diverges above
            // `v ≈ 1/(B h)`).
            let va = v + pull * half_h;
            let s = length(&va);
            if holds && s <= resist * h {
                // Stops within this step, where the pull cannot start it again.
                let ts = if resist > T::zero() {
                    at_most(s / resist, h)
                } else {
                    h
                };
                let p1 = p + va * (ts * lit(0.5));
                t += ts;
                self.record(t, p1, Vector3::zeros());
                return RollEnd {
                    position: p1,
                    duration: t,
                    still_rolling: false,
                };
            }
            let s1 = at_least(s - resist * h, T::zero()) / (T::one() + drag * s * h);
            let vb = if s > T::zero() { va * (s1 / s) } else { va };
            let p1 = p + (va + vb) * half_h;
            let v1 = vb + pull * half_h;
            // Samples inside the step at constant acceleration `(v₁ − v₀)/h`: the position
            // consistent with the velocity (its end is the step's, `p₀ + (v₀ + v₁)h/2`).
            // A straight chord would lag a decelerating ball, and a sample up a slope
            // would then show less energy than the next (found by the ground property test).
            let (p0s, v0s, t0) = (p, v, t);
            let accel = (v1 - v0s) / h;
            self.record_span(t0, t0 + h, |ts| {
                let tau = ts - t0;
                (
                    p0s + v0s * tau + accel * (tau * tau * lit(0.5)),
                    v0s + accel * tau,
                )
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

    /// Level ground, in closed form. With `a(v) = A + B v²`, `k = √(AB)`,
    /// `θ₀ = atan(v₀√(B/A))`:
    ///
    /// ```text
    /// v(τ) = √(A/B)·tan(θ₀ − kτ),   x(τ) = ln(cos(θ₀ − kτ)/cos θ₀)/B,
    /// stops at τ = θ₀/k after ln(1 + B v₀²/A)/(2B)
    /// ```
    ///
    /// (`B = 0`: `v = v₀ − Aτ`, `x = v₀τ − Aτ²/2`).
    fn level(mut self, p0: Vector3<T>, v0: Vector3<T>, resist: T, cap: T) -> RollEnd<T> {
        let u_sq = v0.norm_squared();
        let u = u_sq.root();
        if !(u > T::zero()) {
            self.record(T::zero(), p0, Vector3::zeros());
            return RollEnd {
                position: p0,
                duration: T::zero(),
                still_rolling: false,
            };
        }
        let dir = v0 / u;
        let c = self.grass_drag;
        if !(resist > T::zero() && c > T::zero()) {
            return self.level_constant(p0, dir, u, resist, cap);
        }
        let root_c = c.root();
        let w = u * root_c;
        let k = resist * root_c;
        // θ₀ and the stop from w² = c·u² (not waiting on the square root of u²).
        let w_sq = c * u_sq;
        let theta0 = crate::geometry::atan2_first_quadrant_of_squares(w_sq, T::one());
        let stop = theta0 / k;
        // x = ln(1 + w²)/(2Ac); for a huge w as ln w² (ln_1p's series is for moderate w²).
        let per_b = T::one() / (resist * c);
        let full = if w_sq < lit(1.0e8) {
            w_sq.ln_1p()
        } else {
            w_sq.ln()
        } * (per_b * lit(0.5));
        let state = move |tau: T| {
            let (sn, cs) = (theta0 - k * tau).sin_cos();
            // cos(θ₀ − kτ)/cos θ₀ = cos kτ + w sin kτ = 1 + w sin kτ − 2 sin²(kτ/2): the
            // logarithm from ln_1p, exact for a tiny kτ too (a nearly frictionless turf,
            // where ln cos(θ₀ − kτ) − ln cos θ₀ would cancel catastrophically).
            let half = (k * tau * lit(0.5)).sin();
            let x = (w * (k * tau).sin() - half * half * lit(2.0)).ln_1p() * per_b;
            let x = if x.is_finite() {
                at_least(x, T::zero())
            } else {
                full
            };
            let speed = if cs > T::zero() {
                sn / cs / root_c
            } else {
                T::zero()
            };
            (x, at_least(speed, T::zero()))
        };
        let (end, still_rolling) = if stop <= cap {
            (stop, false)
        } else {
            (cap, true)
        };
        self.record_span(T::zero(), end, |ts| {
            let (x, s) = state(ts);
            (p0 + dir * x, dir * s)
        });
        let (x, s) = if still_rolling {
            state(end)
        } else {
            (full, T::zero())
        };
        let position = p0 + dir * x;
        self.record(end, position, dir * s);
        RollEnd {
            position,
            duration: end,
            still_rolling,
        }
    }

    /// Level ground at a constant resistance: `x(τ) = p₀ + v̂ (u τ − a τ²/2)` until `τ = u/a`.
    fn level_constant(
        mut self,
        p0: Vector3<T>,
        dir: Vector3<T>,
        u: T,
        resist: T,
        cap: T,
    ) -> RollEnd<T> {
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
