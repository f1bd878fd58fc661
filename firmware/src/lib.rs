//! Board support shared by the firmware binaries and the on-target tests: defmt over
//! semihosting, exit codes, the fault and panic handlers, instruction-count markers,
//! virtual-time (SysTick) counting and stack painting.
//!
//! Exit codes seen by the host (the runner passes them to cargo):
//! `0` success, `101` panic, `102` HardFault, anything else is the firmware's own.
#![no_std]

use cortex_m_rt::{ExceptionFrame, exception};
use defmt_semihosting as _; // the global defmt logger: frames go out through SYS_WRITE

pub mod cases;
pub mod compare;
pub mod cost;
pub mod estimate_cases;
pub mod golden;
pub mod ground_cases;
pub mod launch_fit_cases;
pub mod shot;
pub mod stack;

/// Exit code of a panic (like Rust's test harness).
pub const EXIT_PANIC: i32 = 101;
/// Exit code of a HardFault.
pub const EXIT_HARDFAULT: i32 = 102;

/// Ends the emulation with `code` (semihosting `SYS_EXIT_EXTENDED`, which QEMU supports,
/// so any code reaches the host, not just success/failure).
pub fn exit(code: i32) -> ! {
    semihosting::process::exit(code)
}

/// Ends the emulation with success.
pub fn exit_ok() -> ! {
    exit(0)
}

/// Without a handler that exits, a fault would leave QEMU spinning in the default
/// handler until the runner's timeout.
#[exception]
unsafe fn HardFault(ef: &ExceptionFrame) -> ! {
    defmt::error!(
        "HardFault: pc={=u32:#010x} lr={=u32:#010x}",
        ef.pc(),
        ef.lr()
    );
    exit(EXIT_HARDFAULT)
}

/// Any other exception or interrupt that fires is a bug here.
#[exception]
unsafe fn DefaultHandler(irqn: i16) -> ! {
    defmt::error!("unexpected exception/interrupt {=i16}", irqn);
    exit(EXIT_HARDFAULT)
}

// The panic handler reports the location and exits with 101. That the core's impact and
// flight paths cannot reach it is proven separately by `nopanic/` (its handler calls an
// undefined symbol, so a reachable panic fails the link; docs/robustness.md). This image
// also links defmt, semihosting and the test harness, whose own panic paths are not ours.
#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    match info.location() {
        Some(l) => defmt::error!("panicked at {=str}:{=u32}", l.file(), l.line()),
        None => defmt::error!("panicked"),
    }
    exit(EXIT_PANIC)
}
