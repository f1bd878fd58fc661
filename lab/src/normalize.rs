//! `carry normalize`: the carry of the same launch in standard conditions, and back.
//!
//! Launch monitors compare sessions played in different weather by flying each measured
//! launch again in one reference atmosphere. Standard conditions here are sea level
//! (101 325 Pa), 21 °C (70 °F) and 50 % relative humidity, no wind — the moist-air density
//! of the core's weather model, ≈ 1.194 kg/m³ — keeping the scene's aerodynamic model,
//! effects and landing height. `ToStandard` flies the launch in the given conditions
//! (what was measured) and in standard ones (the normalised carry); `ToConditions` the
//! other way round: a carry known in standard conditions, played in these.

use crate::error::Result;
use carry_core::air::{Pressure, Weather};
use carry_core::flight::Integrator;
use carry_core::real::{lit, to_f64};
use carry_core::units::to_deg;
use carry_core::{Air, Ball, BallMotion, FlightOutcome, Real, Scene, Wind};
use serde::Serialize;

/// Standard temperature (°C).
pub const STANDARD_TEMPERATURE_C: f64 = 21.0;
/// Standard relative humidity (0..1).
pub const STANDARD_RELATIVE_HUMIDITY: f64 = 0.5;
/// Standard altitude (m): sea level.
pub const STANDARD_ALTITUDE_M: f64 = 0.0;

/// Which way to normalise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Direction {
    /// Conditions → standard.
    ToStandard,
    /// Standard → conditions.
    ToConditions,
}

/// The standard scene: `conditions` with standard air and no wind.
#[must_use]
pub fn standard_scene<T: Real>(conditions: &Scene<T>) -> Scene<T> {
    Scene {
        air: Air::Weather(Weather {
            temperature_c: lit(STANDARD_TEMPERATURE_C),
            relative_humidity: lit(STANDARD_RELATIVE_HUMIDITY),
            pressure: Pressure::Altitude(lit(STANDARD_ALTITUDE_M)),
        }),
        wind: Wind::None,
        ..*conditions
    }
}

/// One flight's landing, in reporting units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Landing {
    /// Air density (kg/m³).
    pub air_density_kgm3: f64,
    /// Carry (m).
    pub carry_m: f64,
    /// Side (m).
    pub side_m: f64,
    /// Apex (m).
    pub apex_m: f64,
    /// Flight time (s).
    pub flight_time_s: f64,
    /// Landing angle (deg).
    pub land_angle_deg: f64,
}

impl Landing {
    fn of<T: Real>(f: &FlightOutcome<T>) -> Self {
        Self {
            air_density_kgm3: to_f64(f.air_density_kgm3),
            carry_m: to_f64(f.carry_m),
            side_m: to_f64(f.side_m),
            apex_m: to_f64(f.apex_m),
            flight_time_s: to_f64(f.flight_time_s),
            land_angle_deg: to_f64(to_deg(f.landing_angle_rad)),
        }
    }
}

/// The same launch in two atmospheres.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Normalized {
    /// Which way.
    pub direction: Direction,
    /// The flight where the launch was observed.
    pub from: Landing,
    /// The flight it is normalised to.
    pub to: Landing,
    /// The normalised carry, `to.carry_m` (m).
    pub carry_m: f64,
    /// `to.carry_m − from.carry_m` (m).
    pub carry_change_m: f64,
}

/// Flies `launch` in `conditions` and in standard conditions.
///
/// # Errors
/// The core's errors for either scene or flight.
pub fn normalize<T: Real>(
    ball: &Ball<T>,
    launch: &BallMotion<T>,
    conditions: &Scene<T>,
    integrator: &Integrator<T>,
    direction: Direction,
) -> Result<Normalized> {
    let standard = standard_scene(conditions);
    let (from, to) = match direction {
        Direction::ToStandard => (conditions, &standard),
        Direction::ToConditions => (&standard, conditions),
    };
    let fly = |scene: &Scene<T>| -> Result<Landing> {
        let f = scene.prepare(ball)?.fly(launch, integrator, None)?;
        Ok(Landing::of(&f))
    };
    let (from, to) = (fly(from)?, fly(to)?);
    Ok(Normalized {
        direction,
        from,
        to,
        carry_m: to.carry_m,
        carry_change_m: to.carry_m - from.carry_m,
    })
}
