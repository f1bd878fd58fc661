//! The figures of docs/estimate.md §8 (issue 34): the estimator on the single TrackMan drives.
//!
//! Every drive with its five ball numbers and its club speed goes in (driver preset, its
//! calibrated contact, TrackMan's convention); the estimated face, path, dynamic loft and
//! attack come out and are compared with TrackMan's own club data (model − TrackMan).
//! Cross-validated by session block (`carry_lab::drives`: hold out each block of 1,000
//! consecutive rows, fit on the rest):
//!
//! 1. **the prior** — mean and sd of face, path, dynamic loft, attack, club speed (the
//!    rows' club data) and strike toe and height (the rows that carry it) — is fitted on
//!    the training blocks;
//! 2. **the σ calibration** — one factor `k` on the ball data's noise
//!    ([`Noise::launch_monitor`]), standing for the impact model's own error — is chosen on
//!    the training blocks: the `k` at which the median χ² of the most probable deliveries
//!    equals its median under the model (reduced χ² = 1, on medians: heavy tails);
//! 3. the held-out block is estimated with both and scored: mean |error| and the share of
//!    rows within the reported 1σ, per output, and the share the consistency check flags.
//!
//! The last section fits on every block: the constants of `carry_core::estimate`
//! (`DRIVER_PRIOR_*`, `DRIVER_NOISE_SCALE`). Re-run after any change of the impact model and
//! paste them (docs/estimate.md §8 says how). The drives are read where they lie
//! (`../shared/data/trackman_amateur_drives.csv`; `CARRY_DRIVES` overrides), never copied.
//!
//! ```sh
//! cargo run --release -p carry-lab --example estimate_single_shots
//! ```

use carry_core::estimate::{BallData, ClubData, Noise, Prior, Settings, Unknowns, estimate};
use carry_core::{Ball, Preset};
use carry_lab::drives::{self, Drive};
use rayon::prelude::*;

/// One usable drive: ball data (SI), the measured club speed, TrackMan's club data.
struct Row {
    session: usize,
    y: BallData<f64>,
    club_speed_mps: f64,
    /// face, path, dynamic loft, attack (deg).
    truth: [f64; 4],
}

fn rows(all: &[Drive]) -> Vec<Row> {
    all.iter()
        .filter_map(|d| {
            let [v, la, ld, spin, axis] = d.full_launch()?;
            let [speed, attack, path, loft, face] = d.full_delivery()?;
            Some(Row {
                session: d.session(),
                y: BallData {
                    ball_speed_mps: v,
                    launch_angle_rad: la.to_radians(),
                    launch_direction_rad: ld.to_radians(),
                    spin_radps: spin * core::f64::consts::PI / 30.0,
                    spin_axis_rad: axis.to_radians(),
                },
                club_speed_mps: speed,
                truth: [face, path, loft, attack],
            })
        })
        .collect()
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n == 0 {
        return f64::NAN;
    }
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// A robust centre and spread: the median and 1.4826 × the median absolute deviation (the
/// sd of a normal bulk; the club data have heavy tails — a handful of mis-tracked rows
/// would double a plain sd, e.g. dynamic loft 7.3° against 3.4°).
fn mean_sd(v: impl Iterator<Item = f64>) -> (f64, f64) {
    let v: Vec<f64> = v.collect();
    let m = median(v.clone());
    let mad = median(v.iter().map(|x| (x - m).abs()).collect());
    (m, 1.4826 * mad)
}

/// The prior fitted on `train`: robust centre and spread ([`mean_sd`]) of the club data (face, path, loft, attack,
/// speed) over the usable rows, of the strike over the rows that carry it.
fn fit_prior(train: &[&Drive]) -> Prior<f64> {
    let full: Vec<[f64; 5]> = train.iter().filter_map(|d| d.full_delivery()).collect();
    let col = |i: usize| mean_sd(full.iter().map(move |r| r[i]));
    let (speed, attack, path, loft, face) = (col(0), col(1), col(2), col(3), col(4));
    let toe = mean_sd(train.iter().filter_map(|d| d.strike_m).map(|s| s[0]));
    let height = mean_sd(train.iter().filter_map(|d| d.strike_m).map(|s| s[1]));
    let r = f64::to_radians;
    Prior {
        mean: Unknowns {
            face_angle_rad: r(face.0),
            club_path_rad: r(path.0),
            dynamic_loft_rad: r(loft.0),
            attack_angle_rad: r(attack.0),
            impact_toe_m: toe.0,
            impact_height_m: height.0,
            club_speed_mps: speed.0,
        },
        sd: Unknowns {
            face_angle_rad: r(face.1),
            club_path_rad: r(path.1),
            dynamic_loft_rad: r(loft.1),
            attack_angle_rad: r(attack.1),
            impact_toe_m: toe.1,
            impact_height_m: height.1,
            club_speed_mps: speed.1,
        },
    }
}

fn settings(prior: Prior<f64>, scale: f64) -> Settings<f64> {
    let driver = Preset::find("driver").expect("driver");
    let mut s = Settings::<f64>::typical(&driver.typical);
    s.prior = prior;
    s.noise = Noise::launch_monitor().with_ball_scaled(scale);
    s
}

/// Per row: the errors (model − TrackMan, deg) and 1σ of face, path, loft, attack, and
/// whether the consistency check passed; `None` when the estimate failed.
type Outcome = Option<([f64; 4], [f64; 4], bool, f64)>;

fn run(rows: &[&Row], s: &Settings<f64>) -> Vec<Outcome> {
    let driver = Preset::find("driver").expect("driver");
    let club = driver.spec::<f64>().validate().expect("driver");
    let ball = Ball::standard();
    rows.par_iter()
        .map(|r| {
            let c = ClubData {
                club_speed_mps: Some(r.club_speed_mps),
                ..ClubData::default()
            };
            let e = estimate(&club, &ball, &r.y, &c, s).ok()?;
            let (v, sd) = (e.value, e.sd);
            let d = f64::to_degrees;
            let value = [
                d(v.face_angle_rad),
                d(v.club_path_rad),
                d(v.dynamic_loft_rad),
                d(v.attack_angle_rad),
            ];
            let sd = [
                d(sd.face_angle_rad),
                d(sd.club_path_rad),
                d(sd.dynamic_loft_rad),
                d(sd.attack_angle_rad),
            ];
            let err = core::array::from_fn(|i| value[i] - r.truth[i]);
            // χ² relative to its median for these degrees of freedom (Wilson–Hilferty)
            let dof = f64::from(e.consistency.dof);
            let median = dof * (1.0 - 2.0 / (9.0 * dof)).powi(3);
            Some((
                err,
                sd,
                e.consistency.consistent,
                e.consistency.chi2 / median,
            ))
        })
        .collect()
}

/// Mean |error|, share within 1σ (per output), share flagged inconsistent, failures.
struct Score {
    mae: [f64; 4],
    within: [f64; 4],
    flagged: f64,
    /// The median of χ² over its median under the model (1: the noise is right).
    chi2_ratio: f64,
    failed: usize,
    n: usize,
}

fn score(out: &[Outcome]) -> Score {
    let ok: Vec<_> = out.iter().flatten().collect();
    let n = ok.len().max(1) as f64;
    let mut mae = [0.0; 4];
    let mut within = [0.0; 4];
    let mut flagged = 0.0;
    let chi2_ratio = median(ok.iter().map(|o| o.3).collect());
    for (err, sd, consistent, _) in &ok {
        for i in 0..4 {
            mae[i] += err[i].abs() / n;
            if err[i].abs() <= sd[i] {
                within[i] += 1.0 / n;
            }
        }
        if !consistent {
            flagged += 1.0 / n;
        }
    }
    Score {
        mae,
        within,
        flagged,
        chi2_ratio,
        failed: out.len() - ok.len(),
        n: ok.len(),
    }
}

/// The grid of the σ calibration.
const SCALES: [f64; 9] = [1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 5.0, 6.0];

/// The scale at which the median χ² of `rows` equals its median under the model (the
/// "reduced χ² = 1" calibration, on the median because the misfits have heavy tails):
/// log-linear interpolation between the grid's scales; with the table of every scale.
fn calibrate(rows: &[&Row], prior: Prior<f64>) -> (f64, Vec<(f64, Score)>) {
    let table: Vec<(f64, Score)> = SCALES
        .iter()
        .map(|&k| (k, score(&run(rows, &settings(prior, k)))))
        .collect();
    let mut best = SCALES[SCALES.len() - 1];
    for w in table.windows(2) {
        let ((k0, s0), (k1, s1)) = (&w[0], &w[1]);
        let (a, b) = (s0.chi2_ratio.ln(), s1.chi2_ratio.ln());
        if a >= 0.0 && b <= 0.0 {
            let t = if a > b { a / (a - b) } else { 0.0 };
            best = (k0.ln() + t * (k1.ln() - k0.ln())).exp();
            break;
        }
    }
    if table.first().is_some_and(|(_, s)| s.chi2_ratio <= 1.0) {
        best = SCALES[0];
    }
    (((best * 10.0).round() / 10.0), table)
}

fn line(name: &str, s: &Score) -> String {
    format!(
        "| {name} | {} | {:.2} | {:.2} | {:.2} | {:.2} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1} | {:.2} | {} |",
        s.n,
        s.mae[0],
        s.mae[1],
        s.mae[2],
        s.mae[3],
        100.0 * s.within[0],
        100.0 * s.within[1],
        100.0 * s.within[2],
        100.0 * s.within[3],
        100.0 * s.flagged,
        s.chi2_ratio,
        s.failed
    )
}

fn main() {
    let all = drives::read_shared().expect("the single drives (../shared/data)");
    let usable = rows(&all);
    println!(
        "# {} drives, {} with ball data and club data\n",
        all.len(),
        usable.len()
    );
    let driver = Preset::find("driver").expect("driver");
    let header = "| block | rows | face | path | dyn. loft | attack | face ≤1σ % | path ≤1σ % | loft ≤1σ % | attack ≤1σ % | flagged % | median χ² / expected | failed |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|";
    println!("## today's defaults (tour prior, launch-monitor noise), mean |model − TrackMan| °\n");
    println!("{header}");
    let today = Settings::<f64>::typical(&driver.typical);
    for s in drives::sessions(&all) {
        let held: Vec<&Row> = usable.iter().filter(|r| r.session == s).collect();
        println!("{}", line(&format!("{s}"), &score(&run(&held, &today))));
    }
    let every: Vec<&Row> = usable.iter().collect();
    println!("{}", line("all", &score(&run(&every, &today))));

    println!("\n## held-out blocks: prior and σ scale fitted on the other blocks\n");
    println!("{header} scale |");
    let mut pooled: Vec<Outcome> = Vec::new();
    for s in drives::sessions(&all) {
        let train_drives: Vec<&Drive> = all.iter().filter(|d| d.session() != s).collect();
        let prior = fit_prior(&train_drives);
        let train: Vec<&Row> = usable
            .iter()
            .filter(|r| r.session != s)
            .step_by(2)
            .collect();
        let (k, _) = calibrate(&train, prior);
        let held: Vec<&Row> = usable.iter().filter(|r| r.session == s).collect();
        let out = run(&held, &settings(prior, k));
        println!("{} {k} |", line(&format!("{s}"), &score(&out)));
        pooled.extend(out);
    }
    println!("{} |", line("pooled", &score(&pooled)));

    println!("\n## fitted on every block (the core's constants)\n");
    let every_drive: Vec<&Drive> = all.iter().collect();
    let prior = fit_prior(&every_drive);
    let (k, table) = calibrate(&every, prior);
    println!("{header}");
    for (scale, s) in &table {
        println!("{}", line(&format!("scale {scale}"), s));
    }
    // the factor each output's reported 1σ would need to cover 68 % at the chosen scale
    let out = run(&every, &settings(prior, k));
    let factors: Vec<f64> = (0..4)
        .map(|i| {
            let ratio: Vec<f64> = out
                .iter()
                .flatten()
                .map(|(e, s, _, _)| e[i].abs() / s[i])
                .collect();
            let mut r = ratio;
            r.sort_by(f64::total_cmp);
            r[(0.6827 * r.len() as f64) as usize]
        })
        .collect();
    println!(
        "\n68th percentile of |error|/1σ at scale {k} (the 1σ factor each output would need): face {:.2}, path {:.2}, loft {:.2}, attack {:.2}",
        factors[0], factors[1], factors[2], factors[3]
    );
    let d = f64::to_degrees;
    let (m, sd) = (prior.mean, prior.sd);
    println!(
        "\nDRIVER_PRIOR_MEAN: face {:.2}°, path {:.2}°, loft {:.2}°, attack {:.2}°, toe {:.4} m, height {:.4} m, speed {:.2} m/s",
        d(m.face_angle_rad),
        d(m.club_path_rad),
        d(m.dynamic_loft_rad),
        d(m.attack_angle_rad),
        m.impact_toe_m,
        m.impact_height_m,
        m.club_speed_mps
    );
    println!(
        "DRIVER_PRIOR_SD:   face {:.2}°, path {:.2}°, loft {:.2}°, attack {:.2}°, toe {:.4} m, height {:.4} m, speed {:.2} m/s",
        d(sd.face_angle_rad),
        d(sd.club_path_rad),
        d(sd.dynamic_loft_rad),
        d(sd.attack_angle_rad),
        sd.impact_toe_m,
        sd.impact_height_m,
        sd.club_speed_mps
    );
    println!("DRIVER_NOISE_SCALE: {k}");
    let core = Settings::<f64>::for_preset(driver);
    println!(
        "\nthe core's defaults for the driver (Settings::for_preset): {}",
        line("all", &score(&run(&every, &core)))
    );
}
