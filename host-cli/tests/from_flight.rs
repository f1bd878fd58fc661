//! `carry estimate --from flight` end to end (issue 36): `carry flight` forward, the launch
//! from its summaries or its track back; each figure says where it came from; bad or
//! too few observations are one line, status 2.

mod common;

use common::{json, run, temp_file};
use serde_json::Value;

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// `carry flight` of 70 m/s, 12°, 2,800 rpm, axis 5°: its flight summaries.
fn forward() -> Value {
    json(&[
        "flight",
        "--ball-speed",
        "70",
        "--launch-angle",
        "12",
        "--spin",
        "2800",
        "--spin-axis",
        "5",
        "--json",
    ])["flight"]
        .clone()
}

#[test]
fn spin_and_axis_from_the_summaries() {
    let f = forward();
    let s = |k: &str| format!("{}", num(&f[k]));
    let out = json(&[
        "estimate",
        "--from",
        "flight",
        "--ball-speed",
        "70",
        "--launch-angle",
        "12",
        "--launch-direction",
        "0",
        "--apex-height",
        &s("apex_m"),
        "--carry",
        &s("carry_m"),
        "--side",
        &s("side_m"),
        "--flight-time",
        &s("flight_time_s"),
        "--land-angle",
        &s("land_angle_deg"),
        "--json",
    ]);
    let spin = num(&out["spin_rpm"]);
    let sd = num(&out["spin_rpm_sd"]);
    assert!((spin - 2800.0).abs() < 2.0 * sd, "{out}");
    assert!(sd > 0.0 && sd < 300.0, "{out}");
    assert!((num(&out["spin_axis_deg"]) - 5.0).abs() < 2.0 * num(&out["spin_axis_deg_sd"]));
    assert_eq!(out["spin_rpm_source"], "fitted to the flight");
    assert_eq!(out["ball_speed_mps_source"], "measured");
    assert!((num(&out["carry_m"]) - num(&f["carry_m"])).abs() < 1.0);
}

/// Collects a flight's samples.
struct Samples(Vec<carry_core::Sample<f64>>);

impl carry_core::SampleSink<f64> for Samples {
    fn clear(&mut self) {
        self.0.clear();
    }
    fn push(&mut self, s: carry_core::Sample<f64>) -> bool {
        self.0.push(s);
        true
    }
}

#[test]
fn spin_and_axis_from_a_track_file() {
    // 20 radar points over the first second of the same flight, in the shot's frame.
    let launch = carry_core::Launch::from_spin_axis(
        70.0,
        12f64.to_radians(),
        0.0,
        2800.0 * std::f64::consts::TAU / 60.0,
        5f64.to_radians(),
    );
    let times: Vec<f64> = (1..=20).map(|k| f64::from(k) * 0.05).collect();
    let scene = carry_core::Scene::<f64>::default()
        .prepare(&carry_core::Ball::standard())
        .unwrap();
    let mut sink = Samples(Vec::new());
    {
        let mut rec = carry_core::Recorder::at_times(&times, &mut sink).unwrap();
        scene
            .fly(
                &launch.ball_motion().unwrap(),
                &carry_core::Integrator::default(),
                Some(&mut rec),
            )
            .unwrap();
    }
    let mut csv = String::from("t,x,y,z\n");
    for s in sink.0.iter().take(times.len()) {
        let p = s.position_m;
        csv += &format!("{},{},{},{}\n", s.time_s, p.x, p.y, p.z);
    }
    let track = temp_file("track.csv", &csv);
    let out = json(&[
        "estimate",
        "--from",
        "flight",
        "--ball-speed",
        "70",
        "--launch-angle",
        "12",
        "--launch-direction",
        "0",
        "--track",
        track.to_str().unwrap(),
        "--track-sd",
        "0.05",
        "--json",
    ]);
    assert_eq!(num(&out["observations"]), 60.0);
    let sd = num(&out["spin_rpm_sd"]);
    assert!((num(&out["spin_rpm"]) - 2800.0).abs() < 2.0 * sd, "{out}");
    assert!(
        (num(&out["spin_axis_deg"]) - 5.0).abs() < 2.0 * num(&out["spin_axis_deg_sd"]),
        "{out}"
    );
}

#[test]
fn bad_and_too_few_observations_are_one_line_and_status_2() {
    let cases: [(&[&str], &str); 5] = [
        (
            &[
                "--ball-speed",
                "70",
                "--launch-angle",
                "12",
                "--carry",
                "230",
            ],
            "carry: --apex-height, --carry, --side, --flight-time, --land-angle, --track: too few flight observations",
        ),
        (
            &[
                "--ball-speed",
                "70",
                "--launch-angle",
                "12",
                "--launch-direction",
                "0",
                "--apex-height",
                "31.9",
                "--carry",
                "222.4",
                "--flight-time",
                "6.7",
            ],
            "carry: --spin-axis: the flight observations do not determine the spin axis",
        ),
        (
            &[
                "--ball-speed",
                "70",
                "--carry",
                "230",
                "--carry-sd",
                "-1",
                "--side",
                "3",
            ],
            "carry: --carry: its 1σ must be positive",
        ),
        (
            &[
                "--ball-speed",
                "70",
                "--backspin",
                "2500",
                "--carry",
                "230",
                "--side",
                "3",
            ],
            "carry: --backspin, --sidespin: with --from flight give the measured spin as --spin and --spin-axis",
        ),
        (
            &[
                "--ball-speed",
                "70",
                "--carry",
                "230",
                "--track",
                "/nonexistent/track.csv",
            ],
            "carry: --track: /nonexistent/track.csv",
        ),
    ];
    for (args, message) in cases {
        let mut all = vec!["estimate", "--from", "flight"];
        all.extend_from_slice(args);
        let r = run(&all);
        assert_eq!(r.code, 2, "{all:?}: {}", r.stderr);
        assert_eq!(r.stderr.lines().count(), 1, "{}", r.stderr);
        assert!(r.stderr.starts_with(message), "{all:?}: {}", r.stderr);
    }
}

/// A measured launch figure out of range names its own option (issue 34: a launch angle of
/// 95° was reported as a spin out of range, a launch direction of 120° as a spin the
/// observations do not determine, a spin axis of 200° as a fit that did not converge).
#[test]
fn launch_figures_out_of_range_name_their_option() {
    let cases: [(&str, &str, &str); 4] = [
        (
            "--launch-angle",
            "95",
            "carry: --launch-angle: is out of range",
        ),
        (
            "--launch-direction",
            "120",
            "carry: --launch-direction: is out of range",
        ),
        ("--spin-axis", "200", "carry: --spin-axis: is out of range"),
        (
            "--spin",
            "-5",
            "carry: --backspin, --sidespin, --spin: is out of range",
        ),
    ];
    for (option, value, message) in cases {
        let mut all = vec![
            "estimate",
            "--from",
            "flight",
            "--ball-speed",
            "70",
            "--carry",
            "200",
            "--side",
            "5",
            "--apex-height",
            "30",
            "--flight-time",
            "6.5",
        ];
        if option != "--launch-angle" {
            all.extend_from_slice(&["--launch-angle", "12"]);
        }
        all.extend_from_slice(&[option, value]);
        let r = run(&all);
        assert_eq!(r.code, 2, "{all:?}: {}", r.stderr);
        assert_eq!(r.stderr.lines().count(), 1, "{}", r.stderr);
        assert!(r.stderr.starts_with(message), "{all:?}: {}", r.stderr);
    }
}

/// Splits a CSV text into its header and rows (no quoted commas in these).
fn table(csv: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut lines = csv.lines();
    let header = lines
        .next()
        .expect("header")
        .split(',')
        .map(str::to_owned)
        .collect();
    let rows = lines
        .map(|l| l.split(',').map(str::to_owned).collect())
        .collect();
    (header, rows)
}

fn col(header: &[String], name: &str) -> usize {
    header
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {header:?}"))
}

/// `carry batch estimate --from flight`: rows made by `carry batch flight` of known launches
/// (its SI output columns read back: the measured ball speed, launch angle and direction,
/// the carry, side, apex, flight time and landing angle; its spin dropped) give back each
/// launch's spin and axis within their 1σ, every figure says where it came from, and the
/// single-shot command gives the same numbers.
#[test]
fn batch_recovers_the_spin_of_flown_launches() {
    let launches = [
        (70.0, 12.0, 0.0, 2800.0, 5.0),
        (62.0, 14.5, -1.5, 3500.0, -8.0),
        (48.0, 18.0, 1.0, 6000.0, 3.0),
        (75.0, 10.0, 2.0, 2300.0, 10.0),
    ];
    let mut input = String::from("ball_speed,launch_angle,launch_direction,spin,spin_axis\n");
    for (v, a, d, s, x) in launches {
        input += &format!("{v},{a},{d},{s},{x}\n");
    }
    let forward = temp_file("launches.csv", &input);
    let r = run(&["batch", "flight", "-i", forward.to_str().unwrap()]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    let (fh, frows) = table(&r.stdout);
    let keep = [
        "ball_speed_mps",
        "launch_angle_deg",
        "launch_direction_deg",
        "carry_m",
        "side_m",
        "apex_m",
        "flight_time_s",
        "land_angle_deg",
    ];
    let mut obs = format!("label,{}\n", keep.join(","));
    for (i, row) in frows.iter().enumerate() {
        let cells: Vec<&str> = keep.iter().map(|k| row[col(&fh, k)].as_str()).collect();
        obs += &format!("shot{i},{}\n", cells.join(","));
    }
    let path = temp_file("observed.csv", &obs);
    let r = run(&[
        "batch",
        "estimate",
        "--from",
        "flight",
        "-i",
        path.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    let (h, rows) = table(&r.stdout);
    assert_eq!(rows.len(), launches.len());
    for c in [
        "line",
        "label",
        "spin_rpm",
        "spin_rpm_sd",
        "spin_rpm_source",
        "spin_axis_deg_sd",
        "ball_speed_mps_source",
        "carry_m",
        "apex_m",
        "total_m",
        "chi2",
        "error",
    ] {
        col(&h, c);
    }
    let f = |row: &[String], name: &str| -> f64 {
        row[col(&h, name)]
            .parse()
            .unwrap_or_else(|_| panic!("{name} in {row:?}"))
    };
    for (row, (_, _, _, spin, axis)) in rows.iter().zip(launches) {
        assert!(row[col(&h, "error")].is_empty(), "{row:?}");
        let sd = f(row, "spin_rpm_sd");
        assert!(sd > 0.0, "{row:?}");
        assert!(
            (f(row, "spin_rpm") - spin).abs() < sd,
            "spin {spin}: {row:?}"
        );
        let axis_sd = f(row, "spin_axis_deg_sd");
        assert!(
            (f(row, "spin_axis_deg") - axis).abs() < axis_sd,
            "axis {axis}: {row:?}"
        );
        assert_eq!(row[col(&h, "spin_rpm_source")], "fitted to the flight");
        assert_eq!(row[col(&h, "launch_angle_deg_source")], "measured");
        assert!(f(row, "chi2") < 5.0, "{row:?}");
        // no ground: no total
        assert!(row[col(&h, "total_m")].is_empty(), "{row:?}");
    }
    // the single-shot command on the first row: the same fit
    let cell = |k: &str| frows[0][col(&fh, k)].clone();
    let single = json(&[
        "estimate",
        "--from",
        "flight",
        "--ball-speed",
        &cell("ball_speed_mps"),
        "--launch-angle",
        &cell("launch_angle_deg"),
        "--launch-direction",
        &cell("launch_direction_deg"),
        "--carry",
        &cell("carry_m"),
        "--side",
        &cell("side_m"),
        "--apex-height",
        &cell("apex_m"),
        "--flight-time",
        &cell("flight_time_s"),
        "--land-angle",
        &cell("land_angle_deg"),
        "--json",
    ]);
    assert_eq!(f(&rows[0], "spin_rpm"), num(&single["spin_rpm"]));
    assert_eq!(
        f(&rows[0], "spin_axis_deg_sd"),
        num(&single["spin_axis_deg_sd"])
    );
}

/// A row that cannot be fitted keeps its place with its typed error in `error` (the
/// others are fitted); the option-name columns take `--units` and a row's `_sd`.
#[test]
fn batch_rows_that_fail_say_why_in_error() {
    let input = "apex_height,carry,side,flight_time,land_angle,carry_sd,ball_speed,launch_angle,launch_direction\n\
                 32.7,231.3,9.6,6.94,42.7,,70,12,0\n\
                 32.7,231.3,9.6,6.94,42.7,-1,70,12,0\n\
                 ,231.3,,,,,70,12,\n\
                 31.9,222.4,,6.7,,,70,12,0\n\
                 32.7,abc,9.6,6.94,42.7,,70,12,0\n";
    let path = temp_file("rows.csv", input);
    let r = run(&[
        "batch",
        "estimate",
        "--from",
        "flight",
        "-i",
        path.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    let (h, rows) = table(&r.stdout);
    assert_eq!(rows.len(), 5);
    let error = |i: usize| rows[i][col(&h, "error")..].join(",");
    assert!(error(0).is_empty(), "{:?}", rows[0]);
    assert!(!rows[0][col(&h, "spin_rpm")].is_empty());
    let expected = [
        "line 3: carry: its 1σ must be positive",
        "line 4: apex_height, carry, side, flight_time, land_angle, track: too few flight observations",
        "line 5: spin_axis: the flight observations do not determine the spin axis",
        "line 6: carry: 'abc' is not a number",
    ];
    for (i, e) in expected.iter().enumerate() {
        let got = error(i + 1);
        assert!(got.trim_matches('"').starts_with(e), "row {}: {got}", i + 1);
        assert!(rows[i + 1][col(&h, "spin_rpm")].is_empty());
    }
    // --units imperial: carry and side in yards, apex in feet, speed in mph
    let yd = 0.9144;
    let ft = 0.3048;
    let mph = 0.44704;
    let imperial = format!(
        "apex_height,carry,side,flight_time,land_angle,ball_speed,launch_angle,launch_direction\n{},{},{},6.94,42.7,{},12,0\n",
        32.7 / ft,
        231.3 / yd,
        9.6 / yd,
        70.0 / mph
    );
    let path = temp_file("imperial.csv", &imperial);
    let a = run(&[
        "batch",
        "estimate",
        "--from",
        "flight",
        "--units",
        "imperial",
        "-i",
        path.to_str().unwrap(),
    ]);
    assert_eq!(a.code, 0, "{}", a.stderr);
    let (ha, ra) = table(&a.stdout);
    let spin_imperial: f64 = ra[0][col(&ha, "spin_rpm")].parse().unwrap();
    let spin_si: f64 = rows[0][col(&h, "spin_rpm")].parse().unwrap();
    assert!(
        (spin_imperial - spin_si).abs() < 1e-6 * spin_si,
        "{spin_imperial} {spin_si}"
    );
}

/// A bad header is one line on stderr and status 2, nothing on stdout.
#[test]
fn batch_bad_header_is_one_line_and_status_2() {
    let cases = [
        ("carry,bogus\n230,1\n", "unknown column 'bogus'"),
        (
            "carry,carry_m\n230,230\n",
            "column 'carry_m' gives what another column gives",
        ),
        ("carry,backspin\n230,2500\n", "column 'backspin'"),
    ];
    for (i, (text, message)) in cases.iter().enumerate() {
        let path = temp_file(&format!("bad{i}.csv"), text);
        let r = run(&[
            "batch",
            "estimate",
            "--from",
            "flight",
            "-i",
            path.to_str().unwrap(),
        ]);
        assert_eq!(r.code, 2, "{text}: {}", r.stderr);
        assert!(r.stdout.is_empty(), "{}", r.stdout);
        assert_eq!(r.stderr.lines().count(), 1, "{}", r.stderr);
        assert!(r.stderr.starts_with("carry: --input: "), "{}", r.stderr);
        assert!(r.stderr.contains(message), "{text}: {}", r.stderr);
    }
}
