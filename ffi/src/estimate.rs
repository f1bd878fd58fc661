//! Club data from ball data (issue 23): the core's estimator (`carry_core::estimate`,
//! docs/estimate.md) behind the C ABI.

use crate::club::{CarryBall, CarryClub};
use crate::error::{CARRY_ERR_UNKNOWN_OPTION, Result};
use carry_core::estimate::{
    self, BallData, Check, ClubData, ClubEstimate, Datum, Noise, Prior, Settings, Unknowns,
};
use carry_core::presets::Preset;
use carry_core::real::Real;

/// `CarryEstimateInput::posterior`: the posterior mean and calibrated 1σ (the strike
/// height's profile posterior; the default).
pub const CARRY_POSTERIOR_PROFILE: u32 = 0;
/// `CarryEstimateInput::posterior`: the most probable delivery and the Gauss–Newton 1σ
/// (about half the instructions; the 1σ of attack, spin loft and strike height too narrow).
pub const CARRY_POSTERIOR_LAPLACE: u32 = 1;

/// `CarryEstimateInput::measured` bit: the club speed was measured.
pub const CARRY_MEASURED_CLUB_SPEED: u32 = 1;
/// `CarryEstimateInput::measured` bit: the attack angle was measured.
pub const CARRY_MEASURED_ATTACK_ANGLE: u32 = 2;
/// `CarryEstimateInput::measured` bit: the club path was measured.
pub const CARRY_MEASURED_CLUB_PATH: u32 = 4;
/// `CarryEstimateInput::measured` bit: the face angle was measured.
pub const CARRY_MEASURED_FACE_ANGLE: u32 = 8;
/// `CarryEstimateInput::measured` bit: the dynamic loft was measured.
pub const CARRY_MEASURED_DYNAMIC_LOFT: u32 = 16;

/// `CarryEstimateResult::worst`: the measured ball speed.
pub const CARRY_DATUM_BALL_SPEED: u32 = 0;
/// `CarryEstimateResult::worst`: the measured launch angle.
pub const CARRY_DATUM_LAUNCH_ANGLE: u32 = 1;
/// `CarryEstimateResult::worst`: the measured launch direction.
pub const CARRY_DATUM_LAUNCH_DIRECTION: u32 = 2;
/// `CarryEstimateResult::worst`: the measured spin rate.
pub const CARRY_DATUM_SPIN: u32 = 3;
/// `CarryEstimateResult::worst`: the measured spin axis.
pub const CARRY_DATUM_SPIN_AXIS: u32 = 4;
/// `CarryEstimateResult::worst`: the measured club speed.
pub const CARRY_DATUM_CLUB_SPEED: u32 = 5;
/// `CarryEstimateResult::worst`: the measured attack angle.
pub const CARRY_DATUM_ATTACK_ANGLE: u32 = 6;
/// `CarryEstimateResult::worst`: the measured club path.
pub const CARRY_DATUM_CLUB_PATH: u32 = 7;
/// `CarryEstimateResult::worst`: the measured face angle.
pub const CARRY_DATUM_FACE_ANGLE: u32 = 8;
/// `CarryEstimateResult::worst`: the measured dynamic loft.
pub const CARRY_DATUM_DYNAMIC_LOFT: u32 = 9;
/// `CarryEstimateResult::worst`: the club (its prior): the data need a delivery far from
/// its typical one.
pub const CARRY_DATUM_CLUB: u32 = 10;

/// The `CARRY_DATUM_*` code of a datum.
#[must_use]
pub fn datum_code(d: Datum) -> u32 {
    match d {
        Datum::BallSpeed => CARRY_DATUM_BALL_SPEED,
        Datum::LaunchAngle => CARRY_DATUM_LAUNCH_ANGLE,
        Datum::LaunchDirection => CARRY_DATUM_LAUNCH_DIRECTION,
        Datum::Spin => CARRY_DATUM_SPIN,
        Datum::SpinAxis => CARRY_DATUM_SPIN_AXIS,
        Datum::ClubSpeed => CARRY_DATUM_CLUB_SPEED,
        Datum::AttackAngle => CARRY_DATUM_ATTACK_ANGLE,
        Datum::ClubPath => CARRY_DATUM_CLUB_PATH,
        Datum::FaceAngle => CARRY_DATUM_FACE_ANGLE,
        Datum::DynamicLoft => CARRY_DATUM_DYNAMIC_LOFT,
        Datum::Club => CARRY_DATUM_CLUB,
    }
}

/// The estimator's unknowns (TrackMan's convention; m/s, rad, m): also the shape of the
/// prior's mean and spread and of the club measurements and their noise.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CarryDeliveryData<T> {
    /// Face angle at the contact point (rad, + open).
    pub face_angle_rad: T,
    /// Club path (rad, + in-to-out).
    pub club_path_rad: T,
    /// Dynamic loft at the contact point (rad).
    pub dynamic_loft_rad: T,
    /// Attack angle (rad, + up).
    pub attack_angle_rad: T,
    /// Strike toward the toe from the face centre (m).
    pub impact_toe_m: T,
    /// Strike up the face from the face centre (m).
    pub impact_height_m: T,
    /// Club head speed (m/s).
    pub club_speed_mps: T,
}

/// The five ball numbers a launch monitor measures (m/s, rad, rad/s).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CarryBallData<T> {
    /// Ball speed (m/s).
    pub ball_speed_mps: T,
    /// Launch angle, + up (rad).
    pub launch_angle_rad: T,
    /// Launch direction, + right (rad).
    pub launch_direction_rad: T,
    /// Total spin (rad/s).
    pub spin_radps: T,
    /// Spin axis, + tilted right (rad).
    pub spin_axis_rad: T,
}

/// What an estimate needs. Start from `carry_estimate_input_default_*`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarryEstimateInput<T> {
    /// The club head.
    pub club: CarryClub<T>,
    /// The ball.
    pub ball: CarryBall<T>,
    /// The measured ball data.
    pub measured_ball: CarryBallData<T>,
    /// Which club data were measured: an OR of `CARRY_MEASURED_*` bits.
    pub measured: u32,
    /// The measured club data (only the fields `measured` names are read; strike location
    /// unused).
    pub measured_club: CarryDeliveryData<T>,
    /// 1σ noise of the ball data.
    pub ball_noise: CarryBallData<T>,
    /// 1σ noise of the club data.
    pub club_noise: CarryDeliveryData<T>,
    /// Prior mean of the delivery.
    pub prior_mean: CarryDeliveryData<T>,
    /// Prior spread (1σ) of the delivery.
    pub prior_sd: CarryDeliveryData<T>,
    /// Iteration budget, 1..=100.
    pub max_iterations: u32,
    /// Stop when the Newton step is below this many posterior σ, in (0, 1].
    pub tolerance: T,
    /// The posterior summary: `CARRY_POSTERIOR_PROFILE` (default) or
    /// `CARRY_POSTERIOR_LAPLACE`; anything else is `CARRY_ERR_UNKNOWN_OPTION`.
    pub posterior: u32,
    /// The consistency check's χ² tail probability, in (0, 0.5] (default 0.001).
    pub check_tail_probability: T,
    /// The consistency check's bound on a measured datum's miss, in σ (default 4).
    pub check_max_shift_sd: T,
    /// The posterior σ calibration per unknown (finite, > 0; 1 = none): every reported 1σ
    /// is scaled by it (the driver's default: fitted on the TrackMan drives).
    pub sd_scale: CarryDeliveryData<T>,
}

/// The estimated delivery, or its 1σ (rad, m, m/s).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CarryClubEstimate<T> {
    /// Face angle at the contact point (rad).
    pub face_angle_rad: T,
    /// Club path (rad).
    pub club_path_rad: T,
    /// Face to path (rad).
    pub face_to_path_rad: T,
    /// Dynamic loft at the contact point (rad).
    pub dynamic_loft_rad: T,
    /// Attack angle (rad).
    pub attack_angle_rad: T,
    /// Spin loft, dynamic loft − attack (rad).
    pub spin_loft_rad: T,
    /// Strike toward the toe (m).
    pub impact_toe_m: T,
    /// Strike up the face (m).
    pub impact_height_m: T,
    /// Club speed (m/s).
    pub club_speed_mps: T,
    /// Smash factor.
    pub smash_factor: T,
}

/// The result of an estimate.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CarryEstimateResult<T> {
    /// The most probable delivery.
    pub value: CarryClubEstimate<T>,
    /// Its 1σ.
    pub sd: CarryClubEstimate<T>,
    /// Modelled − measured ball data.
    pub residual: CarryBallData<T>,
    /// Iterations used.
    pub iterations: u32,
    /// 1 when the club speed was estimated, 0 when measured.
    pub club_speed_estimated: u32,
    /// 1 when the data passed the consistency check, 0 when not (then the call returns
    /// `CARRY_ERR_INCONSISTENT`).
    pub consistent: u32,
    /// The cost at the most probable delivery (χ²).
    pub chi2: T,
    /// Its bound (the χ² quantile of the tail probability, as many degrees of freedom as data).
    pub chi2_bound: T,
    /// The datum the most probable delivery misses by the most σ (`CARRY_DATUM_*`).
    pub worst: u32,
    /// By how many of its σ.
    pub worst_sd: T,
}

fn to_core<T: Copy>(d: &CarryDeliveryData<T>) -> Unknowns<T> {
    Unknowns {
        face_angle_rad: d.face_angle_rad,
        club_path_rad: d.club_path_rad,
        dynamic_loft_rad: d.dynamic_loft_rad,
        attack_angle_rad: d.attack_angle_rad,
        impact_toe_m: d.impact_toe_m,
        impact_height_m: d.impact_height_m,
        club_speed_mps: d.club_speed_mps,
    }
}

fn from_core<T: Copy>(d: &Unknowns<T>) -> CarryDeliveryData<T> {
    CarryDeliveryData {
        face_angle_rad: d.face_angle_rad,
        club_path_rad: d.club_path_rad,
        dynamic_loft_rad: d.dynamic_loft_rad,
        attack_angle_rad: d.attack_angle_rad,
        impact_toe_m: d.impact_toe_m,
        impact_height_m: d.impact_height_m,
        club_speed_mps: d.club_speed_mps,
    }
}

fn ball_core<T: Copy>(b: &CarryBallData<T>) -> BallData<T> {
    BallData {
        ball_speed_mps: b.ball_speed_mps,
        launch_angle_rad: b.launch_angle_rad,
        launch_direction_rad: b.launch_direction_rad,
        spin_radps: b.spin_radps,
        spin_axis_rad: b.spin_axis_rad,
    }
}

fn ball_c<T: Copy>(b: &BallData<T>) -> CarryBallData<T> {
    CarryBallData {
        ball_speed_mps: b.ball_speed_mps,
        launch_angle_rad: b.launch_angle_rad,
        launch_direction_rad: b.launch_direction_rad,
        spin_radps: b.spin_radps,
        spin_axis_rad: b.spin_axis_rad,
    }
}

fn estimate_c<T: Copy>(e: &ClubEstimate<T>) -> CarryClubEstimate<T> {
    CarryClubEstimate {
        face_angle_rad: e.face_angle_rad,
        club_path_rad: e.club_path_rad,
        face_to_path_rad: e.face_to_path_rad,
        dynamic_loft_rad: e.dynamic_loft_rad,
        attack_angle_rad: e.attack_angle_rad,
        spin_loft_rad: e.spin_loft_rad,
        impact_toe_m: e.impact_toe_m,
        impact_height_m: e.impact_height_m,
        club_speed_mps: e.club_speed_mps,
        smash_factor: e.smash_factor,
    }
}

impl<T: Real> CarryEstimateInput<T> {
    /// The defaults for `preset`: its club, the standard ball, the preset's noise, prior and
    /// consistency check (`Settings::for_preset`), nothing measured, zero ball data.
    #[must_use]
    pub fn typical(preset: &Preset) -> Self {
        let s = Settings::<T>::for_preset(preset);
        Self {
            club: CarryClub::from_spec(&preset.spec()),
            ball: CarryBall::standard(),
            measured_ball: CarryBallData::default_zero(),
            measured: 0,
            measured_club: CarryDeliveryData::default_zero(),
            ball_noise: ball_c(&s.noise.ball),
            club_noise: from_core(&s.noise.club),
            prior_mean: from_core(&s.prior.mean),
            prior_sd: from_core(&s.prior.sd),
            max_iterations: u32::from(s.max_iterations),
            tolerance: s.tolerance,
            posterior: CARRY_POSTERIOR_PROFILE,
            check_tail_probability: s.check.tail_probability,
            check_max_shift_sd: s.check.max_shift_sd,
            sd_scale: from_core(&s.sd_scale),
        }
    }
}

impl<T: Real> CarryBallData<T> {
    fn default_zero() -> Self {
        ball_c(&BallData::from_array([T::zero(); 5]))
    }
}

impl<T: Real> CarryDeliveryData<T> {
    fn default_zero() -> Self {
        from_core(&Unknowns::from_array([T::zero(); 7]))
    }
}

/// The estimate of `input` (also when its data are inconsistent: `consistent` says so,
/// and [`crate::api`] returns `CARRY_ERR_INCONSISTENT` with the result written).
///
/// # Errors
/// The core's errors (`CARRY_ERR_INVALID_INPUT` for a bad measurement, noise, prior,
/// budget, tolerance or check; `CARRY_ERR_NO_CONVERGENCE`, `CARRY_ERR_ILL_POSED`);
/// `CARRY_ERR_UNKNOWN_OPTION` for an unknown `posterior`.
pub fn run<T: Real>(input: &CarryEstimateInput<T>) -> Result<CarryEstimateResult<T>> {
    let club = input.club.spec()?.validate()?;
    let ball = input.ball.ball()?;
    let m = &input.measured_club;
    let has = |bit: u32| input.measured & bit != 0;
    let pick = |bit: u32, v: T| if has(bit) { Some(v) } else { None };
    let data = ClubData {
        club_speed_mps: pick(CARRY_MEASURED_CLUB_SPEED, m.club_speed_mps),
        attack_angle_rad: pick(CARRY_MEASURED_ATTACK_ANGLE, m.attack_angle_rad),
        club_path_rad: pick(CARRY_MEASURED_CLUB_PATH, m.club_path_rad),
        face_angle_rad: pick(CARRY_MEASURED_FACE_ANGLE, m.face_angle_rad),
        dynamic_loft_rad: pick(CARRY_MEASURED_DYNAMIC_LOFT, m.dynamic_loft_rad),
    };
    let settings = Settings {
        noise: Noise {
            ball: ball_core(&input.ball_noise),
            club: to_core(&input.club_noise),
        },
        prior: Prior {
            mean: to_core(&input.prior_mean),
            sd: to_core(&input.prior_sd),
        },
        // out of 1..=100 (also past u8): the core's Iterations error
        max_iterations: u8::try_from(input.max_iterations).unwrap_or(0),
        tolerance: input.tolerance,
        posterior: match input.posterior {
            CARRY_POSTERIOR_PROFILE => estimate::Posterior::Profile,
            CARRY_POSTERIOR_LAPLACE => estimate::Posterior::Laplace,
            _ => return Err(CARRY_ERR_UNKNOWN_OPTION),
        },
        check: Check {
            tail_probability: input.check_tail_probability,
            max_shift_sd: input.check_max_shift_sd,
        },
        sd_scale: to_core(&input.sd_scale),
    };
    let e = estimate::estimate(
        &club,
        &ball,
        &ball_core(&input.measured_ball),
        &data,
        &settings,
    )?;
    Ok(CarryEstimateResult {
        value: estimate_c(&e.value),
        sd: estimate_c(&e.sd),
        residual: ball_c(&e.residual),
        iterations: u32::from(e.iterations),
        club_speed_estimated: u32::from(e.club_speed_estimated),
        consistent: u32::from(e.consistency.consistent),
        chi2: e.consistency.chi2,
        chi2_bound: e.consistency.bound,
        worst: datum_code(e.consistency.worst),
        worst_sd: e.consistency.worst_sd,
    })
}
