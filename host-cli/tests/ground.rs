//! End-to-end tests of the ground options (issue 12): the outputs appear only with a
//! ground, scene and ground files, batch columns, plots, and the bad-input paths (one
//! stderr line, status 2).

mod common;

use common::{Run, json, run, temp_file};

const KEYS: [&str; 6] = [
    "total_m",
    "roll_m",
    "bounces",
    "rest_position_m",
    "time_to_rest_s",
    "still_rolling",
];

#[test]
fn ground_outputs_only_with_a_ground_and_carry_unchanged() {
    let plain = json(&["flight", "--json"]);
    let with = json(&["flight", "--json", "--ground", "fairway"]);
    for k in KEYS {
        assert!(plain["flight"].get(k).is_none(), "{k} without a ground");
        assert!(with["flight"].get(k).is_some(), "{k} missing with a ground");
    }
    assert_eq!(plain["flight"]["carry_m"], with["flight"]["carry_m"]);
    let total = with["flight"]["total_m"].as_f64().expect("total");
    let carry = with["flight"]["carry_m"].as_f64().expect("carry");
    let roll = with["flight"]["roll_m"].as_f64().expect("roll");
    assert!(
        (total - carry - roll).abs() < 1e-9,
        "straight shot: total = carry + roll"
    );
    // CSV: the same keys as columns, only with a ground.
    let Run { stdout: csv, .. } = run(&["flight", "--csv"]);
    assert!(!csv.contains("total_m"));
    let Run { stdout: csv, .. } = run(&["flight", "--csv", "--ground", "green", "--stimp", "11"]);
    let header = csv.lines().next().expect("header");
    assert!(header.ends_with(
        "total_m,roll_m,bounces,rest_position_m_x,rest_position_m_y,rest_position_m_z,time_to_rest_s,still_rolling"
    ));
    let Run { stdout: table, .. } = run(&["shot", "--ground", "rough"]);
    assert!(table.contains("GROUND") && table.contains("total") && table.contains("bounces"));
}

#[test]
fn scene_and_ground_files() {
    let scene = temp_file("scene.toml", "ground = \"green\"\nstimp = 12\n");
    let a = json(&["flight", "--json", "--scene", scene.to_str().expect("utf8")]);
    let b = json(&["flight", "--json", "--ground", "green", "--stimp", "12"]);
    assert_eq!(a["flight"]["total_m"], b["flight"]["total_m"]);
    let table = temp_file(
        "table.toml",
        "[ground]\nsurface = \"fairway\"\nrolling_resistance = 0.2\nslope = 2\nslope_direction = 0\n",
    );
    let c = json(&["flight", "--json", "--scene", table.to_str().expect("utf8")]);
    let file = temp_file(
        "turf.toml",
        "surface = \"fairway\"\nrolling_resistance = 0.2\nslope = 2\n",
    );
    let d = json(&["flight", "--json", "--ground", file.to_str().expect("utf8")]);
    assert_eq!(c["flight"]["total_m"], d["flight"]["total_m"]);
    let e = json(&[
        "flight",
        "--json",
        "--ground",
        "fairway",
        "--rolling-resistance",
        "0.2",
        "--ground-slope",
        "2",
    ]);
    assert_eq!(c["flight"]["total_m"], e["flight"]["total_m"]);
    // Uphill and a slower turf roll less than the firm fairway.
    let f = json(&["flight", "--json", "--ground", "fairway"]);
    assert!(e["flight"]["roll_m"].as_f64() < f["flight"]["roll_m"].as_f64());
    // The grass height (issue 37): the fairway's own 12.7 mm given as an option or a
    // ground file's key is the preset, bit for bit; Penner's 5 mm bounces on, one hop more
    // on this shot.
    let own = json(&[
        "flight",
        "--json",
        "--ground",
        "fairway",
        "--grass-height",
        "0.0127",
    ]);
    assert_eq!(own["flight"]["total_m"], f["flight"]["total_m"]);
    let grass = temp_file(
        "grass.toml",
        "surface = \"fairway\"\ngrass_height = 0.005\n",
    );
    let g = json(&[
        "flight",
        "--json",
        "--ground",
        grass.to_str().expect("utf8"),
    ]);
    let h = json(&[
        "flight",
        "--json",
        "--ground",
        "fairway",
        "--grass-height",
        "0.005",
    ]);
    assert_eq!(g["flight"]["total_m"], h["flight"]["total_m"]);
    assert!(
        g["flight"]["bounces"].as_u64() > f["flight"]["bounces"].as_u64(),
        "{g} {f}"
    );
}

#[test]
fn batch_has_ground_columns_when_the_input_names_a_ground() {
    let input = temp_file(
        "shots.csv",
        "ground,ball_speed\nfairway,70\ngreen,60\nsand,60\nfairway-joint,70\nfairway-trackman,70\n",
    );
    let Run {
        code,
        stdout: out,
        stderr: err,
    } = run(&["batch", "flight", "--input", input.to_str().expect("utf8")]);
    assert_eq!(code, 0, "{err}");
    let lines: Vec<_> = out.lines().collect();
    assert!(lines[0].contains("total_m,roll_m,bounces"));
    assert_eq!(lines.len(), 6);
    assert!(lines[3].contains("unknown surface 'sand'"), "{}", lines[3]);
    // The named turfs by column: the joint fairway's row is `--ground fairway-joint`'s,
    // and differs from the two fairways it was fitted between.
    let total = |line: &str| -> f64 {
        let at = lines[0]
            .split(',')
            .position(|c| c == "total_m")
            .expect("total_m");
        line.split(',')
            .nth(at)
            .expect("cell")
            .parse()
            .expect("number")
    };
    let cli = json(&[
        "flight",
        "--json",
        "--ball-speed",
        "70",
        "--ground",
        "fairway-joint",
    ]);
    let joint = total(lines[4]);
    assert!(
        (joint - cli["flight"]["total_m"].as_f64().expect("total")).abs() < 1e-6,
        "{joint} {cli}"
    );
    assert!(
        joint != total(lines[1]) && joint != total(lines[5]),
        "{out}"
    );
}

#[test]
fn bad_ground_input_is_one_line_and_status_2() {
    let missing = temp_file("missing-dir", "");
    let missing = missing.join("nope.toml");
    for (args, needle) in [
        (vec!["--ground", "sand"], "--ground: unknown surface"),
        (
            vec!["--ground-slope", "3"],
            "--ground: the ground options need a surface",
        ),
        (
            vec!["--ground", "rough", "--stimp", "10"],
            "--stimp: applies to --ground green",
        ),
        (
            vec!["--ground", "green", "--stimp", "40"],
            "--stimp: is out of range",
        ),
        (
            vec!["--ground", "fairway", "--ground-restitution", "1.5"],
            "--ground-restitution",
        ),
        (
            vec!["--ground", "fairway", "--ground-friction", "-1"],
            "--ground-friction",
        ),
        (
            vec!["--ground", "fairway", "--rolling-resistance", "NaN"],
            "--rolling-resistance",
        ),
        (
            vec!["--ground", "fairway", "--ground-slope", "50"],
            "--ground-slope: is out of range",
        ),
        (
            vec!["--ground", "fairway", "--grass-height", "-0.01"],
            "--grass-height: must not be negative (0 to 0.2 m)",
        ),
        (
            vec!["--ground", "fairway", "--grass-height", "0.5"],
            "--grass-height: is out of range (0 to 0.2 m)",
        ),
        (
            vec!["--ground", missing.to_str().expect("utf8")],
            "--ground: cannot read",
        ),
    ] {
        let mut all = vec!["flight"];
        all.extend(args.iter());
        let Run {
            code, stderr: err, ..
        } = run(&all);
        assert_eq!(code, 2, "{all:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{all:?}: {err}");
        assert!(
            err.starts_with(&format!("carry: {needle}")),
            "{all:?}: {err}"
        );
    }
}

#[test]
fn plot_draws_the_run_out() {
    let out = temp_file("run.svg", "");
    let Run {
        code,
        stdout,
        stderr: err,
    } = run(&[
        "plot",
        "flight",
        "--ground",
        "fairway",
        "--vary",
        "launch_angle=9,12",
        "--output",
        out.to_str().expect("utf8"),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        stdout.contains("total") && stdout.contains("roll"),
        "{stdout}"
    );
    assert!(std::fs::metadata(&out).expect("svg").len() > 1000);
}

/// Issue 21: a launch below the horizon meets the ground at once: with a ground it has a
/// total (carry 0); without one it is one line naming the launch angle, status 2. A tee
/// lifts the start; a negative tee height is refused.
#[test]
fn topped_launches_run_out_or_say_why() {
    let out = json(&[
        "flight",
        "--json",
        "--launch-angle",
        "-2",
        "--ground",
        "fairway",
    ]);
    let f = &out["flight"];
    assert_eq!(f["carry_m"].as_f64(), Some(0.0));
    let total = f["total_m"].as_f64().expect("a total");
    assert!(total > 10.0, "{total}");
    let Run {
        code,
        stdout,
        stderr: err,
    } = run(&["flight", "--launch-angle", "-2"]);
    assert_eq!(code, 2);
    assert!(stdout.is_empty());
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("--launch-angle") && err.contains("--ground"),
        "{err}"
    );
    let teed = json(&[
        "flight",
        "--json",
        "--launch-angle",
        "-2",
        "--tee-height",
        "0.05",
    ]);
    assert!(teed["flight"]["carry_m"].as_f64().expect("carry") > 0.0);
    let Run {
        code, stderr: err, ..
    } = run(&["flight", "--tee-height", "-0.1"]);
    assert_eq!(code, 2);
    assert!(err.contains("--tee-height"), "{err}");
}
