//! `carry optimize`: the delivery that maximises carry within bounds, or the optimizer chart.

use super::dispersion::{MonteCarloArgs, NoiseArgs};
use super::{ShotArgs, failure, output, parse_pair, parse_triple, with_setup, write_svg};
use crate::cli::OutputArgs;
use crate::compute::IntegratorChoice;
use crate::error::{Failure, InputError};
use crate::units::{Quantity, Units};
use carry_core::Real;
use carry_lab::optimize::{self, Chart, ChartOptions, Objective, Optimum, Options, Range};
use carry_lab::{Input, Setup};
use clap::{Args, ValueEnum};
use std::fmt::Write as _;
use std::path::PathBuf;

fn pair(s: &str) -> Result<[f64; 2], String> {
    parse_pair(s)
}
fn triple(s: &str) -> Result<[f64; 3], String> {
    parse_triple(s)
}

/// What to optimise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, ValueEnum)]
pub enum ObjectiveChoice {
    /// Maximise carry.
    #[default]
    Carry,
    /// Maximise total distance (carry + bounce and roll; needs --ground).
    Total,
    /// Minimise the side spread under the -sd noise options.
    Dispersion,
}

/// The search options.
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Search")]
pub struct SearchArgs {
    /// Dynamic loft bounds [deg] (default: static loft −8 to +12).
    #[arg(long, value_name = "LO,HI", value_parser = pair, allow_hyphen_values = true)]
    pub dynamic_loft_range: Option<[f64; 2]>,
    /// Attack angle bounds [deg] (default −5,5).
    #[arg(long, value_name = "LO,HI", value_parser = pair, allow_hyphen_values = true)]
    pub attack_angle_range: Option<[f64; 2]>,
    /// Also optimise the impact height within these bounds [m | in] (default: fixed at --impact-height).
    #[arg(long, value_name = "LO,HI", value_parser = pair, allow_hyphen_values = true)]
    pub impact_height_range: Option<[f64; 2]>,
    /// The objective.
    #[arg(long, value_enum, default_value_t = ObjectiveChoice::Carry)]
    pub objective: ObjectiveChoice,
    /// Number of starts: the centre of the bounds, then random points (seeded by --seed).
    #[arg(long, value_name = "N", default_value_t = 1)]
    pub starts: usize,
    /// Print the optimizer chart instead: club speed × attack angle → best dynamic loft.
    #[arg(long)]
    pub chart: bool,
    /// Chart club speeds [m/s | mph] (default 35,55,5 m/s).
    #[arg(long, value_name = "FROM,TO,STEP", value_parser = triple, requires = "chart")]
    pub club_speeds: Option<[f64; 3]>,
    /// Chart attack angles [deg] (default -4,4,2).
    #[arg(long, value_name = "FROM,TO,STEP", value_parser = triple, allow_hyphen_values = true, requires = "chart")]
    pub attack_angles: Option<[f64; 3]>,
    /// Write the chart as an SVG heat map.
    #[arg(long, value_name = "FILE.svg", requires = "chart")]
    pub svg: Option<PathBuf>,
}

/// `carry optimize`.
#[derive(Debug, Clone, Args)]
pub struct OptimizeCmd {
    #[command(flatten)]
    pub shot: ShotArgs,
    #[command(flatten)]
    pub search: SearchArgs,
    #[command(flatten)]
    pub noise: NoiseArgs,
    #[command(flatten)]
    pub monte_carlo: MonteCarloArgs,
    #[command(flatten)]
    pub output: OutputArgs,
}

/// Shots per objective evaluation for `--objective dispersion` unless `--shots` says.
const DISPERSION_OBJECTIVE_SHOTS: usize = 500;

fn grid(
    values: [f64; 3],
    key: &'static str,
    si: impl Fn(f64) -> f64,
) -> Result<Vec<f64>, InputError> {
    let [from, to, step] = values;
    carry_lab::sweep::positions(from, to, step)
        .map(|v| v.into_iter().map(si).collect())
        .map_err(|_| InputError::new(key, "give from,to,step with from ≤ to and a positive step"))
}

impl OptimizeCmd {
    fn options<T: Real>(&self, setup: &Setup<T>) -> Result<Options, Failure> {
        let u = self.output.units;
        let s = &self.search;
        let loft = carry_core::real::to_f64(carry_core::units::to_deg(setup.club.loft_rad()));
        let [a, b] = s
            .dynamic_loft_range
            .unwrap_or([(loft - 8.0).max(0.0), loft + 12.0]);
        let loft_range =
            Range::new(a, b, Input::DynamicLoftRange).map_err(|e| failure(e, "starts"))?;
        let [a, b] = s.attack_angle_range.unwrap_or([-5.0, 5.0]);
        let attack_range =
            Range::new(a, b, Input::AttackAngleRange).map_err(|e| failure(e, "starts"))?;
        let height = s
            .impact_height_range
            .map(|[a, b]| {
                Range::new(
                    u.to_si(Quantity::Offset, a),
                    u.to_si(Quantity::Offset, b),
                    Input::ImpactHeightRange,
                )
            })
            .transpose()
            .map_err(|e| failure(e, "starts"))?;
        let objective = match s.objective {
            ObjectiveChoice::Carry => Objective::Carry,
            ObjectiveChoice::Total => Objective::Total,
            ObjectiveChoice::Dispersion => Objective::Dispersion {
                noise: self.noise.noise(u),
                shots: self.monte_carlo.shots.unwrap_or(DISPERSION_OBJECTIVE_SHOTS),
                seed: self.monte_carlo.seed,
            },
        };
        Ok(Options {
            dynamic_loft_deg: loft_range,
            attack_angle_deg: attack_range,
            impact_height_m: height,
            objective,
            starts: s.starts,
            seed: self.monte_carlo.seed,
            max_iterations: 400,
        })
    }

    fn run_in<T: Real>(&self, setup: Setup<T>, smooth: bool) -> Result<String, Failure> {
        let setup = if smooth { setup.smooth() } else { setup };
        let options = self.options(&setup)?;
        let u = self.output.units;
        if self.search.chart {
            let speeds = grid(
                self.search.club_speeds.unwrap_or([35.0, 55.0, 5.0]),
                "club_speeds",
                |v| {
                    if self.search.club_speeds.is_some() {
                        u.to_si(Quantity::Speed, v)
                    } else {
                        v
                    }
                },
            )?;
            let attacks = grid(
                self.search.attack_angles.unwrap_or([-4.0, 4.0, 2.0]),
                "attack_angles",
                |a| a,
            )?;
            let chart = optimize::chart(
                &setup,
                &ChartOptions {
                    club_speeds_mps: speeds,
                    attack_angles_deg: attacks,
                    dynamic_loft_deg: options.dynamic_loft_deg,
                },
            )
            .map_err(|e| failure(e, "starts"))?;
            if let Some(path) = &self.search.svg {
                write_svg(path, &chart, optimize::draw_chart)?;
            }
            return if self.output.json {
                output::json(&chart)
            } else if self.output.csv {
                output::csv(&chart.cells)
            } else {
                Ok(chart_table(&chart, u))
            };
        }
        let best = optimize::optimize(&setup, &options).map_err(|e| failure(e, "starts"))?;
        if self.output.json {
            output::json(&best)
        } else if self.output.csv {
            output::csv(&[Flat::of(&best)])
        } else {
            Ok(table(&best, u))
        }
    }

    /// Runs the command; returns the text to print.
    ///
    /// # Errors
    /// Bad options (status 2), failing to write the SVG (status 1).
    pub fn run(&self) -> Result<String, Failure> {
        let (p, n) = self.shot.resolve(self.output.units)?;
        // A smooth objective unless the user chose the numerics.
        let smooth = n.integrator == IntegratorChoice::Dp45 && n.tolerance.is_none();
        with_setup(
            &p,
            &n,
            |s| self.run_in(s, smooth),
            |s| self.run_in(s, smooth),
        )
    }
}

/// The optimum as one CSV row: the point, the objective, the shot, the cost.
#[derive(serde::Serialize)]
struct Flat<'a> {
    objective: &'a str,
    #[serde(flatten)]
    point: optimize::Point,
    objective_value: f64,
    #[serde(flatten)]
    shot: carry_lab::ShotSummary,
    evaluations: u64,
    elapsed_s: f64,
}

impl<'a> Flat<'a> {
    fn of(o: &'a Optimum) -> Self {
        Self {
            objective: o.objective,
            point: o.point,
            objective_value: o.objective_value,
            shot: o.shot,
            evaluations: o.evaluations,
            elapsed_s: o.elapsed_s,
        }
    }
}

fn table(o: &Optimum, u: Units) -> String {
    let mut s = String::new();
    let (carry, cu) = u.display(Quantity::Long, o.shot.carry_m);
    let (side, _) = u.display(Quantity::Long, o.shot.side_m);
    let (height, hu) = u.display(Quantity::Offset, o.point.impact_height_m);
    let (speed, su) = u.display(Quantity::Speed, o.shot.launch.ball_speed_mps);
    let _ = writeln!(s, "optimum ({})", o.objective);
    let _ = writeln!(
        s,
        "  dynamic loft      {:8.2} deg",
        o.point.dynamic_loft_deg
    );
    let _ = writeln!(
        s,
        "  attack angle      {:8.2} deg",
        o.point.attack_angle_deg
    );
    let _ = writeln!(s, "  impact height     {height:8.2} {hu}");
    let _ = writeln!(s, "launch");
    let _ = writeln!(s, "  ball speed        {speed:8.2} {su}");
    let _ = writeln!(
        s,
        "  launch angle      {:8.2} deg",
        o.shot.launch.launch_angle_deg
    );
    let _ = writeln!(s, "  spin              {:8.0} rpm", o.shot.launch.spin_rpm);
    let _ = writeln!(s, "  carry             {carry:8.2} {cu}");
    let _ = writeln!(s, "  side              {side:8.2} {cu}");
    if o.objective == "dispersion" {
        let (v, vu) = u.display(Quantity::Long, o.objective_value);
        let _ = writeln!(s, "  side spread (SD)  {v:8.3} {vu}");
    }
    let _ = writeln!(s, "flatness (objective lost, {cu})");
    for f in &o.flatness {
        let step = if f.variable == "impact_height_m" {
            let (h, hu) = u.display(Quantity::Offset, f.step);
            format!("±{h:.0} {hu}")
        } else {
            format!("±{:.0}°", f.step)
        };
        let loss = |x: Option<f64>| {
            x.map_or_else(
                || "fails".to_owned(),
                |v| format!("{:.3}", u.to_display(Quantity::Long, v)),
            )
        };
        let _ = writeln!(
            s,
            "  {:<18} {step:>6}: {} / {}",
            f.variable,
            loss(f.loss_minus_m),
            loss(f.loss_plus_m)
        );
    }
    let _ = writeln!(
        s,
        "search: {} start(s), {} evaluations, {:.3} s",
        o.starts.len(),
        o.evaluations,
        o.elapsed_s
    );
    s
}

fn chart_table(c: &Chart, u: Units) -> String {
    let mut s = String::new();
    let (_, su) = u.display(Quantity::Speed, 1.0);
    let (_, cu) = u.display(Quantity::Long, 1.0);
    let _ = writeln!(
        s,
        "{:>11} {:>8} {:>9} {:>10} {:>8} {:>7} {:>8}",
        format!("club {su}"),
        "attack",
        "dyn loft",
        format!("ball {su}"),
        "launch",
        "spin",
        format!("carry {cu}")
    );
    for cell in &c.cells {
        let _ = writeln!(
            s,
            "{:>11.1} {:>8.1} {:>9.1} {:>10.1} {:>8.1} {:>7.0} {:>8.1}",
            u.to_display(Quantity::Speed, cell.club_speed_mps),
            cell.attack_angle_deg,
            cell.dynamic_loft_deg,
            u.to_display(Quantity::Speed, cell.shot.launch.ball_speed_mps),
            cell.shot.launch.launch_angle_deg,
            cell.shot.launch.spin_rpm,
            u.to_display(Quantity::Long, cell.shot.carry_m)
        );
    }
    s
}
