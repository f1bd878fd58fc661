//! `carry.optimize`, `sweep`, `dispersion` and `normalize`: keyword arguments → lab's typed
//! requests ([`carry_lab::request`]) → the result as a JSON value (the document
//! `carry <command> --json` prints) and the notes of options the analysis replaced.
//!
//! The shot's options go through the same option table as `carry.shot` ([`crate::args`]);
//! the analysis's own options are parsed here by name. Errors read as the CLI's:
//! `--option: reason`.

use crate::args::{self, ArgError};
use carry_io::compute::Mode;
use carry_io::error::{Failure, InputError};
use carry_io::params::{parse_bool, parse_pair, parse_triple};
use carry_lab::request::{
    self, ChartGrid, DispersionRequest, NoiseSd, ObjectiveChoice, OptimizeOutcome, OptimizeRequest,
    SweepRequest, To, parse_sd,
};
use carry_lab::{dispersion, optimize, sweep};
use serde::Serialize;
use serde_json::Value;
use std::path::{Path, PathBuf};

/// Why an analysis failed: bad input (`ValueError`) or anything else (`RuntimeError`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum AnalysisError {
    /// `--option: reason`.
    Input(String),
    /// A file that cannot be written, a failed search: a sentence.
    Failed(String),
}

fn option(name: &str) -> String {
    format!("--{}", name.replace('_', "-"))
}

fn input(name: &str, reason: impl std::fmt::Display) -> AnalysisError {
    AnalysisError::Input(format!("{}: {reason}", option(name)))
}

impl From<Failure> for AnalysisError {
    fn from(e: Failure) -> Self {
        match e {
            Failure::Input(e) => Self::Input(e.to_string()),
            Failure::Io(e) => Self::Failed(e.to_string()),
            Failure::Other(m) => Self::Failed(m),
        }
    }
}

impl From<InputError> for AnalysisError {
    fn from(e: InputError) -> Self {
        Self::Input(e.to_string())
    }
}

/// The options of an analysis that are not the shot's.
const OPTIMIZE: &[&str] = &[
    "dynamic_loft_range",
    "attack_angle_range",
    "impact_height_range",
    "objective",
    "starts",
    "chart",
    "club_speeds",
    "attack_angles",
    "svg",
    "shots",
    "seed",
];
const SWEEP: &[&str] = &["swing", "ball_positions", "svg", "generate"];
const DISPERSION: &[&str] = &["shots", "seed", "svg", "threads", "no_progress"];
const NORMALIZE: &[&str] = &["to"];

/// The analysis's own options, parsed by name.
struct Own<'a>(Vec<(&'a str, &'a str)>);

impl Own<'_> {
    fn text(&self, name: &str) -> Option<&str> {
        self.0.iter().find(|(n, _)| *n == name).map(|(_, t)| *t)
    }
    fn with<T>(
        &self,
        name: &str,
        parse: impl Fn(&str) -> Result<T, String>,
    ) -> Result<Option<T>, AnalysisError> {
        self.text(name)
            .map(|t| parse(t).map_err(|r| input(name, r)))
            .transpose()
    }
    fn count<T: std::str::FromStr>(&self, name: &str) -> Result<Option<T>, AnalysisError> {
        self.with(name, |t| {
            t.trim()
                .parse()
                .map_err(|_| format!("invalid value '{t}': a whole number is required"))
        })
    }
    fn path(&self, name: &str) -> Option<PathBuf> {
        self.text(name).map(PathBuf::from)
    }
    fn noise(&self) -> Result<NoiseSd, AnalysisError> {
        let mut sd = NoiseSd::default();
        for key in NoiseSd::KEYS {
            if let (Some(x), Some(slot)) = (self.with(key, parse_sd)?, sd.get_mut(key)) {
                *slot = x;
            }
        }
        Ok(sd)
    }
}

fn value<T: Serialize>(v: &T) -> Result<Value, AnalysisError> {
    serde_json::to_value(v).map_err(|e| AnalysisError::Failed(e.to_string()))
}

type Draw<T> = fn(&Path, &T) -> Result<(), Box<dyn std::error::Error>>;

fn svg<T>(path: Option<PathBuf>, data: &T, draw: Draw<T>) -> Result<(), AnalysisError> {
    match path {
        Some(p) => draw(&p, data)
            .map_err(|e| AnalysisError::Failed(format!("cannot write {}: {e}", p.display()))),
        None => Ok(()),
    }
}

/// Runs `command` with `options` ((name, text) pairs; flags as `true`); returns the JSON
/// document and the notes.
///
/// # Errors
/// An [`AnalysisError`].
pub fn run(
    command: &str,
    options: &[(String, String)],
) -> Result<(Value, Vec<String>), AnalysisError> {
    let (mode, own_names): (Mode, &[&str]) = match command {
        "optimize" => (Mode::Shot, OPTIMIZE),
        "sweep" => (Mode::Shot, SWEEP),
        "dispersion" => (Mode::Shot, DISPERSION),
        "normalize" => (Mode::Flight, NORMALIZE),
        _ => {
            return Err(AnalysisError::Input(format!(
                "not an analysis: '{command}' (optimize, sweep, dispersion or normalize)"
            )));
        }
    };
    let noise = command == "optimize" || command == "dispersion";
    let is_own = |n: &str| own_names.contains(&n) || (noise && NoiseSd::KEYS.contains(&n));
    let own = Own(options
        .iter()
        .filter(|(n, _)| is_own(n))
        .map(|(n, t)| (n.as_str(), t.as_str()))
        .collect());
    let shot: Vec<(String, String)> = options
        .iter()
        .filter(|(n, _)| !is_own(n))
        .cloned()
        .collect();
    let req = args::request(args::Target::Run(mode), &shot, &[]).map_err(|e: ArgError| {
        let reason = e
            .reason
            .replace("carry.flight", &format!("carry.{command}"))
            .replace("carry.shot", &format!("carry.{command}"));
        input(&e.arg, reason)
    })?;
    let (p, n, units) = (req.base, req.numerics, req.units);
    let mut notes = Vec::new();
    let doc = match command {
        "optimize" => {
            let chart = own.with("chart", parse_bool)?.unwrap_or(false);
            let club_speeds = own.with("club_speeds", parse_triple)?;
            let attack_angles = own.with("attack_angles", parse_triple)?;
            for (name, given) in [
                ("club_speeds", club_speeds.is_some()),
                ("attack_angles", attack_angles.is_some()),
            ] {
                if given && !chart {
                    return Err(input(name, "applies only with chart=True"));
                }
            }
            let objective = match own.text("objective").map(str::trim) {
                None | Some("carry") => ObjectiveChoice::Carry,
                Some("total") => ObjectiveChoice::Total,
                Some("dispersion") => ObjectiveChoice::Dispersion,
                Some(t) => {
                    return Err(input(
                        "objective",
                        format!("invalid value '{t}' (one of: carry, total, dispersion)"),
                    ));
                }
            };
            let r = OptimizeRequest {
                units,
                dynamic_loft_range: own.with("dynamic_loft_range", parse_pair)?,
                attack_angle_range: own.with("attack_angle_range", parse_pair)?,
                impact_height_range: own.with("impact_height_range", parse_pair)?,
                objective,
                starts: own.count("starts")?.unwrap_or(1),
                chart: chart.then_some(ChartGrid {
                    club_speeds,
                    attack_angles,
                }),
                noise: own.noise()?,
                shots: own.count("shots")?,
                seed: own.count("seed")?.unwrap_or(1),
            };
            match r.run(&p, &n, &mut notes)? {
                OptimizeOutcome::Optimum(best) => value(&best)?,
                OptimizeOutcome::Chart(c) => {
                    svg(own.path("svg"), &c, optimize::draw_chart)?;
                    value(&c)?
                }
            }
        }
        "sweep" => {
            if let Some(path) = own.path("generate") {
                SweepRequest::generate(&p, &n, &path)?;
                serde_json::json!({ "wrote": path.display().to_string() })
            } else {
                let r = SweepRequest {
                    units,
                    swing: own.path("swing"),
                    ball_positions: own.with("ball_positions", parse_triple)?,
                };
                let s = r.run(&p, &n, &mut notes)?;
                svg(own.path("svg"), &s, sweep::draw)?;
                value(&s)?
            }
        }
        "dispersion" => {
            own.with("no_progress", parse_bool)?;
            let r = DispersionRequest {
                units,
                noise: own.noise()?,
                shots: own.count("shots")?,
                seed: own.count("seed")?.unwrap_or(1),
                threads: own.count("threads")?,
            };
            let d = r.run(&p, &n, None)?;
            svg(own.path("svg"), &d, dispersion::draw)?;
            value(&d)?
        }
        _ => {
            let to = match own.text("to").map(str::trim) {
                None | Some("standard") => To::Standard,
                Some("conditions") => To::Conditions,
                Some(t) => {
                    return Err(input(
                        "to",
                        format!("invalid value '{t}' (one of: standard, conditions)"),
                    ));
                }
            };
            value(&request::normalize(&p, &n, to)?)?
        }
    };
    Ok((doc, notes))
}
