//! The estimators' small (N×N: 7 for club data, 8 for the launch from the flight) symmetric
//! positive definite solves: one Cholesky factorisation
//! (Golub & Van Loan, "Matrix Computations", 4th ed., Alg. 4.2.1) of the matrix scaled to a
//! unit diagonal, `Ã = D A D` with `D = diag(1/√a_ii)` (the unknowns mix radians, metres
//! and m/s: the scaling makes the pivot test unit-free), `Ã = L Lᵀ`. Then
//! `A⁻¹ b = D L⁻ᵀ L⁻¹ D b` and `A⁻¹ = D L⁻ᵀ L⁻¹ D`.
//!
//! Every access goes through `get`/`get_mut`: no panic path (the no-panic link proof).

use crate::error::{Error, Result};
use crate::real::{Real, lit};
use nalgebra::{SMatrix, SVector};

/// The scaled Cholesky factor of an SPD N×N matrix.
pub(crate) struct Cholesky<T: Real, const N: usize> {
    /// Lower triangle `L` of `D A D = L Lᵀ`.
    l: SMatrix<T, N, N>,
    /// The scaling `D`.
    d: SVector<T, N>,
}

fn at<T: Real, const N: usize>(m: &SMatrix<T, N, N>, i: usize, j: usize) -> T {
    m.get((i, j)).copied().unwrap_or_else(T::zero)
}

fn put<T: Real, const N: usize>(m: &mut SMatrix<T, N, N>, i: usize, j: usize, v: T) {
    if let Some(e) = m.get_mut((i, j)) {
        *e = v;
    }
}

impl<T: Real, const N: usize> Cholesky<T, N> {
    /// Factors `a` (its lower triangle is read).
    ///
    /// # Errors
    /// [`Error::Singular`] when `a` is not positive definite in the precision (a pivot of
    /// the scaled matrix at or below `7 ε`).
    pub fn factor(a: &SMatrix<T, N, N>) -> Result<Self> {
        let mut d = SVector::<T, N>::zeros();
        for (i, v) in d.iter_mut().enumerate() {
            let aii = at(a, i, i);
            if !(aii > T::zero() && aii.is_finite()) {
                return Err(Error::Singular);
            }
            *v = T::one() / aii.root();
        }
        let di = |i: usize| d.get(i).copied().unwrap_or_else(T::zero);
        let tiny = lit::<T>(7.0) * T::default_epsilon();
        let mut l = SMatrix::<T, N, N>::zeros();
        for j in 0..N {
            let mut s = at(a, j, j) * di(j) * di(j);
            for k in 0..j {
                s -= at(&l, j, k) * at(&l, j, k);
            }
            if !(s > tiny) {
                return Err(Error::Singular);
            }
            let ljj = s.root();
            put(&mut l, j, j, ljj);
            for i in j + 1..N {
                let mut s = at(a, i, j) * di(i) * di(j);
                for k in 0..j {
                    s -= at(&l, i, k) * at(&l, j, k);
                }
                put(&mut l, i, j, s / ljj);
            }
        }
        Ok(Self { l, d })
    }

    /// `A⁻¹ b`.
    ///
    /// # Errors
    /// [`Error::Singular`] when the result is not finite.
    pub fn solve(&self, b: &SVector<T, N>) -> Result<SVector<T, N>> {
        let mut y = b.component_mul(&self.d);
        // L y' = y (forward), then Lᵀ x = y' (backward)
        for i in 0..N {
            let mut s = y.get(i).copied().unwrap_or_else(T::zero);
            for k in 0..i {
                s -= at(&self.l, i, k) * y.get(k).copied().unwrap_or_else(T::zero);
            }
            if let Some(v) = y.get_mut(i) {
                *v = s / at(&self.l, i, i);
            }
        }
        for i in (0..N).rev() {
            let mut s = y.get(i).copied().unwrap_or_else(T::zero);
            for k in i + 1..N {
                s -= at(&self.l, k, i) * y.get(k).copied().unwrap_or_else(T::zero);
            }
            if let Some(v) = y.get_mut(i) {
                *v = s / at(&self.l, i, i);
            }
        }
        let x = y.component_mul(&self.d);
        if x.iter().all(|v| v.is_finite()) {
            Ok(x)
        } else {
            Err(Error::Singular)
        }
    }

    /// `A⁻¹`.
    ///
    /// # Errors
    /// [`Error::Singular`] when the result is not finite.
    pub fn inverse(&self) -> Result<SMatrix<T, N, N>> {
        // L⁻¹ by forward substitution, column by column
        let mut li = SMatrix::<T, N, N>::zeros();
        for c in 0..N {
            for i in c..N {
                let mut s = if i == c { T::one() } else { T::zero() };
                for k in c..i {
                    s -= at(&self.l, i, k) * at(&li, k, c);
                }
                put(&mut li, i, c, s / at(&self.l, i, i));
            }
        }
        let inv = li.transpose() * li;
        let di = |i: usize| self.d.get(i).copied().unwrap_or_else(T::zero);
        let c = SMatrix::<T, N, N>::from_fn(|i, j| di(i) * at(&inv, i, j) * di(j));
        if c.iter().all(|v| v.is_finite()) {
            Ok(c)
        } else {
            Err(Error::Singular)
        }
    }
}
