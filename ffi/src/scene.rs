//! The scene of a flight: effects, aerodynamic model, air, wind, landing height, ground.

use crate::error::{CARRY_ERR_UNKNOWN_OPTION, Result};
use carry_core::aero::AeroModel;
use carry_core::air::{Air, Pressure, Weather};
use carry_core::ground::{Ground, Surface, Turf};
use carry_core::real::{Real, lit};
use carry_core::scene::Scene;
use carry_core::wind::{DEFAULT_EXPONENT, DEFAULT_REFERENCE_HEIGHT_M, Wind};
use nalgebra::Vector3;

/// `CarryScene::aero`: the modern model fitted to TrackMan's 2023 tour table and 2010
/// driver chart (the default before issue 35).
pub const CARRY_AERO_TOUR2023: u32 = 0;
/// `CarryScene::aero`: the seed's model (Quintavalla), which PHYSICS.md's numbers use.
pub const CARRY_AERO_QUINTAVALLA: u32 = 1;
/// `CarryScene::aero`: the calibrated default model, fitted to single TrackMan drives with
/// both tables (issue 35).
pub const CARRY_AERO_DRIVES2026: u32 = 2;

/// `CarryScene::air`: a fixed density, `air_density_kgm3`.
pub const CARRY_AIR_DENSITY: u32 = 0;
/// `CarryScene::air`: weather with a measured pressure (`temperature_c`,
/// `relative_humidity`, `pressure_pa`).
pub const CARRY_AIR_WEATHER_PRESSURE: u32 = 1;
/// `CarryScene::air`: weather at an altitude (`temperature_c`, `relative_humidity`,
/// `altitude_m`; standard-atmosphere pressure).
pub const CARRY_AIR_WEATHER_ALTITUDE: u32 = 2;

/// `CarryScene::wind`: still air.
pub const CARRY_WIND_NONE: u32 = 0;
/// `CarryScene::wind`: `wind_mps` everywhere.
pub const CARRY_WIND_UNIFORM: u32 = 1;
/// `CarryScene::wind`: a power-law profile, `wind_mps` at `wind_reference_height_m`.
pub const CARRY_WIND_PROFILE: u32 = 2;

/// `CarryScene::ground`: no ground, the shot ends at the landing (carry).
pub const CARRY_GROUND_NONE: u32 = 0;
/// `CarryScene::ground`: a firm fairway (bounce and roll to rest).
pub const CARRY_GROUND_FAIRWAY: u32 = 1;
/// `CarryScene::ground`: a soft fairway.
pub const CARRY_GROUND_FAIRWAY_SOFT: u32 = 2;
/// `CarryScene::ground`: rough.
pub const CARRY_GROUND_ROUGH: u32 = 3;
/// `CarryScene::ground`: a green of stimpmeter reading `stimp_m`.
pub const CARRY_GROUND_GREEN: u32 = 4;
/// `CarryScene::ground`: custom turf (`ground_restitution`, `ground_friction`,
/// `rolling_resistance`, `crater_scale`).
pub const CARRY_GROUND_CUSTOM: u32 = 5;
/// `CarryScene::ground`: the launch monitor's fairway (fitted to TrackMan's roll on single
/// drives).
pub const CARRY_GROUND_FAIRWAY_TRACKMAN: u32 = 6;
/// `CarryScene::ground`: the fairway of both TrackMan data sets (fitted to its roll on
/// single drives and its 2010 chart's totals at once).
pub const CARRY_GROUND_FAIRWAY_JOINT: u32 = 7;

/// Everything about a flight that is not the ball or its launch (SI units; the humidity
/// is a fraction 0..1, not the CLI's %). Start from `carry_scene_default_*`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarryScene<T> {
    /// Aerodynamic drag on (non-zero) or off (0).
    pub drag: u32,
    /// Magnus lift on (non-zero) or off (0).
    pub lift: u32,
    /// Spin decay on (non-zero) or off (0).
    pub spin_decay: u32,
    /// `CARRY_AERO_DRIVES2026` (default), `CARRY_AERO_TOUR2023` or `CARRY_AERO_QUINTAVALLA`.
    pub aero: u32,
    /// `CARRY_AIR_DENSITY`, `CARRY_AIR_WEATHER_PRESSURE` or `CARRY_AIR_WEATHER_ALTITUDE`.
    pub air: u32,
    /// Fixed air density (kg/m³).
    pub air_density_kgm3: T,
    /// Air temperature (°C).
    pub temperature_c: T,
    /// Relative humidity, 0..1.
    pub relative_humidity: T,
    /// Station pressure (Pa).
    pub pressure_pa: T,
    /// Altitude above sea level (m).
    pub altitude_m: T,
    /// `CARRY_WIND_NONE`, `CARRY_WIND_UNIFORM` or `CARRY_WIND_PROFILE`.
    pub wind: u32,
    /// Wind velocity (m/s, global frame: x downrange, y up, z right).
    pub wind_mps: [T; 3],
    /// Profile reference height (m).
    pub wind_reference_height_m: T,
    /// Profile exponent.
    pub wind_exponent: T,
    /// Height of the landing area (m; + uphill target).
    pub landing_height_m: T,
    /// Flight time limit (s).
    pub time_limit_s: T,
    /// Gravitational acceleration (m/s²).
    pub gravity_mps2: T,
    /// Where the ball starts (m, global frame).
    pub launch_position_m: [T; 3],
    /// `CARRY_GROUND_*`: none (default) or a surface to bounce and roll on.
    pub ground: u32,
    /// Green speed, stimpmeter reading (m), for `CARRY_GROUND_GREEN`.
    pub stimp_m: T,
    /// Custom turf: restitution at vanishing normal speed, 0..1.
    pub ground_restitution: T,
    /// Custom turf: ball–turf friction coefficient.
    pub ground_friction: T,
    /// Custom turf: rolling resistance.
    pub rolling_resistance: T,
    /// Custom turf: crater scale.
    pub crater_scale: T,
    /// Ground plane normal (global frame; (0, 1, 0) is level).
    pub ground_normal: [T; 3],
}

impl<T: Real> Default for CarryScene<T> {
    /// The CLI's defaults: all effects, `drives2026`, 1.225 kg/m³ (weather: 15 °C, dry, sea
    /// level), no wind (profile: 10 m, 1/7), landing at 0 m, 60 s, standard gravity, no
    /// ground (green: 10 ft; custom turf: a firm fairway's).
    fn default() -> Self {
        let core = Scene::<T>::default();
        let turf = Surface::<T>::FairwayFirm.turf().unwrap_or(Turf {
            restitution: T::zero(),
            friction: T::zero(),
            rolling_resistance: T::zero(),
            crater_scale: T::zero(),
            crater_fade_mps: T::one(),
            grass_drag_s2pm2: T::zero(),
            crater_law: carry_core::ground::CraterLaw::Penner,
            grass_height_m: T::zero(),
        });
        let stimp = match Surface::<T>::green() {
            Surface::Green { stimp_m } => stimp_m,
            _ => T::zero(),
        };
        Self {
            drag: 1,
            lift: 1,
            spin_decay: 1,
            aero: CARRY_AERO_DRIVES2026,
            air: CARRY_AIR_DENSITY,
            air_density_kgm3: core.air.density_kgm3().unwrap_or_else(|_| T::zero()),
            temperature_c: lit(15.0),
            relative_humidity: T::zero(),
            pressure_pa: lit(carry_core::air::STANDARD_PRESSURE_PA),
            altitude_m: T::zero(),
            wind: CARRY_WIND_NONE,
            wind_mps: [T::zero(); 3],
            wind_reference_height_m: lit(DEFAULT_REFERENCE_HEIGHT_M),
            wind_exponent: lit(DEFAULT_EXPONENT),
            landing_height_m: core.landing_height_m,
            time_limit_s: core.time_limit_s,
            gravity_mps2: core.gravity_mps2,
            launch_position_m: core.launch_position_m.into(),
            ground: CARRY_GROUND_NONE,
            stimp_m: stimp,
            ground_restitution: turf.restitution,
            ground_friction: turf.friction,
            rolling_resistance: turf.rolling_resistance,
            crater_scale: turf.crater_scale,
            ground_normal: [T::zero(), T::one(), T::zero()],
        }
    }
}

impl<T: Real> CarryScene<T> {
    /// The core scene (validated later, by the core).
    ///
    /// # Errors
    /// `CARRY_ERR_UNKNOWN_OPTION` for an unknown selector.
    pub fn scene(&self) -> Result<Scene<T>> {
        let weather = |pressure| {
            Air::Weather(Weather {
                temperature_c: self.temperature_c,
                relative_humidity: self.relative_humidity,
                pressure,
            })
        };
        let air = match self.air {
            CARRY_AIR_DENSITY => Air::Density(self.air_density_kgm3),
            CARRY_AIR_WEATHER_PRESSURE => weather(Pressure::Pa(self.pressure_pa)),
            CARRY_AIR_WEATHER_ALTITUDE => weather(Pressure::Altitude(self.altitude_m)),
            _ => return Err(CARRY_ERR_UNKNOWN_OPTION),
        };
        let wind_mps = Vector3::from(self.wind_mps);
        let wind = match self.wind {
            CARRY_WIND_NONE => Wind::None,
            CARRY_WIND_UNIFORM => Wind::Uniform(wind_mps),
            CARRY_WIND_PROFILE => Wind::Profile {
                reference_mps: wind_mps,
                reference_height_m: self.wind_reference_height_m,
                exponent: self.wind_exponent,
            },
            _ => return Err(CARRY_ERR_UNKNOWN_OPTION),
        };
        let aero = match self.aero {
            CARRY_AERO_TOUR2023 => AeroModel::tour_2023(),
            CARRY_AERO_QUINTAVALLA => AeroModel::quintavalla(),
            CARRY_AERO_DRIVES2026 => AeroModel::drives_2026(),
            _ => return Err(CARRY_ERR_UNKNOWN_OPTION),
        };
        Ok(Scene {
            effects: carry_core::Effects {
                drag: self.drag != 0,
                lift: self.lift != 0,
                spin_decay: self.spin_decay != 0,
            },
            aero,
            air,
            wind,
            landing_height_m: self.landing_height_m,
            time_limit_s: self.time_limit_s,
            gravity_mps2: self.gravity_mps2,
            launch_position_m: Vector3::from(self.launch_position_m),
            ground: self.ground()?,
        })
    }

    fn ground(&self) -> Result<Option<Ground<T>>> {
        let surface = match self.ground {
            CARRY_GROUND_NONE => return Ok(None),
            CARRY_GROUND_FAIRWAY => Surface::FairwayFirm,
            CARRY_GROUND_FAIRWAY_SOFT => Surface::FairwaySoft,
            CARRY_GROUND_FAIRWAY_TRACKMAN => Surface::FairwayTrackman,
            CARRY_GROUND_FAIRWAY_JOINT => Surface::FairwayJoint,
            CARRY_GROUND_ROUGH => Surface::Rough,
            CARRY_GROUND_GREEN => Surface::Green {
                stimp_m: self.stimp_m,
            },
            // The crater fade, the grass drag and the grass height are the firm
            // fairway's (not in the C struct).
            CARRY_GROUND_CUSTOM => Surface::Custom(Turf {
                restitution: self.ground_restitution,
                friction: self.ground_friction,
                rolling_resistance: self.rolling_resistance,
                crater_scale: self.crater_scale,
                ..Surface::<T>::FairwayFirm.turf()?
            }),
            _ => return Err(CARRY_ERR_UNKNOWN_OPTION),
        };
        Ok(Some(Ground {
            surface,
            normal: Vector3::from(self.ground_normal),
        }))
    }
}
