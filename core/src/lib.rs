//! # carry-core
//!
//! A `no_std`, allocation-free golf physics engine for launch monitors, generic over
//! `f32` and `f64`:
//!
//! 1. **Impact** — the three-dimensional impulse–momentum model of Petersen and McPhee:
//!    rigid club head and ball, instantaneous impulse, normal restitution and rolling
//!    without slipping on an ellipsoidal face (bulge, roll, gear effect). Solved either as
//!    the full 15×15 linear system by Gaussian elimination with partial pivoting
//!    ([`impact::Solver::Full`]) or by the exact 3×3 collision-matrix form
//!    ([`impact::Solver::Reduced`]).
//! 2. **Flight** — Quintavalla's aerodynamic model (drag, Magnus lift, spin decay) with
//!    the effects a [`scene`] asks for, integrated to an exact landing.
//!
//! Data flows one way: [`delivery`] → club state → contact geometry ([`face`],
//! [`contact`]) → [`impact`] solve → [`launch`] → [`flight`] → outcome. Conventions,
//! frames and equations follow the project's physics contract (see the README's
//! "Model" section). SI units inside; [`units`] converts at the edges.
//!
//! The modules are layered: each imports only lower ones, with no import circle (CI checks
//! it with `.ci/core-layers.sh`). Below the flight, [`trajectory`] holds the types every
//! stage shares, [`aero`] the scene's force field and the right-hand side, [`integrator`]
//! the integrators, [`ground`] the run-out and its hops; [`scene`] assembles them and
//! [`flight`] runs them. [`presets`] sit above the club, the impact and the conventions.
//!
//! Every public entry point validates its inputs once and returns a typed
//! [`Error`]; nothing panics or returns NaN.
#![no_std]
// `unsafe` in two places only: the FPU's square root on hard-float ARM (`real.rs`) and the
// lanes kernel's AVX packs on x86-64 (`lanes/avx.rs`: intrinsics behind a CPU-checked token).
#![deny(unsafe_code)]

pub mod ball;
pub mod club;
pub mod contact;
pub mod contact_law;
pub mod convention;
pub mod delivery;
pub mod error;
pub mod estimate;
pub mod face;
pub mod geometry;
pub mod impact;
pub mod launch;
pub mod launch_fit;
pub mod linalg;
pub mod presets;
pub mod real;
pub mod shot;
pub mod units;
mod validate;

// --- flight (ball flight after launch) ---
pub mod aero;
pub mod air;
pub mod flight;
pub mod ground;
pub mod integrator;
pub mod lanes;
pub mod scene;
pub mod trajectory;
pub mod wind;

pub use air::{Air, Pressure, Weather};
pub use flight::{FlightOutcome, Integrator, Recorder, Sample, SampleSink, Stats, fly};
pub use ground::{Ground, Rollout, RunEnd, Surface, Turf};
pub use scene::{Effects, PreparedScene, Scene};
pub use wind::Wind;
// --- end flight ---

pub use ball::{Ball, BallMotion};
pub use club::{ClubHead, ClubSpec, ContactLaw};
pub use convention::DeliveryConvention;
pub use delivery::{ClubMotion, Delivery, FaceLocation, Strike};
pub use error::{Error, Field, Reason, Result};
pub use impact::{ImpactOutcome, Solver};
pub use launch::{Launch, LaunchMetrics};
pub use presets::{PRESETS, Preset};
pub use real::Real;
