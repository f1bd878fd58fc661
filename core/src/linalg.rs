//! Hand-written dense solvers on fixed-size storage: no allocation, no panics.
//!
//! * [`solve_gauss`]: Gaussian elimination with a choice of pivoting for the full
//!   15×15 impact system, refusing pivots below a scale-aware threshold.
//! * [`solve_spd3`]: Cholesky (LDLᵀ) for the symmetric positive definite 3×3 collision
//!   matrix of the reduced form.

use crate::error::{Error, Result};
use crate::real::{Real, lit};
use nalgebra::{Matrix3, SMatrix, SVector, Vector3};

/// Pivoting strategy of [`solve_gauss`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Pivoting {
    /// No row exchanges (fails on a zero diagonal; for comparison only).
    None,
    /// Partial pivoting: the largest remaining entry of the column.
    Partial,
    /// Rows equilibrated to unit max-norm first, then partial pivoting (scaled partial
    /// pivoting): insensitive to the units the equations are written in.
    #[default]
    Equilibrated,
}

/// Solves `A x = b` in place by Gaussian elimination (Golub & Van Loan, Alg. 3.4.1),
/// overwriting `a` with its reduced form.
///
/// A pivot `|u_kk| ≤ N·ε·max|A|` (after equilibration, when chosen) is treated as zero.
///
/// # Errors
/// [`Error::Singular`] when a pivot falls below the threshold or the result is not finite.
pub fn solve_gauss<T: Real, const N: usize>(
    a: &mut SMatrix<T, N, N>,
    b: &SVector<T, N>,
    pivoting: Pivoting,
) -> Result<SVector<T, N>> {
    // Every element access below goes through `get`/`get_mut` (never `a[(i, j)]`, whose
    // bounds check the optimiser does not always remove): the routine has no panic path
    // by construction, which the no-panic link check (nopanic/, issue 7) relies on.
    let mut x = *b;
    if pivoting == Pivoting::Equilibrated {
        for i in 0..N {
            let mut m = T::zero();
            for j in 0..N {
                let v = at(a, i, j).abs();
                if v > m {
                    m = v;
                }
            }
            if !(m > T::zero()) {
                return Err(Error::Singular);
            }
            let inv = T::one() / m;
            for j in 0..N {
                let v = at(a, i, j) * inv;
                set(a, i, j, v);
            }
            let xi = at_v(&x, i) * inv;
            set_v(&mut x, i, xi);
        }
    }
    let tiny = lit::<T>(N as f64) * T::default_epsilon() * a.amax();
    for k in 0..N {
        let mut p = k;
        if pivoting != Pivoting::None {
            let mut best = at(a, k, k).abs();
            for i in k + 1..N {
                let v = at(a, i, k).abs();
                if v > best {
                    best = v;
                    p = i;
                }
            }
        }
        let pivot = at(a, p, k);
        if !(pivot.abs() > tiny) {
            return Err(Error::Singular);
        }
        if p != k {
            for j in 0..N {
                let (u, v) = (at(a, p, j), at(a, k, j));
                set(a, p, j, v);
                set(a, k, j, u);
            }
            let (u, v) = (at_v(&x, p), at_v(&x, k));
            set_v(&mut x, p, v);
            set_v(&mut x, k, u);
        }
        let inv = T::one() / pivot;
        let xk = at_v(&x, k);
        for i in k + 1..N {
            let f = at(a, i, k) * inv;
            if f == T::zero() {
                continue; // the impact matrix is sparse: skip empty rows
            }
            set(a, i, k, T::zero());
            for j in k + 1..N {
                let akj = at(a, k, j);
                if let Some(aij) = a.get_mut((i, j)) {
                    *aij -= f * akj;
                }
            }
            if let Some(xi) = x.get_mut(i) {
                *xi -= f * xk;
            }
        }
    }
    for k in (0..N).rev() {
        let mut s = at_v(&x, k);
        for j in k + 1..N {
            s -= at(a, k, j) * at_v(&x, j);
        }
        set_v(&mut x, k, s / at(a, k, k));
    }
    if x.iter().all(|v| v.is_finite()) {
        Ok(x)
    } else {
        Err(Error::Singular)
    }
}

/// `a[(i, j)]` without a panic path (zero out of range, which the callers never ask for).
#[inline(always)]
fn at<T: Real, const N: usize>(a: &SMatrix<T, N, N>, i: usize, j: usize) -> T {
    a.get((i, j)).copied().unwrap_or_else(T::zero)
}

/// `a[(i, j)] = v` without a panic path.
#[inline(always)]
fn set<T: Real, const N: usize>(a: &mut SMatrix<T, N, N>, i: usize, j: usize, v: T) {
    if let Some(e) = a.get_mut((i, j)) {
        *e = v;
    }
}

/// `x[i]` without a panic path.
#[inline(always)]
fn at_v<T: Real, const N: usize>(x: &SVector<T, N>, i: usize) -> T {
    x.get(i).copied().unwrap_or_else(T::zero)
}

/// `x[i] = v` without a panic path.
#[inline(always)]
fn set_v<T: Real, const N: usize>(x: &mut SVector<T, N>, i: usize, v: T) {
    if let Some(e) = x.get_mut(i) {
        *e = v;
    }
}

/// Solves `K x = b` for a symmetric positive definite 3×3 `K` by LDLᵀ.
///
/// # Errors
/// [`Error::Singular`] when a pivot `d_i ≤ 3ε·max|K|` (not numerically positive definite).
pub fn solve_spd3<T: Real>(k: &Matrix3<T>, b: &Vector3<T>) -> Result<Vector3<T>> {
    let tiny = lit::<T>(3.0) * T::default_epsilon() * k.amax();
    let d0 = k.m11;
    if !(d0 > tiny) {
        return Err(Error::Singular);
    }
    let l10 = k.m21 / d0;
    let l20 = k.m31 / d0;
    let d1 = k.m22 - l10 * l10 * d0;
    if !(d1 > tiny) {
        return Err(Error::Singular);
    }
    let l21 = (k.m32 - l20 * l10 * d0) / d1;
    let d2 = k.m33 - l20 * l20 * d0 - l21 * l21 * d1;
    if !(d2 > tiny) {
        return Err(Error::Singular);
    }
    // forward: L y = b, diagonal: z = y / d, back: Lᵀ x = z
    let y0 = b.x;
    let y1 = b.y - l10 * y0;
    let y2 = b.z - l20 * y0 - l21 * y1;
    let x2 = y2 / d2;
    let x1 = y1 / d1 - l21 * x2;
    let x0 = y0 / d0 - l10 * x1 - l20 * x2;
    let x = Vector3::new(x0, x1, x2);
    if x.iter().all(|v| v.is_finite()) {
        Ok(x)
    } else {
        Err(Error::Singular)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Matrix4, Vector4};

    #[test]
    fn gauss_solves_a_permuted_system() {
        let a0 = Matrix4::new(
            0.0, 2.0, 1.0, 0.0, //
            1e-3, 0.0, 0.0, 4.0, //
            3.0, 1.0, 0.0, 0.0, //
            0.0, 0.0, 5.0, 1.0,
        );
        let xt = Vector4::new(1.0, -2.0, 3.0, 0.5);
        let b = a0 * xt;
        for piv in [Pivoting::Partial, Pivoting::Equilibrated] {
            let mut a = a0;
            let Ok(x) = solve_gauss(&mut a, &b, piv) else {
                panic!("{piv:?}")
            };
            assert!((x - xt).amax() < 1e-13, "{piv:?}");
        }
        let mut a = a0;
        assert_eq!(
            solve_gauss(&mut a, &b, Pivoting::None),
            Err(Error::Singular)
        );
    }

    #[test]
    fn gauss_reports_singular() {
        let mut a = Matrix3::new(1.0_f32, 2.0, 3.0, 2.0, 4.0, 6.0, 0.0, 1.0, 1.0);
        let b = Vector3::new(1.0, 2.0, 3.0);
        assert_eq!(
            solve_gauss(&mut a, &b, Pivoting::Partial),
            Err(Error::Singular)
        );
        let mut z = Matrix3::<f64>::zeros();
        assert_eq!(
            solve_gauss(&mut z, &Vector3::x(), Pivoting::Equilibrated),
            Err(Error::Singular)
        );
    }

    #[test]
    fn ldlt_matches_gauss() {
        let k = Matrix3::new(4.0, 1.0, -0.5, 1.0, 3.0, 0.2, -0.5, 0.2, 2.0);
        let b = Vector3::new(1.0, -1.0, 0.5);
        let Ok(x) = solve_spd3(&k, &b) else { panic!() };
        assert!((k * x - b).amax() < 1e-15);
        let not_pd = Matrix3::new(1.0, 2.0, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0, 1.0);
        assert_eq!(solve_spd3(&not_pd, &b), Err(Error::Singular));
    }
}
