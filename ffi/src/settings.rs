//! Numerical settings: the impact solver and the flight integrator.

use crate::error::{CARRY_ERR_UNKNOWN_OPTION, Result};
use carry_core::flight::{DEFAULT_INITIAL_STEP_S, Integrator};
use carry_core::impact::Solver;
use carry_core::real::{Real, lit};
use carry_core::shot::Fidelity;

/// `CarrySettings::solver`: the exact 3×3 collision-matrix form (default; fast).
pub const CARRY_SOLVER_REDUCED: u32 = 0;
/// `CarrySettings::solver`: the full 15×15 system (seed's rolling contact only).
pub const CARRY_SOLVER_FULL: u32 = 1;

/// `CarrySettings::integrator`: adaptive Dormand–Prince 5(4) (default).
pub const CARRY_INTEGRATOR_DP45: u32 = 0;
/// `CarrySettings::integrator`: classical RK4, fixed step `step_s`.
pub const CARRY_INTEGRATOR_RK4: u32 = 1;
/// `CarrySettings::integrator`: explicit Euler, fixed step `step_s`.
pub const CARRY_INTEGRATOR_EULER: u32 = 2;

/// The CLI's fixed step of euler/rk4 (s).
pub const CARRY_DEFAULT_FIXED_STEP_S: f64 = 1e-3;

/// How the impact is solved and the flight integrated. Start from
/// `carry_settings_default_*` (the CLI's defaults for the precision).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarrySettings<T> {
    /// `CARRY_SOLVER_REDUCED` (default) or `CARRY_SOLVER_FULL`.
    pub solver: u32,
    /// `CARRY_INTEGRATOR_DP45` (default), `CARRY_INTEGRATOR_RK4` or `CARRY_INTEGRATOR_EULER`.
    pub integrator: u32,
    /// Fixed step of RK4 and Euler (s).
    pub step_s: T,
    /// Dormand–Prince relative tolerance.
    pub rtol: T,
    /// Dormand–Prince absolute tolerance (m, m/s, rad/s).
    pub atol: T,
    /// Dormand–Prince first trial step (s).
    pub initial_step_s: T,
    /// Dormand–Prince largest step (s); may be `INFINITY`.
    pub max_step_s: T,
}

impl<T: Real> Default for CarrySettings<T> {
    /// Reduced solver; Dormand–Prince at the precision's default tolerance (carry within
    /// 1 mm in f64, 1 cm in f32) and its first step (0.46 s in f64, 0.69 s in f32), no
    /// step limit; 1 ms fixed step.
    fn default() -> Self {
        let (rtol, atol, initial_step_s, max_step_s) = match Integrator::<T>::default() {
            Integrator::DormandPrince {
                rtol,
                atol,
                initial_step_s,
                max_step_s,
            } => (rtol, atol, initial_step_s, max_step_s),
            _ => (T::one(), T::one(), lit(DEFAULT_INITIAL_STEP_S), T::one()),
        };
        Self {
            solver: CARRY_SOLVER_REDUCED,
            integrator: CARRY_INTEGRATOR_DP45,
            step_s: lit(CARRY_DEFAULT_FIXED_STEP_S),
            rtol,
            atol,
            initial_step_s,
            max_step_s,
        }
    }
}

impl<T: Real> CarrySettings<T> {
    /// The core's solver.
    ///
    /// # Errors
    /// `CARRY_ERR_UNKNOWN_OPTION`.
    pub fn solver(&self) -> Result<Solver> {
        match self.solver {
            CARRY_SOLVER_REDUCED => Ok(Solver::Reduced),
            CARRY_SOLVER_FULL => Ok(Solver::FULL),
            _ => Err(CARRY_ERR_UNKNOWN_OPTION),
        }
    }

    /// The core's integrator (validated by the flight).
    ///
    /// # Errors
    /// `CARRY_ERR_UNKNOWN_OPTION`.
    pub fn integrator(&self) -> Result<Integrator<T>> {
        match self.integrator {
            CARRY_INTEGRATOR_DP45 => Ok(Integrator::DormandPrince {
                rtol: self.rtol,
                atol: self.atol,
                initial_step_s: self.initial_step_s,
                max_step_s: self.max_step_s,
            }),
            CARRY_INTEGRATOR_RK4 => Ok(Integrator::Rk4 {
                step_s: self.step_s,
            }),
            CARRY_INTEGRATOR_EULER => Ok(Integrator::Euler {
                step_s: self.step_s,
            }),
            _ => Err(CARRY_ERR_UNKNOWN_OPTION),
        }
    }

    /// Solver and integrator together.
    ///
    /// # Errors
    /// `CARRY_ERR_UNKNOWN_OPTION`.
    pub fn fidelity(&self) -> Result<Fidelity<T>> {
        Ok(Fidelity {
            solver: self.solver()?,
            integrator: self.integrator()?,
        })
    }
}
