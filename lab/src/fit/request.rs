//! A fit request (`carry fit`, the Python package's `carry.fit`): fits a model family's
//! coefficients to measured shots (the fitting itself is [`crate::fit`]); this module reads
//! the CSV in the CLI's names and units, shows progress, and reports the coefficients, the
//! per-row residuals, the summaries and the leave-one-out errors (a table or the JSON
//! document), or writes the fitted model as TOML.
//!
//! Input columns (header names, case-insensitive; `-` and `_` alike):
//! * launch: `ball_speed`, `launch_angle` (or `launch`), `launch_direction`, and
//!   `backspin` + `sidespin` or `spin` + `spin_axis`;
//! * observed: `carry` (required), `apex` (or `max_height`), `land_angle` (or `land`),
//!   `flight_time`, `side`;
//! * conditions per row (override the options): `temperature`, `humidity` (%),
//!   `pressure` (Pa) or `altitude`, `air_density`;
//! * `label`, `weight` (default 1).
//!
//! Values are in `--units`, unless the column name ends in a unit: `_mph`, `_mps`, `_yd`,
//! `_ft`, `_m`, `_deg`, `_rpm`, `_s`, `_c`, `_f`, `_pa`, `_pct` (so TrackMan's
//! `ball_speed_mph, launch_deg, spin_rpm, max_height_yd, land_deg, carry_yd` read as they
//! are). Without a `label` column, the text of `tour`, `who`, `club` and `source` columns
//! labels the rows. Other columns are ignored and listed.
//!
//! A single-drive TrackMan export (the header `Ball,Club Speed,…,Carry Flat - Length,…` of
//! `../shared/data/trackman_amateur_drives.csv`, a units line under it) is recognised by its
//! header and read by [`read_drives`]: its premium indoor rows, each with its session of
//! 1,000 rows, which the cross-validation holds out together.

use crate::fit::flight::{AeroFamily, AeroProblem, ShotRow};
use crate::fit::{self, Fit, FitOptions, single_shots};
use carry_core::Launch;
use carry_core::flight::Integrator;
use carry_core::units::{M_PER_FOOT, M_PER_YARD, MPS_PER_MPH, deg, rpm};
use carry_io::error::{Failure, InputError};
use carry_io::params::SceneParams;
use carry_io::units::{Quantity, Units};
use serde::Serialize;
use std::fmt::Write as _;
use std::io::IsTerminal as _;
use std::path::PathBuf;

pub use super::command::FitRequest;
use super::command::{Produced, status};

/// The air-condition options of a row or of the command line (the scene options' air
/// fields: density, temperature, humidity, pressure, altitude; SI, humidity in percent).
pub type Conditions = SceneParams;

/// Whether `c` names any air condition.
fn any_condition(c: &Conditions) -> bool {
    c.air_density_kgm3.is_some()
        || c.temperature_c.is_some()
        || c.humidity_pct.is_some()
        || c.pressure_pa.is_some()
        || c.altitude_m.is_some()
}

/// What a column holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Field {
    BallSpeed,
    LaunchAngle,
    LaunchDirection,
    Backspin,
    Sidespin,
    Spin,
    SpinAxis,
    Carry,
    Apex,
    LandAngle,
    FlightTime,
    Side,
    Temperature,
    Humidity,
    Pressure,
    Altitude,
    AirDensity,
    Weight,
}

const NAMES: &[(&str, Field)] = &[
    ("ball_speed", Field::BallSpeed),
    ("launch_angle", Field::LaunchAngle),
    ("launch", Field::LaunchAngle),
    ("launch_direction", Field::LaunchDirection),
    ("backspin", Field::Backspin),
    ("sidespin", Field::Sidespin),
    ("spin", Field::Spin),
    ("spin_axis", Field::SpinAxis),
    ("carry", Field::Carry),
    ("apex", Field::Apex),
    ("max_height", Field::Apex),
    ("land_angle", Field::LandAngle),
    ("land", Field::LandAngle),
    ("flight_time", Field::FlightTime),
    ("side", Field::Side),
    ("temperature", Field::Temperature),
    ("humidity", Field::Humidity),
    ("pressure", Field::Pressure),
    ("altitude", Field::Altitude),
    ("air_density", Field::AirDensity),
    ("weight", Field::Weight),
];

/// Label-source columns when there is no `label`.
const LABEL_PARTS: [&str; 4] = ["tour", "who", "club", "source"];

/// A conversion of a column's values to SI.
type ToSi = fn(f64) -> f64;

/// A unit a column name may end in: how to turn its values into SI.
fn suffix_unit(name: &str) -> Option<(&str, ToSi)> {
    const SUFFIXES: &[(&str, ToSi)] = &[
        ("_mph", |x| x * MPS_PER_MPH),
        ("_mps", |x| x),
        ("_yd", |x| x * M_PER_YARD),
        ("_ft", |x| x * M_PER_FOOT),
        ("_m", |x| x),
        ("_deg", |x| x),
        ("_rpm", |x| x),
        ("_s", |x| x),
        ("_c", |x| x),
        ("_f", |x| (x - 32.0) * (5.0 / 9.0)),
        ("_pa", |x| x),
        ("_pct", |x| x),
    ];
    SUFFIXES
        .iter()
        .find_map(|&(s, f)| name.strip_suffix(s).map(|base| (base, f)))
}

fn quantity(f: Field) -> Quantity {
    match f {
        Field::BallSpeed => Quantity::Speed,
        Field::Carry | Field::Side => Quantity::Long,
        Field::Apex | Field::Altitude => Quantity::Height,
        Field::Temperature => Quantity::Temperature,
        _ => Quantity::Plain,
    }
}

/// A column: its index, field and conversion.
struct Column {
    index: usize,
    field: Field,
    to_si: Box<dyn Fn(f64) -> f64>,
}

/// The rows of a fit input and the names of the columns it ignored.
///
/// # Errors
/// An unreadable file, no header, no `carry` column, or a bad value (naming the line and
/// the column).
pub fn read_rows(
    input: &PathBuf,
    units: Units,
    global: &Conditions,
) -> Result<(Vec<ShotRow>, Vec<String>), InputError> {
    let (source, _) = carry_io::batch::open(input)?;
    let name = input.display().to_string();
    let mut rdr = carry_io::batch::dialect().from_reader(source);
    let header = rdr
        .headers()
        .map_err(|e| InputError::new("input", format!("{name}: cannot read the header: {e}")))?
        .clone();
    let mut columns = Vec::new();
    let (mut label, mut label_parts, mut ignored) = (None, Vec::new(), Vec::new());
    for (i, h) in header.iter().enumerate() {
        let h = h.to_ascii_lowercase().replace('-', "_");
        if h == "label" {
            label = Some(i);
            continue;
        }
        let known = |n: &str| NAMES.iter().find(|(k, _)| *k == n).map(|&(_, f)| f);
        let column = if let Some(f) = known(&h) {
            let q = quantity(f);
            Some((
                f,
                Box::new(move |x| units.to_si(q, x)) as Box<dyn Fn(f64) -> f64>,
            ))
        } else if let Some((base, conv)) = suffix_unit(&h) {
            known(base).map(|f| (f, Box::new(conv) as Box<dyn Fn(f64) -> f64>))
        } else {
            None
        };
        match column {
            Some((field, to_si)) => {
                if columns.iter().any(|c: &Column| c.field == field) {
                    return Err(InputError::new(
                        "input",
                        format!("{name}: column '{h}' repeats another column's quantity"),
                    ));
                }
                columns.push(Column {
                    index: i,
                    field,
                    to_si,
                });
            }
            None if LABEL_PARTS.contains(&h.as_str()) => label_parts.push(i),
            None => ignored.push(h),
        }
    }
    let has = |f: Field| columns.iter().any(|c| c.field == f);
    for (need, what) in [
        (Field::Carry, "carry"),
        (Field::BallSpeed, "ball_speed"),
        (Field::LaunchAngle, "launch_angle"),
    ] {
        if !has(need) {
            return Err(InputError::new(
                "input",
                format!("{name}: no '{what}' column"),
            ));
        }
    }
    if !(has(Field::Backspin) || has(Field::Spin)) {
        return Err(InputError::new(
            "input",
            format!("{name}: no 'backspin' or 'spin' column"),
        ));
    }
    let mut rows = Vec::new();
    for (n, record) in rdr.records().enumerate() {
        let line = n + 2;
        let record = record.map_err(|e| InputError::new("input", format!("line {line}: {e}")))?;
        let mut v: Vec<(Field, f64)> = Vec::new();
        for c in &columns {
            let text = record.get(c.index).unwrap_or("").trim();
            if text.is_empty() {
                continue;
            }
            let col = header.get(c.index).unwrap_or("?");
            let x: f64 = text.parse().map_err(|_| {
                InputError::new(
                    "input",
                    format!("line {line}: {col}: '{text}' is not a number"),
                )
            })?;
            if !x.is_finite() {
                return Err(InputError::new(
                    "input",
                    format!("line {line}: {col}: '{text}' is not a finite number"),
                ));
            }
            v.push((c.field, (c.to_si)(x)));
        }
        let get = |f: Field| v.iter().find(|(g, _)| *g == f).map(|&(_, x)| x);
        let missing =
            |what: &str| InputError::new("input", format!("line {line}: {what}: missing value"));
        let (backspin, sidespin) = match (get(Field::Backspin), get(Field::Spin)) {
            (Some(b), _) => (b, get(Field::Sidespin).unwrap_or(0.0)),
            (None, Some(s)) => {
                let axis = get(Field::SpinAxis).unwrap_or(0.0).to_radians();
                (s * axis.cos(), s * axis.sin())
            }
            (None, None) => return Err(missing("backspin")),
        };
        let row = Conditions {
            air_density_kgm3: get(Field::AirDensity),
            temperature_c: get(Field::Temperature),
            humidity_pct: get(Field::Humidity),
            pressure_pa: get(Field::Pressure),
            altitude_m: get(Field::Altitude),
            ..Conditions::default()
        };
        let conditions = if any_condition(&row) { row } else { *global };
        let air = carry_io::scene::air(&conditions).map_err(|e| {
            InputError::new("input", format!("line {line}: {}: {}", e.key, e.reason))
        })?;
        let weight = get(Field::Weight).unwrap_or(1.0);
        if !(weight > 0.0) {
            return Err(InputError::new(
                "input",
                format!("line {line}: weight: must be positive"),
            ));
        }
        let text = |i: usize| record.get(i).unwrap_or("").to_string();
        let label = label.map(text).unwrap_or_else(|| {
            let parts: Vec<String> = label_parts.iter().map(|&i| text(i)).collect();
            if parts.is_empty() {
                format!("line {line}")
            } else {
                parts.join(" ")
            }
        });
        rows.push(ShotRow {
            label,
            launch: Launch {
                ball_speed_mps: get(Field::BallSpeed).ok_or_else(|| missing("ball_speed"))?,
                launch_angle_rad: deg(
                    get(Field::LaunchAngle).ok_or_else(|| missing("launch_angle"))?
                ),
                launch_direction_rad: deg(get(Field::LaunchDirection).unwrap_or(0.0)),
                backspin_radps: rpm(backspin),
                sidespin_radps: rpm(sidespin),
            },
            air,
            carry_m: get(Field::Carry).ok_or_else(|| missing("carry"))?,
            apex_m: get(Field::Apex),
            land_angle_deg: get(Field::LandAngle),
            flight_time_s: get(Field::FlightTime),
            side_m: get(Field::Side),
            weight,
            wind_mps: [0.0; 3],
            session: None,
        });
    }
    if rows.is_empty() {
        return Err(InputError::new("input", format!("{name}: no rows")));
    }
    Ok((rows, ignored))
}

/// Integrator tolerance of a fit with single drives in it: Dormand–Prince at 1e-9 (carry
/// within 1e-8 relative of the tables' 1e-11, 2.5× faster).
pub const DRIVES_TOLERANCE: f64 = 1e-9;

/// Whether `input` is a single-drive TrackMan export (`Ball,Club Speed,…` with
/// `Carry Flat - Length`, the format of `../shared/data/trackman_amateur_drives.csv`).
fn is_drives_file(input: &PathBuf) -> bool {
    if input.as_os_str() == "-" {
        return false;
    }
    std::fs::read_to_string(input).is_ok_and(|t| crate::drives::is_export(&t))
}

/// The rows of a fit input: a single-drive export ([`read_drives`]) or a table
/// ([`read_rows`]).
///
/// # Errors
/// As [`read_rows`] or [`read_drives`].
pub fn read_input(
    input: &PathBuf,
    units: Units,
    global: &Conditions,
) -> Result<(Vec<ShotRow>, Vec<String>), InputError> {
    if is_drives_file(input) {
        read_drives(input, global)
    } else {
        read_rows(input, units, global)
    }
}

/// The single drives of a TrackMan export as fit rows (issue 35; [`single_shots`]): the
/// premium-ball rows hit indoors with a complete, plausible launch, in the command's air,
/// each with its session (held out together in the cross-validation), less the rows whose
/// carry the default model misses by more than [`single_shots::SCREEN_PCT`]. What was left
/// out is listed with the ignored columns.
///
/// # Errors
/// The file cannot be read or parsed; the conditions are invalid.
pub fn read_drives(
    input: &std::path::Path,
    global: &Conditions,
) -> Result<(Vec<ShotRow>, Vec<String>), InputError> {
    let name = input.display().to_string();
    let drives = crate::drives::read(input).map_err(|e| InputError::new("input", e))?;
    let air = carry_io::scene::air(global)
        .map_err(|e| InputError::new("input", format!("{name}: {}: {}", e.key, e.reason)))?;
    let all = single_shots::drive_rows(&drives, air);
    let premium = single_shots::premium_indoors(&all);
    let reference: Vec<ShotRow> = premium.iter().map(|r| r.row.clone()).collect();
    let predicted = single_shots::carries(
        &carry_core::aero::AeroModel::default(),
        &reference,
        &Integrator::dormand_prince(DRIVES_TOLERANCE),
    );
    let kept = single_shots::screened(&premium, &predicted);
    let note = format!(
        "{name}: {} of {} drives (premium ball, indoors, complete launch; left out: {} \
         incomplete or below 1°, {} outdoors, {} other balls, {} off by > {} % with the \
         default model)",
        kept.len(),
        drives.len(),
        drives.len() - all.len(),
        all.iter().filter(|r| r.outdoors).count(),
        all.iter()
            .filter(|r| !r.outdoors && r.ball != crate::drives::BallKind::Premium)
            .count(),
        premium.len() - kept.len(),
        single_shots::SCREEN_PCT
    );
    if kept.is_empty() {
        return Err(InputError::new("input", format!("{name}: no rows")));
    }
    Ok((kept.into_iter().map(|r| r.row).collect(), vec![note]))
}

/// The JSON document of a fit (SI).
#[derive(Serialize)]
struct Report<'a> {
    family: &'a str,
    rows: usize,
    ignored_columns: &'a [String],
    coefficients: serde_json::Map<String, serde_json::Value>,
    fit: &'a Fit,
}

impl FitRequest {
    fn conditions(&self) -> Conditions {
        let u = self.units;
        Conditions {
            air_density_kgm3: self.air_density,
            temperature_c: self.temperature.map(|t| u.to_si(Quantity::Temperature, t)),
            humidity_pct: self.humidity,
            pressure_pa: self.pressure,
            altitude_m: self.altitude.map(|h| u.to_si(Quantity::Height, h)),
            ..Conditions::default()
        }
    }
}

/// Fits (or evaluates) as `cmd` asks, writes `--output` if given, and returns what
/// `carry fit` prints: the table, or the JSON document as text with `--json`.
///
/// # Errors
/// Bad input (status 2); a fit that cannot start or a file that cannot be written.
pub fn report(cmd: &FitRequest) -> Result<String, Failure> {
    match produce(cmd, false)? {
        Produced::Text(t) => Ok(t),
        Produced::Value(v) => Ok(v.to_string()),
    }
}

/// As [`report`] with `json`, the document as a value (the Python package's `carry.fit`),
/// after [`FitRequest::check`].
///
/// # Errors
/// As [`report`].
pub fn document(cmd: &FitRequest) -> Result<serde_json::Value, Failure> {
    cmd.check()?;
    let cmd = FitRequest {
        json: true,
        no_progress: true,
        ..cmd.clone()
    };
    match produce(&cmd, true)? {
        Produced::Value(v) => Ok(v),
        Produced::Text(t) => Err(Failure::Other(format!("not a document: {t}"))),
    }
}

fn produce(cmd: &FitRequest, value: bool) -> Result<Produced, Failure> {
    if cmd.family == super::request_contact::FAMILY {
        if !cmd.bound.is_empty() {
            return Err(InputError::new(
                "bound",
                "the compliant family has no aerodynamic bounds".to_string(),
            )
            .into());
        }
        return super::request_contact::produce(cmd, value);
    }
    let evaluate = match &cmd.evaluate {
        Some(name) => {
            Some(carry_io::aero_file::resolve(name).map_err(|e| InputError::new("evaluate", e))?)
        }
        None => None,
    };
    let family = match &evaluate {
        Some(m) => Some(AeroFamily::of(m)),
        None => AeroFamily::named(&cmd.family),
    };
    let family = family.ok_or_else(|| {
        let names: Vec<&str> = AeroFamily::ALL.iter().map(|(n, _)| *n).collect();
        InputError::new(
            "family",
            format!(
                "unknown family '{}' (families: {})",
                cmd.family,
                names.join(", ")
            ),
        )
    })?;
    let global = cmd.conditions();
    carry_io::scene::air::<f64>(&global)?;
    let (mut rows, mut ignored) = read_input(&cmd.input, cmd.units, &global)?;
    for more in &cmd.also {
        let (r, i) = read_input(more, cmd.units, &global)?;
        rows.extend(r);
        ignored.extend(
            i.into_iter()
                .filter(|c| !ignored.contains(c))
                .collect::<Vec<_>>(),
        );
    }
    let mut problem = AeroProblem::new(family);
    let sessions = {
        let mut s: Vec<usize> = rows.iter().filter_map(|r| r.session).collect();
        s.sort_unstable();
        s.dedup();
        s.len()
    };
    if sessions > 0 {
        problem.integrator = Integrator::dormand_prince(DRIVES_TOLERANCE);
        if family == AeroFamily::Modern {
            problem.bounds[8] = crate::fit::flight::LOW_SATURATION_BOUNDS_DRIVES;
        }
        if let Some(w) = cmd.table_weight {
            if !(w > 0.0 && w.is_finite()) {
                return Err(InputError::new("table_weight", "must be positive").into());
            }
            for r in rows.iter_mut().filter(|r| r.session.is_none()) {
                r.weight *= w;
            }
        }
    }
    apply_bounds(&mut problem, &cmd.bound)?;
    let options = FitOptions {
        leave_one_out: !cmd.no_cross_validation,
    };
    let single = rows.iter().filter(|r| r.session.is_none()).count();
    let solves = 1 + if options.leave_one_out {
        single + sessions
    } else {
        0
    };
    let bar = (!cmd.no_progress && std::io::stderr().is_terminal()).then(|| {
        let bar = indicatif::ProgressBar::new(solves as u64);
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "fitting {bar:40} {pos}/{len} solves, eta {eta}",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        bar
    });
    let tick = || {
        if let Some(b) = &bar {
            b.inc(1);
        }
    };
    let result = match evaluate.as_ref().and_then(|m| family.parameters(m)) {
        Some(p) => fit::evaluate(&problem, &rows, &p),
        None => fit::fit(&problem, &rows, options, &tick),
    }
    .map_err(|e| Failure::Other(format!("the fit failed: {e}")))?;
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    let model = family.model(&result.values());
    if let Some(path) = &cmd.output {
        let summary = result.summary_of("carry").copied().unwrap_or_default();
        let comment = format!(
            "carry aerodynamic model (family {}), fitted by `carry fit` to {} rows of {}\n\
             carry mean |error| {:.2} %, max {:.2} %{}",
            family_name(family),
            rows.len(),
            inputs(cmd),
            summary.mean_abs_pct,
            summary.max_abs_pct,
            result
                .loo_summary_of("carry")
                .map(|l| format!("; leave-one-out mean {:.2} %", l.mean_abs_pct))
                .unwrap_or_default(),
        );
        std::fs::write(path, carry_io::aero_file::to_toml(&model, &comment))
            .map_err(|e| Failure::Other(format!("cannot write {}: {e}", path.display())))?;
    }
    let text = if cmd.json {
        let coefficients = carry_io::aero_file::coefficients(&model)
            .into_iter()
            .map(|(k, v)| (k.to_string(), serde_json::json!(v)))
            .collect();
        let report = Report {
            family: family_name(family),
            rows: rows.len(),
            ignored_columns: &ignored,
            coefficients,
            fit: &result,
        };
        if value {
            return serde_json::to_value(&report)
                .map(Produced::Value)
                .map_err(|e| Failure::Other(e.to_string()));
        }
        let mut s =
            serde_json::to_string_pretty(&report).map_err(|e| Failure::Other(e.to_string()))?;
        s.push('\n');
        s
    } else {
        table(family, &result, &ignored, cmd)
    };
    Ok(Produced::Text(text))
}

/// The input files, joined with `and`.
fn inputs(cmd: &FitRequest) -> String {
    core::iter::once(&cmd.input)
        .chain(&cmd.also)
        .map(|p| p.display().to_string())
        .collect::<Vec<_>>()
        .join(" and ")
}

fn family_name(f: AeroFamily) -> &'static str {
    AeroFamily::ALL
        .iter()
        .find(|(_, g)| *g == f)
        .map_or("?", |(n, _)| n)
}

/// The readable report.
fn table(family: AeroFamily, f: &Fit, ignored: &[String], cmd: &FitRequest) -> String {
    let u = cmd.units;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "FIT  family {}, {} rows, {} ({} flights)",
        family_name(family),
        f.rows.len(),
        status(f, cmd.evaluate.is_some()),
        f.row_evaluations
    );
    {
        let (notes, columns): (Vec<&String>, Vec<&String>) =
            ignored.iter().partition(|c| c.contains(' '));
        if !columns.is_empty() {
            let columns: Vec<&str> = columns.iter().map(|c| c.as_str()).collect();
            let _ = writeln!(s, "  ignored columns: {}", columns.join(", "));
        }
        for n in notes {
            let _ = writeln!(s, "  {n}");
        }
    }
    let _ = writeln!(s, "\nCOEFFICIENTS");
    for p in &f.parameters {
        let _ = writeln!(
            s,
            "  {:<20} {:>12.6}   bounds [{}, {}]{}",
            p.name,
            p.value,
            p.lower,
            p.upper,
            if (p.value - p.lower).abs() < 1e-6 * (p.upper - p.lower)
                || (p.value - p.upper).abs() < 1e-6 * (p.upper - p.lower)
            {
                "  (on a bound)"
            } else {
                ""
            }
        );
    }
    // Columns: carry, apex, landing angle (the quantities every launch monitor reports).
    let (long, height) = (
        u.input_symbol(Quantity::Long),
        u.input_symbol(Quantity::Height),
    );
    let _ = writeln!(
        s,
        "\nROWS{:22}carry [{long}]{:14}apex [{height}]{:8}landing angle [deg]",
        "", "", ""
    );
    let _ = writeln!(
        s,
        "  {:>3}  {:<16} {:>7} {:>7} {:>6} {:>6}   {:>6} {:>6} {:>6}   {:>5} {:>5} {:>5}",
        "#",
        "label",
        "meas",
        "model",
        "err%",
        "loo%",
        "meas",
        "model",
        "err",
        "meas",
        "model",
        "err"
    );
    let disp = |q: Quantity, x: f64| u.to_display(q, x);
    for r in &f.rows {
        let obs = |i: usize| r.observed.get(i).copied().flatten();
        let pred = |i: usize| r.predicted.get(i).copied().unwrap_or(f64::NAN);
        let carry_obs = obs(0).unwrap_or(f64::NAN);
        let loo = r
            .loo_predicted
            .as_ref()
            .and_then(|l| l.first())
            .map_or(String::from("-"), |l| {
                format!("{:+.1}", 100.0 * (l - carry_obs) / carry_obs)
            });
        let cell = |i: usize, q: Quantity, prec: usize| match obs(i) {
            Some(o) => format!(
                "{:>6.p$} {:>6.p$} {:>+6.p$}",
                disp(q, o),
                disp(q, pred(i)),
                disp(q, pred(i)) - disp(q, o),
                p = prec
            ),
            None => format!("{:>6} {:>6.prec$} {:>6}", "-", disp(q, pred(i)), "-"),
        };
        let label: String = r.label.chars().take(16).collect();
        let _ = writeln!(
            s,
            "  {:>3}  {:<16} {:>7.1} {:>7.1} {:>+6.1} {:>6}   {}   {}",
            r.row,
            label,
            disp(Quantity::Long, carry_obs),
            disp(Quantity::Long, pred(0)),
            100.0 * (pred(0) - carry_obs) / carry_obs,
            loo,
            cell(1, Quantity::Height, 1),
            cell(2, Quantity::Plain, 1),
        );
    }
    let _ = writeln!(
        s,
        "\nERRORS{:14}mean |err|      max |err|      leave-one-out mean / max",
        ""
    );
    let units = [
        ("carry", Quantity::Long, long),
        ("apex", Quantity::Height, height),
        ("land_angle", Quantity::Plain, "deg"),
        ("flight_time", Quantity::Plain, "s"),
        ("side", Quantity::Long, long),
    ];
    for (i, (name, q, sym)) in units.iter().enumerate() {
        let Some(m) = f.summary.get(i).filter(|m| m.rows > 0) else {
            continue;
        };
        let pct = if *name == "carry" {
            format!(" ({:.2} %)", m.mean_abs_pct)
        } else {
            String::new()
        };
        let loo = f
            .loo_summary
            .as_ref()
            .and_then(|l| l.get(i))
            .map_or(String::from("-"), |l| {
                if *name == "carry" {
                    format!("{:.2} % / {:.2} %", l.mean_abs_pct, l.max_abs_pct)
                } else {
                    format!(
                        "{:.2} / {:.2} {sym}",
                        disp(*q, l.mean_abs),
                        disp(*q, l.max_abs)
                    )
                }
            });
        let _ = writeln!(
            s,
            "  {:<16} {:>7.2} {sym:<3}{pct:<11} {:>7.2} {sym:<5} {loo}",
            name,
            disp(*q, m.mean_abs),
            disp(*q, m.max_abs),
        );
    }
    if let Some(path) = &cmd.output {
        let _ = writeln!(s, "\nwrote {}", path.display());
    }
    s
}

/// Applies `--bound` options (`INDEX:LO:HI` or `NAME:LO:HI`) to `problem` and moves its
/// start into the bounds (a millionth of the width inside, where the fit's bounded
/// transform is finite).
///
/// # Errors
/// An [`InputError`] on `bound`: not three fields, an unknown parameter, or not
/// `LO < HI` (both finite).
pub fn apply_bounds(problem: &mut AeroProblem, specs: &[String]) -> Result<(), InputError> {
    let names = problem.family.parameter_names();
    for spec in specs {
        let bad = |why: String| InputError::new("bound", format!("'{spec}': {why}"));
        let fields: Vec<&str> = spec.split(':').collect();
        let [which, lo, hi] = fields[..] else {
            return Err(bad("expected INDEX:LO:HI or NAME:LO:HI".into()));
        };
        let index = which
            .parse::<usize>()
            .ok()
            .or_else(|| names.iter().position(|n| *n == which))
            .filter(|&i| i < names.len())
            .ok_or_else(|| {
                bad(format!(
                    "no parameter '{which}' (0–{} or {})",
                    names.len() - 1,
                    names.join(", ")
                ))
            })?;
        let number = |x: &str| {
            x.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| bad(format!("'{x}' is not a finite number")))
        };
        let (lo, hi) = (number(lo)?, number(hi)?);
        if lo >= hi {
            return Err(bad("the lower bound must be below the upper".into()));
        }
        problem.bounds[index] = (lo, hi);
    }
    for (x, &(lo, hi)) in problem.initial.iter_mut().zip(&problem.bounds) {
        let margin = 1e-6 * (hi - lo);
        *x = x.clamp(lo + margin, hi - margin);
    }
    Ok(())
}
