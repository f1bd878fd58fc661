//! The golden cases (read by `carry-golden`, the one golden-file reader) as the on-target
//! suite's inputs. Host only: `#[path]`-included, beside `cases.rs`, by `build.rs` and by the
//! C API's tests and C golden generator, so all of them hand the same inputs to the engine.

use crate::cases::{FlightInput, ImpactInput};

/// An impact case's input, as the file states it.
pub fn impact_input(c: &carry_golden::ImpactCase) -> ImpactInput {
    let (k, d) = (&c.club, &c.delivery);
    ImpactInput {
        club_mass_kg: k.mass_kg,
        inertia_kgm2: k.inertia_kgm2,
        loft_deg: k.loft_deg,
        roll_radius_m: k.roll_radius_m,
        bulge_radius_m: k.bulge_radius_m,
        face_depth_radius_m: k.face_depth_radius_m,
        cg_to_face_m: k.cg_to_face_m,
        ball_mass_kg: c.ball.mass_kg,
        ball_radius_m: c.ball.radius_m,
        club_speed_mps: d.club_speed_mps,
        attack_angle_deg: d.attack_angle_deg,
        club_path_deg: d.club_path_deg,
        face_angle_deg: d.face_angle_deg,
        dynamic_loft_deg: d.dynamic_loft_deg,
        lie_deg: d.lie_deg,
        club_spin_radps: d.club_spin_radps,
        impact_height_m: d.impact_height_m,
        impact_toe_m: d.impact_toe_m,
        cor: d.cor,
    }
}

/// A flight case's launch and scene, as the file states them.
pub fn flight_input(c: &carry_golden::FlightCase) -> FlightInput {
    let (l, s) = (&c.launch, &c.scene);
    FlightInput {
        ball_speed_mps: l.ball_speed_mps,
        launch_angle_deg: l.launch_angle_deg,
        launch_direction_deg: l.launch_direction_deg,
        backspin_rpm: l.backspin_rpm,
        sidespin_rpm: l.sidespin_rpm,
        landing_height_m: s.landing_height_m,
        drag: s.effects.drag,
        lift: s.effects.lift,
        spin_decay: s.effects.spin_decay,
        air_density_kgm3: s.air_density_kgm3,
        weather: s.weather.map(|w| {
            (
                w.temperature_c,
                w.relative_humidity,
                w.pressure_pa,
                w.altitude_m,
            )
        }),
        wind_mps: s.wind_mps,
        wind_profile: s.wind_profile.map(|p| (p.reference_height_m, p.exponent)),
    }
}
