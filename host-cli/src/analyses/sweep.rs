//! `carry sweep`: a swing file against a range of ball positions.

use super::{ShotArgs, output, parse_triple, print_notes, write_svg};
use crate::args::OutputArgs;
use carry_io::error::Failure;
use carry_io::units::{Quantity, Units};
use carry_lab::request::SweepRequest;
use carry_lab::sweep::{self, Sweep};
use clap::Args;
use std::fmt::Write as _;
use std::path::PathBuf;

fn triple(s: &str) -> Result<[f64; 3], String> {
    parse_triple(s)
}

/// `carry sweep`.
#[derive(Debug, Clone, Args)]
pub struct SweepCmd {
    /// The club-head motion through impact (CSV: t_s, x_m, y_m, z_m, then qw,qx,qy,qz or
    /// face_angle_deg,dynamic_loft_deg,lie_deg; optionally vx_mps,vy_mps,vz_mps and
    /// wx_radps,wy_radps,wz_radps, else derived by central differences). Always SI.
    /// Default: the shipped example, lab/data/swing_driver.csv.
    #[arg(long, value_name = "FILE.csv", conflicts_with = "generate")]
    pub swing: Option<PathBuf>,
    /// Ball positions along the target line [m | in], + towards the target (default -0.1,0.1,0.01 m).
    #[arg(long, value_name = "FROM,TO,STEP", value_parser = triple, allow_hyphen_values = true)]
    pub ball_positions: Option<[f64; 3]>,
    /// Write carry and side against ball position as an SVG.
    #[arg(long, value_name = "FILE.svg")]
    pub svg: Option<PathBuf>,
    /// Write the example swing (the double-pendulum model) to this file and stop.
    #[arg(long, value_name = "FILE.csv")]
    pub generate: Option<PathBuf>,
    #[command(flatten)]
    pub shot: ShotArgs,
    #[command(flatten)]
    pub output: OutputArgs,
}

impl SweepCmd {
    /// Runs the command; returns the text to print.
    ///
    /// # Errors
    /// Bad options or swing file (status 2), failing to write a file (status 1).
    pub fn run(&self) -> Result<String, Failure> {
        let u = self.output.units;
        let (p, n) = self.shot.resolve(u)?;
        if let Some(path) = &self.generate {
            SweepRequest::generate(&p, &n, path)?;
            return Ok(format!("wrote {}\n", path.display()));
        }
        let request = SweepRequest {
            units: u,
            swing: self.swing.clone(),
            ball_positions: self.ball_positions,
        };
        let mut notes = Vec::new();
        let result = request.run(&p, &n, &mut notes);
        print_notes(&notes);
        let result = result?;
        if let Some(path) = &self.svg {
            write_svg(path, &result, sweep::draw)?;
        }
        if self.output.json {
            output::json(&result)
        } else if self.output.csv {
            output::csv(&result.rows)
        } else {
            Ok(table(&result, u))
        }
    }
}

fn table(r: &Sweep, u: Units) -> String {
    let mut s = String::new();
    let (_, pu) = u.display(Quantity::Offset, 1.0);
    let (_, lu) = u.display(Quantity::Long, 1.0);
    let (_, su) = u.display(Quantity::Speed, 1.0);
    let _ = writeln!(
        s,
        "{:>9} {:>8} {:>7} {:>6} {:>6} {:>6} {:>8} {:>7} {:>7} {:>7} {:>8} {:>7}",
        format!("ball {pu}"),
        format!("club {su}"),
        "attack",
        "path",
        "face",
        "loft",
        format!("ball {su}"),
        "launch",
        "dir",
        "spin",
        format!("carry {lu}"),
        "side"
    );
    for (i, row) in r.rows.iter().enumerate() {
        let (pos, _) = u.display(Quantity::Offset, row.ball_position_m);
        let c = &row.club;
        let _ = write!(
            s,
            "{pos:>9.1} {:>8.1} {:>7.2} {:>6.2} {:>6.2} {:>6.2}",
            u.to_display(Quantity::Speed, c.club_speed_mps),
            c.attack_angle_deg,
            c.club_path_deg,
            c.face_angle_deg,
            c.dynamic_loft_deg
        );
        match (&row.shot, &row.error) {
            (Some(shot), _) => {
                let _ = write!(
                    s,
                    " {:>8.1} {:>7.2} {:>7.2} {:>7.0} {:>8.1} {:>7.1}",
                    u.to_display(Quantity::Speed, shot.launch.ball_speed_mps),
                    shot.launch.launch_angle_deg,
                    shot.launch.launch_direction_deg,
                    shot.launch.spin_rpm,
                    u.to_display(Quantity::Long, shot.carry_m),
                    u.to_display(Quantity::Long, shot.side_m)
                );
            }
            (None, e) => {
                let _ = write!(s, "  {}", e.as_deref().unwrap_or("failed"));
            }
        }
        s.push_str(if r.best == Some(i) {
            "  ← best\n"
        } else {
            "\n"
        });
    }
    s
}
