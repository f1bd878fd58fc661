//! Fuzz the impact entry points: club validation, ball, delivery → strike (in the seed's or
//! TrackMan's convention, whose conversion and its inverse are fuzzed too) or a strike given
//! directly, both solvers (every pivoting) and both contact laws (the compliant one with
//! any parameters, valid or not) in f32 and f64. A success must be finite.
#![no_main]

use carry_core::convention::{FaceAim, at_contact_point, centre_aim};
use carry_core::impact::{self, CompliantContact, ContactLaw, Solver};
use carry_core::linalg::Pivoting;
use carry_core::real::lit;
use carry_core::{
    Ball, BallMotion, ClubMotion, ClubSpec, Delivery, DeliveryConvention, FaceLocation, Real,
    Result, Strike,
};
use carry_fuzz::Bytes;
use libfuzzer_sys::fuzz_target;
use nalgebra::{Matrix3, Rotation3, Vector3};

fn v<T: Real>(a: [f64; 3]) -> Vector3<T> {
    Vector3::new(lit(a[0]), lit(a[1]), lit(a[2]))
}

fn run<T: Real>(b: &mut Bytes<'_>) -> Result<()> {
    let mass = b.param(0.05, 1.0);
    let diag = b.vec3(1e-5, 1e-3);
    let prod = b.vec3(-2e-4, 2e-4);
    let inertia = Matrix3::new(
        diag[0], prod[0], prod[1], prod[0], diag[1], prod[2], prod[1], prod[2], diag[2],
    );
    let spec = ClubSpec::<T> {
        mass_kg: lit(mass),
        inertia_kgm2: inertia.map(lit),
        loft_rad: lit(b.param(-0.5, 1.2)),
        roll_radius_m: lit(b.param(0.05, 2.0)),
        bulge_radius_m: lit(b.param(0.05, 2.0)),
        face_depth_radius_m: if b.flag() {
            Some(lit(b.param(0.05, 2.0)))
        } else {
            None
        },
        cg_to_face_m: v(b.vec3(-0.05, 0.06)),
        restitution: lit(b.param(0.0, 1.0)),
        contact: if b.flag() {
            ContactLaw::Rolling
        } else {
            // out-of-range values included: validation must name them
            let friction = match b.byte() % 4 {
                0 => 0.0,
                1 => f64::INFINITY,
                2 => b.param(-0.1, 1e6),
                _ => b.param(0.0, 2.0),
            };
            ContactLaw::Compliant(CompliantContact {
                friction: lit(friction),
                tangential_restitution: lit(b.param(-1.1, 1.1)),
                tangential_restitution_slope: lit(b.param(-5.0, 5.0)),
                restitution_speed_slope_spm: lit(b.param(-0.01, 0.05)),
                tangential_restitution_max: lit(b.param(-0.1, 1.1)),
            })
        },
        // the empirical spin-axis share: mostly the physics' 1, else any value around
        // (0, 1], out-of-range ones included (validation must name them)
        spin_axis_share: if b.flag() {
            lit(b.param(-0.1, 1.1))
        } else {
            T::one()
        },
    };
    if let ContactLaw::Compliant(law) = spec.contact {
        // the law's impulse on its own, with an arbitrary (usually not SPD) matrix and
        // arbitrary velocities: a typed error or a finite impulse, never a panic
        if b.flag() {
            let k = Matrix3::from_fn(|_, _| lit::<T>(b.param(-100.0, 100.0)));
            let u0 = v::<T>(b.vec3(-80.0, 80.0));
            let n = v::<T>(b.vec3(-1.0, 1.0));
            if let Ok((p, _)) = law.impulse(&k, &u0, &n, lit(b.param(0.0, 1.0))) {
                assert!(p.iter().all(|x| x.is_finite()), "non-finite impulse {p:?}");
            }
        }
    }
    let ball = Ball::<T>::new(lit(b.param(0.01, 0.1)), lit(b.param(0.01, 0.05)))?;
    let direct = b.flag();
    let club = spec.validate()?;
    let strike = if direct {
        let axis = b.vec3(-1.0, 1.0);
        let angle = b.param(-3.2, 3.2);
        let r = Rotation3::from_scaled_axis(Vector3::from(axis).normalize() * angle);
        let mut orientation: Matrix3<f64> = *r.matrix();
        if b.flag() {
            // an arbitrary (usually invalid) matrix
            orientation = Matrix3::from_fn(|_, _| b.param(-1.5, 1.5));
        }
        Strike::new(
            ClubMotion {
                velocity_mps: v(b.vec3(-80.0, 80.0)),
                spin_radps: v(b.vec3(-100.0, 100.0)),
                orientation: orientation.map(lit),
            },
            BallMotion {
                velocity_mps: v(b.vec3(-10.0, 10.0)),
                spin_radps: v(b.vec3(-500.0, 500.0)),
            },
            FaceLocation {
                height_m: lit(b.param(-0.04, 0.04)),
                toe_m: lit(b.param(-0.05, 0.05)),
            },
        )?
    } else {
        let delivery = Delivery::<T> {
            club_speed_mps: lit(b.param(0.0, 150.0)),
            attack_angle_rad: lit(b.param(-1.6, 1.6)),
            club_path_rad: lit(b.param(-1.6, 1.6)),
            face_angle_rad: lit(b.param(-1.6, 1.6)),
            dynamic_loft_rad: lit(b.param(-1.0, 1.6)),
            lie_rad: lit(b.param(-1.0, 1.0)),
            club_spin_radps: v(b.vec3(-100.0, 100.0)),
            location: FaceLocation {
                height_m: lit(b.param(-0.04, 0.04)),
                toe_m: lit(b.param(-0.05, 0.05)),
            },
        };
        // either convention; TrackMan's derives the centre orientation (convention.rs),
        // whose inverse must give the angles back where it succeeds
        if b.flag() {
            let convention = DeliveryConvention::TrackMan;
            let aim = FaceAim {
                dynamic_loft_rad: delivery.dynamic_loft_rad,
                face_angle_rad: delivery.face_angle_rad,
            };
            if let Ok(centre) = centre_aim(&club, &delivery.location, delivery.lie_rad, &aim) {
                assert!(centre.dynamic_loft_rad.is_finite() && centre.face_angle_rad.is_finite());
                if let Ok(back) =
                    at_contact_point(&club, &delivery.location, delivery.lie_rad, &centre)
                {
                    assert!(back.dynamic_loft_rad.is_finite() && back.face_angle_rad.is_finite());
                }
            }
            delivery.strike_in(&club, convention)?
        } else {
            delivery.strike(&club)?
        }
    };
    let solver = match b.byte() % 4 {
        0 => Solver::Reduced,
        1 => Solver::Full(Pivoting::Equilibrated),
        2 => Solver::Full(Pivoting::Partial),
        _ => Solver::Full(Pivoting::None),
    };
    let out = impact::solve(&club, &ball, &strike, solver)?;
    let l = out.launch;
    let all = [
        l.ball_speed_mps,
        l.launch_angle_rad,
        l.launch_direction_rad,
        l.spin_radps,
        l.backspin_radps,
        l.sidespin_radps,
        l.spin_axis_rad,
        l.smash_factor,
    ];
    assert!(all.iter().all(|x| x.is_finite()), "non-finite launch {l:?}");
    for vec in [
        out.ball.velocity_mps,
        out.ball.spin_radps,
        out.club.velocity_mps,
        out.club.spin_radps,
        out.impulse_ns,
    ] {
        assert!(
            vec.iter().all(|x| x.is_finite()),
            "non-finite outcome {out:?}"
        );
    }
    Ok(())
}

fuzz_target!(|data: &[u8]| {
    let mut b = Bytes::new(data);
    let _ = if b.flag() {
        run::<f32>(&mut b)
    } else {
        run::<f64>(&mut b)
    };
});
