//! Flight: launch → landing (and bounce and roll when the scene has a ground), with an
//! optional trajectory into a caller-owned buffer.

use crate::club::CarryBall;
use crate::error::{CARRY_ERR_BUFFER_TOO_SMALL, CARRY_ERR_NULL_POINTER, Result};
use crate::scene::CarryScene;
use crate::settings::CarrySettings;
use carry_core::Launch;
use carry_core::flight::{FlightOutcome, Recorder, Sample, SampleSink};
use carry_core::ground::RunEnd;
use carry_core::real::{Real, lit};
use carry_core::units::{deg, mph, rpm};

/// A launch as a launch monitor measures it (m/s, rad, rad/s).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarryLaunch<T> {
    /// Ball speed (m/s).
    pub ball_speed_mps: T,
    /// Launch angle, + up (rad).
    pub launch_angle_rad: T,
    /// Launch direction, + right (rad).
    pub launch_direction_rad: T,
    /// Backspin (rad/s).
    pub backspin_radps: T,
    /// Sidespin, + curves right (rad/s).
    pub sidespin_radps: T,
}

/// One trajectory sample (global frame).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CarrySample<T> {
    /// Time since launch (s).
    pub time_s: T,
    /// Ball position (m).
    pub position_m: [T; 3],
    /// Ball velocity (m/s).
    pub velocity_mps: [T; 3],
    /// Ball spin (rad/s).
    pub spin_radps: [T; 3],
}

/// What a flight needs. Start from `carry_flight_input_default_*`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarryFlightInput<T> {
    /// The ball.
    pub ball: CarryBall<T>,
    /// The launch.
    pub launch: CarryLaunch<T>,
    /// The scene.
    pub scene: CarryScene<T>,
    /// The integrator (`solver` is not used).
    pub settings: CarrySettings<T>,
    /// Trajectory sample interval (s), used when a sample buffer is given.
    pub record_interval_s: T,
}

/// Where and how the ball lands, and where it comes to rest on a ground.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CarryFlightResult<T> {
    /// Carry: horizontal distance from the tee to the landing (m).
    pub carry_m: T,
    /// Carry along the target line (m).
    pub carry_x_m: T,
    /// Side at the landing, + right (m).
    pub side_m: T,
    /// Apex height (m).
    pub apex_m: T,
    /// Time of the apex (s).
    pub apex_time_s: T,
    /// Flight time, launch to landing (s).
    pub flight_time_s: T,
    /// Landing angle below the horizontal (rad).
    pub landing_angle_rad: T,
    /// Landing speed (m/s).
    pub landing_speed_mps: T,
    /// Spin at landing (rad/s).
    pub landing_spin_radps: T,
    /// Landing position (m).
    pub landing_position_m: [T; 3],
    /// Landing velocity (m/s).
    pub landing_velocity_mps: [T; 3],
    /// Spin vector at landing (rad/s).
    pub landing_spin_vector_radps: [T; 3],
    /// Air density flown through (kg/m³).
    pub air_density_kgm3: T,
    /// Force evaluations of the flight.
    pub force_evaluations: u32,
    /// Accepted integrator steps.
    pub steps: u32,
    /// Rejected integrator steps.
    pub rejected_steps: u32,
    /// 1 when the sample buffer filled up and later samples were dropped, else 0.
    pub recording_full: u32,
    /// 1 when the scene had a ground (the fields below are set), else 0.
    pub has_ground: u32,
    /// Total: tee to rest, horizontal (m).
    pub total_m: T,
    /// Roll: landing to rest along the ground (m).
    pub roll_m: T,
    /// Rest position (m).
    pub rest_position_m: [T; 3],
    /// Time from launch to rest (s).
    pub time_to_rest_s: T,
    /// Number of hops after the landing.
    pub bounces: u32,
    /// 1 when the ball was still rolling at the roll time cap, else 0.
    pub still_rolling: u32,
    /// Force evaluations of the hops.
    pub ground_force_evaluations: u32,
}

impl<T: Real> Default for CarryLaunch<T> {
    /// The CLI's `carry flight` launch: 167 mph, 10.9°, straight, 2686 rpm backspin.
    fn default() -> Self {
        Self {
            ball_speed_mps: mph(lit(167.0)),
            launch_angle_rad: deg(lit(10.9)),
            launch_direction_rad: T::zero(),
            backspin_radps: rpm(lit(2686.0)),
            sidespin_radps: T::zero(),
        }
    }
}

impl<T: Real> Default for CarryFlightInput<T> {
    /// The CLI's `carry flight` defaults; samples every 0.1 s.
    fn default() -> Self {
        Self {
            ball: CarryBall::standard(),
            launch: CarryLaunch::default(),
            scene: CarryScene::default(),
            settings: CarrySettings::default(),
            record_interval_s: lit(CARRY_DEFAULT_RECORD_INTERVAL_S),
        }
    }
}

/// Default trajectory sample interval (s).
pub const CARRY_DEFAULT_RECORD_INTERVAL_S: f64 = 0.1;

impl<T: Real> CarryLaunch<T> {
    /// The core launch.
    #[must_use]
    pub fn launch(&self) -> Launch<T> {
        Launch {
            ball_speed_mps: self.ball_speed_mps,
            launch_angle_rad: self.launch_angle_rad,
            launch_direction_rad: self.launch_direction_rad,
            backspin_radps: self.backspin_radps,
            sidespin_radps: self.sidespin_radps,
        }
    }
}

impl<T: Real> CarryFlightResult<T> {
    /// The C form of a core flight outcome.
    #[must_use]
    pub fn from_outcome(o: &FlightOutcome<T>) -> Self {
        let z = T::zero();
        let mut r = Self {
            carry_m: o.carry_m,
            carry_x_m: o.carry_x_m,
            side_m: o.side_m,
            apex_m: o.apex_m,
            apex_time_s: o.apex_time_s,
            flight_time_s: o.flight_time_s,
            landing_angle_rad: o.landing_angle_rad,
            landing_speed_mps: o.landing_speed_mps,
            landing_spin_radps: o.landing_spin_radps,
            landing_position_m: o.landing_position_m.into(),
            landing_velocity_mps: o.landing_velocity_mps.into(),
            landing_spin_vector_radps: o.landing_spin_vector_radps.into(),
            air_density_kgm3: o.air_density_kgm3,
            force_evaluations: o.stats.force_evaluations,
            steps: o.stats.steps,
            rejected_steps: o.stats.rejected_steps,
            recording_full: u32::from(o.recording_full),
            has_ground: 0,
            total_m: z,
            roll_m: z,
            rest_position_m: [z; 3],
            time_to_rest_s: z,
            bounces: 0,
            still_rolling: 0,
            ground_force_evaluations: 0,
        };
        if let Some(g) = &o.ground {
            r.has_ground = 1;
            r.total_m = g.total_m;
            r.roll_m = g.roll_m;
            r.rest_position_m = g.rest_position_m.into();
            r.time_to_rest_s = g.time_to_rest_s;
            r.bounces = g.bounces;
            r.still_rolling = u32::from(g.end == RunEnd::StillRolling);
            r.ground_force_evaluations = g.stats.force_evaluations;
        }
        r
    }
}

/// A caller-owned C buffer of samples: pointer, capacity, count so far.
pub struct Buffer<T> {
    ptr: *mut CarrySample<T>,
    capacity: usize,
    len: usize,
}

impl<T: Real> Buffer<T> {
    /// A buffer of `capacity` samples at `ptr`.
    ///
    /// # Safety
    /// `ptr` is not NULL and points to `capacity` writable samples, not otherwise accessed
    /// while the buffer lives.
    #[must_use]
    pub unsafe fn new(ptr: *mut CarrySample<T>, capacity: usize) -> Self {
        Self {
            ptr,
            capacity,
            len: 0,
        }
    }

    /// Samples written.
    #[must_use]
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether no sample was written.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

impl<T: Real> SampleSink<T> for Buffer<T> {
    fn clear(&mut self) {
        self.len = 0;
    }

    fn push(&mut self, s: Sample<T>) -> bool {
        if self.len >= self.capacity {
            return false;
        }
        let c = CarrySample {
            time_s: s.time_s,
            position_m: s.position_m.into(),
            velocity_mps: s.velocity_mps.into(),
            spin_radps: s.spin_radps.into(),
        };
        // SAFETY: `len < capacity`, and `ptr` holds `capacity` writable samples (`new`).
        unsafe { crate::ptr::write(self.ptr.add(self.len), c) };
        self.len += 1;
        true
    }
}

/// The flight of `input`.
///
/// # Errors
/// The core's errors; `CARRY_ERR_UNKNOWN_OPTION` for an unknown selector.
pub fn run<T: Real>(
    input: &CarryFlightInput<T>,
    buffer: Option<&mut Buffer<T>>,
) -> Result<CarryFlightResult<T>> {
    let ball = input.ball.ball()?;
    let scene = input.scene.scene()?.prepare(&ball);
    let scene = scene.as_ref().map_err(|e| *e)?;
    let motion = input.launch.launch().ball_motion()?;
    let integrator = input.settings.integrator()?;
    let out = match buffer {
        None => scene.fly(&motion, &integrator, None)?,
        Some(b) => {
            let mut recorder = Recorder::with_sink(input.record_interval_s, b)?;
            scene.fly(&motion, &integrator, Some(&mut recorder))?
        }
    };
    Ok(CarryFlightResult::from_outcome(&out))
}

/// The checked trajectory arguments of a C call: no buffer (`samples` NULL), or a buffer
/// with a non-NULL `count`.
///
/// # Safety
/// `samples` is NULL or points to `capacity` writable samples.
///
/// # Errors
/// `CARRY_ERR_NULL_POINTER` for a buffer without a `count`.
pub unsafe fn buffer<T: Real>(
    samples: *mut CarrySample<T>,
    capacity: usize,
    count: *mut usize,
) -> Result<Option<Buffer<T>>> {
    if samples.is_null() {
        return Ok(None);
    }
    if count.is_null() {
        return Err(CARRY_ERR_NULL_POINTER);
    }
    // SAFETY: not NULL, `capacity` writable samples by the caller's contract.
    Ok(Some(unsafe { Buffer::new(samples, capacity) }))
}

/// Writes the sample count when `count` is not NULL: the samples written by a flight that
/// succeeded (`ok`), else 0 (the samples of a failed flight, e.g. a diverging fixed step,
/// are not results).
///
/// # Safety
/// `count` is NULL or writable.
pub unsafe fn finish<T: Real>(buffer: Option<&Buffer<T>>, count: *mut usize, ok: bool) {
    if !count.is_null() {
        let n = if ok { buffer.map_or(0, Buffer::len) } else { 0 };
        // SAFETY: not NULL, writable by the caller's contract.
        unsafe { crate::ptr::write(count, n) };
    }
}

/// `CARRY_ERR_BUFFER_TOO_SMALL` when there is a buffer and it filled up.
///
/// # Errors
/// As above.
pub fn full<T: Real>(buffer: Option<&Buffer<T>>, recording_full: u32) -> Result<()> {
    if buffer.is_some() && recording_full != 0 {
        return Err(CARRY_ERR_BUFFER_TOO_SMALL);
    }
    Ok(())
}
