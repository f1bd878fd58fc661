//! The impact golden file: a club, a ball and a delivery per case, with the expected launch
//! or the expected error.

use crate::json::{Error, Fields, parse_cases};

/// The club as the file states it (the seed's rigid club).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Club {
    /// Head mass (kg).
    pub mass_kg: f64,
    /// Inertia tensor about the centre of gravity, rows (kg·m²).
    pub inertia_kgm2: [[f64; 3]; 3],
    /// Static loft (degrees).
    pub loft_deg: f64,
    /// Face roll radius, vertical curvature (m).
    pub roll_radius_m: f64,
    /// Face bulge radius, horizontal curvature (m).
    pub bulge_radius_m: f64,
    /// The face ellipsoid's depth semi-axis (m), the file's `ellipsoid_a_m`, when given.
    pub face_depth_radius_m: Option<f64>,
    /// Centre of gravity to face centre, club frame (m).
    pub cg_to_face_m: [f64; 3],
}

/// The ball.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ball {
    /// Mass (kg).
    pub mass_kg: f64,
    /// Radius (m).
    pub radius_m: f64,
}

/// The delivery, in the seed's convention (angles at the face centre).
#[derive(Debug, Clone, Copy, PartialEq)]
#[allow(missing_docs)]
pub struct Delivery {
    pub club_speed_mps: f64,
    pub attack_angle_deg: f64,
    pub club_path_deg: f64,
    pub face_angle_deg: f64,
    pub dynamic_loft_deg: f64,
    pub lie_deg: f64,
    pub club_spin_radps: [f64; 3],
    pub impact_height_m: f64,
    pub impact_toe_m: f64,
    /// Normal coefficient of restitution.
    pub cor: f64,
}

/// The expected launch and club state after impact.
#[derive(Debug, Clone, Copy, PartialEq)]
#[allow(missing_docs)]
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

/// One impact case.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactCase {
    /// Case name.
    pub name: String,
    /// The club.
    pub club: Club,
    /// The ball (error cases may hold invalid values).
    pub ball: Ball,
    /// The delivery (error cases may hold invalid values).
    pub delivery: Delivery,
    /// The expected result, unless the case expects an error.
    pub expected: Option<ImpactExpected>,
    /// The expected error's name (`"off_face"`, `"no_approach"`, `"invalid_input"`, …), if any.
    pub expected_error: Option<String>,
}

pub(crate) fn parse(text: &str) -> Result<Vec<ImpactCase>, Error> {
    parse_cases(text, case)
}

fn case(c: &Fields<'_>) -> Result<ImpactCase, Error> {
    let (k, b, d) = (c.object("club")?, c.object("ball")?, c.object("delivery")?);
    Ok(ImpactCase {
        name: c.string("name")?,
        club: Club {
            mass_kg: k.num("mass_kg")?,
            inertia_kgm2: k.matrix3("inertia_kgm2")?,
            loft_deg: k.num("loft_deg")?,
            roll_radius_m: k.num("roll_radius_m")?,
            bulge_radius_m: k.num("bulge_radius_m")?,
            face_depth_radius_m: k.optional_num("ellipsoid_a_m")?,
            cg_to_face_m: k.vec3("cg_to_face_m")?,
        },
        ball: Ball {
            mass_kg: b.num("mass_kg")?,
            radius_m: b.num("radius_m")?,
        },
        delivery: Delivery {
            club_speed_mps: d.num("club_speed_mps")?,
            attack_angle_deg: d.num("attack_angle_deg")?,
            club_path_deg: d.num("club_path_deg")?,
            face_angle_deg: d.num("face_angle_deg")?,
            dynamic_loft_deg: d.num("dynamic_loft_deg")?,
            lie_deg: d.num("lie_deg")?,
            club_spin_radps: d.vec3("club_spin_radps")?,
            impact_height_m: d.num("impact_height_m")?,
            impact_toe_m: d.num("impact_toe_m")?,
            cor: d.num("cor")?,
        },
        expected: c
            .optional_object("expected")?
            .map(|e| expected(&e))
            .transpose()?,
        expected_error: c.optional_string("expected_error"),
    })
}

fn expected(e: &Fields<'_>) -> Result<ImpactExpected, Error> {
    Ok(ImpactExpected {
        ball_speed_mps: e.num("ball_speed_mps")?,
        launch_angle_deg: e.num("launch_angle_deg")?,
        launch_direction_deg: e.num("launch_direction_deg")?,
        spin_rpm: e.num("spin_rpm")?,
        backspin_rpm: e.num("backspin_rpm")?,
        sidespin_rpm: e.num("sidespin_rpm")?,
        spin_axis_deg: e.num("spin_axis_deg")?,
        smash_factor: e.num("smash_factor")?,
        ball_velocity_mps: e.vec3("ball_velocity_mps")?,
        ball_spin_radps: e.vec3("ball_spin_radps")?,
        club_velocity_mps: e.vec3("club_velocity_mps")?,
        club_spin_radps: e.vec3("club_spin_radps")?,
        impulse_ns: e.vec3("impulse_ns")?,
    })
}
