//! The trajectory types every stage of a shot's flight shares: the recorded [`Sample`]s and
//! their [`Recorder`], the work done ([`Stats`]), and the ground contact and plane the
//! flight hands to the run-out. A leaf of the flight's layers: the aerodynamics, the
//! integrator, the ground and the flight all use it, and it uses none of them.

use crate::error::{Field, Result};
use crate::real::{Real, lit};
use crate::validate::positive;
use heapless::vec::VecView;
use nalgebra::Vector3;

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
/// buffer fills, recording stops and [`FlightOutcome::recording_full`](crate::flight::FlightOutcome::recording_full) is set — the
/// flight itself completes normally.
///
/// A recorder may instead sample at given times ([`Recorder::at_times`]): the flight's
/// dense output read where a launch monitor observed the ball (the launch from the flight,
/// [`crate::launch_fit`]), without integrating again per observation.
#[derive(Debug)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Recorder<'a, T: Real> {
    pub(crate) interval_s: T,
    /// The sample times when given explicitly (sorted, not negative); `None`: `k·interval_s`.
    times: Option<&'a [T]>,
    samples: Store<'a, T>,
    pub(crate) full: bool,
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
            times: None,
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
            times: None,
            samples: Store::Sink(sink),
            full: false,
        })
    }

    /// A recorder handing `sink` (cleared) one sample at each of `times` (s since launch)
    /// that the flight reaches, read from the integrator's dense output, then the landing.
    ///
    /// # Errors
    /// [`Field::RecordInterval`] when a time is not finite, negative, or earlier than the
    /// one before it.
    pub fn at_times(times: &'a [T], sink: &'a mut dyn SampleSink<T>) -> Result<Self> {
        let mut last = T::zero();
        for &t in times {
            if !(t.is_finite() && t >= last) {
                return Err(crate::error::Error::invalid(
                    Field::RecordInterval,
                    crate::error::Reason::OutOfRange,
                ));
            }
            last = t;
        }
        sink.clear();
        Ok(Self {
            // The interval is unused with explicit times; any positive value.
            interval_s: T::one(),
            times: Some(times),
            samples: Store::Sink(sink),
            full: false,
        })
    }

    /// The time of sample `k` (s since launch): `k·Δ`, or the `k`-th given time (`None`
    /// past the last one).
    #[inline]
    pub(crate) fn sample_time(&self, k: u32) -> Option<T> {
        match self.times {
            None => Some(lit::<T>(f64::from(k)) * self.interval_s),
            Some(times) => usize::try_from(k).ok().and_then(|k| times.get(k)).copied(),
        }
    }

    /// With explicit times: the index of the first at or after `t` (s since launch).
    pub(crate) fn first_given_at_or_after(&self, t: T) -> Option<u32> {
        let times = self.times?;
        let k = times.iter().take_while(|&&ts| ts < t).count();
        Some(u32::try_from(k).unwrap_or(u32::MAX))
    }

    /// With explicit times: the first strictly after `t` (s since launch), if any and the
    /// recorder has room; `Some(None)` when there is none.
    pub(crate) fn given_after(&self, t: T) -> Option<Option<T>> {
        let times = self.times?;
        if self.full {
            return Some(None);
        }
        Some(times.iter().copied().find(|&ts| ts > t))
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

    /// Forgets the samples so far (a flight starts).
    pub(crate) fn reset(&mut self) {
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
        if let Some(times) = self.times {
            // Explicit times strictly inside the hop.
            for &ts in times {
                let t = ts - from_time;
                if self.full || !(t < duration) {
                    break;
                }
                if t > T::zero() {
                    let (position_m, velocity_mps, spin) = state_at(t);
                    self.push(Sample {
                        time_s: ts,
                        position_m,
                        velocity_mps,
                        spin_radps: axis * spin,
                    });
                }
            }
            return;
        }
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

/// Work done by a flight: force evaluations and steps.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Stats {
    /// Evaluations of the force model (right-hand side), the deterministic cost measure.
    pub force_evaluations: u32,
    /// Accepted steps.
    pub steps: u32,
    /// Rejected steps (adaptive integrator only).
    pub rejected_steps: u32,
}

impl Stats {
    /// Adds another run's work (a hop's to the run-out's), saturating.
    pub(crate) fn add(&mut self, other: &Stats) {
        self.force_evaluations = self
            .force_evaluations
            .saturating_add(other.force_evaluations);
        self.steps = self.steps.saturating_add(other.steps);
        self.rejected_steps = self.rejected_steps.saturating_add(other.rejected_steps);
    }
}

/// The state at a ground contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Contact<T: Real> {
    pub(crate) time: T,
    pub(crate) position: Vector3<T>,
    pub(crate) velocity: Vector3<T>,
    pub(crate) spin: Vector3<T>,
}

/// A ground plane `n·p = c` (unit normal `n` pointing up out of the ground): a hop after
/// a bounce ends when the ball comes down through it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Plane<T> {
    pub(crate) normal: Vector3<T>,
    pub(crate) offset: T,
}
