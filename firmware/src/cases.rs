//! The golden cases as plain data, and the one function per model that turns a case into
//! the core's inputs and its result into a flat array of numbers.
//!
//! This file is compiled twice: into the firmware (for the target) and into `build.rs`
//! (for the host, `#[path]`-included), which runs the same code on the build machine to
//! produce the host results the on-target tests must reproduce bit for bit. It uses only
//! `core`, `carry-core` and `nalgebra`.
#![allow(dead_code)]

use carry_core::aero::AeroModel;
use carry_core::air::{Air, Pressure, Weather};
use carry_core::flight::{self, Integrator};
use carry_core::impact::{self, ContactLaw, Solver};
use carry_core::presets::FITTED_CONTACT;
use carry_core::real::{Real, lit};
use carry_core::scene::{Effects, Scene};
use carry_core::units::{deg, rpm};
use carry_core::wind::Wind;
use carry_core::{Ball, ClubSpec, Delivery, Error, FaceLocation, Launch};
use nalgebra::{Matrix3, Vector3};

/// Club, ball and delivery of an impact case, in launch-monitor terms (deg, SI otherwise).
#[derive(Debug, Clone, Copy)]
pub struct ImpactInput {
    pub club_mass_kg: f64,
    pub inertia_kgm2: [[f64; 3]; 3],
    pub loft_deg: f64,
    pub roll_radius_m: f64,
    pub bulge_radius_m: f64,
    /// `None`: the face's depth radius is not given (the core's default).
    pub face_depth_radius_m: Option<f64>,
    pub cg_to_face_m: [f64; 3],
    pub ball_mass_kg: f64,
    pub ball_radius_m: f64,
    pub club_speed_mps: f64,
    pub attack_angle_deg: f64,
    pub club_path_deg: f64,
    pub face_angle_deg: f64,
    pub dynamic_loft_deg: f64,
    pub lie_deg: f64,
    pub club_spin_radps: [f64; 3],
    pub impact_height_m: f64,
    pub impact_toe_m: f64,
    pub cor: f64,
}

/// Launch and scene of a flight case (deg, rpm, SI otherwise).
#[derive(Debug, Clone, Copy)]
pub struct FlightInput {
    pub ball_speed_mps: f64,
    pub launch_angle_deg: f64,
    pub launch_direction_deg: f64,
    pub backspin_rpm: f64,
    pub sidespin_rpm: f64,
    pub landing_height_m: f64,
    pub drag: bool,
    pub lift: bool,
    pub spin_decay: bool,
    /// Fixed air density, when the case gives no weather.
    pub air_density_kgm3: Option<f64>,
    /// Temperature (°C), relative humidity (0–1), pressure: `Some(Pa)` or from altitude.
    pub weather: Option<(f64, f64, Option<f64>, Option<f64>)>,
    pub wind_mps: [f64; 3],
    /// Power-law profile: reference height (m), exponent.
    pub wind_profile: Option<(f64, f64)>,
}

/// Impact outputs, in this order: ball velocity (3), ball spin (3), club velocity (3),
/// club spin (3), impulse (3), ball speed, launch angle, launch direction, spin,
/// backspin, sidespin, spin axis, smash factor.
pub const IMPACT_OUTPUTS: usize = 23;
/// Names of the impact outputs (for messages).
pub const IMPACT_NAMES: [&str; IMPACT_OUTPUTS] = [
    "ball_vx",
    "ball_vy",
    "ball_vz",
    "ball_wx",
    "ball_wy",
    "ball_wz",
    "club_vx",
    "club_vy",
    "club_vz",
    "club_wx",
    "club_wy",
    "club_wz",
    "impulse_x",
    "impulse_y",
    "impulse_z",
    "ball_speed",
    "launch_angle",
    "launch_direction",
    "spin",
    "backspin",
    "sidespin",
    "spin_axis",
    "smash",
];

/// Flight outputs, in this order: carry, carry X, side, flight time, apex, apex time,
/// landing angle, landing speed, landing spin, air density, then force evaluations,
/// accepted and rejected steps (as numbers).
pub const FLIGHT_OUTPUTS: usize = 13;
/// Names of the flight outputs (for messages).
pub const FLIGHT_NAMES: [&str; FLIGHT_OUTPUTS] = [
    "carry",
    "carry_x",
    "side",
    "flight_time",
    "apex",
    "apex_time",
    "landing_angle",
    "landing_speed",
    "landing_spin",
    "air_density",
    "evaluations",
    "steps",
    "rejected",
];

/// A stable number for each core error (the tests compare error outcomes by it).
#[must_use]
pub fn error_code(e: &Error) -> u8 {
    match e {
        Error::InvalidInput { .. } => 1,
        Error::OffFace => 2,
        Error::NoApproach => 3,
        Error::Singular => 4,
        Error::NoLanding => 5,
        Error::TimeLimit => 6,
        Error::StepSizeUnderflow => 7,
        Error::Unstable => 8,
        Error::NoConvergence => 9,
        Error::IllPosed => 10,
        Error::TooFewObservations => 11,
        Error::Unidentifiable(_) => 12,
        _ => 255,
    }
}

/// The golden file's name of an error code.
#[must_use]
pub fn error_name(code: u8) -> &'static str {
    match code {
        1 => "invalid_input",
        2 => "off_face",
        3 => "no_approach",
        4 => "singular",
        5 => "no_landing",
        6 => "time_limit",
        7 => "step_size_underflow",
        8 => "unstable",
        9 => "no_convergence",
        10 => "ill_posed",
        11 => "too_few_observations",
        12 => "unidentifiable",
        _ => "other",
    }
}

fn v3<T: Real>(v: [f64; 3]) -> Vector3<T> {
    Vector3::new(lit(v[0]), lit(v[1]), lit(v[2]))
}

impl ImpactInput {
    /// The club parameters in precision `T` (restitution from the delivery's COR).
    #[must_use]
    pub fn club<T: Real>(&self) -> ClubSpec<T> {
        let i = &self.inertia_kgm2;
        ClubSpec {
            mass_kg: lit(self.club_mass_kg),
            inertia_kgm2: Matrix3::from_fn(|r, k| lit(i[r][k])),
            loft_rad: deg(lit(self.loft_deg)),
            roll_radius_m: lit(self.roll_radius_m),
            bulge_radius_m: lit(self.bulge_radius_m),
            face_depth_radius_m: self.face_depth_radius_m.map(lit),
            cg_to_face_m: v3(self.cg_to_face_m),
            restitution: lit(self.cor),
            contact: ContactLaw::Rolling,
            spin_axis_share: T::one(),
        }
    }

    /// The delivery in precision `T`.
    #[must_use]
    pub fn delivery<T: Real>(&self) -> Delivery<T> {
        Delivery {
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

    /// Validates, builds the strike and solves the impact: what a launch monitor does
    /// with one measured delivery.
    ///
    /// # Errors
    /// The core's error for an invalid or impossible case.
    pub fn solve<T: Real>(&self, solver: Solver) -> Result<impact::ImpactOutcome<T>, Error> {
        self.solve_with(solver, false, 1.0)
    }

    /// [`Self::solve`] with the seed's rolling contact, or (`compliant`) the calibrated
    /// compliant contact of the presets, and the club's empirical spin-axis share
    /// (`spin_axis_share`, 1: the physics).
    ///
    /// # Errors
    /// As [`Self::solve`].
    pub fn solve_with<T: Real>(
        &self,
        solver: Solver,
        compliant: bool,
        spin_axis_share: f64,
    ) -> Result<impact::ImpactOutcome<T>, Error> {
        let mut spec = self.club::<T>();
        if compliant {
            spec.contact = FITTED_CONTACT.cast();
        }
        spec.spin_axis_share = lit(spin_axis_share);
        let club = spec.validate()?;
        let ball = Ball::new(lit(self.ball_mass_kg), lit(self.ball_radius_m))?;
        let strike = self.delivery::<T>().strike(&club)?;
        impact::solve(&club, &ball, &strike, solver)
    }

    /// [`Self::solve`], flattened (see [`IMPACT_OUTPUTS`]).
    ///
    /// # Errors
    /// As [`Self::solve`].
    pub fn outputs<T: Real>(&self, solver: Solver) -> Result<[T; IMPACT_OUTPUTS], Error> {
        self.outputs_with(solver, false, 1.0)
    }

    /// [`Self::solve_with`], flattened.
    ///
    /// # Errors
    /// As [`Self::solve`].
    pub fn outputs_with<T: Real>(
        &self,
        solver: Solver,
        compliant: bool,
        spin_axis_share: f64,
    ) -> Result<[T; IMPACT_OUTPUTS], Error> {
        let o = self.solve_with::<T>(solver, compliant, spin_axis_share)?;
        let l = &o.launch;
        let vs = [
            o.ball.velocity_mps,
            o.ball.spin_radps,
            o.club.velocity_mps,
            o.club.spin_radps,
            o.impulse_ns,
        ];
        let mut out = [T::zero(); IMPACT_OUTPUTS];
        for (i, v) in vs.iter().enumerate() {
            out[3 * i] = v.x;
            out[3 * i + 1] = v.y;
            out[3 * i + 2] = v.z;
        }
        let m = [
            l.ball_speed_mps,
            l.launch_angle_rad,
            l.launch_direction_rad,
            l.spin_radps,
            l.backspin_radps,
            l.sidespin_radps,
            l.spin_axis_rad,
            l.smash_factor,
        ];
        out[15..].copy_from_slice(&m);
        Ok(out)
    }
}

impl FlightInput {
    /// The launch in SI, precision `T`.
    #[must_use]
    pub fn launch<T: Real>(&self) -> Launch<T> {
        Launch {
            ball_speed_mps: lit(self.ball_speed_mps),
            launch_angle_rad: deg(lit(self.launch_angle_deg)),
            launch_direction_rad: deg(lit(self.launch_direction_deg)),
            backspin_radps: rpm(lit(self.backspin_rpm)),
            sidespin_radps: rpm(lit(self.sidespin_rpm)),
        }
    }

    /// The scene, precision `T`, with the seed's aerodynamics (the golden files pin them).
    #[must_use]
    pub fn scene<T: Real>(&self) -> Scene<T> {
        self.scene_with(AeroModel::quintavalla())
    }

    /// The scene, precision `T`, with the aerodynamic model `aero`.
    #[must_use]
    pub fn scene_with<T: Real>(&self, aero: AeroModel<T>) -> Scene<T> {
        let air = match (self.weather, self.air_density_kgm3) {
            (Some((t, rh, pa, alt)), _) => Air::Weather(Weather {
                temperature_c: lit(t),
                relative_humidity: lit(rh),
                pressure: match (pa, alt) {
                    (Some(p), _) => Pressure::Pa(lit(p)),
                    (None, Some(h)) => Pressure::Altitude(lit(h)),
                    (None, None) => Pressure::Altitude(T::zero()),
                },
            }),
            (None, Some(rho)) => Air::Density(lit(rho)),
            (None, None) => Air::Density(lit(1.225)),
        };
        let w = v3::<T>(self.wind_mps);
        let wind = match self.wind_profile {
            Some((h, e)) => Wind::Profile {
                reference_mps: w,
                reference_height_m: lit(h),
                exponent: lit(e),
            },
            None if self.wind_mps == [0.0; 3] => Wind::None,
            None => Wind::Uniform(w),
        };
        Scene {
            aero,
            effects: Effects {
                drag: self.drag,
                lift: self.lift,
                spin_decay: self.spin_decay,
            },
            air,
            wind,
            landing_height_m: lit(self.landing_height_m),
            ..Scene::default()
        }
    }

    /// Flies the case with `integrator`.
    ///
    /// # Errors
    /// The core's error.
    pub fn fly<T: Real>(
        &self,
        integrator: &Integrator<T>,
        aero: AeroModel<T>,
    ) -> Result<flight::FlightOutcome<T>, Error> {
        let motion = self.launch::<T>().ball_motion()?;
        flight::fly(
            &Ball::standard(),
            &motion,
            &self.scene_with(aero),
            integrator,
            None,
        )
    }

    /// [`Self::fly`] with the seed's aerodynamics, flattened (see [`FLIGHT_OUTPUTS`]).
    ///
    /// # Errors
    /// As [`Self::fly`].
    pub fn outputs<T: Real>(
        &self,
        integrator: &Integrator<T>,
    ) -> Result<[T; FLIGHT_OUTPUTS], Error> {
        self.outputs_with(integrator, AeroModel::quintavalla())
    }

    /// [`Self::fly`] with the aerodynamic model `aero`, flattened.
    ///
    /// # Errors
    /// As [`Self::fly`].
    pub fn outputs_with<T: Real>(
        &self,
        integrator: &Integrator<T>,
        aero: AeroModel<T>,
    ) -> Result<[T; FLIGHT_OUTPUTS], Error> {
        let o = self.fly(integrator, aero)?;
        let n = |x: u32| -> T { lit(f64::from(x)) };
        Ok([
            o.carry_m,
            o.carry_x_m,
            o.side_m,
            o.flight_time_s,
            o.apex_m,
            o.apex_time_s,
            o.landing_angle_rad,
            o.landing_speed_mps,
            o.landing_spin_radps,
            o.air_density_kgm3,
            n(o.stats.force_evaluations),
            n(o.stats.steps),
            n(o.stats.rejected_steps),
        ])
    }
}

/// The integrators the on-target suite runs every flight case with: the default
/// fidelity, and the fixed-step methods at a 10 ms step (for bit-identity across every
/// code path; their accuracy is not the point here, and a coarse step keeps the
/// soft-float runs short).
#[must_use]
pub fn integrators<T: Real>() -> [(&'static str, Integrator<T>); 3] {
    [
        ("default", Integrator::default()),
        ("rk4_10ms", Integrator::Rk4 { step_s: lit(1e-2) }),
        ("euler_10ms", Integrator::Euler { step_s: lit(1e-2) }),
    ]
}

/// The solvers the on-target suite runs every impact case with.
pub const SOLVERS: [(&str, Solver); 2] = [("reduced", Solver::Reduced), ("full", Solver::FULL)];

/// The impact variants compared bit for bit with the host: both solvers with the seed's
/// rolling contact (what the golden values pin), the reduced solver with the calibrated
/// compliant contact (`compliant = true`), and the same with the empirical spin-axis share
/// of docs/impact.md §0.8 (0.45; the last element, 1 elsewhere: the physics).
pub const VARIANTS: [(&str, Solver, bool, f64); 4] = [
    ("reduced", Solver::Reduced, false, 1.0),
    ("full", Solver::FULL, false, 1.0),
    ("compliant", Solver::Reduced, true, 1.0),
    ("axis share", Solver::Reduced, true, 0.45),
];
