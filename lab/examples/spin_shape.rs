//! Issue 36 through issue 35's aerodynamics: why the spin fitted from the flight is biased
//! by spin band, and the aerodynamic fit with the inverse's spin error as a target
//! (docs/launch_fit.md §4, docs/aero.md). The drives are read where they lie.
//!
//! ```sh
//! # per spin band, the held-out drives2026 flying TrackMan's launch: summary residuals,
//! # sensitivities to spin, the linearised spin error against the launch fit's (~1 min):
//! cargo run --release -p carry-lab --example spin_shape -- diagnose
//! # refit per held-out session (all five, or --folds=2,4), drives' apex/landing/time σ from
//! # data (--sigma-data), the linearised spin error as a target of 1σ S (--spin-sigma=S):
//! cargo run --release -p carry-lab --example spin_shape -- cv --sigma-data --spin-sigma=0.05
//! # the drives' carry σ (relative; default 1.5 %): --carry-sigma=0.01
//! # the same fit on every session (the default's coefficients): add --full (--folds=none:
//! # no cross-validation)
//! # leave-one-out over the 53 table rows with the drives in the fit (the default's
//! # objective: --sigma-data --carry-sigma=0.01 --spin-sigma=0.03): each row held out in
//! # turn, the refit linearised at the default (one Gauss–Newton step, warm start), the row
//! # flown with the refit; --solve=I,J also refits rows I, J (0-based) in full (~1 min each):
//! cargo run --release -p carry-lab --example spin_shape -- loo --sigma-data --carry-sigma=0.01 --spin-sigma=0.03
//! # another model than the default (nine coefficients, e.g. a `cv --full` fit): --start=A,B,…
//! ```

use carry_core::Scene;
use carry_core::aero::AeroModel;
use carry_core::flight::Integrator;
use carry_core::launch_fit::Settings;
use carry_io::units::Units;
use carry_lab::drives::{self, BallKind, Drive};
use carry_lab::fit::flight::{AeroFamily, AeroProblem, ShotRow};
use carry_lab::fit::request::{Conditions, read_rows};
use carry_lab::fit::single_shots::{
    CarryErrors, DriveRow, SPEED_BANDS_MPH, SPIN_BANDS_RPM, by_band, carries, drive_rows,
    premium_indoors, screened, standard_air,
};
use carry_lab::fit::spin_target::{
    INVERSE_SIGMA, SpinRow, SpinTargetProblem, gain_of, jacobian, spin_gain,
};
use carry_lab::fit::{residuals, solve};
use carry_lab::launch_drives::{
    ALL, DRIVES_2026_WITHOUT_SESSION, Noise, Shot, SpinError, SpinSummary, held_out_model,
    noise_from_residuals, summary_residuals,
};
use nalgebra034::{DMatrix, DVector};
use rayon::prelude::*;
use std::collections::HashMap;
use std::path::PathBuf;

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

fn scene_with(aero: AeroModel<f64>) -> Scene<f64> {
    Scene {
        aero,
        air: standard_air(),
        ..Scene::default()
    }
}

fn index_of(r: &DriveRow) -> usize {
    r.row
        .label
        .strip_prefix("drive ")
        .and_then(|x| x.parse::<usize>().ok())
        .map_or(usize::MAX, |i| i - 1)
}

/// The premium indoor shots of docs/launch_fit.md §4.
fn shots_of(drives: &[Drive]) -> Vec<Shot> {
    drives
        .iter()
        .filter(|d| !d.tracked_outdoors() && d.ball == BallKind::Premium)
        .filter_map(Shot::of)
        .collect()
}

/// Held-out spin: each shot of `session` fitted with `model` (fitted without it), the
/// summaries' σ from the model's residuals on the other sessions.
fn held_out_spin(shots: &[Shot], session: usize, model: AeroModel<f64>) -> Vec<SpinError> {
    let scene = scene_with(model);
    let residuals: Vec<[f64; 5]> = shots
        .par_iter()
        .filter(|x| x.session != session)
        .filter_map(|x| summary_residuals(x, &scene).ok())
        .collect();
    let noise = noise_from_residuals(&residuals, Noise::RADAR);
    let settings = Settings::default();
    shots
        .par_iter()
        .filter(|s| s.session == session)
        .filter_map(|s| {
            s.fit(&scene, &settings, &noise, ALL, false)
                .ok()
                .map(|f| SpinError::of(s, &f))
        })
        .collect()
}

fn spin_table(errors: &[SpinError], sessions: &[(usize, Vec<SpinError>)]) {
    let all = SpinSummary::of(errors);
    println!(
        "\nheld-out spin: {} fitted, mean |err| {:.2} %, bias {:+.2} %, median {:+.2} %, axis {:.2}°, within 1σ {:.2}",
        all.rows,
        all.mean_abs_pct,
        all.bias_pct,
        all.median_pct,
        all.axis_mean_abs_deg,
        all.spin_within
    );
    println!("| spin rpm | rows | mean \\|err\\| | bias | median |");
    println!("|---|---:|---:|---:|---:|");
    for (&(lo, hi), e) in SPIN_BANDS_RPM.iter().zip(SpinSummary::by_band(
        errors,
        |e| e.spin_rpm,
        &SPIN_BANDS_RPM,
    )) {
        if e.rows > 0 {
            println!(
                "| {lo:.0}–{hi:.0} | {} | {:.1} % | {:+.1} % | {:+.1} % |",
                e.rows, e.mean_abs_pct, e.bias_pct, e.median_pct
            );
        }
    }
    println!("| ball mph | rows | mean \\|err\\| | bias | median |");
    println!("|---|---:|---:|---:|---:|");
    for (&(lo, hi), e) in SPEED_BANDS_MPH.iter().zip(SpinSummary::by_band(
        errors,
        |e| e.ball_speed_mph,
        &SPEED_BANDS_MPH,
    )) {
        if e.rows > 0 {
            println!(
                "| {lo:.0}–{hi:.0} | {} | {:.1} % | {:+.1} % | {:+.1} % |",
                e.rows, e.mean_abs_pct, e.bias_pct, e.median_pct
            );
        }
    }
    for (s, e) in sessions {
        let m = SpinSummary::of(e);
        println!(
            "session {s}: {} fitted, spin {:.1} % (bias {:+.1} %), axis {:.2}°",
            m.rows, m.mean_abs_pct, m.bias_pct, m.axis_mean_abs_deg
        );
    }
}

fn carry_table(title: &str, rows: &[DriveRow], pred: &[f64]) {
    let all = CarryErrors::of(pred.iter().zip(rows).map(|(&p, r)| (p, r.row.carry_m)));
    println!(
        "\n{title}: {} rows, carry mean |err| {:.2} %, bias {:+.2} %, median {:+.2} %",
        all.rows, all.mean_abs_pct, all.mean_pct, all.median_pct
    );
    println!("| spin rpm | rows | mean \\|err\\| | mean | median |");
    println!("|---|---:|---:|---:|---:|");
    for ((lo, hi), e) in
        SPIN_BANDS_RPM
            .iter()
            .zip(by_band(rows, pred, |r| r.spin_rpm, &SPIN_BANDS_RPM))
    {
        if e.rows > 0 {
            println!(
                "| {lo:.0}–{hi:.0} | {} | {:.2} % | {:+.2} % | {:+.2} % |",
                e.rows, e.mean_abs_pct, e.mean_pct, e.median_pct
            );
        }
    }
}

fn tables_line(model: &AeroModel<f64>, tour: &[ShotRow], chart: &[ShotRow]) -> String {
    let mut out = String::new();
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
        out += &format!("{name} {mean:.2} % (worst {worst:.2} %); ");
    }
    out
}

fn diagnose(all: &[DriveRow], shots: &[Shot]) {
    let premium = premium_indoors(all);
    let by_index: HashMap<usize, &Shot> = shots.iter().map(|s| (s.index, s)).collect();
    // Per shot: the residuals (model − TrackMan: carry %, apex m, landing °, time s, side m),
    // the spin column of J (per 1,000 rpm), the linearised spin error.
    struct Row {
        spin_rpm: f64,
        mph: f64,
        r: [f64; 5],
        ds: [f64; 5],
        lin: f64,
        contrib: [f64; 5],
    }
    let rows: Vec<Row> = premium
        .par_iter()
        .filter_map(|d| {
            let shot = by_index.get(&index_of(d))?;
            let model = held_out_model(d.session);
            let side = shot.summaries[2];
            let h =
                carry_lab::fit::flight::predict(&model, &d.row.launch, &d.row.air, &integrator())
                    .ok()?;
            let obs = [
                d.row.carry_m,
                d.row.apex_m?,
                d.row.land_angle_deg?,
                d.row.flight_time_s?,
                side,
            ];
            let j = jacobian(&model, &d.row, &integrator())?;
            let spin = d.spin_rpm * std::f64::consts::TAU / 60.0;
            let g = gain_of(&j, &INVERSE_SIGMA, spin)?;
            let r: [f64; 5] = core::array::from_fn(|q| h[q] - obs[q]);
            let contrib: [f64; 5] = core::array::from_fn(|q| g[q] * r[q]);
            let per_krpm = 1_000.0 * std::f64::consts::TAU / 60.0;
            Some(Row {
                spin_rpm: d.spin_rpm,
                mph: d.ball_speed_mph,
                r: [100.0 * r[0] / obs[0], r[1], r[2], r[3], r[4]],
                ds: core::array::from_fn(|q| j[(q, 3)] * per_krpm),
                lin: contrib.iter().sum(),
                contrib,
            })
        })
        .collect();
    // The launch fit's actual errors, held out (σ from data), for the same bands.
    let mut actual = Vec::new();
    for s in 0..DRIVES_2026_WITHOUT_SESSION.len() {
        actual.extend(held_out_spin(shots, s, held_out_model(s)));
    }
    println!(
        "\n## Held-out drives2026 flying TrackMan's launch ({} rows; σ of the inverse: carry 2.2 m, apex 0.7 m, landing 1.3°, time 0.09 s, side 0.8 m)\n",
        rows.len()
    );
    println!(
        "| spin rpm | rows | carry | apex | landing | time | ∂carry | ∂apex | ∂landing | ∂time /1,000 rpm | spin error linearised: carry + apex + landing + time + side = total | launch fit (bias) |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|");
    let band = |title: String, pick: &dyn Fn(&Row) -> bool, act: &dyn Fn(&SpinError) -> bool| {
        let g: Vec<&Row> = rows.iter().filter(|r| pick(r)).collect();
        if g.is_empty() {
            return;
        }
        #[allow(clippy::cast_precision_loss)]
        let n = g.len() as f64;
        let m = |f: &dyn Fn(&Row) -> f64| g.iter().map(|r| f(r)).sum::<f64>() / n;
        let a = SpinSummary::of(actual.iter().filter(|e| act(e)));
        println!(
            "| {title} | {} | {:+.2} % | {:+.2} m | {:+.2}° | {:+.3} s | {:.1} m | {:.2} m | {:.2}° | {:.3} s | {:+.1} {:+.1} {:+.1} {:+.1} {:+.1} = **{:+.1} %** | {:+.1} % |",
            g.len(),
            m(&|r| r.r[0]),
            m(&|r| r.r[1]),
            m(&|r| r.r[2]),
            m(&|r| r.r[3]),
            m(&|r| r.ds[0]),
            m(&|r| r.ds[1]),
            m(&|r| r.ds[2]),
            m(&|r| r.ds[3]),
            100.0 * m(&|r| r.contrib[0]),
            100.0 * m(&|r| r.contrib[1]),
            100.0 * m(&|r| r.contrib[2]),
            100.0 * m(&|r| r.contrib[3]),
            100.0 * m(&|r| r.contrib[4]),
            100.0 * m(&|r| r.lin),
            a.bias_pct
        );
    };
    for &(lo, hi) in &SPIN_BANDS_RPM {
        band(
            format!("{lo:.0}–{hi:.0}"),
            &|r| (lo..hi).contains(&r.spin_rpm),
            &|e| (lo..hi).contains(&e.spin_rpm),
        );
    }
    for &(lo, hi) in &SPEED_BANDS_MPH {
        band(
            format!("{lo:.0}–{hi:.0} mph"),
            &|r| (lo..hi).contains(&r.mph),
            &|e| (lo..hi).contains(&e.ball_speed_mph),
        );
    }
    band("all".into(), &|_| true, &|_| true);
    #[allow(clippy::cast_precision_loss)]
    let lin_abs = rows.iter().map(|r| r.lin.abs()).sum::<f64>() / rows.len() as f64;
    println!(
        "\nlinearised mean |err| {:.2} %; launch fit {:.2} %",
        100.0 * lin_abs,
        SpinSummary::of(&actual).mean_abs_pct
    );
}

struct Options {
    sigma_data: bool,
    carry_sigma: f64,
    spin_sigma: f64,
    folds: Vec<usize>,
    full: bool,
    weight: f64,
    bounds: Vec<(usize, f64, f64)>,
    /// `loo`'s model (the modern family's nine coefficients; default `drives2026`).
    start: Option<Vec<f64>>,
}

fn training(
    premium: &[DriveRow],
    shots: &HashMap<usize, &Shot>,
    tables: &[ShotRow],
    gain_model: &AeroModel<f64>,
    hold: Option<usize>,
) -> Vec<SpinRow> {
    let mut rows: Vec<SpinRow> = premium
        .par_iter()
        .filter(|r| Some(r.session) != hold)
        .map(|r| SpinRow {
            row: r.row.clone(),
            spin: shots.get(&index_of(r)).and_then(|s| {
                spin_gain(gain_model, &r.row, &INVERSE_SIGMA, &integrator())
                    .map(|g| (s.summaries[2], g))
            }),
        })
        .collect();
    rows.extend(tables.iter().map(|t| SpinRow {
        row: t.clone(),
        spin: None,
    }));
    rows
}

fn problem_of(o: &Options, start: &[f64]) -> SpinTargetProblem {
    let mut inner = AeroProblem::new(AeroFamily::Modern);
    inner.integrator = integrator();
    inner.bounds[8] = (0.01, 0.4);
    for &(i, lo, hi) in &o.bounds {
        inner.bounds[i] = (lo, hi);
    }
    inner.initial = start.to_vec();
    SpinTargetProblem {
        inner,
        drive_sigma: o.sigma_data.then_some([o.carry_sigma, 0.7, 1.3, 0.09]),
        spin_sigma: o.spin_sigma,
    }
}

fn clamp_into(p: &[f64], bounds: &[(f64, f64)]) -> Vec<f64> {
    p.iter()
        .zip(bounds)
        .map(|(x, (lo, hi))| x.clamp(*lo + 1e-6 * (hi - lo), *hi - 1e-6 * (hi - lo)))
        .collect()
}

fn coefficients(p: &[f64]) -> String {
    p.iter()
        .map(|x| format!("{x:.4}"))
        .collect::<Vec<_>>()
        .join(",")
}

fn cv(all: &[DriveRow], shots: &[Shot], o: &Options) {
    let tour = table("trackman_tour_2023.csv");
    let chart = table("trackman_driver_optimizer_2010.csv");
    let mut tables: Vec<ShotRow> = tour.iter().chain(&chart).cloned().collect();
    for r in &mut tables {
        r.weight = o.weight;
    }
    let premium = premium_indoors(all);
    let reference = carries(
        &AeroModel::tour_2023(),
        &premium.iter().map(|r| r.row.clone()).collect::<Vec<_>>(),
        &integrator(),
    );
    let premium = screened(&premium, &reference);
    let by_index: HashMap<usize, &Shot> = shots.iter().map(|s| (s.index, s)).collect();
    println!(
        "options: σ from data {} (carry {}), spin σ {}, table weight {}, bounds {:?}",
        o.sigma_data, o.carry_sigma, o.spin_sigma, o.weight, o.bounds
    );
    if o.full {
        let model = AeroModel::drives_2026();
        let start = AeroFamily::Modern.parameters(&model).unwrap_or_default();
        let problem = problem_of(o, &start);
        let start = clamp_into(&start, &problem.inner.bounds);
        let rows = training(&premium, &by_index, &tables, &model, None);
        let t = std::time::Instant::now();
        let solved = solve(&problem, &rows, &start).expect("the fit");
        let m = AeroFamily::Modern.model(&solved.parameters);
        println!(
            "full fit ({:.0} s, {}): {}\n  {}",
            t.elapsed().as_secs_f64(),
            solved.termination,
            coefficients(&solved.parameters),
            tables_line(&m, &tour, &chart)
        );
        let pred = carries(
            &m,
            &premium.iter().map(|r| r.row.clone()).collect::<Vec<_>>(),
            &integrator(),
        );
        carry_table("in sample", &premium, &pred);
    }
    let mut pred = vec![f64::NAN; premium.len()];
    let mut spin = Vec::new();
    let mut sessions = Vec::new();
    for &s in &o.folds {
        let gain_model = held_out_model(s);
        let start = AeroFamily::Modern
            .parameters(&gain_model)
            .unwrap_or_default();
        let problem = problem_of(o, &start);
        let start = clamp_into(&start, &problem.inner.bounds);
        let rows = training(&premium, &by_index, &tables, &gain_model, Some(s));
        let t = std::time::Instant::now();
        let solved = solve(&problem, &rows, &start).expect("the fit");
        let m = AeroFamily::Modern.model(&solved.parameters);
        let held: Vec<usize> = (0..premium.len())
            .filter(|&i| premium[i].session == s)
            .collect();
        let c = carries(
            &m,
            &held
                .iter()
                .map(|&i| premium[i].row.clone())
                .collect::<Vec<_>>(),
            &integrator(),
        );
        for (&i, v) in held.iter().zip(c) {
            pred[i] = v;
        }
        let e = held_out_spin(shots, s, m);
        let sm = SpinSummary::of(&e);
        println!(
            "without session {s} ({:.0} s, {}): {}\n  {}held-out spin {:.2} % (bias {:+.2} %)",
            t.elapsed().as_secs_f64(),
            solved.termination,
            coefficients(&solved.parameters),
            tables_line(&m, &tour, &chart),
            sm.mean_abs_pct,
            sm.bias_pct
        );
        spin.extend(e.iter().copied());
        sessions.push((s, e));
    }
    let (rows, p): (Vec<DriveRow>, Vec<f64>) = premium
        .iter()
        .zip(&pred)
        .filter(|(_, p)| p.is_finite())
        .map(|(r, &p)| (r.clone(), p))
        .unzip();
    carry_table("held out by session", &rows, &p);
    spin_table(&spin, &sessions);
}

/// A held-out table row: carry error (%) of the default, of the in-sample step, held out;
/// the held-out parameters.
type Held = (f64, f64, f64, Vec<f64>);

/// Each row's own residual vector at `p` (the fit's weighted, scaled residuals).
fn row_residuals(problem: &SpinTargetProblem, rows: &[SpinRow], p: &[f64]) -> Vec<Vec<f64>> {
    rows.par_iter()
        .map(|r| residuals(problem, std::slice::from_ref(r), p).expect("a residual"))
        .collect()
}

/// Leave-one-out over the table rows with the drives in the fit (issue 35). The default is
/// the full fit's optimum; without row `t` the refit is linearised there: with `J`, `r` the
/// Jacobian (central differences, free parameters only: those on a bound stay on it) and
/// residuals of every row, `H = Σ JᵢᵀJᵢ`, `g = Σ Jᵢᵀrᵢ`, the refit moves by
/// `Δ_t = −(H − J_tᵀJ_t)⁻¹(g − J_tᵀr_t)` (the first Gauss–Newton step of a refit started
/// at the default), and row `t` is flown with `p + Δ_t`. In sample: `Δ₀ = −H⁻¹g`.
#[allow(clippy::too_many_lines)]
fn loo(all: &[DriveRow], shots: &[Shot], o: &Options, solve_rows: &[usize]) {
    let tour = table("trackman_tour_2023.csv");
    let chart = table("trackman_driver_optimizer_2010.csv");
    let mut tables: Vec<ShotRow> = tour.iter().chain(&chart).cloned().collect();
    for r in &mut tables {
        r.weight = o.weight;
    }
    let premium = premium_indoors(all);
    let reference = carries(
        &AeroModel::tour_2023(),
        &premium.iter().map(|r| r.row.clone()).collect::<Vec<_>>(),
        &integrator(),
    );
    let premium = screened(&premium, &reference);
    let by_index: HashMap<usize, &Shot> = shots.iter().map(|s| (s.index, s)).collect();
    let model = o
        .start
        .as_ref()
        .map_or_else(AeroModel::drives_2026, |p| AeroFamily::Modern.model(p));
    let p0 = AeroFamily::Modern.parameters(&model).unwrap_or_default();
    let problem = problem_of(o, &p0);
    let rows = training(&premium, &by_index, &tables, &model, None);
    let first_table = rows.len() - tables.len();
    let bounds = problem.inner.bounds.clone();
    let free: Vec<usize> = (0..p0.len())
        .filter(|&k| {
            let (lo, hi) = bounds[k];
            p0[k] - lo > 1e-6 * (hi - lo) && hi - p0[k] > 1e-6 * (hi - lo)
        })
        .collect();
    println!(
        "options: σ from data {} (carry {}), spin σ {}, table weight {}, bounds {:?}; {} drives, {} table rows; free parameters {:?}",
        o.sigma_data,
        o.carry_sigma,
        o.spin_sigma,
        o.weight,
        o.bounds,
        first_table,
        tables.len(),
        free
    );
    let t = std::time::Instant::now();
    let r0 = row_residuals(&problem, &rows, &p0);
    // Jacobian columns per row: central differences, step 1e-4 of the value.
    let columns: Vec<Vec<Vec<f64>>> = free
        .iter()
        .map(|&k| {
            let h = 1e-4 * p0[k].abs();
            let mut plus = p0.clone();
            plus[k] += h;
            let mut minus = p0.clone();
            minus[k] -= h;
            let rp = row_residuals(&problem, &rows, &plus);
            let rm = row_residuals(&problem, &rows, &minus);
            rp.iter()
                .zip(&rm)
                .map(|(a, b)| a.iter().zip(b).map(|(x, y)| (x - y) / (2.0 * h)).collect())
                .collect()
        })
        .collect();
    let n = free.len();
    let block = |i: usize| -> (DMatrix<f64>, DVector<f64>) {
        let m = r0[i].len();
        let j = DMatrix::from_fn(m, n, |a, b| columns[b][i][a]);
        let r = DVector::from_column_slice(&r0[i]);
        (j.transpose() * &j, j.transpose() * r)
    };
    let mut h_all = DMatrix::zeros(n, n);
    let mut g_all = DVector::zeros(n);
    for i in 0..rows.len() {
        let (h, g) = block(i);
        h_all += h;
        g_all += g;
    }
    println!("Jacobian and sums: {:.0} s", t.elapsed().as_secs_f64());
    let step = |h: &DMatrix<f64>, g: &DVector<f64>| -> Vec<f64> {
        let d = h.clone().cholesky().expect("positive definite").solve(g);
        let mut p = p0.clone();
        for (a, &k) in free.iter().enumerate() {
            p[k] -= d[a];
        }
        p
    };
    let p_in = step(&h_all, &g_all);
    println!(
        "in sample (one step from the default): {}",
        coefficients(&p_in)
    );
    let carry_of = |p: &[f64], row: &ShotRow| {
        carries(
            &AeroFamily::Modern.model(p),
            std::slice::from_ref(row),
            &Integrator::dormand_prince(1e-11),
        )[0]
    };
    let pct = |c: f64, row: &ShotRow| 100.0 * (c - row.carry_m) / row.carry_m;
    let held: Vec<Held> = (0..tables.len())
        .into_par_iter()
        .map(|t| {
            let (h, g) = block(first_table + t);
            let p = step(&(&h_all - h), &(&g_all - g));
            let row = &tables[t];
            (
                pct(carry_of(&p0, row), row),
                pct(carry_of(&p_in, row), row),
                pct(carry_of(&p, row), row),
                p,
            )
        })
        .collect();
    println!("\n| row | carry m | default | in sample (step) | held out | held-out S_low | k_L |");
    println!("|---|---:|---:|---:|---:|---:|---:|");
    for (row, (d, i, l, p)) in tables.iter().zip(&held) {
        println!(
            "| {} | {:.1} | {d:+.2} % | {i:+.2} % | {l:+.2} % | {:.4} | {:.4} |",
            row.label, row.carry_m, p[8], p[5]
        );
    }
    for (name, range) in [
        ("tour 2023", 0..tour.len()),
        ("2010 chart", tour.len()..tables.len()),
    ] {
        #[allow(clippy::cast_precision_loss)]
        let stats = |f: &dyn Fn(&Held) -> f64| {
            let v: Vec<f64> = held[range.clone()].iter().map(|x| f(x).abs()).collect();
            (
                v.iter().sum::<f64>() / v.len() as f64,
                v.iter().fold(0.0_f64, |m, x| m.max(*x)),
            )
        };
        let (dm, dw) = stats(&|x| x.0);
        let (im, iw) = stats(&|x| x.1);
        let (lm, lw) = stats(&|x| x.2);
        println!(
            "{name}: default {dm:.2} % (worst {dw:.2} %), in sample {im:.2} % ({iw:.2} %), held out {lm:.2} % ({lw:.2} %)"
        );
    }
    for &t in solve_rows {
        let rest: Vec<SpinRow> = rows
            .iter()
            .enumerate()
            .filter(|&(i, _)| i != first_table + t)
            .map(|(_, r)| r.clone())
            .collect();
        let start = clamp_into(&p0, &bounds);
        let s = std::time::Instant::now();
        let solved = solve(&problem, &rest, &start).expect("the refit");
        let row = &tables[t];
        println!(
            "full refit without {} ({:.0} s, {}): {} → held out {:+.2} % (one step: {:+.2} %)",
            row.label,
            s.elapsed().as_secs_f64(),
            solved.termination,
            coefficients(&solved.parameters),
            pct(carry_of(&solved.parameters, row), row),
            held[t].2
        );
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let drives = drives::read_shared().expect("the shared drives");
    let all = drive_rows(&drives, standard_air());
    let shots = shots_of(&drives);
    match args.first().map(String::as_str) {
        Some("diagnose") | None => diagnose(&all, &shots),
        Some(mode @ ("cv" | "loo")) => {
            let value = |k: &str| args.iter().find_map(|a| a.strip_prefix(k));
            let o = Options {
                sigma_data: args.iter().any(|a| a == "--sigma-data"),
                carry_sigma: value("--carry-sigma=").map_or(0.015, |v| v.parse().unwrap()),
                spin_sigma: value("--spin-sigma=").map_or(f64::INFINITY, |v| v.parse().unwrap()),
                folds: value("--folds=").map_or_else(
                    || (0..DRIVES_2026_WITHOUT_SESSION.len()).collect(),
                    |v| v.split(',').filter_map(|x| x.parse().ok()).collect(),
                ),
                full: args.iter().any(|a| a == "--full"),
                weight: value("--weight=").map_or(20.0, |v| v.parse().unwrap()),
                bounds: args
                    .iter()
                    .filter_map(|a| a.strip_prefix("--bound="))
                    .map(|a| {
                        let v: Vec<f64> = a.split(':').map(|x| x.parse().unwrap()).collect();
                        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
                        (v[0] as usize, v[1], v[2])
                    })
                    .collect(),
                start: value("--start=")
                    .map(|v| v.split(',').map(|x| x.parse().unwrap()).collect()),
            };
            if mode == "cv" {
                cv(&all, &shots, &o);
            } else {
                let solve_rows: Vec<usize> = value("--solve=").map_or_else(Vec::new, |v| {
                    v.split(',').filter_map(|x| x.parse().ok()).collect()
                });
                loo(&all, &shots, &o, &solve_rows);
            }
        }
        Some(other) => panic!("unknown mode {other}"),
    }
}
