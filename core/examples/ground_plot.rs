//! Draws the run-out (bounces and roll after the first landing) of the TrackMan tour
//! driver and pitching wedge on each surface: docs/ground-runout.svg.
//!
//! `cargo run -p carry-core --example ground_plot > docs/ground-runout.svg`
use carry_core::flight::{Recorder, Sample};
use carry_core::ground::{Ground, Surface};
use carry_core::units::{deg, rpm};
use carry_core::{Ball, Integrator, Launch, Scene, fly};
use std::fmt::Write as _;

const MPH: f64 = 0.447_04;
const YD: f64 = 0.9144;

/// (label, ball speed mph, launch deg, backspin rpm): TrackMan PGA Tour 2023 averages.
const SHOTS: [(&str, f64, f64, f64); 2] = [
    (
        "tour driver (171 mph, 10.4°, 2545 rpm)",
        171.0,
        10.4,
        2545.0,
    ),
    (
        "tour pitching wedge (104 mph, 23.7°, 9316 rpm)",
        104.0,
        23.7,
        9316.0,
    ),
];
const SURFACES: [(&str, &str); 4] = [
    ("fairway (firm)", "#1b7f3b"),
    ("fairway-soft", "#7fbf3f"),
    ("rough", "#8c6d1f"),
    ("green (stimp 10)", "#1f5fbf"),
];

fn surface(i: usize) -> Surface<f64> {
    match i {
        0 => Surface::FairwayFirm,
        1 => Surface::FairwaySoft,
        2 => Surface::Rough,
        _ => Surface::green(),
    }
}

fn main() {
    let (w, h) = (900.0, 300.0);
    let mut svg = String::new();
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{}" font-family="sans-serif" font-size="12">"#,
        2.0 * h + 20.0
    );
    let _ = writeln!(svg, r#"<rect width="100%" height="100%" fill="white"/>"#);
    for (k, (label, v, a, s)) in SHOTS.iter().enumerate() {
        let Ok(m) = (Launch {
            ball_speed_mps: v * MPH,
            launch_angle_rad: deg(*a),
            launch_direction_rad: 0.0,
            backspin_radps: rpm(*s),
            sidespin_radps: 0.0,
        })
        .ball_motion() else {
            return;
        };
        let mut curves = Vec::new();
        for i in 0..SURFACES.len() {
            let mut buf = heapless::Vec::<Sample<f64>, 4096>::new();
            let Ok(mut rec) = Recorder::new(0.005, &mut buf) else {
                return;
            };
            let scene = Scene {
                ground: Some(Ground::level(surface(i))),
                ..Scene::default()
            };
            let Ok(out) = fly(
                &Ball::standard(),
                &m,
                &scene,
                &Integrator::default(),
                Some(&mut rec),
            ) else {
                return;
            };
            let x0 = out.landing_position_m.x;
            let pts: Vec<(f64, f64)> = rec
                .samples()
                .iter()
                .filter(|p| p.time_s >= out.flight_time_s - 0.4)
                .map(|p| ((p.position_m.x - x0) / YD, p.position_m.y / YD * 3.0))
                .collect();
            let roll = out.ground.map_or(0.0, |g| g.roll_m / YD);
            curves.push((i, pts, roll));
        }
        let xmax = curves
            .iter()
            .flat_map(|c| c.1.iter().map(|p| p.0))
            .fold(2.0_f64, f64::max)
            .ceil();
        let xmin = -3.0_f64;
        let ymax = 6.0_f64; // ft
        let top = k as f64 * (h + 10.0);
        let (l, r, t, b) = (60.0, w - 20.0, top + 30.0, top + h - 40.0);
        let sx = |x: f64| l + (x - xmin) / (xmax - xmin) * (r - l);
        let sy = |y: f64| b - y.min(ymax) / ymax * (b - t);
        let _ = writeln!(
            svg,
            r#"<text x="{l}" y="{}" font-size="14">{label}: run-out after the first landing (x from the landing, yd; height ft)</text>"#,
            top + 18.0
        );
        let _ = writeln!(
            svg,
            r#"<line x1="{l}" y1="{b}" x2="{r}" y2="{b}" stroke="black"/><line x1="{l}" y1="{t}" x2="{l}" y2="{b}" stroke="black"/>"#
        );
        let step = if xmax - xmin > 20.0 { 5.0 } else { 1.0 };
        let mut x = (xmin / step).ceil() * step;
        while x <= xmax {
            let _ = writeln!(
                svg,
                r#"<line x1="{0}" y1="{b}" x2="{0}" y2="{1}" stroke="black"/><text x="{0}" y="{2}" text-anchor="middle">{3}</text>"#,
                sx(x),
                b + 5.0,
                b + 18.0,
                x + 0.0
            );
            x += step;
        }
        for y in [0.0, 2.0, 4.0, 6.0] {
            let _ = writeln!(
                svg,
                r#"<text x="{}" y="{}" text-anchor="end">{y}</text>"#,
                l - 5.0,
                sy(y) + 4.0
            );
        }
        for (n, (i, pts, roll)) in curves.iter().enumerate() {
            let (name, colour) = SURFACES[*i];
            let mut d = String::new();
            for (j, (x, y)) in pts.iter().enumerate() {
                let _ = write!(
                    d,
                    "{}{:.2},{:.2} ",
                    if j == 0 { "M" } else { "L" },
                    sx(*x),
                    sy(*y)
                );
            }
            let _ = writeln!(
                svg,
                r#"<path d="{d}" fill="none" stroke="{colour}" stroke-width="1.5"/>"#
            );
            if let Some((x, _)) = pts.last() {
                let _ = writeln!(
                    svg,
                    r#"<circle cx="{:.2}" cy="{b}" r="3" fill="{colour}"/>"#,
                    sx(*x)
                );
            }
            let _ = writeln!(
                svg,
                r#"<text x="{}" y="{}" fill="{colour}">{name}: roll {roll:+.1} yd</text>"#,
                r - 230.0,
                t + 15.0 * n as f64 + 10.0
            );
        }
    }
    svg.push_str("</svg>\n");
    print!("{svg}");
}
