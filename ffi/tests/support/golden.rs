//! The golden cases of `tests/golden/*.json` as the firmware's `cases.rs` holds them,
//! turned into the C API's input structs, and the C API's results flattened in the order
//! of `cases.rs` (so that they compare with the core's, bit for bit). Shared by the Rust
//! tests and the C firmware's generator (`examples/golden_c.rs`); both include
//! `firmware/src/cases.rs` as `crate::cases`.
#![allow(dead_code)]

use crate::cases::{FLIGHT_OUTPUTS, FlightInput, IMPACT_OUTPUTS, ImpactInput};
use carry_core::impact::Solver;
use carry_core::presets::FITTED_CONTACT;
use carry_core::real::{Real, lit};
use carry_core::{Integrator, Launch};
use carry_ffi::club::{CARRY_CONTACT_COMPLIANT, CarryClub};
use carry_ffi::flight::CarryLaunch;
use carry_ffi::scene::*;
use carry_ffi::settings::*;
use carry_ffi::{
    CarryBall, CarryDelivery, CarryFlightInput, CarryFlightResult, CarryImpactInput,
    CarryImpactResult,
};
use serde_json::Value;
use std::path::Path;

/// A named impact case.
pub struct ImpactCase {
    pub name: String,
    pub input: ImpactInput,
}

/// A named flight case.
pub struct FlightCase {
    pub name: String,
    pub input: FlightInput,
}

fn read_json(path: &Path) -> Value {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let quoted = text
        .replace("-Infinity", "\"-inf\"")
        .replace("Infinity", "\"inf\"")
        .replace("NaN", "\"nan\"");
    serde_json::from_str(&quoted).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn num(v: &Value) -> f64 {
    match v {
        Value::Number(n) => n.as_f64().unwrap_or(f64::NAN),
        Value::String(s) => s.parse().unwrap_or(f64::NAN),
        other => panic!("not a number: {other}"),
    }
}

fn opt(v: &Value, k: &str) -> Option<f64> {
    v.get(k).filter(|x| !x.is_null()).map(num)
}

fn vec3(v: &Value) -> [f64; 3] {
    [num(&v[0]), num(&v[1]), num(&v[2])]
}

/// The golden directory of the repository (`tests/golden`).
pub fn dir() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/golden")
}

/// Every impact case of `impact.json`.
pub fn impact_cases() -> Vec<ImpactCase> {
    let root = read_json(&dir().join("impact.json"));
    let cases = root["cases"].as_array().cloned().unwrap_or_default();
    cases
        .iter()
        .map(|c| {
            let (club, ball, d) = (&c["club"], &c["ball"], &c["delivery"]);
            let i = &club["inertia_kgm2"];
            ImpactCase {
                name: c["name"].as_str().unwrap_or("?").to_owned(),
                input: ImpactInput {
                    club_mass_kg: num(&club["mass_kg"]),
                    inertia_kgm2: [vec3(&i[0]), vec3(&i[1]), vec3(&i[2])],
                    loft_deg: num(&club["loft_deg"]),
                    roll_radius_m: num(&club["roll_radius_m"]),
                    bulge_radius_m: num(&club["bulge_radius_m"]),
                    face_depth_radius_m: opt(club, "ellipsoid_a_m"),
                    cg_to_face_m: vec3(&club["cg_to_face_m"]),
                    ball_mass_kg: num(&ball["mass_kg"]),
                    ball_radius_m: num(&ball["radius_m"]),
                    club_speed_mps: num(&d["club_speed_mps"]),
                    attack_angle_deg: num(&d["attack_angle_deg"]),
                    club_path_deg: num(&d["club_path_deg"]),
                    face_angle_deg: num(&d["face_angle_deg"]),
                    dynamic_loft_deg: num(&d["dynamic_loft_deg"]),
                    lie_deg: num(&d["lie_deg"]),
                    club_spin_radps: vec3(&d["club_spin_radps"]),
                    impact_height_m: num(&d["impact_height_m"]),
                    impact_toe_m: num(&d["impact_toe_m"]),
                    cor: num(&d["cor"]),
                },
            }
        })
        .collect()
}

/// Every flight case of `flight.json`.
pub fn flight_cases() -> Vec<FlightCase> {
    let root = read_json(&dir().join("flight.json"));
    let cases = root["cases"].as_array().cloned().unwrap_or_default();
    cases
        .iter()
        .map(|c| {
            let (l, s) = (&c["launch"], &c["scene"]);
            let weather = s.get("weather").filter(|w| !w.is_null()).map(|w| {
                (
                    num(&w["temperature_c"]),
                    num(&w["relative_humidity"]),
                    opt(w, "pressure_pa"),
                    opt(w, "altitude_m"),
                )
            });
            let profile = s
                .get("wind_profile")
                .filter(|p| !p.is_null())
                .map(|p| (num(&p["reference_height_m"]), num(&p["exponent"])));
            let effect = |k: &str| s["effects"][k].as_bool().unwrap_or(true);
            FlightCase {
                name: c["name"].as_str().unwrap_or("?").to_owned(),
                input: FlightInput {
                    ball_speed_mps: num(&l["ball_speed_mps"]),
                    launch_angle_deg: num(&l["launch_angle_deg"]),
                    launch_direction_deg: num(&l["launch_direction_deg"]),
                    backspin_rpm: num(&l["backspin_rpm"]),
                    sidespin_rpm: num(&l["sidespin_rpm"]),
                    landing_height_m: num(&s["landing_height_m"]),
                    drag: effect("drag"),
                    lift: effect("lift"),
                    spin_decay: effect("spin_decay"),
                    air_density_kgm3: opt(s, "air_density_kgm3"),
                    weather,
                    wind_mps: vec3(&s["wind_mps"]),
                    wind_profile: profile,
                },
            }
        })
        .collect()
}

/// The impact variants of the on-target suite (`cases::VARIANTS`) as C solver and
/// contact selectors: (name, solver, compliant).
pub fn variants() -> [(&'static str, u32, bool); 3] {
    crate::cases::VARIANTS.map(|(name, solver, compliant)| {
        let s = match solver {
            Solver::Reduced => CARRY_SOLVER_REDUCED,
            Solver::Full(_) => CARRY_SOLVER_FULL,
        };
        (name, s, compliant)
    })
}

/// The C input of an impact case with a solver and (`compliant`) the presets' contact.
pub fn impact_input<T: Real>(c: &ImpactInput, solver: u32, compliant: bool) -> CarryImpactInput<T> {
    let mut spec = c.club::<T>();
    if compliant {
        spec.contact = FITTED_CONTACT.cast();
    }
    let club = CarryClub::from_spec(&spec);
    debug_assert!(!compliant || club.contact == CARRY_CONTACT_COMPLIANT);
    let d = c.delivery::<T>();
    CarryImpactInput {
        club,
        ball: CarryBall {
            mass_kg: lit(c.ball_mass_kg),
            radius_m: lit(c.ball_radius_m),
        },
        delivery: CarryDelivery {
            club_speed_mps: d.club_speed_mps,
            attack_angle_rad: d.attack_angle_rad,
            club_path_rad: d.club_path_rad,
            face_angle_rad: d.face_angle_rad,
            dynamic_loft_rad: d.dynamic_loft_rad,
            lie_rad: d.lie_rad,
            club_spin_radps: d.club_spin_radps.into(),
            impact_height_m: d.location.height_m,
            impact_toe_m: d.location.toe_m,
            convention: carry_ffi::impact::CARRY_CONVENTION_SEED_CENTRE,
        },
        settings: CarrySettings {
            solver,
            ..CarrySettings::default()
        },
    }
}

/// The integrators of the on-target suite (`cases::integrators`) as C settings.
pub fn settings<T: Real>() -> Vec<(&'static str, CarrySettings<T>)> {
    crate::cases::integrators::<T>()
        .iter()
        .map(|(name, i)| (*name, c_settings(i)))
        .collect()
}

/// A core integrator as C settings.
pub fn c_settings<T: Real>(i: &Integrator<T>) -> CarrySettings<T> {
    let d = CarrySettings::<T>::default();
    match *i {
        Integrator::Euler { step_s } => CarrySettings {
            integrator: CARRY_INTEGRATOR_EULER,
            step_s,
            ..d
        },
        Integrator::Rk4 { step_s } => CarrySettings {
            integrator: CARRY_INTEGRATOR_RK4,
            step_s,
            ..d
        },
        Integrator::DormandPrince {
            rtol,
            atol,
            initial_step_s,
            max_step_s,
        } => CarrySettings {
            integrator: CARRY_INTEGRATOR_DP45,
            rtol,
            atol,
            initial_step_s,
            max_step_s,
            ..d
        },
    }
}

/// The C input of a flight case with `aero` (`CARRY_AERO_*`) and `settings`.
pub fn flight_input<T: Real>(
    c: &FlightInput,
    aero: u32,
    settings: CarrySettings<T>,
) -> CarryFlightInput<T> {
    let l: Launch<T> = c.launch();
    let mut scene = CarryScene::<T> {
        aero,
        drag: c.drag.into(),
        lift: c.lift.into(),
        spin_decay: c.spin_decay.into(),
        landing_height_m: lit(c.landing_height_m),
        ..CarryScene::default()
    };
    match (c.weather, c.air_density_kgm3) {
        (Some((t, rh, pa, alt)), _) => {
            scene.temperature_c = lit(t);
            scene.relative_humidity = lit(rh);
            match (pa, alt) {
                (Some(p), _) => {
                    scene.air = CARRY_AIR_WEATHER_PRESSURE;
                    scene.pressure_pa = lit(p);
                }
                (None, a) => {
                    scene.air = CARRY_AIR_WEATHER_ALTITUDE;
                    scene.altitude_m = lit(a.unwrap_or(0.0));
                }
            }
        }
        (None, rho) => {
            scene.air = CARRY_AIR_DENSITY;
            scene.air_density_kgm3 = lit(rho.unwrap_or(1.225));
        }
    }
    scene.wind_mps = c.wind_mps.map(lit);
    scene.wind = match c.wind_profile {
        Some((h, e)) => {
            scene.wind_reference_height_m = lit(h);
            scene.wind_exponent = lit(e);
            CARRY_WIND_PROFILE
        }
        None if c.wind_mps == [0.0; 3] => CARRY_WIND_NONE,
        None => CARRY_WIND_UNIFORM,
    };
    CarryFlightInput {
        launch: CarryLaunch {
            ball_speed_mps: l.ball_speed_mps,
            launch_angle_rad: l.launch_angle_rad,
            launch_direction_rad: l.launch_direction_rad,
            backspin_radps: l.backspin_radps,
            sidespin_radps: l.sidespin_radps,
        },
        scene,
        settings,
        ..CarryFlightInput::default()
    }
}

/// An impact result in the order of `cases::IMPACT_OUTPUTS`.
pub fn impact_outputs<T: Real>(r: &CarryImpactResult<T>) -> [T; IMPACT_OUTPUTS] {
    let mut out = [T::zero(); IMPACT_OUTPUTS];
    let vs = [
        r.ball_velocity_mps,
        r.ball_spin_radps,
        r.club_velocity_mps,
        r.club_spin_radps,
        r.impulse_ns,
    ];
    for (k, v) in vs.iter().enumerate() {
        out[3 * k..3 * k + 3].copy_from_slice(v);
    }
    out[15..].copy_from_slice(&[
        r.ball_speed_mps,
        r.launch_angle_rad,
        r.launch_direction_rad,
        r.spin_radps,
        r.backspin_radps,
        r.sidespin_radps,
        r.spin_axis_rad,
        r.smash_factor,
    ]);
    out
}

/// A flight result in the order of `cases::FLIGHT_OUTPUTS`.
pub fn flight_outputs<T: Real>(r: &CarryFlightResult<T>) -> [T; FLIGHT_OUTPUTS] {
    let n = |x: u32| -> T { lit(f64::from(x)) };
    [
        r.carry_m,
        r.carry_x_m,
        r.side_m,
        r.flight_time_s,
        r.apex_m,
        r.apex_time_s,
        r.landing_angle_rad,
        r.landing_speed_mps,
        r.landing_spin_radps,
        r.air_density_kgm3,
        n(r.force_evaluations),
        n(r.steps),
        n(r.rejected_steps),
    ]
}

/// The golden files' f64 reference carry of each flight case: (name, carry in m).
pub fn flight_reference() -> Vec<(String, f64)> {
    let root = read_json(&dir().join("flight.json"));
    let cases = root["cases"].as_array().cloned().unwrap_or_default();
    cases
        .iter()
        .map(|c| {
            let name = c["name"].as_str().unwrap_or("?").to_owned();
            (name, num(&c["expected"]["carry_m"]))
        })
        .collect()
}
