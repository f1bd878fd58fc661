//! `carry optimize`: the delivery that maximises carry within bounds, or the optimizer chart.

use super::dispersion::{MonteCarloArgs, NoiseArgs};
use super::{ShotArgs, output, parse_pair, parse_triple, print_notes, write_svg};
use crate::args::OutputArgs;
use carry_io::error::Failure;
use carry_io::units::{Quantity, Units};
use carry_lab::optimize::{self, Chart, Optimum};
use carry_lab::request::{self, ChartGrid, OptimizeOutcome, OptimizeRequest};
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

impl OptimizeCmd {
    /// The typed request of these options.
    #[must_use]
    pub fn request(&self) -> OptimizeRequest {
        let s = &self.search;
        OptimizeRequest {
            units: self.output.units,
            dynamic_loft_range: s.dynamic_loft_range,
            attack_angle_range: s.attack_angle_range,
            impact_height_range: s.impact_height_range,
            objective: match s.objective {
                ObjectiveChoice::Carry => request::ObjectiveChoice::Carry,
                ObjectiveChoice::Total => request::ObjectiveChoice::Total,
                ObjectiveChoice::Dispersion => request::ObjectiveChoice::Dispersion,
            },
            starts: s.starts,
            chart: s.chart.then_some(ChartGrid {
                club_speeds: s.club_speeds,
                attack_angles: s.attack_angles,
            }),
            noise: self.noise.sd(),
            shots: self.monte_carlo.shots,
            seed: self.monte_carlo.seed,
        }
    }

    /// Runs the command; returns the text to print.
    ///
    /// # Errors
    /// Bad options (status 2), failing to write the SVG (status 1).
    pub fn run(&self) -> Result<String, Failure> {
        let u = self.output.units;
        let (p, n) = self.shot.resolve(u)?;
        let mut notes = Vec::new();
        let outcome = self.request().run(&p, &n, &mut notes);
        print_notes(&notes);
        match outcome? {
            OptimizeOutcome::Chart(chart) => {
                if let Some(path) = &self.search.svg {
                    write_svg(path, &chart, optimize::draw_chart)?;
                }
                if self.output.json {
                    output::json(&chart)
                } else if self.output.csv {
                    output::csv(&chart.cells)
                } else {
                    Ok(chart_table(&chart, u))
                }
            }
            OptimizeOutcome::Optimum(best) => {
                if self.output.json {
                    output::json(&best)
                } else if self.output.csv {
                    output::csv(&[Flat::of(&best)])
                } else {
                    Ok(table(&best, u))
                }
            }
        }
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
    if let Some(g) = &o.shot.ground {
        let (roll, _) = u.display(Quantity::Long, g.roll_m);
        let (total, _) = u.display(Quantity::Long, g.total_m);
        let _ = writeln!(s, "  roll              {roll:8.2} {cu}");
        let _ = writeln!(s, "  total             {total:8.2} {cu}");
    }
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
    // Total and roll columns only with a ground in the scene.
    let ground = c.cells.iter().any(|cell| cell.shot.ground.is_some());
    let _ = write!(
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
    if ground {
        let _ = write!(
            s,
            " {:>8} {:>8}",
            format!("roll {cu}"),
            format!("total {cu}")
        );
    }
    s.push('\n');
    for cell in &c.cells {
        let _ = write!(
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
        if let Some(g) = &cell.shot.ground {
            let _ = write!(
                s,
                " {:>8.1} {:>8.1}",
                u.to_display(Quantity::Long, g.roll_m),
                u.to_display(Quantity::Long, g.total_m)
            );
        }
        s.push('\n');
    }
    s
}
