//! The bag from delivery alone against TrackMan's 2023 tour averages (docs/impact.md §0.6,
//! [`carry_lab::bag`]): the presets' typical deliveries (PGA), then each tour's rows with their
//! own club speed and attack and the dynamic loft that fits their ball speed, launch and spin
//! best ([`bag::fitted_loft`]).
//!
//! `cargo run --release -p carry-lab --example bag_report [CONTACT.toml]`: optionally a
//! contact law (as `--contact` reads) instead of the presets'.
use carry_lab::bag::{self, BagShot, TourRow};

fn table(title: &str, shots: &[(TourRow, BagShot)]) {
    println!("\n{title}\n");
    println!(
        "| club | dyn. loft ° | ball mph (err) | launch ° | spin rpm (err) | carry yd (err) |"
    );
    println!("|---|---:|---|---|---|---|");
    for (row, s) in shots {
        let e = s.errors(row);
        println!(
            "| {} | {:.1} | {:.1} / {} ({:+.1} %) | {:.1} / {} ({:+.1}) | {:.0} / {} ({:+.0} %) | {:.1} / {} ({:+.1} %) |",
            row.preset.name,
            s.dynamic_loft_deg,
            s.ball_speed_mph,
            row.ball_speed_mph,
            100.0 * e[0],
            s.launch_deg,
            row.launch_deg,
            s.launch_deg - row.launch_deg,
            s.spin_rpm,
            row.spin_rpm,
            100.0 * e[1],
            s.carry_yd,
            row.carry_yd,
            100.0 * e[2]
        );
    }
    let [speed, spin, carry] = bag::mean_abs(shots);
    #[allow(clippy::cast_precision_loss)]
    let launch = shots
        .iter()
        .map(|(row, s)| (s.launch_deg - row.launch_deg).abs())
        .sum::<f64>()
        / shots.len().max(1) as f64;
    println!(
        "| **mean \\|err\\|** | | {:.2} % | {:.2}° | {:.1} % | **{:.2} %** |",
        100.0 * speed,
        launch,
        100.0 * spin,
        100.0 * carry
    );
}

fn main() -> Result<(), String> {
    let contact = match std::env::args().nth(1) {
        Some(path) => carry_io::contact::parse(&path)?,
        None => carry_core::presets::FITTED_CONTACT,
    };
    let rows = bag::tour_rows()?;
    table(
        "presets' typical deliveries (PGA 2023): `carry shot --club X`",
        &bag::presets(&rows, &contact)?,
    );
    for tour in ["PGA", "LPGA"] {
        table(
            &format!(
                "{tour} 2023, each row's club speed and attack, loft fitted to its ball speed, launch and spin"
            ),
            &bag::matched(&rows, tour, &contact)?,
        );
    }
    Ok(())
}
