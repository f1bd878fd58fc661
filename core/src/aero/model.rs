//! The aerodynamic model a scene holds: which family, with which coefficients, and its
//! per-unit-mass form for the flight loop.
//!
//! With `A = ½ρπR²/m_b`, `s = |ω|`, `V = |v_r|`, every family's accelerations are written
//! without dividing by `V` or `s` where it can be avoided, so they stay finite as `V → 0`
//! and at `ω = 0`:
//!
//! ```text
//! a_drag = −A·C_D·V·v_r            a_lift = A·C_L·V·(ω̂ × v_r)
//! ds/dt  = −(½ρπR²·C_M·D/I_b)·V²/… = −λ·V·s      (C_M ∝ S for every family)
//! ```

use super::linear::LinearAero;
use super::modern::ModernAero;
use crate::ball::Ball;
use crate::error::Result;
use crate::real::{Real, lit, to_f64};

/// An aerodynamic model: a family and its coefficients. Held by the
/// [`Scene`](crate::Scene); static dispatch in the flight loop.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum AeroModel<T> {
    /// The seed's linear family; [`AeroModel::quintavalla`] is the seed model itself.
    Linear(LinearAero<T>),
    /// The modern family (drag crisis, saturating lift, Smits & Smith spin decay);
    /// [`AeroModel::tour_2023`] is the calibrated default.
    Modern(ModernAero<T>),
}

/// Names of the built-in models, default first: `tour2023` (the calibrated modern model)
/// and `quintavalla` (the seed model).
pub const BUILT_IN_MODELS: [&str; 2] = ["tour2023", "quintavalla"];

impl<T: Real> AeroModel<T> {
    /// The seed model: Quintavalla's linear coefficients (bit for bit the golden files').
    #[must_use]
    pub fn quintavalla() -> Self {
        Self::Linear(LinearAero::quintavalla())
    }

    /// The calibrated default: the modern family fitted to TrackMan's 2023 tour averages.
    #[must_use]
    pub fn tour_2023() -> Self {
        Self::Modern(ModernAero::tour_2023())
    }

    /// A built-in model by name ([`BUILT_IN_MODELS`]), `None` for an unknown name.
    #[must_use]
    pub fn named(name: &str) -> Option<Self> {
        match name {
            "tour2023" => Some(Self::tour_2023()),
            "quintavalla" => Some(Self::quintavalla()),
            _ => None,
        }
    }

    /// The same model in precision `U` (each coefficient rounded to nearest).
    #[must_use]
    pub fn cast<U: Real>(&self) -> AeroModel<U> {
        let c = |x: T| lit::<U>(to_f64(x));
        match self {
            Self::Linear(m) => AeroModel::Linear(LinearAero::from_array(m.to_array().map(c))),
            Self::Modern(m) => AeroModel::Modern(ModernAero::from_array(m.to_array().map(c))),
        }
    }

    /// The family's name as `carry fit --family` spells it.
    #[must_use]
    pub fn family(&self) -> &'static str {
        match self {
            Self::Linear(_) => "quintavalla",
            Self::Modern(_) => "modern",
        }
    }

    /// Checks the coefficients.
    ///
    /// # Errors
    /// The errors of [`LinearAero::validate`] or [`ModernAero::validate`].
    pub fn validate(&self) -> Result<Self> {
        match self {
            Self::Linear(c) => c.validate().map(Self::Linear),
            Self::Modern(c) => c.validate().map(Self::Modern),
        }
    }

    /// The drag, lift and moment coefficients `(C_D, C_L, C_M)` at spin parameter `S` and
    /// Reynolds number `Re` (for plots, tests and reports; the flight loop uses the
    /// prepared form).
    #[must_use]
    pub fn coefficients(&self, spin_parameter: T, reynolds: T) -> (T, T, T) {
        match self {
            Self::Linear(c) => (
                c.drag_coefficient(spin_parameter),
                c.lift_coefficient(spin_parameter),
                c.moment_coefficient(spin_parameter),
            ),
            Self::Modern(c) => (
                c.drag_coefficient(spin_parameter, reynolds),
                c.lift_coefficient(spin_parameter),
                c.moment_coefficient(spin_parameter),
            ),
        }
    }

    /// The validated model in per-unit-mass form for `ball` in air of density `density`
    /// (kg/m³) and dynamic viscosity `viscosity` (Pa·s).
    pub(crate) fn prepare(
        &self,
        ball: &Ball<T>,
        density: T,
        viscosity: T,
    ) -> Result<PreparedAero<T>> {
        let r = ball.radius_m();
        let half_rho_area = lit::<T>(0.5) * density * T::pi() * r * r;
        let a = half_rho_area / ball.mass_kg();
        Ok(match self.validate()? {
            Self::Linear(c) => PreparedAero {
                forces: Forces::Linear {
                    drag_v: a * c.cd0,
                    drag_s: a * c.cd_spin * r,
                    lift_v: a * c.cl0,
                    lift_s: a * c.cl_spin * r,
                },
                // The seed's operation order, for bit identity with the golden files.
                decay: half_rho_area * c.cm_spin * r * ball.diameter_m() / ball.inertia_kgm2(),
            },
            Self::Modern(c) => PreparedAero {
                forces: Forces::Modern {
                    drag_v: a * c.cd_supercritical,
                    drag_crisis: a * (c.cd_subcritical - c.cd_supercritical),
                    crisis_per_speed_sq: {
                        let per_speed =
                            density * ball.diameter_m() / (viscosity * c.reynolds_critical);
                        per_speed * per_speed
                    },
                    drag_s: a * c.cd_spin * r,
                    lift_max: a * c.cl_max * r,
                    radius: r,
                    lift_half: c.cl_half_spin,
                },
                decay: half_rho_area * r * ball.diameter_m() / ball.inertia_kgm2() * c.cm_spin,
            },
        })
    }
}

impl<T: Real> Default for AeroModel<T> {
    /// The calibrated default, [`AeroModel::tour_2023`].
    fn default() -> Self {
        Self::tour_2023()
    }
}

/// An aerodynamic model in the flight loop's per-unit-mass form.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(crate) struct PreparedAero<T> {
    /// The drag and lift coefficients.
    pub(crate) forces: Forces<T>,
    /// Spin decay `λ` in `ds/dt = −λ·V·s` (1/m): `½ρπR²·c_m·R·D/I_b`.
    pub(crate) decay: T,
}

/// Drag and lift per unit mass, by family.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(crate) enum Forces<T> {
    /// `A·C_D·V = drag_v·V + drag_s·s`, `A·C_L·V = lift_v·V + lift_s·s`.
    Linear {
        /// `A·c_d0` (1/m).
        drag_v: T,
        /// `A·c_d,sp·R` (1/rad).
        drag_s: T,
        /// `A·c_l0` (1/m).
        lift_v: T,
        /// `A·c_l,sp·R` (1/rad).
        lift_s: T,
    },
    /// `A·C_D·V = (drag_v + drag_crisis/(1 + (V²·crisis_per_speed_sq)³))·V + drag_s·s`,
    /// `A·C_L·V = lift_max·s·V/(R·s + S_½·V)`.
    Modern {
        /// `A·c_d,super` (1/m).
        drag_v: T,
        /// `A·(c_d,sub − c_d,super)` (1/m).
        drag_crisis: T,
        /// `(ρ·D/(μ·Re_c))²`: `(Re/Re_c)²` per unit squared speed (s²/m²).
        crisis_per_speed_sq: T,
        /// `A·c_d,S·R` (1/rad).
        drag_s: T,
        /// `A·c_l,max·R` (1/rad).
        lift_max: T,
        /// Ball radius R (m).
        radius: T,
        /// `S_½`.
        lift_half: T,
    },
}

impl<T: Real> Forces<T> {
    /// `(A·C_D·V, A·C_L·V)` (1/s) at air speed `speed = V` (its square `speed_sq`, from
    /// which `V` was taken) and spin `spin`, each only when asked for (`0` otherwise): the
    /// drag acceleration is `−(A·C_D·V)·v_r`, the lift acceleration `(A·C_L·V)·(ω̂ × v_r)`.
    /// One dispatch on the family per evaluation.
    ///
    /// The drag crisis is computed from `V²`, not `V`: `(Re/Re_c)⁶ = (V²·k²)³`, so its
    /// division runs beside the square root instead of after it (−13 % of a host shot).
    #[inline(always)]
    pub(crate) fn factors(&self, speed: T, speed_sq: T, spin: T, drag: bool, lift: bool) -> (T, T) {
        let zero = T::zero();
        match *self {
            Self::Linear {
                drag_v,
                drag_s,
                lift_v,
                lift_s,
            } => (
                if drag {
                    drag_v * speed + drag_s * spin
                } else {
                    zero
                },
                if lift {
                    lift_v * speed + lift_s * spin
                } else {
                    zero
                },
            ),
            Self::Modern {
                drag_v,
                drag_crisis,
                crisis_per_speed_sq,
                drag_s,
                lift_max,
                radius,
                lift_half,
            } => {
                let kd = if drag {
                    let crisis = ModernAero::crisis_of_square(speed_sq * crisis_per_speed_sq);
                    (drag_v + drag_crisis * crisis) * speed + drag_s * spin
                } else {
                    zero
                };
                // C_L·V = c_l,max·S·V/(S + S_½) with S = R·s/V, multiplied through by V.
                let denominator = radius * spin + lift_half * speed;
                let kl = if lift && denominator > zero {
                    lift_max * spin * speed / denominator
                } else {
                    zero
                };
                (kd, kl)
            }
        }
    }
}
