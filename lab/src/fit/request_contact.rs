//! `carry fit --family compliant`: fits the compliant face–ball contact
//! (`carry_lab::fit::impact`) to measured deliveries — club speed, attack angle and dynamic
//! loft → ball speed, launch angle and spin, per club preset — with the same residual
//! table, leave-one-out errors and TOML output as the aerodynamic families. The output file
//! is what `--contact FILE.toml` reads.
//!
//! Input: `club_delivery.csv`'s columns (`club, club_speed_mph, attack_deg,
//! dynamic_loft_deg, ball_speed_mph, launch_deg, spin_rpm`; `who` labels the rows).
//! `--evaluate compliant|FILE.toml` reports a given compliant law without fitting.
//!
//! With `--also` (issue 34, item 2): more tables (the same columns, or a driver chart
//! without a `club` column: TrackMan's 2010 optimizer) and single-drive TrackMan exports
//! (recognised by their header, [`crate::drives::is_export`]), fitted jointly
//! ([`super::joint_contact`]): the drives weigh `1/--table-weight` times the tables in
//! total, k_e stays in Penner's measured range, drives are cross-validated by session and
//! table rows one by one; the report lists the table rows and summarises the drives.

use super::command::{FitRequest, Produced, status};
use super::joint_contact::{self, JointContactProblem, JointRow};
use super::report::QuantitySummary;
use crate::fit::impact::{self, ContactProblem, DeliveryRow, PARAMETERS};
use crate::fit::{self, Fit, FitOptions};
use carry_core::units::MPS_PER_MPH;
use carry_io::error::{Failure, InputError};
use std::fmt::Write as _;
use std::io::{IsTerminal as _, Read as _};
use std::path::PathBuf;

/// The family's name on the command line.
pub const FAMILY: &str = "compliant";

/// Runs `carry fit --family compliant`: what it prints (table or JSON), as
/// the aerodynamic families' `report` (or the document as a value).
///
/// # Errors
/// Bad input or a law that is not compliant (status 2); a fit that fails or a file that
/// cannot be written.
pub(super) fn produce(cmd: &FitRequest, value: bool) -> Result<Produced, Failure> {
    let (problem, given) = match &cmd.evaluate {
        Some(name) => {
            let law = carry_io::contact::parse(name).map_err(|e| InputError::new("evaluate", e))?;
            let (problem, p) = ContactProblem::of(&law).ok_or_else(|| {
                InputError::new(
                    "evaluate",
                    "the rolling contact has no parameters of the compliant family",
                )
            })?;
            (problem, Some(p))
        }
        None => (ContactProblem::default(), None),
    };
    let mut tables = Vec::new();
    let mut drives = Vec::new();
    for path in std::iter::once(&cmd.input).chain(&cmd.also) {
        let option = if path == &cmd.input { "input" } else { "also" };
        read_file(path, option, &mut tables, &mut drives)?;
    }
    if !drives.is_empty() {
        return produce_joint(cmd, value, &problem, given.as_deref(), tables, drives);
    }
    let rows = tables;
    if rows.is_empty() {
        return Err(InputError::new("input", format!("{}: no rows", cmd.input.display())).into());
    }
    let result = run(cmd, &problem, &rows, given.as_deref(), rows.len())?;
    let law = impact::law(&result.values(), problem.friction);
    if let Some(path) = &cmd.output {
        let q = |name: &str| result.summary_of(name).copied().unwrap_or_default();
        let comment = format!(
            "carry contact law (family compliant), fitted by `carry fit` to {} rows of {}\n\
             ball speed mean |error| {:.2} %, launch {:.2} deg, spin {:.2} % (max {:.2} %)",
            rows.len(),
            cmd.input.display(),
            q("ball_speed").mean_abs_pct,
            q("launch_angle").mean_abs,
            q("spin").mean_abs_pct,
            q("spin").max_abs_pct,
        );
        std::fs::write(path, impact::to_toml(&law, &comment))
            .map_err(|e| Failure::Other(format!("cannot write {}: {e}", path.display())))?;
    }
    let text = if cmd.json {
        let coefficients = coefficients(&result, problem.friction);
        let doc = serde_json::json!({
            "family": FAMILY,
            "rows": rows.len(),
            "coefficients": coefficients,
            "fit": result,
        });
        if value {
            return Ok(Produced::Value(doc));
        }
        let mut s =
            serde_json::to_string_pretty(&doc).map_err(|e| Failure::Other(e.to_string()))?;
        s.push('\n');
        s
    } else {
        table(&result, problem.friction, cmd, 0)
    };
    Ok(Produced::Text(text))
}

/// Reads one input file into `tables` (a delivery table or a driver chart,
/// [`joint_contact::read_table`]) or `drives` (a single-drive export: every drive with a
/// full delivery and the launch the fit compares).
///
/// # Errors
/// An unreadable or malformed file, named by `option`.
fn read_file(
    path: &PathBuf,
    option: &'static str,
    tables: &mut Vec<DeliveryRow>,
    drives: &mut Vec<JointRow>,
) -> Result<(), Failure> {
    let (mut source, _) = carry_io::batch::open(path)?;
    let mut text = String::new();
    let name = path.display();
    source
        .read_to_string(&mut text)
        .map_err(|e| InputError::new(option, format!("{name}: {e}")))?;
    if crate::drives::is_export(&text) {
        let all = crate::drives::parse(&text)
            .map_err(|e| InputError::new(option, format!("{name}: {e}")))?;
        drives.extend(
            all.into_iter()
                .filter(|d| {
                    d.full_delivery().is_some() && super::single_drives::observed(d).is_some()
                })
                .map(|d| JointRow::Drive(Box::new(d))),
        );
        return Ok(());
    }
    let label = path
        .file_stem()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let rows = joint_contact::read_table(&text, &label)
        .map_err(|e| InputError::new(option, format!("{name}: {e}")))?;
    if rows.is_empty() {
        return Err(InputError::new(option, format!("{name}: no rows")).into());
    }
    tables.extend(rows);
    Ok(())
}

/// Fits `problem` to `rows` (or evaluates it at `given`) as `cmd` asks: leave-one-out unless
/// `--no-cross-validation`, with a progress bar on a terminal (one tick per solve: one,
/// plus one per held-out group or row, `holdouts` of them).
///
/// # Errors
/// A fit that fails.
fn run<P: fit::Problem>(
    cmd: &FitRequest,
    problem: &P,
    rows: &[P::Row],
    given: Option<&[f64]>,
    holdouts: usize,
) -> Result<Fit, Failure> {
    let options = FitOptions {
        leave_one_out: !cmd.no_cross_validation,
    };
    let bar = (!cmd.no_progress && std::io::stderr().is_terminal()).then(|| {
        let solves = 1 + if options.leave_one_out { holdouts } else { 0 };
        indicatif::ProgressBar::new(solves as u64)
    });
    let tick = || {
        if let Some(b) = &bar {
            b.inc(1);
        }
    };
    let result = match given {
        Some(p) => fit::evaluate(problem, rows, p),
        None => fit::fit(problem, rows, options, &tick),
    }
    .map_err(|e| Failure::Other(format!("the fit failed: {e}")))?;
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    Ok(result)
}

/// The joint fit of tables and single drives ([`JointContactProblem`]): as [`produce`],
/// with the drives summarised rather than listed.
fn produce_joint(
    cmd: &FitRequest,
    value: bool,
    base: &ContactProblem,
    given: Option<&[f64]>,
    tables: Vec<DeliveryRow>,
    drives: Vec<JointRow>,
) -> Result<Produced, Failure> {
    let table_weight = cmd.table_weight.unwrap_or(1.0);
    if !(table_weight.is_finite() && table_weight > 0.0) {
        return Err(InputError::new("table_weight", "must be a positive number").into());
    }
    let n_drives = drives.len();
    let n_tables = tables.len();
    let mut rows = drives;
    rows.extend(tables.into_iter().map(JointRow::Table));
    let mut problem = JointContactProblem::new(&rows, table_weight);
    problem.friction = base.friction;
    let sessions: std::collections::BTreeSet<usize> = rows
        .iter()
        .filter_map(|r| fit::Problem::group(&problem, r))
        .collect();
    let result = run(cmd, &problem, &rows, given, sessions.len() + n_tables)?;
    let is_drive = |r: &super::report::RowResult| r.row <= n_drives; // rows are 1-based
    let drives_summary = result.summaries_of_rows(is_drive);
    let tables_summary = result.summaries_of_rows(|r| !is_drive(r));
    let law = impact::law(&result.values(), problem.friction);
    if let Some(path) = &cmd.output {
        let q = |i: usize, s: &(Vec<QuantitySummary>, Option<Vec<QuantitySummary>>)| {
            s.0.get(i).copied().unwrap_or_default()
        };
        let comment = format!(
            "carry contact law (family compliant), fitted by `carry fit` to {n_tables} table rows \
             and {n_drives} single drives (table weight {table_weight})\n\
             tables: ball speed mean |error| {:.2} %, launch {:.2} deg, spin {:.2} %; \
             drives: {:.2} %, {:.2} deg, {:.2} %",
            q(0, &tables_summary).mean_abs_pct,
            q(1, &tables_summary).mean_abs,
            q(2, &tables_summary).mean_abs_pct,
            q(0, &drives_summary).mean_abs_pct,
            q(1, &drives_summary).mean_abs,
            q(2, &drives_summary).mean_abs_pct,
        );
        std::fs::write(path, impact::to_toml(&law, &comment))
            .map_err(|e| Failure::Other(format!("cannot write {}: {e}", path.display())))?;
    }
    if cmd.json {
        let coefficients = coefficients(&result, problem.friction);
        let doc = serde_json::json!({
            "family": FAMILY,
            "rows": rows.len(),
            "coefficients": coefficients,
            "tables": {
                "rows": n_tables,
                "summary": tables_summary.0,
                "held_out_summary": tables_summary.1,
            },
            "drives": {
                "rows": n_drives,
                "sessions": sessions.len(),
                "weight_each": problem.drive_weight,
                "typical_strike_m": problem.typical_strike_m,
                "summary": drives_summary.0,
                "held_out_summary": drives_summary.1,
            },
            "fit": result,
        });
        if value {
            return Ok(Produced::Value(doc));
        }
        let mut s =
            serde_json::to_string_pretty(&doc).map_err(|e| Failure::Other(e.to_string()))?;
        s.push('\n');
        return Ok(Produced::Text(s));
    }
    let mut s = table(&result, problem.friction, cmd, n_drives);
    let _ = writeln!(
        s,
        "\n{n_drives} SINGLE DRIVES in {} sessions, each weighing {:.4} (the tables {table_weight} \
         times the drives in total); without a measured location struck at the drives' median, \
         toe {:.1} mm, height {:.1} mm",
        sessions.len(),
        problem.drive_weight,
        1e3 * problem.typical_strike_m[0],
        1e3 * problem.typical_strike_m[1],
    );
    errors(
        &mut s,
        "ERRORS, tables",
        "leave-one-out",
        &result.quantities,
        &tables_summary.0,
        tables_summary.1.as_deref(),
    );
    errors(
        &mut s,
        "ERRORS, drives",
        "held out by session",
        &result.quantities,
        &drives_summary.0,
        drives_summary.1.as_deref(),
    );
    Ok(Produced::Text(s))
}

/// The error block of a report: mean and max |error| per quantity, and the held-out ones.
fn errors(
    s: &mut String,
    title: &str,
    held_name: &str,
    quantities: &[&str],
    fitted: &[QuantitySummary],
    held_out: Option<&[QuantitySummary]>,
) {
    let _ = writeln!(
        s,
        "\n{title:<20}mean |err|      max |err|      {held_name} mean / max"
    );
    for (i, name) in quantities.iter().enumerate() {
        let Some(m) = fitted.get(i) else { continue };
        let l = held_out.and_then(|h| h.get(i));
        let (mean, max, l) = if *name == "launch_angle" {
            (
                format!("{:.2} deg", m.mean_abs),
                format!("{:.2} deg", m.max_abs),
                l.map_or("-".into(), |l| {
                    format!("{:.2} / {:.2} deg", l.mean_abs, l.max_abs)
                }),
            )
        } else {
            (
                format!("{:.2} %", m.mean_abs_pct),
                format!("{:.2} %", m.max_abs_pct),
                l.map_or("-".into(), |l| {
                    format!("{:.2} % / {:.2} %", l.mean_abs_pct, l.max_abs_pct)
                }),
            )
        };
        let _ = writeln!(s, "  {name:<16} {mean:>10}   {max:>10}     {l}");
    }
}

/// The fitted law's parameters by name, with the friction it held (the JSON document's
/// `coefficients`).
fn coefficients(result: &Fit, friction: f64) -> serde_json::Map<String, serde_json::Value> {
    PARAMETERS
        .iter()
        .zip(result.values())
        .map(|(k, v)| ((*k).to_string(), serde_json::json!(v)))
        .chain([("friction".to_string(), serde_json::json!(friction))])
        .collect()
}

/// The readable report (ball speed in mph, angles in degrees, spin in rpm).
fn table(f: &Fit, friction: f64, cmd: &FitRequest, skip: usize) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "FIT  family {FAMILY}, {} rows, {} ({} impacts)",
        f.rows.len(),
        status(f, cmd.evaluate.is_some()),
        f.row_evaluations
    );
    let _ = writeln!(s, "\nCOEFFICIENTS");
    for p in &f.parameters {
        let _ = writeln!(
            s,
            "  {:<30} {:>10.5}   bounds [{}, {}]",
            p.name, p.value, p.lower, p.upper
        );
    }
    let _ = writeln!(s, "  {:<30} {:>10.5}   (held)", "friction", friction);
    let _ = writeln!(
        s,
        "\nROWS{:24}ball speed [mph]{:14}launch [deg]{:12}spin [rpm]",
        "", "", ""
    );
    let _ = writeln!(
        s,
        "  {:>3}  {:<18} {:>6} {:>6} {:>5} {:>5}   {:>5} {:>5} {:>5} {:>5}   {:>5} {:>5} {:>5} {:>5}",
        "#",
        "label",
        "meas",
        "model",
        "err%",
        "loo%",
        "meas",
        "model",
        "err",
        "loo",
        "meas",
        "model",
        "err%",
        "loo%"
    );
    for r in f.rows.iter().filter(|r| r.row > skip) {
        let obs = |i: usize| r.observed.get(i).copied().flatten().unwrap_or(f64::NAN);
        let pred = |i: usize| r.predicted.get(i).copied().unwrap_or(f64::NAN);
        let loo = |i: usize| {
            r.loo_predicted
                .as_ref()
                .and_then(|l| l.get(i).copied())
                .unwrap_or(f64::NAN)
        };
        let pct = |x: f64, o: f64| 100.0 * (x - o) / o;
        let label: String = r.label.chars().take(18).collect();
        let _ = writeln!(
            s,
            "  {:>3}  {:<18} {:>6.1} {:>6.1} {:>+5.1} {:>+5.1}   {:>5.1} {:>5.1} {:>+5.2} {:>+5.2}   {:>5.0} {:>5.0} {:>+5.1} {:>+5.1}",
            r.row,
            label,
            obs(0) / MPS_PER_MPH,
            pred(0) / MPS_PER_MPH,
            pct(pred(0), obs(0)),
            pct(loo(0), obs(0)),
            obs(1),
            pred(1),
            pred(1) - obs(1),
            loo(1) - obs(1),
            obs(2),
            pred(2),
            pct(pred(2), obs(2)),
            pct(loo(2), obs(2)),
        );
    }
    let title = if skip > 0 {
        "ERRORS, all rows"
    } else {
        "ERRORS"
    };
    errors(
        &mut s,
        title,
        "leave-one-out",
        &f.quantities,
        &f.summary,
        f.loo_summary.as_deref(),
    );
    if let Some(path) = &cmd.output {
        let _ = writeln!(s, "\nwrote {}", path.display());
    }
    s
}
