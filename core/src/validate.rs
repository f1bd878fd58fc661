//! Input checks shared by every public entry point: validate once, at the boundary.

use crate::error::{Error, Field, Reason, Result};
use crate::real::Real;
use nalgebra::{Matrix3, Vector3};

/// `x` must be finite.
pub(crate) fn finite<T: Real>(x: T, field: Field) -> Result<T> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(Error::invalid(field, Reason::NotFinite))
    }
}

/// `x` must be finite and strictly positive.
pub(crate) fn positive<T: Real>(x: T, field: Field) -> Result<T> {
    if finite(x, field)? > T::zero() {
        Ok(x)
    } else {
        Err(Error::invalid(field, Reason::NotPositive))
    }
}

/// `x` must be finite and not negative.
pub(crate) fn non_negative<T: Real>(x: T, field: Field) -> Result<T> {
    if finite(x, field)? >= T::zero() {
        Ok(x)
    } else {
        Err(Error::invalid(field, Reason::Negative))
    }
}

/// `x` must be strictly positive; `+∞` is allowed (a flat face direction, say).
pub(crate) fn positive_or_infinite<T: Real>(x: T, field: Field) -> Result<T> {
    #[allow(clippy::eq_op)]
    let is_nan = x != x;
    if is_nan {
        Err(Error::invalid(field, Reason::NotFinite))
    } else if x > T::zero() {
        Ok(x)
    } else {
        Err(Error::invalid(field, Reason::NotPositive))
    }
}

/// `lo ≤ x ≤ hi` and finite.
pub(crate) fn in_range<T: Real>(x: T, lo: T, hi: T, field: Field) -> Result<T> {
    let x = finite(x, field)?;
    if x >= lo && x <= hi {
        Ok(x)
    } else {
        Err(Error::invalid(field, Reason::OutOfRange))
    }
}

/// Every component finite.
pub(crate) fn finite_vector<T: Real>(v: &Vector3<T>, field: Field) -> Result<Vector3<T>> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(*v)
    } else {
        Err(Error::invalid(field, Reason::NotFinite))
    }
}

/// Every entry finite.
pub(crate) fn finite_matrix<T: Real>(m: &Matrix3<T>, field: Field) -> Result<Matrix3<T>> {
    if m.iter().all(|x| x.is_finite()) {
        Ok(*m)
    } else {
        Err(Error::invalid(field, Reason::NotFinite))
    }
}
