//! How much shorter an average of carries is than the carry of the average launch
//! (docs/aero.md, "Why the tour table's in-sample carry is 1.86 %").
//!
//! TrackMan's tour rows average each column over many shots, so a row's carry is
//! `E[carry(v, θ, ω)]`, not `carry(E v, E θ, E ω)`. Carry is concave near its optimum,
//! so by Jensen's inequality the average of carries is the shorter. This example measures
//! the gap with the calibrated flight: for each tour row, the expectation over independent
//! normal scatter of ball speed (σ relative), launch (σ in degrees) and spin (σ relative)
//! by a 3-point Gauss–Hermite rule in each of the three (27 flights, exact for any cubic),
//! at the data README's conditions.
//!
//! `cargo run --release -p carry-lab --example average_of_carries [SPEED LAUNCH SPIN]`:
//! one scatter (e.g. `0.04 2 0.15`) instead of the two built in.
// The chart's reader goes unused: its rows are single modelled shots, not averages.
#[allow(dead_code)]
#[path = "../tests/common/mod.rs"]
mod common;

use carry_core::aero::AeroModel;
use carry_core::flight::Integrator;
use carry_lab::fit::flight::{FIT_TOLERANCE, ShotRow, predict};

/// Nodes and weights of the 3-point Gauss–Hermite rule for a standard normal.
const RULE: [(f64, f64); 3] = [
    (-1.732_050_807_568_877_2, 1.0 / 6.0),
    (0.0, 2.0 / 3.0),
    (1.732_050_807_568_877_2, 1.0 / 6.0),
];

/// Shot-to-shot scatter: ball speed (relative), launch (degrees), spin (relative).
#[derive(Clone, Copy)]
struct Scatter {
    name: &'static str,
    speed_rel: f64,
    launch_deg: f64,
    spin_rel: f64,
}

fn carry_m(row: &ShotRow, model: &AeroModel<f64>, integrator: &Integrator<f64>) -> f64 {
    predict(model, &row.launch, &row.air, integrator).map_or(f64::NAN, |p| p[0])
}

/// `E[carry]` over `s`, and the carry of the mean launch (m).
fn expected_carry(
    row: &ShotRow,
    s: Scatter,
    model: &AeroModel<f64>,
    integrator: &Integrator<f64>,
) -> (f64, f64) {
    let mut sum = 0.0;
    for (a, wa) in RULE {
        for (b, wb) in RULE {
            for (c, wc) in RULE {
                let mut r = row.clone();
                r.launch.ball_speed_mps *= 1.0 + s.speed_rel * a;
                r.launch.launch_angle_rad += s.launch_deg.to_radians() * b;
                r.launch.backspin_radps *= 1.0 + s.spin_rel * c;
                sum += wa * wb * wc * carry_m(&r, model, integrator);
            }
        }
    }
    (sum, carry_m(row, model, integrator))
}

fn main() {
    let rows = common::tour_2023().expect("../shared/data/trackman_tour_2023.csv");
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let scatters = match args[..] {
        [speed_rel, launch_deg, spin_rel] => vec![Scatter {
            name: "given",
            speed_rel,
            launch_deg,
            spin_rel,
        }],
        _ => vec![
            // One tour player's shot-to-shot scatter with one club.
            Scatter {
                name: "one player",
                speed_rel: 0.01,
                launch_deg: 1.0,
                spin_rel: 0.08,
            },
            // Over a tour: the players' own averages differ as well.
            Scatter {
                name: "a tour",
                speed_rel: 0.04,
                launch_deg: 2.0,
                spin_rel: 0.15,
            },
        ],
    };
    let model = AeroModel::tour_2023();
    let integrator = Integrator::dormand_prince(FIT_TOLERANCE);
    for s in scatters {
        println!(
            "\n### {}: ball speed σ {:.0} %, launch σ {:.1}°, spin σ {:.0} % (tour2023, 21.1 °C, 50 % RH)\n",
            s.name,
            100.0 * s.speed_rel,
            s.launch_deg,
            100.0 * s.spin_rel
        );
        println!(
            "| row | TrackMan yd | carry of the mean launch (err) | mean of carries (err) | gap |"
        );
        println!("|---|---:|---:|---:|---:|");
        let (mut at_mean, mut averaged) = (0.0, 0.0);
        for row in &rows {
            let (e, c0) = expected_carry(row, s, &model, &integrator);
            let obs = row.carry_m;
            let (err0, err1) = (100.0 * (c0 / obs - 1.0), 100.0 * (e / obs - 1.0));
            at_mean += err0.abs();
            averaged += err1.abs();
            println!(
                "| {} | {:.0} | {:.1} ({err0:+.2} %) | {:.1} ({err1:+.2} %) | {:+.2} % |",
                row.label,
                obs / common::YD,
                c0 / common::YD,
                e / common::YD,
                100.0 * (e / c0 - 1.0)
            );
        }
        #[allow(clippy::cast_precision_loss)]
        let n = rows.len() as f64;
        println!(
            "| **mean \\|err\\|** | | **{:.2} %** | **{:.2} %** | |",
            at_mean / n,
            averaged / n
        );
    }
}
