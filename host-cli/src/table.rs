//! The launch-monitor table of one result, for people (`carry shot` without `--json`).

use carry_io::compute::Mode;
use carry_io::report::Report;
use carry_io::units::{Quantity, Units};
use std::fmt::Write as _;

/// What the table shows besides the results: the delivery for context.
#[derive(Debug, Clone, Copy)]
pub struct TableContext<'a> {
    /// Club preset name.
    pub club: &'a str,
    /// Club speed (m/s), for impact and shot.
    pub club_speed_mps: Option<f64>,
    /// Impact location (height, toe) (m), for impact and shot.
    pub impact_location_m: Option<(f64, f64)>,
}

/// `value` with a zero that would print as "-0" made positive.
fn tidy(value: f64, decimals: usize) -> f64 {
    let half_ulp = 0.5 / 10f64.powi(i32::try_from(decimals).unwrap_or(0));
    if value.abs() < half_ulp { 0.0 } else { value }
}

fn row(out: &mut String, label: &str, value: f64, decimals: usize, unit: &str) {
    let value = tidy(value, decimals);
    let line = format!("  {label:<18}{value:>10.decimals$}  {unit}");
    let _ = writeln!(out, "{}", line.trim_end());
}

fn signed_row(
    out: &mut String,
    label: &str,
    value: f64,
    decimals: usize,
    unit: &str,
    neg: &str,
    pos: &str,
) {
    let value = tidy(value, decimals);
    let side = if value > 0.0 {
        pos
    } else if value < 0.0 {
        neg
    } else {
        ""
    };
    let line = format!("  {label:<18}{value:>10.decimals$}  {unit:<4}{side}");
    let _ = writeln!(out, "{}", line.trim_end());
}

/// The launch-monitor table of `r` in `units`.
#[must_use]
pub fn table(mode: Mode, r: &Report, units: Units, ctx: &TableContext<'_>) -> String {
    let mut out = String::new();
    let speed = |x: f64| units.display(Quantity::Speed, x);
    if mode != Mode::Flight {
        let _ = writeln!(out, "CLUB ({})", ctx.club);
        if let Some(v) = ctx.club_speed_mps {
            let (v, u) = speed(v);
            row(&mut out, "club speed", v, 1, u);
        }
        if let Some((h, t)) = ctx.impact_location_m {
            let (h, u) = units.display(Quantity::Offset, h);
            let (t, _) = units.display(Quantity::Offset, t);
            let d = if units == Units::Si { 1 } else { 2 };
            signed_row(&mut out, "impact height", h, d, u, "low", "high");
            signed_row(&mut out, "impact toe", t, d, u, "heel", "toe");
        }
        out.push('\n');
    }
    let l = &r.launch.figures;
    let _ = writeln!(out, "LAUNCH");
    let (v, u) = speed(l.ball_speed_mps);
    row(&mut out, "ball speed", v, 1, u);
    if let Some(s) = r.launch.smash_factor {
        row(&mut out, "smash factor", s, 3, "");
    }
    row(&mut out, "launch angle", l.launch_angle_deg, 1, "deg");
    signed_row(
        &mut out,
        "launch direction",
        l.launch_direction_deg,
        1,
        "deg",
        "left",
        "right",
    );
    row(&mut out, "spin rate", l.spin_rpm, 0, "rpm");
    row(&mut out, "backspin", l.backspin_rpm, 0, "rpm");
    signed_row(
        &mut out,
        "sidespin",
        l.sidespin_rpm,
        0,
        "rpm",
        "draw",
        "fade",
    );
    signed_row(
        &mut out,
        "spin axis",
        l.spin_axis_deg,
        1,
        "deg",
        "left",
        "right",
    );
    if let Some(g) = &r.flight {
        out.push('\n');
        let _ = writeln!(out, "FLIGHT");
        let (c, u) = units.display(Quantity::Long, g.carry_m);
        row(&mut out, "carry", c, 1, u);
        let (s, u) = units.display(Quantity::Long, g.side_m);
        signed_row(&mut out, "side", s, 1, u, "left", "right");
        let (a, u) = units.display(Quantity::Height, g.apex_m);
        row(&mut out, "apex height", a, 1, u);
        row(&mut out, "apex time", g.apex_time_s, 2, "s");
        row(&mut out, "flight time", g.flight_time_s, 2, "s");
        row(&mut out, "landing angle", g.land_angle_deg, 1, "deg");
        let (v, u) = speed(g.land_speed_mps);
        row(&mut out, "landing speed", v, 1, u);
        row(&mut out, "landing spin", g.land_spin_rpm, 0, "rpm");
        if let Some(r) = &g.ground {
            out.push('\n');
            let _ = writeln!(out, "GROUND");
            let (t, u) = units.display(Quantity::Long, r.total_m);
            row(&mut out, "total", t, 1, u);
            let (l, u) = units.display(Quantity::Long, r.roll_m);
            signed_row(&mut out, "roll", l, 1, u, "back", "");
            row(&mut out, "bounces", f64::from(r.bounces), 0, "");
            let (z, u) = units.display(Quantity::Long, r.rest_position_m[2]);
            signed_row(&mut out, "rest side", z, 1, u, "left", "right");
            let label = if r.still_rolling {
                "rolling at"
            } else {
                "time to rest"
            };
            row(&mut out, label, r.time_to_rest_s, 2, "s");
        }
    }
    if let (Some(c), Mode::Impact) = (&r.club_after, mode) {
        out.push('\n');
        let _ = writeln!(out, "CLUB AFTER IMPACT");
        let v = c.velocity_mps;
        let (s, u) = speed((v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt());
        row(&mut out, "club speed", s, 1, u);
        if let Some(p) = r.impulse_ns {
            let magnitude = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
            row(&mut out, "impulse", magnitude, 3, "N s");
        }
    }
    out
}
