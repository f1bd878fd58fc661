//! The run-out calibrated to TrackMan's 2010 driver chart (`carry calibrate`-style, as a
//! library function: [`calibrate_fairway`]; `cargo run --release -p carry-lab --example
//! ground_calibration` prints it, docs/ground.md has the figures).
//!
//! The chart (`../shared/data/trackman_driver_optimizer_2010.csv`) gives, for 30 drives,
//! the launch (ball speed, launch angle, spin), the carry and the total on "a typical
//! fairway". Each row is flown from its launch data in the data README's conditions
//! (21.1 °C, 50 % RH, 101 325 Pa, no wind, level ground); its roll is the chart's
//! `total − carry`. The one fitted number is the fairway's rolling resistance at low speed
//! ρ₀ ([`carry_core::Turf::rolling_resistance`]); the bounce (Penner's restitution,
//! friction and crater) and the grass drag's growth with speed
//! ([`carry_core::ground::surface::GRASS_DRAG_S2PM2`]) are taken from their sources and
//! not fitted. The fit minimises the mean absolute roll error (not the total's: the
//! carry's own error belongs to the aerodynamics), by golden-section search on `ln ρ₀`,
//! and reports leave-one-out errors.

use carry_core::air::{Pressure, Weather};
use carry_core::ground::{Ground, Surface, Turf};
use carry_core::units::{deg, rpm};
use carry_core::{Air, Ball, Integrator, Launch, Scene};

/// One yard (m).
pub const YARD_M: f64 = 0.9144;
/// One mph (m/s).
pub const MPH_MPS: f64 = 0.447_04;

/// One row of the chart.
#[derive(Debug, Clone, PartialEq)]
pub struct ChartRow {
    /// Club speed (mph) and attack angle (deg), as a label.
    pub label: String,
    /// The chart's club speed (mph).
    pub club_speed_mph: f64,
    /// The chart's attack angle (deg).
    pub attack_deg: f64,
    /// The launch.
    pub launch: Launch<f64>,
    /// The chart's carry (yd).
    pub carry_yd: f64,
    /// The chart's total (yd).
    pub total_yd: f64,
}

/// A row flown and run out.
#[derive(Debug, Clone, PartialEq)]
pub struct RollRow {
    /// The row's label.
    pub label: String,
    /// Chart carry and model carry (yd).
    pub carry_yd: (f64, f64),
    /// Landing angle (deg) and speed (m/s) of the model's flight.
    pub landing: (f64, f64),
    /// Chart roll (`total − carry`) and model roll (yd).
    pub roll_yd: (f64, f64),
    /// Chart total and model total (yd).
    pub total_yd: (f64, f64),
}

impl RollRow {
    /// Model roll − chart roll (yd).
    #[must_use]
    pub fn roll_error_yd(&self) -> f64 {
        self.roll_yd.1 - self.roll_yd.0
    }
    /// Model total − chart total (yd).
    #[must_use]
    pub fn total_error_yd(&self) -> f64 {
        self.total_yd.1 - self.total_yd.0
    }
}

/// The chart's rows from its CSV text.
///
/// # Errors
/// A missing column or a number that does not parse.
pub fn parse_chart(text: &str) -> Result<Vec<ChartRow>, String> {
    let mut lines = text.lines();
    let header = crate::columns::Header::of(lines.next().ok_or("empty chart")?);
    let [club, attack, bs, la, spin, carry, total] = header.columns([
        "club_speed_mph",
        "attack_deg",
        "ball_speed_mph",
        "launch_deg",
        "spin_rpm",
        "carry_yd",
        "total_yd",
    ])?;
    lines
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            let x = |i: usize| -> Result<f64, String> {
                f.get(i)
                    .and_then(|s| s.trim().parse::<f64>().ok())
                    .ok_or(format!("bad row: {l}"))
            };
            Ok(ChartRow {
                label: format!("{} mph, {:+} deg", x(club)?, x(attack)?),
                club_speed_mph: x(club)?,
                attack_deg: x(attack)?,
                launch: Launch {
                    ball_speed_mps: x(bs)? * MPH_MPS,
                    launch_angle_rad: deg(x(la)?),
                    launch_direction_rad: 0.0,
                    backspin_radps: rpm(x(spin)?),
                    sidespin_radps: 0.0,
                },
                carry_yd: x(carry)?,
                total_yd: x(total)?,
            })
        })
        .collect()
}

/// The data README's conditions: 21.1 °C, 50 % RH, 101 325 Pa, on `surface`, level.
#[must_use]
pub fn chart_scene(surface: Surface<f64>) -> Scene<f64> {
    Scene {
        air: Air::Weather(Weather {
            temperature_c: 21.1,
            relative_humidity: 0.5,
            pressure: Pressure::Pa(101_325.0),
        }),
        ground: Some(Ground::level(surface)),
        ..Scene::default()
    }
}

/// Flies and runs out every row in `scene` (which must have a ground).
///
/// # Errors
/// A row that does not fly or run out.
pub fn roll_rows(rows: &[ChartRow], scene: &Scene<f64>) -> Result<Vec<RollRow>, String> {
    let ball = Ball::standard();
    let prepared = scene.prepare(&ball).map_err(|e| e.to_string())?;
    rows.iter()
        .map(|r| {
            let motion = r.launch.ball_motion().map_err(|e| e.to_string())?;
            let o = prepared
                .fly(&motion, &Integrator::default(), None)
                .map_err(|e| format!("{}: {e}", r.label))?;
            let g = o.ground.ok_or("the scene has no ground")?;
            let carry = o.carry_m / YARD_M;
            let total = g.total_m / YARD_M;
            Ok(RollRow {
                label: r.label.clone(),
                carry_yd: (r.carry_yd, carry),
                landing: (o.landing_angle_rad.to_degrees(), o.landing_speed_mps),
                roll_yd: (r.total_yd - r.carry_yd, total - carry),
                total_yd: (r.total_yd, total),
            })
        })
        .collect()
}

/// One line with a turf's coefficients (the ground examples' reports).
#[must_use]
pub fn turf_line(t: &Turf<f64>) -> String {
    format!(
        "{:?}: e0 {:.3}, mu {:.3}, rho0 {:.4}, kappa {:.3}, v_f {:.2} m/s, c {:.4} s2/m2",
        t.crater_law,
        t.restitution,
        t.friction,
        t.rolling_resistance,
        t.crater_scale,
        t.crater_fade_mps,
        t.grass_drag_s2pm2
    )
}

/// Mean absolute value.
#[must_use]
pub fn mean_abs(x: impl Iterator<Item = f64>) -> f64 {
    let (s, n) = x.fold((0.0, 0_u32), |(s, n), e| (s + e.abs(), n + 1));
    if n == 0 { 0.0 } else { s / f64::from(n) }
}

/// The calibrated fairway.
#[derive(Debug, Clone, PartialEq)]
pub struct FairwayFit {
    /// Fitted rolling resistance at low speed ρ₀.
    pub rolling_resistance: f64,
    /// Every row at the fitted ρ₀.
    pub rows: Vec<RollRow>,
    /// Leave-one-out roll error per row (yd): the row predicted with ρ₀ fitted to the others.
    pub leave_one_out_yd: Vec<f64>,
}

/// The firm fairway's turf with rolling resistance `rho` and crater scale `kappa`
/// (Penner's restitution and friction as the preset).
fn fairway_with(rho: f64, kappa: f64) -> Result<Surface<f64>, String> {
    let base = Surface::<f64>::FairwayFirm
        .turf()
        .map_err(|e| e.to_string())?;
    Ok(Surface::Custom(Turf {
        rolling_resistance: rho,
        crater_scale: kappa,
        ..base
    }))
}

/// The minimum of a unimodal `f` on `[a, b]` by golden-section search (40 steps).
fn golden_section(
    mut a: f64,
    mut b: f64,
    f: impl Fn(f64) -> Result<f64, String>,
) -> Result<f64, String> {
    let r = 0.5 * (5.0_f64.sqrt() - 1.0);
    let (mut c, mut d) = (b - r * (b - a), a + r * (b - a));
    let (mut fc, mut fd) = (f(c)?, f(d)?);
    for _ in 0..40 {
        if fc < fd {
            b = d;
            d = c;
            fd = fc;
            c = b - r * (b - a);
            fc = f(c)?;
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + r * (b - a);
            fd = f(d)?;
        }
    }
    Ok(0.5 * (a + b))
}

/// `base` on the firm fairway with `rho` and `kappa`.
fn on_fairway(base: &Scene<f64>, rho: f64, kappa: f64) -> Result<Scene<f64>, String> {
    Ok(Scene {
        ground: Some(Ground::level(fairway_with(rho, kappa)?)),
        ..*base
    })
}

/// Mean absolute roll error over `rows` at `rho` and `kappa`.
fn roll_cost(rows: &[ChartRow], base: &Scene<f64>, rho: f64, kappa: f64) -> Result<f64, String> {
    Ok(mean_abs(
        roll_rows(rows, &on_fairway(base, rho, kappa)?)?
            .iter()
            .map(RollRow::roll_error_yd),
    ))
}

/// ρ₀ minimising the mean absolute roll error over `rows` at crater scale `kappa`
/// (golden section on ln ρ₀ in 0.01–1).
fn fit_rho(rows: &[ChartRow], base: &Scene<f64>, kappa: f64) -> Result<f64, String> {
    let ln_rho = golden_section(0.01_f64.ln(), 1.0_f64.ln(), |l| {
        roll_cost(rows, base, l.exp(), kappa)
    })?;
    Ok(ln_rho.exp())
}

/// The firm fairway preset's crater scale κ (Penner's green: 1).
fn preset_crater_scale() -> Result<f64, String> {
    Ok(Surface::<f64>::FairwayFirm
        .turf()
        .map_err(|e| e.to_string())?
        .crater_scale)
}

/// The chart's fit at one crater scale.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CraterScanRow {
    /// The crater scale κ, held.
    pub crater_scale: f64,
    /// ρ₀ fitted at that κ.
    pub rolling_resistance: f64,
    /// Roll and total mean |err| over the chart (yd).
    pub roll_yd: f64,
    /// Total mean |err| (yd).
    pub total_yd: f64,
}

/// The chart's roll fit with the crater scale held at each of `kappas` in turn (ρ₀ fitted
/// each time): what the chart alone says of the crater (docs/ground.md).
///
/// # Errors
/// A row that does not fly.
pub fn crater_scan(
    rows: &[ChartRow],
    scene: &Scene<f64>,
    kappas: &[f64],
) -> Result<Vec<CraterScanRow>, String> {
    kappas
        .iter()
        .map(|&kappa| {
            let rho = fit_rho(rows, scene, kappa)?;
            let at = roll_rows(rows, &on_fairway(scene, rho, kappa)?)?;
            Ok(CraterScanRow {
                crater_scale: kappa,
                rolling_resistance: rho,
                roll_yd: mean_abs(at.iter().map(RollRow::roll_error_yd)),
                total_yd: mean_abs(at.iter().map(RollRow::total_error_yd)),
            })
        })
        .collect()
}

/// Calibrates the firm fairway's ρ₀ to the chart `rows` in `scene`'s air and aerodynamics
/// (its ground is replaced; the crater scale is the preset's), with leave-one-out errors.
///
/// # Errors
/// A row that does not fly.
pub fn calibrate_fairway(rows: &[ChartRow], scene: &Scene<f64>) -> Result<FairwayFit, String> {
    let kappa = preset_crater_scale()?;
    let rho = fit_rho(rows, scene, kappa)?;
    let fitted = roll_rows(rows, &on_fairway(scene, rho, kappa)?)?;
    let mut loo = Vec::with_capacity(rows.len());
    for i in 0..rows.len() {
        let others: Vec<ChartRow> = rows
            .iter()
            .enumerate()
            .filter(|(j, _)| *j != i)
            .map(|(_, r)| r.clone())
            .collect();
        let rho_i = fit_rho(&others, scene, kappa)?;
        let row = roll_rows(&rows[i..=i], &on_fairway(scene, rho_i, kappa)?)?;
        loo.push(row.first().map_or(f64::NAN, RollRow::roll_error_yd));
    }
    Ok(FairwayFit {
        rolling_resistance: rho,
        rows: fitted,
        leave_one_out_yd: loo,
    })
}
