//! The lanes kernel (issue 37): many flights advanced together, [`LANES`] at a time, as a
//! structure of arrays, for batches. Each lane is one shot with its own adaptive step, its
//! own acceptance, apex and landing; a lane that lands (or fails) is refilled at once with
//! the next shot, so the lanes stay full until the batch runs out. The force evaluations
//! and the Runge–Kutta stages run across the lanes in branch-free loops over `[T; N]`
//! arrays that the compiler vectorises (no SIMD crate: docs/performance.md, "Lanes kernel",
//! measures plain arrays against the `wide` crate); the step control and the events run
//! per lane, through the scalar path's own tracker.
//!
//! **What it covers** ([`covers`]): the modern family ([`crate::aero::ModernAero`], the
//! default `tour2023` and `drives2026`) with every effect on ([`crate::Effects::ALL`]), in
//! still air or a uniform wind, without a ground, with the adaptive Dormand–Prince
//! integrator, and no recorder. Each lane may have its own scene (air, wind, ball,
//! coefficients, landing height, tee). Any other shot (the linear family, a wind profile,
//! a ground's bounce and roll, fixed-step integrators, fewer effects) is flown by the
//! scalar path ([`PreparedScene::fly`]) from inside the same call.
//!
//! **Equal to the scalar path.** A lane runs the scalar path's operations in its order
//! (the same IEEE 754 operations on the same operands, packed or not), so its outcome is
//! the scalar [`PreparedScene::fly`]'s bit for bit: carry, side, apex, times, angles,
//! speeds and the work counted (`tests/tests/lanes.rs` checks equality to 1e-9 relative
//! and counts the bit-identical results).
//!
//! ```
//! use carry_core::{Ball, Launch, Integrator, Scene, lanes::{self, Shot}, units::{deg, rpm}};
//! let scene = Scene::<f64>::default().prepare(&Ball::standard())?;
//! let shots: Vec<Shot<'_, f64>> = (0..10)
//!     .map(|i| Launch { ball_speed_mps: 60.0 + f64::from(i), launch_angle_rad: deg(12.0),
//!         launch_direction_rad: 0.0, backspin_radps: rpm(2800.0), sidespin_radps: 0.0 }
//!         .ball_motion().map(|launch| Shot { scene: &scene, launch }))
//!     .collect::<Result<_, _>>()?;
//! let integrator = Integrator::default();
//! lanes::fly_each(&shots, &integrator, |i, out| {
//!     let scalar = scene.fly(&shots[i].launch, &integrator, None);
//!     assert_eq!(out, scalar);
//! });
//! # Ok::<(), carry_core::Error>(())
//! ```

#[doc(hidden)]
pub mod kernel;

use crate::aero::model::Forces;
use crate::aero::{State, VY, Y};
use crate::ball::BallMotion;
use crate::error::{Error, Result};
use crate::flight::{FlightOutcome, Integrator, MAX_ADAPTIVE_STEPS};
use crate::integrator::Method;
use crate::integrator::events::{Landing, Step, Tracker};
use crate::integrator::integrate::Adaptive;
use crate::real::{Real, larger, length, lit, smaller};
use crate::scene::{Effects, PreparedScene};
use crate::trajectory::Stats;
use crate::wind::WindField;
use kernel::{Pack, States};
use nalgebra::Vector3;

/// Shots advanced together by [`fly_each`]: 4 (a `wide::f64x4`: one AVX register of
/// `f64`, two SSE2 ones on baseline x86-64; docs/performance.md).
pub const LANES: usize = 4;

/// A precision the lanes kernel computes in, with its SIMD pack of [`LANES`] lanes
/// (`f64`: `wide::f64x4`, `f32`: `wide::f32x4`).
pub trait LaneReal: Real {
    /// The pack.
    #[doc(hidden)]
    type Pack: Pack<Scalar = Self>;
}

impl LaneReal for f64 {
    type Pack = wide::f64x4;
}

impl LaneReal for f32 {
    type Pack = wide::f32x4;
}

/// One shot of a batch: the prepared scene it flies through and its launch.
#[derive(Debug, Clone, Copy)]
pub struct Shot<'a, T: Real> {
    /// The scene (prepared for this shot's ball).
    pub scene: &'a PreparedScene<T>,
    /// The launch.
    pub launch: BallMotion<T>,
}

/// Whether the lanes kernel flies shots through `scene` with `integrator` itself (see the
/// module's docs); otherwise [`fly_each`] flies them on the scalar path.
#[must_use]
pub fn covers<T: Real>(scene: &PreparedScene<T>, integrator: &Integrator<T>) -> bool {
    covers_scene(scene) && matches!(integrator.method(), Ok(Method::Adaptive(_)))
}

fn covers_scene<T: Real>(scene: &PreparedScene<T>) -> bool {
    scene.ground.is_none()
        && scene.field.effects == Effects::ALL
        && matches!(scene.field.wind, WindField::None | WindField::Uniform(_))
        && matches!(scene.field.aero.forces, Forces::Modern { .. })
}

/// Flies every shot and hands each result to `sink` with the shot's index, in the order
/// the flights end (not the input order). Each result is what [`PreparedScene::fly`]
/// returns for that shot (without a recorder): an invalid shot gets its own typed error
/// and the others fly on. No allocation.
pub fn fly_each<T: LaneReal>(
    shots: &[Shot<'_, T>],
    integrator: &Integrator<T>,
    mut sink: impl FnMut(usize, Result<FlightOutcome<T>>),
) {
    const N: usize = LANES;
    let cfg = match integrator.method() {
        Ok(Method::Adaptive(cfg)) if T::Pack::LANES == N => cfg,
        _ => {
            for (i, s) in shots.iter().enumerate() {
                sink(i, s.scene.fly(&s.launch, integrator, None));
            }
            return;
        }
    };
    let zero = T::Pack::splat(T::zero());
    let mut run = Run::<T::Pack> {
        cfg,
        field: kernel::Field::zero(),
        y: [zero; 7],
        k1: [zero; 7],
        next: 0,
    };
    let mut lanes: [Option<Lane<'_, T>>; N] = core::array::from_fn(|_| None);
    for (l, slot) in lanes.iter_mut().enumerate() {
        *slot = run.refill(l, shots, integrator, &mut sink);
    }
    loop {
        // Each lane's checks at the top of the scalar loop; a lane that fails is refilled.
        let (mut any, mut fresh) = (false, false);
        for (l, slot) in lanes.iter_mut().enumerate() {
            while let Some(lane) = slot {
                match lane.check() {
                    Ok(()) => {
                        any = true;
                        fresh |= lane.fresh;
                        break;
                    }
                    Err(e) => {
                        sink(lane.index, Err(e));
                        *slot = run.refill(l, shots, integrator, &mut sink);
                    }
                }
            }
        }
        if !any {
            return;
        }
        if fresh {
            // `k₁ = f(y₀)` of the lanes just filled (one evaluation of every lane).
            let k = kernel::eval(&run.field, &run.y);
            for (l, lane) in lanes.iter_mut().enumerate() {
                if let Some(lane) = lane.as_mut().filter(|lane| lane.fresh) {
                    kernel::set_lane(&mut run.k1, l, &kernel::lane(&k, l));
                    lane.stats.force_evaluations = 1;
                    lane.fresh = false;
                }
            }
        }
        let mut h = T::Pack::splat(T::one());
        for (l, lane) in lanes.iter().enumerate() {
            if let Some(lane) = lane {
                h.set(l, lane.h);
            }
        }
        let (rtol, atol) = (T::Pack::splat(cfg.rtol), T::Pack::splat(cfg.atol));
        let st = kernel::step(&run.field, &run.y, &run.k1, h, rtol, atol);
        for (l, slot) in lanes.iter_mut().enumerate() {
            let Some(lane) = slot else { continue };
            let done = run.advance(lane, l, &st);
            if let Some(result) = done {
                sink(lane.index, result);
                *slot = run.refill(l, shots, integrator, &mut sink);
            }
        }
    }
}

/// The lanes' shared arrays.
struct Run<P: Pack> {
    cfg: Adaptive<P::Scalar>,
    field: kernel::Field<P>,
    y: States<P>,
    k1: States<P>,
    /// The next shot to start.
    next: usize,
}

/// One lane's own bookkeeping (the scalar loop's locals).
struct Lane<'s, T: Real> {
    index: usize,
    scene: &'s PreparedScene<T>,
    axis: Vector3<T>,
    t: T,
    h: T,
    rejected_last: bool,
    refined: bool,
    /// `k₁` not evaluated yet.
    fresh: bool,
    stats: Stats,
    tracker: Tracker<'s, 's, T>,
}

impl<T: Real> Lane<'_, T> {
    /// The checks at the top of the scalar step loop; clips the step to the time limit.
    fn check(&mut self) -> Result<()> {
        if self.stats.steps.saturating_add(self.stats.rejected_steps) >= MAX_ADAPTIVE_STEPS {
            return Err(Error::StepLimit);
        }
        let remaining = self.scene.time_limit - self.t;
        if !(remaining > T::zero()) {
            return Err(Error::TimeLimit);
        }
        self.h = smaller(self.h, remaining);
        Ok(())
    }
}

/// `x^(−3/16)` by four square roots (the scalar controller's `inv_root_3_16`).
#[inline]
fn inv_root_3_16<T: Real>(x: T) -> T {
    let r8 = x.root().root().root();
    T::one() / (r8 * r8.root())
}

impl<T: Real, P: Pack<Scalar = T>> Run<P> {
    /// The next shot the kernel covers into lane `l` (the others fly on the scalar path,
    /// and invalid ones get their error, on the way), or `None` when the shots are done.
    fn refill<'s>(
        &mut self,
        l: usize,
        shots: &[Shot<'s, T>],
        integrator: &Integrator<T>,
        sink: &mut impl FnMut(usize, Result<FlightOutcome<T>>),
    ) -> Option<Lane<'s, T>> {
        while let Some(shot) = shots.get(self.next) {
            let index = self.next;
            self.next = self.next.saturating_add(1);
            if !covers_scene(shot.scene) {
                sink(index, shot.scene.fly(&shot.launch, integrator, None));
                continue;
            }
            match self.start(l, shot) {
                Ok((y0, axis)) => {
                    return Some(Lane {
                        index,
                        scene: shot.scene,
                        axis,
                        t: T::zero(),
                        h: smaller(self.cfg.initial_step, self.cfg.max_step),
                        rejected_last: false,
                        refined: false,
                        fresh: true,
                        stats: Stats::default(),
                        tracker: Tracker::new(shot.scene.landing_height, &y0, axis, None),
                    });
                }
                Err(e) => sink(index, Err(e)),
            }
        }
        None
    }

    /// The scalar flight's validation and start (`flight::run`), into lane `l`.
    fn start(&mut self, l: usize, shot: &Shot<'_, T>) -> Result<(State<T>, Vector3<T>)> {
        let scene = shot.scene;
        let launch = shot.launch.validated()?;
        let (y0, axis) = crate::flight::start_state(scene, &launch)?;
        if y0[Y] <= scene.landing_height && launch.velocity_mps.y <= T::zero() {
            // Never comes down through the landing height (no ground in a covered scene).
            return Err(Error::NoLanding);
        }
        self.set_field(l, scene, &axis);
        kernel::set_lane(&mut self.y, l, &y0);
        Ok((y0, axis))
    }

    /// Lane `l` of the force field: `scene`'s (a covered scene) with the spin axis `axis`.
    fn set_field(&mut self, l: usize, scene: &PreparedScene<T>, axis: &Vector3<T>) {
        let Forces::Modern {
            drag_v,
            crisis,
            spin: ref laws,
        } = scene.field.aero.forces
        else {
            return;
        };
        let wind = match scene.field.wind {
            WindField::Uniform(w) => w,
            _ => Vector3::zeros(),
        };
        let f = &mut self.field;
        let put = |x: &mut P, v: T| x.set(l, v);
        put(&mut f.minus_gravity, -scene.field.gravity);
        for k in 0..3 {
            put(&mut f.wind[k], wind[k]);
            put(&mut f.axis[k], axis[k]);
        }
        put(&mut f.decay, scene.field.aero.decay);
        put(&mut f.drag_v, drag_v);
        put(&mut f.crisis_below, crisis.below);
        put(&mut f.crisis_k6, crisis.per_speed_6);
        put(&mut f.per_spin, laws.per_spin);
        put(&mut f.second, laws.second);
        put(&mut f.second_sq, laws.second_sq);
        put(&mut f.saturated_lift, laws.lift_saturated);
        put(&mut f.saturated_drag, laws.drag_saturated);
        for k in 0..5 {
            put(&mut f.rising_lift[k], laws.rising.lift.0[k]);
            put(&mut f.rising_drag[k], laws.rising.drag.0[k]);
            put(&mut f.second_lift[k], laws.second_rising.lift.0[k]);
            put(&mut f.second_drag[k], laws.second_rising.drag.0[k]);
        }
    }

    /// Lane `l`'s part of the scalar loop after the step's stages: acceptance, the grazing
    /// landing's redone step, the apex and landing, the step size. `Some` when the flight
    /// is over (landed or failed).
    fn advance(
        &mut self,
        lane: &mut Lane<'_, T>,
        l: usize,
        st: &kernel::Stages<P>,
    ) -> Option<Result<FlightOutcome<T>>> {
        let cfg = &self.cfg;
        let (safety, grow, shrink) = (lit::<T>(0.9), lit::<T>(5.0), lit::<T>(0.2));
        lane.stats.force_evaluations = lane.stats.force_evaluations.saturating_add(6);
        let err = st.err.get(l);
        let y1 = kernel::lane(&st.y1, l);
        if err <= T::one() && y1.iter().all(|x| x.is_finite()) {
            let hl = lane.scene.landing_height;
            let y0 = kernel::lane(&self.y, l);
            // Only a step with an apex or a landing in it (or a grazing landing to redo)
            // needs the tracker: without them it changes nothing and finds nothing.
            if (y0[VY] > T::zero() && y1[VY] <= T::zero()) || y1[Y] <= hl {
                let (k1, k7) = (kernel::lane(&self.k1, l), kernel::lane(&st.k7, l));
                let (k3, k4) = (kernel::lane(&st.k3, l), kernel::lane(&st.k4, l));
                let (k5, k6) = (kernel::lane(&st.k5, l), kernel::lane(&st.k6, l));
                let step = Step {
                    h: lane.h,
                    y0: &y0,
                    y1: &y1,
                    f0: &k1,
                    f1: &k7,
                    mid: Some([&k3, &k4, &k5, &k6]),
                };
                let refine = if !lane.refined && lane.tracker.ends_below(&step) {
                    lane.tracker.grazing_landing(&step)
                } else {
                    None
                };
                if let Some(th) = refine {
                    lane.refined = true;
                    if th < T::one() && th > T::zero() {
                        lane.stats.rejected_steps = lane.stats.rejected_steps.saturating_add(1);
                        lane.h *= th;
                        return None;
                    }
                }
                lane.stats.steps = lane.stats.steps.saturating_add(1);
                match lane.tracker.on_step(lane.t, &step) {
                    Err(e) => return Some(Err(e)),
                    Ok(Some(th)) => {
                        return Some(outcome(lane, &Landing::in_step(lane.t, th, &step)));
                    }
                    Ok(None) => {}
                }
            } else {
                lane.stats.steps = lane.stats.steps.saturating_add(1);
            }
            lane.t += lane.h;
            kernel::set_lane(&mut self.y, l, &y1);
            kernel::set_lane(&mut self.k1, l, &kernel::lane(&st.k7, l));
            let mut factor = if err > T::zero() {
                smaller(safety * inv_root_3_16(err), grow)
            } else {
                grow
            };
            if lane.rejected_last {
                factor = smaller(factor, T::one());
            }
            lane.h = smaller(lane.h * larger(factor, shrink), cfg.max_step);
            lane.rejected_last = false;
        } else {
            lane.stats.rejected_steps = lane.stats.rejected_steps.saturating_add(1);
            let factor = if err.is_finite() {
                larger(safety * inv_root_3_16(err), shrink)
            } else {
                shrink
            };
            lane.h *= smaller(factor, safety);
            lane.rejected_last = true;
            let eps16 = T::default_epsilon() * lit(16.0);
            if !(lane.h > eps16 * larger(lane.t, T::one())) {
                return Some(Err(Error::StepSizeUnderflow));
            }
        }
        None
    }
}

/// The flight's outcome from its landing (`flight::run`'s end, without a ground).
fn outcome<T: Real>(lane: &Lane<'_, T>, landing: &Landing<T>) -> Result<FlightOutcome<T>> {
    let scene = lane.scene;
    let tracker = &lane.tracker;
    let (apex_m, apex_time_s) = (tracker.apex_height, tracker.apex_time);
    let y = landing.state;
    let speed = length(&Vector3::new(y[3], y[4], y[5]));
    if !(y.iter().all(|x| x.is_finite())
        && speed.is_finite()
        && landing.time.is_finite()
        && apex_m.is_finite())
    {
        return Err(Error::Unstable);
    }
    let p0 = scene.launch_position;
    let position = Vector3::new(y[0], y[1], y[2]);
    let velocity = Vector3::new(y[3], y[4], y[5]);
    let carry_x = position.x - p0.x;
    let side = position.z - p0.z;
    let spin = y[crate::aero::S];
    let (carry_m, landing_angle_rad) =
        crate::flight::carry_and_landing_angle(carry_x, side, &velocity);
    Ok(FlightOutcome {
        carry_m,
        carry_x_m: carry_x,
        side_m: side,
        apex_m,
        apex_time_s,
        flight_time_s: landing.time,
        landing_angle_rad,
        landing_speed_mps: length(&velocity),
        landing_spin_radps: spin,
        landing_position_m: position,
        landing_velocity_mps: velocity,
        landing_spin_vector_radps: lane.axis * spin,
        air_density_kgm3: scene.density,
        stats: lane.stats,
        recording_full: false,
        ground: None,
    })
}
