//! Property tests of the run-out (issue 20): random scenes with a ground never return a
//! non-finite figure, on level ground the roll never gains mechanical energy, and on a
//! slope it gains no more than gravity gives. Every surface, slopes up to the maximum,
//! no wind, uniform wind and a profile, every integrator, f32 and f64, recorder on and off.

use carry_core::ground::{Ground, MAX_SLOPE_RAD, Surface, Turf};
use carry_core::real::{lit, to_f64};
use carry_core::{
    Ball, Error, FlightOutcome, Integrator, Launch, Real, Recorder, Sample, Scene, Wind, fly,
};
use nalgebra::Vector3;
use proptest::prelude::*;

/// One random scene and shot, in f64; converted to the precision under test.
#[derive(Debug, Clone)]
struct Case {
    speed_mps: f64,
    angle_rad: f64,
    direction_rad: f64,
    backspin_radps: f64,
    sidespin_radps: f64,
    surface: u8,
    stimp_m: f64,
    turf: [f64; 5],
    slope_rad: f64,
    slope_direction_rad: f64,
    wind: u8,
    wind_mps: [f64; 3],
    landing_height_m: f64,
    integrator: u8,
    step_s: f64,
    tolerance: f64,
    record: bool,
}

fn cases() -> impl Strategy<Value = Case> {
    (
        (
            5.0..90.0,
            -0.3..1.4,
            -0.3..0.3,
            -300.0..1300.0,
            -400.0..400.0,
        ),
        (
            0u8..8,
            0.31..9.0,
            [0.0..1.0, 0.0..2.0, 0.0..1.0, 0.0..3.0, 0.0..0.05],
        ),
        (
            0.0..1.0,
            -3.2..3.2,
            0u8..3,
            [-15.0..15.0, -3.0..3.0, -15.0..15.0],
        ),
        (-5.0..5.0, 0u8..3, 1e-3..0.05, 1e-6..1e-3, any::<bool>()),
    )
        .prop_map(|(l, s, w, n)| Case {
            speed_mps: l.0,
            angle_rad: l.1,
            direction_rad: l.2,
            backspin_radps: l.3,
            sidespin_radps: l.4,
            surface: s.0,
            stimp_m: s.1,
            turf: s.2,
            // Level in a quarter of the cases; otherwise up to the steepest accepted.
            slope_rad: if w.0 < 0.25 {
                0.0
            } else {
                (w.0 - 0.25) / 0.75 * MAX_SLOPE_RAD * 0.999
            },
            slope_direction_rad: w.1,
            wind: w.2,
            wind_mps: w.3,
            landing_height_m: n.0,
            integrator: n.1,
            step_s: n.2,
            tolerance: n.3,
            record: n.4,
        })
}

fn surface<T: Real>(c: &Case) -> Surface<T> {
    match c.surface {
        0 => Surface::FairwayFirm,
        1 => Surface::FairwaySoft,
        2 => Surface::Rough,
        3 => Surface::Green {
            stimp_m: lit(c.stimp_m),
        },
        5 => Surface::FairwayTrackman,
        7 => Surface::FairwayJoint,
        _ => Surface::Custom(Turf {
            restitution: lit(c.turf[0]),
            friction: lit(c.turf[1]),
            rolling_resistance: lit(c.turf[2]),
            crater_scale: lit(c.turf[3]),
            crater_fade_mps: lit(carry_core::ground::bounce::CRATER_FADE_NORMAL_SPEED_MPS),
            grass_drag_s2pm2: lit(carry_core::ground::surface::GRASS_DRAG_S2PM2),
            crater_law: if c.surface == 6 {
                carry_core::ground::CraterLaw::NormalTangential
            } else {
                carry_core::ground::CraterLaw::Penner
            },
            grass_height_m: lit(c.turf[4]),
        }),
    }
}

fn wind<T: Real>(c: &Case) -> Wind<T> {
    let w = Vector3::new(lit(c.wind_mps[0]), lit(c.wind_mps[1]), lit(c.wind_mps[2]));
    match c.wind {
        0 => Wind::None,
        1 => Wind::Uniform(w),
        _ => Wind::profile(w),
    }
}

fn integrator<T: Real>(c: &Case) -> Integrator<T> {
    match c.integrator {
        // Euler converges slowly: small steps only (its large-step behaviour is covered by
        // the flight's hard cases).
        0 => Integrator::Euler {
            step_s: lit(c.step_s.min(5e-3)),
        },
        1 => Integrator::Rk4 {
            step_s: lit(c.step_s),
        },
        _ => Integrator::dormand_prince(lit(c.tolerance)),
    }
}

/// What a run produced: the outcome, the ground's unit normal and the samples.
type Run<T> = (
    Result<FlightOutcome<T>, Error>,
    Vector3<f64>,
    Vec<Sample<T>>,
);

fn run<T: Real>(c: &Case) -> Run<T> {
    let ground = Ground::sloped(
        surface::<T>(c),
        lit(c.slope_rad),
        lit(c.slope_direction_rad),
    );
    let normal = ground
        .prepare(lit(0.021335))
        .expect("valid ground")
        .normal()
        .map(to_f64);
    let scene = Scene::<T> {
        wind: wind(c),
        landing_height_m: lit(c.landing_height_m),
        ground: Some(ground),
        ..Scene::default()
    };
    let motion = Launch::<T> {
        ball_speed_mps: lit(c.speed_mps),
        launch_angle_rad: lit(c.angle_rad),
        launch_direction_rad: lit(c.direction_rad),
        backspin_radps: lit(c.backspin_radps),
        sidespin_radps: lit(c.sidespin_radps),
    }
    .ball_motion()
    .expect("valid launch");
    let mut buffer: heapless::Vec<Sample<T>, 4096> = heapless::Vec::new();
    let mut recorder = c
        .record
        .then(|| Recorder::new(lit(0.02), &mut buffer).expect("valid interval"));
    let out = fly(
        &Ball::standard(),
        &motion,
        &scene,
        &integrator(c),
        recorder.as_mut(),
    );
    let samples = recorder.map(|r| r.samples().to_vec()).unwrap_or_default();
    (out, normal, samples)
}

/// The properties, in the precision `T` with relative tolerance `rel`.
fn check<T: Real>(c: &Case, rel: f64) -> Result<(), TestCaseError> {
    let (out, n, samples) = run::<T>(c);
    let out = match out {
        Ok(out) => out,
        // A landing height above the apex, or a fixed step too large for the flight:
        // typed errors, never garbage.
        Err(Error::NoLanding | Error::Unstable | Error::TimeLimit) => return Ok(()),
        Err(e) => return Err(TestCaseError::fail(format!("{e:?}"))),
    };
    let g = out.ground.expect("a ground gives a rollout");
    let figures = [
        out.carry_m,
        out.apex_m,
        out.flight_time_s,
        out.landing_speed_mps,
        g.total_m,
        g.roll_m,
        g.time_to_rest_s,
    ];
    prop_assert!(
        figures
            .iter()
            .chain(g.rest_position_m.iter())
            .all(|x| x.is_finite()),
        "{out:?}"
    );
    // Nothing astronomical: a minute of rolling down a 45° slope adds < 9 km.
    prop_assert!(to_f64(g.total_m) < 2.0e4, "{g:?}");
    prop_assert!(g.time_to_rest_s >= out.flight_time_s);
    for s in &samples {
        prop_assert!(
            s.position_m
                .iter()
                .chain(s.velocity_mps.iter())
                .chain(s.spin_radps.iter())
                .all(|x| x.is_finite()),
            "{s:?}"
        );
    }
    // The roll: the samples after the last hop, on the plane through the first landing.
    let landing = out.landing_position_m.map(to_f64);
    let eps = to_f64(T::default_epsilon());
    // Rolling: on the plane (to rounding) and moving along it. A hop's samples fail one of
    // the two: a hop rises at least STOP_HEIGHT_M (5 mm), so a sample within rounding of
    // the plane is at the hop's ends, where it moves across the plane at ≥ 0.3 m/s.
    let rolling = |s: &Sample<T>| {
        let p = s.position_m.map(to_f64);
        let v = s.velocity_mps.map(to_f64);
        (p - landing).dot(&n).abs() < 1e-9 + 8.0 * eps * (p.norm() + landing.norm())
            && v.dot(&n).abs() <= 1e-9 + 1e-3 * v.norm()
    };
    let tail = samples.iter().rev().take_while(|s| rolling(s)).count();
    let roll = &samples[samples.len() - tail..];
    if std::env::var_os("CARRY_TEST_DEBUG").is_some() {
        eprintln!("roll samples checked: {}", roll.len());
    }
    let gravity = 9.80665;
    let radius = to_f64(Ball::<T>::standard().radius_m());
    // Rolling: the spin is n̂ × v / R. A skid (the contact still slipping after the last
    // bounce) has its own spin, and a ball with overspin speeds up while its spin slows:
    // the energy counts both.
    let pure_roll = |s: &Sample<T>| {
        let rolling_spin = n.cross(&s.velocity_mps.map(to_f64)) / radius;
        (s.spin_radps.map(to_f64) - rolling_spin).norm() <= 1e-3 * (1.0 + rolling_spin.norm())
    };
    for w in roll.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        // Kinetic ½v² + ½(2/5)R²ω² (= (7/10)v² rolling) per unit mass, potential g y.
        let e = |s: &Sample<T>| {
            0.5 * to_f64(s.velocity_mps.norm_squared())
                + 0.2 * radius * radius * to_f64(s.spin_radps.norm_squared())
                + gravity * to_f64(s.position_m.y)
        };
        let scale = e(a) - gravity * to_f64(a.position_m.y)
            + gravity * (1.0 + to_f64(a.position_m.y).abs());
        prop_assert!(
            e(b) <= e(a) + rel * scale,
            "the roll gained energy: {a:?} → {b:?} (slope {} rad)",
            c.slope_rad
        );
        if c.slope_rad == 0.0 && pure_roll(a) && pure_roll(b) {
            prop_assert!(
                to_f64(b.velocity_mps.norm()) <= to_f64(a.velocity_mps.norm()) * (1.0 + rel),
                "level roll sped up: {a:?} → {b:?}"
            );
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(192))]

    #[test]
    fn run_out_is_finite_and_never_gains_energy_f64(c in cases()) {
        check::<f64>(&c, 1e-9)?;
    }

    #[test]
    fn run_out_is_finite_and_never_gains_energy_f32(c in cases()) {
        check::<f32>(&c, 1e-4)?;
    }
}
