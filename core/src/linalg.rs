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
/// Column-oriented on nalgebra's column-major storage: the updates run down contiguous
/// columns, and a column whose entry in the pivot row is zero is skipped whole (the impact
/// matrix is sparse: most pivot rows touch two or three columns). A pivot
/// `|u_kk| ≤ N·ε·max|A|` (after equilibration, when chosen) is treated as zero.
///
/// Every access goes through slices, iterators, `get` and `split_at_mut_checked`: the
/// routine has no panic path by construction, which the no-panic link check (`nopanic/`)
/// relies on.
///
/// # Errors
/// [`Error::Singular`] when a pivot falls below the threshold or the result is not finite.
pub fn solve_gauss<T: Real, const N: usize>(
    a: &mut SMatrix<T, N, N>,
    b: &SVector<T, N>,
    pivoting: Pivoting,
) -> Result<SVector<T, N>> {
    let mut x = *b;
    let xs = x.as_mut_slice();
    let cols = a.as_mut_slice();
    // max|A|: after row equilibration every row's largest entry is 1 (to rounding)
    let largest = if pivoting == Pivoting::Equilibrated {
        equilibrate_rows::<T, N>(cols, xs)?;
        T::one()
    } else {
        cols.iter()
            .fold(T::zero(), |m, v| if v.abs() > m { v.abs() } else { m })
    };
    let tiny = lit::<T>(N as f64) * T::default_epsilon() * largest;
    for k in 0..N {
        // columns 0..=k on the left (column k last), the trailing columns on the right
        let (left, right) = cols
            .split_at_mut_checked((k + 1) * N)
            .ok_or(Error::Singular)?;
        let col_k = left.get_mut(k * N..).ok_or(Error::Singular)?;
        let below = col_k.get(k..).unwrap_or(&[]);
        let mut p = 0;
        let mut best = below.first().map_or(T::zero(), |v| v.abs());
        if pivoting != Pivoting::None {
            for (i, v) in below.iter().enumerate().skip(1) {
                if v.abs() > best {
                    best = v.abs();
                    p = i;
                }
            }
        }
        if !(best > tiny) {
            return Err(Error::Singular);
        }
        if p != 0 {
            let p = k + p;
            swap(col_k, k, p);
            for col in right.chunks_exact_mut(N) {
                swap(col, k, p);
            }
            swap(xs, k, p);
        }
        let pivot = col_k.get(k).copied().ok_or(Error::Singular)?;
        // multipliers l_ik = a_ik / a_kk, stored in place below the pivot
        let inv = T::one() / pivot;
        let multipliers = col_k.get_mut(k + 1..).unwrap_or(&mut []);
        for l in multipliers.iter_mut() {
            *l *= inv;
        }
        let multipliers = &*multipliers;
        for col in right.chunks_exact_mut(N) {
            let a_kj = col.get(k).copied().unwrap_or_else(T::zero);
            if a_kj != T::zero() {
                eliminate(col.get_mut(k + 1..).unwrap_or(&mut []), multipliers, a_kj);
            }
        }
        let x_k = xs.get(k).copied().unwrap_or_else(T::zero);
        if x_k != T::zero() {
            eliminate(xs.get_mut(k + 1..).unwrap_or(&mut []), multipliers, x_k);
        }
    }
    // back substitution, column by column: x_k = x_k / u_kk, then x_i −= u_ik x_k (i < k)
    for (k, col) in cols.chunks_exact(N).enumerate().rev() {
        let (above, rest) = xs.split_at_mut_checked(k).ok_or(Error::Singular)?;
        let (Some(x_k), Some(u_kk)) = (rest.first_mut(), col.get(k)) else {
            return Err(Error::Singular);
        };
        *x_k /= *u_kk;
        let x_k = *x_k;
        if x_k != T::zero() {
            eliminate(above, col, x_k);
        }
    }
    if xs.iter().all(|v| v.is_finite()) {
        Ok(x)
    } else {
        Err(Error::Singular)
    }
}

/// `target_i −= l_i · s` (a contiguous axpy).
#[inline(always)]
fn eliminate<T: Real>(target: &mut [T], l: &[T], s: T) {
    for (t, l) in target.iter_mut().zip(l) {
        *t -= *l * s;
    }
}

/// Swaps entries `k < p` of a slice; out-of-range indices leave it unchanged.
#[inline(always)]
fn swap<T: Real>(v: &mut [T], k: usize, p: usize) {
    if let Some((lo, hi)) = v.split_at_mut_checked(p)
        && let (Some(a), Some(b)) = (lo.get_mut(k), hi.first_mut())
    {
        core::mem::swap(a, b);
    }
}

/// Scales every row of the column-major `cols` (and `x`) to unit max-norm.
fn equilibrate_rows<T: Real, const N: usize>(cols: &mut [T], x: &mut [T]) -> Result<()> {
    let mut scale = [T::zero(); N];
    for col in cols.chunks_exact(N) {
        for (s, v) in scale.iter_mut().zip(col) {
            if v.abs() > *s {
                *s = v.abs();
            }
        }
    }
    for s in &mut scale {
        if !(*s > T::zero()) {
            return Err(Error::Singular);
        }
        *s = T::one() / *s;
    }
    for col in cols.chunks_exact_mut(N) {
        for (v, s) in col.iter_mut().zip(&scale) {
            *v *= *s;
        }
    }
    for (v, s) in x.iter_mut().zip(&scale) {
        *v *= *s;
    }
    Ok(())
}

/// Solves `K x = b` for a symmetric positive definite 3×3 `K` by LDLᵀ.
///
/// # Errors
/// [`Error::Singular`] when a pivot `d_i ≤ 3ε·max|K|` (not numerically positive definite).
pub fn solve_spd3<T: Real>(k: &Matrix3<T>, b: &Vector3<T>) -> Result<Vector3<T>> {
    Ldl3::factor(k)?.solve(b)
}

/// The LDLᵀ factors of a symmetric positive definite 3×3 matrix: factor once, solve for
/// several right-hand sides (the compliant contact law solves two).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ldl3<T> {
    d: [T; 3],
    l10: T,
    l20: T,
    l21: T,
}

impl<T: Real> Ldl3<T> {
    /// Factors `k` (its lower triangle is read).
    ///
    /// # Errors
    /// [`Error::Singular`] when a pivot falls below `3ε·max|k|`.
    pub fn factor(k: &Matrix3<T>) -> Result<Self> {
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
        Ok(Self {
            d: [d0, d1, d2],
            l10,
            l20,
            l21,
        })
    }

    /// Solves `K x = b`.
    ///
    /// # Errors
    /// [`Error::Singular`] when the solution is not finite.
    pub fn solve(&self, b: &Vector3<T>) -> Result<Vector3<T>> {
        let [d0, d1, d2] = self.d;
        let (l10, l20, l21) = (self.l10, self.l20, self.l21);
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
