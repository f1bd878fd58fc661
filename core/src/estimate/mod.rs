//! Club data from ball data: the impact model run backwards (issue 23).
//!
//! A launch monitor that sees only the ball measures five numbers `y` (ball speed, launch
//! angle, launch direction, spin rate, spin axis), perhaps with some club data. The club's
//! delivery `x` (face angle, club path, dynamic loft, attack angle, strike toe and height,
//! club speed; TrackMan's convention, [`crate::DeliveryConvention::TrackMan`]) is the
//! maximum a posteriori estimate
//!
//! ```text
//! x̂ = argmin  Σ_k ((f_k(x) − y_k)/σ_k)²  +  Σ_i ((x_i − μ_i)/s_i)²  +  Σ_j ((x_j − c_j)/σ_j)²
//! ```
//!
//! with `f` the forward model (delivery → [`crate::impact::solve`], reduced solver, the
//! club's contact law → launch metrics), `σ_k` the measurement noise ([`Noise`]), `μ, s`
//! the prior ([`Prior`]: the club's typical delivery and a spread) and `c_j, σ_j` the club
//! data the device measured ([`ClubData`]). Six or seven unknowns against five ball numbers:
//! the prior keeps the problem well posed. Levenberg–Marquardt ([`solve`]) with a
//! forward-difference Jacobian, a Cholesky solve of the 7×7 normal matrix, and a bounded
//! number of iterations. The value and 1σ of every datum summarise the posterior
//! ([`Posterior`]): by default its mean and covariance, Gaussian (`(Jᵀ W J + P)⁻¹`) except
//! along the strike height's valley, where the profile posterior is measured on the cost;
//! or the MAP and the Laplace covariance. docs/estimate.md has the sources,
//! identifiability, calibration and the accuracy against cost.

mod model;
mod solve;
pub(crate) mod spd;

pub use model::{Unknowns, predict};

use crate::ball::{Ball, BallMotion};
use crate::club::ClubHead;
use crate::error::{Error, Field, Reason, Result};
use crate::launch::LaunchMetrics;
use crate::presets::TypicalDelivery;
use crate::real::{Real, lit};
use crate::units::{deg, mph, rpm};
use crate::validate::in_range as range;
use core::f64::consts::{FRAC_PI_2, PI};

/// The ball numbers a launch monitor measures (SI: m/s, rad, rad/s). Also the shape of
/// their noise ([`Noise::ball`]) and of the estimate's residuals ([`Estimate::residual`]).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct BallData<T> {
    /// Ball speed (m/s).
    pub ball_speed_mps: T,
    /// Launch angle, + up (rad).
    pub launch_angle_rad: T,
    /// Launch direction, + right (rad).
    pub launch_direction_rad: T,
    /// Total spin rate (rad/s).
    pub spin_radps: T,
    /// Spin axis, + tilted right (rad).
    pub spin_axis_rad: T,
}

impl<T: Real> BallData<T> {
    /// The launch-monitor numbers of a ball leaving with velocity and spin `motion` (the
    /// spin component along the velocity, which a launch monitor does not report, is
    /// dropped with the rest of the spin vector's direction beyond its axis tilt).
    #[must_use]
    pub fn from_motion(motion: &BallMotion<T>) -> Self {
        Self::from_metrics(&LaunchMetrics::from_motion(motion, T::zero()))
    }

    /// The five measured numbers of `m`.
    #[must_use]
    pub fn from_metrics(m: &LaunchMetrics<T>) -> Self {
        Self {
            ball_speed_mps: m.ball_speed_mps,
            launch_angle_rad: m.launch_angle_rad,
            launch_direction_rad: m.launch_direction_rad,
            spin_radps: m.spin_radps,
            spin_axis_rad: m.spin_axis_rad,
        }
    }

    /// As an array in the order of the fields.
    #[must_use]
    pub fn to_array(&self) -> [T; 5] {
        [
            self.ball_speed_mps,
            self.launch_angle_rad,
            self.launch_direction_rad,
            self.spin_radps,
            self.spin_axis_rad,
        ]
    }

    /// From an array in the order of the fields.
    #[must_use]
    pub fn from_array(a: [T; 5]) -> Self {
        let [
            ball_speed_mps,
            launch_angle_rad,
            launch_direction_rad,
            spin_radps,
            spin_axis_rad,
        ] = a;
        Self {
            ball_speed_mps,
            launch_angle_rad,
            launch_direction_rad,
            spin_radps,
            spin_axis_rad,
        }
    }

    /// Checks a measurement: finite, ball speed in (0, 150] m/s, launch angle within ±90°,
    /// launch direction within ±90°, spin in [0, 2,000] rad/s (19,099 rpm), spin axis
    /// within ±180°.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the first bad number.
    pub fn validated(&self) -> Result<Self> {
        let half = lit::<T>(FRAC_PI_2);
        let pi = lit::<T>(PI);
        range(self.ball_speed_mps, T::zero(), lit(150.0), Field::BallSpeed)?;
        if !(self.ball_speed_mps > T::zero()) {
            return Err(Error::invalid(Field::BallSpeed, Reason::NotPositive));
        }
        range(self.launch_angle_rad, -half, half, Field::LaunchAngle)?;
        range(
            self.launch_direction_rad,
            -half,
            half,
            Field::LaunchDirection,
        )?;
        range(self.spin_radps, T::zero(), lit(2000.0), Field::BallSpin)?;
        range(self.spin_axis_rad, -pi, pi, Field::SpinAxis)?;
        Ok(*self)
    }
}

/// What the device measured of the club (each `None` when not measured). SI.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ClubData<T> {
    /// Club head speed (m/s).
    pub club_speed_mps: Option<T>,
    /// Attack angle, + up (rad).
    pub attack_angle_rad: Option<T>,
    /// Club path, + in-to-out (rad).
    pub club_path_rad: Option<T>,
    /// Face angle at the contact point, + open (rad).
    pub face_angle_rad: Option<T>,
    /// Dynamic loft at the contact point (rad).
    pub dynamic_loft_rad: Option<T>,
}

impl<T> Default for ClubData<T> {
    /// Nothing measured.
    fn default() -> Self {
        Self {
            club_speed_mps: None,
            attack_angle_rad: None,
            club_path_rad: None,
            face_angle_rad: None,
            dynamic_loft_rad: None,
        }
    }
}

/// 1σ measurement noise of every number the estimator may be given.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Noise<T> {
    /// Of the ball numbers.
    pub ball: BallData<T>,
    /// Of the club numbers, in the order of [`Unknowns`] (the toe and height entries are
    /// unused: no launch monitor of this kind measures the strike location).
    pub club: Unknowns<T>,
}

impl<T: Real> Noise<T> {
    /// The default noise, read as 1σ: engineering defaults of the order launch-monitor makers
    /// state for their accuracy (docs/estimate.md §2; not a cited figure: set it from the
    /// device's specification): ball speed 0.5 mph, launch angle 0.2°, launch direction 0.3°,
    /// spin 3 % of 2,500 rpm (75 rpm), spin axis 1.5°; club speed 1 mph, attack and path
    /// 1°, face 0.5°, dynamic loft 1°.
    #[must_use]
    pub fn launch_monitor() -> Self {
        Self {
            ball: BallData {
                ball_speed_mps: mph(lit(0.5)),
                launch_angle_rad: deg(lit(0.2)),
                launch_direction_rad: deg(lit(0.3)),
                spin_radps: rpm(lit(75.0)),
                spin_axis_rad: deg(lit(1.5)),
            },
            club: Unknowns {
                face_angle_rad: deg(lit(0.5)),
                club_path_rad: deg(lit(1.0)),
                dynamic_loft_rad: deg(lit(1.0)),
                attack_angle_rad: deg(lit(1.0)),
                impact_toe_m: lit(0.002),
                impact_height_m: lit(0.002),
                club_speed_mps: mph(lit(1.0)),
            },
        }
    }

    /// This noise with the ball data's 1σ multiplied by `factor` (the club data's unchanged):
    /// one factor for the impact model's own error on real shots (the first σ calibration of
    /// issue 34, docs/estimate.md §8.1; the driver now uses [`Noise::with_model_error`]).
    #[must_use]
    pub fn with_ball_scaled(&self, factor: T) -> Self {
        Self {
            ball: BallData::from_array(self.ball.to_array().map(|s| s * factor)),
            club: self.club,
        }
    }

    /// This noise with the impact model's own error `model` (1σ per ball datum) added to the
    /// ball data's in quadrature, `σ = √(σ_meas² + σ_model²)` (the club data's unchanged):
    /// the σ calibration of issue 34 ([`DRIVER_MODEL_ERROR`]; docs/estimate.md §8.3). A
    /// non-finite or negative `model` gives a noise that [`estimate`] rejects
    /// ([`Field::MeasurementNoise`]).
    #[must_use]
    pub fn with_model_error(&self, model: &BallData<T>) -> Self {
        let (s, m) = (self.ball.to_array(), model.to_array());
        Self {
            ball: BallData::from_array(core::array::from_fn(|i| {
                if m[i] >= T::zero() {
                    (s[i] * s[i] + m[i] * m[i]).sqrt()
                } else {
                    lit(f64::NAN)
                }
            })),
            club: self.club,
        }
    }

    fn validated(&self) -> Result<Self> {
        for s in self.ball.to_array().into_iter().chain(self.club.to_array()) {
            if !(s.is_finite() && s > T::zero()) {
                return Err(Error::invalid(Field::MeasurementNoise, Reason::NotPositive));
            }
        }
        Ok(*self)
    }
}

/// The prior on the delivery: independent Gaussians, mean and 1σ per unknown.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Prior<T> {
    /// Means.
    pub mean: Unknowns<T>,
    /// Spreads (1σ), all positive.
    pub sd: Unknowns<T>,
}

/// Default prior spreads (amateur deliveries; docs/estimate.md §2) of face, path, dynamic
/// loft, attack (deg): path 4.6° and attack 3.4° from the issue's trivial-rule errors on
/// amateur TrackMan drives (mean |x − μ| = σ√(2/π)); face 3.5° and loft 3° estimates.
pub const PRIOR_SD_DEG: [f64; 4] = [3.5, 4.6, 3.0, 3.4];
/// Default prior spreads of the strike toe and height (m): estimates.
pub const PRIOR_SD_STRIKE_M: [f64; 2] = [0.012, 0.008];
/// Default prior spread of the club speed, as a fraction of the typical: an estimate.
pub const PRIOR_SD_SPEED_FRACTION: f64 = 0.10;

/// The amateur driver prior's means, fitted on the single TrackMan drives (issue 34; SI, in
/// the order of [`Unknowns`]: face, path, dynamic loft, attack (rad), strike toe and
/// height (m), club speed (m/s)): the medians of TrackMan's club data over the 4,131 drives
/// that carry them with a full launch, and of the strike location over the 996 that carry it.
/// Reproduced, and to be refitted after a change of the impact model, by
/// `cargo run --release -p carry-lab --example estimate_single_shots` (docs/estimate.md §8).
pub const DRIVER_PRIOR_MEAN: [f64; 7] = [
    0.00436332, // face +0.25°
    0.0272271,  // path +1.56° (in-to-out)
    0.266163,   // dynamic loft 15.25°
    -0.0116937, // attack −0.67°
    -0.0081,    // toe −8.1 mm (toward the heel)
    0.0063,     // height +6.3 mm
    42.47,      // club speed (95.0 mph)
];
/// The amateur driver prior's spreads (1σ), fitted with [`DRIVER_PRIOR_MEAN`]: 1.4826 × the
/// median absolute deviation of the same rows (the sd of their normal bulk: the club data
/// have heavy tails, a plain sd of the dynamic loft is 7.3° against 5.5°). SI, the order of
/// [`Unknowns`].
pub const DRIVER_PRIOR_SD: [f64; 7] = [
    0.074002,  // face 4.24°
    0.07662,   // path 4.39°
    0.0954695, // dynamic loft 5.47°
    0.0645772, // attack 3.70°
    0.0163,    // toe 16.3 mm
    0.0102,    // height 10.2 mm
    5.11,      // club speed
];

/// The impact model's own error on real drives, 1σ per ball datum (SI, the order of
/// [`BallData`]: ball speed (m/s), launch angle, launch direction (rad), spin (rad/s), spin
/// axis (rad)), added in quadrature to the launch monitor's noise for the driver
/// ([`Noise::with_model_error`], [`Settings::for_preset`]; issue 34): the robust sd (1.4826 ×
/// MAD) of the forward residual — the ball data the impact model gives at TrackMan's club
/// data and strike location minus TrackMan's ball data — over the single TrackMan drives
/// that carry the strike location. Reproduced by
/// `cargo run --release -p carry-lab --example estimate_single_shots` (docs/estimate.md §8.3).
pub const DRIVER_MODEL_ERROR: [f64; 5] = [
    1.538,   // ball speed 1.54 m/s (3.4 mph, ≈ 2.5 % at 62 m/s)
    0.00913, // launch angle 0.52°
    0.00608, // launch direction 0.35°
    66.33,   // spin 633 rpm (≈ 23 % at 2,700 rpm)
    0.1073,  // spin axis 6.1°
];

/// The driver's posterior σ calibration ([`Settings::sd_scale`]; issue 34), in the order of
/// [`Unknowns`] (face, path, dynamic loft, attack, strike toe, strike height, club speed):
/// with the noise of [`DRIVER_MODEL_ERROR`] and the prior of [`Prior::amateur_driver`], the
/// 68.27th percentile of |estimate − TrackMan| / reported 1σ over the single TrackMan
/// drives (temperature scaling: the factor that makes the reported 1σ cover 68 %; the toe
/// and height from the 948 drives that carry the strike location; the club speed, measured
/// on those drives, is not calibrated: 1). Reproduced by
/// `cargo run --release -p carry-lab --example estimate_single_shots` (docs/estimate.md §8.3).
pub const DRIVER_SD_SCALE: [f64; 7] = [0.51, 1.10, 0.77, 1.47, 1.09, 0.87, 1.0];

/// The default tail probability of the consistency check ([`Check::tail_probability`]): a
/// consistent shot is flagged by the χ² bound once in 1,000.
pub const CHECK_TAIL_PROBABILITY: f64 = 1e-3;
/// The default [`Check::max_shift_sd`]: a measured datum that the most probable delivery
/// misses by more than 4σ (a consistent datum: once in ≈ 16,000) is flagged.
pub const CHECK_MAX_SHIFT_SD: f64 = 4.0;

/// When the data are judged to disagree (with each other, or with the club): the bounds of
/// the consistency check ([`Consistency`]; docs/estimate.md §8).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Check<T> {
    /// The χ² test's tail probability, in (0, 0.5]: the cost at the most probable delivery
    /// is compared with the χ² quantile of this upper tail for as many degrees of freedom
    /// as data (the five ball numbers and the measured club data).
    pub tail_probability: T,
    /// A measured datum (ball or club) that the most probable delivery misses by more than
    /// this many of its σ is flagged, whatever the χ²; positive.
    pub max_shift_sd: T,
}

impl<T: Real> Check<T> {
    /// [`CHECK_TAIL_PROBABILITY`] and [`CHECK_MAX_SHIFT_SD`].
    #[must_use]
    pub fn standard() -> Self {
        Self {
            tail_probability: lit(CHECK_TAIL_PROBABILITY),
            max_shift_sd: lit(CHECK_MAX_SHIFT_SD),
        }
    }

    fn validated(&self) -> Result<Self> {
        let p = self.tail_probability;
        if !(p > T::zero() && p <= lit(0.5)) {
            return Err(Error::invalid(Field::ConsistencyBound, Reason::OutOfRange));
        }
        if !(self.max_shift_sd.is_finite() && self.max_shift_sd > T::zero()) {
            return Err(Error::invalid(Field::ConsistencyBound, Reason::NotPositive));
        }
        Ok(*self)
    }
}

pub use crate::error::Datum;

/// The verdict of the consistency check: do the data agree with each other and with the
/// club? Computed for every estimate at the most probable delivery `x̂` (no forward
/// evaluation), from its cost terms `z` = (modelled − measured)/σ of each ball number,
/// (x̂ − c)/σ of each measured club datum and (x̂ − μ)/s of each prior term:
///
/// ```text
/// χ² = Σ z²   against   χ²_{1−p}(n),  n = 5 + measured club data   (Wilson–Hilferty)
/// ```
///
/// For a linear model with Gaussian noise and prior the minimum cost is exactly χ² with
/// `n` degrees of freedom (the marginal of the data). Inconsistent when `χ² > bound`, or
/// when a measured datum's `|z|` exceeds [`Check::max_shift_sd`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Consistency<T> {
    /// The cost at the most probable delivery, `Σ z²`.
    pub chi2: T,
    /// Its degrees of freedom: the number of data (5 + measured club data).
    pub dof: u8,
    /// The χ² bound: the quantile of [`Check::tail_probability`]'s upper tail.
    pub bound: T,
    /// The term with the largest `|z|` (a measured datum, or [`Datum::Club`]).
    pub worst: Datum,
    /// Its `|z|`: by how many of its σ the most probable delivery misses it.
    pub worst_sd: T,
    /// Whether the data passed: `χ² ≤ bound` and every measured `|z| ≤ max_shift_sd`.
    pub consistent: bool,
}

/// The upper-tail quantile `χ²_{1−p}(n)`: Wilson & Hilferty's cube-root normal
/// approximation (PNAS 17, 1931), `n (1 − 2/9n + z √(2/9n))³`, with the normal quantile
/// `z` of the upper tail `p` from Abramowitz & Stegun 26.2.23 (|error| < 4.5·10⁻⁴). Within
/// 1.5 % of the exact quantile for `n` = 5–10, `p` = 10⁻⁴–0.05 (tested).
#[must_use]
pub fn chi2_quantile<T: Real>(n: u8, p: T) -> T {
    let p = crate::real::smaller(crate::real::larger(p, lit(1e-30)), lit(0.5));
    let t = (-(p.ln() + p.ln())).root();
    let z = t
        - (lit::<T>(2.515_517) + lit::<T>(0.802_853) * t + lit::<T>(0.010_328) * t * t)
            / (T::one()
                + lit::<T>(1.432_788) * t
                + lit::<T>(0.189_269) * t * t
                + lit::<T>(0.001_308) * t * t * t);
    let n = lit::<T>(f64::from(n.max(1)));
    let a = lit::<T>(2.0 / 9.0) / n;
    let c = T::one() - a + z * a.root();
    n * c * c * c
}

impl<T: Real> Prior<T> {
    /// The prior of a club's typical delivery: square and centred across the face, the
    /// typical speed, attack, dynamic loft and strike height, with the default spreads.
    #[must_use]
    pub fn typical(t: &TypicalDelivery) -> Self {
        let [face, path, loft, attack] = PRIOR_SD_DEG;
        let [toe, height] = PRIOR_SD_STRIKE_M;
        Self {
            mean: Unknowns {
                face_angle_rad: T::zero(),
                club_path_rad: T::zero(),
                dynamic_loft_rad: deg(lit(t.dynamic_loft_deg)),
                attack_angle_rad: deg(lit(t.attack_angle_deg)),
                impact_toe_m: T::zero(),
                impact_height_m: lit(t.impact_height_m),
                club_speed_mps: lit(t.club_speed_mps),
            },
            sd: Unknowns {
                face_angle_rad: deg(lit(face)),
                club_path_rad: deg(lit(path)),
                dynamic_loft_rad: deg(lit(loft)),
                attack_angle_rad: deg(lit(attack)),
                impact_toe_m: lit(toe),
                impact_height_m: lit(height),
                club_speed_mps: lit(t.club_speed_mps * PRIOR_SD_SPEED_FRACTION),
            },
        }
    }

    /// The prior of a fitted table ([`DRIVER_PRIOR_MEAN`], [`DRIVER_PRIOR_SD`]): SI, in the
    /// order of [`Unknowns`].
    #[must_use]
    pub fn from_table(mean: &[f64; 7], sd: &[f64; 7]) -> Self {
        Self {
            mean: Unknowns::from_array(mean.map(lit)),
            sd: Unknowns::from_array(sd.map(lit)),
        }
    }

    /// The amateur driver prior fitted on the single TrackMan drives (issue 34;
    /// [`DRIVER_PRIOR_MEAN`], [`DRIVER_PRIOR_SD`]).
    #[must_use]
    pub fn amateur_driver() -> Self {
        Self::from_table(&DRIVER_PRIOR_MEAN, &DRIVER_PRIOR_SD)
    }

    /// This prior with every spread multiplied by `factor` (`factor ≫ 1`: a prior that
    /// does not bind).
    #[must_use]
    pub fn widened(&self, factor: T) -> Self {
        Self {
            mean: self.mean,
            sd: Unknowns::from_array(self.sd.to_array().map(|s| s * factor)),
        }
    }

    fn validated(&self) -> Result<Self> {
        for m in self.mean.to_array() {
            if !m.is_finite() {
                return Err(Error::invalid(Field::PriorMean, Reason::NotFinite));
            }
        }
        for s in self.sd.to_array() {
            if !(s.is_finite() && s > T::zero()) {
                return Err(Error::invalid(Field::PriorSpread, Reason::NotPositive));
            }
        }
        Ok(*self)
    }
}

/// The default iteration budget of [`Settings::max_iterations`].
pub const MAX_ITERATIONS: u8 = 30;

/// The default [`Settings::tolerance`]: stop when the Newton step is below 0.3 posterior σ
/// (docs/estimate.md, "Accuracy against cost": tighter costs iterations, not accuracy).
pub const TOLERANCE: f64 = 0.3;

/// How the posterior is summarised into the reported value and 1σ ([`Settings::posterior`];
/// docs/estimate.md §1 and §4).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Posterior {
    /// The most probable delivery (MAP) and the Laplace 1σ `√(cᵀA⁻¹c)` of the Gauss–Newton
    /// normal matrix: no forward evaluation beyond the solver's, but the 1σ of attack, spin
    /// loft and strike height cover only ≈ 53 % of the errors (their posterior is skewed).
    Laplace,
    /// The posterior mean and 1σ, with the strike height's profile posterior (the cost
    /// minimised with the height held, probed either side of the MAP) in place of the
    /// Laplace approximation along the height's valley: calibrated (68 % ± 5 % for every
    /// datum), ≈ 35 forward evaluations more.
    #[default]
    Profile,
}

/// How to estimate: the noise, the prior, the iteration budget and the posterior summary.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Settings<T> {
    /// Measurement noise.
    pub noise: Noise<T>,
    /// Prior on the delivery.
    pub prior: Prior<T>,
    /// Levenberg–Marquardt iterations (Jacobians) at most, 1..=100.
    pub max_iterations: u8,
    /// Stop when the Newton step's Mahalanobis length `√(δᵀ A δ)` (in posterior σ) is
    /// below this, in (0, 1].
    pub tolerance: T,
    /// How the posterior is summarised.
    pub posterior: Posterior,
    /// When the data are judged inconsistent ([`Estimate::consistency`]).
    pub check: Check<T>,
    /// The posterior σ calibration, per unknown (finite, > 0; 1 = none): the posterior
    /// covariance `C` is reported as `D C D`, `D = diag(sd_scale)`, so every reported 1σ
    /// (also of face to path, spin loft and smash) is scaled consistently. It stands for
    /// what the Gaussian model of the noise and prior gets wrong on real shots (fitted on
    /// them: [`DRIVER_SD_SCALE`]); it moves no estimate and not the consistency check.
    pub sd_scale: Unknowns<T>,
}

impl<T: Real> Settings<T> {
    /// The defaults for a club with typical delivery `t`: [`Noise::launch_monitor`],
    /// [`Prior::typical`], [`MAX_ITERATIONS`], [`TOLERANCE`], [`Posterior::Profile`].
    #[must_use]
    pub fn typical(t: &TypicalDelivery) -> Self {
        Self {
            noise: Noise::launch_monitor(),
            prior: Prior::typical(t),
            max_iterations: MAX_ITERATIONS,
            tolerance: lit(TOLERANCE),
            posterior: Posterior::Profile,
            check: Check::standard(),
            sd_scale: Unknowns::from_array([T::one(); 7]),
        }
    }

    /// The defaults of a preset: for the driver, the prior, the impact model's error and the
    /// posterior σ calibration fitted on the single TrackMan drives ([`Prior::amateur_driver`],
    /// [`DRIVER_MODEL_ERROR`], [`DRIVER_SD_SCALE`]; issue 34);
    /// for every other club, [`Settings::typical`] of its typical delivery.
    #[must_use]
    pub fn for_preset(preset: &crate::Preset) -> Self {
        let typical = Self::typical(&preset.typical);
        if preset.name == "driver" {
            Self {
                noise: typical
                    .noise
                    .with_model_error(&BallData::from_array(DRIVER_MODEL_ERROR.map(lit))),
                prior: Prior::amateur_driver(),
                sd_scale: Unknowns::from_array(DRIVER_SD_SCALE.map(lit)),
                ..typical
            }
        } else {
            typical
        }
    }
}

/// The estimated delivery (values or their 1σ, TrackMan's convention). SI.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ClubEstimate<T> {
    /// Face angle at the contact point, + open (rad).
    pub face_angle_rad: T,
    /// Club path, + in-to-out (rad).
    pub club_path_rad: T,
    /// Face to path, face − path (rad).
    pub face_to_path_rad: T,
    /// Dynamic loft at the contact point (rad).
    pub dynamic_loft_rad: T,
    /// Attack angle, + up (rad).
    pub attack_angle_rad: T,
    /// Spin loft, dynamic loft − attack angle (rad).
    pub spin_loft_rad: T,
    /// Strike location toward the toe from the face centre (m).
    pub impact_toe_m: T,
    /// Strike location up the face from the face centre (m).
    pub impact_height_m: T,
    /// Club head speed (m/s).
    pub club_speed_mps: T,
    /// Smash factor, modelled ball speed / club speed.
    pub smash_factor: T,
}

impl<T: Copy> ClubEstimate<T> {
    /// As an array in the order of the fields.
    #[must_use]
    pub fn to_array(&self) -> [T; 10] {
        [
            self.face_angle_rad,
            self.club_path_rad,
            self.face_to_path_rad,
            self.dynamic_loft_rad,
            self.attack_angle_rad,
            self.spin_loft_rad,
            self.impact_toe_m,
            self.impact_height_m,
            self.club_speed_mps,
            self.smash_factor,
        ]
    }
}

/// The result of [`estimate`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Estimate<T> {
    /// The estimated delivery: the posterior mean ([`Posterior::Profile`]) or the most
    /// probable delivery ([`Posterior::Laplace`]).
    pub value: ClubEstimate<T>,
    /// Its 1σ uncertainties (posterior covariance).
    pub sd: ClubEstimate<T>,
    /// How well the ball data is reproduced by the most probable delivery: modelled −
    /// measured (SI).
    pub residual: BallData<T>,
    /// Levenberg–Marquardt iterations used (Jacobians evaluated).
    pub iterations: u8,
    /// Whether the club speed was estimated (not measured).
    pub club_speed_estimated: bool,
    /// Whether the data agree with each other and with the club, and if not which datum
    /// is the worst ([`Settings::check`]).
    pub consistency: Consistency<T>,
}

impl<T: Real> Estimate<T> {
    /// This estimate, or [`Error::Inconsistent`] naming the worst datum when the
    /// consistency check failed (what the shells report; the estimate itself is the best
    /// compromise between data that disagree).
    ///
    /// # Errors
    /// [`Error::Inconsistent`] when `!self.consistency.consistent`.
    pub fn checked(self) -> Result<Self> {
        if self.consistency.consistent {
            Ok(self)
        } else {
            Err(Error::Inconsistent {
                worst: self.consistency.worst,
            })
        }
    }

    /// The estimated delivery as a core [`crate::Delivery`] in TrackMan's convention (no
    /// lie, no club spin): feed it to [`crate::Delivery::strike_in`] to see its launch.
    #[must_use]
    pub fn delivery(&self) -> crate::Delivery<T> {
        let v = &self.value;
        Unknowns {
            face_angle_rad: v.face_angle_rad,
            club_path_rad: v.club_path_rad,
            dynamic_loft_rad: v.dynamic_loft_rad,
            attack_angle_rad: v.attack_angle_rad,
            impact_toe_m: v.impact_toe_m,
            impact_height_m: v.impact_height_m,
            club_speed_mps: v.club_speed_mps,
        }
        .delivery()
    }
}

/// Estimates the delivery of `club` (its own contact law; the reduced solver) striking
/// `ball` that produced the `measured` ball data, given what was `club_data` measured of
/// the club, with `settings`.
///
/// # Errors
/// [`Error::InvalidInput`] for a non-finite or out-of-range measurement, noise, prior,
/// iteration budget or consistency bound; the forward model's errors at the start (e.g. [`Error::OffFace`] for
/// a prior strike off the face); [`Error::IllPosed`] when the normal matrix is singular in
/// the precision; [`Error::NoConvergence`] when the iteration budget runs out.
pub fn estimate<T: Real>(
    club: &ClubHead<T>,
    ball: &Ball<T>,
    measured: &BallData<T>,
    club_data: &ClubData<T>,
    settings: &Settings<T>,
) -> Result<Estimate<T>> {
    let measured = measured.validated()?;
    let noise = settings.noise.validated()?;
    let prior = settings.prior.validated()?;
    if !(1..=100).contains(&settings.max_iterations) {
        return Err(Error::invalid(Field::Iterations, Reason::OutOfRange));
    }
    let tolerance = settings.tolerance;
    if !(tolerance > T::zero() && tolerance <= T::one()) {
        return Err(Error::invalid(Field::Tolerance, Reason::OutOfRange));
    }
    settings.check.validated()?;
    for f in settings.sd_scale.to_array() {
        if !(f.is_finite() && f > T::zero()) {
            return Err(Error::invalid(Field::PosteriorScale, Reason::NotPositive));
        }
    }
    let half = lit::<T>(FRAC_PI_2);
    if let Some(v) = club_data.club_speed_mps {
        range(v, T::zero(), lit(150.0), Field::ClubSpeed)?;
        if !(v > T::zero()) {
            return Err(Error::invalid(Field::ClubSpeed, Reason::NotPositive));
        }
    }
    for (v, field) in [
        (club_data.attack_angle_rad, Field::AttackAngle),
        (club_data.club_path_rad, Field::ClubPath),
        (club_data.face_angle_rad, Field::FaceAngle),
        (club_data.dynamic_loft_rad, Field::DynamicLoft),
    ] {
        if let Some(v) = v {
            range(v, -half, half, field)?;
        }
    }
    solve::run(
        &model::Model { club, ball },
        &measured,
        club_data,
        &Settings {
            noise,
            prior,
            ..*settings
        },
    )
}
