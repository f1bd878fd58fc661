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
            Self::Modern(c) => {
                let per_speed = density * ball.diameter_m() / (viscosity * c.reynolds_critical);
                let ratio = c.cl_low_saturation_spin / c.cl_saturation_spin;
                PreparedAero {
                    forces: Forces::Modern {
                        drag_v: a * c.cd_supercritical,
                        crisis: Crisis::new(a * (c.cd_subcritical - c.cd_supercritical), per_speed),
                        drag_lift: a * c.cd_lift * c.cl_max,
                        lift_v: a * c.cl_max,
                        lift_low: a * c.cl_low,
                        saturation_per_spin: r / c.cl_low_saturation_spin,
                        ratio,
                        ratio_sq: ratio * ratio,
                    },
                    decay: half_rho_area * r * ball.diameter_m() / ball.inertia_kgm2() * c.cm_spin,
                }
            }
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
    /// With `x = S/S_sat`, `y = S/S_low` ([`ModernAero`]):
    /// `A·C_L·V = (lift_v·sat(x) + lift_low·sat(y))·V`,
    /// `A·C_D·V = (drag_v + A·(c_d,sub − c_d,super)·crisis + drag_lift·sat(x))·V`.
    Modern {
        /// `A·c_d,super` (1/m).
        drag_v: T,
        /// The crisis term `A·(c_d,sub − c_d,super)·crisis·V`.
        crisis: Crisis<T>,
        /// `A·k_L·c_l,max` (1/m).
        drag_lift: T,
        /// `A·c_l,max` (1/m).
        lift_v: T,
        /// `A·c_l,low` (1/m).
        lift_low: T,
        /// `R/S_low` (m): `y = S/S_low = saturation_per_spin·s/V`.
        saturation_per_spin: T,
        /// `S_low/S_sat`: `x = ratio·y`.
        ratio: T,
        /// `ratio²`.
        ratio_sq: T,
    },
}

/// The drag crisis factor `Δ·crisis = Δ/(1 + w³)` ([`ModernAero::crisis`] with
/// `w = (Re/Re_c)² = q·k²`) from `q = V²` alone: its division runs beside the square root.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(crate) struct Crisis<T> {
    /// `Δ = A·(c_d,sub − c_d,super)` (1/m).
    below: T,
    /// `k⁶ = (ρD/(μ·Re_c))⁶` (s⁶/m⁶).
    per_speed_6: T,
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
                crisis,
                drag_lift,
                lift_v,
                lift_low,
                saturation_per_spin,
                ratio,
                ratio_sq,
            } => {
                // Both laws as `P + Q·V` with P, Q from V² and s alone, so the square root
                // is the last input the force waits for: one multiply–add after it, as for
                // the linear family. At V = 0, y² = k²/0 is ∞ or NaN: the saturated
                // branches, `V·1 = 0`. The main component's `x² = ratio²·y²` needs no
                // second division.
                let k = saturation_per_spin * spin;
                let y_sq = k * k / speed_sq;
                let (low_0, low_1) = saturation_parts(k, y_sq);
                let (sat_0, sat_1) = saturation_parts(ratio * k, ratio_sq * y_sq);
                // The crisis term, the last to be ready, joins in the last addition.
                let kd = if drag {
                    (drag_lift * sat_0 + drag_v * speed)
                        + (drag_lift * speed * sat_1 + crisis.at(speed_sq) * speed)
                } else {
                    zero
                };
                let kl = if lift {
                    (lift_v * sat_0 + lift_low * low_0)
                        + (lift_v * sat_1 + lift_low * low_1) * speed
                } else {
                    zero
                };
                (kd, kl)
            }
        }
    }
}

impl<T: Real> Forces<T> {
    /// The rates of change `(dk_d/dt, dk_l/dt)` (1/s²) of the factors of
    /// [`Forces::factors`] when the air speed changes at the relative rate
    /// `relative_speed_rate = V̇/V` (1/s) and the spin at `spin_rate` (rad/s²):
    /// `∂k/∂V·V̇ + ∂k/∂s·ṡ`. For the modern family, with `F = saturation(u)·V`,
    /// `u = S/S_sat = k/V`, `k = (R/S_sat)·s` and the crisis weight
    /// `c = 1/(1 + (Re/Re_c)⁶)`:
    ///
    /// ```text
    /// ∂F/∂V·V = u²·(6V − 8k + 3u²V)   (u < 1; V above),      ∂(Δ·c·V)/∂V = Δ·c·(6c − 5)
    /// ```
    ///
    /// (from `u²` alone, beside the square root), for each lift component. The modern
    /// family's spin term is left out: it is zero past the lift's saturation, and below it
    /// the spin decays by about 1–2 % a second at run-out speeds.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn factor_rates(
        &self,
        speed: T,
        speed_sq: T,
        spin: T,
        relative_speed_rate: T,
        spin_rate: T,
        drag: bool,
        lift: bool,
    ) -> (T, T) {
        let zero = T::zero();
        let speed_rate = relative_speed_rate * speed;
        match *self {
            // Linear in V and s: the rates are the laws at (V̇, ṡ).
            Self::Linear { .. } => self.factors(speed_rate, zero, spin_rate, drag, lift),
            Self::Modern {
                drag_v,
                crisis,
                drag_lift,
                lift_v,
                lift_low,
                saturation_per_spin,
                ratio,
                ratio_sq,
            } => {
                let k = saturation_per_spin * spin;
                // At V = 0, y² is ∞ or NaN: the saturated branches, as in `factors`.
                let y_sq = k * k / speed_sq;
                let rate = |k: T, u_sq: T| {
                    if u_sq < T::one() {
                        let three_u_sq = lit::<T>(3.0) * u_sq;
                        u_sq * (lit::<T>(6.0) * speed - lit::<T>(8.0) * k + three_u_sq * speed)
                            * relative_speed_rate
                    } else {
                        speed_rate
                    }
                };
                let (main_rate, low_rate) = (rate(ratio * k, ratio_sq * y_sq), rate(k, y_sq));
                let dkd = if drag {
                    let c = crisis.weight(speed_sq);
                    let crisis_per_speed = crisis.below * c * (lit::<T>(6.0) * c - lit::<T>(5.0));
                    (drag_v + crisis_per_speed) * speed_rate + drag_lift * main_rate
                } else {
                    zero
                };
                let dkl = if lift {
                    lift_v * main_rate + lift_low * low_rate
                } else {
                    zero
                };
                (dkd, dkl)
            }
        }
    }
}

/// `saturation(S/S_sat)·V = P + Q·V` ([`ModernAero::saturation`]) from `k = (R/S_sat)·s`
/// and `u² = k²/V²`, without `V`: with `u = S/S_sat = k/V`,
/// `(1 − (1 − u)⁴)·V = 4u·V − 6u²·V + 4u³·V − u⁴·V = 4k·(1 + u²) − (6 + u²)·u²·V` below
/// saturation (`u² < 1`), and `V` above it. `u²` needs one division, by `V²`, beside the
/// square root.
#[inline(always)]
fn saturation_parts<T: Real>(k: T, u_sq: T) -> (T, T) {
    if u_sq < T::one() {
        (
            lit::<T>(4.0) * k * (T::one() + u_sq),
            -(lit::<T>(6.0) + u_sq) * u_sq,
        )
    } else {
        (T::zero(), T::one())
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
            let k = |v: f64, s: f64| p.forces.factors(v, v * v, s, true, true);
            for (v, s) in [
                (6.0, 290.0),
                (20.0, 150.0),
                (25.0, 40.0),
                (45.0, 300.0),
                (3.0, 800.0),
            ] {
                let (rel, spin_rate) = (-0.05, if linear { -3.0 } else { 0.0 });
                let (dkd, dkl) = p
                    .forces
                    .factor_rates(v, v * v, s, rel, spin_rate, true, true);
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
