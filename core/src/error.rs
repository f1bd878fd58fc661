//! The one error type of the core: small, `Copy`, no allocation.
//!
//! Every public entry point validates its inputs once and returns [`Error`]; the inner
//! numerical code runs only on validated data. Nothing in the core panics or returns NaN.

use core::fmt;

/// Which input was rejected.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum Field {
    // --- club head ---
    /// Club head mass (kg).
    ClubMass,
    /// Club head inertia tensor about its centre of mass (kg·m²).
    ClubInertia,
    /// Static loft α (rad).
    Loft,
    /// Roll radius b, curvature up the face (m).
    RollRadius,
    /// Bulge radius c, curvature across the face (m).
    BulgeRadius,
    /// Ellipsoid x radius a, the face's depth radius (m).
    FaceDepthRadius,
    /// Club centre of mass → face centre, in the face frame (m).
    CgToFace,
    /// Coefficient of restitution e.
    Restitution,
    // --- contact law (impact::contact_law) ---
    /// The face–ball contact law as a whole (e.g. a solver that does not support it).
    ContactLaw,
    /// Coulomb friction coefficient μ of the face–ball contact.
    Friction,
    /// Tangential restitution e_t at normal incidence.
    TangentialRestitution,
    /// Change of the tangential restitution per unit tan(impact obliquity).
    TangentialRestitutionSlope,
    /// Ceiling of the compliant contact's tangential restitution.
    TangentialRestitutionMax,
    /// The club's empirical D-plane share of the spin axis.
    SpinAxisShare,
    /// Fall of the normal restitution per m/s of normal impact speed (s/m).
    RestitutionSpeedSlope,
    // --- ball ---
    /// Ball mass (kg).
    BallMass,
    /// Ball radius (m).
    BallRadius,
    // --- club delivery ---
    /// Club head speed (m/s).
    ClubSpeed,
    /// Attack angle (rad).
    AttackAngle,
    /// Club path (rad).
    ClubPath,
    /// Face angle (rad).
    FaceAngle,
    /// Dynamic loft (rad).
    DynamicLoft,
    /// Lie / face tilt (rad).
    Lie,
    /// Club angular velocity before impact (rad/s).
    ClubSpin,
    /// Club velocity given directly (m/s).
    ClubVelocity,
    /// Club orientation given directly (rotation C → G).
    ClubOrientation,
    /// Impact location up the face (m).
    ImpactHeight,
    /// Impact location toward the toe (m).
    ImpactToe,
    /// Ball velocity before impact or at launch (m/s).
    BallVelocity,
    /// Ball spin before impact or at launch (rad/s).
    BallSpin,
    // --- launch (flight input) ---
    /// Ball speed at launch (m/s).
    BallSpeed,
    /// Launch angle (rad).
    LaunchAngle,
    /// Launch direction (rad).
    LaunchDirection,
    /// Backspin (rad/s).
    Backspin,
    /// Sidespin (rad/s).
    Sidespin,
    /// Launch position (m).
    LaunchPosition,
    // --- scene ---
    /// Air density (kg/m³).
    AirDensity,
    /// Air temperature (°C).
    Temperature,
    /// Relative humidity (0..1).
    Humidity,
    /// Air pressure (Pa).
    Pressure,
    /// Altitude above sea level (m).
    Altitude,
    /// Wind velocity (m/s).
    Wind,
    /// Wind reference height (m).
    WindReferenceHeight,
    /// Wind profile exponent.
    WindExponent,
    /// Landing height (m).
    LandingHeight,
    /// Flight time limit (s).
    TimeLimit,
    /// Gravitational acceleration (m/s²).
    Gravity,
    /// A drag coefficient of the aerodynamic model.
    DragCoefficient,
    /// A lift coefficient of the aerodynamic model.
    LiftCoefficient,
    /// The spin-decay (moment) coefficient of the aerodynamic model.
    SpinDecayCoefficient,
    /// A Reynolds-number parameter of the aerodynamic model (drag crisis).
    ReynoldsNumber,
    /// Trajectory recording interval (s).
    RecordInterval,
    // --- ground ---
    /// Turf restitution at vanishing normal speed (0..1).
    GroundRestitution,
    /// Ball–turf friction coefficient.
    GroundFriction,
    /// Rolling resistance of the surface.
    RollingResistance,
    /// Crater scale of the surface.
    CraterScale,
    /// Normal speed below which the surface's crater fades (m/s).
    CraterFade,
    /// Growth of the surface's rolling resistance with speed, the grass drag (s²/m²).
    GrassDrag,
    /// Height of the surface's grass, the canopy a rebound must clear to hop (m).
    GrassHeight,
    /// Green speed, stimpmeter reading (m).
    Stimp,
    /// Ground plane normal (slope).
    GroundNormal,
    // --- numerics ---
    /// Integrator step size (s).
    Step,
    /// Integrator tolerance.
    Tolerance,
    // --- estimate (club data from ball data) ---
    /// A measurement's 1σ noise of the estimator.
    MeasurementNoise,
    /// A prior mean of the estimator.
    PriorMean,
    /// A prior spread (1σ) of the estimator.
    PriorSpread,
    /// The estimator's iteration budget.
    Iterations,
    /// A bound of the estimator's consistency check (tail probability or σ count).
    ConsistencyBound,
    /// A posterior σ calibration factor of the estimator ([`crate::estimate::Settings::sd_scale`]).
    PosteriorScale,
    // --- launch from the flight (launch_fit) ---
    /// A flight observation (a track point, a Doppler sample, a summary) or a measured
    /// launch value.
    Observation,
    /// Spin axis (rad).
    SpinAxis,
}

/// Why an input was rejected.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum Reason {
    /// NaN or ±infinity where a finite number is needed.
    NotFinite,
    /// Zero or negative where a positive number is needed.
    NotPositive,
    /// Negative where zero or more is needed.
    Negative,
    /// Outside its documented range.
    OutOfRange,
    /// A matrix that must be symmetric is not.
    NotSymmetric,
    /// A matrix that must be symmetric positive definite is not.
    NotPositiveDefinite,
    /// A rotation matrix that is not orthonormal with determinant +1.
    NotRotation,
    /// A valid choice the requested solver does not implement (the full 15×15 impact
    /// solver supports only the seed's rolling contact).
    UnsupportedBySolver,
}

/// Everything that can go wrong in the core.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum Error {
    /// An input value is invalid: which one, and why.
    InvalidInput {
        /// The rejected input.
        field: Field,
        /// Why it was rejected.
        reason: Reason,
    },
    /// The impact point is off the face ellipsoid (s² ≤ 0, or so close to 0 that the
    /// normal is unreliable in the chosen precision).
    OffFace,
    /// The club is not approaching the ball along the contact normal (n·u⁰ ≥ 0): no impact.
    NoApproach,
    /// The impact system is numerically singular (a pivot fell below its scale-aware
    /// threshold): the inputs are too ill-conditioned for the chosen precision.
    Singular,
    /// The ball never comes down through the landing height (e.g. a target above the apex).
    NoLanding,
    /// The flight time limit was reached before landing (or, with a ground, while the
    /// ball was still bouncing: e.g. down a slope near the steepest accepted).
    TimeLimit,
    /// The adaptive integrator could not meet its tolerance without the step size
    /// underflowing (the tolerance is too tight for the chosen precision).
    StepSizeUnderflow,
    /// A fixed-step integrator produced a non-finite state: the step is too large for
    /// this flight (explicit methods are only conditionally stable).
    Unstable,
    /// The adaptive integrator used up its step budget
    /// ([`crate::flight::MAX_ADAPTIVE_STEPS`]) before landing: the flight is too stiff or
    /// too long for the tolerance. Bounds the run time of every flight (firmware never hangs).
    StepLimit,
    /// The estimator ([`crate::estimate`]) used up its iteration budget before its steps
    /// became small.
    NoConvergence,
    /// The estimator's normal matrix is numerically singular: the measurements and priors
    /// do not pin the unknowns down in this precision.
    IllPosed,
    /// The estimator's data disagree with each other or with the club
    /// ([`crate::estimate::Consistency`]): the χ² of the most probable delivery is beyond
    /// its bound, or a measured datum is missed by more than the stated number of σ.
    Inconsistent {
        /// The datum the most probable delivery misses by the most σ.
        worst: Datum,
    },
    /// The launch fit ([`crate::launch_fit`]) has fewer flight observations than free
    /// unknowns.
    TooFewObservations,
    /// The launch fit's observations do not pin this unknown down (its posterior spread
    /// stays near its prior's).
    Unidentifiable(Field),
}

/// One term of the club-data estimator's cost ([`crate::estimate`]): a measured number, or
/// the club's prior. Here, a leaf, so that [`Error::Inconsistent`] can name it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Datum {
    /// The measured ball speed.
    BallSpeed,
    /// The measured launch angle.
    LaunchAngle,
    /// The measured launch direction.
    LaunchDirection,
    /// The measured spin rate.
    Spin,
    /// The measured spin axis.
    SpinAxis,
    /// The measured club speed.
    ClubSpeed,
    /// The measured attack angle.
    AttackAngle,
    /// The measured club path.
    ClubPath,
    /// The measured face angle.
    FaceAngle,
    /// The measured dynamic loft.
    DynamicLoft,
    /// The club: the delivery the data need is far from the club's prior (its typical
    /// delivery), e.g. ball data no swing of this club gives.
    Club,
}

impl Datum {
    /// The ball data in the order of [`crate::estimate::BallData::to_array`].
    pub const BALL: [Self; 5] = [
        Self::BallSpeed,
        Self::LaunchAngle,
        Self::LaunchDirection,
        Self::Spin,
        Self::SpinAxis,
    ];

    /// A short human name.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::BallSpeed => "ball speed",
            Self::LaunchAngle => "launch angle",
            Self::LaunchDirection => "launch direction",
            Self::Spin => "spin",
            Self::SpinAxis => "spin axis",
            Self::ClubSpeed => "club speed",
            Self::AttackAngle => "attack angle",
            Self::ClubPath => "club path",
            Self::FaceAngle => "face angle",
            Self::DynamicLoft => "dynamic loft",
            Self::Club => "club",
        }
    }
}

impl core::fmt::Display for Datum {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.name())
    }
}

/// Result alias of the core.
pub type Result<T> = core::result::Result<T, Error>;

impl Error {
    /// Shorthand for [`Error::InvalidInput`].
    #[must_use]
    pub const fn invalid(field: Field, reason: Reason) -> Self {
        Self::InvalidInput { field, reason }
    }
}

impl Field {
    /// A short human name, as a launch-monitor user would read it.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::ClubMass => "club mass",
            Self::ClubInertia => "club inertia",
            Self::Loft => "loft",
            Self::RollRadius => "roll radius",
            Self::BulgeRadius => "bulge radius",
            Self::FaceDepthRadius => "face depth radius",
            Self::CgToFace => "CG-to-face offset",
            Self::Restitution => "coefficient of restitution",
            Self::ContactLaw => "contact law",
            Self::Friction => "friction coefficient",
            Self::TangentialRestitution => "tangential restitution",
            Self::TangentialRestitutionSlope => "tangential restitution slope",
            Self::TangentialRestitutionMax => "tangential restitution ceiling",
            Self::SpinAxisShare => "spin-axis share",
            Self::RestitutionSpeedSlope => "restitution speed slope",
            Self::BallMass => "ball mass",
            Self::BallRadius => "ball radius",
            Self::ClubSpeed => "club speed",
            Self::AttackAngle => "attack angle",
            Self::ClubPath => "club path",
            Self::FaceAngle => "face angle",
            Self::DynamicLoft => "dynamic loft",
            Self::Lie => "lie",
            Self::ClubSpin => "club spin",
            Self::ClubVelocity => "club velocity",
            Self::ClubOrientation => "club orientation",
            Self::ImpactHeight => "impact height",
            Self::ImpactToe => "impact toe offset",
            Self::BallVelocity => "ball velocity",
            Self::BallSpin => "ball spin",
            Self::BallSpeed => "ball speed",
            Self::LaunchAngle => "launch angle",
            Self::LaunchDirection => "launch direction",
            Self::Backspin => "backspin",
            Self::Sidespin => "sidespin",
            Self::LaunchPosition => "launch position",
            Self::AirDensity => "air density",
            Self::Temperature => "temperature",
            Self::Humidity => "relative humidity",
            Self::Pressure => "pressure",
            Self::Altitude => "altitude",
            Self::Wind => "wind",
            Self::WindReferenceHeight => "wind reference height",
            Self::WindExponent => "wind exponent",
            Self::LandingHeight => "landing height",
            Self::TimeLimit => "time limit",
            Self::Gravity => "gravity",
            Self::DragCoefficient => "drag coefficient",
            Self::LiftCoefficient => "lift coefficient",
            Self::SpinDecayCoefficient => "spin-decay coefficient",
            Self::ReynoldsNumber => "critical Reynolds number",
            Self::RecordInterval => "record interval",
            Self::GroundRestitution => "ground restitution",
            Self::GroundFriction => "ground friction",
            Self::RollingResistance => "rolling resistance",
            Self::CraterScale => "crater scale",
            Self::CraterFade => "crater fade speed",
            Self::GrassDrag => "grass drag",
            Self::GrassHeight => "grass height",
            Self::Stimp => "stimp",
            Self::GroundNormal => "ground slope",
            Self::Step => "step size",
            Self::Tolerance => "tolerance",
            Self::MeasurementNoise => "measurement noise",
            Self::PriorMean => "prior mean",
            Self::PriorSpread => "prior spread",
            Self::Iterations => "iteration budget",
            Self::ConsistencyBound => "consistency bound",
            Self::PosteriorScale => "posterior σ scale",
            Self::Observation => "observation",
            Self::SpinAxis => "spin axis",
        }
    }
}

impl fmt::Display for Field {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl fmt::Display for Reason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::NotFinite => "is not a finite number",
            Self::NotPositive => "must be positive",
            Self::Negative => "must not be negative",
            Self::OutOfRange => "is out of range",
            Self::NotSymmetric => "is not symmetric",
            Self::NotPositiveDefinite => "is not positive definite",
            Self::NotRotation => "is not a proper rotation",
            Self::UnsupportedBySolver => {
                "is not supported by the full 15×15 solver (use the reduced solver)"
            }
        })
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::InvalidInput { field, reason } => write!(f, "invalid input: {field} {reason}"),
            Self::OffFace => f.write_str("the impact point is off the club face"),
            Self::NoApproach => f.write_str("the club is not approaching the ball: no impact"),
            Self::Singular => f.write_str("the impact system is numerically singular"),
            Self::NoLanding => f.write_str("the ball never comes down through the landing height"),
            Self::TimeLimit => {
                f.write_str("the time limit was reached before the ball landed or while it bounced")
            }
            Self::StepSizeUnderflow => {
                f.write_str("the integrator cannot meet the tolerance in this precision")
            }
            Self::Unstable => {
                f.write_str("the fixed-step integrator diverged: the step is too large")
            }
            Self::StepLimit => {
                f.write_str("the adaptive integrator used up its step budget before landing")
            }
            Self::NoConvergence => {
                f.write_str("the estimate did not converge within its iteration budget")
            }
            Self::IllPosed => f.write_str(
                "the estimate is ill-posed: the data and priors do not determine the delivery",
            ),
            Self::Inconsistent { worst } => write!(
                f,
                "the data disagree with each other or with the club (worst: the {worst})"
            ),
            Self::TooFewObservations => {
                f.write_str("too few flight observations for the unknowns of the launch")
            }
            Self::Unidentifiable(field) => {
                write!(f, "the flight observations do not determine the {field}")
            }
        }
    }
}

impl core::error::Error for Error {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn error_is_small_and_names_the_field() {
        assert!(core::mem::size_of::<Error>() <= 4);
        let e = Error::invalid(Field::Restitution, Reason::OutOfRange);
        let mut buf = heapless::String::<96>::new();
        core::fmt::write(&mut buf, format_args!("{e}")).ok();
        assert_eq!(
            buf.as_str(),
            "invalid input: coefficient of restitution is out of range"
        );
    }
}
