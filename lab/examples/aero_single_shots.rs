//! Issue 35: the default aerodynamics on the single TrackMan drives
//! (`../shared/data/trackman_amateur_drives.csv`, read where it lies), before and after a
//! fit on the drives together with the tour table and the 2010 chart, cross-validated by
//! session; the outdoor rows with a weather estimated per session. docs/aero.md, "Issue 35".
//!
//! ```sh
//! # a model's errors (tour2023, quintavalla, or nine coefficients a,b,...):
//! cargo run --release -p carry-lab --example aero_single_shots -- evaluate [MODEL]
//! # fit on the premium indoor drives + both tables (table rows weighted W each), then
//! # the session cross-validation (one refit per held-out block of 1,000 rows):
//! cargo run --release -p carry-lab --example aero_single_shots -- fit [W] [--cv]
//! # the outdoor premium rows: one air density and wind per session, aerodynamics held:
//! cargo run --release -p carry-lab --example aero_single_shots -- weather [MODEL]
//! ```

use carry_core::aero::{AeroModel, ModernAero};
use carry_core::flight::Integrator;
use carry_io::units::Units;
use carry_lab::drives::{self, BallKind};
use carry_lab::fit::flight::{AeroFamily, AeroProblem, ShotRow};
use carry_lab::fit::request::{Conditions, read_rows};
use carry_lab::fit::single_shots::{
    CarryErrors, DriveRow, SPEED_BANDS_MPH, SPIN_BANDS_RPM, by_band, carries, drive_rows,
    fit_weather, in_weather, premium_indoors, screened, session_cross_validation, standard_air,
    with_side,
};
use carry_lab::fit::solve;
use std::path::PathBuf;

/// The drives' integrator: Dormand–Prince at 1e-9 (carry within 1e-8 relative of the
/// tables' 1e-11, 2.5× faster: 15 µs a flight).
fn integrator() -> Integrator<f64> {
    Integrator::dormand_prince(1e-9)
}

fn table(name: &str) -> Vec<ShotRow> {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../shared/data")
        .join(name);
    let conditions = Conditions {
        temperature_c: Some(21.1),
        humidity_pct: Some(50.0),
        pressure_pa: Some(101_325.0),
        ..Conditions::default()
    };
    read_rows(&path, Units::Si, &conditions)
        .map(|(rows, _)| rows)
        .unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn model_named(arg: Option<&String>) -> AeroModel<f64> {
    match arg.map(String::as_str) {
        None => AeroModel::tour_2023(),
        Some(name) if AeroModel::<f64>::named(name).is_some() => AeroModel::named(name).unwrap(),
        Some(list) => {
            let v: Vec<f64> = list.split(',').map(|x| x.trim().parse().unwrap()).collect();
            AeroModel::Modern(ModernAero::from_array(v.try_into().unwrap()))
        }
    }
}

fn pct(x: f64) -> String {
    format!("{x:+.1}")
}

/// The band tables (spin, ball speed) of `rows` with predictions `pred`.
fn bands(title: &str, rows: &[DriveRow], pred: &[f64]) {
    let all = CarryErrors::of(pred.iter().zip(rows).map(|(&p, r)| (p, r.row.carry_m)));
    println!(
        "\n{title}: {} rows, carry mean |err| {:.2} %, bias {:+.2} %, median {:+.2} %",
        all.rows, all.mean_abs_pct, all.mean_pct, all.median_pct
    );
    for limit in [5.0, 10.0, 20.0] {
        let n = pred
            .iter()
            .zip(rows)
            .filter(|(p, r)| (100.0 * (*p - r.row.carry_m) / r.row.carry_m).abs() > limit)
            .count();
        print!("|err| > {limit} %: {n} rows; ");
    }
    println!();
    println!("| spin rpm | rows | mean \\|err\\| % | mean % | median % |");
    println!("|---|---:|---:|---:|---:|");
    for ((lo, hi), e) in
        SPIN_BANDS_RPM
            .iter()
            .zip(by_band(rows, pred, |r| r.spin_rpm, &SPIN_BANDS_RPM))
    {
        if e.rows > 0 {
            println!(
                "| {lo:.0}–{hi:.0} | {} | {:.2} | {} | {} |",
                e.rows,
                e.mean_abs_pct,
                pct(e.mean_pct),
                pct(e.median_pct)
            );
        }
    }
    println!("| ball mph | rows | mean \\|err\\| % | mean % | median % |");
    println!("|---|---:|---:|---:|---:|");
    for ((lo, hi), e) in
        SPEED_BANDS_MPH
            .iter()
            .zip(by_band(rows, pred, |r| r.ball_speed_mph, &SPEED_BANDS_MPH))
    {
        if e.rows > 0 {
            println!(
                "| {lo:.0}–{hi:.0} | {} | {:.2} | {} | {} |",
                e.rows,
                e.mean_abs_pct,
                pct(e.mean_pct),
                pct(e.median_pct)
            );
        }
    }
}

fn tables_line(model: &AeroModel<f64>, tour: &[ShotRow], chart: &[ShotRow]) {
    for (name, rows) in [("tour 2023", tour), ("2010 chart", chart)] {
        let pred = carries(model, rows, &Integrator::dormand_prince(1e-11));
        let e: Vec<f64> = pred
            .iter()
            .zip(rows)
            .map(|(p, r)| 100.0 * (p - r.carry_m) / r.carry_m)
            .collect();
        #[allow(clippy::cast_precision_loss)]
        let mean = e.iter().map(|x| x.abs()).sum::<f64>() / e.len() as f64;
        let worst = e.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        println!("{name}: carry mean |err| {mean:.2} %, worst {worst:.2} %");
    }
}

fn evaluate(model: &AeroModel<f64>, all: &[DriveRow]) {
    let premium = premium_indoors(all);
    let rows: Vec<ShotRow> = all.iter().map(|r| r.row.clone()).collect();
    let pred = carries(model, &rows, &integrator());
    let pick = |f: &dyn Fn(&DriveRow) -> bool| -> (Vec<DriveRow>, Vec<f64>) {
        all.iter()
            .zip(&pred)
            .filter(|(r, _)| f(r))
            .map(|(r, &p)| (r.clone(), p))
            .unzip()
    };
    let (r, p) = pick(&|r| r.ball == BallKind::Premium && !r.outdoors);
    assert_eq!(r.len(), premium.len());
    bands("premium, indoors (the fit's rows)", &r, &p);
    let (r, p) = pick(&|r| r.ball != BallKind::Premium && !r.outdoors);
    bands("other balls, indoors", &r, &p);
    let (r, p) = pick(&|r| r.ball == BallKind::Premium && r.outdoors);
    bands("premium, tracked outdoors (standard air, no wind)", &r, &p);
    let (r, p) = pick(&|r| r.outdoors && r.ball != BallKind::Premium);
    bands("other balls, tracked outdoors", &r, &p);
}

fn print_parameters(p: &[f64]) {
    println!(
        "coefficients: {}",
        p.iter()
            .map(|x| format!("{x:.4}"))
            .collect::<Vec<_>>()
            .join(",")
    );
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let all = drive_rows(
        &drives::read_shared().expect("the shared drives"),
        standard_air(),
    );
    let tour = table("trackman_tour_2023.csv");
    let chart = table("trackman_driver_optimizer_2010.csv");
    match args.first().map(String::as_str) {
        Some("evaluate") | None => {
            let model = model_named(args.get(1));
            evaluate(&model, &all);
            tables_line(&model, &tour, &chart);
        }
        Some("fit") => {
            let w: f64 = args
                .get(1)
                .filter(|a| !a.starts_with("--"))
                .map_or(20.0, |a| a.parse().unwrap());
            let cv = args.iter().any(|a| a == "--cv");
            let premium = premium_indoors(&all);
            let reference = carries(
                &AeroModel::tour_2023(),
                &premium.iter().map(|r| r.row.clone()).collect::<Vec<_>>(),
                &integrator(),
            );
            let premium = screened(&premium, &reference);
            let mut tables: Vec<ShotRow> = tour.iter().chain(&chart).cloned().collect();
            for r in &mut tables {
                r.weight = w;
            }
            let start = AeroFamily::Modern
                .parameters(&AeroModel::tour_2023())
                .unwrap();
            let mut problem = AeroProblem::new(AeroFamily::Modern);
            problem.integrator = integrator();
            // `--bound I:LO:HI` replaces parameter I's bounds (e.g. S_low's, 8).
            for a in args.iter().filter_map(|a| a.strip_prefix("--bound=")) {
                let v: Vec<f64> = a.split(':').map(|x| x.parse().unwrap()).collect();
                #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
                let i = v[0] as usize;
                problem.bounds[i] = (v[1], v[2]);
            }
            let mut start = start;
            for (x, (lo, hi)) in start.iter_mut().zip(&problem.bounds) {
                *x = x.clamp(*lo + 1e-6 * (hi - lo), *hi - 1e-6 * (hi - lo));
            }
            let mut rows: Vec<ShotRow> = premium.iter().map(|r| r.row.clone()).collect();
            rows.extend(tables.iter().cloned());
            let t = std::time::Instant::now();
            let solved = solve(&problem, &rows, &start).unwrap();
            println!(
                "fit: {} drives + {} table rows (weight {w} each), {:.0} s, {}",
                premium.len(),
                tables.len(),
                t.elapsed().as_secs_f64(),
                solved.termination
            );
            print_parameters(&solved.parameters);
            let model = AeroFamily::Modern.model(&solved.parameters);
            let before = carries(
                &AeroModel::tour_2023(),
                &premium.iter().map(|r| r.row.clone()).collect::<Vec<_>>(),
                &integrator(),
            );
            bands("before (tour2023)", &premium, &before);
            evaluate(&model, &all);
            tables_line(&model, &tour, &chart);
            if cv {
                let held =
                    session_cross_validation(&problem, &premium, &tables, &solved.parameters)
                        .unwrap();
                let mut pred = vec![f64::NAN; premium.len()];
                for h in &held {
                    print!("without session {}: ", h.session);
                    print_parameters(&h.parameters);
                    let idx = premium
                        .iter()
                        .enumerate()
                        .filter(|(_, r)| r.session == h.session)
                        .map(|(i, _)| i);
                    for (i, c) in idx.zip(&h.carry_m) {
                        pred[i] = *c;
                    }
                    let m = AeroFamily::Modern.model(&h.parameters);
                    tables_line(&m, &tour, &chart);
                }
                bands(
                    "session cross-validated (premium, indoors)",
                    &premium,
                    &pred,
                );
            }
        }
        Some("weather") => {
            let model = model_named(args.get(1));
            let outdoor: Vec<DriveRow> = all
                .iter()
                .filter(|r| r.outdoors && r.ball == BallKind::Premium)
                .cloned()
                .collect();
            let mut sessions: Vec<usize> = outdoor.iter().map(|r| r.session).collect();
            sessions.dedup();
            let (mut before, mut after) = (Vec::new(), Vec::new());
            let mut ordered = Vec::new();
            println!("| session | rows | density kg/m³ | tail wind m/s | cross wind m/s |");
            println!("|---|---:|---:|---:|---:|");
            for s in sessions {
                let rows: Vec<DriveRow> =
                    outdoor.iter().filter(|r| r.session == s).cloned().collect();
                let fit_rows = with_side(&rows);
                let (w, _) = fit_weather(&model, &fit_rows, &integrator()).unwrap();
                println!(
                    "| {s} | {} | {:.3} | {:+.2} | {:+.2} |",
                    rows.len(),
                    w.density_kgm3,
                    w.tail_wind_mps,
                    w.cross_wind_mps
                );
                let plain: Vec<ShotRow> = rows.iter().map(|r| r.row.clone()).collect();
                before.extend(carries(&model, &plain, &integrator()));
                after.extend(carries(&model, &in_weather(&plain, w), &integrator()));
                ordered.extend(rows);
            }
            bands("outdoor premium, standard air", &ordered, &before);
            bands(
                "outdoor premium, per-session weather (in sample)",
                &ordered,
                &after,
            );
        }
        Some(other) => panic!("unknown mode {other}"),
    }
}
