//! The measured deliveries of `../shared/data/club_delivery.csv` (TrackMan publications:
//! club speed, attack, dynamic loft → ball speed, launch, spin) and the model's prediction
//! of each row, for calibration and accuracy tests.

use carry_core::impact::{self, ContactLaw, Solver};
use carry_core::units::{deg, mph, to_deg, to_mph, to_rpm};
use carry_core::{Ball, ClubSpec, Delivery, DeliveryConvention, FaceLocation, Preset};
use nalgebra::Vector3;

/// One row of the file (units of the source: mph, degrees, rpm).
#[allow(missing_docs)]
#[derive(Debug, Clone)]
pub struct Row {
    pub source: String,
    pub who: String,
    pub club: String,
    pub club_speed_mph: f64,
    pub attack_deg: f64,
    pub dynamic_loft_deg: f64,
    pub ball_speed_mph: f64,
    pub launch_deg: f64,
    pub spin_rpm: f64,
}

/// A predicted launch (mph, degrees, rpm).
#[allow(missing_docs)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Predicted {
    pub ball_speed_mph: f64,
    pub launch_deg: f64,
    pub spin_rpm: f64,
}

/// The rows of `club_delivery.csv` (the verbatim copy under `tests/data/`).
///
/// # Panics
/// When the file is missing or malformed (a broken test setup).
#[must_use]
pub fn rows() -> Vec<Row> {
    parse(include_str!("../data/club_delivery.csv"))
}

/// Parses the CSV text.
///
/// # Panics
/// On a malformed row.
#[must_use]
pub fn parse(text: &str) -> Vec<Row> {
    text.lines()
        .skip(1)
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            let x = |i: usize| f[i].trim().parse::<f64>().expect("number");
            Row {
                source: f[0].to_owned(),
                who: f[1].to_owned(),
                club: f[2].to_owned(),
                club_speed_mph: x(3),
                attack_deg: x(4),
                dynamic_loft_deg: x(5),
                ball_speed_mph: x(6),
                launch_deg: x(7),
                spin_rpm: x(8),
            }
        })
        .collect()
}

impl Row {
    /// A short label, e.g. `PGA driver`.
    #[must_use]
    pub fn label(&self) -> String {
        format!("{} {}", self.who, self.club)
    }

    /// The preset of this row's club.
    ///
    /// # Panics
    /// For a club without a preset.
    #[must_use]
    pub fn preset(&self) -> &'static Preset {
        Preset::find(&self.club).expect("preset for the row's club")
    }

    /// Where this row's ball meets the face (from its centre, m): the preset's typical
    /// strike for woods, a ball on firm turf for flat-faced clubs
    /// ([`carry_core::Preset::strike_height_m`] at the row's dynamic loft).
    #[must_use]
    pub fn impact_height_m(&self) -> f64 {
        self.preset()
            .strike_height_m(deg(self.dynamic_loft_deg), Ball::<f64>::STANDARD_RADIUS_M)
    }

    /// The model's launch for this row's delivery (square, struck where [`Row::impact_height_m`] says) with the row's preset
    /// and `contact`, reduced solver, f64.
    ///
    /// # Errors
    /// Any core error.
    pub fn predict(&self, contact: ContactLaw<f64>) -> carry_core::Result<Predicted> {
        let spec = ClubSpec {
            contact,
            ..self.preset().spec::<f64>()
        };
        self.predict_with(&spec)
    }

    /// As [`Row::predict`] with a given club.
    ///
    /// # Errors
    /// Any core error.
    pub fn predict_with(&self, spec: &ClubSpec<f64>) -> carry_core::Result<Predicted> {
        self.predict_at(spec, self.impact_height_m())
    }

    /// As [`Row::predict`] with a given club, struck `h` (m) above the face centre.
    ///
    /// # Errors
    /// Any core error.
    pub fn predict_at(&self, spec: &ClubSpec<f64>, h: f64) -> carry_core::Result<Predicted> {
        let club = spec.validate()?;
        // TrackMan's dynamic loft is the face's at the contact point
        let d = Delivery {
            club_speed_mps: mph(self.club_speed_mph),
            attack_angle_rad: deg(self.attack_deg),
            club_path_rad: 0.0,
            face_angle_rad: 0.0,
            dynamic_loft_rad: deg(self.dynamic_loft_deg),
            lie_rad: 0.0,
            club_spin_radps: Vector3::zeros(),
            location: FaceLocation {
                height_m: h,
                toe_m: 0.0,
            },
        };
        let strike = d.strike_in(&club, DeliveryConvention::TrackMan)?;
        let out = impact::solve(&club, &Ball::standard(), &strike, Solver::Reduced)?;
        Ok(Predicted {
            ball_speed_mph: to_mph(out.launch.ball_speed_mps),
            launch_deg: to_deg(out.launch.launch_angle_rad),
            spin_rpm: to_rpm(out.launch.spin_radps),
        })
    }
}

/// Errors of one prediction: ball speed (relative), launch (degrees), spin (relative).
#[allow(missing_docs)]
#[derive(Debug, Clone, Copy, Default)]
pub struct RowError {
    pub speed_rel: f64,
    pub launch_deg: f64,
    pub spin_rel: f64,
}

impl RowError {
    /// Signed errors of `p` against `row`.
    #[must_use]
    pub fn of(row: &Row, p: &Predicted) -> Self {
        Self {
            speed_rel: p.ball_speed_mph / row.ball_speed_mph - 1.0,
            launch_deg: p.launch_deg - row.launch_deg,
            spin_rel: p.spin_rpm / row.spin_rpm - 1.0,
        }
    }
}

/// Mean absolute errors and the worst spin error over the rows.
#[allow(missing_docs)]
#[derive(Debug, Clone, Copy, Default)]
pub struct Summary {
    pub speed_rel: f64,
    pub launch_deg: f64,
    pub spin_rel: f64,
    pub worst_spin_rel: f64,
}

/// How a model variant strikes the rows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Strike {
    /// At the face centre (today's seed use).
    Centred,
    /// Where [`Row::impact_height_m`] says (drivers above centre, irons off the turf).
    Typical,
}

/// Per-row errors and their summary for `contact` (a row that fails counts as NaN).
#[must_use]
pub fn evaluate(rows: &[Row], contact: ContactLaw<f64>) -> (Vec<RowError>, Summary) {
    evaluate_with(rows, contact, Strike::Typical)
}

/// The prediction of `row` with `contact` and `strike`.
///
/// # Errors
/// Any core error.
pub fn predict(
    row: &Row,
    contact: ContactLaw<f64>,
    strike: Strike,
) -> carry_core::Result<Predicted> {
    let spec = ClubSpec {
        contact,
        ..row.preset().spec::<f64>()
    };
    let h = match strike {
        Strike::Centred => 0.0,
        Strike::Typical => row.impact_height_m(),
    };
    row.predict_at(&spec, h)
}

/// [`evaluate`] with a strike model.
#[must_use]
pub fn evaluate_with(
    rows: &[Row],
    contact: ContactLaw<f64>,
    strike: Strike,
) -> (Vec<RowError>, Summary) {
    let errs: Vec<RowError> = rows
        .iter()
        .map(|r| {
            predict(r, contact, strike).map_or(
                RowError {
                    speed_rel: f64::NAN,
                    launch_deg: f64::NAN,
                    spin_rel: f64::NAN,
                },
                |p| RowError::of(r, &p),
            )
        })
        .collect();
    #[allow(clippy::cast_precision_loss)]
    let n = errs.len().max(1) as f64;
    let s = Summary {
        speed_rel: errs.iter().map(|e| e.speed_rel.abs()).sum::<f64>() / n,
        launch_deg: errs.iter().map(|e| e.launch_deg.abs()).sum::<f64>() / n,
        spin_rel: errs.iter().map(|e| e.spin_rel.abs()).sum::<f64>() / n,
        worst_spin_rel: errs.iter().map(|e| e.spin_rel.abs()).fold(0.0, f64::max),
    };
    (errs, s)
}
