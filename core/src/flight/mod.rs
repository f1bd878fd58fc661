//! Ball flight: from launch conditions to where and how the ball lands (PHYSICS.md,
//! "Flight").
//!
//! The aerodynamic model is the one the [`Scene`] holds (see [`crate::aero`]) with the effects, air and wind a
//! [`Scene`] asks for. The state (position, velocity, spin magnitude about the fixed spin
//! axis) is integrated by an [`Integrator`] — explicit Euler, classical RK4 or adaptive
//! Dormand–Prince 5(4) — and the landing and the apex are located *inside* the step by
//! the step's interpolant and a bracketing root finder, never taken as a step end or the
//! highest sample. Every result reports the number of force evaluations it cost.
//!
//! ```
//! use carry_core::{Ball, Launch, aero::AeroModel, flight::{self, Integrator}, scene::Scene,
//!     units::{deg, rpm}};
//! let launch = Launch { ball_speed_mps: 74.65568_f64, launch_angle_rad: deg(10.9),
//!     launch_direction_rad: 0.0, backspin_radps: rpm(2686.0), sidespin_radps: 0.0 };
//! // PHYSICS.md's reference figure is the seed model's (Quintavalla).
//! let seed = Scene { aero: AeroModel::quintavalla(), ..Scene::default() };
//! let out = flight::fly(&Ball::standard(), &launch.ball_motion()?, &seed,
//!     &Integrator::default(), None)?;
//! assert!((out.carry_m - 247.503).abs() < 1e-3);
//! # Ok::<(), carry_core::Error>(())
//! ```

mod aimed;
mod events;
mod integrate;

pub(crate) use events::Plane;
pub use integrate::Stats;

use crate::aero::{Dynamics, ForceEvaluation, Rhs, S, State, Y};
use crate::ball::{Ball, BallMotion};
use crate::error::{Error, Field, Reason, Result};
use crate::ground::{Contact, Hopper, Rollout};
use crate::real::{Real, lit, smaller};
use crate::scene::{PreparedScene, Scene};
use crate::validate::{positive, positive_or_infinite};
use heapless::vec::VecView;
use integrate::Adaptive;
use nalgebra::Vector3;

/// How the flight is integrated.
///
/// [`Integrator::default`] is the documented default fidelity for the precision `T`
/// (see its docs and docs/flight.md).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Integrator<T> {
    /// Explicit Euler with a fixed step (s): first order, 1 force evaluation per step.
    Euler {
        /// Step size (s), finite and positive.
        step_s: T,
    },
    /// Classical 4th-order Runge–Kutta with a fixed step (s): 4 evaluations per step.
    Rk4 {
        /// Step size (s), finite and positive.
        step_s: T,
    },
    /// Adaptive embedded Dormand–Prince 5(4) (FSAL: 6 evaluations per step) with the
    /// mixed error test `|eᵢ| ≤ atol + rtol·max(|y₀ᵢ|, |y₁ᵢ|)` on position (m), velocity
    /// (m/s) and spin (rad/s).
    DormandPrince {
        /// Relative tolerance, finite and positive.
        rtol: T,
        /// Absolute tolerance, finite and positive.
        atol: T,
        /// First trial step (s), finite and positive.
        initial_step_s: T,
        /// Largest step (s), positive (may be +∞).
        max_step_s: T,
    },
}

/// Default-fidelity tolerance of the adaptive integrator in `f64`.
pub const DEFAULT_TOLERANCE_F64: f64 = 4.0e-5;
/// Default-fidelity tolerance of the adaptive integrator in `f32`.
pub const DEFAULT_TOLERANCE_F32: f64 = 3.0e-4;
/// Step budget of the adaptive integrator (accepted + rejected steps). A golf flight at
/// the tightest tolerance takes a few hundred; the budget only stops absurd inputs (it
/// bounds the run time of every flight, so firmware never hangs): [`Error::StepLimit`].
pub const MAX_ADAPTIVE_STEPS: u32 = 100_000;
/// Fastest accepted launch (m/s): 1.5× the fastest golf ball speed on record (about
/// 97 m/s, long drive), Mach 0.44. The force laws are incompressible (their coefficients
/// come from wind tunnels and launch monitors below Mach 0.3); far beyond this a result
/// would be finite but meaningless, so a faster launch is [`Field::BallVelocity`]
/// [`Reason::OutOfRange`] (issue 20: a fuzzed 1.3·10⁵ m/s launch).
pub const MAX_BALL_SPEED_MPS: f64 = 150.0;
/// Largest accepted launch spin (rad/s, about 28,600 rpm): twice the highest spins a
/// golf ball is measured with (wedges, about 12,000–14,000 rpm). The lift and spin-decay
/// laws are fitted at spin parameters below about 0.5; a faster spin is
/// [`Field::BallSpin`] [`Reason::OutOfRange`].
pub const MAX_SPIN_RADPS: f64 = 3000.0;
/// Largest accepted tolerance (`rtol`, and `atol` in m, m/s, rad/s): looser than 1 the
/// error test stops controlling anything.
pub const MAX_TOLERANCE: f64 = 1.0;
/// Default first trial step of the adaptive integrator (s).
pub const DEFAULT_INITIAL_STEP_S: f64 = 0.1;
/// First adaptive step of a hop between bounces, in units of `v_n/g_n` (the vacuum hop
/// lasts 2): a little longer than the hop, so that a short hop takes one step and its
/// landing is found inside it.
pub const HOP_STEP_FACTOR: f64 = 2.1;
/// Cap on the first adaptive step of a hop (s): a tour driver's first hop on a firm
/// fairway lasts about 1 s and takes one step.
pub const HOP_MAX_FIRST_STEP_S: f64 = 2.0;
/// A hop between bounces integrates at this multiple of the flight's tolerances (`rtol`,
/// `atol`; at most [`MAX_TOLERANCE`]): at the default fidelity every hop then takes one
/// Dormand–Prince step (7 force evaluations) instead of two or three. The total distance
/// moves by about 1 cm in 225 m (docs/ground.md), far inside what the bounce model itself
/// knows, and carry is untouched.
pub const HOP_TOLERANCE_FACTOR: f64 = 100.0;
/// Cap on the first adaptive step (s) when the ball starts in a wind profile's singular
/// ground layer (see [`crate::wind::Wind::Profile`]).
pub const PROFILE_INITIAL_STEP_S: f64 = 1.0e-5;

impl<T: Real> Integrator<T> {
    /// Dormand–Prince 5(4) with `rtol = atol = tolerance`, the default first step and no
    /// step limit.
    #[must_use]
    pub fn dormand_prince(tolerance: T) -> Self {
        Self::DormandPrince {
            rtol: tolerance,
            atol: tolerance,
            initial_step_s: lit(DEFAULT_INITIAL_STEP_S),
            max_step_s: T::max_value().unwrap_or_else(T::one),
        }
    }

    /// A reference-grade setting: Dormand–Prince at a tolerance of 1e-12 in `f64`
    /// (carry within 1e-8 m of the 8th-order reference), 1e-6 in `f32` (near its
    /// rounding floor; the smallest accepted `rtol` is 4ε).
    #[must_use]
    pub fn tight() -> Self {
        Self::dormand_prince(if is_single::<T>() {
            lit(1e-6)
        } else {
            lit(1e-12)
        })
    }
}

/// True when `T` is single precision (`f32`).
fn is_single<T: Real>() -> bool {
    T::default_epsilon() > lit(1e-10)
}

impl<T: Real> Default for Integrator<T> {
    /// The default fidelity: Dormand–Prince 5(4) at [`DEFAULT_TOLERANCE_F64`] in `f64`
    /// (carry within 1 mm of the reference on the golden set) or
    /// [`DEFAULT_TOLERANCE_F32`] in `f32` (within 1 cm). See docs/flight.md.
    fn default() -> Self {
        Self::dormand_prince(lit(if is_single::<T>() {
            DEFAULT_TOLERANCE_F32
        } else {
            DEFAULT_TOLERANCE_F64
        }))
    }
}

/// One recorded trajectory sample.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Sample<T: Real> {
    /// Time since launch (s).
    pub time_s: T,
    /// Ball position (m, G).
    pub position_m: Vector3<T>,
    /// Ball velocity, ground frame (m/s, G).
    pub velocity_mps: Vector3<T>,
    /// Ball spin (rad/s, G).
    pub spin_radps: Vector3<T>,
}

/// Where a [`Recorder`] can put its samples besides a `heapless::Vec`: storage the caller
/// owns (e.g. a C caller's buffer, `carry-ffi`), filled in order.
pub trait SampleSink<T: Real> {
    /// Forgets the samples so far (a flight starts).
    fn clear(&mut self);
    /// Stores one sample; `false` when there is no room (recording then stops).
    fn push(&mut self, sample: Sample<T>) -> bool;
}

/// The storage of a [`Recorder`].
enum Store<'a, T: Real> {
    Buffer(&'a mut VecView<Sample<T>>),
    Sink(&'a mut dyn SampleSink<T>),
}

impl<T: Real> core::fmt::Debug for Store<'_, T> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Buffer(b) => f.debug_tuple("Buffer").field(&b.len()).finish(),
            Self::Sink(_) => f.write_str("Sink"),
        }
    }
}

#[cfg(feature = "defmt")]
impl<T: Real> defmt::Format for Store<'_, T> {
    fn format(&self, f: defmt::Formatter<'_>) {
        match self {
            Self::Buffer(b) => defmt::write!(f, "Buffer({=usize})", b.len()),
            Self::Sink(_) => defmt::write!(f, "Sink"),
        }
    }
}

/// Records the trajectory into a caller-provided fixed-capacity buffer: a sample every
/// `interval_s` from launch (interpolated, not step ends), then the landing. When the
/// buffer fills, recording stops and [`FlightOutcome::recording_full`] is set — the
/// flight itself completes normally.
#[derive(Debug)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Recorder<'a, T: Real> {
    interval_s: T,
    samples: Store<'a, T>,
    full: bool,
}

impl<'a, T: Real> Recorder<'a, T> {
    /// A recorder writing into `buffer` (cleared) every `interval_s` seconds.
    ///
    /// # Errors
    /// [`Field::RecordInterval`] when `interval_s` is not finite and positive.
    pub fn new<const N: usize>(
        interval_s: T,
        buffer: &'a mut heapless::Vec<Sample<T>, N>,
    ) -> Result<Self> {
        let interval_s = positive(interval_s, Field::RecordInterval)?;
        buffer.clear();
        Ok(Self {
            interval_s,
            samples: Store::Buffer(buffer.as_mut_view()),
            full: false,
        })
    }

    /// A recorder handing its samples to `sink` (cleared) every `interval_s` seconds.
    ///
    /// # Errors
    /// [`Field::RecordInterval`] when `interval_s` is not finite and positive.
    pub fn with_sink(interval_s: T, sink: &'a mut dyn SampleSink<T>) -> Result<Self> {
        let interval_s = positive(interval_s, Field::RecordInterval)?;
        sink.clear();
        Ok(Self {
            interval_s,
            samples: Store::Sink(sink),
            full: false,
        })
    }

    /// The samples recorded by the last flight (empty for a [`Recorder::with_sink`]: the
    /// sink has them).
    #[must_use]
    pub fn samples(&self) -> &[Sample<T>] {
        match &self.samples {
            Store::Buffer(b) => b,
            Store::Sink(_) => &[],
        }
    }

    /// Whether the buffer filled up (later samples were dropped).
    #[must_use]
    pub fn is_full(&self) -> bool {
        self.full
    }

    fn reset(&mut self) {
        match &mut self.samples {
            Store::Buffer(b) => b.clear(),
            Store::Sink(s) => s.clear(),
        }
        self.full = false;
    }

    /// The recording interval (s).
    pub(crate) fn interval(&self) -> T {
        self.interval_s
    }

    /// Records the samples `k·Δ` strictly inside a hop from `from_time` lasting `duration`
    /// (s), the position, velocity and spin magnitude `t` after its start from `state_at`,
    /// the spin about `axis`. Stops when the buffer is full.
    pub(crate) fn record_hop(
        &mut self,
        from_time: T,
        duration: T,
        axis: &Vector3<T>,
        state_at: impl Fn(T) -> (Vector3<T>, Vector3<T>, T),
    ) {
        let dt = self.interval_s;
        let k = crate::real::to_f64(from_time / dt);
        // Float-to-int `as` saturates (never panics).
        let mut k = if k.is_finite() && k > 0.0 {
            k as u32
        } else {
            0
        };
        // Every pass pushes a sample; a full recorder stops it (the last index repeats).
        while !self.full {
            k = k.saturating_add(1);
            let t = lit::<T>(f64::from(k)) * dt - from_time;
            if !(t > T::zero() && t < duration) {
                break;
            }
            let (position_m, velocity_mps, spin) = state_at(t);
            self.push(Sample {
                time_s: from_time + t,
                position_m,
                velocity_mps,
                spin_radps: axis * spin,
            });
        }
    }

    pub(crate) fn push(&mut self, sample: Sample<T>) {
        let stored = match &mut self.samples {
            Store::Buffer(b) => b.push(sample).is_ok(),
            Store::Sink(s) => s.push(sample),
        };
        if !stored {
            self.full = true;
        }
    }
}

/// Where and how the ball lands.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FlightOutcome<T: Real> {
    /// Carry: horizontal distance from the tee to the landing point (m).
    pub carry_m: T,
    /// Carry along the target line, landing X − tee X (m).
    pub carry_x_m: T,
    /// Side: landing Z − tee Z, + right (m).
    pub side_m: T,
    /// Apex: the highest Y of the flight (m, G; the tee's ground is Y = 0), located on the
    /// interpolant where `v_y = 0`. The launch height if the ball never rises.
    pub apex_m: T,
    /// Time of the apex (s).
    pub apex_time_s: T,
    /// Flight time, launch to landing (s).
    pub flight_time_s: T,
    /// Landing angle below the horizontal (rad), ground frame: `atan2(−v_y, |v_xz|)`.
    pub landing_angle_rad: T,
    /// Landing speed |v|, ground frame (m/s).
    pub landing_speed_mps: T,
    /// Spin at landing |ω| (rad/s).
    pub landing_spin_radps: T,
    /// Landing position (m, G).
    pub landing_position_m: Vector3<T>,
    /// Landing velocity, ground frame (m/s, G).
    pub landing_velocity_mps: Vector3<T>,
    /// Spin vector at landing (rad/s, G).
    pub landing_spin_vector_radps: Vector3<T>,
    /// The air density flown through (kg/m³).
    pub air_density_kgm3: T,
    /// Work done: force evaluations, accepted and rejected steps.
    pub stats: Stats,
    /// The recorder's buffer filled up and samples were dropped.
    pub recording_full: bool,
    /// Bounce and roll to rest, when the scene has a ground (`None` otherwise).
    pub ground: Option<Rollout<T>>,
}

/// Flies `launch` from the scene's tee through `scene` to the landing.
///
/// Validates everything once, then integrates. For many shots in one scene, prepare it
/// once ([`Scene::prepare`]) and call [`PreparedScene::fly`].
///
/// # Errors
/// [`Error::InvalidInput`] for an invalid scene, launch or integrator (NaN/∞, negative
/// density, humidity outside [0, 1], landing height not finite, non-positive step or
/// tolerance, a launch faster than [`MAX_BALL_SPEED_MPS`] or spinning faster than
/// [`MAX_SPIN_RADPS`]); [`Error::NoLanding`] when the ball never comes down through the landing
/// height (a launch at or below the horizon from the landing height, unless the scene has
/// a ground: the ball then meets the turf at once, a topped shot, and bounces and rolls);
/// [`Error::TimeLimit`]; [`Error::StepSizeUnderflow`] when the adaptive step cannot
/// meet the tolerance (also for `rtol` below 4ε of `T`); [`Error::Unstable`] when a fixed step diverges (grows faster than the dynamics allow).
pub fn fly<T: Real>(
    ball: &Ball<T>,
    launch: &BallMotion<T>,
    scene: &Scene<T>,
    integrator: &Integrator<T>,
    recorder: Option<&mut Recorder<'_, T>>,
) -> Result<FlightOutcome<T>> {
    scene.prepare(ball)?.fly(launch, integrator, recorder)
}

impl<T: Real> PreparedScene<T> {
    /// Flies `launch` through this prepared scene (see [`fly`]).
    ///
    /// # Errors
    /// As [`fly`], without the scene's validation errors.
    pub fn fly(
        &self,
        launch: &BallMotion<T>,
        integrator: &Integrator<T>,
        recorder: Option<&mut Recorder<'_, T>>,
    ) -> Result<FlightOutcome<T>> {
        run(self, launch, integrator, recorder, |d| d)
    }
}

/// The flight with the dynamics `make` builds from the runtime dynamics (the production
/// path passes them through; the benchmark substitutes compile-time switches).
fn run<'s, T: Real, R: Rhs<T>>(
    scene: &'s PreparedScene<T>,
    launch: &BallMotion<T>,
    integrator: &Integrator<T>,
    recorder: Option<&mut Recorder<'_, T>>,
    make: impl FnOnce(Dynamics<'s, T>) -> R,
) -> Result<FlightOutcome<T>> {
    let launch = launch.validated()?;
    let method = integrator.method()?;
    if !(launch.velocity_mps.norm() <= lit(MAX_BALL_SPEED_MPS)) {
        return Err(Error::invalid(Field::BallVelocity, Reason::OutOfRange));
    }
    let spin = launch.spin_radps.norm();
    if !(spin <= lit(MAX_SPIN_RADPS)) {
        return Err(Error::invalid(Field::BallSpin, Reason::OutOfRange));
    }
    let axis = if spin > T::zero() {
        launch.spin_radps / spin
    } else {
        Vector3::zeros()
    };
    let p0 = scene.launch_position;
    let v0 = launch.velocity_mps;
    let y0: State<T> = [p0.x, p0.y, p0.z, v0.x, v0.y, v0.z, spin];
    if y0[Y] <= scene.landing_height && v0.y <= T::zero() {
        // At or below the landing height and not rising: it never comes down through it.
        // On a ground it meets the turf at once (a topped shot) and bounces and rolls.
        return match &scene.ground {
            None => Err(Error::NoLanding),
            Some(g) => into_the_ground(scene, g, &launch, axis, spin, method, recorder),
        };
    }
    let rhs = make(Dynamics { scene, axis });
    let mut recorder = recorder;
    if let Some(r) = recorder.as_deref_mut() {
        r.reset();
    }
    let mut tracker =
        events::Tracker::new(scene.landing_height, &y0, axis, recorder.as_deref_mut());
    let mut stats = Stats::default();
    let landing = integrate_to_event(
        scene,
        &rhs,
        y0,
        method,
        scene.time_limit,
        scene.landing_height,
        &mut tracker,
        &mut stats,
    )?;
    let (apex_m, apex_time_s) = (tracker.apex_height, tracker.apex_time);
    let y = landing.state;
    // The step ends are checked finite, but the landing is interpolated inside the step:
    // with absurd (finite) launches the interpolant overflows (∞ − ∞ = NaN; found by
    // fuzzing, issue 7). Never report it.
    let speed = Vector3::new(y[3], y[4], y[5]).norm();
    if !(y.iter().all(|x| x.is_finite())
        && speed.is_finite()
        && landing.time.is_finite()
        && tracker.apex_height.is_finite())
    {
        return Err(Error::Unstable);
    }
    let position = Vector3::new(y[0], y[1], y[2]);
    let velocity = Vector3::new(y[3], y[4], y[5]);
    let carry_x = position.x - p0.x;
    let side = position.z - p0.z;
    let ground = match &scene.ground {
        None => None,
        Some(g) => {
            let first = Contact {
                time: landing.time,
                position,
                velocity,
                spin: axis * y[S],
            };
            let hopper = Hops { scene, method };
            Some(crate::ground::run_out(
                g,
                scene.gravity,
                &p0,
                &first,
                &hopper,
                recorder.as_deref_mut(),
            )?)
        }
    };
    Ok(FlightOutcome {
        carry_m: carry_x.hypot(side),
        carry_x_m: carry_x,
        side_m: side,
        apex_m,
        apex_time_s,
        flight_time_s: landing.time,
        landing_angle_rad: (-velocity.y).atan2(velocity.x.hypot(velocity.z)),
        landing_speed_mps: velocity.norm(),
        landing_spin_radps: y[S],
        landing_position_m: position,
        landing_velocity_mps: velocity,
        landing_spin_vector_radps: axis * y[S],
        air_density_kgm3: scene.density,
        stats,
        recording_full: recorder.is_some_and(|r| r.is_full()),
        ground,
    })
}

/// A ball launched at or below the horizon from the landing height with a ground in the
/// scene (a topped shot): its first contact is the launch itself, at `t = 0`. Carry, apex
/// height above the launch and flight time are zero; the landing angle and speed are the
/// launch's; the run-out starts on a ground plane through the launch point. Out of line
/// and cold: it must not change the code of the common flight.
#[cold]
#[inline(never)]
fn into_the_ground<T: Real>(
    scene: &PreparedScene<T>,
    ground: &crate::ground::PreparedGround<T>,
    launch: &BallMotion<T>,
    axis: Vector3<T>,
    spin: T,
    method: Method<T>,
    recorder: Option<&mut Recorder<'_, T>>,
) -> Result<FlightOutcome<T>> {
    let mut recorder = recorder;
    let p0 = scene.launch_position;
    let velocity = launch.velocity_mps;
    let first = Contact {
        time: T::zero(),
        position: p0,
        velocity,
        spin: axis * spin,
    };
    if let Some(r) = recorder.as_deref_mut() {
        r.reset();
        r.push(Sample {
            time_s: T::zero(),
            position_m: p0,
            velocity_mps: velocity,
            spin_radps: first.spin,
        });
    }
    let hopper = Hops { scene, method };
    let rollout = crate::ground::run_out(
        ground,
        scene.gravity,
        &p0,
        &first,
        &hopper,
        recorder.as_deref_mut(),
    )?;
    Ok(FlightOutcome {
        carry_m: T::zero(),
        carry_x_m: T::zero(),
        side_m: T::zero(),
        apex_m: p0.y,
        apex_time_s: T::zero(),
        flight_time_s: T::zero(),
        landing_angle_rad: (-velocity.y).atan2(velocity.x.hypot(velocity.z)),
        landing_speed_mps: velocity.norm(),
        landing_spin_radps: spin,
        landing_position_m: p0,
        landing_velocity_mps: velocity,
        landing_spin_vector_radps: first.spin,
        air_density_kgm3: scene.density,
        stats: Stats::default(),
        recording_full: recorder.is_some_and(|r| r.is_full()),
        ground: Some(rollout),
    })
}

/// Integrates from `y0` with `method` until the tracker reports its event (the landing
/// through `event_height`, or a hop's return to its plane).
#[allow(clippy::too_many_arguments)]
fn integrate_to_event<T: Real, R: Rhs<T>>(
    scene: &PreparedScene<T>,
    rhs: &R,
    y0: State<T>,
    method: Method<T>,
    limit: T,
    event_height: T,
    tracker: &mut events::Tracker<'_, '_, T>,
    stats: &mut Stats,
) -> Result<events::Landing<T>> {
    match method {
        Method::Fixed { step, rk4 } => integrate::fixed(rhs, y0, step, rk4, limit, tracker, stats),
        Method::Adaptive(mut cfg) => {
            if scene.profile_singular_at(y0[Y]) {
                // The profile's (y/h_ref)^k has an infinite derivative at the ground, where
                // the embedded error estimate is unreliable: start with a small step and let
                // the controller grow it (×5 per step) once the ball is off the ground.
                cfg.initial_step = cfg.initial_step.min(lit(PROFILE_INITIAL_STEP_S));
            }
            // Likewise at the landing: redo the landing step to end there.
            cfg.refine_landing = scene.profile_singular_at(event_height);
            integrate::dormand_prince(rhs, y0, cfg, limit, tracker, stats)
        }
    }
}

/// The hops between bounces: the scene's own dynamics and the flight's integrator.
struct Hops<'s, T: Real> {
    scene: &'s PreparedScene<T>,
    method: Method<T>,
}

impl<T: Real> Hopper<T> for Hops<'_, T> {
    #[cfg_attr(not(target_os = "none"), inline(always))]
    fn forces(
        &self,
        p: &Vector3<T>,
        v: &Vector3<T>,
        spin: T,
        axis: &Vector3<T>,
        stats: &mut Stats,
    ) -> ForceEvaluation<T> {
        stats.force_evaluations = stats.force_evaluations.saturating_add(1);
        Dynamics {
            scene: self.scene,
            axis: *axis,
        }
        .forces(&[p.x, p.y, p.z, v.x, v.y, v.z, spin])
    }

    fn rates_held(&self, forces: &ForceEvaluation<T>, axis: &Vector3<T>) -> (Vector3<T>, T) {
        Dynamics {
            scene: self.scene,
            axis: *axis,
        }
        .rates_held(forces)
    }

    fn wind_varies(&self) -> bool {
        self.scene.wind_varies_with_height()
    }

    fn hop(
        &self,
        from: &Contact<T>,
        plane: Plane<T>,
        recorder: Option<&mut Recorder<'_, T>>,
        stats: &mut Stats,
    ) -> Result<Contact<T>> {
        let start = self.start(from, &plane)?;
        let mut recorder = recorder;
        // One aimed step, in still air or a uniform wind (a profile's ground layer needs
        // small steps); else, or when it does not land, the integrator.
        if let Method::Adaptive(cfg) = &start.method
            && !self.scene.wind_varies_with_height()
        {
            // (Its own count: the integrator's restarts from zero.)
            let mut aimed_stats = Stats::default();
            let aimed = aimed::aimed_hop(
                &start.dynamics,
                from.time,
                &start.y0,
                &plane,
                cfg,
                start.limit,
                recorder.as_deref_mut(),
                &mut aimed_stats,
            );
            stats.add(&aimed_stats);
            if let Some(c) = aimed {
                return Ok(c);
            }
        }
        self.integrated(from.time, &start, plane, recorder, stats)
    }
}

/// What a hop starts from: its state, dynamics, integrator and time left.
struct HopStart<'s, T: Real> {
    y0: State<T>,
    dynamics: Dynamics<'s, T>,
    method: Method<T>,
    limit: T,
}

impl<'s, T: Real> Hops<'s, T> {
    /// The hop's start from contact `from`: the integrator at [`HOP_TOLERANCE_FACTOR`] times
    /// the flight's tolerances, its first trial step a little longer than the vacuum hop.
    fn start(&self, from: &Contact<T>, plane: &Plane<T>) -> Result<HopStart<'s, T>> {
        let scene = self.scene;
        let limit = scene.time_limit - from.time;
        if !(limit > T::zero()) {
            return Err(Error::TimeLimit);
        }
        let spin = from.spin.norm();
        let axis = if spin > T::zero() {
            from.spin / spin
        } else {
            Vector3::zeros()
        };
        let (p, v) = (from.position, from.velocity);
        let mut method = self.method;
        if let Method::Adaptive(cfg) = &mut method {
            // First trial step: a little longer than the vacuum hop 2·v_n/g_n, so that a
            // short hop usually takes one step (its landing is found inside it).
            let g_n = scene.gravity * plane.normal.y;
            let guess = lit::<T>(HOP_STEP_FACTOR) * v.dot(&plane.normal) / g_n;
            if guess > T::zero() && guess.is_finite() {
                cfg.initial_step = smaller(smaller(guess, lit(HOP_MAX_FIRST_STEP_S)), cfg.max_step);
            }
            let factor = lit::<T>(HOP_TOLERANCE_FACTOR);
            cfg.rtol = smaller(cfg.rtol * factor, lit(MAX_TOLERANCE));
            cfg.atol = smaller(cfg.atol * factor, lit(MAX_TOLERANCE));
        }
        Ok(HopStart {
            y0: [p.x, p.y, p.z, v.x, v.y, v.z, spin],
            dynamics: Dynamics { scene, axis },
            method,
            limit,
        })
    }

    /// The hop integrated by the flight's integrator, the landing found on the dense output
    /// (the tracker's plane event).
    fn integrated(
        &self,
        from_time: T,
        start: &HopStart<'s, T>,
        plane: Plane<T>,
        recorder: Option<&mut Recorder<'_, T>>,
        stats: &mut Stats,
    ) -> Result<Contact<T>> {
        let axis = start.dynamics.axis;
        let mut tracker = events::Tracker::hop(plane, &start.y0, axis, from_time, recorder);
        let mut hop_stats = Stats::default();
        let event_height = plane.offset / plane.normal.y;
        let landing = integrate_to_event(
            self.scene,
            &start.dynamics,
            start.y0,
            start.method,
            start.limit,
            event_height,
            &mut tracker,
            &mut hop_stats,
        );
        stats.add(&hop_stats);
        let landing = landing?;
        let y = landing.state;
        if !(y.iter().all(|x| x.is_finite()) && landing.time.is_finite()) {
            return Err(Error::Unstable);
        }
        Ok(Contact {
            time: from_time + landing.time,
            position: Vector3::new(y[0], y[1], y[2]),
            velocity: Vector3::new(y[3], y[4], y[5]),
            spin: axis * y[S],
        })
    }
}

/// A validated integrator.
#[derive(Clone, Copy)]
enum Method<T> {
    Fixed { step: T, rk4: bool },
    Adaptive(Adaptive<T>),
}

impl<T: Real> Integrator<T> {
    fn method(&self) -> Result<Method<T>> {
        Ok(match *self {
            Self::Euler { step_s } => Method::Fixed {
                step: positive(step_s, Field::Step)?,
                rk4: false,
            },
            Self::Rk4 { step_s } => Method::Fixed {
                step: positive(step_s, Field::Step)?,
                rk4: true,
            },
            Self::DormandPrince {
                rtol,
                atol,
                initial_step_s,
                max_step_s,
            } => {
                let tolerance = |x: T| {
                    let x = positive(x, Field::Tolerance)?;
                    if x > lit(MAX_TOLERANCE) {
                        return Err(Error::invalid(Field::Tolerance, Reason::OutOfRange));
                    }
                    Ok(x)
                };
                let cfg = Adaptive {
                    rtol: tolerance(rtol)?,
                    atol: tolerance(atol)?,
                    initial_step: positive(initial_step_s, Field::Step)?,
                    max_step: positive_or_infinite(max_step_s, Field::Step)?,
                    refine_landing: false,
                };
                // Below a few ulps the error test only passes by accident of cancellation
                // (at ever smaller steps): no step size can meet such a tolerance.
                if cfg.rtol < T::default_epsilon() * lit(4.0) {
                    return Err(Error::StepSizeUnderflow);
                }
                Method::Adaptive(cfg)
            }
        })
    }
}

/// Benchmark support, not part of the stable API: the same flight with the effect switches
/// fixed at compile time (monomorphised), to measure what the runtime branches cost.
#[doc(hidden)]
pub mod bench {
    use super::{BallMotion, FlightOutcome, Integrator, PreparedScene, Real, Result, run};
    use crate::aero::Switches;

    /// `WIND` switch: no wind evaluation.
    pub const WIND_NONE: u8 = 0;
    /// `WIND` switch: evaluate the scene's wind field.
    pub const WIND_FIELD: u8 = 1;

    /// [`PreparedScene::fly`] with the effects `DRAG`, `LIFT`, `DECAY` and wind (`WIND` ≠ 0)
    /// fixed at compile time instead of read from the scene.
    ///
    /// # Errors
    /// As [`PreparedScene::fly`].
    pub fn fly_switched<
        T: Real,
        const DRAG: bool,
        const LIFT: bool,
        const DECAY: bool,
        const WIND: u8,
    >(
        scene: &PreparedScene<T>,
        launch: &BallMotion<T>,
        integrator: &Integrator<T>,
    ) -> Result<FlightOutcome<T>> {
        run(
            scene,
            launch,
            integrator,
            None,
            Switches::<T, DRAG, LIFT, DECAY, WIND>,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ground::{HopForces, low_hop};
    use crate::wind::Wind;

    /// A ball leaving the ground at (200, 0, 5) m, 4 s after launch.
    fn leaving(velocity: Vector3<f64>, spin: Vector3<f64>) -> Contact<f64> {
        Contact {
            time: 4.0,
            position: Vector3::new(200.0, 0.0, 5.0),
            velocity,
            spin,
        }
    }

    /// The aimed one-step hop (`aimed`) against the same hop integrated at a tight
    /// tolerance, for hops of 1–5 m with backspin, topspin and sidespin, in still air and a
    /// uniform crosswind: within 2.5 cm, 1 ms and 1.5 cm/s (aimed: measured 3.8 mm, 0.6 ms
    /// and 1.2 cm/s, a 5 m hop at 22 m/s; a driver's first hop 0.5 mm and 1.3 mm/s; the
    /// one hop whose aimed step is rejected, 5 m into the wind, is the integrator's at the
    /// hop tolerance: 2.0 cm), in 7 evaluations and one step. At the tight tolerance the
    /// aimed step fails the error test and the hop is the integrator's, bit for bit.
    #[test]
    fn aimed_hop_matches_the_integrated_hop() {
        let ball = Ball::<f64>::standard();
        for wind in [Wind::None, Wind::Uniform(Vector3::new(-4.0, 0.0, 3.0))] {
            let scene = Scene {
                wind,
                ..Scene::default()
            };
            let Ok(scene) = scene.prepare(&ball) else {
                panic!("scene")
            };
            let (Ok(default), Ok(tight)) =
                (Integrator::default().method(), Integrator::tight().method())
            else {
                panic!("method")
            };
            let aimed = Hops {
                scene: &scene,
                method: default,
            };
            let reference = Hops {
                scene: &scene,
                method: tight,
            };
            let plane = Plane {
                normal: Vector3::y(),
                offset: 0.0,
            };
            for (v, w) in [
                (Vector3::new(6.9, 8.3, -0.3), Vector3::new(0.0, 0.0, -486.0)),
                (Vector3::new(15.0, 5.0, 0.0), Vector3::new(0.0, 0.0, 300.0)),
                (
                    Vector3::new(20.0, 10.0, 2.0),
                    Vector3::new(30.0, 60.0, 250.0),
                ),
                (Vector3::new(3.0, 4.5, 0.0), Vector3::new(0.0, 0.0, 900.0)),
                (
                    Vector3::new(10.0, 6.0, -1.0),
                    Vector3::new(0.0, -40.0, -600.0),
                ),
            ] {
                let from = leaving(v, w);
                let mut stats = Stats::default();
                let Ok(hop) = aimed.hop(&from, plane, None, &mut stats) else {
                    panic!("aimed {v:?}")
                };
                // One aimed step; or, when it is rejected (a 5 m hop into the wind), 7
                // evaluations spent and the integrator's hop.
                let aimed_step = (stats.force_evaluations, stats.steps, stats.rejected_steps);
                assert!(
                    aimed_step == (7, 1, 0) || (aimed_step.2 == 1 && aimed_step.0 > 7),
                    "{v:?}: {aimed_step:?}"
                );
                if v.y < 9.0 {
                    assert_eq!(aimed_step, (7, 1, 0), "{v:?}");
                }
                let Ok(start) = reference.start(&from, &plane) else {
                    panic!("start")
                };
                let mut ref_stats = Stats::default();
                let Ok(exact) =
                    reference.integrated(from.time, &start, plane, None, &mut ref_stats)
                else {
                    panic!("integrated {v:?}")
                };
                let dp = (hop.position - exact.position).norm();
                let dt = (hop.time - exact.time).abs();
                let dv = (hop.velocity - exact.velocity).norm();
                assert!(
                    dp < 0.025 && dt < 1e-3 && dv < 0.015,
                    "{wind:?} {v:?} {w:?}: {dp} m, {dt} s, {dv} m/s"
                );
                // At the tight tolerance: the aimed step is rejected, the integrator flies it.
                let mut tight_stats = Stats::default();
                let Ok(fallback) = reference.hop(&from, plane, None, &mut tight_stats) else {
                    panic!("fallback {v:?}")
                };
                assert_eq!(fallback, exact, "{v:?}");
                assert_eq!(
                    tight_stats.force_evaluations,
                    ref_stats.force_evaluations + 7,
                    "{v:?}"
                );
            }
        }
    }

    /// The closed-form low hop against the same hop integrated at a tight tolerance, for
    /// hops up to the 1 m limit with backspin, topspin and sidespin: forces at both ends in
    /// still air and a uniform crosswind (within 10 cm and 4 ms; measured 6.6 cm and 2.8 ms,
    /// a 0.8 m hop at 20 m/s into the wind), and a third in the middle in a wind profile
    /// (within 20 cm and 15 ms; measured 16.4 cm with the lift of issue 21, 10.8 cm and 10 ms
    /// before it, against 51 cm and 46 ms with the two ends alone, where the profile's wind
    /// is zero).
    #[test]
    fn closed_form_hop_matches_the_integrated_hop() {
        let ball = Ball::<f64>::standard();
        let cases = [
            (Wind::None, 1, 0.05, 5e-3, 0.08),
            (
                Wind::Uniform(Vector3::new(-4.0, 0.0, 3.0)),
                1,
                0.05,
                5e-3,
                0.08,
            ),
            (
                Wind::profile(Vector3::new(-5.0, 0.0, 2.0)),
                3,
                0.2,
                15e-3,
                0.3,
            ),
        ];
        for (wind, evaluations, max_m, max_s, max_mps) in cases {
            let scene = Scene {
                wind,
                ..Scene::default()
            };
            let Ok(scene) = scene.prepare(&ball) else {
                panic!("scene")
            };
            let Ok(method) = Integrator::tight().method() else {
                panic!("method")
            };
            let hops = Hops {
                scene: &scene,
                method,
            };
            let n = Vector3::y();
            let plane = Plane {
                normal: n,
                offset: 0.0,
            };
            for (v, w) in [
                (Vector3::new(20.0, 4.0, 0.0), Vector3::new(0.0, 0.0, 150.0)),
                (
                    Vector3::new(12.0, 2.5, 1.5),
                    Vector3::new(10.0, 40.0, 300.0),
                ),
                (
                    Vector3::new(25.0, 1.0, -2.0),
                    Vector3::new(0.0, 0.0, -400.0),
                ),
                (Vector3::new(3.0, 4.4, 0.0), Vector3::new(0.0, 0.0, 800.0)),
            ] {
                let from = leaving(v, w);
                let mut stats = Stats::default();
                let form = HopForces::for_wind(hops.wind_varies());
                let Some(closed) = low_hop(&from, &n, &hops, form, &mut stats, None) else {
                    panic!("closed form {v:?}")
                };
                assert_eq!(stats.force_evaluations, evaluations);
                let Ok(integrated) = hops.hop(&from, plane, None, &mut stats) else {
                    panic!("integrated {v:?}")
                };
                let dp = (closed.position - integrated.position).norm();
                let dt = (closed.time - integrated.time).abs();
                let dv = (closed.velocity - integrated.velocity).norm();
                assert!(
                    dp < max_m && dt < max_s && dv < max_mps,
                    "{wind:?} {v:?} {w:?}: {dp} m, {dt} s, {dv} m/s"
                );
            }
        }
    }
}
