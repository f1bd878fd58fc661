//! `carry estimate --from flight`: the launch from what a monitor saw of the flight
//! (issue 36; `carry_lab::launch_fit`, `carry_core::launch_fit`, docs/launch_fit.md).
//! The measured launch comes from the launch options (`--ball-speed`, `--launch-angle`,
//! `--launch-direction`, `--spin`, `--spin-axis`; what is not given is fitted), the
//! observations from the options below and `--track FILE.csv`.

use super::output;
use crate::args::{LaunchArgs, OutputArgs, PrecisionArgs, SceneArgs, finite};
use carry_io::compute::Numerics;
use carry_io::error::{Failure, InputError};
use carry_io::params::Params;
use carry_io::units::{Quantity, Units};
use carry_lab::launch_fit::{
    self as lf, DOPPLER_SD_MPS, FlightRecord, FlightRequest, LAUNCH_SD, SUMMARY_SD, TRACK_SD_M,
};
use clap::Args;
use std::fmt::Write as _;
use std::path::PathBuf;

fn vec3(s: &str) -> Result<[f64; 3], String> {
    let v: Vec<f64> = s.split(',').map(finite).collect::<Result<_, _>>()?;
    <[f64; 3]>::try_from(v).map_err(|_| "expected x,y,z".to_owned())
}

/// What the monitor saw of the flight (each optional, with its 1σ), for `--from flight`.
#[derive(Debug, Clone, Args, Default)]
#[command(next_help_heading = "Flight observations (with --from flight)")]
pub struct FlightObsArgs {
    /// Apex height [m | ft].
    #[arg(long, value_name = "H", value_parser = finite, allow_hyphen_values = true)]
    pub apex_height: Option<f64>,
    /// 1σ of --apex-height [m | ft] (default 0.5 m).
    #[arg(long, value_name = "H", value_parser = finite, allow_hyphen_values = true)]
    pub apex_height_sd: Option<f64>,
    /// Time of the apex [s].
    #[arg(long, value_name = "S", value_parser = finite, allow_hyphen_values = true)]
    pub apex_time: Option<f64>,
    /// 1σ of --apex-time [s] (default 0.1).
    #[arg(long, value_name = "S", value_parser = finite, allow_hyphen_values = true)]
    pub apex_time_sd: Option<f64>,
    /// Carry: horizontal distance to the landing [m | yd].
    #[arg(long, value_name = "D", value_parser = finite, allow_hyphen_values = true)]
    pub carry: Option<f64>,
    /// 1σ of --carry [m | yd] (default 1 m).
    #[arg(long, value_name = "D", value_parser = finite, allow_hyphen_values = true)]
    pub carry_sd: Option<f64>,
    /// Side at the landing [m | yd, + right].
    #[arg(long, value_name = "D", value_parser = finite, allow_hyphen_values = true)]
    pub side: Option<f64>,
    /// 1σ of --side [m | yd] (default 0.5 m).
    #[arg(long, value_name = "D", value_parser = finite, allow_hyphen_values = true)]
    pub side_sd: Option<f64>,
    /// Flight time [s].
    #[arg(long, value_name = "S", value_parser = finite, allow_hyphen_values = true)]
    pub flight_time: Option<f64>,
    /// 1σ of --flight-time [s] (default 0.05).
    #[arg(long, value_name = "S", value_parser = finite, allow_hyphen_values = true)]
    pub flight_time_sd: Option<f64>,
    /// Landing angle below the horizontal [deg].
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub land_angle: Option<f64>,
    /// 1σ of --land-angle [deg] (default 0.5).
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub land_angle_sd: Option<f64>,
    /// A track: CSV with header `t,x,y,z` (s; m in the shot's frame: x downrange, y up,
    /// z right, the tee at the origin) or `t,radial_speed` (s; m/s away from the radar at
    /// --radar-position). At most 64 positions or 256 radial speeds. Always SI.
    #[arg(long, value_name = "FILE.csv")]
    pub track: Option<PathBuf>,
    /// 1σ of each track value [m for positions, m/s for radial speeds] (default 0.1).
    #[arg(long, value_name = "SD", value_parser = finite, allow_hyphen_values = true)]
    pub track_sd: Option<f64>,
    /// The radar's position for radial speeds [m, G] (default -2.5,0.3,0: behind the tee).
    #[arg(long, value_name = "X,Y,Z", value_parser = vec3, allow_hyphen_values = true)]
    pub radar_position: Option<[f64; 3]>,
    /// 1σ of the measured launch: ball speed [m/s | mph] (default 0.2 m/s).
    #[arg(long, value_name = "SPEED", value_parser = finite, allow_hyphen_values = true)]
    pub ball_speed_sd: Option<f64>,
    /// 1σ of the measured launch angle [deg] (default 0.2).
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub launch_angle_sd: Option<f64>,
    /// 1σ of the measured launch direction [deg] (default 0.3).
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub launch_direction_sd: Option<f64>,
    /// 1σ of a measured spin [rpm] (default 150).
    #[arg(long, value_name = "RPM", value_parser = finite, allow_hyphen_values = true)]
    pub spin_sd: Option<f64>,
    /// 1σ of a measured spin axis [deg] (default 2).
    #[arg(long, value_name = "DEG", value_parser = finite, allow_hyphen_values = true)]
    pub spin_axis_sd: Option<f64>,
    /// Also fit a uniform wind (outdoor shots in unknown weather).
    #[arg(long)]
    pub fit_wind: bool,
    /// Also fit the air density (outdoor shots in unknown weather).
    #[arg(long)]
    pub fit_air_density: bool,
}

impl FlightObsArgs {
    /// The typed request: the launch options (those given are measured) and the
    /// observations, in SI with degrees and rpm.
    ///
    /// # Errors
    /// A bad track file; --backspin/--sidespin (give --spin and --spin-axis).
    pub fn request(&self, launch: &LaunchArgs, u: Units) -> Result<FlightRequest, InputError> {
        if launch.backspin.is_some() || launch.sidespin.is_some() {
            return Err(InputError::new(
                "backspin, sidespin",
                "with --from flight give the measured spin as --spin and --spin-axis",
            ));
        }
        let si = |q, v: f64| u.to_si(q, v);
        let with = |v: Option<f64>, sd: Option<f64>, default_si: f64, q| {
            v.map(|v| (si(q, v), sd.map_or(default_si, |s| si(q, s))))
        };
        let [s_speed, s_launch, s_dir, s_spin, s_axis] = LAUNCH_SD;
        let [s_apex, s_apex_t, s_carry, s_side, s_time, s_land] = SUMMARY_SD;
        let track = match &self.track {
            Some(path) => lf::read_track(path)?,
            None => lf::Track::default(),
        };
        let track_sd = self.track_sd;
        Ok(FlightRequest {
            ball_speed_mps: with(
                launch.ball_speed,
                self.ball_speed_sd,
                s_speed,
                Quantity::Speed,
            ),
            launch_angle_deg: with(
                launch.launch_angle,
                self.launch_angle_sd,
                s_launch,
                Quantity::Plain,
            ),
            launch_direction_deg: with(
                launch.launch_direction,
                self.launch_direction_sd,
                s_dir,
                Quantity::Plain,
            ),
            spin_rpm: with(launch.spin, self.spin_sd, s_spin, Quantity::Plain),
            spin_axis_deg: with(launch.spin_axis, self.spin_axis_sd, s_axis, Quantity::Plain),
            apex_height_m: with(
                self.apex_height,
                self.apex_height_sd,
                s_apex,
                Quantity::Height,
            ),
            apex_time_s: with(self.apex_time, self.apex_time_sd, s_apex_t, Quantity::Plain),
            carry_m: with(self.carry, self.carry_sd, s_carry, Quantity::Long),
            side_m: with(self.side, self.side_sd, s_side, Quantity::Long),
            flight_time_s: with(
                self.flight_time,
                self.flight_time_sd,
                s_time,
                Quantity::Plain,
            ),
            land_angle_deg: with(self.land_angle, self.land_angle_sd, s_land, Quantity::Plain),
            track_sd_m: track_sd.unwrap_or(TRACK_SD_M),
            doppler_sd_mps: track_sd.unwrap_or(DOPPLER_SD_MPS),
            track,
            radar_position_m: self.radar_position.unwrap_or([-2.5, 0.3, 0.0]),
            fit_wind: self.fit_wind,
            fit_air_density: self.fit_air_density,
        })
    }
}

/// Runs `carry estimate --from flight`; returns the text to print.
///
/// # Errors
/// Bad options, too few or uninformative observations, no convergence (status 2).
pub fn run(
    launch: &LaunchArgs,
    obs: &FlightObsArgs,
    scene: &SceneArgs,
    precision: &PrecisionArgs,
    out: &OutputArgs,
) -> Result<String, Failure> {
    let u = out.units;
    let mut p = Params::default();
    scene.apply(&mut p, u)?;
    let n = Numerics {
        precision: precision.precision,
        ..Numerics::default()
    };
    let request = obs.request(launch, u)?;
    let r = lf::fit(&p, &n, &request)?;
    if out.json {
        output::json(&r)
    } else if out.csv {
        output::csv(&[r])
    } else {
        Ok(table(&r, u))
    }
}

fn table(r: &FlightRecord, u: Units) -> String {
    let mut s = String::new();
    let (_, su) = u.display(Quantity::Speed, 1.0);
    let (_, lu) = u.display(Quantity::Long, 1.0);
    let (_, hu) = u.display(Quantity::Height, 1.0);
    let _ = writeln!(s, "the launch from the flight");
    let _ = writeln!(s, "{:<20} {:>10} {:>10}  source", "", "value", "± 1σ");
    let names = [
        format!("ball speed {su}"),
        "launch angle °".to_owned(),
        "launch direction °".to_owned(),
        "spin rpm".to_owned(),
        "spin axis °".to_owned(),
    ];
    for (i, (name, f)) in names.iter().zip(&r.launch.0).enumerate() {
        let (v, sd) = if i == 0 {
            (
                u.to_display(Quantity::Speed, f.value),
                u.to_display(Quantity::Speed, f.sd),
            )
        } else {
            (f.value, f.sd)
        };
        let _ = writeln!(s, "{name:<20} {v:>10.2} {sd:>10.2}  {}", f.source);
    }
    if let Some([x, z]) = r.wind_mps {
        let _ = writeln!(
            s,
            "{:<20} {:>10.2} {:>10.2}  fitted to the flight",
            format!("wind downrange {su}"),
            u.to_display(Quantity::Speed, x.0),
            u.to_display(Quantity::Speed, x.1)
        );
        let _ = writeln!(
            s,
            "{:<20} {:>10.2} {:>10.2}  fitted to the flight",
            format!("wind right {su}"),
            u.to_display(Quantity::Speed, z.0),
            u.to_display(Quantity::Speed, z.1)
        );
    }
    if let Some((v, sd)) = r.air_density_kgm3 {
        let _ = writeln!(
            s,
            "{:<20} {v:>10.3} {sd:>10.3}  fitted to the flight",
            "air density kg/m³"
        );
    }
    let _ = writeln!(
        s,
        "its flight: carry {:.1} {lu}, side {:+.1} {lu}, apex {:.1} {hu}, {:.2} s, landing {:.1}°",
        u.to_display(Quantity::Long, r.carry_m),
        u.to_display(Quantity::Long, r.side_m),
        u.to_display(Quantity::Height, r.apex_m),
        r.flight_time_s,
        r.land_angle_deg
    );
    if let (Some(total), Some(roll)) = (r.total_m, r.roll_m) {
        let _ = writeln!(
            s,
            "on the ground: total {:.1} {lu}, roll {:.1} {lu}",
            u.to_display(Quantity::Long, total),
            u.to_display(Quantity::Long, roll)
        );
    }
    let _ = writeln!(
        s,
        "χ² {:.2} over {} observations (worst: {}, {:+.2} σ); {} iterations, {} flights",
        r.chi2,
        r.observations,
        r.worst_observation,
        r.worst_residual_sigma,
        r.iterations,
        r.flights
    );
    s
}

/// What a flight column of `carry batch estimate --from flight` sets: a launch figure or
/// a summary (index into [`FIELDS`]), its value or its 1σ.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Part {
    Value,
    Sd,
}

/// The launch figures and summaries a row may give: (option name, SI output name, the
/// quantity of the option's unit under `--units`).
const FIELDS: [(&str, &str, Quantity); 11] = [
    ("ball_speed", "ball_speed_mps", Quantity::Speed),
    ("launch_angle", "launch_angle_deg", Quantity::Plain),
    ("launch_direction", "launch_direction_deg", Quantity::Plain),
    ("spin", "spin_rpm", Quantity::Plain),
    ("spin_axis", "spin_axis_deg", Quantity::Plain),
    ("apex_height", "apex_m", Quantity::Height),
    ("apex_time", "apex_time_s", Quantity::Plain),
    ("carry", "carry_m", Quantity::Long),
    ("side", "side_m", Quantity::Long),
    ("flight_time", "flight_time_s", Quantity::Plain),
    ("land_angle", "land_angle_deg", Quantity::Plain),
];

/// The column `name` as (field, value or 1σ, SI?): `carry`, `carry_sd` (in `--units`),
/// `carry_m`, `carry_m_sd` (SI, as another batch writes them).
fn flight_column(name: &str) -> Option<(usize, Part, bool)> {
    FIELDS.iter().enumerate().find_map(|(i, (opt, si, _))| {
        let sd = |base: &str| name.strip_suffix("_sd").is_some_and(|n| n == base);
        if name == *opt {
            Some((i, Part::Value, false))
        } else if sd(opt) {
            Some((i, Part::Sd, false))
        } else if name == *si {
            Some((i, Part::Value, true))
        } else if sd(si) {
            Some((i, Part::Sd, true))
        } else {
            None
        }
    })
}

/// The request's `Given` of field `i`.
fn given_mut(r: &mut FlightRequest, i: usize) -> Option<&mut lf::Given> {
    Some(match i {
        0 => &mut r.ball_speed_mps,
        1 => &mut r.launch_angle_deg,
        2 => &mut r.launch_direction_deg,
        3 => &mut r.spin_rpm,
        4 => &mut r.spin_axis_deg,
        5 => &mut r.apex_height_m,
        6 => &mut r.apex_time_s,
        7 => &mut r.carry_m,
        8 => &mut r.side_m,
        9 => &mut r.flight_time_s,
        10 => &mut r.land_angle_deg,
        _ => return None,
    })
}

/// `carry batch estimate --from flight`: one launch fit per input row, in parallel (the
/// same lab request as `carry estimate --from flight`). Input columns: the flight
/// summaries `apex_height, apex_time, carry, side, flight_time, land_angle` and the
/// measured launch `ball_speed, launch_angle, launch_direction, spin, spin_axis` (option
/// names: values in `--units`, angles in degrees, spin in rpm; or another batch's SI
/// output names `apex_m, apex_time_s, carry_m, side_m, flight_time_s, land_angle_deg,
/// ball_speed_mps, launch_angle_deg, …`), each with an optional `*_sd` column (its 1σ,
/// same unit); a launch figure given is measured, one not given is fitted. A `track`
/// column names a track CSV per row (relative to the input file's directory). The scene
/// and ball columns of `carry batch flight`, `label`. Empty cells take the command-line
/// value. Output: CSV (`line`, `label` if given, [`FlightRecord::COLUMNS`], `error`) or
/// JSON lines (`--json`: `carry estimate --from flight --json`'s keys).
///
/// # Errors
/// A bad file or header (status 2), failing to write (status 1).
pub fn batch(
    args: &crate::args::BatchArgs,
    launch: &LaunchArgs,
    obs: &FlightObsArgs,
    scene: &SceneArgs,
    precision: &PrecisionArgs,
    output: &OutputArgs,
) -> Result<(), Failure> {
    use carry_io::batch::Columns;
    use carry_io::compute::Mode;
    let u = output.units;
    let mut base = Params::default();
    scene.apply(&mut base, u)?;
    let n = Numerics {
        precision: precision.precision,
        ..Numerics::default()
    };
    let request = obs.request(launch, u)?;
    // the 1σ of a value a row gives without its own `_sd`: the option's, else the default
    let o = obs;
    let option_sd = [
        o.ball_speed_sd,
        o.launch_angle_sd,
        o.launch_direction_sd,
        o.spin_sd,
        o.spin_axis_sd,
        o.apex_height_sd,
        o.apex_time_sd,
        o.carry_sd,
        o.side_sd,
        o.flight_time_sd,
        o.land_angle_sd,
    ];
    let defaults: Vec<f64> = LAUNCH_SD.iter().chain(&SUMMARY_SD).copied().collect();
    let sd_of = |i: usize| {
        let q = FIELDS.get(i).map_or(Quantity::Plain, |f| f.2);
        option_sd
            .get(i)
            .copied()
            .flatten()
            .map(|s| u.to_si(q, s))
            .or_else(|| defaults.get(i).copied())
            .unwrap_or(1.0)
    };
    let (source, _) = carry_io::batch::open(&args.input)?;
    let name = args.input.display().to_string();
    let dir = if args.input.as_os_str() == "-" {
        PathBuf::from(".")
    } else {
        args.input
            .parent()
            .map_or_else(|| PathBuf::from("."), PathBuf::from)
    };
    let mut rdr = carry_io::batch::dialect().from_reader(source);
    let header = rdr
        .byte_headers()
        .map_err(|e| InputError::new("input", format!("{name}: cannot read the header: {e}")))?
        .clone();
    let head_error = |why: String| -> Failure {
        InputError::new("input", format!("{name}: line 1: {why}")).into()
    };
    // split the header: flight columns here, the rest (scene, ball, label) through io
    let mut flight_cols: Vec<(usize, usize, Part, bool)> = Vec::new();
    let mut track_col: Option<usize> = None;
    let mut rest_idx: Vec<usize> = Vec::new();
    let mut rest_header = csv::ByteRecord::new();
    for (i, raw) in header.iter().enumerate() {
        let col = String::from_utf8_lossy(raw);
        let col = col.trim().trim_start_matches('\u{feff}');
        if let Some((field, part, si)) = flight_column(col) {
            if flight_cols
                .iter()
                .any(|&(_, f, p, _)| f == field && p == part)
            {
                return Err(head_error(format!(
                    "column '{col}' gives what another column gives"
                )));
            }
            flight_cols.push((i, field, part, si));
        } else if col == "track" {
            if track_col.replace(i).is_some() {
                return Err(head_error(format!("column '{col}' appears twice")));
            }
        } else if matches!(col, "backspin" | "sidespin") {
            return Err(head_error(format!(
                "column '{col}': with --from flight give the measured spin as spin and spin_axis"
            )));
        } else if matches!(col, "backspin_rpm" | "sidespin_rpm") {
            // another batch's output: its spin is `spin_rpm`, `spin_axis_deg`
        } else {
            rest_idx.push(i);
            rest_header.push_field(raw);
        }
    }
    let cols = Columns::from_header(&rest_header, Mode::Flight)
        .map_err(|e| InputError::new("input", format!("{name}: {}", e.reason)))?;
    let records: Vec<csv::ByteRecord> = rdr
        .byte_records()
        .collect::<Result<_, _>>()
        .map_err(|e| InputError::new("input", format!("{name}: {e}")))?;
    let text = |rec: &csv::ByteRecord, i: usize| {
        String::from_utf8_lossy(rec.get(i).unwrap_or_default())
            .trim()
            .to_owned()
    };
    let row = |rec: &csv::ByteRecord| -> Result<(Params, FlightRequest), InputError> {
        if rec.len() != header.len() {
            return Err(InputError::new(
                "input",
                format!(
                    "expected {} fields as in the header, found {}",
                    header.len(),
                    rec.len()
                ),
            ));
        }
        let mut sub = csv::ByteRecord::new();
        for &i in &rest_idx {
            sub.push_field(rec.get(i).unwrap_or_default());
        }
        let p = cols.apply(&sub, &base, u)?;
        let mut r = request.clone();
        // values first, then their 1σ (a row's `_sd` may refine an option's value)
        for want in [Part::Value, Part::Sd] {
            for &(i, field, part, si) in flight_cols.iter().filter(|c| c.2 == want) {
                let t = text(rec, i);
                if t.is_empty() {
                    continue;
                }
                let (opt, si_name, q) = FIELDS.get(field).copied().unwrap_or(FIELDS[0]);
                let key = if si { si_name } else { opt };
                let v = carry_io::params::parse_finite(&t).map_err(|e| InputError::new(key, e))?;
                let v = if si { v } else { u.to_si(q, v) };
                let Some(g) = given_mut(&mut r, field) else {
                    continue;
                };
                match part {
                    Part::Value => *g = Some((v, sd_of(field))),
                    Part::Sd => {
                        if let Some((_, sd)) = g.as_mut() {
                            *sd = v;
                        }
                    }
                }
            }
        }
        if let Some(i) = track_col {
            let t = text(rec, i);
            if !t.is_empty() {
                r.track = lf::read_track(&dir.join(&t))?;
            }
        }
        Ok((p, r))
    };
    let inputs: Vec<_> = records.iter().map(row).collect();
    let results = lf::fit_rows(&inputs, &n, args.threads)?;
    let label_of = output::label_column(cols.label, &rest_idx);
    let out = output::batch_table(
        &records,
        &results,
        cols.label.is_some(),
        label_of,
        &FlightRecord::COLUMNS,
        FlightRecord::cells,
        output.json,
    );
    crate::write_stdout(out.as_bytes())
}
