//! Rotations and small vector helpers (PHYSICS.md conventions: active rotations).

use crate::real::{Real, lit};
use nalgebra::{Matrix3, Vector3};

/// `(sin x, cos x)`.
///
/// In single precision and for `|x| ≤ π/4` (every delivery and launch angle in practice) it
/// evaluates Cephes' single-precision minimax polynomials (S. L. Moshier, Cephes Math
/// Library, `sinf.c`/`cosf.c`; about 1 ulp on that interval) in f32: `libm`'s `sincosf`
/// evaluates its kernel in f64, which a Cortex-M4F does in software (docs/firmware.md
/// compares the two). In double precision, or for larger angles, it is `libm`'s `sin_cos`.
/// Deterministic either way: the same bits on every target.
#[inline]
#[must_use]
pub fn sin_cos<T: Real>(x: T) -> (T, T) {
    let single = T::default_epsilon() > lit(1e-10);
    if single && x.abs() <= T::frac_pi_4() {
        let z = x * x;
        let sin = ((lit::<T>(-1.951_529_589_1e-4) * z + lit(8.332_160_873_6e-3)) * z
            - lit(1.666_665_461_1e-1))
            * z
            * x
            + x;
        let cos = ((lit::<T>(2.443_315_711_809_948e-5) * z - lit(1.388_731_625_493_765e-3)) * z
            + lit(4.166_664_568_298_827e-2))
            * z
            * z
            - lit::<T>(0.5) * z
            + T::one();
        (sin, cos)
    } else {
        x.sin_cos()
    }
}

/// `(sin x, cos x)` for angles that are usually small (a crater tilt), in both precisions:
/// for `|x| ≤ π/4`, Cephes' minimax polynomials (S. L. Moshier, Cephes Math Library,
/// `sin.c` in double precision, about 1 ulp; [`sin_cos`]'s single-precision ones in `f32`);
/// otherwise libm. libm's double `sincos` reduces the argument first, a long dependency
/// chain (docs/ground.md). Not used on the golden impact path, whose `f64` rotations stay
/// libm's.
#[inline]
#[must_use]
pub fn sin_cos_small<T: Real>(x: T) -> (T, T) {
    let single = T::default_epsilon() > lit(1e-10);
    if single || !(x.abs() <= T::frac_pi_4()) {
        return sin_cos(x);
    }
    const SIN: [f64; 6] = [
        1.5896230157654656e-10,
        -2.5050747762857807e-08,
        2.7557313621385722e-06,
        -0.0001984126982958954,
        0.008333333333322118,
        -0.1666666666666663,
    ];
    const COS: [f64; 6] = [
        -1.1358536521387682e-11,
        2.087570084197473e-09,
        -2.755731417929674e-07,
        2.4801587288851704e-05,
        -0.0013888888888873056,
        0.041666666666666595,
    ];
    let z = x * x;
    let sin = x + x * z * estrin6(&SIN, z);
    let cos = T::one() - lit::<T>(0.5) * z + z * z * estrin6(&COS, z);
    (sin, cos)
}

/// `c₀z⁵ + c₁z⁴ + … + c₅` (coefficients highest power first) by Estrin's scheme: three
/// independent pairs, then `z²` and `z⁴` combine them, so the dependency chain is three
/// multiply–adds deep instead of Horner's six (the bounce waits on it).
#[inline(always)]
fn estrin6<T: Real>(c: &[f64; 6], z: T) -> T {
    let pair = |hi: f64, lo: f64| lit::<T>(hi) * z + lit(lo);
    let z2 = z * z;
    let (p01, p23, p45) = (pair(c[0], c[1]), pair(c[2], c[3]), pair(c[4], c[5]));
    (p01 * z2 + p23) * z2 + p45
}

/// Abramowitz & Stegun (1964), *Handbook of Mathematical Functions*, 4.4.49: the
/// coefficients `a₁, a₃, …, a₁₅` of `atan z ≈ z·(a₁ + a₃z² + … + a₁₅z¹⁴)` on `0 ≤ z ≤ 1`.
const ATAN_A: [f64; 8] = [
    0.999_999_332_9,
    -0.333_298_560_5,
    0.199_465_359_9,
    -0.139_085_335_1,
    0.096_420_044_1,
    -0.055_909_886_1,
    0.021_861_228_8,
    -0.004_054_058_0,
];

/// `atan2(y, x)` for `y, x ≥ 0` (the first quadrant, `0..=π/2`), by the polynomial of
/// Abramowitz & Stegun (1964), *Handbook of Mathematical Functions*, 4.4.49:
///
/// ```text
/// atan z ≈ z·(a₁ + a₃z² + … + a₁₅z¹⁴),  0 ≤ z ≤ 1,  |ε| ≤ 2·10⁻⁸ rad
/// ```
///
/// on `z = min/max` of the two, reflected through `π/2 − atan(1/z)` when `y > x` (within
/// 4·10⁻⁸ rad of libm, rounding included; 3·10⁻⁷ in `f32`). One division and eight
/// multiply–adds, where libm's `atan2f` is a long call on a Cortex-M4F (docs/ground.md).
/// `0` for `(0, 0)`; NaN in, NaN out.
#[inline]
#[must_use]
pub fn atan2_first_quadrant<T: Real>(y: T, x: T) -> T {
    reflected(y, x, |z| z * atan_over_z(z * z))
}

/// [`atan2_first_quadrant`] of `y, x ≥ 0` from their squares `y²`, `x²` (same polynomial,
/// within 4·10⁻⁸ rad of libm): `z² = min/max` of the squares is one division, and `z = √z²`
/// runs beside the polynomial in `z²` instead of before it (the bounce waits on the
/// angle; docs/ground.md). For squares that neither underflow to zero nor overflow
/// (`|y|, |x|` within about `10^±150` in `f64`; the core's speeds are). `0` for `(0, 0)`;
/// NaN in, NaN out.
#[inline]
#[must_use]
pub(crate) fn atan2_first_quadrant_of_squares<T: Real>(y_sq: T, x_sq: T) -> T {
    // y² > x² exactly when y > x for y, x ≥ 0: the same reflection on the squares
    reflected(y_sq, x_sq, |z_sq| z_sq.root() * atan_over_z(z_sq))
}

/// The first quadrant's angle of `(a, b)` (both `y, x` or both their squares): `angle` of
/// the ratio `min/max`, reflected through `π/2 − angle` when `a > b`; `0` for `(0, 0)`, NaN
/// in, NaN out.
#[inline(always)]
fn reflected<T: Real>(a: T, b: T, angle: impl Fn(T) -> T) -> T {
    let steep = a > b;
    let (num, den) = if steep { (b, a) } else { (a, b) };
    if !(den > T::zero()) {
        return if num.partial_cmp(&den).is_none() {
            num + den
        } else {
            T::zero()
        };
    }
    let angle = angle(num / den);
    if steep { T::frac_pi_2() - angle } else { angle }
}

/// `atan(z)/z` for `0 ≤ z ≤ 1` from `z²`: A&S 4.4.49's degree-7 polynomial in `z²` by
/// Estrin's scheme (four independent pairs, then `z⁴` and `z⁸`), four multiply–adds deep
/// instead of Horner's seven.
#[inline(always)]
fn atan_over_z<T: Real>(z2: T) -> T {
    let z4 = z2 * z2;
    let pair = |i: usize| lit::<T>(ATAN_A[i + 1]) * z2 + lit(ATAN_A[i]);
    let low = pair(2) * z4 + pair(0);
    let high = pair(6) * z4 + pair(4);
    high * (z4 * z4) + low
}

/// `Rx(θ)`: turns +Y towards +Z.
#[must_use]
pub fn rot_x<T: Real>(theta: T) -> Matrix3<T> {
    let (s, c) = sin_cos(theta);
    let (o, z) = (T::one(), T::zero());
    Matrix3::new(o, z, z, z, c, -s, z, s, c)
}

/// `Ry(θ)`: turns +Z towards +X.
#[must_use]
pub fn rot_y<T: Real>(theta: T) -> Matrix3<T> {
    let (s, c) = sin_cos(theta);
    let (o, z) = (T::one(), T::zero());
    Matrix3::new(c, z, s, z, o, z, -s, z, c)
}

/// `Rz(θ)`: turns +X towards +Y.
#[must_use]
pub fn rot_z<T: Real>(theta: T) -> Matrix3<T> {
    let (s, c) = sin_cos(theta);
    let (o, z) = (T::one(), T::zero());
    Matrix3::new(c, -s, z, s, c, z, z, z, o)
}

/// The cross-product matrix `[r]×`, so that `[r]× v = r × v`.
#[must_use]
pub fn cross_matrix<T: Real>(r: &Vector3<T>) -> Matrix3<T> {
    let z = T::zero();
    Matrix3::new(z, -r.z, r.y, r.z, z, -r.x, -r.y, r.x, z)
}

/// Two unit tangents `t1`, `t2` completing the unit vector `n` to a right-handed
/// orthonormal frame `(n, t1, t2)`.
///
/// Branch-light construction of Duff et al., "Building an orthonormal basis, revisited"
/// (JCGT 6(1), 2017), written for `n` as the first axis. Stable for every unit `n`.
#[must_use]
pub fn tangents<T: Real>(n: &Vector3<T>) -> (Vector3<T>, Vector3<T>) {
    // Frisvad/Duff basis around the z component of a permuted n = (x, y, z) -> (n.y, n.z, n.x)
    // so that (n, t1, t2) is right-handed.
    let (x, y, z) = (n.y, n.z, n.x);
    let sign = if z >= T::zero() { T::one() } else { -T::one() };
    let a = -T::one() / (sign + z);
    let b = x * y * a;
    let u = Vector3::new(T::one() + sign * x * x * a, sign * b, -sign * x);
    let v = Vector3::new(b, sign + y * y * a, -y);
    // Undo the permutation: components (x, y, z) map back to (n.y, n.z, n.x).
    let t1 = Vector3::new(u.z, u.x, u.y);
    let t2 = Vector3::new(v.z, v.x, v.y);
    (t1, t2)
}

/// Largest deviation of `R Rᵀ` from the identity, and `det R`: how far `r` is from a
/// proper rotation.
#[must_use]
pub fn rotation_defect<T: Real>(r: &Matrix3<T>) -> (T, T) {
    let d = r * r.transpose() - Matrix3::identity();
    (d.amax(), r.determinant())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_angle_sin_cos_is_within_two_ulp() {
        for i in 0..=4000 {
            let x = (f64::from(i) / 4000.0 - 0.5) * 2.0 * core::f64::consts::FRAC_PI_4;
            let (s, c) = sin_cos_small(x);
            assert!(
                (s - x.sin()).abs() <= 2.0 * f64::EPSILON * x.sin().abs().max(1e-300),
                "{x}"
            );
            assert!((c - x.cos()).abs() <= 2.0 * f64::EPSILON, "{x}");
        }
        assert_eq!(sin_cos_small(2.0_f64), 2.0_f64.sin_cos());
        assert_eq!(sin_cos_small(0.3_f32), sin_cos(0.3_f32));
    }

    #[test]
    fn first_quadrant_atan2_is_within_its_bound() {
        let mut worst = 0.0_f64;
        for i in 0..=2000 {
            for (y, x) in [(f64::from(i) / 2000.0, 1.0), (1.0, f64::from(i) / 2000.0)] {
                for scale in [1e-30, 0.7, 3.0e4] {
                    let got = atan2_first_quadrant(y * scale, x * scale);
                    worst = worst.max((got - (y * scale).atan2(x * scale)).abs());
                    let single = atan2_first_quadrant((y * scale) as f32, (x * scale) as f32);
                    assert!((f64::from(single) - y.atan2(x)).abs() < 3e-7, "{y} {x}");
                }
            }
        }
        assert!(worst <= 4e-8, "{worst}"); // A&S: 2e-8, plus the rounding
        let mut worst_sq = 0.0_f64;
        for i in 0..=2000 {
            for (y, x) in [(f64::from(i) / 2000.0, 1.0), (1.0, f64::from(i) / 2000.0)] {
                for scale in [1e-30, 0.7, 3.0e4] {
                    let (y, x) = (y * scale, x * scale);
                    let got = atan2_first_quadrant_of_squares(y * y, x * x);
                    worst_sq = worst_sq.max((got - y.atan2(x)).abs());
                    let (ys, xs) = (y as f32, x as f32);
                    if scale > 1.0e-3 {
                        let single = atan2_first_quadrant_of_squares(ys * ys, xs * xs);
                        assert!((f64::from(single) - y.atan2(x)).abs() < 3e-7, "{y} {x}");
                    }
                }
            }
        }
        assert!(worst_sq <= 4e-8, "{worst_sq}");
        assert_eq!(atan2_first_quadrant_of_squares(0.0_f64, 0.0), 0.0);
        assert_eq!(
            atan2_first_quadrant_of_squares(25.0_f64, 0.0),
            core::f64::consts::FRAC_PI_2
        );
        assert!(atan2_first_quadrant_of_squares(f64::NAN, 1.0).is_nan());
        assert_eq!(atan2_first_quadrant(0.0_f64, 0.0), 0.0);
        assert_eq!(
            atan2_first_quadrant(5.0_f64, 0.0),
            core::f64::consts::FRAC_PI_2
        );
        assert!(atan2_first_quadrant(f32::NAN, 1.0).is_nan());
        assert!(atan2_first_quadrant(0.0, f64::NAN).is_nan());
    }

    #[test]
    fn rotations_follow_physics_md() {
        let q = core::f64::consts::FRAC_PI_2;
        let x = Vector3::x();
        let y = Vector3::y();
        let z = Vector3::z();
        assert!((rot_z(q) * x - y).norm() < 1e-15);
        assert!((rot_y(q) * z - x).norm() < 1e-15);
        assert!((rot_x(q) * y - z).norm() < 1e-15);
    }

    #[test]
    fn single_precision_sin_cos_is_within_two_ulp() {
        let n = 20_000;
        let mut worst = 0.0_f64;
        for i in 0..=n {
            let x = -core::f64::consts::FRAC_PI_4
                + core::f64::consts::FRAC_PI_2 * f64::from(i) / f64::from(n);
            let xf = x as f32;
            let (s, c) = sin_cos(xf);
            let (se, ce) = f64::from(xf).sin_cos();
            worst = worst
                .max((f64::from(s) - se).abs())
                .max((f64::from(c) - ce).abs());
        }
        // f32 ulp at 1 is 1.19e-7: within two ulp of the exact value everywhere on [−π/4, π/4]
        assert!(worst <= 2.0 * f64::from(f32::EPSILON), "worst {worst:e}");
        assert!(worst > 0.0, "compared against f64, not itself");
        // outside the interval and in f64: libm
        assert_eq!(sin_cos(1.0_f32), 1.0_f32.sin_cos());
        assert_eq!(sin_cos(0.3_f64), 0.3_f64.sin_cos());
    }

    #[test]
    fn tangents_are_orthonormal_and_right_handed() {
        let dirs = [
            Vector3::new(1.0, 0.0, 0.0),
            Vector3::new(-1.0, 0.0, 0.0),
            Vector3::new(0.0, 1.0, 0.0),
            Vector3::new(0.0, 0.0, -1.0),
            Vector3::new(0.3, -0.5, 0.8),
            Vector3::new(-0.999, 1e-3, 1e-4),
        ];
        for d in dirs {
            let n: Vector3<f64> = d.normalize();
            let (t1, t2) = tangents(&n);
            assert!((t1.norm() - 1.0).abs() < 1e-14);
            assert!((t2.norm() - 1.0).abs() < 1e-14);
            assert!(n.dot(&t1).abs() < 1e-14 && n.dot(&t2).abs() < 1e-14);
            assert!(t1.dot(&t2).abs() < 1e-14);
            assert!((n.cross(&t1) - t2).norm() < 1e-13, "right-handed for {d:?}");
        }
    }
}
