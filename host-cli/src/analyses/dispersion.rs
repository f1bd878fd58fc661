//! `carry dispersion`: Monte-Carlo over delivery noise.

use super::{ShotArgs, output, write_svg};
use crate::args::OutputArgs;
use carry_io::error::Failure;
use carry_io::units::{Quantity, Units};
use carry_lab::dispersion::{self, Dispersion};
use carry_lab::request::{DispersionRequest, NoiseSd};
use clap::Args;
use std::fmt::Write as _;
use std::io::IsTerminal as _;
use std::path::PathBuf;

fn sd(s: &str) -> Result<f64, String> {
    carry_lab::request::parse_sd(s)
}

/// Delivery noise: standard deviations, named after the delivery options.
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Noise (standard deviations, default 0)")]
pub struct NoiseArgs {
    /// Face angle SD [deg].
    #[arg(long, value_name = "DEG", value_parser = sd, default_value_t = 0.0, allow_hyphen_values = true)]
    pub face_angle_sd: f64,
    /// Club path SD [deg].
    #[arg(long, value_name = "DEG", value_parser = sd, default_value_t = 0.0, allow_hyphen_values = true)]
    pub club_path_sd: f64,
    /// Attack angle SD [deg].
    #[arg(long, value_name = "DEG", value_parser = sd, default_value_t = 0.0, allow_hyphen_values = true)]
    pub attack_angle_sd: f64,
    /// Dynamic loft SD [deg].
    #[arg(long, value_name = "DEG", value_parser = sd, default_value_t = 0.0, allow_hyphen_values = true)]
    pub dynamic_loft_sd: f64,
    /// Club speed SD [m/s | mph].
    #[arg(long, value_name = "SPEED", value_parser = sd, default_value_t = 0.0, allow_hyphen_values = true)]
    pub club_speed_sd: f64,
    /// Impact height SD [m | in].
    #[arg(long, value_name = "LEN", value_parser = sd, default_value_t = 0.0, allow_hyphen_values = true)]
    pub impact_height_sd: f64,
    /// Impact toe SD [m | in].
    #[arg(long, value_name = "LEN", value_parser = sd, default_value_t = 0.0, allow_hyphen_values = true)]
    pub impact_toe_sd: f64,
}

impl NoiseArgs {
    /// The standard deviations, in the user's units.
    #[must_use]
    pub fn sd(&self) -> NoiseSd {
        NoiseSd {
            face_angle_sd: self.face_angle_sd,
            club_path_sd: self.club_path_sd,
            attack_angle_sd: self.attack_angle_sd,
            dynamic_loft_sd: self.dynamic_loft_sd,
            club_speed_sd: self.club_speed_sd,
            impact_height_sd: self.impact_height_sd,
            impact_toe_sd: self.impact_toe_sd,
        }
    }
}

/// Monte-Carlo size and seed.
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Monte-Carlo")]
pub struct MonteCarloArgs {
    /// Number of shots (dispersion: default 10000; optimize --objective dispersion: 500 per evaluation).
    #[arg(long, value_name = "N")]
    pub shots: Option<usize>,
    /// Seed of the noise (and of optimize's random starts): same seed, same shots.
    #[arg(long, value_name = "N", default_value_t = 1)]
    pub seed: u64,
}

/// `carry dispersion`.
#[derive(Debug, Clone, Args)]
pub struct DispersionCmd {
    #[command(flatten)]
    pub shot: ShotArgs,
    #[command(flatten)]
    pub noise: NoiseArgs,
    #[command(flatten)]
    pub monte_carlo: MonteCarloArgs,
    /// Write the landing points and the 95 % ellipse as an SVG scatter.
    #[arg(long, value_name = "FILE.svg", help_heading = "Output")]
    pub svg: Option<PathBuf>,
    /// Worker threads (default: all cores).
    #[arg(long, value_name = "N", help_heading = "Monte-Carlo")]
    pub threads: Option<usize>,
    /// Never show a progress bar.
    #[arg(long, help_heading = "Output")]
    pub no_progress: bool,
    #[command(flatten)]
    pub output: OutputArgs,
}

/// A progress bar shows on a terminal from this many shots.
const PROGRESS_SHOTS: usize = 50_000;

impl DispersionCmd {
    /// Runs the command; returns the text to print.
    ///
    /// # Errors
    /// Bad options (status 2), failing to write the SVG (status 1).
    pub fn run(&self) -> Result<String, Failure> {
        let (p, n) = self.shot.resolve(self.output.units)?;
        let request = DispersionRequest {
            units: self.output.units,
            noise: self.noise.sd(),
            shots: self.monte_carlo.shots,
            seed: self.monte_carlo.seed,
            threads: self.threads,
        };
        let shots = request.shots();
        let bar = (!self.no_progress && shots >= PROGRESS_SHOTS && std::io::stderr().is_terminal())
            .then(|| {
                let bar = indicatif::ProgressBar::new(shots as u64);
                bar.set_style(
                    indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} shots eta {eta}")
                        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
                );
                bar
            });
        let tick = |n: usize| {
            if let Some(b) = &bar {
                b.inc(n as u64);
            }
        };
        let d = request.run(&p, &n, Some(&tick));
        if let Some(b) = bar {
            b.finish_and_clear();
        }
        let d = d?;
        if let Some(path) = &self.svg {
            write_svg(path, &d, dispersion::draw)?;
        }
        if self.output.json {
            output::json(&d)
        } else if self.output.csv {
            output::csv(&[&d])
        } else {
            Ok(table(&d, self.output.units))
        }
    }
}

fn table(d: &Dispersion, u: Units) -> String {
    let mut s = String::new();
    let l = |x: f64| u.to_display(Quantity::Long, x);
    let (_, lu) = u.display(Quantity::Long, 1.0);
    let _ = writeln!(
        s,
        "{} shots ({} failed), seed {}",
        d.shots, d.failed_shots, d.seed
    );
    let _ = writeln!(
        s,
        "{:<8} {:>9} {:>8} {:>9} {:>9} {:>9} {:>9} {:>9}",
        format!("[{lu}]"),
        "mean",
        "sd",
        "p5",
        "p25",
        "median",
        "p75",
        "p95"
    );
    for (name, mean, sd, p) in [
        (
            "carry",
            d.carry_mean_m,
            d.carry_sd_m,
            &d.carry_percentiles_m,
        ),
        ("side", d.side_mean_m, d.side_sd_m, &d.side_percentiles_m),
    ] {
        let _ = writeln!(
            s,
            "{name:<8} {:>9.2} {:>8.2} {:>9.2} {:>9.2} {:>9.2} {:>9.2} {:>9.2}",
            l(mean),
            l(sd),
            l(p.p5),
            l(p.p25),
            l(p.p50),
            l(p.p75),
            l(p.p95)
        );
    }
    let c = d.covariance_m2;
    let _ = writeln!(
        s,
        "landing covariance [m²]: XX {:.3}, XZ {:.3}, ZZ {:.3}",
        c[0][0], c[0][1], c[1][1]
    );
    let e = &d.ellipse_95;
    let _ = writeln!(
        s,
        "95 % ellipse: semi-axes {:.2} × {:.2} {lu}, major axis {:.1}° from the target line",
        l(e.semi_major_m),
        l(e.semi_minor_m),
        e.angle_deg
    );
    s
}
