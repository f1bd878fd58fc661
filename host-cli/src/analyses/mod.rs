//! The lab's commands (`optimize`, `sweep`, `dispersion`, `normalize`): options → a
//! [`carry_lab::Setup`] → the lab's analysis → table, JSON or CSV. All logic lives in
//! carry-lab; this is parsing and formatting.

pub mod dispersion;
pub mod normalize;
pub mod optimize;
mod output;
pub mod sweep;

use crate::cli::{ClubArgs, DeliveryArgs, IntegratorArgs, PrecisionArgs, SceneArgs, SolverArgs};
use crate::compute::{self, Numerics, Precision};
use crate::error::{Failure, InputError};
use crate::params::Params;
use crate::units::Units;
use carry_core::Real;
use carry_core::shot::Fidelity;
use carry_lab::{Error, Input, Setup};

/// Everything of a shot the lab commands share: delivery, club, scene, numerics.
#[derive(Debug, Clone, clap::Args)]
pub struct ShotArgs {
    #[command(flatten)]
    pub delivery: DeliveryArgs,
    #[command(flatten)]
    pub club: ClubArgs,
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub precision: PrecisionArgs,
    #[command(flatten)]
    pub solver: SolverArgs,
    #[command(flatten)]
    pub integrator: IntegratorArgs,
}

impl ShotArgs {
    /// The parameters and numerics, in `units`.
    ///
    /// # Errors
    /// A bad scene file or option combination.
    pub fn resolve(&self, units: Units) -> Result<(Params, Numerics), InputError> {
        let mut p = Params::default();
        self.club.apply(&mut p, units);
        self.delivery.apply(&mut p, units);
        self.scene.apply(&mut p, units)?;
        let n = Numerics {
            precision: self.precision.precision,
            solver: self.solver.solver,
            integrator: self.integrator.integrator,
            step_s: self.integrator.step,
            tolerance: self.integrator.tolerance,
        };
        n.check()?;
        Ok((p, n))
    }
}

/// The lab setup of `p` in precision `T`.
///
/// # Errors
/// The core's validation, naming the option.
pub fn setup<T: Real>(p: &Params, n: &Numerics) -> Result<Setup<T>, InputError> {
    let club = compute::club::<T>(&p.club)?;
    let ball = compute::ball::<T>(p)?;
    let scene = crate::scene::build::<T>(&p.scene)?.prepare(&ball)?;
    Ok(Setup {
        club,
        ball,
        delivery: compute::delivery(p, &club),
        convention: p.delivery.convention,
        scene,
        fidelity: Fidelity {
            solver: n.solver(),
            integrator: n.integrator(),
        },
    })
}

/// Calls `f` with the setup in the precision `n` asks for.
///
/// # Errors
/// Those of [`setup`] and `f`.
pub fn with_setup<R>(
    p: &Params,
    n: &Numerics,
    f32: impl FnOnce(Setup<f32>) -> Result<R, Failure>,
    f64: impl FnOnce(Setup<f64>) -> Result<R, Failure>,
) -> Result<R, Failure> {
    match n.precision {
        Precision::F32 => f32(setup::<f32>(p, n)?),
        Precision::F64 => f64(setup::<f64>(p, n)?),
    }
}

/// The option a noise SD comes from.
const NOISE_KEYS: [&str; 7] = [
    "face_angle_sd",
    "club_path_sd",
    "attack_angle_sd",
    "dynamic_loft_sd",
    "club_speed_sd",
    "impact_height_sd",
    "impact_toe_sd",
];

/// A lab error as the user reads it; `count` names the option of [`Input::Count`].
pub fn failure(e: Error, count: &'static str) -> Failure {
    let key = |input: Input| match input {
        Input::DynamicLoftRange => "dynamic_loft_range",
        Input::AttackAngleRange => "attack_angle_range",
        Input::ImpactHeightRange => "impact_height_range",
        Input::Objective => "objective",
        Input::Count => count,
        Input::NoiseSd(i) => NOISE_KEYS.get(i).copied().unwrap_or("noise"),
        Input::Swing => "swing",
        Input::BallPositions => "ball_positions",
        Input::ChartSpeeds => "club_speeds",
        Input::ChartAttackAngles => "attack_angles",
    };
    match e {
        Error::Core(e) => Failure::from(e),
        Error::Invalid(input, why) => Failure::Input(InputError::new(key(input), why)),
        Error::Library(why) => Failure::Other(why),
    }
}

/// Parses `a,b` (two finite numbers).
///
/// # Errors
/// The reason, for a message.
pub fn parse_pair(text: &str) -> Result<[f64; 2], String> {
    let v: Vec<f64> = text
        .split(',')
        .map(crate::params::parse_finite)
        .collect::<Result<_, _>>()?;
    match v.as_slice() {
        &[a, b] => Ok([a, b]),
        _ => Err(format!("'{}' must be two numbers: low,high", text.trim())),
    }
}

/// Parses `from,to,step` (three finite numbers).
///
/// # Errors
/// The reason, for a message.
pub fn parse_triple(text: &str) -> Result<[f64; 3], String> {
    let v: Vec<f64> = text
        .split(',')
        .map(crate::params::parse_finite)
        .collect::<Result<_, _>>()?;
    match v.as_slice() {
        &[a, b, c] => Ok([a, b, c]),
        _ => Err(format!(
            "'{}' must be three numbers: from,to,step",
            text.trim()
        )),
    }
}

/// A chart writer of the lab.
type Draw<T> = fn(&std::path::Path, &T) -> Result<(), Box<dyn std::error::Error>>;

/// Writes an SVG with `draw`, mapping a failure to status 1.
///
/// # Errors
/// Failing to draw or write.
pub fn write_svg<T>(path: &std::path::Path, data: &T, draw: Draw<T>) -> Result<(), Failure> {
    draw(path, data).map_err(|e| Failure::Other(format!("cannot write {}: {e}", path.display())))
}
