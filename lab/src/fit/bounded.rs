//! Bounds by reparametrisation: the optimiser moves an unbounded `θ`, the model sees
//! `p = lo + (hi − lo)·σ(θ)` with the logistic `σ(θ) = 1/(1 + e^(−θ))`, so every trial
//! point is physical and the bounds are never active constraints the optimiser must
//! handle (a standard transformation, e.g. MINUIT's for bounded parameters).

/// `p(θ)` for bounds `(lo, hi)`.
#[must_use]
pub fn to_bounded(theta: f64, (lo, hi): (f64, f64)) -> f64 {
    lo + (hi - lo) / (1.0 + (-theta).exp())
}

/// `θ(p)`, with `p` pulled strictly inside the bounds (a point on a bound maps to a large
/// finite `θ`).
#[must_use]
pub fn to_unbounded(p: f64, (lo, hi): (f64, f64)) -> f64 {
    let margin = (hi - lo) * 1e-9;
    let p = p.clamp(lo + margin, hi - margin);
    ((p - lo) / (hi - p)).ln()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_and_stays_inside() {
        for b in [(0.0, 1.0), (0.1, 0.5), (-3.0, 2.0)] {
            for p in [b.0 + 0.01, 0.5 * (b.0 + b.1), b.1 - 0.01] {
                assert!((to_bounded(to_unbounded(p, b), b) - p).abs() < 1e-12);
            }
            for theta in [-800.0, -5.0, 0.0, 5.0, 800.0] {
                let p = to_bounded(theta, b);
                assert!(p >= b.0 && p <= b.1);
            }
        }
    }
}
