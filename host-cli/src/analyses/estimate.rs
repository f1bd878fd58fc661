//! `carry estimate`: club data from ball data — the impact model run backwards (issue 23;
//! `carry_core::estimate`, docs/estimate.md).

use super::from_flight::FlightObsArgs;
use super::output;
use crate::args::{ClubArgs, LaunchArgs, OutputArgs, PrecisionArgs, SceneArgs, finite};
use carry_io::compute::{Numerics, PosteriorChoice};
use carry_io::error::Failure;
use carry_io::params::{Key, Params};
use carry_io::units::{Quantity, Units};
use carry_lab::request::{EstimateRecord, MeasuredClub};
use clap::Args;
use std::fmt::Write as _;

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

/// What `carry estimate` infers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum EstimateFrom {
    /// Club data from ball data: the impact run backwards (docs/estimate.md).
    #[default]
    Ball,
    /// The launch quantities not measured (spin, axis, …) from what the monitor saw of
    /// the flight: the flight run backwards (docs/launch_fit.md).
    Flight,
}

/// `carry estimate`.
#[derive(Debug, Clone, Args)]
pub struct EstimateCmd {
    /// `ball`: club data from ball data; `flight`: the launch (spin, axis, …) from the
    /// flight observations below.
    #[arg(long, value_enum, default_value = "ball")]
    pub from: EstimateFrom,
    #[command(flatten)]
    pub launch: LaunchArgs,
    #[command(flatten)]
    pub flight: FlightObsArgs,
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub measured: MeasuredArgs,
    #[command(flatten)]
    pub club: ClubArgs,
    #[command(flatten)]
    pub precision: PrecisionArgs,
    /// How the estimate summarises its posterior: `profile` (posterior mean, calibrated
    /// 1σ) or `laplace` (most probable delivery, Gauss–Newton 1σ: about half the cost,
    /// the 1σ of attack, spin loft and strike height too narrow). docs/estimate.md §1.
    #[arg(long, value_enum, default_value = "profile")]
    pub posterior: PosteriorChoice,
    #[command(flatten)]
    pub output: OutputArgs,
}

impl EstimateCmd {
    /// Runs the command; returns the text to print.
    ///
    /// # Errors
    /// Bad options or no estimate (status 2).
    pub fn run(&self) -> Result<String, Failure> {
        if self.from == EstimateFrom::Flight {
            return super::from_flight::run(
                &self.launch,
                &self.flight,
                &self.scene,
                &self.precision,
                &self.output,
            );
        }
        let u = self.output.units;
        let mut p = Params::default();
        self.club.apply(&mut p, u);
        self.launch.apply(&mut p, u);
        let n = Numerics {
            precision: self.precision.precision,
            posterior: self.posterior,
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

/// The club columns `carry batch estimate` reads besides the launch: (name, SI?, field).
const CLUB_COLUMNS: [(&str, bool, usize); 10] = [
    ("club_speed", false, 0),
    ("club_speed_mps", true, 0),
    ("attack_angle", false, 1),
    ("attack_angle_deg", true, 1),
    ("club_path", false, 2),
    ("club_path_deg", true, 2),
    ("face_angle", false, 3),
    ("face_angle_deg", true, 3),
    ("dynamic_loft", false, 4),
    ("dynamic_loft_deg", true, 4),
];

/// `carry batch estimate`: one estimate per input row, in parallel. Input columns: the
/// launch as in `carry batch flight` (option names in snake_case, or another batch's SI
/// output columns) plus any of the measured club columns (`club_speed`, `attack_angle`,
/// `club_path`, `face_angle`, `dynamic_loft`; or `*_mps`/`*_deg` in SI). Output: CSV
/// (`line`, `label` if given, [`EstimateRecord::COLUMNS`], `error`) or JSON lines.
///
/// # Errors
/// A bad file or header (status 2), failing to write (status 1).
pub fn batch(args: &crate::args::BatchArgs, cmd: &EstimateCmd) -> Result<(), Failure> {
    use carry_io::batch::Columns;
    use carry_io::compute::Mode;
    use carry_io::error::InputError;
    if cmd.from == EstimateFrom::Flight {
        return super::from_flight::batch(
            args,
            &cmd.launch,
            &cmd.flight,
            &cmd.scene,
            &cmd.precision,
            &cmd.output,
        );
    }
    let u = cmd.output.units;
    let mut base = Params::default();
    cmd.club.apply(&mut base, u);
    cmd.launch.apply(&mut base, u);
    let numerics = Numerics {
        precision: cmd.precision.precision,
        posterior: cmd.posterior,
        ..Numerics::default()
    };
    let m = &cmd.measured;
    let given = [
        m.club_speed.map(|v| u.to_si(Quantity::Speed, v)),
        m.attack_angle,
        m.club_path,
        m.face_angle,
        m.dynamic_loft,
    ];
    let (source, _) = carry_io::batch::open(&args.input)?;
    let name = args.input.display().to_string();
    let mut rdr = carry_io::batch::dialect().from_reader(source);
    let header = rdr
        .byte_headers()
        .map_err(|e| InputError::new("input", format!("{name}: cannot read the header: {e}")))?
        .clone();
    // split the header: club columns here, the rest (launch, ball, label) through io
    let mut club_cols: Vec<(usize, bool, usize)> = Vec::new();
    // a per-row club preset (`club`, as `carry batch impact` reads it), else `--club`
    let mut preset_col: Option<usize> = None;
    let mut launch_idx: Vec<usize> = Vec::new();
    let mut launch_header = csv::ByteRecord::new();
    for (i, raw) in header.iter().enumerate() {
        let n = String::from_utf8_lossy(raw);
        let n = n.trim().trim_start_matches('\u{feff}');
        if let Some((_, si, field)) = CLUB_COLUMNS.iter().find(|(c, _, _)| *c == n) {
            club_cols.push((i, *si, *field));
        } else if n == Key::Club.name() {
            if preset_col.replace(i).is_some() {
                return Err(InputError::new(
                    "input",
                    format!("{name}: line 1: column '{n}' appears twice"),
                )
                .into());
            }
        } else if carry_io::batch::is_output_column(n)
            && carry_io::params::Key::find(n).is_none()
            && !matches!(
                n,
                "ball_speed_mps"
                    | "launch_angle_deg"
                    | "launch_direction_deg"
                    | "backspin_rpm"
                    | "sidespin_rpm"
                    | "spin_rpm"
                    | "spin_axis_deg"
            )
        {
            // another command's result column that is not a launch input: ignored
        } else {
            launch_idx.push(i);
            launch_header.push_field(raw);
        }
    }
    let cols = Columns::from_header(&launch_header, Mode::Flight)?;
    let records: Vec<csv::ByteRecord> = rdr
        .byte_records()
        .collect::<Result<_, _>>()
        .map_err(|e| InputError::new("input", format!("{name}: {e}")))?;
    let row = |rec: &csv::ByteRecord| -> Result<(Params, MeasuredClub), InputError> {
        let mut sub = csv::ByteRecord::new();
        for &i in &launch_idx {
            sub.push_field(rec.get(i).unwrap_or_default());
        }
        let mut p = cols.apply(&sub, &base, u)?;
        if let Some(i) = preset_col {
            let text = String::from_utf8_lossy(rec.get(i).unwrap_or_default());
            let text = text.trim();
            if !text.is_empty() {
                Key::Club.set(&mut p, u, Key::Club.parse(text)?);
            }
        }
        let mut club = given;
        for &(i, si, field) in &club_cols {
            let text = String::from_utf8_lossy(rec.get(i).unwrap_or_default());
            let text = text.trim();
            if text.is_empty() {
                continue;
            }
            let v: f64 = carry_io::params::parse_finite(text)
                .map_err(|e| InputError::new("input", format!("club column {}: {e}", i + 1)))?;
            let v = if field == 0 && !si {
                u.to_si(Quantity::Speed, v)
            } else {
                v
            };
            if let Some(c) = club.get_mut(field) {
                *c = Some(v);
            }
        }
        let [
            club_speed_mps,
            attack_angle_deg,
            club_path_deg,
            face_angle_deg,
            dynamic_loft_deg,
        ] = club;
        Ok((
            p,
            MeasuredClub {
                club_speed_mps,
                attack_angle_deg,
                club_path_deg,
                face_angle_deg,
                dynamic_loft_deg,
            },
        ))
    };
    let inputs: Vec<_> = records.iter().map(row).collect();
    let results = carry_lab::request::estimate_rows(&inputs, &numerics, args.threads)?;
    let label_of = output::label_column(cols.label, &launch_idx);
    let out = output::batch_table(
        &records,
        &results,
        cols.label.is_some(),
        label_of,
        &EstimateRecord::COLUMNS,
        |r| r.values().iter().map(f64::to_string).collect(),
        cmd.output.json,
    );
    crate::write_stdout(out.as_bytes())
}
