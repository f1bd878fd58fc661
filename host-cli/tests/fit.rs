//! `carry fit` and `--aero` end to end: the fit on the measured data, model files round
//! trip, bad input is one line and status 2.

mod common;

use common::{Run, json, run, temp_file};
use serde_json::Value;
use std::path::PathBuf;

fn tour_data() -> Option<String> {
    let p =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/data/trackman_tour_2023.csv");
    p.exists().then(|| p.display().to_string())
}

/// Shots flown with the seed model (values from `carry flight --aero quintavalla`), in
/// the CLI's own column names and imperial units.
fn seed_shots() -> PathBuf {
    let mut csv =
        String::from("label,ball_speed,launch_angle,spin,spin_axis,carry,apex,land_angle\n");
    for (i, (speed, angle, spin)) in [
        (167.0, 10.9, 2686.0),
        (120.0, 16.3, 7097.0),
        (102.0, 24.2, 9304.0),
    ]
    .into_iter()
    .enumerate()
    {
        let f = json(&[
            "flight",
            "--json",
            "--aero",
            "quintavalla",
            "--units",
            "imperial",
            "--ball-speed",
            &speed.to_string(),
            "--launch-angle",
            &angle.to_string(),
            "--spin",
            &spin.to_string(),
        ]);
        let fl = &f["flight"];
        let (carry, apex) = (
            fl["carry_m"].as_f64().unwrap_or(0.0),
            fl["apex_m"].as_f64().unwrap_or(0.0),
        );
        csv.push_str(&format!(
            "shot {i},{speed},{angle},{spin},0,{},{},{}\n",
            carry / 0.9144,
            apex / 0.3048,
            fl["land_angle_deg"].as_f64().unwrap_or(0.0)
        ));
    }
    temp_file("seed.csv", &csv)
}

#[test]
fn evaluating_the_seed_on_its_own_shots_gives_zero_error() {
    let input = seed_shots();
    let v = json(&[
        "fit",
        "--input",
        input.to_str().unwrap_or(""),
        "--units",
        "imperial",
        "--evaluate",
        "quintavalla",
        "--json",
    ]);
    assert_eq!(v["family"], "quintavalla");
    assert_eq!(v["rows"], 3);
    let carry = &v["fit"]["summary"][0];
    assert!(
        carry["max_abs"].as_f64().is_some_and(|e| e < 1e-3),
        "{carry}"
    );
    // The calibrated model does not fly the seed's shots the same.
    let v = json(&[
        "fit",
        "--input",
        input.to_str().unwrap_or(""),
        "--units",
        "imperial",
        "--evaluate",
        "tour2023",
        "--json",
    ]);
    assert!(
        v["fit"]["summary"][0]["max_abs"]
            .as_f64()
            .is_some_and(|e| e > 1.0)
    );
}

#[test]
fn fits_the_tour_data_and_the_model_file_round_trips() {
    let Some(data) = tour_data() else {
        return; // ../shared absent
    };
    let model = std::env::temp_dir().join(format!("carry-fit-model-{}.toml", std::process::id()));
    let m = model.to_str().unwrap_or("");
    let conditions = [
        "--temperature",
        "21.1",
        "--humidity",
        "50",
        "--pressure",
        "101325",
    ];
    let mut args = vec!["fit", "--input", &data, "--json", "--output", m];
    args.extend(conditions);
    let v = json(&args);
    assert_eq!(v["rows"], 23);
    assert_eq!(v["fit"]["converged"], true);
    let carry = &v["fit"]["summary"][0];
    assert!(
        carry["mean_abs_pct"].as_f64().is_some_and(|e| e < 2.0),
        "{carry}"
    );
    assert!(
        v["fit"]["loo_summary"][0]["mean_abs_pct"]
            .as_f64()
            .is_some_and(|e| e < 2.5)
    );
    assert_eq!(
        v["ignored_columns"],
        serde_json::json!(["club_speed_mph", "attack_deg", "smash"])
    );
    assert_eq!(v["fit"]["rows"][0]["label"], "PGA driver");
    // The written model reproduces the fit exactly.
    let mut args = vec!["fit", "--input", &data, "--json", "--evaluate", m];
    args.extend(conditions);
    let e = json(&args);
    assert_eq!(
        e["fit"]["rows"],
        v["fit"]["rows"]
            .as_array()
            .map(|rows| {
                rows.iter()
                    .map(|r| {
                        let mut r = r.clone();
                        r["loo_predicted"] = Value::Null;
                        r
                    })
                    .collect::<Vec<_>>()
            })
            .map(Value::from)
            .unwrap_or_default()
    );
    // And flies.
    let Run {
        code, stderr: err, ..
    } = run(&["flight", "--aero", m]);
    assert_eq!(code, 0, "{err}");
}

#[test]
fn a_model_file_flies_bit_for_bit_like_the_built_in() {
    let file = temp_file(
        "q.toml",
        "family = \"quintavalla\"\ncd0 = 0.171\ncd_spin = 0.62\ncl0 = 0.083\ncl_spin = 0.885\ncm_spin = 0.0125\n",
    );
    let a = json(&["flight", "--json", "--aero", file.to_str().unwrap_or("")]);
    let b = json(&["flight", "--json", "--aero", "quintavalla"]);
    assert_eq!(a["flight"], b["flight"]);
    // Scene files name the model too (a relative path is relative to the scene file).
    let scene = temp_file("scene.toml", "aero = \"q.toml\"\n");
    let c = json(&["flight", "--json", "--scene", scene.to_str().unwrap_or("")]);
    assert_eq!(c["flight"], b["flight"]);
    // The calibrated default is what no option gives; `tour2023` stays selectable.
    let d = json(&["flight", "--json"]);
    let e = json(&["flight", "--json", "--aero", "drives2026"]);
    assert_eq!(d["flight"], e["flight"]);
    assert_ne!(d["flight"]["carry_m"], b["flight"]["carry_m"]);
    let t = json(&["flight", "--json", "--aero", "tour2023"]);
    assert_ne!(d["flight"]["carry_m"], t["flight"]["carry_m"]);
}

#[test]
fn bad_input_is_one_line_and_status_two() {
    let bad_row = temp_file(
        "bad.csv",
        "ball_speed,launch_angle,spin,carry\n70,12,2500,230\n70,twelve,2500,230\n",
    );
    let no_carry = temp_file("nocarry.csv", "ball_speed,launch_angle,spin\n70,12,2500\n");
    let bad_model = temp_file("bad.toml", "family = \"modern\"\ncl_max = -1\n");
    let unknown_key = temp_file("unknown.toml", "family = \"modern\"\ncl_maximum = 0.3\n");
    let good = temp_file(
        "good.csv",
        "ball_speed,launch_angle,spin,carry\n70,12,2500,230\n",
    );
    let row = good.to_str().unwrap_or("");
    let bound = |b: &'static str| vec!["fit", "--input", row, "--bound", b];
    let cases: [(Vec<&str>, &str); 10] = [
        (
            bound("9:0.01:0.4"),
            "--bound: '9:0.01:0.4': no parameter '9'",
        ),
        (bound("cd_low:0.1:0.2"), "no parameter 'cd_low'"),
        (
            bound("8:0.4:0.01"),
            "the lower bound must be below the upper",
        ),
        (bound("8:0.01"), "expected INDEX:LO:HI"),
        (
            vec!["fit", "--input", bad_row.to_str().unwrap_or("")],
            "line 3: launch_angle: 'twelve' is not a number",
        ),
        (
            vec!["fit", "--input", no_carry.to_str().unwrap_or("")],
            "no 'carry' column",
        ),
        (
            vec![
                "fit",
                "--input",
                bad_row.to_str().unwrap_or(""),
                "--family",
                "smooth",
            ],
            "unknown family 'smooth'",
        ),
        (
            vec!["flight", "--aero", bad_model.to_str().unwrap_or("")],
            "lift coefficient is out of range",
        ),
        (
            vec!["flight", "--aero", unknown_key.to_str().unwrap_or("")],
            "unknown key 'cl_maximum'",
        ),
        (
            vec!["flight", "--aero", "nonsense"],
            "neither a built-in model",
        ),
    ];
    for (args, needle) in cases {
        let Run {
            code,
            stdout: out,
            stderr: err,
        } = run(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty());
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

/// `--also` joins more inputs: the tour table and the 2010 chart fitted jointly reproduce
/// `tour2023` (`--evaluate tour2023` on the same rows gives the same errors); the compliant
/// family reads only delivery tables, so the tour table as its input is refused with
/// status 2, naming the input.
#[test]
fn joins_inputs_with_also() {
    let Some(data) = tour_data() else {
        return; // ../shared absent
    };
    let chart = data.replace(
        "trackman_tour_2023.csv",
        "trackman_driver_optimizer_2010.csv",
    );
    let conditions = [
        "--temperature",
        "21.1",
        "--humidity",
        "50",
        "--pressure",
        "101325",
    ];
    let mut args = vec![
        "fit",
        "--input",
        &data,
        "--also",
        &chart,
        "--json",
        "--no-cross-validation",
    ];
    args.extend(conditions);
    let v = json(&args);
    assert_eq!(v["rows"], 53);
    assert_eq!(v["fit"]["converged"], true);
    // The chart's rows observe carry only.
    assert_eq!(v["fit"]["rows"][52]["observed"][1], Value::Null);
    let mut args = vec![
        "fit",
        "--input",
        &data,
        "--also",
        &chart,
        "--json",
        "--evaluate",
        "tour2023",
    ];
    args.extend(conditions);
    let e = json(&args);
    let mean = |x: &Value| {
        x["fit"]["summary"][0]["mean_abs_pct"]
            .as_f64()
            .unwrap_or(f64::NAN)
    };
    assert!(
        (mean(&v) - mean(&e)).abs() < 0.01,
        "{} {}",
        mean(&v),
        mean(&e)
    );
    let Run {
        code, stderr: err, ..
    } = run(&[
        "fit",
        "--family",
        "compliant",
        "--input",
        &data,
        "--also",
        &chart,
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.starts_with("carry: --input"), "{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
}

/// The first `n` drives of the shared single-drive export (header, units line, rows),
/// written to a scratch file for one test: read from `../shared` at test time, never kept
/// in the project (the file is removed when the returned guard drops). `None` when
/// `../shared` is absent.
fn drives_sample(n: usize) -> Option<Removed> {
    let data = tour_data()?.replace("trackman_tour_2023.csv", "trackman_amateur_drives.csv");
    let text = std::fs::read_to_string(&data).ok()?;
    let sample: Vec<&str> = text.lines().take(2 + n).collect();
    Some(Removed(temp_file(
        "drives-sample.csv",
        &(sample.join("\n") + "\n"),
    )))
}

/// A scratch file removed when dropped.
struct Removed(PathBuf);

impl Drop for Removed {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

/// Issue 34, item 2: `carry fit --family compliant` fits the contact on delivery tables, a
/// driver chart (no `club` column) and single drives together: every row is read (the
/// drives with a full delivery and launch), the drives weigh `1/--table-weight` times the
/// tables in total, k_e stays in Penner's measured range, and a bad table weight is one
/// line naming `--table-weight` with status 2.
#[test]
fn compliant_family_fits_tables_and_single_drives_together() {
    let Some(delivery) =
        tour_data().map(|d| d.replace("trackman_tour_2023.csv", "club_delivery.csv"))
    else {
        return; // ../shared absent
    };
    let chart = delivery.replace("club_delivery.csv", "trackman_driver_optimizer_2010.csv");
    let Some(sample) = drives_sample(40) else {
        return;
    };
    let drives = sample.0.display().to_string();
    // tables alone: club_delivery.csv's 11 rows and the chart's 30 driver rows
    let t = json(&[
        "fit",
        "--family",
        "compliant",
        "--input",
        &delivery,
        "--also",
        &chart,
        "--json",
        "--no-cross-validation",
    ]);
    assert_eq!(t["rows"], 41, "{t}");
    assert_eq!(
        t["fit"]["rows"][40]["label"],
        "trackman_driver_optimizer_2010"
    );
    let j = json(&[
        "fit",
        "--family",
        "compliant",
        "--input",
        &delivery,
        "--also",
        &chart,
        "--also",
        &drives,
        "--json",
        "--no-cross-validation",
        "--table-weight",
        "2",
    ]);
    let n = j["drives"]["rows"].as_u64().unwrap_or(0);
    assert!(n > 20 && n <= 40, "{j}");
    assert_eq!(j["tables"]["rows"], 41);
    assert_eq!(j["rows"].as_u64(), Some(n + 41));
    let weight = j["drives"]["weight_each"].as_f64().unwrap_or(f64::NAN);
    #[allow(clippy::cast_precision_loss)]
    let expected = 41.0 / n as f64 / 2.0;
    assert!((weight - expected).abs() < 1e-12, "{weight} {expected}");
    let k_e = j["coefficients"]["restitution_speed_slope_spm"]
        .as_f64()
        .unwrap_or(f64::NAN);
    assert!((0.002..=0.004).contains(&k_e), "{k_e}");
    assert!(
        j["drives"]["summary"][2]["mean_abs_pct"]
            .as_f64()
            .is_some_and(f64::is_finite)
    );
    let Run {
        code, stderr: err, ..
    } = run(&[
        "fit",
        "--family",
        "compliant",
        "--input",
        &delivery,
        "--also",
        &drives,
        "--table-weight",
        "0",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.starts_with("carry: --table-weight"), "{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
}

/// `--bound` replaces a parameter's bounds (by index or name) and the fit stays in them:
/// the seed's own shots give back the seed's `cd0` = 0.171 within the family's bounds, and
/// stop on a bound of 0.2–0.3 (the start moved into it).
#[test]
fn bound_replaces_a_parameters_bounds() {
    let input = seed_shots();
    let fit = |extra: &[&str]| {
        let mut args = vec![
            "fit",
            "--input",
            input.to_str().unwrap_or(""),
            "--units",
            "imperial",
            "--family",
            "quintavalla",
            "--no-cross-validation",
            "--json",
        ];
        args.extend(extra);
        json(&args)["fit"]["parameters"][0].clone()
    };
    let free = fit(&[]);
    assert!(
        free["value"]
            .as_f64()
            .is_some_and(|v| (v - 0.171).abs() < 1e-3),
        "{free}"
    );
    for which in ["0:0.2:0.3", "cd0:0.2:0.3"] {
        let p = fit(&["--bound", which]);
        assert_eq!(p["lower"], 0.2, "{p}");
        assert_eq!(p["upper"], 0.3, "{p}");
        assert!(
            p["value"]
                .as_f64()
                .is_some_and(|v| (0.2..0.2 + 1e-3).contains(&v)),
            "{p}"
        );
        assert!(p["initial"].as_f64().is_some_and(|v| v >= 0.2), "{p}");
    }
}
