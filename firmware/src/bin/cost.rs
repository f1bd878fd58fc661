//! Instruction counts per operation. Run by `cost.sh`, under QEMU's exact counting plugin
//! and `-icount shift=0`; it joins the region numbers printed here to the plugin's counts.
//!
//! Every operation runs on the reference driver shot (see `carry_firmware::shot`), with
//! inputs hidden from the optimiser by `black_box`.
#![no_std]
#![no_main]

use carry_core::flight::Integrator;
use carry_core::impact::{self, Solver};
use carry_core::linalg::Pivoting;
use carry_core::real::{Real, lit, to_f64};
use carry_core::scene::Scene;
use carry_core::{Ball, DeliveryConvention, Error};
use carry_firmware::cost::{Ticks, insns_per_call, region};
use carry_firmware::shot;
use core::hint::black_box;
use cortex_m_rt::entry;

/// Counts one operation: `n` calls in one region; `f` returns a work measure (force
/// evaluations for a flight, 0 otherwise) and the carry (m) where there is one.
fn op(
    ticks: &Ticks,
    k: &mut u32,
    name: &str,
    n: u32,
    f: &mut dyn FnMut() -> Result<(u32, f64), Error>,
) {
    let (t, last) = region(ticks, n, f);
    let (evals, carry) = match last {
        Some(Ok(r)) => r,
        Some(Err(e)) => {
            defmt::println!("note: region {=u32} failed: {}", *k, e);
            (u32::MAX, f64::NAN)
        }
        None => (0, f64::NAN),
    };
    defmt::println!(
        "cost region={=u32} n={=u32} ticks={=u32} approx={=u32} evals={=u32} carry={=f64} op={=str}",
        *k,
        n,
        t,
        insns_per_call(t, n),
        evals,
        carry,
        name
    );
    *k += 1;
}

/// The impact and flight operations in precision `T`.
fn suite<T: Real>(ticks: &Ticks, k: &mut u32, p: &str) {
    let spec = black_box(shot::driver::<T>());
    let delivery = black_box(shot::delivery::<T>());
    let club = spec.validate().unwrap_or_else(|_| carry_firmware::exit(1));
    let strike = delivery
        .strike(&club)
        .unwrap_or_else(|_| carry_firmware::exit(1));
    let ball = Ball::<T>::standard();
    let scene = black_box(Scene::<T>::default());
    let hit = impact::solve(&club, &ball, &strike, Solver::Reduced)
        .unwrap_or_else(|_| carry_firmware::exit(1));
    let launch = black_box(hit.ball);

    macro_rules! label {
        ($s:literal) => {
            if p == "f32" {
                concat!($s, " [f32]")
            } else {
                concat!($s, " [f64]")
            }
        };
    }

    op(
        ticks,
        k,
        label!("club: ClubSpec::validate"),
        10,
        &mut || spec.validate().map(|_| (0, f64::NAN)),
    );
    op(
        ticks,
        k,
        label!("delivery: Delivery::strike"),
        10,
        &mut || delivery.strike(&club).map(|_| (0, f64::NAN)),
    );
    // TrackMan's convention off the centre: the club's centre orientation derived from the
    // angles at the contact point (carry_core::convention), then the strike
    let mut located = delivery;
    located.location.height_m = lit(0.01);
    located.location.toe_m = lit(0.015);
    let located = black_box(located);
    op(
        ticks,
        k,
        label!("delivery: strike_in TrackMan's convention, off-centre"),
        10,
        &mut || {
            located
                .strike_in(&club, DeliveryConvention::TrackMan)
                .map(|_| (0, f64::NAN))
        },
    );
    op(
        ticks,
        k,
        label!("impact solve, reduced 3x3"),
        10,
        &mut || impact::solve(&club, &ball, &strike, Solver::Reduced).map(|_| (0, f64::NAN)),
    );
    let compliant_club = black_box(shot::driver_compliant::<T>())
        .validate()
        .unwrap_or_else(|_| carry_firmware::exit(1));
    op(
        ticks,
        k,
        label!("impact solve, reduced 3x3, compliant contact"),
        10,
        &mut || {
            impact::solve(&compliant_club, &ball, &strike, Solver::Reduced).map(|_| (0, f64::NAN))
        },
    );
    op(
        ticks,
        k,
        label!("impact solve, full 15x15 (equilibrated)"),
        10,
        &mut || impact::solve(&club, &ball, &strike, Solver::FULL).map(|_| (0, f64::NAN)),
    );
    op(
        ticks,
        k,
        label!("impact solve, full 15x15 (partial pivoting)"),
        10,
        &mut || {
            impact::solve(&club, &ball, &strike, Solver::Full(Pivoting::Partial))
                .map(|_| (0, f64::NAN))
        },
    );

    let mut fly = |name: &'static str, integrator: Integrator<T>| {
        let integrator = black_box(integrator);
        op(ticks, k, name, 1, &mut || {
            carry_core::flight::fly(&ball, &launch, &scene, &integrator, None)
                .map(|o| (o.stats.force_evaluations, to_f64(o.carry_m)))
        });
    };
    fly(
        label!("flight, default fidelity (DP5(4) default tol)"),
        Integrator::default(),
    );
    fly(
        label!("flight, DP5(4) tol 1e-4"),
        Integrator::dormand_prince(lit(1e-4)),
    );
    fly(
        label!("flight, DP5(4) tol 1e-6"),
        Integrator::dormand_prince(lit(1e-6)),
    );
    fly(
        label!("flight, DP5(4) tol 1e-8"),
        Integrator::dormand_prince(lit(1e-8)),
    );
    fly(
        label!("flight, RK4 step 10 ms"),
        Integrator::Rk4 { step_s: lit(1e-2) },
    );
    fly(
        label!("flight, RK4 step 1 ms"),
        Integrator::Rk4 { step_s: lit(1e-3) },
    );
    fly(
        label!("flight, Euler step 10 ms"),
        Integrator::Euler { step_s: lit(1e-2) },
    );
    fly(
        label!("flight, Euler step 1 ms"),
        Integrator::Euler { step_s: lit(1e-3) },
    );

    let prepared = scene
        .prepare(&ball)
        .unwrap_or_else(|_| carry_firmware::exit(1));
    op(ticks, k, label!("scene: Scene::prepare"), 10, &mut || {
        scene.prepare(&ball).map(|_| (0, f64::NAN))
    });
    let fidelity = black_box(carry_core::shot::Fidelity::<T>::default());
    op(
        ticks,
        k,
        label!("FULL SHOT: shot::play (strike+reduced+flight, default)"),
        1,
        &mut || {
            carry_core::shot::play(&club, &ball, &delivery, &prepared, &fidelity, None)
                .map(|o| (o.flight.stats.force_evaluations, to_f64(o.flight.carry_m)))
        },
    );
    op(
        ticks,
        k,
        label!("FULL SHOT: shot::play, compliant contact"),
        1,
        &mut || {
            carry_core::shot::play(
                &compliant_club,
                &ball,
                &delivery,
                &prepared,
                &fidelity,
                None,
            )
            .map(|o| (o.flight.stats.force_evaluations, to_f64(o.flight.carry_m)))
        },
    );
    // The same shot with the seed's aerodynamics (the calibrated model is the default).
    let seed = Scene::<T> {
        aero: black_box(carry_core::aero::AeroModel::quintavalla()),
        ..Scene::default()
    }
    .prepare(&ball)
    .unwrap_or_else(|_| carry_firmware::exit(1));
    op(
        ticks,
        k,
        label!("FULL SHOT, seed aerodynamics (quintavalla)"),
        1,
        &mut || {
            carry_core::shot::play(&club, &ball, &delivery, &seed, &fidelity, None)
                .map(|o| (o.flight.stats.force_evaluations, to_f64(o.flight.carry_m)))
        },
    );
    // A launch monitor's everyday delivery: every angle non-zero, an off-centre strike
    // (the reference delivery's zero angles make the five sin/cos of `strike` trivial).
    let mut everyday = delivery;
    everyday.attack_angle_rad = carry_core::units::deg(lit(-1.5));
    everyday.club_path_rad = carry_core::units::deg(lit(2.5));
    everyday.face_angle_rad = carry_core::units::deg(lit(1.2));
    everyday.dynamic_loft_rad = carry_core::units::deg(lit(12.0));
    everyday.lie_rad = carry_core::units::deg(lit(-0.8));
    everyday.location.toe_m = lit(0.008);
    everyday.location.height_m = lit(0.004);
    let everyday = black_box(everyday);
    op(
        ticks,
        k,
        label!("FULL SHOT, everyday delivery (all angles non-zero)"),
        1,
        &mut || {
            carry_core::shot::play(&club, &ball, &everyday, &prepared, &fidelity, None)
                .map(|o| (o.flight.stats.force_evaluations, to_f64(o.flight.carry_m)))
        },
    );
    // The ground effect (issue 12): the same shot bouncing and rolling to rest. `evals`
    // counts the flight's and the hops' force evaluations, `carry` shows the total.
    for (name, surface) in [
        (
            label!("FULL SHOT + ground, firm fairway (to rest)"),
            carry_core::ground::Surface::FairwayFirm,
        ),
        (
            label!("FULL SHOT + ground, green stimp 10 (to rest)"),
            carry_core::ground::Surface::green(),
        ),
        (
            label!("FULL SHOT + ground, fairway-trackman (to rest)"),
            carry_core::ground::Surface::FairwayTrackman,
        ),
        (
            label!("FULL SHOT + ground, fairway-joint (to rest)"),
            carry_core::ground::Surface::FairwayJoint,
        ),
    ] {
        let with_ground = Scene::<T> {
            ground: Some(carry_core::ground::Ground::level(surface)),
            ..scene
        };
        let prepared = black_box(with_ground)
            .prepare(&ball)
            .unwrap_or_else(|_| carry_firmware::exit(1));
        op(ticks, k, name, 1, &mut || {
            carry_core::shot::play(&club, &ball, &delivery, &prepared, &fidelity, None).map(|o| {
                let g = o.flight.ground.map_or((0, o.flight.carry_m), |g| {
                    (g.stats.force_evaluations, g.total_m)
                });
                (o.flight.stats.force_evaluations + g.0, to_f64(g.1))
            })
        });
    }
    // Club data from ball data (issue 23): the driver preset, default settings, an
    // everyday shot's ball data (face 1.2° open, path 2.5° in-to-out, loft 12°, attack
    // −1.5°, 8 mm toward the toe, 4 mm up) with its club speed. `evals` counts iterations.
    let preset = &carry_core::PRESETS[0];
    let est_club = black_box(preset.spec::<T>())
        .validate()
        .unwrap_or_else(|_| carry_firmware::exit(1));
    let truth = carry_core::estimate::Unknowns {
        face_angle_rad: carry_core::units::deg(lit(1.2)),
        club_path_rad: carry_core::units::deg(lit(2.5)),
        dynamic_loft_rad: carry_core::units::deg(lit(12.0)),
        attack_angle_rad: carry_core::units::deg(lit(-1.5)),
        impact_toe_m: lit(0.008),
        impact_height_m: lit(0.004),
        club_speed_mps: lit(45.0),
    };
    let truth = black_box(truth);
    op(
        ticks,
        k,
        label!("estimate: one forward model evaluation (predict)"),
        10,
        &mut || carry_core::estimate::predict(&est_club, &ball, &truth).map(|_| (0, f64::NAN)),
    );
    let measured = black_box(
        carry_core::estimate::predict(&est_club, &ball, &truth)
            .unwrap_or_else(|_| carry_firmware::exit(1)),
    );
    let settings = black_box(carry_core::estimate::Settings::<T>::typical(
        &preset.typical,
    ));
    let club_data = black_box(carry_core::estimate::ClubData {
        club_speed_mps: Some(truth.club_speed_mps),
        ..carry_core::estimate::ClubData::default()
    });
    op(
        ticks,
        k,
        label!("ESTIMATE: club data from ball data + club speed (driver)"),
        1,
        &mut || {
            carry_core::estimate::estimate(&est_club, &ball, &measured, &club_data, &settings)
                .map(|e| (u32::from(e.iterations), f64::NAN))
        },
    );
    let laplace = black_box(carry_core::estimate::Settings {
        posterior: carry_core::estimate::Posterior::Laplace,
        ..settings
    });
    op(
        ticks,
        k,
        label!("ESTIMATE: the same, Laplace posterior (MAP, Gauss-Newton 1 sigma)"),
        1,
        &mut || {
            carry_core::estimate::estimate(&est_club, &ball, &measured, &club_data, &laplace)
                .map(|e| (u32::from(e.iterations), f64::NAN))
        },
    );
    // a harder shot, 1.5–2σ of the prior in every datum (more iterations)
    let hard = black_box(carry_core::estimate::Unknowns {
        face_angle_rad: carry_core::units::deg(lit(-4.5)),
        club_path_rad: carry_core::units::deg(lit(6.0)),
        dynamic_loft_rad: carry_core::units::deg(lit(17.0)),
        attack_angle_rad: carry_core::units::deg(lit(4.0)),
        impact_toe_m: lit(-0.018),
        impact_height_m: lit(-0.009),
        club_speed_mps: lit(40.0),
    });
    let hard_measured = black_box(
        carry_core::estimate::predict(&est_club, &ball, &hard)
            .unwrap_or_else(|_| carry_firmware::exit(1)),
    );
    let hard_club = black_box(carry_core::estimate::ClubData {
        club_speed_mps: Some(hard.club_speed_mps),
        ..carry_core::estimate::ClubData::default()
    });
    op(
        ticks,
        k,
        label!("ESTIMATE: a 1.5-2 sigma drive, ball data + club speed"),
        1,
        &mut || {
            carry_core::estimate::estimate(&est_club, &ball, &hard_measured, &hard_club, &settings)
                .map(|e| (u32::from(e.iterations), f64::NAN))
        },
    );
    op(
        ticks,
        k,
        label!("ESTIMATE: the same, Laplace posterior"),
        1,
        &mut || {
            carry_core::estimate::estimate(&est_club, &ball, &hard_measured, &hard_club, &laplace)
                .map(|e| (u32::from(e.iterations), f64::NAN))
        },
    );
    let ball_only = black_box(carry_core::estimate::ClubData::<T>::default());
    op(
        ticks,
        k,
        label!("ESTIMATE: club data from ball data only (driver)"),
        1,
        &mut || {
            carry_core::estimate::estimate(&est_club, &ball, &measured, &ball_only, &settings)
                .map(|e| (u32::from(e.iterations), f64::NAN))
        },
    );

    // The launch from the flight (issue 36): `evals` counts flights, `carry` is the fitted
    // launch's. The observations are made (and noised) before the region; only the fit
    // is counted. The caller-owned workspace lives on the stack here.
    // Not on the micro:bit: its 16 KiB of RAM cannot hold the workspace (21,792 B in f32),
    // and its 256 KiB of flash not this image with the fit in f32 and f64.
    #[cfg(not(carry_m0))]
    {
        let mut ws = carry_core::launch_fit::Workspace::<T>::new();
        let fit_settings = black_box(carry_core::launch_fit::Settings::<T>::default());
        let fit_scene = black_box(Scene::<T>::default());
        let mut fit = |name: &str, case: &carry_firmware::launch_fit_cases::LaunchFitCase| {
            let (measured, obs) = case
                .inputs::<T>()
                .unwrap_or_else(|_| carry_firmware::exit(1));
            let (measured, obs) = (black_box(measured), black_box(obs));
            op(ticks, k, name, 1, &mut || {
                carry_core::launch_fit::fit_launch(
                    &ball,
                    &fit_scene,
                    &measured,
                    &obs,
                    &fit_settings,
                    &mut ws,
                )
                .map(|f| (u32::from(f.flights), to_f64(f.flight.carry_m)))
            });
        };
        let cases = &carry_firmware::launch_fit_cases::LAUNCH_FIT_CASES;
        fit(
            label!(
                "LAUNCH FIT (a): launch + apex, carry, side, flight time, landing -> spin, axis"
            ),
            &cases[0],
        );
        fit(label!("LAUNCH FIT (a), 7 iron"), &cases[1]);
        fit(
            label!("LAUNCH FIT (b): 32-point track over 1.5 s -> full launch"),
            &cases[3],
        );
        fit(
            label!("LAUNCH FIT (c): Doppler 1 s at 100 Hz + launch, axis -> spin"),
            &cases[4],
        );
        if p == "f32" {
            for case in &carry_firmware::launch_fit_cases::COST_CASES {
                fit(case.name, case);
            }
        }
    }

    let integrator = black_box(Integrator::<T>::default());
    op(
        ticks,
        k,
        label!("full shot + ClubSpec::validate + Scene::prepare"),
        1,
        &mut || {
            shot::full(&spec, &delivery, Solver::Reduced, &scene, &integrator)
                .map(|(_, f)| (f.stats.force_evaluations, to_f64(f.carry_m)))
        },
    );
    let compliant_spec = black_box(shot::driver_compliant::<T>());
    op(
        ticks,
        k,
        label!("full shot + validate + prepare, compliant contact"),
        1,
        &mut || {
            shot::full(
                &compliant_spec,
                &delivery,
                Solver::Reduced,
                &scene,
                &integrator,
            )
            .map(|(_, f)| (f.stats.force_evaluations, to_f64(f.carry_m)))
        },
    );
}

#[entry]
fn main() -> ! {
    let cp = cortex_m::Peripherals::take().unwrap_or_else(|| carry_firmware::exit(1));
    let ticks = Ticks::new(cp.SYST);
    let mut k = 0;
    // Region 0 calibrates: the loop and marker overhead of n = 10 empty calls.
    op(
        &ticks,
        &mut k,
        "empty (calibration, n = 10)",
        10,
        &mut || Ok((0, f64::NAN)),
    );
    op(&ticks, &mut k, "empty (calibration, n = 1)", 1, &mut || {
        Ok((0, f64::NAN))
    });
    suite::<f32>(&ticks, &mut k, "f32");
    suite::<f64>(&ticks, &mut k, "f64");
    defmt::println!("reference carry {=f64} m", shot::REFERENCE_CARRY_M);
    carry_firmware::exit_ok()
}
