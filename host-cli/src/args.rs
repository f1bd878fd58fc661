//! The option groups that several commands share (delivery, club, ball, launch, scene,
//! precision, solver, integrator, output, batch input): their clap structs, the value
//! parsers, and how each group applies itself to [`Params`] in the user's units
//! ([`Key::set`]). The commands (`cli`) and the analyses (`analyses`) both build on these;
//! neither is imported from here.

use carry_core::impact::ContactLaw;
use carry_core::{DeliveryConvention, Preset};
use carry_io::compute::{IntegratorChoice, Numerics, Precision, SolverChoice};
use carry_io::error::InputError;
use carry_io::params::{
    Key, Params, Value, parse_finite, parse_preset, parse_radius, parse_tensor, parse_vec3,
};
use carry_io::units::Units;
use clap::Args;
use std::path::PathBuf;

/// A finite number (every numeric option's value parser).
pub(crate) fn finite(s: &str) -> Result<f64, String> {
    parse_finite(s)
}
fn radius(s: &str) -> Result<f64, String> {
    parse_radius(s)
}
fn vec3(s: &str) -> Result<[f64; 3], String> {
    parse_vec3(s)
}
fn tensor(s: &str) -> Result<[f64; 9], String> {
    parse_tensor(s)
}
fn preset(s: &str) -> Result<&'static Preset, String> {
    parse_preset(s)
}
fn convention(s: &str) -> Result<DeliveryConvention, String> {
    carry_io::params::parse_convention(s)
}
fn contact(s: &str) -> Result<ContactLaw<f64>, String> {
    carry_io::contact::parse(s)
}

/// Club delivery options.
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Delivery")]
pub struct DeliveryArgs {
    /// Club head speed [m/s | mph] (default 45 m/s, or the named club's typical tour speed).
    #[arg(long, value_name = "SPEED", value_parser = finite, allow_hyphen_values = true)]
    pub club_speed: Option<f64>,
    /// Attack angle [deg, + up] (default 0, or the named club's typical).
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub attack_angle: Option<f64>,
    /// Club path [deg, + right: in-to-out] (default 0).
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub club_path: Option<f64>,
    /// Face angle [deg, + open: pointing right] (default 0); at the contact point
    /// (`--convention trackman`, the default) or at the face centre (`seed`).
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub face_angle: Option<f64>,
    /// Dynamic loft [deg] (default: the static loft, or the named club's typical); at the
    /// contact point (`--convention trackman`, the default) or at the face centre (`seed`).
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub dynamic_loft: Option<f64>,
    /// Lie / face tilt [deg, + toe up] (default 0).
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub lie: Option<f64>,
    /// Club angular velocity before impact [rad/s, G] (default 0,0,0).
    #[arg(long, value_name = "X,Y,Z", value_parser = vec3, allow_hyphen_values = true)]
    pub club_spin: Option<[f64; 3]>,
    /// Impact point up the face from its centre [m | in] (default 0, or the named club's
    /// typical: the driver 12 mm above centre (7 mm above its sweet spot), fairway woods and
    /// hybrids 2 mm below, irons and wedges where a ball on turf meets the face).
    #[arg(long, value_name = "LEN", value_parser = finite, allow_hyphen_values = true)]
    pub impact_height: Option<f64>,
    /// Impact point toward the toe from the face centre [m | in] (default 0; − = heel).
    #[arg(long, value_name = "LEN", value_parser = finite, allow_hyphen_values = true)]
    pub impact_toe: Option<f64>,
    /// Coefficient of restitution, 0..1 (default: the club's, 0.83 for the driver).
    #[arg(long, value_name = "E", value_parser = finite, allow_hyphen_values = true)]
    pub cor: Option<f64>,
    /// Where face angle and dynamic loft are read: `trackman` (default: at the contact
    /// point, as a launch monitor reports them; club speed, attack and path at the head's
    /// CG) or `seed` (at the face centre: the club's own orientation, PHYSICS.md's; what
    /// the golden files pin). The same for a centre strike or a flat face.
    #[arg(long, value_name = "trackman|seed", value_parser = convention)]
    pub convention: Option<DeliveryConvention>,
}

/// Club head and ball options.
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Club and ball")]
pub struct ClubArgs {
    /// Club preset: driver, 3wood, hybrid, 4iron … 9iron, pw, gw, sw, lw (lw58); see
    /// `carry clubs`. A named club's typical tour delivery (club speed, attack angle, dynamic
    /// loft, impact height) fills in the ones not given.
    #[arg(long, value_name = "PRESET", value_parser = preset)]
    pub club: Option<&'static Preset>,
    /// Face–ball contact law: `compliant` (default: friction-limited, tangential
    /// restitution, COR falling with speed; calibrated on TrackMan data), `rolling` (the
    /// seed's rigid contact, rolling without slipping; what the golden files pin), or a
    /// FILE.toml with its parameters (friction, tangential_restitution,
    /// tangential_restitution_slope, tangential_restitution_max, restitution_speed_slope_spm;
    /// as `carry fit` writes).
    /// The full solver supports only `rolling`.
    #[arg(long, value_name = "NAME|FILE.toml", value_parser = contact)]
    pub contact: Option<ContactLaw<f64>>,
    /// Empirical D-plane share k of the spin axis, in (0, 1]: the launch's axis tangent
    /// scaled, tan a' = k·tan a (default 1: the impact's own axis). A named empirical law
    /// beside the physics (docs/impact.md §0.8: 0.3–0.5 fitted on an amateur's TrackMan drives).
    #[arg(long, value_name = "K", value_parser = finite, allow_hyphen_values = true)]
    pub spin_axis_share: Option<f64>,
    /// Club head mass [kg].
    #[arg(long, value_name = "KG", value_parser = finite, allow_hyphen_values = true)]
    pub club_mass: Option<f64>,
    /// Club head inertia about its CoM [kg·m²]: Ixx,Iyy,Izz or all 9 components row by row.
    #[arg(long, value_name = "I", value_parser = tensor, allow_hyphen_values = true)]
    pub club_inertia: Option<[f64; 9]>,
    /// Static loft [deg].
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub loft: Option<f64>,
    /// Bulge radius, curvature across the face [m]; `flat` or `inf` for a flat face.
    #[arg(long, value_name = "M", value_parser = radius, allow_hyphen_values = true)]
    pub bulge: Option<f64>,
    /// Roll radius, curvature up the face [m]; `flat` or `inf` for a flat face.
    #[arg(long, value_name = "M", value_parser = radius, allow_hyphen_values = true)]
    pub roll: Option<f64>,
    /// Face ellipsoid depth radius a [m] (default: the bulge radius).
    #[arg(long, value_name = "M", value_parser = radius, allow_hyphen_values = true)]
    pub face_depth_radius: Option<f64>,
    /// Club CoM → face centre, in the face frame [m].
    #[arg(long, value_name = "X,Y,Z", value_parser = vec3, allow_hyphen_values = true)]
    pub cg_to_face: Option<[f64; 3]>,
    /// Ball mass [kg] (default 0.04593).
    #[arg(long, value_name = "KG", value_parser = finite, allow_hyphen_values = true)]
    pub ball_mass: Option<f64>,
    /// Ball radius [m] (default 0.021336).
    #[arg(long, value_name = "M", value_parser = finite, allow_hyphen_values = true)]
    pub ball_radius: Option<f64>,
}

/// Ball options for a flight alone.
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Ball")]
pub struct BallArgs {
    /// Ball mass [kg] (default 0.04593).
    #[arg(long, value_name = "KG", value_parser = finite, allow_hyphen_values = true)]
    pub ball_mass: Option<f64>,
    /// Ball radius [m] (default 0.021336).
    #[arg(long, value_name = "M", value_parser = finite, allow_hyphen_values = true)]
    pub ball_radius: Option<f64>,
}

/// Launch options (flight input).
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Launch")]
pub struct LaunchArgs {
    /// Ball speed [m/s | mph] (default 167 mph = 74.66 m/s, the PGA Tour driver average).
    #[arg(long, value_name = "SPEED", value_parser = finite, allow_hyphen_values = true)]
    pub ball_speed: Option<f64>,
    /// Launch angle [deg, + up] (default 10.9).
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub launch_angle: Option<f64>,
    /// Launch direction [deg, + right] (default 0).
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub launch_direction: Option<f64>,
    /// Backspin [rpm] (default 2686).
    #[arg(long, value_name = "RPM", value_parser = finite, allow_hyphen_values = true, conflicts_with_all = ["spin", "spin_axis"])]
    pub backspin: Option<f64>,
    /// Sidespin [rpm, + curves right: fade/slice] (default 0).
    #[arg(long, value_name = "RPM", value_parser = finite, allow_hyphen_values = true, conflicts_with_all = ["spin", "spin_axis"])]
    pub sidespin: Option<f64>,
    /// Total spin [rpm], with --spin-axis instead of --backspin/--sidespin.
    #[arg(long, value_name = "RPM", value_parser = finite, allow_hyphen_values = true)]
    pub spin: Option<f64>,
    /// Spin axis tilt [deg, + right: fade/slice] (default 0).
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub spin_axis: Option<f64>,
}

/// Scene options.
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Scene")]
pub struct SceneArgs {
    /// Scene file (TOML) with the options below as snake_case keys (e.g. `wind_speed = 5`,
    /// `wind = [-3.0, 0.0, 0.0]`, `no_lift = true`), in the units of --units; options given
    /// on the command line override it.
    #[arg(long, value_name = "FILE.toml")]
    pub scene: Option<PathBuf>,
    /// Air density [kg/m³] (default 1.225). Excludes the weather options.
    #[arg(long, value_name = "KG/M3", value_parser = finite, allow_hyphen_values = true, conflicts_with_all = ["temperature", "humidity", "pressure", "altitude"])]
    pub air_density: Option<f64>,
    /// Air temperature [°C | °F] (weather; default 15 °C).
    #[arg(long, value_name = "T", value_parser = finite, allow_hyphen_values = true)]
    pub temperature: Option<f64>,
    /// Relative humidity [percent, 0..100] (weather; default 0).
    #[arg(long, value_name = "PCT", value_parser = finite, allow_hyphen_values = true)]
    pub humidity: Option<f64>,
    /// Station pressure [Pa] (weather). Excludes --altitude.
    #[arg(long, value_name = "PA", value_parser = finite, allow_hyphen_values = true, conflicts_with = "altitude")]
    pub pressure: Option<f64>,
    /// Altitude above sea level [m | ft] (weather; standard-atmosphere pressure; default 0).
    #[arg(long, value_name = "H", value_parser = finite, allow_hyphen_values = true)]
    pub altitude: Option<f64>,
    /// Uniform wind velocity [m/s | mph, G: +X downrange (helping), +Z left-to-right].
    #[arg(long, value_name = "X,Y,Z", value_parser = vec3, allow_hyphen_values = true, conflicts_with_all = ["wind_speed", "wind_direction"])]
    pub wind: Option<[f64; 3]>,
    /// Wind speed at the reference height [m/s | mph] (power-law profile).
    #[arg(long, value_name = "SPEED", value_parser = finite, allow_hyphen_values = true)]
    pub wind_speed: Option<f64>,
    /// Direction the wind blows towards [deg from downrange towards the right]:
    /// 0 helping, 90 left-to-right, 180 into the face.
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub wind_direction: Option<f64>,
    /// Wind profile reference height [m | ft] (default 10 m); with --wind makes it a profile.
    #[arg(long, value_name = "H", value_parser = finite, allow_hyphen_values = true)]
    pub wind_reference_height: Option<f64>,
    /// Wind profile exponent k in w(h) = w_ref·(h/h_ref)^k (default 1/7).
    #[arg(long, value_name = "K", value_parser = finite, allow_hyphen_values = true)]
    pub wind_exponent: Option<f64>,
    /// Height of the landing area relative to the turf at the tee [m | ft] (default 0; +
    /// uphill).
    #[arg(long, value_name = "H", value_parser = finite, allow_hyphen_values = true)]
    pub landing_height: Option<f64>,
    /// Height of the ball above the turf at launch: a tee [m | ft] (default 0, the ball on
    /// the turf). Carry is measured down to the landing height; TrackMan's "carry flat" is
    /// to the launch height (a tee height of 0)
    #[arg(long, value_name = "H", value_parser = finite, allow_hyphen_values = true)]
    pub tee_height: Option<f64>,
    /// Give up if the ball has not landed after this long [s] (default 60).
    #[arg(long, value_name = "S", value_parser = finite, allow_hyphen_values = true)]
    pub time_limit: Option<f64>,
    /// No aerodynamic drag.
    #[arg(long)]
    pub no_drag: bool,
    /// No Magnus lift.
    #[arg(long)]
    pub no_lift: bool,
    /// No spin decay (spin stays at its launch value).
    #[arg(long)]
    pub no_spin_decay: bool,
    /// Aerodynamic model: `drives2026` (default: the modern model calibrated on single
    /// TrackMan drives with the 2023 tour table and the 2010 driver chart, docs/aero.md),
    /// `tour2023` (the same family fitted to the two tables alone), `quintavalla` (the seed
    /// model of PHYSICS.md), or a model file written by `carry fit --output`.
    #[arg(long, value_name = "NAME|FILE.toml")]
    pub aero: Option<String>,
    /// Bounce and roll to rest on this ground: fairway, fairway-trackman (fitted to
    /// TrackMan's roll on single drives), fairway-joint (fitted to TrackMan's single
    /// drives and its 2010 chart at once), fairway-soft, rough, green, or a
    /// ground file FILE.toml (keys surface, stimp, restitution, friction,
    /// rolling_resistance, crater_scale, grass_height, slope, slope_direction). Adds total, roll,
    /// bounces, rest position and time to rest.
    #[arg(long, value_name = "SURFACE")]
    pub ground: Option<String>,
    /// Green speed, stimpmeter reading [ft] (--ground green; default 10).
    #[arg(long, value_name = "FT", value_parser = finite, allow_hyphen_values = true)]
    pub stimp: Option<f64>,
    /// Slope of the ground plane through the landing point [deg] (default 0).
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub ground_slope: Option<f64>,
    /// Direction the ground rises towards [deg from downrange towards the right]:
    /// 0 uphill to the target, 180 downhill, 90 rising to the right.
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub ground_slope_direction: Option<f64>,
    /// Custom turf: restitution at low normal speed [0..1] (Penner's green: 0.51).
    #[arg(long, value_name = "E", value_parser = finite, allow_hyphen_values = true)]
    pub ground_restitution: Option<f64>,
    /// Custom turf: ball–turf friction coefficient during a bounce (Penner: 0.40).
    #[arg(long, value_name = "MU", value_parser = finite, allow_hyphen_values = true)]
    pub ground_friction: Option<f64>,
    /// Custom turf: rolling resistance ρ, the roll decelerates at (5/7)ρg.
    #[arg(long, value_name = "RHO", value_parser = finite, allow_hyphen_values = true)]
    pub rolling_resistance: Option<f64>,
    /// Custom turf: scale of Penner's crater tilt (1 = Penner's green).
    #[arg(long, value_name = "K", value_parser = finite, allow_hyphen_values = true)]
    pub crater_scale: Option<f64>,
    /// Custom turf: grass height [m]; a rebound lower than it ends the bouncing (green
    /// 0.005, fairways 0.0127, rough 0.0381).
    #[arg(long, value_name = "M", value_parser = finite, allow_hyphen_values = true)]
    pub grass_height: Option<f64>,
}

/// Precision option.
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Numerics")]
pub struct PrecisionArgs {
    /// Floating-point precision of the computation.
    #[arg(long, value_enum, default_value_t = Precision::F64)]
    pub precision: Precision,
}

/// Impact solver option.
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Numerics")]
pub struct SolverArgs {
    /// Impact solver: the exact 3×3 collision-matrix form or the full 15×15 system.
    #[arg(long, value_enum, default_value_t = SolverChoice::Reduced)]
    pub solver: SolverChoice,
}

/// Flight integrator options.
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Numerics")]
pub struct IntegratorArgs {
    /// Flight integrator: explicit Euler, classical RK4 (fixed step) or adaptive Dormand–Prince 5(4).
    #[arg(long, value_enum, default_value_t = IntegratorChoice::Dp45)]
    pub integrator: IntegratorChoice,
    /// Step [s]: the fixed step of euler/rk4 (default 0.001), the first trial step of dp45 (default 0.46 in f64, 0.69 in f32).
    #[arg(long, value_name = "S", value_parser = finite, allow_hyphen_values = true)]
    pub step: Option<f64>,
    /// Relative and absolute error tolerance of dp45 (default 1e-6).
    #[arg(long, value_name = "TOL", value_parser = finite, allow_hyphen_values = true)]
    pub tolerance: Option<f64>,
}

/// Output options.
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Output")]
pub struct OutputArgs {
    /// Input and display units (JSON and CSV stay SI).
    #[arg(long, value_enum, default_value_t = Units::Si)]
    pub units: Units,
    /// Print JSON (SI; the stable contract, see the README).
    #[arg(long, conflicts_with = "csv")]
    pub json: bool,
    /// Print CSV: a header and one row (SI; the JSON key names, vectors as _x, _y, _z).
    #[arg(long)]
    pub csv: bool,
}

/// Batch input options.
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Batch")]
pub struct BatchArgs {
    /// Input CSV (`-` for standard input). Header: option names in snake_case (club_speed,
    /// attack_angle, impact_toe, …; vectors as one quoted "x,y,z" field or _x, _y, _z
    /// columns; `club` takes a preset name). Missing columns take the command-line values
    /// or the defaults. Values are in the units of --units. Another `carry batch`'s output
    /// reads as input: its launch columns (ball_speed_mps, launch_angle_deg, …; SI) are
    /// used, a row with an error stays one, the other result columns are ignored.
    #[arg(long, short, value_name = "FILE.csv")]
    pub input: PathBuf,
    /// Worker threads (default: all cores).
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
    /// Never show a progress bar.
    #[arg(long)]
    pub no_progress: bool,
}

// ---------------------------------------------------------------- applying options

fn put(p: &mut Params, units: Units, key: Key, v: Option<f64>) {
    if let Some(x) = v {
        key.set(p, units, Value::Number(x));
    }
}

fn put_vec(p: &mut Params, units: Units, key: Key, v: Option<[f64; 3]>) {
    if let Some(x) = v {
        key.set(p, units, Value::Vector(x));
    }
}

impl DeliveryArgs {
    /// Applies the given options.
    pub fn apply(&self, p: &mut Params, u: Units) {
        put(p, u, Key::ClubSpeed, self.club_speed);
        put(p, u, Key::AttackAngle, self.attack_angle);
        put(p, u, Key::ClubPath, self.club_path);
        put(p, u, Key::FaceAngle, self.face_angle);
        put(p, u, Key::DynamicLoft, self.dynamic_loft);
        put(p, u, Key::Lie, self.lie);
        put_vec(p, u, Key::ClubSpin, self.club_spin);
        put(p, u, Key::ImpactHeight, self.impact_height);
        put(p, u, Key::ImpactToe, self.impact_toe);
        put(p, u, Key::Cor, self.cor);
        if let Some(c) = self.convention {
            Key::Convention.set(p, u, Value::Convention(c));
        }
    }
}

impl ClubArgs {
    /// Applies the given options (the preset first, then the overrides).
    pub fn apply(&self, p: &mut Params, u: Units) {
        if let Some(law) = self.contact {
            Key::Contact.set(p, u, Value::Contact(law));
        }
        if let Some(preset) = self.club {
            Key::Club.set(p, u, Value::Preset(preset));
        }
        put(p, u, Key::SpinAxisShare, self.spin_axis_share);
        put(p, u, Key::ClubMass, self.club_mass);
        if let Some(t) = self.club_inertia {
            Key::ClubInertia.set(p, u, Value::Tensor(t));
        }
        put(p, u, Key::Loft, self.loft);
        put(p, u, Key::Bulge, self.bulge);
        put(p, u, Key::Roll, self.roll);
        put(p, u, Key::FaceDepthRadius, self.face_depth_radius);
        put_vec(p, u, Key::CgToFace, self.cg_to_face);
        put(p, u, Key::BallMass, self.ball_mass);
        put(p, u, Key::BallRadius, self.ball_radius);
    }
}

impl BallArgs {
    /// Applies the given options.
    pub fn apply(&self, p: &mut Params, u: Units) {
        put(p, u, Key::BallMass, self.ball_mass);
        put(p, u, Key::BallRadius, self.ball_radius);
    }
}

impl LaunchArgs {
    /// Applies the given options.
    pub fn apply(&self, p: &mut Params, u: Units) {
        put(p, u, Key::BallSpeed, self.ball_speed);
        put(p, u, Key::LaunchAngle, self.launch_angle);
        put(p, u, Key::LaunchDirection, self.launch_direction);
        put(p, u, Key::Backspin, self.backspin);
        put(p, u, Key::Sidespin, self.sidespin);
        put(p, u, Key::Spin, self.spin);
        put(p, u, Key::SpinAxis, self.spin_axis);
    }
}

impl SceneArgs {
    /// Applies the scene file, then the given options.
    ///
    /// # Errors
    /// A bad scene file.
    pub fn apply(&self, p: &mut Params, u: Units) -> Result<(), InputError> {
        if let Some(path) = &self.scene {
            carry_io::scene::load_file(path, u, p)?;
        }
        put(p, u, Key::AirDensity, self.air_density);
        put(p, u, Key::Temperature, self.temperature);
        put(p, u, Key::Humidity, self.humidity);
        put(p, u, Key::Pressure, self.pressure);
        put(p, u, Key::Altitude, self.altitude);
        put_vec(p, u, Key::Wind, self.wind);
        put(p, u, Key::WindSpeed, self.wind_speed);
        put(p, u, Key::WindDirection, self.wind_direction);
        put(p, u, Key::WindReferenceHeight, self.wind_reference_height);
        put(p, u, Key::WindExponent, self.wind_exponent);
        put(p, u, Key::LandingHeight, self.landing_height);
        put(p, u, Key::TeeHeight, self.tee_height);
        put(p, u, Key::TimeLimit, self.time_limit);
        if let Some(aero) = &self.aero {
            let model = Key::Aero.parse(aero)?;
            Key::Aero.set(p, u, model);
        }
        if let Some(text) = &self.ground {
            Key::Ground.set(p, u, Key::Ground.parse(text)?);
        }
        put(p, u, Key::Stimp, self.stimp);
        put(p, u, Key::GroundSlope, self.ground_slope);
        put(p, u, Key::GroundSlopeDirection, self.ground_slope_direction);
        put(p, u, Key::GroundRestitution, self.ground_restitution);
        put(p, u, Key::GroundFriction, self.ground_friction);
        put(p, u, Key::RollingResistance, self.rolling_resistance);
        put(p, u, Key::CraterScale, self.crater_scale);
        put(p, u, Key::GrassHeight, self.grass_height);
        for (flag, key) in [
            (self.no_drag, Key::NoDrag),
            (self.no_lift, Key::NoLift),
            (self.no_spin_decay, Key::NoSpinDecay),
        ] {
            if flag {
                key.set(p, u, Value::Bool(true));
            }
        }
        Ok(())
    }
}

/// The numerics of a command's precision, solver and integrator options (what it lacks
/// keeps the default), checked.
///
/// # Errors
/// `--tolerance` with a fixed-step integrator.
pub fn numerics(
    precision: &PrecisionArgs,
    solver: Option<&SolverArgs>,
    integrator: Option<&IntegratorArgs>,
) -> Result<Numerics, InputError> {
    let mut n = Numerics {
        precision: precision.precision,
        ..Numerics::default()
    };
    if let Some(s) = solver {
        n.solver = s.solver;
    }
    if let Some(i) = integrator {
        n.integrator = i.integrator;
        n.step_s = i.step;
        n.tolerance = i.tolerance;
    }
    n.check()?;
    Ok(n)
}
