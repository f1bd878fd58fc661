//! The modern family: drag with a Reynolds-number drag crisis and a spin term, lift that
//! saturates at high spin parameter, and the spin decay of Smits & Smith.
//!
//! With the spin parameter `S = |ω|·R/V` and the Reynolds number `Re = ρ·V·D/μ`:
//!
//! ```text
//! C_D(S, Re) = c_d,super + (c_d,sub − c_d,super) / (1 + (Re/Re_c)⁶) + c_d,S · S
//! C_L(S)     = c_l,max · S / (S + S_½)
//! C_M(S)     = c_m · S                        (dω/dt = −(½ρπR²·C_M·D/I_b)·V²/… ∝ V·ω)
//! ```
//!
//! Sources:
//! * **Drag.** Bearman & Harvey (1976), "Golf ball aerodynamics", Aeronaut. Q. 27: a
//!   dimpled ball's drag crisis sits near Re ≈ 5·10⁴ (a smooth sphere's near 3·10⁵), with
//!   `C_D ≈ 0.45–0.5` below it and a supercritical plateau that rises with spin; the
//!   smooth step `1/(1 + (Re/Re_c)⁶)` stands for the measured transition. The spin slope
//!   has the form of Nathan's calculator (`C_D = C_D0 + 0.2087·S` above the crisis) and
//!   Lyu et al. (2018), Proceedings 2(6):238, whose wind-tunnel drag rises linearly with S.
//! * **Lift.** Bearman & Harvey and Lyu et al. measure a lift that grows quickly at small
//!   S and flattens above S ≈ 0.2–0.3 (Nathan fits `0.2294·S^0.4`); `S/(S + S_½)` has that
//!   shape, is 0 at S = 0 (no Magnus force without spin) and needs no `powf`.
//! * **Spin decay.** Smits & Smith (1994), "A new aerodynamic model of a golf ball in
//!   flight", Science and Golf II: spin falls at `dω/dt ≈ −0.0004·V[mph]·ω` per second,
//!   i.e. `−8.95·10⁻⁴ /m · V·ω` at standard air, the same form as a moment coefficient
//!   linear in S; Nathan's calculator uses `τ = R/(2·10⁻⁵·V)`, 4.7 % faster.
//!
//! The coefficients of [`ModernAero::tour_2023`] were fitted to TrackMan's 2023 tour
//! averages by `carry fit` (docs/aero.md), every one inside physical bounds: the fitted
//! drag crisis (`c_d,sub` 0.51, `Re_c` 7.2·10⁴) lies in Bearman & Harvey's measured
//! range; the spin decay ends on its lower bound (1.3 %/s for a driver).

use super::linear::coefficient;
use crate::error::{Error, Field, Reason, Result};
use crate::real::{Real, lit};

/// Coefficients of the modern family (all dimensionless). Validate with
/// [`ModernAero::validate`] (done by [`crate::Scene::prepare`]).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ModernAero<T> {
    /// Zero-spin drag coefficient above the drag crisis, `c_d,super`, in `0..=2`.
    pub cd_supercritical: T,
    /// Zero-spin drag coefficient below the drag crisis, `c_d,sub`, in `0..=2`.
    pub cd_subcritical: T,
    /// Reynolds number in the middle of the drag crisis, `Re_c`, in `10³..=10⁷`.
    pub reynolds_critical: T,
    /// Drag slope in the spin parameter, `c_d,S`, in `0..=10`.
    pub cd_spin: T,
    /// Saturation lift coefficient, `c_l,max`, in `0..=2`.
    pub cl_max: T,
    /// Spin parameter at which the lift is half of `c_l,max`, `S_½`, in `(0, 10]`.
    pub cl_half_spin: T,
    /// Moment (spin-decay) slope in the spin parameter, `c_m`, in `0..=1`.
    pub cm_spin: T,
}

/// The calibrated default ([`ModernAero::tour_2023`]) in `f64`, in the order of
/// [`ModernAero::to_array`]. Produced by `carry fit --family modern --input
/// ../shared/data/trackman_tour_2023.csv --temperature 21.1 --humidity 50 --pressure 101325`
/// (docs/aero.md), rounded to 4 significant digits.
pub const TOUR_2023: [f64; 7] = [0.2352, 0.5091, 7.179e4, 0.1183, 0.4014, 0.1207, 0.002];

/// Names of the modern family's coefficients, in the order of [`ModernAero::to_array`]
/// (the keys of an aerodynamic model file).
pub const MODERN_NAMES: [&str; 7] = [
    "cd_supercritical",
    "cd_subcritical",
    "reynolds_critical",
    "cd_spin",
    "cl_max",
    "cl_half_spin",
    "cm_spin",
];

impl<T: Real> ModernAero<T> {
    /// The calibrated default: fitted to TrackMan's 2023 PGA and LPGA tour averages.
    #[must_use]
    pub fn tour_2023() -> Self {
        Self::from_array(TOUR_2023.map(lit))
    }

    /// The coefficients in order `[cd_supercritical, cd_subcritical, reynolds_critical,
    /// cd_spin, cl_max, cl_half_spin, cm_spin]`.
    #[must_use]
    pub fn to_array(&self) -> [T; 7] {
        [
            self.cd_supercritical,
            self.cd_subcritical,
            self.reynolds_critical,
            self.cd_spin,
            self.cl_max,
            self.cl_half_spin,
            self.cm_spin,
        ]
    }

    /// The inverse of [`ModernAero::to_array`].
    #[must_use]
    pub fn from_array(c: [T; 7]) -> Self {
        Self {
            cd_supercritical: c[0],
            cd_subcritical: c[1],
            reynolds_critical: c[2],
            cd_spin: c[3],
            cl_max: c[4],
            cl_half_spin: c[5],
            cm_spin: c[6],
        }
    }

    /// Checks every coefficient is finite and inside its documented range.
    ///
    /// # Errors
    /// [`Field::DragCoefficient`], [`Field::ReynoldsNumber`], [`Field::LiftCoefficient`]
    /// or [`Field::SpinDecayCoefficient`] with [`Reason::NotFinite`] or
    /// [`Reason::OutOfRange`].
    pub fn validate(&self) -> Result<Self> {
        let two = lit::<T>(2.0);
        coefficient(self.cd_supercritical, two, Field::DragCoefficient)?;
        coefficient(self.cd_subcritical, two, Field::DragCoefficient)?;
        coefficient(self.cd_spin, lit(10.0), Field::DragCoefficient)?;
        let re = coefficient(self.reynolds_critical, lit(1.0e7), Field::ReynoldsNumber)?;
        if re < lit(1.0e3) {
            return Err(Error::invalid(Field::ReynoldsNumber, Reason::OutOfRange));
        }
        coefficient(self.cl_max, two, Field::LiftCoefficient)?;
        let half = coefficient(self.cl_half_spin, lit(10.0), Field::LiftCoefficient)?;
        if half <= T::zero() {
            return Err(Error::invalid(Field::LiftCoefficient, Reason::NotPositive));
        }
        coefficient(self.cm_spin, T::one(), Field::SpinDecayCoefficient)?;
        Ok(*self)
    }

    /// The drag-crisis weight `1/(1 + (Re/Re_c)⁶)`: 1 far below the crisis, 0 far above.
    #[must_use]
    pub fn crisis(ratio: T) -> T {
        Self::crisis_of_square(ratio * ratio)
    }

    /// The same weight from the squared ratio `w = (Re/Re_c)²`: `1/(1 + w³)`.
    #[must_use]
    pub fn crisis_of_square(ratio_sq: T) -> T {
        T::one() / (T::one() + ratio_sq * ratio_sq * ratio_sq)
    }

    /// `C_D(S, Re)`.
    #[must_use]
    pub fn drag_coefficient(&self, spin_parameter: T, reynolds: T) -> T {
        self.cd_supercritical
            + (self.cd_subcritical - self.cd_supercritical)
                * Self::crisis(reynolds / self.reynolds_critical)
            + self.cd_spin * spin_parameter
    }

    /// `C_L(S) = c_l,max·S/(S + S_½)`.
    #[must_use]
    pub fn lift_coefficient(&self, spin_parameter: T) -> T {
        self.cl_max * spin_parameter / (spin_parameter + self.cl_half_spin)
    }

    /// `C_M(S) = c_m·S`.
    #[must_use]
    pub fn moment_coefficient(&self, spin_parameter: T) -> T {
        self.cm_spin * spin_parameter
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn laws_are_the_documented_formulas() {
        let m = ModernAero::<f64>::tour_2023();
        let [sup, sub, rec, cds, clm, half, cm] = TOUR_2023;
        for (s, re) in [(0.0, 2.0e5), (0.1, 1.5e5), (0.3, 6.0e4), (0.6, 4.0e4)] {
            let step = 1.0 / (1.0 + (re / rec).powi(6));
            let cd = sup + (sub - sup) * step + cds * s;
            assert!((m.drag_coefficient(s, re) - cd).abs() < 1e-15);
            assert!((m.lift_coefficient(s) - clm * s / (s + half)).abs() < 1e-15);
            assert!((m.moment_coefficient(s) - cm * s).abs() < 1e-18);
        }
        // The crisis step: half way at Re_c, sub- and supercritical plateaus either side.
        assert!((ModernAero::<f64>::crisis(1.0) - 0.5).abs() < 1e-15);
        assert!(ModernAero::<f64>::crisis(0.3) > 0.99 && ModernAero::<f64>::crisis(3.0) < 0.01);
    }

    #[test]
    fn rejects_absurd_coefficients() {
        let m = ModernAero::<f32>::tour_2023();
        assert_eq!(m.validate(), Ok(m));
        let cases = [
            (
                ModernAero {
                    cl_half_spin: 0.0,
                    ..m
                },
                Field::LiftCoefficient,
            ),
            (
                ModernAero {
                    reynolds_critical: 10.0,
                    ..m
                },
                Field::ReynoldsNumber,
            ),
            (
                ModernAero {
                    cd_spin: f32::NAN,
                    ..m
                },
                Field::DragCoefficient,
            ),
            (
                ModernAero {
                    cm_spin: -1e-3,
                    ..m
                },
                Field::SpinDecayCoefficient,
            ),
        ];
        for (bad, field) in cases {
            assert!(
                matches!(bad.validate(), Err(Error::InvalidInput { field: f, .. }) if f == field)
            );
        }
        assert_eq!(ModernAero::from_array(m.to_array()), m);
    }
}
