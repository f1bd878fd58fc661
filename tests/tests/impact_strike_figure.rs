//! Writes `docs/impact_strike.svg`: spin, spin axis and ball speed against the strike
//! location for the driver preset at 45 m/s (attack 0°, dynamic loft 12.8° and face 0° at
//! the contact point: TrackMan's convention), for the default compliant contact (solid) and
//! the rigid rolling contact (dashed: the full gear effect), with TrackMan's published
//! responses beside them (issue 22: spin ±10 % at 10–30 mm below/above the centre, axis
//! +12°/−11° and ball speed −2.4 %/−2.9 % at 15–40 mm toward the heel/toe, ball speed
//! −1.7 % at 10–30 mm above).
//!
//! `cargo test -p carry-tests --test impact_strike_figure -- --ignored` regenerates it and
//! prints the slopes docs/impact.md reports.

use carry_core::impact::{self, ContactLaw, Solver};
use carry_core::units::{deg, to_deg, to_rpm};
use carry_core::{Ball, ClubSpec, Delivery, DeliveryConvention, FaceLocation, Preset};
use nalgebra::Vector3;
use std::fmt::Write as _;

/// (ball speed m/s, spin rpm, spin axis deg) at a strike `height_m` up and `toe_m` toward
/// the toe, TrackMan's convention.
fn launch(contact: ContactLaw<f64>, height_m: f64, toe_m: f64) -> Option<(f64, f64, f64)> {
    let p = Preset::find("driver")?;
    let club = ClubSpec {
        contact,
        ..p.spec::<f64>()
    }
    .validate()
    .ok()?;
    let d = Delivery {
        club_speed_mps: 45.0,
        attack_angle_rad: 0.0,
        club_path_rad: 0.0,
        face_angle_rad: 0.0,
        dynamic_loft_rad: deg(12.8),
        lie_rad: 0.0,
        club_spin_radps: Vector3::zeros(),
        location: FaceLocation { height_m, toe_m },
    };
    let strike = d.strike_in(&club, DeliveryConvention::TrackMan).ok()?;
    let o = impact::solve(&club, &Ball::standard(), &strike, Solver::Reduced).ok()?;
    let l = o.launch;
    Some((
        l.ball_speed_mps,
        to_rpm(l.spin_radps),
        to_deg(l.spin_axis_rad),
    ))
}

struct Panel {
    x0: f64,
    title: &'static str,
    xlabel: &'static str,
    ylabel: &'static str,
    y: (f64, f64),
}

const W: f64 = 300.0;
const H: f64 = 220.0;
const TOP: f64 = 40.0;
const MM: (f64, f64) = (-40.0, 40.0);

impl Panel {
    fn px(&self, x: f64) -> f64 {
        self.x0 + (x - MM.0) / (MM.1 - MM.0) * W
    }
    fn py(&self, y: f64) -> f64 {
        TOP + H - (y - self.y.0) / (self.y.1 - self.y.0) * H
    }
    fn frame(&self, s: &mut String) {
        let _ = write!(
            s,
            r##"<rect x="{:.1}" y="{TOP}" width="{W}" height="{H}" fill="none" stroke="#444"/>"##,
            self.x0
        );
        let _ = write!(
            s,
            r##"<text x="{:.1}" y="{:.1}" text-anchor="middle" font-weight="bold">{}</text>"##,
            self.x0 + W / 2.0,
            TOP - 12.0,
            self.title
        );
        let _ = write!(
            s,
            r##"<text x="{:.1}" y="{:.1}" text-anchor="middle">{}</text>"##,
            self.x0 + W / 2.0,
            TOP + H + 34.0,
            self.xlabel
        );
        let _ = write!(
            s,
            r##"<text x="{:.1}" y="{:.1}" text-anchor="middle" transform="rotate(-90 {:.1} {:.1})">{}</text>"##,
            self.x0 - 38.0,
            TOP + H / 2.0,
            self.x0 - 38.0,
            TOP + H / 2.0,
            self.ylabel
        );
        for t in [-40.0, -20.0, 0.0, 20.0, 40.0] {
            let _ = write!(
                s,
                r##"<text x="{:.1}" y="{:.1}" text-anchor="middle">{t:.0}</text>"##,
                self.px(t),
                TOP + H + 16.0
            );
        }
        let (lo, hi) = self.y;
        let step = (hi - lo) / 4.0;
        for i in 0..=4 {
            let y = lo + step * f64::from(i);
            let _ = write!(
                s,
                r##"<text x="{:.1}" y="{:.1}" text-anchor="end">{y:.0}</text><line x1="{:.1}" x2="{:.1}" y1="{:.1}" y2="{:.1}" stroke="#ddd"/>"##,
                self.x0 - 4.0,
                self.py(y) + 4.0,
                self.x0,
                self.x0 + W,
                self.py(y),
                self.py(y)
            );
        }
        let _ = write!(
            s,
            r##"<line x1="{:.1}" x2="{:.1}" y1="{:.1}" y2="{:.1}" stroke="#999"/>"##,
            self.x0,
            self.x0 + W,
            self.py(0.0),
            self.py(0.0)
        );
    }
    fn curve(&self, s: &mut String, pts: &[(f64, f64)], colour: &str, dashed: bool) {
        let d: Vec<String> = pts
            .iter()
            .map(|&(x, y)| {
                format!(
                    "{:.1},{:.1}",
                    self.px(x),
                    self.py(y.clamp(self.y.0, self.y.1))
                )
            })
            .collect();
        let dash = if dashed {
            r#" stroke-dasharray="6 4""#
        } else {
            ""
        };
        let _ = write!(
            s,
            r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-width="2"{dash}/>"#,
            d.join(" ")
        );
    }
    /// A published bin: value `y` over the offsets `x0..x1` (a bar with a dot).
    fn bin(&self, s: &mut String, x0: f64, x1: f64, y: f64) {
        let _ = write!(
            s,
            r##"<line x1="{:.1}" x2="{:.1}" y1="{:.1}" y2="{:.1}" stroke="#000" stroke-width="2"/><circle cx="{:.1}" cy="{:.1}" r="4" fill="#000"/>"##,
            self.px(x0),
            self.px(x1),
            self.py(y),
            self.py(y),
            self.px((x0 + x1) / 2.0),
            self.py(y)
        );
    }
}

#[test]
#[ignore = "writes docs/impact_strike.svg"]
fn write_strike_figure() {
    let laws = [
        (carry_core::presets::FITTED_CONTACT, "#1f77b4", false),
        (ContactLaw::Rolling, "#d62728", true),
    ];
    let Some(centre) = launch(laws[0].0, 0.0, 0.0) else {
        panic!("centre")
    };
    let offsets: Vec<f64> = (-40..=40).map(|i| f64::from(i) * 1e-3).collect();
    let mut s = String::new();
    let width = 3.0 * (W + 90.0) + 40.0;
    let _ = write!(
        s,
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0}" height="330" font-family="sans-serif" font-size="12"><rect width="100%" height="100%" fill="#fff"/>"##
    );
    let spin = Panel {
        x0: 70.0,
        title: "spin vs strike height",
        xlabel: "impact height, mm (+ above centre)",
        ylabel: "spin change, %",
        y: (-60.0, 60.0),
    };
    let axis = Panel {
        x0: 70.0 + W + 90.0,
        title: "spin axis vs toe offset",
        xlabel: "impact offset, mm (+ toward the toe)",
        ylabel: "spin axis, deg (+ fade)",
        y: (-40.0, 40.0),
    };
    let speed = Panel {
        x0: 70.0 + 2.0 * (W + 90.0),
        title: "ball speed vs offset",
        xlabel: "offset, mm (solid/dashed: toe; dotted: height)",
        ylabel: "ball speed change, %",
        y: (-8.0, 0.0),
    };
    for p in [&spin, &axis, &speed] {
        p.frame(&mut s);
    }
    for (law, colour, dashed) in laws {
        let Some(c) = launch(law, 0.0, 0.0) else {
            panic!("centre")
        };
        let pts = |f: &dyn Fn(f64) -> Option<f64>| -> Vec<(f64, f64)> {
            offsets
                .iter()
                .filter_map(|&x| f(x).map(|y| (x * 1e3, y)))
                .collect()
        };
        let sp = pts(&|h| launch(law, h, 0.0).map(|l| (l.1 / c.1 - 1.0) * 100.0));
        spin.curve(&mut s, &sp, colour, dashed);
        let ax = pts(&|z| launch(law, 0.0, z).map(|l| l.2));
        axis.curve(&mut s, &ax, colour, dashed);
        let bs = pts(&|z| launch(law, 0.0, z).map(|l| (l.0 / c.0 - 1.0) * 100.0));
        speed.curve(&mut s, &bs, colour, dashed);
        if !dashed {
            let bh = pts(&|h| launch(law, h, 0.0).map(|l| (l.0 / c.0 - 1.0) * 100.0));
            let d: Vec<String> = bh
                .iter()
                .map(|&(x, y)| format!("{:.1},{:.1}", speed.px(x), speed.py(y.max(-8.0))))
                .collect();
            let _ = write!(
                s,
                r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-width="2" stroke-dasharray="2 3"/>"#,
                d.join(" ")
            );
        }
        // slopes for the docs: spin %/mm over ±10 mm, axis °/mm over ±20 mm toe
        let (Some(lo), Some(hi), Some(heel), Some(toe)) = (
            launch(law, -0.01, 0.0),
            launch(law, 0.01, 0.0),
            launch(law, 0.0, -0.02),
            launch(law, 0.0, 0.02),
        ) else {
            panic!("slopes")
        };
        let at = |h: f64, z: f64| launch(law, h, z).map_or(f64::NAN, |l| (l.0 / c.0 - 1.0) * 100.0);
        println!(
            "{}: spin {:+.2} %/mm, axis {:+.2} °/mm toe; ball speed heel 20/30 mm {:+.1}/{:+.1} %, toe 20/30 mm {:+.1}/{:+.1} %, above 20 mm {:+.1} %, below 20 mm {:+.1} %",
            if dashed { "rolling" } else { "default" },
            (hi.1 - lo.1) / c.1 * 100.0 / 20.0,
            (toe.2 - heel.2) / 40.0,
            at(0.0, -0.02),
            at(0.0, -0.03),
            at(0.0, 0.02),
            at(0.0, 0.03),
            at(0.02, 0.0),
            at(-0.02, 0.0),
        );
    }
    // TrackMan's published responses (issue 22)
    spin.bin(&mut s, -30.0, -10.0, 10.0);
    spin.bin(&mut s, 10.0, 30.0, -10.0);
    axis.bin(&mut s, -40.0, -15.0, 12.0);
    axis.bin(&mut s, 15.0, 40.0, -11.0);
    speed.bin(&mut s, -40.0, -15.0, -2.4);
    speed.bin(&mut s, 15.0, 40.0, -2.9);
    speed.bin(&mut s, 10.0, 30.0, -1.7);
    let _ = write!(
        s,
        r##"<text x="70" y="318">driver preset, 45 m/s, attack 0°, dynamic loft 12.8° and face 0° at the contact point (centre: {:.1} m/s, {:.0} rpm). Blue: default (compliant contact); red dashed: rigid rolling contact; black: TrackMan's published bins.</text></svg>"##,
        centre.0, centre.1
    );
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/impact_strike.svg");
    if let Err(e) = std::fs::write(path, s) {
        panic!("{path}: {e}");
    }
}
