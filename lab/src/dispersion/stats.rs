//! Sample statistics of the landing points: means, SDs, covariance, ellipse, percentiles.

use super::{Dispersion, Ellipse, Noise};
use serde::Serialize;

/// χ²₂(0.95) = −2 ln 0.05: the 95 % quantile of a chi-square with 2 degrees of freedom.
pub const CHI2_2DOF_95: f64 = 5.991_464_547_107_979;

/// Percentiles of a sample (linear interpolation between order statistics).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Percentiles {
    /// Smallest.
    pub min: f64,
    /// 5th percentile.
    pub p5: f64,
    /// 25th.
    pub p25: f64,
    /// Median.
    pub p50: f64,
    /// 75th.
    pub p75: f64,
    /// 95th.
    pub p95: f64,
    /// Largest.
    pub max: f64,
}

/// The `q`-quantile (0..1) of sorted values, linear between order statistics.
fn quantile(sorted: &[f64], q: f64) -> f64 {
    let n = sorted.len();
    if n == 0 {
        return f64::NAN;
    }
    #[allow(clippy::cast_precision_loss)]
    let pos = q * (n - 1) as f64;
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let lo = pos.floor() as usize;
    let hi = (lo + 1).min(n - 1);
    let (a, b) = (
        sorted.get(lo).copied().unwrap_or(f64::NAN),
        sorted.get(hi).copied().unwrap_or(f64::NAN),
    );
    #[allow(clippy::cast_precision_loss)]
    let t = pos - lo as f64;
    a + (b - a) * t
}

impl Percentiles {
    /// The percentiles of `values`.
    #[must_use]
    pub fn of(values: impl Iterator<Item = f64>) -> Self {
        let mut v: Vec<f64> = values.collect();
        v.sort_by(f64::total_cmp);
        Self {
            min: quantile(&v, 0.0),
            p5: quantile(&v, 0.05),
            p25: quantile(&v, 0.25),
            p50: quantile(&v, 0.5),
            p75: quantile(&v, 0.75),
            p95: quantile(&v, 0.95),
            max: quantile(&v, 1.0),
        }
    }
}

/// The mean, shifted by the first value (`x₀ + Σ(xᵢ − x₀)/n`): exact when every value is
/// the same (zero noise reproduces the single shot bit for bit), and better conditioned.
fn mean(v: impl Iterator<Item = f64> + Clone) -> f64 {
    let Some(x0) = v.clone().next() else {
        return f64::NAN;
    };
    let (sum, n) = v.fold((0.0, 0_usize), |(s, n), x| (s + (x - x0), n + 1));
    #[allow(clippy::cast_precision_loss)]
    let n = n.max(1) as f64;
    x0 + sum / n
}

/// The 95 % ellipse of covariance `c` (symmetric 2×2) around `centre`: eigenvalues
/// `λ = (a+d)/2 ± √(((a−d)/2)² + b²)`, major axis at `½·atan2(2b, a−d)`.
#[must_use]
pub fn ellipse(centre: [f64; 2], c: [[f64; 2]; 2]) -> Ellipse {
    let (a, b, d) = (c[0][0], c[0][1], c[1][1]);
    let half_trace = 0.5 * (a + d);
    let r = (0.25 * (a - d) * (a - d) + b * b).sqrt();
    let (l1, l2) = (half_trace + r, (half_trace - r).max(0.0));
    Ellipse {
        centre_m: centre,
        semi_major_m: (CHI2_2DOF_95 * l1).sqrt(),
        semi_minor_m: (CHI2_2DOF_95 * l2).sqrt(),
        angle_deg: (0.5 * (2.0 * b).atan2(a - d)).to_degrees(),
    }
}

/// The statistics of the successful shots `ok` (carry, X, Z), at least 2.
pub(super) fn summarise(shots: usize, seed: u64, noise: Noise, ok: &[[f64; 3]]) -> Dispersion {
    #[allow(clippy::cast_precision_loss)]
    let n = ok.len() as f64;
    let carry_mean = mean(ok.iter().map(|s| s[0]));
    let (mx, mz) = (mean(ok.iter().map(|s| s[1])), mean(ok.iter().map(|s| s[2])));
    let var = |f: &dyn Fn(&[f64; 3]) -> f64| ok.iter().map(f).sum::<f64>() / (n - 1.0);
    let cxx = var(&|s| (s[1] - mx) * (s[1] - mx));
    let czz = var(&|s| (s[2] - mz) * (s[2] - mz));
    let cxz = var(&|s| (s[1] - mx) * (s[2] - mz));
    let ccc = var(&|s| (s[0] - carry_mean) * (s[0] - carry_mean));
    let covariance = [[cxx, cxz], [cxz, czz]];
    Dispersion {
        shots,
        failed_shots: shots - ok.len(),
        seed,
        noise,
        carry_mean_m: carry_mean,
        carry_sd_m: ccc.sqrt(),
        side_mean_m: mz,
        side_sd_m: czz.sqrt(),
        landing_mean_m: [mx, mz],
        covariance_m2: covariance,
        ellipse_95: ellipse([mx, mz], covariance),
        carry_percentiles_m: Percentiles::of(ok.iter().map(|s| s[0])),
        side_percentiles_m: Percentiles::of(ok.iter().map(|s| s[2])),
        landings_m: ok.iter().map(|s| [s[1], s[2]]).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ellipse_of_axis_aligned_covariance() {
        let e = ellipse([0.0, 0.0], [[4.0, 0.0], [0.0, 1.0]]);
        assert!((e.semi_major_m - (CHI2_2DOF_95 * 4.0).sqrt()).abs() < 1e-12);
        assert!((e.semi_minor_m - CHI2_2DOF_95.sqrt()).abs() < 1e-12);
        assert!(e.angle_deg.abs() < 1e-12);
        let e = ellipse([0.0, 0.0], [[1.0, 0.0], [0.0, 4.0]]);
        assert!((e.angle_deg.abs() - 90.0).abs() < 1e-9);
    }

    #[test]
    fn quantiles_interpolate() {
        let p = Percentiles::of([3.0, 1.0, 2.0, 4.0, 5.0].into_iter());
        assert_eq!((p.min, p.p50, p.max), (1.0, 3.0, 5.0));
        assert!((p.p25 - 2.0).abs() < 1e-12 && (p.p5 - 1.2).abs() < 1e-12);
    }
}
