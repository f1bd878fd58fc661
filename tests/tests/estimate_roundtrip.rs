//! The estimator (`carry_core::estimate`) through the public API, f64 and f32: simulate
//! deliveries with the default model (the driver preset, its calibrated contact, TrackMan's
//! convention) and estimate them back.
//!
//! * Round trip: with exact data and priors that do not bind, the delivery comes back
//!   exactly where the data determine it. Ball data and club speed leave one direction
//!   undetermined (club path against heel–toe strike and attack against strike height;
//!   docs/estimate.md, "Identifiability"), so the round trip also gives one club datum —
//!   the club path, or the attack angle — and a separate test shows the prior deciding
//!   that direction, within the reported σ, when neither is given.
//! * Calibrated uncertainty: deliveries drawn from the default prior, default launch-monitor
//!   noise on the data; 68 % ± 5 % of the errors fall within the reported 1σ.

use carry_core::estimate::{
    BallData, ClubData, Estimate, Noise, Posterior, Settings, Unknowns, estimate, predict,
};
use carry_core::presets::{PRESETS, Preset};
use carry_core::real::{lit, to_f64};
use carry_core::{Ball, ClubHead, Real};

/// xorshift64* with Box–Muller normals: reproducible, no dependency.
struct Rng(u64);

impl Rng {
    fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let v = self.0.wrapping_mul(0x2545_F491_4F6C_DD1D);
        ((v >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    fn normal(&mut self) -> f64 {
        let (u, v) = (self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (2.0 * std::f64::consts::PI * v).cos()
    }
}

fn head<T: Real>(p: &Preset) -> ClubHead<T> {
    let Ok(h) = p.spec::<T>().validate() else {
        panic!("{}", p.name)
    };
    h
}

/// A delivery drawn from the default prior of `p`, and its ball data (f64 model).
fn draw(p: &Preset, rng: &mut Rng) -> Option<(Unknowns<f64>, BallData<f64>)> {
    let prior = Settings::<f64>::typical(&p.typical).prior;
    let (m, s) = (prior.mean.to_array(), prior.sd.to_array());
    let x: [f64; 7] = core::array::from_fn(|i| m[i] + s[i] * rng.normal());
    let truth = Unknowns::from_array(x);
    let y = predict(&head::<f64>(p), &Ball::standard(), &truth).ok()?;
    Some((truth, y))
}

fn cast<T: Real>(a: [f64; 5]) -> BallData<T> {
    BallData::from_array(a.map(lit))
}

fn run<T: Real>(
    p: &Preset,
    y: &BallData<f64>,
    club: &ClubData<f64>,
    settings: &Settings<f64>,
) -> Result<Estimate<T>, carry_core::Error> {
    let c = |v: Option<f64>| v.map(lit::<T>);
    let club = ClubData {
        club_speed_mps: c(club.club_speed_mps),
        attack_angle_rad: c(club.attack_angle_rad),
        club_path_rad: c(club.club_path_rad),
        face_angle_rad: c(club.face_angle_rad),
        dynamic_loft_rad: c(club.dynamic_loft_rad),
    };
    let u = |a: &Unknowns<f64>| Unknowns::from_array(a.to_array().map(lit::<T>));
    let s = Settings {
        noise: Noise {
            ball: cast(settings.noise.ball.to_array()),
            club: u(&settings.noise.club),
        },
        prior: carry_core::estimate::Prior {
            mean: u(&settings.prior.mean),
            sd: u(&settings.prior.sd),
        },
        max_iterations: settings.max_iterations,
        tolerance: lit(settings.tolerance),
        posterior: settings.posterior,
        check: carry_core::estimate::Check {
            tail_probability: lit(settings.check.tail_probability),
            max_shift_sd: lit(settings.check.max_shift_sd),
        },
        sd_scale: u(&settings.sd_scale),
    };
    estimate(
        &head::<T>(p),
        &Ball::standard(),
        &cast(y.to_array()),
        &club,
        &s,
    )
}

/// The club data the round trip gives beside the club speed.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Given {
    PathAndAttack,
    Path,
    Attack,
}

/// The noise settings of exact (simulated) data: the default noise × 10⁻², so that the
/// posterior collapses onto the delivery that reproduces the data (its mean onto its mode).
const EXACT: f64 = 1e-2;

/// Over `n` random deliveries given exact ball data, the club speed and `given`, priors
/// widened 100×: the largest errors (deg: face, path, loft, attack; m: toe, height), the
/// iterations, the number of estimates outside the issue's limits (0.05°, 1 mm) and the
/// largest |residual|/σ of those (do they reproduce the data as well as the truth does?).
fn round_trip<T: Real>(n: usize, seed: u64, given: Given) -> ([f64; 6], u8, usize, f64) {
    let p = &PRESETS[0];
    let mut rng = Rng(seed);
    let mut worst = [0.0_f64; 6];
    let mut iterations = 0;
    let mut done = 0;
    let mut outside = 0;
    let mut worst_fit: f64 = 0.0;
    while done < n {
        let Some((truth, y)) = draw(p, &mut rng) else {
            continue;
        };
        done += 1;
        let mut settings = Settings::<f64>::typical(&p.typical);
        settings.prior = settings.prior.widened(100.0);
        settings.noise = Noise {
            ball: BallData::from_array(settings.noise.ball.to_array().map(|s| s * EXACT)),
            club: Unknowns::from_array(settings.noise.club.to_array().map(|s| s * EXACT)),
        };
        settings.tolerance = 1e-2;
        let mut club = ClubData {
            club_speed_mps: Some(truth.club_speed_mps),
            ..ClubData::default()
        };
        if given != Given::Attack {
            club.club_path_rad = Some(truth.club_path_rad);
        }
        if given != Given::Path {
            club.attack_angle_rad = Some(truth.attack_angle_rad);
        }
        let e = match run::<T>(p, &y, &club, &settings) {
            Ok(e) => e,
            Err(e) => panic!("{truth:?}: {e:?}"),
        };
        let v = e.value;
        let errs = [
            (to_f64(v.face_angle_rad) - truth.face_angle_rad).to_degrees(),
            (to_f64(v.club_path_rad) - truth.club_path_rad).to_degrees(),
            (to_f64(v.dynamic_loft_rad) - truth.dynamic_loft_rad).to_degrees(),
            (to_f64(v.attack_angle_rad) - truth.attack_angle_rad).to_degrees(),
            to_f64(v.impact_toe_m) - truth.impact_toe_m,
            to_f64(v.impact_height_m) - truth.impact_height_m,
        ];
        for (w, e) in worst.iter_mut().zip(errs) {
            *w = w.max(e.abs());
        }
        if errs[..4].iter().any(|e| e.abs() > 0.05) || errs[4..].iter().any(|e| e.abs() > 0.001) {
            outside += 1;
            for (r, s) in e
                .residual
                .to_array()
                .iter()
                .zip(settings.noise.ball.to_array())
            {
                worst_fit = worst_fit.max((to_f64(*r) / s).abs());
            }
        }
        iterations = iterations.max(e.iterations);
    }
    (worst, iterations, outside, worst_fit)
}

/// The issue's round trip: face, path, loft and attack within 0.05°, the strike within
/// 1 mm (f64), given the club path and attack beside the club speed (see below for why
/// one of them is not enough).
#[test]
fn round_trip_f64_recovers_the_delivery() {
    let (worst, iterations, _, _) = round_trip::<f64>(300, 23, Given::PathAndAttack);
    println!("f64 worst {worst:?}, iterations ≤ {iterations}");
    for w in &worst[..4] {
        assert!(*w <= 0.05, "{worst:?}");
    }
    for w in &worst[4..] {
        assert!(*w <= 0.001, "{worst:?}");
    }
}

#[test]
fn round_trip_f32_recovers_the_delivery() {
    let (worst, iterations, _, _) = round_trip::<f32>(300, 24, Given::PathAndAttack);
    println!("f32 worst {worst:?}, iterations ≤ {iterations}");
    for w in &worst[..4] {
        assert!(*w <= 0.2, "{worst:?}");
    }
    for w in &worst[4..] {
        assert!(*w <= 0.003, "{worst:?}");
    }
}

/// One club datum beside the club speed makes the Jacobian full rank but the delivery
/// not unique: with the path given, some deliveries have a mirror (the strike height
/// reflected about the face's sweet spot, the attack compensating the spin); with the
/// attack given, a second path–toe pair. The estimate then lands on another delivery that
/// reproduces the exact data as well as the truth — the data cannot tell them apart.
/// Measured, so that a change shows (docs/estimate.md §4).
#[test]
fn one_club_datum_leaves_exact_alternatives() {
    for (given, seed) in [(Given::Path, 23), (Given::Attack, 29)] {
        let (worst, _, outside, fit) = round_trip::<f64>(300, seed, given);
        println!(
            "given {given:?}: {outside} of 300 outside the limits, their worst |residual|/σ {fit:.2e}, worst errors {worst:?}"
        );
        assert!(outside > 0, "{given:?}: now unique");
        assert!(fit < 0.1, "{given:?}: {fit}");
    }
}

/// Exact ball data and the club speed only, default settings: the one open direction (path
/// against heel–toe strike, attack against strike height) is the prior's to decide, so the
/// delivery is not recovered exactly — and the reported 1σ says so: the errors of path,
/// attack, toe and height fall within it about as often as a normal error would (a few
/// land on the mirrored branch of the speed–height fold, many σ away: the worst is
/// printed).
#[test]
fn ball_data_and_club_speed_leave_the_open_direction_to_the_prior() {
    let p = &PRESETS[0];
    let mut rng = Rng(31);
    let settings = Settings::<f64>::typical(&p.typical);
    let n = 300;
    let (mut worst_attack, mut worst_z, mut inside) = (0.0_f64, 0.0_f64, [0usize; 4]);
    let mut done = 0;
    while done < n {
        let Some((truth, y)) = draw(p, &mut rng) else {
            continue;
        };
        done += 1;
        let club = ClubData {
            club_speed_mps: Some(truth.club_speed_mps),
            ..ClubData::default()
        };
        let e = match run::<f64>(p, &y, &club, &settings) {
            Ok(e) => e,
            Err(e) => panic!("{truth:?}: {e:?}"),
        };
        let (v, s) = (e.value, e.sd);
        let errs = [
            (v.club_path_rad - truth.club_path_rad, s.club_path_rad),
            (
                v.attack_angle_rad - truth.attack_angle_rad,
                s.attack_angle_rad,
            ),
            (v.impact_toe_m - truth.impact_toe_m, s.impact_toe_m),
            (v.impact_height_m - truth.impact_height_m, s.impact_height_m),
        ];
        worst_attack = worst_attack.max(errs[1].0.to_degrees().abs());
        for (k, (err, sd)) in errs.iter().enumerate() {
            worst_z = worst_z.max((err / sd).abs());
            if err.abs() <= *sd {
                inside[k] += 1;
            }
        }
    }
    let share = inside.map(|c| c as f64 / n as f64);
    println!(
        "worst attack error {worst_attack:.2}°, worst |err|/σ {worst_z:.2}, within 1σ {share:.3?}"
    );
    assert!(
        worst_attack > 0.5,
        "the open direction was resolved: {worst_attack}"
    );
    for s in share {
        assert!((0.6..=0.9).contains(&s), "{share:?}");
    }
}

/// Ball data and the club speed only, default settings: the estimate reproduces the ball
/// data within their noise (the prior takes a little of the fit), within the iteration
/// budget.
fn reproduces<T: Real>(n: usize, seed: u64) -> (f64, u8) {
    let p = &PRESETS[0];
    let mut rng = Rng(seed);
    let settings = Settings::<f64>::typical(&p.typical);
    let sigma = settings.noise.ball.to_array();
    let mut worst: f64 = 0.0;
    let mut iterations = 0;
    let mut done = 0;
    while done < n {
        let Some((truth, y)) = draw(p, &mut rng) else {
            continue;
        };
        done += 1;
        let club = ClubData {
            club_speed_mps: Some(truth.club_speed_mps),
            ..ClubData::default()
        };
        let e = match run::<T>(p, &y, &club, &settings) {
            Ok(e) => e,
            Err(e) => panic!("{truth:?}: {e:?}"),
        };
        for (r, s) in e.residual.to_array().iter().zip(sigma) {
            worst = worst.max((to_f64(*r) / s).abs());
        }
        iterations = iterations.max(e.iterations);
    }
    (worst, iterations)
}

#[test]
fn ball_data_and_club_speed_are_reproduced() {
    let (w64, i64) = reproduces::<f64>(300, 25);
    let (w32, i32) = reproduces::<f32>(300, 26);
    println!("worst |residual|/σ: f64 {w64:.2e} ({i64} it), f32 {w32:.2e} ({i32} it)");
    assert!(w64 < 1.0 && w32 < 1.0, "{w64} {w32}");
}

/// The share of `n` estimates (default settings, ball data and club speed with default
/// noise added, deliveries drawn from the default prior) whose error lies within the
/// reported 1σ, per datum: face, path, face-to-path, loft, attack, spin loft, toe, height.
fn coverage<T: Real>(n: usize, seed: u64) -> [f64; 8] {
    coverage_with::<T>(n, seed, Posterior::Profile)
}

fn coverage_with<T: Real>(n: usize, seed: u64, posterior: Posterior) -> [f64; 8] {
    let p = &PRESETS[0];
    let mut rng = Rng(seed);
    let mut settings = Settings::<f64>::typical(&p.typical);
    settings.posterior = posterior;
    let sigma = settings.noise.ball.to_array();
    let speed_sigma = settings.noise.club.club_speed_mps;
    let mut inside = [0usize; 8];
    let mut done = 0;
    while done < n {
        let Some((truth, y)) = draw(p, &mut rng) else {
            continue;
        };
        let y = BallData::from_array(core::array::from_fn(|i| {
            y.to_array()[i] + sigma[i] * rng.normal()
        }));
        if y.validated().is_err() {
            continue; // noise took a number out of its range (a spin below zero)
        }
        let club = ClubData {
            club_speed_mps: Some(truth.club_speed_mps + speed_sigma * rng.normal()),
            ..ClubData::default()
        };
        let e = match run::<T>(p, &y, &club, &settings) {
            Ok(e) => e,
            Err(e) => panic!("{truth:?}: {e:?}"),
        };
        done += 1;
        let t = &truth;
        let truths = [
            t.face_angle_rad,
            t.club_path_rad,
            t.face_angle_rad - t.club_path_rad,
            t.dynamic_loft_rad,
            t.attack_angle_rad,
            t.dynamic_loft_rad - t.attack_angle_rad,
            t.impact_toe_m,
            t.impact_height_m,
        ];
        let (v, s) = (e.value.to_array(), e.sd.to_array());
        for (k, t) in truths.iter().enumerate() {
            if (to_f64(v[k]) - t).abs() <= to_f64(s[k]) {
                inside[k] += 1;
            }
        }
    }
    inside.map(|c| c as f64 / n as f64)
}

/// The reported 1σ covers 68 % ± 5 % of the errors for all eight data: the Laplace
/// (Gaussian) 1σ for the data the ball pins down through near-linear relations, and the
/// strike height's profile posterior (RMS error about the MAP) for the height, attack and
/// spin loft, whose posterior is skewed (docs/estimate.md §4).
fn check(share: [f64; 8]) {
    for s in share {
        assert!((0.63..=0.73).contains(&s), "{share:?}");
    }
}

#[test]
fn uncertainty_is_calibrated_f64() {
    let share = coverage::<f64>(10_000, 27);
    println!("f64 share within 1σ {share:.3?}");
    check(share);
}

#[test]
fn uncertainty_is_calibrated_f32() {
    let share = coverage::<f32>(10_000, 28);
    println!("f32 share within 1σ {share:.3?}");
    check(share);
}

/// The Laplace summary (the MAP and the Gauss–Newton 1σ), for comparison: calibrated for
/// the data the ball pins down through near-linear relations, but its 1σ of attack, spin
/// loft and strike height cover only about 53 % (their posterior is skewed: §4 of
/// docs/estimate.md). Asserted as measured, so that a change shows.
#[test]
fn laplace_summary_under_covers_the_height() {
    let share = coverage_with::<f64>(10_000, 27, Posterior::Laplace);
    println!("f64 Laplace share within 1σ {share:.3?}");
    for s in [share[0], share[1], share[2], share[3], share[6]] {
        assert!((0.63..=0.73).contains(&s), "{share:?}");
    }
    for s in [share[4], share[5], share[7]] {
        assert!((0.45..0.6).contains(&s), "{share:?}");
    }
}

/// The χ² bound of the consistency check (Wilson–Hilferty with Abramowitz & Stegun's
/// normal quantile) against exact quantiles (tables of the χ² distribution): within 1.5 %.
#[test]
fn chi2_bound_matches_the_tables() {
    for (n, p, exact) in [
        (5, 1e-3, 20.515),
        (6, 1e-3, 22.458),
        (10, 1e-3, 29.588),
        (5, 0.05, 11.070),
        (7, 0.05, 14.067),
        (6, 0.01, 16.812),
        (8, 1e-4, 31.828),
    ] {
        let q = carry_core::estimate::chi2_quantile::<f64>(n, p);
        let q32 = carry_core::estimate::chi2_quantile::<f32>(n, p as f32);
        assert!(
            (q / exact - 1.0).abs() < 0.015,
            "n {n} p {p}: {q} vs {exact}"
        );
        assert!((f64::from(q32) / q - 1.0).abs() < 1e-4, "{q32} vs {q}");
    }
}

/// Issue 34's consistency check on shots that follow the model (deliveries from the default
/// prior, default noise on the ball data and the club speed): the χ² test flags about its
/// tail probability (0.05 here, to be measurable: asserted 2–10 %, the model is not
/// linear), and the default check (p = 0.001, 4σ) almost none (< 1 %). The same shots with
/// the measured club speed 8 m/s (18σ) too high are mostly flagged (measured 68.8 %: an
/// off-centre strike explains part of a low smash factor), the worst term being the
/// club speed, the ball speed that disagrees with it, or the club's prior that the
/// compromise strains.
#[test]
fn consistency_check_flags_its_tail_and_inconsistent_club_speed() {
    use carry_core::estimate::Datum;
    let p = &PRESETS[0];
    let mut rng = Rng(34);
    let base = Settings::<f64>::typical(&p.typical);
    let mut loose = base;
    loose.check.tail_probability = 0.05;
    loose.check.max_shift_sd = 1e6;
    let sigma = base.noise.ball.to_array();
    let speed_sigma = base.noise.club.club_speed_mps;
    let n = 1000;
    let (mut done, mut loose_flags, mut default_flags, mut off_flags) = (0, 0, 0, 0);
    while done < n {
        let Some((truth, y)) = draw(p, &mut rng) else {
            continue;
        };
        let y = BallData::from_array(core::array::from_fn(|i| {
            y.to_array()[i] + sigma[i] * rng.normal()
        }));
        if y.validated().is_err() {
            continue;
        }
        let speed = truth.club_speed_mps + speed_sigma * rng.normal();
        let club = ClubData {
            club_speed_mps: Some(speed),
            ..ClubData::default()
        };
        let e = run::<f64>(p, &y, &club, &loose).expect("estimate");
        assert_eq!(e.consistency.dof, 6);
        loose_flags += usize::from(!e.consistency.consistent);
        let e = run::<f64>(p, &y, &club, &base).expect("estimate");
        default_flags += usize::from(e.checked().is_err());
        let off = ClubData {
            club_speed_mps: Some(speed + 8.0),
            ..ClubData::default()
        };
        match run::<f64>(p, &y, &off, &base).map(carry_core::estimate::Estimate::checked) {
            Ok(Err(carry_core::Error::Inconsistent { worst })) => {
                assert!(
                    matches!(worst, Datum::ClubSpeed | Datum::BallSpeed | Datum::Club),
                    "{worst:?}"
                );
                off_flags += 1;
            }
            Ok(Ok(_)) => {}
            other => panic!("{other:?}"),
        }
        done += 1;
    }
    let share = |k: usize| k as f64 / n as f64;
    println!(
        "flagged: p = 0.05 {:.3}, default {:.4}, club speed +8 m/s {:.3}",
        share(loose_flags),
        share(default_flags),
        share(off_flags)
    );
    assert!((0.02..=0.10).contains(&share(loose_flags)), "{loose_flags}");
    assert!(share(default_flags) < 0.01, "{default_flags}");
    // measured 68.8 %: an off-centre strike explains part of a low smash factor
    assert!(share(off_flags) >= 0.5, "{off_flags}");
}

/// Issue 34's example through the core in f32 and f64, with the driver's defaults
/// (`Settings::for_preset`): a 70 m/s ball, 12°, 2,800 rpm, axis 0°, from a measured club
/// speed of 5 m/s, is flagged, the worst datum the ball or club speed, missed by > 4σ, with a
/// χ² far above its bound; the same ball from a club speed that fits (47 m/s) passes.
#[test]
fn the_issues_inconsistent_example_is_flagged_in_both_precisions() {
    use carry_core::estimate::Datum;
    let p = PRESETS.iter().find(|p| p.name == "driver").expect("driver");
    let settings = Settings::<f64>::for_preset(p);
    let y = BallData {
        ball_speed_mps: 70.0,
        launch_angle_rad: 12f64.to_radians(),
        launch_direction_rad: 0.0,
        spin_radps: 2800.0 * core::f64::consts::PI / 30.0,
        spin_axis_rad: 0.0,
    };
    let club = |v: f64| ClubData {
        club_speed_mps: Some(v),
        ..ClubData::default()
    };
    fn verdict<T: Real>(e: &Estimate<T>) -> (bool, Datum, f64, f64, f64) {
        let c = e.consistency;
        (
            c.consistent,
            c.worst,
            to_f64(c.worst_sd),
            to_f64(c.chi2),
            to_f64(c.bound),
        )
    }
    let bad = [
        verdict(&run::<f64>(p, &y, &club(5.0), &settings).expect("f64")),
        verdict(&run::<f32>(p, &y, &club(5.0), &settings).expect("f32")),
    ];
    for (consistent, worst, sd, chi2, bound) in bad {
        assert!(!consistent);
        assert!(
            matches!(worst, Datum::BallSpeed | Datum::ClubSpeed),
            "{worst:?}"
        );
        assert!(sd > 4.0 && chi2 > bound, "{sd} {chi2} {bound}");
    }
    assert_eq!(bad[0].1, bad[1].1, "f32 and f64 name the same datum");
    let good = run::<f64>(p, &y, &club(47.0), &settings).expect("f64");
    assert!(good.checked().is_ok(), "{:?}", good.consistency);
    let good = run::<f32>(p, &y, &club(47.0), &settings).expect("f32");
    assert!(good.checked().is_ok(), "{:?}", good.consistency);
}
