//! The flight golden file: a launch and a scene per case, with the expected landing.

use crate::json::{Error, Fields, parse_cases};

/// The launch, in launch-monitor units.
#[derive(Debug, Clone, Copy, PartialEq)]
#[allow(missing_docs)]
pub struct Launch {
    pub ball_speed_mps: f64,
    pub launch_angle_deg: f64,
    pub launch_direction_deg: f64,
    pub backspin_rpm: f64,
    pub sidespin_rpm: f64,
}

/// The effects switched on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[allow(missing_docs)]
pub struct Effects {
    pub drag: bool,
    pub lift: bool,
    pub spin_decay: bool,
}

/// Weather: temperature, humidity, and a pressure or an altitude (or neither: sea level).
#[derive(Debug, Clone, Copy, PartialEq)]
#[allow(missing_docs)]
pub struct Weather {
    pub temperature_c: f64,
    pub relative_humidity: f64,
    pub pressure_pa: Option<f64>,
    pub altitude_m: Option<f64>,
}

/// A power-law wind profile: `wind_mps` is then the wind at the reference height.
#[derive(Debug, Clone, Copy, PartialEq)]
#[allow(missing_docs)]
pub struct WindProfile {
    pub reference_height_m: f64,
    pub exponent: f64,
}

/// The scene as the file states it: an air density or weather, wind, landing height.
#[derive(Debug, Clone, Copy, PartialEq)]
#[allow(missing_docs)]
pub struct Scene {
    pub landing_height_m: f64,
    pub effects: Effects,
    pub air_density_kgm3: Option<f64>,
    pub weather: Option<Weather>,
    pub wind_mps: [f64; 3],
    pub wind_profile: Option<WindProfile>,
}

/// The expected landing (SI, except degrees and rpm).
#[derive(Debug, Clone, Copy, PartialEq)]
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

/// One flight case.
#[derive(Debug, Clone, PartialEq)]
pub struct FlightCase {
    /// Case name.
    pub name: String,
    /// The launch.
    pub launch: Launch,
    /// The scene.
    pub scene: Scene,
    /// The reference result.
    pub expected: FlightExpected,
}

pub(crate) fn parse(text: &str) -> Result<Vec<FlightCase>, Error> {
    parse_cases(text, case)
}

fn case(c: &Fields<'_>) -> Result<FlightCase, Error> {
    let (l, s, e) = (
        c.object("launch")?,
        c.object("scene")?,
        c.object("expected")?,
    );
    let fx = s.object("effects")?;
    Ok(FlightCase {
        name: c.string("name")?,
        launch: Launch {
            ball_speed_mps: l.num("ball_speed_mps")?,
            launch_angle_deg: l.num("launch_angle_deg")?,
            launch_direction_deg: l.num("launch_direction_deg")?,
            backspin_rpm: l.num("backspin_rpm")?,
            sidespin_rpm: l.num("sidespin_rpm")?,
        },
        scene: Scene {
            landing_height_m: s.num("landing_height_m")?,
            effects: Effects {
                drag: fx.boolean("drag")?,
                lift: fx.boolean("lift")?,
                spin_decay: fx.boolean("spin_decay")?,
            },
            air_density_kgm3: s.optional_num("air_density_kgm3")?,
            weather: s
                .optional_object("weather")?
                .map(|w| -> Result<Weather, Error> {
                    Ok(Weather {
                        temperature_c: w.num("temperature_c")?,
                        relative_humidity: w.num("relative_humidity")?,
                        pressure_pa: w.optional_num("pressure_pa")?,
                        altitude_m: w.optional_num("altitude_m")?,
                    })
                })
                .transpose()?,
            wind_mps: s.vec3("wind_mps")?,
            wind_profile: s
                .optional_object("wind_profile")?
                .map(|p| -> Result<WindProfile, Error> {
                    Ok(WindProfile {
                        reference_height_m: p.num("reference_height_m")?,
                        exponent: p.num("exponent")?,
                    })
                })
                .transpose()?,
        },
        expected: FlightExpected {
            carry_m: e.num("carry_m")?,
            carry_x_m: e.num("carry_x_m")?,
            side_m: e.num("side_m")?,
            flight_time_s: e.num("flight_time_s")?,
            apex_m: e.num("apex_m")?,
            apex_time_s: e.num("apex_time_s")?,
            land_angle_deg: e.num("land_angle_deg")?,
            land_spin_rpm: e.num("land_spin_rpm")?,
            land_speed_mps: e.num("land_speed_mps")?,
            air_density_kgm3: e.num("air_density_kgm3")?,
        },
    })
}
