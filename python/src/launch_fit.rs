//! `carry.launch_from_flight`: the launch from what a monitor saw of the flight (issue 36)
//! — keyword arguments and numpy track arrays → lab's typed request
//! ([`carry_lab::launch_fit::fit`], the one `carry estimate --from flight` and `carry batch
//! estimate --from flight` run) → the record `carry estimate --from flight --json` prints.
//!
//! The launch figures and summaries (and their `_sd`), `track_sd`, `radar_position`,
//! `fit_wind` and `fit_air_density` are read here; the scene, ball, precision and units
//! go through the shot's option table ([`crate::args`]). Errors read as the CLI's:
//! `--option: reason`.

use crate::analyses::AnalysisError;
use crate::args::{self, ArgError};
use carry_io::compute::Mode;
use carry_io::params::{parse_bool, parse_finite, parse_triple};
use carry_io::units::Quantity;
use carry_lab::launch_fit::{
    self as lf, DOPPLER_SD_MPS, FlightRequest, LAUNCH_SD, SUMMARY_SD, TRACK_SD_M, Track,
};
use serde_json::Value;

/// The figures a call may give: (name, quantity under `units`).
const FIELDS: [(&str, Quantity); 11] = [
    ("ball_speed", Quantity::Speed),
    ("launch_angle", Quantity::Plain),
    ("launch_direction", Quantity::Plain),
    ("spin", Quantity::Plain),
    ("spin_axis", Quantity::Plain),
    ("apex_height", Quantity::Height),
    ("apex_time", Quantity::Plain),
    ("carry", Quantity::Long),
    ("side", Quantity::Long),
    ("flight_time", Quantity::Plain),
    ("land_angle", Quantity::Plain),
];

/// The other arguments of the fit's own.
const OWN: [&str; 4] = ["track_sd", "radar_position", "fit_wind", "fit_air_density"];

fn input(name: &str, reason: impl std::fmt::Display) -> AnalysisError {
    AnalysisError::Input(format!("--{}: {reason}", name.replace('_', "-")))
}

/// The track arrays: times and positions (x, y, z) or times and radial speeds.
pub struct Arrays<'a> {
    /// Times (s).
    pub t: Option<&'a [f64]>,
    /// Positions (m, G).
    pub xyz: Option<[&'a [f64]; 3]>,
    /// Radial speeds (m/s).
    pub radial_speed: Option<&'a [f64]>,
}

/// Fits the launch; returns the JSON record.
///
/// # Errors
/// [`AnalysisError::Input`] naming the argument (a bad value or 1σ, too few or
/// uninformative observations, no convergence), or `Failed`.
pub fn run(options: &[(String, String)], arrays: &Arrays<'_>) -> Result<Value, AnalysisError> {
    let is_sd = |n: &str| {
        n.strip_suffix("_sd")
            .is_some_and(|b| FIELDS.iter().any(|f| f.0 == b))
    };
    let is_own = |n: &str| FIELDS.iter().any(|f| f.0 == n) || is_sd(n) || OWN.contains(&n);
    let text = |name: &str| {
        options
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, t)| t.as_str())
    };
    if text("backspin").is_some() || text("sidespin").is_some() {
        return Err(AnalysisError::Input(
            "--backspin, --sidespin: give the measured spin as spin and spin_axis".to_owned(),
        ));
    }
    let shot: Vec<(String, String)> = options
        .iter()
        .filter(|(n, _)| !is_own(n))
        .cloned()
        .collect();
    let req =
        args::request(args::Target::Run(Mode::Flight), &shot, &[]).map_err(|e: ArgError| {
            input(
                &e.arg,
                e.reason.replace("carry.flight", "carry.launch_from_flight"),
            )
        })?;
    let u = req.units;
    let number = |name: &str| -> Result<Option<f64>, AnalysisError> {
        text(name)
            .map(|t| parse_finite(t).map_err(|r| input(name, r)))
            .transpose()
    };
    let defaults: Vec<f64> = LAUNCH_SD.iter().chain(&SUMMARY_SD).copied().collect();
    let mut given = [None; 11];
    for (k, ((name, q), slot)) in FIELDS.iter().zip(given.iter_mut()).enumerate() {
        let Some(v) = number(name)? else {
            if text(&format!("{name}_sd")).is_some() {
                return Err(input(&format!("{name}_sd"), format!("needs {name}")));
            }
            continue;
        };
        let sd = match number(&format!("{name}_sd"))? {
            Some(s) => u.to_si(*q, s),
            None => defaults.get(k).copied().unwrap_or(1.0),
        };
        *slot = Some((u.to_si(*q, v), sd));
    }
    let track_sd = number("track_sd")?;
    let radar_position = text("radar_position")
        .map(|t| parse_triple(t).map_err(|r| input("radar_position", r)))
        .transpose()?;
    let flag = |name: &str| -> Result<bool, AnalysisError> {
        Ok(text(name)
            .map(|t| parse_bool(t).map_err(|r| input(name, r)))
            .transpose()?
            .unwrap_or(false))
    };
    let track = track(arrays)?;
    let [
        ball_speed_mps,
        launch_angle_deg,
        launch_direction_deg,
        spin_rpm,
        spin_axis_deg,
        apex_height_m,
        apex_time_s,
        carry_m,
        side_m,
        flight_time_s,
        land_angle_deg,
    ] = given;
    let r = FlightRequest {
        ball_speed_mps,
        launch_angle_deg,
        launch_direction_deg,
        spin_rpm,
        spin_axis_deg,
        apex_height_m,
        apex_time_s,
        carry_m,
        side_m,
        flight_time_s,
        land_angle_deg,
        track,
        track_sd_m: track_sd.unwrap_or(TRACK_SD_M),
        doppler_sd_mps: track_sd.unwrap_or(DOPPLER_SD_MPS),
        radar_position_m: radar_position.unwrap_or([-2.5, 0.3, 0.0]),
        fit_wind: flag("fit_wind")?,
        fit_air_density: flag("fit_air_density")?,
    };
    let record = lf::fit(&req.base, &req.numerics, &r)?;
    serde_json::to_value(&record).map_err(|e| AnalysisError::Failed(e.to_string()))
}

/// The track of the arrays: lengths checked (times in order and finite: the core checks).
fn track(a: &Arrays<'_>) -> Result<Track, AnalysisError> {
    let mut track = Track::default();
    let Some(t) = a.t else {
        if a.xyz.is_some() || a.radial_speed.is_some() {
            return Err(input("t", "the track needs its times t"));
        }
        return Ok(track);
    };
    let same = |name: &str, v: &[f64]| {
        if v.len() == t.len() {
            Ok(())
        } else {
            Err(input(
                name,
                format!("{} values for {} times", v.len(), t.len()),
            ))
        }
    };
    match (a.xyz, a.radial_speed) {
        (Some([x, y, z]), None) => {
            for (name, v) in [("x", x), ("y", y), ("z", z)] {
                same(name, v)?;
            }
            if t.len() > lf_max(false) {
                return Err(input(
                    "t",
                    format!("more than {} track points", lf_max(false)),
                ));
            }
            track.positions = t
                .iter()
                .zip(x.iter().zip(y.iter().zip(z)))
                .map(|(t, (x, (y, z)))| (*t, [*x, *y, *z]))
                .collect();
        }
        (None, Some(v)) => {
            same("radial_speed", v)?;
            if t.len() > lf_max(true) {
                return Err(input(
                    "t",
                    format!("more than {} radial speeds", lf_max(true)),
                ));
            }
            track.radial_speeds = t.iter().copied().zip(v.iter().copied()).collect();
        }
        (Some(_), Some(_)) => {
            return Err(input(
                "radial_speed",
                "give positions (x, y, z) or radial speeds, not both",
            ));
        }
        (None, None) => return Err(input("t", "needs x, y, z or radial_speed")),
    }
    Ok(track)
}

fn lf_max(doppler: bool) -> usize {
    if doppler {
        carry_core::launch_fit::MAX_DOPPLER_SAMPLES
    } else {
        carry_core::launch_fit::MAX_TRACK_POINTS
    }
}
