//! The study's fixed, documented shot set (docs/accuracy.md lists it).
//!
//! Three parts, all embedded in the binary (`carry-golden`, the one golden-file reader, embeds
//! the golden files at compile time):
//!
//! * the 21 launches of `tests/golden/flight.json` with their scenes (driver to chip,
//!   slice and hook axes, head-, tail- and crosswind, a wind profile, altitude and cold
//!   weather, up- and downhill landings, no-lift / no-decay / vacuum / knuckleball
//!   variants): they enter the study *at the launch*, so the impact solver does not apply;
//! * the 19 valid deliveries of `tests/golden/impact.json` (driver strikes all over the
//!   face, face/path, attack, lie, club spin, restitution, CG, inertia, 7-iron, 58° wedge),
//!   flown in the default scene;
//! * 12 full shots of our own (3-wood, 5-iron, 7-iron into a headwind, wedges, a chip, a
//!   slice and a hook, a crosswind profile, altitude, downhill with a tailwind).

use carry_core::aero::AeroModel;
use carry_core::air::{Air, Pressure, Weather};
use carry_core::real::lit;
use carry_core::units::{deg, rpm};
use carry_core::{
    Ball, ClubHead, ClubSpec, ContactLaw, Delivery, Effects, FaceLocation, Launch, PRESETS,
    PreparedScene, Real, Scene, Wind,
};
use nalgebra::{Matrix3, Vector3};

/// The scene of a shot, in `f64`.
#[derive(Debug, Clone, Copy)]
pub struct SceneSpec {
    /// The aerodynamic model: the seed's for the golden flights (they pin it), the study's
    /// chosen model for the rest ([`shot_set`]).
    pub aero: AeroModel<f64>,
    pub effects: Effects,
    pub air: Air<f64>,
    pub wind: Wind<f64>,
    pub landing_height_m: f64,
}

impl Default for SceneSpec {
    fn default() -> Self {
        Self {
            aero: AeroModel::quintavalla(),
            effects: Effects::ALL,
            air: Air::default(),
            wind: Wind::None,
            landing_height_m: 0.0,
        }
    }
}

fn v3<T: Real>(v: &Vector3<f64>) -> Vector3<T> {
    v.map(lit)
}

impl SceneSpec {
    /// The core scene in precision `T`.
    pub fn to<T: Real>(&self) -> Scene<T> {
        let air = match self.air {
            Air::Density(r) => Air::Density(lit(r)),
            Air::Weather(w) => Air::Weather(Weather {
                temperature_c: lit(w.temperature_c),
                relative_humidity: lit(w.relative_humidity),
                pressure: match w.pressure {
                    Pressure::Pa(p) => Pressure::Pa(lit(p)),
                    Pressure::Altitude(h) => Pressure::Altitude(lit(h)),
                },
            }),
        };
        let wind = match self.wind {
            Wind::None => Wind::None,
            Wind::Uniform(w) => Wind::Uniform(v3(&w)),
            Wind::Profile {
                reference_mps,
                reference_height_m,
                exponent,
            } => Wind::Profile {
                reference_mps: v3(&reference_mps),
                reference_height_m: lit(reference_height_m),
                exponent: lit(exponent),
            },
        };
        Scene {
            aero: self.aero.cast(),
            effects: self.effects,
            air,
            wind,
            landing_height_m: lit(self.landing_height_m),
            ..Scene::default()
        }
    }

    /// A short description for the shot list.
    pub fn describe(&self) -> String {
        let mut parts = Vec::new();
        if self.effects != Effects::ALL {
            let e = self.effects;
            parts.push(format!(
                "effects drag={} lift={} decay={}",
                e.drag, e.lift, e.spin_decay
            ));
        }
        match self.air {
            Air::Density(r) if (r - 1.225).abs() > 1e-12 => parts.push(format!("ρ {r} kg/m³")),
            Air::Density(_) => {}
            Air::Weather(w) => parts.push(match w.pressure {
                Pressure::Pa(p) => format!(
                    "{} °C, {:.0} % RH, {p} Pa",
                    w.temperature_c,
                    w.relative_humidity * 100.0
                ),
                Pressure::Altitude(h) => format!(
                    "{} °C, {:.0} % RH, {h} m altitude",
                    w.temperature_c,
                    w.relative_humidity * 100.0
                ),
            }),
        }
        match self.wind {
            Wind::None => {}
            Wind::Uniform(w) => parts.push(format!("wind ({}, {}, {}) m/s", w.x, w.y, w.z)),
            Wind::Profile {
                reference_mps: w,
                reference_height_m: h,
                ..
            } => parts.push(format!(
                "wind profile ({}, {}, {}) m/s at {h} m",
                w.x, w.y, w.z
            )),
        }
        if self.landing_height_m != 0.0 {
            parts.push(format!("landing {:+} m", self.landing_height_m));
        }
        if parts.is_empty() {
            "standard air, no wind".to_owned()
        } else {
            parts.join(", ")
        }
    }
}

/// Where a shot starts.
#[derive(Debug, Clone, Copy)]
#[allow(clippy::large_enum_variant)] // a few dozen, built once
pub enum Start {
    /// A launch-monitor launch: flight only.
    Launch(Launch<f64>),
    /// A club delivery: impact, then flight.
    Delivery {
        club: ClubSpec<f64>,
        delivery: Delivery<f64>,
        ball_mass_kg: f64,
        ball_radius_m: f64,
    },
}

/// Where a shot comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Origin {
    /// `tests/golden/flight.json`.
    GoldenFlight,
    /// `tests/golden/impact.json`.
    GoldenImpact,
    /// Defined here.
    Study,
}

/// The golden file's expected values for a shot.
#[derive(Debug, Clone, Copy)]
pub enum Golden {
    /// Flight metrics (m, s, degrees).
    Flight {
        carry_m: f64,
        side_m: f64,
        apex_m: f64,
        flight_time_s: f64,
        land_angle_deg: f64,
    },
    /// Launch metrics (m/s, degrees, rpm).
    Impact {
        ball_speed_mps: f64,
        launch_angle_deg: f64,
        spin_rpm: f64,
        spin_axis_deg: f64,
    },
}

/// One shot of the set.
#[derive(Debug, Clone)]
pub struct Shot {
    pub name: String,
    /// Club class: driver, wood, iron, wedge, chip, … (for the report).
    pub class: &'static str,
    pub origin: Origin,
    pub start: Start,
    pub scene: SceneSpec,
    pub golden: Option<Golden>,
}

impl Shot {
    /// A short description of the start (launch or delivery).
    pub fn describe_start(&self) -> String {
        match &self.start {
            Start::Launch(l) => format!(
                "launch {:.1} m/s, {:.1}°, dir {:+.1}°, back {:.0} rpm, side {:+.0} rpm",
                l.ball_speed_mps,
                l.launch_angle_rad.to_degrees(),
                l.launch_direction_rad.to_degrees(),
                l.backspin_radps * 60.0 / core::f64::consts::TAU,
                l.sidespin_radps * 60.0 / core::f64::consts::TAU,
            ),
            Start::Delivery {
                club, delivery: d, ..
            } => format!(
                "{:.1}° head {:.0} g, {:.1} m/s, attack {:+.1}°, path {:+.1}°, face {:+.1}°, loft {:.1}°, at ({:+.0}, {:+.0}) mm",
                club.loft_rad.to_degrees(),
                club.mass_kg * 1000.0,
                d.club_speed_mps,
                d.attack_angle_rad.to_degrees(),
                d.club_path_rad.to_degrees(),
                d.face_angle_rad.to_degrees(),
                d.dynamic_loft_rad.to_degrees(),
                d.location.height_m * 1000.0,
                d.location.toe_m * 1000.0,
            ),
        }
    }
}

/// A shot in precision `T`, validated once (club head, ball and scene are session
/// constants for a launch monitor, as in the firmware's cost figures; the timed work is
/// strike → impact → launch metrics → flight, `carry_core::shot::play`).
#[derive(Debug, Clone, Copy)]
pub struct Prepared<T: Real> {
    pub ball: Ball<T>,
    pub scene: PreparedScene<T>,
    pub start: PreparedStart<T>,
}

/// The start of a prepared shot.
#[derive(Debug, Clone, Copy)]
pub enum PreparedStart<T: Real> {
    Launch(Launch<T>),
    Delivery {
        head: ClubHead<T>,
        delivery: Delivery<T>,
    },
}

impl Shot {
    /// The shot in precision `T`.
    ///
    /// # Errors
    /// An invalid club or ball (a bug in the set).
    pub fn prepare<T: Real>(&self) -> Result<Prepared<T>, String> {
        let fail = |e: carry_core::Error| format!("shot {}: {e}", self.name);
        let scene = self.scene.to::<T>();
        Ok(match &self.start {
            Start::Launch(l) => Prepared {
                ball: Ball::standard(),
                scene: scene.prepare(&Ball::standard()).map_err(fail)?,
                start: PreparedStart::Launch(Launch {
                    ball_speed_mps: lit(l.ball_speed_mps),
                    launch_angle_rad: lit(l.launch_angle_rad),
                    launch_direction_rad: lit(l.launch_direction_rad),
                    backspin_radps: lit(l.backspin_radps),
                    sidespin_radps: lit(l.sidespin_radps),
                }),
            },
            Start::Delivery {
                club,
                delivery: d,
                ball_mass_kg,
                ball_radius_m,
            } => {
                let spec = ClubSpec::<T> {
                    mass_kg: lit(club.mass_kg),
                    inertia_kgm2: club.inertia_kgm2.map(lit),
                    loft_rad: lit(club.loft_rad),
                    roll_radius_m: lit(club.roll_radius_m),
                    bulge_radius_m: lit(club.bulge_radius_m),
                    face_depth_radius_m: club.face_depth_radius_m.map(lit),
                    cg_to_face_m: v3(&club.cg_to_face_m),
                    restitution: lit(club.restitution),
                    contact: club.contact.cast(),
                    spin_axis_share: lit(club.spin_axis_share),
                };
                let delivery = Delivery::<T> {
                    club_speed_mps: lit(d.club_speed_mps),
                    attack_angle_rad: lit(d.attack_angle_rad),
                    club_path_rad: lit(d.club_path_rad),
                    face_angle_rad: lit(d.face_angle_rad),
                    dynamic_loft_rad: lit(d.dynamic_loft_rad),
                    lie_rad: lit(d.lie_rad),
                    club_spin_radps: v3(&d.club_spin_radps),
                    location: FaceLocation {
                        height_m: lit(d.location.height_m),
                        toe_m: lit(d.location.toe_m),
                    },
                };
                let ball = Ball::new(lit(*ball_mass_kg), lit(*ball_radius_m)).map_err(fail)?;
                Prepared {
                    ball,
                    scene: scene.prepare(&ball).map_err(fail)?,
                    start: PreparedStart::Delivery {
                        head: spec.validate().map_err(fail)?,
                        delivery,
                    },
                }
            }
        })
    }
}

// ------------------------------------------------------------------ golden files

fn class_of(name: &str) -> &'static str {
    if name.contains("chip") {
        "chip"
    } else if name.contains("7iron") || name.contains("iron7") {
        "iron"
    } else if name.contains("pw") || name.contains("wedge") {
        "wedge"
    } else if name.contains("driver") || name.contains("drive") {
        "driver"
    } else {
        "other"
    }
}

fn golden_flights() -> Result<Vec<Shot>, String> {
    let cases = carry_golden::flight_cases().map_err(|e| e.to_string())?;
    let mut out = Vec::new();
    for c in cases {
        let launch = c.launch.to_launch::<f64>();
        let air = c
            .scene
            .air()
            .ok_or_else(|| format!("{}: the scene states no air", c.name))?;
        let x = &c.expected;
        let speed = launch.ball_speed_mps;
        out.push(Shot {
            class: if class_of(&c.name) != "other" {
                class_of(&c.name)
            } else if speed >= 60.0 {
                "driver"
            } else if speed >= 40.0 && launch.launch_angle_rad < deg(45.0) {
                "iron"
            } else if speed >= 20.0 {
                "wedge"
            } else {
                "chip"
            },
            origin: Origin::GoldenFlight,
            start: Start::Launch(launch),
            scene: SceneSpec {
                aero: AeroModel::quintavalla(),
                effects: c.scene.effects(),
                air,
                wind: c.scene.wind(),
                landing_height_m: c.scene.landing_height_m,
            },
            golden: Some(Golden::Flight {
                carry_m: x.carry_m,
                side_m: x.side_m,
                apex_m: x.apex_m,
                flight_time_s: x.flight_time_s,
                land_angle_deg: x.land_angle_deg,
            }),
            name: c.name,
        });
    }
    Ok(out)
}

fn golden_impacts() -> Result<Vec<Shot>, String> {
    let cases = carry_golden::impact_cases().map_err(|e| e.to_string())?;
    let mut out = Vec::new();
    for c in cases {
        let Some(x) = c.expected else {
            continue; // an error case
        };
        out.push(Shot {
            class: class_of(&c.name),
            origin: Origin::GoldenImpact,
            start: Start::Delivery {
                club: c.club_spec(),
                delivery: c.delivery.to_delivery(),
                ball_mass_kg: c.ball.mass_kg,
                ball_radius_m: c.ball.radius_m,
            },
            scene: SceneSpec::default(),
            golden: Some(Golden::Impact {
                ball_speed_mps: x.ball_speed_mps,
                launch_angle_deg: x.launch_angle_deg,
                spin_rpm: x.spin_rpm,
                spin_axis_deg: x.spin_axis_deg,
            }),
            name: c.name,
        });
    }
    Ok(out)
}

// ------------------------------------------------------------------ our own shots

struct Own {
    name: &'static str,
    class: &'static str,
    club: ClubSpec<f64>,
    /// Club speed (m/s), attack, path, face, dynamic loft (deg), impact height, toe (mm).
    delivery: [f64; 7],
    scene: SceneSpec,
}

fn preset(name: &str) -> ClubSpec<f64> {
    PRESETS
        .iter()
        .find(|p| p.name == name)
        // the study compares numerics (both solvers): the seed's rolling contact
        .map_or_else(ClubSpec::driver, |p| ClubSpec {
            contact: ContactLaw::Rolling,
            ..p.spec()
        })
}

/// A 5-iron (estimate: 253 g, 27°, flat face), between the 3-wood and 7-iron presets.
fn five_iron() -> ClubSpec<f64> {
    ClubSpec {
        mass_kg: 0.253,
        inertia_kgm2: Matrix3::from_diagonal(&Vector3::new(1.1e-4, 2.6e-4, 6.0e-5)),
        loft_rad: deg(27.0),
        restitution: 0.81,
        ..preset("7iron")
    }
}

fn own_shots() -> Vec<Shot> {
    let weather = |t: f64, rh: f64, h: f64| {
        Air::Weather(Weather {
            temperature_c: t,
            relative_humidity: rh,
            pressure: Pressure::Altitude(h),
        })
    };
    let std = SceneSpec::default();
    let list = [
        Own {
            name: "study_driver_tour_up_attack",
            class: "driver",
            club: preset("driver"),
            delivery: [50.0, 3.0, 1.0, 0.5, 13.0, 3.0, 5.0],
            scene: std,
        },
        Own {
            name: "study_driver_slice",
            class: "driver",
            club: preset("driver"),
            delivery: [44.0, -1.0, -4.0, 3.0, 11.0, 0.0, -8.0],
            scene: std,
        },
        Own {
            name: "study_driver_hook",
            class: "driver",
            club: preset("driver"),
            delivery: [46.0, 1.0, 5.0, -1.0, 11.5, -2.0, 12.0],
            scene: std,
        },
        Own {
            name: "study_driver_altitude_1600m",
            class: "driver",
            club: preset("driver"),
            delivery: [47.0, 2.0, 0.0, 0.0, 12.0, 0.0, 0.0],
            scene: SceneSpec {
                air: weather(28.0, 0.25, 1600.0),
                ..std
            },
        },
        Own {
            name: "study_driver_crosswind_profile",
            class: "driver",
            club: preset("driver"),
            delivery: [45.0, 0.0, 0.0, 0.0, 10.5, 0.0, 0.0],
            scene: SceneSpec {
                wind: Wind::profile(Vector3::new(0.0, 0.0, 7.0)),
                ..std
            },
        },
        Own {
            name: "study_3wood_fairway",
            class: "wood",
            club: preset("3wood"),
            delivery: [43.0, -2.0, 0.0, 0.0, 14.0, -3.0, 0.0],
            scene: std,
        },
        Own {
            name: "study_5iron",
            class: "iron",
            club: five_iron(),
            delivery: [40.0, -3.5, 1.0, 0.0, 23.0, 0.0, 5.0],
            scene: std,
        },
        Own {
            name: "study_7iron_headwind_uphill",
            class: "iron",
            club: preset("7iron"),
            delivery: [37.0, -4.0, 0.0, 1.0, 30.0, -2.0, 0.0],
            scene: SceneSpec {
                wind: Wind::Uniform(Vector3::new(-5.0, 0.0, 1.5)),
                landing_height_m: 4.0,
                ..std
            },
        },
        Own {
            name: "study_pw_tailwind_downhill",
            class: "wedge",
            club: preset("pw"),
            delivery: [34.0, -5.0, 0.0, 0.0, 41.0, 0.0, 0.0],
            scene: SceneSpec {
                wind: Wind::Uniform(Vector3::new(4.0, 0.0, 0.0)),
                landing_height_m: -8.0,
                ..std
            },
        },
        Own {
            name: "study_lw58_pitch_cold",
            class: "wedge",
            club: preset("lw58"),
            delivery: [22.0, -4.0, -2.0, 2.0, 50.0, 3.0, 4.0],
            scene: SceneSpec {
                air: weather(4.0, 0.8, 0.0),
                ..std
            },
        },
        Own {
            name: "study_chip_lw58",
            class: "chip",
            club: preset("lw58"),
            delivery: [9.0, -3.0, 0.0, 0.0, 48.0, 0.0, 0.0],
            scene: std,
        },
        Own {
            name: "study_chip_pw_bump",
            class: "chip",
            club: preset("pw"),
            delivery: [8.0, -4.0, 0.0, 0.0, 38.0, -4.0, 0.0],
            scene: std,
        },
    ];
    list.into_iter()
        .map(|o| {
            let [v, attack, path, face, loft, height_mm, toe_mm] = o.delivery;
            Shot {
                name: o.name.to_owned(),
                class: o.class,
                origin: Origin::Study,
                start: Start::Delivery {
                    club: o.club,
                    delivery: Delivery {
                        club_speed_mps: v,
                        attack_angle_rad: deg(attack),
                        club_path_rad: deg(path),
                        face_angle_rad: deg(face),
                        dynamic_loft_rad: deg(loft),
                        lie_rad: 0.0,
                        club_spin_radps: Vector3::zeros(),
                        location: FaceLocation {
                            height_m: height_mm / 1000.0,
                            toe_m: toe_mm / 1000.0,
                        },
                    },
                    ball_mass_kg: Ball::<f64>::standard().mass_kg(),
                    ball_radius_m: Ball::<f64>::standard().radius_m(),
                },
                scene: o.scene,
                golden: None,
            }
        })
        .collect()
}

/// Names of the quick set (`--quick`): a driver, an iron, a wedge and a chip from each
/// part, plus the wind profile (the adaptive integrator's hardest case).
const QUICK: [&str; 8] = [
    "tour_driver_launch",
    "tour_7iron_launch",
    "chip_low_slow",
    "headwind_profile_8_at_10m",
    "driver_toe_20mm",
    "wedge_58_slow",
    "study_driver_slice",
    "study_5iron",
];

/// The shot set: everything, or the quick subset. The golden flights keep the seed's
/// aerodynamics (the golden files pin it); every other shot flies with `aero`.
///
/// # Errors
/// A malformed golden file (a build problem).
pub fn shot_set(quick: bool, aero: &AeroModel<f64>) -> Result<Vec<Shot>, String> {
    let mut all = golden_flights()?;
    let mut rest = golden_impacts()?;
    rest.extend(own_shots());
    for s in &mut rest {
        s.scene.aero = *aero;
    }
    all.extend(rest);
    if quick {
        all.retain(|s| QUICK.contains(&s.name.as_str()));
    }
    Ok(all)
}

/// Launches of increasing flight time for the scaling measurement: 45°, 2500 rpm, from a
/// 10 m/s chip to an 80 m/s drive, standard air.
pub fn scaling_launches(quick: bool) -> Vec<Launch<f64>> {
    let speeds: &[f64] = if quick {
        &[10.0, 40.0, 80.0]
    } else {
        &[8.0, 12.0, 18.0, 25.0, 35.0, 45.0, 55.0, 65.0, 80.0]
    };
    speeds
        .iter()
        .map(|&v| Launch {
            ball_speed_mps: v,
            launch_angle_rad: deg(30.0),
            launch_direction_rad: 0.0,
            backspin_radps: rpm(3000.0),
            sidespin_radps: 0.0,
        })
        .collect()
}
