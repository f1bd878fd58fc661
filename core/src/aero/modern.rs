//! The modern family: a smooth Reynolds-number drag crisis, a lift of two saturating
//! components (a steep low-spin one and a slow main one), a spin drag that follows the main
//! lift, and a spin decay of the Smits & Smith form.
//!
//! With the spin parameter `S = |ω|·R/V`, the Reynolds number `Re = ρ·V·D/μ` and
//! `sat(u) = 1 − (1 − min(u, 1))⁴`:
//!
//! ```text
//! C_L(S)     = c_l,max · sat(S/S_sat) + c_l,low · sat(S/S_low)
//! C_D(S, Re) = c_d,super + (c_d,sub − c_d,super) / (1 + (Re/Re_c)⁶) + k_L · c_l,max · sat(S/S_sat)
//! C_M(S)     = c_m · S                          (dω/dt ∝ −V·ω)
//! ```
//!
//! Sources and reasons:
//! * **Drag crisis.** Bearman & Harvey (1976), "Golf ball aerodynamics", Aeronaut. Q. 27:
//!   a dimpled ball's drag falls from ≈ 0.45–0.5 to a supercritical plateau between
//!   Re ≈ 4·10⁴ and 10⁵ (a smooth sphere's near 3·10⁵); the smooth step `1/(1 + (Re/Re_c)⁶)`
//!   stands for the measured transition. A polynomial step (smoothstep over 0.6–1.4 Re_c)
//!   fitted as well but is only once differentiable, and the adaptive integrator then missed
//!   its tolerance by centimetres (docs/aero.md).
//! * **Lift.** Bearman & Harvey's lift is already ≈ 0.13 at their smallest spin parameter
//!   (S ≈ 0.05) and rises about linearly from there (≈ 0.09 + 0.7·S); Naruo et al. ≈ 0.12
//!   at S = 0.05; Nathan's calculator fits `0.2294·S^0.4`. One quartic cannot rise that
//!   steeply at small S and keep rising after, so the lift has two: the low-spin component,
//!   complete by `S_low`, and the main one. Each is 0 without spin and reaches its amplitude
//!   with its first three derivatives zero (smooth enough for the 5th-order integrator),
//!   with no `powf`. With `c_l,low = 0` the family is issue 10's.
//! * **Spin drag.** Drag rises with spin in every measurement (Bearman & Harvey; Lyu et al.;
//!   Nathan's `+0.2087·S`), but a drag linear in S cannot fit both a low-spin driver and the
//!   irons and wedges (S ≈ 0.2–0.45): the spin drag must saturate where the lift does. Tying
//!   it to the main lift (`k_L·c_l,max·sat(S/S_sat)`, the form of a lift-induced drag) does
//!   that with one coefficient. The low-spin lift adds none: Bearman & Harvey's drag barely
//!   moves at small S while their lift rises, and a fitted factor for it went to 0.
//! * **Spin decay.** Smits & Smith (1994), "A new aerodynamic model of a golf ball in
//!   flight", Science and Golf II: `dω/dt ≈ −0.0004·V[mph]·ω` per second (`−8.95·10⁻⁴ /m ·
//!   V·ω` at standard air), the form of a moment coefficient linear in S.
//!
//! The coefficients of [`ModernAero::tour_2023`] were fitted by `carry fit` jointly to
//! TrackMan's 2023 tour averages and 2010 driver chart (docs/aero.md). Four end on a
//! bound: the supercritical drag at 0.17 (the lowest measured; free, the fit takes an
//! unphysical 0.12), the subcritical drag at 0.46 (inside Bearman & Harvey's 0.45–0.5), the
//! spin decay at 7.9 %/s for a driver (Smits & Smith: ≈ 6 %/s) and `S_low` at 0.1: the
//! flight data start at S ≈ 0.065 and cannot place it (any `S_low` ≤ 0.1 fits them alike);
//! Bearman & Harvey's lift, linear from S ≈ 0.05, says the steep rise is over by then.

use super::linear::coefficient;
use crate::error::{Error, Field, Reason, Result};
use crate::real::{Real, lit, smaller};

/// Coefficients of the modern family (all dimensionless). Validate with
/// [`ModernAero::validate`] (done by [`crate::Scene::prepare`]).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ModernAero<T> {
    /// Drag coefficient without spin above the drag crisis, `c_d,super`, in `0..=2`.
    pub cd_supercritical: T,
    /// Drag coefficient without spin below the drag crisis, `c_d,sub`, in `0..=2`.
    pub cd_subcritical: T,
    /// Reynolds number in the middle of the drag crisis, `Re_c`, in `10³..=10⁷`.
    pub reynolds_critical: T,
    /// Saturation lift coefficient, `c_l,max`, in `0..=2`.
    pub cl_max: T,
    /// Spin parameter at which the lift saturates, `S_sat`, in `(0, 10]`.
    pub cl_saturation_spin: T,
    /// Spin drag per unit lift coefficient, `k_L`, in `0..=2`.
    pub cd_lift: T,
    /// Moment (spin-decay) slope in the spin parameter, `c_m`, in `0..=1`.
    pub cm_spin: T,
    /// Amplitude of the lift's low-spin component, `c_l,low`, in `0..=2` (0: the form of
    /// issue 10, one saturating lift).
    pub cl_low: T,
    /// Spin parameter at which the low-spin component saturates, `S_low`, in `(0, 10]`.
    pub cl_low_saturation_spin: T,
}

/// [`ModernAero::tour_2023`] (the default before issue 35) in `f64`, in the order of
/// [`ModernAero::to_array`]. Produced by `carry fit --family modern --input
/// ../shared/data/trackman_tour_2023.csv --temperature 21.1 --humidity 50 --pressure 101325`
/// (docs/aero.md), rounded to 4 significant digits.
pub const TOUR_2023: [f64; MODERN_COEFFICIENTS] = [
    0.17, 0.46, 5.847e4, 0.2887, 1.006, 0.6227, 0.0119, 0.08714, 0.1,
];

/// [`ModernAero::drives_2026`] in `f64`, in the order of [`ModernAero::to_array`]: the
/// family fitted by `carry fit` to the 3,668 premium-ball indoor single drives of
/// `../shared/data/trackman_amateur_drives.csv` (carry, apex, landing angle, flight time)
/// together with the tour table and the 2010 chart (each table row weighted 20), at the data
/// README's 21.1 °C, 50 % RH, 101 325 Pa, with `S_low` free up to 0.4 (docs/aero.md,
/// issue 35); the drives' apex, landing angle and flight time weighed by their scatter
/// about the model (0.7 m, 1.3°, 0.09 s; carry 1 %) and the launch fit's linearised spin
/// error as a target (1σ 3 %; issue 36, docs/launch_fit.md §4); rounded to 4 significant
/// digits.
pub const DRIVES_2026: [f64; MODERN_COEFFICIENTS] = [
    0.17, 0.3, 4.551e4, 0.2934, 1.5, 0.9271, 0.0119, 0.1377, 0.2971,
];

/// Names of the modern family's coefficients, in the order of [`ModernAero::to_array`]
/// (the keys of an aerodynamic model file).
pub const MODERN_NAMES: [&str; MODERN_COEFFICIENTS] = [
    "cd_supercritical",
    "cd_subcritical",
    "reynolds_critical",
    "cl_max",
    "cl_saturation_spin",
    "cd_lift",
    "cm_spin",
    "cl_low",
    "cl_low_saturation_spin",
];

/// The number of the modern family's coefficients.
pub const MODERN_COEFFICIENTS: usize = 9;

impl<T: Real> ModernAero<T> {
    /// Fitted to TrackMan's 2023 PGA and LPGA tour averages (the default before issue 35).
    #[must_use]
    pub fn tour_2023() -> Self {
        Self::from_array(TOUR_2023.map(lit))
    }

    /// The calibrated default: fitted to TrackMan's single drives with both tables (issue
    /// 35). The low-spin lift completes at S ≈ 0.24, not by 0.1 (the single drives at
    /// 1,500–3,000 rpm place it).
    #[must_use]
    pub fn drives_2026() -> Self {
        Self::from_array(DRIVES_2026.map(lit))
    }

    /// The coefficients in order `[cd_supercritical, cd_subcritical, reynolds_critical,
    /// cl_max, cl_saturation_spin, cd_lift, cm_spin]`.
    #[must_use]
    pub fn to_array(&self) -> [T; MODERN_COEFFICIENTS] {
        [
            self.cd_supercritical,
            self.cd_subcritical,
            self.reynolds_critical,
            self.cl_max,
            self.cl_saturation_spin,
            self.cd_lift,
            self.cm_spin,
            self.cl_low,
            self.cl_low_saturation_spin,
        ]
    }

    /// The inverse of [`ModernAero::to_array`].
    #[must_use]
    pub fn from_array(c: [T; MODERN_COEFFICIENTS]) -> Self {
        Self {
            cd_supercritical: c[0],
            cd_subcritical: c[1],
            reynolds_critical: c[2],
            cl_max: c[3],
            cl_saturation_spin: c[4],
            cd_lift: c[5],
            cm_spin: c[6],
            cl_low: c[7],
            cl_low_saturation_spin: c[8],
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
        coefficient(self.cd_lift, two, Field::DragCoefficient)?;
        let re = coefficient(self.reynolds_critical, lit(1.0e7), Field::ReynoldsNumber)?;
        if re < lit(1.0e3) {
            return Err(Error::invalid(Field::ReynoldsNumber, Reason::OutOfRange));
        }
        coefficient(self.cl_max, two, Field::LiftCoefficient)?;
        let saturation = coefficient(self.cl_saturation_spin, lit(10.0), Field::LiftCoefficient)?;
        coefficient(self.cl_low, two, Field::LiftCoefficient)?;
        let low = coefficient(
            self.cl_low_saturation_spin,
            lit(10.0),
            Field::LiftCoefficient,
        )?;
        if saturation <= T::zero() || low <= T::zero() {
            return Err(Error::invalid(Field::LiftCoefficient, Reason::NotPositive));
        }
        coefficient(self.cm_spin, T::one(), Field::SpinDecayCoefficient)?;
        Ok(*self)
    }

    /// The drag-crisis weight `1/(1 + (Re/Re_c)⁶)` at `ratio = Re/Re_c`: 1 far below the
    /// crisis, ½ at `Re_c`, 0 far above.
    #[must_use]
    pub fn crisis(ratio: T) -> T {
        let w = ratio * ratio;
        T::one() / (T::one() + w * w * w)
    }

    /// The lift's saturation `1 − (1 − u)⁴` at `u = min(x, 1)`, with `x = S/S_sat ≥ 0`:
    /// `C_L = c_l,max · saturation(S/S_sat)`.
    #[must_use]
    pub fn saturation(x: T) -> T {
        let w = T::one() - smaller(x, T::one());
        let w2 = w * w;
        T::one() - w2 * w2
    }

    /// The lift's two components `(c_l,max·sat(S/S_sat), c_l,low·sat(S/S_low))`.
    #[must_use]
    pub fn lift_components(&self, spin_parameter: T) -> (T, T) {
        (
            self.cl_max * Self::saturation(spin_parameter / self.cl_saturation_spin),
            self.cl_low * Self::saturation(spin_parameter / self.cl_low_saturation_spin),
        )
    }

    /// `C_L(S) = c_l,max·sat(S/S_sat) + c_l,low·sat(S/S_low)`, `sat(x) = 1 − (1 − min(x, 1))⁴`.
    #[must_use]
    pub fn lift_coefficient(&self, spin_parameter: T) -> T {
        let (main, low) = self.lift_components(spin_parameter);
        main + low
    }

    /// `C_D(S, Re) = c_d,super + (c_d,sub − c_d,super)·crisis + k_L·c_l,max·sat(S/S_sat)`
    /// (the low-spin lift adds no drag).
    #[must_use]
    pub fn drag_coefficient(&self, spin_parameter: T, reynolds: T) -> T {
        let (main, _) = self.lift_components(spin_parameter);
        self.cd_supercritical
            + (self.cd_subcritical - self.cd_supercritical)
                * Self::crisis(reynolds / self.reynolds_critical)
            + self.cd_lift * main
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
        let [sup, sub, rec, clm, sat, kl, cm, cll, satl] = TOUR_2023;
        for (s, re) in [
            (0.0, 2.0e5),
            (0.05, 2.2e5),
            (0.1, 1.5e5),
            (0.3, 6.0e4),
            (0.6, 4.0e4),
            (1.2, 4.0e4),
            (0.2, 7.0e4),
        ] {
            let step = 1.0 / (1.0 + (re / rec).powi(6));
            let main = clm * (1.0 - (1.0 - (s / sat).min(1.0)).powi(4));
            let cl = main + cll * (1.0 - (1.0 - (s / satl).min(1.0)).powi(4));
            let cd = sup + (sub - sup) * step + kl * main;
            assert!((m.lift_coefficient(s) - cl).abs() < 1e-15);
            assert!((m.drag_coefficient(s, re) - cd).abs() < 1e-15);
            assert!((m.moment_coefficient(s) - cm * s).abs() < 1e-18);
        }
        // The crisis step: half way at Re_c, the plateaus either side.
        let at = |re: f64| m.drag_coefficient(0.0, re);
        assert!((at(rec) - 0.5 * (sup + sub)).abs() < 1e-12);
        assert!((at(0.3 * rec) - sub).abs() < 1e-3 && (at(3.0 * rec) - sup).abs() < 1e-3);
        assert!((ModernAero::<f64>::crisis(1.0) - 0.5).abs() < 1e-15);
        // The lift: slope 4·(c_l,max/S_sat + c_l,low/S_low) at 0, c_l,max + c_l,low from
        // the larger saturation on, rising in between.
        assert_eq!(m.lift_coefficient(0.0), 0.0);
        let slope = 4.0 * (clm / sat + cll / satl);
        assert!((m.lift_coefficient(1e-7) / 1e-7 - slope).abs() < 1e-4 * slope);
        let top = sat.max(satl);
        assert_eq!(m.lift_coefficient(top), m.lift_coefficient(top + 0.5));
        assert!((m.lift_coefficient(top) - (clm + cll)).abs() < 1e-15);
        assert!(m.lift_coefficient(0.2) < m.lift_coefficient(0.3));
        assert!(m.lift_coefficient(0.03) < m.lift_coefficient(0.05));
    }

    #[test]
    fn rejects_absurd_coefficients() {
        let m = ModernAero::<f32>::tour_2023();
        assert_eq!(m.validate(), Ok(m));
        let cases = [
            (
                ModernAero {
                    cl_saturation_spin: 0.0,
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
                    cl_low_saturation_spin: 0.0,
                    ..m
                },
                Field::LiftCoefficient,
            ),
            (ModernAero { cl_low: -0.1, ..m }, Field::LiftCoefficient),
            (
                ModernAero {
                    cd_lift: f32::NAN,
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
