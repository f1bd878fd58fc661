//! Results in `f64`, SI: the JSON contract (serde) and the CSV columns (one field visitor,
//! [`visit_fields`]). The launch-monitor table for people is the CLI's.

use crate::mode::Mode;
use carry_core::ground::{Rollout, RunEnd};
use carry_core::real::to_f64;
use carry_core::units::{to_deg, to_rpm};
use carry_core::{LaunchMetrics, Real};
use serde::Serialize;

/// A launch as a launch monitor reports it (f64; m/s, degrees, rpm): the figures every
/// record of a launch shares — [`LaunchReport`] here, lab's `ShotSummary` — converted from
/// the core's [`LaunchMetrics`] in one place, [`LaunchFigures::of`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LaunchFigures {
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
}

impl LaunchFigures {
    /// The figures of the core's launch metrics.
    #[must_use]
    pub fn of<T: Real>(m: &LaunchMetrics<T>) -> Self {
        Self {
            ball_speed_mps: to_f64(m.ball_speed_mps),
            launch_angle_deg: to_f64(to_deg(m.launch_angle_rad)),
            launch_direction_deg: to_f64(to_deg(m.launch_direction_rad)),
            spin_rpm: to_f64(to_rpm(m.spin_radps)),
            backspin_rpm: to_f64(to_rpm(m.backspin_radps)),
            sidespin_rpm: to_f64(to_rpm(m.sidespin_radps)),
            spin_axis_deg: to_f64(to_deg(m.spin_axis_rad)),
        }
    }
}

/// The launch, in launch-monitor terms (JSON object `launch`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LaunchReport {
    /// Ball speed, angles and spins (flattened into `launch`).
    #[serde(flatten)]
    pub figures: LaunchFigures,
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

/// A vector's components in `f64` (a report's `[x, y, z]`).
pub(crate) fn f3<T: Real>(v: &nalgebra::Vector3<T>) -> [f64; 3] {
    [to_f64(v.x), to_f64(v.y), to_f64(v.z)]
}

impl GroundReport {
    /// The report of a core run-out (the CLI's `flight` keys, the lab's shot summaries).
    #[must_use]
    pub fn of<T: Real>(g: &Rollout<T>) -> Self {
        Self {
            total_m: to_f64(g.total_m),
            roll_m: to_f64(g.roll_m),
            bounces: g.bounces,
            rest_position_m: f3(&g.rest_position_m),
            time_to_rest_s: to_f64(g.time_to_rest_s),
            still_rolling: g.end == RunEnd::StillRolling,
        }
    }
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

/// One result field's value, as [`visit_fields`] hands it out.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cell {
    /// A real number (SI, degrees, rpm, as the column name says).
    Real(f64),
    /// A count (force evaluations, steps, bounces).
    Count(u32),
    /// A flag (`still_rolling`).
    Flag(bool),
    /// The result has no such field (an error row, or a run without it).
    Missing,
}

/// The three column names of a vector `v`: `v_x`, `v_y`, `v_z`.
macro_rules! xyz {
    ($v:literal) => {
        [concat!($v, "_x"), concat!($v, "_y"), concat!($v, "_z")]
    };
}

#[inline(always)]
fn real<F: FnMut(&'static str, Cell)>(f: &mut F, name: &'static str, x: Option<f64>) {
    f(name, x.map_or(Cell::Missing, Cell::Real));
}

#[inline(always)]
fn vector<F: FnMut(&'static str, Cell)>(f: &mut F, names: [&'static str; 3], v: Option<[f64; 3]>) {
    for (i, name) in names.into_iter().enumerate() {
        real(f, name, v.map(|v| v[i]));
    }
}

#[inline(always)]
fn count<F: FnMut(&'static str, Cell)>(f: &mut F, name: &'static str, n: Option<u32>) {
    f(name, n.map_or(Cell::Missing, Cell::Count));
}

/// Visits the CSV result columns of `mode` in order — the JSON key names, flattened (a
/// vector `v` as `v_x`, `v_y`, `v_z`), with the ground's when `ground` — handing `f` each
/// column's name and its value in `r` ([`Cell::Missing`] without `r`, or where `r` lacks
/// it). The one list of the columns: [`csv_columns`], [`write_csv_fields`],
/// [`write_csv_empty`] and [`csv_values`] all walk it.
pub fn visit_fields<F: FnMut(&'static str, Cell)>(
    mode: Mode,
    ground: bool,
    r: Option<&Report>,
    mut f: F,
) {
    let f = &mut f;
    let l = r.map(|r| &r.launch);
    let m = l.map(|l| &l.figures);
    real(f, "ball_speed_mps", m.map(|m| m.ball_speed_mps));
    real(f, "launch_angle_deg", m.map(|m| m.launch_angle_deg));
    real(f, "launch_direction_deg", m.map(|m| m.launch_direction_deg));
    real(f, "spin_rpm", m.map(|m| m.spin_rpm));
    real(f, "backspin_rpm", m.map(|m| m.backspin_rpm));
    real(f, "sidespin_rpm", m.map(|m| m.sidespin_rpm));
    real(f, "spin_axis_deg", m.map(|m| m.spin_axis_deg));
    if mode != Mode::Flight {
        real(f, "smash_factor", l.and_then(|l| l.smash_factor));
    }
    vector(f, xyz!("ball_velocity_mps"), l.map(|l| l.ball_velocity_mps));
    vector(f, xyz!("ball_spin_radps"), l.map(|l| l.ball_spin_radps));
    if mode != Mode::Flight {
        let c = r.and_then(|r| r.club_after);
        vector(
            f,
            xyz!("club_after_velocity_mps"),
            c.map(|c| c.velocity_mps),
        );
        vector(f, xyz!("club_after_spin_radps"), c.map(|c| c.spin_radps));
        vector(f, xyz!("impulse_ns"), r.and_then(|r| r.impulse_ns));
    }
    if mode == Mode::Impact {
        return;
    }
    let g = r.and_then(|r| r.flight.as_ref());
    real(f, "carry_m", g.map(|g| g.carry_m));
    real(f, "side_m", g.map(|g| g.side_m));
    real(f, "carry_x_m", g.map(|g| g.carry_x_m));
    real(f, "apex_m", g.map(|g| g.apex_m));
    real(f, "apex_time_s", g.map(|g| g.apex_time_s));
    real(f, "flight_time_s", g.map(|g| g.flight_time_s));
    real(f, "land_angle_deg", g.map(|g| g.land_angle_deg));
    real(f, "land_speed_mps", g.map(|g| g.land_speed_mps));
    real(f, "land_spin_rpm", g.map(|g| g.land_spin_rpm));
    vector(
        f,
        xyz!("landing_position_m"),
        g.map(|g| g.landing_position_m),
    );
    count(f, "force_evaluations", g.map(|g| g.force_evaluations));
    vector(
        f,
        xyz!("landing_velocity_mps"),
        g.map(|g| g.landing_velocity_mps),
    );
    real(f, "air_density_kgm3", g.map(|g| g.air_density_kgm3));
    count(f, "steps", g.map(|g| g.steps));
    count(f, "rejected_steps", g.map(|g| g.rejected_steps));
    if !ground {
        return;
    }
    let h = g.and_then(|g| g.ground);
    real(f, "total_m", h.map(|h| h.total_m));
    real(f, "roll_m", h.map(|h| h.roll_m));
    count(f, "bounces", h.map(|h| h.bounces));
    vector(f, xyz!("rest_position_m"), h.map(|h| h.rest_position_m));
    real(f, "time_to_rest_s", h.map(|h| h.time_to_rest_s));
    f(
        "still_rolling",
        h.map_or(Cell::Missing, |h| Cell::Flag(h.still_rolling)),
    );
}

/// The CSV result columns of `mode`, in order (JSON key names, flattened), with the
/// ground's when `ground`.
#[must_use]
pub fn csv_columns(mode: Mode, ground: bool) -> Vec<&'static str> {
    let mut c = Vec::new();
    visit_fields(mode, ground, None, |name, _| c.push(name));
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

    /// Appends a comma and `cell` (empty when missing or not finite).
    #[inline(always)]
    fn field(&mut self, out: &mut Vec<u8>, cell: Cell) {
        out.push(b',');
        match cell {
            Cell::Real(x) => self.put(out, x),
            Cell::Count(n) => out.extend_from_slice(itoa_u32(n).as_bytes_mut()),
            Cell::Flag(b) => out.extend_from_slice(if b { b"true" } else { b"false" }),
            Cell::Missing => {}
        }
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
    visit_fields(
        mode,
        ground,
        Some(r),
        #[inline(always)]
        |_, cell| f.field(out, cell),
    );
}

/// Appends empty result fields (an error row).
pub fn write_csv_empty(out: &mut Vec<u8>, mode: Mode, ground: bool) {
    visit_fields(mode, ground, None, |_, _| out.push(b','));
}

/// Appends the result values of `r` in [`csv_columns`] order as numbers (counts as
/// floats, `still_rolling` as 1/0, what `r` lacks as NaN): the Python package's arrays.
pub fn csv_values(out: &mut Vec<f64>, mode: Mode, ground: bool, r: &Report) {
    visit_fields(mode, ground, Some(r), |_, cell| out.push(cell_value(cell)));
}

/// As [`csv_values`], into `out` in place: `out` holds one value per [`csv_columns`]
/// entry (what it has beyond them is left as it is).
pub fn write_values(out: &mut [f64], mode: Mode, ground: bool, r: &Report) {
    let mut slots = out.iter_mut();
    visit_fields(
        mode,
        ground,
        Some(r),
        #[inline(always)]
        |_, cell| {
            if let Some(slot) = slots.next() {
                *slot = cell_value(cell);
            }
        },
    );
}

/// A cell as a number: counts as floats, `still_rolling` as 1/0, a missing value as NaN.
#[inline(always)]
fn cell_value(cell: Cell) -> f64 {
    match cell {
        Cell::Real(x) => x,
        Cell::Count(n) => f64::from(n),
        Cell::Flag(b) => f64::from(u8::from(b)),
        Cell::Missing => f64::NAN,
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integers() {
        for n in [0u32, 7, 10, 4_294_967_295] {
            assert_eq!(itoa_u32(n).as_bytes_mut(), n.to_string().as_bytes());
        }
    }
}
