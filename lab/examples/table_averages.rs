//! The tables as averages of shots (docs/aero.md, issue 35, "The tour table as averages").
//!
//! Measures the single drives' within-session spread of ball speed, launch, spin and spin
//! axis (`carry_lab::drives`), then evaluates `drives2026` and `tour2023` on TrackMan's 2023
//! tour table and 2010 driver chart twice: each row flown from its listed launch, and each
//! row's carry, apex and landing angle as the mean over that spread (`carry_lab::fit::
//! table_average`, 81 flights a row), at fractions of it.
//!
//! `cargo run --release -p carry-lab --example table_averages [FACTOR…]` (default 0.25 0.5 1).
#[allow(dead_code)]
#[path = "../tests/common/mod.rs"]
mod common;

use carry_core::aero::AeroModel;
use carry_lab::drives;
use carry_lab::fit::evaluate;
use carry_lab::fit::flight::{AeroFamily, AeroProblem, ShotRow};
use carry_lab::fit::table_average::{AveragedAeroProblem, LaunchSpread, SPREAD_NAMES};

fn summary(
    model: &AeroModel<f64>,
    rows: &[ShotRow],
    spread: LaunchSpread,
) -> Option<(Vec<f64>, String)> {
    let family = AeroFamily::of(model);
    let problem = AveragedAeroProblem {
        inner: AeroProblem::new(family),
        spread,
    };
    let p = family.parameters(model).expect("family");
    let fit = evaluate(&problem, rows, &p).ok()?;
    let pct: Vec<f64> = rows
        .iter()
        .zip(&fit.rows)
        .map(|(r, f)| 100.0 * (f.predicted[0] / r.carry_m - 1.0))
        .collect();
    #[allow(clippy::cast_precision_loss)]
    let n = pct.len() as f64;
    let mean = pct.iter().map(|e| e.abs()).sum::<f64>() / n;
    let worst = pct.iter().fold(0.0_f64, |m, e| m.max(e.abs()));
    let bias = pct.iter().sum::<f64>() / n;
    let mut s = format!("{mean:.2} / {worst:.1} % (bias {bias:+.2} %)");
    if rows[0].apex_m.is_some() {
        let apex = rows
            .iter()
            .zip(&fit.rows)
            .map(|(r, f)| (f.predicted[1] - r.apex_m.unwrap_or(f.predicted[1])).abs())
            .sum::<f64>()
            / n
            / common::YD;
        let land = rows
            .iter()
            .zip(&fit.rows)
            .map(|(r, f)| (f.predicted[2] - r.land_angle_deg.unwrap_or(f.predicted[2])).abs())
            .sum::<f64>()
            / n;
        s += &format!(", apex {apex:.2} yd, land {land:.2}°");
    }
    Some((pct, s))
}

fn main() {
    let factors: Vec<f64> = {
        let a: Vec<f64> = std::env::args()
            .skip(1)
            .filter_map(|a| a.parse().ok())
            .collect();
        if a.is_empty() {
            vec![0.25, 0.5, 1.0]
        } else {
            a
        }
    };
    let all = drives::read_shared().expect("../shared/data/trackman_amateur_drives.csv");
    let pooled = LaunchSpread::of_drives(&all).expect("drives");
    println!(
        "### The single drives' spread (premium, indoors, launch ≥ 1°, mishits beyond 3 robust σ screened; σ within each session)\n"
    );
    println!("| session | {} |", SPREAD_NAMES.join(" | "));
    println!("|---|---:|---:|---:|---:|");
    for s in drives::sessions(&all) {
        let one: Vec<_> = all.iter().filter(|d| d.session() == s).copied().collect();
        if let Some(sp) = LaunchSpread::of_drives(&one) {
            let g = sp.sigma();
            println!(
                "| {s} | {:.2} % | {:.2}° | {:.1} % | {:.2}° |",
                100.0 * g[0],
                g[1],
                100.0 * g[2],
                g[3]
            );
        }
    }
    let g = pooled.sigma();
    println!(
        "| **pooled** | **{:.2} %** | **{:.2}°** | **{:.1} %** | **{:.2}°** |",
        100.0 * g[0],
        g[1],
        100.0 * g[2],
        g[3]
    );
    println!("\ncorrelations (pooled):");
    for (i, name) in SPREAD_NAMES.iter().enumerate() {
        let r: Vec<String> = (0..4)
            .map(|j| format!("{:+.2}", pooled.correlation(i, j)))
            .collect();
        println!("  {name:<18} {}", r.join("  "));
    }

    let tour = common::tour_2023().expect("../shared/data/trackman_tour_2023.csv");
    let chart =
        common::optimizer_2010().expect("../shared/data/trackman_driver_optimizer_2010.csv");
    let models = [
        ("drives2026", AeroModel::<f64>::drives_2026()),
        ("tour2023", AeroModel::<f64>::tour_2023()),
    ];
    let mut spreads = vec![("listed launch (no spread)".to_owned(), LaunchSpread::NONE)];
    for f in &factors {
        spreads.push((format!("{f} × the drives' spread"), pooled.scaled(*f)));
    }
    println!("\n### Carry mean |err| / worst (model − TrackMan), 21.1 °C, 50 % RH\n");
    println!("| model | rows flown as | tour 2023 | 2010 chart |");
    println!("|---|---|---|---|");
    let mut per_row: Vec<(String, Vec<f64>, Vec<f64>)> = Vec::new();
    for (name, model) in &models {
        for (what, spread) in &spreads {
            // A spread too wide for a row (a node launched into the ground) fails it.
            let (t, ts) = summary(model, &tour, *spread)
                .unwrap_or_else(|| (vec![f64::NAN; tour.len()], "a row fails".into()));
            let (c, cs) = summary(model, &chart, *spread)
                .unwrap_or_else(|| (vec![f64::NAN; chart.len()], "a row fails".into()));
            println!("| {name} | {what} | {ts} | {cs} |");
            per_row.push((format!("{name}, {what}"), t, c));
        }
    }
    println!("\n### Per row, carry % (columns: {})\n", {
        let h: Vec<&str> = per_row.iter().map(|p| p.0.as_str()).collect();
        h.join(" | ")
    });
    for (i, r) in tour.iter().enumerate() {
        let v: Vec<String> = per_row.iter().map(|p| format!("{:+.1}", p.1[i])).collect();
        println!("| {} | {} |", r.label, v.join(" | "));
    }
    for (i, r) in chart.iter().enumerate() {
        let v: Vec<String> = per_row.iter().map(|p| format!("{:+.1}", p.2[i])).collect();
        println!("| {} | {} |", r.label, v.join(" | "));
    }
}
