//! The only place raw pointers from C are read and written: null checks, then unaligned
//! copies of plain-data structs (every field is a float or an unsigned integer, so any bit
//! pattern C leaves in them is a valid Rust value).

use crate::error::{CARRY_ERR_NULL_POINTER, Result};

/// Calls `f` with `*p` (in place when aligned, else on an unaligned copy), or fails with
/// `CARRY_ERR_NULL_POINTER`.
///
/// # Safety
/// `p` is NULL or points to a readable `T` that nothing writes during the call.
pub unsafe fn with<T: Copy, R>(p: *const T, f: impl FnOnce(&T) -> Result<R>) -> Result<R> {
    if p.is_null() {
        return Err(CARRY_ERR_NULL_POINTER);
    }
    if p.is_aligned() {
        // SAFETY: not NULL, aligned, readable and not written meanwhile (the caller's
        // contract); every bit pattern is a valid `T` (plain floats and integers).
        return f(unsafe { &*p });
    }
    // SAFETY: not NULL and readable; unaligned reads are allowed; any bits are valid.
    f(&unsafe { p.read_unaligned() })
}

/// Checks that `p` is not NULL.
pub fn non_null<T>(p: *mut T) -> Result<*mut T> {
    if p.is_null() {
        Err(CARRY_ERR_NULL_POINTER)
    } else {
        Ok(p)
    }
}

/// Writes `value` to `p`.
///
/// # Safety
/// `p` is not NULL and points to a writable `T`.
pub unsafe fn write<T>(p: *mut T, value: T) {
    if p.is_aligned() {
        // SAFETY: the caller's contract, and aligned.
        unsafe { p.write(value) }
    } else {
        // SAFETY: the caller's contract; unaligned writes are allowed.
        unsafe { p.write_unaligned(value) }
    }
}
