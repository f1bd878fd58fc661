//! Errors as the user reads them: one line naming the option (or batch column) and why.
//!
//! Every core [`carry_core::Error`] maps to an [`InputError`]: `InvalidInput { field, .. }`
//! names the option of that field (`Field::ClubSpeed` → `--club-speed`); the physical
//! failures name the options that cause them (an impact off the face → `--impact-height,
//! --impact-toe`; no landing → `--landing-height`, …). The ranges a message quotes come from
//! the core's constants (stimp, slope, turf coefficients, launch speed and spin).

use carry_core::estimate::Datum;
use carry_core::ground::surface::MAX_TURF_COEFFICIENT;
use carry_core::units::{
    ALTITUDE_RANGE_M, M_PER_FOOT, MAX_SLOPE_RAD, STIMP_RANGE_M, TEMPERATURE_RANGE_C,
};
use carry_core::{Error, Field};
use std::fmt;

/// A length (m) in whole feet, for a message (stimp readings are quoted in feet).
fn feet(m: f64) -> f64 {
    (m / M_PER_FOOT).round()
}

/// An invalid input: which option (snake_case key; several separated by `, `) and why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct InputError {
    /// Option name(s) in snake_case, e.g. `club_speed` or `impact_height, impact_toe`.
    pub key: &'static str,
    /// Why, e.g. `must not be negative`.
    pub reason: String,
}

impl InputError {
    /// An error for `key`.
    pub fn new(key: &'static str, reason: impl Into<String>) -> Self {
        Self {
            key,
            reason: reason.into(),
        }
    }

    /// The options as the command line spells them: `--club-speed`, `--impact-height, --impact-toe`.
    #[must_use]
    pub fn options(&self) -> String {
        self.key
            .split(", ")
            .map(|k| format!("--{}", k.replace('_', "-")))
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// The batch form, naming the column(s): `club_speed: must not be negative`.
    #[must_use]
    pub fn as_column(&self) -> String {
        format!("{}: {}", self.key, self.reason)
    }
}

impl fmt::Display for InputError {
    /// The command-line form: `--club-speed: must not be negative`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.options(), self.reason)
    }
}

impl std::error::Error for InputError {}

/// The option (snake_case) a core field comes from.
#[must_use]
pub fn field_key(field: Field) -> &'static str {
    match field {
        Field::ClubMass => "club_mass",
        Field::ClubInertia => "club_inertia",
        Field::Loft => "loft",
        Field::RollRadius => "roll",
        Field::BulgeRadius => "bulge",
        Field::FaceDepthRadius => "face_depth_radius",
        Field::CgToFace => "cg_to_face",
        Field::Restitution => "cor",
        Field::BallMass => "ball_mass",
        Field::BallRadius => "ball_radius",
        Field::ClubSpeed => "club_speed",
        Field::AttackAngle => "attack_angle",
        Field::ClubPath => "club_path",
        Field::FaceAngle => "face_angle",
        Field::DynamicLoft => "dynamic_loft",
        Field::Lie => "lie",
        Field::ClubSpin => "club_spin",
        Field::ClubVelocity => "club_speed, attack_angle, club_path",
        Field::ClubOrientation => "face_angle, dynamic_loft, lie",
        Field::ImpactHeight => "impact_height",
        Field::ImpactToe => "impact_toe",
        Field::BallVelocity | Field::BallSpeed => "ball_speed",
        Field::BallSpin => "backspin, sidespin, spin",
        Field::SpinAxis => "spin_axis",
        Field::LaunchAngle => "launch_angle",
        Field::LaunchDirection => "launch_direction",
        Field::Backspin => "backspin",
        Field::Sidespin => "sidespin",
        Field::AirDensity => "air_density",
        Field::Temperature => "temperature",
        Field::Humidity => "humidity",
        Field::Pressure => "pressure",
        Field::Altitude => "altitude",
        Field::Wind => "wind",
        Field::WindReferenceHeight => "wind_reference_height",
        Field::WindExponent => "wind_exponent",
        Field::LandingHeight => "landing_height",
        Field::TimeLimit => "time_limit",
        Field::Step => "step",
        Field::Tolerance => "tolerance",
        Field::RecordInterval => "interval",
        Field::GroundRestitution => "ground_restitution",
        Field::GroundFriction => "ground_friction",
        Field::RollingResistance => "rolling_resistance",
        Field::CraterScale => "crater_scale",
        Field::CraterFade => "crater_fade",
        Field::GrassDrag => "grass_drag",
        Field::GrassHeight => "grass_height",
        Field::Stimp => "stimp",
        Field::GroundNormal => "ground_slope",
        Field::ContactLaw => "contact, solver",
        Field::SpinAxisShare => "spin_axis_share",
        Field::Friction
        | Field::TangentialRestitution
        | Field::TangentialRestitutionSlope
        | Field::TangentialRestitutionMax
        | Field::RestitutionSpeedSlope => "contact",
        // LaunchPosition and Gravity are not options of the CLI (fixed tee, standard g),
        // nor is any field added to the core later.
        _ => "precision",
    }
}

/// The option (snake_case) of a datum of the estimator (`carry estimate`): the measured
/// ball and club data by their options, the club's prior by `club`.
#[must_use]
pub fn datum_key(datum: Datum) -> &'static str {
    match datum {
        Datum::BallSpeed => "ball_speed",
        Datum::LaunchAngle => "launch_angle",
        Datum::LaunchDirection => "launch_direction",
        Datum::Spin => "spin",
        Datum::SpinAxis => "spin_axis",
        Datum::ClubSpeed => "club_speed",
        Datum::AttackAngle => "attack_angle",
        Datum::ClubPath => "club_path",
        Datum::FaceAngle => "face_angle",
        Datum::DynamicLoft => "dynamic_loft",
        Datum::Club => "club",
    }
}

/// The estimator's ball data options, which a non-converged estimate names.
pub const BALL_DATA_KEYS: &str = "ball_speed, launch_angle, launch_direction, spin, spin_axis";

/// A number as the messages write it: a true minus sign (−), no trailing `.0`.
struct Minus(f64);

impl fmt::Display for Minus {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.0 < 0.0 {
            write!(f, "−{}", -self.0)
        } else {
            write!(f, "{}", self.0)
        }
    }
}

impl From<Error> for InputError {
    fn from(e: Error) -> Self {
        match e {
            Error::InvalidInput { field, reason } => {
                let reason = match field {
                    Field::Humidity => format!("{reason} (0 to 100 percent)"),
                    Field::Temperature => {
                        let (lo, hi) = TEMPERATURE_RANGE_C;
                        format!("{reason} ({} to {hi} °C)", Minus(lo))
                    }
                    Field::Altitude => {
                        let (lo, hi) = ALTITUDE_RANGE_M;
                        format!("{reason} ({} to {hi} m)", Minus(lo))
                    }
                    Field::Restitution | Field::GroundRestitution => format!("{reason} (0 to 1)"),
                    Field::SpinAxisShare => format!("{reason} (above 0, at most 1)"),
                    Field::Stimp => {
                        let (lo, hi) = STIMP_RANGE_M;
                        format!("{reason} ({} to {} ft)", feet(lo), feet(hi))
                    }
                    Field::GroundNormal => {
                        format!(
                            "{reason} (0 to {} degrees)",
                            MAX_SLOPE_RAD.to_degrees().round()
                        )
                    }
                    Field::BallVelocity | Field::BallSpeed => format!(
                        "{reason} (at most {} m/s at launch: the aerodynamics are incompressible)",
                        carry_core::flight::MAX_BALL_SPEED_MPS
                    ),
                    Field::BallSpin => format!(
                        "{reason} (at most {:.0} rpm at launch)",
                        carry_core::flight::MAX_SPIN_RADPS * 60.0 / core::f64::consts::TAU
                    ),
                    Field::GroundFriction
                    | Field::RollingResistance
                    | Field::CraterScale
                    | Field::GrassDrag => {
                        format!("{reason} (0 to {MAX_TURF_COEFFICIENT})")
                    }
                    Field::GrassHeight => format!(
                        "{reason} (0 to {} m)",
                        carry_core::ground::surface::MAX_GRASS_HEIGHT_M
                    ),
                    Field::ContactLaw => {
                        "the full 15×15 solver supports only --contact rolling".to_owned()
                    }
                    Field::Friction
                    | Field::TangentialRestitution
                    | Field::TangentialRestitutionSlope
                    | Field::TangentialRestitutionMax
                    | Field::RestitutionSpeedSlope => format!("{} {reason}", field.name()),
                    Field::Pressure => {
                        format!(
                            "{reason} (or below the vapour pressure at this temperature and humidity)"
                        )
                    }
                    _ => reason.to_string(),
                };
                Self::new(field_key(field), reason)
            }
            Error::OffFace => Self::new(
                "impact_height, impact_toe",
                "the impact point is off the club face",
            ),
            Error::NoApproach => Self::new(
                "club_speed, club_path, attack_angle",
                "the club is not moving towards the ball: no impact",
            ),
            Error::Singular => Self::new(
                "precision",
                "the impact system is numerically singular for these inputs in this precision",
            ),
            Error::NoLanding => Self::new(
                "landing_height",
                "the ball never comes down through the landing height",
            ),
            Error::TimeLimit => Self::new(
                "time_limit",
                "the time limit was reached before the ball landed, or while it was still bouncing",
            ),
            Error::StepSizeUnderflow => Self::new(
                "tolerance",
                "the integrator cannot meet this tolerance in this precision (loosen it or use --precision f64)",
            ),
            Error::Unstable => Self::new(
                "step",
                "the fixed-step integrator diverged: the step is too large",
            ),
            Error::StepLimit => Self::new(
                "tolerance",
                "the integrator used up its step budget before landing (loosen the tolerance)",
            ),
            Error::NoConvergence => Self::new(
                BALL_DATA_KEYS,
                "the estimate did not converge within its iteration budget: the data may disagree with each other or with --club",
            ),
            Error::IllPosed => Self::new(
                "precision",
                "the estimate is ill-posed in this precision: the data and priors do not determine the delivery (try --precision f64)",
            ),
            Error::Inconsistent { worst } => Self::new(
                datum_key(worst),
                if worst == Datum::Club {
                    "the ball data disagree with this club: the delivery they need is far from its typical one".to_owned()
                } else {
                    format!("the data disagree with each other or with --club; the {worst} most")
                },
            ),
            // A future core error: still one line, never a panic.
            other => Self::new("precision", other.to_string()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use carry_core::Reason;

    /// The ranges quoted from the core's constants read as they always did.
    #[test]
    fn ranges_come_from_the_core() {
        let reason = |f| InputError::from(Error::invalid(f, Reason::OutOfRange)).reason;
        assert!(reason(Field::Stimp).ends_with("(1 to 30 ft)"));
        assert!(reason(Field::GroundNormal).ends_with("(0 to 45 degrees)"));
        assert!(reason(Field::CraterScale).ends_with("(0 to 10)"));
        assert!(reason(Field::Temperature).ends_with("(−100 to 100 °C)"));
        assert!(reason(Field::Altitude).ends_with("(−5000 to 11000 m)"));
    }

    #[test]
    fn names_the_option() {
        let e = InputError::from(Error::invalid(Field::ClubSpeed, Reason::Negative));
        assert_eq!(e.to_string(), "--club-speed: must not be negative");
        let e = InputError::from(Error::OffFace);
        assert_eq!(
            e.to_string(),
            "--impact-height, --impact-toe: the impact point is off the club face"
        );
        assert_eq!(
            e.as_column(),
            "impact_height, impact_toe: the impact point is off the club face"
        );
    }

    /// The estimator's errors name the options that cause them (issue 34), not `--precision`.
    #[test]
    fn estimate_errors_name_their_options() {
        let e = InputError::from(Error::NoConvergence);
        assert!(
            e.to_string().starts_with("--ball-speed, --launch-angle"),
            "{e}"
        );
        let e = InputError::from(Error::Inconsistent {
            worst: Datum::ClubSpeed,
        });
        assert!(e.to_string().starts_with("--club-speed: "), "{e}");
        let e = InputError::from(Error::Inconsistent { worst: Datum::Club });
        assert!(e.to_string().starts_with("--club: "), "{e}");
        let e = InputError::from(Error::invalid(Field::SpinAxis, Reason::OutOfRange));
        assert!(e.to_string().starts_with("--spin-axis: "), "{e}");
        let e = InputError::from(Error::invalid(Field::LaunchAngle, Reason::OutOfRange));
        assert!(e.to_string().starts_with("--launch-angle: "), "{e}");
    }
}

/// Why a command failed, and so its exit status.
#[derive(Debug)]
pub enum Failure {
    /// Invalid input: status 2.
    Input(InputError),
    /// Writing the output or a file failed: status 1 (a closed pipe ends quietly).
    Io(std::io::Error),
    /// Anything else, already a sentence: status 1.
    Other(String),
}

impl From<InputError> for Failure {
    fn from(e: InputError) -> Self {
        Self::Input(e)
    }
}

impl From<std::io::Error> for Failure {
    fn from(e: std::io::Error) -> Self {
        Self::Io(e)
    }
}

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        Self::Input(e.into())
    }
}
