//! Surfaces: named presets and custom turf, validated once into a [`Turf`].
//!
//! A turf is four numbers (docs/ground.md has the sources and the fits):
//!
//! ```text
//! e₀   restitution at vanishing normal speed: e(v_n) = (e₀/0.510)·e_Penner(v_n)
//! μ    ball–turf Coulomb friction during a bounce and a skid (Penner 2002: 0.40)
//! ρ    rolling resistance at low speed ρ₀: a roll decelerates at (5/7)·ρ₀(1 + c v²)·g,
//!      the grass drag growing with speed (c = GRASS_DRAG_S2PM2; Penner 2002: ρ₀ = 0.131
//!      on a green)
//! κ    crater scale: the turf's crater tilts the impact by κ·θ_c (Penner 2002: κ = 1)
//! v_f  crater fade: below this normal speed the crater fades linearly (a grazing ball
//!      barely dents the turf; `bounce`)
//! c    grass drag: the growth of the rolling resistance with speed, ρ(v) = ρ₀(1 + c v²)
//!      (Penner's putting form: c = GRASS_DRAG_S2PM2)
//! h    grass height: the canopy a rebound must rise clear of to hop; a lower rebound
//!      ends the bouncing and the ball skids and rolls in the grass (Penner's 5 mm stop on
//!      a green; the cut of the turf elsewhere: FAIRWAY_GRASS_HEIGHT_M, ROUGH_GRASS_HEIGHT_M)
//! ```
//!
//! On a green ρ comes from the stimpmeter: the stimpmeter releases the ball at
//! `v₀ = 1.83 m/s` (Holmes 1986; Penner 2002, "The physics of putting") and it rolls the
//! stimp reading S, so `S = ln(1 + c v₀²)/(2·(5/7)ρ₀g·c)`.

use crate::error::{Error, Field, Reason, Result};
use crate::real::{Real, lit};
use crate::validate::{in_range, positive};

/// Speed at which the stimpmeter releases the ball (m/s).
pub const STIMPMETER_SPEED_MPS: f64 = 1.83;
/// One foot (m): stimp readings are quoted in feet.
pub use crate::units::M_PER_FOOT as FOOT_M;

/// Normal speed below which the crater tilt fades out linearly (m/s). Issue 12 took
/// Penner's reference impact's, 18.6 m/s · cos 44.4° = 13.29 m/s; 6 m/s matches
/// TrackMan's roll after shallow landings (a 15° landing at 27 m/s rolls 40 yd; the
/// issue-21 band figures and topped drives; the sweep is in docs/ground.md). Landings
/// steeper than about 15° have a normal speed above it and are unaffected.
pub const CRATER_FADE_NORMAL_SPEED_MPS: f64 = 6.0;
/// Default green speed: stimp 10 ft (a fast club green; tour greens run 11–13).
pub const DEFAULT_STIMP_M: f64 = 10.0 * FOOT_M;
/// Accepted stimp readings (m): 1 ft to 30 ft.
pub use crate::units::STIMP_RANGE_M;
/// Penner's restitution at vanishing normal speed (2002, eq. 5).
pub const PENNER_RESTITUTION_0: f64 = 0.510;
/// Penner's ball–turf friction coefficient (2002).
pub const PENNER_FRICTION: f64 = 0.40;
/// The firm fairway's rolling resistance at low speed ρ₀, calibrated to TrackMan's 2010
/// driver chart (roll = total − carry on "a typical fairway"; `carry_lab::ground_fit`,
/// docs/ground.md; 0.0651 with the default aerodynamics `drives2026`, 0.0617 with
/// `tour2023`, under which it was 0.063): it rolls like a stimp-11 green at putting speeds.
pub const FAIRWAY_ROLLING_RESISTANCE: f64 = 0.065;
/// The launch-monitor fairway (issue 35): the turf with the normal–tangential crater
/// ([`CraterLaw::NormalTangential`]) fitted to TrackMan's roll after its own landings on
/// 3,867 single drives, by landing band and the topped drives (`carry_lab::ground_drives`,
/// docs/ground.md, "Issue 35"): restitution e₀, friction μ, rolling resistance ρ₀, crater
/// scale κ, crater fade v_f (m/s), grass drag c (s²/m²). Three of the six (e₀, μ, ρ₀) sit on the fit's
/// physical bounds (docs/ground.md). Refitted with the fairway's grass height (issue 37:
/// the bouncing ends below 12.7 mm, not Penner's 5 mm), κ 0.841 → 0.829, v_f 13.3 (Penner's
/// reference normal speed, the bound) → 11.2 m/s, c 0.010 → 0.0107 (`cargo run --release
/// -p carry-lab --example ground_single_shots`, the "fitted (all indoor rows)" line).
pub const TRACKMAN_FAIRWAY: [f64; 6] = [0.20, 0.80, 0.30, 0.829, 11.2, 0.0107];
/// The fairway of both TrackMan data sets (issue 35): one turf fitted jointly to
/// TrackMan's roll on 3,867 indoor single drives (by landing band and the topped drives)
/// *and* to TrackMan's 2010 driver chart's totals (its 30 launches flown end to end with
/// `drives2026`), each data set one term in yards (`carry_lab::ground_joint`, weight 1;
/// docs/ground.md, "Issue 35: one turf for the drives and the chart"), same order as
/// [`TRACKMAN_FAIRWAY`]: e₀, μ, ρ₀, κ, v_f (m/s), c (s²/m²), with the normal–tangential
/// crater. The drives' corner (e₀, μ, ρ₀ on the fit's physical bounds, as in
/// [`TRACKMAN_FAIRWAY`]) with a shallower crater (κ 0.84 → 0.62, Penner's 1 scaled: the
/// chart's flat 22–26 yd rolls at 33–46°). Held out (session blocks; chart rows one at a
/// time) it meets every ground target of issue 35 at once. Refit:
/// `cargo run --release -p carry-lab --example ground_joint -- --no-cv` (fit: e₀ 0.200,
/// μ 0.800, ρ₀ 0.3000, κ 0.620, v_f 11.93, c 0.0107 with the fairway's grass height,
/// issue 37; v_f 11.44 with Penner's 5 mm stop before).
pub const JOINT_FAIRWAY: [f64; 6] = [0.20, 0.80, 0.30, 0.620, 11.9, 0.0107];
/// A green's grass height (m): Penner's (2002) 5 mm stop, the height a rebound must rise
/// to hop on the greens his bounce was fitted to (a green is cut at 3–5 mm, 1/8–3/16 inch).
pub const GREEN_GRASS_HEIGHT_M: f64 = 0.005;
/// A fairway's grass height (m): 1/2 inch, the cut "fairways are generally maintained at
/// throughout most of the year" (USGA Course Care, T. Lowe, "Fairway and rough heights
/// vary by the season", 2013: 0.38–0.7 inch by season). Every fairway preset.
pub const FAIRWAY_GRASS_HEIGHT_M: f64 = 0.5 * 0.0254;
/// A rough's grass height (m): 1.5 inches, the cut roughs are "generally maintained at or
/// slightly below" (USGA, Lowe 2013; 1.5–4 inches, Ohio State's turfgrass glossary).
pub const ROUGH_GRASS_HEIGHT_M: f64 = 1.5 * 0.0254;
/// Largest accepted grass height (m): 0.2 m, a hay rough's.
pub const MAX_GRASS_HEIGHT_M: f64 = 0.2;
/// Largest accepted friction coefficient, rolling resistance and crater scale.
pub const MAX_TURF_COEFFICIENT: f64 = 10.0;

/// The ground a ball lands on.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Surface<T: Real> {
    /// A firm, fast fairway (Penner's green bounce; rolling resistance [`FAIRWAY_ROLLING_RESISTANCE`],
    /// calibrated to TrackMan's 2010 driver chart).
    FairwayFirm,
    /// The fairway of a launch monitor (issue 35): the turf fitted to TrackMan's roll on
    /// single drives, all landing angles and the topped drives ([`TRACKMAN_FAIRWAY`]): the
    /// normal–tangential crater ([`CraterLaw::NormalTangential`]), a softer bounce and a
    /// grippier, slower turf than Penner's green.
    FairwayTrackman,
    /// The fairway of both TrackMan data sets (issue 35): one turf fitted jointly to its
    /// roll on single drives (every landing band, the topped drives) and its 2010 driver
    /// chart's totals ([`JOINT_FAIRWAY`]): [`Self::FairwayTrackman`]'s turf with a
    /// shallower crater. The one to pick for "a fairway like the data": held out it is
    /// within every ground target of issue 35 on both (docs/ground.md).
    FairwayJoint,
    /// A soft, watered fairway (stimp-5 roll, 80 % of the restitution, deeper crater).
    FairwaySoft,
    /// Rough: high resistance, little bounce, a deep crater.
    Rough,
    /// A green of the given stimpmeter reading (m; [`DEFAULT_STIMP_M`] is 10 ft), with
    /// Penner's measured green bounce.
    Green {
        /// Stimpmeter reading (m).
        stimp_m: T,
    },
    /// Any turf.
    Custom(Turf<T>),
}

/// The turf coefficients (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Turf<T> {
    /// Restitution at vanishing normal speed e₀, in [0, 1].
    pub restitution: T,
    /// Ball–turf friction coefficient μ during a bounce, ≥ 0.
    pub friction: T,
    /// Rolling resistance at low speed ρ₀ (the roll decelerates at (5/7)ρ₀(1 + c v²)g,
    /// [`GRASS_DRAG_S2PM2`]), ≥ 0.
    pub rolling_resistance: T,
    /// Crater scale κ (multiplies Penner's crater angle), ≥ 0.
    pub crater_scale: T,
    /// Crater fade v_f (m/s): below this normal speed the crater tilt fades linearly,
    /// `θ_c · min(1, v_n/v_f)`; in (0, [`MAX_CRATER_FADE_MPS`]].
    pub crater_fade_mps: T,
    /// Grass drag `c` in `ρ(v) = ρ₀(1 + c v²)` (s²/m²), ≥ 0 ([`GRASS_DRAG_S2PM2`] is
    /// Penner's putting form).
    pub grass_drag_s2pm2: T,
    /// How the crater's tilt depends on the impact angle ([`CraterLaw`]).
    pub crater_law: CraterLaw,
    /// Grass height h (m), in [0, [`MAX_GRASS_HEIGHT_M`]]: a rebound that would not rise
    /// clear of it ends the bouncing (the ball skids and rolls in the grass; docs/ground.md,
    /// *Bounce to roll at the grass canopy*). [`GREEN_GRASS_HEIGHT_M`] on a green (Penner's
    /// stop), [`FAIRWAY_GRASS_HEIGHT_M`] on the fairways, [`ROUGH_GRASS_HEIGHT_M`] in the rough.
    pub grass_height_m: T,
}

/// How the crater's tilt depends on the impact (`bounce`; docs/ground.md, "The crater
/// law"). Both equal Penner's 15.4° at his reference impact (18.6 m/s, 44.4° from the
/// normal) and scale with the crater scale κ and the fade `min(1, v_n/v_f)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum CraterLaw {
    /// Penner (2002), linear in the angle from the normal:
    /// `θ_c = κ·15.4°·(v/18.6 m/s)·(φ/44.4°)`. The seed's surfaces.
    #[default]
    Penner,
    /// The crater as the product of the impact's normal and tangential speeds,
    /// `θ_c = κ·15.4°·(v_n v_t / v)/(18.6 m/s · sin 44.4° cos 44.4°)`
    /// `= κ·15.4°·(v/18.6 m/s)·(sin 2φ / sin 88.8°)`: a crater as deep as the impact's
    /// normal speed presses in, tilted by how far the ball runs across it. Penner's law
    /// at his reference impact, within 13 % of it at 40–50° from the normal; vanishes for a vertical impact (as
    /// Penner's does) and for a grazing one, which barely dents the turf (where Penner's
    /// grows with the speed and ramps a topped ball into long hops). Issue 35.
    NormalTangential,
}

/// Largest accepted crater fade speed (m/s): a landing's normal speed is below 60 m/s.
pub const MAX_CRATER_FADE_MPS: f64 = 100.0;

/// Growth of the rolling resistance with speed, `c` in `ρ(v) = ρ₀(1 + c v²)` (s²/m²):
/// the grass drag. Penner's putting form as quoted in patents citing it,
/// `ρ = (0.7028/S[ft])·(1 + 0.0065 v²)` with `v` in ft/s: `c = 0.0065/0.3048²`.
pub const GRASS_DRAG_S2PM2: f64 = 0.0065 / (FOOT_M * FOOT_M);

/// The stimpmeter's roll `S = ln(1 + c v₀²)/(2·(5/7)ρ₀g·c)` (a roll decelerating at
/// `(5/7)ρ₀g(1 + c v²)`) solved for ρ₀, with standard gravity (the stimpmeter is read on
/// Earth, whatever the scene's gravity).
fn resistance_from_stimp<T: Real>(stimp_m: T) -> T {
    let v0 = STIMPMETER_SPEED_MPS;
    let c = GRASS_DRAG_S2PM2;
    let reach = lit::<T>(c * v0 * v0).ln_1p();
    reach / (lit::<T>(2.0 * 5.0 / 7.0 * crate::units::STANDARD_GRAVITY_MPS2 * c) * stimp_m)
}

impl<T: Real> Surface<T> {
    /// A green at the default stimp (10 ft).
    #[must_use]
    pub fn green() -> Self {
        Self::Green {
            stimp_m: lit(DEFAULT_STIMP_M),
        }
    }

    /// The validated turf.
    ///
    /// # Errors
    /// [`Field::Stimp`] outside 1–30 ft; for a custom turf [`Field::GroundRestitution`]
    /// outside [0, 1], [`Field::GroundFriction`], [`Field::RollingResistance`],
    /// [`Field::CraterScale`] or [`Field::GrassDrag`] negative, not finite or above
    /// [`MAX_TURF_COEFFICIENT`]; [`Field::CraterFade`] not positive or above
    /// [`MAX_CRATER_FADE_MPS`]; [`Field::GrassHeight`] negative, not finite or above
    /// [`MAX_GRASS_HEIGHT_M`].
    pub fn turf(&self) -> Result<Turf<T>> {
        let stimp = |feet: f64| resistance_from_stimp::<T>(lit(feet * FOOT_M));
        let penner = |e_ratio: f64, rho: T, kappa: f64, grass: f64| Turf {
            restitution: lit(PENNER_RESTITUTION_0 * e_ratio),
            friction: lit(PENNER_FRICTION),
            rolling_resistance: rho,
            crater_scale: lit(kappa),
            crater_fade_mps: lit(CRATER_FADE_NORMAL_SPEED_MPS),
            grass_drag_s2pm2: lit(GRASS_DRAG_S2PM2),
            crater_law: CraterLaw::Penner,
            grass_height_m: lit(grass),
        };
        // The issue-35 fits: e₀, μ, ρ₀, κ, v_f, c with the normal–tangential crater.
        let fitted = |[e0, mu, rho, kappa, fade, drag]: [f64; 6]| Turf {
            restitution: lit(e0),
            friction: lit(mu),
            rolling_resistance: lit(rho),
            crater_scale: lit(kappa),
            crater_fade_mps: lit(fade),
            grass_drag_s2pm2: lit(drag),
            crater_law: CraterLaw::NormalTangential,
            grass_height_m: lit(FAIRWAY_GRASS_HEIGHT_M),
        };
        match *self {
            Self::FairwayFirm => Ok(penner(
                1.0,
                lit(FAIRWAY_ROLLING_RESISTANCE),
                1.0,
                FAIRWAY_GRASS_HEIGHT_M,
            )),
            Self::FairwayTrackman => Ok(fitted(TRACKMAN_FAIRWAY)),
            Self::FairwayJoint => Ok(fitted(JOINT_FAIRWAY)),
            Self::FairwaySoft => Ok(penner(0.8, stimp(5.0), 1.2, FAIRWAY_GRASS_HEIGHT_M)),
            Self::Rough => Ok(Turf {
                restitution: lit(0.30),
                friction: lit(0.60),
                rolling_resistance: lit(0.30),
                crater_scale: lit(1.3),
                crater_fade_mps: lit(CRATER_FADE_NORMAL_SPEED_MPS),
                grass_drag_s2pm2: lit(GRASS_DRAG_S2PM2),
                crater_law: CraterLaw::Penner,
                grass_height_m: lit(ROUGH_GRASS_HEIGHT_M),
            }),
            Self::Green { stimp_m } => {
                let s = positive(stimp_m, Field::Stimp)?;
                let s = in_range(s, lit(STIMP_RANGE_M.0), lit(STIMP_RANGE_M.1), Field::Stimp)?;
                Ok(penner(
                    1.0,
                    resistance_from_stimp(s),
                    1.0,
                    GREEN_GRASS_HEIGHT_M,
                ))
            }
            Self::Custom(t) => t.validated(),
        }
    }
}

impl<T: Real> Turf<T> {
    /// Checks every coefficient (see [`Surface::turf`]).
    ///
    /// # Errors
    /// As [`Surface::turf`] for a custom turf.
    pub fn validated(&self) -> Result<Self> {
        let coefficient = |x: T, field: Field| {
            let x = crate::validate::non_negative(x, field)?;
            if x > lit(MAX_TURF_COEFFICIENT) {
                return Err(Error::invalid(field, Reason::OutOfRange));
            }
            Ok(x)
        };
        Ok(Self {
            restitution: in_range(
                self.restitution,
                T::zero(),
                T::one(),
                Field::GroundRestitution,
            )?,
            friction: coefficient(self.friction, Field::GroundFriction)?,
            rolling_resistance: coefficient(self.rolling_resistance, Field::RollingResistance)?,
            crater_scale: coefficient(self.crater_scale, Field::CraterScale)?,
            crater_fade_mps: in_range(
                positive(self.crater_fade_mps, Field::CraterFade)?,
                T::zero(),
                lit(MAX_CRATER_FADE_MPS),
                Field::CraterFade,
            )?,
            grass_drag_s2pm2: coefficient(self.grass_drag_s2pm2, Field::GrassDrag)?,
            crater_law: self.crater_law,
            grass_height_m: in_range(
                crate::validate::non_negative(self.grass_height_m, Field::GrassHeight)?,
                T::zero(),
                lit(MAX_GRASS_HEIGHT_M),
                Field::GrassHeight,
            )?,
        })
    }
}
