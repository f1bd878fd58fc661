//! The bag from delivery alone against TrackMan's 2023 tour averages (docs/impact.md §0.6):
//! each club with a preset, struck by the presets' contact law and flown in the data's
//! conditions (21.1 °C, 50 % RH, 101,325 Pa; the default aerodynamics).
//!
//! * **presets** — the `PGA` rows with the presets' typical deliveries: what `carry shot
//!   --club X` carries (the bag target of issue 22).
//! * **matched** — every row of a tour with its own club speed and attack angle and the
//!   dynamic loft at which the model launches at the row's launch angle (TrackMan's measured
//!   loft for the drivers, `club_delivery.csv`: PGA 12.8°, LPGA 15.5°); ball speed, spin and
//!   carry are then predictions. The PGA column of lofts is how the presets' typical lofts
//!   are chosen; the LPGA rows are a check at other speeds.
//!
//! `cargo run --release -p carry-lab --example bag_report [CONTACT.toml]`: optionally a
//! contact law (as `--contact` reads) instead of the presets'.
use carry_core::air::{Pressure, Weather};
use carry_core::impact::{self, ContactLaw, Solver};
use carry_core::presets::{GivenDelivery, Preset};
use carry_core::units::{deg, mph, to_deg, to_rpm};
use carry_core::{Air, Scene};
use carry_core::{Ball, DeliveryConvention, Integrator};

const TOUR: &str = include_str!("../../tests/data/trackman_tour_2023.csv");
const YARD_M: f64 = 0.9144;

/// One row of the tour table that has a preset.
struct Row {
    tour: String,
    preset: &'static Preset,
    club_speed_mps: f64,
    attack_deg: f64,
    ball_speed_mph: f64,
    launch_deg: f64,
    spin_rpm: f64,
    carry_yd: f64,
}

/// Ball speed (mph), launch (deg), spin (rpm) and carry (yd) of one delivery.
struct Shot {
    ball_speed_mph: f64,
    launch_deg: f64,
    spin_rpm: f64,
    carry_yd: f64,
}

fn rows() -> Result<Vec<Row>, String> {
    let mut lines = TOUR.lines();
    let header = carry_lab::columns::Header::of(lines.next().ok_or("empty table")?);
    let col = |name: &str| header.column(name);
    let (tour, club, speed, attack, ball, launch, spin, carry) = (
        col("tour")?,
        col("club")?,
        col("club_speed_mph")?,
        col("attack_deg")?,
        col("ball_speed_mph")?,
        col("launch_deg")?,
        col("spin_rpm")?,
        col("carry_yd")?,
    );
    let mut out = Vec::new();
    for line in lines {
        let f: Vec<&str> = line.split(',').collect();
        let num = |c: usize| -> Result<f64, String> {
            f.get(c)
                .and_then(|x| x.parse().ok())
                .ok_or(format!("{line}: column {c}"))
        };
        let Some(preset) = f.get(club).and_then(|n| Preset::find(n)) else {
            continue;
        };
        out.push(Row {
            tour: f.get(tour).copied().unwrap_or("").to_owned(),
            preset,
            club_speed_mps: mph(num(speed)?),
            attack_deg: num(attack)?,
            ball_speed_mph: num(ball)?,
            launch_deg: num(launch)?,
            spin_rpm: num(spin)?,
            carry_yd: num(carry)?,
        });
    }
    Ok(out)
}

/// Strikes and flies `preset` at the given club speed, attack and dynamic loft (the
/// named-club rule places the strike) with `contact`.
fn shoot(
    preset: &Preset,
    contact: &ContactLaw<f64>,
    given: &GivenDelivery<f64>,
    scene: &carry_core::scene::PreparedScene<f64>,
) -> Result<Shot, String> {
    let ball = Ball::standard();
    let club = carry_core::ClubSpec {
        contact: *contact,
        ..preset.spec::<f64>()
    }
    .validate()
    .map_err(|e| e.to_string())?;
    let delivery = preset.completed(given, ball.radius_m());
    let strike = delivery
        .strike_in(&club, DeliveryConvention::TrackMan)
        .map_err(|e| e.to_string())?;
    let out = impact::solve(&club, &ball, &strike, Solver::Reduced).map_err(|e| e.to_string())?;
    let flight = scene
        .fly(&out.ball, &Integrator::default(), None)
        .map_err(|e| e.to_string())?;
    Ok(Shot {
        ball_speed_mph: out.launch.ball_speed_mps / mph(1.0),
        launch_deg: to_deg(out.launch.launch_angle_rad),
        spin_rpm: to_rpm(out.launch.spin_radps),
        carry_yd: flight.carry_m / YARD_M,
    })
}

/// The dynamic loft (deg, to 0.1°) at which `row`'s delivery launches at its launch angle.
fn matched_loft(
    row: &Row,
    contact: &ContactLaw<f64>,
    scene: &carry_core::scene::PreparedScene<f64>,
) -> Result<f64, String> {
    let (mut lo, mut hi) = (2.0_f64, 60.0_f64);
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        let s = shoot(row.preset, contact, &given(row, mid), scene)?;
        if s.launch_deg < row.launch_deg {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok((5.0 * (lo + hi)).round() / 10.0)
}

fn given(row: &Row, loft_deg: f64) -> GivenDelivery<f64> {
    GivenDelivery {
        club_speed_mps: Some(row.club_speed_mps),
        attack_angle_rad: Some(deg(row.attack_deg)),
        dynamic_loft_rad: Some(deg(loft_deg)),
        impact_height_m: None,
    }
}

/// Prints one row and returns its relative (ball speed, spin, carry) errors.
fn print_row(name: &str, loft: f64, row: &Row, s: &Shot) -> [f64; 3] {
    let e = [
        s.ball_speed_mph / row.ball_speed_mph - 1.0,
        s.spin_rpm / row.spin_rpm - 1.0,
        s.carry_yd / row.carry_yd - 1.0,
    ];
    println!(
        "| {name} | {loft:.1} | {:.1} / {} ({:+.1} %) | {:.1} / {} | {:.0} / {} ({:+.0} %) | {:.1} / {} ({:+.1} %) |",
        s.ball_speed_mph,
        row.ball_speed_mph,
        100.0 * e[0],
        s.launch_deg,
        row.launch_deg,
        s.spin_rpm,
        row.spin_rpm,
        100.0 * e[1],
        s.carry_yd,
        row.carry_yd,
        100.0 * e[2]
    );
    e
}

fn table_head(title: &str) {
    println!("\n{title}\n");
    println!(
        "| club | dyn. loft ° | ball mph (err) | launch ° | spin rpm (err) | carry yd (err) |"
    );
    println!("|---|---:|---|---|---|---|");
}

fn summary(errors: &[[f64; 3]]) {
    let n = errors.len() as f64;
    let mean = |k: usize| 100.0 * errors.iter().map(|e| e[k].abs()).sum::<f64>() / n;
    println!(
        "| **mean \\|err\\|** | | {:.2} % | | {:.1} % | **{:.2} %** |",
        mean(0),
        mean(1),
        mean(2)
    );
}

fn main() -> Result<(), String> {
    let contact = match std::env::args().nth(1) {
        Some(path) => carry_io::contact::parse(&path)?,
        None => carry_core::presets::FITTED_CONTACT,
    };
    let scene = Scene {
        air: Air::Weather(Weather {
            temperature_c: 21.1,
            relative_humidity: 0.5,
            pressure: Pressure::Pa(101_325.0),
        }),
        ..Scene::default()
    }
    .prepare(&Ball::standard())
    .map_err(|e| e.to_string())?;
    let rows = rows()?;

    table_head("presets' typical deliveries (PGA 2023): `carry shot --club X`");
    let mut errors = Vec::new();
    for row in rows.iter().filter(|r| r.tour == "PGA") {
        let t = row.preset.typical;
        let s = shoot(row.preset, &contact, &GivenDelivery::default(), &scene)?;
        errors.push(print_row(row.preset.name, t.dynamic_loft_deg, row, &s));
    }
    summary(&errors);

    for tour in ["PGA", "LPGA"] {
        table_head(&format!(
            "{tour} 2023, each row's club speed and attack, loft matched to its launch"
        ));
        let mut errors = Vec::new();
        for row in rows.iter().filter(|r| r.tour == tour) {
            let loft = match (row.preset.name, tour) {
                ("driver", "PGA") => 12.8,
                ("driver", _) => 15.5,
                _ => matched_loft(row, &contact, &scene)?,
            };
            let s = shoot(row.preset, &contact, &given(row, loft), &scene)?;
            errors.push(print_row(row.preset.name, loft, row, &s));
        }
        summary(&errors);
    }
    Ok(())
}
