//! `carry fit` for the aerodynamic families: recovery of known coefficients, stability under
//! noise, the calibrated default reproduced from the data, its regression table and its
//! physical plausibility.

mod common;

use carry_core::aero::{AeroModel, LinearAero, TOUR_2023};
use carry_core::flight::Integrator;
use carry_lab::fit::flight::{AeroFamily, AeroProblem, ShotRow, predict};
use carry_lab::fit::{self, FitOptions};

/// Noise-free synthetic shots flown with `model`: the 23 TrackMan launches, observing carry,
/// apex, landing angle and flight time.
fn synthetic(model: &AeroModel<f64>, noise: impl Fn(usize, usize) -> f64) -> Vec<ShotRow> {
    let Some(rows) = common::tour_2023() else {
        return Vec::new();
    };
    let integrator = Integrator::tight();
    rows.into_iter()
        .enumerate()
        .map(|(i, mut r)| {
            let [carry, apex, land, time, _] =
                predict(model, &r.launch, &r.air, &integrator).expect("flies");
            r.carry_m = carry * (1.0 + noise(i, 0));
            r.apex_m = Some(apex * (1.0 + noise(i, 1)));
            r.land_angle_deg = Some(land * (1.0 + noise(i, 2)));
            r.flight_time_s = Some(time * (1.0 + noise(i, 3)));
            r
        })
        .collect()
}

/// `problem` fitted to `rows` without leave-one-out.
fn fit_once(problem: &AeroProblem, rows: &[ShotRow]) -> fit::Fit {
    fit::fit(
        problem,
        rows,
        FitOptions {
            leave_one_out: false,
        },
        &|| {},
    )
    .expect("fits")
}

/// Relative coefficient error of the noise-free recovery of the seed family.
const RECOVERY_REL: f64 = 1e-6;

#[test]
fn recovers_the_seed_coefficients_from_noise_free_shots() {
    let truth = LinearAero::<f64>::quintavalla().to_array();
    let rows = synthetic(&AeroModel::quintavalla(), |_, _| 0.0);
    if rows.is_empty() {
        return; // ../shared absent
    }
    // Start well away from the truth.
    let mut problem = AeroProblem::new(AeroFamily::Quintavalla);
    problem.initial = vec![0.25, 0.4, 0.15, 0.6, 0.02];
    let f = fit_once(&problem, &rows);
    for (p, t) in f.values().iter().zip(truth) {
        assert!(((p - t) / t).abs() <= RECOVERY_REL, "{p} vs {t}: {f:?}");
    }
}

#[test]
fn stays_stable_with_one_percent_noise() {
    // Deterministic ±1 % noise (a fixed pseudo-random pattern).
    let noise = |i: usize, q: usize| {
        let x = ((i * 7 + q * 13) % 17) as f64 / 16.0; // 0..1
        0.02 * (x - 0.5)
    };
    let rows = synthetic(&AeroModel::tour_2023(), noise);
    if rows.is_empty() {
        return;
    }
    let f = fit_once(&AeroProblem::new(AeroFamily::Modern), &rows);
    assert!(f.converged, "{}", f.termination);
    // The refitted model flies the true model's shots to within the noise.
    let carry = f.summary_of("carry").expect("carry");
    assert!(carry.mean_abs_pct < 1.0, "{carry:?}");
    let (cd, cl, _) = match AeroFamily::Modern.model(&f.values()) {
        m @ AeroModel::Modern(_) => m.coefficients(0.15, 1.5e5),
        AeroModel::Linear(_) => unreachable!(),
    };
    let (cd0, cl0, _) = AeroModel::<f64>::tour_2023().coefficients(0.15, 1.5e5);
    assert!(
        (cd - cd0).abs() < 0.02 && (cl - cl0).abs() < 0.03,
        "{cd} {cl}"
    );
}

/// Both tables, jointly: the 23 tour rows, then the 30 rows of the 2010 chart.
fn joint_rows() -> Option<(Vec<ShotRow>, usize)> {
    let mut rows = common::tour_2023()?;
    let tour = rows.len();
    rows.extend(common::optimizer_2010()?);
    Some((rows, tour))
}

/// `tour2023` (the default before issue 35) is what `carry fit --family modern` gives on
/// both tables jointly (to the 4 significant digits it is committed with).
#[test]
fn the_calibrated_default_is_the_joint_fit_of_both_tables() {
    let Some((rows, _)) = joint_rows() else {
        return;
    };
    let f = fit_once(&AeroProblem::new(AeroFamily::Modern), &rows);
    for ((name, p), committed) in f
        .parameters
        .iter()
        .map(|p| (p.name, p.value))
        .zip(TOUR_2023)
    {
        assert!(
            ((p - committed) / committed).abs() < 5e-4,
            "{name}: fitted {p}, committed {committed}"
        );
    }
}

/// Mean and max |carry error| (%) of `predicted` carries against the rows' carries.
fn carry_errors(rows: &[ShotRow], predicted: impl Iterator<Item = f64>) -> (f64, f64) {
    let e: Vec<f64> = rows
        .iter()
        .zip(predicted)
        .map(|(r, c)| 100.0 * (c - r.carry_m).abs() / r.carry_m)
        .collect();
    (
        e.iter().sum::<f64>() / e.len() as f64,
        e.iter().copied().fold(0.0, f64::max),
    )
}

/// The cross-validation targets: the modern family refitted on both tables without each
/// row predicts that row's carry within 2 % on average on the tour table, and the chart's
/// within 1.5 % (measured: docs/aero.md).
#[test]
fn leave_one_out_carry_of_the_modern_family() {
    let Some((rows, tour)) = joint_rows() else {
        return;
    };
    let f = fit::fit(
        &AeroProblem::new(AeroFamily::Modern),
        &rows,
        FitOptions {
            leave_one_out: true,
        },
        &|| {},
    )
    .expect("fits");
    let loo: Vec<f64> = f
        .rows
        .iter()
        .map(|r| r.loo_predicted.as_ref().expect("leave-one-out")[0])
        .collect();
    let (tour_mean, tour_max) = carry_errors(&rows[..tour], loo[..tour].iter().copied());
    let (chart_mean, chart_max) = carry_errors(&rows[tour..], loo[tour..].iter().copied());
    println!(
        "leave-one-out carry: tour {tour_mean:.2} % (max {tour_max:.2} %), chart {chart_mean:.2} % (max {chart_max:.2} %)"
    );
    assert!(
        tour_mean <= 2.0 && chart_mean <= 1.5,
        "{tour_mean} {chart_mean}"
    );
}

/// The committed model's errors on both tables (docs/aero.md): the targets where
/// they are met, regression bounds where they are not (the tour table's in-sample carry;
/// docs/aero.md explains the tension between the tables): a change of the model or the
/// flight that worsens them fails here.
#[test]
fn calibrated_default_errors_on_both_tables() {
    let Some((rows, tour)) = joint_rows() else {
        return;
    };
    let integrator = Integrator::default();
    let flown = |model: &AeroModel<f64>| -> Vec<[f64; 5]> {
        rows.iter()
            .map(|r| predict(model, &r.launch, &r.air, &integrator).expect("flies"))
            .collect()
    };
    let now = flown(&AeroModel::tour_2023());
    let (tour_mean, tour_max) = carry_errors(&rows[..tour], now[..tour].iter().map(|p| p[0]));
    let (chart_mean, chart_max) = carry_errors(&rows[tour..], now[tour..].iter().map(|p| p[0]));
    let n = tour as f64;
    let apex_yd = rows[..tour]
        .iter()
        .zip(&now)
        .map(|(r, p)| (p[1] - r.apex_m.unwrap_or(p[1])).abs())
        .sum::<f64>()
        / n
        / common::YD;
    let land_deg = rows[..tour]
        .iter()
        .zip(&now)
        .map(|(r, p)| (p[2] - r.land_angle_deg.unwrap_or(p[2])).abs())
        .sum::<f64>()
        / n;
    println!(
        "tour: carry mean {tour_mean:.2} % (max {tour_max:.2} %), apex {apex_yd:.2} yd, land {land_deg:.2}°; chart: carry mean {chart_mean:.2} % (max {chart_max:.2} %)"
    );
    // Issue 21's targets for the 2010 chart: mean ≤ 1.5 %, every row ≤ 3 % (the worst row is
    // at 3.04 %: the bound is a regression bound there, docs/aero.md).
    assert!(
        chart_mean <= 1.5 && chart_max <= 3.05,
        "{chart_mean} {chart_max}"
    );
    // Tour: apex ≤ 2 yd and landing angle ≤ 2.5° (targets); carry as regression bounds.
    assert!(apex_yd < 2.0 && land_deg < 2.5, "{apex_yd} {land_deg}");
    assert!(
        tour_mean <= 1.9 && tour_max <= 4.6,
        "{tour_mean} {tour_max}"
    );
    // For scale: the seed model is ~3× worse on the tour's carry.
    let seed = flown(&AeroModel::quintavalla());
    let (seed_mean, _) = carry_errors(&rows[..tour], seed[..tour].iter().map(|p| p[0]));
    assert!(
        seed_mean > 2.0 * tour_mean,
        "seed {seed_mean} vs {tour_mean}"
    );
}

/// Physically plausible over S ∈ [0, 0.6], Re ∈ [5·10⁴, 2.5·10⁵] (issue 21's range): 0 < C_D < 0.6,
/// 0 ≤ C_L < 0.5, C_L rising with S and C_D not falling with it; a driver's spin decays
/// 1–8 %/s.
#[test]
fn calibrated_default_is_physically_plausible() {
    // drives2026 (the default, issue 35) and tour2023 (issue 21), over issue 21's range.
    for m in [
        AeroModel::<f64>::tour_2023(),
        AeroModel::<f64>::drives_2026(),
    ] {
        for i in 0..=60 {
            let s = f64::from(i) * 0.01;
            for j in 0..=40 {
                let re = 5.0e4 + f64::from(j) * 5.0e3;
                let (cd, cl, _) = m.coefficients(s, re);
                assert!(cd > 0.0 && cd < 0.6, "C_D {cd} at S {s}, Re {re}");
                assert!((0.0..0.5).contains(&cl), "C_L {cl} at S {s}, Re {re}");
                if i > 0 {
                    let (cd_before, cl_before, _) = m.coefficients(s - 0.01, re);
                    assert!(cl > cl_before && cd >= cd_before, "S {s}, Re {re}");
                }
            }
        }
        let AeroModel::Modern(c) = m else {
            panic!("both are modern")
        };
        // dω/dt / ω = −(½ρπR²·c_m·R·D/I_b)·V for a 70 m/s driver at 1.225 kg/m³.
        let (r, mass) = (0.021336_f64, 0.04593);
        let lambda = 0.5 * 1.225 * std::f64::consts::PI * r * r * c.cm_spin * r * 2.0 * r
            / (0.4 * mass * r * r);
        let per_second = lambda * 70.0;
        assert!((0.01..0.08).contains(&per_second), "{per_second}");
        assert_eq!(c.validate(), Ok(c));
    }
}

/// The default-fidelity carry of `launch` (given in f64) flown in precision `T` with the
/// default scene (the calibrated model), in metres.
fn carry_of<T: carry_core::Real>(launch: &carry_core::Launch<f64>) -> f64 {
    use carry_core::real::{lit, to_f64};
    use carry_core::{Ball, Launch, Scene, fly};
    let l = Launch::<T> {
        ball_speed_mps: lit(launch.ball_speed_mps),
        launch_angle_rad: lit(launch.launch_angle_rad),
        launch_direction_rad: lit(launch.launch_direction_rad),
        backspin_radps: lit(launch.backspin_radps),
        sidespin_radps: lit(launch.sidespin_radps),
    };
    let m = l.ball_motion().expect("launch");
    let o = fly(
        &Ball::standard(),
        &m,
        &Scene::default(),
        &Integrator::default(),
        None,
    )
    .expect("flies");
    to_f64(o.carry_m)
}

/// f32 flies the calibrated model within 1 cm of f64 at the default fidelity on the 53
/// launches of both tables (the documented f32 accuracy, docs/aero.md).
#[test]
fn calibrated_default_f32_carry_within_a_centimetre_of_f64() {
    let Some((rows, _)) = joint_rows() else {
        return;
    };
    let mut worst = 0.0_f64;
    for r in &rows {
        let fly = |f32_: bool| -> f64 {
            if f32_ {
                carry_of::<f32>(&r.launch)
            } else {
                carry_of::<f64>(&r.launch)
            }
        };
        worst = worst.max((fly(true) - fly(false)).abs());
    }
    println!("worst |f32 − f64| carry: {worst} m");
    assert!(worst < 0.01, "{worst}");
}

/// `tour2023` pinned by a committed regression table: carry, apex and landing
/// angle of the 23 tour launches at the default fidelity in f64 (fit conditions).
/// Produced by `CARRY_BLESS=1 cargo test -p carry-lab --test fit_aero regression_table`
/// when the model is changed on purpose; any other change of its flights fails here.
#[test]
fn regression_table_of_the_calibrated_default() {
    let Some(rows) = common::tour_2023() else {
        return;
    };
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tour2023_regression.csv");
    let mut text = String::from("label,carry_m,apex_m,land_angle_deg\n");
    let mut now = Vec::new();
    for r in &rows {
        let [carry, apex, land, ..] = predict(
            &AeroModel::tour_2023(),
            &r.launch,
            &r.air,
            &Integrator::default(),
        )
        .expect("flies");
        text.push_str(&format!("{},{carry:?},{apex:?},{land:?}\n", r.label));
        now.push([carry, apex, land]);
    }
    if std::env::var_os("CARRY_BLESS").is_some() {
        std::fs::create_dir_all(path.parent().expect("dir")).expect("mkdir");
        std::fs::write(&path, &text).expect("write");
        return;
    }
    let committed = std::fs::read_to_string(&path).expect("the committed table");
    let table: Vec<Vec<f64>> = committed
        .lines()
        .skip(1)
        .map(|l| {
            l.split(',')
                .skip(1)
                .map(|x| x.parse().expect("number"))
                .collect()
        })
        .collect();
    assert_eq!(table.len(), now.len());
    for ((row, got), r) in table.iter().zip(&now).zip(&rows) {
        for (a, b) in row.iter().zip(got) {
            assert!(
                (a - b).abs() <= 1e-9 * a.abs().max(1.0),
                "{}: {a} vs {b}",
                r.label
            );
        }
    }
}
