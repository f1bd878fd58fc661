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

use carry_core::impact::{self, CompliantContact, ContactLaw, Solver};
use carry_core::presets::{FITTED_COMPLIANT, TypicalDelivery};
use carry_core::units::{MPS_PER_MPH, to_deg, to_rpm};
use carry_core::{Ball, ClubSpec, DeliveryConvention, Preset};
use carry_lab::drives::{self, Drive};
use carry_lab::fit::impact::{
    self as fit_impact, BALL_SPEED_SIGMA_REL, DeliveryRow, LAUNCH_SIGMA_DEG, PARAMETERS,
    SPIN_SIGMA_REL,
};
use carry_lab::fit::single_drives::{self, compliant, observed, typical_strike_m};
use carry_lab::fit::{Problem, solve};
use rayon::prelude::*;

/// k_e's bounds (s/m): Penner (2001) measures 0.0029; the law's calibration 0.0027.
const K_E: (f64, f64) = (0.0020, 0.0040);

#[derive(Clone)]
enum Row {
    Drive(Box<Drive>),
    Table(DeliveryRow),
}

struct Joint {
    typical: [f64; 2],
    /// Hold the ceiling e_t,max at the calibrated 0.22 (`--hold-cap`): the irons' spin.
    hold_cap: bool,
    /// Weight of one drive (the tables' rows weigh 1).
    drive_weight: f64,
    /// Fit the driver's CG height too (a fifth parameter, `--sweet-spot`), and strike the
    /// tables' driver rows at the data's typical location.
    sweet_spot: bool,
}

/// The driver's CG height offset's bounds (m, the face frame's y of `cg_to_face_m`; the preset
/// −0.005: its sweet spot 5 mm above the face centre).
const CG_Y: (f64, f64) = (-0.015, 0.005);

/// Ball speed, launch, direction, spin, axis of `delivery` struck by `preset` with `law` and,
/// for the driver, its CG at height `cg_y`.
fn strike(
    preset: &Preset,
    law: ContactLaw<f64>,
    cg_y: Option<f64>,
    delivery: &carry_core::Delivery<f64>,
) -> Result<[f64; 5], String> {
    let mut spec = ClubSpec {
        contact: law,
        ..preset.spec::<f64>()
    };
    if let (Some(y), "driver") = (cg_y, preset.name) {
        spec.cg_to_face_m.y = y;
    }
    let club = spec.validate().map_err(|e| e.to_string())?;
    let st = delivery
        .strike_in(&club, DeliveryConvention::TrackMan)
        .map_err(|e| e.to_string())?;
    let l = impact::solve(&club, &Ball::standard(), &st, Solver::Reduced)
        .map_err(|e| e.to_string())?
        .launch;
    Ok([
        l.ball_speed_mps,
        to_deg(l.launch_angle_rad),
        to_deg(l.launch_direction_rad),
        to_rpm(l.spin_radps),
        to_deg(l.spin_axis_rad),
    ])
}

/// A drive struck at its location (or `typical`) with `law` and the driver's CG at `cg_y`.
fn drive_model(
    d: &Drive,
    law: ContactLaw<f64>,
    cg_y: Option<f64>,
    located: bool,
    typical: [f64; 2],
) -> Result<[f64; 5], String> {
    let loc = if located {
        d.strike_m.unwrap_or(typical)
    } else {
        typical
    };
    let club = d.full_delivery().ok_or("no full delivery")?;
    strike(
        single_drives::driver(),
        law,
        cg_y,
        &single_drives::delivery(club, loc),
    )
}

/// A table row with `law`; with `data_strike`, a driver row is struck at that location.
fn table_model(
    r: &DeliveryRow,
    law: ContactLaw<f64>,
    cg_y: Option<f64>,
    data_strike: Option<[f64; 2]>,
) -> Result<[f64; 3], String> {
    let mut h = fit_impact::impact_height_m(r);
    let mut toe = 0.0;
    if let (Some(s), "driver") = (data_strike, r.preset.name) {
        toe = s[0];
        h = s[1];
    }
    let mut d = TypicalDelivery {
        club_speed_mps: r.club_speed_mps,
        attack_angle_deg: r.attack_deg,
        dynamic_loft_deg: r.dynamic_loft_deg,
        impact_height_m: h,
    }
    .delivery::<f64>();
    d.location.toe_m = toe;
    let m = strike(r.preset, law, cg_y, &d)?;
    Ok([m[0], m[1], m[3]])
}

impl Problem for Joint {
    type Row = Row;
    fn parameter_names(&self) -> Vec<&'static str> {
        let mut v = PARAMETERS.to_vec();
        if self.sweet_spot {
            v.push("driver_cg_height_m");
        }
        v
    }
    fn bounds(&self) -> Vec<(f64, f64)> {
        let cap = FITTED_COMPLIANT.tangential_restitution_max;
        let cap = if self.hold_cap {
            (cap - 1e-6, cap + 1e-6)
        } else {
            (0.0, 1.0)
        };
        let mut b = vec![(-1.0, 1.0), (-3.0, 3.0), cap, K_E];
        if self.sweet_spot {
            b.push(CG_Y);
        }
        b
    }
    fn initial(&self) -> Vec<f64> {
        let c = FITTED_COMPLIANT;
        let mut v = vec![
            c.tangential_restitution,
            c.tangential_restitution_slope,
            c.tangential_restitution_max,
            c.restitution_speed_slope_spm,
        ];
        if self.sweet_spot {
            v.push(single_drives::driver().cg_to_face_m[1]);
        }
        v
    }
    fn quantity_names(&self) -> Vec<&'static str> {
        vec!["ball_speed", "launch_angle", "spin"]
    }
    fn observed(&self, r: &Row) -> Vec<Option<f64>> {
        match r {
            Row::Drive(d) => {
                let o = observed(d);
                vec![o.map(|o| o[0]), o.map(|o| o[1]), o.map(|o| o[3])]
            }
            Row::Table(t) => vec![Some(t.ball_speed_mps), Some(t.launch_deg), Some(t.spin_rpm)],
        }
    }
    fn sigma(&self, r: &Row) -> Vec<f64> {
        let (v, s) = match r {
            Row::Drive(d) => observed(d).map_or((1.0, 1.0), |o| (o[0], o[3])),
            Row::Table(t) => (t.ball_speed_mps, t.spin_rpm),
        };
        vec![
            BALL_SPEED_SIGMA_REL * v,
            LAUNCH_SIGMA_DEG,
            SPIN_SIGMA_REL * s,
        ]
    }
    fn weight(&self, r: &Row) -> f64 {
        match r {
            Row::Drive(_) => self.drive_weight,
            Row::Table(_) => 1.0,
        }
    }
    fn predict(&self, p: &[f64], r: &Row) -> Result<Vec<f64>, String> {
        let law = ContactLaw::Compliant(compliant(p, FITTED_COMPLIANT.friction));
        let cg_y = p.get(4).copied();
        match r {
            Row::Drive(d) => {
                let m = drive_model(d, law, cg_y, true, self.typical)?;
                Ok(vec![m[0], m[1], m[3]])
            }
            Row::Table(t) => {
                Ok(table_model(t, law, cg_y, self.sweet_spot.then_some(self.typical))?.to_vec())
            }
        }
    }
}

fn tables() -> Result<Vec<DeliveryRow>, String> {
    let dir = drives::default_path();
    let shared = dir.parent().ok_or("no data directory")?;
    let text = std::fs::read_to_string(shared.join("club_delivery.csv"))
        .map_err(|e| format!("club_delivery.csv: {e}"))?;
    let mut rows = fit_impact::read_rows(&text)?;
    let chart = std::fs::read_to_string(shared.join("trackman_driver_optimizer_2010.csv"))
        .map_err(|e| format!("chart: {e}"))?;
    let driver = Preset::find("driver").ok_or("no driver")?;
    for line in chart.lines().skip(1).filter(|l| !l.trim().is_empty()) {
        let f: Vec<f64> = line
            .split(',')
            .map(|x| x.trim().parse().unwrap_or(f64::NAN))
            .collect();
        if f.len() < 8 || f.iter().any(|x| !x.is_finite()) {
            return Err(format!("chart: bad line '{line}'"));
        }
        rows.push(DeliveryRow {
            label: "chart".into(),
            preset: driver,
            club_speed_mps: f[0] * MPS_PER_MPH,
            attack_deg: f[1],
            dynamic_loft_deg: f[7],
            ball_speed_mps: f[2] * MPS_PER_MPH,
            launch_deg: f[3],
            spin_rpm: f[4],
        });
    }
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
        let problem = Joint {
            typical,
            hold_cap,
            drive_weight,
            sweet_spot,
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
