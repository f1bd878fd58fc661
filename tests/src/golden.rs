//! Loading the impact golden file (`tests/golden/impact.json`), computed by an independent
//! f64 reference implementation. The file is a verbatim copy of `../shared/golden/`; it
//! contains bare `NaN` tokens (Python's JSON), which are read as NaN.

use carry_core::real::lit;
use carry_core::units::deg;
use carry_core::{Ball, ClubSpec, ContactLaw, Delivery, FaceLocation, Real};
use nalgebra::{Matrix3, Vector3};
use serde_json::Value;

/// Path of a golden file by name.
#[must_use]
pub fn path(name: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("golden")
        .join(name)
}

/// Reads a golden JSON file, accepting bare `NaN`, `Infinity` and `-Infinity` tokens.
///
/// # Panics
/// When the file is missing or malformed (a broken test setup).
#[must_use]
pub fn read_json(name: &str) -> Value {
    let text = std::fs::read_to_string(path(name)).expect("golden file readable");
    let quoted = text
        .replace("-Infinity", "\"-inf\"")
        .replace("Infinity", "\"inf\"")
        .replace("NaN", "\"nan\"");
    serde_json::from_str(&quoted).expect("golden file is JSON")
}

/// A number, accepting the quoted non-finite tokens.
///
/// # Panics
/// When the value is neither a number nor a non-finite token.
#[must_use]
pub fn num(v: &Value) -> f64 {
    match v {
        Value::Number(n) => n.as_f64().expect("f64"),
        Value::String(s) => s.parse().expect("nan/inf token"),
        other => panic!("not a number: {other}"),
    }
}

/// A 3-vector.
#[must_use]
pub fn vec3(v: &Value) -> [f64; 3] {
    [num(&v[0]), num(&v[1]), num(&v[2])]
}

/// One impact golden case.
#[derive(Debug, Clone)]
pub struct ImpactCase {
    /// Case name.
    pub name: String,
    /// The raw JSON (club, ball, delivery, expected).
    pub json: Value,
}

/// Expected impact result (SI, degrees and rpm as in the file).
#[allow(missing_docs)]
#[derive(Debug, Clone, Copy)]
pub struct ImpactExpected {
    pub ball_speed_mps: f64,
    pub launch_angle_deg: f64,
    pub launch_direction_deg: f64,
    pub spin_rpm: f64,
    pub backspin_rpm: f64,
    pub sidespin_rpm: f64,
    pub spin_axis_deg: f64,
    pub smash_factor: f64,
    pub ball_velocity_mps: [f64; 3],
    pub ball_spin_radps: [f64; 3],
    pub club_velocity_mps: [f64; 3],
    pub club_spin_radps: [f64; 3],
    pub impulse_ns: [f64; 3],
}

/// All impact cases.
#[must_use]
pub fn impact_cases() -> Vec<ImpactCase> {
    let root = read_json("impact.json");
    root["cases"]
        .as_array()
        .expect("cases")
        .iter()
        .map(|c| ImpactCase {
            name: c["name"].as_str().expect("name").to_owned(),
            json: c.clone(),
        })
        .collect()
}

impl ImpactCase {
    /// Club parameters in precision `T` (restitution from the delivery's `cor`).
    #[must_use]
    pub fn club<T: Real>(&self) -> ClubSpec<T> {
        let c = &self.json["club"];
        let i = &c["inertia_kgm2"];
        let m = Matrix3::from_fn(|r, k| lit::<T>(num(&i[r][k])));
        let cg = vec3(&c["cg_to_face_m"]);
        ClubSpec {
            mass_kg: lit(num(&c["mass_kg"])),
            inertia_kgm2: m,
            loft_rad: deg(lit(num(&c["loft_deg"]))),
            roll_radius_m: lit(num(&c["roll_radius_m"])),
            bulge_radius_m: lit(num(&c["bulge_radius_m"])),
            face_depth_radius_m: c.get("ellipsoid_a_m").map(|a| lit(num(a))),
            cg_to_face_m: Vector3::new(lit(cg[0]), lit(cg[1]), lit(cg[2])),
            restitution: lit(num(&self.json["delivery"]["cor"])),
            // the golden files pin the seed's model: rolling contact, named explicitly
            contact: ContactLaw::Rolling,
        }
    }

    /// Ball mass and radius (unvalidated: error cases may hold bad values).
    #[must_use]
    pub fn ball_mass_radius<T: Real>(&self) -> (T, T) {
        let b = &self.json["ball"];
        (lit(num(&b["mass_kg"])), lit(num(&b["radius_m"])))
    }

    /// The ball, validated.
    ///
    /// # Errors
    /// When the case holds an invalid ball.
    pub fn ball<T: Real>(&self) -> carry_core::Result<Ball<T>> {
        let (m, r) = self.ball_mass_radius();
        Ball::new(m, r)
    }

    /// Club delivery in precision `T`.
    #[must_use]
    pub fn delivery<T: Real>(&self) -> Delivery<T> {
        let d = &self.json["delivery"];
        let a = |k: &str| deg(lit::<T>(num(&d[k])));
        let w = vec3(&d["club_spin_radps"]);
        Delivery {
            club_speed_mps: lit(num(&d["club_speed_mps"])),
            attack_angle_rad: a("attack_angle_deg"),
            club_path_rad: a("club_path_deg"),
            face_angle_rad: a("face_angle_deg"),
            dynamic_loft_rad: a("dynamic_loft_deg"),
            lie_rad: a("lie_deg"),
            club_spin_radps: Vector3::new(lit(w[0]), lit(w[1]), lit(w[2])),
            location: FaceLocation {
                height_m: lit(num(&d["impact_height_m"])),
                toe_m: lit(num(&d["impact_toe_m"])),
            },
        }
    }

    /// The expected error name (`"off_face"`, `"no_approach"`, `"invalid_input"`, …), if any.
    #[must_use]
    pub fn expected_error(&self) -> Option<&str> {
        self.json.get("expected_error").and_then(Value::as_str)
    }

    /// The expected result, if this is not an error case.
    #[must_use]
    pub fn expected(&self) -> Option<ImpactExpected> {
        let e = self.json.get("expected")?;
        let f = |k: &str| num(&e[k]);
        Some(ImpactExpected {
            ball_speed_mps: f("ball_speed_mps"),
            launch_angle_deg: f("launch_angle_deg"),
            launch_direction_deg: f("launch_direction_deg"),
            spin_rpm: f("spin_rpm"),
            backspin_rpm: f("backspin_rpm"),
            sidespin_rpm: f("sidespin_rpm"),
            spin_axis_deg: f("spin_axis_deg"),
            smash_factor: f("smash_factor"),
            ball_velocity_mps: vec3(&e["ball_velocity_mps"]),
            ball_spin_radps: vec3(&e["ball_spin_radps"]),
            club_velocity_mps: vec3(&e["club_velocity_mps"]),
            club_spin_radps: vec3(&e["club_spin_radps"]),
            impulse_ns: vec3(&e["impulse_ns"]),
        })
    }
}

/// Maps a core error to the golden file's error names.
#[must_use]
pub fn error_name(e: &carry_core::Error) -> &'static str {
    match e {
        carry_core::Error::InvalidInput { .. } => "invalid_input",
        carry_core::Error::OffFace => "off_face",
        carry_core::Error::NoApproach => "no_approach",
        carry_core::Error::Singular => "singular",
        _ => "other",
    }
}
