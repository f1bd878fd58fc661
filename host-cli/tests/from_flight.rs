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
