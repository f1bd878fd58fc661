//! The measured data of ../shared/data (read, never edited), as fit rows.

use carry_core::air::{Pressure, Weather};
use carry_core::units::{deg, rpm};
use carry_core::{Air, Launch};
use carry_lab::fit::flight::ShotRow;
use std::path::PathBuf;

/// 1 mph in m/s.
pub const MPH: f64 = 0.447_04;
/// 1 yd in m.
pub const YD: f64 = 0.9144;

/// The conditions the data README prescribes: 21.1 °C, 50 % RH, 101 325 Pa.
pub fn fitting_air() -> Air<f64> {
    Air::Weather(Weather {
        temperature_c: 21.1,
        relative_humidity: 0.5,
        pressure: Pressure::Pa(101_325.0),
    })
}

/// `../shared/data/<name>` from the workspace root.
pub fn shared_data(name: &str) -> Option<PathBuf> {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../shared/data")
        .join(name);
    p.exists().then_some(p)
}

/// The 23 rows of trackman_tour_2023.csv, or `None` where ../shared is absent.
pub fn tour_2023() -> Option<Vec<ShotRow>> {
    let text = std::fs::read_to_string(shared_data("trackman_tour_2023.csv")?).ok()?;
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next()?.split(',').collect();
    let col = |n: &str| header.iter().position(|h| *h == n);
    let (tour, club, bs, la, spin, apex, land, carry) = (
        col("tour")?,
        col("club")?,
        col("ball_speed_mph")?,
        col("launch_deg")?,
        col("spin_rpm")?,
        col("max_height_yd")?,
        col("land_deg")?,
        col("carry_yd")?,
    );
    lines
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            let x = |i: usize| f.get(i)?.trim().parse::<f64>().ok();
            Some(ShotRow {
                label: format!("{} {}", f.get(tour)?, f.get(club)?),
                launch: Launch {
                    ball_speed_mps: x(bs)? * MPH,
                    launch_angle_rad: deg(x(la)?),
                    launch_direction_rad: 0.0,
                    backspin_radps: rpm(x(spin)?),
                    sidespin_radps: 0.0,
                },
                air: fitting_air(),
                carry_m: x(carry)? * YD,
                apex_m: Some(x(apex)? * YD),
                land_angle_deg: Some(x(land)?),
                flight_time_s: None,
                side_m: None,
                weight: 1.0,
                wind_mps: [0.0; 3],
                session: None,
            })
        })
        .collect()
}

/// The 30 rows of trackman_driver_optimizer_2010.csv (carry only; read by the lab's
/// chart reader), or `None` where ../shared is absent. Labelled by club speed and attack angle.
pub fn optimizer_2010() -> Option<Vec<ShotRow>> {
    let text = std::fs::read_to_string(shared_data("trackman_driver_optimizer_2010.csv")?).ok()?;
    let rows = carry_lab::ground_fit::parse_chart(&text).ok()?;
    Some(
        rows.into_iter()
            .map(|r| ShotRow {
                label: format!("{} mph {:+}°", r.club_speed_mph, r.attack_deg),
                launch: r.launch,
                air: fitting_air(),
                carry_m: r.carry_yd * YD,
                apex_m: None,
                land_angle_deg: None,
                flight_time_s: None,
                side_m: None,
                weight: 1.0,
                wind_mps: [0.0; 3],
                session: None,
            })
            .collect(),
    )
}
