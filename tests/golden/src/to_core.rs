//! The golden cases as the core's types, in either precision. The golden files pin the
//! seed's models, so these name them: the rigid club's rolling contact, angles at the face
//! centre (the seed's delivery convention) and Quintavalla's aerodynamics.

use crate::{Ball, Club, Delivery, ImpactCase, Launch, Scene};
use carry_core::aero::AeroModel;
use carry_core::air::{Air, Pressure, Weather};
use carry_core::real::lit;
use carry_core::units::{deg, rpm};
use carry_core::{ClubSpec, ContactLaw, Effects, FaceLocation, Real, Wind};
use nalgebra::{Matrix3, Vector3};

fn v3<T: Real>(v: [f64; 3]) -> Vector3<T> {
    Vector3::new(lit(v[0]), lit(v[1]), lit(v[2]))
}

impl Club {
    /// The club (rolling contact, the seed's) with normal restitution `cor`.
    #[must_use]
    pub fn to_spec<T: Real>(&self, cor: f64) -> ClubSpec<T> {
        ClubSpec {
            mass_kg: lit(self.mass_kg),
            inertia_kgm2: Matrix3::from_fn(|r, k| lit::<T>(self.inertia_kgm2[r][k])),
            loft_rad: deg(lit(self.loft_deg)),
            roll_radius_m: lit(self.roll_radius_m),
            bulge_radius_m: lit(self.bulge_radius_m),
            face_depth_radius_m: self.face_depth_radius_m.map(lit),
            cg_to_face_m: v3(self.cg_to_face_m),
            restitution: lit(cor),
            contact: ContactLaw::Rolling,
            spin_axis_share: T::one(),
        }
    }
}

impl Ball {
    /// The ball, validated.
    ///
    /// # Errors
    /// When the case holds an invalid ball (some error cases do).
    pub fn to_ball<T: Real>(&self) -> carry_core::Result<carry_core::Ball<T>> {
        carry_core::Ball::new(lit(self.mass_kg), lit(self.radius_m))
    }
}

impl Delivery {
    /// The delivery in SI (angles at the face centre, the seed's convention).
    #[must_use]
    pub fn to_delivery<T: Real>(&self) -> carry_core::Delivery<T> {
        carry_core::Delivery {
            club_speed_mps: lit(self.club_speed_mps),
            attack_angle_rad: deg(lit(self.attack_angle_deg)),
            club_path_rad: deg(lit(self.club_path_deg)),
            face_angle_rad: deg(lit(self.face_angle_deg)),
            dynamic_loft_rad: deg(lit(self.dynamic_loft_deg)),
            lie_rad: deg(lit(self.lie_deg)),
            club_spin_radps: v3(self.club_spin_radps),
            location: FaceLocation {
                height_m: lit(self.impact_height_m),
                toe_m: lit(self.impact_toe_m),
            },
        }
    }
}

impl ImpactCase {
    /// The case's club, restitution from its delivery's `cor`.
    #[must_use]
    pub fn club_spec<T: Real>(&self) -> ClubSpec<T> {
        self.club.to_spec(self.delivery.cor)
    }
}

impl Launch {
    /// The launch in SI.
    #[must_use]
    pub fn to_launch<T: Real>(&self) -> carry_core::Launch<T> {
        carry_core::Launch {
            ball_speed_mps: lit(self.ball_speed_mps),
            launch_angle_rad: deg(lit(self.launch_angle_deg)),
            launch_direction_rad: deg(lit(self.launch_direction_deg)),
            backspin_radps: rpm(lit(self.backspin_rpm)),
            sidespin_radps: rpm(lit(self.sidespin_rpm)),
        }
    }
}

impl Scene {
    /// The air: the weather when the case gives one (pressure, else altitude, else sea
    /// level), else the fixed density, else `None`.
    #[must_use]
    pub fn air<T: Real>(&self) -> Option<Air<T>> {
        match (self.air_density_kgm3, self.weather) {
            (_, Some(w)) => Some(Air::Weather(Weather {
                temperature_c: lit(w.temperature_c),
                relative_humidity: lit(w.relative_humidity),
                pressure: match (w.pressure_pa, w.altitude_m) {
                    (Some(p), _) => Pressure::Pa(lit(p)),
                    (None, Some(h)) => Pressure::Altitude(lit(h)),
                    (None, None) => Pressure::Altitude(T::zero()),
                },
            })),
            (Some(rho), None) => Some(Air::Density(lit(rho))),
            (None, None) => None,
        }
    }

    /// The wind: a power-law profile, a uniform wind, or none.
    #[must_use]
    pub fn wind<T: Real>(&self) -> Wind<T> {
        let w = v3::<T>(self.wind_mps);
        match self.wind_profile {
            Some(p) => Wind::Profile {
                reference_mps: w,
                reference_height_m: lit(p.reference_height_m),
                exponent: lit(p.exponent),
            },
            None if w == Vector3::zeros() => Wind::None,
            None => Wind::Uniform(w),
        }
    }

    /// The effects switched on.
    #[must_use]
    pub fn effects(&self) -> Effects {
        Effects {
            drag: self.effects.drag,
            lift: self.effects.lift,
            spin_decay: self.effects.spin_decay,
        }
    }

    /// The core scene with the seed's aerodynamics (the golden files pin it).
    ///
    /// # Panics
    /// When the scene states neither a density nor weather (not so in the committed file).
    #[must_use]
    pub fn to_scene<T: Real>(&self) -> carry_core::Scene<T> {
        carry_core::Scene {
            aero: AeroModel::quintavalla(),
            effects: self.effects(),
            air: self.air().expect("golden scene states its air"),
            wind: self.wind(),
            landing_height_m: lit(self.landing_height_m),
            ..carry_core::Scene::default()
        }
    }
}
