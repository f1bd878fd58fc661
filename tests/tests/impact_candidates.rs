//! The candidates for the gear effect's size (docs/impact.md §0.2 and §0.5), each varied alone
//! on the `driver` preset: spin per mm of strike height, spin axis per mm toward the toe, ball
//! speed 20/30 mm toward heel and toe and 20 mm above/below the face centre — the rows of the
//! table in docs/impact.md §0 — for 45 m/s, attack 0°, dynamic loft 12.8° and face 0° at the
//! contact point (TrackMan's convention), as `impact_strike_figure` measures them.
//!
//! `cargo test -p carry-tests --test impact_candidates -- --ignored --nocapture`

use carry_core::impact::{self, Solver};
use carry_core::units::{deg, to_deg, to_rpm};
use carry_core::{Ball, ClubSpec, Delivery, DeliveryConvention, FaceLocation, Preset};
use nalgebra::{Matrix3, Vector3};

/// (ball speed m/s, spin rpm, spin axis deg) at `h` up and `z` toward the toe.
fn launch(spec: &ClubSpec<f64>, h: f64, z: f64, club_spin: Vector3<f64>) -> (f64, f64, f64) {
    let Ok(club) = spec.validate() else {
        panic!("club")
    };
    let d = Delivery {
        club_speed_mps: 45.0,
        attack_angle_rad: 0.0,
        club_path_rad: 0.0,
        face_angle_rad: 0.0,
        dynamic_loft_rad: deg(12.8),
        lie_rad: 0.0,
        club_spin_radps: club_spin,
        location: FaceLocation {
            height_m: h,
            toe_m: z,
        },
    };
    let Ok(o) = d
        .strike_in(&club, DeliveryConvention::TrackMan)
        .and_then(|s| impact::solve(&club, &Ball::standard(), &s, Solver::Reduced))
    else {
        panic!("strike at {h}, {z}")
    };
    let l = o.launch;
    (
        l.ball_speed_mps,
        to_rpm(l.spin_radps),
        to_deg(l.spin_axis_rad),
    )
}

fn row(name: &str, spec: &ClubSpec<f64>, w: Vector3<f64>) {
    let at = |h: f64, z: f64| launch(spec, h, z, w);
    let c = at(0.0, 0.0);
    let speed = |h: f64, z: f64| (at(h, z).0 / c.0 - 1.0) * 100.0;
    let spin = (at(0.01, 0.0).1 - at(-0.01, 0.0).1) / c.1 * 100.0 / 20.0;
    let axis = (at(0.0, 0.02).2 - at(0.0, -0.02).2) / 40.0;
    println!(
        "| {name} | {spin:+.2} | {axis:+.2} (toe/heel 27.5 mm: {:+.1}/{:+.1}°) | {:+.1}/{:+.1} %; {:+.1}/{:+.1} % | {:+.1} / {:+.1} % |",
        at(0.0, 0.0275).2,
        at(0.0, -0.0275).2,
        speed(0.0, -0.02),
        speed(0.0, -0.03),
        speed(0.0, 0.02),
        speed(0.0, 0.03),
        speed(0.02, 0.0),
        speed(-0.02, 0.0),
    );
    assert!(spin.is_finite() && axis.is_finite());
}

#[test]
#[ignore = "prints the candidates' table of docs/impact.md §0.5"]
fn candidates_for_the_gear_effects_size() {
    let Some(p) = Preset::find("driver") else {
        panic!("driver")
    };
    let base = p.spec::<f64>();
    let still = Vector3::zeros();
    let with = |f: &dyn Fn(&mut ClubSpec<f64>)| {
        let mut s = base;
        f(&mut s);
        s
    };
    println!(
        "| candidate | spin %/mm height | axis °/mm toe | speed heel 20/30; toe 20/30 | speed above/below 20 mm |"
    );
    println!("|---|---|---|---|---|");
    row("the preset", &base, still);
    for (label, y) in [
        ("sweet spot 6 mm below the centre", 0.006),
        ("sweet spot at the centre (last session)", 0.0),
        ("sweet spot 3 mm above", -0.003),
        ("sweet spot 4 mm above", -0.004),
        ("sweet spot 6 mm above", -0.006),
    ] {
        row(label, &with(&|s| s.cg_to_face_m.y = y), still);
    }
    // the rest from last session's head (sweet spot at the centre)
    let centred = with(&|s| s.cg_to_face_m.y = 0.0);
    let from = |f: &dyn Fn(&mut ClubSpec<f64>)| {
        let mut s = centred;
        f(&mut s);
        s
    };
    for b in [0.254, 0.2794, 0.3556] {
        row(
            &format!("roll radius {b} m"),
            &from(&|s| s.roll_radius_m = b),
            still,
        );
    }
    for d in [0.032, 0.036, 0.044] {
        row(
            &format!("CG depth {d} m"),
            &from(&|s| s.cg_to_face_m.x = d),
            still,
        );
    }
    row(
        "vertical MOI 2,400 g cm2",
        &from(&|s| s.inertia_kgm2 = Matrix3::from_diagonal(&Vector3::new(3.4e-4, 4.8e-4, 2.4e-4))),
        still,
    );
    for w in [
        Vector3::new(0.0, 59.0, 20.0),
        Vector3::new(0.0, 0.0, 20.0),
        Vector3::new(0.0, 0.0, -20.0),
    ] {
        row(
            &format!("club spin ({}, {}, {}) rad/s", w.x, w.y, w.z),
            &centred,
            w,
        );
    }
}
