//! Issue 34, item 2: the compliant contact refitted on the single drives *together with* the
//! tables (`club_delivery.csv`, TrackMan's 2010 driver chart), with a physical k_e, by
//! session (docs/impact.md §0.8, "Item 2, joint refit").
//!
//! Each session held out in turn: the four contact parameters fitted on the other sessions'
//! drives and every table row (the drives' total weight equal to the tables'), k_e held
//! inside Penner's measured range; the drives without a strike location struck at the
//! training sessions' median location. Reported: the held-out session's drives (ball speed,
//! launch, spin, axis; without and with the strike location) and the tables (in the fit),
//! against the default models. `--table-weight W` weighs the tables W times the drives;
//! `--hold-cap` holds e_t,max at 0.22; `--sweet-spot` fits the driver's CG height too and
//! strikes the tables' driver rows at the data's median location.
//!
//! `cargo run --release -p carry-lab --example impact_joint_refit [-- --hold-cap] [-- --table-weight W] [-- --sweet-spot]`

use carry_core::impact::{CompliantContact, ContactLaw};
use carry_core::presets::FITTED_COMPLIANT;
use carry_lab::drives::{self, Drive};
use carry_lab::fit::impact::DeliveryRow;
use carry_lab::fit::joint_contact::{
    JointContactProblem, JointRow as Row, read_table, table_model,
};
use carry_lab::fit::single_drives::{self, compliant, drive_model, observed, typical_strike_m};
use carry_lab::fit::{Problem, solve};
use rayon::prelude::*;

fn tables() -> Result<Vec<DeliveryRow>, String> {
    let dir = drives::default_path();
    let shared = dir.parent().ok_or("no data directory")?;
    let read =
        |name: &str| std::fs::read_to_string(shared.join(name)).map_err(|e| format!("{name}: {e}"));
    let mut rows = read_table(&read("club_delivery.csv")?, "")?;
    rows.extend(read_table(
        &read("trackman_driver_optimizer_2010.csv")?,
        "chart",
    )?);
    Ok(rows)
}

/// Mean |err| over table rows: ball speed %, launch °, spin % and worst spin %.
fn table_errors(
    rows: &[DeliveryRow],
    c: CompliantContact<f64>,
    cg_y: Option<f64>,
    data_strike: Option<[f64; 2]>,
) -> [f64; 4] {
    let mut s = [0.0; 4];
    let mut n = 0.0;
    for r in rows {
        if let Ok(p) = table_model(r, ContactLaw::Compliant(c), cg_y, data_strike) {
            let spin = (p[2] / r.spin_rpm - 1.0).abs();
            s[0] += (p[0] / r.ball_speed_mps - 1.0).abs();
            s[1] += (p[1] - r.launch_deg).abs();
            s[2] += spin;
            s[3] = s[3].max(spin);
            n += 1.0;
        }
    }
    [100.0 * s[0] / n, s[1] / n, 100.0 * s[2] / n, 100.0 * s[3]]
}

/// Mean |err| over drives: ball speed %, launch °, spin %, spin bias %, axis °.
fn drive_errors(
    drives: &[Drive],
    c: CompliantContact<f64>,
    cg_y: Option<f64>,
    located: bool,
    typical: [f64; 2],
) -> ([f64; 5], usize) {
    let rows: Vec<[f64; 5]> = drives
        .par_iter()
        .filter(|d| !located || d.strike_m.is_some())
        .filter_map(|d| {
            let o = observed(d)?;
            let m = drive_model(d, ContactLaw::Compliant(c), cg_y, located, typical).ok()?;
            Some([
                (m[0] / o[0] - 1.0).abs(),
                (m[1] - o[1]).abs(),
                (m[3] / o[3] - 1.0).abs(),
                m[3] / o[3] - 1.0,
                (m[4] - o[4]).abs(),
            ])
        })
        .collect();
    #[allow(clippy::cast_precision_loss)]
    let n = rows.len().max(1) as f64;
    let mut s = [0.0; 5];
    for r in &rows {
        for (a, b) in s.iter_mut().zip(r) {
            *a += b;
        }
    }
    (
        [
            100.0 * s[0] / n,
            s[1] / n,
            100.0 * s[2] / n,
            100.0 * s[3] / n,
            s[4] / n,
        ],
        rows.len(),
    )
}

fn main() {
    let (all, tables) = match (drives::read_shared(), tables()) {
        (Ok(d), Ok(t)) => (d, t),
        (Err(e), _) | (_, Err(e)) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    };
    let args: Vec<String> = std::env::args().collect();
    let hold_cap = args.iter().any(|a| a == "--hold-cap");
    let sweet_spot = args.iter().any(|a| a == "--sweet-spot");
    // the tables' total weight over the drives' (`--table-weight W`, default 1)
    let table_weight = args
        .iter()
        .position(|a| a == "--table-weight")
        .and_then(|i| args.get(i + 1))
        .and_then(|w| w.parse::<f64>().ok())
        .filter(|w| *w > 0.0)
        .unwrap_or(1.0);
    let preset_typical = [0.0, single_drives::driver().typical.impact_height_m];
    let sessions = drives::sessions(&all);
    let base = FITTED_COMPLIANT;
    let tb = table_errors(&tables[..11], base, None, None);
    let cb = table_errors(&tables[11..], base, None, None);
    println!(
        "before (default models): club_delivery.csv ball speed {:.2} %, launch {:.2}°, spin {:.1} % (worst {:.1} %); chart {:.2} %, {:.2}°, {:.1} % (worst {:.1} %)\n",
        tb[0], tb[1], tb[2], tb[3], cb[0], cb[1], cb[2], cb[3]
    );
    println!(
        "| held-out session | e_t0 | slope | e_t max | k_e | typical strike toe, height (mm) | held-out drives, typical strike: ball speed / launch / spin (bias) / axis, before → after | located, before → after | club_delivery.csv (in fit): speed / launch / spin (worst) | chart (in fit) |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    let mut sums = [[0.0; 5]; 4];
    let mut counts = [0usize; 4];
    for &s in &sessions {
        let (test, train) = drives::split(&all, s);
        let typical = typical_strike_m(&train).unwrap_or(preset_typical);
        let train_drives: Vec<Row> = train
            .iter()
            .filter(|d| observed(d).is_some())
            .map(|d| Row::Drive(Box::new(*d)))
            .collect();
        #[allow(clippy::cast_precision_loss)]
        let drive_weight = tables.len() as f64 / train_drives.len().max(1) as f64 / table_weight;
        let problem = JointContactProblem {
            typical_strike_m: typical,
            hold_cap,
            drive_weight,
            driver_cg_height: sweet_spot,
            friction: FITTED_COMPLIANT.friction,
        };
        let mut rows = train_drives;
        rows.extend(tables.iter().cloned().map(Row::Table));
        let (c, cg_y) = match solve(&problem, &rows, &problem.initial()) {
            Ok(f) => (
                compliant(&f.parameters, FITTED_COMPLIANT.friction),
                f.parameters.get(4).copied(),
            ),
            Err(e) => {
                eprintln!("session {s}: {e}");
                continue;
            }
        };
        let (b_t, n_t) = drive_errors(&test, base, None, false, preset_typical);
        let (a_t, _) = drive_errors(&test, c, cg_y, false, typical);
        let (b_l, n_l) = drive_errors(&test, base, None, true, preset_typical);
        let (a_l, _) = drive_errors(&test, c, cg_y, true, typical);
        for (k, (v, n)) in [(b_t, n_t), (a_t, n_t), (b_l, n_l), (a_l, n_l)]
            .into_iter()
            .enumerate()
        {
            #[allow(clippy::cast_precision_loss)]
            for (acc, x) in sums[k].iter_mut().zip(v) {
                *acc += x * n as f64;
            }
            counts[k] += n;
        }
        let data_strike = sweet_spot.then_some(typical);
        let t = table_errors(&tables[..11], c, cg_y, data_strike);
        let ch = table_errors(&tables[11..], c, cg_y, data_strike);
        if let Some(y) = cg_y {
            println!("(session {s}: driver CG height {:.1} mm)", 1e3 * y);
        }
        println!(
            "| {s} | {:.3} | {:.3} | {:.3} | {:.4} | {:.1}, {:.1} | {:.1} → {:.1} % / {:.2} → {:.2}° / {:.1} ({:+.1}) → {:.1} ({:+.1}) % / {:.1} → {:.1}° | {:.1} → {:.1} % / {:.2} → {:.2}° / {:.1} → {:.1} % | {:.2} % / {:.2}° / {:.1} % ({:.1} %) | {:.2} % / {:.2}° / {:.1} % ({:.1} %) |",
            c.tangential_restitution,
            c.tangential_restitution_slope,
            c.tangential_restitution_max,
            c.restitution_speed_slope_spm,
            1e3 * typical[0],
            1e3 * typical[1],
            b_t[0],
            a_t[0],
            b_t[1],
            a_t[1],
            b_t[2],
            b_t[3],
            a_t[2],
            a_t[3],
            b_t[4],
            a_t[4],
            b_l[0],
            a_l[0],
            b_l[1],
            a_l[1],
            b_l[2],
            a_l[2],
            t[0],
            t[1],
            t[2],
            t[3],
            ch[0],
            ch[1],
            ch[2],
            ch[3],
        );
    }
    let name = [
        "typical, before",
        "typical, after",
        "located, before",
        "located, after",
    ];
    println!(
        "\n| all held-out sessions | rows | ball speed | launch | spin (bias) | axis |\n|---|---|---|---|---|---|"
    );
    for k in 0..4 {
        #[allow(clippy::cast_precision_loss)]
        let n = counts[k].max(1) as f64;
        let m = sums[k].map(|x| x / n);
        println!(
            "| {} | {} | {:.2} % | {:.2}° | {:.1} % ({:+.1} %) | {:.1}° |",
            name[k], counts[k], m[0], m[1], m[2], m[3], m[4]
        );
    }
}
