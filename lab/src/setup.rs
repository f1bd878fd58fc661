//! One shot's fixed context — club, ball, prepared scene, numerics — and the base
//! delivery the analyses perturb. Every analysis plays its shots through
//! [`carry_core::shot::play`].

use carry_core::flight::Integrator;
use carry_core::real::{lit, to_f64};
use carry_core::shot::{Fidelity, ShotOutcome, play};
use carry_core::units::to_deg;
use carry_core::{
    Ball, ClubHead, Delivery, DeliveryConvention, PreparedScene, Preset, Real, Scene,
};
use carry_io::report::{GroundReport, LaunchFigures};
use serde::Serialize;

/// Everything a shot needs besides the delivery, plus the base delivery.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Setup<T: Real> {
    /// The validated club head.
    pub club: ClubHead<T>,
    /// The ball.
    pub ball: Ball<T>,
    /// The base delivery (analyses vary some of its fields), read in `convention`.
    pub delivery: Delivery<T>,
    /// Where the deliveries' face angle and dynamic loft are read (TrackMan's contact
    /// point, or the seed's face centre); [`Setup::play`] derives the club's orientation.
    pub convention: DeliveryConvention,
    /// The prepared scene.
    pub scene: PreparedScene<T>,
    /// Impact solver and flight integrator.
    pub fidelity: Fidelity<T>,
}

/// A shot's launch and landing in reporting units (f64; degrees, rpm, metres).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ShotSummary {
    /// Ball speed, angles and spins (flattened: the same keys as the CLI's `launch`).
    #[serde(flatten)]
    pub launch: LaunchFigures,
    /// Smash factor.
    pub smash_factor: f64,
    /// Carry (m).
    pub carry_m: f64,
    /// Side (m, + right).
    pub side_m: f64,
    /// Carry along the target line (m).
    pub carry_x_m: f64,
    /// Apex (m).
    pub apex_m: f64,
    /// Landing angle (deg below the horizontal).
    pub land_angle_deg: f64,
    /// Bounce and roll to rest (total, roll, …), only with a ground in the scene.
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub ground: Option<GroundReport>,
}

impl ShotSummary {
    /// The summary of a core outcome.
    #[must_use]
    pub fn of<T: Real>(out: &ShotOutcome<T>) -> Self {
        let l = &out.impact.launch;
        let f = &out.flight;
        Self {
            launch: LaunchFigures::of(l),
            smash_factor: to_f64(l.smash_factor),
            carry_m: to_f64(f.carry_m),
            side_m: to_f64(f.side_m),
            carry_x_m: to_f64(f.carry_x_m),
            apex_m: to_f64(f.apex_m),
            land_angle_deg: to_f64(to_deg(f.landing_angle_rad)),
            ground: f.ground.as_ref().map(GroundReport::of),
        }
    }
}

/// Flight tolerance of [`Setup::smooth`] in f64: carry then changes smoothly with the
/// delivery (to ~1 µm), which an optimizer needs.
pub const SMOOTH_TOLERANCE_F64: f64 = 1.0e-9;
/// The same in f32 (the tightest it meets on every shot).
pub const SMOOTH_TOLERANCE_F32: f64 = 1.0e-6;

impl<T: Real> Setup<T> {
    /// A square, centred delivery of `preset` at `club_speed_mps` in the default scene
    /// (standard ball, 1.225 kg/m³, no wind) at the default fidelity.
    ///
    /// # Errors
    /// The core's validation of the preset, ball and scene.
    pub fn standard(preset: &Preset, club_speed_mps: f64) -> carry_core::Result<Self> {
        let club = preset.spec::<T>().validate()?;
        let ball = Ball::standard();
        Ok(Self {
            club,
            ball,
            delivery: Delivery::square(lit(club_speed_mps), &club),
            convention: DeliveryConvention::TrackMan,
            scene: Scene::default().prepare(&ball)?,
            fidelity: Fidelity::default(),
        })
    }

    /// This setup with a tight flight tolerance ([`SMOOTH_TOLERANCE_F64`] in f64,
    /// [`SMOOTH_TOLERANCE_F32`] in f32), for optimizers.
    #[must_use]
    pub fn smooth(mut self) -> Self {
        let tol = if core::mem::size_of::<T>() >= 8 {
            SMOOTH_TOLERANCE_F64
        } else {
            SMOOTH_TOLERANCE_F32
        };
        self.fidelity.integrator = Integrator::dormand_prince(lit(tol));
        self
    }

    /// Plays `delivery` (read in the setup's convention) in this setup.
    ///
    /// # Errors
    /// The core's errors for this delivery.
    pub fn play(&self, delivery: &Delivery<T>) -> carry_core::Result<ShotOutcome<T>> {
        play(
            &self.club,
            &self.ball,
            &delivery.in_seed_convention(&self.club, self.convention)?,
            &self.scene,
            &self.fidelity,
            None,
        )
    }

    /// Plays the base delivery.
    ///
    /// # Errors
    /// The core's errors for the base delivery.
    pub fn play_base(&self) -> carry_core::Result<ShotOutcome<T>> {
        self.play(&self.delivery)
    }
}
