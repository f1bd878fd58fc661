//! Issue 34: TrackMan's spin axis against the flight its own radar tracked outdoors
//! (docs/impact.md §0.8, *The tracked curvature*).
//!
//! The rows tracked outdoors past 100 yd ([`Drive::tracked_outdoors`]) carry a measured
//! position of the ball late in its flight: TrackMan's last tracked point (length, side,
//! height, time). Each row with a full delivery and a plausible launch is flown with the
//! default aerodynamics (`drives2026`, f64, Dormand–Prince at 1e-9):
//!
//! * **(A)** TrackMan's launch as reported (ball speed, launch angle and direction, spin,
//!   TrackMan's spin axis);
//! * **(B)** the same launch with the spin axis the default impact model gives from the
//!   row's club data (`single_drives::predict`: the `driver` preset, the presets' contact,
//!   TrackMan's convention, the measured strike location when the row has one, else the
//!   preset's typical strike);
//! * **(C)** the impact model's whole launch.
//!
//! The *curvature* of a flight at the tracked point is its side less the straight line of
//! its launch direction, `z − x·tan(direction)`. The tracked curvature is regressed on
//! face-to-path with one intercept per outing (a run of outdoor rows; one day's cross wind),
//! and so are (A)'s, (B)'s and (C)'s, and the residuals (tracked − flown). Flights are read at
//! the tracked point's downrange length (the main figures) and at its time; in standard air
//! (the data README's 21.1 °C, 50 % RH, 101,325 Pa) and in each outing's weather fitted by
//! `single_shots::fit_weather` (density, tail and cross wind from carry, apex, landing angle,
//! flight time and Carry Flat side, with TrackMan's launch). TrackMan's Carry Flat side is a
//! secondary check (on these rows it lies inside the tracked flight: the last tracked point
//! is the ball coming down on ground below the tee, past Carry Flat, so the flights are
//! continued below the tee's height to be read there).
//!
//! The axis the track implies: TrackMan's axis moved by the tracked curvature's excess over
//! (A), read through (A)'s curvature per degree of axis (a flight with the axis 1° right).
//! Last, TrackMan's and the model's axis by face-to-path band, indoors against outdoors.
//!
//! `cargo run --release -p carry-lab --example axis_tracked_outdoors`
//! (`$CARRY_DRIVES` overrides the file's path.)

use carry_core::aero::AeroModel;
use carry_core::impact::ContactLaw;
use carry_core::presets::FITTED_COMPLIANT;
use carry_core::units::{deg, rpm};
use carry_core::{Air, Ball, Integrator, Launch, Recorder, Sample, SampleSink, Scene, Wind};
use carry_lab::drives::{self, BallKind, Drive};
use carry_lab::fit::single_drives;
use carry_lab::fit::single_shots::{
    SessionWeather, drive_row, fit_weather, standard_air, with_side,
};
use carry_lab::launch_drives::{outing_of, outing_starts};
use nalgebra::Vector3;
use rayon::prelude::*;

/// The sampling step of the flown trajectories (linear interpolation between samples:
/// ≲ a·Δt²/8 ≈ 2e-5 m at the ball's few m/s² of lateral acceleration).
const STEP_S: f64 = 0.005;
/// Samples up to this time (s).
const HORIZON_S: f64 = 15.0;
const YD: f64 = 0.9144;
/// The flights continue down to this height (m): outdoors the last tracked point is
/// mostly the ball coming down on a landing area a few yards below the tee, after
/// TrackMan's Carry Flat (the tee's height), and a flight that comes down sooner than the
/// tracked ball is still read at the tracked time (continued under the same forces).
const FLOOR_M: f64 = -60.0;

struct Samples(Vec<Sample<f64>>);

impl SampleSink<f64> for Samples {
    fn clear(&mut self) {
        self.0.clear();
    }
    fn push(&mut self, sample: Sample<f64>) -> bool {
        self.0.push(sample);
        true
    }
}

/// Where a flight was when and where TrackMan last saw the ball, and where it landed.
#[derive(Clone, Copy, Debug)]
struct Flown {
    /// Side (m) at the tracked time, and the downrange length (m) there.
    side_at_time: f64,
    x_at_time: f64,
    /// Side (m) at the tracked downrange length.
    side_at_length: f64,
    /// Side (m) at TrackMan's carry length (extrapolated along the landing velocity when
    /// the flight lands short of it).
    side_at_carry: f64,
}

/// The trajectory's side at downrange length `x`: interpolated between samples, or
/// continued along the landing velocity past the landing.
fn side_at_x(track: &[Sample<f64>], x: f64) -> f64 {
    match track.iter().position(|s| s.position_m.x >= x) {
        Some(0) => track[0].position_m.z,
        Some(i) => {
            let (a, b) = (&track[i - 1], &track[i]);
            let f = (x - a.position_m.x) / (b.position_m.x - a.position_m.x);
            a.position_m.z + f * (b.position_m.z - a.position_m.z)
        }
        None => {
            let last = track[track.len() - 1];
            last.position_m.z + (x - last.position_m.x) * last.velocity_mps.z / last.velocity_mps.x
        }
    }
}

/// The trajectory's `(side, downrange)` at time `t`, or `None` past the landing.
fn at_time(track: &[Sample<f64>], t: f64) -> Option<(f64, f64)> {
    let i = track.iter().position(|s| s.time_s >= t)?;
    if i == 0 {
        return Some((track[0].position_m.z, track[0].position_m.x));
    }
    let (a, b) = (&track[i - 1], &track[i]);
    let f = (t - a.time_s) / (b.time_s - a.time_s);
    let p = a.position_m + (b.position_m - a.position_m) * f;
    Some((p.z, p.x))
}

/// Flies `launch` in `air` and a uniform `wind` (m/s, G) down to the height `floor` (m)
/// and reads it at the tracked point (`t` s, `x` m downrange) and at
/// TrackMan's carry `carry` (m).
fn fly(
    launch: &Launch<f64>,
    air: Air<f64>,
    wind: [f64; 3],
    floor: f64,
    [t, x, carry]: [f64; 3],
) -> Option<Flown> {
    let scene = Scene {
        aero: AeroModel::default(),
        air,
        wind: if wind == [0.0; 3] {
            Wind::None
        } else {
            Wind::Uniform(Vector3::from(wind))
        },
        landing_height_m: floor,
        ..Scene::default()
    };
    let prepared = scene.prepare(&Ball::standard()).ok()?;
    let motion = launch.ball_motion().ok()?;
    let times: Vec<f64> = (0..=(HORIZON_S / STEP_S) as usize)
        .map(|k| k as f64 * STEP_S)
        .collect();
    let mut sink = Samples(Vec::new());
    let o = {
        let mut rec = Recorder::at_times(&times, &mut sink).ok()?;
        prepared
            .fly(&motion, &Integrator::dormand_prince(1e-9), Some(&mut rec))
            .ok()?
    };
    let mut track: Vec<Sample<f64>> = sink
        .0
        .into_iter()
        .filter(|s| s.time_s < o.flight_time_s)
        .collect();
    track.push(Sample {
        time_s: o.flight_time_s,
        position_m: o.landing_position_m,
        velocity_mps: o.landing_velocity_mps,
        spin_radps: Vector3::zeros(),
    });
    let (side_at_time, x_at_time) = at_time(&track, t)?;
    Some(Flown {
        side_at_time,
        x_at_time,
        side_at_length: side_at_x(&track, x),
        side_at_carry: side_at_x(&track, carry),
    })
}

/// One outdoor drive: what TrackMan measured and what the impact model says.
#[derive(Clone, Copy)]
struct Row {
    drive: Drive,
    outing: usize,
    /// Face to path (°) of the club data (face − path).
    ftp: f64,
    /// TrackMan's launch: ball speed m/s, launch °, direction °, spin rpm, axis °.
    tm: [f64; 5],
    /// The impact model's launch, the same order.
    model: [f64; 5],
    /// The last tracked point: time (s), downrange, height, side (m).
    t: f64,
    last: [f64; 3],
    /// TrackMan's Carry Flat length and side (m).
    carry: f64,
    carry_side: f64,
}

fn launch_of(l: [f64; 5]) -> Launch<f64> {
    Launch::from_spin_axis(l[0], deg(l[1]), deg(l[2]), rpm(l[3]), deg(l[4]))
}

/// The flights of a row: (A) TrackMan's launch, (B) its axis replaced by the model's,
/// (C) the model's launch, and (A) with the axis [`AXIS_STEP_DEG`] to the right (the
/// curvature's sensitivity to the axis).
fn flights(r: &Row, air: Air<f64>, wind: [f64; 3]) -> Option<[Flown; 4]> {
    let mut b = r.tm;
    b[4] = r.model[4];
    let mut d = r.tm;
    d[4] += AXIS_STEP_DEG;
    let go = |l: [f64; 5]| fly(&launch_of(l), air, wind, FLOOR_M, [r.t, r.last[0], r.carry]);
    Some([go(r.tm)?, go(b)?, go(r.model)?, go(d)?])
}

/// The axis step (°) of the curvature's sensitivity (central enough: the curvature is
/// nearly linear in the axis over a degree).
const AXIS_STEP_DEG: f64 = 1.0;

/// Values demeaned within their group.
fn within(groups: &[usize], v: &[f64]) -> Vec<f64> {
    let n = groups.iter().copied().max().map_or(0, |m| m + 1);
    let (mut sum, mut count) = (vec![0.0; n], vec![0.0; n]);
    for (&g, &x) in groups.iter().zip(v) {
        sum[g] += x;
        count[g] += 1.0;
    }
    groups
        .iter()
        .zip(v)
        .map(|(&g, &x)| x - sum[g] / count[g])
        .collect()
}

fn groups_used(groups: &[usize]) -> usize {
    let mut g = groups.to_vec();
    g.sort_unstable();
    g.dedup();
    g.len()
}

/// The slope of `y` on `x` with one intercept per group, and its standard error.
fn slope(groups: &[usize], x: &[f64], y: &[f64]) -> (f64, f64) {
    let (x, y) = (within(groups, x), within(groups, y));
    let sxx: f64 = x.iter().map(|v| v * v).sum();
    let sxy: f64 = x.iter().zip(&y).map(|(a, b)| a * b).sum();
    let b = sxy / sxx;
    let rss: f64 = x.iter().zip(&y).map(|(a, c)| (c - b * a).powi(2)).sum();
    let dof = (x.len() as f64 - groups_used(groups) as f64 - 1.0).max(1.0);
    (b, (rss / dof / sxx).sqrt())
}

/// `y = b₁ x₁ + b₂ x₂` with one intercept per group: `(b₁, se₁, b₂, se₂)`.
fn slopes2(groups: &[usize], x1: &[f64], x2: &[f64], y: &[f64]) -> [f64; 4] {
    let (x1, x2, y) = (within(groups, x1), within(groups, x2), within(groups, y));
    let dot = |a: &[f64], b: &[f64]| -> f64 { a.iter().zip(b).map(|(p, q)| p * q).sum() };
    let (a11, a12, a22) = (dot(&x1, &x1), dot(&x1, &x2), dot(&x2, &x2));
    let (c1, c2) = (dot(&x1, &y), dot(&x2, &y));
    let det = a11 * a22 - a12 * a12;
    let b1 = (a22 * c1 - a12 * c2) / det;
    let b2 = (a11 * c2 - a12 * c1) / det;
    let rss: f64 = (0..y.len())
        .map(|i| (y[i] - b1 * x1[i] - b2 * x2[i]).powi(2))
        .sum();
    let s2 = rss / (y.len() as f64 - groups_used(groups) as f64 - 2.0).max(1.0);
    [b1, (s2 * a22 / det).sqrt(), b2, (s2 * a11 / det).sqrt()]
}

fn mean_abs(v: &[f64]) -> f64 {
    v.iter().map(|x| x.abs()).sum::<f64>() / v.len() as f64
}

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len() as f64
}

/// Which point of the flight is compared.
#[derive(Clone, Copy, PartialEq)]
enum At {
    /// The tracked point's downrange length.
    Length,
    /// The tracked point's time.
    Time,
    /// TrackMan's Carry Flat length (side: Carry Flat - Side).
    Carry,
}

impl At {
    fn name(self) -> &'static str {
        match self {
            Self::Length => "last tracked point, same length",
            Self::Time => "last tracked point, same time",
            Self::Carry => "Carry Flat (TrackMan's landing)",
        }
    }
}

/// The curvatures (m) at `at`: tracked, then (A), (B), (C), and (A) with the axis one
/// step to the right.
fn curvatures(r: &Row, f: &[Flown; 4], at: At) -> [f64; 5] {
    let tan_tm = deg(r.tm[2]).tan();
    let tan_model = deg(r.model[2]).tan();
    let (tracked, x_tracked) = match at {
        At::Carry => (r.carry_side, r.carry),
        _ => (r.last[2], r.last[0]),
    };
    let flown = |k: usize, tan: f64| -> f64 {
        match at {
            At::Length => f[k].side_at_length - x_tracked * tan,
            At::Carry => f[k].side_at_carry - x_tracked * tan,
            At::Time => f[k].side_at_time - f[k].x_at_time * tan,
        }
    };
    [
        tracked - x_tracked * tan_tm,
        flown(0, tan_tm),
        flown(1, tan_tm),
        flown(2, tan_model),
        flown(3, tan_tm),
    ]
}

/// The comparison of one subset at one point, in one air.
#[allow(clippy::too_many_lines)]
fn report(rows: &[(Row, [Flown; 4])], at: At, label: &str) {
    let groups: Vec<usize> = rows.iter().map(|(r, _)| r.outing).collect();
    let ftp: Vec<f64> = rows.iter().map(|(r, _)| r.ftp).collect();
    let axis_tm: Vec<f64> = rows.iter().map(|(r, _)| r.tm[4]).collect();
    let c: Vec<[f64; 5]> = rows.iter().map(|(r, f)| curvatures(r, f, at)).collect();
    let col = |k: usize| -> Vec<f64> { c.iter().map(|v| v[k]).collect() };
    let tracked = col(0);
    println!(
        "\n### {label}: {} ({} rows, {} outings; yd)\n",
        at.name(),
        rows.len(),
        groups_used(&groups)
    );
    println!(
        "| curvature | per ° of face-to-path (± se) | per ° of TrackMan's axis | residual (tracked − flown) per ° of face-to-path | residual per ° of TrackMan's axis | mean \\|Δ\\|, outing offsets removed | mean \\|Δ\\| raw |"
    );
    println!("|---|---|---|---|---|---|---|");
    let (b, se) = slope(&groups, &ftp, &tracked);
    let (ba, sea) = slope(&groups, &axis_tm, &tracked);
    println!(
        "| tracked | {:+.2} ± {:.2} | {:+.2} ± {:.2} | | | | |",
        b / YD,
        se / YD,
        ba / YD,
        sea / YD
    );
    for (k, name) in [
        (1, "(A) TrackMan's launch and axis"),
        (2, "(B) TrackMan's launch, model's axis"),
        (3, "(C) the model's launch"),
    ] {
        let flown = col(k);
        let resid: Vec<f64> = tracked.iter().zip(&flown).map(|(t, f)| t - f).collect();
        let (b, se) = slope(&groups, &ftp, &flown);
        let (ba, sea) = slope(&groups, &axis_tm, &flown);
        let (rb, rse) = slope(&groups, &ftp, &resid);
        let (ra, rsa) = slope(&groups, &axis_tm, &resid);
        println!(
            "| {name} | {:+.2} ± {:.2} | {:+.2} ± {:.2} | {:+.2} ± {:.2} | {:+.2} ± {:.2} | {:.1} | {:.1} |",
            b / YD,
            se / YD,
            ba / YD,
            sea / YD,
            rb / YD,
            rse / YD,
            ra / YD,
            rsa / YD,
            mean_abs(&within(&groups, &resid)) / YD,
            mean_abs(&resid) / YD,
        );
    }
    let [b1, s1, b2, s2] = slopes2(&groups, &col(1), &col(2), &tracked);
    println!(
        "\ntracked = b_A·(A) + b_B·(B) + outing offsets: b_A = {b1:+.2} ± {s1:.2}, b_B = {b2:+.2} ± {s2:.2}"
    );
    let implied = implied_axes(rows, &c);
    let axis_model: Vec<f64> = rows.iter().map(|(r, _)| r.model[4]).collect();
    let (bi, si) = slope(&groups, &ftp, &implied);
    let (bt, st) = slope(&groups, &ftp, &axis_tm);
    let (bm, sm) = slope(&groups, &ftp, &axis_model);
    let off = |a: &[f64]| -> f64 {
        mean_abs(&within(
            &groups,
            &implied
                .iter()
                .zip(a)
                .map(|(i, x)| i - x)
                .collect::<Vec<f64>>(),
        ))
    };
    println!(
        "The axis the track implies (TrackMan's axis + (tracked − (A)) / ∂(A)/∂axis): {bi:.2} ± {si:.2} °/° of face-to-path (TrackMan's reported {bt:.2} ± {st:.2}, the model's {bm:.2} ± {sm:.2}); mean |implied − reported| {:.1}°, |implied − model| {:.1}° (outing offsets removed).",
        off(&axis_tm),
        off(&axis_model)
    );
}

/// The axis (°) each row's tracked curvature implies: TrackMan's axis moved by the tracked
/// curvature's excess over (A), read through (A)'s sensitivity to the axis.
fn implied_axes(rows: &[(Row, [Flown; 4])], c: &[[f64; 5]]) -> Vec<f64> {
    rows.iter()
        .zip(c)
        .map(|((r, _), v)| r.tm[4] + (v[0] - v[1]) * AXIS_STEP_DEG / (v[4] - v[1]))
        .collect()
}

/// The face-to-path bands (°).
const BANDS: [(f64, f64); 6] = [
    (f64::NEG_INFINITY, -4.0),
    (-4.0, -2.0),
    (-2.0, 0.0),
    (0.0, 2.0),
    (2.0, 4.0),
    (4.0, f64::INFINITY),
];

fn band_name(lo: f64, hi: f64) -> String {
    match (lo.is_finite(), hi.is_finite()) {
        (false, _) => format!("< {hi:+}°"),
        (_, false) => format!("≥ {lo:+}°"),
        _ => format!("{lo:+} … {hi:+}°"),
    }
}

/// A row of [`axis_by_band`]: TrackMan's data and the default impact's on one drive.
struct BandRow {
    outdoors: bool,
    /// Face-to-path (°) of the club data.
    ftp: f64,
    /// Spin loft (°): dynamic loft less attack.
    spin_loft: f64,
    /// TrackMan's and the model's spin axis (°).
    axis_tm: f64,
    axis_model: f64,
    /// TrackMan's and the model's spin (rpm).
    spin_tm: f64,
    spin_model: f64,
    /// The strike toward the toe (m), when measured.
    toe_m: Option<f64>,
    /// The session block.
    session: usize,
}

/// TrackMan's and the model's axis by face-to-path band, indoors and outdoors (all rows
/// with a full delivery and a plausible launch; the model at the measured strike location
/// when there is one), with the mean strike location toward the toe where measured; then
/// the spin loft and the spin in the same bands.
fn axis_by_band(all: &[Drive], law: ContactLaw<f64>, typical: [f64; 2]) {
    let rows: Vec<BandRow> = all
        .par_iter()
        .filter_map(|d| {
            let tm = single_drives::observed(d)?;
            let club = d.full_delivery()?;
            let model = single_drives::predict(d, law, true, typical).ok()?;
            Some(BandRow {
                outdoors: d.tracked_outdoors(),
                ftp: club[4] - club[2],
                spin_loft: club[3] - club[1],
                axis_tm: tm[4],
                axis_model: model[4],
                spin_tm: tm[3],
                spin_model: model[3],
                toe_m: d.strike_m.map(|s| s[0]),
                session: d.session(),
            })
        })
        .collect();
    errors_in_variables(&rows);
    let of = |out: bool, lo: f64, hi: f64| -> Vec<&BandRow> {
        rows.iter()
            .filter(|r| r.outdoors == out && (lo..hi).contains(&r.ftp))
            .collect()
    };
    let m = |v: &[&BandRow], k: fn(&BandRow) -> f64| -> f64 {
        mean(&v.iter().map(|r| k(r)).collect::<Vec<f64>>())
    };
    println!(
        "\n### TrackMan's and the model's axis by face-to-path band, indoors and tracked outdoors (all rows with a full delivery and a plausible launch)\n"
    );
    println!(
        "| face-to-path | indoors: rows, mean face-to-path | TrackMan / model axis (mean °) | strike toward the toe (mean mm, rows) | outdoors: rows, mean face-to-path | TrackMan / model axis (mean °) |"
    );
    println!("|---|---|---|---|---|---|");
    for (lo, hi) in BANDS {
        let cell = |v: &[&BandRow]| -> [String; 2] {
            [
                format!("{}, {:+.1}°", v.len(), m(v, |r| r.ftp)),
                format!(
                    "{:+.1} / {:+.1}",
                    m(v, |r| r.axis_tm),
                    m(v, |r| r.axis_model)
                ),
            ]
        };
        let (inside, outside) = (of(false, lo, hi), of(true, lo, hi));
        let toe: Vec<f64> = inside.iter().filter_map(|r| r.toe_m).collect();
        let [ni, ai] = cell(&inside);
        let [no, ao] = cell(&outside);
        println!(
            "| {} | {ni} | {ai} | {:+.1}, {} | {no} | {ao} |",
            band_name(lo, hi),
            mean(&toe) * 1e3,
            toe.len()
        );
    }
    println!(
        "\n### The spin loft and the spin by the same bands: TrackMan's spin against the model's from the club data\n"
    );
    println!(
        "| face-to-path | indoors: spin loft (mean °) | TrackMan / model spin (mean rpm) | outdoors: spin loft (mean °) | TrackMan / model spin (mean rpm) |"
    );
    println!("|---|---|---|---|---|");
    for (lo, hi) in BANDS {
        let cell = |v: &[&BandRow]| -> [String; 2] {
            [
                format!("{:.1}", m(v, |r| r.spin_loft)),
                format!("{:.0} / {:.0}", m(v, |r| r.spin_tm), m(v, |r| r.spin_model)),
            ]
        };
        let [li, si] = cell(&of(false, lo, hi));
        let [lo_, so] = cell(&of(true, lo, hi));
        println!("| {} | {li} | {si} | {lo_} | {so} |", band_name(lo, hi));
    }
}

/// Could noise in the reported face-to-path alone explain TrackMan's flat axis? With noise
/// in the regressor only, the least-squares slope `b` of the axis on face-to-path is
/// attenuated and the reverse regression's inverse `b/R²` over-states the true slope; with
/// noise in both, the true slope lies between them (Frisch's bounds; e.g. Fuller,
/// *Measurement Error Models*, 1987, §1.1.3). A model slope above `b/R²` cannot be reached
/// by the face-to-path's noise, whatever its size. Per subset: rows, `b`, `R²`, `b/R²`, and
/// the model's own slope on the same rows (plain least squares, with an intercept).
fn errors_in_variables(rows: &[BandRow]) {
    let fit = |x: &[f64], y: &[f64]| -> (f64, f64) {
        let (mx, my) = (mean(x), mean(y));
        let sxx: f64 = x.iter().map(|v| (v - mx).powi(2)).sum();
        let syy: f64 = y.iter().map(|v| (v - my).powi(2)).sum();
        let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - mx) * (b - my)).sum();
        (sxy / sxx, sxy * sxy / (sxx * syy))
    };
    println!(
        "\n### Face-to-path noise as the cause? TrackMan's axis slope and its errors-in-variables bound against the model's slope\n"
    );
    println!(
        "| rows | n | TrackMan's axis per ° of face-to-path (least squares) | R² | upper bound b/R² | the model's slope, same rows |"
    );
    println!("|---|---|---|---|---|---|");
    let mut subsets: Vec<(String, Vec<&BandRow>)> = vec![
        ("all".into(), rows.iter().collect()),
        (
            "indoors".into(),
            rows.iter().filter(|r| !r.outdoors).collect(),
        ),
        (
            "tracked outdoors".into(),
            rows.iter().filter(|r| r.outdoors).collect(),
        ),
    ];
    for s in 0..=rows.iter().map(|r| r.session).max().unwrap_or(0) {
        subsets.push((
            format!("session {s}, indoors"),
            rows.iter()
                .filter(|r| !r.outdoors && r.session == s)
                .collect(),
        ));
    }
    for (name, v) in subsets {
        if v.len() < 30 {
            continue;
        }
        let x: Vec<f64> = v.iter().map(|r| r.ftp).collect();
        let (b, r2) = fit(&x, &v.iter().map(|r| r.axis_tm).collect::<Vec<f64>>());
        let (bm, _) = fit(&x, &v.iter().map(|r| r.axis_model).collect::<Vec<f64>>());
        println!(
            "| {name} | {} | {b:.2} | {r2:.2} | {:.2} | {bm:.2} |",
            v.len(),
            b / r2
        );
    }
}

/// The residuals by face-to-path band, outing offsets removed (each flight's own).
fn bands(rows: &[(Row, [Flown; 4])], at: At, label: &str) {
    let groups: Vec<usize> = rows.iter().map(|(r, _)| r.outing).collect();
    let c: Vec<[f64; 5]> = rows.iter().map(|(r, f)| curvatures(r, f, at)).collect();
    let resid = |k: usize| -> Vec<f64> {
        within(
            &groups,
            &c.iter().map(|v| v[0] - v[k]).collect::<Vec<f64>>(),
        )
    };
    let (ra, rb, rc) = (resid(1), resid(2), resid(3));
    let tracked = within(&groups, &c.iter().map(|v| v[0]).collect::<Vec<f64>>());
    let flown = |k: usize| within(&groups, &c.iter().map(|v| v[k]).collect::<Vec<f64>>());
    let (fa, fb) = (flown(1), flown(2));
    // The implied axis anchored to TrackMan's per outing (its outing offset, the day's cross
    // wind, removed).
    let implied: Vec<f64> = {
        let i = implied_axes(rows, &c);
        let d = within(
            &groups,
            &i.iter()
                .zip(rows)
                .map(|(i, (r, _))| i - r.tm[4])
                .collect::<Vec<f64>>(),
        );
        rows.iter().zip(d).map(|((r, _), d)| r.tm[4] + d).collect()
    };
    println!(
        "\n### {label}: by face-to-path band, {} (yd; each flight's outing offsets removed)\n",
        at.name()
    );
    println!(
        "| face-to-path | rows | mean face-to-path (°) | launch direction, model − TrackMan (mean °) | axis: TrackMan / implied by the track / model (mean °) | curvature: tracked / (A) / (B) (mean) | Δ (A): mean, mean \\|Δ\\| | Δ (B): mean, mean \\|Δ\\| | Δ (C): mean, mean \\|Δ\\| |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for (lo, hi) in BANDS {
        let idx: Vec<usize> = (0..rows.len())
            .filter(|&i| (lo..hi).contains(&rows[i].0.ftp))
            .collect();
        if idx.is_empty() {
            continue;
        }
        let pick = |v: &[f64]| -> Vec<f64> { idx.iter().map(|&i| v[i]).collect() };
        let ax_tm = mean(&pick(
            &rows.iter().map(|(r, _)| r.tm[4]).collect::<Vec<_>>(),
        ));
        let ax_m = mean(&pick(
            &rows.iter().map(|(r, _)| r.model[4]).collect::<Vec<_>>(),
        ));
        let band = band_name(lo, hi);
        println!(
            "| {band} | {} | {:+.1} | {:+.2} | {ax_tm:+.1} / {:+.1} / {ax_m:+.1} | {:+.1} / {:+.1} / {:+.1} | {:+.1}, {:.1} | {:+.1}, {:.1} | {:+.1}, {:.1} |",
            idx.len(),
            mean(&pick(&rows.iter().map(|(r, _)| r.ftp).collect::<Vec<_>>())),
            mean(&pick(
                &rows
                    .iter()
                    .map(|(r, _)| r.model[2] - r.tm[2])
                    .collect::<Vec<_>>()
            )),
            mean(&pick(&implied)),
            mean(&pick(&tracked)) / YD,
            mean(&pick(&fa)) / YD,
            mean(&pick(&fb)) / YD,
            mean(&pick(&ra)) / YD,
            mean_abs(&pick(&ra)) / YD,
            mean(&pick(&rb)) / YD,
            mean_abs(&pick(&rb)) / YD,
            mean(&pick(&rc)) / YD,
            mean_abs(&pick(&rc)) / YD,
        );
    }
}

#[allow(clippy::too_many_lines)]
fn main() {
    let all = match drives::read_shared() {
        Ok(d) => d,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    };
    let starts = outing_starts(&all);
    let preset = single_drives::driver();
    let typical = [0.0, preset.typical.impact_height_m];
    let law = ContactLaw::Compliant(FITTED_COMPLIANT);
    let rows: Vec<Row> = all
        .iter()
        .filter(|d| d.tracked_outdoors())
        .filter_map(|d| {
            let tm = single_drives::observed(d)?;
            let club = d.full_delivery()?;
            let model = single_drives::predict(d, law, true, typical).ok()?;
            let [x, y, z] = d.flight.last_point_m?;
            Some(Row {
                drive: *d,
                outing: outing_of(&starts, d.index),
                ftp: club[4] - club[2],
                tm,
                model,
                t: d.flight.last_point_time_s?,
                last: [x, y, z],
                carry: d.flight.carry_m?,
                carry_side: d.flight.carry_side_m?,
            })
        })
        .filter(|r| r.tm[1] >= 1.0)
        .collect();
    let outdoors = all.iter().filter(|d| d.tracked_outdoors()).count();
    println!("# TrackMan's spin axis against the flight its radar tracked outdoors\n");
    println!(
        "{outdoors} rows tracked past 100 yd; {} with a full delivery, a plausible launch ≥ 1°, a last tracked time and a carry; {} with a strike location (struck there).",
        rows.len(),
        rows.iter().filter(|r| r.drive.strike_m.is_some()).count()
    );
    let median = |mut v: Vec<f64>| -> f64 {
        v.sort_by(f64::total_cmp);
        v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
    };
    println!(
        "The last tracked point (medians): {:.1} yd downrange, {:+.1} yd high, {:.2} s; {:+.1} yd and {:+.2} s past TrackMan's Carry Flat (the ball tracked down to a landing area below the tee).",
        median(rows.iter().map(|r| r.last[0] / YD).collect()),
        median(rows.iter().map(|r| r.last[1] / YD).collect()),
        median(rows.iter().map(|r| r.t).collect()),
        median(rows.iter().map(|r| (r.last[0] - r.carry) / YD).collect()),
        median(
            rows.iter()
                .filter_map(|r| Some(r.t - r.drive.flight.flight_time_s?))
                .collect()
        ),
    );
    let ftp: Vec<f64> = rows.iter().map(|r| r.ftp).collect();
    let groups: Vec<usize> = rows.iter().map(|r| r.outing).collect();
    let (bt, st) = slope(
        &groups,
        &ftp,
        &rows.iter().map(|r| r.tm[4]).collect::<Vec<_>>(),
    );
    let (bm, sm) = slope(
        &groups,
        &ftp,
        &rows.iter().map(|r| r.model[4]).collect::<Vec<_>>(),
    );
    println!(
        "Spin axis per ° of face-to-path on these rows (outing offsets): TrackMan {bt:.2} ± {st:.2}, model {bm:.2} ± {sm:.2}."
    );
    let dir_gap: Vec<f64> = rows.iter().map(|r| r.model[2] - r.tm[2]).collect();
    let (bd, sd) = slope(&groups, &ftp, &dir_gap);
    println!(
        "Launch direction, model − TrackMan (the club data's check): mean {:+.2}°, mean |Δ| {:.2}° ({:.2}° outing offsets removed), {bd:+.3} ± {sd:.3} °/° of face-to-path.",
        mean(&dir_gap),
        mean_abs(&dir_gap),
        mean_abs(&within(&groups, &dir_gap))
    );

    // Each outing's weather, fitted on its rows with TrackMan's launch (aerodynamics held).
    let integrator = Integrator::dormand_prince(1e-9);
    let n_outings = groups.iter().copied().max().map_or(0, |m| m + 1);
    let weathers: Vec<Option<SessionWeather>> = (0..n_outings)
        .into_par_iter()
        .map(|g| {
            let drives: Vec<Drive> = rows
                .iter()
                .filter(|r| r.outing == g)
                .map(|r| r.drive)
                .collect();
            let dr: Vec<_> = drives
                .iter()
                .filter_map(|d| drive_row(d, standard_air()))
                .collect();
            if dr.len() < 10 {
                return None;
            }
            fit_weather(&AeroModel::default(), &with_side(&dr), &integrator)
                .ok()
                .map(|(w, _)| w)
        })
        .collect();
    println!(
        "\n| outing | rows | first–last row (file order, 1-based) | premium | fitted density (kg/m³) | tail wind (m/s) | cross wind (m/s) |"
    );
    println!("|---|---|---|---|---|---|---|");
    for (g, w) in weathers.iter().enumerate() {
        let of: Vec<&Row> = rows.iter().filter(|r| r.outing == g).collect();
        if of.is_empty() {
            continue;
        }
        let w = w.map_or_else(
            || "— | — | —".to_owned(),
            |w| {
                format!(
                    "{:.3} | {:+.2} | {:+.2}",
                    w.density_kgm3, w.tail_wind_mps, w.cross_wind_mps
                )
            },
        );
        println!(
            "| {g} | {} | {}–{} | {} | {w} |",
            of.len(),
            of[0].drive.index + 1,
            of[of.len() - 1].drive.index + 1,
            of.iter()
                .filter(|r| r.drive.ball == BallKind::Premium)
                .count(),
        );
    }

    for weather in [false, true] {
        let flown: Vec<(Row, [Flown; 4])> = rows
            .par_iter()
            .filter_map(|r| {
                let (air, wind) = match (weather, weathers.get(r.outing).copied().flatten()) {
                    (true, Some(w)) => (
                        Air::Density(w.density_kgm3),
                        [w.tail_wind_mps, 0.0, w.cross_wind_mps],
                    ),
                    (true, None) => return None,
                    (false, _) => (standard_air(), [0.0; 3]),
                };
                Some((*r, flights(r, air, wind)?))
            })
            .collect();
        let air = if weather {
            "each outing's fitted weather"
        } else {
            "standard air, no wind"
        };
        println!("\n## {air}: {} rows flown", flown.len());
        let premium: Vec<(Row, [Flown; 4])> = flown
            .iter()
            .filter(|(r, _)| r.drive.ball == BallKind::Premium)
            .copied()
            .collect();
        for at in [At::Length, At::Time, At::Carry] {
            report(&flown, at, "all balls");
            if at == At::Length {
                report(&premium, at, "premium ball");
            }
        }
        bands(&flown, At::Length, "all balls");
    }
    axis_by_band(&all, law, typical);
}
