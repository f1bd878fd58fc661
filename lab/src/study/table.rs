//! The study as a text table (the default output).

use super::numbers::{pair, sci};
use super::report::Study;
use super::shots::Origin;
use std::fmt::Write as _;

/// Renders the study as text.
pub fn render(s: &Study) -> String {
    let mut o = String::new();
    let n_launch = s
        .shots
        .iter()
        .filter(|x| x.origin == Origin::GoldenFlight)
        .count();
    let n_impact = s
        .shots
        .iter()
        .filter(|x| x.origin == Origin::GoldenImpact)
        .count();
    let n_own = s.shots.len() - n_launch - n_impact;
    let _ = writeln!(
        o,
        "carry accuracy–cost study{}: {} shots ({} golden launches, {} golden deliveries, {} \
         own full shots; see docs/accuracy.md)",
        if s.quick { " (--quick)" } else { "" },
        s.shots.len(),
        n_launch,
        n_impact,
        n_own
    );
    let r = &s.reference;
    let _ = writeln!(o, "Reference: {}.", r.description);
    let _ = writeln!(
        o,
        "  vs golden flight ({} cases): carry {} m, side {} m, apex {} m, flight time {} s, \
         landing angle {}°",
        r.flight_cases,
        sci(r.flight.carry_m),
        sci(r.flight.side_m),
        sci(r.flight.apex_m),
        sci(r.flight.flight_time_s),
        sci(r.flight.land_angle_deg)
    );
    let _ = writeln!(
        o,
        "  vs golden impact ({} cases): ball speed {} m/s, launch angle {}°, spin {} rpm, spin \
         axis {}° — {}",
        r.impact_cases,
        sci(r.impact.ball_speed_mps),
        sci(r.impact.launch_angle_deg),
        sci(r.impact.spin_rpm),
        sci(r.impact.spin_axis_deg),
        if r.passed { "passed" } else { "FAILED" }
    );
    let _ = writeln!(o, "Timing: {}.", s.timing);

    let _ = writeln!(
        o,
        "\nImpact — errors against the reference, worst (median) over the {} deliveries",
        s.shots
            .iter()
            .filter(|x| x.reference.launch.is_some())
            .count()
    );
    let _ = writeln!(
        o,
        "{:<4} {:<13} {:>22} {:>22} {:>22} {:>22} {:>9} {:>4}",
        "prec",
        "solver",
        "ball speed (m/s)",
        "launch angle (°)",
        "spin (rpm)",
        "spin axis (°)",
        "µs/impact",
        "fail"
    );
    for row in &s.impact {
        let e = &row.errors;
        let _ = writeln!(
            o,
            "{:<4} {:<13} {:>22} {:>22} {:>22} {:>22} {:>9.3} {:>4}",
            row.precision.name(),
            row.solver.name(),
            pair(&e.ball_speed_mps, 1.0),
            pair(&e.launch_angle_deg, 1.0),
            pair(&e.spin_rpm, 1.0),
            pair(&e.spin_axis_deg, 1.0),
            row.us_per_impact,
            row.failures
        );
    }

    let _ = writeln!(
        o,
        "\nFull shot (impact + flight; launches: flight only) — errors against the reference, \
         worst (median) over the set"
    );
    let _ = writeln!(
        o,
        "evals: mean force evaluations per shot (exact); µs: host time per shot (noisy). \
         Marks: * Pareto front (worst carry vs µs), e Pareto front (worst carry vs evals), \
         D default, ! a shot failed"
    );
    let _ = writeln!(
        o,
        "{:<4} {:<7} {:<5} {:<10} {:>8} {:>8} {:<3} {:>20} {:>20} {:>20} {:>18} {:>18}  worst carry shot",
        "prec",
        "solver",
        "integ",
        "param",
        "evals",
        "µs/shot",
        "",
        "carry (mm)",
        "side (mm)",
        "apex (mm)",
        "flight time (ms)",
        "land angle (°)",
    );
    let mut last = None;
    for row in &s.flight {
        let key = (row.setting.precision, row.setting.solver);
        if last.is_some_and(|k| k != key) {
            o.push('\n');
        }
        last = Some(key);
        let marks = format!(
            "{}{}{}{}",
            if row.pareto_time { "*" } else { "" },
            if row.pareto_evals { "e" } else { "" },
            if row.setting.is_default { "D" } else { "" },
            if row.failures > 0 { "!" } else { "" }
        );
        let e = &row.errors;
        let _ = writeln!(
            o,
            "{:<4} {:<7} {:<5} {:<10} {:>8.1} {:>8.2} {:<3} {:>20} {:>20} {:>20} {:>18} {:>18}  {}",
            row.setting.precision.name(),
            row.setting.solver.name(),
            row.setting.integrator.name(),
            row.setting.param_label(),
            row.evals_mean,
            row.us_per_shot,
            marks,
            pair(&e.carry_m, 1e3),
            pair(&e.side_m, 1e3),
            pair(&e.apex_m, 1e3),
            pair(&e.flight_time_s, 1e3),
            pair(&e.land_angle_deg, 1.0),
            row.worst_carry_shot,
        );
        if row.failures > 0 {
            let _ = writeln!(o, "     ({} shots failed)", row.failures);
        }
    }

    let sc = &s.scaling;
    let _ = writeln!(
        o,
        "\nScaling with flight time (f64, 30° launch, 3000 rpm, standard air): evaluations / µs \
         per flight"
    );
    let _ = write!(o, "{:>10} {:>14}", "speed m/s", "flight time s");
    for m in &sc.methods {
        let _ = write!(o, " {m:>22}");
    }
    o.push('\n');
    for r in &sc.flight_time {
        let _ = write!(o, "{:>10.0} {:>14.3}", r.ball_speed_mps, r.flight_time_s);
        for (e, u) in r.evals.iter().zip(&r.us) {
            let _ = write!(o, " {:>22}", format!("{e} / {u:.2}"));
        }
        o.push('\n');
    }
    let _ = write!(o, "{:>25}", "log-log slope");
    for sl in &sc.slopes {
        let _ = write!(
            o,
            " {:>22}",
            format!("{:.2} / {:.2}", sl.evals_slope, sl.time_slope)
        );
    }
    o.push('\n');
    let _ = writeln!(
        o,
        "\nBatch size (default f64 full shot, one core): {}",
        sc.batch
            .iter()
            .map(|b| format!("n={} {:.2} µs/shot", b.batch_size, b.us_per_shot))
            .collect::<Vec<_>>()
            .join(", ")
    );

    let _ = writeln!(o, "\nConclusions");
    for c in &s.conclusions {
        let _ = writeln!(o, "- {c}");
    }
    o
}
