//! Table rows as averages of shots (issue 35): the carry of the average launch is not the
//! average carry.
//!
//! TrackMan's tour table lists, per club, the *average* ball speed, launch and spin and the
//! *average* carry, apex and landing angle of many shots. Carry is nonlinear in the launch
//! (concave near its optimum), so `E[carry(v, θ, ω, α)] ≠ carry(E v, E θ, E ω, E α)`
//! (Jensen's inequality). This module flies a row as the expectation over a spread of
//! launches around its listed one:
//!
//! ```text
//! v = v̄·(1 + x₀),  θ = θ̄ + x₁,  ω = ω̄·(1 + x₂),  α = ᾱ + x₃        x ~ N(0, Σ)
//! E[q] ≈ Σ_k w_k · q(x_k),   x_k = L·z_k,   Σ = L·Lᵀ (Cholesky)
//! ```
//!
//! with `z_k` the tensor product of the 3-point Gauss–Hermite rule in each of the four
//! dimensions (81 flights a row; exact for every polynomial of degree ≤ 5 in each `z`), `α`
//! the spin axis (backspin `ω cos α`, sidespin `ω sin α`). The launch direction is left out:
//! in still air a turned launch turns the whole flight and leaves carry, apex, landing angle
//! and flight time as they are.
//!
//! The spread Σ is measured, not fitted: [`LaunchSpread::of_drives`] pools the
//! within-session covariance of the single drives' launches (`carry_lab::drives`, premium
//! ball, indoors; deviations from each session's mean), so correlations between ball
//! speed, launch and spin are kept. [`AveragedAeroProblem`] evaluates (and can fit) the
//! table rows (rows without a session) this way and every single drive as flown.

use carry_core::aero::AeroModel;
use carry_core::flight::Integrator;

use super::flight::{AeroProblem, ShotRow, predict_in_wind};
use crate::drives::{BallKind, Drive};

/// Nodes and weights of the 3-point Gauss–Hermite rule for a standard normal.
const RULE: [(f64, f64); 3] = [
    (-1.732_050_807_568_877_2, 1.0 / 6.0),
    (0.0, 2.0 / 3.0),
    (1.732_050_807_568_877_2, 1.0 / 6.0),
];

/// Drives further than this many robust standard deviations from their session's median
/// in any launch dimension are mishits, left out of [`LaunchSpread::of_drives`].
pub const SCREEN_ROBUST_SIGMA: f64 = 3.0;

/// The median of `values` (NaN-free; 0 for none).
fn median(values: impl Iterator<Item = f64>) -> f64 {
    let mut v: Vec<f64> = values.collect();
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f64::total_cmp);
    let h = v.len() / 2;
    if v.len() % 2 == 1 {
        v[h]
    } else {
        0.5 * (v[h - 1] + v[h])
    }
}

/// The spread's dimensions, in order.
pub const SPREAD_NAMES: [&str; 4] = [
    "ball speed (rel.)",
    "launch (°)",
    "spin (rel.)",
    "spin axis (°)",
];

/// A normal spread of launches around a row's: ball speed and spin relative, launch angle
/// and spin axis in degrees; `covariance` over [`SPREAD_NAMES`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LaunchSpread {
    /// The covariance Σ of `(Δv/v̄, Δθ °, Δω/ω̄, Δα °)`.
    pub covariance: [[f64; 4]; 4],
}

impl LaunchSpread {
    /// No spread: every row flown from its listed launch.
    pub const NONE: Self = Self {
        covariance: [[0.0; 4]; 4],
    };

    /// Independent normal scatter with these standard deviations.
    #[must_use]
    pub fn independent(speed_rel: f64, launch_deg: f64, spin_rel: f64, axis_deg: f64) -> Self {
        let s = [speed_rel, launch_deg, spin_rel, axis_deg];
        let mut covariance = [[0.0; 4]; 4];
        for (i, x) in s.iter().enumerate() {
            covariance[i][i] = x * x;
        }
        Self { covariance }
    }

    /// The standard deviations.
    #[must_use]
    pub fn sigma(&self) -> [f64; 4] {
        core::array::from_fn(|i| self.covariance[i][i].max(0.0).sqrt())
    }

    /// The correlation coefficient of dimensions `i` and `j` (0 where either has no spread).
    #[must_use]
    pub fn correlation(&self, i: usize, j: usize) -> f64 {
        let s = self.sigma();
        if s[i] > 0.0 && s[j] > 0.0 {
            self.covariance[i][j] / (s[i] * s[j])
        } else {
            0.0
        }
    }

    /// The same correlations with every standard deviation times `factor`.
    #[must_use]
    pub fn scaled(&self, factor: f64) -> Self {
        Self {
            covariance: self.covariance.map(|r| r.map(|c| c * factor * factor)),
        }
    }

    /// The pooled within-session covariance of the single drives' launches: premium ball,
    /// tracked indoors, a complete launch ([`Drive::full_launch`]) at ≥ 1°; each drive's
    /// deviation from its session's median (ball speed and spin relative to it). Mishits
    /// (tops, thin and heel/toe strikes) are screened out as outliers: a drive more than
    /// [`SCREEN_ROBUST_SIGMA`] robust σ (1.4826 × the session's median absolute deviation)
    /// from the median in any dimension is dropped; the rest's deviations from their mean are
    /// summed over sessions and divided by `N − sessions`. `None` with fewer than two drives
    /// a session.
    #[must_use]
    pub fn of_drives(drives: &[Drive]) -> Option<Self> {
        let mut by_session: Vec<Vec<[f64; 4]>> = Vec::new();
        for d in drives {
            if d.ball != BallKind::Premium || d.tracked_outdoors() {
                continue;
            }
            let Some(l) = d.full_launch() else { continue };
            if l[1] < 1.0 {
                continue;
            }
            let s = d.session();
            if by_session.len() <= s {
                by_session.resize(s + 1, Vec::new());
            }
            by_session[s].push([l[0], l[1], l[3], l[4]]);
        }
        let (mut sum, mut n, mut groups) = ([[0.0; 4]; 4], 0usize, 0usize);
        for shots in by_session.iter().filter(|s| s.len() >= 2) {
            let centre: [f64; 4] = core::array::from_fn(|k| median(shots.iter().map(|l| l[k])));
            // Deviations: ball speed and spin relative to the session's median.
            let dev = |l: &[f64; 4]| -> [f64; 4] {
                [
                    l[0] / centre[0] - 1.0,
                    l[1] - centre[1],
                    l[2] / centre[2] - 1.0,
                    l[3] - centre[3],
                ]
            };
            let mad: [f64; 4] =
                core::array::from_fn(|k| 1.4826 * median(shots.iter().map(|l| dev(l)[k].abs())));
            let kept: Vec<[f64; 4]> = shots
                .iter()
                .map(dev)
                .filter(|x| (0..4).all(|k| x[k].abs() <= SCREEN_ROBUST_SIGMA * mad[k]))
                .collect();
            if kept.len() < 2 {
                continue;
            }
            #[allow(clippy::cast_precision_loss)]
            let m = kept.len() as f64;
            let mean: [f64; 4] =
                core::array::from_fn(|k| kept.iter().map(|x| x[k]).sum::<f64>() / m);
            for x in &kept {
                for i in 0..4 {
                    for j in 0..4 {
                        sum[i][j] += (x[i] - mean[i]) * (x[j] - mean[j]);
                    }
                }
            }
            n += kept.len();
            groups += 1;
        }
        if groups == 0 || n <= groups {
            return None;
        }
        #[allow(clippy::cast_precision_loss)]
        let dof = (n - groups) as f64;
        Some(Self {
            covariance: sum.map(|r| r.map(|c| c / dof)),
        })
    }

    /// The lower Cholesky factor `L` (`Σ = L·Lᵀ`); a dimension without spread (or
    /// dependent on the others) gets a zero column.
    fn cholesky(&self) -> [[f64; 4]; 4] {
        let a = &self.covariance;
        let mut l = [[0.0; 4]; 4];
        for j in 0..4 {
            let d = a[j][j] - (0..j).map(|k| l[j][k] * l[j][k]).sum::<f64>();
            if d <= 1e-18 * a[j][j].abs().max(1e-300) || d <= 0.0 {
                continue;
            }
            l[j][j] = d.sqrt();
            for i in j + 1..4 {
                l[i][j] = (a[i][j] - (0..j).map(|k| l[i][k] * l[j][k]).sum::<f64>()) / l[j][j];
            }
        }
        l
    }

    /// The quadrature: `(weight, deviation)` pairs, 81 of them (1 without spread).
    #[must_use]
    pub fn nodes(&self) -> Vec<(f64, [f64; 4])> {
        if self.covariance == Self::NONE.covariance {
            return vec![(1.0, [0.0; 4])];
        }
        let l = self.cholesky();
        let mut out = Vec::with_capacity(81);
        for a in RULE {
            for b in RULE {
                for c in RULE {
                    for d in RULE {
                        let z = [a.0, b.0, c.0, d.0];
                        let x = core::array::from_fn(|i| (0..4).map(|k| l[i][k] * z[k]).sum());
                        out.push((a.1 * b.1 * c.1 * d.1, x));
                    }
                }
            }
        }
        out
    }
}

/// `row`'s launch moved by `x` (a deviation over [`SPREAD_NAMES`]).
#[must_use]
pub fn deviated(row: &ShotRow, x: [f64; 4]) -> ShotRow {
    let mut r = row.clone();
    let l = &mut r.launch;
    let spin = l.backspin_radps.hypot(l.sidespin_radps) * (1.0 + x[2]);
    let axis = l.sidespin_radps.atan2(l.backspin_radps) + x[3].to_radians();
    l.ball_speed_mps *= 1.0 + x[0];
    l.launch_angle_rad += x[1].to_radians();
    l.backspin_radps = spin * axis.cos();
    l.sidespin_radps = spin * axis.sin();
    r
}

/// The expected carry, apex, landing angle, flight time and side of `row` over `spread`
/// (the quadrature above; the flight of the listed launch with [`LaunchSpread::NONE`]).
///
/// # Errors
/// A deviated launch the core cannot fly.
pub fn averaged_predict(
    model: &AeroModel<f64>,
    row: &ShotRow,
    spread: &LaunchSpread,
    integrator: &Integrator<f64>,
) -> Result<[f64; 5], String> {
    let mut sum = [0.0; 5];
    for (w, x) in spread.nodes() {
        let r = deviated(row, x);
        let q = predict_in_wind(model, &r.launch, &r.air, r.wind_mps, integrator)?;
        for (s, v) in sum.iter_mut().zip(q) {
            *s += w * v;
        }
    }
    Ok(sum)
}

/// An [`AeroProblem`] whose table rows (rows without a session) are flown as averages over
/// `spread` ([`averaged_predict`]); single drives (rows with a session) are single shots and
/// flown as they are. Use it with [`super::evaluate`] (or [`super::fit`]: 81 flights a table
/// row).
#[derive(Debug, Clone)]
pub struct AveragedAeroProblem {
    /// The family, start, bounds and integrator.
    pub inner: AeroProblem,
    /// The spread of launches behind every table row.
    pub spread: LaunchSpread,
}

impl super::Problem for AveragedAeroProblem {
    type Row = ShotRow;

    fn parameter_names(&self) -> Vec<&'static str> {
        self.inner.parameter_names()
    }

    fn bounds(&self) -> Vec<(f64, f64)> {
        self.inner.bounds()
    }

    fn initial(&self) -> Vec<f64> {
        self.inner.initial()
    }

    fn quantity_names(&self) -> Vec<&'static str> {
        self.inner.quantity_names()
    }

    fn observed(&self, r: &ShotRow) -> Vec<Option<f64>> {
        self.inner.observed(r)
    }

    fn sigma(&self, r: &ShotRow) -> Vec<f64> {
        self.inner.sigma(r)
    }

    fn label(&self, r: &ShotRow) -> String {
        self.inner.label(r)
    }

    fn group(&self, r: &ShotRow) -> Option<usize> {
        self.inner.group(r)
    }

    fn weight(&self, r: &ShotRow) -> f64 {
        self.inner.weight(r)
    }

    fn predict(&self, p: &[f64], r: &ShotRow) -> Result<Vec<f64>, String> {
        if r.session.is_some() {
            return self.inner.predict(p, r);
        }
        averaged_predict(
            &self.inner.family.model(p),
            r,
            &self.spread,
            &self.inner.integrator,
        )
        .map(Vec::from)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use carry_core::Launch;
    use carry_core::air::Air;
    use carry_core::units::{deg, rpm};

    fn row(speed_mps: f64, launch_deg: f64, spin_rpm: f64) -> ShotRow {
        ShotRow {
            label: "test".into(),
            launch: Launch {
                ball_speed_mps: speed_mps,
                launch_angle_rad: deg(launch_deg),
                launch_direction_rad: 0.0,
                backspin_radps: rpm(spin_rpm),
                sidespin_radps: 0.0,
            },
            air: Air::Density(1.2),
            carry_m: 200.0,
            apex_m: None,
            land_angle_deg: None,
            flight_time_s: None,
            side_m: None,
            weight: 1.0,
            wind_mps: [0.0; 3],
            session: None,
        }
    }

    #[test]
    fn the_rule_has_the_spreads_moments() {
        let s = LaunchSpread {
            covariance: [
                [4e-4, 0.01, -1e-3, 0.0],
                [0.01, 4.0, 0.05, 0.3],
                [-1e-3, 0.05, 0.04, 0.0],
                [0.0, 0.3, 0.0, 25.0],
            ],
        };
        let nodes = s.nodes();
        assert_eq!(nodes.len(), 81);
        let total: f64 = nodes.iter().map(|n| n.0).sum();
        assert!((total - 1.0).abs() < 1e-14);
        for i in 0..4 {
            let mean: f64 = nodes.iter().map(|(w, x)| w * x[i]).sum();
            assert!(mean.abs() < 1e-14, "{i}: {mean}");
            for j in 0..4 {
                let c: f64 = nodes.iter().map(|(w, x)| w * x[i] * x[j]).sum();
                let want = s.covariance[i][j];
                assert!(
                    (c - want).abs() < 1e-12 * want.abs().max(1.0),
                    "{i}{j}: {c} {want}"
                );
            }
        }
        assert!((s.correlation(0, 1) - 0.25).abs() < 1e-12);
        assert_eq!(s.scaled(0.5).sigma()[1], 1.0);
    }

    #[test]
    fn no_spread_is_the_listed_launch_and_a_spread_shortens_a_drive() {
        let model = AeroModel::default();
        let integrator = Integrator::dormand_prince(1e-10);
        let r = row(70.0, 12.0, 2600.0);
        let single = predict_in_wind(&model, &r.launch, &r.air, [0.0; 3], &integrator).unwrap();
        let none = averaged_predict(&model, &r, &LaunchSpread::NONE, &integrator).unwrap();
        assert_eq!(single, none);
        // Carry is concave in launch angle and spin axis around a drive's launch: the
        // average of carries is shorter than the carry of the average launch.
        let spread = LaunchSpread::independent(0.0, 2.0, 0.0, 6.0);
        let avg = averaged_predict(&model, &r, &spread, &integrator).unwrap();
        assert!(avg[0] < single[0] - 0.05, "{} {}", avg[0], single[0]);
        assert!(avg[0] > 0.98 * single[0], "{} {}", avg[0], single[0]);
        // A symmetric spread of the axis averages the side to zero.
        assert!(avg[4].abs() < 0.05, "{}", avg[4]);
    }

    #[test]
    fn a_tilted_axis_keeps_the_total_spin() {
        let r = row(60.0, 14.0, 3000.0);
        let d = deviated(&r, [0.1, 1.0, -0.2, 30.0]);
        let l = d.launch;
        assert!((l.ball_speed_mps - 66.0).abs() < 1e-12);
        assert!((l.launch_angle_rad - deg(15.0)).abs() < 1e-12);
        assert!((l.backspin_radps.hypot(l.sidespin_radps) - rpm(2400.0)).abs() < 1e-9);
        assert!((l.sidespin_radps.atan2(l.backspin_radps) - deg(30.0)).abs() < 1e-12);
    }
}
