//! The only place raw pointers from C are read and written: null checks, then unaligned
//! copies of plain-data structs (every field is a float or an unsigned integer, so any bit
//! pattern C leaves in them is a valid Rust value).

use crate::error::{CARRY_ERR_NULL_POINTER, Result};

/// Copies `*p` out, or fails with `CARRY_ERR_NULL_POINTER`.
///
/// # Safety
/// `p` is NULL or points to a readable `T`.
pub unsafe fn read<T: Copy>(p: *const T) -> Result<T> {
    if p.is_null() {
        return Err(CARRY_ERR_NULL_POINTER);
    }
    // SAFETY: not NULL, readable by the caller's contract; unaligned reads are allowed and
    // every bit pattern is a valid `T` (plain floats and integers).
    Ok(unsafe { p.read_unaligned() })
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
    // SAFETY: the caller's contract; unaligned writes are allowed.
    unsafe { p.write_unaligned(value) }
}
