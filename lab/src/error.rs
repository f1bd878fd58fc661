//! The lab's typed errors: what went wrong, in terms a command line can name.

use std::fmt;

/// Which user-facing input an error is about (the CLI maps it to an option name).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Input {
    /// Dynamic-loft bounds of the optimizer.
    DynamicLoftRange,
    /// Attack-angle bounds of the optimizer.
    AttackAngleRange,
    /// Impact-height bounds of the optimizer.
    ImpactHeightRange,
    /// The optimizer's objective.
    Objective,
    /// Number of starts, shots or grid points.
    Count,
    /// A noise standard deviation (the index into [`crate::dispersion::Noise::FIELDS`]).
    NoiseSd(usize),
    /// The swing file.
    Swing,
    /// The ball positions of a sweep.
    BallPositions,
    /// Club speeds of the optimizer chart.
    ChartSpeeds,
    /// Attack angles of the optimizer chart.
    ChartAttackAngles,
}

/// An analysis failure.
#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// The physics core rejected a shot.
    Core(carry_core::Error),
    /// An input is invalid: which, and why (a sentence fragment).
    Invalid(Input, String),
    /// A maintained library (the optimizer) failed.
    Library(String),
}

impl Error {
    /// An invalid `input`, because `why`.
    pub fn invalid(input: Input, why: impl Into<String>) -> Self {
        Self::Invalid(input, why.into())
    }
}

impl From<carry_core::Error> for Error {
    fn from(e: carry_core::Error) -> Self {
        Self::Core(e)
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Core(e) => write!(f, "{e}"),
            Self::Invalid(input, why) => write!(f, "{input:?}: {why}"),
            Self::Library(why) => write!(f, "{why}"),
        }
    }
}

impl std::error::Error for Error {}

/// A lab result.
pub type Result<T> = std::result::Result<T, Error>;
