//! Every input of a shot as plain SI `f64` values (angles in degrees, launch spins in rpm,
//! as the user gives them), and the table of settable keys shared by the command-line
//! options, the `--scene` file and the batch CSV columns.
//!
//! A key's name is the option's long name in snake_case (`--club-speed` ↔ `club_speed`).

use crate::error::InputError;
use crate::ground::GroundSpec;
use crate::units::{Quantity, Units};
use carry_core::aero::AeroModel;
use carry_core::impact::ContactLaw;
use carry_core::{DeliveryConvention, PRESETS, Preset};

/// Club head: a preset and any overrides.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClubParams {
    /// The preset the overrides start from (unnamed: PHYSICS.md's reference driver,
    /// [`carry_core::presets::REFERENCE_DRIVER`]).
    pub preset: &'static Preset,
    /// Head mass (kg).
    pub mass_kg: Option<f64>,
    /// Inertia tensor, row-major (kg·m²).
    pub inertia_kgm2: Option<[f64; 9]>,
    /// Static loft (deg).
    pub loft_deg: Option<f64>,
    /// Bulge radius (m).
    pub bulge_m: Option<f64>,
    /// Roll radius (m).
    pub roll_m: Option<f64>,
    /// Face depth radius a (m).
    pub face_depth_radius_m: Option<f64>,
    /// CoM → face centre in the face frame (m).
    pub cg_to_face_m: Option<[f64; 3]>,
    /// Coefficient of restitution.
    pub cor: Option<f64>,
    /// The empirical D-plane share of the spin axis, in (0, 1]; `None`: the physics (1).
    pub spin_axis_share: Option<f64>,
    /// Contact law; `None`: the preset's (the fitted compliant contact).
    pub contact: Option<ContactLaw<f64>>,
    /// The user named the preset: unspecified attack angle, dynamic loft and impact height
    /// take its typical delivery.
    pub named: bool,
}

/// The club delivery (launch-monitor terms).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeliveryParams {
    /// Club head speed (m/s); see `club_speed_given`.
    pub club_speed_mps: f64,
    /// The user gave the club speed (else a named club's typical speed replaces the default).
    pub club_speed_given: bool,
    /// Attack angle (deg); `None` = the named club's typical delivery, else 0.
    pub attack_angle_deg: Option<f64>,
    /// Club path (deg).
    pub club_path_deg: f64,
    /// Face angle (deg).
    pub face_angle_deg: f64,
    /// Dynamic loft (deg); `None` = the named club's typical delivery, else its static loft.
    pub dynamic_loft_deg: Option<f64>,
    /// Lie (deg).
    pub lie_deg: f64,
    /// Club angular velocity (rad/s, G).
    pub club_spin_radps: [f64; 3],
    /// Impact height up the face (m); `None` = the named club's typical delivery, else 0.
    pub impact_height_m: Option<f64>,
    /// Impact offset toward the toe (m).
    pub impact_toe_m: f64,
    /// Where the face angle and dynamic loft are read: TrackMan's contact point (the
    /// default) or the seed's face centre.
    pub convention: DeliveryConvention,
}

/// A launch as a launch monitor reports it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LaunchParams {
    /// Ball speed (m/s).
    pub ball_speed_mps: f64,
    /// Launch angle (deg).
    pub launch_angle_deg: f64,
    /// Launch direction (deg, + right).
    pub launch_direction_deg: f64,
    /// Backspin (rpm).
    pub backspin_rpm: Option<f64>,
    /// Sidespin (rpm, + curves right).
    pub sidespin_rpm: Option<f64>,
    /// Total spin (rpm).
    pub spin_rpm: Option<f64>,
    /// Spin axis (deg, + tilted right).
    pub spin_axis_deg: Option<f64>,
}

/// The flight's surroundings, resolved into a core scene by [`crate::scene`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SceneParams {
    /// Fixed air density (kg/m³).
    pub air_density_kgm3: Option<f64>,
    /// Temperature (°C).
    pub temperature_c: Option<f64>,
    /// Relative humidity (percent).
    pub humidity_pct: Option<f64>,
    /// Station pressure (Pa).
    pub pressure_pa: Option<f64>,
    /// Altitude (m).
    pub altitude_m: Option<f64>,
    /// Wind vector (m/s, G).
    pub wind_mps: Option<[f64; 3]>,
    /// Wind speed (m/s).
    pub wind_speed_mps: Option<f64>,
    /// Wind direction (deg, towards, from +X to +Z).
    pub wind_direction_deg: Option<f64>,
    /// Wind profile reference height (m).
    pub wind_reference_height_m: Option<f64>,
    /// Wind profile exponent.
    pub wind_exponent: Option<f64>,
    /// Landing height (m).
    pub landing_height_m: Option<f64>,
    /// Tee height: the ball's start above the turf (m).
    pub tee_height_m: Option<f64>,
    /// Flight time limit (s).
    pub time_limit_s: Option<f64>,
    /// Disable drag.
    pub no_drag: bool,
    /// Disable lift.
    pub no_lift: bool,
    /// Disable spin decay.
    pub no_spin_decay: bool,
    /// The aerodynamic model (`None`: the calibrated default).
    pub aero: Option<AeroModel<f64>>,
    /// The ground after the landing (empty: none).
    pub ground: GroundSpec,
}

/// Everything one shot needs (numerics are global, see [`crate::compute::Numerics`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Params {
    /// Club head.
    pub club: ClubParams,
    /// Ball mass (kg).
    pub ball_mass_kg: f64,
    /// Ball radius (m).
    pub ball_radius_m: f64,
    /// Delivery.
    pub delivery: DeliveryParams,
    /// Launch (flight input).
    pub launch: LaunchParams,
    /// Scene.
    pub scene: SceneParams,
}

/// Default club speed (m/s): the PHYSICS.md reference delivery.
pub const DEFAULT_CLUB_SPEED_MPS: f64 = 45.0;
/// Default launch for `carry flight`: TrackMan's PGA Tour driver average (167 mph, 10.9°,
/// 2686 rpm).
pub const DEFAULT_BALL_SPEED_MPS: f64 = 167.0 * carry_core::units::MPS_PER_MPH;
/// Default launch angle (deg).
pub const DEFAULT_LAUNCH_ANGLE_DEG: f64 = 10.9;
/// Default backspin (rpm).
pub const DEFAULT_BACKSPIN_RPM: f64 = 2686.0;

/// The delivery convention of the CLI, the batch files, Python and the C API: TrackMan's
/// (face angle and dynamic loft at the contact point), what a launch-monitor user gives.
pub const DEFAULT_CONVENTION: DeliveryConvention = DeliveryConvention::TrackMan;

impl Default for Params {
    fn default() -> Self {
        Self {
            club: ClubParams {
                preset: &carry_core::presets::REFERENCE_DRIVER,
                mass_kg: None,
                inertia_kgm2: None,
                loft_deg: None,
                bulge_m: None,
                roll_m: None,
                face_depth_radius_m: None,
                cg_to_face_m: None,
                cor: None,
                spin_axis_share: None,
                contact: None,
                named: false,
            },
            ball_mass_kg: carry_core::Ball::<f64>::STANDARD_MASS_KG,
            ball_radius_m: carry_core::Ball::<f64>::STANDARD_RADIUS_M,
            delivery: DeliveryParams {
                club_speed_mps: DEFAULT_CLUB_SPEED_MPS,
                club_speed_given: false,
                attack_angle_deg: None,
                club_path_deg: 0.0,
                face_angle_deg: 0.0,
                dynamic_loft_deg: None,
                lie_deg: 0.0,
                club_spin_radps: [0.0; 3],
                impact_height_m: None,
                impact_toe_m: 0.0,
                convention: DEFAULT_CONVENTION,
            },
            launch: LaunchParams {
                ball_speed_mps: DEFAULT_BALL_SPEED_MPS,
                launch_angle_deg: DEFAULT_LAUNCH_ANGLE_DEG,
                launch_direction_deg: 0.0,
                backspin_rpm: None,
                sidespin_rpm: None,
                spin_rpm: None,
                spin_axis_deg: None,
            },
            scene: SceneParams::default(),
        }
    }
}

/// How a key's text value is read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A finite number.
    Number,
    /// A positive number or `inf`/`flat` (face radii).
    Radius,
    /// Three comma-separated numbers.
    Vector,
    /// Three or nine comma-separated numbers (inertia).
    Tensor,
    /// A preset name.
    Preset,
    /// A contact-law name or TOML file.
    Contact,
    /// An aerodynamic model: a built-in name or a model file.
    Aero,
    /// `true`/`false`/`1`/`0`/`yes`/`no`.
    Bool,
    /// A surface name or a ground file ([`crate::ground`]).
    Ground,
    /// A delivery convention: `trackman` or `seed` ([`parse_convention`]).
    Convention,
}

macro_rules! keys {
    ($($variant:ident = $name:literal, $kind:ident, $q:ident;)*) => {
        /// A settable key (an option, a scene-file key, a batch column).
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        pub enum Key {
            $(
                #[doc = concat!("`", $name, "`")]
                $variant,
            )*
        }

        impl Key {
            /// Every key.
            pub const ALL: &'static [Key] = &[$(Key::$variant),*];

            /// The snake_case name.
            #[must_use]
            pub fn name(self) -> &'static str {
                match self { $(Key::$variant => $name),* }
            }

            /// How the value is read.
            #[must_use]
            pub fn kind(self) -> Kind {
                match self { $(Key::$variant => Kind::$kind),* }
            }

            /// The key's quantity (for units).
            #[must_use]
            pub fn quantity(self) -> Quantity {
                match self { $(Key::$variant => Quantity::$q),* }
            }
        }
    };
}

keys! {
    ClubSpeed = "club_speed", Number, Speed;
    AttackAngle = "attack_angle", Number, Plain;
    ClubPath = "club_path", Number, Plain;
    FaceAngle = "face_angle", Number, Plain;
    DynamicLoft = "dynamic_loft", Number, Plain;
    Lie = "lie", Number, Plain;
    ClubSpin = "club_spin", Vector, Plain;
    ClubSpinX = "club_spin_x", Number, Plain;
    ClubSpinY = "club_spin_y", Number, Plain;
    ClubSpinZ = "club_spin_z", Number, Plain;
    ImpactHeight = "impact_height", Number, Offset;
    ImpactToe = "impact_toe", Number, Offset;
    Cor = "cor", Number, Plain;
    SpinAxisShare = "spin_axis_share", Number, Plain;
    Convention = "convention", Convention, Plain;
    Club = "club", Preset, Plain;
    Contact = "contact", Contact, Plain;
    ClubMass = "club_mass", Number, Plain;
    ClubInertia = "club_inertia", Tensor, Plain;
    Loft = "loft", Number, Plain;
    Bulge = "bulge", Radius, Plain;
    Roll = "roll", Radius, Plain;
    FaceDepthRadius = "face_depth_radius", Radius, Plain;
    CgToFace = "cg_to_face", Vector, Plain;
    CgToFaceX = "cg_to_face_x", Number, Plain;
    CgToFaceY = "cg_to_face_y", Number, Plain;
    CgToFaceZ = "cg_to_face_z", Number, Plain;
    BallMass = "ball_mass", Number, Plain;
    BallRadius = "ball_radius", Number, Plain;
    BallSpeed = "ball_speed", Number, Speed;
    LaunchAngle = "launch_angle", Number, Plain;
    LaunchDirection = "launch_direction", Number, Plain;
    Backspin = "backspin", Number, Plain;
    Sidespin = "sidespin", Number, Plain;
    Spin = "spin", Number, Plain;
    SpinAxis = "spin_axis", Number, Plain;
    AirDensity = "air_density", Number, Plain;
    Temperature = "temperature", Number, Temperature;
    Humidity = "humidity", Number, Plain;
    Pressure = "pressure", Number, Plain;
    Altitude = "altitude", Number, Height;
    Wind = "wind", Vector, Speed;
    WindX = "wind_x", Number, Speed;
    WindY = "wind_y", Number, Speed;
    WindZ = "wind_z", Number, Speed;
    WindSpeed = "wind_speed", Number, Speed;
    WindDirection = "wind_direction", Number, Plain;
    WindReferenceHeight = "wind_reference_height", Number, Height;
    WindExponent = "wind_exponent", Number, Plain;
    LandingHeight = "landing_height", Number, Height;
    TeeHeight = "tee_height", Number, Height;
    TimeLimit = "time_limit", Number, Plain;
    NoDrag = "no_drag", Bool, Plain;
    NoLift = "no_lift", Bool, Plain;
    NoSpinDecay = "no_spin_decay", Bool, Plain;
    Aero = "aero", Aero, Plain;
    Ground = "ground", Ground, Plain;
    Stimp = "stimp", Number, Plain;
    GroundSlope = "ground_slope", Number, Plain;
    GroundSlopeDirection = "ground_slope_direction", Number, Plain;
    GroundRestitution = "ground_restitution", Number, Plain;
    GroundFriction = "ground_friction", Number, Plain;
    RollingResistance = "rolling_resistance", Number, Plain;
    CraterScale = "crater_scale", Number, Plain;
    GrassHeight = "grass_height", Number, Plain;
}

/// A parsed value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value {
    /// A number (in the user's units).
    Number(f64),
    /// A vector (in the user's units).
    Vector([f64; 3]),
    /// A 3×3 tensor, row-major.
    Tensor([f64; 9]),
    /// A preset.
    Preset(&'static Preset),
    /// A contact law.
    Contact(ContactLaw<f64>),
    /// An aerodynamic model.
    Aero(AeroModel<f64>),
    /// A switch.
    Bool(bool),
    /// A ground (surface and options).
    Ground(GroundSpec),
    /// A delivery convention.
    Convention(DeliveryConvention),
}

impl Key {
    /// Whether this key is one of the ground's (a run with it has the ground's output
    /// columns: `total_m`, `roll_m`, …).
    #[must_use]
    pub fn is_ground(self) -> bool {
        matches!(
            self,
            Self::Ground
                | Self::Stimp
                | Self::GroundSlope
                | Self::GroundSlopeDirection
                | Self::GroundRestitution
                | Self::GroundFriction
                | Self::RollingResistance
                | Self::CraterScale
                | Self::GrassHeight
        )
    }

    /// Looks a key up by its snake_case (or kebab-case) name.
    #[must_use]
    pub fn find(name: &str) -> Option<Self> {
        let name = name.trim();
        Self::ALL.iter().copied().find(|k| {
            let n = k.name();
            n.len() == name.len()
                && n.bytes()
                    .zip(name.bytes())
                    .all(|(a, b)| a == b || (a == b'_' && b == b'-'))
        })
    }

    /// Parses a text value for this key.
    ///
    /// # Errors
    /// An [`InputError`] naming the key and why the text is not a valid value.
    pub fn parse(self, text: &str) -> Result<Value, InputError> {
        let err = |reason: String| InputError::new(self.name(), reason);
        match self.kind() {
            Kind::Number => parse_finite(text).map(Value::Number).map_err(err),
            Kind::Radius => parse_radius(text).map(Value::Number).map_err(err),
            Kind::Vector => parse_vec3(text).map(Value::Vector).map_err(err),
            Kind::Tensor => parse_tensor(text).map(Value::Tensor).map_err(err),
            Kind::Preset => parse_preset(text).map(Value::Preset).map_err(err),
            Kind::Contact => crate::contact::parse(text).map(Value::Contact).map_err(err),
            Kind::Aero => crate::aero_file::resolve(text.trim())
                .map(Value::Aero)
                .map_err(err),
            Kind::Bool => parse_bool(text).map(Value::Bool).map_err(err),
            Kind::Ground => crate::ground::parse(text).map(Value::Ground).map_err(err),
            Kind::Convention => parse_convention(text).map(Value::Convention).map_err(err),
        }
    }

    /// Stores `value` (in `units`) into `p`, converting to SI.
    pub fn set(self, p: &mut Params, units: Units, value: Value) {
        let q = self.quantity();
        let si = |x: f64| units.to_si(q, x);
        let d = &mut p.delivery;
        let c = &mut p.club;
        let l = &mut p.launch;
        let s = &mut p.scene;
        match value {
            Value::Number(x) => {
                let x = si(x);
                if self.set_launch(l, x) {
                    return;
                }
                match self {
                    Key::ClubSpeed => {
                        d.club_speed_mps = x;
                        d.club_speed_given = true;
                    }
                    Key::AttackAngle => d.attack_angle_deg = Some(x),
                    Key::ClubPath => d.club_path_deg = x,
                    Key::FaceAngle => d.face_angle_deg = x,
                    Key::DynamicLoft => d.dynamic_loft_deg = Some(x),
                    Key::Lie => d.lie_deg = x,
                    Key::ClubSpinX => d.club_spin_radps[0] = x,
                    Key::ClubSpinY => d.club_spin_radps[1] = x,
                    Key::ClubSpinZ => d.club_spin_radps[2] = x,
                    Key::ImpactHeight => d.impact_height_m = Some(x),
                    Key::ImpactToe => d.impact_toe_m = x,
                    Key::Cor => c.cor = Some(x),
                    Key::SpinAxisShare => c.spin_axis_share = Some(x),
                    Key::ClubMass => c.mass_kg = Some(x),
                    Key::Loft => c.loft_deg = Some(x),
                    Key::Bulge => c.bulge_m = Some(x),
                    Key::Roll => c.roll_m = Some(x),
                    Key::FaceDepthRadius => c.face_depth_radius_m = Some(x),
                    Key::CgToFaceX => c.cg_to_face_m.get_or_insert(preset_cg(c.preset))[0] = x,
                    Key::CgToFaceY => c.cg_to_face_m.get_or_insert(preset_cg(c.preset))[1] = x,
                    Key::CgToFaceZ => c.cg_to_face_m.get_or_insert(preset_cg(c.preset))[2] = x,
                    Key::BallMass => p.ball_mass_kg = x,
                    Key::BallRadius => p.ball_radius_m = x,
                    Key::AirDensity => s.air_density_kgm3 = Some(x),
                    Key::Temperature => s.temperature_c = Some(x),
                    Key::Humidity => s.humidity_pct = Some(x),
                    Key::Pressure => s.pressure_pa = Some(x),
                    Key::Altitude => s.altitude_m = Some(x),
                    Key::WindX => s.wind_mps.get_or_insert([0.0; 3])[0] = x,
                    Key::WindY => s.wind_mps.get_or_insert([0.0; 3])[1] = x,
                    Key::WindZ => s.wind_mps.get_or_insert([0.0; 3])[2] = x,
                    Key::WindSpeed => s.wind_speed_mps = Some(x),
                    Key::WindDirection => s.wind_direction_deg = Some(x),
                    Key::WindReferenceHeight => s.wind_reference_height_m = Some(x),
                    Key::WindExponent => s.wind_exponent = Some(x),
                    Key::LandingHeight => s.landing_height_m = Some(x),
                    Key::TeeHeight => s.tee_height_m = Some(x),
                    Key::TimeLimit => s.time_limit_s = Some(x),
                    Key::Stimp => s.ground.stimp_ft = Some(x),
                    Key::GroundSlope => s.ground.slope_deg = Some(x),
                    Key::GroundSlopeDirection => s.ground.slope_direction_deg = Some(x),
                    Key::GroundRestitution => s.ground.restitution = Some(x),
                    Key::GroundFriction => s.ground.friction = Some(x),
                    Key::RollingResistance => s.ground.rolling_resistance = Some(x),
                    Key::CraterScale => s.ground.crater_scale = Some(x),
                    Key::GrassHeight => s.ground.grass_height_m = Some(x),
                    _ => {}
                }
            }
            Value::Vector(v) => {
                let v = v.map(si);
                match self {
                    Key::ClubSpin => d.club_spin_radps = v,
                    Key::CgToFace => c.cg_to_face_m = Some(v),
                    Key::Wind => s.wind_mps = Some(v),
                    _ => {}
                }
            }
            Value::Tensor(t) => c.inertia_kgm2 = Some(t),
            Value::Preset(preset) => {
                c.preset = preset;
                c.named = true;
            }
            Value::Contact(law) => c.contact = Some(law),
            Value::Aero(model) => s.aero = Some(model),
            Value::Bool(b) => match self {
                Key::NoDrag => s.no_drag = b,
                Key::NoLift => s.no_lift = b,
                Key::NoSpinDecay => s.no_spin_decay = b,
                _ => {}
            },
            Value::Ground(g) => s.ground.merge(&g),
            Value::Convention(convention) => d.convention = convention,
        }
    }
}

impl Key {
    /// Whether this key is one of the launch's (a flight's input: ball speed, launch angle
    /// and direction, the spins).
    #[must_use]
    pub fn is_launch(self) -> bool {
        matches!(
            self,
            Self::BallSpeed
                | Self::LaunchAngle
                | Self::LaunchDirection
                | Self::Backspin
                | Self::Sidespin
                | Self::Spin
                | Self::SpinAxis
        )
    }

    /// Whether this key changes the scene or the ball a shot flies with (the air, wind,
    /// ground, aerodynamics, the ball's mass and radius): rows whose columns have none of
    /// these share one prepared scene.
    #[must_use]
    pub fn is_scene(self) -> bool {
        use Key::*;
        matches!(
            self,
            BallMass
                | BallRadius
                | AirDensity
                | Temperature
                | Humidity
                | Pressure
                | Altitude
                | Wind
                | WindX
                | WindY
                | WindZ
                | WindSpeed
                | WindDirection
                | WindReferenceHeight
                | WindExponent
                | LandingHeight
                | TeeHeight
                | TimeLimit
                | NoDrag
                | NoLift
                | NoSpinDecay
                | Aero
        ) || self.is_ground()
    }

    /// Stores the number `x` (SI) into the launch `l` when this is a launch key
    /// ([`Key::is_launch`]; what [`Key::set`] does for it); `false` for any other key.
    pub fn set_launch(self, l: &mut LaunchParams, x: f64) -> bool {
        match self {
            Key::BallSpeed => l.ball_speed_mps = x,
            Key::LaunchAngle => l.launch_angle_deg = x,
            Key::LaunchDirection => l.launch_direction_deg = x,
            Key::Backspin => l.backspin_rpm = Some(x),
            Key::Sidespin => l.sidespin_rpm = Some(x),
            Key::Spin => l.spin_rpm = Some(x),
            Key::SpinAxis => l.spin_axis_deg = Some(x),
            _ => return false,
        }
        true
    }

    /// Checks a number for this key as the text parser would ([`parse_finite`], or
    /// [`parse_radius`] for a face radius, which may be `inf`): the Python package's and
    /// other array callers' per-row check.
    ///
    /// # Errors
    /// The message for the row, naming the key.
    #[inline]
    pub fn check_number(self, x: f64) -> Result<f64, InputError> {
        // Every kind takes a finite number: the key's kind is asked only of the rest.
        if x.is_finite() || (self.kind() == Kind::Radius && x == f64::INFINITY) {
            Ok(x)
        } else {
            Err(self.not_finite(x))
        }
    }

    /// The message for a number [`Key::check_number`] rejects.
    #[cold]
    fn not_finite(self, x: f64) -> InputError {
        InputError::new(self.name(), format!("'{x}' is not a finite number"))
    }
}

fn preset_cg(p: &Preset) -> [f64; 3] {
    p.cg_to_face_m
}

/// A finite number.
///
/// # Errors
/// The reason, for a message.
pub fn parse_finite(text: &str) -> Result<f64, String> {
    let t = text.trim();
    let x: f64 = t.parse().map_err(|_| format!("'{t}' is not a number"))?;
    if x.is_finite() {
        Ok(x)
    } else {
        Err(format!("'{t}' is not a finite number"))
    }
}

/// Parses `a,b` (two finite numbers).
///
/// # Errors
/// The reason, for a message.
pub fn parse_pair(text: &str) -> Result<[f64; 2], String> {
    let v: Vec<f64> = text
        .split(',')
        .map(parse_finite)
        .collect::<Result<_, _>>()?;
    match v.as_slice() {
        &[a, b] => Ok([a, b]),
        _ => Err(format!("'{}' must be two numbers: low,high", text.trim())),
    }
}

/// Parses `from,to,step` (three finite numbers).
///
/// # Errors
/// The reason, for a message.
pub fn parse_triple(text: &str) -> Result<[f64; 3], String> {
    let v: Vec<f64> = text
        .split(',')
        .map(parse_finite)
        .collect::<Result<_, _>>()?;
    match v.as_slice() {
        &[a, b, c] => Ok([a, b, c]),
        _ => Err(format!(
            "'{}' must be three numbers: from,to,step",
            text.trim()
        )),
    }
}

/// A face radius: positive finite, or `inf`/`flat` for a flat face.
///
/// # Errors
/// The reason, for a message.
pub fn parse_radius(text: &str) -> Result<f64, String> {
    let t = text.trim();
    if t.eq_ignore_ascii_case("flat") {
        return Ok(f64::INFINITY);
    }
    let x: f64 = t
        .parse()
        .map_err(|_| format!("'{t}' is not a number (or 'flat')"))?;
    if x.is_nan() || x == f64::NEG_INFINITY {
        return Err(format!("'{t}' is not a valid radius"));
    }
    Ok(x)
}

/// Three comma-separated finite numbers.
///
/// # Errors
/// The reason, for a message.
pub fn parse_vec3(text: &str) -> Result<[f64; 3], String> {
    let mut out = [0.0; 3];
    let mut n = 0;
    for part in text.split(',') {
        if n == 3 {
            return Err(format!("'{}' must be three numbers x,y,z", text.trim()));
        }
        out[n] = parse_finite(part)?;
        n += 1;
    }
    if n == 3 {
        Ok(out)
    } else {
        Err(format!("'{}' must be three numbers x,y,z", text.trim()))
    }
}

/// Three (diagonal) or nine (row-major) comma-separated finite numbers.
///
/// # Errors
/// The reason, for a message.
pub fn parse_tensor(text: &str) -> Result<[f64; 9], String> {
    let values = text
        .split(',')
        .map(parse_finite)
        .collect::<Result<Vec<_>, _>>()?;
    match values.as_slice() {
        &[xx, yy, zz] => Ok([xx, 0.0, 0.0, 0.0, yy, 0.0, 0.0, 0.0, zz]),
        v if v.len() == 9 => {
            let mut out = [0.0; 9];
            out.copy_from_slice(v);
            Ok(out)
        }
        _ => Err(format!(
            "'{}' must be Ixx,Iyy,Izz or all nine components",
            text.trim()
        )),
    }
}

/// A preset name.
///
/// # Errors
/// The reason, listing the presets.
pub fn parse_preset(text: &str) -> Result<&'static Preset, String> {
    let t = text.trim();
    Preset::find(t).ok_or_else(|| {
        let names: Vec<&str> = PRESETS.iter().map(|p| p.name).collect();
        format!("unknown club '{t}' (presets: {})", names.join(", "))
    })
}

/// A delivery convention: `trackman` (face angle and dynamic loft at the contact point)
/// or `seed` (at the face centre: the seed's, which the golden files pin).
///
/// # Errors
/// The reason, naming the choices.
pub fn parse_convention(text: &str) -> Result<DeliveryConvention, String> {
    match text.trim().to_ascii_lowercase().as_str() {
        "trackman" | "contact" => Ok(DeliveryConvention::TrackMan),
        "seed" | "centre" | "center" => Ok(DeliveryConvention::SeedCentre),
        t => Err(format!(
            "unknown convention '{t}' (trackman: angles at the contact point; seed: at the face centre)"
        )),
    }
}

/// A switch value.
///
/// # Errors
/// The reason, for a message.
pub fn parse_bool(text: &str) -> Result<bool, String> {
    match text.trim().to_ascii_lowercase().as_str() {
        "1" | "true" | "yes" | "y" => Ok(true),
        "0" | "false" | "no" | "n" | "" => Ok(false),
        t => Err(format!("'{t}' is not true/false")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_round_trip_and_set() {
        for k in Key::ALL {
            assert_eq!(Key::find(k.name()), Some(*k));
        }
        let mut p = Params::default();
        let k = Key::find("club-speed").unwrap_or(Key::Cor);
        k.set(&mut p, Units::Imperial, Value::Number(100.0));
        assert!((p.delivery.club_speed_mps - 44.704).abs() < 1e-12);
        assert!(parse_vec3("1,2").is_err());
        assert!(parse_vec3("1,2,3,4").is_err());
        assert!(parse_finite("nan").is_err());
        assert_eq!(parse_radius("flat"), Ok(f64::INFINITY));
        assert_eq!(parse_tensor("1,2,3").map(|t| t[4]), Ok(2.0));
    }
}
