//! The scene of a flight: which effects exist, the air, the wind, the landing height, the
//! time limit. A scene is validated once ([`Scene::prepare`]) into a [`PreparedScene`] whose
//! per-unit-mass coefficients (`½ρπR²/m_b` and friends) the flight loop uses directly.
//!
//! An effect the scene does not ask for costs nothing measurable: the loop branches on the
//! prepared flags (constant for a flight, perfectly predicted) and skips its arithmetic —
//! no wind evaluation without wind, no air-speed `sqrt` in a vacuum, no spin-decay term
//! without decay. See docs/flight.md for the measured cost per effect.

pub use crate::aero::Effects;
use crate::aero::{AeroModel, ForceField};
use crate::air::Air;
use crate::ball::Ball;
use crate::error::{Error, Field, Reason, Result};
use crate::ground::{Ground, PreparedGround};
use crate::real::{Real, lit};
use crate::validate::{finite, finite_vector, non_negative, positive};
use crate::wind::Wind;
use nalgebra::Vector3;

pub use crate::units::STANDARD_GRAVITY_MPS2;
/// Largest accepted |landing height| and |launch position component| (m): 100 km.
pub const MAX_HEIGHT_M: f64 = 1.0e5;
/// Largest accepted gravitational acceleration (m/s²): 100 g.
pub const MAX_GRAVITY_MPS2: f64 = 1.0e3;
/// Default flight time limit (s): far beyond any golf shot (an 80° wedge flies ~9 s).
pub const DEFAULT_TIME_LIMIT_S: f64 = 60.0;

/// Everything about a flight that is not the ball or its launch.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Scene<T: Real> {
    /// The aerodynamic effects to simulate.
    pub effects: Effects,
    /// The aerodynamic model (drag, lift and spin-decay laws): the calibrated
    /// [`AeroModel::tour_2023`] by default, [`AeroModel::quintavalla`] for the seed's.
    pub aero: AeroModel<T>,
    /// Air density: fixed, or from the weather.
    pub air: Air<T>,
    /// Wind: none, uniform, or a power-law profile.
    pub wind: Wind<T>,
    /// Height of the landing area (m, G): the flight ends when the ball comes down
    /// through it (positive = uphill target). Finite.
    pub landing_height_m: T,
    /// The flight fails with [`crate::Error::TimeLimit`] if it has not landed by then (s).
    pub time_limit_s: T,
    /// Gravitational acceleration (m/s², acting along −Y), finite and not negative.
    pub gravity_mps2: T,
    /// Where the ball starts (m, G): the tee. Carry and side are measured from here.
    pub launch_position_m: Vector3<T>,
    /// The ground after the landing: `None` ends the shot at the first landing (carry);
    /// a ground bounces and rolls the ball to rest ([`crate::ground`]).
    pub ground: Option<Ground<T>>,
}

impl<T: Real> Default for Scene<T> {
    /// All effects with the calibrated aerodynamic model ([`AeroModel::tour_2023`]), and
    /// PHYSICS.md's other defaults: ρ = 1.225 kg/m³, no wind, landing at 0 m, 60 s
    /// time limit, g = 9.80665 m/s², tee at the origin.
    fn default() -> Self {
        Self {
            effects: Effects::ALL,
            aero: AeroModel::default(),
            air: Air::default(),
            wind: Wind::None,
            landing_height_m: T::zero(),
            time_limit_s: lit(DEFAULT_TIME_LIMIT_S),
            gravity_mps2: lit(STANDARD_GRAVITY_MPS2),
            launch_position_m: Vector3::zeros(),
            ground: None,
        }
    }
}

/// A validated scene for one ball, with the hot loop's coefficients precomputed.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct PreparedScene<T: Real> {
    /// The forces: effects, gravity, the aerodynamic model per unit mass, the wind.
    pub(crate) field: ForceField<T>,
    pub(crate) landing_height: T,
    pub(crate) time_limit: T,
    pub(crate) launch_position: Vector3<T>,
    pub(crate) density: T,
    pub(crate) ground: Option<PreparedGround<T>>,
}

impl<T: Real> Scene<T> {
    /// Validates the scene for `ball` and precomputes the flight coefficients.
    ///
    /// # Errors
    /// [`crate::Error::InvalidInput`] naming the offending field: air density (NaN,
    /// infinite, negative) or weather ([`Field::Temperature`], [`Field::Humidity`],
    /// [`Field::Pressure`], [`Field::Altitude`]), the aerodynamic model's coefficients
    /// ([`AeroModel::validate`]), wind, [`Field::LandingHeight`] not finite,
    /// [`Field::TimeLimit`] not finite and positive, [`Field::Gravity`] not finite or
    /// negative, [`Field::LaunchPosition`] not finite.
    pub fn prepare(&self, ball: &Ball<T>) -> Result<PreparedScene<T>> {
        let density = self.air.density_kgm3()?;
        let wind = self.wind.prepare()?;
        // Finite is not enough: a height or a gravity near the precision's maximum
        // overflows the landing speed to ∞ (found by fuzzing, issue 7). The bounds are far
        // outside any golf scene and far inside f32's range.
        let max_height = lit::<T>(MAX_HEIGHT_M);
        let landing_height = finite(self.landing_height_m, Field::LandingHeight)?;
        if !(landing_height.abs() <= max_height) {
            return Err(Error::invalid(Field::LandingHeight, Reason::OutOfRange));
        }
        let time_limit = positive(self.time_limit_s, Field::TimeLimit)?;
        let gravity = non_negative(self.gravity_mps2, Field::Gravity)?;
        if !(gravity <= lit(MAX_GRAVITY_MPS2)) {
            return Err(Error::invalid(Field::Gravity, Reason::OutOfRange));
        }
        let launch_position = finite_vector(&self.launch_position_m, Field::LaunchPosition)?;
        if !(launch_position.amax() <= max_height) {
            return Err(Error::invalid(Field::LaunchPosition, Reason::OutOfRange));
        }
        let viscosity = self.air.dynamic_viscosity_pas()?;
        let aero = self.aero.prepare(ball, density, viscosity)?;
        let ground = match &self.ground {
            Some(g) => Some(g.prepare(ball.radius_m())?),
            None => None,
        };
        Ok(PreparedScene {
            field: ForceField {
                effects: self.effects,
                gravity,
                aero,
                wind,
            },
            landing_height,
            time_limit,
            launch_position,
            density,
            ground,
        })
    }
}

impl<T: Real> PreparedScene<T> {
    /// The air density the flight uses (kg/m³).
    #[must_use]
    pub fn air_density_kgm3(&self) -> T {
        self.density
    }

    /// The effects simulated.
    #[must_use]
    pub fn effects(&self) -> Effects {
        self.field.effects
    }

    /// The validated ground, if the scene has one.
    #[must_use]
    pub fn ground(&self) -> Option<&PreparedGround<T>> {
        self.ground.as_ref()
    }

    /// The landing height (m).
    #[must_use]
    pub fn landing_height_m(&self) -> T {
        self.landing_height
    }
}

/// The per-effect cost ladder: six scenes, each adding one effect to the one before —
/// gravity only → + drag → + lift → + spin decay → + wind profile ((−5, 0, 2) m/s at the
/// 10 m reference height: into the face and left to right; power law 1/7) → + weather
/// (28 °C, 60 % humidity, 300 m altitude). Used by the
/// criterion benchmark (`benches/flight.rs`) and the evaluation-count table of
/// docs/flight.md, so both measure the same scenes.
#[must_use]
pub fn effect_ladder<T: Real>() -> [(&'static str, Scene<T>); 6] {
    use crate::air::{Pressure, Weather};
    let gravity = Scene {
        effects: Effects::GRAVITY_ONLY,
        ..Scene::default()
    };
    let drag = Scene {
        effects: Effects {
            drag: true,
            ..Effects::GRAVITY_ONLY
        },
        ..gravity
    };
    let lift = Scene {
        effects: Effects {
            drag: true,
            lift: true,
            spin_decay: false,
        },
        ..gravity
    };
    let decay = Scene {
        effects: Effects::ALL,
        ..gravity
    };
    let profile = Scene {
        wind: Wind::profile(Vector3::new(lit(-5.0), T::zero(), lit(2.0))),
        ..decay
    };
    let weather = Scene {
        air: Air::Weather(Weather {
            temperature_c: lit(28.0),
            relative_humidity: lit(0.6),
            pressure: Pressure::Altitude(lit(300.0)),
        }),
        ..profile
    };
    [
        ("1_gravity", gravity),
        ("2_drag", drag),
        ("3_lift", lift),
        ("4_spin_decay", decay),
        ("5_wind_profile", profile),
        ("6_weather", weather),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::{Error, Reason};

    #[test]
    fn rejects_bad_scene() {
        let ball = Ball::<f64>::standard();
        let s = Scene {
            landing_height_m: f64::INFINITY,
            ..Scene::default()
        };
        assert_eq!(
            s.prepare(&ball),
            Err(Error::invalid(Field::LandingHeight, Reason::NotFinite))
        );
        let s = Scene {
            time_limit_s: 0.0,
            ..Scene::default()
        };
        assert_eq!(
            s.prepare(&ball),
            Err(Error::invalid(Field::TimeLimit, Reason::NotPositive))
        );
        let s = Scene {
            air: Air::Density(f64::NAN),
            ..Scene::default()
        };
        assert_eq!(
            s.prepare(&ball),
            Err(Error::invalid(Field::AirDensity, Reason::NotFinite))
        );
    }

    #[test]
    fn coefficients() {
        let ball = Ball::<f64>::standard();
        let scene = Scene {
            aero: AeroModel::quintavalla(),
            ..Scene::default()
        };
        let Ok(p) = scene.prepare(&ball) else {
            panic!()
        };
        let a = 0.5 * 1.225 * core::f64::consts::PI * 0.021336_f64.powi(2) / 0.04593;
        let crate::aero::model::Forces::Linear { drag_v, .. } = p.field.aero.forces else {
            panic!()
        };
        assert!((drag_v - a * 0.171).abs() < 1e-15);
        assert!(!p.field.has_wind());
    }
}
