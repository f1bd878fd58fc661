//! The impact on single strikes: the amateur's TrackMan drives ([`crate::drives`]) struck
//! with the `driver` preset, and the compliant contact refitted on them (issue 34,
//! docs/impact.md §0.8).
//!
//! Each drive is struck with its measured club speed, attack angle, club path, face angle
//! and dynamic loft in TrackMan's convention (face and loft at the contact point), no lie,
//! no club spin, at its measured strike location or, without one, at a typical location.
//! Solved in `f64` with the reduced solver.
//!
//! **The D-plane share (a named empirical law, never a default).** TrackMan's spin axis
//! answers face-to-path about half as much as the model's on this golfer's driver, and the
//! share moves from session to session (docs/impact.md §0.8): no property of a fixed head
//! produces that. [`AxisLaw::DPlaneShare`] scales the model's spin-axis tangent,
//! `tan a' = k · tan a`, with `k` fitted by least squares on measured axes
//! ([`fit_dplane_share`]); [`AxisLaw::Physics`] leaves the model's axis alone.

use super::impact::{BALL_SPEED_SIGMA_REL, LAUNCH_SIGMA_DEG, PARAMETERS, SPIN_SIGMA_REL};
use crate::drives::Drive;
use carry_core::impact::{self, CompliantContact, ContactLaw, Solver};
use carry_core::units::{deg, to_deg, to_rpm};
use carry_core::{Ball, ClubSpec, Delivery, DeliveryConvention, FaceLocation, Preset};
use nalgebra::Vector3;

/// What the model predicts of a drive, in order.
pub const QUANTITIES: [&str; 5] = [
    "ball_speed",
    "launch_angle",
    "launch_direction",
    "spin",
    "spin_axis",
];

/// How the spin axis is read off the impact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AxisLaw {
    /// The impact's own axis (the default).
    Physics,
    /// `tan a' = k · tan a`: the empirical D-plane share `k` (docs/impact.md §0.8).
    DPlaneShare(f64),
}

impl AxisLaw {
    /// The axis (degrees) this law reads from the model's `axis_deg`.
    #[must_use]
    pub fn apply(self, axis_deg: f64) -> f64 {
        match self {
            Self::Physics => axis_deg,
            Self::DPlaneShare(k) => to_deg((k * deg(axis_deg).tan()).atan()),
        }
    }
}

/// The `driver` preset.
///
/// # Panics
/// Never: the preset table has a driver.
#[must_use]
pub fn driver() -> &'static Preset {
    Preset::find("driver").unwrap_or(&carry_core::presets::PRESETS[0])
}

/// The drive's delivery, struck at `location` (`[toe, height]`, m from the face centre).
#[must_use]
pub fn delivery(club: [f64; 5], location: [f64; 2]) -> Delivery<f64> {
    let [speed, attack, path, loft, face] = club;
    Delivery {
        club_speed_mps: speed,
        attack_angle_rad: deg(attack),
        club_path_rad: deg(path),
        face_angle_rad: deg(face),
        dynamic_loft_rad: deg(loft),
        lie_rad: 0.0,
        club_spin_radps: Vector3::zeros(),
        location: FaceLocation {
            height_m: location[1],
            toe_m: location[0],
        },
    }
}

/// Ball speed (m/s), launch (°), direction (°), spin (rpm) and axis (°, the impact's own) of
/// `drive` struck by the `driver` head with `contact` at its measured strike location when
/// `use_location` and it has one, else at `typical` (`[toe, height]`, m): [`drive_model`]
/// with the preset's CG.
///
/// # Errors
/// The drive has no full delivery, or the core's error, as a message.
pub fn predict(
    drive: &Drive,
    contact: ContactLaw<f64>,
    use_location: bool,
    typical: [f64; 2],
) -> Result<[f64; 5], String> {
    drive_model(drive, contact, None, use_location, typical)
}

/// Ball speed (m/s), launch (°), direction (°), spin (rpm) and axis (°) of `delivery` struck
/// by `preset` with `law` in TrackMan's convention, the driver's CG at height `cg_y` (m)
/// when given.
///
/// # Errors
/// The club, the strike or the impact's error, as text.
pub fn strike(
    preset: &Preset,
    law: ContactLaw<f64>,
    cg_y: Option<f64>,
    delivery: &Delivery<f64>,
) -> Result<[f64; 5], String> {
    let mut spec = ClubSpec {
        contact: law,
        ..preset.spec::<f64>()
    };
    if let (Some(y), "driver") = (cg_y, preset.name) {
        spec.cg_to_face_m.y = y;
    }
    let club = spec.validate().map_err(|e| e.to_string())?;
    let st = delivery
        .strike_in(&club, DeliveryConvention::TrackMan)
        .map_err(|e| e.to_string())?;
    let l = impact::solve(&club, &Ball::standard(), &st, Solver::Reduced)
        .map_err(|e| e.to_string())?
        .launch;
    Ok([
        l.ball_speed_mps,
        to_deg(l.launch_angle_rad),
        to_deg(l.launch_direction_rad),
        to_rpm(l.spin_radps),
        to_deg(l.spin_axis_rad),
    ])
}

/// A drive struck with `law` (driver CG at `cg_y`) at its measured location when `located`
/// and it has one, else at `typical`.
///
/// # Errors
/// No full delivery, or [`strike`]'s.
pub fn drive_model(
    d: &Drive,
    law: ContactLaw<f64>,
    cg_y: Option<f64>,
    located: bool,
    typical: [f64; 2],
) -> Result<[f64; 5], String> {
    let loc = if located {
        d.strike_m.unwrap_or(typical)
    } else {
        typical
    };
    let club = d.full_delivery().ok_or("no full delivery")?;
    strike(driver(), law, cg_y, &delivery(club, loc))
}

/// The measured `[ball speed m/s, launch °, direction °, spin rpm, axis °]` of `drive`, when
/// it has a full, plausible launch and a full delivery.
#[must_use]
pub fn observed(drive: &Drive) -> Option<[f64; 5]> {
    drive.full_delivery()?;
    let [v, launch, dir, spin, axis] = drive.full_launch()?;
    Some([v, launch, dir, spin, axis])
}

/// The D-plane share `k` of measured against model axes (degrees, `(model, measured)`):
/// the `k` in [0, 2] minimising `Σ (atan(k tan a_m) − a_o)²` (golden-section search; the
/// arctangent keeps a few near-vertical model axes from dominating). `None` without pairs.
#[must_use]
pub fn fit_dplane_share(pairs: &[(f64, f64)]) -> Option<f64> {
    if pairs.is_empty() {
        return None;
    }
    let cost = |k: f64| -> f64 {
        pairs
            .iter()
            .map(|&(m, o)| (AxisLaw::DPlaneShare(k).apply(m) - o).powi(2))
            .sum()
    };
    let g = 0.5 * (5.0_f64.sqrt() - 1.0);
    let (mut lo, mut hi) = (0.0_f64, 2.0_f64);
    for _ in 0..80 {
        let (a, b) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if cost(a) < cost(b) {
            hi = b;
        } else {
            lo = a;
        }
    }
    Some(0.5 * (lo + hi))
}

/// The median `[toe, height]` (m) of the measured strike locations of `drives`, `None`
/// when none has one: the data's typical strike.
#[must_use]
pub fn typical_strike_m(drives: &[Drive]) -> Option<[f64; 2]> {
    let median = |mut v: Vec<f64>| -> Option<f64> {
        if v.is_empty() {
            return None;
        }
        v.sort_by(f64::total_cmp);
        let n = v.len();
        Some(if n % 2 == 1 {
            v[n / 2]
        } else {
            0.5 * (v[n / 2 - 1] + v[n / 2])
        })
    };
    let toe = median(
        drives
            .iter()
            .filter_map(|d| d.strike_m.map(|s| s[0]))
            .collect(),
    )?;
    let height = median(
        drives
            .iter()
            .filter_map(|d| d.strike_m.map(|s| s[1]))
            .collect(),
    )?;
    Some([toe, height])
}

/// The compliant contact fitted to single drives: ball speed, launch and spin (σ as
/// [`super::impact`]'s), the same four parameters, each drive struck where
/// [`predict`] says.
#[derive(Debug, Clone)]
pub struct SingleDriveProblem {
    /// Where the fit starts.
    pub initial: CompliantContact<f64>,
    /// Strike at the measured location when the drive has one.
    pub use_location: bool,
    /// The typical strike `[toe, height]` (m) otherwise.
    pub typical: [f64; 2],
}

impl super::Problem for SingleDriveProblem {
    type Row = Drive;

    fn parameter_names(&self) -> Vec<&'static str> {
        PARAMETERS.to_vec()
    }

    /// [`super::impact::ContactProblem`]'s bounds.
    fn bounds(&self) -> Vec<(f64, f64)> {
        vec![(-1.0, 1.0), (-3.0, 3.0), (0.0, 1.0), (0.0, 0.02)]
    }

    fn initial(&self) -> Vec<f64> {
        let c = &self.initial;
        vec![
            c.tangential_restitution,
            c.tangential_restitution_slope,
            c.tangential_restitution_max,
            c.restitution_speed_slope_spm,
        ]
    }

    fn quantity_names(&self) -> Vec<&'static str> {
        vec!["ball_speed", "launch_angle", "spin"]
    }

    fn observed(&self, r: &Drive) -> Vec<Option<f64>> {
        let o = observed(r);
        vec![o.map(|o| o[0]), o.map(|o| o[1]), o.map(|o| o[3])]
    }

    fn sigma(&self, r: &Drive) -> Vec<f64> {
        let o = observed(r).unwrap_or([1.0; 5]);
        vec![
            BALL_SPEED_SIGMA_REL * o[0],
            LAUNCH_SIGMA_DEG,
            SPIN_SIGMA_REL * o[3],
        ]
    }

    fn label(&self, r: &Drive) -> String {
        format!("drive {}", r.index)
    }

    fn predict(&self, p: &[f64], r: &Drive) -> Result<Vec<f64>, String> {
        let p = predict(
            r,
            super::impact::law(p, self.initial.friction),
            self.use_location,
            self.typical,
        )?;
        Ok(vec![p[0], p[1], p[3]])
    }
}

/// The compliant contact of `p` (in [`PARAMETERS`] order) with `friction`.
#[must_use]
pub fn compliant(p: &[f64], friction: f64) -> CompliantContact<f64> {
    let at = |i: usize| p.get(i).copied().unwrap_or(f64::NAN);
    CompliantContact {
        friction,
        tangential_restitution: at(0),
        tangential_restitution_slope: at(1),
        tangential_restitution_max: at(2),
        restitution_speed_slope_spm: at(3),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use carry_core::presets::FITTED_CONTACT;

    #[test]
    fn the_dplane_share_recovers_a_known_share() {
        let pairs: Vec<(f64, f64)> = [-10.0, -3.0, 2.0, 8.0]
            .iter()
            .map(|&m: &f64| (m, to_deg((0.5 * deg(m).tan()).atan())))
            .collect();
        let Some(k) = fit_dplane_share(&pairs) else {
            panic!("k")
        };
        assert!((k - 0.5).abs() < 1e-6, "{k}");
        assert!((AxisLaw::DPlaneShare(0.5).apply(8.0) - pairs[3].1).abs() < 1e-12);
        assert!((AxisLaw::Physics.apply(8.0) - 8.0).abs() < f64::EPSILON);
        assert_eq!(fit_dplane_share(&[]), None);
    }

    /// A square, centred delivery has no axis and no direction; an open face to the path
    /// tilts the axis right, a toe strike left (gear effect).
    #[test]
    fn the_drive_model_has_the_signs_of_trackman() {
        let club = [45.0, 0.0, 0.0, 13.0, 0.0];
        let drive = |face: f64, toe: f64| {
            let mut d = Drive {
                index: 0,
                ball: crate::drives::BallKind::Premium,
                club: crate::drives::ClubMeasured::default(),
                launch: crate::drives::LaunchMeasured::default(),
                flight: crate::drives::FlightMeasured::default(),
                strike_m: Some([toe, 0.005]),
            };
            d.club.club_speed_mps = Some(club[0]);
            d.club.attack_angle_deg = Some(club[1]);
            d.club.club_path_deg = Some(club[2]);
            d.club.dynamic_loft_deg = Some(club[3]);
            d.club.face_angle_deg = Some(face);
            d
        };
        let at = |face: f64, toe: f64| {
            predict(&drive(face, toe), FITTED_CONTACT, true, [0.0, 0.005]).unwrap_or([f64::NAN; 5])
        };
        let square = at(0.0, 0.0);
        assert!(
            square[4].abs() < 0.2 && square[2].abs() < 0.05,
            "{square:?}"
        );
        assert!(at(2.0, 0.0)[4] > 3.0, "{:?}", at(2.0, 0.0));
        assert!(at(0.0, 0.02)[4] < -3.0, "{:?}", at(0.0, 0.02));
    }
}
