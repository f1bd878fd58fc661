//! The empirical D-plane share of the spin axis (issue 34; docs/impact.md §0.8): a named
//! empirical law beside the physics, never a default ([`crate::ClubSpec::spin_axis_share`]).
//!
//! On an amateur's 4,131 TrackMan drives the measured spin axis answers face-to-path about
//! half as much as the impact model's (1.84°/° against 3.3°/°), the share moving from
//! session to session (0.3–0.8); none of the physical mechanisms tested (head yaw over the
//! measured MOI and CG depths, the shaft, friction, bulge, two-direction compliance, where
//! the face is read) reproduces it. With share `k` the launch's spin axis `a`
//! (PHYSICS.md: `tan a = sidespin/backspin`) becomes `tan a' = k·tan a`, with the spin's
//! magnitude and its component along the horizontal launch direction kept:
//!
//! ```text
//! b = Ω·(−sin ψ, 0, cos ψ),  s = −Ω_y,  r = Ω·(cos ψ, 0, sin ψ)      (ψ: launch direction)
//! m = √(b² + s²),  D = √(b² + k²s²),  b' = m·b/D,  s' = m·k·s/D
//! Ω' = b'·(−sin ψ, 0, cos ψ) + (0, −s', 0) + r·(cos ψ, 0, sin ψ)
//! ```
//!
//! No trigonometry: `sin ψ`, `cos ψ` from the velocity's horizontal components. `k = 1` is
//! not computed at all (the impact's own ball, bit for bit).

use crate::real::Real;
use nalgebra::Vector3;

/// Scales the spin axis' tangent of a ball leaving with velocity `velocity_mps` and spin
/// `spin_radps` by `share`, the spin in place (see the module docs); nothing changes for
/// `share = 1`, for a ball without back- or sidespin, and for one launched straight up
/// (no launch direction). Out of line and in place: the impact's frame, which the
/// estimator's forward model stacks deep, holds no copy for it.
#[inline(never)]
pub fn apply<T: Real>(share: T, velocity_mps: &Vector3<T>, spin_radps: &mut Vector3<T>) {
    let v = velocity_mps;
    let w = *spin_radps;
    let horizontal = (v.x * v.x + v.z * v.z).root();
    #[allow(clippy::float_cmp)]
    if share == T::one() || !(horizontal > T::zero()) {
        return;
    }
    let (sin_psi, cos_psi) = (v.z / horizontal, v.x / horizontal);
    let back = -w.x * sin_psi + w.z * cos_psi;
    let side = -w.y;
    let along = w.x * cos_psi + w.z * sin_psi;
    let magnitude = (back * back + side * side).root();
    let shared_side = share * side;
    let d = (back * back + shared_side * shared_side).root();
    if !(d > T::zero()) {
        return;
    }
    let back = magnitude * (back / d);
    let side = magnitude * (shared_side / d);
    *spin_radps = Vector3::new(
        -back * sin_psi + along * cos_psi,
        -side,
        back * cos_psi + along * sin_psi,
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::BallMotion;
    use crate::launch::LaunchMetrics;

    fn ball(direction_deg: f64, back: f64, side: f64, along: f64) -> BallMotion<f64> {
        let psi = direction_deg.to_radians();
        let (s, c) = psi.sin_cos();
        BallMotion {
            velocity_mps: Vector3::new(60.0 * c, 12.0, 60.0 * s),
            spin_radps: Vector3::new(-back * s + along * c, -side, back * c + along * s),
        }
    }

    #[test]
    fn scales_the_axis_tangent_and_keeps_the_spin() {
        for (dir, back, side, along) in [
            (0.0, 280.0, 60.0, 0.0),
            (4.0, 250.0, -90.0, 3.0),
            (-7.0, 300.0, 200.0, -5.0),
            (2.0, -20.0, 50.0, 1.0),
        ] {
            let b = ball(dir, back, side, along);
            for k in [0.25, 0.5, 0.9] {
                let mut out = b;
                apply(k, &b.velocity_mps, &mut out.spin_radps);
                let before = LaunchMetrics::from_motion(&b, 45.0);
                let after = LaunchMetrics::from_motion(&out, 45.0);
                assert!(
                    (after.spin_axis_rad.tan() - k * before.spin_axis_rad.tan()).abs()
                        < 1e-12 * (1.0 + before.spin_axis_rad.tan().abs()),
                    "{dir} {back} {side} {k}"
                );
                assert!((after.spin_radps - before.spin_radps).abs() < 1e-12 * before.spin_radps);
                // with backspin the axis only tilts back toward upright
                assert!(back < 0.0 || after.spin_axis_rad.abs() <= before.spin_axis_rad.abs());
                assert_eq!(out.velocity_mps, b.velocity_mps);
                let along_after = out.spin_radps.x * dir.to_radians().cos()
                    + out.spin_radps.z * dir.to_radians().sin();
                assert!((along_after - along).abs() < 1e-9);
            }
        }
    }

    #[test]
    fn share_one_and_degenerate_balls_are_untouched() {
        let untouched = |k: f64, b: BallMotion<f64>| {
            let mut out = b;
            apply(k, &b.velocity_mps, &mut out.spin_radps);
            out == b
        };
        assert!(untouched(1.0, ball(3.0, 280.0, 60.0, 2.0)));
        assert!(untouched(0.5, ball(3.0, 0.0, 0.0, 5.0)));
        let up = BallMotion {
            velocity_mps: Vector3::new(0.0, 30.0, 0.0),
            spin_radps: Vector3::new(1.0, 2.0, 3.0),
        };
        assert!(untouched(0.5, up));
    }
}
