//! Writes `docs/impact.svg`: spin and launch against dynamic loft for a driver, a 6-iron, a
//! 7-iron and a pitching wedge at TrackMan's tour club speeds and attack angles, for the
//! seed's rolling contact (centred strike, dashed) and the calibrated compliant contact
//! (typical strike, solid), with the measured rows of `club_delivery.csv` overlaid.
//!
//! `cargo test -p carry-tests --test impact_figure -- --ignored` regenerates it.

use carry_core::impact::ContactLaw;
use carry_core::presets::{FITTED_CONTACT, turf_impact_height_m};
use carry_core::units::deg;
use carry_core::{Ball, ClubSpec, Preset};
use carry_tests::club_delivery::{Row, rows};
use std::fmt::Write as _;

/// One curve family: club, club speed (mph), attack (deg), dynamic-loft range (deg), colour.
const CLUBS: [(&str, f64, f64, f64, f64, &str); 4] = [
    ("driver", 115.0, -0.9, 8.0, 18.0, "#1f77b4"),
    ("6iron", 94.0, -3.7, 16.0, 26.0, "#2ca02c"),
    ("7iron", 92.0, -3.9, 18.0, 28.0, "#ff7f0e"),
    ("pw", 72.0, -3.9, 30.0, 42.0, "#d62728"),
];

fn row(club: &str, mph: f64, attack: f64, loft: f64) -> Row {
    Row {
        source: String::new(),
        who: String::new(),
        club: club.to_owned(),
        club_speed_mph: mph,
        attack_deg: attack,
        dynamic_loft_deg: loft,
        ball_speed_mph: f64::NAN,
        launch_deg: f64::NAN,
        spin_rpm: f64::NAN,
    }
}

/// (launch °, spin rpm) of the seed (rolling, centred) or the default model.
fn model(r: &Row, seed: bool) -> Option<(f64, f64)> {
    let p = Preset::find(&r.club)?;
    let contact = if seed {
        ContactLaw::Rolling
    } else {
        FITTED_CONTACT
    };
    let spec = ClubSpec {
        contact,
        ..p.spec::<f64>()
    };
    let h = if seed {
        0.0
    } else if p.roll_radius_m.is_finite() {
        p.typical.impact_height_m
    } else {
        turf_impact_height_m(deg(r.dynamic_loft_deg), Ball::<f64>::STANDARD_RADIUS_M)
    };
    r.predict_at(&spec, h)
        .ok()
        .map(|x| (x.launch_deg, x.spin_rpm))
}

struct Panel {
    x0: f64,
    y_max: f64,
    label: &'static str,
}

const W: f64 = 460.0;
const H: f64 = 360.0;
const PAD: f64 = 50.0;
const LOFT_MAX: f64 = 45.0;

impl Panel {
    fn px(&self, loft: f64) -> f64 {
        self.x0 + PAD + (W - 1.5 * PAD) * loft / LOFT_MAX
    }
    fn py(&self, y: f64) -> f64 {
        H - PAD + -(H - 1.6 * PAD) * y / self.y_max
    }
    fn axes(&self, svg: &mut String, step: f64) {
        let (x0, x1) = (self.px(0.0), self.px(LOFT_MAX));
        let (y0, y1) = (self.py(0.0), self.py(self.y_max));
        let _ = write!(
            svg,
            r##"<path d="M{x0:.1},{y1:.1}V{y0:.1}H{x1:.1}" stroke="#000" fill="none"/>"##
        );
        let mut t = 0.0;
        while t <= LOFT_MAX + 1e-9 {
            let x = self.px(t);
            let _ = write!(
                svg,
                r##"<text x="{x:.1}" y="{:.1}" font-size="11" text-anchor="middle">{t:.0}</text>"##,
                y0 + 15.0
            );
            t += 5.0;
        }
        let mut v = 0.0;
        while v <= self.y_max + 1e-9 {
            let y = self.py(v);
            let _ = write!(
                svg,
                r##"<text x="{:.1}" y="{:.1}" font-size="11" text-anchor="end">{v:.0}</text><path d="M{x0:.1},{y:.1}H{x1:.1}" stroke="#ddd"/>"##,
                x0 - 4.0,
                y + 4.0
            );
            v += step;
        }
        let _ = write!(
            svg,
            r##"<text x="{:.1}" y="{:.1}" font-size="12" text-anchor="middle">dynamic loft (°)</text><text x="{:.1}" y="{:.1}" font-size="13" font-weight="bold">{}</text>"##,
            (x0 + x1) / 2.0,
            y0 + 32.0,
            x0,
            y1 - 10.0,
            self.label
        );
    }
}

#[test]
#[ignore = "writes docs/impact.svg"]
fn write_figure() {
    let spin = Panel {
        x0: 0.0,
        y_max: 12_000.0,
        label: "spin (rpm)",
    };
    let launch = Panel {
        x0: W,
        y_max: 32.0,
        label: "launch angle (°)",
    };
    let mut svg = format!(
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{}" height="{}" font-family="sans-serif"><rect width="100%" height="100%" fill="#fff"/>"##,
        2.0 * W,
        H + 40.0
    );
    spin.axes(&mut svg, 2000.0);
    launch.axes(&mut svg, 5.0);
    for (club, mph, attack, lo, hi, colour) in CLUBS {
        for seed in [true, false] {
            let mut pts = (Vec::new(), Vec::new());
            for i in 0..=40 {
                let loft = lo + (hi - lo) * f64::from(i) / 40.0;
                if let Some((la, sp)) = model(&row(club, mph, attack, loft), seed) {
                    pts.0
                        .push(format!("{:.1},{:.1}", spin.px(loft), spin.py(sp)));
                    pts.1
                        .push(format!("{:.1},{:.1}", launch.px(loft), launch.py(la)));
                }
            }
            let dash = if seed {
                r#" stroke-dasharray="5,4""#
            } else {
                ""
            };
            for p in [pts.0, pts.1] {
                let _ = write!(
                    svg,
                    r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-width="2"{dash}/>"#,
                    p.join(" ")
                );
            }
        }
    }
    for r in rows() {
        let colour = CLUBS.iter().find(|c| c.0 == r.club).map_or("#000", |c| c.5);
        for (p, y) in [(&spin, r.spin_rpm), (&launch, r.launch_deg)] {
            let _ = write!(
                svg,
                r##"<circle cx="{:.1}" cy="{:.1}" r="4" fill="{colour}" stroke="#000"/>"##,
                p.px(r.dynamic_loft_deg),
                p.py(y)
            );
        }
    }
    let mut y = H + 12.0;
    for (club, mph, attack, _, _, colour) in CLUBS {
        let _ = write!(
            svg,
            r#"<text x="{:.1}" y="{y:.1}" font-size="11" fill="{colour}">{club}: {mph} mph, attack {attack}°</text>"#,
            PAD
        );
        y += 13.0;
    }
    let _ = write!(
        svg,
        r#"<text x="{:.1}" y="{:.1}" font-size="11">solid: calibrated compliant contact, typical strike · dashed: seed (rolling, centred) · dots: club_delivery.csv (each at its own club speed)</text></svg>"#,
        W * 0.55,
        H + 12.0
    );
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/impact.svg");
    std::fs::write(&path, svg).expect("write docs/impact.svg");
}
