//! Locating events inside a step: the interpolant of an accepted step, a bracketing root
//! finder, and the tracker that finds the apex, the landing and the recording samples.
//!
//! Every step carries a continuous extension in Hairer's form (Hairer, Nørsett & Wanner,
//! *Solving ODEs I*, §II.6, `CONTD5`):
//!
//! ```text
//! y(t₀ + θh) = r₁ + θ (r₂ + (1−θ) (r₃ + θ (r₄ + (1−θ) r₅)))
//! r₁ = y₀,  r₂ = y₁ − y₀,  r₃ = h f₀ − r₂,  r₄ = r₂ − h f₁ − r₃
//! ```
//!
//! With `r₅ = 0` this is the cubic Hermite interpolant through `(y₀, f₀, y₁, f₁)` (used by
//! Euler and RK4; O(h⁴) locally). Dormand–Prince adds Shampine's
//! `r₅ = h Σ dᵢ kᵢ`, the 4th-order dense output of Dormand & Prince (1980).
//! The landing is the root of `y(θ) − h_land`, the apex the root of `v_y(θ)`: both inside
//! the step, never a step end or the highest sample.

use crate::aero::{S, State, VY, Y};
use crate::error::{Error, Result};
use crate::real::{Real, larger, lit, to_f64};
use crate::trajectory::{Plane, Recorder, Sample};
use nalgebra::Vector3;

/// Dense-output weights dᵢ of DOPRI5 (Hairer's `CONTD5`), for k₁, k₃, k₄, k₅, k₆, k₇.
pub(crate) const DP_DENSE: [f64; 6] = [
    -12_715_105_075.0 / 11_282_082_432.0,
    87_487_479_700.0 / 32_700_410_799.0,
    -10_690_763_975.0 / 1_880_347_072.0,
    701_980_252_875.0 / 199_316_789_632.0,
    -1_453_857_185.0 / 822_651_844.0,
    69_997_945.0 / 29_380_423.0,
];

/// One accepted step and what its interpolant needs.
pub(crate) struct Step<'a, T> {
    /// Step size (s).
    pub(crate) h: T,
    /// State at the start.
    pub(crate) y0: &'a State<T>,
    /// State at the end.
    pub(crate) y1: &'a State<T>,
    /// Derivative at the start.
    pub(crate) f0: &'a State<T>,
    /// Derivative at the end.
    pub(crate) f1: &'a State<T>,
    /// Dormand–Prince stages k₃..k₆ for the 4th-order dense output (None: Hermite).
    pub(crate) mid: Option<[&'a State<T>; 4]>,
}

/// Coefficients `r₁..r₅` of one component's interpolant.
#[derive(Clone, Copy)]
struct Poly<T>([T; 5]);

impl<T: Real> Poly<T> {
    #[inline]
    fn at(&self, th: T) -> T {
        let [r1, r2, r3, r4, r5] = self.0;
        let th1 = T::one() - th;
        r1 + th * (r2 + th1 * (r3 + th * (r4 + th1 * r5)))
    }

    /// The value and the derivative in `θ` at `th`: `y(θ) = r₁ + θ·q(θ)`, `y' = q + θ·q'`
    /// with the deflated `q` of [`deflated`].
    #[inline]
    fn with_slope(&self, th: T) -> (T, T) {
        let [r1, r2, r3, r4, r5] = self.0;
        let (q, dq) = deflated(r2, r3, r4, r5, th);
        (r1 + th * q, q + th * dq)
    }
}

/// `q(θ) = r₂ + (1−θ)(r₃ + θ(r₄ + (1−θ)r₅))`, the interpolant's `(y(θ) − r₁)/θ`, and its
/// derivative in `θ`: each nested factor with its derivative, side by side.
#[inline(always)]
fn deflated<T: Real>(r2: T, r3: T, r4: T, r5: T, th: T) -> (T, T) {
    let th1 = T::one() - th;
    let c = r4 + th1 * r5;
    let b = r3 + th * c;
    let db = c - th * r5;
    (r2 + th1 * b, th1 * db - b)
}

impl<T: Real> Step<'_, T> {
    /// The interpolant coefficients of component `i` (the values at index `i` of the
    /// states; `get` keeps it panic-free for any `i`).
    #[inline]
    fn poly_of(&self, i: usize) -> Poly<T> {
        let g = |s: &State<T>| s.get(i).copied().unwrap_or_else(T::zero);
        let (y0, y1) = (g(self.y0), g(self.y1));
        let r2 = y1 - y0;
        let r3 = self.h * g(self.f0) - r2;
        let r4 = r2 - self.h * g(self.f1) - r3;
        let r5 = match self.mid {
            None => T::zero(),
            Some([k3, k4, k5, k6]) => {
                let [d1, d3, d4, d5, d6, d7] = DP_DENSE;
                self.h
                    * (lit::<T>(d1) * g(self.f0)
                        + lit::<T>(d3) * g(k3)
                        + lit::<T>(d4) * g(k4)
                        + lit::<T>(d5) * g(k5)
                        + lit::<T>(d6) * g(k6)
                        + lit::<T>(d7) * g(self.f1))
            }
        };
        Poly([y0, r2, r3, r4, r5])
    }

    /// The interpolant of `n · (components base..base+3) − c` (a projection of the
    /// position, `base = 0`, or of the velocity, `base = 3`): the interpolant is linear
    /// in the states, so it is the same combination of the component coefficients.
    fn poly_along(&self, n: &Vector3<T>, base: usize, c: T) -> Poly<T> {
        let mut r = [T::zero(); 5];
        for (k, nk) in n.iter().enumerate() {
            let p = self.poly_of(base + k);
            for (ri, pi) in r.iter_mut().zip(p.0.iter()) {
                *ri += *nk * *pi;
            }
        }
        r[0] -= c;
        Poly(r)
    }

    /// The whole interpolated state at `θ ∈ [0, 1]`.
    pub(crate) fn state_at(&self, th: T) -> State<T> {
        let mut out = *self.y0;
        for (i, o) in out.iter_mut().enumerate() {
            *o = self.poly_of(i).at(th);
        }
        out
    }
}

/// The root of `f` in `[a, b]`, given `f(a)` and `f(b)` of opposite signs (or `f(b) = 0`),
/// where `f` returns the value and the derivative: Newton's method kept inside the shrinking
/// bracket (a step that would leave it bisects instead; Press et al., *Numerical Recipes*,
/// `rtsafe`), from the secant through the ends. Quadratic near a simple root: the apex and
/// the landing take about four evaluations (the Illinois method took seven). Stops when a
/// step is a few ulps of `θ ∈ [0, 1]` or the bracket is that narrow; at most 64 iterations.
pub(crate) fn find_root<T: Real>(
    f: impl Fn(T) -> (T, T),
    mut a: T,
    mut b: T,
    mut fa: T,
    fb: T,
) -> T {
    if fb == T::zero() {
        return b;
    }
    let half = lit::<T>(0.5);
    let tiny = T::default_epsilon() * lit(4.0);
    let denom = fb - fa;
    let mut x = if denom != T::zero() {
        (a * fb - b * fa) / denom
    } else {
        (a + b) * half
    };
    for _ in 0..64 {
        // The ends are never NaN (given finite, then only moved to an `x` that passed this
        // test): one comparison orders them, where `smaller`/`larger` also handle NaN.
        let (lo, hi) = if a < b { (a, b) } else { (b, a) };
        if !(x > lo && x < hi) {
            x = (a + b) * half;
        }
        let (fx, slope) = f(x);
        if fx == T::zero() {
            return x;
        }
        if (fx > T::zero()) == (fa > T::zero()) {
            a = x;
            fa = fx;
        } else {
            b = x;
        }
        let step = fx / slope;
        let next = x - step;
        // (A NaN step, from a zero slope, fails the bracket test and bisects.)
        if step.abs() <= tiny || (b - a).abs() <= tiny {
            let (lo, hi) = if a < b { (a, b) } else { (b, a) };
            return if next > lo && next < hi { next } else { x };
        }
        x = next;
    }
    x
}

/// The landing found inside a step: time and interpolated state.
pub(crate) struct Landing<T> {
    pub(crate) time: T,
    pub(crate) state: State<T>,
}

impl<T: Real> Landing<T> {
    /// The landing at fraction `th` of `step`, which starts at time `t0`.
    #[inline]
    pub(crate) fn in_step(t0: T, th: T, step: &Step<'_, T>) -> Self {
        Self {
            time: t0 + th * step.h,
            state: step.state_at(th),
        }
    }
}

/// Tracks the apex, the landing and the recording across accepted steps.
pub(crate) struct Tracker<'r, 'b, T: Real> {
    landing_height: T,
    /// A hop: the landing is on this plane instead of the level `landing_height`, and
    /// there is no apex bookkeeping.
    plane: Option<Plane<T>>,
    /// Time of the integration's start since launch (s): 0 for the flight, the bounce
    /// time for a hop (recorded samples keep the launch's clock).
    time_offset: T,
    /// Apex (time, height) so far.
    pub(crate) apex_time: T,
    pub(crate) apex_height: T,
    axis: Vector3<T>,
    recorder: Option<&'r mut Recorder<'b, T>>,
    next_sample: u32,
}

impl<'r, 'b, T: Real> Tracker<'r, 'b, T> {
    pub(crate) fn new(
        landing_height: T,
        y0: &State<T>,
        axis: Vector3<T>,
        recorder: Option<&'r mut Recorder<'b, T>>,
    ) -> Self {
        Self {
            landing_height,
            plane: None,
            time_offset: T::zero(),
            apex_time: T::zero(),
            apex_height: y0[Y],
            axis,
            recorder,
            next_sample: 0,
        }
    }

    /// A tracker for a hop starting on `plane` at `time_offset` after launch: it finds where
    /// the ball comes back down through the plane, and records on the launch's clock.
    pub(crate) fn hop(
        plane: Plane<T>,
        y0: &State<T>,
        axis: Vector3<T>,
        time_offset: T,
        recorder: Option<&'r mut Recorder<'b, T>>,
    ) -> Self {
        // The first sample time k·Δ at or after the offset (saturating, never panics).
        let next_sample = recorder.as_deref().map_or(0, |r| {
            if let Some(k) = r.first_given_at_or_after(time_offset) {
                return k;
            }
            let k = to_f64(time_offset / r.interval_s);
            let k = if k.is_finite() && k > 0.0 { k } else { 0.0 };
            // Float-to-int `as` saturates; ceil without std: the truncation, plus one when short.
            let n = k as u32;
            if f64::from(n) < k {
                n.saturating_add(1)
            } else {
                n
            }
        });
        Self {
            landing_height: y0[Y],
            plane: Some(plane),
            time_offset,
            apex_time: T::zero(),
            apex_height: y0[Y],
            axis,
            recorder,
            next_sample,
        }
    }

    /// Processes one accepted step starting at `t0`: the apex if `v_y` turns negative in it,
    /// the landing if the ball comes down through the landing height in it, and the
    /// recording samples that fall in it.
    ///
    /// Returns where in the step the landing is (θ ∈ [0, 1]), if it is in this step; the
    /// caller builds the [`Landing`] ([`Landing::in_step`]). A small return value on purpose:
    /// returning the whole landing state made every step copy it (a `memcpy` per step on
    /// the M4F).
    ///
    /// # Errors
    /// [`Error::NoLanding`] when the ball peaks at or below the landing height.
    pub(crate) fn on_step(&mut self, t0: T, step: &Step<'_, T>) -> Result<Option<T>> {
        let h = step.h;
        if let Some(plane) = self.plane {
            let landing = locate_on_plane(step, &plane);
            if self.recorder.is_some() {
                self.record(t0, step, landing);
            }
            return Ok(landing);
        }
        // Most steps hold neither the apex nor the landing: `locate` would find nothing
        // (the same tests as its own), so it is not called.
        if !self.may_hold_event(step) {
            if self.recorder.is_some() {
                self.record(t0, step, None);
            }
            return Ok(None);
        }
        let (apex, landing) = self.locate(step);
        if let Some((th, ya)) = apex {
            if ya > self.apex_height {
                self.apex_height = ya;
                self.apex_time = t0 + th * h;
            }
            if ya <= self.landing_height {
                return Err(Error::NoLanding);
            }
        }
        if self.recorder.is_some() {
            self.record(t0, step, landing);
        }
        Ok(landing)
    }

    /// Whether [`on_step`](Self::on_step) would do nothing with this step: a flight's
    /// (not a hop's) step that holds neither the apex nor the landing (its own tests),
    /// without a recording. Inlined into the step loop on hosts, so that most steps make
    /// no call (a call there spills the loop's live SSE registers, all caller-saved).
    #[inline(always)]
    pub(crate) fn quiet(&self, step: &Step<'_, T>) -> bool {
        self.plane.is_none() && self.recorder.is_none() && !self.may_hold_event(step)
    }

    /// Whether a flight's step may hold the apex (the climb ends in it) or the landing
    /// (it ends at or below the landing height): `locate`'s own first tests.
    #[inline(always)]
    fn may_hold_event(&self, step: &Step<'_, T>) -> bool {
        let (y0, y1) = (step.y0, step.y1);
        let may_hold_apex = y0[VY] > T::zero() && y1[VY] <= T::zero();
        may_hold_apex || y1[Y] <= self.landing_height
    }

    /// Whether the step ends below the landing height (a hop's: its plane), so that the
    /// landing is in it (or was at its start): one comparison, in every step.
    #[inline(always)]
    pub(crate) fn ends_below(&self, step: &Step<'_, T>) -> bool {
        // `height(y1) <= 0` without its subtraction on the flight's path (every step).
        match self.plane {
            None => step.y1[Y] <= self.landing_height,
            Some(_) => self.height(step.y1) <= T::zero(),
        }
    }

    /// Height of state `y` above the landing height (a hop's: its plane), m.
    #[inline(always)]
    fn height(&self, y: &State<T>) -> T {
        match self.plane {
            None => y[Y] - self.landing_height,
            Some(plane) => plane.normal.dot(&Vector3::new(y[Y - 1], y[Y], y[Y + 1])) - plane.offset,
        }
    }

    /// For a step that [`ends_below`](Self::ends_below): the landing's θ in it if the ball
    /// comes down there at less than [`GRAZING_LANDING_RAD`](super::GRAZING_LANDING_RAD) to
    /// the landing height (a hop's: its plane). First without looking inside the step: the
    /// velocity interpolated linearly to where the height crosses linearly. The height is
    /// concave and the descent steepens, so the chord crosses early and this estimate comes
    /// down shallower than the landing; only if it is under twice the grazing angle is the
    /// landing located on the interpolant and its angle tested there. Out of line: the
    /// flight's step loop keeps its registers (inlined, it cost the flight ~60 instructions
    /// a step on x86-64).
    #[inline(never)]
    #[cold]
    pub(crate) fn grazing_landing(&self, step: &Step<'_, T>) -> Option<T> {
        let (y0, y1) = (step.y0, step.y1);
        let (g0, g1) = (self.height(y0), self.height(y1));
        let th = if g0 > T::zero() {
            g0 / (g0 - g1)
        } else {
            T::zero()
        };
        let velocity = |y: &State<T>| Vector3::new(y[VY - 1], y[VY], y[VY + 1]);
        let (v0, v1) = (velocity(y0), velocity(y1));
        if self.descends_at(&(v0 + (v1 - v0) * th), lit(super::GRAZING_TAN_SQ_TWICE)) {
            return None;
        }
        let th = self.landing_in(step)?;
        let v = Vector3::new(
            step.poly_of(VY - 1).at(th),
            step.poly_of(VY).at(th),
            step.poly_of(VY + 1).at(th),
        );
        (!self.descends_at(&v, lit(super::GRAZING_TAN_SQ))).then_some(th)
    }

    /// Whether velocity `v` comes down to the landing height (a hop's: its plane) at an
    /// angle whose tangent squared is `tan_sq` or more.
    fn descends_at(&self, v: &Vector3<T>, tan_sq: T) -> bool {
        let vn = match self.plane {
            None => v.y,
            Some(plane) => plane.normal.dot(v),
        };
        vn < T::zero() && vn * vn >= tan_sq * (v.norm_squared() - vn * vn)
    }

    /// Where in the step the landing is (θ), if it is in this step; no side effects.
    pub(crate) fn landing_in(&self, step: &Step<'_, T>) -> Option<T> {
        match self.plane {
            Some(plane) => locate_on_plane(step, &plane),
            None => self.locate(step).1,
        }
    }

    /// The apex `(θ, height)` if `v_y` turns negative in the step, and the landing θ if the
    /// ball comes down through the landing height in it (not when it peaks below it).
    fn locate(&self, step: &Step<'_, T>) -> (Option<(T, T)>, Option<T>) {
        let (y0, y1) = (step.y0, step.y1);
        let hl = self.landing_height;
        // Where in the step the ball is (last) above the landing height, and f there.
        let mut above: Option<(T, T)> = (y0[Y] > hl).then(|| (T::zero(), y0[Y] - hl));
        let mut apex = None;
        if y0[VY] > T::zero() && y1[VY] <= T::zero() {
            let vy = step.poly_of(VY);
            let th = find_root(|x| vy.with_slope(x), T::zero(), T::one(), y0[VY], y1[VY]);
            let ya = step.poly_of(Y).at(th);
            apex = Some((th, ya));
            above = (ya > hl).then(|| (th, ya - hl));
        }
        let landing = match above {
            Some((lo, f_lo)) if y1[Y] <= hl => {
                let py = step.poly_of(Y);
                Some(find_root(
                    |x| {
                        let (y, slope) = py.with_slope(x);
                        (y - hl, slope)
                    },
                    lo,
                    T::one(),
                    f_lo,
                    y1[Y] - hl,
                ))
            }
            _ => None,
        };
        (apex, landing)
    }

    /// Records the samples `t = k·Δ` inside the step (before the landing), then the
    /// landing itself. Stops, flagging the recorder full, when the buffer is.
    fn record(&mut self, t0: T, step: &Step<'_, T>, landing: Option<T>) {
        let Some(rec) = self.recorder.as_deref_mut() else {
            return;
        };
        let h = step.h;
        let offset = self.time_offset;
        // The landing's time, computed once: the samples before it are compared with it in
        // time (not as fractions of the step), so they stay in time order even when the
        // landing is within rounding of a sample (a fuzz find: a landing at t ≈ 1e-285 s).
        let landing_time = landing.map(|th| t0 + th * h + offset);
        while !rec.full {
            let Some(ts) = rec.sample_time(self.next_sample) else {
                break;
            };
            if ts < offset {
                // Before this hop began (the first index after the offset rounded down: a
                // fuzz find with a 5e243 s interval). The last index repeats its time.
                if self.next_sample == u32::MAX {
                    break;
                }
                self.next_sample += 1;
                continue;
            }
            let th = (ts - offset - t0) / h;
            let past = match landing_time {
                Some(tl) => !(ts < tl),
                None => th > T::one(),
            };
            if past {
                break;
            }
            let th = larger(th, T::zero());
            rec.push(Sample::new(ts, &step.state_at(th), &self.axis));
            self.next_sample = self.next_sample.saturating_add(1);
        }
        if let (Some(th), Some(tl)) = (landing, landing_time) {
            rec.push(Sample::new(tl, &step.state_at(th), &self.axis));
        }
    }
}

/// Where in the step the ball comes down through `plane` (θ), if it does: the plane
/// analogue of [`Tracker::locate`], with the height `g(θ) = n·p(θ) − c` a linear
/// combination of the component interpolants.
fn locate_on_plane<T: Real>(step: &Step<'_, T>, plane: &Plane<T>) -> Option<T> {
    let n = plane.normal;
    let level = n.x == T::zero() && n.z == T::zero() && n.y == T::one();
    let height = if level {
        // Level ground: the height interpolant itself.
        let mut height = step.poly_of(Y);
        height.0[0] -= plane.offset;
        height
    } else {
        step.poly_along(&n, 0, plane.offset)
    };
    let [g0, r2, r3, r4, r5] = height.0;
    let g1 = height.at(T::one());
    if !(g1 <= T::zero()) {
        return None;
    }
    if g0 > T::zero() {
        return Some(find_root(
            |x| height.with_slope(x),
            T::zero(),
            T::one(),
            g0,
            g1,
        ));
    }
    // The hop's first step starts on the plane (g₀ = 0 to rounding): the landing is the
    // root of the deflated g(θ)/θ = r₂ + (1−θ)(r₃ + θ(r₄ + (1−θ)r₅)), positive at 0
    // (h·ġ₀ > 0, leaving the plane) and g₁ − g₀ < 0 at 1.
    let (d0, d1) = (r2 + r3, r2);
    (d0 > T::zero() && d1 < T::zero()).then(|| {
        find_root(
            |th| deflated(r2, r3, r4, r5, th),
            T::zero(),
            T::one(),
            d0,
            d1,
        )
    })
}

impl<T: Real> Sample<T> {
    fn new(time_s: T, y: &State<T>, axis: &Vector3<T>) -> Self {
        Self {
            time_s,
            position_m: Vector3::new(y[0], y[1], y[2]),
            velocity_mps: Vector3::new(y[3], y[4], y[5]),
            spin_radps: axis * y[S],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn newton_finds_roots() {
        let r = find_root(|x: f64| (x * x - 0.3, 2.0 * x), 0.0, 1.0, -0.3, 0.7);
        assert!((r - 0.3_f64.sqrt()).abs() < 1e-15);
        let r = find_root(
            |x: f32| (0.2 - x * x * x, -3.0 * x * x),
            0.0,
            1.0,
            0.2,
            -0.8,
        );
        assert!((r - 0.2_f32.cbrt()).abs() < 1e-6);
        // A root at the end given.
        assert_eq!(find_root(|x: f64| (x - 1.0, 1.0), 0.0, 1.0, -1.0, 0.0), 1.0);
    }

    #[test]
    fn bad_slopes_fall_back_to_bisection() {
        // A zero slope (NaN step) and a wrong-signed one both leave the bracket: the
        // iteration bisects and still converges on the root, inside the bracket.
        let r = find_root(|x: f64| (x - 0.3, 0.0), 0.0, 1.0, -0.3, 0.7);
        assert!((r - 0.3).abs() < 1e-14, "{r}");
        let r = find_root(|x: f64| (x - 0.3, -1.0), 0.0, 1.0, -0.3, 0.7);
        assert!((r - 0.3).abs() < 1e-14, "{r}");
        // A NaN value stops inside the bracket instead of looping.
        let r = find_root(|_: f32| (f32::NAN, 1.0), 0.0, 1.0, 1.0, -1.0);
        assert!((0.0..=1.0).contains(&r) || r.is_nan());
    }

    #[test]
    fn slope_matches_the_interpolant() {
        let p = Poly([0.3_f64, -1.2, 0.7, 2.1, -0.4]);
        for th in [0.0, 0.2, 0.5, 0.9, 1.0] {
            let (y, slope) = p.with_slope(th);
            assert!((y - p.at(th)).abs() < 1e-15, "{th}");
            let h = 1e-6;
            let numeric = (p.at(th + h) - p.at(th - h)) / (2.0 * h);
            assert!((slope - numeric).abs() < 1e-8, "{th}: {slope} {numeric}");
        }
    }

    #[test]
    fn hermite_form_reproduces_a_cubic() {
        // y = 1 + 2t − t² + 0.5 t³ on [0, 2]
        let y = |t: f64| 1.0 + 2.0 * t - t * t + 0.5 * t * t * t;
        let dy = |t: f64| 2.0 - 2.0 * t + 1.5 * t * t;
        let h = 2.0;
        let st = |v: f64| [v, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let (y0, y1, f0, f1) = (st(y(0.0)), st(y(h)), st(dy(0.0)), st(dy(h)));
        let step = Step {
            h,
            y0: &y0,
            y1: &y1,
            f0: &f0,
            f1: &f1,
            mid: None,
        };
        for th in [0.0, 0.1, 0.5, 0.77, 1.0] {
            assert!((step.state_at(th)[0] - y(th * h)).abs() < 1e-14);
        }
    }
}
