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
use super::saturation::SpinLaws;
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
    /// [`AeroModel::drives_2026`] is the calibrated default.
    Modern(ModernAero<T>),
}

/// Names of the built-in models, default first: `drives2026` (the calibrated default: the
/// modern family fitted to single drives with both tables, issue 35), `tour2023` (the
/// modern family fitted to the tables alone, issue 21) and `quintavalla` (the seed model).
pub const BUILT_IN_MODELS: [&str; 3] = ["drives2026", "tour2023", "quintavalla"];

impl<T: Real> AeroModel<T> {
    /// The seed model: Quintavalla's linear coefficients (bit for bit the golden files').
    #[must_use]
    pub fn quintavalla() -> Self {
        Self::Linear(LinearAero::quintavalla())
    }

    /// The modern family fitted to TrackMan's 2023 tour averages and 2010 driver chart
    /// (issue 21; the default before issue 35).
    #[must_use]
    pub fn tour_2023() -> Self {
        Self::Modern(ModernAero::tour_2023())
    }

    /// The calibrated default: the modern family fitted to TrackMan's single drives with
    /// both tables (issue 35).
    #[must_use]
    pub fn drives_2026() -> Self {
        Self::Modern(ModernAero::drives_2026())
    }

    /// A built-in model by name ([`BUILT_IN_MODELS`]), `None` for an unknown name.
    #[must_use]
    pub fn named(name: &str) -> Option<Self> {
        match name {
            "tour2023" => Some(Self::tour_2023()),
            "quintavalla" => Some(Self::quintavalla()),
            "drives2026" => Some(Self::drives_2026()),
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
            Self::Modern(c) => {
                let per_speed = density * ball.diameter_m() / (viscosity * c.reynolds_critical);
                PreparedAero {
                    forces: Forces::Modern {
                        drag_v: a * c.cd_supercritical,
                        crisis: Crisis::new(a * (c.cd_subcritical - c.cd_supercritical), per_speed),
                        spin: SpinLaws::new(
                            r,
                            (a * c.cl_max, a * c.cd_lift * c.cl_max, c.cl_saturation_spin),
                            (a * c.cl_low, T::zero(), c.cl_low_saturation_spin),
                        ),
                    },
                    decay: half_rho_area * r * ball.diameter_m() / ball.inertia_kgm2() * c.cm_spin,
                }
            }
        })
    }
}

impl<T: Real> Default for AeroModel<T> {
    /// The calibrated default, [`AeroModel::drives_2026`].
    fn default() -> Self {
        Self::drives_2026()
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
    /// [`ModernAero`]: `A·C_D·V = (drag_v + A·(c_d,sub − c_d,super)·crisis)·V + spin drag`,
    /// `A·C_L·V` and the spin drag `A·k_L·c_l,max·sat(S/S_sat)·V` from [`SpinLaws`].
    Modern {
        /// `A·c_d,super` (1/m).
        drag_v: T,
        /// The crisis term `A·(c_d,sub − c_d,super)·crisis·V`.
        crisis: Crisis<T>,
        /// The lift and the spin drag.
        spin: SpinLaws<T>,
    },
}

/// The drag crisis factor `Δ·crisis = Δ/(1 + w³)` ([`ModernAero::crisis`] with
/// `w = (Re/Re_c)² = q·k²`) from `q = V²` alone: its division runs beside the square root.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(crate) struct Crisis<T> {
    /// `Δ = A·(c_d,sub − c_d,super)` (1/m).
    pub(crate) below: T,
    /// `k⁶ = (ρD/(μ·Re_c))⁶` (s⁶/m⁶).
    pub(crate) per_speed_6: T,
}

impl<T: Real> Crisis<T> {
    /// The factor for `Δ = below` and `k = ρD/(μ·Re_c)` = `per_speed` (s/m).
    fn new(below: T, per_speed: T) -> Self {
        let k_sq = per_speed * per_speed;
        Self {
            below,
            per_speed_6: k_sq * k_sq * k_sq,
        }
    }

    /// `1 + w³` at `q = V²`, with `w³ = q²·(q·k⁶)`: the two products side by side (two
    /// multiplies deep, not three).
    #[inline(always)]
    fn one_plus_w3(&self, speed_sq: T) -> T {
        T::one() + (speed_sq * speed_sq) * (speed_sq * self.per_speed_6)
    }

    /// `Δ·crisis` at `q = V²`: `Δ/(1 + w³)`, one division (`Δ` in the numerator rather than
    /// a multiply after it: it is on the force's critical path).
    #[inline(always)]
    fn at(&self, speed_sq: T) -> T {
        self.below / self.one_plus_w3(speed_sq)
    }

    /// The crisis weight `c = 1/(1 + w³)` alone (for its derivative).
    fn weight(&self, speed_sq: T) -> T {
        T::one() / self.one_plus_w3(speed_sq)
    }
}

impl<T: Real> Forces<T> {
    /// `(A·C_D·V, A·C_L·V)` (1/s) at air speed `speed = V` (its square `speed_sq`, from
    /// which `V` was taken) and spin `spin`, each only when asked for (`0` otherwise): the
    /// drag acceleration is `−(A·C_D·V)·v_r`, the lift acceleration `(A·C_L·V)·(ω̂ × v_r)`.
    /// One dispatch on the family per evaluation; called only when drag or lift is on.
    ///
    /// The modern family's two divisions (the lift's `s²/V²` and the crisis) need only `V²`,
    /// so they run beside the square root rather than after it.
    ///
    /// `spin_sq`: the spin's square when known apart from `spin` (a hop's; see
    /// `SpinLaws::piece`), else `None`.
    #[inline(always)]
    pub(crate) fn factors(
        &self,
        speed: T,
        speed_sq: T,
        spin: T,
        spin_sq: Option<T>,
        drag: bool,
        lift: bool,
    ) -> (T, T) {
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
                crisis,
                spin: ref spin_laws,
            } => {
                // Both laws as `P + Q·V` with P, Q from V² and s alone, so the square root
                // is the last input the force waits for: one multiply–add after it, as for
                // the linear family. At V = 0 the laws are past saturation: `Q·0 = 0`.
                let ((lift_0, lift_1), (drag_0, drag_1)) = spin_laws.at(spin, spin_sq, speed_sq);
                // The crisis term, the last to be ready, joins in the last addition.
                let kd = if drag {
                    (drag_0 + drag_v * speed) + (drag_1 * speed + crisis.at(speed_sq) * speed)
                } else {
                    zero
                };
                let kl = if lift { lift_0 + lift_1 * speed } else { zero };
                (kd, kl)
            }
        }
    }
}

impl<T: Real> Forces<T> {
    /// The rates of change `(dk_d/dt, dk_l/dt)` (1/s²) of the factors of
    /// [`Forces::factors`] when the air speed changes at the relative rate
    /// `relative_speed_rate = V̇/V` (1/s) and the spin at `spin_rate` (rad/s²):
    /// `∂k/∂V·V̇ + ∂k/∂s·ṡ`. For the modern family, the spin laws' `V·∂F/∂V` on their
    /// piece ([`SpinLaws::speed_derivatives`]; for one quartic, `u²·(6V − 8k + 3u²V)` below
    /// saturation, `V` above) and, with the crisis weight `c = 1/(1 + (Re/Re_c)⁶)`,
    /// `∂(Δ·c·V)/∂V = Δ·c·(6c − 5)` (from `V²` alone, beside the square root). The modern
    /// family's spin term is left out: it is zero past the lift's saturation, and below it
    /// the spin decays by about 1–2 % a second at run-out speeds.
    ///
    /// Inlined on hosts and on hard-float targets (the M4F: a call spills and shuffles the
    /// low hop's live registers around it); out of line on the micro:bit (flash, stack).
    #[allow(clippy::too_many_arguments)]
    #[cfg_attr(any(not(target_os = "none"), target_abi = "eabihf"), inline(always))]
    pub(crate) fn factor_rates(
        &self,
        speed: T,
        speed_sq: T,
        spin: T,
        spin_sq: Option<T>,
        relative_speed_rate: T,
        spin_rate: T,
        drag: bool,
        lift: bool,
    ) -> (T, T) {
        let zero = T::zero();
        let speed_rate = relative_speed_rate * speed;
        match *self {
            // Linear in V and s: the rates are the laws at (V̇, ṡ).
            Self::Linear { .. } => self.factors(speed_rate, zero, spin_rate, None, drag, lift),
            Self::Modern {
                drag_v,
                crisis,
                spin: ref spin_laws,
            } => {
                let (lift_rate, drag_rate) =
                    spin_laws.speed_derivatives(spin, spin_sq, speed, speed_sq);
                let dkd = if drag {
                    let c = crisis.weight(speed_sq);
                    let crisis_per_speed = crisis.below * c * (lit::<T>(6.0) * c - lit::<T>(5.0));
                    (drag_v + crisis_per_speed) * speed_rate + drag_rate * relative_speed_rate
                } else {
                    zero
                };
                let dkl = if lift {
                    lift_rate * relative_speed_rate
                } else {
                    zero
                };
                (dkd, dkl)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `factor_rates` against central differences of `factors` along a speed and a spin
    /// change, for both families: below and past the lift's saturation, below, inside and
    /// above the drag crisis. The modern family leaves its spin term out (documented), so
    /// it is checked with the speed changing alone.
    #[test]
    fn factor_rates_are_the_factors_derivatives() {
        let ball = Ball::<f64>::standard();
        for model in [AeroModel::quintavalla(), AeroModel::tour_2023()] {
            let Ok(p) = model.prepare(&ball, 1.225, crate::air::STANDARD_VISCOSITY_PAS) else {
                panic!("prepare")
            };
            let linear = matches!(p.forces, Forces::Linear { .. });
            let k = |v: f64, s: f64| p.forces.factors(v, v * v, s, None, true, true);
            for (v, s) in [
                (6.0, 290.0),
                (20.0, 150.0),
                (25.0, 40.0),
                (45.0, 300.0),
                (3.0, 800.0),
            ] {
                let (rel, spin_rate) = (-0.05, if linear { -3.0 } else { 0.0 });
                let (dkd, dkl) =
                    p.forces
                        .factor_rates(v, v * v, s, None, rel, spin_rate, true, true);
                let dt = 1e-4;
                let (v1, s1) = (v * (1.0 + rel * dt), s + spin_rate * dt);
                let (v0, s0) = (v * (1.0 - rel * dt), s - spin_rate * dt);
                let ((d1, l1), (d0, l0)) = (k(v1, s1), k(v0, s0));
                let (fd, fl) = ((d1 - d0) / (2.0 * dt), (l1 - l0) / (2.0 * dt));
                let close = |a: f64, b: f64| (a - b).abs() <= 1e-6 * b.abs().max(1e-3);
                assert!(
                    close(dkd, fd) && close(dkl, fl),
                    "{v} m/s, {s} rad/s: ({dkd}, {dkl}) against ({fd}, {fl})"
                );
            }
        }
    }
}
