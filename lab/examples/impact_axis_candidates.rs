//! Issue 34, item 1: the physical candidates for the driver's spin axis, one by one, with
//! physical parameter values (docs/impact.md §0.8, "The physical candidates").
//!
//! For each candidate: the axis's slope per degree of face-to-path at a driver (spin loft
//! 13°), a 7-iron (26°) and a wedge (35°), synthetic deliveries struck at the preset's typical
//! height, face ±2° to a square path; and on the amateur's single drives (no parameter is
//! fitted, so every session is predicted out of sample): the slope of the model's axis on the
//! measured face-to-path against TrackMan's, and the mean absolute axis error per session
//! (typical strike; measured location). Then the data's own diagnostics of the measurement
//! (face and path separately, the noise on face-to-path the attenuation would need).
//!
//! `cargo run --release -p carry-lab --example impact_axis_candidates`

use carry_core::ball::BallMotion;
use carry_core::impact::{self, ContactLaw, Solver};
use carry_core::units::{deg, to_deg};
use carry_core::{
    Ball, ClubSpec, Delivery, DeliveryConvention, FaceLocation, LaunchMetrics, Preset,
};
use carry_lab::drives::{self, Drive};
use carry_lab::fit::single_drives::observed;
use nalgebra::Vector3;
use rayon::prelude::*;

/// One candidate mechanism, as a change to the model.
#[derive(Clone, Copy)]
struct Candidate {
    name: &'static str,
    values: &'static str,
    /// The change to a preset's head (`preset`, its spec).
    head: fn(&Preset, ClubSpec<f64>) -> ClubSpec<f64>,
    /// How the measured face and loft are read.
    convention: DeliveryConvention,
    /// The face-parallel horizontal (heel–toe) impulse: scaled by this factor…
    scale_h: f64,
    /// …and capped at μ_h P_n (anisotropic friction; `INFINITY`: the isotropic law's).
    mu_h: f64,
    /// Path at the face centre minus path at the CG (°): TrackMan's path is the CG's, the
    /// face centre's runs about 3° more out-to-in on a driver (the head turning about the
    /// vertical); modelled as the head's yaw rate `ω = v tan(offset) / d_CG` (+ closing).
    face_path_offset_deg: f64,
    /// Read the measured face angle at the face centre (the loft stays at the contact point).
    face_at_centre: bool,
    /// The seed's rolling contact instead of the compliant law.
    rolling: bool,
}

const BASE: Candidate = Candidate {
    name: "baseline (default models)",
    values: "driver preset: Iyy 4,800 g cm², CG 40 mm deep, bulge 0.30 m, μ 0.40, e_t(ψ)",
    head: |_, s| s,
    convention: DeliveryConvention::TrackMan,
    scale_h: 1.0,
    mu_h: f64::INFINITY,
    face_path_offset_deg: 0.0,
    face_at_centre: false,
    rolling: false,
};

fn driver_only(
    p: &Preset,
    s: ClubSpec<f64>,
    f: fn(ClubSpec<f64>) -> ClubSpec<f64>,
) -> ClubSpec<f64> {
    if p.name == "driver" { f(s) } else { s }
}

/// g cm² → kg m².
const GCM2: f64 = 1e-7;

fn candidates() -> Vec<Candidate> {
    vec![
        BASE,
        Candidate {
            name: "rigid rolling contact (seed law)",
            values: "no tangential compliance, no slip: the D-plane geometry with the head's turn",
            rolling: true,
            ..BASE
        },
        Candidate {
            name: "head yaw: heel–toe MOI low",
            values: "Iyy 4,500 g cm² (460 cc heads, Alba/Tutelman 3,870–5,867)",
            head: |p, s| {
                driver_only(p, s, |mut s| {
                    s.inertia_kgm2[(1, 1)] = 4500.0 * GCM2;
                    s
                })
            },
            ..BASE
        },
        Candidate {
            name: "head yaw: heel–toe MOI high",
            values: "Iyy 5,900 g cm² (USGA limit 5,900)",
            head: |p, s| {
                driver_only(p, s, |mut s| {
                    s.inertia_kgm2[(1, 1)] = 5900.0 * GCM2;
                    s
                })
            },
            ..BASE
        },
        Candidate {
            name: "head yaw: CG shallow",
            values: "CG 30 mm behind the face (Alba 32–47 mm)",
            head: |p, s| {
                driver_only(p, s, |mut s| {
                    s.cg_to_face_m.x = 0.030;
                    s
                })
            },
            ..BASE
        },
        Candidate {
            name: "head yaw: CG deep",
            values: "CG 45 mm behind the face",
            head: |p, s| {
                driver_only(p, s, |mut s| {
                    s.cg_to_face_m.x = 0.045;
                    s
                })
            },
            ..BASE
        },
        Candidate {
            name: "head yaw, deepest CG and lowest MOI together",
            values: "CG 47 mm, Iyy 3,870 g cm² (the ends of Alba's 17 heads)",
            head: |p, s| {
                driver_only(p, s, |mut s| {
                    s.cg_to_face_m.x = 0.047;
                    s.inertia_kgm2[(1, 1)] = 3870.0 * GCM2;
                    s
                })
            },
            ..BASE
        },
        Candidate {
            name: "head yaw, sensitivity (not physical)",
            values: "Iyy ÷ 10 = 480 g cm²",
            head: |p, s| {
                driver_only(p, s, |mut s| {
                    s.inertia_kgm2[(1, 1)] = 480.0 * GCM2;
                    s
                })
            },
            ..BASE
        },
        Candidate {
            name: "shaft: effective mass",
            values: "head + 2.5 g (Caldwell & McPhee 2024's fitted effective mass of a driver)",
            head: |p, s| {
                driver_only(p, s, |mut s| {
                    s.mass_kg += 0.0025;
                    s
                })
            },
            ..BASE
        },
        Candidate {
            name: "shaft: yaw held (bound)",
            values: "Iyy × 1,000 (the shaft stops the head's turn: the stiff limit)",
            head: |p, s| {
                driver_only(p, s, |mut s| {
                    s.inertia_kgm2[(1, 1)] *= 1000.0;
                    s
                })
            },
            ..BASE
        },
        Candidate {
            name: "friction: isotropic low",
            values: "μ 0.20 both ways (measured 0.2–0.5; Caldwell & McPhee 0.36 driver)",
            head: |_, mut s| {
                if let ContactLaw::Compliant(c) = &mut s.contact {
                    c.friction = 0.20;
                }
                s
            },
            ..BASE
        },
        Candidate {
            name: "friction: anisotropic, across the face low",
            values: "μ_h 0.10 heel–toe, μ 0.40 up the face (no measurement this low)",
            mu_h: 0.10,
            ..BASE
        },
        Candidate {
            name: "friction: anisotropic, sensitivity (not physical)",
            values: "μ_h 0.03 heel–toe",
            mu_h: 0.03,
            ..BASE
        },
        Candidate {
            name: "bulge flatter",
            values: "bulge 14 in = 0.356 m (drivers 10–14 in)",
            head: |p, s| {
                driver_only(p, s, |mut s| {
                    s.bulge_radius_m = 0.356;
                    s
                })
            },
            ..BASE
        },
        Candidate {
            name: "bulge rounder",
            values: "bulge 10 in = 0.254 m",
            head: |p, s| {
                driver_only(p, s, |mut s| {
                    s.bulge_radius_m = 0.254;
                    s
                })
            },
            ..BASE
        },
        Candidate {
            name: "face angle read at the face centre, loft at the contact point",
            values: "TrackMan's face at the contact point vs the club's own (bulge 0.30 m)",
            face_at_centre: true,
            ..BASE
        },
        Candidate {
            name: "face and loft read at the face centre",
            values: "the seed's convention (loft +2.3° at 12 mm up a 0.30 m roll)",
            convention: DeliveryConvention::SeedCentre,
            ..BASE
        },
        Candidate {
            name: "ball compliance, horizontal softer (two directions)",
            values: "heel–toe impulse × 0.96 (a generous bound: K's heel–toe/up-the-face ratio 0.983 moves the spring's r by 1 %)",
            scale_h: 0.96,
            ..BASE
        },
        Candidate {
            name: "ball compliance, sensitivity (not physical)",
            values: "heel–toe impulse × 0.5: e_t,h ≈ −0.5 (the ball keeps half its slip)",
            scale_h: 0.5,
            ..BASE
        },
        Candidate {
            name: "path at the CG, the face centre's 3° more out-to-in",
            values: "head yaw rate v·tan 3°/40 mm ≈ 59 rad/s at 45 m/s (TrackMan, Club Data Definitions)",
            face_path_offset_deg: -3.0,
            ..BASE
        },
    ]
}

fn preset(name: &str) -> &'static Preset {
    Preset::find(name).unwrap_or(&carry_core::presets::PRESETS[0])
}

/// `[ball speed, launch, direction, spin rpm, axis]` (m/s, °) of `d` struck by `p` changed by `c`.
fn launch(p: &Preset, c: &Candidate, d: &Delivery<f64>) -> Option<[f64; 5]> {
    let mut spec = (c.head)(p, p.spec::<f64>());
    if c.rolling {
        spec.contact = ContactLaw::Rolling;
    }
    let club = spec.validate().ok()?;
    let mut d = *d;
    // the face centre's path offset is a driver's (TrackMan: small for other clubs)
    if p.name == "driver" {
        let cg_depth = spec.cg_to_face_m.x;
        d.club_spin_radps = Vector3::new(
            0.0,
            -d.club_speed_mps * deg(c.face_path_offset_deg).tan() / cg_depth,
            0.0,
        );
    }
    let strike = if c.face_at_centre {
        let mut centre = d.in_seed_convention(&club, c.convention).ok()?;
        centre.face_angle_rad = d.face_angle_rad;
        centre.strike(&club).ok()?
    } else {
        d.strike_in(&club, c.convention).ok()?
    };
    let ball = Ball::standard();
    let l = if c.scale_h == 1.0 && c.mu_h.is_infinite() {
        impact::solve(&club, &ball, &strike, Solver::Reduced)
            .ok()?
            .launch
    } else {
        let pr = impact::Problem::new(&club, &ball, &strike).ok()?;
        let k = impact::reduced::collision_matrix(&pr);
        let ContactLaw::Compliant(law) = club.contact_law() else {
            return None;
        };
        let n = pr.contact.normal;
        let (mut imp, _) = law.impulse(&k, &pr.approach_mps, &n, pr.restitution).ok()?;
        // the face's heel–toe direction: horizontal, in the face's tangent plane
        let h = Vector3::y().cross(&n).normalize();
        let (pn, ph) = (n.dot(&imp), h.dot(&imp));
        let new = (c.scale_h * ph).clamp(-c.mu_h * pn, c.mu_h * pn);
        imp += h * (new - ph);
        let post = pr.apply_impulse(&imp);
        LaunchMetrics::from_motion(
            &BallMotion {
                velocity_mps: post.ball_velocity_mps,
                spin_radps: post.ball_spin_radps,
            },
            d.club_speed_mps,
        )
    };
    Some([
        l.ball_speed_mps,
        to_deg(l.launch_angle_rad),
        to_deg(l.launch_direction_rad),
        l.spin_radps * 30.0 / std::f64::consts::PI,
        to_deg(l.spin_axis_rad),
    ])
}

fn delivery(
    speed: f64,
    attack: f64,
    path: f64,
    loft: f64,
    face: f64,
    loc: [f64; 2],
) -> Delivery<f64> {
    Delivery {
        club_speed_mps: speed,
        attack_angle_rad: deg(attack),
        club_path_rad: deg(path),
        face_angle_rad: deg(face),
        dynamic_loft_rad: deg(loft),
        lie_rad: 0.0,
        club_spin_radps: Vector3::zeros(),
        location: FaceLocation {
            toe_m: loc[0],
            height_m: loc[1],
        },
    }
}

/// Synthetic slope (°/°) at spin loft `loft − attack`: face ±2° to a square path.
fn synthetic(c: &Candidate, name: &str, speed: f64, attack: f64, loft: f64) -> f64 {
    let p = preset(name);
    let h = p.strike_height_m(deg(loft), Ball::<f64>::standard().radius_m());
    let at = |face: f64| {
        launch(p, c, &delivery(speed, attack, 0.0, loft, face, [0.0, h])).map_or(f64::NAN, |l| l[4])
    };
    (at(2.0) - at(-2.0)) / 4.0
}

/// Least-squares slope of `y` on `x` with an intercept.
fn slope(x: &[f64], y: &[f64]) -> f64 {
    #[allow(clippy::cast_precision_loss)]
    let n = x.len().max(1) as f64;
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx).powi(2)).sum();
    sxy / sxx
}

/// Two-regressor least squares with an intercept: coefficients of `y` on `a` and `b`.
fn slope2(a: &[f64], b: &[f64], y: &[f64]) -> [f64; 2] {
    #[allow(clippy::cast_precision_loss)]
    let n = a.len().max(1) as f64;
    let m = |v: &[f64]| v.iter().sum::<f64>() / n;
    let (ma, mb, my) = (m(a), m(b), m(y));
    let c = |u: &[f64], mu: f64, v: &[f64], mv: f64| -> f64 {
        u.iter().zip(v).map(|(p, q)| (p - mu) * (q - mv)).sum()
    };
    let (saa, sbb, sab) = (c(a, ma, a, ma), c(b, mb, b, mb), c(a, ma, b, mb));
    let (say, sby) = (c(a, ma, y, my), c(b, mb, y, my));
    let det = saa * sbb - sab * sab;
    [(say * sbb - sby * sab) / det, (sby * saa - say * sab) / det]
}

struct Shot {
    session: usize,
    ftp: f64,
    face: f64,
    path: f64,
    obs: f64,
    typical: f64,
    located: Option<f64>,
    /// Model spin over TrackMan's − 1 (typical strike).
    spin_rel: f64,
    /// Launch direction (°): TrackMan's, the model's (typical strike).
    dir: [f64; 2],
}

fn shots(all: &[Drive], c: &Candidate) -> Vec<Shot> {
    let p = preset("driver");
    let typical = [0.0, p.typical.impact_height_m];
    all.par_iter()
        .filter_map(|d| {
            let o = observed(d)?;
            let [speed, attack, path, loft, face] = d.full_delivery()?;
            let t = launch(p, c, &delivery(speed, attack, path, loft, face, typical))?;
            let l = match d.strike_m {
                Some(s) => Some(launch(p, c, &delivery(speed, attack, path, loft, face, s))?[4]),
                None => None,
            };
            Some(Shot {
                session: d.session(),
                ftp: face - path,
                face,
                path,
                obs: o[4],
                typical: t[4],
                located: l,
                spin_rel: t[3] / o[3] - 1.0,
                dir: [o[2], t[2]],
            })
        })
        .collect()
}

fn mae(v: impl Iterator<Item = (f64, f64)>) -> (f64, f64) {
    let (mut s, mut b, mut n) = (0.0, 0.0, 0.0);
    for (m, o) in v {
        s += (m - o).abs();
        b += m - o;
        n += 1.0;
    }
    (s / n, b / n)
}

fn main() {
    let all = match drives::read_shared() {
        Ok(d) => d,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    };
    let sessions = drives::sessions(&all);
    let geometry = |sl: f64| 1.0 / deg(sl).sin();
    println!(
        "pure D-plane geometry d(axis)/d(ftp) = 1/sin(spin loft): driver 13° {:.2}, 7-iron 26° {:.2}, wedge 35° {:.2}\n",
        geometry(13.0),
        geometry(26.0),
        geometry(35.0)
    );
    println!(
        "| candidate | values (source) | driver 13° | 7-iron 26° | wedge 35° | drives: model slope (TrackMan) | axis MAE typical strike (bias) | axis MAE located | spin bias, typical | per-session axis MAE, typical |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    let mut base_shots = None;
    for c in candidates() {
        let drv = synthetic(&c, "driver", 45.0, 0.0, 13.0);
        let i7 = synthetic(&c, "7iron", 38.0, -4.0, 22.0);
        let wdg = synthetic(&c, "pw", 34.0, -4.0, 31.0);
        let s = shots(&all, &c);
        let x: Vec<f64> = s.iter().map(|r| r.ftp).collect();
        let tm = slope(&x, &s.iter().map(|r| r.obs).collect::<Vec<_>>());
        let md = slope(&x, &s.iter().map(|r| r.typical).collect::<Vec<_>>());
        let (e_t, b_t) = mae(s.iter().map(|r| (r.typical, r.obs)));
        let (e_l, _) = mae(s.iter().filter_map(|r| r.located.map(|l| (l, r.obs))));
        let (_, spin_bias) = mae(s.iter().map(|r| (r.spin_rel, 0.0)));
        let per: Vec<String> = sessions
            .iter()
            .map(|&k| {
                format!(
                    "{:.1}",
                    mae(s
                        .iter()
                        .filter(|r| r.session == k)
                        .map(|r| (r.typical, r.obs)))
                    .0
                )
            })
            .collect();
        println!(
            "| {} | {} | {:.2} ({:.2}) | {:.2} ({:.2}) | {:.2} ({:.2}) | {:.2} ({:.2}) | {:.1}° ({:+.1}°) | {:.1}° | {:+.1} % | {} |",
            c.name,
            c.values,
            drv,
            drv / geometry(13.0),
            i7,
            i7 / geometry(26.0),
            wdg,
            wdg / geometry(35.0),
            md,
            tm,
            e_t,
            b_t,
            e_l,
            100.0 * spin_bias,
            per.join(" / ")
        );
        if base_shots.is_none() {
            base_shots = Some(s);
        }
    }
    let Some(s) = base_shots else { return };

    // The collision matrix's tangential entries: how much the head's turn and the ball's
    // effective tangential mass differ between heel–toe and up the face.
    let p = preset("driver");
    let d = delivery(45.0, 0.0, 0.0, 13.0, 0.0, [0.0, p.typical.impact_height_m]);
    let problem = p.spec::<f64>().validate().and_then(|club| {
        let strike = d.strike_in(&club, DeliveryConvention::TrackMan)?;
        impact::Problem::new(&club, &Ball::standard(), &strike)
    });
    if let Ok(pr) = problem {
        let k = impact::reduced::collision_matrix(&pr);
        let n = pr.contact.normal;
        let h = Vector3::y().cross(&n).normalize();
        let v = n.cross(&h);
        println!(
            "\ncollision matrix at the typical driver strike (1/kg): n·Kn {:.1}, h·Kh (heel–toe) {:.1}, v·Kv (up the face) {:.1}; ratio h/v {:.3}",
            n.dot(&(k * n)),
            h.dot(&(k * h)),
            v.dot(&(k * v)),
            h.dot(&(k * h)) / v.dot(&(k * v))
        );
    }

    // The measurement: face and path as separate regressors (the geometry gives them equal
    // and opposite weights), per session; and the face-to-path noise an attenuation of the
    // model's slope down to TrackMan's would need: σ² = var(ftp)·(1 − b_TM/b_model).
    println!(
        "\n| session | rows | SD face-to-path | TrackMan axis on face, path | model axis on face, path | TrackMan / model slope on ftp | ftp noise σ the attenuation needs | direction on face, path: TrackMan / model | direction residual SD |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    let mut groups: Vec<(String, Vec<&Shot>)> = sessions
        .iter()
        .map(|&k| {
            (
                format!("{k}"),
                s.iter().filter(|r| r.session == k).collect(),
            )
        })
        .collect();
    groups.push(("all".into(), s.iter().collect()));
    for (name, g) in groups {
        let col = |f: fn(&Shot) -> f64| g.iter().map(|r| f(r)).collect::<Vec<f64>>();
        let (ftp, face, path) = (col(|r| r.ftp), col(|r| r.face), col(|r| r.path));
        let (obs, typ) = (col(|r| r.obs), col(|r| r.typical));
        #[allow(clippy::cast_precision_loss)]
        let n = ftp.len() as f64;
        let m = ftp.iter().sum::<f64>() / n;
        let var = ftp.iter().map(|x| (x - m).powi(2)).sum::<f64>() / n;
        let (b_tm, b_md) = (slope(&ftp, &obs), slope(&ftp, &typ));
        let lambda = b_tm / b_md;
        let [tf, tp] = slope2(&face, &path, &obs);
        let [mf, mp] = slope2(&face, &path, &typ);
        let (d_obs, d_md) = (col(|r| r.dir[0]), col(|r| r.dir[1]));
        let [df, dp] = slope2(&face, &path, &d_obs);
        let [mdf, mdp] = slope2(&face, &path, &d_md);
        let res: Vec<f64> = d_obs.iter().zip(&d_md).map(|(o, m)| o - m).collect();
        let rm = res.iter().sum::<f64>() / n;
        let res_sd = (res.iter().map(|x| (x - rm).powi(2)).sum::<f64>() / n).sqrt();
        println!(
            "| {name} | {} | {:.2}° | {:.2}, {:.2} | {:.2}, {:.2} | {:.2} / {:.2} = {:.2} | {:.2}° | {:.3}, {:.3} / {:.3}, {:.3} | {:.2}° |",
            g.len(),
            var.sqrt(),
            tf,
            tp,
            mf,
            mp,
            b_tm,
            b_md,
            lambda,
            (var * (1.0 - lambda)).max(0.0).sqrt(),
            df,
            dp,
            mdf,
            mdp,
            res_sd
        );
    }
}
