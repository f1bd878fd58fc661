//! Loading the flight golden file (`tests/golden/flight.json`), computed in f64 by an
//! independent reference implementation (adaptive 8th-order integrator at 1e-12, exact
//! landing event). Launches are in launch-monitor units (deg, rpm); the expected values are
//! SI except angles (deg) and spin (rpm).

use carry_core::aero::AeroModel;
use carry_core::air::{Air, Pressure, Weather};
use carry_core::real::lit;
use carry_core::units::{deg, rpm};
use carry_core::{Effects, Launch, Real, Scene, Wind};
use nalgebra::Vector3;
use serde::Deserialize;

/// The whole file.
#[derive(Debug, Clone, Deserialize)]
pub struct FlightGolden {
    /// What the file is.
    pub description: String,
    /// The cases.
    pub cases: Vec<FlightCase>,
}

/// One case: a launch, a scene and the expected landing.
#[derive(Debug, Clone, Deserialize)]
pub struct FlightCase {
    /// Case name.
    pub name: String,
    /// Launch, launch-monitor units.
    pub launch: GoldenLaunch,
    /// The scene.
    pub scene: GoldenScene,
    /// The reference result.
    pub expected: FlightExpected,
}

/// Launch in deg / rpm.
#[derive(Debug, Clone, Copy, Deserialize)]
#[allow(missing_docs)]
pub struct GoldenLaunch {
    pub ball_speed_mps: f64,
    pub launch_angle_deg: f64,
    pub launch_direction_deg: f64,
    pub backspin_rpm: f64,
    pub sidespin_rpm: f64,
}

/// Effects switched on.
#[derive(Debug, Clone, Copy, Deserialize)]
#[allow(missing_docs)]
pub struct GoldenEffects {
    pub drag: bool,
    pub lift: bool,
    pub spin_decay: bool,
}

/// Weather: temperature, humidity and altitude or pressure.
#[derive(Debug, Clone, Copy, Deserialize)]
#[allow(missing_docs)]
pub struct GoldenWeather {
    pub temperature_c: f64,
    pub relative_humidity: f64,
    pub altitude_m: Option<f64>,
    pub pressure_pa: Option<f64>,
}

/// Power-law wind profile (then `wind_mps` is the wind at the reference height).
#[derive(Debug, Clone, Copy, Deserialize)]
#[allow(missing_docs)]
pub struct GoldenProfile {
    pub reference_height_m: f64,
    pub exponent: f64,
}

/// The scene as the file states it.
#[derive(Debug, Clone, Copy, Deserialize)]
#[allow(missing_docs)]
pub struct GoldenScene {
    pub landing_height_m: f64,
    pub effects: GoldenEffects,
    pub air_density_kgm3: Option<f64>,
    pub weather: Option<GoldenWeather>,
    pub wind_mps: [f64; 3],
    pub wind_profile: Option<GoldenProfile>,
}

/// Expected results.
#[derive(Debug, Clone, Copy, Deserialize)]
#[allow(missing_docs)]
pub struct FlightExpected {
    pub carry_m: f64,
    pub carry_x_m: f64,
    pub side_m: f64,
    pub flight_time_s: f64,
    pub apex_m: f64,
    pub apex_time_s: f64,
    pub land_angle_deg: f64,
    pub land_spin_rpm: f64,
    pub land_speed_mps: f64,
    pub air_density_kgm3: f64,
}

/// Loads `tests/golden/flight.json`.
///
/// # Panics
/// When the file is missing or malformed (a broken test setup).
#[must_use]
pub fn load() -> FlightGolden {
    let text =
        std::fs::read_to_string(crate::golden::path("flight.json")).expect("flight.json readable");
    serde_json::from_str(&text).expect("flight.json matches the schema")
}

impl GoldenLaunch {
    /// The launch in SI, precision `T`.
    #[must_use]
    pub fn to_launch<T: Real>(&self) -> Launch<T> {
        Launch {
            ball_speed_mps: lit(self.ball_speed_mps),
            launch_angle_rad: deg(lit(self.launch_angle_deg)),
            launch_direction_rad: deg(lit(self.launch_direction_deg)),
            backspin_radps: rpm(lit(self.backspin_rpm)),
            sidespin_radps: rpm(lit(self.sidespin_rpm)),
        }
    }
}

impl GoldenScene {
    /// The core scene, precision `T`.
    ///
    /// # Panics
    /// When the scene states neither a density nor weather.
    #[must_use]
    pub fn to_scene<T: Real>(&self) -> Scene<T> {
        let air = match (self.air_density_kgm3, self.weather) {
            (_, Some(w)) => Air::Weather(Weather {
                temperature_c: lit(w.temperature_c),
                relative_humidity: lit(w.relative_humidity),
                pressure: match (w.pressure_pa, w.altitude_m) {
                    (Some(p), _) => Pressure::Pa(lit(p)),
                    (None, Some(h)) => Pressure::Altitude(lit(h)),
                    (None, None) => Pressure::Altitude(T::zero()),
                },
            }),
            (Some(rho), None) => Air::Density(lit(rho)),
            (None, None) => panic!("scene without air"),
        };
        let w = Vector3::new(
            lit(self.wind_mps[0]),
            lit(self.wind_mps[1]),
            lit(self.wind_mps[2]),
        );
        let wind = match self.wind_profile {
            Some(p) => Wind::Profile {
                reference_mps: w,
                reference_height_m: lit(p.reference_height_m),
                exponent: lit(p.exponent),
            },
            None if w == Vector3::zeros() => Wind::None,
            None => Wind::Uniform(w),
        };
        Scene {
            // The golden files pin the seed's aerodynamics.
            aero: AeroModel::quintavalla(),
            effects: Effects {
                drag: self.effects.drag,
                lift: self.effects.lift,
                spin_decay: self.effects.spin_decay,
            },
            air,
            wind,
            landing_height_m: lit(self.landing_height_m),
            ..Scene::default()
        }
    }
}
