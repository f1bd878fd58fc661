//! The study's conclusions, in words, from its measurements.

use super::CARRY_TARGET_M;
use super::measure::{self, Method, Prec, SolverKind};
use super::numbers::{sci, sig};
use super::report::{Row, Study};

fn find(rows: &[Row], f: impl Fn(&Row) -> bool) -> Option<&Row> {
    rows.iter().find(|r| f(r))
}

fn cheapest(rows: &[Row], f: impl Fn(&Row) -> bool) -> Option<&Row> {
    rows.iter()
        .filter(|r| r.failures == 0 && f(r))
        .min_by(|a, b| a.us_per_shot.total_cmp(&b.us_per_shot))
}
/// The conclusions of a study (everything but the conclusions themselves filled in).
pub fn derive(s: &Study) -> Vec<String> {
    let mut out = Vec::new();
    let rows = &s.flight;
    out.push(format!(
        "Reference check against the golden files: {} (flight: carry {} m, apex {} m; impact: \
         ball speed {} m/s, spin {} rpm).",
        if s.reference.passed {
            "passed"
        } else {
            "FAILED"
        },
        sci(s.reference.flight.carry_m),
        sci(s.reference.flight.apex_m),
        sci(s.reference.impact.ball_speed_mps),
        sci(s.reference.impact.spin_rpm),
    ));
    for prec in [Prec::F64, Prec::F32] {
        let p = |r: &Row| r.setting.precision == prec;
        if let Some(d) = find(rows, |r| p(r) && r.setting.is_default) {
            out.push(format!(
                "{} default ({}): worst carry error {} mm (median {} mm), {:.1} evaluations \
                 and {:.2} µs per shot; {} the 1 cm target on every shot{}.",
                prec.name(),
                d.label,
                sig(d.errors.carry_m.worst * 1e3),
                sig(d.errors.carry_m.median * 1e3),
                d.evals_mean,
                d.us_per_shot,
                if d.within_1cm { "meets" } else { "MISSES" },
                if d.pareto_time {
                    ", on the Pareto front"
                } else {
                    ""
                },
            ));
        }
        for (target, what) in [(CARRY_TARGET_M, "1 cm"), (1e-3, "1 mm")] {
            if let Some(c) = cheapest(rows, |r| p(r) && r.errors.carry_m.worst <= target) {
                out.push(format!(
                    "{}: cheapest setting within {what} on every shot: {} ({} mm, {:.1} \
                     evaluations, {:.2} µs).",
                    prec.name(),
                    c.label,
                    sig(c.errors.carry_m.worst * 1e3),
                    c.evals_mean,
                    c.us_per_shot
                ));
            }
        }
    }
    // The f32 noise floor: the best worst-case carry error f32 reaches, and the cheapest
    // setting within 1.5× of it.
    let f32_rows: Vec<&Row> = rows
        .iter()
        .filter(|r| r.setting.precision == Prec::F32 && r.failures == 0)
        .collect();
    if let Some(floor) = f32_rows
        .iter()
        .map(|r| r.errors.carry_m.worst)
        .min_by(f64::total_cmp)
        && let Some(c) = cheapest(rows, |r| {
            r.setting.precision == Prec::F32 && r.errors.carry_m.worst <= 1.5 * floor
        })
    {
        out.push(format!(
            "f32 noise floor: worst carry error {} mm at best; reached (within 1.5×) by {} at \
             {:.1} evaluations — tighter tolerances and smaller steps cost more and do not \
             improve it.",
            sig(floor * 1e3),
            c.label,
            c.evals_mean
        ));
    }
    if let (Some(r), Some(f)) = (
        find(rows, |r| {
            r.setting.precision == Prec::F64 && r.setting.is_default
        }),
        find(rows, |r| {
            r.setting.precision == Prec::F64
                && r.setting.solver == SolverKind::Full
                && r.setting.integrator == Method::Dp45
                && r.setting.param == measure::default_tolerance(Prec::F64)
        }),
    ) {
        out.push(format!(
            "Impact solver: the full 15×15 solve costs {:+.2} µs per shot over the reduced 3×3 \
             at the default integrator and changes the worst carry error by {} mm: both are \
             exact, so the reduced form is the default.",
            f.us_per_shot - r.us_per_shot,
            sig((f.errors.carry_m.worst - r.errors.carry_m.worst).abs() * 1e3),
        ));
    }
    if let (Some(e), Some(d)) = (
        find(rows, |r| {
            r.setting.precision == Prec::F64
                && r.setting.solver == SolverKind::Reduced
                && r.setting.integrator == Method::Euler
                && (r.setting.param - 2e-3).abs() < 1e-12
        }),
        find(rows, |r| {
            r.setting.precision == Prec::F64 && r.setting.is_default
        }),
    ) {
        out.push(format!(
            "Explicit Euler at 500 Hz (the peer's scheme): worst carry error {} mm with {:.0} \
             evaluations per shot, against {} mm with {:.0} for the default.",
            sig(e.errors.carry_m.worst * 1e3),
            e.evals_mean,
            sig(d.errors.carry_m.worst * 1e3),
            d.evals_mean
        ));
    }
    for sl in &s.scaling.slopes {
        out.push(format!(
            "Scaling with flight time, {}: evaluations ∝ T^{:.2}, host time ∝ T^{:.2}.",
            sl.integrator, sl.evals_slope, sl.time_slope
        ));
    }
    if let (Some(lo), Some(hi)) = (
        s.scaling
            .batch
            .iter()
            .map(|b| b.us_per_shot)
            .min_by(f64::total_cmp),
        s.scaling
            .batch
            .iter()
            .map(|b| b.us_per_shot)
            .max_by(f64::total_cmp),
    ) {
        out.push(format!(
            "Batch size 1 to {}: {:.2}–{:.2} µs per default f64 shot (flat).",
            s.scaling.batch.last().map_or(0, |b| b.batch_size),
            lo,
            hi
        ));
    }
    out
}
