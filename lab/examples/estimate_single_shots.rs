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
//! 2. **the impact model's error** per ball datum — the robust sd of the forward residual
//!    `f(x_TrackMan) − y_TrackMan` over the training rows that carry the strike location —
//!    is added to the launch monitor's noise in quadrature ([`Noise::with_model_error`]);
//! 3. **the posterior σ calibration** per output — the 68.27th percentile of |error|/1σ of
//!    every other training row estimated with 1 and 2 (temperature scaling) — is fitted;
//! 4. the held-out block is estimated and scored: mean |error| and the share of rows
//!    within the reported 1σ (without and with the factors of 3), per output (face, path,
//!    loft, attack; toe and height where TrackMan has them), and the share the consistency
//!    check flags.
//!
//! The last section fits on every block: the constants of `carry_core::estimate`
//! (`DRIVER_PRIOR_*`, `DRIVER_MODEL_ERROR`, `DRIVER_SD_SCALE`). Re-run after any change of
//! the impact model and paste them (docs/estimate.md §8.3 says how). The drives are read
//! where they lie (`../shared/data/trackman_amateur_drives.csv`; `CARRY_DRIVES` overrides),
//! never copied.
//!
//! With `--spin-axis-share=fit` every fold also fits the empirical D-plane share of the
//! axis (docs/impact.md §0.8) on its training rows and estimates with it (the named law,
//! opt-in: `carry estimate --spin-axis-share K`); `--spin-axis-share=K` uses a given share.
//!
//! ```sh
//! cargo run --release -p carry-lab --example estimate_single_shots
//! cargo run --release -p carry-lab --example estimate_single_shots -- --spin-axis-share=fit
//! ```

use carry_core::estimate::{
    BallData, ClubData, Noise, Prior, Settings, Unknowns, estimate, predict,
};
use carry_core::{Ball, ClubHead, Preset};
use carry_lab::drives::{self, Drive};
use carry_lab::fit::single_drives::fit_dplane_share;
use rayon::prelude::*;

/// One usable drive: ball data (SI), the measured club speed, TrackMan's club data.
struct Row {
    session: usize,
    y: BallData<f64>,
    club_speed_mps: f64,
    /// face, path, dynamic loft, attack (deg).
    truth: [f64; 4],
    /// TrackMan's strike location (toe, height; m), where it has it.
    strike_m: Option<[f64; 2]>,
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
                strike_m: d.strike_m,
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

/// The impact model's own error on real drives, per ball datum: the robust sd (1.4826 ×
/// MAD) of the forward residual `f(x_TrackMan) − y_TrackMan` — the ball data the model gives
/// at TrackMan's club data and strike location minus TrackMan's ball data — over the rows of
/// `rows` that carry the strike location (it contains TrackMan's own ball and club
/// measurement noise too, which is small against it). With the number of rows used.
fn model_error(rows: &[&Row], club: &ClubHead<f64>) -> (BallData<f64>, usize) {
    let res: Vec<[f64; 5]> = forward(rows, club)
        .into_iter()
        .map(|(f, y)| core::array::from_fn(|i| f[i] - y[i]))
        .collect();
    let sd = core::array::from_fn(|i| mean_sd(res.iter().map(|r| r[i])).1);
    (BallData::from_array(sd), res.len())
}

/// The ball data the impact model gives at TrackMan's club data and strike location, with
/// TrackMan's ball data, for the rows of `rows` that carry the strike location.
fn forward(rows: &[&Row], club: &ClubHead<f64>) -> Vec<([f64; 5], [f64; 5])> {
    let ball = Ball::standard();
    rows.par_iter()
        .filter_map(|r| {
            let [toe, height] = r.strike_m?;
            let r2 = f64::to_radians;
            let x = Unknowns {
                face_angle_rad: r2(r.truth[0]),
                club_path_rad: r2(r.truth[1]),
                dynamic_loft_rad: r2(r.truth[2]),
                attack_angle_rad: r2(r.truth[3]),
                impact_toe_m: toe,
                impact_height_m: height,
                club_speed_mps: r.club_speed_mps,
            };
            let f = predict(club, &ball, &x).ok()?.to_array();
            Some((f, r.y.to_array()))
        })
        .collect()
}

/// The driver preset's club with the empirical spin-axis share `k` (1: the physics).
fn club(k: f64) -> ClubHead<f64> {
    let mut spec = Preset::find("driver").expect("driver").spec::<f64>();
    spec.spin_axis_share = k;
    spec.validate().expect("a share in (0, 1]")
}

/// The axis law for a fold: `None` for the physics; `Some(None)` to fit the D-plane share
/// on the training rows (`fit_dplane_share` on the model's axis at TrackMan's club data and
/// strike against TrackMan's axis); `Some(Some(k))` for a given share.
type AxisArg = Option<Option<f64>>;

fn share_for(axis: AxisArg, train: &[&Row]) -> f64 {
    match axis {
        None => 1.0,
        Some(Some(k)) => k,
        Some(None) => {
            let pairs: Vec<(f64, f64)> = forward(train, &club(1.0))
                .into_iter()
                .map(|(f, y)| (f[4].to_degrees(), y[4].to_degrees()))
                .collect();
            fit_dplane_share(&pairs)
                .expect("training rows with a strike location")
                .clamp(0.01, 1.0)
        }
    }
}

fn settings(prior: Prior<f64>, model: &BallData<f64>) -> Settings<f64> {
    let driver = Preset::find("driver").expect("driver");
    let mut s = Settings::<f64>::typical(&driver.typical);
    s.prior = prior;
    s.noise = Noise::launch_monitor().with_model_error(model);
    s
}

/// The outputs scored: face, path, dynamic loft, attack (deg), strike toe and height (mm).
const OUTPUTS: [&str; 6] = ["face", "path", "loft", "attack", "toe", "height"];

/// Per row: the errors (model − TrackMan; deg, mm; NaN where TrackMan has no value) and 1σ
/// of the [`OUTPUTS`], whether the consistency check passed, χ² over its median; `None`
/// when the estimate failed.
type Outcome = Option<([f64; 6], [f64; 6], bool, f64)>;

fn run(rows: &[&Row], s: &Settings<f64>, club: &ClubHead<f64>) -> Vec<Outcome> {
    let ball = Ball::standard();
    rows.par_iter()
        .map(|r| {
            let c = ClubData {
                club_speed_mps: Some(r.club_speed_mps),
                ..ClubData::default()
            };
            let e = estimate(club, &ball, &r.y, &c, s).ok()?;
            let (v, sd) = (e.value, e.sd);
            let d = f64::to_degrees;
            let value = [
                d(v.face_angle_rad),
                d(v.club_path_rad),
                d(v.dynamic_loft_rad),
                d(v.attack_angle_rad),
                1e3 * v.impact_toe_m,
                1e3 * v.impact_height_m,
            ];
            let sd = [
                d(sd.face_angle_rad),
                d(sd.club_path_rad),
                d(sd.dynamic_loft_rad),
                d(sd.attack_angle_rad),
                1e3 * sd.impact_toe_m,
                1e3 * sd.impact_height_m,
            ];
            let strike = r
                .strike_m
                .map_or([f64::NAN; 2], |s| [1e3 * s[0], 1e3 * s[1]]);
            let truth = [
                r.truth[0], r.truth[1], r.truth[2], r.truth[3], strike[0], strike[1],
            ];
            let err = core::array::from_fn(|i| value[i] - truth[i]);
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

/// Mean |error|, share within 1σ × `factor` (per output, over the rows where TrackMan has
/// it), share flagged inconsistent, failures.
struct Score {
    mae: [f64; 6],
    within: [f64; 6],
    flagged: f64,
    /// The median of χ² over its median under the model (1: the noise is right).
    chi2_ratio: f64,
    failed: usize,
    n: usize,
}

fn score(out: &[Outcome], factor: &[f64; 6]) -> Score {
    let ok: Vec<_> = out.iter().flatten().collect();
    let n = ok.len().max(1) as f64;
    let mut mae = [0.0; 6];
    let mut within = [0.0; 6];
    let mut count = [0.0_f64; 6];
    let mut flagged = 0.0;
    let chi2_ratio = median(ok.iter().map(|o| o.3).collect());
    for (err, sd, consistent, _) in &ok {
        for i in 0..6 {
            if err[i].is_nan() {
                continue;
            }
            count[i] += 1.0;
            mae[i] += err[i].abs();
            if err[i].abs() <= factor[i] * sd[i] {
                within[i] += 1.0;
            }
        }
        if !consistent {
            flagged += 1.0 / n;
        }
    }
    for i in 0..6 {
        mae[i] /= count[i].max(1.0);
        within[i] /= count[i].max(1.0);
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

/// The per-output posterior σ calibration: the 68.27th percentile of |error|/1σ over the
/// rows of `out` (temperature scaling; 1 would be calibrated already).
fn sd_factors(out: &[Outcome]) -> [f64; 6] {
    core::array::from_fn(|i| {
        let mut r: Vec<f64> = out
            .iter()
            .flatten()
            .filter(|o| !o.0[i].is_nan())
            .map(|(e, s, _, _)| e[i].abs() / s[i])
            .collect();
        if r.is_empty() {
            return 1.0;
        }
        r.sort_by(f64::total_cmp);
        r[((0.6827 * r.len() as f64) as usize).min(r.len() - 1)]
    })
}

const ONE: [f64; 6] = [1.0; 6];

fn line(name: &str, s: &Score) -> String {
    format!(
        "| {name} | {} | {:.2} | {:.2} | {:.2} | {:.2} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1} | {:.2} | {} |",
        s.n,
        s.mae[0],
        s.mae[1],
        s.mae[2],
        s.mae[3],
        s.mae[4],
        s.mae[5],
        100.0 * s.within[0],
        100.0 * s.within[1],
        100.0 * s.within[2],
        100.0 * s.within[3],
        100.0 * s.within[4],
        100.0 * s.within[5],
        100.0 * s.flagged,
        s.chi2_ratio,
        s.failed
    )
}

fn f6(f: &[f64; 6]) -> String {
    f.iter()
        .map(|x| format!("{x:.2}"))
        .collect::<Vec<_>>()
        .join(" / ")
}

fn main() {
    let axis: AxisArg = match std::env::args().nth(1).as_deref() {
        None => None,
        Some("--spin-axis-share=fit") => Some(None),
        Some(a) => Some(Some(
            a.strip_prefix("--spin-axis-share=")
                .and_then(|k| k.parse().ok())
                .filter(|k: &f64| *k > 0.0 && *k <= 1.0)
                .expect("usage: [--spin-axis-share=fit|K], K in (0, 1]"),
        )),
    };
    let all = drives::read_shared().expect("the single drives (../shared/data)");
    let usable = rows(&all);
    println!(
        "# {} drives, {} with ball data and club data, {} of them with the strike location\n",
        all.len(),
        usable.len(),
        usable.iter().filter(|r| r.strike_m.is_some()).count()
    );
    let driver = Preset::find("driver").expect("driver");
    let header = "| block | rows | face ° | path ° | loft ° | attack ° | toe mm | height mm | face ≤1σ % | path ≤1σ % | loft ≤1σ % | attack ≤1σ % | toe ≤1σ % | height ≤1σ % | flagged % | median χ² / expected | failed |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|";

    println!("## held-out blocks: prior, model error and σ factors fitted on the other blocks\n");
    println!("{header}");
    let mut pooled_raw: Vec<Outcome> = Vec::new();
    let mut pooled_cal_out: Vec<(Outcome, [f64; 6])> = Vec::new();
    let mut lines = Vec::new();
    for s in drives::sessions(&all) {
        let train_drives: Vec<&Drive> = all.iter().filter(|d| d.session() != s).collect();
        let prior = fit_prior(&train_drives);
        let train_all: Vec<&Row> = usable.iter().filter(|r| r.session != s).collect();
        let k = share_for(axis, &train_all);
        let club = club(k);
        let (me, n_me) = model_error(&train_all, &club);
        let st = settings(prior, &me);
        let train: Vec<&Row> = train_all.iter().copied().step_by(2).collect();
        let factor = sd_factors(&run(&train, &st, &club));
        let held: Vec<&Row> = usable.iter().filter(|r| r.session == s).collect();
        let out = run(&held, &st, &club);
        let m = me.to_array();
        lines.push(format!(
            "block {s}: spin-axis share {k:.3}; model error from {n_me} training rows: ball speed {:.2} m/s, launch {:.2}°, direction {:.2}°, spin {:.0} rpm, axis {:.2}°; σ factors {}",
            m[0],
            m[1].to_degrees(),
            m[2].to_degrees(),
            m[3] * 30.0 / core::f64::consts::PI,
            m[4].to_degrees(),
            f6(&factor)
        ));
        let raw = score(&out, &ONE);
        let cal = score(&out, &factor);
        println!("{}", line(&format!("{s} model error"), &raw));
        println!("{}", line(&format!("{s} + σ factors"), &cal));
        for o in &out {
            pooled_cal_out.push((*o, factor));
        }
        pooled_raw.extend(out);
    }
    println!("{}", line("pooled, model error", &score(&pooled_raw, &ONE)));
    // pooled coverage with each block's own factors
    let mut within = [0.0; 6];
    let mut count = [0.0_f64; 6];
    for (o, f) in &pooled_cal_out {
        if let Some((e, sd, _, _)) = o {
            for i in 0..6 {
                if !e[i].is_nan() {
                    count[i] += 1.0;
                    if e[i].abs() <= f[i] * sd[i] {
                        within[i] += 1.0;
                    }
                }
            }
        }
    }
    println!(
        "pooled, + σ factors: within 1σ % {}",
        (0..6)
            .map(|i| format!(
                "{} {:.1}",
                OUTPUTS[i],
                100.0 * within[i] / count[i].max(1.0)
            ))
            .collect::<Vec<_>>()
            .join(", ")
    );
    for l in &lines {
        println!("{l}");
    }

    println!("\n## fitted on every block (the core's constants)\n");
    let every: Vec<&Row> = usable.iter().collect();
    let every_drive: Vec<&Drive> = all.iter().collect();
    let prior = fit_prior(&every_drive);
    let k = share_for(axis, &every);
    let every_club = club(k);
    println!("spin-axis share: {k:.3}");
    let (me, n_me) = model_error(&every, &every_club);
    let out = run(&every, &settings(prior, &me), &every_club);
    let factor = sd_factors(&out);
    let d = f64::to_degrees;
    let (m, sd) = (prior.mean, prior.sd);
    println!(
        "DRIVER_PRIOR_MEAN: face {:.2}°, path {:.2}°, loft {:.2}°, attack {:.2}°, toe {:.4} m, height {:.4} m, speed {:.2} m/s",
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
    println!("DRIVER_MODEL_ERROR ({n_me} rows; SI): {:?}", me.to_array());
    println!(
        "DRIVER_SD_SCALE (face, path, loft, attack, toe, height): {}",
        f6(&factor)
    );
    println!("{header}");
    println!("{}", line("all, model error", &score(&out, &ONE)));
    let core = Settings::<f64>::for_preset(driver);
    println!(
        "{}",
        line(
            "all, the core's defaults (Settings::for_preset)",
            &score(&run(&every, &core, &every_club), &ONE)
        )
    );
}
