//! `carry fit --family compliant`: fits the compliant face–ball contact
//! (`carry_lab::fit::impact`) to measured deliveries — club speed, attack angle and dynamic
//! loft → ball speed, launch angle and spin, per club preset — with the same residual
//! table, leave-one-out errors and TOML output as the aerodynamic families. The output file
//! is what `--contact FILE.toml` reads.
//!
//! Input: `club_delivery.csv`'s columns (`club, club_speed_mph, attack_deg,
//! dynamic_loft_deg, ball_speed_mph, launch_deg, spin_rpm`; `who` labels the rows).
//! `--evaluate compliant|FILE.toml` reports a given compliant law without fitting.

use super::command::{FitRequest, Produced, status};
use crate::fit::impact::{self, ContactProblem, PARAMETERS};
use crate::fit::{self, Fit, FitOptions};
use carry_core::units::MPS_PER_MPH;
use carry_io::error::{Failure, InputError};
use std::fmt::Write as _;
use std::io::{IsTerminal as _, Read as _};

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
    let (mut source, _) = carry_io::batch::open(&cmd.input)?;
    let mut text = String::new();
    source
        .read_to_string(&mut text)
        .map_err(|e| InputError::new("input", format!("{}: {e}", cmd.input.display())))?;
    let rows = impact::read_rows(&text)
        .map_err(|e| InputError::new("input", format!("{}: {e}", cmd.input.display())))?;
    if rows.is_empty() {
        return Err(InputError::new("input", format!("{}: no rows", cmd.input.display())).into());
    }
    let options = FitOptions {
        leave_one_out: !cmd.no_cross_validation,
    };
    let bar = (!cmd.no_progress && std::io::stderr().is_terminal()).then(|| {
        let solves = 1 + if options.leave_one_out { rows.len() } else { 0 };
        indicatif::ProgressBar::new(solves as u64)
    });
    let tick = || {
        if let Some(b) = &bar {
            b.inc(1);
        }
    };
    let result = match &given {
        Some(p) => fit::evaluate(&problem, &rows, p),
        None => fit::fit(&problem, &rows, options, &tick),
    }
    .map_err(|e| Failure::Other(format!("the fit failed: {e}")))?;
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
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
        let coefficients: serde_json::Map<String, serde_json::Value> = PARAMETERS
            .iter()
            .zip(result.values())
            .map(|(k, v)| ((*k).to_string(), serde_json::json!(v)))
            .chain([("friction".to_string(), serde_json::json!(problem.friction))])
            .collect();
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
        table(&result, problem.friction, cmd)
    };
    Ok(Produced::Text(text))
}

/// The readable report (ball speed in mph, angles in degrees, spin in rpm).
fn table(f: &Fit, friction: f64, cmd: &FitRequest) -> String {
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
    for r in &f.rows {
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
    let _ = writeln!(
        s,
        "\nERRORS{:14}mean |err|      max |err|      leave-one-out mean / max",
        ""
    );
    let loo = |i: usize| f.loo_summary.as_ref().and_then(|l| l.get(i)).copied();
    for (i, name) in f.quantities.iter().enumerate() {
        let Some(m) = f.summary.get(i) else { continue };
        let (mean, max, l) = if *name == "launch_angle" {
            (
                format!("{:.2} deg", m.mean_abs),
                format!("{:.2} deg", m.max_abs),
                loo(i).map_or("-".into(), |l| {
                    format!("{:.2} / {:.2} deg", l.mean_abs, l.max_abs)
                }),
            )
        } else {
            (
                format!("{:.2} %", m.mean_abs_pct),
                format!("{:.2} %", m.max_abs_pct),
                loo(i).map_or("-".into(), |l| {
                    format!("{:.2} % / {:.2} %", l.mean_abs_pct, l.max_abs_pct)
                }),
            )
        };
        let _ = writeln!(s, "  {name:<16} {mean:>10}   {max:>10}     {l}");
    }
    if let Some(path) = &cmd.output {
        let _ = writeln!(s, "\nwrote {}", path.display());
    }
    s
}
