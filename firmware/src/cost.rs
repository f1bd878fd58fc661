//! Instruction counting.
//!
//! Two deterministic counters:
//!
//! * **Exact**, with the QEMU TCG plugin in `icount-plugin/`: it counts every guest
//!   instruction and prints the count between a call of [`carry_icount_start`] and the
//!   next [`carry_icount_stop`] (`icount region <k> <n>`). The firmware prints which
//!   region `k` is which; `cost.sh` joins the two.
//! * **Virtual time**, with `qemu-system-arm -icount shift=0`: QEMU then advances virtual
//!   time by exactly 1 ns per instruction, and SysTick (on the core clock: 25 MHz on the
//!   MPS2 boards, 16 MHz on the micro:bit) ticks once per 40 (62.5) instructions, so
//!   `ticks × 10⁹ / SYSCLK_HZ` counts instructions to within one tick per measurement. [`Region`] reads both. (`DWT.CYCCNT` reads 0
//!   under QEMU 7.2.) Without `-icount` the SysTick figure is host wall time: meaningless.
//!
//! Both are *instruction* counts, not cycles.

use cortex_m::peripheral::{SYST, syst::SystClkSource};

/// The core clock SysTick counts, as QEMU models the board: 25 MHz on the MPS2 boards,
/// 16 MHz on the micro:bit (nRF51).
pub const SYSCLK_HZ: u64 = if cfg!(carry_m0) {
    16_000_000
} else {
    25_000_000
};

/// Instructions per call from `ticks` over `n` calls, under `-icount shift=0` (where one
/// instruction is 1 ns of virtual time).
#[must_use]
pub fn insns_per_call(ticks: u32, n: u32) -> u32 {
    (u64::from(ticks) * 1_000_000_000 / SYSCLK_HZ / u64::from(n.max(1))) as u32
}

/// Opens a counted region (the plugin snapshots its counter at this function's entry).
#[unsafe(no_mangle)]
#[inline(never)]
pub extern "C" fn carry_icount_start() {
    // Distinct bodies so that no pass merges the two markers into one address.
    unsafe { core::arch::asm!("nop", options(nomem, nostack, preserves_flags)) };
}

/// Closes the counted region.
#[unsafe(no_mangle)]
#[inline(never)]
pub extern "C" fn carry_icount_stop() {
    unsafe { core::arch::asm!("nop", "nop", options(nomem, nostack, preserves_flags)) };
}

/// A free-running 24-bit SysTick.
pub struct Ticks {
    syst: SYST,
}

impl Ticks {
    /// Starts SysTick on the core clock, counting down from 2²⁴ − 1, no interrupt.
    pub fn new(mut syst: SYST) -> Self {
        syst.set_clock_source(SystClkSource::Core);
        syst.set_reload(0x00FF_FFFF);
        syst.clear_current();
        syst.enable_counter();
        Self { syst }
    }

    /// The current (down-counting) value.
    #[inline(always)]
    pub fn now(&self) -> u32 {
        SYST::get_current()
    }

    /// Ticks elapsed from `t0` to `t1` (one wrap at most).
    #[inline(always)]
    pub fn elapsed(t0: u32, t1: u32) -> u32 {
        t0.wrapping_sub(t1) & 0x00FF_FFFF
    }

    /// Releases the peripheral.
    pub fn free(self) -> SYST {
        self.syst
    }
}

/// Runs `f` `n` times inside one marked region; returns the SysTick ticks of the whole
/// loop and `f`'s last return value. Regions may not nest. A region of `n` empty
/// iterations calibrates the loop overhead.
#[inline(never)]
pub fn region<R>(ticks: &Ticks, n: u32, f: &mut dyn FnMut() -> R) -> (u32, Option<R>) {
    let mut last = None;
    let t0 = ticks.now();
    carry_icount_start();
    for _ in 0..n {
        last = Some(core::hint::black_box(f()));
    }
    carry_icount_stop();
    let t1 = ticks.now();
    (Ticks::elapsed(t0, t1), last)
}
