//! The compliant contact fitted on single drives *together with* delivery tables (issue 34,
//! item 2; docs/impact.md §0.8, "Joint refit"): `carry fit --family compliant --also
//! DRIVES.csv` and the `impact_joint_refit` example.
//!
//! Rows are single TrackMan drives ([`crate::drives`]: struck by the `driver` preset with
//! their measured delivery in TrackMan's convention, at their measured strike location or,
//! without one, at the data's typical strike, the median of the measured locations) and
//! table rows ([`DeliveryRow`]: `club_delivery.csv`, or TrackMan's 2010 driver chart read by
//! [`read_table`]). The drives' total weight is `1/W` times the tables' (`W` the table
//! weight), so 4,000 drives do not drown 40 table rows; a drive's cross-validation group is
//! its session (1,000 consecutive rows), a table row is held out alone. k_e is held inside
//! Penner's measured range ([`K_E_PENNER_SPM`]) whenever drives are in the fit: alone, the
//! drives drive it to 0, against the measured fall of the COR with speed.

use super::Problem;
use super::impact::{
    self, BALL_SPEED_SIGMA_REL, DeliveryRow, LAUNCH_SIGMA_DEG, PARAMETERS, SPIN_SIGMA_REL,
};
use super::single_drives::{self, compliant, drive_model, observed, strike};
use crate::drives::Drive;
use carry_core::impact::ContactLaw;
use carry_core::presets::{FITTED_COMPLIANT, TypicalDelivery};

/// k_e's bounds (s/m) with drives in the fit: Penner (2001) measures 0.0029; the law's
/// calibration is 0.0027.
pub const K_E_PENNER_SPM: (f64, f64) = (0.0020, 0.0040);

/// The driver's CG height's bounds (m, the face frame's y of `cg_to_face_m`; the preset's
/// −0.005 puts its sweet spot 5 mm above the face centre) when it is fitted
/// ([`JointContactProblem::driver_cg_height`]).
pub const DRIVER_CG_HEIGHT_M: (f64, f64) = (-0.015, 0.005);

/// One row of a joint fit.
#[derive(Debug, Clone)]
pub enum JointRow {
    /// A single drive.
    Drive(Box<Drive>),
    /// A table row.
    Table(DeliveryRow),
}

/// The compliant contact's four parameters ([`PARAMETERS`]) fitted to ball speed, launch
/// angle and spin of drives and table rows together (σ as [`super::impact`]'s).
#[derive(Debug, Clone)]
pub struct JointContactProblem {
    /// Where a drive without a measured location is struck `[toe, height]` (m).
    pub typical_strike_m: [f64; 2],
    /// Weight of one drive (a table row weighs 1).
    pub drive_weight: f64,
    /// Hold the ceiling e_t,max at the calibrated value (the irons' spin).
    pub hold_cap: bool,
    /// Fit the driver's CG height too (a fifth parameter) and strike the tables' driver
    /// rows at the typical strike.
    pub driver_cg_height: bool,
    /// The friction coefficient the fit holds.
    pub friction: f64,
}

impl JointContactProblem {
    /// The problem of `rows` with the tables weighing `table_weight` times the drives in
    /// total; the typical strike is the drives' median measured location (the `driver`
    /// preset's typical height, centred, when none has one).
    #[must_use]
    pub fn new(rows: &[JointRow], table_weight: f64) -> Self {
        let drives: Vec<Drive> = rows
            .iter()
            .filter_map(|r| match r {
                JointRow::Drive(d) => Some(**d),
                JointRow::Table(_) => None,
            })
            .collect();
        let tables = rows.len() - drives.len();
        #[allow(clippy::cast_precision_loss)]
        let drive_weight = if drives.is_empty() {
            1.0
        } else {
            tables.max(1) as f64 / drives.len() as f64 / table_weight
        };
        Self {
            typical_strike_m: single_drives::typical_strike_m(&drives)
                .unwrap_or([0.0, single_drives::driver().typical.impact_height_m]),
            drive_weight,
            hold_cap: false,
            driver_cg_height: false,
            friction: FITTED_COMPLIANT.friction,
        }
    }
}

/// A table row struck with `law` (ball speed, launch, spin); with `data_strike`, a driver
/// row is struck at that location instead of the row's typical height.
///
/// # Errors
/// [`strike`]'s.
pub fn table_model(
    r: &DeliveryRow,
    law: ContactLaw<f64>,
    cg_y: Option<f64>,
    data_strike: Option<[f64; 2]>,
) -> Result<[f64; 3], String> {
    let mut h = impact::impact_height_m(r);
    let mut toe = 0.0;
    if let (Some(s), "driver") = (data_strike, r.preset.name) {
        toe = s[0];
        h = s[1];
    }
    let mut d = TypicalDelivery {
        club_speed_mps: r.club_speed_mps,
        attack_angle_deg: r.attack_deg,
        dynamic_loft_deg: r.dynamic_loft_deg,
        impact_height_m: h,
    }
    .delivery::<f64>();
    d.location.toe_m = toe;
    let m = strike(r.preset, law, cg_y, &d)?;
    Ok([m[0], m[1], m[3]])
}

/// Delivery rows of a table: `club_delivery.csv`'s columns ([`impact::read_rows`]), or,
/// without a `club` column, a driver chart (TrackMan's 2010 optimizer: `club_speed_mph,
/// attack_deg, ball_speed_mph, launch_deg, spin_rpm, …, dynamic_loft_deg`), each row the
/// `driver` preset labelled `label`.
///
/// # Errors
/// A one-line message naming the line and column at fault.
pub fn read_table(text: &str, label: &str) -> Result<Vec<DeliveryRow>, String> {
    impact::read_rows_or(text, Some((single_drives::driver(), label)))
}

impl Problem for JointContactProblem {
    type Row = JointRow;
    fn parameter_names(&self) -> Vec<&'static str> {
        let mut v = PARAMETERS.to_vec();
        if self.driver_cg_height {
            v.push("driver_cg_height_m");
        }
        v
    }
    fn bounds(&self) -> Vec<(f64, f64)> {
        let cap = FITTED_COMPLIANT.tangential_restitution_max;
        let cap = if self.hold_cap {
            (cap - 1e-6, cap + 1e-6)
        } else {
            (0.0, 1.0)
        };
        let mut b = vec![(-1.0, 1.0), (-3.0, 3.0), cap, K_E_PENNER_SPM];
        if self.driver_cg_height {
            b.push(DRIVER_CG_HEIGHT_M);
        }
        b
    }
    fn initial(&self) -> Vec<f64> {
        let c = FITTED_COMPLIANT;
        let mut v = vec![
            c.tangential_restitution,
            c.tangential_restitution_slope,
            c.tangential_restitution_max,
            c.restitution_speed_slope_spm,
        ];
        if self.driver_cg_height {
            v.push(single_drives::driver().cg_to_face_m[1]);
        }
        v
    }
    fn quantity_names(&self) -> Vec<&'static str> {
        vec!["ball_speed", "launch_angle", "spin"]
    }
    fn observed(&self, r: &JointRow) -> Vec<Option<f64>> {
        match r {
            JointRow::Drive(d) => {
                let o = observed(d);
                vec![o.map(|o| o[0]), o.map(|o| o[1]), o.map(|o| o[3])]
            }
            JointRow::Table(t) => {
                vec![Some(t.ball_speed_mps), Some(t.launch_deg), Some(t.spin_rpm)]
            }
        }
    }
    fn sigma(&self, r: &JointRow) -> Vec<f64> {
        let (v, s) = match r {
            JointRow::Drive(d) => observed(d).map_or((1.0, 1.0), |o| (o[0], o[3])),
            JointRow::Table(t) => (t.ball_speed_mps, t.spin_rpm),
        };
        vec![
            BALL_SPEED_SIGMA_REL * v,
            LAUNCH_SIGMA_DEG,
            SPIN_SIGMA_REL * s,
        ]
    }
    fn label(&self, r: &JointRow) -> String {
        match r {
            JointRow::Drive(d) => format!("drive {} (session {})", d.index, d.session()),
            JointRow::Table(t) => t.label.clone(),
        }
    }
    fn group(&self, r: &JointRow) -> Option<usize> {
        match r {
            JointRow::Drive(d) => Some(d.session()),
            JointRow::Table(_) => None,
        }
    }
    fn weight(&self, r: &JointRow) -> f64 {
        match r {
            JointRow::Drive(_) => self.drive_weight,
            JointRow::Table(_) => 1.0,
        }
    }
    fn predict(&self, p: &[f64], r: &JointRow) -> Result<Vec<f64>, String> {
        let law = ContactLaw::Compliant(compliant(p, self.friction));
        let cg_y = p.get(4).copied();
        match r {
            JointRow::Drive(d) => {
                let m = drive_model(d, law, cg_y, true, self.typical_strike_m)?;
                Ok(vec![m[0], m[1], m[3]])
            }
            JointRow::Table(t) => Ok(table_model(
                t,
                law,
                cg_y,
                self.driver_cg_height.then_some(self.typical_strike_m),
            )?
            .to_vec()),
        }
    }
}
