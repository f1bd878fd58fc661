//! Issue 35, item 2: the run-out against TrackMan's roll on the single amateur drives
//! (`../shared/data/trackman_amateur_drives.csv`, read where it lies), by landing band,
//! before (the seed's firm fairway; the first pass's `fairway-trackman`, Penner's crater)
//! and after (the turf with the normal–tangential crater fitted to the indoor rows), with
//! the session cross-validation, the topped drives and the outdoor rows apart; then
//! TrackMan's 2010 chart on each turf (docs/ground.md, "Issue 35").
//!
//! Each run-out starts at TrackMan's landing (its angle and speed; heading and spin from
//! the flight of TrackMan's launch with `drives2026`): `carry_lab::ground_drives`.
//! Totals are given two ways: TrackMan's carry plus the model's roll (the ground alone),
//! and flown end to end from the launch (`drives2026`'s carry too).
//! Conditions: 21.1 °C, 50 % RH, 101 325 Pa, no wind, level ground.
//!
//! `cargo run --release -p carry-lab --example ground_single_shots [--no-cv]`
use carry_core::aero::AeroModel;
use carry_core::ground::bounce::CRATER_FADE_NORMAL_SPEED_MPS;
use carry_core::ground::surface::{GRASS_DRAG_S2PM2, PENNER_FRICTION, PENNER_RESTITUTION_0};
use carry_core::ground::{CraterLaw, Surface, Turf};
use carry_core::units::{deg, rpm};
use carry_core::{Integrator, Launch};
use carry_lab::drives;
use carry_lab::ground_drives::{self as gd, BANDS, BandFigures, Landing};
use carry_lab::ground_fit::{YARD_M, chart_scene, mean_abs, parse_chart, roll_rows, turf_line};

/// The seed's firm fairway (issue 21: the 2010 chart's ρ₀ with Penner's bounce).
const SEED_FAIRWAY: Turf<f64> = Turf {
    restitution: PENNER_RESTITUTION_0,
    friction: PENNER_FRICTION,
    rolling_resistance: 0.063,
    crater_scale: 1.0,
    crater_fade_mps: CRATER_FADE_NORMAL_SPEED_MPS,
    grass_drag_s2pm2: GRASS_DRAG_S2PM2,
    crater_law: CraterLaw::Penner,
    // (The seed's and the first pass's stop: Penner's 5 mm on every turf.)
    grass_height_m: carry_core::ground::STOP_HEIGHT_M,
};

/// `fairway-trackman` as the first pass of issue 35 left it: Penner's crater law, fitted to
/// the landing bands alone (with `tour2023`'s landing spin).
const FIRST_PASS_TRACKMAN: Turf<f64> = Turf {
    restitution: 0.20,
    friction: 0.376,
    rolling_resistance: 0.0796,
    crater_scale: 0.609,
    crater_fade_mps: 2.13,
    grass_drag_s2pm2: 0.657,
    crater_law: CraterLaw::Penner,
    grass_height_m: carry_core::ground::STOP_HEIGHT_M,
};

/// The fit's start: the seed's firm fairway with the crater of the impact's normal and
/// tangential speeds.
const START: Turf<f64> = Turf {
    crater_law: CraterLaw::NormalTangential,
    grass_height_m: carry_core::ground::surface::FAIRWAY_GRASS_HEIGHT_M,
    ..FIRST_PASS_TRACKMAN
};

fn band_name(i: usize) -> String {
    let (lo, hi) = BANDS[i];
    if lo.is_infinite() {
        format!("< {hi:.0}°")
    } else if hi.is_infinite() {
        format!("> {lo:.0}°")
    } else {
        format!("{lo:.0}–{hi:.0}°")
    }
}

fn cell(b: &BandFigures) -> String {
    format!("{:5.1} ({:+5.1})", b.mean_abs_yd, b.bias_yd)
}

/// Total errors (mean |rel|, bias) as "a % (b %)".
fn pct((a, b, n): (f64, f64, usize)) -> String {
    format!("{:5.1} % ({:+5.1} %) n {n}", 100.0 * a, 100.0 * b)
}

fn main() -> Result<(), String> {
    let cv = !std::env::args().any(|a| a == "--no-cv");
    // The flight (each drive's landing spin and heading, the end-to-end totals, the chart's
    // carries): `drives2026`, the modern family fitted to these drives.
    let air = carry_core::Scene {
        aero: AeroModel::drives_2026(),
        ..chart_scene(Surface::FairwayFirm)
    };
    let all = drives::read_shared()?;
    let landings = gd::landings(&all, &air)?;
    let indoor = |l: &Landing| !l.outdoors;
    let outdoor = |l: &Landing| l.outdoors;
    println!(
        "{} drives with launch, carry, total and landing: {} indoor, {} outdoor",
        landings.len(),
        landings.iter().filter(|l| indoor(l)).count(),
        landings.iter().filter(|l| outdoor(l)).count()
    );

    let preset = Surface::<f64>::FairwayTrackman
        .turf()
        .map_err(|e| e.to_string())?;
    let (fitted, cost) = gd::fit_turf(&landings, &air, START, &indoor)?;
    println!("\nseed fairway:   {}", turf_line(&SEED_FAIRWAY));
    println!("first pass:     {}", turf_line(&FIRST_PASS_TRACKMAN));
    println!(
        "fitted (all indoor rows, fit cost {cost:.2} yd): {}",
        turf_line(&fitted)
    );
    println!("fairway-trackman preset: {}", turf_line(&preset));

    let seed_ground = gd::on_ground(&air, Surface::Custom(SEED_FAIRWAY))?;
    let first_ground = gd::on_ground(&air, Surface::Custom(FIRST_PASS_TRACKMAN))?;
    let fit_ground = gd::on_ground(&air, Surface::Custom(fitted))?;
    let preset_ground = gd::on_ground(&air, Surface::FairwayTrackman)?;
    let roll_seed = gd::rolls(&landings, &seed_ground);
    let roll_first = gd::rolls(&landings, &first_ground);
    let roll_fit = gd::rolls(&landings, &fit_ground);
    let roll_preset = gd::rolls(&landings, &preset_ground);

    // Session cross-validation: each session's rows predicted by the turf fitted to the others.
    let folds = if cv {
        gd::cross_validate(&landings, &air, START)?
    } else {
        Vec::new()
    };
    let cv_rows: Vec<Landing> = folds.iter().flat_map(|f| f.rows.clone()).collect();
    let cv_rolls: Vec<f64> = folds.iter().flat_map(|f| f.rolls_m.clone()).collect();

    let b_seed = gd::band_figures(&landings, &roll_seed, indoor);
    let b_first = gd::band_figures(&landings, &roll_first, indoor);
    let b_fit = gd::band_figures(&landings, &roll_fit, indoor);
    let b_preset = gd::band_figures(&landings, &roll_preset, indoor);
    let b_cv = gd::band_figures(&cv_rows, &cv_rolls, |_| true);
    let b_out_seed = gd::band_figures(&landings, &roll_seed, outdoor);
    let b_out_preset = gd::band_figures(&landings, &roll_preset, outdoor);
    println!("\nroll from TrackMan's landing, model − TrackMan, mean |err| (bias) yd; indoor rows");
    println!(
        "| band | rows | TrackMan roll | seed fairway | first pass | fitted, all rows | session CV | preset | outdoor rows | outdoor: seed | outdoor: preset |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for i in 0..BANDS.len() {
        println!(
            "| {} | {} | {:.1} | {} | {} | {} | {} | {} | {} | {} | {} |",
            band_name(i),
            b_seed[i].rows,
            b_seed[i].trackman_yd,
            cell(&b_seed[i]),
            cell(&b_first[i]),
            cell(&b_fit[i]),
            cell(&b_cv[i]),
            cell(&b_preset[i]),
            b_out_seed[i].rows,
            cell(&b_out_seed[i]),
            cell(&b_out_preset[i]),
        );
    }

    // Totals: TrackMan's carry plus the model's roll, and flown end to end.
    let plus_carry = |rolls: &[f64], rows: &[Landing]| -> Vec<f64> {
        rows.iter().zip(rolls).map(|(l, r)| l.carry_m + r).collect()
    };
    let end_seed = gd::totals_end_to_end(&landings, &seed_ground);
    let end_preset = gd::totals_end_to_end(&landings, &preset_ground);
    let topped = |l: &Landing| indoor(l) && l.topped();
    let low = |l: &Landing| indoor(l) && l.land_angle_deg < 15.0;
    println!("\ntotal, mean |model − TrackMan| / TrackMan (bias)");
    println!(
        "| rows | seed: TM carry + roll | first pass: TM carry + roll | preset: TM carry + roll | session CV: TM carry + roll | seed: flown end to end | preset: flown end to end |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|");
    type Pick<'a> = (&'a str, &'a dyn Fn(&Landing) -> bool);
    let picks: [Pick<'_>; 4] = [
        ("indoor", &indoor),
        ("indoor topped (launch ≤ 0.5°)", &topped),
        ("indoor landing < 15°", &low),
        ("outdoor (own weather)", &outdoor),
    ];
    for (name, keep) in picks {
        let keep_cv = |l: &Landing| keep(l);
        println!(
            "| {name} | {} | {} | {} | {} | {} | {} |",
            pct(gd::total_error(
                &landings,
                &plus_carry(&roll_seed, &landings),
                keep
            )),
            pct(gd::total_error(
                &landings,
                &plus_carry(&roll_first, &landings),
                keep
            )),
            pct(gd::total_error(
                &landings,
                &plus_carry(&roll_preset, &landings),
                keep
            )),
            if cv {
                pct(gd::total_error(
                    &cv_rows,
                    &plus_carry(&cv_rolls, &cv_rows),
                    keep_cv,
                ))
            } else {
                "–".to_owned()
            },
            pct(gd::total_error(&landings, &end_seed, keep)),
            pct(gd::total_error(&landings, &end_preset, keep)),
        );
    }

    if cv {
        println!("\nsession folds (fitted on the other sessions' indoor rows)");
        println!(
            "| held out | rows | fitted turf | held-out fit cost (yd) | held-out band cost (yd) | held-out total |"
        );
        println!("|---:|---:|---|---:|---:|---:|");
        for f in &folds {
            println!(
                "| {} | {} | {} | {:.2} | {:.2} | {} |",
                f.held_out,
                f.rows.len(),
                turf_line(&f.turf),
                gd::fit_cost(&f.rows, &f.rolls_m),
                gd::cost(&gd::band_figures(&f.rows, &f.rolls_m, |_| true)),
                pct(gd::total_error(
                    &f.rows,
                    &plus_carry(&f.rolls_m, &f.rows),
                    |_| true
                )),
            );
        }
    }

    // TrackMan's 2010 chart (its own launches flown with the default aerodynamics).
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../shared/data/trackman_driver_optimizer_2010.csv");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let chart = parse_chart(&text)?;
    println!("\nTrackMan's 2010 chart (drives2026), mean |err| yd: roll, total");
    for (name, turf) in [
        ("seed fairway", SEED_FAIRWAY),
        ("first pass", FIRST_PASS_TRACKMAN),
        ("fitted", fitted),
        ("preset", preset),
    ] {
        let scene = carry_core::Scene {
            aero: air.aero,
            ..chart_scene(Surface::Custom(turf))
        };
        let rows = roll_rows(&chart, &scene)?;
        println!(
            "{name:12}: roll {:.2}, total {:.2} (carry {:.2})",
            mean_abs(rows.iter().map(|r| r.roll_error_yd())),
            mean_abs(rows.iter().map(|r| r.total_error_yd())),
            mean_abs(rows.iter().map(|r| r.carry_yd.1 - r.carry_yd.0)),
        );
    }

    // Roll from a landing (a launch downwards from the turf) with 2,000 rpm of backspin.
    println!(
        "\nroll (yd) from a landing at angle (rows) and speed (columns, m/s), 2,000 rpm: fairway -> first pass -> fairway-trackman"
    );
    let speeds = [22.0, 26.0, 30.0, 34.0, 38.0, 46.0];
    for angle in [0.5, 2.0, 8.0, 17.0, 30.0, 40.0] {
        print!("| {angle}° |");
        for v in speeds {
            let motion = Launch {
                ball_speed_mps: v,
                launch_angle_rad: deg(-angle),
                launch_direction_rad: 0.0,
                backspin_radps: rpm(2000.0),
                sidespin_radps: 0.0,
            }
            .ball_motion()
            .map_err(|e| e.to_string())?;
            let roll = |g: &carry_core::PreparedScene<f64>| -> Result<f64, String> {
                let o = g
                    .fly(&motion, &Integrator::default(), None)
                    .map_err(|e| e.to_string())?;
                Ok(o.ground.map_or(f64::NAN, |r| r.total_m / YARD_M))
            };
            print!(
                " {:.1} → {:.1} → {:.1} |",
                roll(&seed_ground)?,
                roll(&first_ground)?,
                roll(&preset_ground)?
            );
        }
        println!();
    }
    Ok(())
}
