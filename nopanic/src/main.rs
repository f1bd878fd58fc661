//! The no-panic link check of issue 7 (see Cargo.toml and docs/robustness.md).
//!
//! Every input comes through [`black_box`], so the optimiser knows nothing about it: a
//! panic path in the core survives unless the code itself rules it out. The results go
//! back into `black_box` so nothing is dead code. Both precisions are linked. The flight
//! paths include the ground after the landing (bounces, hops, roll; issue 12). The C
//! API's entry points have their own image, `src/bin/ffi.rs` (issue 13).
#![no_std]
#![no_main]

use carry_core::aero::AeroModel;
use carry_core::air::{Air, Pressure, Weather};
use carry_core::flight::{Integrator, Recorder, Sample, fly};
use carry_core::ground::{CraterLaw, Ground, Surface, Turf};
use carry_core::impact::{self, CompliantContact, ContactLaw, Solver};
use carry_core::linalg::Pivoting;
use carry_core::scene::{Effects, Scene};
use carry_core::wind::Wind;
use carry_core::{
    Ball, BallMotion, ClubMotion, ClubSpec, Delivery, DeliveryConvention, FaceLocation, Launch,
    Real, Strike,
};
use core::hint::black_box;
use nalgebra::{Matrix3, Vector3};

/// An opaque value of the working precision.
#[inline(never)]
fn x<T: Real>(v: f64) -> T {
    black_box(carry_core::real::lit::<T>(black_box(v)))
}

fn v3<T: Real>(a: f64, b: f64, c: f64) -> Vector3<T> {
    Vector3::new(x(a), x(b), x(c))
}

fn club<T: Real>(contact: ContactLaw<T>) -> ClubSpec<T> {
    ClubSpec {
        mass_kg: x(0.2),
        inertia_kgm2: Matrix3::new(
            x(3e-4),
            x(1e-5),
            x(0.0),
            x(1e-5),
            x(4.2e-4),
            x(0.0),
            x(0.0),
            x(0.0),
            x(2.2e-4),
        ),
        loft_rad: x(0.18),
        roll_radius_m: x(0.3),
        bulge_radius_m: x(0.3),
        face_depth_radius_m: if black_box(false) {
            Some(x(0.25))
        } else {
            None
        },
        cg_to_face_m: v3(0.04, 0.0, 0.0),
        restitution: x(0.83),
        contact,
        // an empirical spin-axis share, so that its path is linked and proved too
        spin_axis_share: x(0.6),
    }
}

/// The seed's rolling contact and the compliant one, with opaque parameters.
fn laws<T: Real>() -> [ContactLaw<T>; 2] {
    [
        ContactLaw::Rolling,
        ContactLaw::Compliant(CompliantContact {
            friction: x(0.4),
            tangential_restitution: x(0.02),
            tangential_restitution_slope: x(0.25),
            tangential_restitution_max: x(0.25),
            restitution_speed_slope_spm: x(0.003),
        }),
    ]
}

/// Every impact entry point: validation, delivery → strike, a strike given directly, and
/// the solvers (reduced; full with each pivoting).
fn impact_paths<T: Real>() -> T {
    let mut acc = T::zero();
    for law in laws() {
        acc += impact_paths_with(black_box(law));
    }
    acc
}

fn impact_paths_with<T: Real>(law: ContactLaw<T>) -> T {
    let mut acc = T::zero();
    let Ok(head) = club::<T>(law).validate() else {
        return acc;
    };
    let Ok(ball) = Ball::new(x(0.04593), x(0.021336)) else {
        return acc;
    };
    let delivery = Delivery {
        club_speed_mps: x(45.0),
        attack_angle_rad: x(0.0),
        club_path_rad: x(0.0),
        face_angle_rad: x(0.0),
        dynamic_loft_rad: x(0.18),
        lie_rad: x(0.0),
        club_spin_radps: v3(0.0, 0.0, 0.0),
        location: FaceLocation {
            height_m: x(0.0),
            toe_m: x(0.01),
        },
    };
    let direct = Strike::new(
        ClubMotion {
            velocity_mps: v3(45.0, 0.0, 0.0),
            spin_radps: v3(0.0, 0.0, 1.0),
            orientation: Matrix3::identity().map(|e: T| black_box(e)),
        },
        BallMotion {
            velocity_mps: v3(0.0, 0.0, 0.0),
            spin_radps: v3(0.0, 0.0, 0.0),
        },
        FaceLocation {
            height_m: x(0.0),
            toe_m: x(0.0),
        },
    );
    // the named-club rule: a preset's typical delivery completed with a given loft (a flat
    // face strikes at that loft's turf height)
    let preset = &carry_core::PRESETS[black_box(3_usize) % carry_core::PRESETS.len()];
    let named = preset.completed::<T>(
        &carry_core::presets::GivenDelivery {
            dynamic_loft_rad: Some(x(0.3)),
            ..Default::default()
        },
        x(0.021_336),
    );
    acc += named.location.height_m + named.dynamic_loft_rad;
    // TrackMan's convention: the centre orientation derived from the contact point, and
    // back (`convention::centre_aim` / `at_contact_point` through `strike_in`)
    let convention = if black_box(true) {
        DeliveryConvention::TrackMan
    } else {
        DeliveryConvention::SeedCentre
    };
    let aim = carry_core::convention::FaceAim {
        dynamic_loft_rad: x(0.2),
        face_angle_rad: x(0.01),
    };
    if let Ok(c) = carry_core::convention::at_contact_point(&head, &delivery.location, x(0.0), &aim)
    {
        acc += c.dynamic_loft_rad + c.face_angle_rad;
    }
    let strikes = [
        delivery.strike(&head),
        direct,
        delivery.strike_in(&head, convention),
    ];
    let solvers = [
        Solver::Reduced,
        Solver::Full(Pivoting::Equilibrated),
        Solver::Full(Pivoting::Partial),
        Solver::Full(Pivoting::None),
    ];
    for strike in strikes.iter().flatten() {
        for solver in solvers {
            if let Ok(out) = impact::solve(&head, &ball, strike, black_box(solver)) {
                let l = black_box(out.launch);
                acc += l.ball_speed_mps + l.spin_axis_rad + l.smash_factor + out.impulse_ns.x;
                // impact → launch → flight, as a launch monitor chains them
                let back = Launch::from_motion(&out.ball);
                acc += back.backspin_radps;
            }
        }
    }
    acc
}

/// Every flight entry point: launch metrics → ball motion, scene preparation (density,
/// weather by pressure and by altitude, uniform and profile wind), the three integrators,
/// with and without a recorder.
fn flight_paths<T: Real>() -> T {
    let mut acc = T::zero();
    let ball = Ball::<T>::standard();
    let launch = Launch::from_spin_axis(x(70.0), x(0.19), x(0.0), x(280.0), x(0.05));
    let Ok(motion) = launch.ball_motion() else {
        return acc;
    };
    let air = match black_box(0_u8) {
        0 => Air::Density(x(1.225)),
        1 => Air::Weather(Weather {
            temperature_c: x(20.0),
            relative_humidity: x(0.5),
            pressure: Pressure::Pa(x(101_325.0)),
        }),
        _ => Air::Weather(Weather {
            temperature_c: x(20.0),
            relative_humidity: x(0.5),
            pressure: Pressure::Altitude(x(1600.0)),
        }),
    };
    let wind = match black_box(0_u8) {
        0 => Wind::None,
        1 => Wind::Uniform(v3(3.0, 0.0, -2.0)),
        _ => Wind::Profile {
            reference_mps: v3(3.0, 0.0, -2.0),
            reference_height_m: x(10.0),
            exponent: x(1.0 / 7.0),
        },
    };
    let aero = if black_box(true) {
        AeroModel::tour_2023()
    } else {
        AeroModel::quintavalla()
    };
    let scene = Scene {
        aero,
        effects: Effects {
            drag: black_box(true),
            lift: black_box(true),
            spin_decay: black_box(true),
        },
        air,
        wind,
        landing_height_m: x(0.0),
        time_limit_s: x(60.0),
        gravity_mps2: x(9.80665),
        launch_position_m: v3(0.0, 0.0, 0.0),
        ground: ground(),
    };
    let integrators = [
        Integrator::default(),
        Integrator::DormandPrince {
            rtol: x(1e-6),
            atol: x(1e-6),
            initial_step_s: x(0.1),
            max_step_s: x(1.0),
        },
        Integrator::Rk4 { step_s: x(0.01) },
        Integrator::Euler { step_s: x(0.001) },
    ];
    let mut buffer: heapless::Vec<Sample<T>, 64> = heapless::Vec::new();
    for integrator in integrators {
        if let Ok(out) = fly(&ball, &motion, &scene, &integrator, None) {
            acc += black_box(out).carry_m;
        }
    }
    if let Ok(mut rec) = Recorder::new(x(0.1), &mut buffer) {
        let flown = scene
            .prepare(&ball)
            .and_then(|p| p.fly(&motion, &black_box(Integrator::default()), Some(&mut rec)));
        if let Ok(out) = flown {
            acc += out.apex_m;
        }
        acc += rec.samples().last().map_or(T::zero(), |s| s.time_s);
    }
    acc
}

/// The ground after the landing (issue 12): none, each surface, a custom turf, level or
/// sloped; and one bounce through the public entry point.
fn ground<T: Real>() -> Option<Ground<T>> {
    let surface = match black_box(0_u8) {
        0 => Surface::FairwayFirm,
        1 => Surface::FairwaySoft,
        4 => Surface::FairwayTrackman,
        6 => Surface::FairwayJoint,
        2 => Surface::Rough,
        3 => Surface::Green { stimp_m: x(3.0) },
        _ => Surface::Custom(Turf {
            restitution: x(0.5),
            friction: x(0.4),
            rolling_resistance: x(0.1),
            crater_scale: x(1.0),
            crater_fade_mps: x(6.0),
            grass_drag_s2pm2: x(0.07),
            crater_law: if black_box(0_u8) == 0 {
                CraterLaw::Penner
            } else {
                CraterLaw::NormalTangential
            },
            grass_height_m: x(0.0127),
        }),
    };
    match black_box(1_u8) {
        0 => None,
        1 => Some(Ground::level(surface)),
        _ => Some(Ground {
            surface,
            normal: v3(0.05, 1.0, -0.02),
        }),
    }
}

fn bounce_paths<T: Real>() -> T {
    let Some(g) = ground::<T>() else {
        return T::zero();
    };
    match g.prepare(x(0.021_336)) {
        Ok(p) => match p.bounce(&v3(20.0, -15.0, 1.0), &v3(10.0, 5.0, 600.0)) {
            Ok(r) => r.velocity_mps.x + r.spin_radps.z,
            Err(_) => T::one(),
        },
        Err(_) => T::zero(),
    }
}

/// The estimator (issue 23): club data from ball data, with and without club data, on
/// opaque measurements, noise, prior and budget.
fn estimate_paths<T: Real>() -> T {
    use carry_core::estimate::{BallData, ClubData, Settings, estimate};
    let preset = &carry_core::PRESETS[black_box(0_usize) % carry_core::PRESETS.len()];
    let Ok(head) = preset.spec::<T>().validate() else {
        return T::zero();
    };
    let ball = Ball::<T>::standard();
    let measured = BallData {
        ball_speed_mps: x(66.0),
        launch_angle_rad: x(0.22),
        launch_direction_rad: x(0.01),
        spin_radps: x(280.0),
        spin_axis_rad: x(0.05),
    };
    let mut settings = Settings::<T>::typical(&preset.typical);
    settings.noise.ball.spin_radps = x(7.8);
    settings.prior.sd.club_path_rad = x(0.08);
    settings.max_iterations = black_box(30);
    settings.tolerance = x(0.1);
    let club = ClubData {
        club_speed_mps: if black_box(true) { Some(x(45.0)) } else { None },
        attack_angle_rad: if black_box(false) {
            Some(x(0.01))
        } else {
            None
        },
        club_path_rad: if black_box(false) { Some(x(0.0)) } else { None },
        face_angle_rad: if black_box(false) { Some(x(0.0)) } else { None },
        dynamic_loft_rad: if black_box(false) { Some(x(0.2)) } else { None },
    };
    match estimate(&head, &ball, &measured, &club, &settings) {
        Ok(e) => {
            let c = e.consistency;
            let checked = match e.checked() {
                Ok(_) => T::zero(),
                Err(_) => T::one(),
            };
            e.value.face_angle_rad + e.sd.impact_height_m + e.residual.spin_radps + c.chi2 + checked
        }
        Err(_) => T::one(),
    }
}

/// The launch from the flight (issue 36): spin and axis fitted to opaque summaries and a
/// track, with and without wind and air density.
fn launch_fit_paths<T: Real>() -> T {
    use carry_core::launch_fit::{
        Datum, LaunchValues, Observations, Settings, TrackPoint, Workspace, fit_launch,
    };
    let measured = LaunchValues {
        ball_speed_mps: Some(Datum::new(x(66.0), x(0.2))),
        launch_angle_rad: Some(Datum::new(x(0.22), x(0.004))),
        launch_direction_rad: Some(Datum::new(x(0.01), x(0.005))),
        spin_radps: None,
        spin_axis_rad: None,
    };
    let mut obs = Observations::<T> {
        apex_height_m: Some(Datum::new(x(30.0), x(0.5))),
        carry_m: Some(Datum::new(x(210.0), x(1.0))),
        side_m: Some(Datum::new(x(5.0), x(0.5))),
        ..Observations::default()
    };
    let _ = obs.track.push(TrackPoint {
        time_s: x(0.5),
        position_m: v3(30.0, 6.0, 0.3),
        sd_m: x(0.1),
    });
    let settings = Settings::<T> {
        fit_wind: black_box(false),
        fit_air_density: black_box(false),
        max_iterations: black_box(30),
        ..Settings::default()
    };
    let mut ws = Workspace::<T>::new();
    match fit_launch(
        &Ball::standard(),
        &Scene::default(),
        &measured,
        &obs,
        &settings,
        &mut ws,
    ) {
        Ok(f) => f.value.spin_radps + f.sd.spin_axis_rad,
        Err(_) => T::one(),
    }
}

#[cortex_m_rt::entry]
fn main() -> ! {
    // The negative control (`--features canary`): an index the optimiser cannot check, so
    // the link must fail — proof that the check catches a reachable panic.
    #[cfg(feature = "canary")]
    black_box([1_u8; 4][black_box(7_usize) % black_box(8_usize)]);
    loop {
        black_box(impact_paths::<f32>());
        black_box(impact_paths::<f64>());
        black_box(flight_paths::<f32>());
        black_box(flight_paths::<f64>());
        black_box(bounce_paths::<f32>());
        black_box(bounce_paths::<f64>());
        black_box(estimate_paths::<f32>());
        black_box(estimate_paths::<f64>());
        black_box(launch_fit_paths::<f32>());
        black_box(launch_fit_paths::<f64>());
    }
}

#[cfg(not(feature = "diagnose"))]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo<'_>) -> ! {
    unsafe extern "C" {
        /// Never defined: referencing it fails the link.
        fn carry_core_reached_a_panic_path() -> !;
    }
    // SAFETY: never runs; the symbol does not exist, so an image that still calls the
    // panic handler does not link.
    unsafe { carry_core_reached_a_panic_path() }
}

#[cfg(feature = "diagnose")]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo<'_>) -> ! {
    loop {
        core::hint::spin_loop();
    }
}
