//! The whole shot: delivery → impact → flight.

use crate::club::{CarryBall, CarryClub};
use crate::error::Result;
use crate::flight::{Buffer, CARRY_DEFAULT_RECORD_INTERVAL_S, CarryFlightResult};
use crate::impact::{CarryDelivery, CarryImpactResult};
use crate::scene::CarryScene;
use crate::settings::CarrySettings;
use carry_core::flight::Recorder;
use carry_core::real::{Real, lit};
use carry_core::shot;

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
#[derive(Debug, Clone, Copy, PartialEq)]
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

/// The shot of `input`, as the core's `shot::play` plays it.
///
/// # Errors
/// The core's errors; `CARRY_ERR_UNKNOWN_OPTION` for an unknown selector.
pub fn run<T: Real>(
    input: &CarryShotInput<T>,
    buffer: Option<&mut Buffer<T>>,
) -> Result<CarryShotResult<T>> {
    let club = input.club.spec()?.validate()?;
    let ball = input.ball.ball()?;
    let scene = input.scene.scene()?.prepare(&ball)?;
    let fidelity = input.settings.fidelity()?;
    let delivery = input.delivery.delivery();
    let out = match buffer {
        None => shot::play(&club, &ball, &delivery, &scene, &fidelity, None)?,
        Some(b) => {
            let mut recorder = Recorder::with_sink(input.record_interval_s, b)?;
            shot::play(
                &club,
                &ball,
                &delivery,
                &scene,
                &fidelity,
                Some(&mut recorder),
            )?
        }
    };
    Ok(CarryShotResult {
        impact: CarryImpactResult::from_outcome(&out.impact),
        flight: CarryFlightResult::from_outcome(&out.flight),
    })
}
