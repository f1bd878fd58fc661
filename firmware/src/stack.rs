//! Stack high-water measurement by painting.
//!
//! [`measure`] fills the unused stack (everything below the current stack pointer, down to
//! the end of the stack region) with a pattern, runs the closure, then scans up from the
//! bottom for the first overwritten word. The difference to the stack pointer at the call
//! is the closure's worst-case stack use, including its callees, on this run.

use core::ptr::{addr_of, read_volatile, write_volatile};

const PAINT: u32 = 0xCCCC_CCCC;
/// Headroom left unpainted just below the stack pointer: the frame of [`measure`] itself.
const GUARD: usize = 256;

unsafe extern "C" {
    // The lowest address of the stack region. cortex-m-rt's `_stack_end`; with flip-link,
    // the stack sits at the bottom of RAM below .data/.bss, ending at the start of RAM.
    static _stack_end: u32;
}

fn sp() -> usize {
    cortex_m::register::msp::read() as usize
}

/// The bytes of stack below the current stack pointer.
#[must_use]
pub fn free() -> usize {
    sp() - stack_bottom()
}

fn stack_bottom() -> usize {
    // SAFETY: a linker-provided symbol; only its address is used.
    addr_of!(_stack_end) as usize
}

/// Runs `f` and returns its result with the peak stack use (bytes) of `f` and its callees.
#[inline(never)]
pub fn measure<R>(f: impl FnOnce() -> R) -> (R, usize) {
    let top = sp() - GUARD;
    let bottom = stack_bottom();
    let mut a = bottom;
    while a < top {
        // SAFETY: [bottom, top) is unused stack below our own frame.
        unsafe { write_volatile(a as *mut u32, PAINT) };
        a += 4;
    }
    let r = core::hint::black_box(f());
    let mut lowest = top;
    let mut a = bottom;
    while a < top {
        // SAFETY: as above; reading back the painted region.
        if unsafe { read_volatile(a as *const u32) } != PAINT {
            lowest = a;
            break;
        }
        a += 4;
    }
    (r, top + GUARD - lowest)
}
