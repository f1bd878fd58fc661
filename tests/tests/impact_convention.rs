//! The delivery conventions (`carry_core::convention`): TrackMan's face angle and dynamic
//! loft at the contact point → the club's centre orientation, and back. Property tests over
//! random clubs, locations and angles in f32 and f64, plus the closed forms.

use carry_core::contact::Contact;
use carry_core::convention::{FaceAim, at_contact_point, centre_aim};
use carry_core::real::{lit, to_f64};
use carry_core::units::deg;
use carry_core::{
    Ball, ClubHead, ClubSpec, Delivery, DeliveryConvention, Error, FaceLocation, Field, Preset,
    Real,
};
use nalgebra::Vector3;
use proptest::prelude::*;

fn club<T: Real>(loft_deg: f64, roll_m: f64, bulge_m: f64) -> ClubHead<T> {
    let mut spec = ClubSpec::<f64>::driver();
    spec.loft_rad = deg(loft_deg);
    spec.roll_radius_m = roll_m;
    spec.bulge_radius_m = bulge_m;
    let spec = ClubSpec::<T> {
        mass_kg: lit(spec.mass_kg),
        inertia_kgm2: spec.inertia_kgm2.map(lit),
        loft_rad: lit(spec.loft_rad),
        roll_radius_m: lit(spec.roll_radius_m),
        bulge_radius_m: lit(spec.bulge_radius_m),
        face_depth_radius_m: None,
        cg_to_face_m: spec.cg_to_face_m.map(lit),
        restitution: lit(spec.restitution),
        contact: spec.contact.cast(),
        spin_axis_share: lit(spec.spin_axis_share),
    };
    let Ok(head) = spec.validate() else {
        panic!("club")
    };
    head
}

fn aim<T: Real>(loft_deg: f64, face_deg: f64) -> FaceAim<T> {
    FaceAim {
        dynamic_loft_rad: deg(lit(loft_deg)),
        face_angle_rad: deg(lit(face_deg)),
    }
}

fn at<T: Real>(height_m: f64, toe_m: f64) -> FaceLocation<T> {
    FaceLocation {
        height_m: lit(height_m),
        toe_m: lit(toe_m),
    }
}

/// The contact normal in G of a seed-convention delivery.
fn normal<T: Real>(head: &ClubHead<T>, d: &Delivery<T>) -> Vector3<f64> {
    let Ok(strike) = d.strike(head) else {
        panic!("strike")
    };
    let Ok(c) = Contact::new(head, &Ball::standard(), &strike) else {
        panic!("contact")
    };
    c.normal.map(to_f64)
}

fn delivery<T: Real>(a: &FaceAim<T>, loc: FaceLocation<T>, lie_rad: T) -> Delivery<T> {
    Delivery {
        club_speed_mps: lit(45.0),
        attack_angle_rad: T::zero(),
        club_path_rad: T::zero(),
        face_angle_rad: a.face_angle_rad,
        dynamic_loft_rad: a.dynamic_loft_rad,
        lie_rad,
        club_spin_radps: Vector3::zeros(),
        location: loc,
    }
}

/// Random inputs: loft, radii, location inside the face, angles, lie.
fn inputs() -> impl Strategy<Value = (f64, f64, f64, f64, f64, f64, f64, f64)> {
    (
        5.0..40.0_f64,   // static loft (deg)
        0.2..0.5_f64,    // roll radius (m)
        0.2..0.5_f64,    // bulge radius (m)
        -0.03..0.03_f64, // height (m)
        -0.04..0.04_f64, // toe (m)
        0.0..45.0_f64,   // dynamic loft at the contact point (deg)
        -10.0..10.0_f64, // face angle at the contact point (deg)
        -10.0..10.0_f64, // lie (deg)
    )
}

fn round_trip<T: Real>(
    (loft, roll, bulge, h, z, dl, fa, lie): (f64, f64, f64, f64, f64, f64, f64, f64),
    tol_rad: f64,
) -> Result<(), TestCaseError> {
    let head = club::<T>(loft, roll, bulge);
    let loc = at::<T>(h, z);
    let lie = deg(lit::<T>(lie));
    let want = aim::<T>(dl, fa);
    let Ok(centre) = centre_aim(&head, &loc, lie, &want) else {
        return Err(TestCaseError::fail("centre_aim"));
    };
    let Ok(back) = at_contact_point(&head, &loc, lie, &centre) else {
        return Err(TestCaseError::fail("at_contact_point"));
    };
    let d_loft = to_f64(back.dynamic_loft_rad - want.dynamic_loft_rad);
    let d_face = to_f64(back.face_angle_rad - want.face_angle_rad);
    prop_assert!(d_loft.abs() <= tol_rad, "loft {d_loft}");
    prop_assert!(d_face.abs() <= tol_rad, "face {d_face}");
    // the contact normal of the centre orientation is the centre normal of the asked angles
    let n = normal(&head, &delivery(&centre, loc, lie));
    let n0 = normal(&head, &delivery(&want, FaceLocation::centre(), lie));
    prop_assert!((n - n0).norm() <= 4.0 * tol_rad, "{n:?} vs {n0:?}");
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    /// TrackMan → centre → TrackMan is the identity, and the centre orientation puts the
    /// contact normal where the asked angles point (f64 to 1e-12 rad).
    #[test]
    fn round_trip_f64(x in inputs()) {
        round_trip::<f64>(x, 1e-12)?;
    }

    /// The same in f32 (to 2e-5 rad ≈ 0.001°).
    #[test]
    fn round_trip_f32(x in inputs()) {
        round_trip::<f32>(x, 2e-5)?;
    }

    /// f32 and f64 agree to 2e-5 rad.
    #[test]
    fn f32_agrees_with_f64(x in inputs()) {
        let (loft, roll, bulge, h, z, dl, fa, lie) = x;
        let a64 = centre_aim(&club::<f64>(loft, roll, bulge), &at(h, z), deg(lie), &aim(dl, fa));
        let a32 = centre_aim(&club::<f32>(loft, roll, bulge), &at(h, z), deg(lie as f32), &aim(dl, fa));
        let (Ok(a64), Ok(a32)) = (a64, a32) else {
            return Err(TestCaseError::fail("conversion"));
        };
        prop_assert!((f64::from(a32.dynamic_loft_rad) - a64.dynamic_loft_rad).abs() <= 2e-5);
        prop_assert!((f64::from(a32.face_angle_rad) - a64.face_angle_rad).abs() <= 2e-5);
    }

    /// A centre strike, or any strike on a flat face, is the identity, bit for bit.
    #[test]
    fn centre_and_flat_faces_are_the_identity(x in inputs()) {
        let (loft, roll, bulge, h, z, dl, fa, lie) = x;
        let want = aim::<f64>(dl, fa);
        let curved = club::<f64>(loft, roll, bulge);
        let flat = club::<f64>(loft, f64::INFINITY, f64::INFINITY);
        for (head, loc) in [(&curved, FaceLocation::centre()), (&flat, at(h, z))] {
            prop_assert_eq!(centre_aim(head, &loc, deg(lie), &want), Ok(want));
            prop_assert_eq!(at_contact_point(head, &loc, deg(lie), &want), Ok(want));
        }
    }
}

/// Without lie, to first order: loft minus the roll's tilt, face minus the bulge's
/// (asin(ΔY/b), asin(ΔZ/c) on a sphere); exactly so for a pure height or toe offset.
#[test]
fn pure_offsets_turn_the_club_by_the_normals_tilt() {
    let head = club::<f64>(10.5, 0.30, 0.30);
    for h in [-0.02, -0.005, 0.003, 0.02] {
        let Ok(c) = centre_aim(&head, &at(h, 0.0), 0.0, &aim(12.8, 1.0)) else {
            panic!()
        };
        let want = deg(12.8) - (h / 0.30_f64).asin();
        assert!((c.dynamic_loft_rad - want).abs() < 1e-14, "{h}");
        assert!((c.face_angle_rad - deg(1.0)).abs() < 1e-14, "{h}");
    }
    for z in [-0.03, 0.01, 0.025] {
        let Ok(c) = centre_aim(&head, &at(0.0, z), 0.0, &aim(12.8, 0.0)) else {
            panic!()
        };
        // the toe's normal is turned right by β = asin(z/c); keeping its elevation δ, its
        // azimuth after the loft turn is atan(tan β / cos λ'), sin λ' = sin δ / cos β
        let beta = (z / 0.30_f64).asin();
        let lift = (deg(12.8_f64).sin() / beta.cos()).asin();
        let want = -(beta.tan() / lift.cos()).atan();
        assert!((c.face_angle_rad - want).abs() < 1e-14, "{z}");
    }
}

/// A delivery read in the seed's convention is unchanged; TrackMan's keeps everything but
/// the two angles.
#[test]
fn delivery_conversion_keeps_the_other_inputs() {
    let Some(p) = Preset::find("driver") else {
        panic!()
    };
    let Ok(head) = p.spec::<f64>().validate() else {
        panic!()
    };
    let mut d = p.typical.delivery::<f64>();
    d.location.toe_m = 0.015;
    d.face_angle_rad = deg(2.0);
    assert_eq!(
        d.in_seed_convention(&head, DeliveryConvention::SeedCentre),
        Ok(d)
    );
    let Ok(c) = d.in_seed_convention(&head, DeliveryConvention::TrackMan) else {
        panic!()
    };
    assert_eq!(
        (c.club_speed_mps, c.attack_angle_rad, c.location),
        (d.club_speed_mps, d.attack_angle_rad, d.location)
    );
    assert!(c.dynamic_loft_rad < d.dynamic_loft_rad && c.face_angle_rad < d.face_angle_rad);
}

/// Typed errors: non-finite inputs named, off the face, and an unreachable loft.
#[test]
fn errors_are_typed() {
    let head = club::<f64>(10.5, 0.30, 0.30);
    let bad = |r: Result<FaceAim<f64>, Error>, field: Field| {
        assert!(
            matches!(r, Err(Error::InvalidInput { field: f, .. }) if f == field),
            "{r:?}"
        );
    };
    bad(
        centre_aim(&head, &at(f64::NAN, 0.0), 0.0, &aim(12.0, 0.0)),
        Field::ImpactHeight,
    );
    bad(
        centre_aim(&head, &at(0.0, 0.01), 0.0, &aim(f64::INFINITY, 0.0)),
        Field::DynamicLoft,
    );
    bad(
        centre_aim(&head, &at(0.0, 0.01), f64::NAN, &aim(12.0, 0.0)),
        Field::Lie,
    );
    assert_eq!(
        centre_aim(&head, &at(0.0, 0.31), 0.0, &aim(12.0, 0.0)),
        Err(Error::OffFace)
    );
    // a normal tilted 40° toward the toe cannot reach a 60° elevation... but can reach 45°;
    // at 0.9 of the radius it is tilted ~64°: 80° of loft is out of reach
    bad(
        centre_aim(&head, &at(0.0, 0.27), 0.0, &aim(80.0, 0.0)),
        Field::DynamicLoft,
    );
}
