//! The whole shot: delivery → impact → flight.

use crate::club::{CarryBall, CarryClub};
use crate::error::Result;
use crate::flight::{Buffer, CARRY_DEFAULT_RECORD_INTERVAL_S, CarryFlightResult};
use crate::impact::{CarryDelivery, CarryImpactResult};
use crate::scene::CarryScene;
use crate::settings::CarrySettings;
use carry_core::flight::Recorder;
use carry_core::impact;
use carry_core::real::{Real, lit};

/// What a shot needs. Start from `carry_shot_input_default_*`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarryShotInput<T> {
    /// The club head.
    pub club: CarryClub<T>,
    /// The ball.
    pub ball: CarryBall<T>,
    /// The delivery.
    pub delivery: CarryDelivery<T>,
    /// The scene.
    pub scene: CarryScene<T>,
    /// Solver and integrator.
    pub settings: CarrySettings<T>,
    /// Trajectory sample interval (s), used when a sample buffer is given.
    pub record_interval_s: T,
}

/// Impact and flight of one shot.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CarryShotResult<T> {
    /// The impact.
    pub impact: CarryImpactResult<T>,
    /// The flight of the launched ball.
    pub flight: CarryFlightResult<T>,
}

impl<T: Real> Default for CarryShotInput<T> {
    /// The CLI's `carry shot` defaults: the driver preset at 45 m/s, square and centred,
    /// in the default scene and settings.
    fn default() -> Self {
        let club = crate::club::default_club();
        Self {
            club,
            ball: CarryBall::standard(),
            delivery: CarryDelivery::square(&club),
            scene: CarryScene::default(),
            settings: CarrySettings::default(),
            record_interval_s: lit(CARRY_DEFAULT_RECORD_INTERVAL_S),
        }
    }
}

/// The shot of `input`: the steps of the core's `shot::play` (strike → impact → flight),
/// spelled out so that the outcomes go straight into the C result (`play` returns them
/// through two more copies; the results are the same, bit for bit: `tests/api.rs`).
///
/// # Errors
/// The core's errors; `CARRY_ERR_UNKNOWN_OPTION` for an unknown selector.
pub fn run<T: Real>(
    input: &CarryShotInput<T>,
    buffer: Option<&mut Buffer<T>>,
) -> Result<CarryShotResult<T>> {
    let mut result = None;
    run_with(input, buffer, |r| result = Some(r()))?;
    result.ok_or(crate::error::CARRY_ERR_OTHER)
}

/// [`run`], handing `emit` a maker of the result so that the caller builds it in place
/// (on the target every move of a large struct is a copy: 4 % of a full f32 shot, docs/ffi.md).
/// Returns whether the sample buffer filled up.
///
/// # Errors
/// As [`run`].
#[inline(always)]
pub fn run_with<T: Real>(
    input: &CarryShotInput<T>,
    buffer: Option<&mut Buffer<T>>,
    emit: impl FnOnce(&dyn Fn() -> CarryShotResult<T>),
) -> Result<bool> {
    let club = input.club.spec()?.validate();
    let club = club.as_ref().map_err(|e| *e)?;
    let ball = input.ball.ball()?;
    let scene = input.scene.scene()?.prepare(&ball);
    let scene = scene.as_ref().map_err(|e| *e)?;
    let solver = input.settings.solver()?;
    let integrator = input.settings.integrator()?;
    let strike = input.delivery.strike(club)?;
    // Borrowed from the `Result`s, not moved out: the outcomes are large, and each move is
    // a copy on the target (docs/ffi.md, "Cost").
    let hit = impact::solve(club, &ball, &strike, solver);
    let hit = hit.as_ref().map_err(|e| *e)?;
    let flight = match buffer {
        None => scene.fly(&hit.ball, &integrator, None),
        Some(b) => {
            let mut recorder = Recorder::with_sink(input.record_interval_s, b)?;
            scene.fly(&hit.ball, &integrator, Some(&mut recorder))
        }
    };
    let flight = flight.as_ref().map_err(|e| *e)?;
    emit(&|| CarryShotResult {
        impact: CarryImpactResult::from_outcome(hit),
        flight: CarryFlightResult::from_outcome(flight),
    });
    Ok(flight.recording_full)
}
