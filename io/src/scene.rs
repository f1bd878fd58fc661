//! Scene building: the scene options (or a `--scene` TOML file) → a core [`Scene`].
//!
//! Rules (documented in `--help`):
//! - `--air-density` fixes the density; otherwise any of `--temperature`, `--humidity`,
//!   `--pressure`, `--altitude` selects weather (defaults 15 °C, 0 %, sea level), and
//!   `--pressure` and `--altitude` exclude each other. Neither: 1.225 kg/m³.
//! - `--wind x,y,z` is a uniform wind; with `--wind-reference-height` or `--wind-exponent`
//!   it becomes the wind at that height of a power-law profile. `--wind-speed` +
//!   `--wind-direction` (the direction it blows towards, degrees from downrange towards
//!   the right) is always a profile (default 10 m, exponent 1/7), as PHYSICS.md specifies.

use crate::error::InputError;
use crate::params::{Key, Kind, Params, SceneParams, Value};
use crate::units::Units;
use carry_core::aero::AeroModel;
use carry_core::air::{Pressure, Weather};
use carry_core::real::lit;
use carry_core::units::deg;
use carry_core::wind::{DEFAULT_EXPONENT, DEFAULT_REFERENCE_HEIGHT_M};
use carry_core::{Air, Effects, Real, Scene, Wind};
use nalgebra::Vector3;
use std::path::Path;

/// Default temperature when weather is given without one (°C): the standard atmosphere.
pub const DEFAULT_TEMPERATURE_C: f64 = 15.0;

/// The keys a scene file may hold.
pub const SCENE_KEYS: &[Key] = &[
    Key::AirDensity,
    Key::Temperature,
    Key::Humidity,
    Key::Pressure,
    Key::Altitude,
    Key::Wind,
    Key::WindX,
    Key::WindY,
    Key::WindZ,
    Key::WindSpeed,
    Key::WindDirection,
    Key::WindReferenceHeight,
    Key::WindExponent,
    Key::LandingHeight,
    Key::TeeHeight,
    Key::TimeLimit,
    Key::NoDrag,
    Key::NoLift,
    Key::NoSpinDecay,
    Key::Aero,
    Key::Ground,
    Key::Stimp,
    Key::GroundSlope,
    Key::GroundSlopeDirection,
    Key::GroundRestitution,
    Key::GroundFriction,
    Key::RollingResistance,
    Key::CraterScale,
    Key::GrassHeight,
];

fn v3<T: Real>(v: [f64; 3]) -> Vector3<T> {
    Vector3::new(lit(v[0]), lit(v[1]), lit(v[2]))
}

/// The air of the scene options: a fixed density, the weather (defaults 15 °C, 0 %, sea
/// level), or standard air. Also the per-row conditions of `carry fit`.
///
/// # Errors
/// Both a density and weather, or both a pressure and an altitude.
pub fn air<T: Real>(s: &SceneParams) -> Result<Air<T>, InputError> {
    let weather_given = s.temperature_c.is_some()
        || s.humidity_pct.is_some()
        || s.pressure_pa.is_some()
        || s.altitude_m.is_some();
    Ok(match (s.air_density_kgm3, weather_given) {
        (Some(_), true) => {
            return Err(InputError::new(
                "air_density",
                "give either the air density or the weather (temperature, humidity, pressure/altitude), not both",
            ));
        }
        (Some(rho), false) => Air::Density(lit(rho)),
        (None, false) => Air::default(),
        (None, true) => {
            let pressure = match (s.pressure_pa, s.altitude_m) {
                (Some(_), Some(_)) => {
                    return Err(InputError::new(
                        "pressure",
                        "give either the pressure or the altitude, not both",
                    ));
                }
                (Some(p), None) => Pressure::Pa(lit(p)),
                (None, h) => Pressure::Altitude(lit(h.unwrap_or(0.0))),
            };
            Air::Weather(Weather {
                temperature_c: lit(s.temperature_c.unwrap_or(DEFAULT_TEMPERATURE_C)),
                relative_humidity: lit(s.humidity_pct.unwrap_or(0.0) / 100.0),
                pressure,
            })
        }
    })
}

/// Resolves the scene options into a core scene in precision `T` (the core validates the
/// values themselves when the flight prepares it).
///
/// # Errors
/// Conflicting options, or a wind speed that is negative.
pub fn build<T: Real>(s: &SceneParams) -> Result<Scene<T>, InputError> {
    let air = air(s)?;
    let profile_given = s.wind_reference_height_m.is_some() || s.wind_exponent.is_some();
    let polar_given = s.wind_speed_mps.is_some() || s.wind_direction_deg.is_some();
    let profile = |reference_mps: Vector3<T>| Wind::Profile {
        reference_mps,
        reference_height_m: lit(s
            .wind_reference_height_m
            .unwrap_or(DEFAULT_REFERENCE_HEIGHT_M)),
        exponent: lit(s.wind_exponent.unwrap_or(DEFAULT_EXPONENT)),
    };
    let wind = match (s.wind_mps, polar_given) {
        (Some(_), true) => {
            return Err(InputError::new(
                "wind",
                "give either the wind vector or the wind speed and direction, not both",
            ));
        }
        (Some(w), false) if profile_given => profile(v3(w)),
        (Some(w), false) => Wind::Uniform(v3(w)),
        (None, true) => {
            let speed = s.wind_speed_mps.unwrap_or(0.0);
            if speed < 0.0 {
                return Err(InputError::new("wind_speed", "must not be negative"));
            }
            let (sin, cos) = deg(lit::<T>(s.wind_direction_deg.unwrap_or(0.0))).sin_cos();
            let speed: T = lit(speed);
            profile(Vector3::new(cos * speed, T::zero(), sin * speed))
        }
        (None, false) if profile_given => {
            return Err(InputError::new(
                if s.wind_exponent.is_some() {
                    "wind_exponent"
                } else {
                    "wind_reference_height"
                },
                "a wind profile needs a wind (--wind or --wind-speed)",
            ));
        }
        (None, false) => Wind::None,
    };
    let mut scene = Scene {
        aero: s.aero.map_or_else(AeroModel::default, |m| m.cast()),
        effects: Effects {
            drag: !s.no_drag,
            lift: !s.no_lift,
            spin_decay: !s.no_spin_decay,
        },
        air,
        wind,
        ..Scene::default()
    };
    if let Some(h) = s.landing_height_m {
        scene.landing_height_m = lit(h);
    }
    if let Some(h) = s.tee_height_m {
        if !(h >= 0.0) {
            return Err(InputError::new(
                "tee_height",
                "must not be negative (the ball starts on or above the turf)",
            ));
        }
        scene.launch_position_m.y = lit(h);
    }
    if let Some(t) = s.time_limit_s {
        scene.time_limit_s = lit(t);
    }
    scene.ground = crate::ground::build(&s.ground)?;
    Ok(scene)
}

/// Reads a scene file (TOML, keys = the scene options in snake_case, values in `units`)
/// into `params`.
///
/// # Errors
/// An [`InputError`] on `--scene` for an unreadable file, bad TOML or an unknown key; on
/// the key for a bad value.
pub fn load_file(path: &Path, units: Units, params: &mut Params) -> Result<(), InputError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| InputError::new("scene", format!("cannot read {}: {e}", path.display())))?;
    let table: toml::Table = text.parse().map_err(|e: toml::de::Error| {
        let msg = e.message().replace('\n', " ");
        InputError::new(
            "scene",
            format!("{}: not valid TOML: {}", path.display(), msg.trim()),
        )
    })?;
    for (name, value) in &table {
        let key = Key::find(name)
            .filter(|k| SCENE_KEYS.contains(k))
            .ok_or_else(|| {
                let names: Vec<&str> = SCENE_KEYS.iter().map(|k| k.name()).collect();
                InputError::new(
                    "scene",
                    format!(
                        "{}: unknown key '{name}' (keys: {})",
                        path.display(),
                        names.join(", ")
                    ),
                )
            })?;
        let bad =
            |what: &str| InputError::new(key.name(), format!("in {}: {what}", path.display()));
        let number = |v: &toml::Value| -> Result<f64, InputError> {
            let x = match v {
                toml::Value::Float(x) => *x,
                #[allow(clippy::cast_precision_loss)]
                toml::Value::Integer(i) => *i as f64,
                _ => return Err(bad("must be a number")),
            };
            if x.is_finite() {
                Ok(x)
            } else {
                Err(bad("is not a finite number"))
            }
        };
        let parsed = match (key.kind(), value) {
            (Kind::Aero, toml::Value::String(name)) => {
                // A model file named relative to the scene file.
                let relative = path.parent().map(|d| d.join(name));
                let name = match relative {
                    Some(r) if AeroModel::<f64>::named(name).is_none() && r.exists() => {
                        r.display().to_string()
                    }
                    _ => name.clone(),
                };
                key.parse(&name)?
            }
            (Kind::Aero, _) => return Err(bad("must be a model name or a file path (a string)")),
            (Kind::Bool, toml::Value::Boolean(b)) => Value::Bool(*b),
            (Kind::Bool, _) => return Err(bad("must be true or false")),
            (Kind::Vector, toml::Value::Array(a)) if a.len() == 3 => {
                Value::Vector([number(&a[0])?, number(&a[1])?, number(&a[2])?])
            }
            (Kind::Vector, _) => return Err(bad("must be an array of three numbers [x, y, z]")),
            (Kind::Ground, toml::Value::String(t)) => {
                Value::Ground(crate::ground::parse(t).map_err(|e| bad(&e))?)
            }
            (Kind::Ground, toml::Value::Table(t)) => {
                Value::Ground(crate::ground::from_table(t).map_err(|e| bad(&e))?)
            }
            (Kind::Ground, _) => return Err(bad("must be a surface name or a table")),
            (Kind::Convention, toml::Value::String(t)) => key.parse(t)?,
            (_, v) => Value::Number(number(v)?),
        };
        key.set(params, units, parsed);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conflicts_and_defaults() {
        let s = SceneParams {
            air_density_kgm3: Some(1.2),
            temperature_c: Some(20.0),
            ..SceneParams::default()
        };
        assert_eq!(
            build::<f64>(&s).map(|_| ()).map_err(|e| e.key),
            Err("air_density")
        );
        let s = SceneParams {
            wind_speed_mps: Some(5.0),
            wind_direction_deg: Some(90.0),
            ..SceneParams::default()
        };
        let Ok(scene) = build::<f64>(&s) else {
            panic!()
        };
        let Wind::Profile { reference_mps, .. } = scene.wind else {
            panic!()
        };
        assert!((reference_mps.z - 5.0).abs() < 1e-12 && reference_mps.x.abs() < 1e-12);
    }
}
