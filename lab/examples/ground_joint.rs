//! One turf for the single drives' rolls and TrackMan's 2010 chart's totals, fitted jointly
//! and held out both ways (docs/ground.md, "Issue 35: one turf for the drives and the
//! chart"; library `carry_lab::ground_joint`). Before: `fairway-trackman` (the drives'
//! turf) and `fairway` (the chart's, ρ₀ fitted to its rolls), each held out as it was
//! fitted. After: the joint fit, and the named preset `fairway-joint`
//! (`Surface::FairwayJoint`, `carry_core::ground::surface::JOINT_FAIRWAY`: the fit on every
//! row, rounded), with a side-by-side summary of the three named fairways at the end.
//! Flight `drives2026`; 21.1 °C, 50 % RH, 101 325 Pa, no wind, level ground.
//!
//! `cargo run --release -p carry-lab --example ground_joint [--no-cv] [--weight=W] [--rows]`
//! (`--rows`: after the cross-validation, each chart row's total error, in sample and held
//! out, for the seed's `fairway` and for `fairway-joint`)
use carry_core::Scene;
use carry_core::aero::AeroModel;
use carry_core::ground::{CraterLaw, Surface, Turf};
use carry_lab::drives;
use carry_lab::ground_drives::{self as gd, BandFigures, Landing};
use carry_lab::ground_fit::{
    ChartRow, RollRow, calibrate_fairway, chart_scene, mean_abs, parse_chart, turf_line,
};
use carry_lab::ground_joint::{self as gj, CHART_WEIGHT};

/// Roll bands, total and topped (TrackMan carry + model roll) of `rows` with rolls `m`.
fn drive_figures(name: &str, rows: &[Landing], m: &[f64]) {
    let b = gd::band_figures(rows, m, |_| true);
    let totals: Vec<f64> = rows.iter().zip(m).map(|(l, r)| l.carry_m + r).collect();
    let (t, tb, _) = gd::total_error(rows, &totals, |_| true);
    let (tt, ttb, n) = gd::total_error(rows, &totals, Landing::topped);
    let cells: Vec<String> = b
        .iter()
        .map(|x: &BandFigures| format!("{:.1} ({:+.1})", x.mean_abs_yd, x.bias_yd))
        .collect();
    println!(
        "{name:28} bands {} | worst {:.1} yd | total {:.2} % ({:+.2}) | topped {:.1} % ({:+.1}, {n} rows) | fit cost {:.2} yd",
        cells.join(", "),
        b.iter().map(|x| x.mean_abs_yd).fold(0.0, f64::max),
        100.0 * t,
        100.0 * tb,
        100.0 * tt,
        100.0 * ttb,
        gd::fit_cost(rows, m)
    );
}

/// Drives' figures for the summary: worst band (yd), total (%), topped (%), and the total
/// of each session block (%).
fn drive_summary(rows: &[Landing], m: &[f64]) -> (f64, f64, f64, Vec<f64>) {
    let b = gd::band_figures(rows, m, |_| true);
    let totals: Vec<f64> = rows.iter().zip(m).map(|(l, r)| l.carry_m + r).collect();
    let (t, _, _) = gd::total_error(rows, &totals, |_| true);
    let (tt, _, _) = gd::total_error(rows, &totals, Landing::topped);
    let mut ids: Vec<usize> = rows.iter().map(Landing::session).collect();
    ids.sort_unstable();
    ids.dedup();
    let by_session = ids
        .iter()
        .map(|s| 100.0 * gd::total_error(rows, &totals, |l| l.session() == *s).0)
        .collect();
    (
        b.iter().map(|x| x.mean_abs_yd).fold(0.0, f64::max),
        100.0 * t,
        100.0 * tt,
        by_session,
    )
}

fn chart_total(rows: &[RollRow]) -> f64 {
    mean_abs(rows.iter().map(RollRow::total_error_yd))
}

fn chart_figures(name: &str, rows: &[RollRow]) {
    let worst = rows
        .iter()
        .map(|r| r.total_error_yd().abs())
        .fold(0.0, f64::max);
    println!(
        "{name:28} chart: total {:.2} yd (worst {:.1}), roll {:.2} yd, carry {:.2} yd",
        mean_abs(rows.iter().map(RollRow::total_error_yd)),
        worst,
        mean_abs(rows.iter().map(RollRow::roll_error_yd)),
        mean_abs(rows.iter().map(|r| r.carry_yd.1 - r.carry_yd.0))
    );
}

fn main() -> Result<(), String> {
    let weight = std::env::args()
        .find_map(|a| a.strip_prefix("--weight=").map(str::to_owned))
        .map_or(Ok(CHART_WEIGHT), |w| {
            w.parse::<f64>().map_err(|e| e.to_string())
        })?;
    let cv = !std::env::args().any(|a| a == "--no-cv");
    let per_row = std::env::args().any(|a| a == "--rows");
    let air = Scene {
        aero: AeroModel::drives_2026(),
        ..chart_scene(Surface::FairwayFirm)
    };
    let all = drives::read_shared()?;
    let landings = gd::landings(&all, &air)?;
    let indoor_rows: Vec<Landing> = landings.iter().filter(|l| !l.outdoors).cloned().collect();
    let indoor = |l: &Landing| !l.outdoors;
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../tests/data/trackman_driver_optimizer_2010.csv"
    );
    let chart: Vec<ChartRow> =
        parse_chart(&std::fs::read_to_string(path).map_err(|e| e.to_string())?)?;
    println!(
        "{} indoor drives, {} chart rows; chart weight {weight}",
        indoor_rows.len(),
        chart.len()
    );

    // Before, in sample: the two presets on both data sets.
    let trackman = Surface::<f64>::FairwayTrackman
        .turf()
        .map_err(|e| e.to_string())?;
    let firm = Surface::<f64>::FairwayFirm
        .turf()
        .map_err(|e| e.to_string())?;
    let preset = Surface::<f64>::FairwayJoint
        .turf()
        .map_err(|e| e.to_string())?;
    println!("\nin sample (indoor drives: TrackMan carry + model roll; chart: flown end to end)");
    let mut in_sample = Vec::new();
    let mut chart_in_sample = Vec::new();
    for (name, t) in [
        ("fairway", firm),
        ("fairway-trackman", trackman),
        ("fairway-joint", preset),
    ] {
        let m = gd::rolls(&indoor_rows, &gd::on_ground(&air, Surface::Custom(t))?);
        drive_figures(name, &indoor_rows, &m);
        let c = gj::chart_rows(&chart, &air, t)?;
        chart_figures(name, &c);
        in_sample.push((drive_summary(&indoor_rows, &m), chart_total(&c)));
        chart_in_sample.push(c);
    }
    println!("fairway-joint preset: {}", turf_line(&preset));

    // The joint fit on every row.
    let starts = [
        trackman,
        Turf {
            crater_law: CraterLaw::NormalTangential,
            ..firm
        },
    ];
    let (joint, cost) = gj::fit_joint(&landings, &air, &chart, &starts, &indoor, weight)?;
    println!("\njoint fit: {} (cost {cost:.3} yd)", turf_line(&joint));
    let m = gd::rolls(&indoor_rows, &gd::on_ground(&air, Surface::Custom(joint))?);
    drive_figures("joint", &indoor_rows, &m);
    chart_figures("joint", &gj::chart_rows(&chart, &air, joint)?);
    let ends = gd::totals_end_to_end(&indoor_rows, &gd::on_ground(&air, Surface::Custom(joint))?);
    let (e, eb, _) = gd::total_error(&indoor_rows, &ends, |_| true);
    println!(
        "joint, drives flown end to end: total {:.2} % ({:+.2})",
        100.0 * e,
        100.0 * eb
    );
    if !cv {
        return Ok(());
    }

    // Before, held out: the chart's ρ₀ leave-one-out (fairway) ...
    let fit = calibrate_fairway(&chart, &chart_scene(Surface::FairwayFirm))?;
    let loo_total: Vec<f64> = fit
        .rows
        .iter()
        .zip(&fit.leave_one_out_yd)
        .map(|(r, roll)| r.carry_yd.1 - r.carry_yd.0 + roll)
        .collect();
    println!(
        "\nheld out, before: fairway (rho0 fitted to the chart's rolls), chart total {:.2} yd (worst {:.1})",
        mean_abs(loo_total.iter().copied()),
        loo_total.iter().fold(0.0_f64, |w, e| w.max(e.abs()))
    );
    // ... and the drives' session CV (fairway-trackman's own fit).
    let folds = gd::cross_validate(&landings, &air, starts[0])?;
    let rows: Vec<Landing> = folds.iter().flat_map(|f| f.rows.clone()).collect();
    let m: Vec<f64> = folds.iter().flat_map(|f| f.rolls_m.clone()).collect();
    drive_figures("before: drives session CV", &rows, &m);
    let trackman_cv = drive_summary(&rows, &m);

    // After, held out both ways.
    let v = gj::cross_validate(&landings, &air, &chart, &starts, weight, |s| {
        eprintln!("{s}");
    })?;
    let rows: Vec<Landing> = v.sessions.iter().flat_map(|f| f.rows.clone()).collect();
    let m: Vec<f64> = v.sessions.iter().flat_map(|f| f.rolls_m.clone()).collect();
    println!();
    for f in &v.sessions {
        println!(
            "session {} held out ({} rows): {}",
            f.held_out,
            f.rows.len(),
            turf_line(&f.turf)
        );
    }
    drive_figures("joint: drives session CV", &rows, &m);
    let held: Vec<RollRow> = v.chart.iter().map(|(_, r)| r.clone()).collect();
    chart_figures("joint: chart leave-one-out", &held);
    let kappas: Vec<f64> = v.chart.iter().map(|(t, _)| t.crater_scale).collect();
    println!(
        "chart leave-one-out turfs: kappa {:.3}–{:.3}",
        kappas.iter().copied().fold(f64::INFINITY, f64::min),
        kappas.iter().copied().fold(0.0, f64::max)
    );
    let joint_cv = drive_summary(&rows, &m);

    // Side by side: each named fairway held out as it is fitted. `fairway`'s rho0 sees only
    // the chart (its drive figures are held out as they stand), `fairway-trackman` only
    // the drives (its chart figure is held out as it stands); `fairway-joint` both.
    let held_out = [
        (&in_sample[0].0, mean_abs(loo_total.iter().copied())),
        (&trackman_cv, in_sample[1].1),
        (&joint_cv, chart_total(&held)),
    ];
    println!(
        "\nsummary | chart total in sample / held out (yd) | drives held out: total (%), by session | worst band (yd) | topped (%)"
    );
    for (i, name) in ["fairway", "fairway-trackman", "fairway-joint"]
        .iter()
        .enumerate()
    {
        let (d, chart_ho) = held_out[i];
        let sessions: Vec<String> = d.3.iter().map(|x| format!("{x:.2}")).collect();
        println!(
            "{name:18} | {:.2} / {chart_ho:.2} | {:.2} ({}) | {:.1} | {:.1}",
            in_sample[i].1,
            d.1,
            sessions.join(" / "),
            d.0,
            d.2
        );
    }
    if per_row {
        // fit.rows, the in-sample rows and the held-out rows are all in the chart's order.
        println!(
            "\nper chart row: model total - chart total (yd) | fairway in sample / held out (rho0) | fairway-joint in sample / held out (joint fit)"
        );
        for (i, h) in held.iter().enumerate() {
            if fit.rows[i].label != h.label || chart_in_sample[0][i].label != h.label {
                return Err(format!("chart row {i}: the row orders differ"));
            }
            let err = |r: &RollRow| r.total_yd.1 - r.total_yd.0;
            println!(
                "{:24} chart {:6.1} | {:+6.1} / {:+6.1} | {:+6.1} / {:+6.1}",
                h.label,
                h.total_yd.0,
                err(&chart_in_sample[0][i]),
                loo_total[i],
                err(&chart_in_sample[2][i]),
                err(h)
            );
        }
    }
    Ok(())
}
