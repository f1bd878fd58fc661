//! Issue 34: the impact on the amateur's single TrackMan drives, model against data, before
//! and after, with cross-validation by session (docs/impact.md §0.8).
//!
//! Before: the default models (the `driver` preset, the presets' calibrated contact, the
//! preset's typical strike 12 mm above the face centre). After, each session held out in
//! turn (blocks of 1,000 consecutive rows) and everything fitted on the others: the compliant
//! contact refitted on single drives, the typical strike the median measured location, and
//! the named empirical D-plane share on the spin axis (an option, never the default).
//!
//! `cargo run --release -p carry-lab --example impact_single_shots`
//! (`$CARRY_DRIVES` overrides the file's path; `-- --no-refit` skips the contact refit.)

use carry_core::impact::ContactLaw;
use carry_core::presets::FITTED_COMPLIANT;
use carry_lab::drives::{self, Drive};
use carry_lab::fit::single_drives::{
    self, AxisLaw, SingleDriveProblem, compliant, fit_dplane_share, observed, typical_strike_m,
};
use carry_lab::fit::solve;
use rayon::prelude::*;

/// One drive's measurement and the model's, with and without the strike location.
#[derive(Clone, Copy)]
struct Row {
    drive: Drive,
    obs: [f64; 5],
    /// Model without the strike location (typical strike).
    typical: [f64; 5],
    /// Model at the measured strike location (= `typical` when the drive has none).
    located: [f64; 5],
}

fn model_rows(
    drives: &[Drive],
    c: carry_core::impact::CompliantContact<f64>,
    typical: [f64; 2],
) -> Vec<Row> {
    drives
        .par_iter()
        .filter_map(|d| {
            let obs = observed(d)?;
            let law = ContactLaw::Compliant(c);
            let t = single_drives::predict(d, law, false, typical).ok()?;
            let l = if d.strike_m.is_some() {
                single_drives::predict(d, law, true, typical).ok()?
            } else {
                t
            };
            Some(Row {
                drive: *d,
                obs,
                typical: t,
                located: l,
            })
        })
        .collect()
}

/// Mean absolute errors: ball speed %, launch °, direction °, spin %, spin bias %, axis °.
fn errors(rows: &[(&Row, [f64; 5])]) -> [f64; 6] {
    let mut s = [0.0; 6];
    for (r, m) in rows {
        let o = r.obs;
        s[0] += 100.0 * ((m[0] - o[0]) / o[0]).abs();
        s[1] += (m[1] - o[1]).abs();
        s[2] += (m[2] - o[2]).abs();
        s[3] += 100.0 * ((m[3] - o[3]) / o[3]).abs();
        s[4] += 100.0 * (m[3] - o[3]) / o[3];
        s[5] += (m[4] - o[4]).abs();
    }
    #[allow(clippy::cast_precision_loss)]
    let n = rows.len().max(1) as f64;
    s.map(|x| x / n)
}

fn line(name: &str, n: usize, before: [f64; 6], after: [f64; 6]) -> String {
    format!(
        "| {name} | {n} | {:.1} → {:.1} % | {:.2} → {:.2}° | {:.2} → {:.2}° | {:.1} → {:.1} % ({:+.1} → {:+.1} %) | {:.1} → {:.1}° |",
        before[0],
        after[0],
        before[1],
        after[1],
        before[2],
        after[2],
        before[3],
        after[3],
        before[4],
        after[4],
        before[5],
        after[5]
    )
}

/// Least-squares coefficients of `y` on the columns `x` (normal equations, Gaussian
/// elimination with partial pivoting).
#[allow(clippy::needless_range_loop)]
fn ols<const M: usize>(x: &[[f64; M]], y: &[f64]) -> [f64; M] {
    let mut a = [[0.0; M]; M];
    let mut b = [0.0; M];
    for (xi, &yi) in x.iter().zip(y) {
        for i in 0..M {
            for j in 0..M {
                a[i][j] += xi[i] * xi[j];
            }
            b[i] += xi[i] * yi;
        }
    }
    for c in 0..M {
        let p = (c..M)
            .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
            .unwrap_or(c);
        a.swap(c, p);
        b.swap(c, p);
        for r in c + 1..M {
            let f = a[r][c] / a[c][c];
            for k in c..M {
                a[r][k] -= f * a[c][k];
            }
            b[r] -= f * b[c];
        }
    }
    let mut out = [0.0; M];
    for c in (0..M).rev() {
        let s: f64 = (c + 1..M).map(|k| a[c][k] * out[k]).sum();
        out[c] = (b[c] - s) / a[c][c];
    }
    out
}

/// Slopes of `y` on face-to-path (and toe, when `two`), with an intercept.
fn slopes(x: &[[f64; 2]], y: &[f64], two: bool) -> [f64; 2] {
    if two {
        let c = ols(&x.iter().map(|v| [v[0], v[1], 1.0]).collect::<Vec<_>>(), y);
        [c[0], c[1]]
    } else {
        let c = ols(&x.iter().map(|v| [v[0], 1.0]).collect::<Vec<_>>(), y);
        [c[0], f64::NAN]
    }
}

type Band = (&'static str, fn(&Row) -> bool);

fn ftp(r: &Row) -> f64 {
    r.drive.club.face_to_path_deg.unwrap_or_else(|| {
        r.drive.club.face_angle_deg.unwrap_or(0.0) - r.drive.club.club_path_deg.unwrap_or(0.0)
    })
}
fn mph(r: &Row) -> f64 {
    r.drive.club.club_speed_mps.unwrap_or(0.0) / 0.447_04
}
fn toe_mm(r: &Row) -> f64 {
    r.drive.strike_m.map_or(f64::NAN, |s| 1e3 * s[0])
}
fn height_mm(r: &Row) -> f64 {
    r.drive.strike_m.map_or(f64::NAN, |s| 1e3 * s[1])
}

const BANDS: [Band; 20] = [
    ("all", |_| true),
    ("face-to-path < −4°", |r| ftp(r) < -4.0),
    ("face-to-path −4 … −2°", |r| {
        (-4.0..-2.0).contains(&ftp(r))
    }),
    ("face-to-path −2 … 0°", |r| {
        (-2.0..0.0).contains(&ftp(r))
    }),
    ("face-to-path 0 … 2°", |r| (0.0..2.0).contains(&ftp(r))),
    ("face-to-path 2 … 4°", |r| (2.0..4.0).contains(&ftp(r))),
    ("face-to-path > 4°", |r| ftp(r) >= 4.0),
    ("club < 85 mph", |r| mph(r) < 85.0),
    ("club 85–95 mph", |r| (85.0..95.0).contains(&mph(r))),
    ("club 95–105 mph", |r| (95.0..105.0).contains(&mph(r))),
    ("club > 105 mph", |r| mph(r) >= 105.0),
    ("heel (< −10 mm)", |r| toe_mm(r) < -10.0),
    ("centre (±10 mm)", |r| (-10.0..=10.0).contains(&toe_mm(r))),
    ("toe (> 10 mm)", |r| toe_mm(r) > 10.0),
    ("low (< 0 mm)", |r| height_mm(r) < 0.0),
    ("centre height (0–12 mm)", |r| {
        (0.0..=12.0).contains(&height_mm(r))
    }),
    ("high (> 12 mm)", |r| height_mm(r) > 12.0),
    ("premium ball", |r| {
        r.drive.ball == drives::BallKind::Premium
    }),
    ("other balls", |r| r.drive.ball != drives::BallKind::Premium),
    ("tracked outdoors", |r| r.drive.tracked_outdoors()),
];

#[allow(clippy::too_many_lines)]
fn main() {
    let refit = !std::env::args().any(|a| a == "--no-refit");
    let all = match drives::read_shared() {
        Ok(d) => d,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    };
    let preset = single_drives::driver();
    let preset_typical = [0.0, preset.typical.impact_height_m];
    let before = model_rows(&all, FITTED_COMPLIANT, preset_typical);
    let sessions = drives::sessions(&all);

    // After: per held-out session, everything fitted on the other sessions.
    let mut after: Vec<Row> = Vec::new();
    let mut folds = Vec::new();
    for &s in &sessions {
        let (test, train) = drives::split(&all, s);
        let typical = typical_strike_m(&train).unwrap_or(preset_typical);
        let c = if refit {
            let problem = SingleDriveProblem {
                initial: FITTED_COMPLIANT,
                use_location: true,
                typical,
            };
            let fit_rows: Vec<Drive> = train
                .iter()
                .filter(|d| observed(d).is_some())
                .copied()
                .collect();
            match solve(
                &problem,
                &fit_rows,
                &carry_lab::fit::Problem::initial(&problem),
            ) {
                Ok(f) => compliant(&f.parameters, FITTED_COMPLIANT.friction),
                Err(e) => {
                    eprintln!("session {s}: {e}");
                    FITTED_COMPLIANT
                }
            }
        } else {
            FITTED_COMPLIANT
        };
        let train_rows = model_rows(&train, c, typical);
        let pairs: Vec<(f64, f64)> = train_rows
            .iter()
            .map(|r| (r.typical[4], r.obs[4]))
            .collect();
        let pairs_l: Vec<(f64, f64)> = train_rows
            .iter()
            .filter(|r| r.drive.strike_m.is_some())
            .map(|r| (r.located[4], r.obs[4]))
            .collect();
        let k = fit_dplane_share(&pairs).unwrap_or(1.0);
        let k_l = fit_dplane_share(&pairs_l).unwrap_or(1.0);
        let test_rows = model_rows(&test, c, typical);
        // The held-out session's own share (not used for prediction: the variation).
        let own: Vec<(f64, f64)> = test_rows.iter().map(|r| (r.typical[4], r.obs[4])).collect();
        folds.push((
            s,
            c,
            typical,
            k,
            k_l,
            fit_dplane_share(&own).unwrap_or(f64::NAN),
            test_rows.len(),
        ));
        for r in test_rows {
            let mut r = r;
            r.typical[4] = AxisLaw::DPlaneShare(k).apply(r.typical[4]);
            if r.drive.strike_m.is_some() {
                r.located[4] = AxisLaw::DPlaneShare(k_l).apply(r.located[4]);
            } else {
                r.located[4] = r.typical[4];
            }
            after.push(r);
        }
    }
    after.sort_by_key(|r| r.drive.index);
    let mut before = before;
    before.sort_by_key(|r| r.drive.index);

    println!("## Folds (each session held out; fitted on the others)\n");
    println!(
        "| held-out session | rows | e_t0 | slope | e_t max | k_e (s/m) | typical strike toe, height (mm) | D-plane share k (typical / located) | held-out session's own k |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for (s, c, t, k, kl, own, n) in &folds {
        println!(
            "| {s} | {n} | {:.3} | {:.3} | {:.3} | {:.4} | {:.1}, {:.1} | {k:.2} / {kl:.2} | {own:.2} |",
            c.tangential_restitution,
            c.tangential_restitution_slope,
            c.tangential_restitution_max,
            c.restitution_speed_slope_spm,
            1e3 * t[0],
            1e3 * t[1]
        );
    }

    for (title, located) in [
        ("without strike location (typical strike)", false),
        ("with strike location (rows that have one)", true),
    ] {
        println!(
            "\n## {title}: before (default models) → after (held-out session, fitted on the others)\n"
        );
        println!(
            "| band | rows | ball speed | launch | direction | spin (bias) | axis |\n|---|---|---|---|---|---|---|"
        );
        for (name, keep) in BANDS {
            let pick = |rows: &[Row]| -> Vec<(Row, [f64; 5])> {
                rows.iter()
                    .filter(|r| keep(r) && (!located || r.drive.strike_m.is_some()))
                    .map(|r| (*r, if located { r.located } else { r.typical }))
                    .collect()
            };
            let (b, a) = (pick(&before), pick(&after));
            if b.is_empty() {
                continue;
            }
            let eb = errors(&b.iter().map(|(r, m)| (r, *m)).collect::<Vec<_>>());
            let ea = errors(&a.iter().map(|(r, m)| (r, *m)).collect::<Vec<_>>());
            println!("{}", line(name, b.len(), eb, ea));
        }
        println!("\nper held-out session (after):\n");
        println!(
            "| session | rows | ball speed | launch | direction | spin (bias) | axis |\n|---|---|---|---|---|---|---|"
        );
        for &s in &sessions {
            let pick = |rows: &[Row]| -> Vec<(Row, [f64; 5])> {
                rows.iter()
                    .filter(|r| r.drive.session() == s && (!located || r.drive.strike_m.is_some()))
                    .map(|r| (*r, if located { r.located } else { r.typical }))
                    .collect()
            };
            let (b, a) = (pick(&before), pick(&after));
            if b.is_empty() {
                continue;
            }
            let eb = errors(&b.iter().map(|(r, m)| (r, *m)).collect::<Vec<_>>());
            let ea = errors(&a.iter().map(|(r, m)| (r, *m)).collect::<Vec<_>>());
            println!("{}", line(&format!("{s}"), b.len(), eb, ea));
        }
    }

    // The axis's response: degrees of axis per degree of face-to-path (and per mm toward
    // the toe), TrackMan against the model; and the D-plane ratio per session.
    println!("\n## Spin axis: response to face-to-path (°/°) and toe (°/mm)\n");
    println!(
        "| rows | TrackMan | model (before) | model + D-plane share (after, held out) |\n|---|---|---|---|"
    );
    for (name, located) in [
        ("all (typical strike)", false),
        ("with strike location", true),
    ] {
        let rows: Vec<&Row> = before
            .iter()
            .filter(|r| !located || r.drive.strike_m.is_some())
            .collect();
        let x: Vec<[f64; 2]> = rows.iter().map(|r| [ftp(r), toe_mm(r)]).collect();
        let get = |v: &dyn Fn(&Row) -> f64| -> Vec<f64> { rows.iter().map(|r| v(r)).collect() };
        let tm = slopes(&x, &get(&|r| r.obs[4]), located);
        let mb = slopes(
            &x,
            &get(&|r| if located { r.located[4] } else { r.typical[4] }),
            located,
        );
        let idx: std::collections::HashMap<usize, &Row> =
            after.iter().map(|r| (r.drive.index, r)).collect();
        let ma = slopes(
            &x,
            &get(&|r| {
                idx.get(&r.drive.index).map_or(f64::NAN, |a| {
                    if located { a.located[4] } else { a.typical[4] }
                })
            }),
            located,
        );
        let f = |s: [f64; 2]| {
            if located {
                format!("{:.2}°/°, {:+.2}°/mm", s[0], s[1])
            } else {
                format!("{:.2}°/°", s[0])
            }
        };
        println!("| {name} | {} | {} | {} |", f(tm), f(mb), f(ma));
    }

    // The share by subset (model before, all rows at the typical strike): where the ball's
    // curvature is tracked (outdoors) against the indoor rows, by ball, by session.
    println!("\n## D-plane share k by subset (tan a_TrackMan = k tan a_model, before)\n");
    println!(
        "| subset | rows | k | axis per ° of face-to-path: TrackMan / model |\n|---|---|---|---|"
    );
    let subsets: [Band; 4] = [
        ("indoors (tracked < 100 yd)", |r| {
            !r.drive.tracked_outdoors()
        }),
        ("tracked outdoors", |r| r.drive.tracked_outdoors()),
        ("premium ball", |r| {
            r.drive.ball == drives::BallKind::Premium
        }),
        ("other balls", |r| r.drive.ball != drives::BallKind::Premium),
    ];
    let share = |rows: Vec<&Row>, name: &str| {
        let pairs: Vec<(f64, f64)> = rows.iter().map(|r| (r.typical[4], r.obs[4])).collect();
        let x: Vec<[f64; 2]> = rows.iter().map(|r| [ftp(r), 0.0]).collect();
        let tm: Vec<f64> = rows.iter().map(|r| r.obs[4]).collect();
        let m: Vec<f64> = rows.iter().map(|r| r.typical[4]).collect();
        println!(
            "| {name} | {} | {:.2} | {:.2} / {:.2} |",
            pairs.len(),
            fit_dplane_share(&pairs).unwrap_or(f64::NAN),
            slopes(&x, &tm, false)[0],
            slopes(&x, &m, false)[0]
        );
    };
    for (name, keep) in subsets {
        share(before.iter().filter(|r| keep(r)).collect(), name);
    }
    for &s in &sessions {
        for (place, out) in [("indoors", false), ("outdoors", true)] {
            let rows: Vec<&Row> = before
                .iter()
                .filter(|r| r.drive.session() == s && r.drive.tracked_outdoors() == out)
                .collect();
            if rows.len() >= 30 {
                share(rows, &format!("session {s}, {place}"));
            }
        }
    }

    // Spin's growth with club speed, other delivery terms held (rpm per mph).
    let x: Vec<[f64; 4]> = before
        .iter()
        .map(|r| {
            let d = r.drive.full_delivery().unwrap_or([0.0; 5]);
            [mph(r), d[1], d[3], 1.0]
        })
        .collect();
    let fit_on = |y: &[f64]| -> f64 { ols(&x, y)[0] };
    let obs: Vec<f64> = before.iter().map(|r| r.obs[3]).collect();
    let mb: Vec<f64> = before.iter().map(|r| r.typical[3]).collect();
    let ma: Vec<f64> = after.iter().map(|r| r.typical[3]).collect();
    println!(
        "\nspin per mph of club speed (attack and dynamic loft held): TrackMan {:.0}, model before {:.0}, after {:.0} rpm/mph",
        fit_on(&obs),
        fit_on(&mb),
        fit_on(&ma)
    );
}
