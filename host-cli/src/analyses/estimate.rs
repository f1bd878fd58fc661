//! `carry estimate`: club data from ball data — the impact model run backwards (issue 23;
//! `carry_core::estimate`, docs/estimate.md).

use super::output;
use crate::cli::{ClubArgs, LaunchArgs, OutputArgs, PrecisionArgs};
use carry_io::compute::Numerics;
use carry_io::error::Failure;
use carry_io::params::Params;
use carry_io::units::{Quantity, Units};
use carry_lab::request::{EstimateRecord, MeasuredClub};
use clap::Args;
use std::fmt::Write as _;

fn finite(s: &str) -> Result<f64, String> {
    carry_io::params::parse_finite(s)
}

/// What the launch monitor measured of the club (each optional).
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Measured club data (optional)")]
pub struct MeasuredArgs {
    /// Measured club head speed [m/s | mph].
    #[arg(long, value_name = "SPEED", value_parser = finite, allow_hyphen_values = true)]
    pub club_speed: Option<f64>,
    /// Measured attack angle [deg, + up].
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub attack_angle: Option<f64>,
    /// Measured club path [deg, + in-to-out].
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub club_path: Option<f64>,
    /// Measured face angle at the contact point [deg, + open].
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub face_angle: Option<f64>,
    /// Measured dynamic loft at the contact point [deg].
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub dynamic_loft: Option<f64>,
}

/// `carry estimate`.
#[derive(Debug, Clone, Args)]
pub struct EstimateCmd {
    #[command(flatten)]
    pub launch: LaunchArgs,
    #[command(flatten)]
    pub measured: MeasuredArgs,
    #[command(flatten)]
    pub club: ClubArgs,
    #[command(flatten)]
    pub precision: PrecisionArgs,
    #[command(flatten)]
    pub output: OutputArgs,
}

impl EstimateCmd {
    /// Runs the command; returns the text to print.
    ///
    /// # Errors
    /// Bad options or no estimate (status 2).
    pub fn run(&self) -> Result<String, Failure> {
        let u = self.output.units;
        let mut p = Params::default();
        self.club.apply(&mut p, u);
        self.launch.apply(&mut p, u);
        let n = Numerics {
            precision: self.precision.precision,
            ..Numerics::default()
        };
        let m = &self.measured;
        let club = MeasuredClub {
            club_speed_mps: m.club_speed.map(|v| u.to_si(Quantity::Speed, v)),
            attack_angle_deg: m.attack_angle,
            club_path_deg: m.club_path,
            face_angle_deg: m.face_angle,
            dynamic_loft_deg: m.dynamic_loft,
        };
        let r = carry_lab::request::estimate(&p, &n, &club)?;
        if self.output.json {
            output::json(&r)
        } else if self.output.csv {
            output::csv(&[r])
        } else {
            Ok(table(&r, u, p.club.preset.name))
        }
    }
}

fn table(r: &EstimateRecord, u: Units, club: &str) -> String {
    let mut s = String::new();
    let (_, su) = u.display(Quantity::Speed, 1.0);
    let _ = writeln!(
        s,
        "club data from ball data ({club}, TrackMan's convention)"
    );
    let _ = writeln!(s, "{:<16} {:>10} {:>10}", "", "estimate", "± 1σ");
    let deg = [
        ("face angle °", r.face_angle_deg, r.face_angle_deg_sd),
        ("club path °", r.club_path_deg, r.club_path_deg_sd),
        ("face to path °", r.face_to_path_deg, r.face_to_path_deg_sd),
        ("dynamic loft °", r.dynamic_loft_deg, r.dynamic_loft_deg_sd),
        ("attack angle °", r.attack_angle_deg, r.attack_angle_deg_sd),
        ("spin loft °", r.spin_loft_deg, r.spin_loft_deg_sd),
    ];
    for (name, v, sd) in deg {
        let _ = writeln!(s, "{name:<16} {v:>10.2} {sd:>10.2}");
    }
    let mm = [
        ("toe mm", r.impact_toe_m, r.impact_toe_m_sd),
        ("height mm", r.impact_height_m, r.impact_height_m_sd),
    ];
    for (name, v, sd) in mm {
        let _ = writeln!(s, "{name:<16} {:>10.1} {:>10.1}", 1e3 * v, 1e3 * sd);
    }
    let speed = format!("club speed {su}");
    let _ = writeln!(
        s,
        "{speed:<16} {:>10.2} {:>10.2}{}",
        u.to_display(Quantity::Speed, r.club_speed_mps),
        u.to_display(Quantity::Speed, r.club_speed_mps_sd),
        if r.club_speed_estimated {
            ""
        } else {
            "  (measured, refined)"
        }
    );
    let _ = writeln!(
        s,
        "{:<16} {:>10.3} {:>10.3}",
        "smash", r.smash_factor, r.smash_factor_sd
    );
    let _ = writeln!(
        s,
        "residuals: ball speed {:+.3} m/s, launch {:+.3}°, direction {:+.3}°, spin {:+.1} rpm, axis {:+.2}°; {} iterations",
        r.residual_ball_speed_mps,
        r.residual_launch_angle_deg,
        r.residual_launch_direction_deg,
        r.residual_spin_rpm,
        r.residual_spin_axis_deg,
        r.iterations
    );
    s
}
