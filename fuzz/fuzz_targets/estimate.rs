//! Fuzz the estimator (issue 23): any club (a preset, or arbitrary parameters, valid or
//! not), any measured ball data, any subset of club data, any noise, prior, iteration
//! budget and tolerance, in f32 and f64. A success must be finite with non-negative 1σ;
//! anything else a typed error.
#![no_main]

use carry_core::estimate::{BallData, ClubData, Posterior, Prior, Settings, Unknowns, estimate};
use carry_core::real::lit;
use carry_core::{Ball, ClubSpec, PRESETS, Real, Result};
use carry_fuzz::Bytes;
use libfuzzer_sys::fuzz_target;
use nalgebra::{Matrix3, Vector3};

fn maybe<T: Real>(b: &mut Bytes<'_>, lo: f64, hi: f64) -> Option<T> {
    if b.flag() {
        Some(lit(b.param(lo, hi)))
    } else {
        None
    }
}

fn unknowns<T: Real>(b: &mut Bytes<'_>, base: &Unknowns<T>) -> Unknowns<T> {
    // mostly the given values; sometimes an arbitrary scale (zero, negative, huge, NaN)
    let a = base.to_array();
    Unknowns::from_array(a.map(|v| {
        if b.flag() {
            v * lit(b.param(-2.0, 1e3))
        } else {
            v
        }
    }))
}

fn run<T: Real>(b: &mut Bytes<'_>) -> Result<()> {
    let preset = &PRESETS[usize::from(b.byte()) % PRESETS.len()];
    let mut spec = preset.spec::<T>();
    if b.flag() {
        let d = b.vec3(1e-5, 1e-3);
        spec = ClubSpec::<T> {
            mass_kg: lit(b.param(0.05, 1.0)),
            inertia_kgm2: Matrix3::from_diagonal(&Vector3::new(lit(d[0]), lit(d[1]), lit(d[2]))),
            loft_rad: lit(b.param(-0.5, 1.2)),
            roll_radius_m: lit(b.param(0.05, 2.0)),
            bulge_radius_m: lit(b.param(0.05, 2.0)),
            face_depth_radius_m: None,
            cg_to_face_m: Vector3::from(b.vec3(-0.05, 0.06).map(lit)),
            restitution: lit(b.param(0.0, 1.0)),
            contact: spec.contact,
            spin_axis_share: lit(b.param(-0.1, 1.1)),
        };
    } else if b.flag() {
        // the empirical D-plane share through the estimator's forward model
        spec.spin_axis_share = lit(b.param(0.05, 1.0));
    }
    let club = spec.validate()?;
    let ball = Ball::<T>::standard();
    let measured = BallData {
        ball_speed_mps: lit(b.param(0.0, 100.0)),
        launch_angle_rad: lit(b.param(-0.6, 1.2)),
        launch_direction_rad: lit(b.param(-0.5, 0.5)),
        spin_radps: lit(b.param(0.0, 1500.0)),
        spin_axis_rad: lit(b.param(-1.6, 1.6)),
    };
    let club_data = ClubData {
        club_speed_mps: maybe(b, 0.0, 70.0),
        attack_angle_rad: maybe(b, -0.4, 0.4),
        club_path_rad: maybe(b, -0.4, 0.4),
        face_angle_rad: maybe(b, -0.4, 0.4),
        dynamic_loft_rad: maybe(b, -0.2, 1.3),
    };
    let mut settings = Settings::<T>::typical(&preset.typical);
    if b.flag() {
        settings.noise.club = unknowns(b, &settings.noise.club);
        settings.prior = Prior {
            mean: unknowns(b, &settings.prior.mean),
            sd: unknowns(b, &settings.prior.sd),
        };
    }
    if b.flag() {
        settings.max_iterations = b.byte();
        settings.tolerance = lit(b.param(0.0, 1.0));
    }
    if b.flag() {
        settings.posterior = Posterior::Laplace;
    }
    // read last, so that the corpus keeps its meaning: arbitrary consistency bounds
    if b.flag() {
        settings.check.tail_probability = lit(b.param(-0.1, 0.6));
        settings.check.max_shift_sd = lit(b.param(-1.0, 20.0));
    }
    // read after the bounds, for the same reason: arbitrary posterior σ factors
    if b.flag() {
        settings.sd_scale = unknowns(b, &settings.sd_scale);
    }
    let e = estimate(&club, &ball, &measured, &club_data, &settings)?;
    let c = e.consistency;
    assert!(
        c.chi2 >= T::zero() && c.bound > T::zero() && c.worst_sd >= T::zero(),
        "bad consistency verdict {c:?}"
    );
    assert!((5..=10).contains(&c.dof), "dof {c:?}");
    assert_eq!(e.checked().is_ok(), c.consistent);
    let all = e
        .value
        .to_array()
        .into_iter()
        .chain(e.sd.to_array())
        .chain(e.residual.to_array());
    for v in all {
        assert!(v.is_finite(), "non-finite estimate {e:?}");
    }
    assert!(
        e.sd.to_array().iter().all(|s| *s >= T::zero()),
        "negative 1σ {e:?}"
    );
    assert!(e.iterations >= 1 && e.iterations <= settings.max_iterations);
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
