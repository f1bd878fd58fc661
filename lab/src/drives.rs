//! Single TrackMan drives: `../shared/data/trackman_amateur_drives.csv` (5,000 drives of one
//! amateur, in session order; `../shared/data/README.md` has the provenance and licence).
//!
//! The file is read where it lies and never copied into the project. Each row becomes a
//! [`Drive`] in SI units (speeds m/s, lengths m, times s) with angles in degrees and spin in
//! rpm, as a launch monitor reports them; a cell TrackMan left empty is `None`.
//!
//! **Sessions.** The rows are in session order; cross-validation holds out blocks of
//! [`SESSION_ROWS`] consecutive rows ([`Drive::session`]), so a model is always checked on
//! shots of another day than the ones it was fitted on.
//!
//! **Indoors and outdoors.** Most rows were hit indoors: the radar tracked the ball for about
//! 6 yd and TrackMan's own flight and roll model supplied carry and total from the measured
//! launch. Rows whose last tracked point is past [`OUTDOOR_TRACK_M`] were tracked outdoors in
//! unknown weather ([`Drive::tracked_outdoors`]): 627 rows, 340 of them with the premium ball.

use std::path::{Path, PathBuf};

use crate::columns::Header;

/// Rows per cross-validation block ("session"): the issues' blocks of about 1,000
/// consecutive rows.
pub const SESSION_ROWS: usize = 1000;

/// A last tracked point further than this (91.44 m = 100 yd) means the ball was tracked
/// outdoors (indoors the radar sees about 6 yd).
pub const OUTDOOR_TRACK_M: f64 = 91.44;

const MPH_MPS: f64 = 0.447_04;
const YARD_M: f64 = 0.9144;
const FOOT_M: f64 = 0.3048;
const MM_M: f64 = 1e-3;

/// The file's path beside the project (`../shared/data/trackman_amateur_drives.csv` from the
/// workspace root), or `$CARRY_DRIVES` when set.
#[must_use]
pub fn default_path() -> PathBuf {
    std::env::var_os("CARRY_DRIVES").map_or_else(
        || {
            Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../../shared/data/trackman_amateur_drives.csv")
        },
        PathBuf::from,
    )
}

/// The ball TrackMan was told was hit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BallKind {
    /// `Premium`: a tour ball (4,597 rows).
    Premium,
    /// `Limited Distance Soft`: a range ball made to fly short.
    LimitedDistanceSoft,
    /// `Soft`.
    Soft,
    /// `Medium`.
    Medium,
    /// Anything else or empty.
    Other,
}

impl BallKind {
    fn parse(s: &str) -> Self {
        match s.trim() {
            "Premium" => Self::Premium,
            "Limited Distance Soft" => Self::LimitedDistanceSoft,
            "Soft" => Self::Soft,
            "Medium" => Self::Medium,
            _ => Self::Other,
        }
    }
}

/// TrackMan's club data (face and loft at the contact point; speed, attack and path of the
/// head), each as measured or `None`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ClubMeasured {
    /// Club speed, m/s.
    pub club_speed_mps: Option<f64>,
    /// Attack angle, degrees (+ up).
    pub attack_angle_deg: Option<f64>,
    /// Club path, degrees (+ right, in to out for a right-hander).
    pub club_path_deg: Option<f64>,
    /// Dynamic loft, degrees.
    pub dynamic_loft_deg: Option<f64>,
    /// Face angle, degrees (+ open, right).
    pub face_angle_deg: Option<f64>,
    /// Face to path, degrees (face angle − club path).
    pub face_to_path_deg: Option<f64>,
}

/// TrackMan's ball data at launch.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LaunchMeasured {
    /// Ball speed, m/s.
    pub ball_speed_mps: Option<f64>,
    /// Smash factor (ball speed / club speed).
    pub smash: Option<f64>,
    /// Launch angle, degrees.
    pub launch_angle_deg: Option<f64>,
    /// Launch direction, degrees (+ right).
    pub launch_direction_deg: Option<f64>,
    /// Spin rate, rpm.
    pub spin_rpm: Option<f64>,
    /// Spin axis, degrees (+ right: fade/slice).
    pub spin_axis_deg: Option<f64>,
}

/// What TrackMan reports of the flight and the run-out (its own model's on indoor rows).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FlightMeasured {
    /// Apex height, m.
    pub apex_m: Option<f64>,
    /// The last tracked point in the frame G: downrange, height, side (m); its time below.
    pub last_point_m: Option<[f64; 3]>,
    /// Time of the last tracked point, s.
    pub last_point_time_s: Option<f64>,
    /// Carry on flat ground, m.
    pub carry_m: Option<f64>,
    /// Side at the landing on flat ground, m (+ right).
    pub carry_side_m: Option<f64>,
    /// Landing angle, degrees below the horizontal.
    pub land_angle_deg: Option<f64>,
    /// Ball speed at landing, m/s.
    pub land_speed_mps: Option<f64>,
    /// Flight time, s.
    pub flight_time_s: Option<f64>,
    /// Total (carry plus bounce and roll), m.
    pub total_m: Option<f64>,
    /// Side at rest, m (+ right).
    pub total_side_m: Option<f64>,
}

/// One drive: a row of the file.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Drive {
    /// The row's index among the shots (0-based, in file order).
    pub index: usize,
    /// The ball.
    pub ball: BallKind,
    /// The club data.
    pub club: ClubMeasured,
    /// The launch.
    pub launch: LaunchMeasured,
    /// The flight and run-out.
    pub flight: FlightMeasured,
    /// Strike location on the face, m: toward the toe (+) and up (+) from the face centre
    /// (996 rows).
    pub strike_m: Option<[f64; 2]>,
}

impl Drive {
    /// The cross-validation block: `index / SESSION_ROWS`.
    #[must_use]
    pub fn session(&self) -> usize {
        self.index / SESSION_ROWS
    }

    /// Tracked outdoors past [`OUTDOOR_TRACK_M`] (its carry is measured, in unknown weather).
    #[must_use]
    pub fn tracked_outdoors(&self) -> bool {
        self.flight
            .last_point_m
            .is_some_and(|p| p[0] > OUTDOOR_TRACK_M)
    }

    /// The launch, when ball speed, launch angle and direction, spin and axis are all there
    /// and plausible for a drive (ball speed 10–100 m/s, spin 0–15,000 rpm, |axis| < 90°):
    /// `(ball speed m/s, launch °, direction °, spin rpm, axis °)`.
    #[must_use]
    pub fn full_launch(&self) -> Option<[f64; 5]> {
        let l = &self.launch;
        let out = [
            l.ball_speed_mps?,
            l.launch_angle_deg?,
            l.launch_direction_deg?,
            l.spin_rpm?,
            l.spin_axis_deg?,
        ];
        let plausible = (10.0..100.0).contains(&out[0])
            && out[1].abs() < 90.0
            && out[2].abs() < 90.0
            && (0.0..15_000.0).contains(&out[3])
            && out[4].abs() < 90.0;
        plausible.then_some(out)
    }

    /// The club delivery, when club speed, attack, path, dynamic loft and face are all there:
    /// `(club speed m/s, attack °, path °, dynamic loft °, face °)`.
    #[must_use]
    pub fn full_delivery(&self) -> Option<[f64; 5]> {
        let c = &self.club;
        let out = [
            c.club_speed_mps?,
            c.attack_angle_deg?,
            c.club_path_deg?,
            c.dynamic_loft_deg?,
            c.face_angle_deg?,
        ];
        out.iter().all(|v| v.is_finite()).then_some(out)
    }
}

/// Reads the drives from `path` (the file's format: a names line, a units line, then one
/// shot a row).
///
/// # Errors
/// The file cannot be read, a header column is missing, or a cell is not a number
/// (`line N: column: 'text' is not a number`).
pub fn read(path: &Path) -> Result<Vec<Drive>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    parse(&text)
}

/// Whether `text` is a single-drive TrackMan export: its header starts `Ball,` and names
/// `Carry Flat - Length` (the format of `../shared/data/trackman_amateur_drives.csv`).
#[must_use]
pub fn is_export(text: &str) -> bool {
    text.lines()
        .next()
        .is_some_and(|h| h.starts_with("Ball,") && h.contains("Carry Flat - Length"))
}

/// Reads the drives from the shared file ([`default_path`]).
///
/// # Errors
/// As [`read`].
pub fn read_shared() -> Result<Vec<Drive>, String> {
    read(&default_path())
}

const COLUMNS: [&str; 27] = [
    "Ball",
    "Club Speed",
    "Attack Angle",
    "Club Path",
    "Dyn. Loft",
    "Face Angle",
    "Face To Path",
    "Ball Speed",
    "Smash Factor",
    "Launch Angle",
    "Launch Direction",
    "Spin Rate",
    "Spin Axis",
    "Max Height - Height",
    "Last data Point - Length",
    "Last data Point - Side",
    "Last data Point - Height",
    "Last data Point - Time",
    "Carry Flat - Length",
    "Carry Flat - Side",
    "Carry Flat - Land. Angle",
    "Carry Flat - Ball Speed",
    "Carry Flat - Time",
    "Total",
    "Side Total",
    "Impact Offset",
    "Impact Height",
];

/// Parses the file's text (see [`read`]).
///
/// # Errors
/// As [`read`].
pub fn parse(text: &str) -> Result<Vec<Drive>, String> {
    let mut lines = text.lines();
    let header = Header::of(lines.next().ok_or("empty file")?);
    let at = header.columns(COLUMNS)?;
    lines.next().ok_or("no units line")?;
    let mut drives = Vec::new();
    for (index, line) in lines.enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let cells: Vec<&str> = line.split(',').map(str::trim).collect();
        let line_no = index + 3;
        let num = |k: usize, scale: f64| -> Result<Option<f64>, String> {
            let cell = cells.get(at[k]).copied().unwrap_or("");
            if cell.is_empty() {
                return Ok(None);
            }
            cell.parse::<f64>()
                .map(|v| v.is_finite().then_some(v * scale))
                .map_err(|_| format!("line {line_no}: {}: '{cell}' is not a number", COLUMNS[k]))
        };
        let point = match (num(14, YARD_M)?, num(15, YARD_M)?, num(16, YARD_M)?) {
            (Some(x), Some(z), Some(y)) => Some([x, y, z]),
            _ => None,
        };
        let strike_m = match (num(25, MM_M)?, num(26, MM_M)?) {
            (Some(toe), Some(height)) => Some([toe, height]),
            _ => None,
        };
        drives.push(Drive {
            index,
            ball: BallKind::parse(cells.get(at[0]).copied().unwrap_or("")),
            club: ClubMeasured {
                club_speed_mps: num(1, MPH_MPS)?,
                attack_angle_deg: num(2, 1.0)?,
                club_path_deg: num(3, 1.0)?,
                dynamic_loft_deg: num(4, 1.0)?,
                face_angle_deg: num(5, 1.0)?,
                face_to_path_deg: num(6, 1.0)?,
            },
            launch: LaunchMeasured {
                ball_speed_mps: num(7, MPH_MPS)?,
                smash: num(8, 1.0)?,
                launch_angle_deg: num(9, 1.0)?,
                launch_direction_deg: num(10, 1.0)?,
                spin_rpm: num(11, 1.0)?,
                spin_axis_deg: num(12, 1.0)?,
            },
            flight: FlightMeasured {
                apex_m: num(13, FOOT_M)?,
                last_point_m: point,
                last_point_time_s: num(17, 1.0)?,
                carry_m: num(18, YARD_M)?,
                carry_side_m: num(19, YARD_M)?,
                land_angle_deg: num(20, 1.0)?,
                land_speed_mps: num(21, MPH_MPS)?,
                flight_time_s: num(22, 1.0)?,
                total_m: num(23, YARD_M)?,
                total_side_m: num(24, YARD_M)?,
            },
            strike_m,
        });
    }
    Ok(drives)
}

/// The sessions (cross-validation blocks) present in `drives`, in order.
#[must_use]
pub fn sessions(drives: &[Drive]) -> Vec<usize> {
    let mut out: Vec<usize> = drives.iter().map(Drive::session).collect();
    out.dedup();
    out
}

/// A session-blocked split: the drives of `held_out` and the others.
#[must_use]
pub fn split(drives: &[Drive], held_out: usize) -> (Vec<Drive>, Vec<Drive>) {
    drives.iter().partition(|d| d.session() == held_out)
}

#[cfg(test)]
mod tests {
    use super::*;

    const SAMPLE: &str = "Ball,Club Speed,Attack Angle,Club Path,Dyn. Loft,Face Angle,Face To Path,Ball Speed,Smash Factor,Launch Angle,Launch Direction,Spin Rate,Spin Axis,Max Height - Height,Last data Point - Length,Last data Point - Side,Last data Point - Height,Last data Point - Time,Carry Flat - Length,Carry Flat - Side,Carry Flat - Land. Angle,Carry Flat - Ball Speed,Carry Flat - Time,Total,Side Total,Impact Offset,Impact Height
,[mph],[deg],[deg],[deg],[deg],[deg],[mph],[],[deg],[deg],[rpm],[deg],[ft],[yds],[yds],[yds],[s],[yds],[yds],[deg],[mph],[s],[yds],[yds],[mm],[mm]
Premium,100,1,2,12,0.5,-1.5,145,1.45,12,0.4,2500,-3,90,6,0.1,1,0.1,230,-5,38,60,6.2,250,-6,,
Limited Distance Soft,,,,,,,140,,11,0,2600,2,80,150,1,20,3,220,2,36,58,6.0,240,3,4,-2
";

    #[test]
    fn reads_units_and_empty_cells() {
        let d = parse(SAMPLE).unwrap();
        assert_eq!(d.len(), 2);
        let a = &d[0];
        assert_eq!(a.ball, BallKind::Premium);
        assert!((a.club.club_speed_mps.unwrap() - 44.704).abs() < 1e-12);
        assert!((a.flight.carry_m.unwrap() - 230.0 * 0.9144).abs() < 1e-12);
        assert!((a.flight.apex_m.unwrap() - 90.0 * 0.3048).abs() < 1e-12);
        assert_eq!(a.strike_m, None);
        assert!(a.full_delivery().is_some() && a.full_launch().is_some());
        assert!(!a.tracked_outdoors());
        let b = &d[1];
        assert_eq!(b.ball, BallKind::LimitedDistanceSoft);
        assert_eq!(b.club.club_speed_mps, None);
        assert!(b.full_delivery().is_none());
        assert_eq!(b.strike_m, Some([0.004, -0.002]));
        assert!(b.tracked_outdoors());
        assert_eq!(b.session(), 0);
    }

    #[test]
    fn names_a_bad_cell_and_a_missing_column() {
        let bad = SAMPLE.replace("145,1.45", "fast,1.45");
        assert_eq!(
            parse(&bad).unwrap_err(),
            "line 3: Ball Speed: 'fast' is not a number"
        );
        let missing = SAMPLE.replace("Spin Axis", "Axis");
        assert_eq!(parse(&missing).unwrap_err(), "no column 'Spin Axis'");
    }

    #[test]
    fn implausible_launches_are_not_full() {
        let bogus = SAMPLE.replace(",2500,", ",-21474836480,");
        assert!(parse(&bogus).unwrap()[0].full_launch().is_none());
    }

    #[test]
    fn the_shared_file_when_present() {
        let path = default_path();
        if !path.exists() {
            return;
        }
        let d = read(&path).unwrap();
        assert_eq!(d.len(), 5000);
        assert_eq!(sessions(&d), vec![0, 1, 2, 3, 4]);
        assert_eq!(d.iter().filter(|x| x.strike_m.is_some()).count(), 996);
        let outdoors = d.iter().filter(|x| x.tracked_outdoors());
        assert_eq!(outdoors.clone().count(), 627);
        assert_eq!(
            outdoors.filter(|x| x.ball == BallKind::Premium).count(),
            340
        );
        let (held, rest) = split(&d, 2);
        assert_eq!((held.len(), rest.len()), (1000, 4000));
    }
}
