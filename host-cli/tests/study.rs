//! End-to-end test of `carry bench accuracy --quick` (the accuracy–cost study, issue 6):
//! the reduced sweep runs in well under a second even unoptimised.

mod common;

use common::carry;
use serde_json::Value;

fn quick_json() -> Value {
    let out = carry()
        .args(["bench", "accuracy", "--quick", "--json"])
        .output()
        .expect("carry runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON")
}

#[test]
fn quick_study_checks_its_reference_and_measures_every_axis() {
    let v = quick_json();
    assert_eq!(v["quick"], true);
    // The reference agrees with both golden files.
    assert_eq!(v["reference"]["passed"], true, "{}", v["reference"]);
    assert!(v["reference"]["flight_cases"].as_u64() >= Some(1));
    assert!(v["reference"]["impact_cases"].as_u64() >= Some(1));

    // Every axis: precision × solver × integrator, each with a sweep.
    let rows = v["flight"].as_array().expect("rows");
    for prec in ["f64", "f32"] {
        for solver in ["reduced", "full"] {
            for integ in ["euler", "rk4", "dp45"] {
                let n = rows
                    .iter()
                    .filter(|r| {
                        r["setting"]["precision"] == prec
                            && r["setting"]["solver"] == solver
                            && r["setting"]["integrator"] == integ
                    })
                    .count();
                assert!(n >= 2, "{prec} {solver} {integ}: {n} settings");
            }
        }
    }
    for r in rows {
        assert!(r["evals_mean"].as_f64() > Some(0.0), "{r}");
        assert!(r["us_per_shot"].as_f64() > Some(0.0), "{r}");
        let carry = r["errors"]["carry_m"]["worst"]
            .as_f64()
            .expect("carry error");
        assert!(carry.is_finite() && carry >= 0.0, "{r}");
    }

    // The defaults (one per precision) meet the 1 cm target and sit on their front.
    let defaults: Vec<&Value> = rows
        .iter()
        .filter(|r| r["setting"]["is_default"] == true)
        .collect();
    assert_eq!(defaults.len(), 2);
    for d in defaults {
        assert_eq!(d["within_1cm"], true, "{d}");
        assert_eq!(d["pareto_evals"], true, "{d}");
    }
    // Each precision has a non-empty Pareto front.
    for prec in ["f64", "f32"] {
        assert!(
            rows.iter()
                .any(|r| r["setting"]["precision"] == prec && r["pareto_time"] == true)
        );
    }

    // Impact: both solvers in both precisions, f64 exact to rounding.
    let impact = v["impact"].as_array().expect("impact rows");
    assert!(impact.len() >= 4);
    for r in impact {
        let e = r["errors"]["ball_speed_mps"]["worst"]
            .as_f64()
            .expect("error");
        let bound = if r["precision"] == "f64" { 1e-9 } else { 1e-3 };
        assert!(e <= bound, "{r}");
    }

    // Scaling: fixed steps grow linearly with flight time, the adaptive one slower.
    let slopes = v["scaling"]["slopes"].as_array().expect("slopes");
    let slope = |name: &str| {
        slopes
            .iter()
            .find(|s| {
                s["integrator"]
                    .as_str()
                    .is_some_and(|n| n.starts_with(name))
            })
            .and_then(|s| s["evals_slope"].as_f64())
            .expect("slope")
    };
    assert!((slope("euler") - 1.0).abs() < 0.05);
    assert!((slope("rk4") - 1.0).abs() < 0.05);
    assert!(slope("dp45") < 0.9);
    assert!(!v["conclusions"].as_array().expect("conclusions").is_empty());
}

#[test]
fn quick_study_table_and_svg() {
    let dir = std::env::temp_dir().join(format!("carry-study-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let svg = dir.join("pareto.svg");
    let out = carry()
        .args(["bench", "accuracy", "--quick", "--svg"])
        .arg(&svg)
        .output()
        .expect("carry runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    for needle in [
        "Reference:",
        "Impact",
        "Full shot",
        "Pareto",
        "Conclusions",
        "passed",
    ] {
        assert!(text.contains(needle), "missing {needle}:\n{text}");
    }
    let drawing = std::fs::read_to_string(&svg).expect("svg written");
    assert!(drawing.starts_with("<svg") && drawing.contains("Pareto front"));
    let _ = std::fs::remove_dir_all(&dir);
}
