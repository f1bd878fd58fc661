//! The golden cases of `tests/golden/*.json` as the firmware's `cases.rs` holds them,
//! turned into the C API's input structs, and the C API's results flattened in the order
//! of `cases.rs` (so that they compare with the core's, bit for bit). Shared by the Rust
//! tests and the C firmware's generator (`examples/golden_c.rs`); both include
//! `firmware/src/cases.rs` as `crate::cases` and `firmware/src/golden_input.rs` (the cases
//! read by `carry-golden`, the one golden-file reader) as `crate::golden_input`.
#![allow(dead_code)]

use crate::cases::{FLIGHT_OUTPUTS, FlightInput, IMPACT_OUTPUTS, ImpactInput};
use carry_core::convention::DeliveryConvention;
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

/// Every impact case of `impact.json`.
pub fn impact_cases() -> Vec<ImpactCase> {
    let golden = carry_golden::impact_cases().unwrap_or_else(|e| panic!("{e}"));
    golden
        .iter()
        .map(|c| ImpactCase {
            name: c.name.clone(),
            input: crate::golden_input::impact_input(c),
        })
        .collect()
}

/// Every flight case of `flight.json`.
pub fn flight_cases() -> Vec<FlightCase> {
    let golden = carry_golden::flight_cases().unwrap_or_else(|e| panic!("{e}"));
    golden
        .iter()
        .map(|c| FlightCase {
            name: c.name.clone(),
            input: crate::golden_input::flight_input(c),
        })
        .collect()
}

/// The impact variants of the on-target suite (`cases::VARIANTS`) as C solver and
/// contact selectors: (name, solver, compliant, spin-axis share).
pub fn variants() -> [(&'static str, u32, bool, f64); crate::cases::VARIANTS.len()] {
    crate::cases::VARIANTS.map(|(name, solver, compliant, share)| {
        let s = match solver {
            Solver::Reduced => CARRY_SOLVER_REDUCED,
            Solver::Full(_) => CARRY_SOLVER_FULL,
        };
        (name, s, compliant, share)
    })
}

/// The C input of an impact case with a solver, (`compliant`) the presets' contact and the
/// club's spin-axis share.
pub fn impact_input<T: Real>(
    c: &ImpactInput,
    solver: u32,
    compliant: bool,
    spin_axis_share: f64,
) -> CarryImpactInput<T> {
    let mut spec = c.club::<T>();
    if compliant {
        spec.contact = FITTED_CONTACT.cast();
    }
    spec.spin_axis_share = carry_core::real::lit(spin_axis_share);
    let club = CarryClub::from_spec(&spec);
    debug_assert!(!compliant || club.contact == CARRY_CONTACT_COMPLIANT);
    let d = c.delivery::<T>();
    CarryImpactInput {
        club,
        ball: CarryBall {
            mass_kg: lit(c.ball_mass_kg),
            radius_m: lit(c.ball_radius_m),
        },
        delivery: CarryDelivery::from_delivery(&d, DeliveryConvention::SeedCentre),
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
    let golden = carry_golden::flight_cases().unwrap_or_else(|e| panic!("{e}"));
    golden
        .into_iter()
        .map(|c| (c.name, c.expected.carry_m))
        .collect()
}
