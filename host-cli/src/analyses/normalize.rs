//! `carry normalize`: a launch's carry in standard conditions, and back.

use super::output;
use crate::args::{BallArgs, IntegratorArgs, LaunchArgs, OutputArgs, PrecisionArgs, SceneArgs};
use carry_io::error::Failure;
use carry_io::params::Params;
use carry_io::units::{Quantity, Units};
use carry_lab::normalize::{self, Direction, Normalized};
use clap::{Args, ValueEnum};
use std::fmt::Write as _;

/// Which way to normalise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, ValueEnum)]
pub enum To {
    /// From the given conditions to standard ones.
    #[default]
    Standard,
    /// From standard conditions to the given ones.
    Conditions,
}

/// `carry normalize`.
#[derive(Debug, Clone, Args)]
pub struct NormalizeCmd {
    /// Direction: `standard` flies the launch as measured in the given conditions and in
    /// standard ones (sea level, 21 °C, 50 % RH, no wind); `conditions` the reverse.
    #[arg(long, value_enum, default_value_t = To::Standard)]
    pub to: To,
    #[command(flatten)]
    pub launch: LaunchArgs,
    #[command(flatten)]
    pub ball: BallArgs,
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub precision: PrecisionArgs,
    #[command(flatten)]
    pub integrator: IntegratorArgs,
    #[command(flatten)]
    pub output: OutputArgs,
}

impl NormalizeCmd {
    /// Runs the command; returns the text to print.
    ///
    /// # Errors
    /// Bad options (status 2).
    pub fn run(&self) -> Result<String, Failure> {
        let u = self.output.units;
        let mut p = Params::default();
        self.ball.apply(&mut p, u);
        self.launch.apply(&mut p, u);
        self.scene.apply(&mut p, u)?;
        let n = crate::args::numerics(&self.precision, None, Some(&self.integrator))?;
        let to = match self.to {
            To::Standard => carry_lab::request::To::Standard,
            To::Conditions => carry_lab::request::To::Conditions,
        };
        let r = carry_lab::request::normalize(&p, &n, to)?;
        if self.output.json {
            output::json(&r)
        } else if self.output.csv {
            output::csv(&[r])
        } else {
            Ok(table(&r, u))
        }
    }
}

/// A table line: label, value, quantity, unit.
type Line = (
    &'static str,
    fn(&normalize::Landing) -> f64,
    Quantity,
    &'static str,
);

fn table(r: &Normalized, u: Units) -> String {
    let mut s = String::new();
    let (_, lu) = u.display(Quantity::Long, 1.0);
    let (_, hu) = u.display(Quantity::Height, 1.0);
    let (from, to) = match r.direction {
        Direction::ToStandard => ("conditions", "standard"),
        Direction::ToConditions => ("standard", "conditions"),
    };
    let _ = writeln!(s, "{:<12} {:>12} {:>12}", "", from, to);
    let rows: [Line; 5] = [
        ("air kg/m³", |l| l.air_density_kgm3, Quantity::Plain, ""),
        ("carry", |l| l.carry_m, Quantity::Long, lu),
        ("side", |l| l.side_m, Quantity::Long, lu),
        ("apex", |l| l.apex_m, Quantity::Height, hu),
        ("flight s", |l| l.flight_time_s, Quantity::Plain, ""),
    ];
    for (name, f, q, unit) in rows {
        let label = if unit.is_empty() {
            name.to_owned()
        } else {
            format!("{name} {unit}")
        };
        let _ = writeln!(
            s,
            "{label:<12} {:>12.3} {:>12.3}",
            u.to_display(q, f(&r.from)),
            u.to_display(q, f(&r.to))
        );
    }
    let _ = writeln!(
        s,
        "normalised carry {:.2} {lu} ({:+.2} {lu})",
        u.to_display(Quantity::Long, r.carry_m),
        u.to_display(Quantity::Long, r.carry_change_m)
    );
    s
}
