//! `--contact` and the presets' typical deliveries through the `carry` binary.

mod common;

use common::{Run, json, run, temp_file};
use serde_json::Value;
use std::path::PathBuf;

fn launch(v: &Value, key: &str) -> f64 {
    v["launch"][key].as_f64().expect("number")
}

/// Half-widths of "a 7-iron a golfer would recognise" around TrackMan's 2023 PGA 7-iron
/// (92 mph: 123 mph ball speed, 16.1° launch, 7124 rpm): 5 % ball speed, 1.5°, 15 % spin.
const SEVEN_IRON: [(&str, f64, f64); 3] = [
    ("ball_speed_mps", 123.0 * 0.44704, 0.05),
    ("launch_angle_deg", 16.1, 1.5),
    ("spin_rpm", 7124.0, 0.15),
];

#[test]
fn a_named_seven_iron_is_recognisable() {
    let v = json(&[
        "shot",
        "--club",
        "7iron",
        "--club-speed",
        "92",
        "--units",
        "imperial",
        "--json",
    ]);
    for (key, want, tol) in SEVEN_IRON {
        let got = launch(&v, key);
        let err = if key == "launch_angle_deg" {
            (got - want).abs()
        } else {
            (got / want - 1.0).abs()
        };
        assert!(err <= tol, "{key}: {got} vs {want}");
    }
}

#[test]
fn contact_names_and_files() {
    let seed = json(&["impact", "--json", "--contact", "rolling"]);
    let fitted = json(&["impact", "--json"]);
    let named = json(&["impact", "--json", "--contact", "compliant"]);
    assert_eq!(fitted["launch"], named["launch"]);
    assert!((launch(&seed, "ball_speed_mps") - 65.879_767_727_750_29).abs() < 1e-9);
    assert_ne!(seed["launch"], fitted["launch"]);
    // a file with every parameter at the seed's limit is the seed's answer (to rounding)
    let file = temp_file(
        "seed.toml",
        "friction = \"inf\"\ntangential_restitution = 0.0\ntangential_restitution_slope = 0.0\nrestitution_speed_slope_spm = 0.0\n",
    );
    let from_file = json(&[
        "impact",
        "--json",
        "--contact",
        file.to_str().expect("utf-8"),
    ]);
    let (a, b) = (launch(&from_file, "spin_rpm"), launch(&seed, "spin_rpm"));
    assert!((a - b).abs() < 1e-6, "{a} vs {b}");
}

#[test]
fn bad_contact_is_one_line_and_status_2() {
    let bad = temp_file("bad.toml", "friction = \n");
    let negative = temp_file("negative.toml", "friction = -0.1\n");
    let unknown = temp_file("unknown.toml", "mu = 0.3\n");
    for args in [
        vec!["impact", "--contact", "sticky"],
        vec!["impact", "--contact", bad.to_str().expect("utf-8")],
        vec!["impact", "--contact", negative.to_str().expect("utf-8")],
        vec!["impact", "--contact", unknown.to_str().expect("utf-8")],
        vec!["impact", "--contact", "/nonexistent/contact.toml"],
        vec!["impact", "--solver", "full"],
    ] {
        let Run {
            code, stderr: err, ..
        } = run(&args);
        assert_eq!(code, 2, "{args:?}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("carry: --contact"), "{args:?}: {err}");
    }
}

#[test]
fn batch_takes_a_contact_column() {
    let csv = temp_file(
        "contact.csv",
        "club_speed,contact\n45,rolling\n45,compliant\n45,sticky\n",
    );
    let Run {
        code, stdout: out, ..
    } = run(&[
        "batch",
        "impact",
        "--input",
        csv.to_str().expect("utf-8"),
        "--json",
    ]);
    assert_eq!(code, 0);
    let rows: Vec<Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).expect("JSON"))
        .collect();
    let seed = json(&["impact", "--json", "--contact", "rolling"]);
    assert_eq!(rows[0]["launch"], seed["launch"]);
    assert_ne!(rows[1]["launch"], seed["launch"]);
    assert!(
        rows[2]["error"]
            .as_str()
            .is_some_and(|e| e.contains("contact"))
    );
}

/// The file the lab's fit writes reads back as the same law.
#[test]
fn the_fit_output_reads_back() {
    let text = carry_lab::fit::impact::to_toml(&carry_core::presets::FITTED_CONTACT, "fitted");
    let file = temp_file("fitted.toml", &text);
    let from_file = json(&[
        "impact",
        "--json",
        "--contact",
        file.to_str().expect("utf-8"),
    ]);
    let named = json(&["impact", "--json", "--contact", "compliant"]);
    assert_eq!(from_file["launch"], named["launch"]);
}

fn club_delivery() -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/data/club_delivery.csv")
        .to_str()
        .expect("utf-8")
        .to_owned()
}

/// `carry fit --family compliant` fits, cross-validates and writes a file `--contact`
/// reads; the mean targets hold for the fitted law.
#[test]
fn fit_compliant_family_round_trip() {
    let data = club_delivery();
    let out = std::env::temp_dir().join(format!("carry-contact-fit-{}.toml", std::process::id()));
    let out_s = out.to_str().expect("utf-8");
    let v = json(&[
        "fit",
        "--family",
        "compliant",
        "--input",
        &data,
        "--output",
        out_s,
        "--json",
        "--no-progress",
    ]);
    assert_eq!(v["family"], "compliant");
    assert_eq!(v["rows"], 11);
    assert_eq!(v["fit"]["converged"], true);
    let summary = |q: usize, k: &str| v["fit"]["summary"][q][k].as_f64().expect("number");
    assert!(summary(0, "mean_abs_pct") <= 2.0);
    assert!(summary(1, "mean_abs") <= 1.0);
    assert!(summary(2, "mean_abs_pct") <= 10.0);
    assert!(v["fit"]["loo_summary"].is_array());
    let fitted = json(&["impact", "--json", "--club", "7iron", "--contact", out_s]);
    let default = json(&["impact", "--json", "--club", "7iron"]);
    assert_ne!(fitted["launch"], default["launch"]);
    let _ = std::fs::remove_file(&out);
}

/// `--evaluate compliant` reports the default law without fitting: docs/impact.md's means.
#[test]
fn fit_compliant_family_evaluates_the_default() {
    let v = json(&[
        "fit",
        "--family",
        "compliant",
        "--input",
        &club_delivery(),
        "--evaluate",
        "compliant",
        "--json",
    ]);
    let summary = |q: usize, k: &str| v["fit"]["summary"][q][k].as_f64().expect("number");
    assert!((summary(0, "mean_abs_pct") - 1.44).abs() < 0.01);
    assert!((summary(1, "mean_abs") - 0.55).abs() < 0.01);
    assert!((summary(2, "mean_abs_pct") - 5.45).abs() < 0.01);
    assert!(summary(2, "max_abs_pct") <= 30.0);
    let Run {
        code, stderr: err, ..
    } = run(&[
        "fit",
        "--family",
        "compliant",
        "--input",
        &club_delivery(),
        "--evaluate",
        "rolling",
    ]);
    assert_eq!(code, 2);
    assert!(err.starts_with("carry: --evaluate"), "{err}");
}

/// Issue 34: `--spin-axis-share K` scales the launch's spin-axis tangent by K and leaves
/// ball speed, launch and total spin alone (the empirical D-plane share, an option beside
/// the physics: the default is the impact's own axis); in a batch it is a column; a share
/// outside (0, 1] is one line naming the option, status 2.
#[test]
fn spin_axis_share_scales_the_axis_only() {
    let args = ["impact", "--json", "--face-angle", "3", "--club-path", "-1"];
    let physics = json(&args);
    let same = json(&[&args[..], &["--spin-axis-share", "1"]].concat());
    assert_eq!(physics["launch"], same["launch"]);
    let half = json(&[&args[..], &["--spin-axis-share", "0.5"]].concat());
    for key in ["ball_speed_mps", "launch_angle_deg", "launch_direction_deg"] {
        assert_eq!(launch(&half, key), launch(&physics, key), "{key}");
    }
    assert!((launch(&half, "spin_rpm") / launch(&physics, "spin_rpm") - 1.0).abs() < 1e-12);
    let tan = |v: &Value| launch(v, "spin_axis_deg").to_radians().tan();
    assert!(tan(&physics).abs() > 0.1, "{}", tan(&physics));
    assert!((tan(&half) - 0.5 * tan(&physics)).abs() < 1e-9);
    let csv = temp_file(
        "share.csv",
        "face_angle,club_path,spin_axis_share\n3,-1,1\n3,-1,0.5\n3,-1,0\n",
    );
    let Run { code, stdout, .. } = run(&["batch", "impact", "--input", &csv.display().to_string()]);
    assert_eq!(code, 0);
    let lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(lines.len(), 4, "{stdout}");
    assert!(lines[3].contains("spin_axis_share"), "{}", lines[3]);
    for bad in ["0", "1.01", "-0.2", "nan"] {
        let Run { code, stderr, .. } = run(&["impact", "--spin-axis-share", bad]);
        assert_eq!(code, 2, "{bad}: {stderr}");
        assert!(
            stderr.starts_with("carry: --spin-axis-share"),
            "{bad}: {stderr}"
        );
        assert_eq!(stderr.trim().lines().count(), 1);
    }
}
