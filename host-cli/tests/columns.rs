//! Issue 24, item 4: every `carry batch` reads the others' output columns, and `--input -`
//! reads standard input, so `carry batch impact --input d.csv | carry batch flight --input -`
//! works — and flies exactly the launch the impact wrote.

mod common;

use common::carry;

fn batch(mode: &str, extra: &[&str], stdin: &str) -> (String, String) {
    let out = carry()
        .args(["batch", mode, "--input", "-"])
        .args(extra)
        .write_stdin(stdin.to_owned())
        .output()
        .expect("carry runs");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    (
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The rows of a CSV as (header, rows), fields split on commas (no quoting in these).
fn table(csv: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut lines = csv.lines();
    let header = lines
        .next()
        .unwrap_or_default()
        .split(',')
        .map(str::to_owned)
        .collect();
    let rows = lines
        .map(|l| l.split(',').map(str::to_owned).collect())
        .collect();
    (header, rows)
}

fn column<'a>(t: &'a (Vec<String>, Vec<Vec<String>>), name: &str) -> Vec<&'a str> {
    let i =
        t.0.iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("no column {name} in {:?}", t.0));
    t.1.iter().map(|r| r[i].as_str()).collect()
}

fn flight_json(args: &[String]) -> serde_json::Value {
    let out = carry()
        .arg("flight")
        .args(args)
        .arg("--json")
        .output()
        .expect("carry runs");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON")
}

#[test]
fn impact_output_pipes_into_flight() {
    let input = "label,club,club_speed,attack_angle\n\
                 drive,driver,45,3\n\
                 iron,7iron,38,-4\n\
                 bad,driver,-5,0\n";
    // Imperial units on the flight side: the read-back launch columns stay SI.
    let (impact, _) = batch("impact", &[], input);
    let (flight, stderr) = batch("flight", &["--units", "imperial"], &impact);
    let i = table(&impact);
    let f = table(&flight);
    assert_eq!(f.1.len(), 3);
    assert_eq!(column(&f, "label"), ["drive", "iron", "bad"]);
    // The failed impact row stays a failed row, with its reason.
    let errors = column(&f, "error");
    assert!(errors[0].is_empty() && errors[1].is_empty(), "{errors:?}");
    assert!(errors[2].contains("the input row failed"), "{errors:?}");
    assert!(stderr.contains("1 of 3 rows"), "{stderr}");
    // The launch flown is the launch the impact wrote, digit for digit.
    for name in [
        "ball_speed_mps",
        "launch_angle_deg",
        "launch_direction_deg",
        "backspin_rpm",
        "sidespin_rpm",
    ] {
        assert_eq!(column(&f, name)[..2], column(&i, name)[..2], "{name}");
    }
    // … and it carries as far as the same launch given as options.
    for row in 0..2 {
        let get = |name: &str| column(&i, name)[row].to_owned();
        let mps = get("ball_speed_mps").parse::<f64>().expect("a number");
        let direct = flight_json(&[
            "--ball-speed".into(),
            format!("{}", mps / carry_core::units::MPS_PER_MPH),
            "--launch-angle".into(),
            get("launch_angle_deg"),
            format!("--launch-direction={}", get("launch_direction_deg")),
            format!("--backspin={}", get("backspin_rpm")),
            format!("--sidespin={}", get("sidespin_rpm")),
            "--units".into(),
            "imperial".into(),
        ]);
        let carry: f64 = column(&f, "carry_m")[row].parse().expect("a number");
        let expected = direct["flight"]["carry_m"].as_f64().expect("carry");
        assert!(
            (carry - expected).abs() <= 1e-9 * expected,
            "row {row}: {carry} vs {expected}"
        );
    }
}

#[test]
fn shot_output_pipes_into_flight_and_impact() {
    let (shot, _) = batch("shot", &[], "club_speed\n44\n");
    let (flight, _) = batch("flight", &[], &shot);
    let s = table(&shot);
    let f = table(&flight);
    // The shot's own flight from its launch: the same carry (to rounding: the launch is
    // read back through degrees and rpm, which need not return the same last bit).
    let (from_shot, flown) = (column(&s, "carry_m"), column(&f, "carry_m"));
    assert_eq!(from_shot.len(), 1);
    let (a, b): (f64, f64) = (
        from_shot[0].parse().expect("a number"),
        flown[0].parse().expect("a number"),
    );
    assert!((a - b).abs() <= 1e-12 * a, "{a} vs {b}");
    // Nothing of a shot's output is an impact input: the defaults, and no error.
    let (impact, _) = batch("impact", &[], &shot);
    assert_eq!(column(&table(&impact), "error"), [""]);
}

#[test]
fn a_spin_and_axis_output_is_read_without_backspin() {
    let (flight, _) = batch(
        "flight",
        &[],
        "ball_speed_mps,launch_angle_deg,spin_rpm,spin_axis_deg\n70,12,3000,5\n",
    );
    let f = table(&flight);
    assert_eq!(column(&f, "error"), [""]);
    let spin: f64 = column(&f, "spin_rpm")[0].parse().expect("a number");
    assert!((spin - 3000.0).abs() < 1e-9, "{spin}");
}
