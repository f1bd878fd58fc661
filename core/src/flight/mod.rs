//! Ball flight: from launch conditions to where and how the ball lands (PHYSICS.md,
//! "Flight").
//!
//! The ball flies through the force field of a [`Scene`]: its aerodynamic model
//! ([`crate::aero`]), effects, air and wind. The state (position, velocity, spin magnitude
//! about the fixed spin axis) is integrated by an [`Integrator`] — explicit Euler,
//! classical RK4 or adaptive Dormand–Prince 5(4) ([`crate::integrator`]) — and the landing
//! and the apex are located *inside* the step by the step's interpolant and a bracketing
//! root finder, never taken as a step end or the highest sample. With a ground in the
//! scene the run-out follows ([`crate::ground`]). Every result reports the number of force
//! evaluations it cost.
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

mod outcome;

pub use crate::ground::{
    HOP_MAX_FIRST_STEP_S, HOP_MAX_TOLERANCE, HOP_STEP_FACTOR, HOP_TOLERANCE_FACTOR,
};
pub use crate::integrator::{
    DEFAULT_INITIAL_STEP_F32_S, DEFAULT_INITIAL_STEP_F64_S, DEFAULT_INITIAL_STEP_S,
    DEFAULT_TOLERANCE_F32, DEFAULT_TOLERANCE_F64, GRAZING_LANDING_RAD, INITIAL_STEP_SCALE_S,
    Integrator, MAX_ADAPTIVE_STEPS, MAX_TOLERANCE, PROFILE_INITIAL_STEP_S,
};
pub use crate::trajectory::{Recorder, Sample, SampleSink, Stats};
pub use outcome::FlightOutcome;

use crate::aero::{Dynamics, Rhs, S, State, Switches, Y};
use crate::ball::{Ball, BallMotion};
use crate::error::{Error, Field, Reason, Result};
use crate::ground::Hops;
use crate::integrator::{Method, events, integrate_to_event};
use crate::real::{Real, length, lit};
use crate::scene::{PreparedScene, Scene};
use crate::trajectory::Contact;
use nalgebra::Vector3;

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
    // Read where it was returned: `?` would move the prepared scene (a few hundred bytes)
    // out of its `Result`, ≈ 1,200 instructions of `memcpy` on a Cortex-M4F.
    match &scene.prepare(ball) {
        Ok(prepared) => prepared.fly(launch, integrator, recorder),
        Err(e) => Err(*e),
    }
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
        // On hosts, the everyday scene (drag, lift and spin decay, still air) flies with
        // its effects as compile-time switches: the same operations (bit for bit), without
        // the effect branches in each of the ≈ 43 force evaluations, and with the
        // integrator's registers allocated for one force model (−5 % of the flight's
        // instructions, docs/performance.md). One more copy of the integrator loop, so not
        // on embedded targets (flash; their flights keep the runtime branches).
        let e = &self.field.effects;
        if !cfg!(target_os = "none") && e.drag && e.lift && e.spin_decay && !self.field.has_wind() {
            return run(
                self,
                launch,
                integrator,
                recorder,
                Switches::<T, true, true, true, 0>,
            );
        }
        run(self, launch, integrator, recorder, |d| d)
    }
}

/// The flight's start from a validated launch: the speed and spin bounds, the state
/// `[x, y, z, vx, vy, vz, ω]` at the scene's launch position and the unit spin axis (zero
/// without spin). Shared by the scalar flight and the lanes kernel.
pub(crate) fn start_state<T: Real>(
    scene: &PreparedScene<T>,
    launch: &BallMotion<T>,
) -> Result<(State<T>, Vector3<T>)> {
    if !(length(&launch.velocity_mps) <= lit(MAX_BALL_SPEED_MPS)) {
        return Err(Error::invalid(Field::BallVelocity, Reason::OutOfRange));
    }
    let spin = length(&launch.spin_radps);
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
    Ok(([p0.x, p0.y, p0.z, v0.x, v0.y, v0.z, spin], axis))
}

/// The carry `√(x² + z²)` (m) from the landing's offsets downrange and sideways, and the
/// landing angle `atan2(−v_y, √(v_x² + v_z²))` (rad) below the horizontal. Shared by the
/// scalar flight and the lanes kernel, which must agree bit for bit. No `hypot`: metres and
/// metres per second are far from overflow, and libm's is a long out-of-line call where a
/// square root is one instruction.
pub(crate) fn carry_and_landing_angle<T: Real>(
    carry_x: T,
    side: T,
    velocity: &Vector3<T>,
) -> (T, T) {
    let horizontal = (velocity.x * velocity.x + velocity.z * velocity.z).root();
    (
        (carry_x * carry_x + side * side).root(),
        (-velocity.y).atan2(horizontal),
    )
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
    let (y0, axis) = start_state(scene, &launch)?;
    let spin = y0[S];
    let p0 = scene.launch_position;
    if y0[Y] <= scene.landing_height && launch.velocity_mps.y <= T::zero() {
        // At or below the landing height and not rising: it never comes down through it.
        // On a ground it meets the turf at once (a topped shot) and bounces and rolls.
        return match &scene.ground {
            None => Err(Error::NoLanding),
            Some(g) => into_the_ground(scene, g, &launch, axis, spin, method, recorder),
        };
    }
    let rhs = make(Dynamics {
        field: &scene.field,
        axis,
    });
    let mut recorder = recorder;
    if let Some(r) = recorder.as_deref_mut() {
        r.reset();
    }
    let mut tracker =
        events::Tracker::new(scene.landing_height, &y0, axis, recorder.as_deref_mut());
    let mut stats = Stats::default();
    let landing = integrate_to_event(
        &scene.field,
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
    let speed = length(&Vector3::new(y[3], y[4], y[5]));
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
    let mut ground = None;
    if let Some(g) = &scene.ground {
        let first = Contact {
            time: landing.time,
            position,
            velocity,
            spin: axis * y[S],
        };
        let hopper = Hops {
            field: &scene.field,
            time_limit: scene.time_limit,
            method,
        };
        crate::ground::run_out(
            g,
            scene.field.gravity,
            &p0,
            &first,
            &hopper,
            recorder.as_deref_mut(),
            &mut ground,
        )?;
    }
    let (carry_m, landing_angle_rad) = carry_and_landing_angle(carry_x, side, &velocity);
    Ok(FlightOutcome {
        carry_m,
        carry_x_m: carry_x,
        side_m: side,
        apex_m,
        apex_time_s,
        flight_time_s: landing.time,
        landing_angle_rad,
        landing_speed_mps: length(&velocity),
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
    let hopper = Hops {
        field: &scene.field,
        time_limit: scene.time_limit,
        method,
    };
    let mut rollout = None;
    crate::ground::run_out(
        ground,
        scene.field.gravity,
        &p0,
        &first,
        &hopper,
        recorder.as_deref_mut(),
        &mut rollout,
    )?;
    Ok(FlightOutcome {
        carry_m: T::zero(),
        carry_x_m: T::zero(),
        side_m: T::zero(),
        apex_m: p0.y,
        apex_time_s: T::zero(),
        flight_time_s: T::zero(),
        landing_angle_rad: (-velocity.y).atan2(velocity.x.hypot(velocity.z)),
        landing_speed_mps: length(&velocity),
        landing_spin_radps: spin,
        landing_position_m: p0,
        landing_velocity_mps: velocity,
        landing_spin_vector_radps: first.spin,
        air_density_kgm3: scene.density,
        stats: Stats::default(),
        recording_full: recorder.is_some_and(|r| r.is_full()),
        ground: rollout,
    })
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
