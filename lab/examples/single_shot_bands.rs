//! Where issue 21's single drives should now stand (docs/aero.md, "The single shots").
//!
//! Issue 21 reports the amateur drives' carry errors by spin band and by ball-speed band,
//! flown with issue 10's model. The drives are not shared, but the change of model on the
//! same launch is computable: for a grid of driver launches in each band (launch 9, 12 and
//! 15°), the carry of `tour2023` against issue 10's, at the data README's conditions. Then
//! `(1 + reported) · (1 + change) − 1` is what the same drives should show today, if
//! their spread inside the band is like the grid's.
//!
//! `cargo run --release -p carry-lab --example single_shot_bands`
// Only the conditions are used: the bands are grids, not rows of the tables.
#[allow(dead_code)]
#[path = "../tests/common/mod.rs"]
mod common;

use carry_core::Launch;
use carry_core::aero::{AeroModel, ModernAero};
use carry_core::flight::Integrator;
use carry_core::units::{deg, mph, rpm};
use carry_lab::fit::flight::{FIT_TOLERANCE, predict};

/// Issue 10's calibrated model.
const ISSUE_10: [f64; 9] = include!("issue_10_model.in");

/// A band of the issue: its name, the error it reports with issue 10's model (None where
/// the issue gives none), ball speeds (mph) and spins (rpm) of the grid.
struct Band {
    name: &'static str,
    reported: Option<(f64, f64)>,
    speeds_mph: &'static [f64],
    spins_rpm: &'static [f64],
}

const ALL_SPEEDS: &[f64] = &[90.0, 100.0, 110.0, 120.0, 130.0, 140.0, 150.0, 160.0, 170.0];
const MID_SPINS: &[f64] = &[1_750.0, 2_250.0, 2_750.0, 3_250.0, 3_750.0];
const LAUNCHES_DEG: [f64; 3] = [9.0, 12.0, 15.0];

const BANDS: [Band; 7] = [
    Band {
        name: "spin < 1,500 rpm",
        reported: Some((-0.10, -0.10)),
        speeds_mph: ALL_SPEEDS,
        spins_rpm: &[800.0, 1_100.0, 1_400.0],
    },
    Band {
        name: "spin 1,500–3,000 rpm",
        reported: Some((-0.06, -0.04)),
        speeds_mph: ALL_SPEEDS,
        spins_rpm: &[1_750.0, 2_250.0, 2_750.0],
    },
    Band {
        name: "spin 3,000–5,000 rpm",
        reported: None,
        speeds_mph: ALL_SPEEDS,
        spins_rpm: &[3_500.0, 4_000.0, 4_500.0],
    },
    Band {
        name: "spin > 5,000 rpm",
        reported: Some((-0.01, 0.01)),
        speeds_mph: ALL_SPEEDS,
        spins_rpm: &[5_500.0, 6_500.0],
    },
    Band {
        name: "ball 80–110 mph",
        reported: Some((-0.026, -0.026)),
        speeds_mph: &[85.0, 95.0, 105.0],
        spins_rpm: MID_SPINS,
    },
    Band {
        name: "ball 110–150 mph",
        reported: None,
        speeds_mph: &[115.0, 125.0, 135.0, 145.0],
        spins_rpm: MID_SPINS,
    },
    Band {
        name: "ball > 150 mph",
        reported: Some((-0.047, -0.047)),
        speeds_mph: &[155.0, 165.0, 175.0],
        spins_rpm: MID_SPINS,
    },
];

fn carry_m(model: &AeroModel<f64>, launch: &Launch<f64>) -> f64 {
    let integrator = Integrator::dormand_prince(FIT_TOLERANCE);
    predict(model, launch, &common::fitting_air(), &integrator).map_or(f64::NAN, |p| p[0])
}

fn main() {
    let now = AeroModel::tour_2023();
    let before = AeroModel::Modern(ModernAero::from_array(ISSUE_10));
    println!(
        "| band | reported with issue 10 | tour2023 / issue 10, mean (range) | expected today |"
    );
    println!("|---|---:|---:|---:|");
    for band in &BANDS {
        let mut changes = Vec::new();
        for &v in band.speeds_mph {
            for &w in band.spins_rpm {
                for a in LAUNCHES_DEG {
                    let launch = Launch {
                        ball_speed_mps: mph(v),
                        launch_angle_rad: deg(a),
                        launch_direction_rad: 0.0,
                        backspin_radps: rpm(w),
                        sidespin_radps: 0.0,
                    };
                    changes.push(carry_m(&now, &launch) / carry_m(&before, &launch) - 1.0);
                }
            }
        }
        #[allow(clippy::cast_precision_loss)]
        let mean = changes.iter().sum::<f64>() / changes.len() as f64;
        let (lo, hi) = changes
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &c| {
                (l.min(c), h.max(c))
            });
        let pct = |x: f64| format!("{:+.1} %", 100.0 * x);
        let (reported, expected) = band.reported.map_or(("—".into(), "—".into()), |(a, b)| {
            let today = |r: f64| (1.0 + r) * (1.0 + mean) - 1.0;
            if a == b {
                (pct(a), pct(today(a)))
            } else {
                (
                    format!("{} … {}", pct(a), pct(b)),
                    format!("{} … {}", pct(today(a)), pct(today(b))),
                )
            }
        });
        println!(
            "| {} | {reported} | {} ({} … {}) | {expected} |",
            band.name,
            pct(mean),
            pct(lo),
            pct(hi)
        );
    }
}
