//! Keyword arguments → one request: the options every row shares (a base [`Params`],
//! numerics, units) and the keys of the per-row numeric columns.
//!
//! Names are the CLI's options in snake_case (carry-io's `params::Key` table), plus `units`,
//! `scene`, `precision`, `solver`, `integrator`, `step`, `tolerance` and `posterior`. Options apply in the
//! CLI's order: units, scene file, club, the other options, then each row's numbers.

use carry_io::batch::applies;
use carry_io::choice::Choice;
use carry_io::compute::{
    IntegratorChoice, Mode, Numerics, PosteriorChoice, Precision, SolverChoice,
};
use carry_io::error::InputError;
use carry_io::params::{Key, Kind, Params, Value, parse_finite};
use carry_io::units::Units;
use std::fmt;

/// A bad argument: which one and why (raised as `ValueError`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ArgError {
    /// The argument's name.
    pub arg: String,
    /// Why it is rejected.
    pub reason: String,
}

impl ArgError {
    fn new(arg: &str, reason: impl Into<String>) -> Self {
        Self {
            arg: arg.to_owned(),
            reason: reason.into(),
        }
    }
}

impl fmt::Display for ArgError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.arg, self.reason)
    }
}

impl From<InputError> for ArgError {
    fn from(e: InputError) -> Self {
        Self::new(e.key, e.reason)
    }
}

/// The arguments that are settings of the whole call, not shot inputs.
pub const SETTINGS: &[&str] = &[
    "units",
    "scene",
    "precision",
    "solver",
    "integrator",
    "step",
    "tolerance",
    "posterior",
];

/// Whether setting `name` means something for `mode`.
fn setting_applies(mode: Mode, name: &str) -> bool {
    match name {
        "solver" => mode != Mode::Flight,
        "scene" | "integrator" | "step" | "tolerance" => mode != Mode::Impact,
        "posterior" => false,
        _ => true,
    }
}

/// What a call computes: one of carry-io's runs, or the estimator (club data from ball
/// data: the launch and the club as inputs, the club data a launch monitor measured as
/// optional measurements).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    /// `carry.impact`, `carry.flight` or `carry.shot`.
    Run(Mode),
    /// `carry.estimate`.
    Estimate,
}

/// The club data a launch monitor may measure, in [`carry_lab::request::MeasuredClub`]'s
/// order: inputs of `carry.estimate` besides the launch and the club.
pub const MEASURED: [Key; 5] = [
    Key::ClubSpeed,
    Key::AttackAngle,
    Key::ClubPath,
    Key::FaceAngle,
    Key::DynamicLoft,
];

impl Target {
    /// The target called `name`.
    #[must_use]
    pub fn of(name: &str) -> Option<Self> {
        match name {
            "impact" => Some(Self::Run(Mode::Impact)),
            "flight" => Some(Self::Run(Mode::Flight)),
            "shot" => Some(Self::Run(Mode::Shot)),
            "estimate" => Some(Self::Estimate),
            _ => None,
        }
    }

    /// The Python function's name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Run(mode) => mode_name(mode),
            Self::Estimate => "estimate",
        }
    }

    /// Whether `key` is an input: for the estimator the launch, the club and the ball as
    /// in `carry estimate`, and the measured club data.
    #[must_use]
    pub fn applies(self, key: Key) -> bool {
        use Key::*;
        match self {
            Self::Run(mode) => applies(mode, key),
            Self::Estimate => {
                MEASURED.contains(&key)
                    || matches!(
                        key,
                        BallMass
                            | BallRadius
                            | BallSpeed
                            | LaunchAngle
                            | LaunchDirection
                            | Backspin
                            | Sidespin
                            | Spin
                            | SpinAxis
                            | Club
                            | Contact
                            | ClubMass
                            | ClubInertia
                            | Loft
                            | Bulge
                            | Roll
                            | FaceDepthRadius
                            | CgToFace
                            | CgToFaceX
                            | CgToFaceY
                            | CgToFaceZ
                            | Cor
                    )
            }
        }
    }

    fn setting_applies(self, name: &str) -> bool {
        match self {
            Self::Run(mode) => setting_applies(mode, name),
            Self::Estimate => matches!(name, "units" | "precision" | "posterior"),
        }
    }

    /// The run whose options the call resolves (the estimator reads a flight's launch).
    fn mode(self) -> Mode {
        match self {
            Self::Run(mode) => mode,
            Self::Estimate => Mode::Flight,
        }
    }
}

/// The kind of a key as the Python layer sees it.
#[must_use]
pub fn kind_name(kind: Kind) -> &'static str {
    match kind {
        Kind::Number => "number",
        Kind::Radius => "radius",
        Kind::Vector => "vector",
        Kind::Tensor => "tensor",
        Kind::Preset => "preset",
        Kind::Contact => "contact",
        Kind::Aero => "aero",
        Kind::Bool => "bool",
        Kind::Ground => "ground",
        Kind::Convention => "convention",
    }
}

/// The arguments `target` takes: shot inputs with their kind, then the settings (`setting`).
#[must_use]
pub fn inputs(target: Target) -> Vec<(&'static str, &'static str)> {
    Key::ALL
        .iter()
        .filter(|k| target.applies(**k))
        .map(|k| (k.name(), kind_name(k.kind())))
        .chain(
            SETTINGS
                .iter()
                .filter(|s| target.setting_applies(s))
                .map(|s| (*s, "setting")),
        )
        .collect()
}

/// The command name of `mode`, for messages.
#[must_use]
pub fn mode_name(mode: Mode) -> &'static str {
    match mode {
        Mode::Impact => "impact",
        Mode::Flight => "flight",
        Mode::Shot => "shot",
    }
}

/// One call: shared options and the per-row keys.
#[derive(Debug, Clone)]
pub struct Request {
    /// What to compute.
    pub mode: Mode,
    /// The options every row shares, in SI.
    pub base: Params,
    /// Numerical settings.
    pub numerics: Numerics,
    /// Units of the input values.
    pub units: Units,
    /// The key of each numeric column, in column order.
    pub keys: Vec<Key>,
    /// Whether the output has the ground's columns.
    pub ground: bool,
}

fn value_enum<E: Choice>(arg: &str, text: &str) -> Result<E, ArgError> {
    E::parse(text).map_err(|reason| ArgError::new(arg, reason))
}

fn key_of(target: Target, name: &str) -> Result<Key, ArgError> {
    let key = Key::find(name)
        .filter(|k| k.name() == name)
        .ok_or_else(|| ArgError::new(name, "unknown argument"))?;
    if target.applies(key) {
        Ok(key)
    } else {
        Err(ArgError::new(
            name,
            format!("is not an input of carry.{}", target.name()),
        ))
    }
}

/// Resolves the options (name, text) and the names of the numeric columns.
///
/// # Errors
/// An [`ArgError`] naming the first bad argument.
pub fn request(
    target: Target,
    options: &[(String, String)],
    columns: &[String],
) -> Result<Request, ArgError> {
    let mode = target.mode();
    let mut units = Units::Si;
    let mut numerics = Numerics::default();
    let mut base = Params::default();
    let get = |name: &str| {
        options
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, t)| t.as_str())
    };
    if let Some(t) = get("units") {
        units = value_enum::<Units>("units", t)?;
    }
    for (name, _) in options {
        if SETTINGS.contains(&name.as_str()) && !target.setting_applies(name) {
            return Err(ArgError::new(
                name,
                format!("is not a setting of carry.{}", target.name()),
            ));
        }
    }
    if let Some(path) = get("scene") {
        carry_io::scene::load_file(std::path::Path::new(path), units, &mut base)?;
    }
    if let Some(t) = get("precision") {
        numerics.precision = value_enum::<Precision>("precision", t)?;
    }
    if let Some(t) = get("solver") {
        numerics.solver = value_enum::<SolverChoice>("solver", t)?;
    }
    if let Some(t) = get("integrator") {
        numerics.integrator = value_enum::<IntegratorChoice>("integrator", t)?;
    }
    if let Some(t) = get("step") {
        numerics.step_s = Some(parse_finite(t).map_err(|r| ArgError::new("step", r))?);
    }
    if let Some(t) = get("tolerance") {
        numerics.tolerance = Some(parse_finite(t).map_err(|r| ArgError::new("tolerance", r))?);
    }
    if let Some(t) = get("posterior") {
        numerics.posterior = value_enum::<PosteriorChoice>("posterior", t)?;
    }
    numerics.check()?;
    // The club first: component overrides (cg_to_face_x, …) start from its preset.
    let mut keyed: Vec<(Key, &str)> = Vec::new();
    for (name, text) in options {
        if SETTINGS.contains(&name.as_str()) {
            continue;
        }
        keyed.push((key_of(target, name)?, text));
    }
    keyed.sort_by_key(|(k, _)| *k != Key::Club);
    for (key, text) in &keyed {
        let value = key.parse(text)?;
        key.set(&mut base, units, value);
    }
    let mut keys = Vec::with_capacity(columns.len());
    for name in columns {
        let key = key_of(target, name)?;
        if !matches!(key.kind(), Kind::Number | Kind::Radius) {
            return Err(ArgError::new(
                name,
                format!("takes a {} value, not numbers", kind_name(key.kind())),
            ));
        }
        keys.push(key);
    }
    let ground = target != Target::Estimate
        && mode != Mode::Impact
        && (!base.scene.ground.is_empty()
            || keyed.iter().any(|(k, _)| k.is_ground())
            || keys.iter().any(|k| k.is_ground()));
    Ok(Request {
        mode,
        base,
        numerics,
        units,
        keys,
        ground,
    })
}

/// Checks one row's value for `key` as the CLI's text parser would.
///
/// # Errors
/// The message for the row, naming the key.
pub fn check_value(key: Key, x: f64) -> Result<Value, InputError> {
    key.check_number(x).map(Value::Number)
}
