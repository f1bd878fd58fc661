//! Produces the figures of docs/aero.md: the calibrated modern model fitted jointly to
//! TrackMan's 2023 tour averages and 2010 driver chart (fit and leave-one-out errors per
//! row), compared with the seed and with issue 10's tour-only fit, its coefficients against
//! published wind-tunnel values, and the SVG of C_L(S), C_D(S) and C_D(Re) with the
//! published points.
//!
//! ```sh
//! cargo run --release -p carry-lab --example aero_report -- docs/aero-coefficients.svg
//! ```

#[path = "../tests/common/mod.rs"]
mod common;

use carry_core::aero::{AeroModel, ModernAero, TOUR_2023};
use carry_lab::fit::flight::{AeroFamily, AeroProblem, ShotRow};
use carry_lab::fit::{self, Fit, FitOptions};
use plotters::prelude::*;

/// Issue 10's calibrated model (fitted to the tour table alone), for comparison: the same
/// family without the low-spin lift.
const ISSUE_10: [f64; 9] = include!("issue_10_model.in");

/// Bearman & Harvey (1976), hexagonal-dimple ball, figures 7 and 8, as digitised in the
/// public repository lrhgit/tkt4140 (allfiles/Kap1/Eks14golf/cdcldata.m): (speed m/s,
/// spin rpm, C_D, C_L), every speed at 2,000 to 6,000 rpm in steps of 1,000.
const BEARMAN_HARVEY: [(f64, f64, f64, f64); 50] = include!("bearman_harvey.in");

/// Ball diameter (m) and kinematic viscosity (m²/s) assumed for the wind-tunnel points'
/// S and Re (a 1.68 in ball, air at about 20 °C).
const TUNNEL_DIAMETER_M: f64 = 0.04267;
const TUNNEL_NU: f64 = 1.5e-5;

/// `(S, Re, C_D, C_L)` of a wind-tunnel point.
fn tunnel(v: f64, rpm: f64, cd: f64, cl: f64) -> (f64, f64, f64, f64) {
    let omega = rpm * std::f64::consts::PI / 30.0;
    (
        0.5 * TUNNEL_DIAMETER_M * omega / v,
        v * TUNNEL_DIAMETER_M / TUNNEL_NU,
        cd,
        cl,
    )
}

/// Carry error (%), apex error (yd) and landing-angle error (°) of row `i` (fit or LOO).
fn errors(f: &Fit, i: usize, loo: bool) -> [f64; 3] {
    let r = &f.rows[i];
    let p = if loo {
        r.loo_predicted.as_ref().unwrap_or(&r.predicted)
    } else {
        &r.predicted
    };
    let o = |k: usize| r.observed[k].unwrap_or(f64::NAN);
    [
        100.0 * (p[0] - o(0)) / o(0),
        (p[1] - o(1)) / common::YD,
        p[2] - o(2),
    ]
}

/// Mean and max |carry error| (%) over `range` (fit or LOO).
fn carry_stats(f: &Fit, range: std::ops::Range<usize>, loo: bool) -> (f64, f64) {
    let e: Vec<f64> = range.map(|i| errors(f, i, loo)[0].abs()).collect();
    (
        e.iter().sum::<f64>() / e.len() as f64,
        e.iter().copied().fold(0.0, f64::max),
    )
}

/// Mean |apex error| (yd) and |landing-angle error| (°) over `range`.
fn shape_stats(f: &Fit, range: std::ops::Range<usize>, loo: bool) -> (f64, f64) {
    let n = range.len() as f64;
    let (mut a, mut l) = (0.0, 0.0);
    for i in range {
        let e = errors(f, i, loo);
        a += e[1].abs();
        l += e[2].abs();
    }
    (a / n, l / n)
}

fn evaluate(rows: &[ShotRow], model: &AeroModel<f64>) -> Fit {
    let family = AeroFamily::of(model);
    fit::evaluate(
        &AeroProblem::new(family),
        rows,
        &family.parameters(model).expect("family"),
    )
    .expect("evaluates")
}

fn main() {
    let svg = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "aero-coefficients.svg".into());
    let tour = common::tour_2023().expect("../shared/data/trackman_tour_2023.csv");
    let chart =
        common::optimizer_2010().expect("../shared/data/trackman_driver_optimizer_2010.csv");
    let (nt, nc) = (tour.len(), chart.len());
    let mut rows = tour.clone();
    rows.extend(chart.iter().cloned());
    let all = 0..nt + nc;
    let (tr, cr) = (0..nt, nt..nt + nc);
    let issue10 = AeroModel::Modern(ModernAero::from_array(ISSUE_10));
    let seed = evaluate(&rows, &AeroModel::quintavalla());
    let old = evaluate(&rows, &issue10);
    let t = std::time::Instant::now();
    let joint = fit::fit(
        &AeroProblem::new(AeroFamily::Modern),
        &rows,
        FitOptions::default(),
        &|| {},
    )
    .expect("joint fit");
    println!(
        "joint fit + {} leave-one-out refits: {:.1?} ({}, {} row evaluations in the main fit)\n",
        rows.len(),
        t.elapsed(),
        joint.termination,
        joint.row_evaluations
    );
    println!("| coefficient | fitted | committed (tour2023) | bounds |");
    println!("|---|---:|---:|---|");
    for (p, c) in joint.parameters.iter().zip(TOUR_2023) {
        println!(
            "| `{}` | {:.6} | {c} | {}–{} |",
            p.name, p.value, p.lower, p.upper
        );
    }
    let committed = evaluate(&rows, &AeroModel::tour_2023());

    println!("\n### Tour 2023 per club (model − TrackMan)\n");
    println!(
        "| club | seed carry % | issue 10 carry % | tour2023 carry % (LOO) | issue 10 / tour2023 apex yd | issue 10 / tour2023 land ° |"
    );
    println!("|---|---:|---:|---:|---:|---:|");
    for i in tr.clone() {
        let (s, o, n, l) = (
            errors(&seed, i, false),
            errors(&old, i, false),
            errors(&committed, i, false),
            errors(&joint, i, true),
        );
        println!(
            "| {} | {:+.1} | {:+.1} | {:+.1} ({:+.1}) | {:+.1} / {:+.1} | {:+.1} / {:+.1} |",
            rows[i].label, s[0], o[0], n[0], l[0], o[1], n[1], o[2], n[2]
        );
    }
    println!("\n### 2010 driver chart per row (carry, model − TrackMan, %)\n");
    println!(
        "| club speed, attack | ball mph / launch ° / rpm | S at launch | seed | issue 10 | tour2023 (LOO) |"
    );
    println!("|---|---|---:|---:|---:|---:|");
    for i in cr.clone() {
        let r = &rows[i];
        let l = &r.launch;
        let s = 0.021_335 * l.backspin_radps / l.ball_speed_mps;
        println!(
            "| {} | {:.0} / {:.1} / {:.0} | {:.3} | {:+.1} | {:+.1} | {:+.1} ({:+.1}) |",
            r.label,
            l.ball_speed_mps / common::MPH,
            l.launch_angle_rad.to_degrees(),
            l.backspin_radps * 30.0 / std::f64::consts::PI,
            s,
            errors(&seed, i, false)[0],
            errors(&old, i, false)[0],
            errors(&committed, i, false)[0],
            errors(&joint, i, true)[0],
        );
    }
    println!(
        "\n### Summary (carry |error| %, mean / max; apex yd and landing ° mean, tour rows)\n"
    );
    println!(
        "| model | tour carry | tour LOO carry | tour apex | tour land | chart carry | chart LOO carry | both carry |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|");
    let fmt = |(a, b): (f64, f64)| format!("{a:.2} / {b:.2}");
    for (name, f) in [
        ("seed (`quintavalla`)", &seed),
        ("issue 10 (tour only)", &old),
        ("**`tour2023`** (joint)", &committed),
    ] {
        let (apex, land) = shape_stats(f, tr.clone(), false);
        let (tl, cl) = if name.contains("joint") {
            (
                fmt(carry_stats(&joint, tr.clone(), true)),
                fmt(carry_stats(&joint, cr.clone(), true)),
            )
        } else {
            ("—".into(), "—".into())
        };
        println!(
            "| {name} | {} | {tl} | {apex:.2} | {land:.2} | {} | {cl} | {} |",
            fmt(carry_stats(f, tr.clone(), false)),
            fmt(carry_stats(f, cr.clone(), false)),
            fmt(carry_stats(f, all.clone(), false)),
        );
    }
    let (la, ll) = shape_stats(&joint, tr.clone(), true);
    println!("\nleave-one-out apex {la:.2} yd, landing angle {ll:.2}° (tour rows)");

    println!("\n### Published coefficients against tour2023 (at the point's S and Re)\n");
    println!("| source | S | Re | C_L published | C_L tour2023 | C_D published | C_D tour2023 |");
    println!("|---|---:|---:|---:|---:|---:|---:|");
    let m = AeroModel::<f64>::tour_2023();
    let mut checks: Vec<(String, f64, f64, String, String)> = Vec::new();
    for &(v, rpm, cd, cl) in &BEARMAN_HARVEY {
        if v > 60.0 && rpm <= 4000.0 {
            let (s, re, cd, cl) = tunnel(v, rpm, cd, cl);
            checks.push((
                format!("Bearman & Harvey, {v} m/s, {rpm:.0} rpm"),
                s,
                re,
                format!("{cl:.3}"),
                format!("{cd:.3}"),
            ));
        }
    }
    checks.push((
        "US 6,916,255 (four balls)".into(),
        0.110,
        1.8e5,
        "0.158–0.179".into(),
        "0.225–0.228".into(),
    ));
    checks.push((
        "WO 2001/019464, 2,000 rpm".into(),
        0.18,
        7.0e4,
        "> 0.18".into(),
        "—".into(),
    ));
    checks.push((
        "WO 2001/019464, 3,000 rpm".into(),
        0.106,
        1.8e5,
        "—".into(),
        "< 0.232".into(),
    ));
    checks.push((
        "Naruo et al. 2004 (quoted)".into(),
        0.05,
        1.0e5,
        "≈ 0.12".into(),
        "—".into(),
    ));
    for (name, s, re, cl, cd) in checks {
        let (mcd, mcl, _) = m.coefficients(s, re);
        println!("| {name} | {s:.3} | {re:.2e} | {cl} | {mcl:.3} | {cd} | {mcd:.3} |");
    }
    draw(&svg, &issue10).expect("svg");
    println!("\nwrote {svg}");
}

/// C_L(S), C_D(S) and C_D(Re) of the calibrated model (and issue 10's, and the seed's)
/// with Bearman & Harvey's points, the patents' and the published fits.
fn draw(path: &str, issue10: &AeroModel<f64>) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (1200, 430)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((1, 3));
    let s_grid: Vec<f64> = (0..=120).map(|i| f64::from(i) * 0.005).collect();
    let now = AeroModel::<f64>::tour_2023();
    let blue = |k: u8| RGBColor(20 + 50 * k, 70 + 45 * k, 200);
    let points: Vec<(f64, f64, f64, f64)> = BEARMAN_HARVEY
        .iter()
        .map(|&(v, rpm, cd, cl)| tunnel(v, rpm, cd, cl))
        .filter(|p| p.0 <= 0.6)
        .collect();
    // Re bands of the points and the curves drawn for them.
    let bands: [(f64, f64, f64, &str); 3] = [
        (5.0e4, 1.0e5, 7.5e4, "Re 5e4–1e5"),
        (1.0e5, 1.7e5, 1.4e5, "Re 1e5–1.7e5"),
        (1.7e5, 3.0e5, 2.2e5, "Re 1.7e5–3e5"),
    ];
    for (panel, pick) in panels.iter().zip(0..3) {
        let (title, x_desc, xr, yr): (&str, &str, std::ops::Range<f64>, std::ops::Range<f64>) =
            match pick {
                0 => (
                    "lift coefficient C_L(S)",
                    "spin parameter S = Rω/V",
                    0.0..0.6,
                    0.0..0.5,
                ),
                1 => (
                    "drag coefficient C_D(S)",
                    "spin parameter S = Rω/V",
                    0.0..0.6,
                    0.1..0.6,
                ),
                _ => (
                    "drag coefficient C_D(Re)",
                    "Reynolds number Re / 10⁵",
                    0.4..2.6,
                    0.1..0.6,
                ),
            };
        let mut chart = ChartBuilder::on(panel)
            .caption(title, ("sans-serif", 16))
            .margin(8)
            .x_label_area_size(32)
            .y_label_area_size(40)
            .build_cartesian_2d(xr, yr)?;
        chart.configure_mesh().x_desc(x_desc).draw()?;
        if pick < 2 {
            for (k, &(lo, hi, re, name)) in bands.iter().enumerate() {
                let c = blue(k as u8);
                // The lift does not depend on Re: one curve, the points of every band.
                if pick == 1 || k == 0 {
                    let label = if pick == 0 {
                        "tour2023 (any Re)".to_string()
                    } else {
                        format!("tour2023, Re {re:.1e}")
                    };
                    chart
                        .draw_series(LineSeries::new(
                            s_grid.iter().map(|&s| {
                                let (cd, cl, _) = now.coefficients(s, re);
                                (s, if pick == 0 { cl } else { cd })
                            }),
                            c.stroke_width(2),
                        ))?
                        .label(label)
                        .legend(move |(x, y)| {
                            PathElement::new(vec![(x, y), (x + 16, y)], c.stroke_width(2))
                        });
                }
                chart
                    .draw_series(points.iter().filter(|p| p.1 >= lo && p.1 < hi).map(|p| {
                        Circle::new((p.0, if pick == 0 { p.3 } else { p.2 }), 3, c.filled())
                    }))?
                    .label(format!("Bearman & Harvey, {name}"))
                    .legend(move |(x, y)| Circle::new((x + 8, y), 3, c.filled()));
            }
            let orange = RGBColor(230, 120, 20);
            chart
                .draw_series(LineSeries::new(
                    s_grid.iter().map(|&s| {
                        let (cd, cl, _) = issue10.coefficients(s, 2.2e5);
                        (s, if pick == 0 { cl } else { cd })
                    }),
                    orange.stroke_width(1),
                ))?
                .label("issue 10 (tour only), Re 2.2e5")
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], orange));
            let red = RGBColor(200, 40, 40);
            chart
                .draw_series(LineSeries::new(
                    s_grid.iter().map(|&s| {
                        let (cd, cl, _) = AeroModel::<f64>::quintavalla().coefficients(s, 2.2e5);
                        (s, if pick == 0 { cl } else { cd })
                    }),
                    red.stroke_width(1),
                ))?
                .label("seed (Quintavalla)")
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], red));
            // Published fits, second-hand (REFERENCES.md), dashed over their stated ranges.
            let grey = RGBColor(60, 60, 60);
            let fit_curve: Box<dyn Fn(f64) -> Option<f64>> = if pick == 0 {
                Box::new(|s: f64| {
                    (0.04..=0.32)
                        .contains(&s)
                        .then_some(1.99 * s - 3.25 * s * s)
                })
            } else {
                Box::new(|s: f64| (0.08..=0.2).contains(&s).then_some(0.24 + 0.18 * s))
            };
            chart
                .draw_series(DashedLineSeries::new(
                    s_grid.iter().filter_map(|&s| fit_curve(s).map(|y| (s, y))),
                    5,
                    4,
                    grey.stroke_width(1),
                ))?
                .label(if pick == 0 {
                    "Lyu et al. 2018 fit (quoted)"
                } else {
                    "Smits & Smith 1994, Re 9e4 (quoted)"
                })
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], grey));
            // US 6,916,255 at Re 1.8e5, S 0.110 (ranges over four balls).
            let green = RGBColor(20, 150, 60);
            let (lo, hi) = if pick == 0 {
                (0.158, 0.179)
            } else {
                (0.225, 0.228)
            };
            chart
                .draw_series(std::iter::once(PathElement::new(
                    vec![(0.110, lo), (0.110, hi + 0.002)],
                    green.stroke_width(4),
                )))?
                .label("US 6,916,255, Re 1.8e5 (four balls)")
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 16, y)], green.stroke_width(4))
                });
        } else {
            for (k, s) in [0.1_f64, 0.2].into_iter().enumerate() {
                let c = blue(2 * k as u8);
                chart
                    .draw_series(LineSeries::new(
                        (0..=110).map(|i| {
                            let re = 4.0e4 + f64::from(i) * 2.0e3;
                            (re / 1e5, now.coefficients(s, re).0)
                        }),
                        c.stroke_width(2),
                    ))?
                    .label(format!("tour2023, S {s}"))
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 16, y)], c.stroke_width(2))
                    });
                chart
                    .draw_series(
                        points
                            .iter()
                            .filter(|p| (p.0 - s).abs() < 0.025)
                            .map(|p| Circle::new((p.1 / 1e5, p.2), 3, c.filled())),
                    )?
                    .label(format!(
                        "Bearman & Harvey, S {:.3}–{:.3}",
                        s - 0.025,
                        s + 0.025
                    ))
                    .legend(move |(x, y)| Circle::new((x + 8, y), 3, c.filled()));
            }
            let grey = RGBColor(60, 60, 60);
            chart
                .draw_series(DashedLineSeries::new(
                    (0..=62).map(|i| {
                        let re = 7.5e4 + f64::from(i) * 2.0e3;
                        (re / 1e5, 1.91e-11 * re * re - 5.40e-6 * re + 0.56)
                    }),
                    5,
                    4,
                    grey.stroke_width(1),
                ))?
                .label("Lyu et al. 2018 fit (quoted; spin mixed)")
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], grey));
        }
        chart
            .configure_series_labels()
            .border_style(BLACK)
            .background_style(WHITE.mix(0.85))
            .position(if pick == 0 {
                SeriesLabelPosition::LowerRight
            } else {
                SeriesLabelPosition::UpperRight
            })
            .label_font(("sans-serif", 10))
            .draw()?;
    }
    root.present()?;
    Ok(())
}
