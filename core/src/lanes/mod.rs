//! The lanes kernel (issue 37): many flights advanced together, [`LANES`] at a time, as a
//! structure of arrays, for batches. Each lane is one shot with its own adaptive step, its
//! own acceptance, apex and landing; a lane that lands (or fails) is refilled at once with
//! the next shot, so the lanes stay full until the batch runs out. The force evaluations,
//! the Runge–Kutta stages, the error norm, the acceptance test and the step controller run
//! across the lanes on SIMD packs (`wide`'s, or AVX or AVX-512 registers through an [`Avx`]
//! token: [`fly_each_on`]), the lanes' `t`, `h` and states kept in packs between steps. On the AVX
//! packs the apex and the landing are located packed too (one Newton root finding across
//! the lanes, each on its own interpolant, the scalar tracker's operations); a lane's event
//! decision and outcome, a refill and a failure are handled lane by lane, and a landing that
//! may graze (and every event on `wide`'s packs) goes through the scalar path's own tracker
//! (docs/performance.md, "Lanes kernel").
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
//! and counts the bit-identical results). The one exception is an [`Avx`] token with FMA
//! ([`Avx::with_fma_unchecked`]): its `f64` kernel fuses multiply–adds, and its results
//! are within 1e-9 relative of the scalar path's, not equal ([`Avx::exact`] drops FMA).
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

/// What every x86 pack ([`avx`]'s and [`avx512`]'s) writes the same way: its operators,
/// each one intrinsic on the register it wraps (`[+, −, ×, ÷, &, |, ^]` in that order),
/// `!` as `^` with all ones (`$set1`), and its `N` lanes in place (`lanes`, `lanes_mut`:
/// one scalar load or store each, also where the caller is not compiled for the
/// register's features and would otherwise move the whole register through memory).
/// `$safe` is the module's macro that runs an intrinsic under its soundness note (a pack
/// exists only inside code compiled for, and run on, a CPU with its features).
#[cfg(target_arch = "x86_64")]
macro_rules! x86_pack {
    (
        impl[$($gen:tt)*] $pack:ty, $scalar:ty, $n:literal, $safe:ident, $set1:ident,
        [$add:ident, $sub:ident, $mul:ident, $div:ident, $and:ident, $or:ident, $xor:ident]
    ) => {
        x86_pack!(@op [$($gen)*] $pack, $safe, Add, add, $add);
        x86_pack!(@op [$($gen)*] $pack, $safe, Sub, sub, $sub);
        x86_pack!(@op [$($gen)*] $pack, $safe, Mul, mul, $mul);
        x86_pack!(@op [$($gen)*] $pack, $safe, Div, div, $div);
        x86_pack!(@op [$($gen)*] $pack, $safe, BitAnd, bitand, $and);
        x86_pack!(@op [$($gen)*] $pack, $safe, BitOr, bitor, $or);
        x86_pack!(@op [$($gen)*] $pack, $safe, BitXor, bitxor, $xor);

        impl<$($gen)*> core::ops::Not for $pack {
            type Output = Self;
            #[inline(always)]
            fn not(self) -> Self {
                self ^ Self($safe!($set1(<$scalar>::from_bits(!0))))
            }
        }

        impl<$($gen)*> $pack {
            /// The lanes in place.
            #[inline(always)]
            fn lanes(&self) -> &[$scalar; $n] {
                // SAFETY: the pack is a transparent SIMD register of exactly `N` lanes of
                // its scalar (any bit pattern valid), aligned at least as the scalar: the
                // layout of `[scalar; N]`.
                unsafe { &*core::ptr::from_ref(self).cast::<[$scalar; $n]>() }
            }

            /// See `lanes`.
            #[inline(always)]
            fn lanes_mut(&mut self) -> &mut [$scalar; $n] {
                // SAFETY: as in `lanes`; the borrow is unique.
                unsafe { &mut *core::ptr::from_mut(self).cast::<[$scalar; $n]>() }
            }
        }
    };
    (@op [$($gen:tt)*] $pack:ty, $safe:ident, $tr:ident, $f:ident, $intr:ident) => {
        impl<$($gen)*> core::ops::$tr for $pack {
            type Output = Self;
            #[inline(always)]
            fn $f(self, o: Self) -> Self {
                Self($safe!($intr(self.0, o.0)))
            }
        }
    };
}

#[cfg(target_arch = "x86_64")]
mod avx;
#[cfg(target_arch = "x86_64")]
mod avx512;
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
use crate::real::{Real, length, lit, smaller};
use crate::scene::{Effects, PreparedScene};
use crate::trajectory::Stats;
use crate::wind::WindField;
use kernel::{Pack, States};
use nalgebra::Vector3;

/// Shots advanced together by [`fly_each`]: 4 (`f64`: one AVX register with the [`Avx`]
/// token, else a `wide::f64x4`, two SSE2 registers on baseline x86-64; docs/performance.md).
/// [`fly_each_on`] with the token flies `f32` shots eight at a time (one AVX register), and
/// with a token with AVX-512 `f64` shots eight and `f32` shots sixteen at a time (one
/// 512-bit register).
pub const LANES: usize = 4;

/// A precision the lanes kernel computes in, with its SIMD pack of [`LANES`] lanes
/// (`f64`: `wide::f64x4`, `f32`: `wide::f32x4`).
pub trait LaneReal: Real {
    /// The pack.
    #[doc(hidden)]
    type Pack: Pack<Scalar = Self>;

    /// [`fly_each`] on this precision's AVX packs (four `f64` or eight `f32` lanes; with
    /// AVX-512, eight `f64` or sixteen `f32`).
    #[cfg(target_arch = "x86_64")]
    #[doc(hidden)]
    fn fly_each_avx(
        cpu: Avx,
        shots: &[Shot<'_, Self>],
        integrator: &Integrator<Self>,
        sink: &mut dyn FnMut(usize, Result<FlightOutcome<Self>>),
    );

    /// [`fly_each`] on the fastest packs `cpu` allows (the baseline ones without it).
    #[doc(hidden)]
    #[inline]
    fn fly_each_on(
        cpu: Option<Avx>,
        shots: &[Shot<'_, Self>],
        integrator: &Integrator<Self>,
        sink: &mut dyn FnMut(usize, Result<FlightOutcome<Self>>),
    ) {
        #[cfg(target_arch = "x86_64")]
        if let Some(cpu) = cpu {
            return Self::fly_each_avx(cpu, shots, integrator, sink);
        }
        let _ = cpu;
        fly_each_in::<Self::Pack, LANES>(shots, integrator, sink);
    }
}

impl LaneReal for f64 {
    type Pack = wide::f64x4;

    #[cfg(target_arch = "x86_64")]
    fn fly_each_avx(
        cpu: Avx,
        shots: &[Shot<'_, Self>],
        integrator: &Integrator<Self>,
        sink: &mut dyn FnMut(usize, Result<FlightOutcome<Self>>),
    ) {
        avx::fly_each(cpu, shots, integrator, sink);
    }
}

impl LaneReal for f32 {
    type Pack = wide::f32x4;

    #[cfg(target_arch = "x86_64")]
    fn fly_each_avx(
        cpu: Avx,
        shots: &[Shot<'_, Self>],
        integrator: &Integrator<Self>,
        sink: &mut dyn FnMut(usize, Result<FlightOutcome<Self>>),
    ) {
        avx::fly_each_f32(cpu, shots, integrator, sink);
    }
}

/// A proof that the CPU running the program has AVX (x86-64), and perhaps FMA: with it,
/// [`fly_each_on`] flies shots on 256-bit packs compiled for AVX whatever the build's
/// baseline (the `x86-64` baseline has SSE2 only). The core is `no_std` and cannot ask the
/// CPU; a host makes one after `is_x86_feature_detected!("avx")` (and `"fma"`:
/// `carry_io::lanes`). On other architectures it exists but changes nothing.
///
/// Without FMA ([`Avx::new_unchecked`], [`Avx::exact`]) every `f64` and `f32` result is the
/// scalar path's bit for bit. With FMA ([`Avx::with_fma_unchecked`]) the `f64` kernel fuses
/// its multiply–adds (one rounding instead of two): faster, and each figure within 1e-9
/// relative of the scalar path's rather than equal (docs/performance.md, "Lanes kernel";
/// `f32` stays exact).
///
/// With AVX-512 ([`Avx::with_avx512_unchecked`]: AVX-512 F and DQ) the kernel runs on
/// 512-bit packs, eight `f64` or sixteen `f32` lanes, fused (`f64`) or exact as the token's
/// FMA says: the exact ones are the scalar path's bit for bit too, and the fused ones give
/// the fused 256-bit packs' results bit for bit (a lane's operations do not depend on the
/// pack's width).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Avx {
    fma: bool,
    avx512: bool,
}

impl Avx {
    /// The token (AVX, no FMA: results bit for bit the scalar path's).
    ///
    /// # Safety
    /// The CPU that runs the program must have AVX (and the OS must save its registers):
    /// what `std::is_x86_feature_detected!("avx")` checks.
    #[allow(unsafe_code)]
    #[must_use]
    pub const unsafe fn new_unchecked() -> Self {
        Self {
            fma: false,
            avx512: false,
        }
    }

    /// The token with FMA: the `f64` kernel fuses its multiply–adds.
    ///
    /// # Safety
    /// The CPU that runs the program must also have FMA (FMA3): what
    /// `std::is_x86_feature_detected!("fma")` checks.
    #[allow(unsafe_code)]
    #[must_use]
    pub const unsafe fn with_fma_unchecked(self) -> Self {
        Self { fma: true, ..self }
    }

    /// The token with AVX-512: the `f64` kernel runs on eight lanes a 512-bit register
    /// (fused with FMA, else bit for bit the scalar path's).
    ///
    /// # Safety
    /// The CPU that runs the program must also have AVX-512 F and DQ (and the OS must save
    /// their registers): what `std::is_x86_feature_detected!("avx512f")` and `("avx512dq")`
    /// check.
    #[allow(unsafe_code)]
    #[must_use]
    pub const unsafe fn with_avx512_unchecked(self) -> Self {
        Self {
            avx512: true,
            ..self
        }
    }

    /// The token without FMA: the packs whose results are the scalar path's bit for bit
    /// (eight lanes a register with AVX-512, four without).
    #[must_use]
    pub const fn exact(self) -> Self {
        Self { fma: false, ..self }
    }

    /// The token without AVX-512: the 256-bit packs (four `f64` lanes).
    #[must_use]
    pub const fn avx256(self) -> Self {
        Self {
            avx512: false,
            ..self
        }
    }

    /// Whether the `f64` kernel fuses its multiply–adds with this token.
    #[must_use]
    pub const fn fma(self) -> bool {
        self.fma
    }

    /// Whether the `f64` kernel runs on AVX-512 packs (eight lanes) with this token.
    #[must_use]
    pub const fn avx512(self) -> bool {
        self.avx512
    }
}

/// [`fly_each`] on the fastest packs `cpu` allows: with an [`Avx`] token, shots fly on AVX
/// packs (four `f64` or eight `f32` lanes; the same results bit for bit, or in `f64` with
/// a token with FMA within 1e-9 relative; docs/performance.md, "Lanes kernel"); without one,
/// as [`fly_each`].
pub fn fly_each_on<T: LaneReal>(
    cpu: Option<Avx>,
    shots: &[Shot<'_, T>],
    integrator: &Integrator<T>,
    mut sink: impl FnMut(usize, Result<FlightOutcome<T>>),
) {
    T::fly_each_on(cpu, shots, integrator, &mut sink);
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
#[inline]
pub fn fly_each<T: LaneReal>(
    shots: &[Shot<'_, T>],
    integrator: &Integrator<T>,
    sink: impl FnMut(usize, Result<FlightOutcome<T>>),
) {
    fly_each_in::<T::Pack, LANES>(shots, integrator, sink);
}

/// [`fly_each`] on the packs `P`: the whole kernel, inlined into its caller, so that a
/// caller compiled with more target features (a host's runtime dispatch to AVX2,
/// `carry_io::lanes`) compiles the kernel with them.
#[doc(hidden)]
#[inline(always)]
pub fn fly_each_in<P: Pack, const N: usize>(
    shots: &[Shot<'_, P::Scalar>],
    integrator: &Integrator<P::Scalar>,
    mut sink: impl FnMut(usize, Result<FlightOutcome<P::Scalar>>),
) {
    let cfg = match integrator.method() {
        Ok(Method::Adaptive(cfg)) if P::LANES == N => cfg,
        _ => {
            for (i, s) in shots.iter().enumerate() {
                sink(i, s.scene.fly(&s.launch, integrator, None));
            }
            return;
        }
    };
    let mut run = Run::<P, N>::new(cfg);
    // The lanes' states and `k₁` are locals, not `run`'s fields: kept in registers (and
    // spill slots) rather than in memory, where a blend compiles to a masked store (slow).
    let zero = P::splat(lit(0.0));
    let (mut y, mut k1): (States<P>, States<P>) = ([zero; 7], [zero; 7]);
    let mut lanes: [Option<Lane<'_, P::Scalar>>; N] = core::array::from_fn(|_| None);
    for (l, slot) in lanes.iter_mut().enumerate() {
        *slot = run.refill(l, shots, integrator, &mut sink, &mut y);
    }
    let (rtol, atol) = (P::splat(cfg.rtol), P::splat(cfg.atol));
    loop {
        // The checks at the top of the scalar step loop, every lane at once; a lane that
        // fails is refilled (and the new shot checked in the next round).
        loop {
            let failed = run.check();
            if failed == 0 {
                break;
            }
            for (l, slot) in lanes.iter_mut().enumerate() {
                if failed & (1 << l) != 0
                    && let Some(lane) = slot.take()
                {
                    sink(lane.index, Err(run.failure(l)));
                    *slot = run.refill(l, shots, integrator, &mut sink, &mut y);
                }
            }
        }
        if run.active == 0 {
            return;
        }
        if run.fresh != 0 {
            // `k₁ = f(y₀)` of the lanes just filled (one evaluation of every lane).
            let k = kernel::eval(&run.field, &y);
            let fresh = P::mask(run.fresh);
            for (k1, ki) in k1.iter_mut().zip(k.iter()) {
                *k1 = fresh.blend(*ki, *k1);
            }
            run.fresh = 0;
        }
        let st = kernel::step(&run.field, &y, &k1, run.h, rtol, atol);
        run.advance(
            &st,
            (&mut y, &mut k1),
            &mut lanes,
            shots,
            integrator,
            &mut sink,
        );
    }
}

/// The lanes' state, kept in packs between steps (the scalar loop's locals, lane by lane).
struct Run<P: Pack, const N: usize> {
    cfg: Adaptive<P::Scalar>,
    field: kernel::Field<P>,
    /// Time `t`, step `h`, the flight's time limit and landing height, and the mask of
    /// "the last step was rejected".
    t: P,
    h: P,
    time_limit: P,
    landing_height: P,
    rejected_last: P,
    /// Steps tried (accepted or not) and rejected, per lane.
    attempts: [u32; N],
    rejected: [u32; N],
    /// The address of the scene whose field each lane holds (0: none): a shot through the
    /// lane's last scene sets only its spin axis.
    scene_of: [usize; N],
    /// Bit masks of the lanes in flight, of those whose `k₁` is not evaluated yet, and of
    /// those whose grazing landing was refined (the scalar loop's `refined`).
    active: u32,
    fresh: u32,
    refined: u32,
    /// The next shot to start.
    next: usize,
}

/// One lane's own bookkeeping, used at its events only.
struct Lane<'s, T: Real> {
    index: usize,
    scene: &'s PreparedScene<T>,
    axis: Vector3<T>,
    /// The apex so far (height, time): the scalar tracker's.
    apex_m: T,
    apex_time_s: T,
}

/// What a lane's events made of its accepted step.
enum Event<T: Real> {
    /// Nothing ends the flight: the step is taken.
    Take,
    /// A grazing landing: the step is redone with `h·θ` (counted as rejected).
    Redo(T),
    /// The flight is over (landed or failed).
    Done(Result<FlightOutcome<T>>),
}

/// `x^(−3/16)` by four square roots in every lane (the scalar controller's
/// `inv_root_3_16`).
#[inline(always)]
fn inv_root_3_16<P: Pack>(x: P) -> P {
    if P::FUSED {
        // (The fused packs, whose results need only be within 1e-9: the same value to an
        // ulp or two, `x^(1/16) · (1/x^(1/4))`, the division beside the last two roots
        // rather than after them.)
        let r4 = x.sqrt().sqrt();
        return r4.sqrt().sqrt() * (P::splat(lit(1.0)) / r4);
    }
    let r8 = x.sqrt().sqrt().sqrt();
    P::splat(lit(1.0)) / (r8 * r8.sqrt())
}

/// `smaller(a, b)` of `crate::real` (C's `fmin`) as one blend.
#[inline(always)]
fn smaller_p<P: Pack>(a: P, b: P) -> P {
    (b.lt(a) | a.ne(a)).blend(b, a)
}

/// `larger(a, b)` of `crate::real` (C's `fmax`) as one blend.
#[inline(always)]
fn larger_p<P: Pack>(a: P, b: P) -> P {
    (a.lt(b) | a.ne(a)).blend(b, a)
}

impl<T: Real, P: Pack<Scalar = T>, const N: usize> Run<P, N> {
    fn new(cfg: Adaptive<T>) -> Self {
        let zero = P::splat(T::zero());
        Self {
            cfg,
            field: kernel::Field::zero(),
            t: zero,
            h: P::splat(T::one()),
            time_limit: P::splat(T::one()),
            landing_height: zero,
            rejected_last: zero,
            attempts: [0; N],
            rejected: [0; N],
            scene_of: [0; N],
            active: 0,
            fresh: 0,
            refined: 0,
            next: 0,
        }
    }

    /// The checks at the top of the scalar step loop (the step limit, the time limit) in
    /// every lane, and the step clipped to the time left: the mask of the lanes that fail.
    #[inline(always)]
    fn check(&mut self) -> u32 {
        let remaining = self.time_limit - self.t;
        let mut failed = !P::splat(T::zero()).lt(remaining).bits();
        for (l, a) in self.attempts.iter().enumerate() {
            if *a >= MAX_ADAPTIVE_STEPS {
                failed |= 1 << l;
            }
        }
        // (Neither is NaN in a lane in flight: the scalar path's `below`.)
        self.h = remaining.lt(self.h).blend(remaining, self.h);
        failed & self.active
    }

    /// The error of lane `l` that failed [`Run::check`].
    fn failure(&self, l: usize) -> Error {
        if self
            .attempts
            .get(l)
            .is_some_and(|a| *a >= MAX_ADAPTIVE_STEPS)
        {
            Error::StepLimit
        } else {
            Error::TimeLimit
        }
    }

    /// Lane `l`'s step counts as the scalar path's [`Stats`].
    fn stats(&self, l: usize) -> Stats {
        let (a, r) = (
            self.attempts.get(l).copied().unwrap_or(0),
            self.rejected.get(l).copied().unwrap_or(0),
        );
        Stats {
            steps: a.saturating_sub(r),
            rejected_steps: r,
            force_evaluations: a.saturating_mul(6).saturating_add(1),
        }
    }

    /// The next shot the kernel covers into lane `l` (the others fly on the scalar path,
    /// and invalid ones get their error, on the way), its start state written into lane `l`
    /// of `y`, or `None` when the shots are done.
    fn refill<'s>(
        &mut self,
        l: usize,
        shots: &[Shot<'s, T>],
        integrator: &Integrator<T>,
        sink: &mut impl FnMut(usize, Result<FlightOutcome<T>>),
        y: &mut States<P>,
    ) -> Option<Lane<'s, T>> {
        let bit = 1u32 << l;
        while let Some(shot) = shots.get(self.next) {
            let index = self.next;
            self.next = self.next.saturating_add(1);
            if !covers_scene(shot.scene) {
                sink(index, shot.scene.fly(&shot.launch, integrator, None));
                continue;
            }
            match self.start(l, shot) {
                Ok((y0, axis)) => {
                    self.t.set(l, T::zero());
                    self.h
                        .set(l, smaller(self.cfg.initial_step, self.cfg.max_step));
                    self.time_limit.set(l, shot.scene.time_limit);
                    self.landing_height.set(l, shot.scene.landing_height);
                    self.rejected_last.set(l, T::zero());
                    if let (Some(a), Some(r)) = (self.attempts.get_mut(l), self.rejected.get_mut(l))
                    {
                        (*a, *r) = (0, 0);
                    }
                    self.active |= bit;
                    self.fresh |= bit;
                    self.refined &= !bit;
                    kernel::set_lane(y, l, &y0);
                    return Some(Lane {
                        index,
                        scene: shot.scene,
                        axis,
                        apex_m: y0[Y],
                        apex_time_s: T::zero(),
                    });
                }
                Err(e) => sink(index, Err(e)),
            }
        }
        self.active &= !bit;
        self.fresh &= !bit;
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
        Ok((y0, axis))
    }

    /// Lane `l` of the force field: `scene`'s (a covered scene) with the spin axis `axis`.
    fn set_field(&mut self, l: usize, scene: &PreparedScene<T>, axis: &Vector3<T>) {
        for k in 0..3 {
            self.field.axis[k].set(l, axis[k]);
        }
        // (Shots in one call borrow their scenes for the whole call: one address, one scene.)
        let address = core::ptr::from_ref(scene).addr();
        match self.scene_of.get_mut(l) {
            Some(a) if *a != address => *a = address,
            _ => return,
        }
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

    /// The scalar loop after the step's stages, every lane at once: acceptance, the step
    /// size, `t`, `y`, `k₁`. Only a lane with an apex or a landing in its accepted step
    /// (or a grazing landing to redo), and a lane that fails, is handled on its own.
    #[inline(always)]
    fn advance<'s>(
        &mut self,
        st: &kernel::Stages<P>,
        (y, k1): (&mut States<P>, &mut States<P>),
        lanes: &mut [Option<Lane<'s, T>>; N],
        shots: &[Shot<'s, T>],
        integrator: &Integrator<T>,
        sink: &mut impl FnMut(usize, Result<FlightOutcome<T>>),
    ) {
        let zero = P::splat(T::zero());
        let one = P::splat(T::one());
        let (safety, grow, shrink) = (P::splat(lit(0.9)), P::splat(lit(5.0)), P::splat(lit(0.2)));
        let active = self.active;
        for (l, a) in self.attempts.iter_mut().enumerate() {
            if active & (1 << l) != 0 {
                *a = a.saturating_add(1);
            }
        }
        // A finite `y₁` (`|x| < ∞` is false for ±∞ and NaN) and `err ≤ 1`.
        let inf = P::splat(lit(f64::INFINITY));
        let mut finite_y1 = st.y1[0].abs().lt(inf);
        for x in &st.y1[1..] {
            finite_y1 = finite_y1 & x.abs().lt(inf);
        }
        let ok = st.err.le(one) & finite_y1;
        // Only a step with an apex or a landing in it (or a grazing landing to redo)
        // needs the tracker: without them it changes nothing and finds nothing.
        let event = (zero.lt(y[VY]) & st.y1[VY].le(zero)) | st.y1[Y].le(self.landing_height);
        let accepted = ok.bits() & active;
        // The lanes that may have an event, before the error norm is known, and those that
        // do (accepted).
        let maybe = (event & finite_y1).bits() & active;
        let events = maybe & accepted;
        let rejected = active & !accepted;
        let mut take = accepted & !events;
        // The controller (`integrate::dormand_prince`): an accepted step grows `h` by
        // `min(0.9·err^(−3/16), 5)` (at most 1 after a rejection), at least 0.2, to at most
        // `max_step`; a rejected one shrinks it by `max(0.9·err^(−3/16), 0.2)`, at most 0.9
        // (0.2 for a NaN error). Computed before the events (which change neither for a
        // lane that takes its step or rejects it), so that its chain of four square roots
        // and a division runs while the events' root finding does (both are latency).
        let ir = safety * inv_root_3_16(st.err);
        let mut grown = zero.lt(st.err).blend(grow.lt(ir).blend(grow, ir), grow);
        grown = self
            .rejected_last
            .blend(one.lt(grown).blend(one, grown), grown);
        let h_take = self.h * grown.lt(shrink).blend(shrink, grown);
        let max_step = P::splat(self.cfg.max_step);
        let h_take = max_step.lt(h_take).blend(max_step, h_take);
        let finite = st.err.abs().lt(inf);
        let shrunk = finite.blend(larger_p(ir, shrink), shrink);
        let h_reject = self.h * smaller_p(shrunk, safety);
        if events != 0 {
            // Located in every lane that may have an event, whether its step passes or not
            // (known only from the error norm, which this then does not wait for); only
            // the lanes whose step passes use it.
            let found = self.locate(maybe, st, y, k1);
            for (l, slot) in lanes.iter_mut().enumerate() {
                if events & (1 << l) == 0 {
                    continue;
                }
                let Some(lane) = slot else { continue };
                if found.slow & (1 << l) == 0 {
                    // (The result goes to `sink` from `found`, not through an `Event`: one
                    // copy of the outcome fewer.)
                    if self.found(lane, l, &found, sink) {
                        *slot = self.refill(l, shots, integrator, sink, y);
                    } else {
                        take |= 1 << l;
                    }
                    continue;
                }
                let (y0, f0) = (kernel::lane(y, l), kernel::lane(k1, l));
                match self.event(lane, l, st, &y0, &f0) {
                    Event::Take => take |= 1 << l,
                    Event::Redo(th) => {
                        if let Some(r) = self.rejected.get_mut(l) {
                            *r = r.saturating_add(1);
                        }
                        self.h.set(l, self.h.get(l) * th);
                    }
                    Event::Done(result) => {
                        sink(lane.index, result);
                        *slot = self.refill(l, shots, integrator, sink, y);
                    }
                }
            }
        }
        let (tk, rj) = (P::mask(take), P::mask(rejected));
        let h0 = self.h;
        self.h = tk.blend(h_take, rj.blend(h_reject, h0));
        self.t = tk.blend(self.t + h0, self.t);
        for (y, y1) in y.iter_mut().zip(st.y1.iter()) {
            *y = tk.blend(*y1, *y);
        }
        for (k1, k7) in k1.iter_mut().zip(st.k7.iter()) {
            *k1 = tk.blend(*k7, *k1);
        }
        self.rejected_last = (rj | self.rejected_last) & !tk;
        if rejected != 0 {
            for (l, r) in self.rejected.iter_mut().enumerate() {
                if rejected & (1 << l) != 0 {
                    *r = r.saturating_add(1);
                }
            }
            let eps16 = P::splat(T::default_epsilon() * lit(16.0));
            let floor = eps16 * larger_p(self.t, one);
            let under = !floor.lt(self.h).bits() & rejected;
            if under != 0 {
                for (l, slot) in lanes.iter_mut().enumerate() {
                    if under & (1 << l) != 0
                        && let Some(lane) = slot.take()
                    {
                        sink(lane.index, Err(Error::StepSizeUnderflow));
                        *slot = self.refill(l, shots, integrator, sink, y);
                    }
                }
            }
        }
    }

    /// Lane `l`'s events in its accepted step (the scalar loop's tracker calls): the
    /// grazing landing's redone step, the apex, the landing.
    fn event(
        &mut self,
        lane: &mut Lane<'_, T>,
        l: usize,
        st: &kernel::Stages<P>,
        y0: &State<T>,
        f0: &State<T>,
    ) -> Event<T> {
        let (h, t) = (self.h.get(l), self.t.get(l));
        let y1 = kernel::lane(&st.y1, l);
        let k7 = kernel::lane(&st.k7, l);
        let (k3, k4) = (kernel::lane(&st.k3, l), kernel::lane(&st.k4, l));
        let (k5, k6) = (kernel::lane(&st.k5, l), kernel::lane(&st.k6, l));
        let step = Step {
            h,
            y0,
            y1: &y1,
            f0,
            f1: &k7,
            mid: Some([&k3, &k4, &k5, &k6]),
        };
        let bit = 1u32 << l;
        // The scalar tracker, with the lane's apex so far (copied back).
        let mut tracker = Tracker::new(lane.scene.landing_height, y0, lane.axis, None);
        (tracker.apex_height, tracker.apex_time) = (lane.apex_m, lane.apex_time_s);
        let refine = if self.refined & bit == 0 && tracker.ends_below(&step) {
            tracker.grazing_landing(&step)
        } else {
            None
        };
        if let Some(th) = refine {
            self.refined |= bit;
            if th < T::one() && th > T::zero() {
                return Event::Redo(th);
            }
        }
        let found = tracker.on_step(t, &step);
        (lane.apex_m, lane.apex_time_s) = (tracker.apex_height, tracker.apex_time);
        match found {
            Err(e) => Event::Done(Err(e)),
            Ok(Some(th)) => Event::Done(outcome(
                lane,
                &Landing::in_step(t, th, &step),
                self.stats(l),
            )),
            Ok(None) => Event::Take,
        }
    }
}

/// What [`Run::locate`] found in the lanes with an event, packed.
struct Found<P> {
    /// Lanes left to the scalar tracker ([`Run::event`]): a landing step that may graze.
    slow: u32,
    /// Lanes with an apex in the step, its `θ` and height.
    apex: u32,
    apex_th: P,
    apex_m: P,
    /// Lanes with a landing in the step, its `θ` and interpolated state.
    landing: u32,
    landing_th: P,
    landing_state: States<P>,
}

impl<T: Real, P: Pack<Scalar = T>, const N: usize> Run<P, N> {
    /// The tracker's work (`Tracker::locate`, `grazing_landing`'s first test,
    /// `Landing::in_step`) in the lanes `events`, packed: each lane's operations are the
    /// scalar tracker's, so its apex, landing `θ` and landing state are the scalar ones bit
    /// for bit. The apex's root (of `v_y`) and a landing's root (of `y − h_land`) run in one
    /// packed root finding, lane by lane on its own interpolant; a landing after an apex in
    /// the same step takes a second one. A landing step whose chord estimate does not rule
    /// out a grazing landing goes to the scalar tracker (`slow`).
    #[inline(always)]
    fn locate(
        &self,
        events: u32,
        st: &kernel::Stages<P>,
        y0: &States<P>,
        f0: &States<P>,
    ) -> Found<P> {
        let zero = P::splat(T::zero());
        let one = P::splat(T::one());
        let (h, hl, y1) = (self.h, self.landing_height, &st.y1);
        let below = y1[Y].le(hl).bits();
        if !P::PACKED_EVENTS {
            return Found {
                slow: events,
                apex: 0,
                apex_th: zero,
                apex_m: zero,
                landing: 0,
                landing_th: zero,
                landing_state: [zero; 7],
            };
        }
        // `grazing_landing`'s first test: the velocity interpolated linearly to where the
        // height crosses linearly comes down at twice the grazing angle or more.
        let candidates = events & below & !self.refined;
        let mut slow = 0;
        if candidates != 0 {
            let (g0, g1) = (y0[Y] - hl, y1[Y] - hl);
            let th = zero.lt(g0).blend(g0 / (g0 - g1), zero);
            let vx = y0[VY - 1] + (y1[VY - 1] - y0[VY - 1]) * th;
            let vy = y0[VY] + (y1[VY] - y0[VY]) * th;
            let vz = y0[VY + 1] + (y1[VY + 1] - y0[VY + 1]) * th;
            // `v.norm_squared()`: `0 + ((x² + y²) + z²)` (nalgebra's order).
            let norm_sq = zero + ((vx * vx + vy * vy) + vz * vz);
            let tan_sq = P::splat(lit(crate::integrator::GRAZING_TAN_SQ_TWICE));
            let steep = vy.lt(zero) & (tan_sq * (norm_sq - vy * vy)).le(vy * vy);
            slow = candidates & !steep.bits();
        }
        let fast = events & !slow;
        let apex = fast & (zero.lt(y0[VY]) & y1[VY].le(zero)).bits();
        // A landing in a step without an apex: from `θ = 0` if the step starts above.
        let first = fast & !apex & hl.lt(y0[Y]).bits() & below;
        let mut found = Found {
            slow,
            apex,
            apex_th: zero,
            apex_m: zero,
            landing: first,
            landing_th: zero,
            landing_state: [zero; 7],
        };
        if apex | first == 0 {
            return found;
        }
        let py = kernel::poly(h, y0[Y], y1[Y], f0[Y], st.k7[Y], mid(st, Y));
        let a = P::mask(apex);
        let (mut r, mut c, mut fa, mut fb) = (py, hl, y0[Y] - hl, y1[Y] - hl);
        if apex != 0 {
            let pv = kernel::poly(h, y0[VY], y1[VY], f0[VY], st.k7[VY], mid(st, VY));
            for (ri, vi) in r.iter_mut().zip(pv.iter()) {
                *ri = a.blend(*vi, *ri);
            }
            c = a.blend(zero, c);
            fa = a.blend(y0[VY], fa);
            fb = a.blend(y1[VY], fb);
        }
        let th = kernel::find_root(P::mask(apex | first), &r, c, zero, one, fa, fb);
        found.landing_th = th;
        if apex != 0 {
            let ya = kernel::at(&py, th);
            (found.apex_th, found.apex_m) = (th, ya);
            // A landing after the apex in the same step: from the apex, if above.
            let second = apex & hl.lt(ya).bits() & below;
            if second != 0 {
                let th2 = kernel::find_root(P::mask(second), &py, hl, th, one, ya - hl, y1[Y] - hl);
                found.landing_th = P::mask(second).blend(th2, th);
                found.landing |= second;
            }
        }
        if found.landing != 0 {
            let th = found.landing_th;
            for (i, s) in found.landing_state.iter_mut().enumerate() {
                *s = if i == Y {
                    kernel::at(&py, th)
                } else {
                    kernel::at(
                        &kernel::poly(h, y0[i], y1[i], f0[i], st.k7[i], mid(st, i)),
                        th,
                    )
                };
            }
        }
        found
    }

    /// Lane `l`'s events from what [`Run::locate`] found (`Tracker::on_step` after it):
    /// the apex kept if higher, no landing if the apex is at or below the landing height,
    /// the landing. Whether the flight is over (its result handed to `sink`).
    fn found(
        &self,
        lane: &mut Lane<'_, T>,
        l: usize,
        found: &Found<P>,
        sink: &mut impl FnMut(usize, Result<FlightOutcome<T>>),
    ) -> bool {
        let bit = 1u32 << l;
        let (h, t, hl) = (self.h.get(l), self.t.get(l), self.landing_height.get(l));
        if found.apex & bit != 0 {
            let ya = found.apex_m.get(l);
            if ya > lane.apex_m {
                lane.apex_m = ya;
                lane.apex_time_s = t + found.apex_th.get(l) * h;
            }
            if ya <= hl {
                sink(lane.index, Err(Error::NoLanding));
                return true;
            }
        }
        if found.landing & bit == 0 {
            return false;
        }
        let th = found.landing_th.get(l);
        let landing = Landing {
            time: t + th * h,
            state: kernel::lane(&found.landing_state, l),
        };
        sink(lane.index, outcome(lane, &landing, self.stats(l)));
        true
    }
}

/// Component `i` of the stages `k₃..k₆` of every lane.
#[inline(always)]
fn mid<P: Pack>(st: &kernel::Stages<P>, i: usize) -> [P; 4] {
    [st.k3[i], st.k4[i], st.k5[i], st.k6[i]]
}

/// The flight's outcome from its landing (`flight::run`'s end, without a ground).
fn outcome<T: Real>(
    lane: &Lane<'_, T>,
    landing: &Landing<T>,
    stats: Stats,
) -> Result<FlightOutcome<T>> {
    let scene = lane.scene;
    let (apex_m, apex_time_s) = (lane.apex_m, lane.apex_time_s);
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
        stats,
        recording_full: false,
        ground: None,
    })
}
