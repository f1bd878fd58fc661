//! The force field a flight flies through, per unit mass: which effects act, gravity, the
//! prepared aerodynamic model and the wind. Grouped so that the flight's right-hand side
//! ([`super::Dynamics`]) borrows this, not the whole scene.

use super::PreparedAero;
use crate::real::Real;
use crate::wind::WindField;

/// Which aerodynamic effects a flight simulates (gravity always acts).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Effects {
    /// Aerodynamic drag.
    pub drag: bool,
    /// Magnus lift.
    pub lift: bool,
    /// Spin decay from the aerodynamic torque (otherwise the spin stays at its launch value).
    pub spin_decay: bool,
}

impl Effects {
    /// The full model: drag, lift and spin decay.
    pub const ALL: Self = Self {
        drag: true,
        lift: true,
        spin_decay: true,
    };
    /// Gravity only: a vacuum parabola.
    pub const GRAVITY_ONLY: Self = Self {
        drag: false,
        lift: false,
        spin_decay: false,
    };
}

impl Default for Effects {
    fn default() -> Self {
        Self::ALL
    }
}

/// The force field of a validated scene, per unit mass: the effects simulated, gravity,
/// the aerodynamic model (`A = ½ρπR²/m_b` folded in) and the wind.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(crate) struct ForceField<T: Real> {
    pub(crate) effects: Effects,
    /// Gravitational acceleration (m/s²).
    pub(crate) gravity: T,
    /// The aerodynamic model per unit mass.
    pub(crate) aero: PreparedAero<T>,
    pub(crate) wind: WindField<T>,
}

impl<T: Real> ForceField<T> {
    /// Whether a wind profile is singular near height `y`: its derivative
    /// `k·w_ref·y^(k−1)/h_ref^k` is unbounded at the ground, and steep up to ~h_ref.
    pub(crate) fn profile_singular_at(&self, y: T) -> bool {
        match self.wind {
            WindField::Profile {
                inv_reference_height,
                exponent,
                ..
            } => exponent > T::zero() && y * inv_reference_height < T::one(),
            _ => false,
        }
    }

    /// Whether any wind is evaluated (an aerodynamic effect and a wind).
    #[inline(always)]
    pub(crate) fn has_wind(&self) -> bool {
        !matches!(self.wind, WindField::None)
    }

    /// Whether the wind changes with height (a profile).
    pub(crate) fn wind_varies_with_height(&self) -> bool {
        matches!(self.wind, WindField::Profile { .. })
    }
}
