//! Results in `f64`, SI: the JSON contract (serde), the CSV columns, and the
//! launch-monitor table for people.

use crate::compute::Mode;
use crate::units::{Quantity, Units};
use serde::Serialize;
use std::fmt::Write as _;

/// The launch, in launch-monitor terms (JSON object `launch`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LaunchReport {
    /// Ball speed (m/s).
    pub ball_speed_mps: f64,
    /// Launch angle (deg, + up).
    pub launch_angle_deg: f64,
    /// Launch direction (deg, + right).
    pub launch_direction_deg: f64,
    /// Total spin (rpm).
    pub spin_rpm: f64,
    /// Backspin (rpm).
    pub backspin_rpm: f64,
    /// Sidespin (rpm, + curves right).
    pub sidespin_rpm: f64,
    /// Spin axis (deg, + tilted right).
    pub spin_axis_deg: f64,
    /// Smash factor (impact and shot only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub smash_factor: Option<f64>,
    /// Ball velocity (m/s, G).
    pub ball_velocity_mps: [f64; 3],
    /// Ball spin (rad/s, G).
    pub ball_spin_radps: [f64; 3],
}

/// The club after impact (JSON object `club_after`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ClubAfter {
    /// CoM velocity (m/s, G).
    pub velocity_mps: [f64; 3],
    /// Angular velocity (rad/s, G).
    pub spin_radps: [f64; 3],
}

/// The flight (JSON object `flight`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlightReport {
    /// Carry, tee to landing, horizontal (m).
    pub carry_m: f64,
    /// Side, + right (m).
    pub side_m: f64,
    /// Carry along the target line (m).
    pub carry_x_m: f64,
    /// Apex height (m).
    pub apex_m: f64,
    /// Time of the apex (s).
    pub apex_time_s: f64,
    /// Flight time (s).
    pub flight_time_s: f64,
    /// Landing angle below the horizontal (deg).
    pub land_angle_deg: f64,
    /// Landing speed (m/s).
    pub land_speed_mps: f64,
    /// Spin at landing (rpm).
    pub land_spin_rpm: f64,
    /// Landing position (m, G).
    pub landing_position_m: [f64; 3],
    /// Force-model evaluations the flight cost.
    pub force_evaluations: u32,
    /// Landing velocity (m/s, G).
    pub landing_velocity_mps: [f64; 3],
    /// Air density flown through (kg/m³).
    pub air_density_kgm3: f64,
    /// Accepted integrator steps.
    pub steps: u32,
    /// Rejected integrator steps.
    pub rejected_steps: u32,
    /// Bounce and roll, only with a ground (flattened into `flight`).
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub ground: Option<GroundReport>,
}

/// Bounce and roll to rest (keys of the JSON object `flight`, only with a ground).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GroundReport {
    /// Total: tee to rest, horizontal (m).
    pub total_m: f64,
    /// Roll: first landing to rest along the ground (m; negative: spun back).
    pub roll_m: f64,
    /// Bounces (hops).
    pub bounces: u32,
    /// Rest position (m, G).
    pub rest_position_m: [f64; 3],
    /// Launch to rest (s).
    pub time_to_rest_s: f64,
    /// The ball was still rolling at the roll time cap (a slope steeper than the
    /// surface's rolling resistance): "rest" is where it was then.
    pub still_rolling: bool,
}

/// One result: impact, flight or both.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Report {
    /// The launch.
    pub launch: LaunchReport,
    /// The club after impact.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub club_after: Option<ClubAfter>,
    /// Impulse on the ball (N·s, G).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub impulse_ns: Option<[f64; 3]>,
    /// The flight.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub flight: Option<FlightReport>,
}

// ---------------------------------------------------------------- CSV

const LAUNCH_COLUMNS: &[&str] = &[
    "ball_speed_mps",
    "launch_angle_deg",
    "launch_direction_deg",
    "spin_rpm",
    "backspin_rpm",
    "sidespin_rpm",
    "spin_axis_deg",
];
const SMASH_COLUMN: &[&str] = &["smash_factor"];
const LAUNCH_VECTOR_COLUMNS: &[&str] = &[
    "ball_velocity_mps_x",
    "ball_velocity_mps_y",
    "ball_velocity_mps_z",
    "ball_spin_radps_x",
    "ball_spin_radps_y",
    "ball_spin_radps_z",
];
const IMPACT_COLUMNS: &[&str] = &[
    "club_after_velocity_mps_x",
    "club_after_velocity_mps_y",
    "club_after_velocity_mps_z",
    "club_after_spin_radps_x",
    "club_after_spin_radps_y",
    "club_after_spin_radps_z",
    "impulse_ns_x",
    "impulse_ns_y",
    "impulse_ns_z",
];
const FLIGHT_COLUMNS: &[&str] = &[
    "carry_m",
    "side_m",
    "carry_x_m",
    "apex_m",
    "apex_time_s",
    "flight_time_s",
    "land_angle_deg",
    "land_speed_mps",
    "land_spin_rpm",
    "landing_position_m_x",
    "landing_position_m_y",
    "landing_position_m_z",
    "force_evaluations",
    "landing_velocity_mps_x",
    "landing_velocity_mps_y",
    "landing_velocity_mps_z",
    "air_density_kgm3",
    "steps",
    "rejected_steps",
];

const GROUND_COLUMNS: &[&str] = &[
    "total_m",
    "roll_m",
    "bounces",
    "rest_position_m_x",
    "rest_position_m_y",
    "rest_position_m_z",
    "time_to_rest_s",
    "still_rolling",
];

/// The CSV result columns of `mode`, in order (JSON key names, flattened), with the
/// ground's when `ground`.
#[must_use]
pub fn csv_columns(mode: Mode, ground: bool) -> Vec<&'static str> {
    let mut c = Vec::new();
    c.extend_from_slice(LAUNCH_COLUMNS);
    if mode != Mode::Flight {
        c.extend_from_slice(SMASH_COLUMN);
    }
    c.extend_from_slice(LAUNCH_VECTOR_COLUMNS);
    if mode != Mode::Flight {
        c.extend_from_slice(IMPACT_COLUMNS);
    }
    if mode != Mode::Impact {
        c.extend_from_slice(FLIGHT_COLUMNS);
        if ground {
            c.extend_from_slice(GROUND_COLUMNS);
        }
    }
    c
}

/// Writes a comma-separated header line.
pub fn write_csv_header(
    out: &mut Vec<u8>,
    prefix: &[&str],
    mode: Mode,
    ground: bool,
    suffix: &[&str],
) {
    let middle = csv_columns(mode, ground);
    let cols = prefix.iter().chain(middle.iter()).chain(suffix.iter());
    for (i, c) in cols.enumerate() {
        if i > 0 {
            out.push(b',');
        }
        out.extend_from_slice(c.as_bytes());
    }
    out.push(b'\n');
}

/// Fast float output (shortest round-trip form).
pub struct Floats(ryu::Buffer);

impl Default for Floats {
    fn default() -> Self {
        Self(ryu::Buffer::new())
    }
}

impl Floats {
    /// Appends `x` (empty for a non-finite value).
    pub fn put(&mut self, out: &mut Vec<u8>, x: f64) {
        if x.is_finite() {
            out.extend_from_slice(self.0.format_finite(x).as_bytes());
        }
    }

    fn field(&mut self, out: &mut Vec<u8>, x: f64) {
        out.push(b',');
        self.put(out, x);
    }

    fn vector(&mut self, out: &mut Vec<u8>, v: &[f64; 3]) {
        for x in v {
            self.field(out, *x);
        }
    }

    fn count(out: &mut Vec<u8>, n: u32) {
        out.push(b',');
        let mut b = itoa_u32(n);
        out.extend_from_slice(b.as_bytes_mut());
    }
}

struct Digits {
    buf: [u8; 10],
    start: usize,
}

impl Digits {
    fn as_bytes_mut(&mut self) -> &[u8] {
        &self.buf[self.start..]
    }
}

fn itoa_u32(mut n: u32) -> Digits {
    let mut buf = [0u8; 10];
    let mut i = buf.len();
    loop {
        i -= 1;
        // n % 10 < 10: the cast cannot truncate.
        #[allow(clippy::cast_possible_truncation)]
        let d = (n % 10) as u8;
        buf[i] = b'0' + d;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    Digits { buf, start: i }
}

/// Appends the result fields of `r` (each preceded by a comma) in [`csv_columns`] order.
pub fn write_csv_fields(out: &mut Vec<u8>, f: &mut Floats, mode: Mode, ground: bool, r: &Report) {
    let l = &r.launch;
    for x in [
        l.ball_speed_mps,
        l.launch_angle_deg,
        l.launch_direction_deg,
        l.spin_rpm,
        l.backspin_rpm,
        l.sidespin_rpm,
        l.spin_axis_deg,
    ] {
        f.field(out, x);
    }
    if mode != Mode::Flight {
        f.field(out, l.smash_factor.unwrap_or(f64::NAN));
    }
    f.vector(out, &l.ball_velocity_mps);
    f.vector(out, &l.ball_spin_radps);
    if mode != Mode::Flight {
        let nan = [f64::NAN; 3];
        let c = r.club_after.unwrap_or(ClubAfter {
            velocity_mps: nan,
            spin_radps: nan,
        });
        f.vector(out, &c.velocity_mps);
        f.vector(out, &c.spin_radps);
        f.vector(out, &r.impulse_ns.unwrap_or(nan));
    }
    if mode != Mode::Impact {
        if let Some(g) = &r.flight {
            for x in [
                g.carry_m,
                g.side_m,
                g.carry_x_m,
                g.apex_m,
                g.apex_time_s,
                g.flight_time_s,
                g.land_angle_deg,
                g.land_speed_mps,
                g.land_spin_rpm,
            ] {
                f.field(out, x);
            }
            f.vector(out, &g.landing_position_m);
            Floats::count(out, g.force_evaluations);
            f.vector(out, &g.landing_velocity_mps);
            f.field(out, g.air_density_kgm3);
            Floats::count(out, g.steps);
            Floats::count(out, g.rejected_steps);
        } else {
            for _ in FLIGHT_COLUMNS {
                out.push(b',');
            }
        }
        if ground {
            match r.flight.and_then(|g| g.ground) {
                Some(g) => {
                    f.field(out, g.total_m);
                    f.field(out, g.roll_m);
                    Floats::count(out, g.bounces);
                    f.vector(out, &g.rest_position_m);
                    f.field(out, g.time_to_rest_s);
                    out.extend_from_slice(if g.still_rolling { b",true" } else { b",false" });
                }
                None => out.resize(out.len() + GROUND_COLUMNS.len(), b','),
            }
        }
    }
}

/// Appends empty result fields (an error row).
pub fn write_csv_empty(out: &mut Vec<u8>, mode: Mode, ground: bool) {
    let n = LAUNCH_COLUMNS.len()
        + LAUNCH_VECTOR_COLUMNS.len()
        + if mode == Mode::Flight {
            0
        } else {
            SMASH_COLUMN.len() + IMPACT_COLUMNS.len()
        }
        + if mode == Mode::Impact {
            0
        } else {
            FLIGHT_COLUMNS.len() + if ground { GROUND_COLUMNS.len() } else { 0 }
        };
    out.resize(out.len() + n, b',');
}

/// Appends the result values of `r` in [`csv_columns`] order as numbers (counts as
/// floats, `still_rolling` as 1/0, what `r` lacks as NaN): the Python package's arrays.
pub fn csv_values(out: &mut Vec<f64>, mode: Mode, ground: bool, r: &Report) {
    let l = &r.launch;
    out.extend([
        l.ball_speed_mps,
        l.launch_angle_deg,
        l.launch_direction_deg,
        l.spin_rpm,
        l.backspin_rpm,
        l.sidespin_rpm,
        l.spin_axis_deg,
    ]);
    if mode != Mode::Flight {
        out.push(l.smash_factor.unwrap_or(f64::NAN));
    }
    out.extend(l.ball_velocity_mps);
    out.extend(l.ball_spin_radps);
    let nan = [f64::NAN; 3];
    if mode != Mode::Flight {
        out.extend(r.club_after.map_or(nan, |c| c.velocity_mps));
        out.extend(r.club_after.map_or(nan, |c| c.spin_radps));
        out.extend(r.impulse_ns.unwrap_or(nan));
    }
    if mode == Mode::Impact {
        return;
    }
    match &r.flight {
        Some(g) => {
            out.extend([
                g.carry_m,
                g.side_m,
                g.carry_x_m,
                g.apex_m,
                g.apex_time_s,
                g.flight_time_s,
                g.land_angle_deg,
                g.land_speed_mps,
                g.land_spin_rpm,
            ]);
            out.extend(g.landing_position_m);
            out.push(f64::from(g.force_evaluations));
            out.extend(g.landing_velocity_mps);
            out.push(g.air_density_kgm3);
            out.push(f64::from(g.steps));
            out.push(f64::from(g.rejected_steps));
        }
        None => out.extend(FLIGHT_COLUMNS.iter().map(|_| f64::NAN)),
    }
    if ground {
        match r.flight.and_then(|g| g.ground) {
            Some(g) => {
                out.extend([g.total_m, g.roll_m, f64::from(g.bounces)]);
                out.extend(g.rest_position_m);
                out.push(g.time_to_rest_s);
                out.push(if g.still_rolling { 1.0 } else { 0.0 });
            }
            None => out.extend(GROUND_COLUMNS.iter().map(|_| f64::NAN)),
        }
    }
}

/// One CSV header plus one row (the `--csv` output of a single command).
#[must_use]
pub fn single_csv(mode: Mode, r: &Report) -> Vec<u8> {
    let ground = r.flight.is_some_and(|g| g.ground.is_some());
    let mut out = Vec::new();
    write_csv_header(&mut out, &[], mode, ground, &[]);
    let mut f = Floats::default();
    let start = out.len();
    write_csv_fields(&mut out, &mut f, mode, ground, r);
    // Drop the leading comma of the first field.
    out.remove(start);
    out.push(b'\n');
    out
}

// ---------------------------------------------------------------- table

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
    let l = &r.launch;
    let _ = writeln!(out, "LAUNCH");
    let (v, u) = speed(l.ball_speed_mps);
    row(&mut out, "ball speed", v, 1, u);
    if let Some(s) = l.smash_factor {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integers() {
        for n in [0u32, 7, 10, 4_294_967_295] {
            assert_eq!(itoa_u32(n).as_bytes_mut(), n.to_string().as_bytes());
        }
    }

    /// The numeric row matches the CSV row, column for column, in every mode.
    #[test]
    fn csv_values_follow_the_csv_columns() {
        use crate::compute::{Numerics, run};
        use crate::params::{Key, Params};
        let mut p = Params::default();
        Key::Ground.set(
            &mut p,
            Units::Si,
            Key::Ground.parse("fairway").expect("a surface"),
        );
        for mode in [Mode::Impact, Mode::Flight, Mode::Shot] {
            let r = run(mode, &p, &Numerics::default()).expect("the defaults fly");
            let ground = mode != Mode::Impact;
            let mut values = Vec::new();
            csv_values(&mut values, mode, ground, &r);
            let text = String::from_utf8(single_csv(mode, &r)).expect("UTF-8");
            let row: Vec<&str> = text.lines().nth(1).unwrap_or_default().split(',').collect();
            assert_eq!(values.len(), csv_columns(mode, ground).len());
            assert_eq!(values.len(), row.len());
            for (v, t) in values.iter().zip(row) {
                let t = match t {
                    "true" => 1.0,
                    "false" => 0.0,
                    t => t.parse().expect("a number"),
                };
                assert_eq!(*v, t);
            }
        }
    }
}
