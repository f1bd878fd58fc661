//! Bounce and roll after the landing (issue 12), through the public API: the published
//! targets, the invariants as property tests, and the error paths.

use carry_core::ground::{Ground, RunEnd, Surface, Turf};
use carry_core::units::{deg, rpm};
use carry_core::{Ball, BallMotion, Error, FlightOutcome, Integrator, Launch, Real, Scene, fly};
use nalgebra::Vector3;
use proptest::prelude::*;

const MPH: f64 = 0.447_04;
const YD: f64 = 0.9144;

fn launch<T: Real>(
    speed_mph: f64,
    angle_deg: f64,
    dir_deg: f64,
    back: f64,
    side: f64,
) -> BallMotion<T> {
    Launch {
        ball_speed_mps: nalgebra::convert::<f64, T>(speed_mph * MPH),
        launch_angle_rad: deg(nalgebra::convert(angle_deg)),
        launch_direction_rad: deg(nalgebra::convert(dir_deg)),
        backspin_radps: rpm(nalgebra::convert(back)),
        sidespin_radps: rpm(nalgebra::convert(side)),
    }
    .ball_motion()
    .expect("valid launch")
}

fn go<T: Real>(m: &BallMotion<T>, ground: Option<Ground<T>>) -> FlightOutcome<T> {
    go_with(m, ground, carry_core::aero::AeroModel::default())
}

fn go_with<T: Real>(
    m: &BallMotion<T>,
    ground: Option<Ground<T>>,
    aero: carry_core::aero::AeroModel<T>,
) -> FlightOutcome<T> {
    let scene = Scene {
        ground,
        aero,
        ..Scene::default()
    };
    fly(&Ball::standard(), m, &scene, &Integrator::default(), None).expect("shot")
}

/// TrackMan PGA Tour 2023 averages (../shared/data/trackman_tour_2023.csv).
fn tour_driver<T: Real>() -> BallMotion<T> {
    launch(171.0, 10.4, 0.0, 2545.0, 0.0)
}
fn tour_pw<T: Real>() -> BallMotion<T> {
    launch(104.0, 23.7, 0.0, 9316.0, 0.0)
}

fn roll_yd<T: Real>(m: &BallMotion<T>, ground: Ground<T>) -> (f64, FlightOutcome<T>) {
    // The targets are stated for TrackMan's landings (the driver at 39°): the seed's
    // aerodynamics land the tour driver there (38.9°); the calibrated model lands it
    // steeper (docs/aero.md), which is an aerodynamic matter, not the ground's.
    let out = go_with(m, Some(ground), carry_core::aero::AeroModel::quintavalla());
    let roll = out.ground.expect("a ground gives a rollout").roll_m;
    (carry_core::real::to_f64(roll) / YD, out)
}

/// The targets, in f64 and f32: a tour driver landing near 38° on a firm fairway
/// rolls 20–30 yd; a tour wedge landing near 52° with 7,000+ rpm on a green stops within a
/// few yards (or spins back).
fn targets<T: Real>() {
    let (driver, out) = roll_yd(&tour_driver::<T>(), Ground::level(Surface::FairwayFirm));
    let land = carry_core::real::to_f64(out.landing_angle_rad).to_degrees();
    assert!((36.0..41.0).contains(&land), "driver lands at {land}°");
    assert!((20.0..30.0).contains(&driver), "driver rolls {driver} yd");
    let (wedge, out) = roll_yd(&tour_pw::<T>(), Ground::level(Surface::green()));
    let land = carry_core::real::to_f64(out.landing_angle_rad).to_degrees();
    let spin = carry_core::real::to_f64(out.landing_spin_radps) * 60.0 / std::f64::consts::TAU;
    assert!(
        land > 50.0 && spin > 7000.0,
        "wedge lands at {land}°, {spin} rpm"
    );
    assert!((-5.0..3.0).contains(&wedge), "wedge rolls {wedge} yd");
}

#[test]
fn published_targets_f64() {
    targets::<f64>();
}

#[test]
fn published_targets_f32() {
    targets::<f32>();
}

#[test]
fn carry_keeps_its_meaning() {
    // The flight part of the outcome is bit-identical with and without a ground.
    let m = tour_driver::<f64>();
    let without = go(&m, None);
    let with = go(&m, Some(Ground::level(Surface::FairwayFirm)));
    assert!(without.ground.is_none());
    assert_eq!(
        FlightOutcome {
            ground: None,
            ..with
        },
        without
    );
    let g = with.ground.expect("rollout");
    assert!(g.total_m > with.carry_m && g.time_to_rest_s > with.flight_time_s);
    assert_eq!(g.end, RunEnd::Rest);
}

#[test]
fn vertical_drop_without_spin_does_not_travel() {
    for surface in [
        Surface::FairwayFirm,
        Surface::FairwaySoft,
        Surface::Rough,
        Surface::green(),
        Surface::FairwayTrackman,
        Surface::FairwayJoint,
    ] {
        let scene = Scene {
            launch_position_m: Vector3::new(3.0, 2.0, -1.0),
            ground: Some(Ground::level(surface)),
            ..Scene::default()
        };
        let m = BallMotion {
            velocity_mps: Vector3::new(0.0, -3.0, 0.0),
            spin_radps: Vector3::zeros(),
        };
        let out = fly(&Ball::standard(), &m, &scene, &Integrator::default(), None).expect("drop");
        let g = out.ground.expect("rollout");
        assert_eq!((g.rest_position_m.x, g.rest_position_m.z), (3.0, -1.0));
        assert_eq!(g.roll_m, 0.0);
        assert!(g.bounces >= 1, "a 2 m drop bounces");
    }
}

#[test]
fn steeper_than_the_resistance_rolls_to_the_time_cap() {
    // A stimp-13 green (ρ ≈ 0.06) tilted 10° (tan = 0.18): it never stops.
    let green = Surface::Green {
        stimp_m: 13.0 * 0.3048,
    };
    let out = go(
        &tour_pw::<f64>(),
        Some(Ground::sloped(green, deg(10.0), deg(90.0))),
    );
    let g = out.ground.expect("rollout");
    assert_eq!(g.end, RunEnd::StillRolling);
    assert!(g.time_to_rest_s.is_finite() && g.rest_position_m.iter().all(|x| x.is_finite()));
    // The same green at 2° holds the ball.
    let out = go(
        &tour_pw::<f64>(),
        Some(Ground::sloped(green, deg(2.0), deg(90.0))),
    );
    assert_eq!(out.ground.expect("rollout").end, RunEnd::Rest);
}

#[test]
fn absurd_surfaces_are_named_errors() {
    let turf = |restitution, friction, rolling_resistance| Turf {
        restitution,
        friction,
        rolling_resistance,
        crater_scale: 1.0,
        crater_fade_mps: carry_core::ground::bounce::CRATER_FADE_NORMAL_SPEED_MPS,
        grass_drag_s2pm2: carry_core::ground::surface::GRASS_DRAG_S2PM2,
        crater_law: carry_core::ground::CraterLaw::Penner,
        grass_height_m: carry_core::ground::STOP_HEIGHT_M,
    };
    for (t, field) in [
        (turf(1.01, 0.4, 0.1), carry_core::Field::GroundRestitution),
        (turf(0.5, -0.4, 0.1), carry_core::Field::GroundFriction),
        (
            turf(0.5, 0.4, f64::NAN),
            carry_core::Field::RollingResistance,
        ),
        (
            Turf {
                grass_height_m: -1e-3,
                ..turf(0.5, 0.4, 0.1)
            },
            carry_core::Field::GrassHeight,
        ),
        (
            Turf {
                grass_height_m: 0.3,
                ..turf(0.5, 0.4, 0.1)
            },
            carry_core::Field::GrassHeight,
        ),
        (
            Turf {
                grass_height_m: f64::INFINITY,
                ..turf(0.5, 0.4, 0.1)
            },
            carry_core::Field::GrassHeight,
        ),
    ] {
        let scene = Scene {
            ground: Some(Ground::level(Surface::Custom(t))),
            ..Scene::default()
        };
        let err = fly(
            &Ball::standard(),
            &tour_driver(),
            &scene,
            &Integrator::default(),
            None,
        );
        assert!(
            matches!(err, Err(Error::InvalidInput { field: f, .. }) if f == field),
            "{err:?}"
        );
    }
}

/// The grass height (issue 37) only decides where the bouncing ends: the bounces up to
/// there are the same, so a taller grass never adds a bounce, and a rebound that stops
/// in it leaves the ball to skid and roll. The presets: Penner's 5 mm on a green, the
/// 1/2-inch cut on every fairway, 1.5 inches in the rough.
#[test]
fn taller_grass_never_adds_a_bounce() {
    use carry_core::ground::surface::{
        FAIRWAY_GRASS_HEIGHT_M, GREEN_GRASS_HEIGHT_M, ROUGH_GRASS_HEIGHT_M,
    };
    let grass = |s: Surface<f64>| s.turf().expect("turf").grass_height_m;
    assert_eq!(grass(Surface::green()), GREEN_GRASS_HEIGHT_M);
    assert_eq!(grass(Surface::green()), carry_core::ground::STOP_HEIGHT_M);
    for s in [
        Surface::FairwayFirm,
        Surface::FairwaySoft,
        Surface::FairwayTrackman,
        Surface::FairwayJoint,
    ] {
        assert_eq!(grass(s), FAIRWAY_GRASS_HEIGHT_M);
    }
    assert_eq!(grass(Surface::Rough), ROUGH_GRASS_HEIGHT_M);
    for m in [
        tour_driver::<f64>(),
        tour_pw(),
        launch(147.4, 8.7, 0.0, 2258.0, 0.0),
        launch(70.0, 3.0, 0.0, -500.0, 0.0),
    ] {
        for base in [
            Surface::FairwayFirm,
            Surface::FairwayTrackman,
            Surface::Rough,
        ] {
            let mut last: Option<u32> = None;
            for h in [0.0, 0.002, 0.005, 0.0127, 0.03, 0.1, 0.2] {
                let turf = Turf {
                    grass_height_m: h,
                    ..base.turf().expect("turf")
                };
                let g = go(&m, Some(Ground::level(Surface::Custom(turf))))
                    .ground
                    .expect("rollout");
                assert!(g.total_m.is_finite() && g.end == RunEnd::Rest, "{h}: {g:?}");
                if let Some(b) = last {
                    assert!(g.bounces <= b, "{base:?} {h}: {} > {b}", g.bounces);
                }
                last = Some(g.bounces);
            }
        }
    }
}

#[test]
fn the_recording_includes_bounces_and_roll() {
    let mut buffer = heapless::Vec::<carry_core::Sample<f64>, 2048>::new();
    let mut rec = carry_core::Recorder::new(0.02, &mut buffer).expect("recorder");
    let scene = Scene {
        ground: Some(Ground::level(Surface::FairwayFirm)),
        ..Scene::default()
    };
    let out = fly(
        &Ball::standard(),
        &tour_driver(),
        &scene,
        &Integrator::default(),
        Some(&mut rec),
    )
    .expect("shot");
    let g = out.ground.expect("rollout");
    let s = rec.samples();
    let last = s.last().expect("samples");
    assert_eq!(last.position_m, g.rest_position_m);
    assert_eq!(last.time_s, g.time_to_rest_s);
    let after: Vec<_> = s.iter().filter(|x| x.time_s > out.flight_time_s).collect();
    assert!(after.iter().any(|x| x.position_m.y > 0.5), "a bounce rises");
    assert!(
        s.windows(2).all(|w| w[1].time_s >= w[0].time_s),
        "time runs forward"
    );
    assert!(!rec.is_full());
    // Recording changes nothing.
    assert_eq!(
        FlightOutcome {
            recording_full: false,
            ..out
        },
        go(&tour_driver(), Some(Ground::level(Surface::FairwayFirm)))
    );
}

/// Any recording interval keeps the samples in time order, across the flight, the hops
/// (each starts its sample count after the bounce) and the roll.
#[test]
fn samples_stay_in_time_order_for_any_interval() {
    let scene = Scene {
        ground: Some(Ground::level(Surface::FairwayFirm)),
        ..Scene::default()
    };
    for interval in [4.744949279081164e243, 1e30, 7.0, 0.3, 1e-3, 1e-200] {
        let mut buffer = heapless::Vec::<carry_core::Sample<f64>, 512>::new();
        let mut rec = carry_core::Recorder::new(interval, &mut buffer).expect("recorder");
        let out = fly(
            &Ball::standard(),
            &tour_driver(),
            &scene,
            &Integrator::default(),
            Some(&mut rec),
        )
        .expect("shot");
        let s = rec.samples();
        assert!(
            s.windows(2).all(|w| w[1].time_s >= w[0].time_s),
            "interval {interval} s: {:?}",
            s.iter().map(|x| x.time_s).collect::<Vec<_>>()
        );
        let end = out.ground.expect("rollout").time_to_rest_s;
        assert!(s.iter().all(|x| x.time_s >= 0.0 && x.time_s <= end));
    }
}

/// A fuzz find: a ball landing at t ≈ 1e-285 s with a 5e243 s recording interval. The
/// hop's first sample index, offset/interval, underflowed to 0, and the hop recorded a
/// sample at t = 0 after the landing.
#[test]
fn a_hop_records_nothing_before_it_starts() {
    let scene = Scene {
        landing_height_m: -2.025767951045099e-296,
        ground: Some(Ground {
            surface: Surface::FairwaySoft,
            normal: Vector3::new(-0.5763179980163271, 1.3167315175097276, -0.7063859006637674),
        }),
        ..Scene::default()
    };
    let motion = BallMotion {
        velocity_mps: Vector3::new(20.022049286640726, -2.0022049286640726e-11, 0.0),
        spin_radps: Vector3::new(0.0, 400.0, -300.0),
    };
    let mut buffer = heapless::Vec::<carry_core::Sample<f64>, 64>::new();
    let mut rec = carry_core::Recorder::new(4.744949279081164e243, &mut buffer).expect("rec");
    let integrator = Integrator::dormand_prince(4e-5);
    let out = fly(
        &Ball::standard(),
        &motion,
        &scene,
        &integrator,
        Some(&mut rec),
    );
    let out = out.expect("shot");
    let times: Vec<f64> = rec.samples().iter().map(|x| x.time_s).collect();
    assert!(out.flight_time_s < 1e-200, "{out:?}");
    assert!(times.windows(2).all(|w| w[1] >= w[0]), "{times:?}");
}

fn energy(v: &Vector3<f64>, w: &Vector3<f64>) -> f64 {
    let ball = Ball::<f64>::standard();
    0.5 * ball.mass_kg() * v.norm_squared() + 0.5 * ball.inertia_kgm2() * w.norm_squared()
}

fn surfaces() -> impl Strategy<Value = Surface<f64>> {
    prop_oneof![
        Just(Surface::FairwayFirm),
        Just(Surface::FairwaySoft),
        Just(Surface::Rough),
        Just(Surface::FairwayTrackman),
        Just(Surface::FairwayJoint),
        (2.0..4.5_f64).prop_map(|s| Surface::Green { stimp_m: s }),
        (0.0..=1.0_f64, 0.0..2.0_f64, 0.0..1.0_f64, 0.0..3.0_f64).prop_map(|(e, mu, rho, k)| {
            Surface::Custom(Turf {
                restitution: e,
                friction: mu,
                rolling_resistance: rho,
                crater_scale: k,
                crater_fade_mps: carry_core::ground::bounce::CRATER_FADE_NORMAL_SPEED_MPS,
                grass_drag_s2pm2: carry_core::ground::surface::GRASS_DRAG_S2PM2,
                crater_law: carry_core::ground::CraterLaw::Penner,
                grass_height_m: carry_core::ground::STOP_HEIGHT_M,
            })
        }),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Kinetic energy (translation + rotation) never increases at a bounce.
    #[test]
    fn energy_never_increases_at_a_bounce(
        surface in surfaces(),
        slope in 0.0..40.0_f64, dir in -180.0..180.0_f64,
        v in prop::array::uniform3(-60.0..60.0_f64),
        w in prop::array::uniform3(-1200.0..1200.0_f64),
    ) {
        let ground = Ground::sloped(surface, deg(slope), deg(dir))
            .prepare(Ball::<f64>::standard().radius_m())
            .expect("valid ground");
        let v = Vector3::from(v);
        let w = Vector3::from(w);
        // Only impacts: the ball moves into the ground.
        prop_assume!(v.dot(&ground.normal()) < 0.0);
        let r = ground.bounce(&v, &w).expect("finite");
        let (before, after) = (energy(&v, &w), energy(&r.velocity_mps, &r.spin_radps));
        prop_assert!(after <= before * (1.0 + 1e-12), "{before} → {after}");
        // Off the ground, to rounding.
        let out = r.velocity_mps.dot(&ground.normal());
        prop_assert!(out >= -1e-12 * v.norm(), "rebounds off the ground: {out}");
    }

    /// Forward-rolling shots roll further on firmer ground (firm fairway > soft > rough).
    #[test]
    fn roll_increases_with_firmness(
        speed in 120.0..175.0_f64, angle in 8.0..16.0_f64, spin in 1800.0..3500.0_f64,
    ) {
        let m = launch::<f64>(speed, angle, 0.0, spin, 0.0);
        let roll = |s| roll_yd(&m, Ground::level(s)).0;
        let (firm, soft, rough) = (roll(Surface::FairwayFirm), roll(Surface::FairwaySoft), roll(Surface::Rough));
        prop_assert!(firm > soft && soft > rough, "{firm} {soft} {rough}");
    }

    /// Uphill rolls less: the roll decreases as the ground rises more steeply towards the
    /// target.
    #[test]
    fn roll_decreases_uphill(
        speed in 130.0..175.0_f64, spin in 1800.0..3500.0_f64,
        a in 0.0..6.0_f64, more in 0.5..4.0_f64,
    ) {
        let m = launch::<f64>(speed, 11.0, 0.0, spin, 0.0);
        let roll = |slope: f64| roll_yd(&m, Ground::sloped(Surface::FairwayFirm, deg(slope), 0.0)).0;
        let (gentle, steep) = (roll(a), roll(a + more));
        prop_assert!(steep < gentle, "{a}°: {gentle} yd, {}°: {steep} yd", a + more);
    }

    /// Left and right mirror: a mirrored shot on mirrored ground rests at the mirrored
    /// point.
    #[test]
    fn mirror_symmetry(
        speed in 80.0..175.0_f64, angle in 8.0..30.0_f64, dir in -6.0..6.0_f64,
        back in 1500.0..9000.0_f64, side in -1500.0..1500.0_f64,
        slope in 0.0..4.0_f64, sdir in -180.0..180.0_f64, surface in surfaces(),
    ) {
        let rest = |d: f64, s: f64, sd: f64| {
            let out = go(&launch::<f64>(speed, angle, d, back, s), Some(Ground::sloped(surface, deg(slope), deg(sd))));
            out.ground.expect("rollout").rest_position_m
        };
        let (a, b) = (rest(dir, side, sdir), rest(-dir, -side, -sdir));
        let scale = 1.0 + a.x.abs();
        prop_assert!((a.x - b.x).abs() <= 1e-6 * scale, "{a} vs {b}");
        prop_assert!((a.z + b.z).abs() <= 1e-6 * scale, "{a} vs {b}");
    }
}

/// Issue 21: a ball launched at or below the horizon from the turf meets the ground at
/// once on a ground (carry 0, the run-out from the launch) and is `NoLanding` without one;
/// a topped drive totals what TrackMan's do (50–135 yd), far short of a struck drive.
fn topped<T: Real>() {
    let fairway = Ground::level(Surface::<T>::FairwayFirm);
    for (speed, angle, spin) in [
        (80.0, -2.0, 300.0),
        (100.0, 0.0, 1000.0),
        (120.0, -1.0, 500.0),
    ] {
        let m = launch::<T>(speed, angle, 0.0, spin, 0.0);
        let Ok(out) = fly(
            &Ball::standard(),
            &m,
            &Scene {
                ground: Some(fairway),
                ..Scene::default()
            },
            &Integrator::default(),
            None,
        ) else {
            panic!("topped {speed} mph {angle}°")
        };
        assert_eq!(out.carry_m, T::zero());
        assert_eq!(out.flight_time_s, T::zero());
        let g = out.ground.expect("a rollout");
        let total = carry_core::real::to_f64(g.total_m) / YD;
        assert!(
            (50.0..=140.0).contains(&total),
            "{speed} mph {angle}°: {total:.1} yd"
        );
        assert_eq!(g.end, RunEnd::Rest);
        let bare = fly(
            &Ball::standard(),
            &m,
            &Scene::default(),
            &Integrator::default(),
            None,
        );
        assert_eq!(bare.err(), Some(Error::NoLanding));
    }
    // On a tee the same launch flies a little first, then runs out.
    let m = launch::<T>(100.0, -2.0, 0.0, 1000.0, 0.0);
    let teed = Scene {
        launch_position_m: Vector3::new(T::zero(), nalgebra::convert(0.05), T::zero()),
        ground: Some(fairway),
        ..Scene::default()
    };
    let Ok(out) = fly(&Ball::standard(), &m, &teed, &Integrator::default(), None) else {
        panic!("teed")
    };
    assert!(out.carry_m > T::zero() && out.ground.expect("a rollout").total_m > out.carry_m);
}

#[test]
fn topped_shots_f64() {
    topped::<f64>();
}

#[test]
fn topped_shots_f32() {
    topped::<f32>();
}

/// Issue 21: f32 within 1 cm of f64 on carry and total, at each precision's default
/// fidelity, for topped and low shots that skip in many low hops (launched from −3° to
/// 8°, topspin to 4,000 rpm of backspin, 60–160 mph) on every surface. Before the hops'
/// tolerance cap (`HOP_MAX_TOLERANCE`) a topped 160 mph drive's totals differed by 1.5 m,
/// and before the grazing landings' redone step (`GRAZING_LANDING_RAD`) by up to 4.8 cm.
#[test]
fn topped_and_low_shots_agree_in_f32_and_f64() {
    fn surface<T: Real>(i: usize) -> Surface<T> {
        [
            Surface::FairwayFirm,
            Surface::FairwaySoft,
            Surface::Rough,
            Surface::green(),
            Surface::FairwayTrackman,
            Surface::FairwayJoint,
        ][i]
    }
    let mut worst = (0.0_f64, String::new());
    for i in 0..6 {
        for speed in [60.0, 85.0, 110.0, 135.0, 160.0] {
            for angle in [-3.0, -1.0, 0.0, 0.5, 1.0, 2.0, 5.0, 8.0] {
                for spin in [-500.0, 0.0, 300.0, 1500.0, 4000.0] {
                    let o64 = go(
                        &launch::<f64>(speed, angle, 0.0, spin, 0.0),
                        Some(Ground::level(surface(i))),
                    );
                    let o32 = go(
                        &launch::<f32>(speed, angle, 0.0, spin, 0.0),
                        Some(Ground::level(surface(i))),
                    );
                    let total64 = o64.ground.expect("rollout").total_m;
                    let total32 = f64::from(o32.ground.expect("rollout").total_m);
                    let d = (total32 - total64)
                        .abs()
                        .max((f64::from(o32.carry_m) - o64.carry_m).abs());
                    if d > worst.0 {
                        let name = format!("{:?}", surface::<f64>(i));
                        worst = (d, format!("{name} {speed} mph {angle}° {spin} rpm"));
                    }
                }
            }
        }
    }
    assert!(worst.0 <= 0.01, "{:.4} m: {}", worst.0, worst.1);
}

/// Issue 21: shallow landings no longer run away. The example (101.5 mph, 8.1°,
/// 2,626 rpm: lands near 15°, TrackMan 40 yd of roll; issue 12's ground gave 97) rolls
/// under 60 yd, and a drive's roll falls as its landing steepens.
#[test]
fn shallow_landings_roll_like_trackmans() {
    let m = launch::<f64>(101.5, 8.1, 0.0, 2626.0, 0.0);
    let (roll, out) = roll_yd(&m, Ground::level(Surface::FairwayFirm));
    assert!(out.landing_angle_rad.to_degrees() < 16.0);
    assert!((25.0..60.0).contains(&roll), "{roll:.1} yd");
    let mut last = f64::INFINITY;
    for (angle, spin) in [
        (8.1, 2626.0),
        (12.0, 3000.0),
        (16.0, 4500.0),
        (26.0, 8000.0),
    ] {
        let (r, _) = roll_yd(
            &launch::<f64>(130.0, angle, 0.0, spin, 0.0),
            Ground::level(Surface::FairwayFirm),
        );
        assert!(r < last, "{angle}°: {r:.1} yd after {last:.1}");
        last = r;
    }
}
