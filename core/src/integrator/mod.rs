//! The numerical integration of a flight's equations of motion: the [`Integrator`]
//! settings (explicit Euler, classical RK4, adaptive Dormand–Prince 5(4)), the steppers
//! (`integrate`) and the events located inside a step (`events`: the landing, a hop's
//! return to its plane, the apex, the recorded samples). Used by the flight and by the
//! ground's hops; knows the right-hand side only through [`crate::aero`]'s `Rhs`.

pub(crate) mod events;
pub(crate) mod integrate;

use crate::aero::{ForceField, Rhs, State, Y};
use crate::error::{Error, Field, Reason, Result};
use crate::real::{Real, lit};
use crate::trajectory::Stats;
use crate::validate::{positive, positive_or_infinite};
use integrate::Adaptive;

/// How the flight is integrated.
///
/// [`Integrator::default`] is the documented default fidelity for the precision `T`
/// (see its docs and docs/flight.md).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Integrator<T> {
    /// Explicit Euler with a fixed step (s): first order, 1 force evaluation per step.
    Euler {
        /// Step size (s), finite and positive.
        step_s: T,
    },
    /// Classical 4th-order Runge–Kutta with a fixed step (s): 4 evaluations per step.
    Rk4 {
        /// Step size (s), finite and positive.
        step_s: T,
    },
    /// Adaptive embedded Dormand–Prince 5(4) (FSAL: 6 evaluations per step) with the
    /// mixed error test `|eᵢ| ≤ atol + rtol·max(|y₀ᵢ|, |y₁ᵢ|)` on position (m), velocity
    /// (m/s) and spin (rad/s).
    DormandPrince {
        /// Relative tolerance, finite and positive.
        rtol: T,
        /// Absolute tolerance, finite and positive.
        atol: T,
        /// First trial step (s), finite and positive.
        initial_step_s: T,
        /// Largest step (s), positive (may be +∞).
        max_step_s: T,
    },
}

/// Default-fidelity tolerance of the adaptive integrator in `f64`.
pub const DEFAULT_TOLERANCE_F64: f64 = 4.0e-5;
/// Default-fidelity tolerance of the adaptive integrator in `f32`.
pub const DEFAULT_TOLERANCE_F32: f64 = 3.0e-4;
/// Step budget of the adaptive integrator (accepted + rejected steps). A golf flight at
/// the tightest tolerance takes a few hundred; the budget only stops absurd inputs (it
/// bounds the run time of every flight, so firmware never hangs): [`Error::StepLimit`].
pub const MAX_ADAPTIVE_STEPS: u32 = 100_000;
/// A flight coming down at less than this (rad, 10°) below the horizontal ends on a
/// Runge–Kutta step redone to the landing, not on the step's interpolant. At a grazing
/// landing the height's error `δy` on the interpolant moves the landing point by
/// `δy / tan θ` (115× at 0.5°) and its velocity with it: at the default `f32` tolerance
/// a topped shot's total (which the bounces take from the landing) moved by up to 4.8 cm
/// against `f64`'s; redone, within 4 mm (docs/ground.md, Cost). One extra step (6 force
/// evaluations) for such flights only; the others pay one comparison a step.
pub const GRAZING_LANDING_RAD: f64 = 10.0 * core::f64::consts::PI / 180.0;
/// `tan²` of [`GRAZING_LANDING_RAD`].
pub(crate) const GRAZING_TAN_SQ: f64 = 0.031_091_204_125_763_38;
/// `tan²` of twice [`GRAZING_LANDING_RAD`]: a landing step whose linear estimate of the
/// landing comes down this steeply is not looked into.
pub(crate) const GRAZING_TAN_SQ_TWICE: f64 = 0.132_474_331_431_794_2;

/// Largest accepted tolerance (`rtol`, and `atol` in m, m/s, rad/s): looser than 1 the
/// error test stops controlling anything.
pub const MAX_TOLERANCE: f64 = 1.0;
/// First trial step (s) of [`Integrator::dormand_prince`] at any tolerance, and of the
/// seed's default fidelity ([`Integrator::seed`]).
pub const DEFAULT_INITIAL_STEP_S: f64 = 0.1;
/// First trial step (s) of the default fidelity in `f64`: `C·tol^(1/5)` with
/// `C = `[`INITIAL_STEP_SCALE_S`] at [`DEFAULT_TOLERANCE_F64`] (0.4621 s), rounded.
pub const DEFAULT_INITIAL_STEP_F64_S: f64 = 0.46;
/// First trial step (s) of the default fidelity in `f32`: `C·tol^(1/5)` at
/// [`DEFAULT_TOLERANCE_F32`] (0.6909 s), rounded.
pub const DEFAULT_INITIAL_STEP_F32_S: f64 = 0.69;
/// The scale `C` (s) of the default first trial step `h₀ = C·tol^(1/5)`.
///
/// A 5th-order step's local error grows as `h⁵`, so the largest first step that meets a
/// tolerance scales as `tol^(1/5)` (Hairer, Nørsett & Wanner, *Solving ODEs I*, §II.4,
/// whose starting-step estimate spends an extra force evaluation to find the constant
/// per problem). For golf flights the constant was found over a grid of 1,512 launches
/// (60–180 mph, 1–40°, 1,500–10,000 rpm, still air and three winds): 3.5 s gives the
/// fewest force evaluations at every tolerance from 3e-4 to 1e-12 within 1 % (docs/flight.md,
/// `cargo run --release -p carry-core --example initial_step`).
pub const INITIAL_STEP_SCALE_S: f64 = 3.5;
/// Cap on the first adaptive step (s) when the ball starts in a wind profile's singular
/// ground layer (see [`crate::wind::Wind::Profile`]).
pub const PROFILE_INITIAL_STEP_S: f64 = 1.0e-5;

impl<T: Real> Integrator<T> {
    /// Dormand–Prince 5(4) with `rtol = atol = tolerance`, the default first step and no
    /// step limit.
    #[must_use]
    pub fn dormand_prince(tolerance: T) -> Self {
        Self::DormandPrince {
            rtol: tolerance,
            atol: tolerance,
            initial_step_s: lit(DEFAULT_INITIAL_STEP_S),
            max_step_s: T::max_value().unwrap_or_else(T::one),
        }
    }

    /// The seed's default fidelity: Dormand–Prince at the precision's default tolerance
    /// with the first trial step [`DEFAULT_INITIAL_STEP_S`] (0.1 s), the default before
    /// issue 21. Its flights are bit for bit the ones before then, except those that land
    /// at under [`GRAZING_LANDING_RAD`] (none of the golden cases), which now end on a
    /// redone step.
    #[must_use]
    pub fn seed() -> Self {
        Self::dormand_prince(lit(default_tolerance::<T>()))
    }

    /// A reference-grade setting: Dormand–Prince at a tolerance of 1e-12 in `f64`
    /// (carry within 1e-8 m of the 8th-order reference), 1e-6 in `f32` (near its
    /// rounding floor; the smallest accepted `rtol` is 4ε).
    #[must_use]
    pub fn tight() -> Self {
        Self::dormand_prince(if is_single::<T>() {
            lit(1e-6)
        } else {
            lit(1e-12)
        })
    }
}

/// True when `T` is single precision (`f32`).
fn is_single<T: Real>() -> bool {
    T::default_epsilon() > lit(1e-10)
}

/// The default tolerance of the precision `T`.
fn default_tolerance<T: Real>() -> f64 {
    if is_single::<T>() {
        DEFAULT_TOLERANCE_F32
    } else {
        DEFAULT_TOLERANCE_F64
    }
}

impl<T: Real> Default for Integrator<T> {
    /// The default fidelity: Dormand–Prince 5(4) at [`DEFAULT_TOLERANCE_F64`] in `f64`
    /// (carry within 1 mm of the reference on the golden set) or
    /// [`DEFAULT_TOLERANCE_F32`] in `f32` (within 1 cm), first trial step
    /// [`DEFAULT_INITIAL_STEP_F64_S`] or [`DEFAULT_INITIAL_STEP_F32_S`]. See docs/flight.md.
    fn default() -> Self {
        let mut fidelity = Self::seed();
        if let Self::DormandPrince { initial_step_s, .. } = &mut fidelity {
            *initial_step_s = lit(if is_single::<T>() {
                DEFAULT_INITIAL_STEP_F32_S
            } else {
                DEFAULT_INITIAL_STEP_F64_S
            });
        }
        fidelity
    }
}

/// Integrates from `y0` with `method` until the tracker reports its event (the landing
/// through `event_height`, or a hop's return to its plane).
#[allow(clippy::too_many_arguments)]
pub(crate) fn integrate_to_event<T: Real, R: Rhs<T>>(
    field: &ForceField<T>,
    rhs: &R,
    y0: State<T>,
    method: Method<T>,
    limit: T,
    event_height: T,
    tracker: &mut events::Tracker<'_, '_, T>,
    stats: &mut Stats,
) -> Result<events::Landing<T>> {
    match method {
        Method::Fixed { step, rk4 } => integrate::fixed(rhs, y0, step, rk4, limit, tracker, stats),
        Method::Adaptive(mut cfg) => {
            if field.profile_singular_at(y0[Y]) {
                // The profile's (y/h_ref)^k has an infinite derivative at the ground, where
                // the embedded error estimate is unreliable: start with a small step and let
                // the controller grow it (×5 per step) once the ball is off the ground.
                cfg.initial_step = cfg.initial_step.min(lit(PROFILE_INITIAL_STEP_S));
            }
            // Likewise at the landing: redo the landing step to end there.
            cfg.refine_landing = field.profile_singular_at(event_height);
            integrate::dormand_prince(rhs, y0, cfg, limit, tracker, stats)
        }
    }
}

/// A validated integrator.
#[derive(Clone, Copy)]
pub(crate) enum Method<T> {
    Fixed { step: T, rk4: bool },
    Adaptive(Adaptive<T>),
}

impl<T: Real> Integrator<T> {
    /// The validated integrator.
    pub(crate) fn method(&self) -> Result<Method<T>> {
        Ok(match *self {
            Self::Euler { step_s } => Method::Fixed {
                step: positive(step_s, Field::Step)?,
                rk4: false,
            },
            Self::Rk4 { step_s } => Method::Fixed {
                step: positive(step_s, Field::Step)?,
                rk4: true,
            },
            Self::DormandPrince {
                rtol,
                atol,
                initial_step_s,
                max_step_s,
            } => {
                let tolerance = |x: T| {
                    let x = positive(x, Field::Tolerance)?;
                    if x > lit(MAX_TOLERANCE) {
                        return Err(Error::invalid(Field::Tolerance, Reason::OutOfRange));
                    }
                    Ok(x)
                };
                let cfg = Adaptive {
                    rtol: tolerance(rtol)?,
                    atol: tolerance(atol)?,
                    initial_step: positive(initial_step_s, Field::Step)?,
                    max_step: positive_or_infinite(max_step_s, Field::Step)?,
                    refine_landing: false,
                };
                // Below a few ulps the error test only passes by accident of cancellation
                // (at ever smaller steps): no step size can meet such a tolerance.
                if cfg.rtol < T::default_epsilon() * lit(4.0) {
                    return Err(Error::StepSizeUnderflow);
                }
                Method::Adaptive(cfg)
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn first_step<T: Real>(i: &Integrator<T>) -> f64 {
        match *i {
            Integrator::DormandPrince { initial_step_s, .. } => crate::real::to_f64(initial_step_s),
            _ => f64::NAN,
        }
    }

    /// The default first steps are the rule `C·tol^(1/5)` at the default tolerances
    /// (rounded to 1 %), and the seed's is the 0.1 s of `dormand_prince`.
    #[test]
    fn default_first_step_follows_the_tolerance_rule() {
        for (step, tol) in [
            (
                first_step(&Integrator::<f64>::default()),
                DEFAULT_TOLERANCE_F64,
            ),
            (
                first_step(&Integrator::<f32>::default()),
                DEFAULT_TOLERANCE_F32,
            ),
        ] {
            let rule = INITIAL_STEP_SCALE_S * tol.powf(0.2);
            assert!((step / rule - 1.0).abs() < 0.01, "{step} vs {rule}");
        }
        assert_eq!(
            first_step(&Integrator::<f64>::seed()),
            DEFAULT_INITIAL_STEP_S
        );
        assert_eq!(
            first_step(&Integrator::<f32>::seed()),
            DEFAULT_INITIAL_STEP_S as f32 as f64
        );
    }

    #[test]
    fn grazing_constant_is_the_angles_tangent_squared() {
        let t = GRAZING_LANDING_RAD.tan();
        assert!((GRAZING_TAN_SQ / (t * t) - 1.0).abs() < 1e-15);
        let t = (2.0 * GRAZING_LANDING_RAD).tan();
        assert!((GRAZING_TAN_SQ_TWICE / (t * t) - 1.0).abs() < 1e-15);
    }

    /// The seed's fidelity differs from the default only in its first step.
    #[test]
    fn seed_is_the_default_with_the_seed_first_step() {
        fn check<T: Real>() {
            let (
                Integrator::DormandPrince {
                    rtol,
                    atol,
                    max_step_s,
                    ..
                },
                Integrator::DormandPrince {
                    rtol: r,
                    atol: a,
                    max_step_s: m,
                    ..
                },
            ) = (Integrator::<T>::seed(), Integrator::<T>::default())
            else {
                panic!("both adaptive")
            };
            assert!(rtol == r && atol == a && max_step_s == m);
        }
        check::<f32>();
        check::<f64>();
    }
}
